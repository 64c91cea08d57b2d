/*
 * Paths, batches and motions with a world set (opx_query_set_world) on the
 * generated arm among scattered objects, with the scattered map and
 * without an octree: the batch answers equal the single calls on a query
 * with the same world (FK, then opx_query_collide / opx_query_distance,
 * and self-collision), for 1, 2 and 3 threads and both engines; motions
 * equal a walk over their samples; a path's first colliding waypoint and
 * least distance equal the single calls at its waypoints.
 */
#include "opx_batch_test.h"

#define ROWS 160
#define MOTIONS 24
#define RESOLUTION 0.05

/* 30 boxes, spheres and capsules (8 to 20 cm) in the arm's reach. */
static opx_world *new_scatter_world(uint64_t seed) {
    opx_world *world = NULL;
    assert_ok(opx_world_create(&world));
    for (int i = 0; i < 30; ++i) {
        const opx_pose at = pose_at(next_uniform(&seed, -0.8, 0.8), next_uniform(&seed, -0.8, 0.8),
                                    next_uniform(&seed, 0.2, 1.4));
        uint32_t object = 0;
        assert_ok(opx_world_add_object(world, "thing", &at, &object));
        const double size = next_uniform(&seed, 0.08, 0.2);
        const opx_shape shape = i % 3 == 0   ? box_shape(size, 2 * size, size)
                                : i % 3 == 1 ? sphere_shape(size)
                                             : capsule_shape(size / 2, size);
        assert_ok(opx_world_add_shape(world, object, &shape, NULL));
    }
    return world;
}

static opx_query *query_in(int32_t engine, const opx_world *world) {
    opx_query *query = new_query_with(engine);
    assert_ok(opx_query_set_world(query, world));
    return query;
}

typedef struct world_case {
    int32_t engine;
    uint32_t threads;
    int distance, self;
    const opx_octree *tree; /* NULL: the objects alone */
} world_case;

static void check_batch(const world_case *c, const opx_world *world, opx_linkset *arm, const double *rows) {
    opx_query *query = query_in(c->engine, world), *single = query_in(OPX_ENGINE_DIRECT, world);
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.max_threads = c->threads;
    request.compute_distance = c->distance;
    request.self_collision = c->self;
    uint8_t collided[ROWS];
    double distances[ROWS];
    assert_ok(opx_query_check_configurations(query, c->tree, arm, rows, ROWS, ARM_JOINTS, 0, NULL, 0, 0, &request,
                                             collided, distances, ROWS));
    int hits = 0;
    for (size_t i = 0; i < ROWS; ++i) {
        const double *q = rows + i * ARM_JOINTS;
        const int expected = c->self ? single_collides_or_self(single, c->tree, arm, q, NULL)
                                     : single_collides(single, c->tree, arm, q, NULL);
        assert_int_equal(collided[i], expected);
        hits += expected;
        if (!c->distance) continue;
        double distance = single_distance(single, c->tree, arm, q, NULL, 0.0);
        if (c->self) distance = fmin(distance, single_self_distance(single, arm, 0.0));
        assert_true(distances[i] == distance);
    }
    assert_true(hits > ROWS / 20 && hits < ROWS * 19 / 20);
    opx_query_destroy(single);
    opx_query_destroy(query);
}

static void batches_equal_single_calls(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    disable_adjacent_arm_pairs(arm);
    opx_octree *tree = new_scatter_map(7);
    opx_world *world = new_scatter_world(5);
    double *rows = random_arm_rows(ROWS, 11);
    const int32_t engines[2] = {OPX_ENGINE_DIRECT, OPX_ENGINE_AMORTIZED};
    for (int k = 0; k < 24; ++k) { /* engines x 1-3 threads x distance x with and without the map */
        const world_case c = {engines[k % 2], 1 + (uint32_t)(k / 2) % 3, (k / 6) % 2, k % 5 == 0,
                              k / 12 == 0 ? tree : NULL};
        check_batch(&c, world, arm, rows);
    }
    free(rows);
    opx_world_destroy(world);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

/* The objects alone collide less often than objects and map: the world
 * changes the answers (a batch ignoring it would fail above only by
 * chance). */
static void the_world_changes_the_answers(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    opx_world *world = new_scatter_world(5);
    double *rows = random_arm_rows(ROWS, 11);
    opx_query *plain = new_query(), *with_world = query_in(OPX_ENGINE_DIRECT, world);
    opx_octree *tree = new_scatter_map(7);
    uint8_t map_only[ROWS], both[ROWS];
    assert_ok(opx_query_check_configurations(plain, tree, arm, rows, ROWS, ARM_JOINTS, 0, NULL, 0, 0, NULL, map_only,
                                             NULL, ROWS));
    assert_ok(opx_query_check_configurations(with_world, tree, arm, rows, ROWS, ARM_JOINTS, 0, NULL, 0, 0, NULL, both,
                                             NULL, ROWS));
    int more = 0;
    for (size_t i = 0; i < ROWS; ++i) {
        assert_true(both[i] >= map_only[i]);
        more += both[i] > map_only[i];
    }
    assert_true(more > 0);
    /* Without a world, a NULL octree is still refused. */
    uint8_t collided[ROWS];
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_check_configurations", "tree",
                   opx_query_check_configurations(plain, NULL, arm, rows, ROWS, ARM_JOINTS, 0, NULL, 0, 0, NULL,
                                                  collided, NULL, ROWS));
    opx_query_destroy(with_world);
    opx_query_destroy(plain);
    opx_octree_destroy(tree);
    free(rows);
    opx_world_destroy(world);
    opx_linkset_destroy(arm);
}

