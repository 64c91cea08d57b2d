"""What the package gives back and how it says no: flags are bools, codes
IntEnum members; engines and insert modes by name; errors name the Python
method (a closed handle says it is closed); octrees pickle, link sets and
queries refuse; request structs are built once per distinct keywords."""
import copy
import pickle
import unittest
from unittest import mock

import numpy as np

import octoprox
from octoprox import _requests

from scenes import C0, RES, one_cell_map, sphere_at
from test_self_collision import two_cubes
from test_urdf import ARM

TOUCHING = (0.1, 0.35, C0, C0)  # a sphere touching the one cell's face x = 0.25
FAR = (0.1, 2.0, C0, C0)


class BoolsAndEnums(unittest.TestCase):
    def test_result_flags_are_bools(self):
        tree, query = one_cell_map(), octoprox.Query()
        hit = query.collide(tree, sphere_at(*TOUCHING))
        self.assertIs(hit.collided, True)
        self.assertIs(hit.truncated, False)
        self.assertIs(query.collide(tree, sphere_at(*FAR)).collided, False)
        near = query.distance(tree, sphere_at(*FAR))
        self.assertIs(near.found, True)
        self.assertIs(near.collided, False)
        self.assertIs(query.path(tree, sphere_at(*FAR), [[[0.35, C0, C0]]]).collided, True)
        self.assertIs(query.self_collide(two_cubes(-0.01)).collided, True)
        self.assertIs(query.self_distance(two_cubes(0.01)).found, True)
        self.assertIs(tree.stats.has_occupied, True)
        self.assertEqual(hit.to_dict()["collided"], True)

    def test_codes_are_enum_members(self):
        tree = one_cell_map()
        self.assertIs(tree.classify((C0, C0, C0)).cell_class, octoprox.CellClass.OCCUPIED)
        self.assertIs(tree.classify((5, 5, 5)).cell_class, octoprox.CellClass.UNKNOWN)
        near = octoprox.Query().distance(tree, sphere_at(*FAR))
        self.assertIs(near.cell_class, octoprox.CellClass.OCCUPIED)
        self.assertIs(octoprox.Query("amortized").stats.engine, octoprox.Engine.AMORTIZED)
        robot = octoprox.LinkSet.from_urdf_string(ARM)
        self.assertIs(robot.joint_info(0).type, octoprox.JointType.REVOLUTE)
        self.assertIs(robot.shape(0, 0).kind, octoprox.ShapeKind.BOX)

    def test_constants_are_the_members(self):
        self.assertIs(octoprox.CELL_OCCUPIED, octoprox.CellClass.OCCUPIED)
        self.assertIs(octoprox.ENGINE_AMORTIZED, octoprox.Engine.AMORTIZED)
        self.assertIs(octoprox.UNKNOWN_OCCUPIED, octoprox.UnknownPolicy.OCCUPIED)
        self.assertIs(octoprox.INSERT_ENDPOINTS, octoprox.InsertMode.ENDPOINTS)
        self.assertIs(octoprox.SHAPE_MESH, octoprox.ShapeKind.MESH)
        self.assertEqual(octoprox.MASK_ALL_KNOWN, octoprox.CellMask.ALL_KNOWN)
        self.assertEqual(int(octoprox.MASK_ALL_KNOWN), 0b1110)
        # Members are ints: arrays of contacts compare with them.
        self.assertEqual(np.int32(3), octoprox.CELL_OCCUPIED)
        self.assertEqual(hash(octoprox.CELL_OCCUPIED), hash(3))


