/*
 * Collision and distance queries with a world set (opx_query_set_world):
 * objects alone (no octree), objects beside the one-cell map, contact and
 * result fields, max_contacts across both, disabled and removed objects,
 * per-link and signed distances, and what queries with a world refuse.
 */
#include "opx_query_test.h"

/* A world of one box 0.2 x 0.2 x 0.2 centred at (2, 0, 0), and a second
 * object, a sphere of radius 0.1 at (0, 2, 0). */
static opx_world *new_two_object_world(void) {
    opx_world *world = NULL;
    assert_ok(opx_world_create(&world));
    const opx_pose at_box = pose_at(2, 0, 0), at_ball = pose_at(0, 2, 0);
    uint32_t box = 0, ball = 0;
    assert_ok(opx_world_add_object(world, "box", &at_box, &box));
    assert_ok(opx_world_add_object(world, "ball", &at_ball, &ball));
    const opx_shape cube = box_shape(0.2, 0.2, 0.2), sphere = sphere_shape(0.1);
    assert_ok(opx_world_add_shape(world, box, &cube, NULL));
    assert_ok(opx_world_add_shape(world, ball, &sphere, NULL));
    return world;
}

static opx_query *query_with(const opx_world *world) {
    opx_query *query = new_query();
    assert_ok(opx_query_set_world(query, world));
    return query;
}

static void test_objects_only_collision(void **state) {
    (void)state;
    opx_world *world = new_two_object_world();
    opx_query *query = query_with(world);
    opx_linkset *links = new_sphere_at(0.05, 2.14, 0, 0);  /* 0.01 into the box */
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.max_contacts = UINT32_MAX;
    request.compute_penetration = 1;
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    assert_ok(opx_query_collide(query, NULL, links, &request, &result));
    assert_int_equal(result.collided, 1);
    assert_int_equal(result.contact_count, 1);
    const opx_contact c = get_contact(query, 0);
    assert_int_equal(c.object, 0);
    assert_int_equal(c.object_shape, 0);
    assert_int_equal(c.link, 0);
    assert_int_equal(c.cell_class, 0);
    assert_near(c.cell_size, 0.0, 0.0);
    assert_near(c.depth, 0.01, 1e-9);
    assert_near(c.normal[0], -1.0, 1e-9);
    assert_center(c.position, 2.095, 0, 0);

    /* Disabled, then moved away: no collision. */
    assert_ok(opx_world_set_object_enabled(world, 0, 0));
    assert_int_equal(collide_with(query, NULL, links, 1).collided, 0);
    assert_ok(opx_world_set_object_enabled(world, 0, 1));
    assert_int_equal(collide_with(query, NULL, links, 1).collided, 1);
    const opx_pose far = pose_at(5, 0, 0);
    assert_ok(opx_world_set_object_pose(world, 0, &far));
    assert_int_equal(collide_with(query, NULL, links, 1).collided, 0);
    opx_linkset_destroy(links);
    opx_query_destroy(query);
    opx_world_destroy(world);
}

static void test_objects_only_distance(void **state) {
    (void)state;
    opx_world *world = new_two_object_world();
    opx_query *query = query_with(world);
    opx_linkset *links = new_sphere_at(0.05, 0.0, 1.5, 0.0);  /* 0.35 from the ball */
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.per_link = 1;
    opx_distance_result r = distance_with(query, NULL, links, &request);
    assert_int_equal(r.found, 1);
    assert_near(r.distance, 0.35, 1e-12);
    assert_int_equal(r.object, 1);
    assert_int_equal(r.object_shape, 0);
    assert_near(r.cell_size, 0.0, 0.0);
    assert_center(r.point_on_link, 0, 1.55, 0);
    assert_center(r.point_on_cell, 0, 1.9, 0);
    double per_link[2] = {0, 0};
    size_t count = 0;
    assert_ok(opx_query_get_link_distances(query, per_link, 2, &count));
    assert_int_equal(count, 1);
    assert_near(per_link[0], 0.35, 1e-12);

    /* Signed: 0.03 into the ball. */
    const opx_pose inside = pose_at(0.0, 1.88, 0.0);
    assert_ok(opx_linkset_set_poses(links, &inside, 1, 0));
    request.signed_distance = 1;
    r = distance_with(query, NULL, links, &request);
    assert_near(r.distance, -0.03, 1e-9);
    assert_int_equal(r.collided, 1);
    assert_int_equal(r.object, 1);

    /* A cutoff below the distance: not found. */
    const opx_pose away = pose_at(0.0, 1.0, 0.0);
    assert_ok(opx_linkset_set_poses(links, &away, 1, 0));
    request.cutoff = 0.5;
    r = distance_with(query, NULL, links, &request);
    assert_int_equal(r.found, 0);
    assert_near(r.distance, 0.5, 0.0);
    assert_int_equal(r.object, -1);
    opx_linkset_destroy(links);
    opx_query_destroy(query);
    opx_world_destroy(world);
}

