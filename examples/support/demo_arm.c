/* The demo's built-in 7-joint arm: see demo_arm.h. */
#include "demo_arm.h"

#include <math.h>
#include <stdio.h>

const char *const kDemoArmJointNames[DEMO_ARM_JOINTS] = {
    "arm_joint_1", "arm_joint_2", "arm_joint_3", "arm_joint_4", "arm_joint_5", "arm_joint_6", "arm_joint_7"};

#define REVOLUTE(name, parent, child, z, axis)                                                         \
    "  <joint name=\"" name "\" type=\"revolute\">\n"                                                  \
    "    <parent link=\"" parent "\"/><child link=\"" child "\"/>\n"                                   \
    "    <origin xyz=\"0 0 " z "\" rpy=\"0 0 0\"/><axis xyz=\"" axis "\"/>\n"                          \
    "    <limit lower=\"-3.1\" upper=\"3.1\" effort=\"50\" velocity=\"2\"/>\n"                         \
    "  </joint>\n"

#define LINK(name, geometry, z)                                                                        \
    "  <link name=\"" name "\"><collision><origin xyz=\"0 0 " z "\" rpy=\"0 0 0\"/>"                   \
    "<geometry>" geometry "</geometry></collision></link>\n"

static const char kUrdf[] =
    "<?xml version=\"1.0\"?>\n"
    "<robot name=\"opx_demo_arm\">\n"
    LINK("pedestal", "<cylinder radius=\"0.12\" length=\"0.5\"/>", "0.25")
    LINK("shoulder", "<sphere radius=\"0.09\"/>", "0.1")
    LINK("upper_arm", "<cylinder radius=\"0.055\" length=\"0.45\"/>", "0.225")
    LINK("elbow", "<sphere radius=\"0.07\"/>", "0")
    LINK("forearm", "<mesh filename=\"" DEMO_ARM_FOREARM_MESH "\"/>", "0")
    LINK("wrist_roll", "<cylinder radius=\"0.04\" length=\"0.06\"/>", "0.03")
    LINK("wrist", "<sphere radius=\"0.05\"/>", "0")
    LINK("hand", "<mesh filename=\"" DEMO_ARM_HAND_MESH "\"/>", "0")
    REVOLUTE("arm_joint_1", "pedestal", "shoulder", "0.5", "0 0 1")
    REVOLUTE("arm_joint_2", "shoulder", "upper_arm", "0.1", "0 1 0")
    REVOLUTE("arm_joint_3", "upper_arm", "elbow", "0.45", "0 0 1")
    REVOLUTE("arm_joint_4", "elbow", "forearm", "0", "0 1 0")
    REVOLUTE("arm_joint_5", "forearm", "wrist_roll", "0.40", "0 0 1")
    REVOLUTE("arm_joint_6", "wrist_roll", "wrist", "0.06", "0 1 0")
    REVOLUTE("arm_joint_7", "wrist", "hand", "0", "0 0 1")
    "</robot>\n";

const char *demo_arm_urdf(void) { return kUrdf; }

/* The forearm: an octagonal shell tapering from r 0.05 to r 0.04 along z
 * in [0, 0.40], capped at both ends. */
static int write_forearm(const char *path) {
    const int sides = 8;
    FILE *f = fopen(path, "w");
    int i;
    if (f == NULL) return -1;
    fprintf(f, "# OctoProx demo arm: forearm shell (metres)\n");
    for (i = 0; i < sides; ++i) {
        const double a = 2.0 * 3.14159265358979323846 * i / sides;
        fprintf(f, "v %.5f %.5f 0\nv %.5f %.5f 0.4\n", 0.05 * cos(a), 0.05 * sin(a), 0.04 * cos(a), 0.04 * sin(a));
    }
    fprintf(f, "v 0 0 0\nv 0 0 0.4\n");
    for (i = 0; i < sides; ++i) {
        const int b0 = 2 * i + 1, t0 = 2 * i + 2, b1 = 2 * ((i + 1) % sides) + 1, t1 = 2 * ((i + 1) % sides) + 2;
        fprintf(f, "f %d %d %d\nf %d %d %d\n", b0, b1, t1, b0, t1, t0);
        fprintf(f, "f %d %d %d\nf %d %d %d\n", 2 * sides + 1, b1, b0, 2 * sides + 2, t0, t1);
    }
    return fclose(f) == 0 ? 0 : -1;
}

static void stl_box(FILE *f, const double lo[3], const double hi[3]) {
    static const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    double c[8][3];
    int i, q, k;
    for (i = 0; i < 8; ++i) {
        c[i][0] = i & 1 ? hi[0] : lo[0];
        c[i][1] = i & 2 ? hi[1] : lo[1];
        c[i][2] = i & 4 ? hi[2] : lo[2];
    }
    for (q = 0; q < 6; ++q)
        for (k = 0; k < 2; ++k) {
            const int t[3] = {quads[q][0], quads[q][1 + k], quads[q][2 + k]};
            fprintf(f, " facet normal 0 0 0\n  outer loop\n");
            for (i = 0; i < 3; ++i) fprintf(f, "   vertex %.5f %.5f %.5f\n", c[t[i]][0], c[t[i]][1], c[t[i]][2]);
            fprintf(f, "  endloop\n endfacet\n");
        }
}

/* The hand: a palm and two fingers, along z in [0, 0.15]. */
static int write_hand(const char *path) {
    static const double palm[2][3] = {{-0.04, -0.06, 0.0}, {0.04, 0.06, 0.06}};
    static const double finger1[2][3] = {{-0.012, -0.06, 0.06}, {0.012, -0.035, 0.15}};
    static const double finger2[2][3] = {{-0.012, 0.035, 0.06}, {0.012, 0.06, 0.15}};
    FILE *f = fopen(path, "w");
    if (f == NULL) return -1;
    fprintf(f, "solid opx_demo_hand\n");
    stl_box(f, palm[0], palm[1]);
    stl_box(f, finger1[0], finger1[1]);
    stl_box(f, finger2[0], finger2[1]);
    fprintf(f, "endsolid opx_demo_hand\n");
    return fclose(f) == 0 ? 0 : -1;
}

int demo_arm_write_meshes(const char *dir) {
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, DEMO_ARM_FOREARM_MESH);
    if (write_forearm(path) != 0) return -1;
    snprintf(path, sizeof path, "%s/%s", dir, DEMO_ARM_HAND_MESH);
    return write_hand(path);
}
