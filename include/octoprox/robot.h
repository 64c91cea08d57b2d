/*
 * Robot models from URDF: a link set built from a URDF file or string, its
 * joint tree, and forward kinematics (FK) that sets every link pose at once.
 *
 * Frames:
 *   - A link's frame is the URDF link frame: opx_linkset_get_pose gives it
 *     in the MAP frame, and every shape pose (opx_shape.pose) is in it.
 *   - base_pose (FK calls) is the pose of the URDF ROOT link (the one no
 *     joint has as child) in the map frame; NULL means identity.
 *   - A joint's origin is the child link frame in the parent link frame at
 *     joint position 0; the joint axis is in the child link frame (URDF).
 * Units: metres and radians (joint positions: radians for revolute and
 * continuous joints, metres for prismatic joints).
 *
 * What becomes what:
 *   - Every URDF <link> becomes one link of the set, with the same name, in
 *     the order the links appear in the file; links without <collision>
 *     have no shapes but still get a pose from FK.
 *   - Every <collision> element becomes one shape of its link, its <origin>
 *     giving the shape pose in the link frame: <box size> (full edge
 *     lengths), <sphere radius>, <cylinder radius length> (full length
 *     along z, as OPX_SHAPE_CYLINDER), <mesh filename scale> (OPX_SHAPE_MESH).
 *     <visual> elements are ignored (their files need not exist).
 *   - Meshes are read with assimp (STL, DAE, OBJ and the other formats it
 *     knows): all meshes of a file are merged into one triangle mesh with
 *     the file's node transforms applied, then the URDF scale.  A DAE's
 *     <unit> is applied (its coordinates become metres); its <up_axis> is
 *     not turned into assimp's Y-up, so coordinates stay as written (z up),
 *     as ROS tools (RViz, MoveIt) read them.  A mesh is a
 *     SURFACE (see linkset.h): a cell wholly inside a closed mesh touches no
 *     triangle.
 *   - Other collision geometry (e.g. <capsule>) fails the load with
 *     OPX_ERROR_UNSUPPORTED naming the link (it is never silently dropped).
 *     A box, sphere or cylinder with a size <= 0, a mesh with a zero scale,
 *     or a missing or malformed value: OPX_ERROR_CORRUPT.
 *
 * Mesh file names:
 *   - "package://NAME/rest": for each entry DIR of package_dirs in order,
 *     DIR/NAME/rest, then DIR/rest when the last component of DIR is NAME.
 *     An entry "NAME=DIR" maps package NAME to DIR explicitly (DIR/rest),
 *     e.g. "moveit_resources_pr2_description=/data/robots/pr2_description".
 *     The first existing file wins; none: OPX_ERROR_IO naming the URI.
 *   - "file:///abs/path" and absolute paths as they are.
 *   - Relative paths (and "file://rel"): relative to base_dir.
 *
 * Joints keep the URDF file's order (fixed joints included); that is the
 * "model order" of opx_linkset_set_joint_positions.  Joint limits are
 * reported, not enforced.  A link set made by opx_linkset_create has no
 * joints: the FK calls on it fail with OPX_ERROR_UNSUPPORTED.
 *
 * Active joints: the revolute, continuous and prismatic joints that mimic
 * no other joint, in model order.  Their values alone decide every link
 * pose: fixed joints do not move, mimic joints follow their leaders, and
 * floating and planar joints are not moved by FK (see OPX_JOINT_FLOATING;
 * place a mobile base with base_pose), so none of those is active.  For
 * a robot without floating or planar joints they are the joints MoveIt
 * calls active (neither fixed nor mimic), in the URDF file's order; MoveIt
 * and Pinocchio order joints along the kinematic tree, which may differ:
 * match them by name (opx_linkset_get_active_joints, opx_joint_info.name)
 * or use opx_linkset_set_named_joint_positions.
 * opx_linkset_set_active_joint_positions takes one value per active joint;
 * the batch calls (batch.h) take rows of either order.
 */
#ifndef OCTOPROX_ROBOT_H
#define OCTOPROX_ROBOT_H

#include "common.h"
#include "linkset.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct opx_urdf_options {
    uint32_t struct_size;
    uint32_t reserved0;              /**< padding; keep 0 */
    /** Directories that resolve package:// URIs (see above); the strings
     * are read during the call only. */
    const char *const *package_dirs;
    size_t package_dir_count;
    /** Base of relative mesh paths.  NULL: the URDF file's folder
     * (opx_linkset_load_urdf_file) or the current directory (_string). */
    const char *base_dir;
    /** Optional SRDF file: its <disable_collisions link1 link2> pairs are
     * read (and only those): self-collision skips them (self_collision.h),
     * see also opx_linkset_get_disabled_pair.  NULL: none. */
    const char *srdf_path;
} opx_urdf_options;

