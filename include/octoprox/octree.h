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

/*
 * Options of a new octree.  Probabilities are in (0, 1).  Requirements:
 * 1e-6 <= resolution <= 1e6 (metres); prob_miss < 0.5 < prob_hit; clamp_min < clamp_max;
 * 0 < free_threshold <= occupied_threshold < 1.
 */
typedef struct opx_octree_options {
    uint32_t struct_size;
    uint32_t reserved0;
    double resolution;         /* edge of a finest cell, metres; default 0.05 */
    double prob_hit;           /* update of a cell holding an endpoint; 0.7 */
    double prob_miss;          /* update of a cell a ray passes; 0.4 */
    double clamp_min;          /* lower clamping bound; 0.1192 */
    double clamp_max;          /* upper clamping bound; 0.971 */
    double occupied_threshold; /* occupied when p >= this; 0.5 */
    double free_threshold;     /* free when p < this; 0.5 */
} opx_octree_options;

#define OPX_OCTREE_OPTIONS_INIT \
    {sizeof(opx_octree_options), 0, 0.05, 0.7, 0.4, 0.1192, 0.971, 0.5, 0.5}
/* Fills *options with the defaults; size is sizeof *options. */
OPX_API opx_status opx_octree_options_init(opx_octree_options *options, size_t size);

/* Creates an empty octree.  options may be NULL (defaults). */
OPX_API opx_status opx_octree_create(const opx_octree_options *options, opx_octree **out);
/* Destroys the octree; NULL is a no-op. */
OPX_API void opx_octree_destroy(opx_octree *tree);
/* Removes every cell; the options stay. */
OPX_API opx_status opx_octree_clear(opx_octree *tree);
/* Copies the octree's options (resolution of a loaded map included). */
OPX_API opx_status opx_octree_get_options(const opx_octree *tree, opx_octree_options *out);

/* ---- Inserting sensor frames ------------------------------------------ */

/* Ray-cast: cells along each ray become more free, the endpoint cell more
 * occupied (OctoMap's insertPointCloud: each cell is updated once per
 * frame, an endpoint wins over a ray). */
#define OPX_INSERT_RAYCAST 0
/* Endpoints only: each endpoint cell gets one hit; no free space. */
#define OPX_INSERT_ENDPOINTS 1

typedef struct opx_insert_options {
    uint32_t struct_size;
    int32_t mode;         /* OPX_INSERT_RAYCAST (default) or OPX_INSERT_ENDPOINTS */
    opx_pose sensor_pose; /* the sensor frame in the map frame; identity */
    /* Points farther than this from the sensor origin (metres) are skipped
     * and counted.  Unlike OctoMap, which clears free space along a
     * truncated ray, a skipped point changes nothing.  <= 0 or +infinity: no
     * limit (the default, -1, OctoMap's "no limit" value); NaN is invalid. */
    double max_range;
} opx_insert_options;

#define OPX_INSERT_OPTIONS_INIT \
    {sizeof(opx_insert_options), OPX_INSERT_RAYCAST, OPX_POSE_IDENTITY, -1.0}
OPX_API opx_status opx_insert_options_init(opx_insert_options *options, size_t size);

/* What one insert did.  Every point is counted once: used + nonfinite +
 * out_of_range + outside_map == count. */
typedef struct opx_insert_report {
    uint32_t struct_size;
    uint32_t reserved0;
    uint64_t points_used;
    uint64_t points_nonfinite;    /* NaN or infinite coordinates */
    uint64_t points_out_of_range; /* beyond max_range */
    uint64_t points_outside_map;  /* outside the octree's addressable cube */
    uint64_t cells_hit;           /* cells updated as occupied */
    uint64_t cells_missed;        /* cells updated as free */
} opx_insert_report;

#define OPX_INSERT_REPORT_INIT {sizeof(opx_insert_report), 0, 0, 0, 0, 0, 0, 0}
OPX_API opx_status opx_insert_report_init(opx_insert_report *report, size_t size);

/*
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

/* ---- Reading the map --------------------------------------------------- */

