/*
 * The demo's built-in robot: a 7-joint arm on a fixed pedestal, defined
 * as a URDF string.  Its links are primitives (cylinders, spheres) and two
 * small meshes the demo writes itself: a tapered forearm shell (OBJ) and
 * a hand with two fingers (ASCII STL).  No download.
 *
 * The arm frame: the pedestal stands on z = 0 (0.5 m high), the shoulder
 * is at z = 0.6; joints 1, 3, 5, 7 turn about the link's z axis (yaw and
 * rolls), joints 2, 4, 6 about its y axis (pitches: positive tips the arm
 * towards +x).  Link lengths: upper arm 0.45 m, forearm 0.40 m, wrist
 * 0.06 m, hand 0.15 m.
 */
#ifndef OPX_EXAMPLES_DEMO_ARM_H
#define OPX_EXAMPLES_DEMO_ARM_H

#define DEMO_ARM_JOINTS 7
#define DEMO_ARM_FOREARM_MESH "demo-arm-forearm.obj"
#define DEMO_ARM_HAND_MESH "demo-arm-hand.stl"

/* The URDF; mesh file names are relative (load with base_dir = the
 * folder demo_arm_write_meshes wrote to). */
const char *demo_arm_urdf(void);
/* The joint names in order, "arm_joint_1" .. "arm_joint_7". */
extern const char *const kDemoArmJointNames[DEMO_ARM_JOINTS];

/* Writes the two mesh files into dir; 0, or -1 when a file cannot be
 * written. */
int demo_arm_write_meshes(const char *dir);

#endif /* OPX_EXAMPLES_DEMO_ARM_H */
