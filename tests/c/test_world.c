/*
 * opx_world: objects, their shapes, poses and flags, and every function's
 * refusal of bad input (NULL, NaN and zero-quaternion poses, indices out of
 * range, bad shapes), each naming the function and the argument and
 * leaving the world as it was.
 */
#include "opx_query_test.h"

static opx_world *new_world(void) {
    opx_world *world = NULL;
    assert_ok(opx_world_create(&world));
    assert_non_null(world);
    return world;
}

static uint32_t add_object(opx_world *world, const char *name, double x, double y, double z) {
    const opx_pose pose = pose_at(x, y, z);
    uint32_t index = UINT32_MAX;
    assert_ok(opx_world_add_object(world, name, &pose, &index));
    return index;
}

static uint32_t object_count(const opx_world *world) {
    uint32_t count = UINT32_MAX;
    assert_ok(opx_world_get_object_count(world, &count));
    return count;
}

static const char *object_name(const opx_world *world, uint32_t object) {
    const char *name = NULL;
    assert_ok(opx_world_get_object_name(world, object, &name));
    return name;
}

static void test_create_and_destroy(void **state) {
    (void)state;
    opx_world_destroy(NULL);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_create", "out", opx_world_create(NULL));
    opx_world *world = new_world();
    assert_int_equal(object_count(world), 0);
    opx_world_destroy(world);
}

static void test_objects_by_index_and_name(void **state) {
    (void)state;
    opx_world *world = new_world();
    assert_int_equal(add_object(world, "table", 1, 0, 0), 0);
    assert_int_equal(add_object(world, "shelf", 2, 0, 0), 1);
    assert_int_equal(add_object(world, "table", 3, 0, 0), 2);
    assert_ok(opx_world_add_object(world, "wall", NULL, NULL));  /* identity pose, no index wanted */
    assert_int_equal(object_count(world), 4);
    assert_string_equal(object_name(world, 1), "shelf");
    uint32_t found = UINT32_MAX;
    assert_ok(opx_world_find_object(world, "table", &found));
    assert_int_equal(found, 0);  /* the first of two */
    opx_pose pose = OPX_POSE_IDENTITY;
    assert_ok(opx_world_get_object_pose(world, 3, &pose));
    assert_center(pose.position, 0, 0, 0);
    assert_near(pose.orientation[3], 1.0, 1e-15);

    /* Removing moves the later objects down by one. */
    assert_ok(opx_world_remove_object(world, 0));
    assert_int_equal(object_count(world), 3);
    assert_string_equal(object_name(world, 0), "shelf");
    assert_ok(opx_world_find_object(world, "table", &found));
    assert_int_equal(found, 1);
    assert_ok(opx_world_get_object_pose(world, found, &pose));
    assert_center(pose.position, 3, 0, 0);

    /* Poses are normalised; flags start enabled. */
    opx_pose turned = {{0.5, -1.0, 2.0}, {0.0, 0.0, 2.0, 2.0}};
    assert_ok(opx_world_set_object_pose(world, 1, &turned));
    assert_ok(opx_world_get_object_pose(world, 1, &pose));
    assert_center(pose.position, 0.5, -1.0, 2.0);
    assert_near(pose.orientation[2], sqrt(0.5), 1e-12);
    assert_near(pose.orientation[3], sqrt(0.5), 1e-12);
    int32_t enabled = -1;
    assert_ok(opx_world_get_object_enabled(world, 2, &enabled));
    assert_int_equal(enabled, 1);
    assert_ok(opx_world_set_object_enabled(world, 2, 0));
    assert_ok(opx_world_get_object_enabled(world, 2, &enabled));
    assert_int_equal(enabled, 0);
    opx_world_destroy(world);
}

static void test_shapes_of_every_kind(void **state) {
    (void)state;
    opx_world *world = new_world();
    const uint32_t object = add_object(world, "bin", 0, 0, 0);
    opx_shape shapes[6] = {sphere_shape(0.1), box_shape(0.1, 0.2, 0.3), cylinder_shape(0.05, 0.4),
                           capsule_shape(0.05, 0.2), convex_shape(TETRA, 4, 0), mesh_shape(TETRA, 4, 0, TETRA_FACES, 4)};
    shapes[1].pose = pose_at(0.0, 0.0, 0.5);
    for (uint32_t i = 0; i < 6; ++i) {
        uint32_t index = UINT32_MAX;
        assert_ok(opx_world_add_shape(world, object, &shapes[i], &index));
        assert_int_equal(index, i);
    }
    uint32_t count = 0;
    assert_ok(opx_world_get_shape_count(world, object, &count));
    assert_int_equal(count, 6);
    opx_shape out = OPX_SHAPE_INIT;
    assert_ok(opx_world_get_shape(world, object, 1, &out));
    assert_int_equal(out.kind, OPX_SHAPE_BOX);
    assert_near(out.size[2], 0.3, 1e-15);
    assert_center(out.pose.position, 0, 0, 0.5);
    assert_ok(opx_world_get_shape(world, object, 2, &out));
    assert_near(out.length, 0.4, 1e-15);
    assert_ok(opx_world_get_shape(world, object, 5, &out));
    assert_int_equal(out.kind, OPX_SHAPE_MESH);
    assert_int_equal(out.vertex_count, 4);
    assert_int_equal(out.triangle_count, 4);
    opx_world_destroy(world);
}

