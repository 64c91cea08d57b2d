/*
 * opx_query_check_configurations and opx_query_check_motion on an arm made
 * of spheres alone, whose map test reads the map's obstacle grid instead of
 * placing shapes: the answers equal the single calls (FK on the link set,
 * then opx_query_collide) for both engines, 1 and 2 threads, global and
 * per-link padding, a disabled link, an attached sphere, both obstacle
 * geometries, two thresholds and unknown space as obstacle, on a 2 cm map
 * whose surfaces the arm reaches into; a changed map is read anew; an arm
 * with one box among its spheres answers the same way.
 */
#include "opx_batch_test.h"

#define ROWS 300
#define MOTIONS 12

typedef struct sphere_case {
    int32_t engine;
    uint32_t threads;
    double padding;            /* the whole arm's */
    int32_t obstacle_geometry; /* OPX_OBSTACLE_CELLS or OPX_OBSTACLE_POINT_EXTENTS */
    double threshold;          /* 0: the map's */
    int32_t unknown_policy;
} sphere_case;

/* A table top, a post and scattered points in the arm's reach, ray cast
 * from above into 2 cm cells; a second frame of the scattered points
 * alone leaves some cells less occupied than others. */
static const double kSensor[3] = {0.05, 0.02, 2.2};

static opx_octree *new_reach_map(uint64_t seed) {
    opx_octree *tree = new_tree(0.02);
    enum { POINTS = 3000 };
    double *xyz = malloc(3 * POINTS * sizeof *xyz);
    assert_non_null(xyz);
    for (int i = 0; i < POINTS; ++i) {
        double *p = xyz + 3 * i;
        switch (i % 4) {
        case 0:
        case 1:  /* the table, beside the arm's base */
            p[0] = next_uniform(&seed, 0.3, 0.9), p[1] = next_uniform(&seed, -0.6, 0.6);
            p[2] = 0.45 + next_uniform(&seed, 0.0, 0.01);
            break;
        case 2:  /* the post */
            p[0] = next_uniform(&seed, -0.5, -0.4), p[1] = next_uniform(&seed, -0.1, 0.1);
            p[2] = next_uniform(&seed, 0.1, 1.3);
            break;
        default: /* scattered, 0.35 m or more from the arm's axis */
            p[0] = next_uniform(&seed, -0.9, 0.9), p[1] = next_uniform(&seed, 0.35, 0.9);
            p[2] = next_uniform(&seed, 0.1, 1.3);
            if (i % 8 == 3) p[1] = -p[1];
        }
        for (int axis = 0; axis < 3; ++axis) p[axis] -= kSensor[axis];  /* points are in the sensor frame */
    }
    const opx_insert_options from_above = sensor_at(kSensor[0], kSensor[1], kSensor[2], OPX_INSERT_RAYCAST);
    insert_f64(tree, xyz, POINTS, &from_above);
    insert_f64(tree, xyz + 3 * (POINTS / 2), POINTS / 8, &from_above);
    free(xyz);
    return tree;
}

static opx_batch_request batch_request(const sphere_case *c) {
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.max_threads = c->threads;
    request.obstacle_geometry = c->obstacle_geometry;
    request.occupancy_threshold = c->threshold;
    request.unknown_policy = c->unknown_policy;
    return request;
}

/* The single call: FK on the caller's arm, then opx_query_collide. */
static int single_answer(const sphere_case *c, opx_query *query, const opx_octree *tree, opx_linkset *arm,
                         const double *q) {
    assert_ok(opx_linkset_set_joint_positions(arm, q, ARM_JOINTS, NULL));
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.max_contacts = 0;
    request.obstacle_geometry = c->obstacle_geometry;
    request.occupancy_threshold = c->threshold;
    request.unknown_policy = c->unknown_policy;
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    assert_ok(opx_query_collide(query, tree, arm, &request, &result));
    return result.collided;
}

/* The sphere arm with the case's padding, more on link 3, link 5 left
 * out, and a sphere held between the fingers. */
static opx_linkset *sphere_arm(const sphere_case *c) {
    opx_linkset *arm = load_arm_of(1);
    assert_ok(opx_linkset_set_padding(arm, c->padding));
    assert_ok(opx_linkset_set_link_padding(arm, 3, 0.015));
    assert_ok(opx_linkset_set_link_enabled(arm, 5, 0));
    opx_shape held = OPX_SHAPE_INIT;
    held.kind = OPX_SHAPE_SPHERE;
    held.radius = 0.03;
    const opx_pose in_hand = {{0.0, 0.0, 0.06}, {0.0, 0.0, 0.0, 1.0}};
    assert_ok(opx_linkset_attach_object(arm, 7, "part", &held, 1, &in_hand, NULL, 0, NULL));
    return arm;
}

