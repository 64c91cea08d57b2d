/*
 * URDF link sets, failures: every bad argument or input gives its status
 * and a message naming the function and the argument (or the bad part of
 * the input), *out stays NULL, and a failed FK call changes nothing.
 */
#include "opx_urdf_test.h"

#define LOAD_STRING "opx_linkset_load_urdf_string"

/* The whole observable state: link poses and joint positions. */
typedef struct fk_state {
    opx_pose poses[TEST_LINKS];
    double positions[TEST_JOINTS];
} fk_state;

static fk_state fk_state_of(const opx_linkset *robot) {
    fk_state s;
    memset(&s, 0, sizeof s);
    for (uint32_t i = 0; i < TEST_LINKS; ++i) s.poses[i] = get_pose(robot, i);
    size_t count = 0;
    assert_ok(opx_linkset_get_joint_positions(robot, s.positions, TEST_JOINTS, &count));
    assert_int_equal(count, TEST_JOINTS);
    return s;
}

static void assert_fk_unchanged(const opx_linkset *robot, const fk_state *before) {
    const fk_state now = fk_state_of(robot);
    assert_memory_equal(&now, before, sizeof now);
}

/* Loading `xml` fails with `status` and a message holding `needle`. */
static void expect_load_failure(const char *xml, opx_status status, const char *needle) {
    opx_linkset *robot = (opx_linkset *)&robot; /* must be reset to NULL */
    expect_failure(status, LOAD_STRING, needle, opx_linkset_load_urdf_string(xml, NULL, &robot));
    assert_null(robot);
}

static void load_rejects_null_and_bad_options(void **state) {
    (void)state;
    opx_linkset *robot = NULL;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, LOAD_STRING, "xml", opx_linkset_load_urdf_string(NULL, NULL, &robot));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, LOAD_STRING, "out", opx_linkset_load_urdf_string(TEST_URDF, NULL, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_load_urdf_file", "path",
                   opx_linkset_load_urdf_file(NULL, NULL, &robot));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_load_urdf_file", "out",
                   opx_linkset_load_urdf_file("/x.urdf", NULL, NULL));
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, LOAD_STRING, "options", opx_linkset_load_urdf_string(TEST_URDF, &options, &robot));
    opx_urdf_options_init(&options, sizeof options);
    options.package_dir_count = 1;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, LOAD_STRING, "options->package_dirs",
                   opx_linkset_load_urdf_string(TEST_URDF, &options, &robot));
    const char *dirs[2] = {"/tmp", NULL};
    options.package_dirs = dirs;
    options.package_dir_count = 2;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, LOAD_STRING, "options->package_dirs[1]",
                   opx_linkset_load_urdf_string(TEST_URDF, &options, &robot));
    opx_urdf_options_init(&options, sizeof options);
    options.srdf_path = "";
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, LOAD_STRING, "options->srdf_path",
                   opx_linkset_load_urdf_string(TEST_URDF, &options, &robot));
    assert_null(robot);
}

