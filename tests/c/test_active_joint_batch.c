/*
 * The batch calls (batch.h) on rows of active joints: on the generated
 * arm (fixed and mimic joints) and on the robot with every joint type, the
 * answers equal those of the same configurations in model order, with the
 * order told by joint_count (OPX_JOINTS_BY_COUNT) or by joint_order;
 * a joint_count the order does not allow, or an unknown order, fails.
 */
#include "opx_batch_test.h"
#include "opx_joints_test.h"

#define ROWS 60
#define ARM_ACTIVE 8

/* `rows` random active vectors of the arm (j1..j7, finger_l) and the same
 * configurations in model order (mimic and fixed joints at garbage). */
static void arm_rows(uint64_t seed, double active[ROWS * ARM_ACTIVE], double model[ROWS * ARM_JOINTS]) {
    double *from_model = random_arm_rows(ROWS, seed);
    for (size_t i = 0; i < ROWS; ++i)
        for (size_t j = 0; j < ARM_ACTIVE; ++j) active[i * ARM_ACTIVE + j] = from_model[i * ARM_JOINTS + j];
    memcpy(model, from_model, ROWS * ARM_JOINTS * sizeof *model);
    free(from_model);
}

static void check_configurations(opx_query *query, const opx_octree *tree, const opx_linkset *arm,
                                 const double *rows, size_t joint_count, int32_t order, uint8_t *collided,
                                 double *distances) {
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.compute_distance = 1;
    request.self_collision = 1;
    request.joint_order = order;
    assert_ok(opx_query_check_configurations(query, tree, arm, rows, ROWS, joint_count, 0, NULL, 0, 0, &request,
                                             collided, distances, ROWS));
}

