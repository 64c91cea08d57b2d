/*
 * opx_octree: an occupancy octree built from sensor frames (OctoMap
 * semantics: log-odds per cell, hit/miss updates, clamping).
 *
 * Cells fall in four classes by their occupancy probability p:
 *   occupied   p >= occupied_threshold             (OctoMap's rule, ">=")
 *   uncertain  free_threshold <= p < occupied_threshold
 *   free       p < free_threshold
 *   unknown    never observed (no cell in the tree)
 * With the defaults both thresholds are 0.5, so no observed cell is
 * uncertain; lower free_threshold (e.g. 0.3) to get the uncertain band of
 * the paper (section IV.C).
 *
 * All coordinates are in the map frame, in metres.  The map is a cube of
 * 2^16 cells per axis centred on the origin: +-32768 * resolution metres
 * (+-1638.4 m at 5 cm).
 */
#ifndef OCTOPROX_OCTREE_H
#define OCTOPROX_OCTREE_H

#include "common.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct opx_octree opx_octree;

/* Cell classes (see above). */
#define OPX_CELL_UNKNOWN 0
#define OPX_CELL_FREE 1
#define OPX_CELL_UNCERTAIN 2
#define OPX_CELL_OCCUPIED 3
/* Masks of classes, for opx_octree_get_leaves. */
#define OPX_MASK_FREE (1u << OPX_CELL_FREE)
#define OPX_MASK_UNCERTAIN (1u << OPX_CELL_UNCERTAIN)
#define OPX_MASK_OCCUPIED (1u << OPX_CELL_OCCUPIED)
#define OPX_MASK_ALL_KNOWN (OPX_MASK_FREE | OPX_MASK_UNCERTAIN | OPX_MASK_OCCUPIED)

/**
 * Options of a new octree.  Probabilities are in (0, 1).  Requirements:
 * 1e-6 <= resolution <= 1e6 (metres); prob_miss < 0.5 < prob_hit; clamp_min < clamp_max;
 * 0 < free_threshold <= occupied_threshold < 1.
 */
typedef struct opx_octree_options {
    uint32_t struct_size;
    uint32_t reserved0;
    double resolution;         /**< edge of a finest cell, metres; default 0.05 */
    double prob_hit;           /**< update of a cell holding an endpoint; 0.7 */
    double prob_miss;          /**< update of a cell a ray passes; 0.4 */
    double clamp_min;          /**< lower clamping bound; 0.1192 */
    double clamp_max;          /**< upper clamping bound; 0.971 */
    double occupied_threshold; /**< occupied when p >= this; 0.5 */
    double free_threshold;     /**< free when p < this; 0.5 */
} opx_octree_options;

#define OPX_OCTREE_OPTIONS_INIT \
    {sizeof(opx_octree_options), 0, 0.05, 0.7, 0.4, 0.1192, 0.971, 0.5, 0.5}
/** Fills *options with the defaults; size is sizeof *options. */
OPX_API opx_status opx_octree_options_init(opx_octree_options *options, size_t size);

/** Creates an empty octree.  options may be NULL (defaults). */
OPX_API opx_status opx_octree_create(const opx_octree_options *options, opx_octree **out);
/** Destroys the octree; NULL is a no-op. */
OPX_API void opx_octree_destroy(opx_octree *tree);
/** Removes every cell; the options stay. */
OPX_API opx_status opx_octree_clear(opx_octree *tree);
/** Copies the octree's options (resolution of a loaded map included). */
OPX_API opx_status opx_octree_get_options(const opx_octree *tree, opx_octree_options *out);

/* ---- Inserting sensor frames ------------------------------------------ */

/** Ray-cast: cells along each ray become more free, the endpoint cell more
 * occupied (OctoMap's insertPointCloud: each cell is updated once per
 * frame, an endpoint wins over a ray). */
#define OPX_INSERT_RAYCAST 0
/** Endpoints only: each endpoint cell gets one hit; no free space. */
#define OPX_INSERT_ENDPOINTS 1

