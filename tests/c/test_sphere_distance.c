/*
 * opx_query_distance_spheres through the C ABI: world objects (boxes and
 * balls) against their exact signed distance fields, the map and the world
 * together, unknown space as an obstacle, strided rows and optional
 * outputs, answers independent of the thread count, and bad input named.
 * (The map's distances against a brute force: unit_sphere_distance.)
 */
#include "opx_test.h"

#include <stdlib.h>
#include <string.h>

static double draw(unsigned *state, double lo, double hi) {
    *state = *state * 1103515245u + 12345u;
    return lo + (hi - lo) * (double)((*state >> 8) & 0xFFFFFF) / (double)0x1000000;
}

/* Three boxes and two balls, apart from each other. */
static const double kBoxes[3][6] = {{0.0, 0.0, 0.0, 0.4, 0.2, 0.3}, {1.0, -0.5, 0.0, 1.2, 0.5, 0.1},
                                    {-1.0, 0.5, -0.2, -0.6, 0.6, 0.2}};
static const double kBalls[2][4] = {{0.0, -1.0, 0.0, 0.25}, {0.7, 0.8, 0.5, 0.1}};

static opx_world *objects(void) {
    opx_world *world = NULL;
    size_t i;
    assert_ok(opx_world_create(&world));
    for (i = 0; i < 5; ++i) {
        opx_shape shape = OPX_SHAPE_INIT;
        uint32_t object = 0;
        assert_ok(opx_world_add_object(world, "o", NULL, &object));
        if (i < 3) {
            int a;
            shape.kind = OPX_SHAPE_BOX;
            for (a = 0; a < 3; ++a) {
                shape.size[a] = kBoxes[i][3 + a] - kBoxes[i][a];
                shape.pose.position[a] = 0.5 * (kBoxes[i][a] + kBoxes[i][3 + a]);
            }
        } else {
            shape.kind = OPX_SHAPE_SPHERE;
            shape.radius = kBalls[i - 3][3];
            memcpy(shape.pose.position, kBalls[i - 3], 3 * sizeof(double));
        }
        assert_ok(opx_world_add_shape(world, object, &shape, NULL));
    }
    return world;
}

/* The signed distance field of one box or ball at p. */
static double box_sdf(const double *b, const double p[3]) {
    double out = 0.0, in = 1e300;
    int a;
    for (a = 0; a < 3; ++a) {
        const double gap = fmax(fmax(b[a] - p[a], p[a] - b[3 + a]), 0.0);
        out += gap * gap;
        in = fmin(in, fmin(p[a] - b[a], b[3 + a] - p[a]));
    }
    return out > 0.0 ? sqrt(out) : -in;
}

static double ball_sdf(const double *s, const double p[3]) {
    return sqrt((p[0] - s[0]) * (p[0] - s[0]) + (p[1] - s[1]) * (p[1] - s[1]) + (p[2] - s[2]) * (p[2] - s[2])) - s[3];
}

/* Apart, the union's field is the one part holding p, else the nearest. */
static double world_sdf(const double p[3]) {
    double best = 1e300;
    size_t i;
    for (i = 0; i < 5; ++i) {
        const double d = i < 3 ? box_sdf(kBoxes[i], p) : ball_sdf(kBalls[i - 3], p);
        if (d <= 0.0) return d;
        best = fmin(best, d);
    }
    return best;
}

