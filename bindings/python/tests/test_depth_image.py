"""Depth frames from numpy arrays: the hand-computed 4 x 3 frame of the C
tests (tests/c/opx_depth_test.h) gives the map of its points, uint16 and
float32 agree, views go in without a copy, bad input raises."""
import unittest

import numpy as np

import octoprox
from octoprox import _arrays

from scenes import C0, RES
from test_ingest import no_copy

SENSOR = (C0, C0, C0)
CAMERA = (2.0, 4.0, 1.5, 1.0)  # fx, fy, cx, cy
MM = np.array([[2000, 0, 2000, 1000],
               [2000, 2000, 0, 3000],
               [0, 2000, 0, 0]], dtype=np.uint16)
# ((u - cx) * z / fx, (v - cy) * z / fy, z) of the pixels with a return.
POINTS = [[-1.5, -0.5, 2.0], [0.5, -0.5, 2.0], [0.75, -0.25, 1.0], [-1.5, 0.0, 2.0],
          [-0.5, 0.0, 2.0], [2.25, 0.0, 3.0], [-0.5, 0.5, 2.0]]


def metres():
    """The frame in float32 metres, each kind of missing return once."""
    m = MM.astype(np.float32) / 1000
    m[0, 1], m[1, 2], m[2, 2], m[2, 3] = np.nan, np.inf, -1.0, -np.inf
    return m


def leaves(tree):
    return tree.leaves(octoprox.MASK_ALL_KNOWN).tobytes()


class DepthImage(unittest.TestCase):
    def setUp(self):
        self.reference = octoprox.Octree(resolution=RES)
        self.expected = self.reference.insert_points(np.array(POINTS), sensor_pose=SENSOR)

    def insert(self, depth, **keywords):
        tree = octoprox.Octree(resolution=RES)
        report = tree.insert_depth_image(depth, CAMERA, sensor_pose=SENSOR, **keywords)
        self.assertEqual((report.points_used, report.pixels_no_return), (7, 5))
        self.assertEqual((report.cells_hit, report.cells_missed),
                         (self.expected.cells_hit, self.expected.cells_missed))
        self.assertEqual(leaves(tree), leaves(self.reference))
        return tree

    def test_the_tiny_frame_gives_the_map_of_its_points(self):
        tree = self.insert(MM)
        for x, y, z in POINTS:
            cell = tree.classify((C0 + x, C0 + y, C0 + z))
            self.assertEqual(cell.cell_class, octoprox.CELL_OCCUPIED)

    def test_uint16_and_float32_go_in_place(self):
        for depth in (MM, metres()):
            view = _arrays.depth_view(depth, "test")
            self.assertEqual((view.address, view.row_stride),
                             (depth.ctypes.data, 4 * depth.itemsize))
            with no_copy():
                self.insert(depth)

    def test_a_view_of_a_bigger_image_is_not_copied(self):
        big = np.full((6, 9), 1234, dtype=np.uint16)
        big[::2, 2:6] = MM
        view = big[::2, 2:6]
        self.assertFalse(view.flags.c_contiguous)
        depth = _arrays.depth_view(view, "test")
        self.assertEqual((depth.address, depth.row_stride), (big.ctypes.data + 4, 2 * 9 * 2))
        with no_copy():
            self.insert(view)

    def test_other_layouts_get_one_copy(self):
        self.insert(metres().astype(np.float64))
        self.insert(MM.astype(">u2"))  # byte-swapped
        self.insert(np.asfortranarray(MM))  # columns strided
        self.insert(np.ascontiguousarray(MM[::-1])[::-1])  # rows backwards
        self.insert(metres().tolist())  # float64 metres

    def test_depth_scale_and_options(self):
        tree = octoprox.Octree(resolution=RES)
        tum = (MM.astype(np.uint32) * 5).astype(np.uint16)  # 1/5000 m units
        report = tree.insert_depth_image(tum, CAMERA, depth_scale=5000, sensor_pose=SENSOR,
                                         mode=octoprox.INSERT_ENDPOINTS, max_range=2.52,
                                         max_threads=0)
        self.assertEqual((report.points_used, report.points_out_of_range), (5, 2))
        self.assertEqual((report.cells_hit, report.cells_missed), (5, 0))
        intrinsics = octoprox.CameraIntrinsics(fx=2.0, fy=4.0, cx=1.5, cy=1.0)
        tree = octoprox.Octree(resolution=RES)
        tree.insert_depth_image(MM, intrinsics, sensor_pose=SENSOR)
        self.assertEqual(leaves(tree), leaves(self.reference))

    def test_points_take_max_threads(self):
        tree = octoprox.Octree(resolution=RES)
        tree.insert_points(np.array(POINTS), sensor_pose=SENSOR, max_threads=0)
        self.assertEqual(leaves(tree), leaves(self.reference))

    def test_an_empty_image_changes_nothing(self):
        tree = octoprox.Octree(resolution=RES)
        report = tree.insert_depth_image(np.zeros((0, 4), np.uint16), CAMERA)
        self.assertEqual(report.points_used + report.pixels_no_return, 0)
        self.assertEqual(len(tree.leaves(octoprox.MASK_ALL_KNOWN)), 0)

    def test_bad_input_raises(self):
        tree = octoprox.Octree(resolution=RES)
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "2 dimensions"):
            tree.insert_depth_image(np.zeros((2, 2, 2), np.uint16), CAMERA)
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "uint16"):
            tree.insert_depth_image(np.zeros((2, 2), np.int32), CAMERA)
        with self.assertRaisesRegex(ValueError, "fx, fy, cx, cy"):
            tree.insert_depth_image(MM, (525.0, 525.0, 320.0))
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "intrinsics.fx"):
            tree.insert_depth_image(MM, (0.0, 4.0, 1.5, 1.0))
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "depth_scale"):
            tree.insert_depth_image(MM, CAMERA, depth_scale=0)
        with self.assertRaises(TypeError):
            tree.insert_depth_image(MM, CAMERA, frame_id="camera")
        self.assertEqual(len(tree.leaves(octoprox.MASK_ALL_KNOWN)), 0)


if __name__ == "__main__":
    unittest.main()
