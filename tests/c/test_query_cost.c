/*
 * Cost of uncertain and unknown space in collision queries, and
 * opx_query_get_cost_box, on a hand-made map:
 *
 *   one ray from (C0, C0, C0) to (1.125, C0, C0) at RES = 0.25: free cells
 *   (p = 0.4) at x in [0, 1], an occupied cell (p = 0.7) at x in [1, 1.25],
 *   all with y, z in [0, 0.25]; unknown space behind it, x >= 1.25: a finest
 *   cell [1.25, 1.5] (its sibling is observed) and a cube of edge 0.5,
 *   [1.5, 2] x [0, 0.5]^2.
 *
 * The link: one box spanning x [0.55, 1.875], y and z [0.05, 0.2] (its own
 * bounding box); cross-section 0.15 x 0.15 = 0.0225 m^2.
 */
#include "opx_query_test.h"

#define SECTION 0.0225

static opx_octree *new_cost_map(double free_threshold) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = RES;
    options.free_threshold = free_threshold;
    opx_octree *tree = new_tree_with(&options);
    insert_one_ray(tree, 1.0, 0.0, 0.0);
    return tree;
}

static opx_linkset *new_bar(void) {
    opx_linkset *links = new_linkset();
    add_shape(links, add_link(links, "bar"), box_shape(1.325, 0.15, 0.15));
    const opx_pose pose = pose_at(1.2125, C0, C0);
    assert_ok(opx_linkset_set_poses(links, &pose, 1, 0));
    return links;
}

/* Unknown space counts in [0, 2] x [0, 0.25]^2: behind the obstacle only. */
static opx_collision_request cost_request(void) {
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.compute_cost = 1;
    request.region_max[0] = 2.0;
    request.region_max[1] = request.region_max[2] = RES;
    return request;
}

static opx_cost_box get_cost_box(const opx_query *query, size_t index) {
    opx_cost_box box = OPX_COST_BOX_INIT;
    assert_ok(opx_query_get_cost_box(query, index, &box));
    return box;
}

static void assert_box(const opx_cost_box *b, double x0, double x1, double cost, double cx,
                       double cyz, double size, int32_t cell_class, double p) {
    assert_int_equal(b->link, 0);
    assert_int_equal(b->cell_class, cell_class);
    assert_center(b->min, x0, 0.05, 0.05);
    assert_center(b->max, x1, 0.2, 0.2);
    assert_near(b->probability, p, OPX_PROB_TOL);
    assert_near(b->cost, cost, 1e-9);
    assert_center(b->cell_center, cx, cyz, cyz);
    assert_near(b->cell_size, size, OPX_GEOM_TOL);
}

/* Unknown boxes: [1.25, 1.5] (0.5 x 0.25 x SECTION) and [1.5, 1.875]
 * (0.5 x 0.375 x SECTION), costliest first; the contact still reported. */
static void unknown_space_behind_an_obstacle(void **state) {
    (void)state;
    opx_octree *tree = new_cost_map(0.5);
    opx_linkset *links = new_bar();
    opx_query *query = new_query();
    opx_collision_request request = cost_request();
    opx_collision_result r = OPX_COLLISION_RESULT_INIT;
    assert_ok(opx_query_collide(query, tree, links, &request, &r));
    assert_int_equal(r.collided, 1);
    assert_int_equal(r.contact_count, 1);
    assert_center(get_contact(query, 0).cell_center, 1.125, C0, C0);
    const double small = 0.5 * 0.25 * SECTION, large = 0.5 * 0.375 * SECTION;
    assert_near(r.total_cost, small + large, 1e-9);
    assert_int_equal(r.cost_boxes_found, 2);
    assert_int_equal(r.cost_box_count, 2);
    opx_cost_box b = get_cost_box(query, 0);
    assert_box(&b, 1.5, 1.875, large, 1.75, 0.25, 0.5, OPX_CELL_UNKNOWN, 0.5);
    b = get_cost_box(query, 1);
    assert_box(&b, 1.25, 1.5, small, 1.375, C0, RES, OPX_CELL_UNKNOWN, 0.5);

    /* unknown_probability scales the cost; max_cost_boxes keeps the
     * costliest, the total still sums all. */
    request.unknown_probability = 0.8;
    request.max_cost_boxes = 1;
    assert_ok(opx_query_collide(query, tree, links, &request, &r));
    assert_near(r.total_cost, 1.6 * (small + large), 1e-9);
    assert_int_equal(r.cost_boxes_found, 2);
    assert_int_equal(r.cost_box_count, 1);
    b = get_cost_box(query, 0);
    assert_box(&b, 1.5, 1.875, 1.6 * large, 1.75, 0.25, 0.5, OPX_CELL_UNKNOWN, 0.8);
    opx_cost_box none = OPX_COST_BOX_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_get_cost_box", "index",
                   opx_query_get_cost_box(query, 1, &none));

    /* Without compute_cost: no cost, no boxes held. */
    assert_ok(opx_query_collide(query, tree, links, NULL, &r));
    assert_true(r.total_cost == 0.0);
    assert_int_equal(r.cost_box_count + r.cost_boxes_found, 0);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_get_cost_box", "index",
                   opx_query_get_cost_box(query, 0, &none));
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