/* The sphere arm of a case, a reach map and ROWS random rows. */
typedef struct sphere_scene {
    opx_linkset *arm;
    opx_octree *tree;
    double *rows;
} sphere_scene;

static sphere_scene open_scene(const sphere_case *c, uint64_t map_seed, uint64_t rows_seed, size_t rows) {
    const sphere_scene scene = {sphere_arm(c), new_reach_map(map_seed), random_arm_rows(rows, rows_seed)};
    return scene;
}

static void close_scene(sphere_scene *scene) {
    free(scene->rows);
    opx_octree_destroy(scene->tree);
    opx_linkset_destroy(scene->arm);
}

/* Every row of the batch, asked of `query`, equals its single call;
 * returns the colliding rows. */
static int check_rows_on(opx_query *query, const sphere_case *c, opx_linkset *arm, const opx_octree *tree,
                         const double *rows) {
    opx_query *single = new_query();
    const opx_batch_request request = batch_request(c);
    uint8_t collided[ROWS];
    assert_ok(opx_query_check_configurations(query, tree, arm, rows, ROWS, ARM_JOINTS, 0, NULL, 0, 0, &request,
                                             collided, NULL, ROWS));
    int hits = 0;
    for (size_t i = 0; i < ROWS; ++i) {
        assert_int_equal(collided[i], single_answer(c, single, tree, arm, rows + i * ARM_JOINTS));
        hits += collided[i];
    }
    opx_query_destroy(single);
    return hits;
}

static int check_rows(const sphere_case *c, opx_linkset *arm, const opx_octree *tree, const double *rows) {
    opx_query *query = new_query_with(c->engine);
    const int hits = check_rows_on(query, c, arm, tree, rows);
    opx_query_destroy(query);
    return hits;
}

static void check_case(const sphere_case *c) {
    sphere_scene scene = open_scene(c, 5, 17, ROWS);
    const int hits = check_rows(c, scene.arm, scene.tree, scene.rows);
    assert_true(hits > ROWS / 20 && hits < ROWS * 19 / 20); /* near surfaces: both answers occur */
    close_scene(&scene);
}

static void equals_single_calls(void **state) {
    (void)state;
    const int32_t engines[2] = {OPX_ENGINE_DIRECT, OPX_ENGINE_AMORTIZED};
    for (int e = 0; e < 2; ++e)
        for (uint32_t threads = 1; threads <= 2; ++threads) {
            const sphere_case plain = {engines[e], threads, 0.0, OPX_OBSTACLE_CELLS, 0.0, OPX_UNKNOWN_FREE};
            check_case(&plain);
            const sphere_case padded = {engines[e], threads, 0.02, OPX_OBSTACLE_CELLS, 0.0, OPX_UNKNOWN_FREE};
            check_case(&padded);
        }
}

static void equals_single_calls_every_setting(void **state) {
    (void)state;
    const sphere_case extents = {OPX_ENGINE_DIRECT, 1, 0.005, OPX_OBSTACLE_POINT_EXTENTS, 0.0, OPX_UNKNOWN_FREE};
    check_case(&extents);
    const sphere_case strict = {OPX_ENGINE_DIRECT, 2, 0.0, OPX_OBSTACLE_CELLS, 0.8, OPX_UNKNOWN_FREE};
    check_case(&strict);
    const sphere_case unknown = {OPX_ENGINE_DIRECT, 1, 0.0, OPX_OBSTACLE_CELLS, 0.0, OPX_UNKNOWN_OCCUPIED};
    sphere_scene scene = open_scene(&unknown, 5, 17, ROWS);
    assert_true(check_rows(&unknown, scene.arm, scene.tree, scene.rows) > 0);
    close_scene(&scene);
}

/* The same query checks a map, then the map after another frame. */
/* A slab of points across the arm's reach, 0.8 to 0.84 m high (map frame). */
static void insert_slab(opx_octree *tree) {
    enum { SIDE = 41 };
    double *xyz = malloc(3 * SIDE * SIDE * 3 * sizeof *xyz);
    assert_non_null(xyz);
    size_t n = 0;
    for (int layer = 0; layer < 3; ++layer)
        for (int i = 0; i < SIDE; ++i)
            for (int j = 0; j < SIDE; ++j, ++n) {
                xyz[3 * n] = -0.6 + 0.03 * i - kSensor[0];
                xyz[3 * n + 1] = -0.6 + 0.03 * j - kSensor[1];
                xyz[3 * n + 2] = 0.8 + 0.02 * layer - kSensor[2];
            }
    const opx_insert_options endpoints = sensor_at(kSensor[0], kSensor[1], kSensor[2], OPX_INSERT_ENDPOINTS);
    insert_f64(tree, xyz, n, &endpoints);
    free(xyz);
}

