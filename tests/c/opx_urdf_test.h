/*
 * Helpers of the URDF tests: a small hand-written robot with every joint
 * type and primitive shape, the test's own rotation maths (independent of
 * the library's), pose comparisons, and scratch files in a temporary folder.
 */
#ifndef OPX_URDF_TEST_H
#define OPX_URDF_TEST_H

#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include "opx_query_test.h"

#include <unistd.h>

#define HALF_PI 1.5707963267948966

/*
 * The test robot.  Links in file order: base(0) arm(1) slider(2) wheel(3)
 * finger(4) tool(5).  Joints in file order:
 *   0 shoulder  revolute   base->arm      xyz 0 0 0.2, axis z, limits [-1, 2] effort 10 velocity 1.5
 *   1 slide     prismatic  arm->slider    xyz 0.5 0 0, axis x, limits [0, 0.3] effort 100 velocity 0.2
 *   2 wheel     continuous base->wheel    xyz 0 0.2 0 rpy pi/2 0 0, axis z, velocity 3 effort 4
 *   3 finger    prismatic  slider->finger xyz 0 0 0.05, axis y, mimic slide * 2 + 0.01
 *   4 tool      fixed      finger->tool   xyz 0 0 0.1 rpy 0 0 pi/2
 * The joints are listed out of tree order on purpose (wheel after slide).
 */
static const char TEST_URDF[] =
    "<?xml version=\"1.0\"?>\n"
    "<robot name=\"test\">\n"
    " <link name=\"base\"><collision><origin xyz=\"0 0 0.1\" rpy=\"0 0 0\"/>"
    "<geometry><box size=\"0.4 0.3 0.2\"/></geometry></collision></link>\n"
    " <link name=\"arm\">"
    "<collision><origin xyz=\"0.25 0 0\" rpy=\"0 1.5707963267948966 0\"/>"
    "<geometry><cylinder radius=\"0.05\" length=\"0.5\"/></geometry></collision>"
    "<collision><origin xyz=\"0.5 0 0\"/><geometry><sphere radius=\"0.07\"/></geometry></collision>"
    "</link>\n"
    " <link name=\"slider\"/>\n"
    " <link name=\"wheel\"><collision><origin xyz=\"0 0 0.02\" rpy=\"0.3 0 0\"/>"
    "<geometry><cylinder radius=\"0.1\" length=\"0.04\"/></geometry></collision></link>\n"
    " <link name=\"finger\"/>\n"
    " <link name=\"tool\"><collision><geometry><sphere radius=\"0.03\"/></geometry></collision></link>\n"
    " <joint name=\"shoulder\" type=\"revolute\"><parent link=\"base\"/><child link=\"arm\"/>"
    "<origin xyz=\"0 0 0.2\" rpy=\"0 0 0\"/><axis xyz=\"0 0 1\"/>"
    "<limit lower=\"-1\" upper=\"2\" effort=\"10\" velocity=\"1.5\"/></joint>\n"
    " <joint name=\"slide\" type=\"prismatic\"><parent link=\"arm\"/><child link=\"slider\"/>"
    "<origin xyz=\"0.5 0 0\"/><axis xyz=\"1 0 0\"/>"
    "<limit lower=\"0\" upper=\"0.3\" effort=\"100\" velocity=\"0.2\"/></joint>\n"
    " <joint name=\"wheel\" type=\"continuous\"><parent link=\"base\"/><child link=\"wheel\"/>"
    "<origin xyz=\"0 0.2 0\" rpy=\"1.5707963267948966 0 0\"/><axis xyz=\"0 0 1\"/>"
    "<limit effort=\"4\" velocity=\"3\"/></joint>\n"
    " <joint name=\"finger\" type=\"prismatic\"><parent link=\"slider\"/><child link=\"finger\"/>"
    "<origin xyz=\"0 0 0.05\"/><axis xyz=\"0 1 0\"/>"
    "<limit lower=\"0\" upper=\"1\" effort=\"1\" velocity=\"1\"/>"
    "<mimic joint=\"slide\" multiplier=\"2\" offset=\"0.01\"/></joint>\n"
    " <joint name=\"tool\" type=\"fixed\"><parent link=\"finger\"/><child link=\"tool\"/>"
    "<origin xyz=\"0 0 0.1\" rpy=\"0 0 1.5707963267948966\"/></joint>\n"
    "</robot>\n";

enum { L_BASE, L_ARM, L_SLIDER, L_WHEEL, L_FINGER, L_TOOL, TEST_LINKS };
enum { J_SHOULDER, J_SLIDE, J_WHEEL, J_FINGER, J_TOOL, TEST_JOINTS };

static inline opx_linkset *load_test_robot(void) {
    opx_linkset *robot = NULL;
    assert_ok(opx_linkset_load_urdf_string(TEST_URDF, NULL, &robot));
    assert_non_null(robot);
    return robot;
}

