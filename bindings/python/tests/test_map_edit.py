"""Clearing regions and shapes, decay, cropping and bounded inserts."""
import math
import unittest

import numpy as np

import octoprox


def row_map():
    """Eight occupied cells of 0.25 m in a row along x, from x = 0 to 2."""
    tree = octoprox.Octree(resolution=0.25)
    xs = (np.arange(8) + 0.5) * 0.25
    tree.insert_points(np.column_stack([xs, np.full(8, 0.125), np.full(8, 0.125)]), mode="endpoints")
    return tree


def classes(tree):
    return [int(tree.classify(((i + 0.5) * 0.25, 0.125, 0.125)).cell_class) for i in range(8)]


OCC, FREE, UNK = int(octoprox.CellClass.OCCUPIED), int(octoprox.CellClass.FREE), int(octoprox.CellClass.UNKNOWN)


class MapEdit(unittest.TestCase):
    def test_clear_region_takes_the_cell_above_a_face(self):
        tree = row_map()
        tree.clear_region((0.5, 0, 0), (1.0, 0, 0))
        self.assertEqual(classes(tree), [OCC, OCC, UNK, UNK, UNK, OCC, OCC, OCC])
        tree.clear_region((1.5 + 1e-9, 0, 0), (1.75 - 1e-9, 0, 0), to="free")
        self.assertEqual(classes(tree)[5:], [OCC, FREE, OCC])
        tree.clear_region((-math.inf, -math.inf, -math.inf), (math.inf, math.inf, math.inf),
                          to=octoprox.CellClass.UNKNOWN)
        self.assertEqual(tree.stats.leaves_occupied, 0)

    def test_clear_shapes_clears_what_they_touch(self):
        tree = row_map()
        tree.clear_shapes([{"kind": "sphere", "radius": 0.2, "pose": (0.1, 0, 0)}], pose=(0.9, 0, 0))
        self.assertEqual(classes(tree), [OCC, OCC, OCC, UNK, UNK, OCC, OCC, OCC])
        world = octoprox.World()
        box = world.add_box("block", (0.2, 0.2, 0.2), (1.875, 0.125, 0.125))
        tree.clear_shapes([world.shape(box, 0)], world.pose(box), to="free")
        self.assertEqual(classes(tree)[7], FREE)

    def test_decay_fades_and_forgets(self):
        tree = row_map()
        before = tree.classify((0.125, 0.125, 0.125)).probability
        tree.decay(0.3)
        after = tree.classify((0.125, 0.125, 0.125)).probability
        l = math.log(before / (1 - before)) - 0.3
        self.assertAlmostEqual(after, 1 / (1 + math.exp(-l)), places=6)
        tree.decay(1.0)
        self.assertEqual(tree.stats.leaves_occupied, 0)

    def test_crop_and_bounds(self):
        tree = row_map()
        tree.crop((0.25, -1, -1), (1.0, 1, 1))
        self.assertEqual(classes(tree), [UNK, OCC, OCC, OCC, OCC, UNK, UNK, UNK])
        bounded = octoprox.Octree(resolution=0.25)
        xs = (np.arange(8) + 0.5) * 0.25
        report = bounded.insert_points(np.column_stack([xs, np.full(8, 0.125), np.full(8, 0.125)]),
                                       mode="endpoints", bounds=((0.25, -1, -1), (1.0, 1, 1)))
        self.assertEqual(report.cells_hit, 4)
        self.assertEqual(classes(bounded), classes(tree))
        depth = np.full((4, 4), 1000, dtype=np.uint16)
        report = bounded.insert_depth_image(depth, (2.0, 2.0, 1.5, 1.5), bounds=((5, 5, 5), (6, 6, 6)))
        self.assertEqual(report.cells_hit + report.cells_missed, 0)

    def test_bad_input_names_the_argument_and_changes_nothing(self):
        tree = row_map()
        before = tree.to_bytes(octoprox.FORMAT_OT)
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "box_max"):
            tree.clear_region((0, 0, 0), (1, math.nan, 1))
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "inverted"):
            tree.crop((1, 0, 0), (0, 1, 1))
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "amount"):
            tree.decay(-1.0)
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "amount"):
            tree.decay(math.nan)
        with self.assertRaisesRegex(ValueError, "to"):
            tree.clear_region((0, 0, 0), (1, 1, 1), to="occupied")
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "bounds_min"):
            tree.insert_points(np.zeros((1, 3)), bounds=((1, 1, 1), (0, 0, 0)))
        self.assertEqual(tree.to_bytes(octoprox.FORMAT_OT), before)


if __name__ == "__main__":
    unittest.main()