static void test_null_arguments(void **state) {
    (void)state;
    opx_world *world = new_world();
    const uint32_t object = add_object(world, "table", 0, 0, 0);
    const opx_pose pose = OPX_POSE_IDENTITY;
    const opx_shape shape = sphere_shape(0.1);
    uint32_t index = 0;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_object", "world", opx_world_add_object(NULL, "a", &pose, &index));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_object", "name", opx_world_add_object(world, NULL, &pose, &index));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_shape", "world", opx_world_add_shape(NULL, 0, &shape, &index));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_shape", "shape", opx_world_add_shape(world, object, NULL, &index));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_remove_object", "world", opx_world_remove_object(NULL, 0));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_set_object_pose", "pose", opx_world_set_object_pose(world, object, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_get_object_pose", "out_pose", opx_world_get_object_pose(world, object, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_set_object_enabled", "world", opx_world_set_object_enabled(NULL, 0, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_get_object_enabled", "out_enabled", opx_world_get_object_enabled(world, object, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_get_object_count", "out_count", opx_world_get_object_count(world, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_get_object_name", "out_name", opx_world_get_object_name(world, object, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_find_object", "name", opx_world_find_object(world, NULL, &index));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_find_object", "out_object", opx_world_find_object(world, "table", NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_get_shape_count", "out_count", opx_world_get_shape_count(world, object, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_get_shape", "out_shape", opx_world_get_shape(world, object, 0, NULL));
    opx_world *loaded = world;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_load_scene_file", "path", opx_world_load_scene_file(NULL, &loaded));
    assert_null(loaded);
    loaded = world;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_load_scene_memory", "data",
                   opx_world_load_scene_memory(NULL, 4, OPX_SCENE_FORMAT_YAML, &loaded));
    assert_null(loaded);  /* *out is NULL on failure */
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_load_scene_memory", "out",
                   opx_world_load_scene_memory("x", 1, OPX_SCENE_FORMAT_YAML, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_set_world", "query", opx_query_set_world(NULL, world));
    assert_int_equal(object_count(world), 1);
    opx_world_destroy(world);
}

static void test_bad_poses_and_indices(void **state) {
    (void)state;
    opx_world *world = new_world();
    const uint32_t object = add_object(world, "table", 1, 2, 3);
    opx_pose nan_pose = pose_at(NAN, 0, 0);
    opx_pose zero_q = pose_at(0, 0, 0);
    zero_q.orientation[3] = 0.0;
    opx_pose inf_q = OPX_POSE_IDENTITY;
    inf_q.orientation[1] = INFINITY;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_object", "pose.position[0]",
                   opx_world_add_object(world, "x", &nan_pose, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_set_object_pose", "pose.orientation",
                   opx_world_set_object_pose(world, object, &zero_q));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_set_object_pose", "pose.orientation[1]",
                   opx_world_set_object_pose(world, object, &inf_q));
    opx_pose pose = OPX_POSE_IDENTITY;
    assert_ok(opx_world_get_object_pose(world, object, &pose));
    assert_center(pose.position, 1, 2, 3);  /* unchanged */

    const opx_shape sphere = sphere_shape(0.1);
    uint32_t index = 0;
    int32_t flag = 0;
    const char *name = NULL;
    opx_shape out = OPX_SHAPE_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_shape", "object 1", opx_world_add_shape(world, 1, &sphere, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_remove_object", "object 7", opx_world_remove_object(world, 7));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_set_object_pose", "object 1", opx_world_set_object_pose(world, 1, &pose));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_get_object_pose", "object 1", opx_world_get_object_pose(world, 1, &pose));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_set_object_enabled", "object 1", opx_world_set_object_enabled(world, 1, 0));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_get_object_enabled", "object 1", opx_world_get_object_enabled(world, 1, &flag));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_get_object_name", "object 1", opx_world_get_object_name(world, 1, &name));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_get_shape_count", "object 1", opx_world_get_shape_count(world, 1, &index));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_get_shape", "shape 0", opx_world_get_shape(world, object, 0, &out));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_find_object", "chair", opx_world_find_object(world, "chair", &index));

    opx_shape bad = sphere_shape(-0.1);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_shape", "shape->radius", opx_world_add_shape(world, object, &bad, NULL));
    bad = sphere_shape(NAN);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_shape", "shape->radius", opx_world_add_shape(world, object, &bad, NULL));
    bad = box_shape(0.1, 0.1, 0.1);
    bad.pose.position[2] = NAN;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_shape", "shape->pose", opx_world_add_shape(world, object, &bad, NULL));
    bad.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, "opx_world_add_shape", "shape", opx_world_add_shape(world, object, &bad, NULL));
    bad = sphere_shape(0.1);
    bad.kind = 9;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_shape", "shape->kind", opx_world_add_shape(world, object, &bad, NULL));
    out.struct_size = 0;
    assert_ok(opx_world_add_shape(world, object, &sphere, NULL));
    expect_failure(OPX_ERROR_VERSION, "opx_world_get_shape", "out_shape", opx_world_get_shape(world, object, 0, &out));

    uint32_t count = 0;
    assert_ok(opx_world_get_shape_count(world, object, &count));
    assert_int_equal(count, 1);  /* only the good sphere */
    assert_int_equal(object_count(world), 1);
    opx_world_destroy(world);
}

