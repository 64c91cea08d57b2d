/*
 * Helpers of the batch query tests: a generated 7-joint arm with a
 * two-finger gripper (the right finger mimics the left one), a map of
 * scattered occupied cells around it, seeded random configurations, and
 * the single calls the batch answers must equal (FK on the link set, then
 * opx_query_collide / opx_query_distance).
 */
#ifndef OPX_BATCH_TEST_H
#define OPX_BATCH_TEST_H

#include "opx_query_test.h"

#define ARM_REVOLUTE 7
/* Joints in model order: j1..j7 (revolute), finger_l (prismatic),
 * finger_r (prismatic, mimics finger_l x -1), tool (fixed). */
#define ARM_JOINTS 10
#define ARM_LINKS 11
#define ARM_PI 3.141592653589793

/* Link k (1..7) of the arm: a cylinder along its z from 0 to 0.24 (with
 * `spheres`: three spheres along it instead) and a sphere at its far end,
 * each joint 0.24 above the previous one. */
static inline void append_arm_link(char *xml, size_t size, int k, int spheres) {
    const size_t used = strlen(xml);
    const char *body = spheres ? "<collision><origin xyz=\"0 0 0.04\"/><geometry><sphere radius=\"0.035\"/>"
                                 "</geometry></collision><collision><origin xyz=\"0 0 0.11\"/><geometry>"
                                 "<sphere radius=\"0.035\"/></geometry></collision><collision><origin "
                                 "xyz=\"0 0 0.18\"/><geometry><sphere radius=\"0.035\"/></geometry></collision>"
                               : "<collision><origin xyz=\"0 0 0.12\"/><geometry>"
                                 "<cylinder radius=\"0.035\" length=\"0.2\"/></geometry></collision>";
    snprintf(xml + used, size - used,
             " <link name=\"l%d\">%s"
             "<collision><origin xyz=\"0 0 0.24\"/><geometry><sphere radius=\"0.045\"/>"
             "</geometry></collision></link>\n"
             " <joint name=\"j%d\" type=\"revolute\"><parent link=\"l%d\"/><child link=\"l%d\"/>"
             "<origin xyz=\"0 0 %s\"/><axis xyz=\"0 %d %d\"/>"
             "<limit lower=\"-3.14\" upper=\"3.14\" effort=\"1\" velocity=\"1\"/></joint>\n",
             k, body, k, k - 1, k, k == 1 ? "0.1" : "0.24", k % 2 == 0, k % 2 == 1);
}

/* The arm's URDF, written into `xml` (16 KiB is plenty); with `spheres`,
 * the same kinematics built of spheres alone (the model of sphere-based
 * planners). */
static inline void arm_urdf_of(char *xml, size_t size, int spheres) {
    snprintf(xml, size,
             "<?xml version=\"1.0\"?>\n<robot name=\"arm\">\n"
             " <link name=\"l0\"><collision><origin xyz=\"0 0 0.05\"/><geometry>%s"
             "</geometry></collision></link>\n",
             spheres ? "<sphere radius=\"0.09\"/>" : "<box size=\"0.2 0.2 0.1\"/>");
    for (int k = 1; k <= ARM_REVOLUTE; ++k) append_arm_link(xml, size, k, spheres);
    const char *finger = spheres ? "<sphere radius=\"0.012\"/>" : "<box size=\"0.02 0.02 0.06\"/>";
    const size_t used = strlen(xml);
    snprintf(xml + used, size - used,
             " <link name=\"finger_l\"><collision><origin xyz=\"0 0 0.03\"/><geometry>%s"
             "</geometry></collision></link>\n"
             " <link name=\"finger_r\"><collision><origin xyz=\"0 0 0.03\"/><geometry>%s"
             "</geometry></collision></link>\n"
             " <link name=\"tool\"><collision><geometry><sphere radius=\"0.01\"/></geometry>"
             "</collision></link>\n"
             " <joint name=\"finger_l\" type=\"prismatic\"><parent link=\"l7\"/>"
             "<child link=\"finger_l\"/><origin xyz=\"0 0 0.27\"/><axis xyz=\"0 1 0\"/>"
             "<limit lower=\"0\" upper=\"0.04\" effort=\"1\" velocity=\"1\"/></joint>\n"
             " <joint name=\"finger_r\" type=\"prismatic\"><parent link=\"l7\"/>"
             "<child link=\"finger_r\"/><origin xyz=\"0 0 0.27\"/><axis xyz=\"0 1 0\"/>"
             "<limit lower=\"-0.04\" upper=\"0\" effort=\"1\" velocity=\"1\"/>"
             "<mimic joint=\"finger_l\" multiplier=\"-1\"/></joint>\n"
             " <joint name=\"tool\" type=\"fixed\"><parent link=\"l7\"/><child link=\"tool\"/>"
             "<origin xyz=\"0 0 0.33\"/></joint>\n"
             "</robot>\n",
             finger, finger);
}

