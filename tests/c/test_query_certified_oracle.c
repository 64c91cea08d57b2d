/*
 * OPX_MOTION_CERTIFIED against a dense walk: random motions of the
 * generated arm (cylinders, spheres, boxes, a mimic finger) and of its
 * sphere twin among the scattered cells, world objects, both or the
 * objects alone, with and without self-collision.  Every motion called
 * free has no colliding configuration among 10,001 evenly spaced ones
 * (1e-4 of the motion); every motion called colliding reports a
 * configuration within the contact distance, and none of the walk's
 * configurations before its fraction less the tolerance collides.
 * opx_query_check_motions gives the single call's answers bit for bit for
 * both engines and 1, 2 and 3 threads.
 */
#include "opx_batch_test.h"

#define MOTIONS 8
/* Samples a motion's dense walk takes: 1e-4 of the segment; a tenth of
 * that under the sanitizers, whose run checks memory, not density. */
#ifdef OPX_SANITIZED
#define DENSE 1000
#else
#define DENSE 10000
#endif
#define TOLERANCE 1e-3

typedef struct oracle_case {
    int spheres, self, with_map, with_world;
    int32_t engine;
} oracle_case;

static opx_world *new_world(uint64_t seed) {
    opx_world *world = NULL;
    assert_ok(opx_world_create(&world));
    for (int i = 0; i < 12; ++i) {
        const opx_pose at = pose_at(next_uniform(&seed, -0.8, 0.8), next_uniform(&seed, -0.8, 0.8),
                                    next_uniform(&seed, 0.2, 1.4));
        uint32_t object = 0;
        assert_ok(opx_world_add_object(world, "thing", &at, &object));
        const double size = next_uniform(&seed, 0.03, 0.12);
        const opx_shape shape = i % 2 == 0 ? box_shape(size, 0.004, size) : sphere_shape(size / 2);
        assert_ok(opx_world_add_shape(world, object, &shape, NULL));
    }
    return world;
}

static opx_query *query_with_world(int32_t engine, const opx_world *world) {
    opx_query *query = new_query_with(engine);
    if (world != NULL) assert_ok(opx_query_set_world(query, world));
    return query;
}

static int walk_collides(opx_query *single, const opx_octree *tree, opx_linkset *arm, const double *q, int self) {
    return self ? single_collides_or_self(single, tree, arm, q, NULL) : single_collides(single, tree, arm, q, NULL);
}

/* Short motions from free configurations, so that some stay free and
 * some do not. */
static double *short_motions(opx_query *single, const opx_octree *tree, opx_linkset *arm, int self, uint64_t seed) {
    double *rows = malloc(2 * MOTIONS * ARM_JOINTS * sizeof *rows);
    assert_non_null(rows);
    for (size_t m = 0; m < MOTIONS; ++m) {
        double *a = rows + 2 * m * ARM_JOINTS, *b = a + ARM_JOINTS;
        do {
            double *drawn = random_arm_rows(1, seed++);
            memcpy(a, drawn, ARM_JOINTS * sizeof *a);
            free(drawn);
        } while (walk_collides(single, tree, arm, a, self));
        memcpy(b, a, ARM_JOINTS * sizeof *b);
        for (int j = 0; j < ARM_REVOLUTE; ++j) b[j] = a[j] + next_uniform(&seed, -0.6, 0.6);
        b[7] = next_uniform(&seed, 0.0, 0.04);
    }
    return rows;
}

static void assert_oracle_agrees(opx_query *single, const opx_octree *tree, opx_linkset *arm, const double *a,
                                 const double *b, int self, double fraction) {
    double q[ARM_JOINTS];
    const double end = fraction < 0.0 ? 2.0 : fraction - TOLERANCE;
    for (int i = 0; i <= DENSE && (double)i / DENSE < end; ++i) {
        motion_sample(a, b, (uint64_t)i, DENSE, q);
        assert_int_equal(walk_collides(single, tree, arm, q, self), 0);
    }
    if (fraction < 0.0) return;
    for (int j = 0; j < ARM_JOINTS; ++j) q[j] = fraction == 1.0 ? b[j] : a[j] + fraction * (b[j] - a[j]);
    double nearest = single_distance(single, tree, arm, q, NULL, 0.01);
    if (self) nearest = fmin(nearest, single_self_distance(single, arm, 0.01));
    assert_true(nearest <= OPX_MOTION_CONTACT_DISTANCE);
}

