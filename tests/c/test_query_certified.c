/*
 * OPX_MOTION_CERTIFIED against obstacles that sampling steps over: a
 * stick turning about z sweeps its tip sphere past a single 2 cm cell, a
 * 2 mm world plate and a lone sensed point (point extents), each lying
 * between two samples at the caller's resolution.  The sampled check says
 * free; the certified one says collides, its fraction's configuration
 * touching the obstacle and no configuration of a dense walk (1e-4 of the
 * motion) colliding before the fraction less the tolerance.  Then bad
 * input: tolerance, check codes, cost, NaN joints; a zero-length motion.
 */
#include "opx_batch_test.h"

#define TIP 1.0         /* the tip sphere's centre, metres from the axis */
#define TIP_RADIUS 0.01
#define CROSSING 0.05   /* rad: where the obstacles lie */
#define TURN 1.0        /* rad: the motion */
#define COARSE 0.1      /* rad: the sampled check's resolution */
#define DENSE 10000

static opx_linkset *load_stick(void) {
    static const char xml[] =
        "<?xml version=\"1.0\"?><robot name=\"stick\"><link name=\"base\"/>"
        "<link name=\"stick\"><collision><origin xyz=\"1 0 0\"/><geometry><sphere radius=\"0.01\"/>"
        "</geometry></collision></link>"
        "<joint name=\"turn\" type=\"revolute\"><parent link=\"base\"/><child link=\"stick\"/>"
        "<axis xyz=\"0 0 1\"/><limit lower=\"-3\" upper=\"3\" effort=\"1\" velocity=\"1\"/></joint></robot>";
    opx_linkset *stick = NULL;
    assert_ok(opx_linkset_load_urdf_string(xml, NULL, &stick));
    return stick;
}

typedef struct obstacle_case {
    const opx_octree *tree;
    const opx_world *world;
    int32_t geometry;
} obstacle_case;

static opx_query *query_for(const obstacle_case *c) {
    opx_query *query = new_query();
    if (c->world != NULL) assert_ok(opx_query_set_world(query, c->world));
    return query;
}

static opx_motion_result check_one(const obstacle_case *c, opx_linkset *stick, int32_t check, double goal) {
    opx_query *query = query_for(c);
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.resolution = COARSE;
    request.obstacle_geometry = c->geometry;
    request.check = check;
    const double start = 0.0;
    opx_motion_result result = OPX_MOTION_RESULT_INIT;
    assert_ok(opx_query_check_motion(query, c->tree, stick, &start, &goal, 1, NULL, &request, &result));
    opx_query_destroy(query);
    return result;
}

static int collides_at(opx_query *query, const obstacle_case *c, opx_linkset *stick, double angle) {
    assert_ok(opx_linkset_set_joint_positions(stick, &angle, 1, NULL));
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.max_contacts = 0;
    request.obstacle_geometry = c->geometry;
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    assert_ok(opx_query_collide(query, c->tree, stick, &request, &result));
    return result.collided;
}

static double distance_at(opx_query *query, const obstacle_case *c, opx_linkset *stick, double angle) {
    assert_ok(opx_linkset_set_joint_positions(stick, &angle, 1, NULL));
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.obstacle_geometry = c->geometry;
    return distance_with(query, c->tree, stick, &request).distance;
}

static void sampling_misses_certified_finds(const obstacle_case *c) {
    opx_linkset *stick = load_stick();
    const opx_motion_result sampled = check_one(c, stick, OPX_MOTION_SAMPLED, TURN);
    assert_int_equal(sampled.collided, 0);
    const opx_motion_result certified = check_one(c, stick, OPX_MOTION_CERTIFIED, TURN);
    assert_int_equal(certified.collided, 1);
    const double f = certified.first_collision_fraction, tolerance = 1e-3;
    assert_true(f > 0.0 && f < CROSSING / TURN);
    opx_query *query = query_for(c);
    assert_true(distance_at(query, c, stick, f * TURN) <= OPX_MOTION_CONTACT_DISTANCE);
    for (int i = 0; i <= DENSE && (double)i / DENSE < f - tolerance; ++i)
        assert_int_equal(collides_at(query, c, stick, (double)i / DENSE * TURN), 0);
    assert_int_equal(collides_at(query, c, stick, CROSSING), 1); /* the obstacle is there */
    opx_query_destroy(query);
    opx_linkset_destroy(stick);
}

static void misses_a_single_cell(void **state) {
    (void)state;
    opx_octree *tree = new_tree(0.02);
    const double xyz[3] = {TIP * cos(CROSSING), TIP * sin(CROSSING), 0.0};
    const opx_insert_options options = sensor_at(0.0, 0.0, 0.0, OPX_INSERT_ENDPOINTS);
    insert_f64(tree, xyz, 1, &options);
    const obstacle_case c = {tree, NULL, OPX_OBSTACLE_CELLS};
    sampling_misses_certified_finds(&c);
    opx_octree_destroy(tree);
}

