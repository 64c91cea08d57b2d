/**
 * @file world.h
 * opx_world: known objects beside the sensed map (tables, shelves, walls,
 * bins), as MoveIt keeps them in its planning scene.
 *
 * An object has a name, a pose in the MAP frame, an enabled flag, and
 * shapes of the link-set kinds (opx_shape, linkset.h: sphere, box,
 * cylinder, capsule, convex, mesh), each at its own pose in the OBJECT
 * frame.  Objects have no padding: a link's padding is the margin.  A mesh
 * is a surface, as on links: a link wholly inside a closed mesh touches
 * none of its triangles (use a convex hull or boxes for a solid).
 *
 * Queries check a link set against a world's enabled objects when the
 * world is set on the query context (opx_query_set_world): collision,
 * distance, paths, batches and motions then answer for the octree and the
 * objects together.
 *
 * Indices are positions: object i is the i-th of the world; removing an
 * object moves every later one down by one.  Names need not be unique
 * (opx_world_find_object returns the first).
 *
 * Copy semantics: the library copies names, vertices and indices.  A world
 * is read-only while queries run on it (any number of threads may query
 * one world at once); changing it needs exclusive access.
 */
#ifndef OCTOPROX_WORLD_H
#define OCTOPROX_WORLD_H

#include "common.h"
#include "linkset.h"
#include "query.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct opx_world opx_world;

/** An empty world. */
OPX_API opx_status opx_world_create(opx_world **out);
/** Destroys the world; NULL is a no-op.  No query may still have it set. */
OPX_API void opx_world_destroy(opx_world *world);

/**
 * Adds an object named `name` (copied) at `pose` (the object frame in the
 * map frame: x y z qx qy qz qw, ROS order; NULL: identity; a position
 * within +-1e6 m), enabled and without shapes.  *out_object (may be NULL)
 * gets its index.
 */
OPX_API opx_status opx_world_add_object(opx_world *world, const char *name, const opx_pose *pose,
                                        uint32_t *out_object);
/**
 * Adds a shape to object `object`: shape->pose places it in the OBJECT
 * frame; sizes as in linkset.h (a box's full edges, a cylinder's full
 * length along its z axis), every size and position within +-1e6 m.
 * *out_shape (may be NULL) gets its index within the object.  Meshes get
 * their triangle tree here, once; the object's other shapes are not
 * placed again.
 */
OPX_API opx_status opx_world_add_shape(opx_world *world, uint32_t object, const opx_shape *shape,
                                       uint32_t *out_shape);
/** Removes object `object`; the later objects move down by one. */
OPX_API opx_status opx_world_remove_object(opx_world *world, uint32_t object);

/** Moves object `object`: pose is its frame in the map frame (x y z qx qy qz qw). */
OPX_API opx_status opx_world_set_object_pose(opx_world *world, uint32_t object, const opx_pose *pose);
/** The object's pose in the map frame. */
OPX_API opx_status opx_world_get_object_pose(const opx_world *world, uint32_t object, opx_pose *out_pose);
/** Disabled objects take part in no query.  Objects start enabled. */
OPX_API opx_status opx_world_set_object_enabled(opx_world *world, uint32_t object, int32_t enabled);
OPX_API opx_status opx_world_get_object_enabled(const opx_world *world, uint32_t object,
                                                int32_t *out_enabled);

OPX_API opx_status opx_world_get_object_count(const opx_world *world, uint32_t *out_count);
/** The object's name; valid until the world changes or is destroyed. */
OPX_API opx_status opx_world_get_object_name(const opx_world *world, uint32_t object,
                                             const char **out_name);
/** The first object named `name`; OPX_ERROR_INVALID_ARGUMENT when none. */
OPX_API opx_status opx_world_find_object(const opx_world *world, const char *name, uint32_t *out_object);
OPX_API opx_status opx_world_get_shape_count(const opx_world *world, uint32_t object,
                                             uint32_t *out_count);
/**
 * Shape `shape` of object `object` as it was added (its pose in the object
 * frame).  For convex and mesh shapes, vertices and indices point into the
 * world (packed; valid until the world changes or is destroyed); a mesh
 * holds only the vertices its triangles use.  out_shape->struct_size must
 * be set.
 */
OPX_API opx_status opx_world_get_shape(const opx_world *world, uint32_t object, uint32_t shape,
                                       opx_shape *out_shape);

/**
 * Attaches a copy of world object `object` (its name and shapes) to link
 * `link` of `links` where it stands now: its pose in the link frame is
 * the object's map pose seen from the link's current pose.  `touch_links`
 * as in opx_linkset_attach_object.  The world does not change: remove or
 * disable the object there (opx_world_remove_object,
 * opx_world_set_object_enabled), as MoveIt moves an object it attaches out
 * of its world, or the attached copy touches the original.  An object
 * without shapes is an invalid argument.
 */
