"""Collision, distance, cost and path queries on the scenes of the C and
Rust tests; results as structs and numpy structured arrays; threads."""
import threading
import unittest
from unittest import mock

import numpy as np

import octoprox
from octoprox import _arrays

from scenes import C0, RES, one_cell_map, sphere_at


class Collide(unittest.TestCase):
    def test_a_touching_sphere_collides_and_reports_the_cell(self):
        tree = one_cell_map()
        query = octoprox.Query()
        # Sphere r 0.1 at x = 0.35 touches the cell face x = 0.25.
        result = query.collide(tree, sphere_at(0.1, 0.35, C0, C0))
        self.assertEqual((result.collided, result.contact_count), (1, 1))
        contacts = query.contacts()
        self.assertEqual(contacts.dtype, _arrays.CONTACT_DTYPE)
        self.assertEqual((contacts["link"][0], contacts["shape"][0]), (0, 0))
        np.testing.assert_array_equal(contacts["cell_center"][0], [C0, C0, C0])
        self.assertEqual(contacts["cell_class"][0], octoprox.CELL_OCCUPIED)
        self.assertEqual(query.collide(tree, sphere_at(0.1, 0.5, C0, C0)).collided, 0)
        self.assertEqual(len(query.contacts()), 0)

    def test_unknown_space_and_penetration(self):
        tree = one_cell_map()
        query = octoprox.Query()
        far = sphere_at(0.1, 2, 2, 2)
        result = query.collide(tree, far, unknown_policy=octoprox.UNKNOWN_OCCUPIED)
        self.assertEqual(result.collided, 1)
        self.assertEqual(query.contacts()["cell_class"][0], octoprox.CELL_UNKNOWN)
        near = sphere_at(0.1, 0.4, C0, C0)  # 0.05 m from the cell
        self.assertEqual(query.collide(tree, near).collided, 0)
        near.set_padding(0.08)
        self.assertEqual(query.collide(tree, near, compute_penetration=True).collided, 1)
        contact = query.contacts()[0]
        self.assertAlmostEqual(contact["depth"], 0.03, places=6)
        self.assertAlmostEqual(contact["normal"][0], -1.0, places=6)

    def test_cost_of_unknown_space_behind_an_obstacle(self):
        # tests/c/test_query_cost.c: a bar through free cells, an occupied
        # cell and unknown space behind it.
        tree = octoprox.Octree(resolution=RES)
        tree.insert_points([[1.0, 0, 0]], sensor_pose=(C0, C0, C0))
        bar = octoprox.LinkSet()
        bar.add_box(bar.add_link("bar"), (1.325, 0.15, 0.15))
        bar.set_poses([[1.2125, C0, C0]])
        query = octoprox.Query()
        result = query.collide(tree, bar, compute_cost=True, region_max=(2.0, RES, RES))
        small, large = 0.5 * 0.25 * 0.0225, 0.5 * 0.375 * 0.0225
        self.assertEqual((result.collided, result.cost_box_count), (1, 2))
        self.assertAlmostEqual(result.total_cost, small + large, places=12)
        boxes = query.cost_boxes()
        self.assertEqual(boxes.dtype, _arrays.COST_BOX_DTYPE)
        np.testing.assert_allclose(boxes["cost"], [large, small], atol=1e-12)
        self.assertTrue((boxes["cell_class"] == octoprox.CELL_UNKNOWN).all())
        np.testing.assert_allclose(boxes["max"][0], [1.875, 0.2, 0.2], atol=1e-9)


class Distance(unittest.TestCase):
    def test_distance_witnesses_and_per_link(self):
        tree = one_cell_map()
        robot = octoprox.LinkSet()
        above, beside = robot.add_link("above"), robot.add_link("beside")
        robot.add_sphere(above, 0.1)
        robot.add_box(beside, (0.1, 0.1, 0.1))
        robot.set_poses([[C0, C0, 1.0, 0, 0, 0, 1], [C0, 1.0, C0, 0, 0, 0, 1]])
        query = octoprox.Query()
        result = query.distance(tree, robot, per_link=True)
        self.assertEqual((result.found, result.collided, result.link), (1, 0, above))
        self.assertAlmostEqual(result.distance, 0.65, places=9)
        self.assertAlmostEqual(result.point_on_cell[2], 0.25, places=9)
        np.testing.assert_allclose(query.link_distances(), [0.65, 0.7], atol=1e-9)
        robot.set_link_enabled(above, False)
        self.assertEqual(query.distance(tree, robot).link, beside)
        self.assertEqual(len(query.link_distances()), 0)

    def test_the_amortized_engine_gives_the_direct_answer(self):
        tree = one_cell_map()
        query = octoprox.Query(engine="amortized")
        self.assertAlmostEqual(query.distance(tree, sphere_at(0.1, C0, C0, 1.0)).distance, 0.65)
        stats = query.stats
        self.assertEqual((stats.engine, stats.builds, stats.boxes),
                         (octoprox.ENGINE_AMORTIZED, 1, 1))