typedef struct opx_insert_options {
    uint32_t struct_size;
    int32_t mode;         /**< OPX_INSERT_RAYCAST (default) or OPX_INSERT_ENDPOINTS */
    opx_pose sensor_pose; /**< the sensor frame in the map frame; identity */
    /** Points farther than this from the sensor origin (metres) are counted
     * as out of range and, as in OctoMap, give no occupied cell: in
     * ray-cast mode the ray is cut at max_range and its cells become more
     * free; in endpoint mode the point changes nothing.  <= 0 or +infinity:
     * no limit (the default, -1, OctoMap's "no limit" value); NaN is
     * invalid. */
    double max_range;
    /** Threads a ray-cast insert may use, the caller's included: 1 (the
     * default) keeps all work on the caller's thread and starts none, as
     * firmware with its own scheduling expects; 0 means one per hardware
     * thread, the choice on a workstation.  The map after an insert does
     * not depend on it. */
    uint32_t max_threads;
    uint32_t reserved0;
    /** Self-filtering (see "The robot in its own frame" below): the robot
     * at the moment the frame was captured, its link poses as last set
     * (opx_linkset_set_poses, opx_linkset_set_joint_positions...), attached
     * objects included.  The call only reads it and keeps no pointer.
     * NULL (the default): no self-filtering. */
    const struct opx_linkset *robot;
    /** Metres added to every link's own padding (the set's and the link's,
     * opx_linkset_set_padding and opx_linkset_set_link_padding) for the
     * filter only; >= 0 and finite.  Default 0. */
    double robot_padding;
    /** Nonzero: every cell lying entirely inside one of the robot's
     * unpadded solids becomes free (log-odds set to the free clamp) in the
     * same update.  Needs `robot`.  Default 0. */
    uint32_t clear_robot_volume;
    uint32_t reserved1;
    /** Nonzero: only the cells of the box [bounds_min, bounds_max] (map
     * frame; "Boxes of the map" below) change; every other cell stays as it
     * was.  Default 0 (the whole map). */
    uint32_t use_bounds;
    uint32_t reserved2;
    double bounds_min[3];
    double bounds_max[3];
} opx_insert_options;

#define OPX_INSERT_OPTIONS_INIT \
    {sizeof(opx_insert_options), OPX_INSERT_RAYCAST, OPX_POSE_IDENTITY, -1.0, 1u, 0u, NULL, 0.0, 0u, 0u, \
     0u, 0u, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}
OPX_API opx_status opx_insert_options_init(opx_insert_options *options, size_t size);

/** What one insert did.  Every point (every pixel of a depth image) is
 * counted once: used + nonfinite + out_of_range + outside_map +
 * points_on_robot + points_shadowed + pixels_no_return == count
 * (width * height for a depth image).  A point beyond max_range is
 * counted out of range even when its cut ray meets the robot. */
typedef struct opx_insert_report {
    uint32_t struct_size;
    uint32_t reserved0;
    uint64_t points_used;
    uint64_t points_nonfinite;    /**< NaN or infinite coordinates */
    uint64_t points_out_of_range; /**< beyond max_range */
    uint64_t points_outside_map;  /**< outside the octree's addressable cube */
    uint64_t cells_hit;           /**< cells updated as occupied */
    uint64_t cells_missed;        /**< cells updated as free */
    /** Depth images: pixels without a depth (0; for float32 also NaN,
     * infinite or negative), skipped.  0 for opx_octree_insert_points. */
    uint64_t pixels_no_return;
    /** Self-filtering: points inside the padded robot (no occupied cell;
     * their rays carve up to the robot). */
    uint64_t points_on_robot;
    /** Self-filtering: points behind the padded robot (their ray passes
     * through it first; no occupied cell, carve up to the robot). */
    uint64_t points_shadowed;
    /** Cells set free by clear_robot_volume (not in cells_missed). */
    uint64_t cells_cleared;
} opx_insert_report;

#define OPX_INSERT_REPORT_INIT {sizeof(opx_insert_report), 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}
OPX_API opx_status opx_insert_report_init(opx_insert_report *report, size_t size);

