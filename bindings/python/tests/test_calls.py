"""Query.collide and Query.distance as compiled methods
(octoprox._fastcall) and as Python methods on ctypes alone answer and fail alike: every
scenario runs twice in one process, once as the package runs it and once
with the compiled path switched off, and the results (or the errors' types
and messages) must be equal.  ctest runs the whole suite both ways too:
python_unittest with the module the build puts beside the library
(OPX_EXPECT_EXTENSION=1), python_unittest_ctypes with OPX_CTYPES_ONLY=1."""
import contextlib
import ctypes
import inspect
import os
import threading
import typing
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


def python_method(name):
    method = getattr(octoprox.Query, name)
    return getattr(method, "__wrapped__", method)


def ctypes_alone():
    """The methods as without the compiled module: the Python methods."""
    patches = contextlib.ExitStack()
    for name in ("collide", "distance"):
        patches.enter_context(mock.patch.object(octoprox.Query, name, python_method(name)))
    return patches


class CountedMethod:
    """Query.collide's Python method, counting the calls the compiled
    method leaves to it."""

    def __init__(self):
        self.method = python_method("collide")
        self.__kwdefaults__ = self.method.__kwdefaults__
        self.calls = 0

    def __call__(self, *args, **keywords):
        self.calls += 1
        return self.method(*args, **keywords)

    def compiled(self):
        return _calls.compiled_method(self, "opx_query_collide", query_module._DEFAULT_COLLIDE,
                                      octoprox.CollisionResult, octoprox.Query, octoprox.Octree,
                                      octoprox.LinkSet, "_map_result", "_collide_requests",
                                      query_module._COLLIDE)


class TheEnvironmentChoosesThePath(unittest.TestCase):
    def test_the_compiled_path_is_used_as_the_environment_says(self):
        compiled = type(octoprox.Query.collide).__name__ == "method"
        if switched_on("OPX_CTYPES_ONLY"):
            self.assertIsNone(_calls.EXTENSION)
            self.assertFalse(compiled)
        elif switched_on("OPX_EXPECT_EXTENSION"):
            self.assertIsNotNone(_calls.EXTENSION, "the build made octoprox_fastcall, not found")
            self.assertTrue(compiled)
            self.assertEqual(type(octoprox.Query.distance).__name__, "method")
        else:
            self.skipTest("neither OPX_CTYPES_ONLY nor OPX_EXPECT_EXTENSION set")

    def test_binding_checks_its_arguments(self):
        if _calls.EXTENSION is None:
            self.skipTest("no compiled call path")
        types = (octoprox.CollisionResult, octoprox.Query, octoprox.Octree, octoprox.LinkSet)
        good = (print, 1, 1) + types + (None, "_collide_requests", ("a",), (0,))
        _calls.EXTENSION.method(*good)
        for at, bad in ((1, 0), (2, 0), (3, "not a type"), (7, 5), (8, None), (9, ("a", 1)),
                        (10, (0, 1)), (9, ()), (10, ())):
            with self.subTest(argument=at, value=bad):
                with self.assertRaises((TypeError, ValueError)):
                    _calls.EXTENSION.method(*good[:at], bad, *good[at + 1:])
        with self.assertRaises(TypeError):
            _calls.EXTENSION.method(*good[:-1])
        with self.assertRaises(TypeError):
            _calls.EXTENSION.method(*good, 1)

    def test_the_compiled_methods_show_the_python_methods(self):
        for name in ("collide", "distance"):
            method = getattr(octoprox.Query, name)
            python = getattr(method, "__wrapped__", method)
            self.assertEqual(inspect.signature(method), inspect.signature(python))
            self.assertEqual(method.__doc__, python.__doc__)
            self.assertEqual(inspect.getdoc(method), inspect.getdoc(python))
            self.assertEqual(method.__qualname__, f"Query.{name}")
            self.assertEqual(typing.get_type_hints(method), typing.get_type_hints(python))
            self.assertTrue(inspect.isroutine(method))


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
        with ctypes_alone():
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

    def test_the_usual_call_is_served_and_the_others_are_left_to_python(self):
        counted = CountedMethod()
        query = octoprox.Query()
        with mock.patch.object(octoprox.Query, "collide", counted.compiled()):
            first = query.collide(self.tree, self.touching)  # the default request
            second = query.collide(self.tree, self.touching, world=None)  # its key not cached yet
            self.assertEqual(counted.calls, 1)
            query.collide(self.tree, self.touching, world=None)
            query.collide(self.tree, self.touching, max_contacts=2)  # the request is built
            query.collide(self.tree, self.touching, max_contacts=2)
            query.collide(self.tree, self.touching, max_contacts=2, unknown_policy=0)
            self.assertEqual(counted.calls, 2)
            query.collide(self.tree, self.touching, region_min=np.zeros(3))  # an array: not kept
            query.collide(self.tree, self.touching, region_min=np.zeros(3))
            query.collide(self.tree, self.touching, world=octoprox.World())
            self.assertEqual(counted.calls, 5)
            with self.assertRaises(TypeError):
                query.collide(self.tree, self.touching, no_such_keyword=1)
            self.assertEqual(counted.calls, 6)
            last = query.collide(self.tree, self.touching)
        self.assertIs(query._map_result, last)  # what contacts() reads
        self.assertEqual(query.contacts()["link"].tolist(), [0])
        self.assertIsNot(first, second)  # a new result every call
        self.assertEqual(first.to_dict(), second.to_dict())
        self.assertEqual(second.struct_size, ctypes.sizeof(octoprox.CollisionResult))

    def test_the_method_is_called_as_python_methods_are(self):
        class Subclass(octoprox.Query):
            pass
        for query in (octoprox.Query(), Subclass()):
            bound = query.collide
            self.assertTrue(bound(self.tree, self.touching).collided)
            self.assertTrue(octoprox.Query.collide(query, self.tree, self.touching).collided)
            self.assertFalse(type(query).distance(query, self.tree, self.apart).collided)
        with self.assertRaises(TypeError):
            octoprox.Query().collide(self.tree)

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
