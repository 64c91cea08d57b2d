/*
 * The values of a URDF: numbers that are NaN, infinite, beyond a double or
 * beyond the documented bounds, missing attributes, and mimic joints that
 * loop, chain or compose to huge factors.  Each bad value fails the load
 * with a message naming the element and the attribute.
 */
#include "opx_urdf_test.h"

#define LOAD_STRING "opx_linkset_load_urdf_string"

static void expect_load_failure(const char *xml, opx_status status, const char *needle) {
    opx_linkset *robot = (opx_linkset *)&robot; /* must be reset to NULL */
    expect_failure(status, LOAD_STRING, needle, opx_linkset_load_urdf_string(xml, NULL, &robot));
    assert_null(robot);
}

/* A URDF of one link `a` whose one <collision> holds `inside`. */
static void expect_collision_failure(const char *inside, opx_status status, const char *needle) {
    char xml[512];
    snprintf(xml, sizeof xml, "<robot name=\"r\"><link name=\"a\"><collision>%s</collision></link></robot>", inside);
    expect_load_failure(xml, status, needle);
}

/* Links a, b and joint j (a -> b) of `type`, holding `inside`. */
static void format_joint_urdf(char *xml, size_t size, const char *type, const char *inside) {
    snprintf(xml, size,
             "<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><joint name=\"j\" type=\"%s\">"
             "<parent link=\"a\"/><child link=\"b\"/>%s</joint></robot>",
             type, inside);
}

static void expect_joint_failure(const char *type, const char *inside, const char *needle) {
    char xml[512];
    format_joint_urdf(xml, sizeof xml, type, inside);
    expect_load_failure(xml, OPX_ERROR_CORRUPT, needle);
}

#define SPHERE "<geometry><sphere radius=\"1\"/></geometry>"
#define LIMIT "<limit effort=\"1\" velocity=\"1\"/>"

static void origins_must_be_finite_numbers_in_range(void **state) {
    (void)state;
    const opx_status bad = OPX_ERROR_CORRUPT;
    expect_collision_failure("<origin xyz=\"nan 0 0\"/>" SPHERE, bad, "link 'a' collision 0 origin xyz 'nan' is not a number");
    expect_collision_failure("<origin rpy=\"0 inf 0\"/>" SPHERE, bad, "origin rpy 'inf' is not a number");
    expect_collision_failure("<origin xyz=\"1e400 0 0\"/>" SPHERE, bad, "origin xyz '1e400' is out of range");
    expect_collision_failure("<origin xyz=\"2e6 0 0\"/>" SPHERE, bad, "origin xyz 2000000 is beyond +-1000000");
    expect_collision_failure("<origin xyz=\"0x10 0 0\"/>" SPHERE, bad, "origin xyz '0x10' is not a number");
    expect_collision_failure("<origin xyz=\"1,5 0 0\"/>" SPHERE, bad, "origin xyz '1,5' is not a number");
    expect_collision_failure("<origin xyz=\"1 2\"/>" SPHERE, bad, "origin xyz '1 2' has 2 numbers, not 3");
    expect_collision_failure("<origin quat_xyzw=\"0 0 0 1\"/>" SPHERE, OPX_ERROR_UNSUPPORTED,
                             "link 'a' collision 0: <origin quat_xyzw> is not supported");
    expect_joint_failure("fixed", "<origin xyz=\"0 0 -1e7\"/>", "joint 'j' origin xyz -10000000 is beyond");
}

/* White space, signs and a leading point are read as numbers. */
static void numbers_are_read_with_signs_and_white_space(void **state) {
    (void)state;
    char xml[512];
    format_joint_urdf(xml, sizeof xml, "fixed", "<origin xyz=\" 1.5e-3\t+2\n -.5 \" rpy=\"0 0 +0.\"/>");
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string(xml, NULL, &robot));
    assert_link_at(robot, 1, frame_of(0.0015, 2, -0.5, rot_z(0)), 1e-12);
    opx_linkset_destroy(robot);
}

static void shapes_need_their_sizes(void **state) {
    (void)state;
    const opx_status bad = OPX_ERROR_CORRUPT;
    expect_collision_failure("<geometry><sphere/></geometry>", bad, "link 'a' collision 0 sphere has no radius");
    expect_collision_failure("<geometry><sphere radius=\"0\"/></geometry>", bad, "sphere radius is 0, not > 0");
    expect_collision_failure("<geometry><sphere radius=\"-nan\"/></geometry>", bad, "sphere radius '-nan' is not a number");
    expect_collision_failure("<geometry><box size=\"1 -1 1\"/></geometry>", bad, "box size y is -1, not > 0");
    expect_collision_failure("<geometry><box size=\"1 1\"/></geometry>", bad, "box size '1 1' has 2 numbers");
    expect_collision_failure("<geometry><box/></geometry>", bad, "box has no size");
    expect_collision_failure("<geometry><cylinder radius=\"1\"/></geometry>", bad, "cylinder has no length");
    expect_collision_failure("<geometry><cylinder radius=\"1e300\" length=\"1\"/></geometry>", bad,
                             "cylinder radius 1e+300 is beyond +-1000000");
    expect_collision_failure("<geometry><mesh/></geometry>", bad, "mesh has no filename");
    expect_collision_failure("<geometry><mesh filename=\"m.stl\" scale=\"1 0 1\"/></geometry>", bad,
                             "mesh scale has a zero factor");
    expect_collision_failure("<origin/>", bad, "link 'a' collision 0 has no <geometry>");
}