static void world_objects_have_their_signed_distance_fields(void **state) {
    enum { kCount = 2000 };
    opx_world *world = objects();
    opx_query *query = NULL;
    double *spheres = malloc(kCount * 4 * sizeof(double)), *distance = malloc(kCount * sizeof(double));
    double *gradient = malloc(kCount * 3 * sizeof(double)), *witness = malloc(kCount * 3 * sizeof(double));
    opx_sphere_distance_request request = OPX_SPHERE_DISTANCE_REQUEST_INIT;
    unsigned seed = 3;
    size_t i, inside = 0, truncated = 0;
    (void)state;
    request.max_distance = 0.2;
    for (i = 0; i < kCount; ++i) {
        spheres[4 * i] = draw(&seed, -1.3, 1.5);
        spheres[4 * i + 1] = draw(&seed, -1.4, 1.1);
        spheres[4 * i + 2] = draw(&seed, -0.5, 0.8);
        spheres[4 * i + 3] = draw(&seed, 0.0, 0.05);
    }
    assert_ok(opx_query_create(NULL, &query));
    assert_ok(opx_query_set_world(query, world));
    assert_ok(opx_query_distance_spheres(query, NULL, spheres, kCount, 0, &request, distance, gradient, witness,
                                         kCount));
    for (i = 0; i < kCount; ++i) {
        const double *c = spheres + 4 * i, *g = gradient + 3 * i;
        const double sdf = world_sdf(c), expected = fmin(sdf - c[3], 0.2);
        assert_near(distance[i], expected, 2e-9);
        if (sdf - c[3] >= 0.2 + 1e-9) {
            assert_true(g[0] == 0.0 && g[1] == 0.0 && g[2] == 0.0 && isnan(witness[3 * i]));
            ++truncated;
        } else if (fabs(sdf) > 1e-6 && sdf - c[3] < 0.2 - 1e-9) {
            /* The witness is |sdf| away, and the gradient points from it (outside) or to it (inside). */
            const double *w = witness + 3 * i, sign = sdf > 0.0 ? 1.0 : -1.0;
            int a;
            for (a = 0; a < 3; ++a) assert_near(g[a], sign * (c[a] - w[a]) / fabs(sdf), 1e-7);
            assert_near(world_sdf(w), 0.0, 1e-9);
            inside += sdf < 0.0;
        }
    }
    assert_true(inside > 20 && truncated > kCount / 4);
    opx_query_destroy(query);
    opx_world_destroy(world);
    free(spheres), free(distance), free(gradient), free(witness);
}

/* One occupied cell [0, 0.25]^3 and a world ball: the nearer wins. */
static void the_map_and_the_world_together(void **state) {
    opx_octree *tree = new_tree(RES);
    opx_world *world = NULL;
    opx_query *query = NULL;
    opx_shape ball = OPX_SHAPE_INIT;
    uint32_t object = 0;
    const double point[3] = {C0, C0, C0};
    const opx_insert_options options = sensor_at(0.0, 0.0, 0.0, OPX_INSERT_ENDPOINTS);
    /* nearer the cell; nearer the ball; inside the ball; inside the cell */
    const double spheres[4][4] = {{0.5, C0, C0, 0.0}, {2.0, C0, C0, 0.1}, {2.5, C0, C0, 0.0}, {0.05, C0, C0, 0.0}};
    double distance[4], gradient[12];
    opx_sphere_distance_request request = OPX_SPHERE_DISTANCE_REQUEST_INIT;
    (void)state;
    insert_f64(tree, point, 1, &options);
    assert_ok(opx_world_create(&world));
    assert_ok(opx_world_add_object(world, "ball", NULL, &object));
    ball.kind = OPX_SHAPE_SPHERE;
    ball.radius = 0.25;
    ball.pose.position[0] = 2.5;
    ball.pose.position[1] = C0;
    ball.pose.position[2] = C0;
    assert_ok(opx_world_add_shape(world, object, &ball, NULL));
    assert_ok(opx_query_create(NULL, &query));
    assert_ok(opx_query_set_world(query, world));
    request.max_distance = 1.0;
    assert_ok(opx_query_distance_spheres(query, tree, &spheres[0][0], 4, 0, &request, distance, gradient, NULL, 4));
    assert_near(distance[0], 0.25, 1e-12);
    assert_near(gradient[0], 1.0, 1e-12);
    assert_near(distance[1], 2.25 - 2.0 - 0.1, 1e-9);
    assert_near(gradient[3], -1.0, 1e-9);
    assert_near(distance[2], -0.25, 1e-9);
    assert_near(distance[3], -0.05, 1e-12);
    assert_near(gradient[9], -1.0, 1e-12);
    opx_query_destroy(query);
    opx_world_destroy(world);
    opx_octree_destroy(tree);
}

