"""Query.distance_spheres: signed distances, gradients and witnesses as
numpy arrays, against the one cell [0, 0.25]^3 and a World's ball."""
import unittest

import numpy as np

import octoprox

from scenes import C0, one_cell_map


def cell_sdf(p):
    """The signed distance field of the cell [0, 0.25]^3 at p."""
    gap = np.maximum(np.maximum(-p, p - 0.25), 0.0)
    outside = np.linalg.norm(gap, axis=-1)
    inside = np.minimum(p, 0.25 - p).min(axis=-1)
    return np.where(outside > 0.0, outside, -inside)


class DistanceSpheres(unittest.TestCase):
    def test_distances_gradients_and_witnesses(self):
        rng = np.random.default_rng(5)
        spheres = np.column_stack([rng.uniform(-0.3, 0.55, (500, 3)), rng.uniform(0, 0.05, 500)])
        distance, gradient, witness = octoprox.Query().distance_spheres(one_cell_map(), spheres,
                                                                        max_distance=0.1)
        self.assertEqual((distance.shape, gradient.shape, witness.shape), ((500,), (500, 3), (500, 3)))
        sdf = cell_sdf(spheres[:, :3]) - spheres[:, 3]
        np.testing.assert_allclose(distance, np.minimum(sdf, 0.1), atol=1e-9)
        far = sdf >= 0.1
        self.assertTrue(far.any() and (sdf < 0).any())
        self.assertTrue((gradient[far] == 0).all() and np.isnan(witness[far]).all())
        near = ~far
        np.testing.assert_allclose(np.linalg.norm(gradient[near], axis=1), 1.0, atol=1e-12)
        # The witness is |sdf| from the centre, and lies on the cell's surface.
        np.testing.assert_allclose(np.linalg.norm(witness[near] - spheres[near, :3], axis=1),
                                   np.abs(cell_sdf(spheres[near, :3])), atol=1e-9)
        np.testing.assert_allclose(cell_sdf(witness[near]), 0.0, atol=1e-9)

    def test_a_world_and_the_keywords(self):
        world = octoprox.World()
        world.add_sphere("ball", 0.2, (1.0, C0, C0))
        query = octoprox.Query()
        rows = [[1.5, C0, C0, 0.1], [0.6, C0, C0, 0.0]]
        distance, gradient, _ = query.distance_spheres(one_cell_map(), rows, 1.0, world, threads=2)
        np.testing.assert_allclose(distance, [0.2, 0.2], atol=1e-9)
        np.testing.assert_allclose(gradient[0], [1.0, 0.0, 0.0], atol=1e-9)
        distance, _, _ = query.distance_spheres(None, rows, max_distance=np.inf, world=world)
        np.testing.assert_allclose(distance, [0.2, 0.2], atol=1e-9)
        distance, _, _ = query.distance_spheres(one_cell_map(), [[0.5, 0.5, 0.5, 0.0]],
                                                unknown_policy=octoprox.UNKNOWN_OCCUPIED,
                                                max_distance=np.inf)
        self.assertLess(distance[0], -1000.0)  # deep in unknown space

    def test_bad_input(self):
        query, tree = octoprox.Query(), one_cell_map()
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "row 1"):
            query.distance_spheres(tree, [[0, 0, 0, 0.1], [0, 0, np.nan, 0.1]])
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "row 0"):
            query.distance_spheres(tree, [[0, 0, 0, -0.1]])
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "max_distance"):
            query.distance_spheres(tree, [[0, 0, 0, 0.1]], max_distance=0.0)
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "Query.distance_spheres"):
            query.distance_spheres(tree, np.zeros((2, 3)))
        with self.assertRaises(TypeError):
            query.distance_spheres(None, [[0, 0, 0, 0.1]])


if __name__ == "__main__":
    unittest.main()
