"""What help() shows: every public name of the package has a docstring,
the query methods take the fields of their C requests as named keywords
with the C defaults, every keyword reaches its field, type hints resolve,
and the package ships py.typed."""
import importlib
import inspect
import os
import pkgutil
import pydoc
import sys
import typing
import unittest

import numpy as np

import octoprox
from octoprox import _library, _structs as s

from scenes import C0, REPO, one_cell_map, sphere_at
from test_batch import load_arm, scatter_map

PACKAGE = os.path.join(REPO, "bindings", "python")


def modules():
    """Every module of the package, private ones included."""
    names = [info.name for info in pkgutil.iter_modules(octoprox.__path__, "octoprox.")]
    return [octoprox] + [importlib.import_module(name) for name in names]


def defined_in(module):
    """The public classes and functions a module defines (not imports)."""
    for name, value in vars(module).items():
        if not name.startswith("_") and (inspect.isclass(value) or inspect.isfunction(value)) \
                and value.__module__ == module.__name__:
            yield name, value


def own_members(cls):
    """The public methods and properties a class itself defines, and its
    own __init__ (help() would show an inherited docstring)."""
    for name, value in vars(cls).items():
        if name.startswith("_") and name != "__init__":
            continue
        if isinstance(value, (staticmethod, classmethod)):
            value = value.__func__
        if inspect.isfunction(value) or isinstance(value, property):
            yield name, value


def request_fields(struct_type):
    """The fields a caller sets: all but struct_size and reserved*."""
    return [name for name, _ in struct_type._fields_
            if name != "struct_size" and not name.startswith("reserved")]


def c_default(struct_type, name):
    value = getattr(_library.init_struct(struct_type), name)
    return tuple(value) if hasattr(value, "__len__") else value


class EveryPublicNameHasADocstring(unittest.TestCase):
    def test_modules_classes_functions_methods_and_properties(self):
        missing = []
        for module in modules():
            if not (module.__doc__ or "").strip():
                missing.append(module.__name__)
            for name, value in defined_in(module):
                if not (value.__doc__ or "").strip():
                    missing.append(f"{module.__name__}.{name}")
                if inspect.isclass(value):
                    missing += [f"{module.__name__}.{name}.{member}"
                                for member, item in own_members(value)
                                if not (item.__doc__ or "").strip()]
        self.assertEqual(missing, [])

    def test_every_exported_class_and_function(self):
        for name in octoprox.__all__:
            value = getattr(octoprox, name)
            if inspect.isclass(value) or inspect.isfunction(value) or inspect.ismodule(value):
                self.assertTrue((value.__doc__ or "").strip(), name)

    def test_help_shows_the_keywords_and_what_they_mean(self):
        text = pydoc.render_doc(octoprox.Query.collide, renderer=pydoc.plaintext)
        for words in ("obstacle_geometry: 'ObstacleGeometryLike' = <ObstacleGeometry.CELLS: 0>",
                      "max_contacts: 'int' = 1", "unknown_policy", "Returns a CollisionResult",
                      "(m^3)"):
            self.assertIn(words, text)
        self.assertIn("Query.collide", octoprox.CollisionRequest.__doc__)
        self.assertIn("max_contacts", octoprox.CollisionRequest.__doc__)


# method -> (request struct, the method's names of fields it names otherwise, fields it omits)
KEYWORDS = {
    "collide": (s.CollisionRequest, {}, ()),
    "distance": (s.DistanceRequest, {}, ()),
    "path": (s.PathRequest, {}, ()),
    "self_collide": (s.SelfCollisionRequest, {}, ()),
    "self_distance": (s.SelfDistanceRequest, {}, ()),
    "check_configurations": (s.BatchRequest,
                             {"threads": "max_threads", "distance": "compute_distance"}, ()),
    "check_motion": (s.MotionRequest, {"certified": "check"}, ("max_threads",)),
    "distance_spheres": (s.SphereDistanceRequest, {"threads": "max_threads"}, ()),
    "trajectory_cost": (s.TrajectoryCostRequest, {}, ()),
    "check_motions": (s.MotionRequest, {"threads": "max_threads", "certified": "check"},
                      ("compute_cost", "max_cost_boxes", "unknown_probability", "region_min",
                       "region_max")),
}


