/*
 * Link sets from URDF: links, shapes and joints of a hand-written robot,
 * forward kinematics against poses composed by the test itself, named
 * positions, mimic joints, clones, meshes (STL, OBJ; relative, package://
 * and file:// paths; scale) and SRDF disabled pairs.  Errors:
 * test_urdf_errors.c.  The PR2: tests/real/test_pr2_urdf.cpp.
 */
#include "opx_urdf_test.h"

/* The expected link poses for shoulder a, slide s, wheel w (finger mimics
 * slide: 2 s + 0.01), root at `base`. */
static void expected_poses(frame base, double a, double s, double w, frame out[TEST_LINKS]) {
    const mat3 I = rot_z(0.0);
    out[L_BASE] = base;
    out[L_ARM] = frame_mul(base, frame_of(0, 0, 0.2, rot_z(a)));
    out[L_SLIDER] = frame_mul(out[L_ARM], frame_of(0.5 + s, 0, 0, I));
    out[L_FINGER] = frame_mul(out[L_SLIDER], frame_of(0, 2 * s + 0.01, 0.05, I));
    out[L_TOOL] = frame_mul(out[L_FINGER], frame_of(0, 0, 0.1, rot_z(HALF_PI)));
    out[L_WHEEL] = frame_mul(base, frame_mul(frame_of(0, 0.2, 0, rot_x(HALF_PI)), frame_of(0, 0, 0, rot_z(w))));
}

static void assert_all_links_at(const opx_linkset *robot, const frame expected[TEST_LINKS]) {
    for (uint32_t i = 0; i < TEST_LINKS; ++i) assert_link_at(robot, i, expected[i], 1e-12);
}

static void links_shapes_and_joints_come_from_the_file(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    static const char *const link_names[TEST_LINKS] = {"base", "arm", "slider", "wheel", "finger", "tool"};
    static const uint32_t shapes[TEST_LINKS] = {1, 2, 0, 1, 0, 1};
    assert_int_equal(link_count(robot), TEST_LINKS);
    for (uint32_t i = 0; i < TEST_LINKS; ++i) {
        const char *name = NULL;
        uint32_t count = 99;
        assert_ok(opx_linkset_get_link_name(robot, i, &name));
        assert_string_equal(name, link_names[i]);
        assert_ok(opx_linkset_get_shape_count(robot, i, &count));
        assert_int_equal(count, shapes[i]);
    }
    uint32_t joints = 0, index = 99;
    assert_ok(opx_linkset_get_joint_count(robot, &joints));
    assert_int_equal(joints, TEST_JOINTS);
    assert_ok(opx_linkset_find_joint(robot, "wheel", &index));
    assert_int_equal(index, J_WHEEL);
    assert_ok(opx_linkset_find_joint(robot, "tool", &index));
    assert_int_equal(index, J_TOOL);
    opx_linkset_destroy(robot);
}

static opx_joint_info info_of(const opx_linkset *robot, uint32_t joint) {
    opx_joint_info info = OPX_JOINT_INFO_INIT;
    assert_ok(opx_linkset_get_joint_info(robot, joint, &info));
    assert_int_equal(info.struct_size, sizeof info);
    return info;
}

static void joint_info_reports_types_links_axes_limits_and_mimic(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    opx_joint_info j = info_of(robot, J_SHOULDER);
    assert_string_equal(j.name, "shoulder");
    assert_int_equal(j.type, OPX_JOINT_REVOLUTE);
    assert_int_equal(j.parent_link, L_BASE);
    assert_int_equal(j.child_link, L_ARM);
    assert_true(j.axis[0] == 0.0 && j.axis[1] == 0.0 && j.axis[2] == 1.0);
    assert_true(j.origin.position[2] == 0.2 && j.origin.orientation[3] == 1.0);
    assert_int_equal(j.has_limits, 1);
    assert_true(j.lower == -1.0 && j.upper == 2.0 && j.effort == 10.0 && j.velocity == 1.5);
    assert_int_equal(j.mimic_joint, OPX_JOINT_NONE);

    j = info_of(robot, J_SLIDE);
    assert_int_equal(j.type, OPX_JOINT_PRISMATIC);
    assert_true(j.lower == 0.0 && j.upper == 0.3 && j.effort == 100.0 && j.velocity == 0.2);

    j = info_of(robot, J_WHEEL);
    assert_int_equal(j.type, OPX_JOINT_CONTINUOUS);
    assert_int_equal(j.parent_link, L_BASE);
    assert_int_equal(j.child_link, L_WHEEL);
    assert_true(isinf(j.lower) && j.lower < 0 && isinf(j.upper) && j.upper > 0);
    assert_true(j.velocity == 3.0 && j.effort == 4.0);
    /* rpy pi/2 0 0 is the quaternion (sin pi/4, 0, 0, cos pi/4). */
    assert_near(j.origin.orientation[0], sqrt(0.5), 1e-15);
    assert_near(j.origin.orientation[3], sqrt(0.5), 1e-15);

    j = info_of(robot, J_FINGER);
    assert_int_equal(j.mimic_joint, J_SLIDE);
    assert_true(j.mimic_multiplier == 2.0 && j.mimic_offset == 0.01);
    assert_true(j.axis[1] == 1.0);

    j = info_of(robot, J_TOOL);
    assert_string_equal(j.name, "tool");
    assert_int_equal(j.type, OPX_JOINT_FIXED);
    assert_int_equal(j.has_limits, 0);
    assert_int_equal(j.parent_link, L_FINGER);
    assert_int_equal(j.child_link, L_TOOL);
    opx_linkset_destroy(robot);
}

