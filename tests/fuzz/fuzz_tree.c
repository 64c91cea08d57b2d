/* Reads and checks of a map made by a fuzz input: see fuzz_tree.h. */
#include "fuzz_tree.h"

#include "fuzz_check.h"

#include <math.h>
#include <stdlib.h>

/* Leaves read back and classified at most; maps of fuzz inputs are small. */
#define FUZZ_MAX_LEAVES 65536
#define FUZZ_CLASSIFIED_LEAVES 16

static void check_leaves_against_stats(const opx_octree *tree, const opx_octree_stats *stats) {
    size_t count = 0;
    const opx_status status = FUZZ_CALL(opx_octree_get_leaves, tree, OPX_MASK_ALL_KNOWN, NULL, 0, &count);
    FUZZ_REQUIRE(status == OPX_OK || status == OPX_ERROR_BUFFER_TOO_SMALL);
    FUZZ_REQUIRE(count == stats->leaves_occupied + stats->leaves_uncertain + stats->leaves_free);
    if (count == 0 || count > FUZZ_MAX_LEAVES) return;
    opx_leaf *leaves = malloc(count * sizeof *leaves);
    FUZZ_REQUIRE(leaves != NULL);
    size_t written = 0;
    FUZZ_REQUIRE(FUZZ_CALL(opx_octree_get_leaves, tree, OPX_MASK_ALL_KNOWN, leaves, count, &written) == OPX_OK);
    FUZZ_REQUIRE(written == count);
    for (size_t i = 0; i < count && i < FUZZ_CLASSIFIED_LEAVES; ++i) {
        opx_cell_info info = OPX_CELL_INFO_INIT;
        FUZZ_REQUIRE(leaves[i].cell_class >= OPX_CELL_FREE && leaves[i].cell_class <= OPX_CELL_OCCUPIED);
        if (FUZZ_CALL(opx_octree_classify, tree, leaves[i].center, &info) != OPX_OK) continue;
        FUZZ_REQUIRE(info.cell_class == leaves[i].cell_class);
        FUZZ_REQUIRE(info.depth == leaves[i].depth);
    }
    free(leaves);
}

/* Saves in `format` and loads the image back with the map's own options;
 * returns the copy or NULL. */
static opx_octree *save_and_reload(const opx_octree *tree, int32_t format,
                                   const opx_octree_options *options) {
    size_t size = 0;
    opx_status status = FUZZ_CALL(opx_octree_save_memory, tree, format, NULL, 0, &size);
    if (status != OPX_OK && status != OPX_ERROR_BUFFER_TOO_SMALL) return NULL;
    void *image = malloc(size > 0 ? size : 1);
    FUZZ_REQUIRE(image != NULL);
    size_t written = 0;
    FUZZ_REQUIRE(FUZZ_CALL(opx_octree_save_memory, tree, format, image, size, &written) == OPX_OK);
    FUZZ_REQUIRE(written == size);
    opx_octree *copy = NULL;
    /* A map the library saved must load. */
    FUZZ_REQUIRE(FUZZ_CALL(opx_octree_load_memory, image, size, options, &copy) == OPX_OK);
    free(image);
    return copy;
}

static void check_round_trips(const opx_octree *tree, const opx_octree_options *options,
                              const opx_octree_stats *stats) {
    opx_octree *full = save_and_reload(tree, OPX_FORMAT_OT, options);
    if (full != NULL) {
        opx_octree_stats copied = OPX_OCTREE_STATS_INIT;
        FUZZ_REQUIRE(FUZZ_CALL(opx_octree_get_stats, full, &copied) == OPX_OK);
        FUZZ_REQUIRE(copied.leaves_occupied == stats->leaves_occupied);
        FUZZ_REQUIRE(copied.leaves_uncertain == stats->leaves_uncertain);
        FUZZ_REQUIRE(copied.leaves_free == stats->leaves_free);
        opx_octree_destroy(full);
    }
    opx_octree_destroy(save_and_reload(tree, OPX_FORMAT_BT, options));
}