/* Unknown space as an obstacle: in an empty map, the whole map cube. */
static void unknown_space_is_a_solid_when_occupied(void **state) {
    opx_octree *tree = new_tree(0.1);
    opx_query *query = NULL;
    opx_sphere_distance_request request = OPX_SPHERE_DISTANCE_REQUEST_INIT;
    const double sphere[4] = {1.0, 0.0, 0.0, 0.5};
    double distance = 0.0, gradient[3], witness[3];
    (void)state;
    request.unknown_policy = OPX_UNKNOWN_OCCUPIED;
    request.max_distance = INFINITY;
    assert_ok(opx_query_create(NULL, &query));
    assert_ok(opx_query_distance_spheres(query, tree, sphere, 1, 0, &request, &distance, gradient, witness, 1));
    assert_near(distance, -(3276.8 - 1.0) - 0.5, 1e-9);
    assert_near(gradient[0], 1.0, 1e-12);
    assert_near(witness[0], 3276.8, 1e-9);
    request.unknown_policy = OPX_UNKNOWN_FREE;
    assert_ok(opx_query_distance_spheres(query, tree, sphere, 1, 0, &request, &distance, gradient, witness, 1));
    assert_true(isinf(distance) && distance > 0.0 && gradient[0] == 0.0 && isnan(witness[0]));
    opx_query_destroy(query);
    opx_octree_destroy(tree);
}

static opx_octree *random_map(unsigned *state) {
    opx_octree *tree = new_tree(0.05);
    double xyz[3 * 900];
    size_t i;
    for (i = 0; i < 900; ++i) {
        const int wall = i % 3 == 0;
        xyz[3 * i] = wall ? 1.0 + 0.3 * (double)(i % 2) : draw(state, 0.5, 1.5);
        xyz[3 * i + 1] = draw(state, -0.6, 0.6);
        xyz[3 * i + 2] = draw(state, -0.4, 0.4);
    }
    {
        const opx_insert_options options = sensor_at(0.01, 0.02, 0.03, OPX_INSERT_RAYCAST);
        insert_f64(tree, xyz, 900, &options);
    }
    return tree;
}

/* Strided rows, optional outputs, and the same bits for every thread count. */
static void threads_strides_and_optional_outputs(void **state) {
    enum { kCount = 3000 };
    unsigned seed = 11;
    opx_octree *tree = random_map(&seed);
    opx_query *query = NULL;
    double *rows = malloc(kCount * 6 * sizeof(double));
    double *d[3], *g[3], *w[3], *alone = malloc(kCount * sizeof(double));
    const uint32_t threads[3] = {1, 0, 3};
    size_t i, t;
    int extents;
    (void)state;
    for (i = 0; i < kCount; ++i) {
        rows[6 * i] = draw(&seed, 0.3, 1.7);
        rows[6 * i + 1] = draw(&seed, -0.8, 0.8);
        rows[6 * i + 2] = draw(&seed, -0.6, 0.6);
        rows[6 * i + 3] = draw(&seed, 0.0, 0.1);
        rows[6 * i + 4] = rows[6 * i + 5] = NAN; /* beyond the row: never read */
    }
    for (t = 0; t < 3; ++t) {
        d[t] = malloc(kCount * sizeof(double));
        g[t] = malloc(kCount * 3 * sizeof(double));
        w[t] = malloc(kCount * 3 * sizeof(double));
    }
    assert_ok(opx_query_create(NULL, &query));
    for (extents = 0; extents < 2; ++extents) {
        opx_sphere_distance_request request = OPX_SPHERE_DISTANCE_REQUEST_INIT;
        request.obstacle_geometry = extents ? OPX_OBSTACLE_POINT_EXTENTS : OPX_OBSTACLE_CELLS;
        request.max_distance = 0.15;
        for (t = 0; t < 3; ++t) {
            request.max_threads = threads[t];
            assert_ok(opx_query_distance_spheres(query, tree, rows, kCount, 6 * sizeof(double), &request, d[t], g[t],
                                                 w[t], kCount));
        }
        for (t = 1; t < 3; ++t) {
            assert_memory_equal(d[0], d[t], kCount * sizeof(double));
            assert_memory_equal(g[0], g[t], kCount * 3 * sizeof(double));
            assert_memory_equal(w[0], w[t], kCount * 3 * sizeof(double));
        }
        request.max_threads = 2;
        assert_ok(opx_query_distance_spheres(query, tree, rows, kCount, 48, &request, alone, NULL, NULL, kCount));
        assert_memory_equal(d[0], alone, kCount * sizeof(double));
    }
    {
        size_t negative = 0, truncated = 0;
        for (i = 0; i < kCount; ++i) negative += d[0][i] < 0.0, truncated += d[0][i] == 0.15;
        assert_true(negative > 50 && truncated > 50 && negative + truncated < kCount);
    }
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    for (t = 0; t < 3; ++t) free(d[t]), free(g[t]), free(w[t]);
    free(rows), free(alone);
}

