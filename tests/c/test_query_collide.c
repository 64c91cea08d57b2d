/*
 * opx_query_create, opx_query_collide and opx_query_get_contact: every
 * invalid argument is rejected, named in the message, and leaves the link
 * set and the query's last results unchanged; touching, contacts,
 * max_contacts, thresholds, the unknown policy and penetration by hand.
 * Cost boxes: test_query_cost.c.
 */
#include "opx_query_test.h"

static const char *const FN = "opx_query_collide";

static void create_rejects_bad_arguments(void **state) {
    (void)state;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_create", "out", opx_query_create(NULL, NULL));
    opx_query *query = (opx_query *)&query; /* must be reset to NULL */
    opx_query_options options = OPX_QUERY_OPTIONS_INIT;
    options.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, "opx_query_create", "struct_size", opx_query_create(&options, &query));
    assert_null(query);
    const int32_t bad[] = {0, 3, -1, INT32_MAX};
    for (size_t i = 0; i < 4; ++i) {
        opx_query_options o = OPX_QUERY_OPTIONS_INIT;
        o.engine = bad[i];
        query = (opx_query *)&query;
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_create", "engine", opx_query_create(&o, &query));
        assert_null(query);
    }
    const uint32_t bad_bits[] = {0, 22};
    for (size_t i = 0; i < 2; ++i) {
        opx_query_options o = OPX_QUERY_OPTIONS_INIT;
        o.engine = OPX_ENGINE_AMORTIZED;
        o.morton_bits = bad_bits[i];
        query = (opx_query *)&query;
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_create", "morton_bits", opx_query_create(&o, &query));
        assert_null(query);
    }
    opx_query_options o = OPX_QUERY_OPTIONS_INIT;
    assert_ok(opx_query_create(&o, &query));
    assert_non_null(query);
    opx_query_destroy(query);
    o.engine = OPX_ENGINE_AMORTIZED;
    assert_ok(opx_query_create(&o, &query));
    assert_non_null(query);
    opx_query_destroy(query);
    opx_query_destroy(NULL); /* a no-op */
}

/* A query that found the robot's one contact, for the failure tests. */
typedef struct fixture {
    opx_octree *tree;
    opx_linkset *robot;
    opx_query *query;
    linkset_snapshot before;
} fixture;

static fixture setup(void) {
    fixture f;
    f.tree = new_one_cell_map();
    f.robot = new_robot();
    f.before = robot_snapshot(f.robot);
    f.query = new_query();
    const opx_collision_result r = collide_with(f.query, f.tree, f.robot, 1);
    assert_int_equal(r.contact_count, 1);
    return f;
}

/* The link set and the query's contact are as they were. */
static void teardown(fixture *f) {
    assert_linkset_unchanged(f->robot, &f->before);
    const opx_contact c = get_contact(f->query, 0);
    assert_int_equal(c.link, 0);
    assert_center(c.cell_center, C0, C0, C0);
    opx_contact none = OPX_CONTACT_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_get_contact", "index",
                   opx_query_get_contact(f->query, 1, &none));
    opx_query_destroy(f->query);
    opx_linkset_destroy(f->robot);
    opx_octree_destroy(f->tree);
}

static void expect_request_fails(fixture *f, const opx_collision_request *request,
                                 opx_status expected, const char *argument) {
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    expect_failure(expected, FN, argument, opx_query_collide(f->query, f->tree, f->robot, request, &result));
}

static void collide_rejects_null_and_versions(void **state) {
    (void)state;
    fixture f = setup();
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "query", opx_query_collide(NULL, f.tree, f.robot, NULL, &result));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "tree", opx_query_collide(f.query, NULL, f.robot, NULL, &result));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "links", opx_query_collide(f.query, f.tree, NULL, NULL, &result));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "out_result", opx_query_collide(f.query, f.tree, f.robot, NULL, NULL));
    result.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, FN, "out_result", opx_query_collide(f.query, f.tree, f.robot, NULL, &result));
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.struct_size = 0;
    expect_request_fails(&f, &request, OPX_ERROR_VERSION, "request");
    teardown(&f);
}