/* The one-cell map [0, 0.25]^3 and a box object beside it, both touched. */
static void test_octree_and_objects_together(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_world *world = NULL;
    assert_ok(opx_world_create(&world));
    const opx_pose at = pose_at(0.6, C0, C0);
    assert_ok(opx_world_add_object(world, "crate", &at, NULL));
    const opx_shape cube = box_shape(0.2, 0.2, 0.2);
    assert_ok(opx_world_add_shape(world, 0, &cube, NULL));
    assert_ok(opx_world_add_shape(world, 0, &cube, NULL));  /* a second, equal shape */
    opx_query *query = query_with(world);
    opx_linkset *links = new_sphere_at(0.13, 0.375, C0, C0);  /* 0.005 into the cell and the crate */

    opx_collision_result r = collide_with(query, tree, links, UINT32_MAX);
    assert_int_equal(r.collided, 1);
    assert_int_equal(r.contact_count, 3);
    assert_int_equal(get_contact(query, 0).object, -1);  /* the cell first */
    assert_near(get_contact(query, 0).cell_size, RES, 0.0);
    assert_int_equal(get_contact(query, 1).object, 0);
    assert_int_equal(get_contact(query, 2).object_shape, 1);
    opx_contact out = OPX_CONTACT_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_get_contact", "index 3", opx_query_get_contact(query, 3, &out));

    r = collide_with(query, tree, links, 2);
    assert_int_equal(r.contact_count, 2);
    assert_int_equal(r.truncated, 1);
    r = collide_with(query, tree, links, 1);
    assert_int_equal(r.contact_count, 1);
    r = collide_with(query, tree, links, 0);
    assert_int_equal(r.collided, 1);
    assert_int_equal(r.contact_count, 0);

    /* Distance: the nearer of the two (a smaller sphere in the gap). */
    opx_linkset_destroy(links);
    links = new_sphere_at(0.05, 0.35, C0, C0);  /* 0.05 from the cell, 0.10 from the crate */
    opx_distance_result d = distance_with(query, tree, links, NULL);
    assert_int_equal(d.object, -1);
    assert_near(d.distance, 0.05, 1e-12);
    assert_near(d.cell_size, RES, 0.0);
    const opx_pose nearer_crate = pose_at(0.42, C0, C0);  /* 0.12 from the cell, 0.03 from the crate */
    assert_ok(opx_linkset_set_poses(links, &nearer_crate, 1, 0));
    d = distance_with(query, tree, links, NULL);
    assert_int_equal(d.object, 0);
    assert_near(d.distance, 0.03, 1e-12);
    assert_near(d.cell_size, 0.0, 0.0);
    assert_center(d.point_on_cell, 0.5, C0, C0);

    /* Detached: the octree alone again. */
    assert_ok(opx_query_set_world(query, NULL));
    d = distance_with(query, tree, links, NULL);
    assert_int_equal(d.object, -1);
    opx_linkset_destroy(links);
    opx_query_destroy(query);
    opx_world_destroy(world);
    opx_octree_destroy(tree);
}

static void test_calls_refusing_a_world(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_world *world = new_two_object_world();
    opx_query *query = new_query();
    opx_linkset *links = new_sphere_at(0.1, 1, 1, 1);
    opx_collision_result cr = OPX_COLLISION_RESULT_INIT;
    opx_distance_result dr = OPX_DISTANCE_RESULT_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_collide", "tree", opx_query_collide(query, NULL, links, NULL, &cr));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_distance", "tree", opx_query_distance(query, NULL, links, NULL, &dr));
    assert_ok(opx_query_set_world(query, world));
    opx_collision_request cost = OPX_COLLISION_REQUEST_INIT;
    cost.compute_cost = 1;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_collide", "compute_cost", opx_query_collide(query, NULL, links, &cost, &cr));
    opx_distance_request bad = OPX_DISTANCE_REQUEST_INIT;
    bad.occupancy_threshold = 1.5;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_distance", "occupancy_threshold", opx_query_distance(query, NULL, links, &bad, &dr));
    bad = (opx_distance_request)OPX_DISTANCE_REQUEST_INIT;
    bad.cutoff = NAN;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_distance", "cutoff", opx_query_distance(query, NULL, links, &bad, &dr));
    const opx_pose pose = pose_at(1, 1, 1);
    opx_path_request path_cost = OPX_PATH_REQUEST_INIT;
    path_cost.compute_cost = 1;
    opx_path_result pr = OPX_PATH_RESULT_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_path", "compute_cost",
                   opx_query_path(query, NULL, links, &pose, 1, 0, 0, &path_cost, &pr));
    expect_failure(OPX_ERROR_UNSUPPORTED, "opx_query_collide_boxes", "opx_query_set_world",
                   opx_query_collide_boxes(query, links, NULL, &cr));
    expect_failure(OPX_ERROR_UNSUPPORTED, "opx_query_distance_boxes", "opx_query_set_world",
                   opx_query_distance_boxes(query, links, NULL, &dr));
    /* Self-collision ignores the world. */
    opx_self_collision_result sr = OPX_SELF_COLLISION_RESULT_INIT;
    assert_ok(opx_query_self_collide(query, links, NULL, &sr));
    opx_linkset_destroy(links);
    opx_query_destroy(query);
    opx_world_destroy(world);
    opx_octree_destroy(tree);
}

static void test_contact_init_names_no_object(void **state) {
    (void)state;
    opx_contact contact;
    memset(&contact, 0x55, sizeof contact);
    assert_ok(opx_contact_init(&contact, sizeof contact));
    assert_int_equal(contact.object, -1);
    assert_int_equal(contact.object_shape, 0);
    opx_distance_result result;
    memset(&result, 0x55, sizeof result);
    assert_ok(opx_distance_result_init(&result, sizeof result));
    assert_int_equal(result.object, -1);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_objects_only_collision),     cmocka_unit_test(test_objects_only_distance),
        cmocka_unit_test(test_octree_and_objects_together), cmocka_unit_test(test_calls_refusing_a_world),
        cmocka_unit_test(test_contact_init_names_no_object),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
