/*
 * opx_query_distance and opx_query_get_link_distances: every invalid
 * argument is rejected, named in the message, and leaves the link set and
 * the query's last per-link distances unchanged; distances, witnesses,
 * cutoff, per-link minima, signed distance and empty maps by hand.
 */
#include "opx_query_test.h"

static const char *const FN = "opx_query_distance";

typedef struct fixture {
    opx_octree *tree;
    opx_linkset *robot;
    opx_query *query;
    linkset_snapshot before;
} fixture;

/* A query whose last per-link distances are the robot's 0, 0.6, 0.7. */
static fixture setup(void) {
    fixture f;
    f.tree = new_one_cell_map();
    f.robot = new_robot();
    f.before = robot_snapshot(f.robot);
    f.query = new_query();
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.per_link = 1;
    distance_with(f.query, f.tree, f.robot, &request);
    return f;
}

static void assert_robot_link_distances(const opx_query *query) {
    double d[3] = {-1.0, -1.0, -1.0};
    size_t count = 0;
    assert_ok(opx_query_get_link_distances(query, d, 3, &count));
    assert_int_equal(count, 3);
    assert_near(d[0], 0.0, 1e-9);
    assert_near(d[1], 0.6, 1e-9);
    assert_near(d[2], 0.7, 1e-9);
}

static void teardown(fixture *f) {
    assert_linkset_unchanged(f->robot, &f->before);
    assert_robot_link_distances(f->query);
    opx_query_destroy(f->query);
    opx_linkset_destroy(f->robot);
    opx_octree_destroy(f->tree);
}

static void expect_request_fails(fixture *f, const opx_distance_request *request,
                                 opx_status expected, const char *argument) {
    opx_distance_result result = OPX_DISTANCE_RESULT_INIT;
    expect_failure(expected, FN, argument, opx_query_distance(f->query, f->tree, f->robot, request, &result));
}

static void distance_rejects_null_and_versions(void **state) {
    (void)state;
    fixture f = setup();
    opx_distance_result r = OPX_DISTANCE_RESULT_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "query", opx_query_distance(NULL, f.tree, f.robot, NULL, &r));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "tree", opx_query_distance(f.query, NULL, f.robot, NULL, &r));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "links", opx_query_distance(f.query, f.tree, NULL, NULL, &r));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "out_result", opx_query_distance(f.query, f.tree, f.robot, NULL, NULL));
    r.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, FN, "out_result", opx_query_distance(f.query, f.tree, f.robot, NULL, &r));
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.struct_size = 0;
    expect_request_fails(&f, &request, OPX_ERROR_VERSION, "request");
    teardown(&f);
}

static void distance_rejects_bad_request_fields(void **state) {
    (void)state;
    fixture f = setup();
    const int32_t policies[] = {-1, 2, 100};
    for (size_t i = 0; i < 3; ++i) {
        opx_distance_request r = OPX_DISTANCE_REQUEST_INIT;
        r.per_link = 1;
        r.unknown_policy = policies[i];
        expect_request_fails(&f, &r, OPX_ERROR_INVALID_ARGUMENT, "unknown_policy");
    }
    const double thresholds[] = {-0.1, 1.0, 1.5, NAN, INFINITY, -INFINITY};
    for (size_t i = 0; i < 6; ++i) {
        opx_distance_request r = OPX_DISTANCE_REQUEST_INIT;
        r.per_link = 1;
        r.occupancy_threshold = thresholds[i];
        expect_request_fails(&f, &r, OPX_ERROR_INVALID_ARGUMENT, "occupancy_threshold");
    }
    const double errors[] = {-1e-9, -1.0, NAN, INFINITY, -INFINITY};
    for (size_t i = 0; i < 5; ++i) {
        opx_distance_request r = OPX_DISTANCE_REQUEST_INIT;
        r.per_link = 1;
        r.abs_err = errors[i];
        expect_request_fails(&f, &r, OPX_ERROR_INVALID_ARGUMENT, "abs_err");
        r.abs_err = 0.0;
        r.rel_err = errors[i];
        expect_request_fails(&f, &r, OPX_ERROR_INVALID_ARGUMENT, "rel_err");
    }
    const double cutoffs[] = {-1e-9, -1.0, NAN, -INFINITY};
    for (size_t i = 0; i < 4; ++i) {
        opx_distance_request r = OPX_DISTANCE_REQUEST_INIT;
        r.per_link = 1;
        r.cutoff = cutoffs[i];
        expect_request_fails(&f, &r, OPX_ERROR_INVALID_ARGUMENT, "cutoff");
    }
    teardown(&f);
}