static void collide_rejects_bad_request_fields(void **state) {
    (void)state;
    fixture f = setup();
    const int32_t policies[] = {-1, 2, 100};
    for (size_t i = 0; i < 3; ++i) {
        opx_collision_request r = OPX_COLLISION_REQUEST_INIT;
        r.unknown_policy = policies[i];
        expect_request_fails(&f, &r, OPX_ERROR_INVALID_ARGUMENT, "unknown_policy");
    }
    const double thresholds[] = {-0.1, -1e-300, 1.0, 1.5, NAN, INFINITY, -INFINITY};
    for (size_t i = 0; i < 7; ++i) {
        opx_collision_request r = OPX_COLLISION_REQUEST_INIT;
        r.occupancy_threshold = thresholds[i];
        expect_request_fails(&f, &r, OPX_ERROR_INVALID_ARGUMENT, "occupancy_threshold");
    }
    const double probabilities[] = {-0.1, 1.0 + 1e-9, 2.0, NAN, INFINITY};
    for (size_t i = 0; i < 5; ++i) {
        opx_collision_request r = OPX_COLLISION_REQUEST_INIT;
        r.compute_cost = 1;
        r.unknown_probability = probabilities[i];
        expect_request_fails(&f, &r, OPX_ERROR_INVALID_ARGUMENT, "unknown_probability");
    }
    const double bad[] = {NAN, INFINITY, -INFINITY};
    for (size_t b = 0; b < 3; ++b) {
        for (int axis = 0; axis < 3; ++axis) {
            opx_collision_request r = OPX_COLLISION_REQUEST_INIT;
            r.compute_cost = 1;
            r.region_max[0] = r.region_max[1] = r.region_max[2] = 1.0;
            r.region_min[axis] = bad[b];
            expect_request_fails(&f, &r, OPX_ERROR_INVALID_ARGUMENT, "region");
            r.region_min[axis] = 0.0;
            r.region_max[axis] = bad[b];
            expect_request_fails(&f, &r, OPX_ERROR_INVALID_ARGUMENT, "region");
        }
    }
    teardown(&f);
}

static void get_contact_rejects_bad_arguments(void **state) {
    (void)state;
    fixture f = setup();
    const char *fn = "opx_query_get_contact";
    opx_contact c = OPX_CONTACT_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "query", opx_query_get_contact(NULL, 0, &c));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "out_contact", opx_query_get_contact(f.query, 0, NULL));
    c.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, fn, "out_contact", opx_query_get_contact(f.query, 0, &c));
    c.struct_size = sizeof c;
    const size_t bad[] = {1, 2, SIZE_MAX};
    for (size_t i = 0; i < 3; ++i)
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "index", opx_query_get_contact(f.query, bad[i], &c));
    /* A fresh query holds no contact. */
    opx_query *fresh = new_query();
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "index", opx_query_get_contact(fresh, 0, &c));
    opx_query_destroy(fresh);
    teardown(&f);
}

/* ---- Positive behaviour ------------------------------------------------- */

/* Closed sets: a sphere touching the face, edge or corner of the cell
 * collides; 1e-6 m farther it does not.  A box flush with a face collides. */
