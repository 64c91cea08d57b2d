/* Operations of the call-sequence fuzzer on octrees: see fuzz_api.h. */
#include "fuzz_api.h"
#include "fuzz_tree.h"

#include <stdlib.h>

/* Options with every field fuzzed, resolutions from 0 and denormals to
 * huge and negative ones included. */
static void take_octree_options(fuzz_input *in, opx_octree_options *options) {
    options->struct_size = take_struct_size(in, sizeof *options);
    const uint8_t fuzzed = take_u8(in); /* which fields change */
    if (fuzzed & 1) {
        static const double resolutions[] = {0.05, 0.1, 1.0, 1e-6, 1e6, 0.0, -0.05, 9e-7, 1.1e6};
        options->resolution = take_bool(in) ? resolutions[take_below(in, 9)] : take_double(in);
    }
    if (fuzzed & 2) options->prob_hit = take_fraction(in);
    if (fuzzed & 4) options->prob_miss = take_fraction(in);
    if (fuzzed & 8) options->clamp_min = take_fraction(in);
    if (fuzzed & 16) options->clamp_max = take_fraction(in);
    if (fuzzed & 32) options->occupied_threshold = take_fraction(in);
    if (fuzzed & 64) options->free_threshold = take_fraction(in);
}

void op_octree_create(fuzz_api *api) {
    const size_t slot = take_slot(api);
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    take_octree_options(&api->in, &options);
    opx_octree *tree = NULL;
    const opx_status status = FUZZ_CALL(opx_octree_create, take_bool(&api->in) ? &options : NULL, &tree);
    FUZZ_REQUIRE((status == OPX_OK) == (tree != NULL));
    if (tree == NULL) return;
    opx_octree_destroy(api->trees[slot]);
    api->trees[slot] = tree;
}

void op_octree_destroy(fuzz_api *api) {
    const size_t slot = take_slot(api);
    opx_octree_destroy(api->trees[slot]);
    api->trees[slot] = NULL;
}

static double resolution_of(const opx_octree *tree) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    if (tree == NULL || opx_octree_get_options(tree, &options) != OPX_OK) return 0.05;
    return options.resolution;
}

static void take_insert_options(fuzz_input *in, opx_insert_options *options, double resolution) {
    options->struct_size = take_struct_size(in, sizeof *options);
    const uint8_t mode = take_u8(in);
    options->mode = mode < 120 ? OPX_INSERT_RAYCAST : mode < 240 ? OPX_INSERT_ENDPOINTS : (int32_t)take_u32(in);
    take_pose(in, &options->sensor_pose);
    options->max_range = take_double(in);
    /* Rays are walked cell by cell: a long one at a fine resolution would
     * take seconds.  NaN stays (an invalid argument). */
    const double longest = FUZZ_MAX_RAY_CELLS * resolution;
    if (options->mode != OPX_INSERT_ENDPOINTS && !(options->max_range > 0.0 && options->max_range <= longest) &&
        !isnan(options->max_range))
        options->max_range = longest;
}

/* Self-filtering: a robot from a slot (maybe NULL, maybe never posed),
 * paddings from sensible to NaN and negative, clearing with or without it. */
static void take_robot_options(fuzz_api *api, opx_insert_options *options) {
    fuzz_input *in = &api->in;
    const uint8_t fuzzed = take_u8(in);
    if (fuzzed & 1) options->robot = take_linkset(api);
    if (fuzzed & 2) {
        static const double paddings[] = {0.0, 0.02, 0.5, -0.01, 1e6};
        options->robot_padding = take_bool(in) ? paddings[take_below(in, 5)] : take_double(in);
    }
    if (fuzzed & 4) options->clear_robot_volume = take_bool(in) ? 1u : take_u32(in);
}

/* Fills count points of `scalar` (4 or 8 bytes) `step` bytes apart. */
static void fill_points(fuzz_input *in, unsigned char *points, size_t count, size_t step, size_t scalar) {
    for (size_t i = 0; i < count; ++i) {
        for (size_t axis = 0; axis < 3; ++axis) {
            const double value = take_u8(in) < 200 ? (double)(int8_t)take_u8(in) / 20.0 : take_double(in);
            unsigned char *at = points + i * step + axis * scalar;
            if (scalar == 4) {
                const float narrow = (float)(isfinite(value) && fabs(value) > 3e38 ? 3e38 : value);
                memcpy(at, &narrow, 4);
            } else {
                memcpy(at, &value, 8);
            }
        }
    }
}

