/*
 * opx_query_check_motion and opx_query_check_motions on the generated arm:
 * the first colliding configuration equals a brute-force walk over the
 * same samples with single calls (FK, then opx_query_collide); the batch
 * equals the single motion call for 1, 2 and 3 threads and both engines;
 * the swept cost equals opx_query_path over the samples' link poses; with
 * self_collision, the first sample touching the map or the arm itself.
 */
#include "opx_batch_test.h"

#define MOTIONS 40
#define RESOLUTION 0.05

static void check_against_brute_force(int self) {
    opx_linkset *arm = load_arm();
    disable_adjacent_arm_pairs(arm);
    opx_octree *tree = new_scatter_map(7);
    double *ends = random_arm_rows(2 * MOTIONS, 31);
    opx_query *query = new_query(), *single = new_query();
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.resolution = RESOLUTION;
    request.self_collision = self;
    int colliding = 0, free_motions = 0;
    for (size_t m = 0; m < MOTIONS; ++m) {
        const double *a = ends + 2 * m * ARM_JOINTS, *b = a + ARM_JOINTS;
        opx_motion_result result = OPX_MOTION_RESULT_INIT;
        assert_ok(opx_query_check_motion(query, tree, arm, a, b, ARM_JOINTS, NULL, &request, &result));
        const uint64_t n = motion_steps(a, b, RESOLUTION);
        assert_int_equal(result.steps, n);
        const int64_t first = first_colliding_sample(single, tree, arm, a, b, n, self);
        assert_int_equal(result.collided, first >= 0);
        assert_true(result.first_collision_fraction == (first < 0 ? -1.0 : (double)first / (double)n));
        assert_true(result.configurations_checked <= n + 1);
        if (first < 0) assert_int_equal(result.configurations_checked, n + 1);
        colliding += first >= 0, free_motions += first < 0;
    }
    assert_true(colliding > 0 && free_motions > 0);
    opx_query_destroy(single);
    opx_query_destroy(query);
    free(ends);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

static void first_collision_equals_brute_force(void **state) {
    (void)state;
    check_against_brute_force(0);
    check_against_brute_force(1);
}

/* Short motions from a configuration to a nearby one, so that some are free. */
static double *nearby_motions(size_t count, uint64_t seed) {
    double *rows = random_arm_rows(2 * count, seed);
    for (size_t m = 0; m < count; ++m) {
        const double *a = rows + 2 * m * ARM_JOINTS;
        double *b = rows + (2 * m + 1) * ARM_JOINTS;
        for (int j = 0; j < ARM_REVOLUTE; ++j) b[j] = a[j] + next_uniform(&seed, -0.4, 0.4);
    }
    return rows;
}

static void batch_equals_single_motion_calls(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    opx_octree *tree = new_scatter_map(7);
    double *ends = nearby_motions(MOTIONS, 41);
    const size_t stride = 2 * ARM_JOINTS * sizeof(double);
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.resolution = RESOLUTION;
    opx_query *single = new_query();
    const int32_t engines[2] = {OPX_ENGINE_DIRECT, OPX_ENGINE_AMORTIZED};
    disable_adjacent_arm_pairs(arm);
    for (int k = 0; k < 12; ++k) { /* engines x 1-3 threads x self-collision off and on */
        const int e = k % 2, self = k / 6;
        const uint32_t threads = 1 + (k / 2) % 3;
        {
            opx_query *query = new_query_with(engines[e]);
            request.max_threads = threads;
            request.self_collision = self;
            uint8_t collided[MOTIONS];
            double fractions[MOTIONS];
            assert_ok(opx_query_check_motions(query, tree, arm, ends, ends + ARM_JOINTS, MOTIONS, ARM_JOINTS, stride,
                                              NULL, 0, 0, &request, collided, fractions, MOTIONS));
            for (size_t m = 0; m < MOTIONS; ++m) {
                const double *a = ends + 2 * m * ARM_JOINTS;
                opx_motion_result result = OPX_MOTION_RESULT_INIT;
                assert_ok(opx_query_check_motion(single, tree, arm, a, a + ARM_JOINTS, ARM_JOINTS, NULL, &request,
                                                 &result));
                assert_int_equal(collided[m], result.collided);
                assert_true(fractions[m] == result.first_collision_fraction);
            }
            opx_query_destroy(query);
        }
    }
    opx_query_destroy(single);
    free(ends);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

/* The samples' link poses, waypoint-major, as opx_query_path takes them. */
static opx_pose *sample_poses(opx_linkset *arm, const double *a, const double *b, uint64_t n) {
    opx_pose *poses = malloc((n + 1) * ARM_LINKS * sizeof *poses);
    assert_non_null(poses);
    double q[ARM_JOINTS];
    for (uint64_t i = 0; i <= n; ++i) {
        motion_sample(a, b, i, n, q);
        assert_ok(opx_linkset_set_joint_positions(arm, q, ARM_JOINTS, NULL));
        arm_poses(arm, poses + i * ARM_LINKS);
    }
    return poses;
}

static void swept_cost_equals_the_path_query(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    opx_octree *tree = new_scatter_map(7);
    disable_adjacent_arm_pairs(arm);
    double *ends = nearby_motions(6, 51);
    opx_query *query = new_query(), *path = new_query();
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.resolution = RESOLUTION;
    request.compute_cost = 1;
    opx_path_request path_request = OPX_PATH_REQUEST_INIT;
    path_request.compute_cost = 1;
    for (size_t m = 0; m < 6; ++m) {
        const double *a = ends + 2 * m * ARM_JOINTS, *b = a + ARM_JOINTS;
        opx_motion_result result = OPX_MOTION_RESULT_INIT;
        assert_ok(opx_query_check_motion(query, tree, arm, a, b, ARM_JOINTS, NULL, &request, &result));
        const uint64_t n = result.steps;
        /* With self-collision: the first sample colliding with either. */
        opx_motion_request self_request = request;
        self_request.self_collision = 1;
        opx_motion_result self_result = OPX_MOTION_RESULT_INIT;
        assert_ok(opx_query_check_motion(query, tree, arm, a, b, ARM_JOINTS, NULL, &self_request, &self_result));
        const int64_t self_first = first_colliding_sample(path, tree, arm, a, b, n, 1);
        assert_true(self_result.first_collision_fraction == (self_first < 0 ? -1.0 : (double)self_first / (double)n));
        opx_pose *poses = sample_poses(arm, a, b, n);
        opx_path_result expected = OPX_PATH_RESULT_INIT;
        assert_ok(opx_query_path(path, tree, arm, poses, n + 1, 0, 0, &path_request, &expected));
        assert_int_equal(result.collided, expected.collided);
        const double fraction = expected.collided ? (double)expected.first_colliding_waypoint / (double)n : -1.0;
        assert_true(result.first_collision_fraction == fraction);
        assert_int_equal(result.configurations_checked, n + 1);
        /* The path's poses went through quaternions: equal to rounding. */
        assert_near(result.total_cost, expected.total_cost, 1e-12);
        assert_true(result.total_cost > 0.0);
        assert_int_equal(result.cost_boxes_found, expected.cost_boxes_found);
        assert_int_equal(result.cost_box_count, expected.cost_box_count);
        for (uint64_t k = 0; k < result.cost_box_count; ++k) {
            opx_cost_box got = OPX_COST_BOX_INIT, want = OPX_COST_BOX_INIT;
            assert_ok(opx_query_get_cost_box(query, k, &got));
            assert_ok(opx_query_get_cost_box(path, k, &want));
            assert_int_equal(got.link, want.link);
            assert_center(got.cell_center, want.cell_center[0], want.cell_center[1], want.cell_center[2]);
            assert_near(got.cost, want.cost, 1e-12);
        }
        free(poses);
    }
    opx_query_destroy(path);
    opx_query_destroy(query);
    free(ends);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

/* With compute_cost every sample's link poses are held: a motion of 1e6
 * steps (within the 1e7 limit) on the arm is too many for that, refused at
 * once with its own error, and the same motion without cost runs. */
static void a_costed_motion_holds_bounded_poses(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    opx_octree *tree = new_scatter_map(7);
    double start[ARM_JOINTS] = {0}, goal[ARM_JOINTS] = {0};
    goal[0] = 1.0;
    opx_query *query = new_query();
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.resolution = 1e-6;
    request.compute_cost = 1;
    opx_motion_result result = OPX_MOTION_RESULT_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_check_motion", "compute_cost",
                   opx_query_check_motion(query, tree, arm, start, goal, ARM_JOINTS, NULL, &request, &result));
    request.compute_cost = 0;
    request.resolution = 1e-3;
    assert_ok(opx_query_check_motion(query, tree, arm, start, goal, ARM_JOINTS, NULL, &request, &result));
    assert_int_equal(result.steps, 1000);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

/* A motion that does not move (start = goal) is one step, two samples. */
static void a_motion_that_stays_put(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    opx_octree *tree = new_scatter_map(7);
    double *rows = random_arm_rows(8, 61);
    opx_query *query = new_query();
    for (size_t i = 0; i < 8; ++i) {
        const double *q = rows + i * ARM_JOINTS;
        opx_motion_result result = OPX_MOTION_RESULT_INIT;
        assert_ok(opx_query_check_motion(query, tree, arm, q, q, ARM_JOINTS, NULL, NULL, &result));
        assert_int_equal(result.steps, 1);
        assert_int_equal(result.collided, single_collides(query, tree, arm, q, NULL));
        if (result.collided) assert_true(result.first_collision_fraction == 0.0);
    }
    opx_query_destroy(query);
    free(rows);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(first_collision_equals_brute_force),
        cmocka_unit_test(batch_equals_single_motion_calls),
        cmocka_unit_test(swept_cost_equals_the_path_query),
        cmocka_unit_test(a_motion_that_stays_put),
        cmocka_unit_test(a_costed_motion_holds_bounded_poses),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
