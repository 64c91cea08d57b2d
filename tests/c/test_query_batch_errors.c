/*
 * The batch queries refuse bad input with a status and a message naming
 * the function and the argument, and leave the link set as it was: NULL
 * handles and arrays, strides smaller than a row or a pose, zero rows,
 * NaN and out-of-range joints, too-small outputs, uninitialised structs,
 * a joint count that is not the robot's, base pose counts, resolutions,
 * and link sets without joints.
 */
#include "opx_batch_test.h"

static const char *const CHECK = "opx_query_check_configurations";
static const char *const MOTION = "opx_query_check_motion";
static const char *const MOTIONS = "opx_query_check_motions";

typedef struct fixture {
    opx_linkset *arm;
    opx_octree *tree;
    opx_query *query;
    double rows[4 * ARM_JOINTS];
    uint8_t collided[4];
    double distances[4];
    opx_pose before[ARM_LINKS];
} fixture;

static int setup(void **state) {
    fixture *f = calloc(1, sizeof *f);
    f->arm = load_arm();
    f->tree = new_scatter_map(7);
    f->query = new_query();
    double *rows = random_arm_rows(4, 3);
    memcpy(f->rows, rows, sizeof f->rows);
    free(rows);
    arm_poses(f->arm, f->before);
    *state = f;
    return 0;
}

static int teardown(void **state) {
    fixture *f = *state;
    assert_arm_at(f->arm, f->before);
    opx_query_destroy(f->query);
    opx_octree_destroy(f->tree);
    opx_linkset_destroy(f->arm);
    free(f);
    return 0;
}

#define CHECK_CALL(f, rows, n, joints, stride, bases, nb, bstride, req, out, dist, cap) \
    opx_query_check_configurations((f)->query, (f)->tree, (f)->arm, (rows), (n), (joints), (stride), (bases), \
                                   (nb), (bstride), (req), (out), (dist), (cap))

static void configurations_refuse_bad_arrays(void **state) {
    fixture *f = *state;
    const double *q = f->rows;
    uint8_t *out = f->collided;
    const int32_t BAD = OPX_ERROR_INVALID_ARGUMENT;
    expect_failure(BAD, CHECK, "query",
                   opx_query_check_configurations(NULL, f->tree, f->arm, q, 4, ARM_JOINTS, 0, NULL, 0, 0, NULL,
                                                  out, NULL, 4));
    expect_failure(BAD, CHECK, "tree",
                   opx_query_check_configurations(f->query, NULL, f->arm, q, 4, ARM_JOINTS, 0, NULL, 0, 0, NULL,
                                                  out, NULL, 4));
    expect_failure(BAD, CHECK, "links",
                   opx_query_check_configurations(f->query, f->tree, NULL, q, 4, ARM_JOINTS, 0, NULL, 0, 0, NULL,
                                                  out, NULL, 4));
    expect_failure(BAD, CHECK, "positions", CHECK_CALL(f, NULL, 4, ARM_JOINTS, 0, NULL, 0, 0, NULL, out, NULL, 4));
    expect_failure(BAD, CHECK, "out_collided", CHECK_CALL(f, q, 4, ARM_JOINTS, 0, NULL, 0, 0, NULL, NULL, NULL, 4));
    expect_failure(BAD, CHECK, "configuration_count", CHECK_CALL(f, q, 0, ARM_JOINTS, 0, NULL, 0, 0, NULL, out, NULL, 4));
    expect_failure(BAD, CHECK, "stride", CHECK_CALL(f, q, 4, ARM_JOINTS, 8 * ARM_JOINTS - 8, NULL, 0, 0, NULL, out, NULL, 4));
    expect_failure(BAD, CHECK, "joint_count", CHECK_CALL(f, q, 4, ARM_JOINTS - 1, 0, NULL, 0, 0, NULL, out, NULL, 4));
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, CHECK, "capacity",
                   CHECK_CALL(f, q, 4, ARM_JOINTS, 0, NULL, 0, 0, NULL, out, NULL, 3));
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.compute_distance = 1;
    expect_failure(BAD, CHECK, "out_distances", CHECK_CALL(f, q, 4, ARM_JOINTS, 0, NULL, 0, 0, &request, out, NULL, 4));
}