static void malformed_urdfs_are_corrupt(void **state) {
    (void)state;
    expect_load_failure("", OPX_ERROR_CORRUPT, "XML");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"></robot>", OPX_ERROR_CORRUPT, "not well-formed XML");
    expect_load_failure("<model name=\"r\"><link name=\"a\"/></model>", OPX_ERROR_CORRUPT, "<robot>");
    expect_load_failure("<robot name=\"r\"/>", OPX_ERROR_CORRUPT, "no <link>");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/>"
                        "<joint name=\"j\" type=\"fixed\"><child link=\"b\"/></joint></robot>",
                        OPX_ERROR_CORRUPT, "joint 'j' (line 1) has no <parent link=...>");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/>"
                        "<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"nolink\"/></joint></robot>",
                        OPX_ERROR_CORRUPT, "child link 'nolink' does not exist");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/>"
                        "<joint name=\"j\" type=\"hinge\"><parent link=\"a\"/><child link=\"b\"/></joint></robot>",
                        OPX_ERROR_CORRUPT, "type 'hinge'");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/>"
                        "<joint name=\"j\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/>"
                        "<mimic joint=\"ghost\"/></joint></robot>",
                        OPX_ERROR_CORRUPT, "mimics joint 'ghost'");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><link name=\"c\"/>"
                        "<joint name=\"j\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/>"
                        "<mimic joint=\"k\"/></joint>"
                        "<joint name=\"k\" type=\"continuous\"><parent link=\"b\"/><child link=\"c\"/>"
                        "<mimic joint=\"j\"/></joint></robot>",
                        OPX_ERROR_CORRUPT, "its mimic joints form a loop");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"/><link name=\"a\"/></robot>", OPX_ERROR_CORRUPT,
                        "two links have the same name");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/></robot>", OPX_ERROR_CORRUPT,
                        "links 'a' and 'b' are both roots");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"><collision><geometry><sphere radius=\"-1\"/>"
                        "</geometry></collision></link></robot>",
                        OPX_ERROR_CORRUPT, "link 'a' collision 0 sphere radius is -1");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"><collision><geometry><capsule radius=\"1\" "
                        "length=\"1\"/></geometry></collision></link></robot>",
                        OPX_ERROR_UNSUPPORTED, "link 'a' collision 0: geometry <capsule> is not supported");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"><collision><geometry><sphere/>"
                        "</geometry></collision></link></robot>",
                        OPX_ERROR_CORRUPT, "link 'a' collision 0 sphere has no radius");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/>"
                        "<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>"
                        "<axis xyz=\"0 0 0\"/><limit lower=\"0\" upper=\"1\" effort=\"1\" velocity=\"1\"/>"
                        "</joint></robot>",
                        OPX_ERROR_CORRUPT, "joint 'j' has a zero or non-finite axis");
}

static void missing_files_and_packages_are_io_errors(void **state) {
    (void)state;
    opx_linkset *robot = NULL;
    expect_failure(OPX_ERROR_IO, "opx_linkset_load_urdf_file", "path '/nonexistent/robot.urdf'",
                   opx_linkset_load_urdf_file("/nonexistent/robot.urdf", NULL, &robot));
    expect_failure(OPX_ERROR_IO, "opx_linkset_load_urdf_file", "path '/tmp'",
                   opx_linkset_load_urdf_file("/tmp", NULL, &robot));
    expect_load_failure("<robot name=\"r\"><link name=\"a\"><collision><geometry><mesh filename=\"nope/m.stl\"/>"
                        "</geometry></collision></link></robot>",
                        OPX_ERROR_IO, "link 'a' collision 0: mesh 'nope/m.stl'");
    expect_load_failure("<robot name=\"r\"><link name=\"a\"><collision><geometry>"
                        "<mesh filename=\"package://ghost/m.stl\"/></geometry></collision></link></robot>",
                        OPX_ERROR_IO, "package 'ghost' is unknown (options->package_dirs is empty; a package "
                                      "folder named otherwise is mapped by an entry 'ghost=DIR')");
    const char *dirs[1] = {"/tmp"};
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.package_dirs = dirs;
    options.package_dir_count = 1;
    expect_failure(OPX_ERROR_IO, LOAD_STRING, "tried /tmp/ghost/m.stl",
                   opx_linkset_load_urdf_string("<robot name=\"r\"><link name=\"a\"><collision><geometry>"
                                                "<mesh filename=\"package://ghost/m.stl\"/></geometry></collision>"
                                                "</link></robot>",
                                                &options, &robot));
    opx_urdf_options_init(&options, sizeof options);
    options.srdf_path = "/nonexistent/robot.srdf";
    expect_failure(OPX_ERROR_IO, LOAD_STRING, "options->srdf_path '/nonexistent/robot.srdf'",
                   opx_linkset_load_urdf_string(TEST_URDF, &options, &robot));
    assert_null(robot);
}

