/*
 * Accessor names: every opx_linkset_get_* accessor and the alias kept for
 * compatibility under its other name give the same answers on the test
 * robot (with an SRDF of two disabled pairs), and the errors of each name
 * that function.
 */
#include "opx_urdf_test.h"

static const char TEST_SRDF[] =
    "<?xml version=\"1.0\"?><robot name=\"test\">"
    "<disable_collisions link1=\"base\" link2=\"arm\" reason=\"Adjacent\"/>"
    "<disable_collisions link1=\"tool\" link2=\"wheel\" reason=\"Never\"/>"
    "</robot>";

static int setup_robot(void **state) {
    const scratch_dir d = make_scratch_dir();
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.srdf_path = write_scratch(&d, "test.srdf", TEST_SRDF);
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string(TEST_URDF, &options, &robot));
    remove_scratch_dir(&d);
    *state = robot;
    return 0;
}

static int teardown_robot(void **state) {
    opx_linkset_destroy(*state);
    return 0;
}

static void link_count_shape_count_and_link_name(void **state) {
    const opx_linkset *robot = *state;
    uint32_t count = 0, alias_count = 0;
    assert_ok(opx_linkset_get_link_count(robot, &count));
    assert_ok(opx_linkset_link_count(robot, &alias_count));
    assert_int_equal(count, TEST_LINKS);
    assert_int_equal(alias_count, count);
    for (uint32_t link = 0; link < count; ++link) {
        uint32_t shapes = 99, alias_shapes = 98;
        assert_ok(opx_linkset_get_shape_count(robot, link, &shapes));
        assert_ok(opx_linkset_shape_count(robot, link, &alias_shapes));
        assert_int_equal(shapes, alias_shapes);
        const char *name = NULL, *alias_name = NULL;
        assert_ok(opx_linkset_get_link_name(robot, link, &name));
        assert_ok(opx_linkset_link_name(robot, link, &alias_name));
        assert_string_equal(name, alias_name);
    }
    uint32_t shapes = 0;
    assert_ok(opx_linkset_get_shape_count(robot, L_ARM, &shapes));
    assert_int_equal(shapes, 2);
    const char *name = NULL;
    assert_ok(opx_linkset_get_link_name(robot, L_WHEEL, &name));
    assert_string_equal(name, "wheel");
}

static void joint_count_and_joint_info(void **state) {
    const opx_linkset *robot = *state;
    uint32_t count = 0, alias_count = 0;
    assert_ok(opx_linkset_get_joint_count(robot, &count));
    assert_ok(opx_linkset_joint_count(robot, &alias_count));
    assert_int_equal(count, TEST_JOINTS);
    assert_int_equal(alias_count, count);
    for (uint32_t joint = 0; joint < count; ++joint) {
        opx_joint_info info = OPX_JOINT_INFO_INIT, alias_info = OPX_JOINT_INFO_INIT;
        assert_ok(opx_linkset_get_joint_info(robot, joint, &info));
        assert_ok(opx_linkset_joint_info(robot, joint, &alias_info));
        assert_memory_equal(&info, &alias_info, sizeof info);
    }
    opx_joint_info info = OPX_JOINT_INFO_INIT;
    assert_ok(opx_linkset_get_joint_info(robot, J_FINGER, &info));
    assert_string_equal(info.name, "finger");
    assert_int_equal(info.type, OPX_JOINT_PRISMATIC);
    assert_int_equal(info.mimic_joint, J_SLIDE);
}

static void disabled_pairs(void **state) {
    const opx_linkset *robot = *state;
    uint32_t count = 0, alias_count = 0;
    assert_ok(opx_linkset_get_disabled_pair_count(robot, &count));
    assert_ok(opx_linkset_disabled_pair_count(robot, &alias_count));
    assert_int_equal(count, 2);
    assert_int_equal(alias_count, count);
    const uint32_t expected[2][2] = {{L_BASE, L_ARM}, {L_TOOL, L_WHEEL}};
    for (uint32_t pair = 0; pair < count; ++pair) {
        uint32_t a = 99, b = 99, alias_a = 98, alias_b = 98;
        assert_ok(opx_linkset_get_disabled_pair(robot, pair, &a, &b));
        assert_ok(opx_linkset_disabled_pair(robot, pair, &alias_a, &alias_b));
        assert_int_equal(a, expected[pair][0]);
        assert_int_equal(b, expected[pair][1]);
        assert_int_equal(alias_a, a);
        assert_int_equal(alias_b, b);
    }
}

/* The same bad call through both names: the same status, and each message
 * names the function called (the check is by substring, so the expected
 * name is followed by its ':'). */
static void errors_name_the_function_called(void **state) {
    const opx_linkset *robot = *state;
    uint32_t a = 0, b = 0;
    const char *name = NULL;
    opx_joint_info info = OPX_JOINT_INFO_INIT;
    const int I = OPX_ERROR_INVALID_ARGUMENT;
    expect_failure(I, "opx_linkset_get_link_count:", "out_count", opx_linkset_get_link_count(robot, NULL));
    expect_failure(I, "opx_linkset_link_count:", "out_count", opx_linkset_link_count(robot, NULL));
    expect_failure(I, "opx_linkset_get_shape_count:", "link 6", opx_linkset_get_shape_count(robot, 6, &a));
    expect_failure(I, "opx_linkset_shape_count:", "link 6", opx_linkset_shape_count(robot, 6, &a));
    expect_failure(I, "opx_linkset_get_link_name:", "link 6", opx_linkset_get_link_name(robot, 6, &name));
    expect_failure(I, "opx_linkset_link_name:", "link 6", opx_linkset_link_name(robot, 6, &name));
    expect_failure(I, "opx_linkset_get_joint_count:", "links", opx_linkset_get_joint_count(NULL, &a));
    expect_failure(I, "opx_linkset_joint_count:", "links", opx_linkset_joint_count(NULL, &a));
    expect_failure(I, "opx_linkset_get_joint_info:", "joint 5", opx_linkset_get_joint_info(robot, 5, &info));
    expect_failure(I, "opx_linkset_joint_info:", "joint 5", opx_linkset_joint_info(robot, 5, &info));
    expect_failure(I, "opx_linkset_get_disabled_pair_count:", "out_count",
                   opx_linkset_get_disabled_pair_count(robot, NULL));
    expect_failure(I, "opx_linkset_disabled_pair_count:", "out_count",
                   opx_linkset_disabled_pair_count(robot, NULL));
    expect_failure(I, "opx_linkset_get_disabled_pair:", "pair 2", opx_linkset_get_disabled_pair(robot, 2, &a, &b));
    expect_failure(I, "opx_linkset_disabled_pair:", "pair 2", opx_linkset_disabled_pair(robot, 2, &a, &b));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(link_count_shape_count_and_link_name),
        cmocka_unit_test(joint_count_and_joint_info),
        cmocka_unit_test(disabled_pairs),
        cmocka_unit_test(errors_name_the_function_called),
    };
    return cmocka_run_group_tests(tests, setup_robot, teardown_robot);
}