void fuzz_exercise_tree(const opx_octree *tree) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    FUZZ_REQUIRE(FUZZ_CALL(opx_octree_get_options, tree, &options) == OPX_OK);
    FUZZ_REQUIRE(options.resolution >= 1e-6 && options.resolution <= 1e6);
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    FUZZ_REQUIRE(FUZZ_CALL(opx_octree_get_stats, tree, &stats) == OPX_OK);
    check_leaves_against_stats(tree, &stats);
    check_round_trips(tree, &options, &stats);
    const double origin[3] = {0.0, 0.0, 0.0};
    opx_cell_info info = OPX_CELL_INFO_INIT;
    FUZZ_CALL(opx_octree_classify, tree, origin, &info);
    if (stats.has_occupied) {
        double center[3];
        for (int axis = 0; axis < 3; ++axis)
            center[axis] = 0.5 * (stats.occupied_min[axis] + stats.occupied_max[axis]);
        fuzz_query_sphere(tree, center, 2.0 * options.resolution);
    }
    fuzz_query_sphere(tree, origin, 8.0 * options.resolution);
}

/* One link holding a tiny sphere; the padding sets the sphere's radius.
 * Made once and kept: the fuzz targets run one input at a time. */
typedef struct sphere_scene {
    opx_linkset *links;
    opx_query *engines[2]; /* direct, amortized */
} sphere_scene;

static sphere_scene *get_sphere_scene(void) {
    static sphere_scene scene;
    if (scene.links != NULL) return &scene;
    opx_shape sphere = OPX_SHAPE_INIT;
    sphere.kind = OPX_SHAPE_SPHERE;
    sphere.radius = 1e-6;
    uint32_t link = 0;
    FUZZ_REQUIRE(opx_linkset_create(&scene.links) == OPX_OK);
    FUZZ_REQUIRE(opx_linkset_add_link(scene.links, "sphere", &link) == OPX_OK);
    FUZZ_REQUIRE(opx_linkset_add_shape(scene.links, link, &sphere, NULL) == OPX_OK);
    opx_query_options options = OPX_QUERY_OPTIONS_INIT;
    FUZZ_REQUIRE(opx_query_create(&options, &scene.engines[0]) == OPX_OK);
    options.engine = OPX_ENGINE_AMORTIZED;
    FUZZ_REQUIRE(opx_query_create(&options, &scene.engines[1]) == OPX_OK);
    return &scene;
}

static int same_distance(double a, double b) {
    if (a == b) return 1;
    return fabs(a - b) <= 1e-9 * fmax(1.0, fmax(fabs(a), fabs(b)));
}

void fuzz_query_sphere(const opx_octree *tree, const double center[3], double radius) {
    sphere_scene *scene = get_sphere_scene();
    opx_pose pose = OPX_POSE_IDENTITY;
    for (int axis = 0; axis < 3; ++axis) pose.position[axis] = center[axis];
    if (FUZZ_CALL(opx_linkset_set_poses, scene->links, &pose, 1, 0) != OPX_OK) return;
    if (FUZZ_CALL(opx_linkset_set_padding, scene->links, radius) != OPX_OK) return;
    opx_collision_result collision[2] = {OPX_COLLISION_RESULT_INIT, OPX_COLLISION_RESULT_INIT};
    opx_distance_result distance[2] = {OPX_DISTANCE_RESULT_INIT, OPX_DISTANCE_RESULT_INIT};
    opx_status collide_status[2], distance_status[2];
    for (int engine = 0; engine < 2; ++engine) {
        collide_status[engine] =
            FUZZ_CALL(opx_query_collide, scene->engines[engine], tree, scene->links, NULL, &collision[engine]);
        distance_status[engine] =
            FUZZ_CALL(opx_query_distance, scene->engines[engine], tree, scene->links, NULL, &distance[engine]);
    }
    /* The amortized engine's answers equal the direct engine's (query.h). */
    if (collide_status[0] == OPX_OK && collide_status[1] == OPX_OK)
        FUZZ_REQUIRE(collision[0].collided == collision[1].collided);
    if (distance_status[0] == OPX_OK && distance_status[1] == OPX_OK) {
        FUZZ_REQUIRE(distance[0].found == distance[1].found);
        FUZZ_REQUIRE(same_distance(distance[0].distance, distance[1].distance));
    }
}

void fuzz_check_loaded(opx_status status, opx_octree *tree) {
    if (status != OPX_OK) {
        FUZZ_REQUIRE(tree == NULL);
        return;
    }
    FUZZ_REQUIRE(tree != NULL);
    fuzz_exercise_tree(tree);
    opx_octree_destroy(tree);
}
