/*
 * opx_linkset_add_shape: every invalid shape is rejected, named in the
 * message, and leaves the link set unchanged; valid shapes of every kind
 * are placed where their pose says (shape pose inside link pose).
 */
#include "opx_query_test.h"

static const char *const FN = "opx_linkset_add_shape";

static const double BAD_LENGTHS[] = {0.0, -0.0, -1e-3, -1.0, NAN, INFINITY, -INFINITY};
#define N_BAD_LENGTHS (sizeof BAD_LENGTHS / sizeof BAD_LENGTHS[0])

/* Adds `shape` to link 1 of the robot, expects `expected` naming `argument`,
 * and checks the robot did not change. */
static void expect_shape_fails(opx_shape shape, opx_status expected, const char *argument) {
    opx_linkset *robot = new_robot();
    const linkset_snapshot before = robot_snapshot(robot);
    uint32_t index = 77;
    expect_failure(expected, FN, argument, opx_linkset_add_shape(robot, 1, &shape, &index));
    assert_int_equal(index, 77);
    assert_linkset_unchanged(robot, &before);
    opx_linkset_destroy(robot);
}

static void rejects_null_links_shape_and_bad_link(void **state) {
    (void)state;
    const opx_shape sphere = sphere_shape(0.1);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "links", opx_linkset_add_shape(NULL, 0, &sphere, NULL));
    opx_linkset *robot = new_robot();
    const linkset_snapshot before = robot_snapshot(robot);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "shape", opx_linkset_add_shape(robot, 0, NULL, NULL));
    const uint32_t bad[] = {3, 4, UINT32_MAX};
    for (size_t i = 0; i < 3; ++i)
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "link", opx_linkset_add_shape(robot, bad[i], &sphere, NULL));
    assert_linkset_unchanged(robot, &before);
    opx_linkset_destroy(robot);
    /* No link at all yet. */
    opx_linkset *empty = new_linkset();
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "link", opx_linkset_add_shape(empty, 0, &sphere, NULL));
    assert_int_equal(link_count(empty), 0);
    opx_linkset_destroy(empty);
}

static void rejects_struct_size_zero(void **state) {
    (void)state;
    opx_shape shape = sphere_shape(0.1);
    shape.struct_size = 0;
    expect_shape_fails(shape, OPX_ERROR_VERSION, "struct_size");
    shape.struct_size = 3;
    expect_shape_fails(shape, OPX_ERROR_VERSION, "struct_size");
}

static void rejects_bad_kind(void **state) {
    (void)state;
    const int32_t bad[] = {0, -1, 7, 100, INT32_MIN};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        opx_shape shape = sphere_shape(0.1);
        shape.kind = bad[i];
        expect_shape_fails(shape, OPX_ERROR_INVALID_ARGUMENT, "kind");
    }
}

static void rejects_bad_sphere_radius(void **state) {
    (void)state;
    for (size_t i = 0; i < N_BAD_LENGTHS; ++i)
        expect_shape_fails(sphere_shape(BAD_LENGTHS[i]), OPX_ERROR_INVALID_ARGUMENT, "radius");
}

static void rejects_bad_box_size(void **state) {
    (void)state;
    for (size_t i = 0; i < N_BAD_LENGTHS; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            opx_shape shape = box_shape(0.1, 0.2, 0.3);
            shape.size[axis] = BAD_LENGTHS[i];
            expect_shape_fails(shape, OPX_ERROR_INVALID_ARGUMENT, "size");
        }
    }
}

static void rejects_bad_cylinder(void **state) {
    (void)state;
    for (size_t i = 0; i < N_BAD_LENGTHS; ++i) {
        expect_shape_fails(cylinder_shape(BAD_LENGTHS[i], 0.2), OPX_ERROR_INVALID_ARGUMENT, "radius");
        expect_shape_fails(cylinder_shape(0.1, BAD_LENGTHS[i]), OPX_ERROR_INVALID_ARGUMENT, "length");
    }
}

/* A capsule's length is the cylindrical part: 0 is a sphere (valid), so
 * only negative and non-finite lengths are rejected. */
