/*
 * URDF files on disk: mesh files (ASCII STL, OBJ, DAE) found by relative,
 * package:// (all three package_dirs forms) and file:// names, the URDF
 * scale applied, a URDF file's folder as the default base, and SRDF
 * disabled pairs.  Each test writes its files into a fresh /tmp folder.
 */
#include "opx_urdf_test.h"

/* The tetrahedron of opx_query_test.h (TETRA, TETRA_FACES) as files. */
static const char TETRA_STL[] =
    "solid tetra\n"
    "facet normal 0 0 0\n outer loop\n  vertex 0 0 0\n  vertex 0 0.1 0\n  vertex 0.1 0 0\n endloop\nendfacet\n"
    "facet normal 0 0 0\n outer loop\n  vertex 0 0 0\n  vertex 0.1 0 0\n  vertex 0 0 0.1\n endloop\nendfacet\n"
    "facet normal 0 0 0\n outer loop\n  vertex 0 0 0\n  vertex 0 0 0.1\n  vertex 0 0.1 0\n endloop\nendfacet\n"
    "facet normal 0 0 0\n outer loop\n  vertex 0.1 0 0\n  vertex 0 0.1 0\n  vertex 0 0 0.1\n endloop\nendfacet\n"
    "endsolid tetra\n";
static const char TETRA_OBJ[] =
    "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0 0 0.1\n"
    "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

/* A root link and three mesh links on fixed joints: m1 the relative STL
 * scaled (2, 1, 3), m2 the OBJ by package://, m3 the STL by file:// URI. */
static const char *mesh_urdf(const char *abs_stl) {
    static char xml[2048];
    snprintf(xml, sizeof xml,
             "<robot name=\"m\"><link name=\"root\"/>"
             "<link name=\"m1\"><collision><origin xyz=\"0.1 0 0\"/><geometry>"
             "<mesh filename=\"meshes/tetra.stl\" scale=\"2 1 3\"/></geometry></collision></link>"
             "<link name=\"m2\"><collision><geometry>"
             "<mesh filename=\"package://mypkg/meshes/tetra.obj\"/></geometry></collision></link>"
             "<link name=\"m3\"><collision><geometry>"
             "<mesh filename=\"file://%s\"/></geometry></collision></link>"
             "<joint name=\"j1\" type=\"fixed\"><parent link=\"root\"/><child link=\"m1\"/>"
             "<origin xyz=\"0.5 0 0\"/></joint>"
             "<joint name=\"j2\" type=\"fixed\"><parent link=\"root\"/><child link=\"m2\"/>"
             "<origin xyz=\"0 0.6 0\"/></joint>"
             "<joint name=\"j3\" type=\"fixed\"><parent link=\"root\"/><child link=\"m3\"/>"
             "<origin xyz=\"0 0 0.7\" rpy=\"0 0 1\"/></joint></robot>",
             abs_stl);
    return xml;
}

/* dir/pkgs/mypkg/meshes/tetra.{stl,obj}; the URDF at dir/pkgs/mypkg/robot.urdf. */
static const char *write_mesh_package(const scratch_dir *d) {
    static char stl[256];
    make_scratch_subdir(d, "pkgs/mypkg/meshes");
    snprintf(stl, sizeof stl, "%s", write_scratch(d, "pkgs/mypkg/meshes/tetra.stl", TETRA_STL));
    write_scratch(d, "pkgs/mypkg/meshes/tetra.obj", TETRA_OBJ);
    return write_scratch(d, "pkgs/mypkg/robot.urdf", mesh_urdf(stl));
}

/* The meshes added by hand, scaled, at the URDF set's poses, answer the
 * same per-link distances (all finite: the robot sits near the cell). */