/* One query kept across changes of the map (its grid cache and the map's
 * are both keyed by the map's state): a slab in the arm's reach adds
 * collisions, a cleared map has none. */
static void reads_a_changed_map_anew(void **state) {
    (void)state;
    const sphere_case c = {OPX_ENGINE_DIRECT, 1, 0.0, OPX_OBSTACLE_CELLS, 0.0, OPX_UNKNOWN_FREE};
    sphere_scene scene = open_scene(&c, 5, 23, ROWS);
    opx_query *query = new_query_with(c.engine);
    const int before = check_rows_on(query, &c, scene.arm, scene.tree, scene.rows);
    insert_slab(scene.tree);
    const int after = check_rows_on(query, &c, scene.arm, scene.tree, scene.rows);
    assert_true(after > before);
    assert_ok(opx_octree_clear(scene.tree));
    assert_int_equal(check_rows_on(query, &c, scene.arm, scene.tree, scene.rows), 0);
    opx_query_destroy(query);
    close_scene(&scene);
}

/* One map and one query at two occupancy thresholds in turn, the higher
 * first: each answer is its own threshold's, and the thresholds do differ
 * on this map.  (The higher threshold's grid sees fewer obstacles, so its
 * clearances read for the lower one would call colliding spheres clear.) */
static void one_query_at_two_thresholds(void **state) {
    (void)state;
    sphere_case low = {OPX_ENGINE_DIRECT, 1, 0.0, OPX_OBSTACLE_CELLS, 0.55, OPX_UNKNOWN_FREE};
    sphere_case high = low;
    high.threshold = 0.8;
    sphere_scene scene = open_scene(&low, 5, 31, ROWS);
    opx_query *query = new_query_with(low.engine);
    const int at_high = check_rows_on(query, &high, scene.arm, scene.tree, scene.rows);
    const int at_low = check_rows_on(query, &low, scene.arm, scene.tree, scene.rows);
    assert_true(at_high < at_low);
    assert_int_equal(check_rows_on(query, &high, scene.arm, scene.tree, scene.rows), at_high);
    opx_query_destroy(query);
    close_scene(&scene);
}

/* A box among the spheres: the same answers, from placed shapes. */
static void arm_with_a_box_answers_the_same(void **state) {
    (void)state;
    const sphere_case c = {OPX_ENGINE_DIRECT, 2, 0.0, OPX_OBSTACLE_CELLS, 0.0, OPX_UNKNOWN_FREE};
    sphere_scene scene = open_scene(&c, 9, 29, ROWS);
    opx_shape box = OPX_SHAPE_INIT;
    box.kind = OPX_SHAPE_BOX;
    box.size[0] = box.size[1] = box.size[2] = 0.04;
    assert_ok(opx_linkset_add_shape(scene.arm, 2, &box, NULL));
    assert_true(check_rows(&c, scene.arm, scene.tree, scene.rows) > 0);
    close_scene(&scene);
}

/* A motion's first colliding sample is the first one single calls find. */
static void motions_equal_single_calls(void **state) {
    (void)state;
    const sphere_case c = {OPX_ENGINE_DIRECT, 1, 0.0, OPX_OBSTACLE_CELLS, 0.0, OPX_UNKNOWN_FREE};
    sphere_scene scene = open_scene(&c, 5, 41, 2 * MOTIONS);
    opx_linkset *arm = scene.arm;
    const opx_octree *tree = scene.tree;
    const double *ends = scene.rows;
    opx_query *query = new_query(), *single = new_query();
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.resolution = 0.05;
    int colliding = 0;
    for (size_t m = 0; m < MOTIONS; ++m) {
        const double *a = ends + 2 * m * ARM_JOINTS, *b = a + ARM_JOINTS;
        opx_motion_result result = OPX_MOTION_RESULT_INIT;
        assert_ok(opx_query_check_motion(query, tree, arm, a, b, ARM_JOINTS, NULL, &request, &result));
        const uint64_t n = motion_steps(a, b, request.resolution);
        const int64_t first = first_colliding_sample(single, tree, arm, a, b, n, 0);
        assert_int_equal(result.collided, first >= 0);
        assert_true(result.first_collision_fraction == (first < 0 ? -1.0 : (double)first / (double)n));
        colliding += first >= 0;
    }
    assert_true(colliding > 0 && colliding < MOTIONS);
    opx_query_destroy(single);
    opx_query_destroy(query);
    close_scene(&scene);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(equals_single_calls),
        cmocka_unit_test(equals_single_calls_every_setting),
        cmocka_unit_test(reads_a_changed_map_anew),
        cmocka_unit_test(one_query_at_two_thresholds),
        cmocka_unit_test(arm_with_a_box_answers_the_same),
        cmocka_unit_test(motions_equal_single_calls),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
