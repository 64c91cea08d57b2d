/*
 * opx_linkset: a robot as a set of links, each with shapes fixed in the link
 * frame, a padding, and a pose in the map frame.
 *
 * Shape conventions (all in metres, in the SHAPE frame, which sits at
 * opx_shape.pose in the link frame):
 *   sphere    radius, centred at the shape origin
 *   box       size[3]: FULL edge lengths along x, y, z (as URDF and FCL),
 *             centred at the origin
 *   cylinder  radius and FULL length along z, centred at the origin (URDF)
 *   capsule   radius and length of the cylindrical part along z (the
 *             distance between the two sphere centres; FCL's convention),
 *             centred at the origin
 *   convex    the convex hull of `vertices` (solid)
 *   mesh      triangles `indices` over `vertices` (a surface: a cell wholly
 *             inside a closed mesh touches no triangle and is not reported,
 *             as in FCL; use a convex hull for a solid part)
 * Sizes, vertex coordinates and shape positions are within +-1e6 m (as a
 * URDF's), so that distances over them stay finite.
 *
 * Padding is a safety margin: a padded shape is the Minkowski sum of the
 * shape with a ball of radius padding (exact rounding, not scaling).  A
 * link's padding is its own plus the set's global padding.
 *
 * Copy semantics: the library copies vertices, indices and names; a link
 * set is read-only while queries run on it (any number of threads may
 * query one link set at once); changing it needs exclusive access.
 */
#ifndef OCTOPROX_LINKSET_H
#define OCTOPROX_LINKSET_H

#include "common.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct opx_linkset opx_linkset;

#define OPX_SHAPE_SPHERE 1
#define OPX_SHAPE_BOX 2
#define OPX_SHAPE_CYLINDER 3
#define OPX_SHAPE_CAPSULE 4
#define OPX_SHAPE_CONVEX 5
#define OPX_SHAPE_MESH 6

typedef struct opx_shape {
    uint32_t struct_size;
    int32_t kind;        /**< OPX_SHAPE_* */
    opx_pose pose;       /**< the shape frame in the link frame; identity */
    double radius;       /**< sphere, cylinder, capsule */
    double length;       /**< cylinder: full length; capsule: cylindrical part */
    double size[3];      /**< box: full edge lengths */
    /** convex and mesh: vertex_count points of 3 doubles, vertex_stride bytes
     * apart (0: packed), in the shape frame */
    const double *vertices;
    size_t vertex_count;
    size_t vertex_stride;
    /** mesh: triangle_count triangles of 3 vertex indices, packed */
    const uint32_t *indices;
    size_t triangle_count;
} opx_shape;

#define OPX_SHAPE_INIT {sizeof(opx_shape), 0, OPX_POSE_IDENTITY, 0.0, 0.0, {0.0, 0.0, 0.0}, \
    NULL, 0, 0, NULL, 0}
OPX_API opx_status opx_shape_init(opx_shape *shape, size_t size);

OPX_API opx_status opx_linkset_create(opx_linkset **out);
OPX_API void opx_linkset_destroy(opx_linkset *links);
/** A deep copy (shapes, names, poses, paddings, enabled flags and pairs). */
OPX_API opx_status opx_linkset_clone(const opx_linkset *links, opx_linkset **out);

/** Adds a link named `name` (copied; names need not be unique, but
 * opx_linkset_find_link returns the first) with an identity pose. */
OPX_API opx_status opx_linkset_add_link(opx_linkset *links, const char *name,
                                        uint32_t *out_link);
/** Adds a shape to a link; *out_shape (may be NULL) gets its index within
 * the link.  Meshes are built into a BVH over their triangles here, once.
 * Only the new shape is placed; the link set's own BVH is rebuilt by the
 * next opx_linkset_set_poses or query, so building a set of n shapes one
 * by one costs O(n log n). */
