"""Self-filtering at ingest (the robot keywords of Octree.insert_points and
insert_depth_image), as the C tests (tests/c/test_self_filter.c) and the
Rust ones: a ball in front of the sensor sorts points into robot, shadowed
and kept ones; the robot's volume is cleared when asked; a URDF robot
filters at its joint positions; depth images are filtered; bad keywords
raise naming them."""
import gc
import math
import unittest

import numpy as np

import octoprox

from scenes import sphere_at

# On the ball's near side (a robot point), behind it (shadowed), elsewhere (kept).
FRAME = np.array([[1.81, 0.0, 0.0], [3.0, 0.0, 0.0], [1.0, 1.0, 0.0]])
# A ball on a prismatic joint along x: at 1 m it stands at (2, 0, 0).
SLIDER = """<robot name="slider">
  <link name="base"/>
  <link name="ball"><collision><geometry><sphere radius="0.2"/></geometry></collision></link>
  <joint name="slide" type="prismatic"><parent link="base"/><child link="ball"/>
    <origin xyz="1 0 0"/><axis xyz="1 0 0"/><limit lower="0" upper="2" velocity="1" effort="1"/>
  </joint>
</robot>"""


def ball():
    """A ball of radius 0.2 at (2, 0, 0), map frame; the sensor at the origin."""
    return sphere_at(0.2, 2.0, 0.0, 0.0)


def class_at(tree, x, y, z):
    return tree.classify((x, y, z)).cell_class


class SelfFilter(unittest.TestCase):
    def test_sorts_points_into_robot_shadowed_and_kept(self):
        tree = octoprox.Octree(resolution=0.05)
        report = tree.insert_points(FRAME, robot=ball())
        self.assertEqual((report.points_used, report.points_on_robot, report.points_shadowed),
                         (1, 1, 1))
        self.assertEqual((report.cells_hit, report.cells_cleared), (1, 0))
        self.assertEqual(class_at(tree, 1.0, 1.0, 0.0), octoprox.CELL_OCCUPIED)
        self.assertEqual(class_at(tree, 1.81, 0.0, 0.0), octoprox.CELL_UNKNOWN)
        self.assertEqual(class_at(tree, 3.0, 0.0, 0.0), octoprox.CELL_UNKNOWN)
        # The rays still carve up to the ball.
        self.assertEqual(class_at(tree, 1.0, 0.0, 0.0), octoprox.CELL_FREE)

    def test_robot_padding_widens_the_band(self):
        robot, near = ball(), [[1.7, 0.0, 0.0]]  # 0.1 m in front of the ball
        for padding, on_robot in ((0.0, 0), (0.15, 1)):
            tree = octoprox.Octree(resolution=0.05)
            report = tree.insert_points(near, robot=robot, robot_padding=padding)
            self.assertEqual(report.points_on_robot, on_robot, padding)

    def test_without_a_robot_every_point_counts(self):
        report = octoprox.Octree(resolution=0.05).insert_points(FRAME)
        self.assertEqual(report.points_used, 3)
        self.assertEqual(report.points_on_robot + report.points_shadowed + report.cells_cleared, 0)

    def test_clear_robot_volume_clears_a_ghost(self):
        for clear in (False, True):
            tree = octoprox.Octree(resolution=0.05)
            tree.insert_points([[2.0, 0.0, 0.0]])
            self.assertEqual(class_at(tree, 2.0, 0.0, 0.0), octoprox.CELL_OCCUPIED)
            report = tree.insert_points([[0.0, 3.0, 0.0]], robot=ball(), clear_robot_volume=clear)
            expected = octoprox.CELL_FREE if clear else octoprox.CELL_OCCUPIED
            self.assertEqual((report.cells_cleared > 0, class_at(tree, 2.0, 0.0, 0.0)),
                             (clear, expected))

    def test_a_urdf_robot_filters_at_its_joint_positions(self):
        robot = octoprox.LinkSet.from_urdf_string(SLIDER)
        robot.set_joint_positions([1.0])
        report = octoprox.Octree(resolution=0.05).insert_points(FRAME, robot=robot)
        self.assertEqual((report.points_used, report.points_on_robot, report.points_shadowed),
                         (1, 1, 1))

    def test_the_call_holds_the_robot(self):
        tree = octoprox.Octree(resolution=0.05)
        report = tree.insert_points(FRAME, robot=ball())  # no other reference to the robot
        gc.collect()
        self.assertEqual(report.points_on_robot, 1)

    def test_filters_depth_images(self):
        robot = sphere_at(0.3, 0.0, 0.0, 2.0)  # 2 m along the optical axis
        depth = np.full((9, 9), 3000, dtype=np.uint16)  # 3 m: behind the ball at the centre
        depth[4, 4] = 1750  # on the ball's near side
        tree = octoprox.Octree(resolution=0.05)
        report = tree.insert_depth_image(depth, (10.0, 10.0, 4.0, 4.0), robot=robot,
                                         robot_padding=0.0, clear_robot_volume=True)
        self.assertEqual(report.points_on_robot, 1)
        self.assertGreater(report.points_shadowed, 0)
        self.assertGreater(report.cells_cleared, 0)
        self.assertEqual(report.points_used + report.points_on_robot + report.points_shadowed, 81)


class BadKeywords(unittest.TestCase):
    def assert_invalid(self, field, call):
        tree = octoprox.Octree(resolution=0.05)
        tree.insert_points([[1.0, 1.0, 0.0]])
        before = tree.to_bytes(octoprox.FileFormat.OT)
        with self.assertRaises(octoprox.InvalidArgumentError) as caught:
            call(tree)
        self.assertIn(field, str(caught.exception))
        self.assertEqual(tree.to_bytes(octoprox.FileFormat.OT), before)
        return caught.exception

    def test_a_bad_robot_padding_names_it(self):
        robot = ball()
        for padding in (-0.01, math.nan, math.inf):
            error = self.assert_invalid("robot_padding", lambda tree: tree.insert_points(
                FRAME, robot=robot, robot_padding=padding))
            self.assertEqual(error.where, "Octree.insert_points")
        self.assert_invalid("robot_padding", lambda tree: tree.insert_depth_image(
            np.ones((2, 2), dtype=np.uint16), (1.0, 1.0, 0.5, 0.5), robot=robot,
            robot_padding=-1.0))
        with self.assertRaises(TypeError) as caught:
            octoprox.Octree().insert_points(FRAME, robot=robot, robot_padding="wide")
        self.assertIn("robot_padding", str(caught.exception))

    def test_clear_robot_volume_needs_a_robot(self):
        self.assert_invalid("clear_robot_volume",
                            lambda tree: tree.insert_points(FRAME, clear_robot_volume=True))

    def test_a_robot_without_poses(self):
        unposed = octoprox.LinkSet()
        unposed.add_sphere(unposed.add_link("ball"), 0.2)
        self.assert_invalid("robot", lambda tree: tree.insert_points(FRAME, robot=unposed))

    def test_the_robot_is_a_live_link_set(self):
        closed = ball()
        closed.close()
        error = self.assert_invalid("closed", lambda tree: tree.insert_points(FRAME, robot=closed))
        self.assertEqual(str(error), "Octree.insert_points: the link set is closed")
        with self.assertRaises(TypeError) as caught:
            octoprox.Octree().insert_points(FRAME, robot=[[2.0, 0.0, 0.0]])
        self.assertIn("robot must be a LinkSet", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
