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


ARM = """<robot name='arm'>
<link name='base'><collision><geometry><sphere radius='0.05'/></geometry></collision></link>
<link name='l1'><collision><origin xyz='0 0 0.15'/><geometry><sphere radius='0.06'/></geometry></collision></link>
<link name='l2'><collision><origin xyz='0.3 0 0'/><geometry><sphere radius='0.05'/></geometry></collision></link>
<joint name='j1' type='revolute'><parent link='base'/><child link='l1'/><origin xyz='0 0 0.1'/>
<axis xyz='0 0 1'/><limit lower='-3' upper='3' effort='1' velocity='1'/></joint>
<joint name='j2' type='revolute'><parent link='l1'/><child link='l2'/><origin xyz='0 0 0.3'/>
<axis xyz='0 1 0'/><limit lower='-3' upper='3' effort='1' velocity='1'/></joint>
</robot>"""


class TrajectoryCost(unittest.TestCase):
    def test_cost_and_gradient_against_central_differences(self):
        tree = octoprox.Octree(resolution=0.04)
        rng = np.random.default_rng(3)
        tree.insert_points(rng.uniform([-0.6, -0.6, -0.2], [0.6, 0.6, 0.8], (800, 3)),
                           mode=octoprox.INSERT_ENDPOINTS)
        arm = octoprox.LinkSet.from_urdf_string(ARM)
        query = octoprox.Query()
        q = rng.uniform(-1.2, 1.2, (6, 2))
        cost, gradient = query.trajectory_cost(tree, arm, q, activation=0.1)
        self.assertGreater(cost, 0.0)
        self.assertEqual(gradient.shape, (6, 2))
        h, checked = 1e-6, 0
        for w in range(6):
            for j in range(2):
                plus, minus = q.copy(), q.copy()
                plus[w, j] += h
                minus[w, j] -= h
                fd = (query.trajectory_cost(tree, arm, plus, 0.1)[0] -
                      query.trajectory_cost(tree, arm, minus, 0.1)[0]) / (2 * h)
                if abs(fd - gradient[w, j]) <= 1e-6 * max(abs(fd), 1e-3):
                    checked += 1
        self.assertGreaterEqual(checked, 10)  # all but kinks

    def test_a_robot_not_all_spheres(self):
        boxes = octoprox.LinkSet.from_urdf_string(
            "<robot name='b'><link name='a'><collision><geometry><box size='0.1 0.1 0.1'/>"
            "</geometry></collision></link></robot>")
        with self.assertRaisesRegex(octoprox.OctoproxError, "sphere"):
            octoprox.Query().trajectory_cost(one_cell_map(), boxes, np.zeros((1, 0)))