static void bad_input_names_the_argument(void **state) {
    const char *fn = "opx_query_distance_spheres";
    opx_octree *tree = new_sample_map();
    opx_query *query = NULL;
    double sphere[4] = {0.5, 0.5, 0.5, 0.1}, d[2], g[6];
    opx_sphere_distance_request bad = OPX_SPHERE_DISTANCE_REQUEST_INIT;
    map_snapshot before = take_snapshot(tree);
    (void)state;
    assert_ok(opx_query_create(NULL, &query));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "query",
                   opx_query_distance_spheres(NULL, tree, sphere, 1, 0, NULL, d, g, NULL, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "tree",
                   opx_query_distance_spheres(query, NULL, sphere, 1, 0, NULL, d, g, NULL, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "spheres",
                   opx_query_distance_spheres(query, tree, NULL, 1, 0, NULL, d, g, NULL, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "out_distance",
                   opx_query_distance_spheres(query, tree, sphere, 1, 0, NULL, NULL, g, NULL, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "count",
                   opx_query_distance_spheres(query, tree, sphere, 0, 0, NULL, d, g, NULL, 1));
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, fn, "capacity",
                   opx_query_distance_spheres(query, tree, sphere, 2, 0, NULL, d, g, NULL, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "stride",
                   opx_query_distance_spheres(query, tree, sphere, 1, 24, NULL, d, g, NULL, 1));
    sphere[3] = -0.1;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "row 0",
                   opx_query_distance_spheres(query, tree, sphere, 1, 0, NULL, d, g, NULL, 1));
    sphere[3] = 0.1;
    sphere[0] = NAN;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "row 0",
                   opx_query_distance_spheres(query, tree, sphere, 1, 0, NULL, d, g, NULL, 1));
    sphere[0] = INFINITY;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "row 0",
                   opx_query_distance_spheres(query, tree, sphere, 1, 0, NULL, d, g, NULL, 1));
    sphere[0] = 0.5;
    bad.max_distance = 0.0;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "max_distance",
                   opx_query_distance_spheres(query, tree, sphere, 1, 0, &bad, d, g, NULL, 1));
    bad.max_distance = NAN;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "max_distance",
                   opx_query_distance_spheres(query, tree, sphere, 1, 0, &bad, d, g, NULL, 1));
    bad = (opx_sphere_distance_request)OPX_SPHERE_DISTANCE_REQUEST_INIT;
    bad.obstacle_geometry = 5;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "obstacle_geometry",
                   opx_query_distance_spheres(query, tree, sphere, 1, 0, &bad, d, g, NULL, 1));
    bad = (opx_sphere_distance_request)OPX_SPHERE_DISTANCE_REQUEST_INIT;
    bad.unknown_policy = 9;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "unknown_policy",
                   opx_query_distance_spheres(query, tree, sphere, 1, 0, &bad, d, g, NULL, 1));
    bad = (opx_sphere_distance_request)OPX_SPHERE_DISTANCE_REQUEST_INIT;
    bad.occupancy_threshold = 2.0;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "occupancy_threshold",
                   opx_query_distance_spheres(query, tree, sphere, 1, 0, &bad, d, g, NULL, 1));
    bad = (opx_sphere_distance_request)OPX_SPHERE_DISTANCE_REQUEST_INIT;
    bad.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, fn, "request",
                   opx_query_distance_spheres(query, tree, sphere, 1, 0, &bad, d, g, NULL, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_sphere_distance_request_init", "request",
                   opx_sphere_distance_request_init(NULL, 8));
    assert_unchanged(tree, &before);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(world_objects_have_their_signed_distance_fields),
        cmocka_unit_test(the_map_and_the_world_together),
        cmocka_unit_test(unknown_space_is_a_solid_when_occupied),
        cmocka_unit_test(threads_strides_and_optional_outputs),
        cmocka_unit_test(bad_input_names_the_argument),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
