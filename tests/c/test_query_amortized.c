/*
 * The amortized engine through the C API: it binds a tree to the octree
 * frame (rebuilt only when the map changes), refines it per query, reports
 * its quality, and answers as the direct engine does.
 */
#define _POSIX_C_SOURCE 200809L /* pthreads under -std=c99 */

#include "opx_query_test.h"

#include <math.h>
#include <pthread.h>

/* A wall of occupied cells at x = 1 (resolution 0.1), 1 m by 1 m. */
static opx_octree *make_wall(void) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = 0.1;
    opx_octree *tree = NULL;
    assert_ok(opx_octree_create(&options, &tree));
    float points[100 * 3];
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j) {
            float *p = points + 3 * (10 * i + j);
            p[0] = 1.05f, p[1] = -0.45f + 0.1f * (float)i, p[2] = -0.45f + 0.1f * (float)j;
        }
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    insert.mode = OPX_INSERT_ENDPOINTS;
    assert_ok(opx_octree_insert_points(tree, points, 100, 0, OPX_SCALAR_FLOAT32, &insert, NULL));
    return tree;
}

static opx_query *make_query(int32_t engine) {
    opx_query_options options = OPX_QUERY_OPTIONS_INIT;
    options.engine = engine;
    options.refine_steps = 4;
    opx_query *query = NULL;
    assert_ok(opx_query_create(&options, &query));
    return query;
}

