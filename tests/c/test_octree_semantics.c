/*
 * OctoMap semantics on tiny maps computed by hand.  Resolution RES = 0.25,
 * the sensor at the centre (C0, C0, C0) of the cell [0, 0.25)^3, rays along
 * the axes.  A ray to sensor-frame (1, 0, 0) crosses the cells x = 0, 0.25,
 * 0.5, 0.75 (free, the sensor's cell included) and ends in x = 1.0
 * (occupied, centre 1.125).  Log-odds: l(p) = ln(p / (1 - p)).
 */
#include "opx_test.h"

static void assert_cell(const opx_octree *tree, double x, double y, double z, int32_t cls,
                        double p) {
    const opx_cell_info info = classify_at(tree, x, y, z);
    if (info.cell_class != cls)
        fail_msg("cell at (%g, %g, %g): class %d, expected %d (p %.9g)", x, y, z,
                 (int)info.cell_class, (int)cls, info.probability);
    assert_near(info.probability, p, OPX_PROB_TOL);
}

static void one_hit_gives_prob_hit(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    const opx_insert_report r = insert_one_ray(tree, 1.0, 0.0, 0.0);
    assert_int_equal(r.points_used, 1);
    assert_int_equal(r.cells_hit, 1);
    assert_int_equal(r.cells_missed, 4);
    assert_cell(tree, 1.125, C0, C0, OPX_CELL_OCCUPIED, 0.7);
    const opx_cell_info info = classify_at(tree, 1.1, 0.01, 0.24);
    assert_near(info.center[0], 1.125, OPX_GEOM_TOL);
    assert_near(info.center[1], C0, OPX_GEOM_TOL);
    assert_near(info.center[2], C0, OPX_GEOM_TOL);
    assert_near(info.size, RES, OPX_GEOM_TOL);
    assert_int_equal(info.depth, 16);
    opx_octree_destroy(tree);
}

static void cells_on_a_ray_get_prob_miss(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    insert_one_ray(tree, 1.0, 0.0, 0.0);
    for (int i = 0; i < 4; ++i) assert_cell(tree, C0 + i * RES, C0, C0, OPX_CELL_FREE, 0.4);
    /* Beyond the endpoint and beside the ray: never observed. */
    assert_cell(tree, 1.375, C0, C0, OPX_CELL_UNKNOWN, 0.5);
    assert_cell(tree, C0, 0.375, C0, OPX_CELL_UNKNOWN, 0.5);
    opx_octree_destroy(tree);
}

static void endpoints_mode_touches_no_free_cell(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    const double xyz[6] = {1.0, 0.0, 0.0, 0.0, 0.0, 2.0};
    const opx_insert_options options = sensor_at(C0, C0, C0, OPX_INSERT_ENDPOINTS);
    const opx_insert_report r = insert_f64(tree, xyz, 2, &options);
    assert_int_equal(r.cells_hit, 2);
    assert_int_equal(r.cells_missed, 0);
    const opx_octree_stats stats = stats_of(tree);
    assert_int_equal(stats.leaves_occupied, 2);
    assert_int_equal(stats.leaves_free, 0);
    assert_cell(tree, 1.125, C0, C0, OPX_CELL_OCCUPIED, 0.7);
    assert_cell(tree, C0, C0, 2.125, OPX_CELL_OCCUPIED, 0.7);
    assert_cell(tree, 0.625, C0, C0, OPX_CELL_UNKNOWN, 0.5);
    opx_octree_destroy(tree);
}

/* Two frames: log-odds add.  The cell hit in frame 1 is on the ray of
 * frame 2: l = l(0.7) + l(0.4). */
static void frames_accumulate_log_odds(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    insert_one_ray(tree, 1.0, 0.0, 0.0);
    insert_one_ray(tree, 2.0, 0.0, 0.0);
    assert_cell(tree, 1.125, C0, C0, OPX_CELL_OCCUPIED, probability(log_odds(0.7) + log_odds(0.4)));
    assert_cell(tree, 0.625, C0, C0, OPX_CELL_FREE, probability(2.0 * log_odds(0.4)));
    assert_cell(tree, 2.125, C0, C0, OPX_CELL_OCCUPIED, 0.7);
    insert_one_ray(tree, 2.0, 0.0, 0.0);
    assert_cell(tree, 2.125, C0, C0, OPX_CELL_OCCUPIED, probability(2.0 * log_odds(0.7)));
    assert_near(probability(2.0 * log_odds(0.7)), 0.49 / 0.58, 1e-12); /* the hand value */
    opx_octree_destroy(tree);
}

