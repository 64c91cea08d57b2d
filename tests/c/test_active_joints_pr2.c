/*
 * The active joints of the PR2 of the shared data ($OPX_DATA_DIR, else
 * ../shared/data; skipped with 77 when absent): the moving joints that
 * mimic none; FK from random active vectors equals FK from the model-order
 * vectors holding them, bit for bit, by order and by name; a batch of
 * active rows answers as the same rows in model order.
 */
#define _POSIX_C_SOURCE 200809L /* stat */

#include "opx_batch_test.h"
#include "opx_data_test.h"
#include "opx_joints_test.h"

#define PR2_ROWS 24

static char g_urdf[4096], g_srdf[4096], g_package[4096];

static opx_linkset *load_pr2(void) {
    const char *dirs[1] = {g_package};
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.package_dirs = dirs;
    options.package_dir_count = 1;
    options.srdf_path = g_srdf;
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_file(g_urdf, &options, &robot));
    return robot;
}

static uint32_t joint_count_of(const opx_linkset *robot) {
    uint32_t count = 0;
    assert_ok(opx_linkset_get_joint_count(robot, &count));
    return count;
}

/* Random values of the active joints within their limits (continuous
 * joints and joints without limits: +-pi). */
static void random_active(const opx_linkset *robot, const uint32_t *indices, size_t n, uint64_t *seed, double *out) {
    for (size_t i = 0; i < n; ++i) {
        opx_joint_info info = OPX_JOINT_INFO_INIT;
        assert_ok(opx_linkset_get_joint_info(robot, indices[i], &info));
        const int bounded = info.has_limits && isfinite(info.lower) && isfinite(info.upper);
        out[i] = bounded ? next_uniform(seed, info.lower, info.upper) : next_uniform(seed, -3.14, 3.14);
    }
}

static void the_active_joints_are_the_moving_joints_that_mimic_none(void **state) {
    (void)state;
    opx_linkset *robot = load_pr2();
    const uint32_t joints = joint_count_of(robot);
    size_t n = 0, moving = 0;
    uint32_t *indices = active_joints_of(robot, &n);
    for (uint32_t j = 0, next = 0; j < joints; ++j) {
        opx_joint_info info = OPX_JOINT_INFO_INIT;
        assert_ok(opx_linkset_get_joint_info(robot, j, &info));
        const int moves = info.type == OPX_JOINT_REVOLUTE || info.type == OPX_JOINT_CONTINUOUS ||
                          info.type == OPX_JOINT_PRISMATIC;
        const int active = next < n && indices[next] == j;
        assert_int_equal(active, moves && info.mimic_joint == OPX_JOINT_NONE);
        next += active;
        moving += moves;
    }
    assert_true(n > 30 && n < moving && moving < joints); /* fixed and mimic joints left out */
    printf("PR2: %u joints, %zu moving, %zu active\n", joints, moving, n);
    free(indices);
    opx_linkset_destroy(robot);
}

static void active_fk_equals_model_fk_by_order_and_by_name(void **state) {
    (void)state;
    opx_linkset *by_active = load_pr2(), *by_model = load_pr2(), *by_name = load_pr2();
    const uint32_t joints = joint_count_of(by_model);
    size_t n = 0;
    uint32_t *indices = active_joints_of(by_model, &n);
    double *active = malloc(n * sizeof *active), *model = malloc(joints * sizeof *model);
    const char **names = malloc(n * sizeof *names);
    assert_true(active != NULL && model != NULL && names != NULL);
    for (size_t i = 0; i < n; ++i) {
        opx_joint_info info = OPX_JOINT_INFO_INIT;
        assert_ok(opx_linkset_get_joint_info(by_model, indices[i], &info));
        names[i] = info.name;
    }
    const opx_pose base = {{0.5, -1.0, 0.0}, {0.0, 0.0, 0.25881904510252074, 0.96592582628906831}};
    uint64_t seed = 31;
    for (int trial = 0; trial < 10; ++trial) {
        random_active(by_model, indices, n, &seed, active);
        model_vector(indices, n, active, joints, -0.5, model);
        assert_ok(opx_linkset_set_active_joint_positions(by_active, active, n, &base));
        assert_ok(opx_linkset_set_joint_positions(by_model, model, joints, &base));
        assert_ok(opx_linkset_set_named_joint_positions(by_name, names, active, n, &base));
        assert_same_poses(by_active, by_model);
        assert_same_poses(by_name, by_model);
    }
    free(names);
    free(model);
    free(active);
    free(indices);
    opx_linkset_destroy(by_active);
    opx_linkset_destroy(by_model);
    opx_linkset_destroy(by_name);
}

static void active_rows_answer_as_model_rows(void **state) {
    (void)state;
    opx_linkset *robot = load_pr2();
    const uint32_t joints = joint_count_of(robot);
    size_t n = 0;
    uint32_t *indices = active_joints_of(robot, &n);
    double *active = malloc(PR2_ROWS * n * sizeof *active), *model = malloc(PR2_ROWS * joints * sizeof *model);
    assert_true(active != NULL && model != NULL);
    uint64_t seed = 77;
    for (size_t r = 0; r < PR2_ROWS; ++r) {
        random_active(robot, indices, n, &seed, active + r * n);
        model_vector(indices, n, active + r * n, joints, 0.25, model + r * joints);
    }
    opx_octree *tree = new_scatter_map(13);
    opx_query *query = new_query();
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.compute_distance = 1;
    request.self_collision = 1;
    uint8_t hit_model[PR2_ROWS], hit_active[PR2_ROWS];
    double d_model[PR2_ROWS], d_active[PR2_ROWS];
    assert_ok(opx_query_check_configurations(query, tree, robot, model, PR2_ROWS, joints, 0, NULL, 0, 0, &request,
                                             hit_model, d_model, PR2_ROWS));
    assert_ok(opx_query_check_configurations(query, tree, robot, active, PR2_ROWS, n, 0, NULL, 0, 0, &request,
                                             hit_active, d_active, PR2_ROWS));
    assert_memory_equal(hit_model, hit_active, sizeof hit_model);
    assert_memory_equal(d_model, d_active, sizeof d_model);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    free(model);
    free(active);
    free(indices);
    opx_linkset_destroy(robot);
}

int main(void) {
    require_data_file("robots/pr2_description/urdf/robot.xml", g_urdf, sizeof g_urdf);
    require_data_file("robots/pr2_description/srdf/pr2.srdf", g_srdf, sizeof g_srdf);
    snprintf(g_package, sizeof g_package, "moveit_resources_pr2_description=%s/robots/pr2_description",
             data_dir());
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_active_joints_are_the_moving_joints_that_mimic_none),
        cmocka_unit_test(active_fk_equals_model_fk_by_order_and_by_name),
        cmocka_unit_test(active_rows_answer_as_model_rows),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