static void fk_matches_hand_composed_poses(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    frame expected[TEST_LINKS];
    const frame identity = frame_of(0, 0, 0, rot_z(0.0));
    /* Loaded at zero. */
    expected_poses(identity, 0.0, 0.0, 0.0, expected);
    assert_all_links_at(robot, expected);
    /* The finger sits at the slider + (0, 0.01, 0.05) by its mimic offset. */
    assert_near(get_pose(robot, L_FINGER).position[0], 0.5, 1e-15);
    assert_near(get_pose(robot, L_FINGER).position[1], 0.01, 1e-15);
    assert_near(get_pose(robot, L_FINGER).position[2], 0.25, 1e-15);

    /* The fixed joint's value and the mimic's own value are ignored. */
    const double q[TEST_JOINTS] = {0.5, 0.1, 1.0, 123.0, -7.0};
    assert_ok(opx_linkset_set_joint_positions(robot, q, TEST_JOINTS, NULL));
    expected_poses(identity, 0.5, 0.1, 1.0, expected);
    assert_all_links_at(robot, expected);
    /* One value written out: the slider at 0.6 m along the arm at 0.5 rad. */
    assert_near(get_pose(robot, L_SLIDER).position[0], 0.6 * cos(0.5), 1e-12);
    assert_near(get_pose(robot, L_SLIDER).position[1], 0.6 * sin(0.5), 1e-12);

    /* A base pose moves everything: root at (1, 2, 3), turned pi/2 about z. */
    opx_pose base = pose_at(1.0, 2.0, 3.0);
    base.orientation[2] = sqrt(0.5), base.orientation[3] = sqrt(0.5);
    const double q2[TEST_JOINTS] = {-0.8, 0.25, -2.5, 0.0, 0.0};
    assert_ok(opx_linkset_set_joint_positions(robot, q2, TEST_JOINTS, &base));
    expected_poses(frame_of(1.0, 2.0, 3.0, rot_z(HALF_PI)), -0.8, 0.25, -2.5, expected);
    assert_all_links_at(robot, expected);
    opx_linkset_destroy(robot);
}

static void named_positions_change_only_the_named_joints(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    const double q[TEST_JOINTS] = {0.5, 0.1, 1.0, 0.0, 0.0};
    assert_ok(opx_linkset_set_joint_positions(robot, q, TEST_JOINTS, NULL));
    const char *const names[2] = {"wheel", "slide"};
    const double values[2] = {-1.5, 0.2};
    assert_ok(opx_linkset_set_named_joint_positions(robot, names, values, 2, NULL));
    frame expected[TEST_LINKS];
    expected_poses(frame_of(0, 0, 0, rot_z(0.0)), 0.5, 0.2, -1.5, expected);
    assert_all_links_at(robot, expected);

    double positions[TEST_JOINTS + 1];
    size_t count = 0;
    assert_ok(opx_linkset_get_joint_positions(robot, positions, TEST_JOINTS + 1, &count));
    assert_int_equal(count, TEST_JOINTS);
    assert_true(positions[J_SHOULDER] == 0.5 && positions[J_SLIDE] == 0.2 && positions[J_WHEEL] == -1.5);
    assert_near(positions[J_FINGER], 0.41, 1e-15); /* the mimic's computed value */
    assert_true(positions[J_TOOL] == 0.0);
    /* count 0 keeps every joint but may move the base. */
    opx_pose base = pose_at(0.0, 0.0, 1.0);
    assert_ok(opx_linkset_set_named_joint_positions(robot, NULL, NULL, 0, &base));
    expected_poses(frame_of(0, 0, 1.0, rot_z(0.0)), 0.5, 0.2, -1.5, expected);
    assert_all_links_at(robot, expected);
    opx_linkset_destroy(robot);
}