static void get_link_distances_rejects_bad_arguments(void **state) {
    (void)state;
    fixture f = setup();
    const char *fn = "opx_query_get_link_distances";
    double d[3] = {-1.0, -1.0, -1.0};
    size_t count = 77;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "query", opx_query_get_link_distances(NULL, d, 3, &count));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "out_count", opx_query_get_link_distances(f.query, d, 3, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "out_distances", opx_query_get_link_distances(f.query, NULL, 3, &count));
    /* Too small: the needed count and the first `capacity` values. */
    count = 77;
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, fn, "out_distances", opx_query_get_link_distances(f.query, d, 2, &count));
    assert_int_equal(count, 3);
    assert_near(d[0], 0.0, 1e-9);
    assert_near(d[1], 0.6, 1e-9);
    assert_true(d[2] == -1.0);
    count = 77;
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, fn, NULL, opx_query_get_link_distances(f.query, NULL, 0, &count));
    assert_int_equal(count, 3);
    /* A larger buffer is fine. */
    double more[5] = {-1.0, -1.0, -1.0, -1.0, -1.0};
    assert_ok(opx_query_get_link_distances(f.query, more, 5, &count));
    assert_int_equal(count, 3);
    assert_true(more[3] == -1.0);
    teardown(&f);
}

/* ---- Positive behaviour ------------------------------------------------- */

/* A sphere r 0.1 at (0.55, 0.65, C0) and the cell [0, 0.25]^3: the closest
 * cell point is the edge (0.25, 0.25, C0), 0.5 from the centre along
 * (0.6, 0.8, 0): distance 0.4, witness on the sphere at (0.49, 0.57, C0).
 * With padding 0.05: 0.35, witness on the padded sphere (0.46, 0.53, C0). */