/* Within one frame each cell is updated once and an endpoint wins over a
 * ray crossing it. */
static void one_update_per_cell_per_frame(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    const double xyz[6] = {1.0, 0.0, 0.0, 2.0, 0.0, 0.0};
    const opx_insert_options options = sensor_at(C0, C0, C0, OPX_INSERT_RAYCAST);
    const opx_insert_report r = insert_f64(tree, xyz, 2, &options);
    assert_int_equal(r.cells_hit, 2);
    assert_int_equal(r.cells_missed, 7); /* x = 0 .. 1.75 except the endpoint 1.0 */
    assert_cell(tree, 1.125, C0, C0, OPX_CELL_OCCUPIED, 0.7);
    assert_cell(tree, 0.375, C0, C0, OPX_CELL_FREE, 0.4); /* crossed twice, updated once */
    assert_cell(tree, 1.375, C0, C0, OPX_CELL_FREE, 0.4);
    opx_octree_destroy(tree);
}

static void clamping_at_clamp_max_and_min(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    /* l(0.971) = 3.51: the 5th hit (5 * 0.847 = 4.24) is clamped; l(0.1192)
     * = -2.0: the 5th miss (5 * -0.405 = -2.03) is clamped. */
    for (int frame = 0; frame < 6; ++frame) insert_one_ray(tree, 1.0, 0.0, 0.0);
    assert_cell(tree, 1.125, C0, C0, OPX_CELL_OCCUPIED, 0.971);
    assert_cell(tree, 0.375, C0, C0, OPX_CELL_FREE, 0.1192);
    /* Clamped means one miss is enough to leave the bound. */
    insert_one_ray(tree, 2.0, 0.0, 0.0);
    assert_cell(tree, 1.125, C0, C0, OPX_CELL_OCCUPIED, probability(log_odds(0.971) + log_odds(0.4)));
    opx_octree_destroy(tree);
}

static void clamping_with_custom_bounds(void **state) {
    (void)state;
    opx_octree_options o = OPX_OCTREE_OPTIONS_INIT;
    o.resolution = RES;
    o.clamp_max = 0.8;
    o.clamp_min = 0.35;
    opx_octree *tree = new_tree_with(&o);
    insert_one_ray(tree, 1.0, 0.0, 0.0);
    insert_one_ray(tree, 1.0, 0.0, 0.0);
    assert_cell(tree, 1.125, C0, C0, OPX_CELL_OCCUPIED, 0.8);  /* 0.845 clamped */
    assert_cell(tree, 0.375, C0, C0, OPX_CELL_FREE, 0.35);     /* 0.308 clamped */
    opx_octree_destroy(tree);
}

/* A cell at p = 0.4: free when free_threshold is 0.45, uncertain when it is
 * 0.3; a cell at 0.7 is uncertain below occupied_threshold 0.75. */
static void thresholds_choose_the_class(void **state) {
    (void)state;
    const double free_thresholds[2] = {0.45, 0.3};
    const int32_t free_cell_class[2] = {OPX_CELL_FREE, OPX_CELL_UNCERTAIN};
    for (int i = 0; i < 2; ++i) {
        opx_octree_options o = OPX_OCTREE_OPTIONS_INIT;
        o.resolution = RES;
        o.free_threshold = free_thresholds[i];
        o.occupied_threshold = 0.75;
        opx_octree *tree = new_tree_with(&o);
        insert_one_ray(tree, 1.0, 0.0, 0.0);
        assert_cell(tree, 0.375, C0, C0, free_cell_class[i], 0.4);
        assert_cell(tree, 1.125, C0, C0, OPX_CELL_UNCERTAIN, 0.7);
        const opx_octree_stats stats = stats_of(tree);
        assert_int_equal(stats.leaves_occupied, 0);
        assert_int_equal(stats.has_occupied, 0);
        assert_int_equal(stats.leaves_uncertain, i == 0 ? 1 : 5);
        assert_int_equal(stats.leaves_free, i == 0 ? 4 : 0);
        opx_octree_destroy(tree);
    }
}

/* "occupied when p >= occupied_threshold": a cell hit once with p_hit 0.7
 * and occupied_threshold 0.7 is occupied. */