/*
 * The robot in its own frame (options->robot): a camera on a robot sees
 * the robot.  Each point of the frame is then one of three kinds, decided
 * in double precision on the point in the map frame and the sensor origin
 * (options->sensor_pose's position):
 *
 *   robot point: its distance to some link's solid is at most that link's
 *     padding (the set's plus its own) plus robot_padding, the distance
 *     being exact for every solid (a point on the band's edge is a robot
 *     point).  It gives no occupied cell; its ray carves free space from
 *     the sensor up to where it enters the padded robot, exactly as a ray
 *     cut at max_range does (the cells before the cut point's cell get a
 *     miss; that cell and every cell after get nothing).
 *   shadowed point: not a robot point, but its ray (the segment from the
 *     sensor origin to the point) passes through the padded robot; it gives
 *     no occupied cell and its ray carves up to where it enters the robot.
 *   kept point: every other point, inserted as without a robot, bit for bit
 *     OctoMap's semantics.  A cell holding a kept point becomes occupied
 *     even when robot points share it.
 *
 * Solids: spheres, boxes, cylinders, capsules and convex hulls exactly; a
 * closed triangle mesh (every edge shared by exactly two triangles) as the
 * solid it bounds, so points deep inside a link are robot points; an open
 * mesh as the convex hull of its vertices.  Padding is exact distance to
 * the solid, as for queries.  Disabled links filter nothing.
 *
 * The cut point: the ray is cut at a point of it from which no point
 * nearer the sensor lies in the padded robot and whose distance to the
 * padded robot is at most 1e-9 m (a ray that comes that close to it counts
 * as passing through it).  A solid whose padded volume holds the sensor
 * origin (a camera inside its own housing) shadows nothing; a point inside
 * it is still a robot point, and when no other solid cuts its ray first,
 * its ray carves nothing.  A point beyond max_range is cut at max_range
 * and then, where the cut ray meets the robot, where it enters it; it is
 * counted out of range.
 *
 * clear_robot_volume: every finest cell lying entirely inside one of the
 * unpadded solids (all of its closed cube inside the solid) is set to the
 * free clamp in the same update, so an obstacle where the arm now stands,
 * or the arm's own earlier image, does not stay.  Cells only partly inside
 * are left to the rays.  A cell already at or below the free clamp is left
 * as it is, as a miss would leave it.
 *
 * The map after the call does not depend on max_threads.  Invalid: a link
 * set whose poses were never set, a robot_padding that is negative, NaN or
 * infinite, clear_robot_volume without a robot; the map is then unchanged.
 */

/*
 * Bounded inserts (options->use_bounds): the frame is inserted as without
 * bounds (every point's ray, cut at max_range or at the robot, every
 * endpoint, each cell updated once, an endpoint winning over a ray), and
 * then only the updates of cells inside the box are applied.  So a ray
 * from outside the box still makes the cells it crosses inside the box
 * more free.  OctoMap's bounding-box insert (setBBXMin/Max, useBBXLimit)
 * differs there: it drops every point outside its box and every point
 * beyond max_range, so their rays change nothing even inside it; both
 * change no cell outside the box.  The report counts every point as
 * without bounds; cells_hit, cells_missed and cells_cleared count the
 * cells inside the box only.  bounds_min and bounds_max follow the rules
 * of "Boxes of the map" below (NaN or inverted: an invalid argument).
 */

/**
 * Inserts one sensor frame.  Successive frames accumulate log-odds.
 * points: `count` points of three coordinates (x, y, z) in the SENSOR frame,
 * each `stride` bytes after the previous (0: packed), of `scalar_type`
 * OPX_SCALAR_FLOAT32 or OPX_SCALAR_FLOAT64.  Extra fields after x, y, z
 * (intensity, rgb: a ROS PointCloud2 with point_step as stride) are ignored;
 * stride need not be a multiple of the scalar size, points are read
 * unaligned.  options may be NULL (defaults); out_report may be NULL.
 * On an invalid argument the map is unchanged.
 */