/* The same shapes added by hand at the URDF origins answer the same
 * per-link distances to the one-cell map. */
static void shapes_sit_at_their_urdf_origins(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    const double q[TEST_JOINTS] = {0.7, 0.05, 0.4, 0.0, 0.0};
    opx_pose base = pose_at(0.3, -0.35, 0.05);
    assert_ok(opx_linkset_set_joint_positions(robot, q, TEST_JOINTS, &base));

    opx_linkset *hand = new_linkset();
    for (uint32_t i = 0; i < TEST_LINKS; ++i) add_link(hand, "x");
    opx_shape box = box_shape(0.4, 0.3, 0.2);
    box.pose.position[2] = 0.1;
    add_shape(hand, L_BASE, box);
    opx_shape cylinder = cylinder_shape(0.05, 0.5);
    cylinder.pose.position[0] = 0.25;
    cylinder.pose.orientation[1] = sin(HALF_PI / 2), cylinder.pose.orientation[3] = cos(HALF_PI / 2);
    add_shape(hand, L_ARM, cylinder);
    opx_shape ball = sphere_shape(0.07);
    ball.pose.position[0] = 0.5;
    add_shape(hand, L_ARM, ball);
    opx_shape disc = cylinder_shape(0.1, 0.04);
    disc.pose.position[2] = 0.02;
    disc.pose.orientation[0] = sin(0.15), disc.pose.orientation[3] = cos(0.15);
    add_shape(hand, L_WHEEL, disc);
    add_shape(hand, L_TOOL, sphere_shape(0.03));
    opx_pose poses[TEST_LINKS];
    for (uint32_t i = 0; i < TEST_LINKS; ++i) poses[i] = get_pose(robot, i);
    assert_ok(opx_linkset_set_poses(hand, poses, TEST_LINKS, 0));

    const linkset_snapshot a = take_linkset_snapshot(robot), b = take_linkset_snapshot(hand);
    for (uint32_t i = 0; i < TEST_LINKS; ++i) {
        const int has_shapes = i != L_SLIDER && i != L_FINGER;
        assert_int_equal(isfinite(a.link_distance[i]) != 0, has_shapes);
        if (has_shapes) assert_near(a.link_distance[i], b.link_distance[i], 1e-9);
    }
    assert_near(a.distance, b.distance, 1e-9);
    opx_linkset_destroy(hand);
    opx_linkset_destroy(robot);
}

static opx_shape shape_of(const opx_linkset *robot, uint32_t link, uint32_t index) {
    opx_shape shape = OPX_SHAPE_INIT;
    assert_ok(opx_linkset_get_shape(robot, link, index, &shape));
    assert_int_equal(shape.struct_size, sizeof shape);
    return shape;
}

static void shapes_are_stored_as_written(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    opx_shape s = shape_of(robot, L_BASE, 0);
    assert_int_equal(s.kind, OPX_SHAPE_BOX);
    assert_true(s.size[0] == 0.4 && s.size[1] == 0.3 && s.size[2] == 0.2);
    assert_true(s.pose.position[2] == 0.1 && s.pose.orientation[3] == 1.0);
    s = shape_of(robot, L_ARM, 0);
    assert_int_equal(s.kind, OPX_SHAPE_CYLINDER);
    assert_true(s.radius == 0.05 && s.length == 0.5 && s.pose.position[0] == 0.25);
    assert_near(s.pose.orientation[1], sqrt(0.5), 1e-15); /* rpy 0 pi/2 0 */
    assert_near(s.pose.orientation[3], sqrt(0.5), 1e-15);
    s = shape_of(robot, L_ARM, 1);
    assert_int_equal(s.kind, OPX_SHAPE_SPHERE);
    assert_true(s.radius == 0.07 && s.pose.position[0] == 0.5);
    s = shape_of(robot, L_WHEEL, 0);
    assert_int_equal(s.kind, OPX_SHAPE_CYLINDER);
    assert_near(s.pose.orientation[0], sin(0.15), 1e-15);
    assert_null(s.vertices);
    assert_null(s.indices);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_shape", "shape 1",
                   opx_linkset_get_shape(robot, L_WHEEL, 1, &s));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_shape", "shape 0",
                   opx_linkset_get_shape(robot, L_SLIDER, 0, &s));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_shape", "link 6",
                   opx_linkset_get_shape(robot, 6, 0, &s));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_shape", "out_shape",
                   opx_linkset_get_shape(robot, 0, 0, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_shape", "links",
                   opx_linkset_get_shape(NULL, 0, 0, &s));
    s.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, "opx_linkset_get_shape", "out_shape",
                   opx_linkset_get_shape(robot, 0, 0, &s));
    opx_linkset_destroy(robot);
}