OPX_API opx_status opx_linkset_attach_world_object(opx_linkset *links, uint32_t link,
                                                   const opx_world *world, uint32_t object,
                                                   const char *const *touch_links,
                                                   size_t touch_link_count, uint32_t *out_attached);

/* ---- MoveIt planning scenes -------------------------------------------- */

/**
 * A moveit_msgs/PlanningScene as YAML (rostopic echo, ros2 topic echo, a
 * dump): world.collision_objects[] (a PlanningSceneWorld's
 * collision_objects[] too), applied in file order: ADD (replacing an
 * object of the same id), APPEND, REMOVE (an empty id: all) and MOVE.
 * Primitives BOX [x y z], SPHERE [radius] and CYLINDER [height, radius];
 * meshes; poses on the object and on each shape.  header.frame_id is taken
 * as the map frame, unless it names a child frame of the scene's
 * fixed_frame_transforms, whose transform then places the object.  CONE
 * primitives, planes and meshes given as files (`resource`) are refused
 * (OPX_ERROR_UNSUPPORTED); the robot state, allowed collision matrix,
 * octomap and colours are ignored.  Several documents apply in order, one
 * that is not a diff clearing the world first.  Robowflex's dialect
 * (MotionBenchMaker's scenes) is read as well: positions, translations
 * and vertices as lists [x, y, z], orientations and rotations as
 * [x, y, z, w], primitive types as the words box, sphere, cylinder and
 * cone, operations as add, remove, append and move (any case), triangles
 * as bare [i, j, k].
 */
#define OPX_SCENE_FORMAT_YAML 1
/**
 * MoveIt's .scene text (PlanningScene::saveGeometryToStream), with object
 * poses and subframes (MoveIt 1.1 and later) or without (older files):
 * box, sphere, cylinder ("radius length") and mesh shapes.
 */
#define OPX_SCENE_FORMAT_TEXT 2

/**
 * A new world holding the objects of the scene file at `path`, whose
 * extension gives the format: .yaml or .yml (OPX_SCENE_FORMAT_YAML),
 * .scene (OPX_SCENE_FORMAT_TEXT).  A file that cannot be read gives
 * OPX_ERROR_IO; a malformed one OPX_ERROR_CORRUPT, the message naming the
 * file, the line and the field.  *out is NULL on failure.
 */
OPX_API opx_status opx_world_load_scene_file(const char *path, opx_world **out);
/** As opx_world_load_scene_file, from `size` bytes in `format` (OPX_SCENE_FORMAT_*). */
OPX_API opx_status opx_world_load_scene_memory(const void *data, size_t size, int32_t format,
                                               opx_world **out);

/* ---- Queries ----------------------------------------------------------- */

/**
 * Sets the world whose enabled objects opx_query_collide and
 * opx_query_distance check besides the octree (NULL detaches it).  The
 * query keeps the pointer: the world must outlive its use by the query
 * (set NULL or destroy the query first), and must not change while a
 * query runs.  With a world set:
 *  - the octree may be NULL (objects only);
 *  - collision: collided when the links touch a cell or an object; the
 *    contacts hold both (opx_contact.object: the object's index, -1 for a
 *    cell), up to max_contacts together, cells first; an object contact's
 *    cell fields are zero, and with compute_penetration it has the depth,
 *    normal and point of the shape pair; cost boxes come from the octree
 *    alone (compute_cost needs an octree);
 *  - distance: the least of the octree's and the objects' distances
 *    (opx_distance_result.object names the object, -1 for a cell; the
 *    witness point_on_cell then lies on the object); per-link distances
 *    the least per link; signed_distance measures the objects' overlap by
 *    the same exact kernels as self-collision.  abs_err and rel_err apply
 *    to the octree; objects are measured exactly.
 *  - paths, batches and motions (opx_query_path, opx_query_check_*) check
 *    every waypoint or configuration against the octree and the objects
 *    by the same rules: collided when either is touched, distances the
 *    least of both; the octree may be NULL there too.  Objects have no
 *    cost (they are known): a path's or motion's cost comes from the
 *    octree alone, and compute_cost needs one.  Batch workers share the
 *    world read-only (its object tree is built once, on the calling
 *    thread, before the work is split), so the answers do not depend on
 *    max_threads.
 * Caller boxes (opx_query_*_boxes) do not check objects: on a query with a
 * world they give OPX_ERROR_UNSUPPORTED.  Self-collision ignores the
 * world.
 */
OPX_API opx_status opx_query_set_world(opx_query *query, const opx_world *world);

#ifdef __cplusplus
}
#endif

#endif /* OCTOPROX_WORLD_H */
