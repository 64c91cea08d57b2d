/*
 * opx_linkset_get_poses: every link's pose in the map frame, in link
 * order, as opx_linkset_get_pose gives each; after FK, after
 * opx_linkset_set_poses, with links added after loading, and for an empty
 * set; a buffer too small gets the needed count and nothing else.
 */
#include "opx_urdf_test.h" /* first: it sets _POSIX_C_SOURCE */

#include "opx_joints_test.h"

/* get_poses equals get_pose for every link, bit for bit. */
static void assert_poses_match_one_by_one(const opx_linkset *links) {
    size_t count = 0;
    opx_pose *poses = poses_of(links, &count);
    for (uint32_t i = 0; i < count; ++i) {
        const opx_pose one = get_pose(links, i);
        assert_memory_equal(&poses[i], &one, sizeof one);
    }
    free(poses);
}

static void every_pose_equals_the_single_getter(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    assert_poses_match_one_by_one(robot);
    const double q[TEST_JOINTS] = {0.7, 0.12, -2.5, 0.0, 0.0};
    const opx_pose base = {{1.0, 2.0, 0.5}, {0.0, 0.0, 0.70710678118654757, 0.70710678118654757}};
    assert_ok(opx_linkset_set_joint_positions(robot, q, TEST_JOINTS, &base));
    assert_poses_match_one_by_one(robot);
    /* A link added after loading keeps the pose it is given. */
    const uint32_t extra = add_link(robot, "extra");
    assert_int_equal(extra, TEST_LINKS);
    size_t count = 0;
    opx_pose *poses = poses_of(robot, &count);
    assert_int_equal(count, TEST_LINKS + 1);
    const opx_pose identity = OPX_POSE_IDENTITY;
    assert_memory_equal(&poses[extra], &identity, sizeof identity);
    free(poses);
    assert_poses_match_one_by_one(robot);
    opx_linkset_destroy(robot);
}

static void poses_set_by_hand_come_back_in_link_order(void **state) {
    (void)state;
    opx_linkset *links = new_linkset();
    add_link(links, "a"), add_link(links, "b"), add_link(links, "c");
    const opx_pose set[3] = {pose_at(1, 0, 0), pose_at(0, 2, 0), pose_at(0, 0, 3)};
    assert_ok(opx_linkset_set_poses(links, set, 3, 0));
    size_t count = 0;
    opx_pose *poses = poses_of(links, &count);
    assert_memory_equal(poses, set, sizeof set);
    free(poses);
    opx_linkset_destroy(links);
}

static void an_empty_set_has_no_poses(void **state) {
    (void)state;
    opx_linkset *links = new_linkset();
    size_t count = 9;
    assert_ok(opx_linkset_get_poses(links, NULL, 0, &count));
    assert_int_equal(count, 0);
    opx_linkset_destroy(links);
}

#define F "opx_linkset_get_poses"

static void bad_arguments_and_small_buffers_fail(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    opx_pose poses[TEST_LINKS + 1];
    memset(poses, 0xAB, sizeof poses);
    const opx_pose untouched = poses[0];
    size_t count = 0;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, F, "links", opx_linkset_get_poses(NULL, poses, TEST_LINKS, &count));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, F, "out_count", opx_linkset_get_poses(robot, poses, TEST_LINKS, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, F, "out_poses", opx_linkset_get_poses(robot, NULL, TEST_LINKS, &count));
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, F, "capacity 5",
                   opx_linkset_get_poses(robot, poses, TEST_LINKS - 1, &count));
    assert_int_equal(count, TEST_LINKS);
    assert_memory_equal(&poses[0], &untouched, sizeof untouched);
    count = 0;
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, F, "capacity 0", opx_linkset_get_poses(robot, NULL, 0, &count));
    assert_int_equal(count, TEST_LINKS);
    /* A larger buffer: the links' poses, the rest untouched. */
    assert_ok(opx_linkset_get_poses(robot, poses, TEST_LINKS + 1, &count));
    assert_int_equal(count, TEST_LINKS);
    assert_memory_equal(&poses[TEST_LINKS], &untouched, sizeof untouched);
    opx_linkset_destroy(robot);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_pose_equals_the_single_getter),
        cmocka_unit_test(poses_set_by_hand_come_back_in_link_order),
        cmocka_unit_test(an_empty_set_has_no_poses),
        cmocka_unit_test(bad_arguments_and_small_buffers_fail),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
