/*
 * opx_query_collide_spheres: every sphere answers as opx_query_collide
 * answers a link set holding that sphere alone, on random maps (occupied,
 * free and unknown space, pruned leaves), at spheres near surfaces, with
 * both unknown policies, both obstacle models and two thresholds, at
 * spheres whose boxes end on cell faces and at the map's outer faces; bad
 * input is an error naming the argument.
 */
#include "opx_test.h"

#include <stdlib.h>

/* A deterministic uniform draw in [lo, hi). */
static double draw(unsigned *state, double lo, double hi) {
    *state = *state * 1103515245u + 12345u;
    return lo + (hi - lo) * (double)((*state >> 8) & 0xFFFFFF) / (double)0x1000000;
}

/* A random cloud in front of a sensor: walls, blobs and stray points. */
static opx_octree *random_map(unsigned *state, double resolution) {
    opx_octree *tree = new_tree(resolution);
    double xyz[3 * 600];
    size_t i;
    for (i = 0; i < 600; ++i) {
        const int wall = i % 3 == 0;
        xyz[3 * i] = wall ? 1.0 + 0.3 * (double)(i % 2) : draw(state, 0.5, 1.5);
        xyz[3 * i + 1] = draw(state, -0.6, 0.6);
        xyz[3 * i + 2] = draw(state, -0.4, 0.4);
    }
    const opx_insert_options options = sensor_at(0.01, 0.02, 0.03, OPX_INSERT_RAYCAST);
    insert_f64(tree, xyz, 600, &options);
    return tree;
}

static int collides_as_link_set(opx_query *query, const opx_octree *tree, const double sphere[4],
                                const opx_sphere_request *r) {
    opx_linkset *links = NULL;
    uint32_t link = 0;
    opx_shape shape = OPX_SHAPE_INIT;
    opx_pose pose = OPX_POSE_IDENTITY;
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    assert_ok(opx_linkset_create(&links));
    assert_ok(opx_linkset_add_link(links, "ball", &link));
    shape.kind = OPX_SHAPE_SPHERE;
    shape.radius = sphere[3];
    assert_ok(opx_linkset_add_shape(links, link, &shape, NULL));
    pose.position[0] = sphere[0], pose.position[1] = sphere[1], pose.position[2] = sphere[2];
    assert_ok(opx_linkset_set_poses(links, &pose, 1, 0));
    request.max_contacts = 0;
    request.unknown_policy = r->unknown_policy;
    request.occupancy_threshold = r->occupancy_threshold;
    request.obstacle_geometry = r->obstacle_geometry;
    assert_ok(opx_query_collide(query, tree, links, &request, &result));
    opx_linkset_destroy(links);
    return result.collided;
}

static void spheres_answer_as_one_sphere_link_sets(void **state) {
    unsigned seed = 7;
    opx_query *query = NULL;
    size_t map, i, collided = 0, checked = 0;
    (void)state;
    assert_ok(opx_query_create(NULL, &query));
    for (map = 0; map < 4; ++map) {
        opx_octree *tree = random_map(&seed, map % 2 ? 0.05 : 0.1);
        double spheres[4 * 200];
        uint8_t got[200];
        int variant;
        for (i = 0; i < 200; ++i) {
            spheres[4 * i] = draw(&seed, 0.3, 1.7);
            spheres[4 * i + 1] = draw(&seed, -0.8, 0.8);
            spheres[4 * i + 2] = draw(&seed, -0.6, 0.6);
            spheres[4 * i + 3] = i % 10 == 0 ? 0.001 : draw(&seed, 0.005, 0.3);
        }
        for (variant = 0; variant < 8; ++variant) {
            opx_sphere_request request = OPX_SPHERE_REQUEST_INIT;
            request.unknown_policy = variant & 1 ? OPX_UNKNOWN_OCCUPIED : OPX_UNKNOWN_FREE;
            request.obstacle_geometry = variant & 2 ? OPX_OBSTACLE_POINT_EXTENTS : OPX_OBSTACLE_CELLS;
            request.occupancy_threshold = variant & 4 ? 0.8 : 0.0;
            assert_ok(opx_query_collide_spheres(query, tree, spheres, 200, 0, &request, got, 200));
            for (i = 0; i < 200; ++i) {
                const int expected = collides_as_link_set(query, tree, spheres + 4 * i, &request);
                if (got[i] != expected)
                    fail_msg("map %zu, variant %d, sphere %zu (%g %g %g r %g): %d, as a link set %d", map, variant, i,
                             spheres[4 * i], spheres[4 * i + 1], spheres[4 * i + 2], spheres[4 * i + 3], got[i],
                             expected);
                collided += got[i];
                ++checked;
            }
        }
        opx_octree_destroy(tree);
    }
    assert_true(collided > checked / 10 && collided < checked * 9 / 10);
    opx_query_destroy(query);
}

