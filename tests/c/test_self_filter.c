/* Self-filtering at ingest (opx_insert_options.robot): robot points,
 * shadowed points and kept points, the band's edges per solid kind, the
 * cells the cut rays free, clear_robot_volume, the report, thread
 * independence, the depth-image path and bad input. */
#include "opx_test.h"

#include <octoprox/linkset.h>

static const char *const FN = "opx_octree_insert_points";

/* A robot of one link holding `shape`, its pose set (identity). */
static opx_linkset *robot_with(const opx_shape *shape) {
    opx_linkset *links = NULL;
    assert_ok(opx_linkset_create(&links));
    uint32_t link = 0;
    assert_ok(opx_linkset_add_link(links, "body", &link));
    assert_ok(opx_linkset_add_shape(links, link, shape, NULL));
    const opx_pose identity = OPX_POSE_IDENTITY;
    assert_ok(opx_linkset_set_poses(links, &identity, 1, 0));
    return links;
}

static opx_shape sphere_at(double x, double y, double z, double radius) {
    opx_shape s = OPX_SHAPE_INIT;
    s.kind = OPX_SHAPE_SPHERE;
    s.radius = radius;
    s.pose.position[0] = x, s.pose.position[1] = y, s.pose.position[2] = z;
    return s;
}

static opx_insert_options filtered(const opx_linkset *robot, double padding) {
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    options.robot = robot;
    options.robot_padding = padding;
    return options;
}

static int class_at(const opx_octree *tree, double x, double y, double z) {
    return classify_at(tree, x, y, z).cell_class;
}

/* A sphere of radius 0.2 at (2, 0, 0); the sensor at the origin. */
static void sorts_points_into_robot_shadowed_and_kept(void **state) {
    (void)state;
    const opx_shape ball = sphere_at(2.0, 0.0, 0.0, 0.2);
    opx_linkset *robot = robot_with(&ball);
    opx_octree *tree = new_tree(0.05);
    const double xyz[9] = {1.81, 0.0, 0.0, /* on the ball's near side */
                           3.0, 0.0, 0.0,  /* behind it */
                           1.0, 1.0, 0.0}; /* elsewhere */
    const opx_insert_options options = filtered(robot, 0.0);
    const opx_insert_report r = insert_f64(tree, xyz, 3, &options);
    assert_int_equal(r.points_used, 1);
    assert_int_equal(r.points_on_robot, 1);
    assert_int_equal(r.points_shadowed, 1);
    assert_int_equal(r.cells_hit, 1);
    assert_int_equal(class_at(tree, 1.0, 1.0, 0.0), OPX_CELL_OCCUPIED);
    assert_int_equal(class_at(tree, 1.81, 0.0, 0.0), OPX_CELL_UNKNOWN);
    assert_int_equal(class_at(tree, 3.0, 0.0, 0.0), OPX_CELL_UNKNOWN);
    assert_int_equal(class_at(tree, 2.5, 0.0, 0.0), OPX_CELL_UNKNOWN);
    /* The rays still carve up to the ball (it starts at x = 1.8). */
    assert_int_equal(class_at(tree, 1.0, 0.0, 0.0), OPX_CELL_FREE);
    assert_int_equal(class_at(tree, 1.72, 0.0, 0.0), OPX_CELL_FREE);
    opx_octree_destroy(tree);
    opx_linkset_destroy(robot);
}

/* Without a robot the same frame occupies all three cells. */
static void without_a_robot_every_point_counts(void **state) {
    (void)state;
    opx_octree *tree = new_tree(0.05);
    const double xyz[9] = {1.81, 0.0, 0.0, 3.0, 0.0, 0.0, 1.0, 1.0, 0.0};
    const opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    const opx_insert_report r = insert_f64(tree, xyz, 3, &options);
    assert_int_equal(r.points_used, 3);
    assert_int_equal(r.points_on_robot + r.points_shadowed + r.cells_cleared, 0);
    assert_int_equal(class_at(tree, 1.81, 0.0, 0.0), OPX_CELL_OCCUPIED);
    opx_octree_destroy(tree);
}

