/*
 * opx_query_path: every invalid argument is rejected, named in the
 * message, and leaves the link set unchanged; the first colliding
 * waypoint, the minimum distance, strides and the swept cost by hand.
 */
#include "opx_query_test.h"

static const char *const FN = "opx_query_path";

/* Waypoints of the robot: 2 x 3 poses, the robot's own then shifted up. */
static void robot_path(opx_pose poses[6]) {
    poses[0] = pose_at(0.35, C0, C0);
    poses[1] = pose_at(C0, C0, 1.0);
    poses[2] = pose_at(C0, 1.0, C0);
    for (int i = 0; i < 3; ++i) {
        poses[3 + i] = poses[i];
        poses[3 + i].position[2] += 1.0;
    }
}

static void expect_path_fails(opx_linkset *robot, const opx_pose *poses, size_t waypoints,
                              size_t pose_stride, size_t waypoint_stride,
                              const opx_path_request *request, opx_status expected,
                              const char *argument) {
    opx_octree *tree = new_one_cell_map();
    opx_query *query = new_query();
    const linkset_snapshot before = take_linkset_snapshot(robot);
    opx_path_result result = OPX_PATH_RESULT_INIT;
    expect_failure(expected, FN, argument,
                   opx_query_path(query, tree, robot, poses, waypoints, pose_stride,
                                  waypoint_stride, request, &result));
    assert_linkset_unchanged(robot, &before);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
}

static void rejects_null_and_versions(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_linkset *robot = new_robot();
    const linkset_snapshot before = robot_snapshot(robot);
    opx_query *query = new_query();
    opx_pose poses[6];
    robot_path(poses);
    opx_path_result r = OPX_PATH_RESULT_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "query", opx_query_path(NULL, tree, robot, poses, 2, 0, 0, NULL, &r));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "tree", opx_query_path(query, NULL, robot, poses, 2, 0, 0, NULL, &r));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "links", opx_query_path(query, tree, NULL, poses, 2, 0, 0, NULL, &r));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "out_result", opx_query_path(query, tree, robot, poses, 2, 0, 0, NULL, NULL));
    r.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, FN, "out_result", opx_query_path(query, tree, robot, poses, 2, 0, 0, NULL, &r));
    assert_linkset_unchanged(robot, &before);
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    request.struct_size = 0;
    expect_path_fails(robot, poses, 2, 0, 0, &request, OPX_ERROR_VERSION, "request");
    /* NULL poses with waypoints (also when one waypoint is asked). */
    expect_path_fails(robot, NULL, 2, 0, 0, NULL, OPX_ERROR_INVALID_ARGUMENT, "poses");
    expect_path_fails(robot, NULL, 1, 0, 0, NULL, OPX_ERROR_INVALID_ARGUMENT, "poses");
    opx_query_destroy(query);
    opx_linkset_destroy(robot);
    opx_octree_destroy(tree);
}

static void rejects_bad_strides(void **state) {
    (void)state;
    opx_linkset *robot = new_robot();
    opx_pose poses[6];
    robot_path(poses);
    const size_t pose_strides[] = {1, 8, sizeof(opx_pose) - 1};
    for (size_t i = 0; i < 3; ++i)
        expect_path_fails(robot, poses, 2, pose_strides[i], 0, NULL, OPX_ERROR_INVALID_ARGUMENT,
                          "pose_stride");
    /* A waypoint of 3 links needs 2 strides and one pose: 168 bytes packed. */
    const size_t waypoint_strides[] = {8, sizeof(opx_pose), 3 * sizeof(opx_pose) - 1};
    for (size_t i = 0; i < 3; ++i)
        expect_path_fails(robot, poses, 2, 0, waypoint_strides[i], NULL,
                          OPX_ERROR_INVALID_ARGUMENT, "waypoint_stride");
    opx_linkset_destroy(robot);
}

/* One link: a waypoint is one pose, so a waypoint_stride below one pose
 * makes waypoints overlap, as a pose_stride below one pose would. */
static void rejects_a_waypoint_stride_below_one_pose_for_one_link(void **state) {
    (void)state;
    opx_linkset *ball = new_sphere_at(0.1, 1.0, C0, C0);
    const opx_pose poses[3] = {pose_at(1.0, C0, C0), pose_at(2.0, C0, C0), pose_at(3.0, C0, C0)};
    expect_path_fails(ball, poses, 2, 0, 8, NULL, OPX_ERROR_INVALID_ARGUMENT, "waypoint_stride");
    expect_path_fails(ball, poses, 2, 0, sizeof(opx_pose) - 1, NULL, OPX_ERROR_INVALID_ARGUMENT,
                      "waypoint_stride");
    opx_linkset_destroy(ball);
}

