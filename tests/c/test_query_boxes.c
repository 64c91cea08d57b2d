/*
 * A caller's boxes as the map of an amortized context (opx_query_bind_boxes,
 * opx_query_collide_boxes, opx_query_distance_boxes).  Checked: the
 * occupied cells of an octree given as boxes answer exactly as the octree
 * does (every shape kind, random poses); random non-cubic boxes against a
 * sphere match a brute-force distance; strides, empty maps, stats; and every
 * bad input gets an error naming the function and argument, with the boxes
 * bound before left in place.
 */
#include "opx_query_test.h"

#include <math.h>
#include <stdlib.h>

#define BOX_DOUBLES 6

/* Deterministic uniform numbers in [lo, hi) (a 64-bit LCG, top 53 bits). */
static uint64_t g_seed = 0x0B0C5u;
static double uniform(double lo, double hi) {
    g_seed = g_seed * 6364136223846793005ull + 1442695040888963407ull;
    return lo + (hi - lo) * (double)(g_seed >> 11) * 0x1.0p-53;
}

static opx_query *new_amortized_query(void) {
    opx_query_options options = OPX_QUERY_OPTIONS_INIT;
    options.engine = OPX_ENGINE_AMORTIZED;
    opx_query *query = NULL;
    assert_ok(opx_query_create(&options, &query));
    return query;
}

/* 300 random hits in [-1, 1]^3 at 0.1 m. */
static opx_octree *new_random_map(void) {
    opx_octree *tree = new_tree(0.1);
    double xyz[300 * 3];
    for (int i = 0; i < 300 * 3; ++i) xyz[i] = uniform(-1.0, 1.0);
    const opx_insert_options options = sensor_at(0.0, 0.0, 0.0, OPX_INSERT_ENDPOINTS);
    insert_f64(tree, xyz, 300, &options);
    return tree;
}

/* The occupied leaves of `tree` as boxes (malloc'ed, 6 doubles each). */
static double *leaves_as_boxes(const opx_octree *tree, size_t *out_count) {
    opx_leaf *leaves = all_leaves(tree, OPX_MASK_OCCUPIED, out_count);
    double *boxes = malloc(*out_count * BOX_DOUBLES * sizeof(double) + 1);
    assert_non_null(boxes);
    for (size_t i = 0; i < *out_count; ++i)
        for (int axis = 0; axis < 3; ++axis) {
            boxes[BOX_DOUBLES * i + axis] = leaves[i].center[axis] - 0.5 * leaves[i].size;
            boxes[BOX_DOUBLES * i + 3 + axis] = leaves[i].center[axis] + 0.5 * leaves[i].size;
        }
    free(leaves);
    return boxes;
}

static void random_poses(opx_pose *poses, uint32_t count) {
    for (uint32_t i = 0; i < count; ++i) {
        poses[i] = pose_at(uniform(-1.2, 1.2), uniform(-1.2, 1.2), uniform(-1.2, 1.2));
        double norm = 0.0;
        for (int k = 0; k < 4; ++k) {
            poses[i].orientation[k] = uniform(-1.0, 1.0);
            norm += poses[i].orientation[k] * poses[i].orientation[k];
        }
        for (int k = 0; k < 4; ++k) poses[i].orientation[k] /= sqrt(norm);
    }
}

/* The deepest contact (compute_penetration) and the signed distance
 * against the cells as boxes equal the octree's. */