/* ---- The test's own rotations (3x3 row-major) -------------------------- */

typedef struct mat3 {
    double m[3][3];
} mat3;

static inline mat3 mat_mul(mat3 a, mat3 b) {
    mat3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
    return r;
}

static inline mat3 rot_x(double t) {
    mat3 r = {{{1, 0, 0}, {0, cos(t), -sin(t)}, {0, sin(t), cos(t)}}};
    return r;
}
static inline mat3 rot_y(double t) {
    mat3 r = {{{cos(t), 0, sin(t)}, {0, 1, 0}, {-sin(t), 0, cos(t)}}};
    return r;
}
static inline mat3 rot_z(double t) {
    mat3 r = {{{cos(t), -sin(t), 0}, {sin(t), cos(t), 0}, {0, 0, 1}}};
    return r;
}

/* Rotation of a unit quaternion x y z w (ROS order). */
static inline mat3 mat_from_quat(const double q[4]) {
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    mat3 r = {{{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
               {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
               {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}}};
    return r;
}

/* A rigid transform of the test: p_parent = rot * p_child + pos. */
typedef struct frame {
    mat3 rot;
    double pos[3];
} frame;

static inline frame frame_of(double x, double y, double z, mat3 rot) {
    frame f;
    f.rot = rot;
    f.pos[0] = x, f.pos[1] = y, f.pos[2] = z;
    return f;
}

static inline frame frame_mul(frame a, frame b) {
    frame r;
    r.rot = mat_mul(a.rot, b.rot);
    for (int i = 0; i < 3; ++i)
        r.pos[i] = a.rot.m[i][0] * b.pos[0] + a.rot.m[i][1] * b.pos[1] + a.rot.m[i][2] * b.pos[2] + a.pos[i];
    return r;
}

static inline opx_pose pose_of_frame(frame f) {
    /* Shepperd's method is overkill: the test frames keep w well away from 0. */
    opx_pose p = OPX_POSE_IDENTITY;
    const double w = 0.5 * sqrt(1.0 + f.rot.m[0][0] + f.rot.m[1][1] + f.rot.m[2][2]);
    p.orientation[3] = w;
    p.orientation[0] = (f.rot.m[2][1] - f.rot.m[1][2]) / (4 * w);
    p.orientation[1] = (f.rot.m[0][2] - f.rot.m[2][0]) / (4 * w);
    p.orientation[2] = (f.rot.m[1][0] - f.rot.m[0][1]) / (4 * w);
    for (int i = 0; i < 3; ++i) p.position[i] = f.pos[i];
    return p;
}

/* The link's pose equals `expected` (position and rotation) within tol. */
#define assert_link_at(links, link, expected, tol) \
    opx_assert_link_at((links), (link), (expected), (tol), __FILE__, __LINE__)

static inline void opx_assert_link_at(const opx_linkset *links, uint32_t link, frame expected,
                                      double tol, const char *file, int line) {
    opx_pose pose;
    assert_ok(opx_linkset_get_pose(links, link, &pose));
    const mat3 r = mat_from_quat(pose.orientation);
    for (int i = 0; i < 3; ++i) {
        if (!(fabs(pose.position[i] - expected.pos[i]) <= tol))
            fail_msg("%s:%d: link %u position[%d] is %.12f, expected %.12f", file, line,
                     (unsigned)link, i, pose.position[i], expected.pos[i]);
        for (int j = 0; j < 3; ++j)
            if (!(fabs(r.m[i][j] - expected.rot.m[i][j]) <= tol))
                fail_msg("%s:%d: link %u rotation[%d][%d] is %.12f, expected %.12f", file, line,
                         (unsigned)link, i, j, r.m[i][j], expected.rot.m[i][j]);
    }
}

/* ---- Scratch files ----------------------------------------------------- */

typedef struct scratch_dir {
    char path[64];
} scratch_dir;

static inline scratch_dir make_scratch_dir(void) {
    scratch_dir d;
    strcpy(d.path, "/tmp/opx_urdf_XXXXXX");
    assert_non_null(mkdtemp(d.path));
    return d;
}

/* Writes `text` to dir/relative (sub-folders must exist); returns the path. */
static inline const char *write_scratch(const scratch_dir *d, const char *relative, const char *text) {
    static char path[256];
    snprintf(path, sizeof path, "%s/%s", d->path, relative);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(text, 1, strlen(text), f), strlen(text));
    fclose(f);
    return path;
}

static inline void make_scratch_subdir(const scratch_dir *d, const char *relative) {
    char command[256];
    snprintf(command, sizeof command, "mkdir -p '%s/%s'", d->path, relative);
    assert_int_equal(system(command), 0);
}

static inline void remove_scratch_dir(const scratch_dir *d) {
    char command[128];
    snprintf(command, sizeof command, "rm -rf '%s'", d->path);
    assert_int_equal(system(command), 0);
}

#endif /* OPX_URDF_TEST_H */