static void bad_mesh_and_srdf_files_are_corrupt(void **state) {
    (void)state;
    const scratch_dir d = make_scratch_dir();
    write_scratch(&d, "garbage.stl", "this is not a mesh\n");
    write_scratch(&d, "empty.obj", "# no faces\nv 0 0 0\n");
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.base_dir = d.path;
    opx_linkset *robot = NULL;
    expect_failure(OPX_ERROR_CORRUPT, LOAD_STRING, "garbage.stl",
                   opx_linkset_load_urdf_string("<robot name=\"r\"><link name=\"a\"><collision><geometry>"
                                                "<mesh filename=\"garbage.stl\"/></geometry></collision>"
                                                "</link></robot>",
                                                &options, &robot));
    expect_failure(OPX_ERROR_CORRUPT, LOAD_STRING, "empty.obj",
                   opx_linkset_load_urdf_string("<robot name=\"r\"><link name=\"a\"><collision><geometry>"
                                                "<mesh filename=\"empty.obj\"/></geometry></collision>"
                                                "</link></robot>",
                                                &options, &robot));
    options.base_dir = NULL;
    options.srdf_path = write_scratch(&d, "bad.srdf", "<robot name=\"test\"><disable_collisions link1=\"base\" "
                                                      "link2=\"ghost\"/></robot>");
    expect_failure(OPX_ERROR_CORRUPT, LOAD_STRING, "link 'ghost'",
                   opx_linkset_load_urdf_string(TEST_URDF, &options, &robot));
    options.srdf_path = write_scratch(&d, "broken.srdf", "<robot name=\"test\"><disable_collisions");
    expect_failure(OPX_ERROR_CORRUPT, LOAD_STRING, "options->srdf_path",
                   opx_linkset_load_urdf_string(TEST_URDF, &options, &robot));
    assert_null(robot);
    remove_scratch_dir(&d);
}

static void fk_rejects_bad_arguments_and_changes_nothing(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    const double q[TEST_JOINTS] = {0.5, 0.1, 1.0, 0.0, 0.0};
    assert_ok(opx_linkset_set_joint_positions(robot, q, TEST_JOINTS, NULL));
    const fk_state before = fk_state_of(robot);
    const char *fn = "opx_linkset_set_joint_positions";
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "links", opx_linkset_set_joint_positions(NULL, q, TEST_JOINTS, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "count 4", opx_linkset_set_joint_positions(robot, q, 4, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "count 6", opx_linkset_set_joint_positions(robot, q, 6, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "positions",
                   opx_linkset_set_joint_positions(robot, NULL, TEST_JOINTS, NULL));
    static const double bad_values[5] = {NAN, INFINITY, -INFINITY, 1.5e6, -1e300};
    for (int i = 0; i < 5; ++i) {
        double bad[TEST_JOINTS] = {0.9, 0.2, -1.0, 0.0, 0.0};
        bad[4] = bad_values[i]; /* even an ignored (fixed) slot */
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "positions[4]",
                       opx_linkset_set_joint_positions(robot, bad, TEST_JOINTS, NULL));
    }
    opx_pose zero_quaternion = pose_at(1, 2, 3);
    zero_quaternion.orientation[3] = 0.0;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "base_pose",
                   opx_linkset_set_joint_positions(robot, q, TEST_JOINTS, &zero_quaternion));
    assert_fk_unchanged(robot, &before);
    opx_linkset_destroy(robot);
}