static void occupied_threshold_is_inclusive(void **state) {
    (void)state;
    opx_octree_options o = OPX_OCTREE_OPTIONS_INIT;
    o.resolution = RES;
    o.occupied_threshold = 0.7;
    opx_octree *tree = new_tree_with(&o);
    insert_one_ray(tree, 1.0, 0.0, 0.0);
    assert_cell(tree, 1.125, C0, C0, OPX_CELL_OCCUPIED, 0.7);
    opx_octree_destroy(tree);
}

/* A point beyond max_range gives no hit; as in OctoMap its ray is cut at
 * max_range and frees the cells up to there (documented in
 * opx_insert_options). */
static void max_range_cuts_rays(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    const double xyz[6] = {1.0, 0.0, 0.0, 0.0, 3.0, 0.0};
    opx_insert_options options = sensor_at(C0, C0, C0, OPX_INSERT_RAYCAST);
    options.max_range = 2.0;
    const opx_insert_report r = insert_f64(tree, xyz, 2, &options);
    assert_int_equal(r.points_used, 1);
    assert_int_equal(r.points_out_of_range, 1);
    assert_int_equal(r.cells_hit, 1);
    /* 4 cells along +x (the origin's included), 7 more along +y up to 2 m. */
    assert_int_equal(r.cells_missed, 11);
    assert_cell(tree, C0, 0.375, C0, OPX_CELL_FREE, 0.4);
    assert_cell(tree, C0, C0 + 7 * RES, C0, OPX_CELL_FREE, 0.4);
    assert_cell(tree, C0, C0 + 8 * RES, C0, OPX_CELL_UNKNOWN, 0.5); /* the cut end's cell */
    assert_cell(tree, C0, 3.125, C0, OPX_CELL_UNKNOWN, 0.5);
    /* +infinity and negative values mean no limit. */
    options.max_range = INFINITY;
    assert_int_equal(insert_f64(tree, xyz, 2, &options).points_out_of_range, 0);
    options.max_range = -INFINITY;
    assert_int_equal(insert_f64(tree, xyz, 2, &options).points_out_of_range, 0);
    options.max_range = 0.0;
    assert_int_equal(insert_f64(tree, xyz, 2, &options).points_out_of_range, 0);
    opx_octree_destroy(tree);
}

/* Eight hits filling the eight cells of a 0.5 m cube, all equal: OctoMap
 * prunes them into one leaf at depth 15. */
static void equal_siblings_are_pruned(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    double xyz[24];
    for (int i = 0; i < 8; ++i) {
        xyz[3 * i + 0] = (i & 1) ? RES : 0.0;
        xyz[3 * i + 1] = (i & 2) ? RES : 0.0;
        xyz[3 * i + 2] = (i & 4) ? RES : 0.0;
    }
    const opx_insert_options options = sensor_at(C0, C0, C0, OPX_INSERT_ENDPOINTS);
    insert_f64(tree, xyz, 8, &options);
    const opx_cell_info info = classify_at(tree, 0.1, 0.4, 0.2);
    assert_int_equal(info.cell_class, OPX_CELL_OCCUPIED);
    assert_int_equal(info.depth, 15);
    assert_near(info.size, 2 * RES, OPX_GEOM_TOL);
    assert_near(info.center[0], 2 * C0, OPX_GEOM_TOL); /* the cube [0, 0.5)^3 */
    assert_near(info.center[1], 2 * C0, OPX_GEOM_TOL);
    assert_near(info.center[2], 2 * C0, OPX_GEOM_TOL);
    assert_int_equal(stats_of(tree).leaves_occupied, 1);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(one_hit_gives_prob_hit),
        cmocka_unit_test(cells_on_a_ray_get_prob_miss),
        cmocka_unit_test(endpoints_mode_touches_no_free_cell),
        cmocka_unit_test(frames_accumulate_log_odds),
        cmocka_unit_test(one_update_per_cell_per_frame),
        cmocka_unit_test(clamping_at_clamp_max_and_min),
        cmocka_unit_test(clamping_with_custom_bounds),
        cmocka_unit_test(thresholds_choose_the_class),
        cmocka_unit_test(occupied_threshold_is_inclusive),
        cmocka_unit_test(max_range_cuts_rays),
        cmocka_unit_test(equal_siblings_are_pruned),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
