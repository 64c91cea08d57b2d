"""Link sets from URDF: links, joints, FK, named positions, a collision
check after FK, and errors (the scenarios of the Rust URDF tests)."""
import math
import os
import tempfile
import unittest

import numpy as np

import octoprox

from scenes import C0, one_cell_map, sphere_at

# base --shoulder (revolute z, 0.2 up)--> arm --slide (prismatic x, 0.5
# along the arm)--> finger.
ARM = """<robot name="arm">
  <link name="base"><collision><geometry><box size="0.2 0.2 0.1"/></geometry></collision></link>
  <link name="arm"><collision><origin xyz="0.25 0 0"/><geometry><sphere radius="0.05"/></geometry></collision></link>
  <link name="finger"><collision><geometry><sphere radius="0.02"/></geometry></collision></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.2"/><axis xyz="0 0 1"/><limit lower="-1.5" upper="1.5" velocity="1" effort="10"/></joint>
  <joint name="slide" type="prismatic"><parent link="arm"/><child link="finger"/>
    <origin xyz="0.5 0 0"/><axis xyz="1 0 0"/><limit lower="0" upper="0.2" velocity="2" effort="5"/></joint>
</robot>"""


class Urdf(unittest.TestCase):
    def test_links_and_joints_come_from_the_urdf(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "arm.urdf")
            with open(path, "w") as f:
                f.write(ARM)
            robot = octoprox.LinkSet.from_urdf(path)
        self.assertEqual(robot.link_names, ["base", "arm", "finger"])
        self.assertEqual(robot.joint_names, ["shoulder", "slide"])
        shoulder = robot.joint_info(robot.find_joint("shoulder"))
        self.assertEqual((shoulder.type, shoulder.parent_link, shoulder.child_link),
                         (octoprox.JOINT_REVOLUTE, 0, 1))
        self.assertEqual((tuple(shoulder.axis), shoulder.lower, shoulder.upper),
                         ((0.0, 0.0, 1.0), -1.5, 1.5))
        self.assertEqual(shoulder.mimic_joint, octoprox.JOINT_NONE)
        self.assertEqual(shoulder.to_dict()["name"], "shoulder")
        self.assertEqual(robot.disabled_pairs, [])
        np.testing.assert_allclose(robot.pose(2)[:3], [0.5, 0, 0.2], atol=1e-12)

    def test_forward_kinematics_and_named_positions(self):
        robot = octoprox.LinkSet.from_urdf_string(ARM)
        robot.set_joint_positions([math.pi / 2, 0.1])
        np.testing.assert_allclose(robot.pose(2)[:3], [0, 0.6, 0.2], atol=1e-12)
        robot.set_joint_positions(np.array([math.pi / 2, 0.1]), base_pose=(1, 0, 0))
        np.testing.assert_allclose(robot.pose(2)[:3], [1, 0.6, 0.2], atol=1e-12)
        robot.set_named_joint_positions({"slide": 0.0})
        np.testing.assert_allclose(robot.pose(2)[:3], [0, 0.5, 0.2], atol=1e-12)
        np.testing.assert_array_equal(robot.joint_positions, [math.pi / 2, 0.0])
        self.assertEqual(robot.clone().joint_count, 2)

    def test_a_check_after_fk(self):
        tree = one_cell_map()
        robot = octoprox.LinkSet.from_urdf_string(ARM)
        query = octoprox.Query()
        robot.set_joint_positions([0, 0], base_pose=(2, 2, 0))
        self.assertEqual(query.collide(tree, robot).collided, 0)
        # The base placed so that, at every joint 0, the finger is at the cell's centre.
        robot.set_joint_positions([0, 0], base_pose=(-0.5 + C0, C0, -0.2 + C0))
        self.assertEqual(query.collide(tree, robot, max_contacts=10).collided, 1)
        self.assertIn(robot.find_link("finger"), query.contacts()["link"])

    def test_errors(self):
        with self.assertRaises(OSError) as caught:
            octoprox.LinkSet.from_urdf("/nonexistent/robot.urdf")
        self.assertIn("/nonexistent/robot.urdf", caught.exception.message)
        with self.assertRaises(octoprox.CorruptDataError):
            octoprox.LinkSet.from_urdf_string("<robot name=")
        robot = octoprox.LinkSet.from_urdf_string(ARM)
        with self.assertRaises(ValueError):
            robot.set_joint_positions([0.0])
        with self.assertRaises(ValueError) as caught:
            robot.set_named_joint_positions({"elbow": 1.0})
        self.assertIn("elbow", caught.exception.message)
        with self.assertRaises(octoprox.UnsupportedError):
            sphere_at(0.1, 0, 0, 0).set_joint_positions([])


if __name__ == "__main__":
    unittest.main()
