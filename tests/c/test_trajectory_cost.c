/*
 * opx_query_trajectory_cost: the cost is the sum of CHOMP's penalty over
 * waypoints and spheres, as opx_query_distance_spheres measures the placed
 * spheres; its gradient matches central differences of the cost (relative
 * error below 1e-6 where smooth), in both joint orders, through revolute,
 * prismatic and mimic joints; a robot not all spheres and bad input are
 * errors naming the argument.
 */
#include "opx_test.h"

#include <stdlib.h>
#include <string.h>

/* base -> j1 (revolute z) -> j2 (revolute y) -> j3 (prismatic x), and j4
 * mimicking j2 (x 0.5 + 0.1) on a side branch; a fixed tool. Joints in
 * model order: j1 j2 j3 j4 tool; active: j1 j2 j3. */
static const char *kArm =
    "<robot name='arm'>"
    "<link name='base'><collision><geometry><sphere radius='0.05'/></geometry></collision></link>"
    "<link name='l1'><collision><origin xyz='0 0 0.15'/><geometry><sphere radius='0.06'/></geometry></collision></link>"
    "<link name='l2'><collision><origin xyz='0.2 0 0'/><geometry><sphere radius='0.05'/></geometry></collision>"
    "<collision><origin xyz='0.35 0 0.02'/><geometry><sphere radius='0.04'/></geometry></collision></link>"
    "<link name='l3'><collision><origin xyz='0.1 0.02 0'/><geometry><sphere radius='0.045'/></geometry></collision></link>"
    "<link name='side'><collision><origin xyz='0 0.15 0.05'/><geometry><sphere radius='0.05'/></geometry></collision></link>"
    "<link name='tool'><collision><origin xyz='0.05 0 0'/><geometry><sphere radius='0.03'/></geometry></collision></link>"
    "<joint name='j1' type='revolute'><parent link='base'/><child link='l1'/><origin xyz='0 0 0.1'/>"
    "<axis xyz='0 0 1'/><limit lower='-3' upper='3' effort='1' velocity='1'/></joint>"
    "<joint name='j2' type='revolute'><parent link='l1'/><child link='l2'/><origin xyz='0 0 0.3' rpy='0.1 0 0'/>"
    "<axis xyz='0 1 0'/><limit lower='-3' upper='3' effort='1' velocity='1'/></joint>"
    "<joint name='j3' type='prismatic'><parent link='l2'/><child link='l3'/><origin xyz='0.4 0 0'/>"
    "<axis xyz='1 0 0'/><limit lower='0' upper='0.3' effort='1' velocity='1'/></joint>"
    "<joint name='j4' type='revolute'><parent link='l1'/><child link='side'/><origin xyz='0 0 0.2'/>"
    "<axis xyz='1 0 0'/><mimic joint='j2' multiplier='0.5' offset='0.1'/>"
    "<limit lower='-3' upper='3' effort='1' velocity='1'/></joint>"
    "<joint name='tool' type='fixed'><parent link='l3'/><child link='tool'/><origin xyz='0.1 0 0'/></joint>"
    "</robot>";

/* The point p (link frame) in the map frame. */
static void pose_apply(const opx_pose *pose, const double p[3], double out[3]) {
    const double x = pose->orientation[0], y = pose->orientation[1], z = pose->orientation[2], w = pose->orientation[3];
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    int a;
    for (a = 0; a < 3; ++a) out[a] = r[a][0] * p[0] + r[a][1] * p[1] + r[a][2] * p[2] + pose->position[a];
}

static double draw(unsigned *state, double lo, double hi) {
    *state = *state * 1103515245u + 12345u;
    return lo + (hi - lo) * (double)((*state >> 8) & 0xFFFFFF) / (double)0x1000000;
}

static opx_linkset *load(const char *xml) {
    opx_linkset *links = NULL;
    assert_ok(opx_linkset_load_urdf_string(xml, NULL, &links));
    return links;
}

/* Scattered cells through the arm's reach, at 4 cm. */
static opx_octree *scene(void) {
    opx_octree *tree = new_tree(0.04);
    double xyz[3 * 1500];
    unsigned seed = 5;
    size_t i;
    for (i = 0; i < 1500; ++i) {
        xyz[3 * i] = draw(&seed, -0.9, 0.9);
        xyz[3 * i + 1] = draw(&seed, -0.9, 0.9);
        xyz[3 * i + 2] = draw(&seed, -0.3, 1.0);
    }
    {
        const opx_insert_options options = sensor_at(0.0, 0.0, 0.0, OPX_INSERT_ENDPOINTS);
        insert_f64(tree, xyz, 1500, &options);
    }
    return tree;
}