void op_octree_insert(fuzz_api *api) {
    fuzz_input *in = &api->in;
    opx_octree *tree = take_tree(api);
    const size_t count = take_below(in, FUZZ_MAX_POINTS + 1);
    const uint8_t type = take_u8(in);
    const int32_t scalar_type = type < 120 ? OPX_SCALAR_FLOAT32 : type < 240 ? OPX_SCALAR_FLOAT64 : (int32_t)type;
    const size_t scalar = scalar_type == OPX_SCALAR_FLOAT32 ? 4 : 8;
    const size_t stride = take_stride(in, 3 * scalar);
    const size_t step = stride == 0 ? 3 * scalar : stride;
    /* Enough for the layout the API documents, whatever the stride. */
    unsigned char *points = calloc((count + 1) * (step + 3 * scalar), 1);
    FUZZ_REQUIRE(points != NULL);
    if (step >= 3 * scalar) fill_points(in, points, count, step, scalar);
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    take_insert_options(in, &options, resolution_of(tree));
    take_robot_options(api, &options);
    opx_insert_report report = OPX_INSERT_REPORT_INIT;
    const uint8_t nulls = take_u8(in) < 200 ? 0 : take_u8(in); /* NULLs, a wrong count */
    const opx_status status =
        FUZZ_CALL(opx_octree_insert_points, tree, (nulls & 1) ? NULL : points, (nulls & 2) ? count + 1 : count,
                  stride, scalar_type, (nulls & 4) ? NULL : &options, (nulls & 8) ? NULL : &report);
    if (status == OPX_OK && !(nulls & 8))
        FUZZ_REQUIRE(report.points_used + report.points_nonfinite + report.points_out_of_range +
                         report.points_outside_map + report.points_on_robot + report.points_shadowed ==
                     ((nulls & 2) ? count + 1 : count));
    free(points);
}

void op_octree_clear(fuzz_api *api) { FUZZ_CALL(opx_octree_clear, take_tree(api)); }

void op_octree_read(fuzz_api *api) {
    fuzz_input *in = &api->in;
    const opx_octree *tree = take_tree(api);
    opx_cell_info info = OPX_CELL_INFO_INIT;
    info.struct_size = take_struct_size(in, sizeof info);
    double point[3];
    for (int axis = 0; axis < 3; ++axis) point[axis] = take_double(in);
    FUZZ_CALL(opx_octree_classify, tree, take_bool(in) ? point : NULL, &info);
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    stats.struct_size = take_struct_size(in, sizeof stats);
    FUZZ_CALL(opx_octree_get_stats, tree, &stats);
    opx_leaf leaves[8];
    size_t count = 0;
    const uint32_t mask = take_bool(in) ? take_u32(in) : OPX_MASK_ALL_KNOWN;
    FUZZ_CALL(opx_octree_get_leaves, tree, mask, leaves, take_below(in, 9), &count);
    opx_octree_options options;
    options.struct_size = take_struct_size(in, sizeof options);
    FUZZ_CALL(opx_octree_get_options, tree, &options);
}

/* Saves a map in memory (maybe with a short buffer) and loads the image,
 * as a file image or as a message body, into a slot. */
void op_octree_image(fuzz_api *api) {
    fuzz_input *in = &api->in;
    const opx_octree *tree = take_tree(api);
    const int32_t format = (int32_t)take_below(in, 4); /* 3 is no format */
    size_t size = 0;
    opx_status status = FUZZ_CALL(opx_octree_save_memory, tree, format, NULL, 0, &size);
    if (status != OPX_OK && status != OPX_ERROR_BUFFER_TOO_SMALL) return;
    unsigned char *image = malloc(size + 1);
    FUZZ_REQUIRE(image != NULL);
    image[size] = '\0'; /* for strstr below */
    const size_t capacity = take_bool(in) ? size : take_below(in, size + 1);
    size_t written = 0;
    status = FUZZ_CALL(opx_octree_save_memory, tree, format, image, capacity, &written);
    FUZZ_REQUIRE(written == size && (status == OPX_OK) == (capacity >= size));
    opx_octree *copy = NULL;
    if (status == OPX_OK && take_bool(in)) {
        FUZZ_REQUIRE(FUZZ_CALL(opx_octree_load_memory, image, size, NULL, &copy) == OPX_OK);
    } else if (status == OPX_OK) {
        /* A message body is the file image without its text header. */
        const char *body = strstr((const char *)image, "\ndata\n");
        const double resolution = take_bool(in) ? resolution_of(tree) : take_double(in);
        if (body != NULL)
            FUZZ_CALL(opx_octree_load_message, body + 6, size - (size_t)(body + 6 - (const char *)image),
                      format != OPX_FORMAT_OT, resolution, NULL, &copy);
    }
    free(image);
    if (copy == NULL) return;
    const size_t slot = take_slot(api);
    opx_octree_destroy(api->trees[slot]);
    api->trees[slot] = copy;
}