OPX_API opx_status opx_octree_insert_points(opx_octree *tree, const void *points, size_t count,
                                            size_t stride, int32_t scalar_type,
                                            const opx_insert_options *options,
                                            opx_insert_report *out_report);

/**
 * An organized depth frame, row after row, each row `width` pixels from
 * left to right.  The library reads it during the call only.
 *   OPX_SCALAR_UINT16: depth in units of 1/depth_scale metres (depth_scale
 *     is units per metre: 1000 for millimetres, as OpenNI and most ROS
 *     16UC1 images; 5000 for TUM RGB-D PNGs); 0 means no return.
 *   OPX_SCALAR_FLOAT32: depth in metres (ROS 32FC1); 0, NaN, infinite and
 *     negative values mean no return; depth_scale is not read.
 * Depth is the distance along the optical axis (z), not along the ray.
 * Pixels are native-endian and need not be aligned.
 */
typedef struct opx_depth_image {
    uint32_t struct_size;
    int32_t scalar_type;  /**< OPX_SCALAR_UINT16 (default) or OPX_SCALAR_FLOAT32 */
    const void *data;     /**< the first row; may be NULL when width or height is 0 */
    size_t width;         /**< pixels per row (columns) */
    size_t height;        /**< rows */
    size_t row_stride;    /**< bytes from a row to the next; 0: packed (width pixels) */
    double depth_scale;   /**< OPX_SCALAR_UINT16: units per metre; 1000 (millimetres) */
} opx_depth_image;

#define OPX_DEPTH_IMAGE_INIT \
    {sizeof(opx_depth_image), OPX_SCALAR_UINT16, NULL, 0, 0, 0, 1000.0}
OPX_API opx_status opx_depth_image_init(opx_depth_image *image, size_t size);

/**
 * A pinhole camera without distortion (a ROS CameraInfo's K: fx = K[0],
 * cx = K[2], fy = K[4], cy = K[5]), in pixels.  fx and fy must be positive,
 * cx and cy finite.  The defaults are all 0: set every field.
 */
typedef struct opx_camera_intrinsics {
    uint32_t struct_size;
    uint32_t reserved0;
    double fx; /**< horizontal focal length (x), pixels */
    double fy; /**< vertical focal length (y), pixels */
    double cx; /**< principal point: column (x), pixels */
    double cy; /**< principal point: row (y), pixels */
} opx_camera_intrinsics;

#define OPX_CAMERA_INTRINSICS_INIT {sizeof(opx_camera_intrinsics), 0, 0.0, 0.0, 0.0, 0.0}
OPX_API opx_status opx_camera_intrinsics_init(opx_camera_intrinsics *intrinsics, size_t size);

/**
 * Inserts one depth frame, exactly as opx_octree_insert_points inserts the
 * points it back-projects (same options, same report).
 *
 * The sensor frame is the camera's optical frame: z forward along the
 * optical axis, x right, y down (a ROS camera's *_optical_frame, the frame
 * of its PointCloud2 clouds).  The pixel in column u and row v (0-based,
 * pixel centres at integer coordinates, as PCL and ROS depth_image_proc
 * count) with depth z metres becomes the point
 *     ((u - cx) * z / fx, (v - cy) * z / fy, z)
 * in that frame, rounded to float32 (the call holds these points, 12 bytes
 * a pixel, while it runs).  options->sensor_pose places the optical frame
 * in the map frame; options->max_range is the distance from the camera's
 * centre along the ray, not the depth.
 *
 * Pixels without a return are skipped and counted in pixels_no_return;
 * every other pixel is counted as a point (a point too large for float32
 * in points_nonfinite).  image and intrinsics must not be NULL; options
 * may be NULL (defaults); out_report may be NULL.  An empty image (width
 * or height 0) changes nothing.  `image->data` must hold `height` rows of
 * `row_stride` bytes (the last one `width` pixels).  On an invalid
 * argument the map is unchanged; on OPX_ERROR_OUT_OF_MEMORY too.
 */
OPX_API opx_status opx_octree_insert_depth_image(opx_octree *tree, const opx_depth_image *image,
                                                 const opx_camera_intrinsics *intrinsics,
                                                 const opx_insert_options *options,
                                                 opx_insert_report *out_report);