/* opx_linkset_get_shape gives back what opx_linkset_add_shape stored. */
static void get_shape_round_trips_hand_added_shapes(void **state) {
    (void)state;
    opx_linkset *robot = new_robot(); /* every kind, see opx_query_test.h */
    opx_shape s = shape_of(robot, 1, 1);
    assert_int_equal(s.kind, OPX_SHAPE_CAPSULE);
    assert_true(s.radius == 0.05 && s.length == 0.2);
    s = shape_of(robot, 2, 1);
    assert_int_equal(s.kind, OPX_SHAPE_CONVEX);
    assert_int_equal(s.vertex_count, 4);
    assert_memory_equal(s.vertices, TETRA, sizeof TETRA);
    s = shape_of(robot, 2, 2);
    assert_int_equal(s.kind, OPX_SHAPE_MESH);
    assert_int_equal(s.triangle_count, 4);
    for (size_t t = 0; t < 4; ++t)
        for (int k = 0; k < 3; ++k) /* the same corners, maybe renumbered */
            assert_memory_equal(&s.vertices[3 * s.indices[3 * t + k]], &TETRA[3 * TETRA_FACES[3 * t + k]],
                                3 * sizeof(double));
    opx_linkset_destroy(robot);
}

static void clone_copies_the_joint_tree(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    const double q[TEST_JOINTS] = {0.5, 0.1, 1.0, 0.0, 0.0};
    assert_ok(opx_linkset_set_joint_positions(robot, q, TEST_JOINTS, NULL));
    opx_linkset *copy = NULL;
    assert_ok(opx_linkset_clone(robot, &copy));
    opx_linkset_destroy(robot); /* the copy owns its names and tree */
    uint32_t joints = 0;
    assert_ok(opx_linkset_get_joint_count(copy, &joints));
    assert_int_equal(joints, TEST_JOINTS);
    assert_string_equal(info_of(copy, J_FINGER).name, "finger");
    const char *const names[1] = {"shoulder"};
    const double values[1] = {-0.3};
    assert_ok(opx_linkset_set_named_joint_positions(copy, names, values, 1, NULL));
    frame expected[TEST_LINKS];
    expected_poses(frame_of(0, 0, 0, rot_z(0.0)), -0.3, 0.1, 1.0, expected);
    assert_all_links_at(copy, expected);
    opx_linkset_destroy(copy);
}

static void a_link_added_later_keeps_its_pose(void **state) {
    (void)state;
    opx_linkset *robot = load_test_robot();
    const uint32_t extra = add_link(robot, "held_object");
    add_shape(robot, extra, sphere_shape(0.05));
    opx_pose poses[TEST_LINKS + 1];
    for (uint32_t i = 0; i <= TEST_LINKS; ++i) poses[i] = get_pose(robot, i);
    poses[extra] = pose_at(4.0, 5.0, 6.0);
    assert_ok(opx_linkset_set_poses(robot, poses, TEST_LINKS + 1, 0));
    const double q[TEST_JOINTS] = {0.5, 0.1, 1.0, 0.0, 0.0};
    assert_ok(opx_linkset_set_joint_positions(robot, q, TEST_JOINTS, NULL));
    assert_near(get_pose(robot, extra).position[0], 4.0, 0.0);
    assert_near(get_pose(robot, extra).position[2], 6.0, 0.0);
    frame expected[TEST_LINKS];
    expected_poses(frame_of(0, 0, 0, rot_z(0.0)), 0.5, 0.1, 1.0, expected);
    assert_all_links_at(robot, expected);
    opx_linkset_destroy(robot);
}

/* Chains a -> b -> c of prismatic joints along x: b mimics a (3 a + 0.5),
 * c mimics b (2 b + 1); p is planar and f floating: both stay at their
 * origin whatever their values. */