/* free_threshold 0.3 makes the ray's cells (p = 0.4) uncertain: the bar
 * overlaps two of them, [0.55, 0.75] of the cell [0.5, 0.75] and all of
 * [0.75, 1], at their own probability. */
static void uncertain_cells_and_the_default_region(void **state) {
    (void)state;
    opx_octree *tree = new_cost_map(0.3);
    opx_linkset *links = new_bar();
    opx_query *query = new_query();
    opx_collision_request request = cost_request();
    opx_collision_result r = OPX_COLLISION_RESULT_INIT;
    assert_ok(opx_query_collide(query, tree, links, &request, &r));
    const double part = 0.4 * 0.2 * SECTION, whole = 0.4 * 0.25 * SECTION;
    const double unknown = 0.5 * 0.625 * SECTION;
    assert_near(r.total_cost, part + whole + unknown, 1e-8);
    assert_int_equal(r.cost_boxes_found, 4);
    assert_int_equal(r.contact_count, 1);
    opx_cost_box b = get_cost_box(query, 2);
    assert_box(&b, 0.75, 1.0, whole, 0.875, C0, RES, OPX_CELL_UNCERTAIN, 0.4);
    b = get_cost_box(query, 3);
    assert_box(&b, 0.55, 0.75, part, 0.625, C0, RES, OPX_CELL_UNCERTAIN, 0.4);
    /* The default region (zeros) is the observed cells' bounds, x <= 1.25:
     * no unknown space behind the obstacle counts. */
    request.region_max[0] = request.region_max[1] = request.region_max[2] = 0.0;
    assert_ok(opx_query_collide(query, tree, links, &request, &r));
    assert_near(r.total_cost, part + whole, 1e-8);
    for (size_t i = 0; i < r.cost_box_count; ++i)
        if (get_cost_box(query, i).cell_class != OPX_CELL_UNCERTAIN)
            assert_true(get_cost_box(query, i).cost == 0.0);
    /* A region not below region_max on every axis is the default too. */
    request.region_min[0] = 3.0;
    request.region_max[0] = 2.0;
    request.region_max[1] = request.region_max[2] = RES;
    assert_ok(opx_query_collide(query, tree, links, &request, &r));
    assert_near(r.total_cost, part + whole, 1e-8);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

static void get_cost_box_rejects_bad_arguments(void **state) {
    (void)state;
    opx_octree *tree = new_cost_map(0.5);
    opx_linkset *links = new_bar();
    const linkset_snapshot before = take_linkset_snapshot(links);
    opx_query *query = new_query();
    const opx_collision_request request = cost_request();
    opx_collision_result r = OPX_COLLISION_RESULT_INIT;
    assert_ok(opx_query_collide(query, tree, links, &request, &r));
    assert_int_equal(r.cost_box_count, 2);
    const char *fn = "opx_query_get_cost_box";
    opx_cost_box b = OPX_COST_BOX_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "query", opx_query_get_cost_box(NULL, 0, &b));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "out_box", opx_query_get_cost_box(query, 0, NULL));
    b.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, fn, "out_box", opx_query_get_cost_box(query, 0, &b));
    b.struct_size = sizeof b;
    const size_t bad[] = {2, 3, SIZE_MAX};
    for (size_t i = 0; i < 3; ++i)
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "index", opx_query_get_cost_box(query, bad[i], &b));
    /* A failing collide keeps the boxes of the last one. */
    opx_collision_request broken = cost_request();
    broken.unknown_probability = NAN;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_collide", "unknown_probability",
                   opx_query_collide(query, tree, links, &broken, &r));
    assert_near(get_cost_box(query, 1).cost, 0.5 * 0.25 * SECTION, 1e-9);
    assert_linkset_unchanged(links, &before);
    opx_query *fresh = new_query();
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "index", opx_query_get_cost_box(fresh, 0, &b));
    opx_query_destroy(fresh);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

/* An older caller's cost box is written no further than its struct_size. */
static void cost_box_is_written_no_further_than_struct_size(void **state) {
    (void)state;
    opx_octree *tree = new_cost_map(0.5);
    opx_linkset *links = new_bar();
    opx_query *query = new_query();
    const opx_collision_request request = cost_request();
    opx_collision_result r = OPX_COLLISION_RESULT_INIT;
    assert_ok(opx_query_collide(query, tree, links, &request, &r));
    opx_cost_box b;
    memset(&b, 0x5A, sizeof b);
    b.struct_size = (uint32_t)offsetof(opx_cost_box, probability);
    assert_ok(opx_query_get_cost_box(query, 0, &b));
    assert_int_equal(b.struct_size, offsetof(opx_cost_box, probability));
    assert_near(b.max[0], 1.875, OPX_GEOM_TOL);
    const unsigned char *bytes = (const unsigned char *)&b;
    for (size_t i = offsetof(opx_cost_box, probability); i < sizeof b; ++i)
        assert_int_equal(bytes[i], 0x5A);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(unknown_space_behind_an_obstacle),
        cmocka_unit_test(uncertain_cells_and_the_default_region),
        cmocka_unit_test(get_cost_box_rejects_bad_arguments),
        cmocka_unit_test(cost_box_is_written_no_further_than_struct_size),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