OPX_API opx_status opx_linkset_add_shape(opx_linkset *links, uint32_t link,
                                         const opx_shape *shape, uint32_t *out_shape);

OPX_API opx_status opx_linkset_get_link_count(const opx_linkset *links, uint32_t *out_count);
OPX_API opx_status opx_linkset_get_shape_count(const opx_linkset *links, uint32_t link,
                                               uint32_t *out_count);
/** The link's name; valid until the link set changes or is destroyed. */
OPX_API opx_status opx_linkset_get_link_name(const opx_linkset *links, uint32_t link,
                                             const char **out_name);
/**
 * Shape `shape` of link `link` as it was added (shape frame at out->pose in
 * the link frame; a box's full sizes, a cylinder's full length).  For
 * convex and mesh shapes, vertices and indices point into the link set
 * (packed; valid until the link set changes or is destroyed); a mesh holds
 * only the vertices its triangles use.  out->struct_size must be set.
 */
OPX_API opx_status opx_linkset_get_shape(const opx_linkset *links, uint32_t link, uint32_t shape,
                                         opx_shape *out_shape);
/** The first link named `name`; OPX_ERROR_INVALID_ARGUMENT when none. */
OPX_API opx_status opx_linkset_find_link(const opx_linkset *links, const char *name,
                                         uint32_t *out_link);

/** Paddings in metres (>= 0): global and per link. */
OPX_API opx_status opx_linkset_set_padding(opx_linkset *links, double padding);
OPX_API opx_status opx_linkset_set_link_padding(opx_linkset *links, uint32_t link,
                                                double padding);
/** Disabled links take part in no query (e.g. links the sensor cannot see,
 * or a gripper holding an object), nor do the objects attached to them.
 * All links start enabled. */
OPX_API opx_status opx_linkset_set_link_enabled(opx_linkset *links, uint32_t link,
                                                int32_t enabled);

/** Whether self-collision queries (self_collision.h) check links a and b
 * (a != b; the order does not matter).  Every pair starts enabled but the
 * pairs an SRDF disables (robot.h).  A link that is itself disabled takes
 * part in no pair, whatever its pairs say. */
OPX_API opx_status opx_linkset_set_pair_enabled(opx_linkset *links, uint32_t a, uint32_t b,
                                                int32_t enabled);
OPX_API opx_status opx_linkset_get_pair_enabled(const opx_linkset *links, uint32_t a, uint32_t b,
                                                int32_t *out_enabled);

/**
 * Sets the pose of every link in the MAP frame: `count` must equal the
 * number of links; pose i is at (const char *)poses + i * stride (0:
 * packed).  The BVH over the links is refit, not rebuilt.  On an invalid
 * pose nothing changes.
 */
OPX_API opx_status opx_linkset_set_poses(opx_linkset *links, const opx_pose *poses,
                                         size_t count, size_t stride);
/** The pose of link `link` in the MAP frame (position + unit quaternion
 * x y z qx qy qz qw). */
OPX_API opx_status opx_linkset_get_pose(const opx_linkset *links, uint32_t link,
                                        opx_pose *out_pose);
/** Every link's pose in the MAP frame, in link order (out_poses[i] is link
 * i, as opx_linkset_get_pose gives it; packed opx_pose elements).
 * *out_count gets the link count; capacity below it:
 * OPX_ERROR_BUFFER_TOO_SMALL (nothing written; out_poses may then be
 * NULL). */
OPX_API opx_status opx_linkset_get_poses(const opx_linkset *links, opx_pose *out_poses,
                                         size_t capacity, size_t *out_count);

/* ---- Attached objects --------------------------------------------------- */
/*
 * An object attached to a link (MoveIt's attached collision object, e.g. a
 * part the gripper holds) moves with the link: forward kinematics, poses,
 * paths and batches move it.  Against the octree and world objects it is
 * checked as the link's own shapes are (with the link's padding and
 * enabled flag); contacts and distances name the link, the attached
 * object (opx_contact.attached, opx_distance_result.attached) and the
 * shape within it.  Against the robot (self-collision) it is checked with
 * every link but the one it is attached to and its touch links (links it
 * may touch, e.g. the gripper's fingers), whatever the link pairs say, and
 * with the objects attached to other links.  Indices are positions:
 * detaching an object moves every later one down by one.
 */

