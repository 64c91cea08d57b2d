/*
 * The active joints (robot.h): which joints they are on robots with fixed,
 * mimic, floating and planar joints; FK from active values equals FK from
 * the model-order vector holding them, bit for bit; naming the active
 * joints alone does the same; bad arguments fail, name the argument and
 * change nothing.
 */
#include "opx_urdf_test.h" /* first: it sets _POSIX_C_SOURCE */

#include "opx_batch_test.h"
#include "opx_joints_test.h"

static void assert_active_joints(const opx_linkset *robot, const uint32_t *expected, size_t count) {
    size_t n = 0;
    uint32_t *indices = active_joints_of(robot, &n);
    assert_int_equal(n, count);
    for (size_t i = 0; i < count; ++i) assert_int_equal(indices[i], expected[i]);
    free(indices);
}

static void active_joints_are_the_moving_joints_that_mimic_none(void **state) {
    (void)state;
    opx_linkset *test = load_test_robot();
    const uint32_t test_active[3] = {J_SHOULDER, J_SLIDE, J_WHEEL};
    assert_active_joints(test, test_active, 3);
    opx_linkset *mixed = load_urdf_text(MIXED_URDF);
    assert_active_joints(mixed, MIXED_ACTIVE_JOINTS, MIXED_ACTIVE);
    opx_linkset *arm = load_arm();
    const uint32_t arm_active[8] = {0, 1, 2, 3, 4, 5, 6, 7}; /* j1..j7, finger_l */
    assert_active_joints(arm, arm_active, 8);
    /* Each active joint moves and mimics none; each other joint does not. */
    size_t n = 0;
    uint32_t *indices = active_joints_of(mixed, &n);
    for (uint32_t j = 0, next = 0; j < MIXED_JOINTS; ++j) {
        opx_joint_info info = OPX_JOINT_INFO_INIT;
        assert_ok(opx_linkset_get_joint_info(mixed, j, &info));
        const int moves = info.type == OPX_JOINT_REVOLUTE || info.type == OPX_JOINT_CONTINUOUS ||
                          info.type == OPX_JOINT_PRISMATIC;
        const int active = next < n && indices[next] == j;
        assert_int_equal(active, moves && info.mimic_joint == OPX_JOINT_NONE);
        next += active;
    }
    free(indices);
    opx_linkset_destroy(test);
    opx_linkset_destroy(mixed);
    opx_linkset_destroy(arm);
}

/* FK from `active` values and from the model vector holding them (other
 * joints at a filler FK ignores) gives the same poses, bit for bit. */
static void check_same_fk(const char *xml, const double *active, size_t active_count, const opx_pose *base) {
    opx_linkset *by_active = load_urdf_text(xml), *by_model = load_urdf_text(xml);
    uint32_t joints = 0;
    assert_ok(opx_linkset_get_joint_count(by_model, &joints));
    size_t n = 0;
    uint32_t *indices = active_joints_of(by_model, &n);
    assert_int_equal(n, active_count);
    double *model = malloc((joints + 1) * sizeof *model);
    assert_non_null(model);
    model_vector(indices, n, active, joints, 0.75, model);
    assert_ok(opx_linkset_set_active_joint_positions(by_active, active, active_count, base));
    assert_ok(opx_linkset_set_joint_positions(by_model, model, joints, base));
    assert_same_poses(by_active, by_model);
    /* The joint positions FK used agree too (mimic joints computed). */
    double from_active[16], from_model[16];
    size_t count_a = 0, count_m = 0;
    assert_ok(opx_linkset_get_joint_positions(by_active, from_active, 16, &count_a));
    assert_ok(opx_linkset_get_joint_positions(by_model, from_model, 16, &count_m));
    assert_int_equal(count_a, count_m);
    assert_memory_equal(from_active, from_model, count_a * sizeof(double));
    free(model);
    free(indices);
    opx_linkset_destroy(by_active);
    opx_linkset_destroy(by_model);
}