static void deepest_contacts_agree(opx_query *direct, const opx_octree *tree, opx_query *amortized,
                                   const opx_linkset *robot) {
    opx_collision_request depth = OPX_COLLISION_REQUEST_INIT;
    depth.max_contacts = UINT32_MAX;
    depth.compute_penetration = 1;
    opx_collision_result expected = OPX_COLLISION_RESULT_INIT, actual = OPX_COLLISION_RESULT_INIT;
    assert_ok(opx_query_collide(direct, tree, robot, &depth, &expected));
    assert_ok(opx_query_collide_boxes(amortized, robot, &depth, &actual));
    assert_int_equal(actual.contact_count, expected.contact_count);
    double deepest[2] = {0.0, 0.0};
    opx_query *queries[2] = {direct, amortized};
    for (int q = 0; q < 2; ++q)
        for (size_t i = 0; i < expected.contact_count; ++i) {
            opx_contact contact = OPX_CONTACT_INIT;
            assert_ok(opx_query_get_contact(queries[q], i, &contact));
            assert_true(contact.depth >= 0.0);
            if (contact.depth > deepest[q]) deepest[q] = contact.depth;
        }
    assert_near(deepest[1], deepest[0], 1e-9);
    opx_distance_request signed_request = OPX_DISTANCE_REQUEST_INIT;
    signed_request.signed_distance = 1;
    const opx_distance_result d_expected = distance_with(direct, tree, robot, &signed_request);
    opx_distance_result d_actual = OPX_DISTANCE_RESULT_INIT;
    assert_ok(opx_query_distance_boxes(amortized, robot, &signed_request, &d_actual));
    assert_true(d_expected.distance <= 0.0);
    assert_near(d_actual.distance, d_expected.distance, 1e-9);
}

static void boxes_answer_as_the_octree_does(void **state) {
    (void)state;
    opx_octree *tree = new_random_map();
    size_t count = 0;
    double *boxes = leaves_as_boxes(tree, &count);
    assert_true(count > 250);
    opx_linkset *robot = new_robot(); /* every shape kind */
    opx_query *direct = new_query(), *amortized = new_amortized_query();
    assert_ok(opx_query_bind_boxes(amortized, boxes, count, 0));
    opx_distance_request per_link = OPX_DISTANCE_REQUEST_INIT;
    per_link.per_link = 1;
    int hits = 0;
    for (int trial = 0; trial < 300; ++trial) {
        opx_pose poses[3];
        random_poses(poses, 3);
        assert_ok(opx_linkset_set_poses(robot, poses, 3, 0));
        opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
        request.max_contacts = UINT32_MAX;
        opx_collision_result expected = OPX_COLLISION_RESULT_INIT, actual = OPX_COLLISION_RESULT_INIT;
        assert_ok(opx_query_collide(direct, tree, robot, &request, &expected));
        assert_ok(opx_query_collide_boxes(amortized, robot, &request, &actual));
        assert_int_equal(actual.collided, expected.collided);
        assert_int_equal(actual.contact_count, expected.contact_count);
        hits += expected.collided;
        const opx_distance_result d_expected = distance_with(direct, tree, robot, &per_link);
        opx_distance_result d_actual = OPX_DISTANCE_RESULT_INIT;
        assert_ok(opx_query_distance_boxes(amortized, robot, &per_link, &d_actual));
        assert_int_equal(d_actual.found, d_expected.found);
        assert_near(d_actual.distance, d_expected.distance, 1e-9); /* GJK shapes: its tolerance */
        assert_int_equal(d_actual.collided, d_expected.collided);
        double a[3], b[3];
        size_t n = 0;
        assert_ok(opx_query_get_link_distances(direct, b, 3, &n));
        assert_ok(opx_query_get_link_distances(amortized, a, 3, &n));
        for (int l = 0; l < 3; ++l) assert_near(a[l], b[l], 1e-9);
        if (expected.collided) deepest_contacts_agree(direct, tree, amortized, robot);
    }
    assert_true(hits > 10 && hits < 290); /* both answers exercised */
    opx_query_stats stats = OPX_QUERY_STATS_INIT;
    assert_ok(opx_query_get_stats(amortized, &stats));
    assert_int_equal(stats.boxes, count);
    assert_int_equal(stats.builds, 1);
    assert_int_equal(stats.refine_steps_done, 600 + 2 * hits); /* one step a query */
    opx_query_destroy(direct);
    opx_query_destroy(amortized);
    opx_linkset_destroy(robot);
    free(boxes);
    opx_octree_destroy(tree);
}