static void named_fk_rejects_unknown_names_and_changes_nothing(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    const fk_state before = fk_state_of(robot);
    const char *fn = "opx_linkset_set_named_joint_positions";
    const char *const names[3] = {"shoulder", "ghost_joint", "wheel"};
    const char *const with_null[2] = {"shoulder", NULL};
    const double values[3] = {0.5, 0.1, 1.0}, nan_values[3] = {0.5, NAN, 1.0};
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "links", opx_linkset_set_named_joint_positions(NULL, names, values, 1, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "names[1] \"ghost_joint\"",
                   opx_linkset_set_named_joint_positions(robot, names, values, 3, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "names", opx_linkset_set_named_joint_positions(robot, NULL, values, 1, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "positions", opx_linkset_set_named_joint_positions(robot, names, NULL, 1, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "names[1]", opx_linkset_set_named_joint_positions(robot, with_null, values, 2, NULL));
    const char *const good[3] = {"shoulder", "slide", "wheel"};
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "positions[1] (joint \"slide\")",
                   opx_linkset_set_named_joint_positions(robot, good, nan_values, 3, NULL));
    assert_fk_unchanged(robot, &before);
    opx_linkset_destroy(robot);
}

/* A link set made by hand has no joints: FK is unsupported, counts are 0. */
static void a_set_without_joints_has_no_fk(void **state) {
    (void)state;
    opx_linkset *robot = new_robot();
    const double q[1] = {0.0};
    const char *const names[1] = {"base"};
    expect_failure(OPX_ERROR_UNSUPPORTED, "opx_linkset_set_joint_positions", "links",
                   opx_linkset_set_joint_positions(robot, q, 0, NULL));
    expect_failure(OPX_ERROR_UNSUPPORTED, "opx_linkset_set_named_joint_positions", "links",
                   opx_linkset_set_named_joint_positions(robot, names, q, 1, NULL));
    uint32_t count = 99;
    size_t positions = 99;
    assert_ok(opx_linkset_get_joint_count(robot, &count));
    assert_int_equal(count, 0);
    assert_ok(opx_linkset_get_joint_positions(robot, NULL, 0, &positions));
    assert_int_equal(positions, 0);
    assert_ok(opx_linkset_get_disabled_pair_count(robot, &count));
    assert_int_equal(count, 0);
    opx_linkset_destroy(robot);
}

static void joint_queries_reject_bad_arguments(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    uint32_t index = 99, count = 0;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_joint_count", "links",
                   opx_linkset_get_joint_count(NULL, &count));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_joint_count", "out_count",
                   opx_linkset_get_joint_count(robot, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_find_joint", "ghost", opx_linkset_find_joint(robot, "ghost", &index));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_find_joint", "name", opx_linkset_find_joint(robot, NULL, &index));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_find_joint", "out_joint", opx_linkset_find_joint(robot, "wheel", NULL));
    assert_int_equal(index, 99);
    opx_joint_info info = OPX_JOINT_INFO_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_joint_info", "joint 5",
                   opx_linkset_get_joint_info(robot, 5, &info));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_joint_info", "out",
                   opx_linkset_get_joint_info(robot, 0, NULL));
    info.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, "opx_linkset_get_joint_info", "out",
                   opx_linkset_get_joint_info(robot, 0, &info));
    double positions[TEST_JOINTS];
    size_t n = 0;
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, "opx_linkset_get_joint_positions", "capacity 4",
                   opx_linkset_get_joint_positions(robot, positions, 4, &n));
    assert_int_equal(n, TEST_JOINTS);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_joint_positions", "out",
                   opx_linkset_get_joint_positions(robot, NULL, TEST_JOINTS, &n));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_joint_positions", "out_count",
                   opx_linkset_get_joint_positions(robot, positions, TEST_JOINTS, NULL));
    uint32_t a = 0, b = 0;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_disabled_pair_count", "out_count",
                   opx_linkset_get_disabled_pair_count(robot, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_disabled_pair", "pair 0",
                   opx_linkset_get_disabled_pair(robot, 0, &a, &b));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_disabled_pair", "out_link2",
                   opx_linkset_get_disabled_pair(robot, 0, &a, NULL));
    opx_linkset_destroy(robot);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(load_rejects_null_and_bad_options),
        cmocka_unit_test(malformed_urdfs_are_corrupt),
        cmocka_unit_test(missing_files_and_packages_are_io_errors),
        cmocka_unit_test(bad_mesh_and_srdf_files_are_corrupt),
        cmocka_unit_test(fk_rejects_bad_arguments_and_changes_nothing),
        cmocka_unit_test(named_fk_rejects_unknown_names_and_changes_nothing),
        cmocka_unit_test(a_set_without_joints_has_no_fk),
        cmocka_unit_test(joint_queries_reject_bad_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