static void assert_meshes_match_hand_built(const opx_linkset *robot) {
    static double scaled[12];
    for (int i = 0; i < 4; ++i) {
        scaled[3 * i] = 2.0 * TETRA[3 * i];
        scaled[3 * i + 1] = TETRA[3 * i + 1];
        scaled[3 * i + 2] = 3.0 * TETRA[3 * i + 2];
    }
    opx_linkset *hand = new_linkset();
    add_link(hand, "root");
    for (int i = 1; i <= 3; ++i) add_link(hand, "m");
    opx_shape first = mesh_shape(scaled, 4, 0, TETRA_FACES, 4);
    first.pose.position[0] = 0.1;
    add_shape(hand, 1, first);
    add_shape(hand, 2, mesh_shape(TETRA, 4, 0, TETRA_FACES, 4));
    add_shape(hand, 3, mesh_shape(TETRA, 4, 0, TETRA_FACES, 4));
    opx_pose poses[4];
    for (uint32_t i = 0; i < 4; ++i) poses[i] = get_pose(robot, i);
    assert_ok(opx_linkset_set_poses(hand, poses, 4, 0));
    /* The stored mesh: 4 triangles over the 4 scaled corners (float precision). */
    opx_shape stored = OPX_SHAPE_INIT;
    assert_ok(opx_linkset_get_shape(robot, 1, 0, &stored));
    assert_int_equal(stored.kind, OPX_SHAPE_MESH);
    assert_int_equal(stored.vertex_count, 4);
    assert_int_equal(stored.triangle_count, 4);
    double max[3] = {0, 0, 0};
    for (size_t v = 0; v < 4; ++v)
        for (int k = 0; k < 3; ++k) max[k] = fmax(max[k], stored.vertices[3 * v + k]);
    assert_near(max[0], 0.2, 1e-7);
    assert_near(max[1], 0.1, 1e-7);
    assert_near(max[2], 0.3, 1e-7);
    assert_true(stored.pose.position[0] == 0.1);
    const linkset_snapshot a = take_linkset_snapshot(robot), b = take_linkset_snapshot(hand);
    for (uint32_t i = 1; i < 4; ++i) {
        assert_true(isfinite(a.link_distance[i]));
        /* assimp reads vertices as float: ~1e-8 m off the decimal values. */
        assert_near(a.link_distance[i], b.link_distance[i], 1e-6);
    }
    opx_linkset_destroy(hand);
}

static opx_linkset *load_with_package_dir(const char *urdf_path, const char *package_dir) {
    const char *dirs[2] = {"/nonexistent/first", package_dir};
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.package_dirs = dirs;
    options.package_dir_count = 2;
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_file(urdf_path, &options, &robot));
    assert_int_equal(link_count(robot), 4);
    return robot;
}

static void meshes_resolve_by_every_path_form(void **state) {
    (void)state;
    const scratch_dir d = make_scratch_dir();
    char urdf_path[256], dir[256];
    snprintf(urdf_path, sizeof urdf_path, "%s", write_mesh_package(&d));
    /* DIR holding the package folder; DIR that is the package; NAME=DIR. */
    snprintf(dir, sizeof dir, "%s/pkgs", d.path);
    opx_linkset *robot = load_with_package_dir(urdf_path, dir);
    const opx_pose base = pose_at(0.05, 0.05, -0.4);
    const double zeros[3] = {0, 0, 0}; /* three fixed joints */
    assert_ok(opx_linkset_set_joint_positions(robot, zeros, 3, &base));
    assert_meshes_match_hand_built(robot);
    opx_linkset_destroy(robot);

    snprintf(dir, sizeof dir, "%s/pkgs/mypkg/", d.path);
    robot = load_with_package_dir(urdf_path, dir);
    assert_meshes_match_hand_built(robot);
    opx_linkset_destroy(robot);

    snprintf(dir, sizeof dir, "mypkg=%s/pkgs/mypkg", d.path);
    robot = load_with_package_dir(urdf_path, dir);
    assert_meshes_match_hand_built(robot);
    opx_linkset_destroy(robot);
    remove_scratch_dir(&d);
}

/* A string has no folder: relative meshes need options->base_dir. */
static void a_string_uses_base_dir_for_relative_meshes(void **state) {
    (void)state;
    const scratch_dir d = make_scratch_dir();
    char urdf_path[256], base[256], pkgs[256];
    snprintf(urdf_path, sizeof urdf_path, "%s", write_mesh_package(&d));
    snprintf(base, sizeof base, "%s/pkgs/mypkg", d.path);
    snprintf(pkgs, sizeof pkgs, "%s/pkgs", d.path);
    char stl[320];
    snprintf(stl, sizeof stl, "%s/meshes/tetra.stl", base);
    const char *dirs[1] = {pkgs};
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.package_dirs = dirs;
    options.package_dir_count = 1;
    opx_linkset *robot = NULL;
    /* Without base_dir, "meshes/tetra.stl" is looked up in the current folder. */
    expect_failure(OPX_ERROR_IO, "opx_linkset_load_urdf_string", "meshes/tetra.stl",
                   opx_linkset_load_urdf_string(mesh_urdf(stl), &options, &robot));
    assert_null(robot);
    options.base_dir = base;
    assert_ok(opx_linkset_load_urdf_string(mesh_urdf(stl), &options, &robot));
    assert_meshes_match_hand_built(robot);
    opx_linkset_destroy(robot);
    remove_scratch_dir(&d);
}

