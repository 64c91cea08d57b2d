/*
 * opx_query_check_configurations on the generated arm: the answers equal
 * the single calls (FK on the link set, then opx_query_collide or
 * opx_query_distance, and opx_query_self_collide or _self_distance with
 * self_collision) for 1, 2 and 3 threads and both engines, with one
 * root pose or one per row, packed or strided rows; the caller's link set
 * does not move; two threads may check one link set at once.
 */
#define _POSIX_C_SOURCE 200809L
#include "opx_batch_test.h"

#include <pthread.h>

#define ROWS 240

typedef struct batch_case {
    int32_t engine;
    uint32_t threads;
    int distance;
    double cutoff;
    int self;
} batch_case;

/* The single calls' answer for row q: collided, and with distance the
 * nearer of the map's and (with self) the arm's own. */
static int expected_answer(const batch_case *c, opx_query *single, const opx_octree *tree, opx_linkset *arm,
                           const double *q, const opx_pose *base, double *distance) {
    const int collided = c->self ? single_collides_or_self(single, tree, arm, q, base)
                                 : single_collides(single, tree, arm, q, base);
    if (!c->distance) return collided;
    *distance = single_distance(single, tree, arm, q, base, c->cutoff);
    if (c->self) *distance = fmin(*distance, single_self_distance(single, arm, c->cutoff));
    return collided;
}

/* Runs the batch (rows packed, one root pose `base` or none) and checks
 * every answer against the single calls. */