class NamesForValues(unittest.TestCase):
    def test_engines_by_name_member_or_value(self):
        for engine in ("amortized", "AMORTIZED", octoprox.Engine.AMORTIZED, 2):
            self.assertIs(octoprox.Query(engine).stats.engine, octoprox.Engine.AMORTIZED)
        self.assertIs(octoprox.Query(engine="direct").stats.engine, octoprox.Engine.DIRECT)

    def test_a_bad_engine_lists_the_valid_ones(self):
        for engine in ("fast", 7, None):
            with self.assertRaises(ValueError) as caught:
                octoprox.Query(engine=engine)
            message = str(caught.exception)
            self.assertTrue(message.startswith("Query: engine must be one of"), message)
            self.assertIn('"direct" (1), "amortized" (2)', message)

    def test_insert_modes_by_name(self):
        by_name, by_member = octoprox.Octree(resolution=RES), octoprox.Octree(resolution=RES)
        rays = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
        by_name.insert_points(rays, mode="endpoints")
        by_member.insert_points(rays, mode=octoprox.INSERT_ENDPOINTS)
        self.assertEqual(by_name.stats.leaves_free, 0)
        self.assertEqual(by_name.leaves(octoprox.MASK_ALL_KNOWN).tobytes(),
                         by_member.leaves(octoprox.MASK_ALL_KNOWN).tobytes())
        by_name.insert_points(rays, mode="raycast")
        self.assertGreater(by_name.stats.leaves_free, 0)
        with self.assertRaises(ValueError) as caught:
            by_name.insert_points(rays, mode="sideways")
        self.assertIn("Octree.insert_points: mode must be one of", str(caught.exception))
        self.assertIn('"raycast" (0), "endpoints" (1)', str(caught.exception))

    def test_request_values_by_name(self):
        hit = octoprox.Query().collide(one_cell_map(), sphere_at(*FAR), unknown_policy="occupied")
        self.assertTrue(hit.collided)
        with self.assertRaisesRegex(ValueError, "Query.distance: obstacle_geometry must be one of"):
            octoprox.Query().distance(one_cell_map(), sphere_at(*FAR), obstacle_geometry="voxels")


class ErrorsNameTheMethod(unittest.TestCase):
    def test_a_closed_handle_says_so(self):
        tree, ball, query = one_cell_map(), sphere_at(*FAR), octoprox.Query()
        tree.close()
        cases = {
            "Octree.insert_points: the octree is closed": lambda: tree.insert_points([[1, 0, 0]]),
            "Octree.stats: the octree is closed": lambda: tree.stats,
            "Query.collide: the octree is closed": lambda: query.collide(tree, ball),
            "Query.path: the octree is closed": lambda: query.path(tree, ball, [[[0, 0, 0]]]),
        }
        ball.close()
        cases["Query.distance: the link set is closed"] = \
            lambda: query.distance(one_cell_map(), ball)
        cases["LinkSet.add_link: the link set is closed"] = lambda: ball.add_link("x")
        cases["Query.self_collide: the link set is closed"] = lambda: query.self_collide(ball)
        for expected, call in cases.items():
            with self.assertRaises(octoprox.InvalidArgumentError) as caught:
                call()
            self.assertEqual(str(caught.exception), expected)
        query.close()
        with self.assertRaises(ValueError) as caught:
            query.collide(one_cell_map(), sphere_at(*FAR))
        self.assertEqual(str(caught.exception), "Query.collide: the query is closed")
        self.assertTrue(query.closed)

    def test_library_errors_carry_the_method_and_the_c_message(self):
        robot = octoprox.LinkSet()
        with self.assertRaises(octoprox.InvalidArgumentError) as caught:
            robot.add_sphere(robot.add_link("hand"), -1.0)
        error = caught.exception
        self.assertEqual(error.where, "LinkSet.add_sphere")
        self.assertTrue(error.message.startswith("opx_linkset_add_shape: "), error.message)
        self.assertEqual(str(error), "LinkSet.add_sphere: " + error.message)
        with self.assertRaises(ValueError) as caught:
            octoprox.Query().collide(one_cell_map(), sphere_at(*FAR), occupancy_threshold=2.0)
        self.assertTrue(str(caught.exception).startswith(
            "Query.collide: opx_query_collide: request->occupancy_threshold"))
        copied = pickle.loads(pickle.dumps(error))
        self.assertEqual((type(copied), str(copied), copied.status),
                         (type(error), str(error), error.status))

    def test_bad_keyword_values_name_the_method_and_keyword(self):
        tree, ball = one_cell_map(), sphere_at(*FAR)
        with self.assertRaisesRegex(TypeError, "^Query.collide: max_contacts: "):
            octoprox.Query().collide(tree, ball, max_contacts="all")
        with self.assertRaisesRegex(ValueError, "^Query.path: .*region_min.*3 values"):
            octoprox.Query().path(tree, ball, [[[0, 0, 0]]], region_min=(1.0, 2.0))
        with self.assertRaisesRegex(TypeError, "^Query.collide: expected an Octree and a LinkSet"):
            octoprox.Query().collide(ball, tree)