#define OPX_URDF_OPTIONS_INIT {sizeof(opx_urdf_options), 0, NULL, 0, NULL, NULL}
OPX_API opx_status opx_urdf_options_init(opx_urdf_options *options, size_t size);

/**
 * A new link set from a URDF file or an XML string (options NULL:
 * defaults).  All link poses start at FK with every joint at 0 and the
 * root link at the map origin.  Errors: OPX_ERROR_IO (file or mesh cannot
 * be read, unknown package), OPX_ERROR_CORRUPT (malformed XML or URDF, bad
 * geometry, a mesh without triangles, a bad SRDF), OPX_ERROR_UNSUPPORTED
 * (collision geometry other than box, sphere, cylinder, mesh),
 * OPX_ERROR_INVALID_ARGUMENT (NULLs, bad options); *out is NULL on failure.
 * Limits, checked before any XML parser reads the text: URDF and SRDF text
 * is valid UTF-8 without NUL bytes; elements nest at most 100 deep; the
 * links form one tree (no cycle, one parent each, one root) at most 1,000
 * joints deep; lengths, angles, axes, scales and mimic factors are finite
 * numbers within +-1e6.  The library writes nothing to stderr.
 */
OPX_API opx_status opx_linkset_load_urdf_file(const char *path, const opx_urdf_options *options,
                                              opx_linkset **out);
OPX_API opx_status opx_linkset_load_urdf_string(const char *xml, const opx_urdf_options *options,
                                                opx_linkset **out);

/* Joint types.  FLOATING and PLANAR joints are not moved by FK: they stay
 * at their origin (as if fixed) and their positions are ignored. */
#define OPX_JOINT_FIXED 0
#define OPX_JOINT_REVOLUTE 1
#define OPX_JOINT_CONTINUOUS 2
#define OPX_JOINT_PRISMATIC 3
#define OPX_JOINT_FLOATING 4
#define OPX_JOINT_PLANAR 5

/** No mimic joint / no link. */
#define OPX_JOINT_NONE UINT32_MAX

typedef struct opx_joint_info {
    uint32_t struct_size;
    int32_t type;                /**< OPX_JOINT_* */
    const char *name;            /**< valid while the link set lives */
    uint32_t parent_link;        /**< link indices in the set */
    uint32_t child_link;
    double axis[3];              /**< unit axis in the child link frame */
    opx_pose origin;             /**< child link frame in the parent link frame at 0 */
    int32_t has_limits;          /**< 1 when the URDF has a <limit> element */
    uint32_t mimic_joint;        /**< joint this one mimics, or OPX_JOINT_NONE */
    double lower, upper;         /**< position limits (m or rad); continuous: -inf, +inf */
    double velocity, effort;     /**< as in the URDF (m/s or rad/s; N or N m); 0 when absent */
    double mimic_multiplier;     /**< position = multiplier * master + offset */
    double mimic_offset;
} opx_joint_info;

#define OPX_JOINT_INFO_INIT {sizeof(opx_joint_info), 0, NULL, OPX_JOINT_NONE, OPX_JOINT_NONE, \
    {0.0, 0.0, 0.0}, OPX_POSE_IDENTITY, 0, OPX_JOINT_NONE, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0}
OPX_API opx_status opx_joint_info_init(opx_joint_info *info, size_t size);

/** Number of joints (0 for a set not made from URDF). */
OPX_API opx_status opx_linkset_get_joint_count(const opx_linkset *links, uint32_t *out_count);
/** The joint named `name`; OPX_ERROR_INVALID_ARGUMENT when none. */
OPX_API opx_status opx_linkset_find_joint(const opx_linkset *links, const char *name,
                                          uint32_t *out_joint);
OPX_API opx_status opx_linkset_get_joint_info(const opx_linkset *links, uint32_t joint,
                                              opx_joint_info *out);

/**
 * FK: sets every joint position and then every link pose in the map frame
 * (and refits the link set like opx_linkset_set_poses).  `positions` has
 * `count` = joint count values in model order; values of fixed, floating
 * and planar joints are ignored; a mimic joint takes multiplier * master +
 * offset and its own value is ignored.  All values must be finite and
 * within +-1e6 (rad or m).
 * base_pose: the root link in the map frame (NULL: identity).  Links added
 * with opx_linkset_add_link after loading keep their pose.  On error
 * nothing changes.
 */