static void binds_once_per_frame_and_refines(void **state) {
    (void)state;
    opx_octree *tree = make_wall();
    opx_linkset *links = NULL;
    assert_ok(opx_linkset_create(&links));
    uint32_t link;
    assert_ok(opx_linkset_add_link(links, "ball", &link));
    opx_shape ball = sphere_shape(0.2);
    assert_ok(opx_linkset_add_shape(links, link, &ball, NULL));
    opx_pose pose = pose_at(0.5, 0.0, 0.0);
    assert_ok(opx_linkset_set_poses(links, &pose, 1, 0));
    opx_query *query = make_query(OPX_ENGINE_AMORTIZED);
    opx_collision_result hit = OPX_COLLISION_RESULT_INIT;
    for (int i = 0; i < 3; ++i) assert_ok(opx_query_collide(query, tree, links, NULL, &hit));
    assert_int_equal(hit.collided, 0);
    opx_query_stats stats = OPX_QUERY_STATS_INIT;
    assert_ok(opx_query_get_stats(query, &stats));
    assert_int_equal(stats.engine, OPX_ENGINE_AMORTIZED);
    assert_int_equal(stats.boxes, 100);
    assert_int_equal(stats.builds, 1);
    assert_true(stats.refine_steps_done >= 1 && stats.refine_steps_done <= 12);
    assert_true(stats.sah_ratio > 0.0 && stats.sah_ratio < 2.0);
    /* A changed map is bound again. */
    float more[3] = {1.05f, 0.55f, 0.05f};
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    insert.mode = OPX_INSERT_ENDPOINTS;
    assert_ok(opx_octree_insert_points(tree, more, 1, 0, OPX_SCALAR_FLOAT32, &insert, NULL));
    assert_ok(opx_query_collide(query, tree, links, NULL, &hit));
    assert_ok(opx_query_get_stats(query, &stats));
    assert_int_equal(stats.builds, 2);
    assert_int_equal(stats.boxes, 101);
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

static void answers_as_the_direct_engine(void **state) {
    (void)state;
    opx_octree *tree = make_wall();
    opx_linkset *links = NULL;
    assert_ok(opx_linkset_create(&links));
    uint32_t link;
    assert_ok(opx_linkset_add_link(links, "box", &link));
    opx_shape box = box_shape(0.3, 0.3, 0.3);
    assert_ok(opx_linkset_add_shape(links, link, &box, NULL));
    opx_query *direct = make_query(OPX_ENGINE_DIRECT), *amortized = make_query(OPX_ENGINE_AMORTIZED);
    for (int step = 0; step < 20; ++step) {
        opx_pose pose = pose_at(0.5 + 0.025 * step, 0.1, 0.0);
        assert_ok(opx_linkset_set_poses(links, &pose, 1, 0));
        opx_collision_request all = OPX_COLLISION_REQUEST_INIT;
        all.max_contacts = UINT32_MAX;
        opx_collision_result a = OPX_COLLISION_RESULT_INIT, b = OPX_COLLISION_RESULT_INIT;
        assert_ok(opx_query_collide(direct, tree, links, &all, &a));
        assert_ok(opx_query_collide(amortized, tree, links, &all, &b));
        assert_int_equal(a.collided, b.collided);
        assert_int_equal(a.contact_count, b.contact_count);
        opx_distance_result da = OPX_DISTANCE_RESULT_INIT, db = OPX_DISTANCE_RESULT_INIT;
        assert_ok(opx_query_distance(direct, tree, links, NULL, &da));
        assert_ok(opx_query_distance(amortized, tree, links, NULL, &db));
        assert_true(fabs(da.distance - db.distance) <= 1e-12);
        /* The box's face is at x = 0.65 + 0.025 step; the wall starts at x = 1. */
        const double expected = 1.0 - (0.65 + 0.025 * step);
        assert_true(fabs(da.distance - (expected > 0.0 ? expected : 0.0)) <= 1e-9);
    }
    opx_query_destroy(direct);
    opx_query_destroy(amortized);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

/* One thread's opx_query_get_stats on a query shared with another. */
typedef struct {
    const opx_query *query;
    pthread_barrier_t *start;
    opx_status status;
    opx_query_stats stats;
} stats_reader;

static void *read_stats(void *arg) {
    stats_reader *reader = arg;
    opx_query_stats_init(&reader->stats, sizeof reader->stats);
    pthread_barrier_wait(reader->start);
    reader->status = opx_query_get_stats(reader->query, &reader->stats);
    return NULL;
}

/* Two threads ask for the stats of one query right after each rebuild, so
 * both may find the median-split reference not yet computed: both succeed
 * and read the same values as a later call on one thread. */
static void two_threads_read_one_querys_stats(void **state) {
    (void)state;
    opx_octree *tree = make_wall();
    opx_linkset *links = NULL;
    assert_ok(opx_linkset_create(&links));
    uint32_t link;
    assert_ok(opx_linkset_add_link(links, "ball", &link));
    opx_shape ball = sphere_shape(0.2);
    assert_ok(opx_linkset_add_shape(links, link, &ball, NULL));
    opx_pose pose = pose_at(0.5, 0.0, 0.0);
    assert_ok(opx_linkset_set_poses(links, &pose, 1, 0));
    opx_query *query = make_query(OPX_ENGINE_AMORTIZED);
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    insert.mode = OPX_INSERT_ENDPOINTS;
    for (int round = 0; round < 40; ++round) {
        /* A new cell behind the wall: the next query builds the tree again. */
        float cell[3] = {1.15f + 0.1f * (float)(round % 8), -0.45f + 0.1f * (float)(round / 8), 0.05f};
        assert_ok(opx_octree_insert_points(tree, cell, 1, 0, OPX_SCALAR_FLOAT32, &insert, NULL));
        opx_collision_result hit = OPX_COLLISION_RESULT_INIT;
        assert_ok(opx_query_collide(query, tree, links, NULL, &hit));
        pthread_barrier_t start;
        assert_int_equal(pthread_barrier_init(&start, NULL, 2), 0);
        stats_reader readers[2] = {{query, &start, OPX_OK, OPX_QUERY_STATS_INIT},
                                   {query, &start, OPX_OK, OPX_QUERY_STATS_INIT}};
        pthread_t threads[2];
        for (int i = 0; i < 2; ++i)
            assert_int_equal(pthread_create(&threads[i], NULL, read_stats, &readers[i]), 0);
        for (int i = 0; i < 2; ++i) assert_int_equal(pthread_join(threads[i], NULL), 0);
        pthread_barrier_destroy(&start);
        opx_query_stats alone = OPX_QUERY_STATS_INIT;
        assert_ok(opx_query_get_stats(query, &alone));
        assert_int_equal(alone.builds, round + 1);
        assert_int_equal(alone.boxes, 100 + round + 1);
        assert_true(alone.sah_ratio > 0.0 && alone.sah_ratio < 2.0);
        for (int i = 0; i < 2; ++i) {
            assert_ok(readers[i].status);
            assert_int_equal(readers[i].stats.builds, alone.builds);
            assert_int_equal(readers[i].stats.boxes, alone.boxes);
            assert_int_equal(readers[i].stats.refine_steps_done, alone.refine_steps_done);
            assert_true(readers[i].stats.sah_ratio == alone.sah_ratio);
        }
    }
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(binds_once_per_frame_and_refines),
        cmocka_unit_test(answers_as_the_direct_engine),
        cmocka_unit_test(two_threads_read_one_querys_stats),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