/* A point in front of the shape on the ray through `toward`, at distance
 * `gap` from the padded solid's near face (negative: inside). */
static opx_insert_report one_point(const opx_shape *shape, double padding, double near_face, double gap) {
    opx_linkset *robot = robot_with(shape);
    opx_octree *tree = new_tree(0.05);
    const double xyz[3] = {near_face - padding - gap, 0.0, 0.0};
    const opx_insert_options options = filtered(robot, padding);
    const opx_insert_report r = insert_f64(tree, xyz, 1, &options);
    opx_octree_destroy(tree);
    opx_linkset_destroy(robot);
    return r;
}

/* padding - 1e-6 from the solid: a robot point; padding + 1e-6: kept. */
static void expect_band_edge(const opx_shape *shape, double near_face) {
    const double padding = 0.05;
    opx_insert_report inside = one_point(shape, padding, near_face, -1e-6);
    assert_int_equal(inside.points_on_robot, 1);
    assert_int_equal(inside.points_used, 0);
    opx_insert_report outside = one_point(shape, padding, near_face, 1e-6);
    assert_int_equal(outside.points_on_robot + outside.points_shadowed, 0);
    assert_int_equal(outside.points_used, 1);
}

static void band_edges_are_exact_for_every_solid(void **state) {
    (void)state;
    const opx_shape ball = sphere_at(2.0, 0.0, 0.0, 0.2);
    expect_band_edge(&ball, 1.8);

    opx_shape box = OPX_SHAPE_INIT;
    box.kind = OPX_SHAPE_BOX;
    box.size[0] = 0.4, box.size[1] = 0.3, box.size[2] = 0.2;
    box.pose.position[0] = 2.0;
    expect_band_edge(&box, 1.8);

    opx_shape cylinder = OPX_SHAPE_INIT; /* axis along z: its round side faces the sensor */
    cylinder.kind = OPX_SHAPE_CYLINDER;
    cylinder.radius = 0.2, cylinder.length = 0.5;
    cylinder.pose.position[0] = 2.0;
    expect_band_edge(&cylinder, 1.8);

    opx_shape capsule = cylinder;
    capsule.kind = OPX_SHAPE_CAPSULE;
    expect_band_edge(&capsule, 1.8);

    /* A convex hull: a tetrahedron with a face square to the ray at x = 1.8. */
    static const double corners[12] = {1.8, -0.3, -0.3, 1.8, 0.3, -0.3, 1.8, 0.0, 0.4, 2.4, 0.0, 0.0};
    opx_shape hull = OPX_SHAPE_INIT;
    hull.kind = OPX_SHAPE_CONVEX;
    hull.vertices = corners, hull.vertex_count = 4;
    expect_band_edge(&hull, 1.8);

    /* The same tetrahedron as a closed mesh. */
    static const uint32_t faces[12] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3};
    opx_shape mesh = hull;
    mesh.kind = OPX_SHAPE_MESH;
    mesh.indices = faces, mesh.triangle_count = 4;
    expect_band_edge(&mesh, 1.8);
}