class Pickling(unittest.TestCase):
    def test_an_octree_round_trips_with_its_leaves_and_options(self):
        tree = octoprox.Octree(resolution=0.1, free_threshold=0.3, prob_hit=0.8)
        rng = np.random.default_rng(4)
        for _ in range(3):
            tree.insert_points(rng.uniform(-1, 1, size=(200, 3)), sensor_pose=(0.1, 0.2, 0.3))
        for copied in (pickle.loads(pickle.dumps(tree)), copy.deepcopy(tree)):
            self.assertEqual(copied.leaves(octoprox.MASK_ALL_KNOWN).tobytes(),
                             tree.leaves(octoprox.MASK_ALL_KNOWN).tobytes())
            self.assertEqual(copied.options.to_dict(), tree.options.to_dict())
            self.assertGreater(copied.stats.leaves_uncertain, 0)

    def test_link_sets_and_queries_refuse_with_a_reason(self):
        for handle, reason in ((sphere_at(*FAR), "clone()"), (octoprox.Query(), "one in each")):
            with self.assertRaises(TypeError) as caught:
                pickle.dumps(handle)
            self.assertIn("cannot be pickled", str(caught.exception))
            self.assertIn(reason, str(caught.exception))


class RequestCache(unittest.TestCase):
    def test_a_repeated_query_builds_no_request(self):
        tree, ball, query = one_cell_map(), sphere_at(*TOUCHING), octoprox.Query()
        query.collide(tree, ball, max_contacts=4)
        query.collide(tree, ball)
        query.distance(tree, ball, cutoff=1.0)
        with mock.patch.object(_requests.RequestCache, "build", side_effect=AssertionError):
            for _ in range(3):
                self.assertTrue(query.collide(tree, ball).collided)
                self.assertEqual(query.collide(tree, ball, max_contacts=4).contact_count, 1)
                self.assertEqual(query.distance(tree, ball, cutoff=1.0).distance, 0.0)

    def test_arrays_and_lists_as_keywords(self):
        tree, ball, query = one_cell_map(), sphere_at(*FAR), octoprox.Query()
        region = dict(compute_cost=True, region_min=(-3.0, -3.0, -3.0), region_max=(3.0, 3.0, 3.0))
        expected = query.collide(tree, ball, **region).total_cost
        self.assertGreater(expected, 0.0)
        for kind in (np.array, list):
            for _ in range(2):
                result = query.collide(tree, ball, compute_cost=True,
                                       region_min=kind(region["region_min"]),
                                       region_max=kind(region["region_max"]))
                self.assertEqual(result.total_cost, expected)

    def test_many_distinct_cutoffs_keep_the_cache_small(self):
        tree, ball, query = one_cell_map(), sphere_at(*FAR), octoprox.Query()
        for i in range(200):
            query.distance(tree, ball, cutoff=1.0 + i)
        self.assertLessEqual(len(query._distance_requests._by_key), 64)


if __name__ == "__main__":
    unittest.main()