static void rejects_bad_capsule(void **state) {
    (void)state;
    for (size_t i = 0; i < N_BAD_LENGTHS; ++i) {
        expect_shape_fails(capsule_shape(BAD_LENGTHS[i], 0.2), OPX_ERROR_INVALID_ARGUMENT, "radius");
        if (BAD_LENGTHS[i] == 0.0) continue;
        expect_shape_fails(capsule_shape(0.1, BAD_LENGTHS[i]), OPX_ERROR_INVALID_ARGUMENT, "length");
    }
}

/* Checks common to convex hulls and meshes. */
static void expect_vertex_failures(int32_t kind) {
    opx_shape base = mesh_shape(TETRA, 4, 0, TETRA_FACES, 4);
    base.kind = kind;
    opx_shape s = base;
    s.vertices = NULL;
    expect_shape_fails(s, OPX_ERROR_INVALID_ARGUMENT, "vertices");
    s = base;
    s.vertex_count = 0;
    expect_shape_fails(s, OPX_ERROR_INVALID_ARGUMENT, "vertex_count");
    s.vertices = NULL;
    expect_shape_fails(s, OPX_ERROR_INVALID_ARGUMENT, "vertex_count");
    const size_t bad_strides[] = {1, 8, 16, 23};
    for (size_t i = 0; i < 4; ++i) {
        s = base;
        s.vertex_stride = bad_strides[i];
        expect_shape_fails(s, OPX_ERROR_INVALID_ARGUMENT, "vertex_stride");
    }
    /* A non-finite coordinate in any vertex, read with a stride of 32. */
    const double bad[] = {NAN, INFINITY, -INFINITY};
    for (size_t b = 0; b < 3; ++b) {
        for (size_t v = 0; v < 4; ++v) {
            double strided[16];
            for (size_t i = 0; i < 4; ++i) {
                memcpy(&strided[4 * i], &TETRA[3 * i], 3 * sizeof(double));
                strided[4 * i + 3] = NAN; /* ignored: beyond x, y, z */
            }
            strided[4 * v + (v % 3)] = bad[b];
            s = base;
            s.vertices = strided;
            s.vertex_stride = 4 * sizeof(double);
            expect_shape_fails(s, OPX_ERROR_INVALID_ARGUMENT, "vertices");
        }
    }
}

static void rejects_bad_convex(void **state) {
    (void)state;
    expect_vertex_failures(OPX_SHAPE_CONVEX);
}

static void rejects_bad_mesh(void **state) {
    (void)state;
    expect_vertex_failures(OPX_SHAPE_MESH);
    const opx_shape base = mesh_shape(TETRA, 4, 0, TETRA_FACES, 4);
    opx_shape s = base;
    s.triangle_count = 0;
    expect_shape_fails(s, OPX_ERROR_INVALID_ARGUMENT, "triangle_count");
    s = base;
    s.indices = NULL;
    expect_shape_fails(s, OPX_ERROR_INVALID_ARGUMENT, "indices");
    /* An index == vertex_count, in the last triangle; and a huge one. */
    uint32_t faces[12];
    memcpy(faces, TETRA_FACES, sizeof faces);
    faces[11] = 4;
    s = base;
    s.indices = faces;
    expect_shape_fails(s, OPX_ERROR_INVALID_ARGUMENT, "indices");
    faces[11] = 3;
    faces[0] = UINT32_MAX;
    expect_shape_fails(s, OPX_ERROR_INVALID_ARGUMENT, "indices");
    /* Valid indices, but fewer vertices than they reach. */
    s = base;
    s.vertex_count = 3;
    expect_shape_fails(s, OPX_ERROR_INVALID_ARGUMENT, "indices");
}