static void active_fk_equals_model_fk(void **state) {
    (void)state;
    const opx_pose base = {{0.4, -0.2, 0.1}, {0.0, 0.0, 0.38268343236508978, 0.92387953251128674}};
    const double test_values[3] = {0.7, 0.12, -2.5};
    check_same_fk(TEST_URDF, test_values, 3, NULL);
    check_same_fk(TEST_URDF, test_values, 3, &base);
    const double mixed_values[MIXED_ACTIVE] = {0.35, 1.1};
    check_same_fk(MIXED_URDF, mixed_values, MIXED_ACTIVE, &base);
    static char arm_xml[16384];
    arm_urdf(arm_xml, sizeof arm_xml);
    uint64_t seed = 5;
    for (int trial = 0; trial < 20; ++trial) {
        double values[8];
        for (int j = 0; j < 7; ++j) values[j] = next_uniform(&seed, -3.1, 3.1);
        values[7] = next_uniform(&seed, 0.0, 0.04);
        check_same_fk(arm_xml, values, 8, trial % 2 ? &base : NULL);
    }
}

/* The mimic chain of the mixed robot follows lift; the floating and
 * planar joints hold their children at their origins. */
static void mimic_joints_follow_their_leaders(void **state) {
    (void)state;
    opx_linkset *robot = load_urdf_text(MIXED_URDF);
    const double values[MIXED_ACTIVE] = {0.4, 0.9};
    assert_ok(opx_linkset_set_active_joint_positions(robot, values, MIXED_ACTIVE, NULL));
    double positions[MIXED_JOINTS];
    size_t count = 0;
    assert_ok(opx_linkset_get_joint_positions(robot, positions, MIXED_JOINTS, &count));
    assert_near(positions[2], 0.4, 0.0);
    assert_near(positions[4], 0.5 * 0.4 + 0.01, 1e-15);
    assert_near(positions[5], 0.9, 0.0);
    assert_near(positions[6], 2.0 * (0.5 * 0.4 + 0.01) + 0.1, 1e-15);
    assert_true(positions[0] == 0.0 && positions[1] == 0.0 && positions[3] == 0.0);
    const opx_pose b = get_pose(robot, 2), d = get_pose(robot, 4);
    assert_near(b.position[0], 0.1, 1e-15);
    assert_near(b.position[2], 0.1, 1e-15);
    assert_near(d.position[1], 0.1, 1e-15);
    assert_near(d.position[2], 0.2 + 0.4, 1e-15);
    opx_linkset_destroy(robot);
}

/* Naming the active joints alone, in any order, poses every link as the
 * active vector does; a named subset keeps the other joints' values. */
static void named_active_joints_set_every_pose(void **state) {
    (void)state;
    opx_linkset *named = load_test_robot(), *active = load_test_robot();
    const char *names[3] = {"wheel", "shoulder", "slide"};
    const double by_name[3] = {-2.5, 0.7, 0.12}, in_order[3] = {0.7, 0.12, -2.5};
    assert_ok(opx_linkset_set_named_joint_positions(named, names, by_name, 3, NULL));
    assert_ok(opx_linkset_set_active_joint_positions(active, in_order, 3, NULL));
    assert_same_poses(named, active);
    const char *one[1] = {"slide"};
    const double slide[1] = {0.2}, changed[3] = {0.7, 0.2, -2.5};
    assert_ok(opx_linkset_set_named_joint_positions(named, one, slide, 1, NULL));
    assert_ok(opx_linkset_set_active_joint_positions(active, changed, 3, NULL));
    assert_same_poses(named, active);
    opx_linkset_destroy(named);
    opx_linkset_destroy(active);
}

/* A robot whose joints are all fixed has no active joint: count 0 sets
 * the root pose alone. */
static void a_robot_without_active_joints_takes_an_empty_vector(void **state) {
    (void)state;
    static const char xml[] =
        "<robot name=\"still\"><link name=\"base\"><collision><geometry><sphere radius=\"0.1\"/>"
        "</geometry></collision></link><link name=\"top\"/>"
        "<joint name=\"weld\" type=\"fixed\"><parent link=\"base\"/><child link=\"top\"/>"
        "<origin xyz=\"0 0 1\"/></joint></robot>";
    opx_linkset *robot = load_urdf_text(xml);
    assert_int_equal(active_joint_count(robot), 0);
    size_t count = 7;
    assert_ok(opx_linkset_get_active_joints(robot, NULL, 0, &count));
    assert_int_equal(count, 0);
    const opx_pose base = pose_at(1.0, 2.0, 3.0);
    assert_ok(opx_linkset_set_active_joint_positions(robot, NULL, 0, &base));
    assert_near(get_pose(robot, 1).position[2], 4.0, 1e-15);
    opx_linkset_destroy(robot);
}