static void configurations_refuse_bad_values(void **state) {
    fixture *f = *state;
    uint8_t *out = f->collided;
    const int32_t BAD = OPX_ERROR_INVALID_ARGUMENT;
    double rows[4 * ARM_JOINTS];
    memcpy(rows, f->rows, sizeof rows);
    rows[2 * ARM_JOINTS + 3] = NAN;
    expect_failure(BAD, CHECK, "positions[row 2][joint 3]",
                   CHECK_CALL(f, rows, 4, ARM_JOINTS, 0, NULL, 0, 0, NULL, out, NULL, 4));
    rows[2 * ARM_JOINTS + 3] = 2e6;
    expect_failure(BAD, CHECK, "positions[row 2][joint 3]",
                   CHECK_CALL(f, rows, 4, ARM_JOINTS, 0, NULL, 0, 0, NULL, out, NULL, 4));
    opx_pose bases[4] = {pose_at(0, 0, 0), pose_at(0, 0, 0), pose_at(0, 0, 0), pose_at(0, 0, 0)};
    expect_failure(BAD, CHECK, "base_pose_count",
                   CHECK_CALL(f, f->rows, 4, ARM_JOINTS, 0, bases, 2, 0, NULL, out, NULL, 4));
    expect_failure(BAD, CHECK, "base_pose_stride",
                   CHECK_CALL(f, f->rows, 4, ARM_JOINTS, 0, bases, 4, sizeof(opx_pose) - 8, NULL, out, NULL, 4));
    expect_failure(BAD, CHECK, "base_poses", CHECK_CALL(f, f->rows, 4, ARM_JOINTS, 0, NULL, 1, 0, NULL, out, NULL, 4));
    bases[3].orientation[3] = 0.0;
    expect_failure(BAD, CHECK, "base_poses[3]", CHECK_CALL(f, f->rows, 4, ARM_JOINTS, 0, bases, 4, 0, NULL, out, NULL, 4));
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, CHECK, "request",
                   CHECK_CALL(f, f->rows, 4, ARM_JOINTS, 0, NULL, 0, 0, &request, out, NULL, 4));
    request = (opx_batch_request)OPX_BATCH_REQUEST_INIT;
    request.distance_cutoff = -1.0;
    expect_failure(BAD, CHECK, "request->distance_cutoff",
                   CHECK_CALL(f, f->rows, 4, ARM_JOINTS, 0, NULL, 0, 0, &request, out, f->distances, 4));
    request = (opx_batch_request)OPX_BATCH_REQUEST_INIT;
    request.unknown_policy = 7;
    expect_failure(BAD, CHECK, "request->unknown_policy",
                   CHECK_CALL(f, f->rows, 4, ARM_JOINTS, 0, NULL, 0, 0, &request, out, NULL, 4));
    request = (opx_batch_request)OPX_BATCH_REQUEST_INIT;
    request.occupancy_threshold = 1.5;
    expect_failure(BAD, CHECK, "request->occupancy_threshold",
                   CHECK_CALL(f, f->rows, 4, ARM_JOINTS, 0, NULL, 0, 0, &request, out, NULL, 4));
}

static void a_link_set_without_joints_is_unsupported(void **state) {
    fixture *f = *state;
    opx_linkset *plain = new_robot();
    const double q[1] = {0.0};
    expect_failure(OPX_ERROR_UNSUPPORTED, CHECK, "joint tree",
                   opx_query_check_configurations(f->query, f->tree, plain, q, 1, 1, 0, NULL, 0, 0, NULL,
                                                  f->collided, NULL, 4));
    opx_motion_result result = OPX_MOTION_RESULT_INIT;
    expect_failure(OPX_ERROR_UNSUPPORTED, MOTION, "joint tree",
                   opx_query_check_motion(f->query, f->tree, plain, q, q, 1, NULL, NULL, &result));
    opx_linkset_destroy(plain);
}