/* ---- Changing regions of the map ---------------------------------------- */

/*
 * Boxes of the map: a box is given by its min and max corners in the map
 * frame (metres), min <= max on every axis; either may be infinite (no
 * limit on that side) and reach beyond the map's cube.  It covers the
 * finest cells holding a point of the closed box: on each axis, from the
 * cell holding min to the cell holding max, each found as
 * opx_octree_classify finds a point's cell (OctoMap's coordToKey: a point
 * on the face between two cells lies in the upper one).  So at 0.1 m the
 * box from 0.2 to 0.5 on an axis covers the cells [0.2, 0.3) to
 * [0.5, 0.6): the cell above the upper face too, as OctoMap's bounding
 * box does; use 0.5 - 1e-9 to stop below it.  A pruned leaf the box cuts
 * through is split along the box's faces; cells wholly inside or outside
 * change as one.  A NaN corner or min > max on an axis is an invalid
 * argument naming box_min or box_max, and the map is unchanged.
 *
 * "to" of the clearing calls: OPX_CELL_FREE sets every covered cell, known
 * or unknown, to the free clamp (clamp_min's log-odds, as
 * clear_robot_volume does), or OPX_CELL_UNKNOWN removes it from the map
 * (unknown space; a node whose cells are all removed goes too).  Cost:
 * the cubes along the region's surface.  Cleared to free, unknown space
 * there gets new nodes, about one per surface cell (a box of 2 m at 2 cm:
 * some 10^5), so a box cleared to free must be finite, and a region as
 * large as the map is cleared to unknown.  A cleared
 * cell loses its point extent.  The map is left as OctoMap would leave it
 * after updating each cell alone: nodes of eight equal leaves pruned,
 * inner nodes holding the max of their children.  On
 * OPX_ERROR_OUT_OF_MEMORY the map is unchanged.
 */

/** Clears every cell of the box [box_min, box_max] (map frame) to `to`:
 * OPX_CELL_FREE or OPX_CELL_UNKNOWN (see above).  Use it when a grasped
 * object leaves the scene (to OPX_CELL_UNKNOWN, or to OPX_CELL_FREE when
 * the space it held is known to be empty). */
OPX_API opx_status opx_octree_clear_region(opx_octree *tree, const double box_min[3],
                                           const double box_max[3], int32_t to);

/**
 * Clears the cells occupied by an object to `to` (OPX_CELL_FREE or
 * OPX_CELL_UNKNOWN, see above): `shape_count` shapes (opx_shape,
 * linkset.h, as opx_linkset_attach_object takes them: each at its pose in
 * the object frame, shapes[i].pose, sizes as for links), the object frame
 * at `pose` in the map frame (x y z qx qy qz qw; NULL: identity) -- a
 * world object's shapes at its pose (opx_world_get_shape,
 * opx_world_get_object_pose), or an attached object's shapes at its link's
 * pose composed with its pose on the link.  A finest cell is cleared when
 * one of the shapes touches its cube, decided exactly as a collision query
 * decides that an unpadded link shape touches a cell (touching counts,
 * within 1e-9 m; a mesh is its surface); so afterwards, cleared to
 * unknown, the shapes collide with no cell of the map.  Use it when an
 * object is added to the world, whose sensed image would count it twice.
 * shape_count 0 changes nothing.  An invalid shape names shapes[i].
 */
struct opx_shape; /* linkset.h */
OPX_API opx_status opx_octree_clear_shapes(opx_octree *tree, const struct opx_shape *shapes,
                                           size_t shape_count, const opx_pose *pose, int32_t to);

/**
 * Forgets a little of what the map holds: every known cell's log-odds v
 * moves toward 0 by `amount` (log-odds units, >= 0): v - amount when v is
 * positive, v + amount when negative, computed in double and rounded to
 * the stored float, never across 0.  A cell whose log-odds reaches 0 (or
 * holds 0) becomes unknown and its node is removed, a node whose cells
 * all go with it; nodes left are pruned and hold the max of their children
 * as after an insert.  A cell that ends below the occupied threshold loses
 * its point extent.  amount 0 changes nothing; +infinity removes every
 * cell.  Called once per frame, an obstacle that left the view fades: an
 * occupied cell at clamp_max takes logodds(clamp_max) / amount calls to
 * go.  NaN or a negative amount is an invalid argument; the map is then
 * unchanged.  Allocates nothing.
 */