static void rejects_bad_poses(void **state) {
    (void)state;
    opx_linkset *robot = new_robot();
    opx_pose poses[6];
    const double bad[] = {NAN, INFINITY, -INFINITY};
    for (size_t b = 0; b < 3; ++b) {
        for (int axis = 0; axis < 3; ++axis) {
            robot_path(poses);
            poses[5].position[axis] = bad[b]; /* waypoint 1, link 2 */
            expect_path_fails(robot, poses, 2, 0, 0, NULL, OPX_ERROR_INVALID_ARGUMENT, "waypoint 1, link 2");
        }
        for (int c = 0; c < 4; ++c) {
            robot_path(poses);
            poses[4].orientation[c] = bad[b];
            expect_path_fails(robot, poses, 2, 0, 0, NULL, OPX_ERROR_INVALID_ARGUMENT, "waypoint 1, link 1");
        }
    }
    robot_path(poses);
    poses[2].orientation[3] = 0.0;
    expect_path_fails(robot, poses, 2, 0, 0, NULL, OPX_ERROR_INVALID_ARGUMENT, "waypoint 0, link 2");
    /* A bad pose after a colliding waypoint is still found. */
    robot_path(poses);
    poses[3].position[0] = NAN;
    expect_path_fails(robot, poses, 2, 0, 0, NULL, OPX_ERROR_INVALID_ARGUMENT, "waypoint 1, link 0");
    opx_linkset_destroy(robot);
}

static void rejects_bad_request_fields(void **state) {
    (void)state;
    opx_linkset *robot = new_robot();
    opx_pose poses[6];
    robot_path(poses);
    const int32_t policies[] = {-1, 2};
    for (size_t i = 0; i < 2; ++i) {
        opx_path_request r = OPX_PATH_REQUEST_INIT;
        r.unknown_policy = policies[i];
        expect_path_fails(robot, poses, 2, 0, 0, &r, OPX_ERROR_INVALID_ARGUMENT, "unknown_policy");
    }
    const double thresholds[] = {-0.1, 1.0, NAN, INFINITY};
    for (size_t i = 0; i < 4; ++i) {
        opx_path_request r = OPX_PATH_REQUEST_INIT;
        r.occupancy_threshold = thresholds[i];
        expect_path_fails(robot, poses, 2, 0, 0, &r, OPX_ERROR_INVALID_ARGUMENT, "occupancy_threshold");
    }
    const double probabilities[] = {-0.1, 1.5, NAN};
    for (size_t i = 0; i < 3; ++i) {
        opx_path_request r = OPX_PATH_REQUEST_INIT;
        r.compute_cost = 1;
        r.unknown_probability = probabilities[i];
        expect_path_fails(robot, poses, 2, 0, 0, &r, OPX_ERROR_INVALID_ARGUMENT, "unknown_probability");
    }
    opx_path_request r = OPX_PATH_REQUEST_INIT;
    r.compute_cost = 1;
    r.region_max[1] = INFINITY;
    expect_path_fails(robot, poses, 2, 0, 0, &r, OPX_ERROR_INVALID_ARGUMENT, "region");
    r.region_max[1] = 0.0;
    r.region_min[2] = NAN;
    expect_path_fails(robot, poses, 2, 0, 0, &r, OPX_ERROR_INVALID_ARGUMENT, "region");
    opx_linkset_destroy(robot);
}

/* ---- Positive behaviour ------------------------------------------------- */

/* A sphere r 0.1 approaching the cell along x: 0.65, 0.35 away, then
 * touching (x = 0.35) at waypoint 2 and inside at 3.  The link set itself
 * does not move. */