static uint64_t steps_between(const double *a, const double *b) {
    double largest = 0.0;
    for (int j = 0; j < ARM_REVOLUTE + 1; ++j) largest = fmax(largest, fabs(b[j] - a[j]));
    const double steps = ceil(largest / RESOLUTION);
    return steps < 1.0 ? 1 : (uint64_t)steps;
}

/* The first colliding sample of a -> b by single calls; -1: none. */
static int64_t walk_motion(opx_query *single, const opx_octree *tree, opx_linkset *arm, const double *a,
                           const double *b, uint64_t n, int self) {
    double q[ARM_JOINTS];
    for (uint64_t i = 0; i <= n; ++i) {
        for (int j = 0; j < ARM_JOINTS; ++j) q[j] = i == n ? b[j] : a[j] + ((double)i / (double)n) * (b[j] - a[j]);
        if (self ? single_collides_or_self(single, tree, arm, q, NULL) : single_collides(single, tree, arm, q, NULL))
            return (int64_t)i;
    }
    return -1;
}

/* Short motions from random configurations, so that some are free. */
static double *short_motions(uint64_t seed) {
    double *rows = random_arm_rows(2 * MOTIONS, seed);
    for (size_t m = 0; m < MOTIONS; ++m) {
        const double *a = rows + 2 * m * ARM_JOINTS;
        double *b = rows + (2 * m + 1) * ARM_JOINTS;
        for (int j = 0; j < ARM_REVOLUTE; ++j) b[j] = a[j] + next_uniform(&seed, -0.4, 0.4);
    }
    return rows;
}