static void strided_rows_and_an_empty_map(void **state) {
    opx_octree *tree = new_tree(0.1);
    opx_query *query = NULL;
    double rows[2][6] = {{0.5, 0.0, 0.0, 0.1, 99, 99}, {2.0, 0.0, 0.0, 0.2, 99, 99}};
    uint8_t got[2] = {7, 7};
    opx_sphere_request unknown_occupied = OPX_SPHERE_REQUEST_INIT;
    (void)state;
    assert_ok(opx_query_create(NULL, &query));
    assert_ok(opx_query_collide_spheres(query, tree, &rows[0][0], 2, sizeof rows[0], NULL, got, 2));
    assert_int_equal(got[0], 0);
    assert_int_equal(got[1], 0);
    unknown_occupied.unknown_policy = OPX_UNKNOWN_OCCUPIED;
    assert_ok(opx_query_collide_spheres(query, tree, &rows[0][0], 2, sizeof rows[0], &unknown_occupied, got, 2));
    assert_int_equal(got[0], 1);
    assert_int_equal(got[1], 1);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
}

/* A sphere of radius 0 is a point: it collides inside an occupied cell. */
static void a_point_is_a_sphere_of_radius_zero(void **state) {
    opx_octree *tree = new_sample_map(); /* occupied: the cells around (1, 0, 0) and (0, 1, 0) */
    opx_query *query = NULL;
    const double points[2][4] = {{1.1, 0.1, 0.1, 0.0}, {0.6, 0.1, 0.1, 0.0}};
    uint8_t got[2];
    (void)state;
    assert_ok(opx_query_create(NULL, &query));
    assert_ok(opx_query_collide_spheres(query, tree, &points[0][0], 2, 0, NULL, got, 2));
    assert_int_equal(classify_at(tree, 1.1, 0.1, 0.1).cell_class, OPX_CELL_OCCUPIED);
    assert_int_equal(got[0], 1);
    assert_int_equal(got[1], 0);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
}

/* Occupied cells around the origin and against the map's outer faces
 * (0.1 m cells: the map ends at +-3276.8 m), and spheres whose boxes end on
 * cell faces, straddle the origin's planes or reach past the map. */