static void check_case(const batch_case *c, const opx_pose *base) {
    opx_linkset *arm = load_arm();
    disable_adjacent_arm_pairs(arm);
    opx_octree *tree = new_scatter_map(7);
    double *rows = random_arm_rows(ROWS, 11);
    opx_pose before[ARM_LINKS];
    arm_poses(arm, before);
    opx_query *query = new_query_with(c->engine);
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.max_threads = c->threads;
    request.compute_distance = c->distance;
    request.distance_cutoff = c->cutoff;
    request.self_collision = c->self;
    uint8_t collided[ROWS];
    double distances[ROWS];
    assert_ok(opx_query_check_configurations(query, tree, arm, rows, ROWS, ARM_JOINTS, 0, base,
                                             base != NULL, 0, &request, collided, distances, ROWS));
    assert_arm_at(arm, before);
    opx_query *single = new_query();
    int hits = 0;
    for (size_t i = 0; i < ROWS; ++i) {
        double distance = 0.0;
        assert_int_equal(collided[i], expected_answer(c, single, tree, arm, rows + i * ARM_JOINTS, base, &distance));
        hits += collided[i];
        if (c->distance) assert_true(distances[i] == distance);
    }
    assert_true(hits > ROWS / 10 && hits < ROWS * 9 / 10); /* the map is neither empty nor full */
    opx_query_destroy(single);
    opx_query_destroy(query);
    free(rows);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

static void equals_single_calls_every_thread_count(void **state) {
    (void)state;
    const int32_t engines[2] = {OPX_ENGINE_DIRECT, OPX_ENGINE_AMORTIZED};
    for (int e = 0; e < 2; ++e) {
        for (uint32_t threads = 1; threads <= 3; ++threads) {
            for (int self = 0; self <= 1; ++self) {
                const batch_case collide = {engines[e], threads, 0, 0.0, self};
                check_case(&collide, NULL);
                const batch_case distance = {engines[e], threads, 1, 0.0, self};
                check_case(&distance, NULL);
            }
        }
    }
}

static void distance_cutoff_and_shared_base_pose(void **state) {
    (void)state;
    opx_pose base = pose_at(0.1, -0.2, 0.05);
    base.orientation[2] = sin(0.3), base.orientation[3] = cos(0.3);
    for (uint32_t threads = 1; threads <= 3; ++threads) {
        const batch_case c = {OPX_ENGINE_DIRECT, threads, 1, 0.15, 1};
        check_case(&c, &base);
    }
}

/* Rows inside a wider array (stride > row), each with its own root pose
 * in a strided array; the answers are the single calls'. */
static void strided_rows_and_a_base_pose_per_row(void **state) {
    (void)state;
    enum { N = 60, WIDE = ARM_JOINTS + 3 };
    opx_linkset *arm = load_arm();
    opx_octree *tree = new_scatter_map(3);
    double *packed = random_arm_rows(N, 5);
    double wide[N * WIDE];
    struct padded_pose {
        opx_pose pose;
        double pad;
    } bases[N];
    uint64_t seed = 99;
    for (size_t i = 0; i < N; ++i) {
        memcpy(wide + i * WIDE, packed + i * ARM_JOINTS, ARM_JOINTS * sizeof(double));
        bases[i].pose = pose_at(next_uniform(&seed, -0.3, 0.3), next_uniform(&seed, -0.3, 0.3), 0.0);
    }
    opx_query *query = new_query();
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.max_threads = 2;
    uint8_t collided[N];
    assert_ok(opx_query_check_configurations(query, tree, arm, wide, N, ARM_JOINTS, WIDE * sizeof(double),
                                             &bases[0].pose, N, sizeof bases[0], &request, collided, NULL, N));
    for (size_t i = 0; i < N; ++i)
        assert_int_equal(collided[i], single_collides(query, tree, arm, packed + i * ARM_JOINTS, &bases[i].pose));
    opx_query_destroy(query);
    free(packed);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

typedef struct shared_job {
    const opx_octree *tree;
    const opx_linkset *arm;
    const double *rows;
    uint8_t collided[ROWS];
    opx_status status;
} shared_job;

static void *run_job(void *arg) {
    shared_job *job = arg;
    opx_query *query = NULL;
    job->status = opx_query_create(NULL, &query);
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.max_threads = 2;
    for (int repeat = 0; repeat < 3 && job->status == OPX_OK; ++repeat)
        job->status = opx_query_check_configurations(query, job->tree, job->arm, job->rows, ROWS, ARM_JOINTS, 0,
                                                     NULL, 0, 0, &request, job->collided, NULL, ROWS);
    opx_query_destroy(query);
    return NULL;
}

/* The link set is read-only to the batch: two threads check it at once. */
static void two_threads_share_one_link_set(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    opx_octree *tree = new_scatter_map(7);
    double *rows = random_arm_rows(ROWS, 11);
    shared_job jobs[2] = {{tree, arm, rows, {0}, OPX_OK}, {tree, arm, rows, {0}, OPX_OK}};
    pthread_t threads[2];
    for (int t = 0; t < 2; ++t) assert_int_equal(pthread_create(&threads[t], NULL, run_job, &jobs[t]), 0);
    for (int t = 0; t < 2; ++t) assert_int_equal(pthread_join(threads[t], NULL), 0);
    opx_query *query = new_query();
    for (int t = 0; t < 2; ++t) {
        assert_ok(jobs[t].status);
        for (size_t i = 0; i < ROWS; ++i)
            assert_int_equal(jobs[t].collided[i], single_collides(query, tree, arm, rows + i * ARM_JOINTS, NULL));
    }
    opx_query_destroy(query);
    free(rows);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

/* A link set changed between calls (padding) is copied again. */
static void a_changed_link_set_is_seen(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    opx_octree *tree = new_scatter_map(7);
    double *rows = random_arm_rows(ROWS, 21);
    opx_query *query = new_query();
    uint8_t thin[ROWS], padded[ROWS];
    assert_ok(opx_query_check_configurations(query, tree, arm, rows, ROWS, ARM_JOINTS, 0, NULL, 0, 0, NULL, thin,
                                             NULL, ROWS));
    assert_ok(opx_linkset_set_padding(arm, 0.1));
    assert_ok(opx_query_check_configurations(query, tree, arm, rows, ROWS, ARM_JOINTS, 0, NULL, 0, 0, NULL,
                                             padded, NULL, ROWS));
    int more = 0;
    for (size_t i = 0; i < ROWS; ++i) {
        assert_true(padded[i] >= thin[i]);
        more += padded[i] > thin[i];
        assert_int_equal(padded[i], single_collides(query, tree, arm, rows + i * ARM_JOINTS, NULL));
    }
    assert_true(more > 0);
    opx_query_destroy(query);
    free(rows);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

/* Rows that each change one joint of the previous (as a planner's
 * neighbours do; FK then redoes only the links below it), a repeated row,
 * and a root pose that changes once: distances equal the single calls'
 * bit for bit. */
static void rows_changing_one_joint_at_a_time(void **state) {
    (void)state;
    enum { N = 80 };
    opx_linkset *arm = load_arm();
    opx_octree *tree = new_scatter_map(7);
    double *rows = random_arm_rows(N, 17);
    uint64_t seed = 5;
    for (size_t i = 1; i < N; ++i) {
        memcpy(rows + i * ARM_JOINTS, rows + (i - 1) * ARM_JOINTS, ARM_JOINTS * sizeof(double));
        const int j = (int)(i % 9 == 4 ? 7 : i % ARM_REVOLUTE);
        if (i % 11 != 5) rows[i * ARM_JOINTS + j] = next_uniform(&seed, -3.0, 3.0) * (j == 7 ? 0.01 : 1.0);
    }
    opx_pose bases[N];
    for (size_t i = 0; i < N; ++i) bases[i] = pose_at(i < N / 2 ? 0.0 : 0.2, 0.0, 0.0);
    opx_query *query = new_query();
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.compute_distance = 1;
    uint8_t collided[N];
    double distances[N];
    assert_ok(opx_query_check_configurations(query, tree, arm, rows, N, ARM_JOINTS, 0, bases, N, 0, &request,
                                             collided, distances, N));
    for (size_t i = 0; i < N; ++i) {
        const double *q = rows + i * ARM_JOINTS;
        assert_int_equal(collided[i], single_collides(query, tree, arm, q, &bases[i]));
        assert_true(distances[i] == single_distance(query, tree, arm, q, &bases[i], 0.0));
    }
    opx_query_destroy(query);
    free(rows);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

/* The arm folds onto itself in some configurations free of the map: the
 * self check adds them, and only them. */
static void self_collision_adds_configurations(void **state) {
    (void)state;
    opx_linkset *arm = load_arm();
    disable_adjacent_arm_pairs(arm);
    opx_octree *tree = new_scatter_map(7);
    double *rows = random_arm_rows(ROWS, 13);
    opx_query *query = new_query();
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    uint8_t world[ROWS], both[ROWS];
    assert_ok(opx_query_check_configurations(query, tree, arm, rows, ROWS, ARM_JOINTS, 0, NULL, 0, 0, &request,
                                             world, NULL, ROWS));
    request.self_collision = 1;
    assert_ok(opx_query_check_configurations(query, tree, arm, rows, ROWS, ARM_JOINTS, 0, NULL, 0, 0, &request,
                                             both, NULL, ROWS));
    int added = 0;
    for (size_t i = 0; i < ROWS; ++i) {
        assert_true(both[i] >= world[i]);
        added += both[i] > world[i];
    }
    assert_true(added > 0);
    opx_query_destroy(query);
    free(rows);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(equals_single_calls_every_thread_count),
        cmocka_unit_test(distance_cutoff_and_shared_base_pose),
        cmocka_unit_test(strided_rows_and_a_base_pose_per_row),
        cmocka_unit_test(two_threads_share_one_link_set),
        cmocka_unit_test(a_changed_link_set_is_seen),
        cmocka_unit_test(self_collision_adds_configurations),
        cmocka_unit_test(rows_changing_one_joint_at_a_time),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
