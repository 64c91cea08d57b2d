"""Active joints and every pose at once: LinkSet.active_joint_names and
friends on a generated arm with fixed and mimic joints (and the PR2 of the
shared data when present); set_joint_positions takes an active vector, a
model-order vector or a dict alike; poses() equals pose() row by row; the
batch queries answer active rows as the same rows in model order."""
import os
import unittest

import numpy as np

import octoprox

from scenes import REPO, skip_without_data
from test_batch import scatter_map

ARM_ACTIVE = 8  # j1..j7, finger_l
ARM_JOINTS = 10  # and finger_r (mimic), tool (fixed)


def gripper_arm_urdf():
    """The batch tests' 7-joint arm with a gripper: finger_r mimics
    finger_l, the tool is fixed."""
    links, joints = [], []
    for k in range(8):
        links.append(f'<link name="l{k}"><collision><origin xyz="0 0 0.12"/><geometry>'
                     f'<cylinder radius="0.035" length="0.16"/></geometry></collision></link>')
        if k:
            axis = "0 0 1" if k % 2 else "0 1 0"
            joints.append(f'<joint name="j{k}" type="revolute"><parent link="l{k - 1}"/>'
                          f'<child link="l{k}"/><origin xyz="0 0 {0.1 if k == 1 else 0.24}"/>'
                          f'<axis xyz="{axis}"/><limit lower="-3.14" upper="3.14" effort="1" '
                          f'velocity="1"/></joint>')
    for name in ("finger_l", "finger_r", "tool"):
        links.append(f'<link name="{name}"><collision><geometry><box size="0.02 0.02 0.06"/>'
                     f'</geometry></collision></link>')
    limit = '<limit lower="0" upper="0.04" effort="1" velocity="1"/>'
    joints += [
        f'<joint name="finger_l" type="prismatic"><parent link="l7"/><child link="finger_l"/>'
        f'<origin xyz="0 0 0.27"/><axis xyz="0 1 0"/>{limit}</joint>',
        f'<joint name="finger_r" type="prismatic"><parent link="l7"/><child link="finger_r"/>'
        f'<origin xyz="0 0 0.27"/><axis xyz="0 -1 0"/>{limit}<mimic joint="finger_l"/></joint>',
        '<joint name="tool" type="fixed"><parent link="l7"/><child link="tool"/>'
        '<origin xyz="0 0 0.33"/></joint>',
    ]
    return '<robot name="arm">' + "".join(links + joints) + "</robot>"


def load_gripper_arm():
    """The arm, its pairs that touch in every configuration disabled (each
    link and the next, the hand's links among themselves), as an SRDF
    does."""
    arm = octoprox.LinkSet.from_urdf_string(gripper_arm_urdf())
    for k in range(1, 8):
        arm.set_pair_enabled(f"l{k - 1}", f"l{k}", False)
    hand = ("l7", "finger_l", "finger_r", "tool")
    for i, a in enumerate(hand):
        for b in hand[i + 1:]:
            arm.set_pair_enabled(a, b, False)
    return arm


def random_active(n, seed):
    rng = np.random.default_rng(seed)
    return np.column_stack([rng.uniform(-3.1, 3.1, (n, 7)), rng.uniform(0.0, 0.04, n)])


def in_model_order(robot, active, filler=0.5):
    """The model-order rows holding `active` rows (other joints at a filler
    forward kinematics ignores)."""
    active = np.atleast_2d(active)
    model = np.full((len(active), robot.joint_count), filler)
    model[:, robot.active_joints] = active
    return model


class ActiveJoints(unittest.TestCase):
    def test_the_active_joints_are_the_moving_joints_that_mimic_none(self):
        arm = load_gripper_arm()
        self.assertEqual((arm.joint_count, arm.active_joint_count), (ARM_JOINTS, ARM_ACTIVE))
        self.assertEqual(arm.active_joints, list(range(ARM_ACTIVE)))
        self.assertEqual(arm.active_joint_names, [f"j{k}" for k in range(1, 8)] + ["finger_l"])
        self.assertEqual(octoprox.LinkSet().active_joint_count, 0)

    def test_active_model_and_named_vectors_pose_alike(self):
        by_active, by_model, by_name = load_gripper_arm(), load_gripper_arm(), load_gripper_arm()
        base = (0.3, -0.1, 0.2, 0.0, 0.0, 0.38268343236508978, 0.92387953251128674)
        for q in random_active(10, 3):
            by_active.set_joint_positions(q, base_pose=base)
            by_model.set_joint_positions(in_model_order(by_model, q)[0], base_pose=base)
            by_name.set_joint_positions(dict(zip(by_name.active_joint_names, q)), base_pose=base)
            np.testing.assert_array_equal(by_active.poses(), by_model.poses())
            np.testing.assert_array_equal(by_name.poses(), by_model.poses())
            np.testing.assert_array_equal(by_active.active_joint_positions, q)
        explicit = load_gripper_arm()
        explicit.set_active_joint_positions(q, base_pose=base)
        np.testing.assert_array_equal(explicit.poses(), by_model.poses())
        # The mimic finger follows its leader.
        self.assertEqual(by_active.joint_positions[8], q[7])

    def test_bad_vectors_raise_and_change_nothing(self):
        arm = load_gripper_arm()
        arm.set_joint_positions(np.full(ARM_ACTIVE, 0.2))
        before = arm.poses()
        with self.assertRaises(octoprox.InvalidArgumentError) as caught:
            arm.set_joint_positions(np.zeros(9))
        self.assertIn("LinkSet.set_joint_positions", str(caught.exception))
        self.assertIn("8 active joints", str(caught.exception))
        with self.assertRaises(ValueError):
            arm.set_joint_positions(np.r_[np.zeros(7), np.nan])
        with self.assertRaises(ValueError) as caught:
            arm.set_active_joint_positions(np.zeros(ARM_JOINTS))
        self.assertIn("count 10", str(caught.exception))
        np.testing.assert_array_equal(arm.poses(), before)
        with self.assertRaises(octoprox.UnsupportedError):
            octoprox.LinkSet().set_active_joint_positions([])