static const char CHAIN_URDF[] =
    "<robot name=\"chain\"><link name=\"l0\"/><link name=\"l1\"/><link name=\"l2\"/><link name=\"l3\"/>"
    "<link name=\"l4\"/><link name=\"l5\"/>"
    "<joint name=\"c\" type=\"prismatic\"><parent link=\"l2\"/><child link=\"l3\"/><axis xyz=\"1 0 0\"/>"
    "<limit lower=\"-9\" upper=\"9\" effort=\"1\" velocity=\"1\"/><mimic joint=\"b\" multiplier=\"2\" offset=\"1\"/></joint>"
    "<joint name=\"a\" type=\"prismatic\"><parent link=\"l0\"/><child link=\"l1\"/><axis xyz=\"1 0 0\"/>"
    "<limit lower=\"-9\" upper=\"9\" effort=\"1\" velocity=\"1\"/></joint>"
    "<joint name=\"b\" type=\"prismatic\"><parent link=\"l1\"/><child link=\"l2\"/><axis xyz=\"1 0 0\"/>"
    "<limit lower=\"-9\" upper=\"9\" effort=\"1\" velocity=\"1\"/><mimic joint=\"a\" multiplier=\"3\" offset=\"0.5\"/></joint>"
    "<joint name=\"p\" type=\"planar\"><parent link=\"l0\"/><child link=\"l4\"/><origin xyz=\"0 1 0\"/></joint>"
    "<joint name=\"f\" type=\"floating\"><parent link=\"l4\"/><child link=\"l5\"/><origin xyz=\"0 0 1\"/></joint>"
    "</robot>";

static void mimic_chains_compose_and_planar_floating_stay_put(void **state) {
    (void)state;
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string(CHAIN_URDF, NULL, &robot));
    assert_int_equal(info_of(robot, 3).type, OPX_JOINT_PLANAR);
    assert_int_equal(info_of(robot, 4).type, OPX_JOINT_FLOATING);
    const double q[5] = {7.0, 0.1, 7.0, 5.0, 5.0}; /* c, a, b, p, f */
    assert_ok(opx_linkset_set_joint_positions(robot, q, 5, NULL));
    double positions[5];
    size_t count = 0;
    assert_ok(opx_linkset_get_joint_positions(robot, positions, 5, &count));
    assert_near(positions[1], 0.1, 1e-15);
    assert_near(positions[2], 0.8, 1e-15);        /* 3 * 0.1 + 0.5 */
    assert_near(positions[0], 2.6, 1e-15);        /* 2 * 0.8 + 1 */
    assert_true(positions[3] == 0.0 && positions[4] == 0.0);
    assert_near(get_pose(robot, 3).position[0], 0.1 + 0.8 + 2.6, 1e-14);
    const opx_pose l5 = get_pose(robot, 5);
    assert_true(l5.position[0] == 0.0 && l5.position[1] == 1.0 && l5.position[2] == 1.0);
    opx_linkset_destroy(robot);
}

/* One link and no joint: FK has no values but still places the root. */
static void a_single_link_robot_follows_its_base_pose(void **state) {
    (void)state;
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string("<robot name=\"r\"><link name=\"only\"><collision><geometry>"
                                           "<sphere radius=\"0.1\"/></geometry></collision></link></robot>",
                                           NULL, &robot));
    uint32_t joints = 99;
    assert_ok(opx_linkset_get_joint_count(robot, &joints));
    assert_int_equal(joints, 0);
    const opx_pose base = pose_at(1.0, -2.0, 0.5);
    assert_ok(opx_linkset_set_joint_positions(robot, NULL, 0, &base));
    const opx_pose pose = get_pose(robot, 0);
    assert_memory_equal(&pose, &base, sizeof pose);
    opx_linkset_destroy(robot);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(links_shapes_and_joints_come_from_the_file),
        cmocka_unit_test(joint_info_reports_types_links_axes_limits_and_mimic),
        cmocka_unit_test(fk_matches_hand_composed_poses),
        cmocka_unit_test(named_positions_change_only_the_named_joints),
        cmocka_unit_test(shapes_sit_at_their_urdf_origins),
        cmocka_unit_test(shapes_are_stored_as_written),
        cmocka_unit_test(get_shape_round_trips_hand_added_shapes),
        cmocka_unit_test(clone_copies_the_joint_tree),
        cmocka_unit_test(a_link_added_later_keeps_its_pose),
        cmocka_unit_test(mimic_chains_compose_and_planar_floating_stay_put),
        cmocka_unit_test(a_single_link_robot_follows_its_base_pose),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