/**
 * Attaches an object named `name` (copied; names need not be unique) to
 * link `link`: `shape_count` (>= 1) shapes, each at its pose in the OBJECT
 * frame (shapes[i].pose), the object frame at `pose` in the LINK frame
 * (x y z qx qy qz qw; NULL: the link frame).  `touch_links` names
 * `touch_link_count` links (each the first link of that name; may be NULL
 * when the count is 0) the object may touch; the link it is attached to
 * always may.  *out_object (may be NULL) gets its index.  On error
 * nothing changes.
 */
OPX_API opx_status opx_linkset_attach_object(opx_linkset *links, uint32_t link, const char *name,
                                             const opx_shape *shapes, size_t shape_count,
                                             const opx_pose *pose, const char *const *touch_links,
                                             size_t touch_link_count, uint32_t *out_object);
/** Detaches (removes) attached object `object`; later ones move down by one. */
OPX_API opx_status opx_linkset_detach_object(opx_linkset *links, uint32_t object);
OPX_API opx_status opx_linkset_get_attached_count(const opx_linkset *links, uint32_t *out_count);
/** The first attached object named `name`; OPX_ERROR_INVALID_ARGUMENT when none. */
OPX_API opx_status opx_linkset_find_attached(const opx_linkset *links, const char *name,
                                             uint32_t *out_object);
/** The attached object's name; valid until the link set changes or is destroyed. */
OPX_API opx_status opx_linkset_get_attached_name(const opx_linkset *links, uint32_t object,
                                                 const char **out_name);
/** The link the object is attached to. */
OPX_API opx_status opx_linkset_get_attached_link(const opx_linkset *links, uint32_t object,
                                                 uint32_t *out_link);
/** The object frame in its link's frame (x y z qx qy qz qw). */
OPX_API opx_status opx_linkset_get_attached_pose(const opx_linkset *links, uint32_t object,
                                                 opx_pose *out_pose);
OPX_API opx_status opx_linkset_get_attached_shape_count(const opx_linkset *links, uint32_t object,
                                                        uint32_t *out_count);
/** Shape `shape` of the attached object as it was given (its pose in the
 * OBJECT frame); vertices and indices as in opx_linkset_get_shape. */
OPX_API opx_status opx_linkset_get_attached_shape(const opx_linkset *links, uint32_t object,
                                                  uint32_t shape, opx_shape *out_shape);
/** The object's touch links (link indices, ascending; its own link not
 * among them): *out_count gets their number; capacity below it:
 * OPX_ERROR_BUFFER_TOO_SMALL (nothing written; out_links may then be NULL). */
OPX_API opx_status opx_linkset_get_attached_touch_links(const opx_linkset *links, uint32_t object,
                                                        uint32_t *out_links, size_t capacity,
                                                        size_t *out_count);

/*
 * Aliases kept for compatibility: each behaves exactly as the function
 * named in its comment (its errors name the alias).  Use those names.
 */
/** Alias of opx_linkset_get_link_count. */
OPX_API opx_status opx_linkset_link_count(const opx_linkset *links, uint32_t *out_count);
/** Alias of opx_linkset_get_shape_count. */
OPX_API opx_status opx_linkset_shape_count(const opx_linkset *links, uint32_t link,
                                           uint32_t *out_count);
/** Alias of opx_linkset_get_link_name. */
OPX_API opx_status opx_linkset_link_name(const opx_linkset *links, uint32_t link,
                                         const char **out_name);

#ifdef __cplusplus
}
#endif

#endif /* OCTOPROX_LINKSET_H */