#define F "opx_linkset_set_active_joint_positions"
#define BAD OPX_ERROR_INVALID_ARGUMENT

static void bad_active_positions_fail_and_change_nothing(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    const double start[3] = {0.3, 0.1, 1.0};
    assert_ok(opx_linkset_set_active_joint_positions(robot, start, 3, NULL));
    size_t n = 0;
    opx_pose *before = poses_of(robot, &n);
    const double nan_value[3] = {0.1, NAN, 0.2}, huge[3] = {0.1, 0.2, 2e6}, inf[3] = {INFINITY, 0.0, 0.0};
    const double all[TEST_JOINTS] = {0.0};
    opx_pose bad_base = pose_at(0.0, 0.0, 0.0);
    bad_base.orientation[3] = 0.0;
    expect_failure(BAD, F, "links", opx_linkset_set_active_joint_positions(NULL, start, 3, NULL));
    expect_failure(BAD, F, "positions", opx_linkset_set_active_joint_positions(robot, NULL, 3, NULL));
    expect_failure(BAD, F, "count 2", opx_linkset_set_active_joint_positions(robot, start, 2, NULL));
    expect_failure(BAD, F, "count 5", opx_linkset_set_active_joint_positions(robot, all, TEST_JOINTS, NULL));
    expect_failure(BAD, F, "positions[1]", opx_linkset_set_active_joint_positions(robot, nan_value, 3, NULL));
    expect_failure(BAD, F, "positions[2]", opx_linkset_set_active_joint_positions(robot, huge, 3, NULL));
    expect_failure(BAD, F, "positions[0]", opx_linkset_set_active_joint_positions(robot, inf, 3, NULL));
    expect_failure(BAD, F, "base_pose", opx_linkset_set_active_joint_positions(robot, start, 3, &bad_base));
    size_t m = 0;
    opx_pose *after = poses_of(robot, &m);
    assert_memory_equal(before, after, n * sizeof *before);
    free(before);
    free(after);
    /* A link set built by hand has no joints. */
    opx_linkset *by_hand = new_linkset();
    add_link(by_hand, "only");
    expect_failure(OPX_ERROR_UNSUPPORTED, F, "joint tree",
                   opx_linkset_set_active_joint_positions(by_hand, NULL, 0, NULL));
    assert_int_equal(active_joint_count(by_hand), 0);
    opx_linkset_destroy(by_hand);
    opx_linkset_destroy(robot);
}

#define G "opx_linkset_get_active_joints"

static void active_joint_getters_check_their_arguments(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    uint32_t count32 = 0;
    expect_failure(BAD, "opx_linkset_get_active_joint_count", "links",
                   opx_linkset_get_active_joint_count(NULL, &count32));
    expect_failure(BAD, "opx_linkset_get_active_joint_count", "out_count",
                   opx_linkset_get_active_joint_count(robot, NULL));
    uint32_t indices[4] = {99, 99, 99, 99};
    size_t count = 0;
    expect_failure(BAD, G, "links", opx_linkset_get_active_joints(NULL, indices, 4, &count));
    expect_failure(BAD, G, "out_count", opx_linkset_get_active_joints(robot, indices, 4, NULL));
    expect_failure(BAD, G, "out_joint_indices", opx_linkset_get_active_joints(robot, NULL, 3, &count));
    /* Too small: the needed count is reported, nothing is written. */
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, G, "capacity 2",
                   opx_linkset_get_active_joints(robot, indices, 2, &count));
    assert_int_equal(count, 3);
    assert_int_equal(indices[0], 99);
    count = 0;
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, G, "capacity 0",
                   opx_linkset_get_active_joints(robot, NULL, 0, &count));
    assert_int_equal(count, 3);
    /* A larger buffer: only the count is written. */
    assert_ok(opx_linkset_get_active_joints(robot, indices, 4, &count));
    assert_int_equal(count, 3);
    assert_int_equal(indices[3], 99);
    opx_linkset_destroy(robot);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(active_joints_are_the_moving_joints_that_mimic_none),
        cmocka_unit_test(active_fk_equals_model_fk),
        cmocka_unit_test(mimic_joints_follow_their_leaders),
        cmocka_unit_test(named_active_joints_set_every_pose),
        cmocka_unit_test(a_robot_without_active_joints_takes_an_empty_vector),
        cmocka_unit_test(bad_active_positions_fail_and_change_nothing),
        cmocka_unit_test(active_joint_getters_check_their_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