static void touching_collides_a_micrometre_away_does_not(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    const double a = 0.1 / sqrt(3.0), e = 0.1 / sqrt(2.0);
    const double touching[][3] = {{0.35, C0, C0}, {C0, -0.1, C0}, {C0, C0, 0.35},
                                  {0.25 + e, C0, 0.25 + e}, {0.25 + a, 0.25 + a, 0.25 + a}};
    const double away[][3] = {{0.350001, C0, C0}, {C0, -0.100001, C0}, {C0, C0, 0.350001},
                              {0.25 + e + 1e-6, C0, 0.25 + e + 1e-6},
                              {0.25 + a + 1e-6, 0.25 + a + 1e-6, 0.25 + a + 1e-6}};
    for (size_t i = 0; i < 5; ++i) {
        opx_linkset *in = new_sphere_at(0.1, touching[i][0], touching[i][1], touching[i][2]);
        opx_linkset *out = new_sphere_at(0.1, away[i][0], away[i][1], away[i][2]);
        if (!collides(in, tree)) fail_msg("touching sphere %zu does not collide", i);
        if (collides(out, tree)) fail_msg("sphere %zu 1e-6 away collides", i);
        opx_linkset_destroy(in);
        opx_linkset_destroy(out);
    }
    opx_linkset *links = new_linkset();
    add_shape(links, add_link(links, "box"), box_shape(0.2, 0.2, 0.2));
    opx_pose pose = pose_at(0.35, C0, C0);
    assert_ok(opx_linkset_set_poses(links, &pose, 1, 0));
    assert_true(collides(links, tree));
    pose.position[0] = 0.350001;
    assert_ok(opx_linkset_set_poses(links, &pose, 1, 0));
    assert_false(collides(links, tree));
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

/* The contact names link, shape and cell. */
static void contact_fields(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_linkset *robot = new_robot();
    opx_query *query = new_query();
    const opx_collision_result r = collide_with(query, tree, robot, 1);
    assert_int_equal(r.struct_size, sizeof r);
    assert_int_equal(r.collided, 1);
    assert_int_equal(r.contact_count, 1);
    assert_int_equal(r.truncated, 0);
    assert_true(r.narrow_tests >= 1);
    assert_true(r.total_cost == 0.0 && r.cost_box_count == 0 && r.cost_boxes_found == 0);
    const opx_contact c = get_contact(query, 0);
    assert_int_equal(c.struct_size, sizeof c);
    assert_int_equal(c.link, 0);
    assert_int_equal(c.shape, 0);
    assert_int_equal(c.cell_class, OPX_CELL_OCCUPIED);
    assert_center(c.cell_center, C0, C0, C0);
    assert_near(c.cell_size, RES, OPX_GEOM_TOL);
    assert_near(c.cell_probability, 0.7, OPX_PROB_TOL);
    assert_true(c.depth == 0.0); /* no penetration asked */
    opx_query_destroy(query);
    opx_linkset_destroy(robot);
    opx_octree_destroy(tree);
}

/* Three occupied cells along x; a box 0.6 long touches all three:
 * 0 yes/no only, 1 the first, N up to N with truncated when one more
 * exists. */
static void max_contacts_semantics(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    const double xyz[9] = {C0, C0, C0, C0 + RES, C0, C0, C0 + 2 * RES, C0, C0};
    const opx_insert_options o = sensor_at(0.0, 0.0, 0.0, OPX_INSERT_ENDPOINTS);
    insert_f64(tree, xyz, 3, &o);
    opx_linkset *links = new_linkset();
    add_shape(links, add_link(links, "bar"), box_shape(0.6, 0.1, 0.1));
    const opx_pose pose = pose_at(0.4, C0, C0); /* x from 0.1 to 0.7 */
    assert_ok(opx_linkset_set_poses(links, &pose, 1, 0));
    opx_query *query = new_query();
    const uint32_t max[] = {0, 1, 2, 3, 4, UINT32_MAX};
    const uint64_t count[] = {0, 1, 2, 3, 3, 3};
    const int32_t truncated[] = {0, 0, 1, 0, 0, 0};
    for (size_t i = 0; i < 6; ++i) {
        const opx_collision_result r = collide_with(query, tree, links, max[i]);
        assert_int_equal(r.collided, 1);
        assert_int_equal(r.contact_count, count[i]);
        assert_int_equal(r.truncated, truncated[i]);
        int seen[3] = {0, 0, 0};
        for (size_t k = 0; k < count[i]; ++k) {
            const opx_contact c = get_contact(query, k);
            const double cell = (c.cell_center[0] - C0) / RES;
            assert_true(cell == 0.0 || cell == 1.0 || cell == 2.0);
            assert_int_equal(seen[(int)cell]++, 0); /* each cell once */
        }
        opx_contact none = OPX_CONTACT_INIT;
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_get_contact", "index",
                       opx_query_get_contact(query, count[i], &none));
    }
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

/* The one cell has p = 0.7: a request threshold of 0.69 keeps it an
 * obstacle, 0.71 does not, 0 is the octree's 0.5.  A free cell (p = 0.4)
 * becomes an obstacle below 0.4, and its contact says it is free. */
static void occupancy_threshold(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_linkset *links = new_sphere_at(0.1, 0.3, C0, C0);
    opx_query *query = new_query();
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    opx_collision_result r = OPX_COLLISION_RESULT_INIT;
    const double thresholds[] = {0.0, 0.69, 0.71, 0.99};
    const int32_t expected[] = {1, 1, 0, 0};
    for (size_t i = 0; i < 4; ++i) {
        request.occupancy_threshold = thresholds[i];
        assert_ok(opx_query_collide(query, tree, links, &request, &r));
        assert_int_equal(r.collided, expected[i]);
    }
    opx_octree *ray = new_tree(RES);
    insert_one_ray(ray, 1.0, 0.0, 0.0); /* free cells at x index 0..3 */
    opx_linkset *inside = new_sphere_at(0.05, 0.375, C0, C0);
    request.occupancy_threshold = 0.0;
    assert_ok(opx_query_collide(query, ray, inside, &request, &r));
    assert_int_equal(r.collided, 0);
    request.occupancy_threshold = 0.39;
    assert_ok(opx_query_collide(query, ray, inside, &request, &r));
    assert_int_equal(r.collided, 1);
    const opx_contact c = get_contact(query, 0);
    assert_int_equal(c.cell_class, OPX_CELL_FREE);
    assert_near(c.cell_probability, 0.4, OPX_PROB_TOL);
    assert_center(c.cell_center, 0.375, C0, C0);
    opx_linkset_destroy(inside);
    opx_octree_destroy(ray);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

/* An empty map is all unknown: free by default, an obstacle with
 * OPX_UNKNOWN_OCCUPIED, except outside the map cube (+-8192 m at RES). */
static void unknown_occupied_on_an_empty_map(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    opx_linkset *links = new_sphere_at(0.1, 3.0, -2.0, 1.0);
    opx_query *query = new_query();
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    opx_collision_result r = OPX_COLLISION_RESULT_INIT;
    assert_ok(opx_query_collide(query, tree, links, &request, &r));
    assert_int_equal(r.collided, 0);
    assert_int_equal(r.contact_count, 0);
    request.unknown_policy = OPX_UNKNOWN_OCCUPIED;
    assert_ok(opx_query_collide(query, tree, links, &request, &r));
    assert_int_equal(r.collided, 1);
    assert_int_equal(r.contact_count, 1);
    const opx_contact c = get_contact(query, 0);
    assert_int_equal(c.cell_class, OPX_CELL_UNKNOWN);
    assert_true(c.cell_probability == 0.5);
    assert_true(c.cell_size >= RES);
    for (int axis = 0; axis < 3; ++axis) /* the cell holds the sphere's centre */
        assert_true(fabs(pose_at(3.0, -2.0, 1.0).position[axis] - c.cell_center[axis]) <= c.cell_size / 2);
    opx_linkset *outside = new_sphere_at(0.1, 9000.0, 0.0, 0.0);
    assert_ok(opx_query_collide(query, tree, outside, &request, &r));
    assert_int_equal(r.collided, 0);
    opx_linkset_destroy(outside);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

/* A sphere r 0.1 at x = 0.3 is 0.05 deep in the cell through its face
 * x = 0.25: it went in along -x; the point is midway between its deepest
 * point x = 0.2 and the face. */
static void penetration_by_hand(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_linkset *links = new_sphere_at(0.1, 0.3, C0, C0);
    opx_query *query = new_query();
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.compute_penetration = 1;
    opx_collision_result r = OPX_COLLISION_RESULT_INIT;
    assert_ok(opx_query_collide(query, tree, links, &request, &r));
    assert_int_equal(r.contact_count, 1);
    const opx_contact c = get_contact(query, 0);
    assert_near(c.depth, 0.05, 1e-9);
    assert_center(c.normal, -1.0, 0.0, 0.0);
    assert_center(c.position, 0.225, C0, C0);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(create_rejects_bad_arguments),
        cmocka_unit_test(collide_rejects_null_and_versions),
        cmocka_unit_test(collide_rejects_bad_request_fields),
        cmocka_unit_test(get_contact_rejects_bad_arguments),
        cmocka_unit_test(touching_collides_a_micrometre_away_does_not),
        cmocka_unit_test(contact_fields),
        cmocka_unit_test(max_contacts_semantics),
        cmocka_unit_test(occupancy_threshold),
        cmocka_unit_test(unknown_occupied_on_an_empty_map),
        cmocka_unit_test(penetration_by_hand),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