/* Sizes and positions share the URDF's bound: +-1e6 m. */
static void test_shapes_beyond_a_thousand_km(void **state) {
    (void)state;
    opx_world *world = new_world();
    const uint32_t object = add_object(world, "post", 0, 0, 0);
    opx_shape huge = OPX_SHAPE_INIT;
    huge.kind = OPX_SHAPE_CYLINDER, huge.radius = 1e200, huge.length = 1e200;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_shape", "shape->radius is 1e+200",
                   opx_world_add_shape(world, object, &huge, NULL));
    huge.radius = 0.1;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_shape", "shape->length",
                   opx_world_add_shape(world, object, &huge, NULL));
    opx_shape far = sphere_shape(0.1);
    far.pose.position[1] = -2e6;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_shape", "shape->pose.position[1]",
                   opx_world_add_shape(world, object, &far, NULL));
    const double vertices[9] = {0, 0, 0, 1, 0, 0, 0, 1e7, 0};
    const uint32_t indices[3] = {0, 1, 2};
    opx_shape mesh = OPX_SHAPE_INIT;
    mesh.kind = OPX_SHAPE_MESH, mesh.vertices = vertices, mesh.vertex_count = 3;
    mesh.indices = indices, mesh.triangle_count = 1;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_shape", "shape->vertices[2]",
                   opx_world_add_shape(world, object, &mesh, NULL));
    const opx_pose far_pose = pose_at(0, 0, 1.5e6);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_add_object", "pose.position[2]",
                   opx_world_add_object(world, "far", &far_pose, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_set_object_pose", "pose.position[2]",
                   opx_world_set_object_pose(world, object, &far_pose));
    const opx_shape edge = sphere_shape(1e6);  /* the bound itself is taken */
    assert_ok(opx_world_add_shape(world, object, &edge, NULL));
    assert_int_equal(object_count(world), 1);
    opx_world_destroy(world);
}

static void test_scene_arguments(void **state) {
    (void)state;
    opx_world *world = NULL;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_load_scene_memory", "format 3",
                   opx_world_load_scene_memory("x", 1, 3, &world));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_world_load_scene_file", ".scene",
                   opx_world_load_scene_file("/tmp/room.urdf", &world));
    expect_failure(OPX_ERROR_IO, "opx_world_load_scene_file", "/nonexistent/room.yaml",
                   opx_world_load_scene_file("/nonexistent/room.yaml", &world));
    assert_null(world);
    /* An empty PlanningSceneWorld is a world without objects. */
    const char *empty = "collision_objects: []\n";
    assert_ok(opx_world_load_scene_memory(empty, strlen(empty), OPX_SCENE_FORMAT_YAML, &world));
    assert_int_equal(object_count(world), 0);
    opx_world_destroy(world);
    assert_ok(opx_world_load_scene_memory("empty\n.\n", 8, OPX_SCENE_FORMAT_TEXT, &world));
    assert_int_equal(object_count(world), 0);
    opx_world_destroy(world);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_create_and_destroy),   cmocka_unit_test(test_objects_by_index_and_name),
        cmocka_unit_test(test_shapes_of_every_kind), cmocka_unit_test(test_null_arguments),
        cmocka_unit_test(test_bad_poses_and_indices), cmocka_unit_test(test_scene_arguments),
        cmocka_unit_test(test_shapes_beyond_a_thousand_km),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