static double cost_of(opx_query *query, const opx_octree *tree, const opx_linkset *links, const double *q,
                      size_t joints, const opx_trajectory_cost_request *request, double *gradient) {
    double cost = -1.0;
    assert_ok(opx_query_trajectory_cost(query, tree, links, q, 1, joints, 0, NULL, request, &cost, gradient, 1));
    return cost;
}

/* Central differences at two steps; a point where they disagree is not smooth. */
static void gradients_match_central_differences(void **state) {
    opx_linkset *arm = load(kArm);
    opx_octree *tree = scene();
    opx_query *query = NULL;
    unsigned seed = 9;
    size_t compared = 0, active_cost = 0, trial, order;
    (void)state;
    assert_ok(opx_query_create(NULL, &query));
    for (order = 0; order < 2; ++order) {
        opx_trajectory_cost_request request = OPX_TRAJECTORY_COST_REQUEST_INIT;
        const size_t joints = order == 0 ? 3 : 5;
        request.joint_order = order == 0 ? OPX_JOINTS_ACTIVE : OPX_JOINTS_MODEL;
        request.activation = 0.1;
        for (trial = 0; trial < 60; ++trial) {
            double q[5] = {draw(&seed, -1.5, 1.5), draw(&seed, -1.2, 1.2), draw(&seed, 0.0, 0.3), 0.0, 0.0};
            double gradient[5], ignored[5];
            size_t i;
            if (order == 1) q[3] = draw(&seed, -1, 1); /* a mimic joint's own value: never read */
            const double cost = cost_of(query, tree, arm, q, joints, &request, gradient);
            if (cost <= 0.0) continue;
            ++active_cost;
            for (i = 0; i < joints; ++i) {
                double fd[2];
                int k;
                for (k = 0; k < 2; ++k) {
                    const double h = k == 0 ? 1e-6 : 5e-7;
                    double plus[5], minus[5];
                    memcpy(plus, q, sizeof q), memcpy(minus, q, sizeof q);
                    plus[i] += h, minus[i] -= h;
                    fd[k] = (cost_of(query, tree, arm, plus, joints, &request, ignored) -
                             cost_of(query, tree, arm, minus, joints, &request, ignored)) / (2 * h);
                }
                if (fabs(fd[0] - fd[1]) > 1e-7 * fmax(1.0, fabs(fd[0]))) continue; /* a kink nearby */
                if (fabs(fd[0] - gradient[i]) > 1e-6 * fmax(fabs(gradient[i]), 1e-3))
                    fail_msg("order %zu trial %zu joint %zu: gradient %.12g, central difference %.12g", order, trial,
                             i, gradient[i], fd[0]);
                ++compared;
            }
            if (order == 1) { /* the mimic and the fixed joint's entries */
                assert_true(gradient[3] == 0.0 && gradient[4] == 0.0);
            }
        }
    }
    assert_true(active_cost > 30 && compared > 100);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

/* The cost is CHOMP's penalty of the distances opx_query_distance_spheres
 * gives the placed spheres, summed over two waypoints. */
static void the_cost_is_the_penalty_of_the_sphere_distances(void **state) {
    opx_linkset *arm = load(kArm);
    opx_octree *tree = scene();
    opx_query *query = NULL;
    opx_trajectory_cost_request request = OPX_TRAJECTORY_COST_REQUEST_INIT;
    opx_sphere_distance_request spheres_request = OPX_SPHERE_DISTANCE_REQUEST_INIT;
    const double q[2][3] = {{0.3, 0.9, 0.1}, {-0.4, 1.1, 0.25}};
    const double eps = 0.08;
    double cost = 0.0, expected = 0.0, gradient[6];
    size_t w;
    (void)state;
    request.activation = eps;
    spheres_request.max_distance = eps;
    assert_ok(opx_query_create(NULL, &query));
    assert_ok(opx_query_trajectory_cost(query, tree, arm, &q[0][0], 2, 3, 0, NULL, &request, &cost, gradient, 2));
    for (w = 0; w < 2; ++w) {
        double rows[7][4], d[7];
        size_t shape_count = 0, link;
        uint32_t links = 0;
        assert_ok(opx_linkset_set_active_joint_positions(arm, q[w], 3, NULL));
        assert_ok(opx_linkset_get_link_count(arm, &links));
        for (link = 0; link < links; ++link) {
            uint32_t shapes = 0, s;
            opx_pose pose;
            assert_ok(opx_linkset_get_pose(arm, (uint32_t)link, &pose));
            assert_ok(opx_linkset_get_shape_count(arm, (uint32_t)link, &shapes));
            for (s = 0; s < shapes; ++s) {
                opx_shape shape = OPX_SHAPE_INIT;
                double world[3];
                assert_ok(opx_linkset_get_shape(arm, (uint32_t)link, s, &shape));
                pose_apply(&pose, shape.pose.position, world);
                memcpy(rows[shape_count], world, sizeof world);
                rows[shape_count++][3] = shape.radius;
            }
        }
        assert_int_equal(shape_count, 7);
        assert_ok(opx_query_distance_spheres(query, tree, &rows[0][0], 7, 0, &spheres_request, d, NULL, NULL, 7));
        for (size_t i = 0; i < 7; ++i) {
            if (d[i] < 0.0) expected += -d[i] + 0.5 * eps;
            else if (d[i] < eps) expected += 0.5 * (d[i] - eps) * (d[i] - eps) / eps;
        }
    }
    assert_true(expected > 0.0);
    assert_near(cost, expected, 1e-12 * fmax(1.0, expected));
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

static void bad_input_names_the_argument(void **state) {
    const char *fn = "opx_query_trajectory_cost";
    opx_linkset *arm = load(kArm);
    opx_octree *tree = scene();
    opx_query *query = NULL;
    opx_linkset *boxes = NULL;
    opx_trajectory_cost_request bad = OPX_TRAJECTORY_COST_REQUEST_INIT;
    double q[3] = {0.1, 0.2, 0.1}, cost = 0.0, gradient[6];
    (void)state;
    assert_ok(opx_query_create(NULL, &query));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "query",
                   opx_query_trajectory_cost(NULL, tree, arm, q, 1, 3, 0, NULL, NULL, &cost, gradient, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "tree",
                   opx_query_trajectory_cost(query, NULL, arm, q, 1, 3, 0, NULL, NULL, &cost, gradient, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "links",
                   opx_query_trajectory_cost(query, tree, NULL, q, 1, 3, 0, NULL, NULL, &cost, gradient, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "out_cost",
                   opx_query_trajectory_cost(query, tree, arm, q, 1, 3, 0, NULL, NULL, NULL, gradient, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "waypoint_count",
                   opx_query_trajectory_cost(query, tree, arm, q, 0, 3, 0, NULL, NULL, &cost, gradient, 1));
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, fn, "capacity",
                   opx_query_trajectory_cost(query, tree, arm, q, 2, 3, 0, NULL, NULL, &cost, gradient, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "joint_count",
                   opx_query_trajectory_cost(query, tree, arm, q, 1, 4, 0, NULL, NULL, &cost, gradient, 1));
    q[1] = NAN;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "positions",
                   opx_query_trajectory_cost(query, tree, arm, q, 1, 3, 0, NULL, NULL, &cost, gradient, 1));
    q[1] = 0.2;
    bad.activation = 0.0;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "activation",
                   opx_query_trajectory_cost(query, tree, arm, q, 1, 3, 0, NULL, &bad, &cost, gradient, 1));
    bad.activation = INFINITY;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "activation",
                   opx_query_trajectory_cost(query, tree, arm, q, 1, 3, 0, NULL, &bad, &cost, gradient, 1));
    assert_ok(opx_linkset_load_urdf_string(
        "<robot name='b'><link name='a'><collision><geometry><box size='0.1 0.1 0.1'/></geometry></collision></link>"
        "<link name='c'/><joint name='j' type='revolute'><parent link='a'/><child link='c'/><axis xyz='0 0 1'/>"
        "<limit lower='-1' upper='1' effort='1' velocity='1'/></joint></robot>",
        NULL, &boxes));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "sphere",
                   opx_query_trajectory_cost(query, tree, boxes, q, 1, 1, 0, NULL, NULL, &cost, gradient, 1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_trajectory_cost_request_init", "request",
                   opx_trajectory_cost_request_init(NULL, 8));
    opx_linkset_destroy(boxes);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    opx_linkset_destroy(arm);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gradients_match_central_differences),
        cmocka_unit_test(the_cost_is_the_penalty_of_the_sphere_distances),
        cmocka_unit_test(bad_input_names_the_argument),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