class QueryKeywords(unittest.TestCase):
    def test_every_request_field_is_a_keyword_with_the_c_default(self):
        for method, (struct_type, renamed, omitted) in KEYWORDS.items():
            parameters = inspect.signature(getattr(octoprox.Query, method)).parameters
            fields = {renamed.get(name, name): p for name, p in parameters.items()}
            for field in request_fields(struct_type):
                if field in omitted:
                    self.assertNotIn(field, fields, method)
                    continue
                self.assertIn(field, fields, f"Query.{method} lacks {field}")
                default = fields[field].default
                default = tuple(default) if isinstance(default, tuple) else default
                self.assertEqual(default, c_default(struct_type, field), f"{method}.{field}")
            self.assertFalse(any(p.kind == p.VAR_KEYWORD for p in parameters.values()), method)

    def test_the_obstacle_geometry_constants(self):
        self.assertIs(octoprox.OBSTACLE_CELLS, octoprox.ObstacleGeometry.CELLS)
        self.assertIs(octoprox.OBSTACLE_POINT_EXTENTS, octoprox.ObstacleGeometry.POINT_EXTENTS)
        self.assertEqual((octoprox.OBSTACLE_CELLS, octoprox.OBSTACLE_POINT_EXTENTS), (0, 1))
        for method in ("collide", "distance", "path", "check_configurations", "check_motion",
                       "check_motions"):
            parameter = inspect.signature(getattr(octoprox.Query, method)).parameters
            self.assertIs(parameter["obstacle_geometry"].default, octoprox.OBSTACLE_CELLS)

    def assert_reaches(self, cache, call, values):
        """Each keyword, set alone to a value other than its default, is in
        the struct the call passed (the cache's last request)."""
        for name, value in values.items():
            call(**{name: value})
            struct = cache.request._obj
            got = getattr(struct, name)
            got = tuple(got) if hasattr(got, "__len__") else got
            self.assertEqual(got, value, name)

    def test_every_keyword_reaches_its_field(self):
        tree, ball, query = one_cell_map(), sphere_at(0.1, 2.0, C0, C0), octoprox.Query()
        extents = octoprox.OBSTACLE_POINT_EXTENTS
        shared = dict(unknown_policy=octoprox.UNKNOWN_OCCUPIED, occupancy_threshold=0.6,
                      obstacle_geometry=extents)
        cost = dict(compute_cost=True, max_cost_boxes=5, unknown_probability=0.25,
                    region_min=(-1.0, -2.0, -3.0), region_max=(1.0, 2.0, 3.0))
        self.assert_reaches(query._collide_requests, lambda **k: query.collide(tree, ball, **k),
                            dict(shared, **cost, max_contacts=3, compute_penetration=True))
        self.assert_reaches(query._distance_requests, lambda **k: query.distance(tree, ball, **k),
                            dict(shared, abs_err=0.01, rel_err=0.1, cutoff=5.0, per_link=True,
                                 signed_distance=True))
        poses = [[[1.0, C0, C0]], [[0.6, C0, C0]]]
        self.assert_reaches(query._path_requests, lambda **k: query.path(tree, ball, poses, **k),
                            dict(shared, **cost, compute_distance=True))
        self.assert_reaches(query._self_collide_requests, lambda **k: query.self_collide(ball, **k),
                            dict(max_contacts=0, compute_penetration=True))
        self.assert_reaches(query._self_distance_requests,
                            lambda **k: query.self_distance(ball, **k),
                            dict(signed_distance=True, cutoff=0.5))

    def test_every_batch_keyword_reaches_its_field(self):
        arm, tree, query = load_arm(), scatter_map(), octoprox.Query()
        rows = np.zeros((2, 7))
        shared = dict(unknown_policy=octoprox.UNKNOWN_OCCUPIED, occupancy_threshold=0.6,
                      obstacle_geometry=octoprox.OBSTACLE_POINT_EXTENTS,
                      joint_order=octoprox.JOINTS_ACTIVE)
        self.assert_reaches(query._configuration_requests,
                            lambda **k: query.check_configurations(tree, arm, rows, **k),
                            dict(shared, self_collision=True, distance_cutoff=0.5))
        self.assert_reaches(query._motion_requests,
                            lambda **k: query.check_motion(tree, arm, rows[0], rows[1] + 0.1, **k),
                            dict(shared, resolution=0.05, self_collision=True, compute_cost=True,
                                 max_cost_boxes=5, unknown_probability=0.25,
                                 region_min=(-1.0, -1.0, 0.0), region_max=(1.0, 1.0, 2.0)))
        self.assert_reaches(query._motions_requests,
                            lambda **k: query.check_motions(tree, arm, rows, rows + 0.1, **k),
                            dict(shared, resolution=0.05, self_collision=True))
        query.check_configurations(tree, arm, rows, threads=2, distance=True)
        request = query._configuration_requests.request._obj
        self.assertEqual((request.max_threads, request.compute_distance), (2, True))

    def test_unknown_keywords_are_type_errors_naming_the_method(self):
        tree, ball, query = one_cell_map(), sphere_at(0.1, 2.0, C0, C0), octoprox.Query()
        calls = {
            "Query.collide": lambda: query.collide(tree, ball, max_contact=3),
            "Query.distance": lambda: query.distance(tree, ball, cut_off=1.0),
            "Query.path": lambda: query.path(tree, ball, [[[0, 0, 0]]], distance=True),
            "Query.self_collide": lambda: query.self_collide(ball, penetration=True),
            "Query.check_configurations":
                lambda: query.check_configurations(tree, ball, [[0.0]], compute_cost=True),
            "Octree.insert_points": lambda: tree.insert_points([[0, 0, 0]], frame="camera"),
            "Octree.load": lambda: octoprox.Octree.load("map.bt", resolution=0.1),
            "LinkSet.from_urdf_string": lambda: octoprox.LinkSet.from_urdf_string("", srdf_path=""),
        }
        for method, call in calls.items():
            with self.assertRaises(TypeError) as caught:
                call()
            expected = method if sys.version_info >= (3, 10) else method.split(".")[1]
            self.assertIn(expected, str(caught.exception))
            self.assertIn("unexpected keyword", str(caught.exception))