static void spheres_on_cell_faces_and_at_the_map_edge(void **state) {
    const double edge = 3276.8;
    const double points[][3] = {{0.05, 0.05, 0.05},    {-0.15, 0.25, -0.05}, {0.35, -0.05, 0.15},
                                {edge - 0.05, 0.05, 0.05}, {-edge + 0.05, -0.05, 0.25}, {0.05, edge - 0.15, -edge + 0.05}};
    const double radii[] = {0.001, 0.05, 0.1, 0.2, 0.3};
    opx_octree *tree = new_tree(0.1);
    opx_query *query = NULL;
    const opx_insert_options options = sensor_at(0.0, 0.0, 0.0, OPX_INSERT_ENDPOINTS);
    size_t p, r, collided = 0, checked = 0;
    int dx, dy;
    (void)state;
    insert_f64(tree, &points[0][0], 6, &options);
    assert_ok(opx_query_create(NULL, &query));
    for (p = 0; p < 6; ++p)
        for (r = 0; r < 5; ++r)
            for (dx = -3; dx <= 3; ++dx)
                for (dy = -3; dy <= 3; ++dy) {
                    /* centres on cell faces, edges and centres next to the point */
                    const double sphere[4] = {points[p][0] + 0.05 * dx, points[p][1] + 0.05 * dy, points[p][2] - 0.05,
                                              radii[r]};
                    const opx_sphere_request request = OPX_SPHERE_REQUEST_INIT;
                    uint8_t got = 2;
                    assert_ok(opx_query_collide_spheres(query, tree, sphere, 1, 0, &request, &got, 1));
                    if (got != collides_as_link_set(query, tree, sphere, &request))
                        fail_msg("sphere (%g %g %g r %g): %d", sphere[0], sphere[1], sphere[2], sphere[3], got);
                    collided += got;
                    ++checked;
                }
    assert_true(collided > checked / 10 && collided < checked * 9 / 10);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
}

static void bad_input_names_the_argument(void **state) {
    const char *fn = "opx_query_collide_spheres";
    opx_octree *tree = new_sample_map();
    opx_query *query = NULL;
    double sphere[4] = {0.5, 0.5, 0.5, 0.1};
    uint8_t got[2];
    opx_sphere_request bad = OPX_SPHERE_REQUEST_INIT;
    (void)state;
    assert_ok(opx_query_create(NULL, &query));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "query", opx_query_collide_spheres(NULL, tree, sphere, 1, 0, NULL, got, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "tree", opx_query_collide_spheres(query, NULL, sphere, 1, 0, NULL, got, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "spheres", opx_query_collide_spheres(query, tree, NULL, 1, 0, NULL, got, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "out_collided",
                   opx_query_collide_spheres(query, tree, sphere, 1, 0, NULL, NULL, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "count", opx_query_collide_spheres(query, tree, sphere, 0, 0, NULL, got, 1));
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, fn, "capacity",
                   opx_query_collide_spheres(query, tree, sphere, 2, 0, NULL, got, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "stride", opx_query_collide_spheres(query, tree, sphere, 1, 16, NULL, got, 1));
    sphere[3] = -0.1;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "row 0", opx_query_collide_spheres(query, tree, sphere, 1, 0, NULL, got, 1));
    sphere[3] = 0.1;
    sphere[1] = NAN;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "row 0", opx_query_collide_spheres(query, tree, sphere, 1, 0, NULL, got, 1));
    sphere[1] = 0.5;
    bad.obstacle_geometry = 7;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "obstacle_geometry",
                   opx_query_collide_spheres(query, tree, sphere, 1, 0, &bad, got, 1));
    bad = (opx_sphere_request)OPX_SPHERE_REQUEST_INIT;
    bad.unknown_policy = 3;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "unknown_policy",
                   opx_query_collide_spheres(query, tree, sphere, 1, 0, &bad, got, 1));
    bad = (opx_sphere_request)OPX_SPHERE_REQUEST_INIT;
    bad.occupancy_threshold = 1.5;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "occupancy_threshold",
                   opx_query_collide_spheres(query, tree, sphere, 1, 0, &bad, got, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_sphere_request_init", "request", opx_sphere_request_init(NULL, 8));
    opx_query_destroy(query);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(spheres_answer_as_one_sphere_link_sets),
        cmocka_unit_test(strided_rows_and_an_empty_map),
        cmocka_unit_test(a_point_is_a_sphere_of_radius_zero),
        cmocka_unit_test(spheres_on_cell_faces_and_at_the_map_edge),
        cmocka_unit_test(bad_input_names_the_argument),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