/* A closed mesh is a solid: a point deep inside is a robot point. */
static void a_closed_mesh_holds_its_inside(void **state) {
    (void)state;
    static const double corners[24] = {1, -1, -1, 3, -1, -1, 3, 1, -1, 1, 1, -1,
                                       1, -1, 1,  3, -1, 1,  3, 1, 1,  1, 1, 1};
    static const uint32_t faces[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                       1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
    opx_shape cube = OPX_SHAPE_INIT;
    cube.kind = OPX_SHAPE_MESH;
    cube.vertices = corners, cube.vertex_count = 8;
    cube.indices = faces, cube.triangle_count = 12;
    opx_linkset *robot = robot_with(&cube);
    opx_octree *tree = new_tree(0.05);
    const double xyz[6] = {2.0, 0.0, 0.0, /* the cube's centre, 1 m from every face */
                           5.0, 0.0, 0.0}; /* behind it */
    const opx_insert_options options = filtered(robot, 0.0);
    const opx_insert_report r = insert_f64(tree, xyz, 2, &options);
    assert_int_equal(r.points_on_robot, 1);
    assert_int_equal(r.points_shadowed, 1);
    assert_int_equal(class_at(tree, 0.5, 0.0, 0.0), OPX_CELL_FREE);
    assert_int_equal(class_at(tree, 1.5, 0.0, 0.0), OPX_CELL_UNKNOWN);
    opx_octree_destroy(tree);
    opx_linkset_destroy(robot);
}

/* An obstacle where the arm then stands: cleared with clear_robot_volume,
 * left without it. */
static void clears_the_robot_volume_only_when_asked(void **state) {
    (void)state;
    for (int clear = 0; clear < 2; ++clear) {
        opx_octree *tree = new_tree(0.05);
        double wall[3 * 81];
        for (int i = 0; i < 81; ++i) {
            wall[3 * i] = 2.0, wall[3 * i + 1] = -0.2 + 0.05 * (i % 9), wall[3 * i + 2] = -0.2 + 0.05 * (i / 9);
        }
        const opx_insert_options plain = OPX_INSERT_OPTIONS_INIT;
        insert_f64(tree, wall, 81, &plain);
        assert_int_equal(class_at(tree, 2.0, 0.0, 0.0), OPX_CELL_OCCUPIED);
        const opx_shape ball = sphere_at(2.0, 0.0, 0.0, 0.3);
        opx_linkset *robot = robot_with(&ball);
        opx_insert_options options = filtered(robot, 0.0);
        options.clear_robot_volume = (uint32_t)clear;
        const double far_point[3] = {0.0, 3.0, 0.0};
        const opx_insert_report r = insert_f64(tree, far_point, 1, &options);
        const opx_cell_info cell = classify_at(tree, 2.0, 0.0, 0.0);
        if (clear) {
            assert_true(r.cells_cleared > 0);
            assert_int_equal(cell.cell_class, OPX_CELL_FREE);
            assert_true(fabs(cell.probability - 0.1192) < 1e-3);
        } else {
            assert_int_equal(r.cells_cleared, 0);
            assert_int_equal(cell.cell_class, OPX_CELL_OCCUPIED);
        }
        /* A wall cell only partly inside the ball stays. */
        assert_int_equal(class_at(tree, 2.0, 0.2, 0.2), OPX_CELL_OCCUPIED);
        opx_octree_destroy(tree);
        opx_linkset_destroy(robot);
    }
}

/* Many random points around a few shapes: the same map on 1 and 2 threads. */
static void results_do_not_depend_on_threads(void **state) {
    (void)state;
    const opx_shape ball = sphere_at(1.5, 0.2, 0.1, 0.35);
    opx_linkset *robot = robot_with(&ball);
    enum { N = 40000 };
    double *xyz = malloc(3 * N * sizeof *xyz);
    assert_non_null(xyz);
    unsigned seed = 12345u;
    for (int i = 0; i < 3 * N; ++i) {
        seed = seed * 1103515245u + 12345u;
        const double unit = (double)(seed >> 8) / 16777216.0;
        xyz[i] = (i % 3 == 0) ? 0.5 + 3.0 * unit : -1.5 + 3.0 * unit;
    }
    byte_buffer maps[2];
    opx_insert_report reports[2];
    for (int t = 0; t < 2; ++t) {
        opx_octree *tree = new_tree(0.05);
        opx_insert_options options = filtered(robot, 0.02);
        options.max_threads = (uint32_t)(t + 1);
        options.clear_robot_volume = 1;
        reports[t] = insert_f64(tree, xyz, N, &options);
        maps[t] = save_to_memory(tree, OPX_FORMAT_OT);
        opx_octree_destroy(tree);
    }
    assert_true(reports[0].points_on_robot > 0 && reports[0].points_shadowed > 0);
    assert_int_equal(reports[0].points_used + reports[0].points_on_robot + reports[0].points_shadowed, N);
    assert_memory_equal(&reports[0], &reports[1], sizeof reports[0]);
    assert_int_equal(maps[0].size, maps[1].size);
    assert_memory_equal(maps[0].data, maps[1].data, maps[0].size);
    free(maps[0].data), free(maps[1].data), free(xyz);
    opx_linkset_destroy(robot);
}

/* A depth image whose centre pixels see the ball. */
static void filters_depth_images(void **state) {
    (void)state;
    const opx_shape ball = sphere_at(0.0, 0.0, 2.0, 0.3); /* 2 m along the optical axis */
    opx_linkset *robot = robot_with(&ball);
    uint16_t depth[9 * 9];
    for (int i = 0; i < 81; ++i) depth[i] = 3000; /* 3 m: behind the ball at the centre */
    depth[4 * 9 + 4] = 1750;                      /* on the ball's near side */
    opx_depth_image image = OPX_DEPTH_IMAGE_INIT;
    image.data = depth, image.width = 9, image.height = 9;
    opx_camera_intrinsics k = OPX_CAMERA_INTRINSICS_INIT;
    k.fx = k.fy = 10.0, k.cx = k.cy = 4.0;
    opx_octree *tree = new_tree(0.05);
    const opx_insert_options options = filtered(robot, 0.0);
    opx_insert_report r = OPX_INSERT_REPORT_INIT;
    assert_ok(opx_octree_insert_depth_image(tree, &image, &k, &options, &r));
    assert_int_equal(r.points_on_robot, 1);
    assert_true(r.points_shadowed > 0);
    assert_int_equal(r.points_used + r.points_on_robot + r.points_shadowed, 81);
    opx_octree_destroy(tree);
    opx_linkset_destroy(robot);
}

static void rejects_bad_robot_options(void **state) {
    (void)state;
    const double xyz[3] = {1.0, 0.0, 0.0};
    const opx_shape ball = sphere_at(2.0, 0.0, 0.0, 0.2);
    opx_linkset *robot = robot_with(&ball);
    const double bad_padding[] = {-0.01, NAN, INFINITY};
    for (size_t i = 0; i < 3; ++i) {
        opx_octree *tree = new_sample_map();
        map_snapshot before = take_snapshot(tree);
        const opx_insert_options options = filtered(robot, bad_padding[i]);
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "robot_padding",
                       opx_octree_insert_points(tree, xyz, 1, 0, OPX_SCALAR_FLOAT64, &options, NULL));
        assert_unchanged(tree, &before);
        opx_octree_destroy(tree);
    }
    opx_octree *tree = new_sample_map();
    map_snapshot before = take_snapshot(tree);
    opx_insert_options clear_alone = OPX_INSERT_OPTIONS_INIT;
    clear_alone.clear_robot_volume = 1;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "clear_robot_volume",
                   opx_octree_insert_points(tree, xyz, 1, 0, OPX_SCALAR_FLOAT64, &clear_alone, NULL));
    opx_linkset *unposed = NULL;
    assert_ok(opx_linkset_create(&unposed));
    uint32_t link = 0;
    assert_ok(opx_linkset_add_link(unposed, "body", &link));
    assert_ok(opx_linkset_add_shape(unposed, link, &ball, NULL));
    const opx_insert_options no_poses = filtered(unposed, 0.0);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "options.robot",
                   opx_octree_insert_points(tree, xyz, 1, 0, OPX_SCALAR_FLOAT64, &no_poses, NULL));
    assert_unchanged(tree, &before);
    opx_octree_destroy(tree);
    opx_linkset_destroy(unposed);
    opx_linkset_destroy(robot);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sorts_points_into_robot_shadowed_and_kept),
        cmocka_unit_test(without_a_robot_every_point_counts),
        cmocka_unit_test(band_edges_are_exact_for_every_solid),
        cmocka_unit_test(a_closed_mesh_holds_its_inside),
        cmocka_unit_test(clears_the_robot_volume_only_when_asked),
        cmocka_unit_test(results_do_not_depend_on_threads),
        cmocka_unit_test(filters_depth_images),
        cmocka_unit_test(rejects_bad_robot_options),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