void op_octree_exercise(fuzz_api *api) {
    const opx_octree *tree = take_tree(api);
    if (tree != NULL) fuzz_exercise_tree(tree);
}

/* A box corner: mostly a whole number of cells within the rays' reach
 * (so that an edit's surface stays small at any resolution), sometimes
 * any double (NaN and infinities included). */
static void take_corner(fuzz_input *in, double resolution, double corner[3]) {
    for (int axis = 0; axis < 3; ++axis)
        corner[axis] = take_u8(in) < 230 ? ((double)(int8_t)take_u8(in) / 5.0) * resolution : take_double(in);
}

/* A few small shapes (sizes and offsets within a few cells). */
static size_t take_edit_shapes(fuzz_input *in, double resolution, opx_shape shapes[3]) {
    const size_t count = take_below(in, 4);
    for (size_t i = 0; i < count; ++i) {
        opx_shape *shape = &shapes[i];
        *shape = (opx_shape)OPX_SHAPE_INIT;
        shape->struct_size = take_struct_size(in, sizeof *shape);
        shape->kind = (int32_t)take_below(in, 8); /* 0 and 7 are no kind; 5 and 6 need vertices */
        const double size = take_u8(in) < 240 ? (double)take_u8(in) / 32.0 * resolution : take_double(in);
        shape->radius = size;
        shape->length = 2.0 * size;
        for (int axis = 0; axis < 3; ++axis) {
            shape->size[axis] = size * (1 + axis);
            shape->pose.position[axis] = (double)(int8_t)take_u8(in) / 16.0 * resolution;
        }
    }
    return count;
}

/* Clearing a box or shapes, decay, cropping, or an insert with bounds. */
void op_octree_edit(fuzz_api *api) {
    fuzz_input *in = &api->in;
    opx_octree *tree = take_tree(api);
    const double resolution = resolution_of(tree);
    double lo[3], hi[3];
    take_corner(in, resolution, lo);
    take_corner(in, resolution, hi);
    const uint8_t targets[4] = {OPX_CELL_FREE, OPX_CELL_UNKNOWN, OPX_CELL_OCCUPIED, 9};
    const int32_t to = targets[take_below(in, 4)];
    const uint8_t nulls = take_u8(in) < 220 ? 0 : take_u8(in);
    /* Cleared to free, unknown space along the region's surface gets a
     * node per cell (octree.h): far corners would take the run's memory
     * and time.  They go NaN there (still an invalid argument). */
    for (int axis = 0; to == OPX_CELL_FREE && axis < 3; ++axis) {
        if (!(fabs(lo[axis]) <= 64.0 * resolution)) lo[axis] = NAN;
        if (!(fabs(hi[axis]) <= 64.0 * resolution)) hi[axis] = NAN;
    }
    switch (take_below(in, 5)) {
    case 0:
        FUZZ_CALL(opx_octree_clear_region, tree, (nulls & 1) ? NULL : lo, (nulls & 2) ? NULL : hi, to);
        break;
    case 1: {
        opx_shape shapes[3];
        const size_t count = take_edit_shapes(in, resolution, shapes);
        for (size_t i = 0; to == OPX_CELL_FREE && i < count; ++i)
            if (!(shapes[i].radius <= 8.0 * resolution)) shapes[i].radius = shapes[i].length = shapes[i].size[0] = -1.0;
        opx_pose pose;
        take_pose(in, &pose);
        for (int axis = 0; axis < 3; ++axis) pose.position[axis] = lo[axis];
        FUZZ_CALL(opx_octree_clear_shapes, tree, (nulls & 1) ? NULL : shapes, count, (nulls & 2) ? NULL : &pose,
                  to);
        break;
    }
    case 2: {
        static const double amounts[] = {0.0, 0.1, 0.4, 2.0, -0.1, INFINITY};
        FUZZ_CALL(opx_octree_decay, tree, take_bool(in) ? amounts[take_below(in, 6)] : take_double(in));
        break;
    }
    case 3:
        FUZZ_CALL(opx_octree_crop, tree, (nulls & 1) ? NULL : lo, (nulls & 2) ? NULL : hi);
        break;
    default: {
        double xyz[12];
        for (int i = 0; i < 12; ++i) xyz[i] = (double)(int8_t)take_u8(in) / 8.0 * resolution;
        opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
        take_insert_options(in, &options, resolution);
        options.use_bounds = take_bool(in) ? 1u : take_u32(in);
        for (int axis = 0; axis < 3; ++axis) {
            options.bounds_min[axis] = lo[axis];
            options.bounds_max[axis] = hi[axis];
        }
        FUZZ_CALL(opx_octree_insert_points, tree, xyz, 4, 0, OPX_SCALAR_FLOAT64, &options, NULL);
        break;
    }
    }
}