/* A Collada triangle in centimetres, z up, under a node moved 10 cm up. */
static const char TRIANGLE_DAE[] =
    "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
    "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
    "<asset><unit name=\"centimeter\" meter=\"0.01\"/><up_axis>Z_UP</up_axis></asset>\n"
    "<library_geometries><geometry id=\"tri\"><mesh>\n"
    "<source id=\"pos\"><float_array id=\"pos-array\" count=\"9\">0 0 0 100 0 0 0 0 50</float_array>\n"
    "<technique_common><accessor source=\"#pos-array\" count=\"3\" stride=\"3\">"
    "<param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" type=\"float\"/>"
    "</accessor></technique_common></source>\n"
    "<vertices id=\"vtx\"><input semantic=\"POSITION\" source=\"#pos\"/></vertices>\n"
    "<triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#vtx\" offset=\"0\"/><p>0 1 2</p></triangles>\n"
    "</mesh></geometry></library_geometries>\n"
    "<library_visual_scenes><visual_scene id=\"scene\"><node id=\"n\"><translate>0 0 10</translate>"
    "<instance_geometry url=\"#tri\"/></node></visual_scene></library_visual_scenes>\n"
    "<scene><instance_visual_scene url=\"#scene\"/></scene>\n"
    "</COLLADA>\n";

/* The DAE's unit and node transform apply; its up axis does not rotate it. */
static void dae_units_and_nodes_apply_z_stays_up(void **state) {
    (void)state;
    const scratch_dir d = make_scratch_dir();
    write_scratch(&d, "tri.dae", TRIANGLE_DAE);
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.base_dir = d.path;
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string("<robot name=\"r\"><link name=\"a\"><collision><geometry>"
                                           "<mesh filename=\"tri.dae\"/></geometry></collision></link></robot>",
                                           &options, &robot));
    opx_shape s = OPX_SHAPE_INIT;
    assert_ok(opx_linkset_get_shape(robot, 0, 0, &s));
    assert_int_equal(s.kind, OPX_SHAPE_MESH);
    assert_int_equal(s.triangle_count, 1);
    assert_int_equal(s.vertex_count, 3);
    static const double expected[9] = {0, 0, 0.1, 1, 0, 0.1, 0, 0, 0.6};
    for (int v = 0; v < 3; ++v)
        for (int k = 0; k < 3; ++k)
            assert_near(s.vertices[3 * s.indices[v] + k], expected[3 * v + k], 1e-7);
    opx_linkset_destroy(robot);
    remove_scratch_dir(&d);
}

static void srdf_disabled_pairs_are_read(void **state) {
    (void)state;
    const scratch_dir d = make_scratch_dir();
    const char *srdf = write_scratch(&d, "test.srdf",
                                     "<?xml version=\"1.0\"?><robot name=\"test\">"
                                     "<group name=\"arm\"><joint name=\"shoulder\"/></group>"
                                     "<disable_collisions link1=\"base\" link2=\"arm\" reason=\"Adjacent\"/>"
                                     "<disable_collisions link1=\"tool\" link2=\"wheel\" reason=\"Never\"/>"
                                     "</robot>");
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.srdf_path = srdf;
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string(TEST_URDF, &options, &robot));
    uint32_t count = 0, a = 99, b = 99;
    assert_ok(opx_linkset_get_disabled_pair_count(robot, &count));
    assert_int_equal(count, 2);
    assert_ok(opx_linkset_get_disabled_pair(robot, 0, &a, &b));
    assert_int_equal(a, L_BASE);
    assert_int_equal(b, L_ARM);
    assert_ok(opx_linkset_get_disabled_pair(robot, 1, &a, &b));
    assert_int_equal(a, L_TOOL);
    assert_int_equal(b, L_WHEEL);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_linkset_get_disabled_pair", "pair 2",
                   opx_linkset_get_disabled_pair(robot, 2, &a, &b));
    opx_linkset_destroy(robot);

    /* Without an SRDF: no pairs. */
    robot = load_test_robot();
    assert_ok(opx_linkset_get_disabled_pair_count(robot, &count));
    assert_int_equal(count, 0);
    opx_linkset_destroy(robot);
    remove_scratch_dir(&d);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(meshes_resolve_by_every_path_form),
        cmocka_unit_test(a_string_uses_base_dir_for_relative_meshes),
        cmocka_unit_test(dae_units_and_nodes_apply_z_stays_up),
        cmocka_unit_test(srdf_disabled_pairs_are_read),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