class Poses(unittest.TestCase):
    def test_every_pose_at_once_equals_one_by_one(self):
        arm = load_gripper_arm()
        arm.set_joint_positions(random_active(1, 5)[0], base_pose=(1.0, 2.0, 0.0))
        poses = arm.poses()
        self.assertEqual((poses.shape, poses.dtype), ((arm.link_count, 7), np.float64))
        for i, row in enumerate(poses):
            self.assertEqual(tuple(row), arm.pose(i))
        copy = octoprox.LinkSet()
        for name in arm.link_names:
            copy.add_link(name)
        copy.set_poses(poses)  # the rotations go through matrices: equal to rounding
        np.testing.assert_allclose(copy.poses(), poses, rtol=0.0, atol=1e-15)

    def test_an_empty_set_has_no_poses(self):
        self.assertEqual(octoprox.LinkSet().poses().shape, (0, 7))


class BatchesOfActiveJoints(unittest.TestCase):
    def setUp(self):
        self.arm, self.tree, self.query = load_gripper_arm(), scatter_map(), octoprox.Query()
        self.active = random_active(80, 11)
        self.model = in_model_order(self.arm, self.active, filler=7.0)

    def test_configurations(self):
        check = self.query.check_configurations
        hit, distance = check(self.tree, self.arm, self.model, distance=True, self_collision=True)
        self.assertTrue(0 < hit.sum() < len(hit))
        for order in ("by_count", "active", octoprox.JOINTS_ACTIVE):
            again = check(self.tree, self.arm, self.active, distance=True, self_collision=True,
                          joint_order=order)
            np.testing.assert_array_equal(again[0], hit)
            np.testing.assert_array_equal(again[1], distance)
        with self.assertRaises(octoprox.InvalidArgumentError) as caught:
            check(self.tree, self.arm, self.active, joint_order=octoprox.JointOrder.MODEL)
        self.assertIn("OPX_JOINTS_MODEL", str(caught.exception))
        with self.assertRaises(ValueError):
            check(self.tree, self.arm, self.active[:, :5])

    def test_motions(self):
        starts, goals = self.active[0::2], self.active[1::2]
        by_model = self.query.check_motions(self.tree, self.arm, self.model[0::2], self.model[1::2],
                                            resolution=0.05)
        by_active = self.query.check_motions(self.tree, self.arm, starts, goals, resolution=0.05)
        np.testing.assert_array_equal(by_active[0], by_model[0])
        np.testing.assert_array_equal(by_active[1], by_model[1])
        one = self.query.check_motion(self.tree, self.arm, starts[0], goals[0], resolution=0.05,
                                      joint_order="active")
        self.assertEqual(one.collided, by_model[0][0])
        self.assertEqual(one.steps, self.query.check_motion(
            self.tree, self.arm, self.model[0], self.model[1], resolution=0.05).steps)


def pr2_paths():
    data = os.environ.get("OPX_DATA_DIR") or os.path.join(REPO, "..", "shared", "data")
    robot = os.path.join(data, "robots", "pr2_description")
    urdf, srdf = os.path.join(robot, "urdf", "robot.xml"), os.path.join(robot, "srdf", "pr2.srdf")
    return (urdf, srdf, f"moveit_resources_pr2_description={robot}") if os.path.exists(urdf) else None


class Pr2(unittest.TestCase):
    def setUp(self):
        paths = pr2_paths()
        if paths is None:
            skip_without_data(self, "the PR2 of the shared data is absent (set OPX_DATA_DIR)")
        urdf, srdf, package = paths
        self.load = lambda: octoprox.LinkSet.from_urdf(urdf, package_dirs=[package], srdf=srdf)

    def random_active(self, robot, n, seed):
        rng = np.random.default_rng(seed)
        lower, upper = [], []
        for j in robot.active_joints:
            info = robot.joint_info(j)
            bounded = info.has_limits and np.isfinite(info.lower) and np.isfinite(info.upper)
            lower.append(info.lower if bounded else -3.14)
            upper.append(info.upper if bounded else 3.14)
        return rng.uniform(lower, upper, (n, len(lower)))

    def test_active_fk_and_batches_equal_model_order(self):
        by_active, by_model = self.load(), self.load()
        self.assertTrue(30 < by_active.active_joint_count < by_active.joint_count)
        active = self.random_active(by_active, 12, 21)
        model = in_model_order(by_model, active, filler=-0.25)
        for q, full in zip(active, model):
            by_active.set_joint_positions(q)
            by_model.set_joint_positions(full)
            np.testing.assert_array_equal(by_active.poses(), by_model.poses())
        query, tree = octoprox.Query(), scatter_map(13)
        a = query.check_configurations(tree, by_active, active, self_collision=True, distance=True)
        m = query.check_configurations(tree, by_active, model, self_collision=True, distance=True)
        np.testing.assert_array_equal(a[0], m[0])
        np.testing.assert_array_equal(a[1], m[1])


if __name__ == "__main__":
    unittest.main()