/* Sphere to box, exact: the gap from the centre to the box less the radius. */
static double sphere_box_distance(const double c[3], double r, const double *box) {
    double squared = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double below = box[axis] - c[axis], above = c[axis] - box[3 + axis];
        const double gap = below > 0.0 ? below : above > 0.0 ? above : 0.0;
        squared += gap * gap;
    }
    const double d = sqrt(squared) - r;
    return d > 0.0 ? d : 0.0;
}

static void odd_boxes_match_brute_force(void **state) {
    (void)state;
    enum { N = 200 };
    double boxes[N * BOX_DOUBLES];
    for (int i = 0; i < N; ++i)
        for (int axis = 0; axis < 3; ++axis) {
            const double lo = uniform(-3.0, 3.0);
            boxes[BOX_DOUBLES * i + axis] = lo;
            boxes[BOX_DOUBLES * i + 3 + axis] = lo + uniform(0.0, 0.6); /* flat boxes too */
        }
    opx_query *query = new_amortized_query();
    assert_ok(opx_query_bind_boxes(query, boxes, N, 0));
    const double radius = 0.15;
    opx_linkset *ball = new_sphere_at(radius, 0.0, 0.0, 0.0);
    int touching = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const double c[3] = {uniform(-3.5, 3.5), uniform(-3.5, 3.5), uniform(-3.5, 3.5)};
        const opx_pose pose = pose_at(c[0], c[1], c[2]);
        assert_ok(opx_linkset_set_poses(ball, &pose, 1, 0));
        double expected = INFINITY;
        for (int i = 0; i < N; ++i) {
            const double d = sphere_box_distance(c, radius, boxes + BOX_DOUBLES * i);
            if (d < expected) expected = d;
        }
        opx_distance_result d = OPX_DISTANCE_RESULT_INIT;
        assert_ok(opx_query_distance_boxes(query, ball, NULL, &d));
        assert_int_equal(d.found, 1);
        assert_near(d.distance, expected, 1e-9);
        double gap = 0.0;
        for (int axis = 0; axis < 3; ++axis)
            gap += (d.point_on_cell[axis] - d.point_on_link[axis]) * (d.point_on_cell[axis] - d.point_on_link[axis]);
        assert_near(sqrt(gap), d.distance, 1e-9);
        if (fabs(expected) > 1e-6) { /* clear of the touch tolerance */
            opx_collision_result r = OPX_COLLISION_RESULT_INIT;
            assert_ok(opx_query_collide_boxes(query, ball, NULL, &r));
            assert_int_equal(r.collided, expected == 0.0);
        }
        touching += expected == 0.0;
        if (d.distance == 0.0 && d.found) {
            opx_collision_result r = OPX_COLLISION_RESULT_INIT;
            assert_ok(opx_query_collide_boxes(query, ball, NULL, &r));
            assert_int_equal(r.collided, 1);
            const opx_contact contact = get_contact(query, 0);
            assert_int_equal(contact.cell_class, OPX_CELL_OCCUPIED);
            assert_near(contact.cell_probability, 1.0, 0.0);
        }
    }
    assert_true(touching > 20 && touching < 1980);
    opx_linkset_destroy(ball);
    opx_query_destroy(query);
}