OPX_API opx_status opx_octree_decay(opx_octree *tree, double amount);

/**
 * Removes every cell outside the box [box_min, box_max] (map frame; "Boxes
 * of the map" above): the cells the box covers stay as they are.  A mobile
 * base keeps a window around itself this way.  The memory of the removed
 * nodes is given back to the heap (the nodes left are moved together)
 * when more than a quarter of the map's node memory (and more than
 * 64 KiB) is then idle, so
 * opx_octree_get_stats' memory_bytes follows the cells kept.  On
 * OPX_ERROR_OUT_OF_MEMORY the map is unchanged.
 */
OPX_API opx_status opx_octree_crop(opx_octree *tree, const double box_min[3], const double box_max[3]);

/* ---- Reading the map --------------------------------------------------- */

/** The cell holding a point (map frame). */
typedef struct opx_cell_info {
    uint32_t struct_size;
    int32_t cell_class;  /**< OPX_CELL_* */
    double probability;  /**< occupancy probability; 0.5 (the prior) when unknown */
    double center[3];    /**< centre of the cell, map frame, metres */
    double size;         /**< edge of the cell, metres.  For unknown space:
                          * the largest unobserved cube holding the point */
    uint32_t depth;      /**< 0 (root cube) .. 16 (finest cells) */
    uint32_t reserved0;
} opx_cell_info;

#define OPX_CELL_INFO_INIT {sizeof(opx_cell_info), 0, 0.0, {0.0, 0.0, 0.0}, 0.0, 0, 0}
OPX_API opx_status opx_cell_info_init(opx_cell_info *info, size_t size);

/** Classifies the point (x, y, z, map frame).  A point outside the
 * addressable cube is an invalid argument.  out->struct_size must be set. */
OPX_API opx_status opx_octree_classify(const opx_octree *tree, const double point[3],
                                       opx_cell_info *out);

typedef struct opx_octree_stats {
    uint32_t struct_size;
    int32_t has_occupied; /**< 1 when occupied_min/max are set, else 0 */
    double resolution;    /**< metres */
    uint64_t leaves_occupied;
    uint64_t leaves_uncertain;
    uint64_t leaves_free;
    uint64_t inner_nodes;  /**< nodes with children, the root included */
    uint64_t memory_bytes; /**< bytes the tree holds: nodes, in blocks of 8 children (free blocks too) */
    /** Tight bounds of the occupied cells' boxes (not the root cube), map
     * frame; zeros when has_occupied is 0. */
    double occupied_min[3];
    double occupied_max[3];
    /** Tight bounds of all observed cells' boxes; zeros when the map is empty. */
    double known_min[3];
    double known_max[3];
    /** Occupied leaves that keep the box of their sensed points
     * (OPX_OBSTACLE_POINT_EXTENTS); the others are whole cubes. */
    uint64_t leaves_with_extent;
} opx_octree_stats;

#define OPX_OCTREE_STATS_INIT {sizeof(opx_octree_stats), 0, 0.0, 0, 0, 0, 0, 0, \
    {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0}
OPX_API opx_status opx_octree_stats_init(opx_octree_stats *stats, size_t size);

/** Counts, bounds and memory of the map (one pass over the leaves). */
OPX_API opx_status opx_octree_get_stats(const opx_octree *tree, opx_octree_stats *out);

/** One leaf of the map: the paper's "collision map" entry.  A fixed layout
 * (never extended; a richer leaf would get a new type and function). */
typedef struct opx_leaf {
    double center[3];   /**< map frame, metres */
    double size;        /**< edge, metres */
    double probability; /**< occupancy probability */
    int32_t cell_class; /**< OPX_CELL_* */
    uint32_t depth;     /**< 0 .. 16 */
} opx_leaf;