static void misses_a_thin_world_plate(void **state) {
    (void)state;
    opx_world *world = NULL;
    assert_ok(opx_world_create(&world));
    const opx_pose at = pose_at(TIP, TIP * sin(CROSSING), 0.0);
    uint32_t object = 0;
    assert_ok(opx_world_add_object(world, "plate", &at, &object));
    const opx_shape plate = box_shape(0.2, 0.002, 0.2);
    assert_ok(opx_world_add_shape(world, object, &plate, NULL));
    const obstacle_case c = {NULL, world, OPX_OBSTACLE_CELLS};
    sampling_misses_certified_finds(&c);
    opx_world_destroy(world);
}

static void misses_a_lone_point_extent(void **state) {
    (void)state;
    opx_octree *tree = new_tree(0.2); /* the cell holds both samples; its point does not */
    const double xyz[3] = {TIP * cos(CROSSING), TIP * sin(CROSSING), 0.0};
    const opx_insert_options options = sensor_at(0.0, 0.0, 0.0, OPX_INSERT_ENDPOINTS);
    insert_f64(tree, xyz, 1, &options);
    const obstacle_case c = {tree, NULL, OPX_OBSTACLE_POINT_EXTENTS};
    sampling_misses_certified_finds(&c);
    opx_octree_destroy(tree);
}

/* Far from the cell both ways, and the motion of zero length at a free
 * and at a colliding configuration. */
static void free_and_zero_length_motions(void **state) {
    (void)state;
    opx_octree *tree = new_tree(0.02);
    const double xyz[3] = {TIP * cos(CROSSING), TIP * sin(CROSSING), 0.0};
    const opx_insert_options options = sensor_at(0.0, 0.0, 0.0, OPX_INSERT_ENDPOINTS);
    insert_f64(tree, xyz, 1, &options);
    const obstacle_case c = {tree, NULL, OPX_OBSTACLE_CELLS};
    opx_linkset *stick = load_stick();
    opx_query *query = query_for(&c);
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.check = OPX_MOTION_CERTIFIED;
    opx_motion_result result = OPX_MOTION_RESULT_INIT;
    const double a = 0.5, b = 2.5, at_cell = CROSSING;
    assert_ok(opx_query_check_motion(query, tree, stick, &a, &b, 1, NULL, &request, &result));
    assert_int_equal(result.collided, 0);
    assert_true(result.first_collision_fraction == -1.0);
    assert_ok(opx_query_check_motion(query, tree, stick, &a, &a, 1, NULL, &request, &result));
    assert_int_equal(result.collided, 0);
    assert_ok(opx_query_check_motion(query, tree, stick, &at_cell, &at_cell, 1, NULL, &request, &result));
    assert_int_equal(result.collided, 1);
    assert_true(result.first_collision_fraction == 0.0);
    opx_query_destroy(query);
    opx_linkset_destroy(stick);
    opx_octree_destroy(tree);
}

static void expect_invalid(opx_query *query, const opx_octree *tree, opx_linkset *stick, const double *a,
                           const double *b, const opx_motion_request *request, const char *argument) {
    opx_motion_result result = OPX_MOTION_RESULT_INIT;
    assert_int_equal(opx_query_check_motion(query, tree, stick, a, b, 1, NULL, request, &result),
                     OPX_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(opx_last_error(), argument));
    uint8_t collided = 7;
    assert_int_equal(opx_query_check_motions(query, tree, stick, a, b, 1, 1, 0, NULL, 0, 0, request, &collided,
                                             NULL, 1),
                     OPX_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(opx_last_error(), "opx_query_check_motions"));
}

static void bad_input_is_refused(void **state) {
    (void)state;
    opx_octree *tree = new_tree(0.02);
    opx_linkset *stick = load_stick();
    opx_query *query = new_query();
    const double a = 0.0, b = 1.0, nan_value = NAN;
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.check = OPX_MOTION_CERTIFIED;
    const double tolerances[4] = {0.0, -1e-3, NAN, 1.5};
    for (int i = 0; i < 4; ++i) {
        request.tolerance = tolerances[i];
        expect_invalid(query, tree, stick, &a, &b, &request, "request->tolerance");
    }
    request.tolerance = 1e-3;
    request.compute_cost = 1;
    expect_invalid(query, tree, stick, &a, &b, &request, "request->compute_cost");
    request.compute_cost = 0;
    expect_invalid(query, tree, stick, &nan_value, &b, &request, "start");
    expect_invalid(query, tree, stick, &a, &nan_value, &request, "goal");
    request.check = 2;
    expect_invalid(query, tree, stick, &a, &b, &request, "request->check");
    request.check = -1;
    expect_invalid(query, tree, stick, &a, &b, &request, "request->check");
    /* The resolution does not apply: any value is accepted. */
    request.check = OPX_MOTION_CERTIFIED;
    request.resolution = 0.0;
    opx_motion_result result = OPX_MOTION_RESULT_INIT;
    assert_ok(opx_query_check_motion(query, tree, stick, &a, &b, 1, NULL, &request, &result));
    opx_query_destroy(query);
    opx_linkset_destroy(stick);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(misses_a_single_cell),
        cmocka_unit_test(misses_a_thin_world_plate),
        cmocka_unit_test(misses_a_lone_point_extent),
        cmocka_unit_test(free_and_zero_length_motions),
        cmocka_unit_test(bad_input_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
