"""Query.collide and Query.distance through the compiled call path
(octoprox._fastcall) and through ctypes alone answer and fail alike: every
scenario runs twice in one process, once as the package runs it and once
with the compiled path switched off, and the results (or the errors' types
and messages) must be equal.  ctest runs the whole suite both ways too:
python_unittest with the module the build puts beside the library
(OPX_EXPECT_EXTENSION=1), python_unittest_ctypes with OPX_CTYPES_ONLY=1."""
import ctypes
import os
import threading
import unittest
from unittest import mock

import numpy as np

import octoprox
from octoprox import _calls, query as query_module

from scenes import C0, RES, one_cell_map, sphere_at


def switched_on(variable):
    return os.environ.get(variable, "0") not in ("", "0")


def outcome(call):
    """call()'s result as a dict with the query's rows, or its error as
    (type, message)."""
    try:
        result = call()
    except Exception as error:  # the comparison is the test
        return type(error).__name__, str(error)
    return result.to_dict()


class ServedCalls:
    """Counts the calls the compiled path serves (it returns a result or
    a status) and those it leaves to ctypes (None)."""

    def __init__(self, name):
        self.name, self.served, self.deferred = name, 0, 0
        self.call = getattr(query_module, name)

    def __call__(self, *args):
        out = self.call(*args)
        if out is None:
            self.deferred += 1
        else:
            self.served += 1
        return out


class TheEnvironmentChoosesThePath(unittest.TestCase):
    def test_the_compiled_path_is_used_as_the_environment_says(self):
        if switched_on("OPX_CTYPES_ONLY"):
            self.assertIsNone(_calls.EXTENSION)
            self.assertIsNone(query_module._collide_cached)
        elif switched_on("OPX_EXPECT_EXTENSION"):
            self.assertIsNotNone(_calls.EXTENSION, "the build made octoprox_fastcall, not found")
            self.assertIsNotNone(query_module._collide_cached)
            self.assertIsNotNone(query_module._distance_cached)
        else:
            self.skipTest("neither OPX_CTYPES_ONLY nor OPX_EXPECT_EXTENSION set")

    def test_binding_checks_its_arguments(self):
        if _calls.EXTENSION is None:
            self.skipTest("no compiled call path")
        with self.assertRaises(ValueError):
            _calls.EXTENSION.bind(0, octoprox.CollisionResult, octoprox.Octree, octoprox.LinkSet)
        with self.assertRaises(TypeError):
            _calls.EXTENSION.bind(1, "not a type", octoprox.Octree, octoprox.LinkSet)
        call = _calls.cached_call("opx_query_collide", octoprox.CollisionResult, octoprox.Octree,
                                  octoprox.LinkSet)
        with self.assertRaises(TypeError):
            call(1, 2)