class CallerBoxes(unittest.TestCase):
    def test_boxes_strided_in_place_answer_like_the_cell(self):
        # The one cell as a box, every other row of a (2, 6) view: stride 96.
        table = np.zeros((2, 12))
        table[:, :6] = [[0, 0, 0, RES, RES, RES], [5, 5, 5, 6, 6, 6]]
        query = octoprox.Query(engine="amortized")
        query.bind_boxes(table[:, :6])
        ball = sphere_at(0.1, C0, C0, 1.0)
        expected = octoprox.Query().distance(one_cell_map(), ball).distance
        result = query.distance_boxes(ball)
        self.assertAlmostEqual(result.distance, expected, places=12)
        self.assertEqual(list(result.cell_center), [C0, C0, C0])
        self.assertFalse(query.collide_boxes(ball).collided)
        touching = sphere_at(0.1, 0.35, C0, C0)
        self.assertTrue(query.collide_boxes(touching, max_contacts=4).collided)
        self.assertEqual(len(query.contacts()), 1)
        self.assertEqual(query.stats.boxes, 2)

    def test_bad_boxes_and_a_direct_context_are_refused(self):
        with self.assertRaises(octoprox.InvalidArgumentError):
            octoprox.Query(engine="amortized").bind_boxes(np.zeros((3, 5)))
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "OPX_ENGINE_AMORTIZED"):
            octoprox.Query().bind_boxes([[0, 0, 0, 1, 1, 1]])
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "boxes\\[0\\]"):
            octoprox.Query(engine="amortized").bind_boxes([[0, 0, 0, 1, np.nan, 1]])


class Paths(unittest.TestCase):
    def test_first_colliding_waypoint(self):
        tree = one_cell_map()
        ball = sphere_at(0.1, 2.0, C0, C0)
        # The sphere moves in along x: 1.0, 0.6, 0.3 (touching), 0.2.
        poses = [[[x, C0, C0]] for x in (1.0, 0.6, 0.3, 0.2)]
        query = octoprox.Query()
        result = query.path(tree, ball, poses, compute_distance=True)
        self.assertEqual((result.collided, result.first_colliding_waypoint), (1, 2))
        self.assertEqual(ball.pose(0)[0], 2.0)  # not moved
        self.assertEqual(query.path(tree, ball, poses[:2]).first_colliding_waypoint, -1)

    def test_strided_poses_are_read_in_place(self):
        tree = one_cell_map()
        ball = sphere_at(0.1, 2.0, C0, C0)
        # A (waypoints, links, 7) view of a bigger array: every other row.
        big = np.zeros((8, 1, 9))
        big[:, 0, 6] = 1.0
        big[::2, 0, 0] = [1.0, 0.6, 0.3, 0.2]
        big[:, 0, 1:3] = C0
        view = big[::2, :, :7]
        with mock.patch.object(np, "ascontiguousarray", side_effect=AssertionError("copied")):
            arr = _arrays.pose_array(view, "test", 3)
            self.assertEqual(arr.ctypes.data, big.ctypes.data)
            result = octoprox.Query().path(tree, ball, view)
        self.assertEqual(result.first_colliding_waypoint, 2)


class Shapes(unittest.TestCase):
    def test_every_shape_kind(self):
        tetra = np.array([[0, 0, 0], [0.1, 0, 0], [0, 0.1, 0], [0, 0, 0.1]])
        faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
        robot = octoprox.LinkSet()
        tool = robot.add_link("tool")
        self.assertEqual(robot.add_cylinder(tool, 0.05, 0.2), 0)
        self.assertEqual(robot.add_capsule(tool, 0.05, 0.2, pose=(0, 0, 0.1)), 1)
        self.assertEqual(robot.add_convex(tool, tetra), 2)
        self.assertEqual(robot.add_mesh(tool, tetra, faces), 3)
        strided = np.zeros((4, 5))
        strided[:, :3] = tetra
        self.assertEqual(robot.add_convex(tool, strided[:, :3]), 4)
        self.assertEqual(robot.shape_count(tool), 5)
        capsule = robot.shape(tool, 1)
        self.assertEqual((capsule.kind, capsule.radius, capsule.length, capsule.pose[2]),
                         (octoprox.SHAPE_CAPSULE, 0.05, 0.2, 0.1))
        mesh = robot.shape(tool, 3)
        # A stored mesh renumbers its vertices: compare the triangles' corners.
        np.testing.assert_array_equal(mesh.vertices[mesh.triangles], tetra[np.array(faces)])
        self.assertEqual(len(robot.shape(tool, 2).vertices), 4)
        with self.assertRaises(ValueError):
            robot.shape(tool, 5)
        self.assertEqual((robot.find_link("tool"), robot.link_names), (tool, ["tool"]))
        with robot.clone() as copy:
            self.assertEqual(copy.shape_count(tool), 5)


class Threads(unittest.TestCase):
    def test_queries_from_several_threads_on_one_octree(self):
        tree = one_cell_map()
        robot = octoprox.LinkSet()
        for i in range(8):
            robot.add_sphere(robot.add_link(f"link{i}"), 0.1)
        robot.set_poses([[C0, C0, 0.45 + 0.01 * i] for i in range(8)])
        answers, errors = [], []

        def worker():
            try:
                with octoprox.Query() as query:
                    for _ in range(50):
                        near = query.distance(tree, robot, per_link=True)
                        hit = query.collide(tree, robot)
                        answers.append((near.distance, hit.collided, len(query.link_distances())))
            except Exception as error:  # reported below, in the main thread
                errors.append(error)

        threads = [threading.Thread(target=worker) for _ in range(4)]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        self.assertEqual(errors, [])
        self.assertEqual(len(answers), 200)
        for distance, collided, links in answers:
            self.assertAlmostEqual(distance, 0.1, places=9)
            self.assertEqual((collided, links), (0, 8))


if __name__ == "__main__":
    unittest.main()