static void joints_need_their_limits_and_axes(void **state) {
    (void)state;
    expect_joint_failure("revolute", "", "joint 'j' is revolute and has no <limit>");
    expect_joint_failure("prismatic", "<axis xyz=\"1 0 0\"/>", "joint 'j' is prismatic and has no <limit>");
    expect_joint_failure("revolute", "<limit effort=\"1\"/>", "joint 'j' limit has no velocity");
    expect_joint_failure("continuous", "<limit velocity=\"1\"/>", "joint 'j' limit has no effort");
    expect_joint_failure("revolute", "<limit effort=\"nan\" velocity=\"1\"/>", "joint 'j' limit effort 'nan' is not a number");
    expect_joint_failure("revolute", "<limit lower=\"-1e999\" effort=\"1\" velocity=\"1\"/>",
                         "joint 'j' limit lower '-1e999' is out of range");
    expect_joint_failure("continuous", "<axis xyz=\"0 0 1e7\"/>", "joint 'j' axis xyz 10000000 is beyond");
    expect_joint_failure("continuous", "<axis xyz=\"0 0 x\"/>", "joint 'j' axis xyz 'x' is not a number");
    /* Limits are reported as written, even huge or reversed. */
    char xml[512];
    format_joint_urdf(xml, sizeof xml, "revolute", "<limit lower=\"2\" upper=\"1\" effort=\"1e300\" velocity=\"0\"/>");
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string(xml, NULL, &robot));
    opx_joint_info info = OPX_JOINT_INFO_INIT;
    assert_ok(opx_linkset_get_joint_info(robot, 0, &info));
    assert_true(info.lower == 2.0 && info.upper == 1.0 && info.effort == 1e300 && info.velocity == 0.0);
    opx_linkset_destroy(robot);
}

static void mimic_values_are_checked(void **state) {
    (void)state;
    expect_joint_failure("continuous", "<mimic joint=\"j\"/>", "joint 'j': its mimic joints form a loop");
    expect_joint_failure("continuous", "<mimic joint=\"j\" multiplier=\"1e7\"/>", "joint 'j' mimic multiplier 10000000 is beyond");
    expect_joint_failure("continuous", "<mimic joint=\"j\" offset=\"-inf\"/>", "joint 'j' mimic offset '-inf' is not a number");
    /* Three factors of 1e6 compose to 1e18. */
    expect_load_failure("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><link name=\"c\"/><link name=\"d\"/>"
                        "<joint name=\"j1\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/></joint>"
                        "<joint name=\"j2\" type=\"continuous\"><parent link=\"a\"/><child link=\"c\"/>"
                        "<mimic joint=\"j1\" multiplier=\"1e6\"/></joint>"
                        "<joint name=\"j3\" type=\"continuous\"><parent link=\"a\"/><child link=\"d\"/>"
                        "<mimic joint=\"j2\" multiplier=\"-1e6\"/></joint>"
                        "<joint name=\"j4\" type=\"continuous\"><parent link=\"a\"/><child link=\"a4\"/>"
                        "<mimic joint=\"j3\" multiplier=\"1e6\"/></joint><link name=\"a4\"/></robot>",
                        OPX_ERROR_CORRUPT, "joint 'j4': its mimic chain composes to a multiplier or offset beyond +-1e12");
}

/* Joint i+1 mimics joint i (times 1, plus 0.001), on links that all hang
 * from the root: a chain of mimics with no kinematic depth. */
static char *mimic_chain_urdf(size_t joints) {
    const size_t size = 200 * (joints + 2);
    char *xml = malloc(size);
    assert_non_null(xml);
    size_t used = (size_t)snprintf(xml, size, "<robot name=\"r\"><link name=\"root\"/>");
    for (size_t i = 0; i < joints; ++i) {
        used += (size_t)snprintf(xml + used, size - used,
                                 "<link name=\"l%zu\"/><joint name=\"j%zu\" type=\"continuous\"><parent link=\"root\"/>"
                                 "<child link=\"l%zu\"/>",
                                 i, i, i);
        if (i > 0) used += (size_t)snprintf(xml + used, size - used, "<mimic joint=\"j%zu\" offset=\"0.001\"/>", i - 1);
        used += (size_t)snprintf(xml + used, size - used, "</joint>");
    }
    snprintf(xml + used, size - used, "</robot>");
    return xml;
}

static void long_mimic_chains_compose(void **state) {
    (void)state;
    enum { N = 20000 };
    char *xml = mimic_chain_urdf(N);
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string(xml, NULL, &robot));
    free(xml);
    double *positions = calloc(N, sizeof *positions);
    assert_non_null(positions);
    positions[0] = 0.5;
    assert_ok(opx_linkset_set_joint_positions(robot, positions, N, NULL));
    size_t count = 0;
    assert_ok(opx_linkset_get_joint_positions(robot, positions, N, &count));
    assert_int_equal(count, N);
    assert_near(positions[1], 0.501, 1e-12);
    assert_near(positions[N - 1], 0.5 + 0.001 * (N - 1), 1e-9);
    free(positions);
    opx_linkset_destroy(robot);
}

static void versions_other_than_1_0_are_unsupported(void **state) {
    (void)state;
    expect_load_failure("<robot name=\"r\" version=\"2.0\"><link name=\"a\"/></robot>", OPX_ERROR_UNSUPPORTED,
                        "<robot version=\"2.0\"> is not supported (1.0)");
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string("<robot version=\" 1.0 \"><link name=\"a\"/></robot>", NULL, &robot));
    opx_linkset_destroy(robot);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(origins_must_be_finite_numbers_in_range),
        cmocka_unit_test(numbers_are_read_with_signs_and_white_space),
        cmocka_unit_test(shapes_need_their_sizes),
        cmocka_unit_test(joints_need_their_limits_and_axes),
        cmocka_unit_test(mimic_values_are_checked),
        cmocka_unit_test(long_mimic_chains_compose),
        cmocka_unit_test(versions_other_than_1_0_are_unsupported),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