OPX_API opx_status opx_linkset_set_joint_positions(opx_linkset *links, const double *positions,
                                                   size_t count, const opx_pose *base_pose);
/** As above, but only the `count` named joints change (any subset, in
 * any order; a name given twice takes its last value); the others keep
 * their last values (initially 0).  Naming the active joints alone sets
 * every link pose.  A mimic, fixed, floating or planar joint may be named
 * but its value is ignored, as in model order.  count 0 recomputes the
 * poses at base_pose.  An unknown name is an invalid argument (the name
 * is in the message) and changes nothing. */
OPX_API opx_status opx_linkset_set_named_joint_positions(opx_linkset *links,
                                                         const char *const *names,
                                                         const double *positions, size_t count,
                                                         const opx_pose *base_pose);
/** Number of active joints (see above): at most the joint count; 0 for a
 * set not made from URDF. */
OPX_API opx_status opx_linkset_get_active_joint_count(const opx_linkset *links,
                                                      uint32_t *out_count);
/** The model indices of the active joints, in model order (ascending):
 * out_joint_indices[i] is the joint (opx_linkset_get_joint_info) that value
 * i of opx_linkset_set_active_joint_positions sets.  *out_count gets the
 * active joint count; capacity below it: OPX_ERROR_BUFFER_TOO_SMALL
 * (nothing written; out_joint_indices may then be NULL). */
OPX_API opx_status opx_linkset_get_active_joints(const opx_linkset *links,
                                                 uint32_t *out_joint_indices, size_t capacity,
                                                 size_t *out_count);
/**
 * FK from the active joints: `positions` holds `count` values, one per
 * active joint in model order (opx_linkset_get_active_joints), and `count`
 * must equal the active joint count.  Mimic joints follow their leaders;
 * fixed, floating and planar joints need no value.  The link poses equal
 * those of opx_linkset_set_joint_positions with the same values at the
 * active joints' model indices.  Values, base_pose, errors and the links
 * added after loading as in opx_linkset_set_joint_positions; on error
 * nothing changes.
 */
OPX_API opx_status opx_linkset_set_active_joint_positions(opx_linkset *links,
                                                          const double *positions, size_t count,
                                                          const opx_pose *base_pose);
/** The current joint positions in model order, as FK uses them (mimic
 * joints: their computed value; fixed, floating, planar: 0).  *out_count
 * gets the joint count; capacity below it: OPX_ERROR_BUFFER_TOO_SMALL
 * (nothing written; out may then be NULL). */
OPX_API opx_status opx_linkset_get_joint_positions(const opx_linkset *links, double *out,
                                                   size_t capacity, size_t *out_count);

/** SRDF <disable_collisions> pairs as the file lists them: count, and the
 * two link indices of pair i.  Loading disables each in the link set's
 * self-collision pairs (opx_linkset_get_pair_enabled); later calls to
 * opx_linkset_set_pair_enabled change the pairs, not this list. */
OPX_API opx_status opx_linkset_get_disabled_pair_count(const opx_linkset *links,
                                                       uint32_t *out_count);
OPX_API opx_status opx_linkset_get_disabled_pair(const opx_linkset *links, uint32_t pair,
                                                 uint32_t *out_link1, uint32_t *out_link2);

/*
 * Aliases kept for compatibility: each behaves exactly as the function
 * named in its comment (its errors name the alias).  Use those names.
 */
/** Alias of opx_linkset_get_joint_count. */
OPX_API opx_status opx_linkset_joint_count(const opx_linkset *links, uint32_t *out_count);
/** Alias of opx_linkset_get_joint_info. */
OPX_API opx_status opx_linkset_joint_info(const opx_linkset *links, uint32_t joint,
                                          opx_joint_info *out);
/** Alias of opx_linkset_get_disabled_pair_count. */
OPX_API opx_status opx_linkset_disabled_pair_count(const opx_linkset *links, uint32_t *out_count);
/** Alias of opx_linkset_get_disabled_pair. */
OPX_API opx_status opx_linkset_disabled_pair(const opx_linkset *links, uint32_t pair,
                                             uint32_t *out_link1, uint32_t *out_link2);

#ifdef __cplusplus
}
#endif

#endif /* OCTOPROX_ROBOT_H */
