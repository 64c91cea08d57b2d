"""Obstacles as their point extents (obstacle_geometry=OBSTACLE_POINT_EXTENTS),
OctoProx map bytes (FORMAT_OPX) and spheres per call (Query.collide_spheres)."""
import os
import pickle
import tempfile
import unittest

import numpy as np

import octoprox


def wall_map():
    """Points on the plane x = 2.05, in the middle of 0.1 m cells [2.0, 2.1]."""
    tree = octoprox.Octree(resolution=0.1)
    ys, zs = np.meshgrid(np.arange(-0.5, 0.5, 0.01), np.arange(-0.5, 0.5, 0.01))
    points = np.column_stack([np.full(ys.size, 2.05), ys.ravel(), zs.ravel()])
    tree.insert_points(points)
    return tree


def sphere_at(x, radius=0.1):
    links = octoprox.LinkSet()
    link = links.add_link("ball")
    links.add_sphere(link, radius)
    links.set_poses([(x, 0.0, 0.0)])
    return links


class PointExtents(unittest.TestCase):
    def test_a_sphere_between_the_points_and_their_cell_face(self):
        tree = wall_map()
        self.assertEqual(tree.stats.leaves_with_extent, tree.stats.leaves_occupied)
        links = sphere_at(1.92)  # reaches x = 2.02: into the cells, short of the points
        query = octoprox.Query()
        self.assertTrue(query.collide(tree, links).collided)
        hit = query.collide(tree, links, obstacle_geometry=octoprox.OBSTACLE_POINT_EXTENTS)
        self.assertFalse(hit.collided)
        near = query.distance(tree, links, obstacle_geometry=octoprox.OBSTACLE_POINT_EXTENTS)
        self.assertGreater(near.distance, 0.02)
        self.assertLessEqual(near.distance, 2.05 - 2.02 + 1e-9)

    def test_opx_bytes_files_and_pickles_keep_the_extents(self):
        tree = wall_map()
        links = sphere_at(1.92)
        query = octoprox.Query()
        extents = octoprox.ObstacleGeometry.POINT_EXTENTS
        for copy in (octoprox.Octree.from_bytes(tree.to_bytes(octoprox.FORMAT_OPX)),
                     pickle.loads(pickle.dumps(tree))):
            self.assertEqual(copy.stats.leaves_with_extent, tree.stats.leaves_with_extent)
            self.assertFalse(query.collide(copy, links, obstacle_geometry=extents).collided)
        ot = octoprox.Octree.from_bytes(tree.to_bytes(octoprox.FORMAT_OT))
        self.assertEqual(ot.stats.leaves_with_extent, 0)
        self.assertTrue(query.collide(ot, links, obstacle_geometry=extents).collided)
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "wall.opx")
            tree.save(path)
            self.assertEqual(octoprox.Octree.load(path).stats.leaves_with_extent,
                             tree.stats.leaves_with_extent)


class Spheres(unittest.TestCase):
    def test_spheres_answer_as_one_sphere_link_sets(self):
        tree = wall_map()
        query = octoprox.Query()
        rng = np.random.default_rng(3)
        spheres = np.column_stack([rng.uniform(1.7, 2.4, 200), rng.uniform(-0.6, 0.6, 200),
                                   rng.uniform(-0.6, 0.6, 200), rng.uniform(0.01, 0.2, 200)])
        for geometry in octoprox.ObstacleGeometry:
            got = query.collide_spheres(tree, spheres, obstacle_geometry=geometry)
            self.assertEqual(got.dtype, np.bool_)
            for row, collided in zip(spheres, got):
                links = sphere_at(row[0], row[3])
                links.set_poses([tuple(row[:3])])
                self.assertEqual(collided, query.collide(tree, links, obstacle_geometry=geometry).collided)
        self.assertTrue(0 < got.sum() < len(got))

    def test_bad_spheres_name_the_method(self):
        query = octoprox.Query()
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "Query.collide_spheres"):
            query.collide_spheres(wall_map(), np.zeros((2, 3)))
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "row 1"):
            query.collide_spheres(wall_map(), [[0, 0, 0, 0.1], [0, 0, 0, -1.0]])


if __name__ == "__main__":
    unittest.main()