static void check_case(const oracle_case *c, uint64_t seed) {
    opx_linkset *arm = load_arm_of(c->spheres);
    disable_adjacent_arm_pairs(arm);
    opx_octree *tree = c->with_map ? new_scatter_map(seed) : NULL;
    opx_world *world = c->with_world ? new_world(seed + 1) : NULL;
    opx_query *query = query_with_world(c->engine, world), *single = query_with_world(OPX_ENGINE_DIRECT, world);
    double *ends = short_motions(single, tree, arm, c->self, seed + 2);
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.check = OPX_MOTION_CERTIFIED;
    request.tolerance = TOLERANCE;
    request.self_collision = c->self;
    double fractions[MOTIONS];
    int colliding = 0;
    for (size_t m = 0; m < MOTIONS; ++m) {
        const double *a = ends + 2 * m * ARM_JOINTS, *b = a + ARM_JOINTS;
        opx_motion_result result = OPX_MOTION_RESULT_INIT;
        assert_ok(opx_query_check_motion(query, tree, arm, a, b, ARM_JOINTS, NULL, &request, &result));
        fractions[m] = result.first_collision_fraction;
        assert_int_equal(result.collided, fractions[m] >= 0.0);
        colliding += result.collided;
        assert_oracle_agrees(single, tree, arm, a, b, c->self, fractions[m]);
    }
    assert_true(colliding > 0 && colliding < MOTIONS);
    for (uint32_t threads = 1; threads <= 3; ++threads) {
        for (int e = 0; e < 2; ++e) {
            opx_query *batch = query_with_world(e == 0 ? OPX_ENGINE_DIRECT : OPX_ENGINE_AMORTIZED, world);
            request.max_threads = threads;
            uint8_t collided[MOTIONS];
            double got[MOTIONS];
            assert_ok(opx_query_check_motions(batch, tree, arm, ends, ends + ARM_JOINTS, MOTIONS, ARM_JOINTS,
                                              2 * ARM_JOINTS * sizeof(double), NULL, 0, 0, &request, collided, got,
                                              MOTIONS));
            for (size_t m = 0; m < MOTIONS; ++m) {
                assert_true(got[m] == fractions[m]);
                assert_int_equal(collided[m], fractions[m] >= 0.0);
            }
            opx_query_destroy(batch);
        }
    }
    opx_query_destroy(single);
    opx_query_destroy(query);
    free(ends);
    opx_world_destroy(world);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

static void arm_among_cells(void **state) {
    (void)state;
    const oracle_case c = {0, 0, 1, 0, OPX_ENGINE_DIRECT};
    check_case(&c, 11);
}

static void arm_among_cells_and_objects_with_self(void **state) {
    (void)state;
    const oracle_case c = {0, 1, 1, 1, OPX_ENGINE_AMORTIZED};
    check_case(&c, 23);
}

static void sphere_arm_among_cells(void **state) {
    (void)state;
    const oracle_case c = {1, 0, 1, 0, OPX_ENGINE_AMORTIZED};
    check_case(&c, 37);
}

static void arm_among_objects_alone_with_self(void **state) {
    (void)state;
    const oracle_case c = {0, 1, 0, 1, OPX_ENGINE_DIRECT};
    check_case(&c, 41);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(arm_among_cells),
        cmocka_unit_test(arm_among_cells_and_objects_with_self),
        cmocka_unit_test(sphere_arm_among_cells),
        cmocka_unit_test(arm_among_objects_alone_with_self),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