/* The cell holding a point (map frame). */
typedef struct opx_cell_info {
    uint32_t struct_size;
    int32_t cell_class;  /* OPX_CELL_* */
    double probability;  /* occupancy probability; 0.5 (the prior) when unknown */
    double center[3];    /* centre of the cell, map frame, metres */
    double size;         /* edge of the cell, metres.  For unknown space:
                          * the largest unobserved cube holding the point */
    uint32_t depth;      /* 0 (root cube) .. 16 (finest cells) */
    uint32_t reserved0;
} opx_cell_info;

#define OPX_CELL_INFO_INIT {sizeof(opx_cell_info), 0, 0.0, {0.0, 0.0, 0.0}, 0.0, 0, 0}
OPX_API opx_status opx_cell_info_init(opx_cell_info *info, size_t size);

/* Classifies the point (x, y, z, map frame).  A point outside the
 * addressable cube is an invalid argument.  out->struct_size must be set. */
OPX_API opx_status opx_octree_classify(const opx_octree *tree, const double point[3],
                                       opx_cell_info *out);

typedef struct opx_octree_stats {
    uint32_t struct_size;
    int32_t has_occupied; /* 1 when occupied_min/max are set, else 0 */
    double resolution;    /* metres */
    uint64_t leaves_occupied;
    uint64_t leaves_uncertain;
    uint64_t leaves_free;
    uint64_t inner_nodes;  /* nodes with children, the root included */
    uint64_t memory_bytes; /* bytes the tree holds: nodes, in blocks of 8 children (free blocks too) */
    /* Tight bounds of the occupied cells' boxes (not the root cube), map
     * frame; zeros when has_occupied is 0. */
    double occupied_min[3];
    double occupied_max[3];
    /* Tight bounds of all observed cells' boxes; zeros when the map is empty. */
    double known_min[3];
    double known_max[3];
} opx_octree_stats;

#define OPX_OCTREE_STATS_INIT {sizeof(opx_octree_stats), 0, 0.0, 0, 0, 0, 0, 0, \
    {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}
OPX_API opx_status opx_octree_stats_init(opx_octree_stats *stats, size_t size);

/* Counts, bounds and memory of the map (one pass over the leaves). */
OPX_API opx_status opx_octree_get_stats(const opx_octree *tree, opx_octree_stats *out);

/* One leaf of the map: the paper's "collision map" entry.  A fixed layout
 * (never extended; a richer leaf would get a new type and function). */
typedef struct opx_leaf {
    double center[3];   /* map frame, metres */
    double size;        /* edge, metres */
    double probability; /* occupancy probability */
    int32_t cell_class; /* OPX_CELL_* */
    uint32_t depth;     /* 0 .. 16 */
} opx_leaf;

/*
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

/* Loading: OPX_FORMAT_AUTO reads the header.  Saving: AUTO picks by the
 * path's extension (.bt or .ot); for memory it means BT. */
#define OPX_FORMAT_AUTO 0
/* OctoMap binary (.bt): per leaf only occupied/free; a loaded leaf gets
 * the clamping bound of its class as probability. */
#define OPX_FORMAT_BT 1
/* OctoMap full (.ot, type "OcTree"): the log-odds of every node. */
#define OPX_FORMAT_OT 2

/*
 * Loads a .bt or .ot file (OctoMap 1.x, type OcTree).  The resolution comes
 * from the file; the other fields of options (may be NULL: defaults) set the
 * probabilities and thresholds.  Corrupt or truncated data gives
 * OPX_ERROR_CORRUPT and no handle (*out = NULL).
 */
OPX_API opx_status opx_octree_load_file(const char *path, const opx_octree_options *options,
                                        opx_octree **out);
/* The same from the bytes of such a file held in memory. */
OPX_API opx_status opx_octree_load_memory(const void *data, size_t size,
                                          const opx_octree_options *options, opx_octree **out);
/*
 * Loads the `data` field of a ROS octomap_msgs/Octomap message: `binary`
 * nonzero for a binary map (.bt body), zero for a full map (.ot body).  The
 * caller checks the message's `id`: only "OcTree" maps are read correctly.
 * resolution is the message's, in metres (1e-6 to 1e6).
 */
OPX_API opx_status opx_octree_load_message(const void *data, size_t size, int32_t binary,
                                           double resolution, const opx_octree_options *options,
                                           opx_octree **out);

/* Saves to a file; format OPX_FORMAT_AUTO, _BT or _OT. */
OPX_API opx_status opx_octree_save_file(const opx_octree *tree, const char *path,
                                        int32_t format);
/*
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