class TypeHints(unittest.TestCase):
    def test_the_hints_of_every_public_function_resolve(self):
        for module in modules():
            for name, value in defined_in(module):
                functions = [value] if inspect.isfunction(value) else [
                    item.fget if isinstance(item, property) else item
                    for _, item in own_members(value)] + [vars(value).get("__init__")]
                for function in filter(None, functions):
                    typing.get_type_hints(function)  # raises on a name that does not resolve

    def test_the_query_methods_are_annotated(self):
        hints = typing.get_type_hints(octoprox.Query.collide)
        self.assertIs(hints["return"], octoprox.CollisionResult)
        self.assertEqual(hints["tree"], typing.Optional[octoprox.Octree])  # None with world=
        self.assertEqual(hints["max_contacts"], int)
        for method in KEYWORDS:
            self.assertIn("return", typing.get_type_hints(getattr(octoprox.Query, method)), method)

    def test_the_package_ships_py_typed(self):
        self.assertTrue(os.path.isfile(os.path.join(os.path.dirname(octoprox.__file__),
                                                    "py.typed")))
        sys.path.insert(0, os.path.join(PACKAGE, "backend"))
        try:
            backend = importlib.import_module("octoprox_wheel")
        except ImportError as error:  # tomli, before Python 3.11
            self.skipTest(f"the build backend cannot be imported: {error}")
        finally:
            sys.path.remove(os.path.join(PACKAGE, "backend"))
        self.assertIn("octoprox/py.typed", [name for name, _ in backend._package_files()])


if __name__ == "__main__":
    unittest.main()