static void third_waypoint_first_collides(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_linkset *ball = new_sphere_at(0.1, 5.0, 5.0, 5.0);
    const opx_pose before = get_pose(ball, 0);
    opx_query *query = new_query();
    const opx_pose poses[4] = {pose_at(1.0, C0, C0), pose_at(0.7, C0, C0), pose_at(0.35, C0, C0),
                               pose_at(0.3, C0, C0)};
    opx_path_result r = OPX_PATH_RESULT_INIT;
    assert_ok(opx_query_path(query, tree, ball, poses, 4, 0, 0, NULL, &r));
    assert_int_equal(r.struct_size, sizeof r);
    assert_int_equal(r.collided, 1);
    assert_int_equal(r.first_colliding_waypoint, 2);
    assert_true(isinf(r.min_distance) && r.min_distance > 0.0); /* not asked */
    assert_int_equal(r.min_distance_waypoint, -1);
    /* Only the first two: no collision. */
    assert_ok(opx_query_path(query, tree, ball, poses, 2, 0, 0, NULL, &r));
    assert_int_equal(r.collided, 0);
    assert_int_equal(r.first_colliding_waypoint, -1);
    /* With the distance: the minimum over the path, 0 at waypoint 2. */
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    request.compute_distance = 1;
    assert_ok(opx_query_path(query, tree, ball, poses, 4, 0, 0, &request, &r));
    assert_int_equal(r.first_colliding_waypoint, 2);
    assert_near(r.min_distance, 0.0, 1e-9);
    assert_int_equal(r.min_distance_waypoint, 2);
    /* No waypoint: nothing collides (poses may be NULL). */
    assert_ok(opx_query_path(query, tree, ball, NULL, 0, 0, 0, NULL, &r));
    assert_int_equal(r.collided, 0);
    assert_int_equal(r.first_colliding_waypoint, -1);
    const opx_pose after = get_pose(ball, 0);
    assert_memory_equal(&after, &before, sizeof after);
    opx_query_destroy(query);
    opx_linkset_destroy(ball);
    opx_octree_destroy(tree);
}

/* Distances 0.65, 0.4 (the edge case of test_query_distance) and 0.9:
 * the minimum 0.4 at waypoint 1.  On an empty map: +infinity, -1. */
static void minimum_distance_along_a_path(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_linkset *ball = new_sphere_at(0.1, 5.0, 5.0, 5.0);
    opx_query *query = new_query();
    const opx_pose poses[3] = {pose_at(1.0, C0, C0), pose_at(0.55, 0.65, C0), pose_at(C0, C0, 1.25)};
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    request.compute_distance = 1;
    opx_path_result r = OPX_PATH_RESULT_INIT;
    assert_ok(opx_query_path(query, tree, ball, poses, 3, 0, 0, &request, &r));
    assert_int_equal(r.collided, 0);
    assert_int_equal(r.first_colliding_waypoint, -1);
    assert_near(r.min_distance, 0.4, 1e-12);
    assert_int_equal(r.min_distance_waypoint, 1);
    assert_true(r.narrow_tests >= 3);
    opx_octree *empty = new_tree(RES);
    assert_ok(opx_query_path(query, empty, ball, poses, 3, 0, 0, &request, &r));
    assert_int_equal(r.collided, 0);
    assert_true(isinf(r.min_distance) && r.min_distance > 0.0);
    assert_int_equal(r.min_distance_waypoint, -1);
    opx_octree_destroy(empty);
    opx_query_destroy(query);
    opx_linkset_destroy(ball);
    opx_octree_destroy(tree);
}

/* The robot's poses laid out with a pose_stride of 64 bytes (pose + a
 * double of the caller's) and a waypoint_stride of 3 x 64 + 16. */
static void strides_are_honoured(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_linkset *robot = new_robot();
    opx_query *query = new_query();
    unsigned char buffer[3 * (3 * 64 + 16)];
    memset(buffer, 0xFF, sizeof buffer); /* NaNs everywhere not a pose */
    opx_pose poses[6];
    robot_path(poses);
    /* Waypoint 0: the robot lifted (no collision); 1: lifted too; 2: the
     * robot's own poses (base touches the cell). */
    for (size_t w = 0; w < 3; ++w) {
        for (size_t l = 0; l < 3; ++l) {
            opx_pose p = w == 2 ? poses[l] : poses[3 + l];
            if (w == 1) p.position[2] += 1.0;
            memcpy(buffer + w * (3 * 64 + 16) + l * 64, &p, sizeof p);
        }
    }
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    request.compute_distance = 1;
    opx_path_result r = OPX_PATH_RESULT_INIT;
    assert_ok(opx_query_path(query, tree, robot, (const opx_pose *)(const void *)buffer, 3, 64,
                             3 * 64 + 16, &request, &r));
    assert_int_equal(r.first_colliding_waypoint, 2);
    assert_int_equal(r.min_distance_waypoint, 2);
    assert_near(r.min_distance, 0.0, 1e-9);
    /* Only waypoints 0 and 1: the lifted base (x = 0.35, z = C0 + 1) is the
     * closest, 0.1 in x and 0.875 in z from the cell, minus its radius. */
    assert_ok(opx_query_path(query, tree, robot, (const opx_pose *)(const void *)buffer, 2, 64,
                             3 * 64 + 16, &request, &r));
    assert_int_equal(r.collided, 0);
    assert_near(r.min_distance, sqrt(0.1 * 0.1 + 0.875 * 0.875) - 0.1, 1e-9);
    assert_int_equal(r.min_distance_waypoint, 0);
    opx_query_destroy(query);
    opx_linkset_destroy(robot);
    opx_octree_destroy(tree);
}