static void active_rows_answer_as_model_rows(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    disable_adjacent_arm_pairs(arm);
    opx_octree *tree = new_scatter_map(3);
    opx_query *query = new_query();
    static double active[ROWS * ARM_ACTIVE], model[ROWS * ARM_JOINTS];
    arm_rows(17, active, model);
    uint8_t by_model[ROWS], by_count[ROWS], by_order[ROWS];
    double d_model[ROWS], d_count[ROWS], d_order[ROWS];
    check_configurations(query, tree, arm, model, ARM_JOINTS, OPX_JOINTS_BY_COUNT, by_model, d_model);
    check_configurations(query, tree, arm, active, ARM_ACTIVE, OPX_JOINTS_BY_COUNT, by_count, d_count);
    check_configurations(query, tree, arm, active, ARM_ACTIVE, OPX_JOINTS_ACTIVE, by_order, d_order);
    assert_memory_equal(by_model, by_count, sizeof by_model);
    assert_memory_equal(by_model, by_order, sizeof by_model);
    assert_memory_equal(d_model, d_count, sizeof d_model);
    assert_memory_equal(d_model, d_order, sizeof d_model);
    int hits = 0;
    for (size_t i = 0; i < ROWS; ++i) hits += by_model[i];
    assert_true(hits > 0 && hits < ROWS); /* the rows tell something apart */
    /* Model order insisted on gives the same. */
    check_configurations(query, tree, arm, model, ARM_JOINTS, OPX_JOINTS_MODEL, by_order, d_order);
    assert_memory_equal(by_model, by_order, sizeof by_model);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

static void active_motions_answer_as_model_motions(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    opx_octree *tree = new_scatter_map(5);
    opx_query *query = new_query();
    static double active[ROWS * ARM_ACTIVE], model[ROWS * ARM_JOINTS];
    arm_rows(23, active, model);
    /* Motions from row 2m to row 2m + 1: starts and goals interleaved. */
    const size_t motions = ROWS / 2;
    uint8_t hit_model[ROWS / 2], hit_active[ROWS / 2];
    double first_model[ROWS / 2], first_active[ROWS / 2];
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.resolution = 0.05;
    assert_ok(opx_query_check_motions(query, tree, arm, model, model + ARM_JOINTS, motions, ARM_JOINTS,
                                      2 * ARM_JOINTS * sizeof(double), NULL, 0, 0, &request, hit_model,
                                      first_model, motions));
    request.joint_order = OPX_JOINTS_ACTIVE;
    assert_ok(opx_query_check_motions(query, tree, arm, active, active + ARM_ACTIVE, motions, ARM_ACTIVE,
                                      2 * ARM_ACTIVE * sizeof(double), NULL, 0, 0, &request, hit_active,
                                      first_active, motions));
    assert_memory_equal(hit_model, hit_active, sizeof hit_model);
    assert_memory_equal(first_model, first_active, sizeof first_model);
    /* One motion, with cost: the same steps, checks and cost. */
    request.joint_order = OPX_JOINTS_BY_COUNT;
    request.compute_cost = 1;
    opx_motion_result by_model = OPX_MOTION_RESULT_INIT, by_active = OPX_MOTION_RESULT_INIT;
    assert_ok(opx_query_check_motion(query, tree, arm, model, model + ARM_JOINTS, ARM_JOINTS, NULL, &request,
                                     &by_model));
    assert_ok(opx_query_check_motion(query, tree, arm, active, active + ARM_ACTIVE, ARM_ACTIVE, NULL, &request,
                                     &by_active));
    assert_memory_equal(&by_model, &by_active, sizeof by_model);
    assert_true(by_model.steps > 1);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

/* The robot with floating, planar and chained mimic joints: two values a
 * row, and the single FK call agrees. */
static void every_joint_type_batches_by_its_active_joints(void **state) {
    (void)state;
    opx_linkset *robot = load_urdf_text(MIXED_URDF);
    /* A thin wall at x = 0.37 that link e's box meets for a middle lift. */
    opx_octree *tree = new_tree(0.05);
    double wall[3 * 17];
    for (int k = 0; k < 17; ++k) wall[3 * k] = 0.37, wall[3 * k + 1] = 0.01, wall[3 * k + 2] = 0.2 + 0.05 * k;
    const opx_insert_options endpoints = sensor_at(0.0, 0.0, 0.0, OPX_INSERT_ENDPOINTS);
    insert_f64(tree, wall, 17, &endpoints);
    opx_query *query = new_query();
    enum { N = 40 };
    double rows[N * MIXED_ACTIVE];
    uint64_t seed = 9;
    for (int i = 0; i < N; ++i) {
        rows[2 * i] = next_uniform(&seed, 0.0, 0.8);      /* lift */
        rows[2 * i + 1] = next_uniform(&seed, -3.0, 3.0); /* spin */
    }
    uint8_t collided[N];
    double distances[N];
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.compute_distance = 1;
    assert_ok(opx_query_check_configurations(query, tree, robot, rows, N, MIXED_ACTIVE, 0, NULL, 0, 0, &request,
                                             collided, distances, N));
    int hits = 0;
    for (int i = 0; i < N; ++i) {
        assert_ok(opx_linkset_set_active_joint_positions(robot, rows + 2 * i, MIXED_ACTIVE, NULL));
        assert_int_equal(collided[i], collide_with(query, tree, robot, 0).collided);
        opx_distance_request single = OPX_DISTANCE_REQUEST_INIT;
        assert_true(distances[i] == distance_with(query, tree, robot, &single).distance);
        hits += collided[i];
    }
    assert_true(hits > 0 && hits < N);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    opx_linkset_destroy(robot);
}

#define CHECK "opx_query_check_configurations"
#define BAD OPX_ERROR_INVALID_ARGUMENT

static opx_status check_with_order(opx_query *query, const opx_octree *tree, const opx_linkset *arm,
                                   const double *rows, size_t joint_count, int32_t order) {
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.joint_order = order;
    uint8_t collided[2];
    return opx_query_check_configurations(query, tree, arm, rows, 2, joint_count, 0, NULL, 0, 0, &request,
                                          collided, NULL, 2);
}

static void a_count_the_order_does_not_allow_fails(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    opx_octree *tree = new_scatter_map(5);
    opx_query *query = new_query();
    double rows[2 * ARM_JOINTS] = {0.0};
    expect_failure(BAD, CHECK, "joint_count 9", check_with_order(query, tree, arm, rows, 9, OPX_JOINTS_BY_COUNT));
    expect_failure(BAD, CHECK, "OPX_JOINTS_MODEL",
                   check_with_order(query, tree, arm, rows, ARM_ACTIVE, OPX_JOINTS_MODEL));
    expect_failure(BAD, CHECK, "OPX_JOINTS_ACTIVE",
                   check_with_order(query, tree, arm, rows, ARM_JOINTS, OPX_JOINTS_ACTIVE));
    expect_failure(BAD, CHECK, "request->joint_order", check_with_order(query, tree, arm, rows, ARM_JOINTS, 3));
    expect_failure(BAD, CHECK, "request->joint_order", check_with_order(query, tree, arm, rows, ARM_JOINTS, -1));
    /* A bad value in a row of active joints is named by its place in the row. */
    rows[ARM_ACTIVE + 5] = NAN;
    expect_failure(BAD, CHECK, "positions[row 1][joint 5]",
                   check_with_order(query, tree, arm, rows, ARM_ACTIVE, OPX_JOINTS_BY_COUNT));
    /* An older request without joint_order: rows told by their count. */
    opx_batch_request older = OPX_BATCH_REQUEST_INIT;
    older.struct_size = offsetof(opx_batch_request, joint_order);
    older.joint_order = 77; /* beyond the caller's struct_size: not read */
    rows[ARM_ACTIVE + 5] = 0.0;
    uint8_t collided[2];
    assert_ok(opx_query_check_configurations(query, tree, arm, rows, 2, ARM_ACTIVE, 0, NULL, 0, 0, &older,
                                             collided, NULL, 2));
    opx_motion_request motion = OPX_MOTION_REQUEST_INIT;
    motion.joint_order = OPX_JOINTS_MODEL;
    opx_motion_result result = OPX_MOTION_RESULT_INIT;
    expect_failure(BAD, "opx_query_check_motion", "OPX_JOINTS_MODEL",
                   opx_query_check_motion(query, tree, arm, rows, rows, ARM_ACTIVE, NULL, &motion, &result));
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

/* When every joint is active, the two orders are one: both counts and
 * every joint_order accept the rows. */
static void every_joint_active_makes_one_order(void **state) {
    (void)state;
    static const char xml[] =
        "<robot name=\"pendulum\"><link name=\"base\"/><link name=\"bob\"><collision><origin xyz=\"1 0 0\"/>"
        "<geometry><sphere radius=\"0.1\"/></geometry></collision></link>"
        "<joint name=\"swing\" type=\"continuous\"><parent link=\"base\"/><child link=\"bob\"/>"
        "<axis xyz=\"0 0 1\"/></joint></robot>";
    opx_linkset *robot = load_urdf_text(xml);
    assert_int_equal(active_joint_count(robot), 1);
    opx_octree *tree = new_one_cell_map();
    opx_query *query = new_query();
    const double rows[2] = {0.0, 1.0};
    assert_ok(check_with_order(query, tree, robot, rows, 1, OPX_JOINTS_BY_COUNT));
    assert_ok(check_with_order(query, tree, robot, rows, 1, OPX_JOINTS_MODEL));
    assert_ok(check_with_order(query, tree, robot, rows, 1, OPX_JOINTS_ACTIVE));
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    opx_linkset_destroy(robot);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(active_rows_answer_as_model_rows),
        cmocka_unit_test(active_motions_answer_as_model_motions),
        cmocka_unit_test(every_joint_type_batches_by_its_active_joints),
        cmocka_unit_test(a_count_the_order_does_not_allow_fails),
        cmocka_unit_test(every_joint_active_makes_one_order),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