static void rejects_bad_shape_pose(void **state) {
    (void)state;
    const double bad[] = {NAN, INFINITY, -INFINITY};
    for (size_t b = 0; b < 3; ++b) {
        for (int axis = 0; axis < 3; ++axis) {
            opx_shape s = sphere_shape(0.1);
            s.pose.position[axis] = bad[b];
            expect_shape_fails(s, OPX_ERROR_INVALID_ARGUMENT, "pose");
        }
        for (int c = 0; c < 4; ++c) {
            opx_shape s = box_shape(0.1, 0.1, 0.1);
            s.pose.orientation[c] = bad[b];
            expect_shape_fails(s, OPX_ERROR_INVALID_ARGUMENT, "pose");
        }
    }
    opx_shape s = convex_shape(TETRA, 4, 0);
    s.pose.orientation[3] = 0.0;
    expect_shape_fails(s, OPX_ERROR_INVALID_ARGUMENT, "pose");
}

/* ---- Valid shapes ------------------------------------------------------ */

/* Every kind is accepted; indices count per link; the caller's arrays are
 * copied (overwriting them afterwards changes nothing). */
static void adds_every_kind(void **state) {
    (void)state;
    opx_linkset *links = new_linkset();
    add_link(links, "a");
    add_link(links, "b");
    double vertices[12];
    uint32_t faces[12];
    memcpy(vertices, TETRA, sizeof vertices);
    memcpy(faces, TETRA_FACES, sizeof faces);
    assert_int_equal(add_shape(links, 1, sphere_shape(0.1)), 0);
    assert_int_equal(add_shape(links, 1, box_shape(0.1, 0.2, 0.3)), 1);
    assert_int_equal(add_shape(links, 0, cylinder_shape(0.1, 0.2)), 0);
    assert_int_equal(add_shape(links, 1, capsule_shape(0.1, 0.0)), 2);
    assert_int_equal(add_shape(links, 1, convex_shape(vertices, 4, 0)), 3);
    assert_int_equal(add_shape(links, 1, mesh_shape(vertices, 4, 0, faces, 4)), 4);
    opx_shape s = sphere_shape(0.2);
    assert_ok(opx_linkset_add_shape(links, 0, &s, NULL)); /* out_shape may be NULL */
    uint32_t count = 0;
    assert_ok(opx_linkset_get_shape_count(links, 0, &count));
    assert_int_equal(count, 2);
    assert_ok(opx_linkset_get_shape_count(links, 1, &count));
    assert_int_equal(count, 5);
    /* The hull and mesh sit at link b: 0.75 from the cell (x = 1.0 + 0). */
    const opx_pose poses[2] = {pose_at(-5, -5, -5), pose_at(1.0, C0, C0)};
    assert_ok(opx_linkset_set_poses(links, poses, 2, 0));
    memset(vertices, 0, sizeof vertices);
    memset(faces, 0xFF, sizeof faces);
    opx_octree *tree = new_one_cell_map();
    opx_query *query = new_query();
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.per_link = 1;
    const opx_distance_result d = distance_with(query, tree, links, &request);
    assert_int_equal(d.link, 1);
    assert_near(d.distance, 0.65, 1e-9); /* the sphere r 0.1 at x = 1.0 */
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    opx_linkset_destroy(links);
}

/* Shape pose composed with the link pose: the link at (2, C0, C0) turned
 * 90 degrees about z (quaternion 0 0 3 3), which maps (0, -1.75, 0) in the link frame to
 * (1.75, 0, 0): a sphere r 0.1 there is centred at (3.75, C0, C0), 3.4 from
 * the cell face x = 0.25. */