static inline void arm_urdf(char *xml, size_t size) { arm_urdf_of(xml, size, 0); }

static inline opx_linkset *load_arm_of(int spheres) {
    static char xml[16384];
    arm_urdf_of(xml, sizeof xml, spheres);
    opx_linkset *arm = NULL;
    assert_ok(opx_linkset_load_urdf_string(xml, NULL, &arm));
    uint32_t joints = 0;
    assert_ok(opx_linkset_get_joint_count(arm, &joints));
    assert_int_equal(joints, ARM_JOINTS);
    assert_int_equal(link_count(arm), ARM_LINKS);
    return arm;
}

static inline opx_linkset *load_arm(void) { return load_arm_of(0); }

/* Disables the pairs that touch at every configuration, as an SRDF
 * does: each link and the next, the hand's links among themselves. */
static inline void disable_adjacent_arm_pairs(opx_linkset *arm) {
    for (uint32_t k = 1; k <= ARM_REVOLUTE; ++k) assert_ok(opx_linkset_set_pair_enabled(arm, k - 1, k, 0));
    const uint32_t hand[4] = {7, 8, 9, 10}; /* l7, finger_l, finger_r, tool */
    for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) assert_ok(opx_linkset_set_pair_enabled(arm, hand[a], hand[b], 0));
}

/* ---- Seeded random numbers (the test's own, portable) ----------------- */

static inline double next_uniform(uint64_t *state, double lo, double hi) {
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double unit = (double)(*state >> 11) * (1.0 / 9007199254740992.0);
    return lo + (hi - lo) * unit;
}

/* `count` configurations of the arm, row-major (count x ARM_JOINTS):
 * revolute joints within +-3.1 rad, the finger within its limits, the
 * mimic and fixed joints' values garbage (FK ignores them). */
static inline double *random_arm_rows(size_t count, uint64_t seed) {
    double *rows = malloc(count * ARM_JOINTS * sizeof *rows);
    assert_non_null(rows);
    for (size_t i = 0; i < count; ++i) {
        double *q = rows + i * ARM_JOINTS;
        for (int j = 0; j < ARM_REVOLUTE; ++j) q[j] = next_uniform(&seed, -3.1, 3.1);
        q[7] = next_uniform(&seed, 0.0, 0.04);
        q[8] = 123.0, q[9] = -7.0;
    }
    return rows;
}

/* Occupied cells (0.05 m) scattered in the arm's reach, and the free
 * cells of two rays from above; the rest unknown. */
static inline opx_octree *new_scatter_map(uint64_t seed) {
    opx_octree *tree = new_tree(0.05);
    enum { POINTS = 90 };
    double xyz[3 * POINTS];
    for (int i = 0; i < POINTS; ++i) {
        xyz[3 * i + 0] = next_uniform(&seed, -1.1, 1.1);
        xyz[3 * i + 1] = next_uniform(&seed, -1.1, 1.1);
        xyz[3 * i + 2] = next_uniform(&seed, 0.15, 1.9);
    }
    const opx_insert_options endpoints = sensor_at(0.0, 0.0, 0.0, OPX_INSERT_ENDPOINTS);
    insert_f64(tree, xyz, POINTS, &endpoints);
    const double far[6] = {2.0, 0.3, -1.0, -2.0, -0.2, -0.8};
    const opx_insert_options rays = sensor_at(0.0, 0.0, 2.5, OPX_INSERT_RAYCAST);
    insert_f64(tree, far, 2, &rays);
    return tree;
}