@unittest.skipIf(_calls.EXTENSION is None, "no compiled call path (built beside the library)")
class BothPathsAgree(unittest.TestCase):
    def setUp(self):
        self.tree = one_cell_map()
        self.touching = sphere_at(0.1, 0.35, C0, C0)
        self.apart = sphere_at(0.1, 0.5, C0, C0)

    def both(self, scenario):
        """scenario(query) run on the compiled path (twice: the second
        call of a key is the one it serves) and on ctypes alone, each with
        a fresh Query; returns the compiled and the ctypes outcomes."""
        compiled = [outcome(lambda: scenario(query)) for query in [octoprox.Query()] * 2]
        with mock.patch.object(query_module, "_collide_cached", None), \
                mock.patch.object(query_module, "_distance_cached", None):
            plain = [outcome(lambda: scenario(query)) for query in [octoprox.Query()] * 2]
        self.assertEqual(compiled, plain)
        return compiled[-1]

    def test_collisions_with_each_request(self):
        for keywords in ({}, {"max_contacts": 0}, {"max_contacts": octoprox.ALL_CONTACTS},
                         {"compute_penetration": True}, {"unknown_policy": "occupied"},
                         {"compute_cost": True, "max_cost_boxes": 4},
                         {"obstacle_geometry": octoprox.OBSTACLE_POINT_EXTENTS}):
            for links in (self.touching, self.apart):
                with self.subTest(keywords=keywords, links=links is self.touching):
                    def collide(query):
                        result = query.collide(self.tree, links, **keywords)
                        return Rows(result, query.contacts(), query.cost_boxes())
                    self.both(collide)

    def test_distances_with_each_request(self):
        for keywords in ({}, {"per_link": True}, {"cutoff": 0.05}, {"signed_distance": True},
                         {"abs_err": 0.01, "rel_err": 0.1}):
            for links in (self.touching, self.apart):
                with self.subTest(keywords=keywords, links=links is self.touching):
                    def distance(query):
                        result = query.distance(self.tree, links, **keywords)
                        return Rows(result, query.link_distances())
                    self.both(distance)

    def test_the_usual_call_is_served_and_the_others_are_left_to_ctypes(self):
        counter = ServedCalls("_collide_cached")
        query = octoprox.Query()
        with mock.patch.object(query_module, "_collide_cached", counter):
            first = query.collide(self.tree, self.touching)  # the request is built
            second = query.collide(self.tree, self.touching)
            query.collide(self.tree, self.touching, region_min=np.zeros(3))  # an array: not kept
            query.collide(self.tree, self.touching, world=octoprox.World())
        self.assertEqual((counter.served, counter.deferred), (1, 2))
        self.assertIsNot(first, second)  # a new result every call
        self.assertEqual(first.to_dict(), second.to_dict())
        self.assertEqual(second.struct_size, ctypes.sizeof(octoprox.CollisionResult))

    def test_closed_handles_are_named(self):
        nouns = {"tree": "octree", "links": "link set", "query": "query"}
        for closing, noun in nouns.items():
            with self.subTest(closing=closing):
                def collide(query):
                    operands = {"tree": one_cell_map(), "links": sphere_at(0.1, 0.35, C0, C0),
                                "query": query}
                    query.collide(operands["tree"], operands["links"])
                    operands[closing].close()
                    return query.collide(operands["tree"], operands["links"])
                error = self.both(collide)
                self.assertEqual(error[0], "InvalidArgumentError")
                self.assertEqual(error[1], f"Query.collide: the {noun} is closed")

    def test_operands_of_the_wrong_types_and_bad_values(self):
        cases = {
            "a link set as the octree": lambda q: q.collide(self.touching, self.touching),
            "a string as the links": lambda q: q.distance(self.tree, "ball"),
            "no octree and no world": lambda q: q.collide(None, self.touching),
            "an unknown policy": lambda q: q.collide(self.tree, self.touching,
                                                     unknown_policy="sometimes"),
            "a threshold the library refuses": lambda q: q.collide(self.tree, self.touching,
                                                                   occupancy_threshold=2.0),
            "a negative cutoff": lambda q: q.distance(self.tree, self.touching, cutoff=-1.0),
        }
        for name, scenario in cases.items():
            with self.subTest(name):
                def twice(query):  # the second call has the first one's key
                    outcome(lambda: scenario(query))
                    return scenario(query)
                error = self.both(twice)
                self.assertIsInstance(error, tuple, "expected an error")
                self.assertRegex(error[1], r"^Query\.(collide|distance)")

    def test_queries_in_threads_answer_as_alone(self):
        answers = []

        def worker():
            query = octoprox.Query()
            for _ in range(200):
                answers.append(query.collide(self.tree, self.touching).collided)
        threads = [threading.Thread(target=worker) for _ in range(4)]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        self.assertEqual(answers, [True] * 800)


class Rows:
    """A result with the rows its query holds after it, compared as dicts."""

    def __init__(self, result, *rows):
        self.result, self.rows = result, rows

    def to_dict(self):
        return {"result": self.result.to_dict(),
                "rows": [(str(array.dtype), array.tobytes()) for array in self.rows]}


if __name__ == "__main__":
    unittest.main()