static void strides_and_empty_maps(void **state) {
    (void)state;
    /* [1, 2] x [0, 1] x [0, 3] and a far box, each padded with a seventh double. */
    const double padded[14] = {1.0, 0.0, 0.0, 2.0, 1.0, 3.0, NAN, 10.0, 10.0, 10.0, 11.0, 11.0, 11.0, NAN};
    opx_query *query = new_amortized_query();
    assert_ok(opx_query_bind_boxes(query, padded, 2, 7 * sizeof(double)));
    opx_linkset *ball = new_sphere_at(0.25, 0.5, 0.5, 1.5);
    opx_distance_result d = OPX_DISTANCE_RESULT_INIT;
    assert_ok(opx_query_distance_boxes(query, ball, NULL, &d));
    assert_near(d.distance, 0.25, 1e-12);
    assert_center(d.cell_center, 1.5, 0.5, 1.5);
    assert_near(d.cell_size, 3.0, 1e-12); /* the longest edge */
    assert_int_equal(d.cell_class, OPX_CELL_OCCUPIED);
    opx_distance_request near = OPX_DISTANCE_REQUEST_INIT;
    near.cutoff = 0.1; /* the box is 0.25 away: "at least 0.1" */
    assert_ok(opx_query_distance_boxes(query, ball, &near, &d));
    assert_int_equal(d.found, 0);
    assert_near(d.distance, 0.1, 0.0);
    assert_ok(opx_query_bind_boxes(query, NULL, 0, 0));
    opx_collision_result r = OPX_COLLISION_RESULT_INIT;
    assert_ok(opx_query_collide_boxes(query, ball, NULL, &r));
    assert_int_equal(r.collided, 0);
    assert_ok(opx_query_distance_boxes(query, ball, NULL, &d));
    assert_int_equal(d.found, 0);
    assert_true(isinf(d.distance));
    opx_linkset_destroy(ball);
    opx_query_destroy(query);
}

static void bad_input_is_refused(void **state) {
    (void)state;
    const double good[6] = {0.0, 0.0, 0.0, 1.0, 1.0, 1.0};
    const double nan_box[12] = {0, 0, 0, 1, 1, 1, 0, NAN, 0, 1, 1, 1};
    const double inverted[6] = {0.0, 2.0, 0.0, 1.0, 1.0, 1.0};
    opx_query *direct = new_query(), *query = new_amortized_query();
    opx_linkset *ball = new_sphere_at(0.1, 1.05, 0.5, 0.5); /* 0.05 into the box */
    opx_collision_result r = OPX_COLLISION_RESULT_INIT;
    opx_distance_result d = OPX_DISTANCE_RESULT_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_bind_boxes", "OPX_ENGINE_AMORTIZED",
                   opx_query_bind_boxes(direct, good, 1, 0));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_collide_boxes", "opx_query_bind_boxes",
                   opx_query_collide_boxes(query, ball, NULL, &r));
    assert_ok(opx_query_bind_boxes(query, good, 1, 0));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_bind_boxes", "query",
                   opx_query_bind_boxes(NULL, good, 1, 0));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_bind_boxes", "boxes",
                   opx_query_bind_boxes(query, NULL, 1, 0));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_bind_boxes", "boxes[1]",
                   opx_query_bind_boxes(query, nan_box, 2, 0));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_bind_boxes", "boxes[0]",
                   opx_query_bind_boxes(query, inverted, 1, 0));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_bind_boxes", "stride",
                   opx_query_bind_boxes(query, good, 1, 40));
    /* The failed binds left the good box bound. */
    assert_ok(opx_query_collide_boxes(query, ball, NULL, &r));
    assert_int_equal(r.collided, 1);
    opx_collision_request cost = OPX_COLLISION_REQUEST_INIT;
    cost.compute_cost = 1;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_collide_boxes", "compute_cost",
                   opx_query_collide_boxes(query, ball, &cost, &r));
    opx_distance_request cutoff = OPX_DISTANCE_REQUEST_INIT;
    cutoff.cutoff = NAN;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_distance_boxes", "cutoff",
                   opx_query_distance_boxes(query, ball, &cutoff, &d));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_distance_boxes", "links",
                   opx_query_distance_boxes(query, NULL, NULL, &d));
    /* An octree query binds its frame: the boxes are gone. */
    opx_octree *tree = new_one_cell_map();
    assert_ok(opx_query_collide(query, tree, ball, NULL, &r));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_query_distance_boxes", "opx_query_bind_boxes",
                   opx_query_distance_boxes(query, ball, NULL, &d));
    opx_octree_destroy(tree);
    opx_linkset_destroy(ball);
    opx_query_destroy(direct);
    opx_query_destroy(query);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(boxes_answer_as_the_octree_does),
        cmocka_unit_test(odd_boxes_match_brute_force),
        cmocka_unit_test(strides_and_empty_maps),
        cmocka_unit_test(bad_input_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