static void motions_equal_a_walk_over_their_samples(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    disable_adjacent_arm_pairs(arm);
    opx_octree *tree = new_scatter_map(7);
    opx_world *world = new_scatter_world(9);
    double *ends = short_motions(41);
    const size_t stride = 2 * ARM_JOINTS * sizeof(double);
    opx_query *single = query_in(OPX_ENGINE_DIRECT, world);
    const int32_t engines[2] = {OPX_ENGINE_DIRECT, OPX_ENGINE_AMORTIZED};
    for (int k = 0; k < 12; ++k) { /* engines x 1-3 threads x with and without the map; self on odd threads */
        const opx_octree *map = k < 6 ? tree : NULL;
        opx_query *query = query_in(engines[k % 2], world);
        opx_motion_request request = OPX_MOTION_REQUEST_INIT;
        request.resolution = RESOLUTION;
        request.max_threads = 1 + (uint32_t)(k / 2) % 3;
        request.self_collision = request.max_threads % 2;
        uint8_t collided[MOTIONS];
        double fractions[MOTIONS];
        assert_ok(opx_query_check_motions(query, map, arm, ends, ends + ARM_JOINTS, MOTIONS, ARM_JOINTS, stride,
                                          NULL, 0, 0, &request, collided, fractions, MOTIONS));
        int hits = 0;
        for (size_t m = 0; m < MOTIONS; ++m) {
            const double *a = ends + 2 * m * ARM_JOINTS, *b = a + ARM_JOINTS;
            const uint64_t n = steps_between(a, b);
            const int64_t first = walk_motion(single, map, arm, a, b, n, request.self_collision);
            assert_int_equal(collided[m], first >= 0);
            assert_true(fractions[m] == (first < 0 ? -1.0 : (double)first / (double)n));
            opx_motion_result one = OPX_MOTION_RESULT_INIT;
            assert_ok(opx_query_check_motion(query, map, arm, a, b, ARM_JOINTS, NULL, &request, &one));
            assert_true(one.first_collision_fraction == fractions[m]);
            hits += first >= 0;
        }
        assert_true(hits > 0 && hits < MOTIONS);
        opx_query_destroy(query);
    }
    opx_query_destroy(single);
    free(ends);
    opx_world_destroy(world);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

/* A path over the samples of a few motions (their link poses): the first
 * colliding waypoint and the least distance are the single calls'. */
static void paths_equal_single_calls_at_their_waypoints(void **state) {
    (void)state;
    enum { WAYPOINTS = 30 };
    opx_linkset *arm = load_arm();
    opx_octree *tree = new_scatter_map(7);
    opx_world *world = new_scatter_world(9);
    double *rows = random_arm_rows(WAYPOINTS, 77);
    opx_pose *poses = malloc(WAYPOINTS * ARM_LINKS * sizeof *poses);
    assert_non_null(poses);
    for (size_t w = 0; w < WAYPOINTS; ++w) {
        assert_ok(opx_linkset_set_joint_positions(arm, rows + w * ARM_JOINTS, ARM_JOINTS, NULL));
        arm_poses(arm, poses + w * ARM_LINKS);
    }
    opx_query *single = query_in(OPX_ENGINE_DIRECT, world);
    const int32_t engines[2] = {OPX_ENGINE_DIRECT, OPX_ENGINE_AMORTIZED};
    for (int k = 0; k < 4; ++k) {
        const opx_octree *map = k < 2 ? tree : NULL;
        opx_query *query = query_in(engines[k % 2], world);
        int64_t first = -1, nearest_at = -1;
        double nearest = INFINITY;
        for (size_t w = 0; w < WAYPOINTS; ++w) {
            const double *q = rows + w * ARM_JOINTS;
            if (first < 0 && single_collides(single, map, arm, q, NULL)) first = (int64_t)w;
            const double d = single_distance(single, map, arm, q, NULL, 0.0);
            if (d < nearest) nearest = d, nearest_at = (int64_t)w;
        }
        opx_path_request request = OPX_PATH_REQUEST_INIT;
        request.compute_distance = 1;
        opx_path_result result = OPX_PATH_RESULT_INIT;
        assert_ok(opx_query_path(query, map, arm, poses, WAYPOINTS, 0, 0, &request, &result));
        assert_int_equal(result.first_colliding_waypoint, first);
        assert_true(first >= 0);
        assert_int_equal(result.min_distance_waypoint, nearest_at);
        assert_true(result.min_distance == nearest);
        opx_query_destroy(query);
    }
    opx_query_destroy(single);
    free(poses);
    free(rows);
    opx_world_destroy(world);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

/* Cost needs an octree; with one, the objects add no cost. */
static void path_cost_comes_from_the_octree_alone(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    opx_octree *tree = new_scatter_map(7);
    opx_world *world = new_scatter_world(9);
    double *rows = random_arm_rows(8, 3);
    opx_pose poses[8 * ARM_LINKS];
    for (size_t w = 0; w < 8; ++w) {
        assert_ok(opx_linkset_set_joint_positions(arm, rows + w * ARM_JOINTS, ARM_JOINTS, NULL));
        arm_poses(arm, poses + w * ARM_LINKS);
    }
    opx_query *plain = new_query(), *with_world = query_in(OPX_ENGINE_DIRECT, world);
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    request.compute_cost = 1;
    opx_path_result a = OPX_PATH_RESULT_INIT, b = OPX_PATH_RESULT_INIT;
    assert_ok(opx_query_path(plain, tree, arm, poses, 8, 0, 0, &request, &a));
    assert_ok(opx_query_path(with_world, tree, arm, poses, 8, 0, 0, &request, &b));
    assert_true(a.total_cost > 0.0);
    assert_true(a.total_cost == b.total_cost);
    assert_int_equal(a.cost_boxes_found, b.cost_boxes_found);
    assert_true(b.first_colliding_waypoint <= a.first_colliding_waypoint || a.first_colliding_waypoint < 0);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_path", "compute_cost",
                   opx_query_path(with_world, NULL, arm, poses, 8, 0, 0, &request, &b));
    opx_motion_request motion = OPX_MOTION_REQUEST_INIT;
    motion.compute_cost = 1;
    opx_motion_result m = OPX_MOTION_RESULT_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_check_motion", "compute_cost",
                   opx_query_check_motion(with_world, NULL, arm, rows, rows + ARM_JOINTS, ARM_JOINTS, NULL, &motion,
                                          &m));
    assert_ok(opx_query_check_motion(with_world, tree, arm, rows, rows + ARM_JOINTS, ARM_JOINTS, NULL, &motion, &m));
    opx_query_destroy(with_world);
    opx_query_destroy(plain);
    free(rows);
    opx_world_destroy(world);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(batches_equal_single_calls),
        cmocka_unit_test(the_world_changes_the_answers),
        cmocka_unit_test(motions_equal_a_walk_over_their_samples),
        cmocka_unit_test(paths_equal_single_calls_at_their_waypoints),
        cmocka_unit_test(path_cost_comes_from_the_octree_alone),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