/**
 * Copies the leaves whose class is in class_mask (OPX_MASK_*) into
 * out_leaves, in depth-first order.  *out_count gets the number of such
 * leaves.  When it exceeds capacity, the first `capacity` are written and
 * OPX_ERROR_BUFFER_TOO_SMALL is returned: call again with a buffer of
 * *out_count leaves (out_leaves may be NULL when capacity is 0).
 */
OPX_API opx_status opx_octree_get_leaves(const opx_octree *tree, uint32_t class_mask,
                                         opx_leaf *out_leaves, size_t capacity,
                                         size_t *out_count);

/* ---- Files and messages ----------------------------------------------- */

/** Loading: OPX_FORMAT_AUTO reads the header.  Saving: AUTO picks by the
 * path's extension (.bt, .ot or .opx); for memory it means BT. */
#define OPX_FORMAT_AUTO 0
/** OctoMap binary (.bt): per leaf only occupied/free; a loaded leaf gets
 * the clamping bound of its class as probability. */
#define OPX_FORMAT_BT 1
/** OctoMap full (.ot, type "OcTree"): the log-odds of every node. */
#define OPX_FORMAT_OT 2
/** OctoProx map (.opx): the .ot content and every occupied leaf's point
 * extent (OPX_OBSTACLE_POINT_EXTENTS), which .bt and .ot cannot hold.  The
 * layout is in docs/geometry.md. */
#define OPX_FORMAT_OPX 3

/**
 * Loads a .bt or .ot file (OctoMap 1.x, type OcTree) or an OctoProx .opx
 * map (the same with point extents).  The resolution comes
 * from the file; the other fields of options (may be NULL: defaults) set the
 * probabilities and thresholds.  Corrupt or truncated data gives
 * OPX_ERROR_CORRUPT and no handle (*out = NULL).  The header is read and
 * checked first, and the file no further than its node count allows: a
 * longer file, a device or pipe that does not end (/dev/zero), or one
 * whose header gives no node count is OPX_ERROR_CORRUPT.
 */
OPX_API opx_status opx_octree_load_file(const char *path, const opx_octree_options *options,
                                        opx_octree **out);
/** The same from the bytes of such a file held in memory. */
OPX_API opx_status opx_octree_load_memory(const void *data, size_t size,
                                          const opx_octree_options *options, opx_octree **out);
/**
 * Loads the `data` field of a ROS octomap_msgs/Octomap message: `binary`
 * nonzero for a binary map (.bt body), zero for a full map (.ot body).  The
 * caller checks the message's `id`: only "OcTree" maps are read correctly.
 * resolution is the message's, in metres (1e-6 to 1e6).
 */
OPX_API opx_status opx_octree_load_message(const void *data, size_t size, int32_t binary,
                                           double resolution, const opx_octree_options *options,
                                           opx_octree **out);

/**
 * Saves to a file; format OPX_FORMAT_AUTO (by the path's extension), _BT,
 * _OT or _OPX.  The map is written to a new temporary file beside path
 * (an unpredictable name, created exclusively, never through a link),
 * synced and renamed over path, so path holds the old map or the whole
 * new one, and saves of one path running at once leave the last one
 * renamed.  A path that is a link replaces the file it points to; one
 * that is no regular file (a device, a FIFO) is written directly.  On
 * failure (OPX_ERROR_IO) the temporary is removed and path is untouched.
 */
OPX_API opx_status opx_octree_save_file(const opx_octree *tree, const char *path,
                                        int32_t format);
/**
 * Saves the bytes of a .bt/.ot file into buffer.  *out_size gets the size
 * needed; OPX_ERROR_BUFFER_TOO_SMALL when it exceeds capacity (nothing
 * written; buffer may be NULL when capacity is 0).
 */
OPX_API opx_status opx_octree_save_memory(const opx_octree *tree, int32_t format, void *buffer,
                                          size_t capacity, size_t *out_size);

#ifdef __cplusplus
}
#endif

#endif /* OCTOPROX_OCTREE_H */