static void sphere_to_a_cell_by_hand(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_linkset *links = new_sphere_at(0.1, 0.55, 0.65, C0);
    opx_query *query = new_query();
    opx_distance_result d = distance_with(query, tree, links, NULL);
    assert_int_equal(d.struct_size, sizeof d);
    assert_int_equal(d.found, 1);
    assert_int_equal(d.collided, 0);
    assert_int_equal(d.cell_class, OPX_CELL_OCCUPIED);
    assert_int_equal(d.link, 0);
    assert_int_equal(d.shape, 0);
    assert_near(d.distance, 0.4, 1e-12);
    assert_center(d.point_on_link, 0.49, 0.57, C0);
    assert_center(d.point_on_cell, 0.25, 0.25, C0);
    assert_center(d.cell_center, C0, C0, C0);
    assert_near(d.cell_size, RES, OPX_GEOM_TOL);
    assert_near(d.cell_probability, 0.7, OPX_PROB_TOL);
    assert_true(d.narrow_tests >= 1);
    assert_ok(opx_linkset_set_padding(links, 0.05));
    d = distance_with(query, tree, links, NULL);
    assert_near(d.distance, 0.35, 1e-12);
    assert_center(d.point_on_link, 0.46, 0.53, C0);
    assert_center(d.point_on_cell, 0.25, 0.25, C0);
    /* An approximate query is within its bound of the true distance. */
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.abs_err = 0.01;
    request.rel_err = 0.1;
    d = distance_with(query, tree, links, &request);
    assert_int_equal(d.found, 1);
    assert_true(d.distance >= 0.35 - 1e-12 && d.distance <= 0.35 + 0.035 + 1e-12);
    /* A request threshold above the cell's 0.7: no obstacle at all. */
    request = (opx_distance_request)OPX_DISTANCE_REQUEST_INIT;
    request.occupancy_threshold = 0.71;
    d = distance_with(query, tree, links, &request);
    assert_int_equal(d.found, 0);
    assert_true(isinf(d.distance) && d.distance > 0.0);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

/* A convex shape keeps reading its own vertices when shapes added after it
 * (here to an earlier link, then to its own) move it in the link set's
 * storage; under ASan a stale vertex pointer is a use after free. */
static void convex_shape_survives_later_shapes(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_linkset *links = new_linkset();
    assert_int_equal(add_link(links, "a"), 0);
    assert_int_equal(add_link(links, "b"), 1);
    assert_int_equal(add_shape(links, 1, convex_shape(TETRA, 4, 0)), 0);
    for (int i = 0; i < 8; ++i) add_shape(links, 0, sphere_shape(0.01));
    opx_shape far_ball = sphere_shape(0.01);
    far_ball.pose.position[0] = 1.0; /* link frame: well beyond the tetrahedron */
    assert_int_equal(add_shape(links, 1, far_ball), 1);
    opx_pose poses[2] = {pose_at(5.0, 5.0, 5.0), pose_at(0.55, C0, C0)};
    assert_ok(opx_linkset_set_poses(links, poses, 2, 0));
    opx_query *query = new_query();
    const opx_distance_result d = distance_with(query, tree, links, NULL);
    /* The tetrahedron's nearest vertex is its origin, 0.3 from the cell's face x = 0.25. */
    assert_int_equal(d.link, 1);
    assert_int_equal(d.shape, 0);
    assert_near(d.distance, 0.3, 1e-9);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

/* Farther than the cutoff: found 0 and distance = cutoff. */
static void cutoff(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_linkset *links = new_sphere_at(0.1, 0.55, 0.65, C0);
    opx_query *query = new_query();
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    const double cutoffs[] = {0.3, 0.39, 0.41, 0.5, 0.0, INFINITY};
    const int32_t found[] = {0, 0, 1, 1, 1, 1};
    for (size_t i = 0; i < 6; ++i) {
        request.cutoff = cutoffs[i];
        const opx_distance_result d = distance_with(query, tree, links, &request);
        assert_int_equal(d.found, found[i]);
        assert_near(d.distance, found[i] ? 0.4 : cutoffs[i], 1e-12);
        assert_int_equal(d.collided, 0);
    }
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

/* Nothing to find: +infinity without a cutoff, the cutoff with one; with
 * OPX_UNKNOWN_OCCUPIED the unknown space itself is at distance 0. */
static void empty_map(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    opx_linkset *links = new_sphere_at(0.1, 1.0, 2.0, 3.0);
    opx_query *query = new_query();
    opx_distance_result d = distance_with(query, tree, links, NULL);
    assert_int_equal(d.found, 0);
    assert_int_equal(d.collided, 0);
    assert_true(isinf(d.distance) && d.distance > 0.0);
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.cutoff = 2.0;
    d = distance_with(query, tree, links, &request);
    assert_int_equal(d.found, 0);
    assert_true(d.distance == 2.0);
    request = (opx_distance_request)OPX_DISTANCE_REQUEST_INIT;
    request.unknown_policy = OPX_UNKNOWN_OCCUPIED;
    d = distance_with(query, tree, links, &request);
    assert_int_equal(d.found, 1);
    assert_int_equal(d.collided, 1);
    assert_true(d.distance == 0.0);
    assert_int_equal(d.cell_class, OPX_CELL_UNKNOWN);
    assert_true(d.cell_probability == 0.5);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

/* Each link's minimum, in link order; +infinity for a disabled link and
 * for one with nothing within the cutoff. */
static void per_link_distances(void **state) {
    (void)state;
    fixture f = setup();
    assert_robot_link_distances(f.query);
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.per_link = 1;
    request.cutoff = 0.65;
    opx_distance_result d = distance_with(f.query, f.tree, f.robot, &request);
    assert_int_equal(d.found, 1);
    assert_int_equal(d.link, 0);
    double out[3] = {-1.0, -1.0, -1.0};
    size_t count = 0;
    assert_ok(opx_query_get_link_distances(f.query, out, 3, &count));
    assert_int_equal(count, 3);
    assert_near(out[0], 0.0, 1e-9);
    assert_near(out[1], 0.6, 1e-9);
    assert_true(isinf(out[2]) && out[2] > 0.0);
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_clone(f.robot, &robot));
    assert_ok(opx_linkset_set_link_enabled(robot, 0, 0));
    request.cutoff = 0.0;
    d = distance_with(f.query, f.tree, robot, &request);
    assert_int_equal(d.link, 1); /* the capsule, 0.6 away */
    assert_int_equal(d.shape, 1);
    assert_near(d.distance, 0.6, 1e-9);
    assert_near(d.point_on_link[2], 0.85, 1e-9);
    assert_near(d.point_on_cell[2], 0.25, 1e-9);
    assert_ok(opx_query_get_link_distances(f.query, out, 3, &count));
    assert_true(isinf(out[0]) && out[0] > 0.0);
    assert_near(out[1], 0.6, 1e-9);
    assert_near(out[2], 0.7, 1e-9);
    opx_linkset_destroy(robot);
    distance_with(f.query, f.tree, f.robot, &request); /* back to the robot */
    teardown(&f);
}

/* Signed: a sphere r 0.1 at x = 0.3 is 0.05 deep; the witnesses are its
 * deepest point x = 0.2 and the face x = 0.25.  Unsigned: 0. */
static void signed_distance(void **state) {
    (void)state;
    opx_octree *tree = new_one_cell_map();
    opx_linkset *links = new_sphere_at(0.1, 0.3, C0, C0);
    opx_query *query = new_query();
    opx_distance_result d = distance_with(query, tree, links, NULL);
    assert_int_equal(d.found, 1);
    assert_int_equal(d.collided, 1);
    assert_true(d.distance == 0.0);
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.signed_distance = 1;
    d = distance_with(query, tree, links, &request);
    assert_int_equal(d.collided, 1);
    assert_near(d.distance, -0.05, 1e-9);
    assert_center(d.point_on_link, 0.2, C0, C0);
    assert_center(d.point_on_cell, 0.25, C0, C0);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(distance_rejects_null_and_versions),
        cmocka_unit_test(distance_rejects_bad_request_fields),
        cmocka_unit_test(get_link_distances_rejects_bad_arguments),
        cmocka_unit_test(sphere_to_a_cell_by_hand),
        cmocka_unit_test(cutoff),
        cmocka_unit_test(empty_map),
        cmocka_unit_test(per_link_distances),
        cmocka_unit_test(signed_distance),
        cmocka_unit_test(convex_shape_survives_later_shapes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