static void shape_pose_is_in_the_link_frame(void **state) {
    (void)state;
    opx_linkset *links = new_linkset();
    add_link(links, "l");
    opx_shape s = sphere_shape(0.1);
    s.pose = pose_at(0.0, -1.75, 0.0);
    add_shape(links, 0, s);
    opx_pose pose = pose_at(2.0, C0, C0);
    pose.orientation[2] = 3.0; /* not unit: normalised by the library */
    pose.orientation[3] = 3.0;
    assert_ok(opx_linkset_set_poses(links, &pose, 1, 0));
    opx_octree *tree = new_one_cell_map();
    opx_query *query = new_query();
    const opx_distance_result d = distance_with(query, tree, links, NULL);
    assert_int_equal(d.found, 1);
    assert_near(d.distance, 3.4, 1e-9);
    assert_center(d.point_on_link, 3.65, C0, C0);
    assert_center(d.point_on_cell, 0.25, C0, C0);
    /* A box 1 x 0.2 x 0.2 (full edges) turned in its shape frame by 90
     * degrees about y: 1 m along z in the map.  At (C0, C0, 0.85) its
     * bottom is at z = 0.35: 0.1 from the cell.  A cylinder r 0.05 of full
     * length 0.5 at (C0 + 5, C0, 0.6) spans z 0.35..0.85: its closest point
     * (5.075, C0, 0.35) is 4.825 from the cell in x and 0.1 in z. */
    opx_linkset *box = new_linkset();
    add_link(box, "b");
    s = box_shape(1.0, 0.2, 0.2);
    s.pose.orientation[1] = sqrt(0.5);
    s.pose.orientation[3] = sqrt(0.5);
    add_shape(box, 0, s);
    add_link(box, "c");
    add_shape(box, 1, cylinder_shape(0.05, 0.5));
    const opx_pose two[2] = {pose_at(C0, C0, 0.85), pose_at(C0 + 5.0, C0, 0.6)};
    assert_ok(opx_linkset_set_poses(box, two, 2, 0));
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.per_link = 1;
    const opx_distance_result e = distance_with(query, tree, box, &request);
    assert_near(e.distance, 0.1, 1e-9);
    double per_link[2] = {0.0, 0.0};
    size_t count = 0;
    assert_ok(opx_query_get_link_distances(query, per_link, 2, &count));
    assert_int_equal(count, 2);
    assert_near(per_link[0], 0.1, 1e-9);
    assert_near(per_link[1], sqrt(0.1 * 0.1 + 4.825 * 4.825), 1e-6);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    opx_linkset_destroy(box);
    opx_linkset_destroy(links);
}

/* A mesh is a surface: the cell lies wholly inside this tetrahedron (its
 * faces x, y, z = -1 and x + y + z = 1 are at least 0.25 from the cell) and
 * touches no triangle; the convex hull of the same vertices is solid. */
static void mesh_is_a_surface_convex_is_solid(void **state) {
    (void)state;
    static const double big[12] = {-1, -1, -1, 3, -1, -1, -1, 3, -1, -1, -1, 3};
    opx_octree *tree = new_one_cell_map();
    opx_linkset *mesh = new_linkset();
    add_shape(mesh, add_link(mesh, "m"), mesh_shape(big, 4, 0, TETRA_FACES, 4));
    opx_linkset *hull = new_linkset();
    add_shape(hull, add_link(hull, "h"), convex_shape(big, 4, 0));
    const opx_pose identity = OPX_POSE_IDENTITY;
    assert_ok(opx_linkset_set_poses(mesh, &identity, 1, 0));
    assert_ok(opx_linkset_set_poses(hull, &identity, 1, 0));
    assert_false(collides(mesh, tree));
    assert_true(collides(hull, tree));
    opx_query *query = new_query();
    /* The closest face of the mesh, x + y + z = 1, is (1 - 0.75) / sqrt(3)
     * from the cell corner (0.25, 0.25, 0.25). */
    const opx_distance_result d = distance_with(query, tree, mesh, NULL);
    assert_near(d.distance, 0.25 / sqrt(3.0), 1e-9);
    assert_center(d.point_on_cell, 0.25, 0.25, 0.25);
    opx_query_destroy(query);
    opx_linkset_destroy(hull);
    opx_linkset_destroy(mesh);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rejects_null_links_shape_and_bad_link),
        cmocka_unit_test(rejects_struct_size_zero),
        cmocka_unit_test(rejects_bad_kind),
        cmocka_unit_test(rejects_bad_sphere_radius),
        cmocka_unit_test(rejects_bad_box_size),
        cmocka_unit_test(rejects_bad_cylinder),
        cmocka_unit_test(rejects_bad_capsule),
        cmocka_unit_test(rejects_bad_convex),
        cmocka_unit_test(rejects_bad_mesh),
        cmocka_unit_test(rejects_bad_shape_pose),
        cmocka_unit_test(adds_every_kind),
        cmocka_unit_test(shape_pose_is_in_the_link_frame),
        cmocka_unit_test(mesh_is_a_surface_convex_is_solid),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