static void motion_refuses_bad_input(void **state) {
    fixture *f = *state;
    const double *a = f->rows, *b = f->rows + ARM_JOINTS;
    opx_motion_result result = OPX_MOTION_RESULT_INIT;
    const int32_t BAD = OPX_ERROR_INVALID_ARGUMENT;
    expect_failure(BAD, MOTION, "start", opx_query_check_motion(f->query, f->tree, f->arm, NULL, b, ARM_JOINTS, NULL, NULL, &result));
    expect_failure(BAD, MOTION, "goal", opx_query_check_motion(f->query, f->tree, f->arm, a, NULL, ARM_JOINTS, NULL, NULL, &result));
    expect_failure(BAD, MOTION, "out_result", opx_query_check_motion(f->query, f->tree, f->arm, a, b, ARM_JOINTS, NULL, NULL, NULL));
    opx_motion_result unset = OPX_MOTION_RESULT_INIT;
    unset.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, MOTION, "out_result",
                   opx_query_check_motion(f->query, f->tree, f->arm, a, b, ARM_JOINTS, NULL, NULL, &unset));
    double nan_goal[ARM_JOINTS];
    memcpy(nan_goal, b, sizeof nan_goal);
    nan_goal[5] = NAN;
    expect_failure(BAD, MOTION, "goal[row 0][joint 5]",
                   opx_query_check_motion(f->query, f->tree, f->arm, a, nan_goal, ARM_JOINTS, NULL, NULL, &result));
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    const double resolutions[3] = {0.0, -0.1, NAN};
    for (int i = 0; i < 3; ++i) {
        request.resolution = resolutions[i];
        expect_failure(BAD, MOTION, "request->resolution",
                       opx_query_check_motion(f->query, f->tree, f->arm, a, b, ARM_JOINTS, NULL, &request, &result));
    }
    request.resolution = 1e-9; /* billions of steps */
    expect_failure(BAD, MOTION, "steps",
                   opx_query_check_motion(f->query, f->tree, f->arm, a, b, ARM_JOINTS, NULL, &request, &result));
}

static void motions_refuse_bad_input(void **state) {
    fixture *f = *state;
    const double *a = f->rows, *b = f->rows + 2 * ARM_JOINTS;
    const size_t stride = 2 * ARM_JOINTS * sizeof(double);
    const int32_t BAD = OPX_ERROR_INVALID_ARGUMENT;
#define MOTIONS_CALL(starts, goals, n, st, req, out, cap)                                                        \
    opx_query_check_motions(f->query, f->tree, f->arm, (starts), (goals), (n), ARM_JOINTS, (st), NULL, 0, 0, (req), \
                            (out), NULL, (cap))
    expect_failure(BAD, MOTIONS, "starts", MOTIONS_CALL(NULL, b, 2, stride, NULL, f->collided, 2));
    expect_failure(BAD, MOTIONS, "goals", MOTIONS_CALL(a, NULL, 2, stride, NULL, f->collided, 2));
    expect_failure(BAD, MOTIONS, "motion_count", MOTIONS_CALL(a, b, 0, stride, NULL, f->collided, 2));
    expect_failure(BAD, MOTIONS, "stride", MOTIONS_CALL(a, b, 2, 8, NULL, f->collided, 2));
    expect_failure(BAD, MOTIONS, "out_collided", MOTIONS_CALL(a, b, 2, stride, NULL, NULL, 2));
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, MOTIONS, "capacity", MOTIONS_CALL(a, b, 2, stride, NULL, f->collided, 1));
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.compute_cost = 1;
    expect_failure(BAD, MOTIONS, "request->compute_cost", MOTIONS_CALL(a, b, 2, stride, &request, f->collided, 2));
    request = (opx_motion_request)OPX_MOTION_REQUEST_INIT;
    request.resolution = 1e-9;
    expect_failure(BAD, MOTIONS, "motion 0", MOTIONS_CALL(a, b, 2, stride, &request, f->collided, 2));
#undef MOTIONS_CALL
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(configurations_refuse_bad_arrays, setup, teardown),
        cmocka_unit_test_setup_teardown(configurations_refuse_bad_values, setup, teardown),
        cmocka_unit_test_setup_teardown(a_link_set_without_joints_is_unsupported, setup, teardown),
        cmocka_unit_test_setup_teardown(motion_refuses_bad_input, setup, teardown),
        cmocka_unit_test_setup_teardown(motions_refuse_bad_input, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
