/*
 * Helpers of the active-joint tests: a generated robot with a joint of
 * every type (fixed, floating, planar, a mimic of a mimic), every link pose
 * at once, and the model-order vector that holds given active values.
 */
#ifndef OPX_JOINTS_TEST_H
#define OPX_JOINTS_TEST_H

#include "opx_query_test.h"

/*
 * Joints in file order (links root a b c d e f g):
 *   0 bolt    fixed       root->a
 *   1 drift   floating    a->b
 *   2 lift    prismatic   root->c  axis z
 *   3 glide   planar      c->d
 *   4 follow  prismatic   c->e     axis x, mimics lift x 0.5 + 0.01
 *   5 spin    continuous  e->f     axis z
 *   6 echo    revolute    f->g     axis y, mimics follow x 2 + 0.1
 * Active: lift (2) and spin (5).
 */
static const char MIXED_URDF[] =
    "<?xml version=\"1.0\"?>\n<robot name=\"mixed\">\n"
    " <link name=\"root\"><collision><geometry><box size=\"0.3 0.3 0.1\"/></geometry></collision></link>\n"
    " <link name=\"a\"><collision><geometry><sphere radius=\"0.05\"/></geometry></collision></link>\n"
    " <link name=\"b\"><collision><geometry><sphere radius=\"0.04\"/></geometry></collision></link>\n"
    " <link name=\"c\"><collision><geometry><sphere radius=\"0.06\"/></geometry></collision></link>\n"
    " <link name=\"d\"/>\n"
    " <link name=\"e\"><collision><origin xyz=\"0.1 0 0\"/><geometry><box size=\"0.2 0.05 0.05\"/>"
    "</geometry></collision></link>\n"
    " <link name=\"f\"><collision><origin xyz=\"0.15 0 0\"/><geometry><cylinder radius=\"0.03\" "
    "length=\"0.3\"/></geometry></collision></link>\n"
    " <link name=\"g\"><collision><origin xyz=\"0 0 0.1\"/><geometry><sphere radius=\"0.03\"/>"
    "</geometry></collision></link>\n"
    " <joint name=\"bolt\" type=\"fixed\"><parent link=\"root\"/><child link=\"a\"/>"
    "<origin xyz=\"0 0 0.1\"/></joint>\n"
    " <joint name=\"drift\" type=\"floating\"><parent link=\"a\"/><child link=\"b\"/>"
    "<origin xyz=\"0.1 0 0\"/></joint>\n"
    " <joint name=\"lift\" type=\"prismatic\"><parent link=\"root\"/><child link=\"c\"/>"
    "<origin xyz=\"0 0 0.2\"/><axis xyz=\"0 0 1\"/>"
    "<limit lower=\"0\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n"
    " <joint name=\"glide\" type=\"planar\"><parent link=\"c\"/><child link=\"d\"/>"
    "<origin xyz=\"0 0.1 0\"/><axis xyz=\"0 0 1\"/></joint>\n"
    " <joint name=\"follow\" type=\"prismatic\"><parent link=\"c\"/><child link=\"e\"/>"
    "<origin xyz=\"0.05 0 0\"/><axis xyz=\"1 0 0\"/>"
    "<limit lower=\"0\" upper=\"1\" effort=\"1\" velocity=\"1\"/>"
    "<mimic joint=\"lift\" multiplier=\"0.5\" offset=\"0.01\"/></joint>\n"
    " <joint name=\"spin\" type=\"continuous\"><parent link=\"e\"/><child link=\"f\"/>"
    "<origin xyz=\"0.2 0 0\" rpy=\"0.3 0 0\"/><axis xyz=\"0 0 1\"/></joint>\n"
    " <joint name=\"echo\" type=\"revolute\"><parent link=\"f\"/><child link=\"g\"/>"
    "<origin xyz=\"0.3 0 0\"/><axis xyz=\"0 1 0\"/>"
    "<limit lower=\"-3\" upper=\"3\" effort=\"1\" velocity=\"1\"/>"
    "<mimic joint=\"follow\" multiplier=\"2\" offset=\"0.1\"/></joint>\n"
    "</robot>\n";

enum { MIXED_JOINTS = 7, MIXED_LINKS = 8, MIXED_ACTIVE = 2 };
static const uint32_t MIXED_ACTIVE_JOINTS[MIXED_ACTIVE] = {2, 5};

static inline opx_linkset *load_urdf_text(const char *xml) {
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string(xml, NULL, &robot));
    assert_non_null(robot);
    return robot;
}

static inline uint32_t active_joint_count(const opx_linkset *robot) {
    uint32_t count = 0;
    assert_ok(opx_linkset_get_active_joint_count(robot, &count));
    return count;
}

/* The active joints' model indices (malloc'd; *count gets their number). */
static inline uint32_t *active_joints_of(const opx_linkset *robot, size_t *count) {
    const size_t n = active_joint_count(robot);
    uint32_t *indices = malloc((n + 1) * sizeof *indices);
    assert_non_null(indices);
    assert_ok(opx_linkset_get_active_joints(robot, indices, n, count));
    assert_int_equal(*count, n);
    return indices;
}

/* Every link pose (malloc'd; *count gets the link count). */
static inline opx_pose *poses_of(const opx_linkset *robot, size_t *count) {
    const size_t n = link_count(robot);
    opx_pose *poses = malloc((n + 1) * sizeof *poses);
    assert_non_null(poses);
    assert_ok(opx_linkset_get_poses(robot, poses, n, count));
    assert_int_equal(*count, n);
    return poses;
}

/* A model-order vector of `joint_count` values: `active` at the active
 * joints' indices, `filler` (ignored by FK) everywhere else. */
static inline void model_vector(const uint32_t *indices, size_t active_count, const double *active,
                                size_t joint_count, double filler, double *out) {
    for (size_t j = 0; j < joint_count; ++j) out[j] = filler;
    for (size_t i = 0; i < active_count; ++i) out[indices[i]] = active[i];
}

/* Both link sets' poses are equal bit for bit. */
static inline void assert_same_poses(const opx_linkset *a, const opx_linkset *b) {
    size_t na = 0, nb = 0;
    opx_pose *pa = poses_of(a, &na), *pb = poses_of(b, &nb);
    assert_int_equal(na, nb);
    assert_memory_equal(pa, pb, na * sizeof *pa);
    free(pa);
    free(pb);
}

#endif /* OPX_JOINTS_TEST_H */