/* The cost map of test_query_cost.c, a bar at x [0.55, 1.875] then 0.05
 * further: each unknown cell counted once, with the bounding box of its two
 * boxes: [1.25, 1.5] and [1.5, 1.925], x 0.0225 m^2 x 0.5. */
static void swept_cost_counts_each_cell_once(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    insert_one_ray(tree, 1.0, 0.0, 0.0);
    opx_linkset *bar = new_linkset();
    add_shape(bar, add_link(bar, "bar"), box_shape(1.325, 0.15, 0.15));
    opx_query *query = new_query();
    const opx_pose poses[2] = {pose_at(1.2125, C0, C0), pose_at(1.2625, C0, C0)};
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    request.compute_cost = 1;
    request.region_max[0] = 2.0;
    request.region_max[1] = request.region_max[2] = RES;
    opx_path_result r = OPX_PATH_RESULT_INIT;
    assert_ok(opx_query_path(query, tree, bar, poses, 2, 0, 0, &request, &r));
    assert_int_equal(r.first_colliding_waypoint, 0);
    assert_near(r.total_cost, 0.5 * (0.25 + 0.425) * 0.0225, 1e-9);
    assert_int_equal(r.cost_boxes_found, 2);
    assert_int_equal(r.cost_box_count, 2);
    opx_cost_box b = OPX_COST_BOX_INIT;
    assert_ok(opx_query_get_cost_box(query, 0, &b));
    assert_center(b.min, 1.5, 0.05, 0.05);
    assert_center(b.max, 1.925, 0.2, 0.2);
    assert_near(b.cost, 0.5 * 0.425 * 0.0225, 1e-9);
    assert_int_equal(b.cell_class, OPX_CELL_UNKNOWN);
    opx_query_destroy(query);
    opx_linkset_destroy(bar);
    opx_octree_destroy(tree);
}

/* A query answers for the link set it is given, even when that set sits
 * where a destroyed one (with as many changes) was. */
static void a_new_link_set_at_a_reused_address(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_query *query = new_query();
    const opx_pose pose = pose_at(0.75, C0, C0);
    opx_path_result r = OPX_PATH_RESULT_INIT;
    for (int round = 0; round < 4; ++round) {
        opx_linkset *small = new_linkset(); /* r 0.1: 0.4 from the cell */
        add_shape(small, add_link(small, "s"), sphere_shape(0.1));
        assert_ok(opx_query_path(query, tree, small, &pose, 1, 0, 0, NULL, &r));
        assert_int_equal(r.collided, 0);
        opx_linkset_destroy(small);
        opx_linkset *large = new_linkset(); /* r 0.6: overlaps it */
        add_shape(large, add_link(large, "l"), sphere_shape(0.6));
        assert_ok(opx_query_path(query, tree, large, &pose, 1, 0, 0, NULL, &r));
        if (r.collided != 1)
            fail_msg("round %d: a sphere r 0.6 at x = 0.75 does not collide (the query used the "
                     "destroyed set's shapes?)", round);
        opx_linkset_destroy(large);
    }
    opx_query_destroy(query);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rejects_null_and_versions),
        cmocka_unit_test(rejects_bad_strides),
        cmocka_unit_test(rejects_a_waypoint_stride_below_one_pose_for_one_link),
        cmocka_unit_test(rejects_bad_poses),
        cmocka_unit_test(rejects_bad_request_fields),
        cmocka_unit_test(third_waypoint_first_collides),
        cmocka_unit_test(minimum_distance_along_a_path),
        cmocka_unit_test(strides_are_honoured),
        cmocka_unit_test(swept_cost_counts_each_cell_once),
        cmocka_unit_test(a_new_link_set_at_a_reused_address),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