static inline opx_query *new_query_with(int32_t engine) {
    opx_query_options options = OPX_QUERY_OPTIONS_INIT;
    options.engine = engine;
    opx_query *query = NULL;
    assert_ok(opx_query_create(&options, &query));
    return query;
}

/* ---- The single calls a batch must agree with -------------------------- */

/* Moves `robot` to q (base NULL: origin) and asks opx_query_collide. */
static inline int single_collides(opx_query *query, const opx_octree *tree, opx_linkset *robot,
                                  const double *q, const opx_pose *base) {
    assert_ok(opx_linkset_set_joint_positions(robot, q, ARM_JOINTS, base));
    return collide_with(query, tree, robot, 0).collided;
}

/* The same with self-collision: the map, then the arm itself. */
static inline int single_collides_or_self(opx_query *query, const opx_octree *tree, opx_linkset *robot,
                                          const double *q, const opx_pose *base) {
    if (single_collides(query, tree, robot, q, base)) return 1;
    opx_self_collision_request request = OPX_SELF_COLLISION_REQUEST_INIT;
    request.max_contacts = 0;
    opx_self_collision_result result = OPX_SELF_COLLISION_RESULT_INIT;
    assert_ok(opx_query_self_collide(query, robot, &request, &result));
    return result.collided;
}

static inline double single_self_distance(opx_query *query, const opx_linkset *robot, double cutoff) {
    opx_self_distance_request request = OPX_SELF_DISTANCE_REQUEST_INIT;
    request.cutoff = cutoff;
    opx_self_distance_result result = OPX_SELF_DISTANCE_RESULT_INIT;
    assert_ok(opx_query_self_distance(query, robot, &request, &result));
    return result.distance;
}

static inline double single_distance(opx_query *query, const opx_octree *tree, opx_linkset *robot,
                                     const double *q, const opx_pose *base, double cutoff) {
    assert_ok(opx_linkset_set_joint_positions(robot, q, ARM_JOINTS, base));
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.cutoff = cutoff;
    return distance_with(query, tree, robot, &request).distance;
}

/* ---- Motions: their samples walked with single calls ------------------ */

/* The steps opx_query_check_motion promises: the largest joint move over the
 * resolution, the mimic finger moving as much as its master. */
static inline uint64_t motion_steps(const double *a, const double *b, double resolution) {
    double largest = 0.0;
    for (int j = 0; j < ARM_REVOLUTE + 1; ++j) largest = fmax(largest, fabs(b[j] - a[j]));
    const double steps = ceil(largest / resolution);
    return steps < 1.0 ? 1 : (uint64_t)steps;
}

static inline void motion_sample(const double *a, const double *b, uint64_t i, uint64_t n, double *q) {
    for (int j = 0; j < ARM_JOINTS; ++j) q[j] = i == n ? b[j] : a[j] + ((double)i / (double)n) * (b[j] - a[j]);
}

/* The first colliding sample by walking them all in order; -1: none. */
static inline int64_t first_colliding_sample(opx_query *query, const opx_octree *tree, opx_linkset *arm,
                                             const double *a, const double *b, uint64_t n, int self) {
    double q[ARM_JOINTS];
    for (uint64_t i = 0; i <= n; ++i) {
        motion_sample(a, b, i, n, q);
        if (self ? single_collides_or_self(query, tree, arm, q, NULL) : single_collides(query, tree, arm, q, NULL))
            return (int64_t)i;
    }
    return -1;
}

/* Every link's pose, to prove a batch did not move the caller's set. */
static inline void arm_poses(const opx_linkset *robot, opx_pose poses[ARM_LINKS]) {
    for (uint32_t l = 0; l < ARM_LINKS; ++l) poses[l] = get_pose(robot, l);
}

static inline void assert_arm_at(const opx_linkset *robot, const opx_pose poses[ARM_LINKS]) {
    opx_pose now[ARM_LINKS];
    arm_poses(robot, now);
    assert_memory_equal(now, poses, sizeof now);
}

#endif /* OPX_BATCH_TEST_H */
