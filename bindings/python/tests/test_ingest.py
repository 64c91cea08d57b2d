"""Inserting sensor frames from numpy arrays without copies, classifying,
leaves, files and bytes (the scenarios of the Rust ingest tests)."""
import os
import tempfile
import unittest
from unittest import mock

import numpy as np

import octoprox
from octoprox import _arrays

from scenes import C0, RES

SENSOR = (C0, C0, C0)
# Two rays, to (1, 0, 0) and (0, 1, 0) in the sensor frame: 2 occupied and
# 7 free cells.
RAYS = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]


def no_copy():
    """A guard: the code path must not copy (np.ascontiguousarray raises)."""
    return mock.patch.object(np, "ascontiguousarray", side_effect=AssertionError("copied"))


class Ingest(unittest.TestCase):
    def insert(self, points):
        tree = octoprox.Octree(resolution=RES)
        report = tree.insert_points(points, sensor_pose=SENSOR)
        self.assertEqual((report.points_used, report.cells_hit, report.cells_missed), (2, 2, 7))
        self.assert_sample_map(tree)
        return tree

    def assert_sample_map(self, tree):
        stats = tree.stats
        self.assertEqual((stats.leaves_occupied, stats.leaves_free), (2, 7))
        hit = tree.classify((1.0 + C0, C0, C0))
        self.assertEqual(hit.cell_class, octoprox.CELL_OCCUPIED)
        self.assertAlmostEqual(hit.probability, 0.7, places=4)
        self.assertEqual(tree.classify((0.5 + C0, C0, C0)).cell_class, octoprox.CELL_FREE)
        self.assertEqual(tree.classify((-3, -3, -3)).cell_class, octoprox.CELL_UNKNOWN)

    def test_packed_float32_and_float64_go_in_place(self):
        for dtype in (np.float32, np.float64):
            for columns in (3, 4):
                points = np.zeros((2, columns), dtype=dtype)
                points[:, :3] = RAYS
                view = _arrays.point_view(points, "test")
                self.assertEqual(view.address, points.ctypes.data)
                self.assertEqual(view.stride, columns * points.itemsize)
                with no_copy():
                    self.insert(points)

    def test_a_strided_view_of_a_bigger_array_is_not_copied(self):
        big = np.full((6, 5), 99.0)
        big[0, :3], big[3, :3] = RAYS
        view = big[::3, :4]  # rows 0 and 3, 4 of 5 columns
        self.assertFalse(view.flags.c_contiguous)
        points = _arrays.point_view(view, "test")
        self.assertEqual((points.address, points.stride), (big.ctypes.data, 3 * 5 * 8))
        with no_copy():
            self.insert(view)

    def test_a_pointcloud2_buffer_goes_in_by_point_step(self):
        # x y z float32 at offsets 0, 4, 8 and rgb at 16: point_step 32.
        dtype = np.dtype({"names": ["x", "y", "z", "rgb"], "formats": ["<f4"] * 3 + ["<u4"],
                          "offsets": [0, 4, 8, 16], "itemsize": 32})
        data = bytearray(64)
        cloud = np.frombuffer(data, dtype=dtype)
        cloud["x"], cloud["y"], cloud["z"] = [1, 0], [0, 1], [0, 0]
        view = _arrays.point_view(cloud, "test")
        self.assertEqual((view.address, view.stride, view.scalar_type),
                         (cloud.ctypes.data, 32, _arrays.SCALAR_FLOAT32))
        with no_copy():
            self.insert(cloud)

    def test_other_inputs_get_one_copy(self):
        self.insert(RAYS)  # a list
        self.insert(np.array(RAYS, dtype=np.int64))
        self.insert(np.asfortranarray(np.array(RAYS)))  # columns strided
        self.insert(np.array(RAYS, dtype=">f8"))  # byte-swapped
        shuffled = np.zeros(2, dtype=[("z", "f4"), ("y", "f4"), ("x", "f4")])
        shuffled["x"], shuffled["y"] = [1, 0], [0, 1]
        self.insert(shuffled)

    def test_insert_options(self):
        tree = octoprox.Octree(resolution=RES)
        report = tree.insert_points(np.array(RAYS), sensor_pose=SENSOR, max_range=0.5,
                                    mode=octoprox.INSERT_ENDPOINTS)
        self.assertEqual((report.points_used, report.points_out_of_range), (0, 2))
        nan = tree.insert_points(np.array([[np.nan, 0, 0]]), mode=octoprox.INSERT_ENDPOINTS)
        self.assertEqual(nan.points_nonfinite, 1)

    def test_leaves_are_a_structured_array(self):
        tree = self.insert(np.array(RAYS))
        occupied = tree.leaves()
        self.assertEqual(occupied.dtype, _arrays.LEAF_DTYPE)
        self.assertEqual(len(occupied), 2)
        self.assertTrue((occupied["cell_class"] == octoprox.CELL_OCCUPIED).all())
        np.testing.assert_allclose(sorted(occupied["center"][:, 0]), [C0, 1.0 + C0])
        self.assertEqual(len(tree.leaves(octoprox.MASK_ALL_KNOWN)), 9)
        self.assertEqual(len(octoprox.Octree().leaves()), 0)

    def test_bytes_files_and_messages_round_trip(self):
        tree = self.insert(np.array(RAYS))
        self.assert_sample_map(octoprox.Octree.from_bytes(tree.to_bytes(octoprox.FORMAT_OT)))
        message = tree.to_bytes(octoprox.FORMAT_BT)
        self.assertTrue(message.startswith(b"# Octomap OcTree binary file"))
        # A ROS octomap_msgs/Octomap carries the data after the header.
        body = message[message.index(b"\ndata\n") + 6:]
        from_message = octoprox.Octree.from_message(body, True, RES)
        stats = from_message.stats  # .bt keeps classes, not probabilities
        self.assertEqual((stats.leaves_occupied, stats.leaves_free), (2, 7))
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "map.ot")
            tree.save(path)
            self.assert_sample_map(octoprox.Octree.load(path))

    def test_clear(self):
        tree = self.insert(np.array(RAYS))
        tree.clear()
        self.assertEqual(tree.stats.leaves_occupied, 0)
        self.assertEqual(tree.options.resolution, RES)


if __name__ == "__main__":
    unittest.main()
