/*
 * opx_linkset_get_shape: every kind comes back as it was added (full box
 * sizes and cylinder lengths, the shape pose, a mesh's used vertices and
 * triangles); bad links, shapes and structs are rejected by name.
 */
#include "opx_query_test.h"

static const char *const FN = "opx_linkset_get_shape";

static opx_linkset *linkset_with_every_kind(void) {
    static const double tetra[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    /* Vertex 4 is used by no triangle: the library drops it. */
    static const double mesh_vertices[5][3] = {{0, 0, 0}, {9, 9, 9}, {1, 0, 0}, {0, 1, 0}, {0, 0, 2}};
    static const uint32_t mesh_indices[6] = {0, 2, 3, 0, 3, 4};
    opx_linkset *links = NULL;
    uint32_t link = 0;
    opx_shape shape = OPX_SHAPE_INIT;
    assert_ok(opx_linkset_create(&links));
    assert_ok(opx_linkset_add_link(links, "base", &link));
    shape.kind = OPX_SHAPE_BOX;
    shape.size[0] = 0.1; shape.size[1] = 0.2; shape.size[2] = 0.3;
    shape.pose.position[2] = 0.5;
    shape.pose.orientation[2] = 1.0; shape.pose.orientation[3] = 1.0; /* 90 deg about z, unnormalised */
    assert_ok(opx_linkset_add_shape(links, link, &shape, NULL));
    shape = (opx_shape)OPX_SHAPE_INIT;
    shape.kind = OPX_SHAPE_CYLINDER;
    shape.radius = 0.05; shape.length = 0.4;
    assert_ok(opx_linkset_add_shape(links, link, &shape, NULL));
    shape = (opx_shape)OPX_SHAPE_INIT;
    shape.kind = OPX_SHAPE_CONVEX;
    shape.vertices = &tetra[0][0]; shape.vertex_count = 4;
    assert_ok(opx_linkset_add_shape(links, link, &shape, NULL));
    shape = (opx_shape)OPX_SHAPE_INIT;
    shape.kind = OPX_SHAPE_MESH;
    shape.vertices = &mesh_vertices[0][0]; shape.vertex_count = 5;
    shape.indices = mesh_indices; shape.triangle_count = 2;
    assert_ok(opx_linkset_add_shape(links, link, &shape, NULL));
    return links;
}

static void returns_every_kind_as_added(void **state) {
    (void)state;
    opx_linkset *links = linkset_with_every_kind();
    opx_shape got = OPX_SHAPE_INIT;
    assert_ok(opx_linkset_get_shape(links, 0, 0, &got));
    assert_int_equal(got.kind, OPX_SHAPE_BOX);
    assert_near(got.size[0], 0.1, OPX_GEOM_TOL);
    assert_near(got.size[1], 0.2, OPX_GEOM_TOL);
    assert_near(got.size[2], 0.3, OPX_GEOM_TOL);
    assert_near(got.pose.position[2], 0.5, OPX_GEOM_TOL);
    assert_near(got.pose.orientation[2], sqrt(0.5), OPX_GEOM_TOL);
    assert_near(got.pose.orientation[3], sqrt(0.5), OPX_GEOM_TOL);
    assert_null(got.vertices);
    assert_ok(opx_linkset_get_shape(links, 0, 1, &got));
    assert_int_equal(got.kind, OPX_SHAPE_CYLINDER);
    assert_near(got.radius, 0.05, OPX_GEOM_TOL);
    assert_near(got.length, 0.4, OPX_GEOM_TOL);
    assert_ok(opx_linkset_get_shape(links, 0, 2, &got));
    assert_int_equal(got.kind, OPX_SHAPE_CONVEX);
    assert_int_equal(got.vertex_count, 4);
    assert_near(got.vertices[3 * 3 + 2], 1.0, 0.0);
    assert_ok(opx_linkset_get_shape(links, 0, 3, &got));
    assert_int_equal(got.kind, OPX_SHAPE_MESH);
    assert_int_equal(got.vertex_count, 4);
    assert_int_equal(got.triangle_count, 2);
    /* The second triangle's last vertex is (0, 0, 2), wherever it went. */
    assert_near(got.vertices[3 * got.indices[5] + 2], 2.0, 0.0);
    opx_linkset_destroy(links);
}

static void rejects_bad_arguments(void **state) {
    (void)state;
    opx_linkset *links = linkset_with_every_kind();
    opx_shape got = OPX_SHAPE_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "links", opx_linkset_get_shape(NULL, 0, 0, &got));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "link 1", opx_linkset_get_shape(links, 1, 0, &got));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "shape 4", opx_linkset_get_shape(links, 0, 4, &got));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "out_shape", opx_linkset_get_shape(links, 0, 0, NULL));
    got.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, FN, "out_shape", opx_linkset_get_shape(links, 0, 0, &got));
    opx_linkset_destroy(links);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(returns_every_kind_as_added),
        cmocka_unit_test(rejects_bad_arguments),
    };
    return cmocka_run_group_tests_name("c_linkset_get_shape", tests, NULL, NULL);
}
