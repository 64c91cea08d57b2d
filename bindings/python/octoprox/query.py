"""Query contexts (opx_query): collision, distance and path queries against
an octree or bound boxes; self-collision (self_collision.py) and many
configurations per call (batch.py) are mixed in.

Every query reads the link set at its current poses (map frame), enabled
links only, paddings included; a shape touching an obstacle (distance
<= 1e-9 m) collides.  Keywords are the fields of the C request with the C
defaults; units are metres.
"""
from __future__ import annotations

import ctypes
from typing import Optional

import numpy as np

from . import _structs as s
from ._calls import compiled_method, keyword_defaults
from ._arrays import CONTACT_DTYPE, COST_BOX_DTYPE, box_array, pose_array, pose_strides, read_array
from ._enums import Engine, ObstacleGeometry, UnknownPolicy
from ._errors import invalid
from ._handle import Handle, api, failure
from ._library import init_struct, lib, unchecked
from ._requests import RequestCache
from ._structs import CollisionResult, DistanceResult, PathResult, QueryStats
from ._types import ArrayLike, EngineLike, ObstacleGeometryLike, UnknownPolicyLike, Vector3
from .batch import BatchQueries, _check_operands
from .linkset import LinkSet
from .octree import Octree
from .self_collision import SelfCollisionQueries
from .world import World, call_with_world, query_with_world

ENGINE_DIRECT, ENGINE_AMORTIZED = Engine.DIRECT, Engine.AMORTIZED
UNKNOWN_FREE, UNKNOWN_OCCUPIED = UnknownPolicy.FREE, UnknownPolicy.OCCUPIED
OBSTACLE_CELLS, OBSTACLE_POINT_EXTENTS = ObstacleGeometry.CELLS, ObstacleGeometry.POINT_EXTENTS
_ZERO3 = (0.0, 0.0, 0.0)
ALL_CONTACTS = 0xFFFFFFFF  # max_contacts: keep every contact

# The keywords of each method, in the order its key tuple lists them.
_COLLIDE = ("unknown_policy", "occupancy_threshold", "max_contacts", "compute_cost",
            "max_cost_boxes", "unknown_probability", "region_min", "region_max",
            "compute_penetration", "obstacle_geometry")
_DISTANCE = ("unknown_policy", "occupancy_threshold", "abs_err", "rel_err", "cutoff", "per_link",
             "signed_distance", "obstacle_geometry")
_PATH = ("unknown_policy", "occupancy_threshold", "compute_distance", "compute_cost",
         "max_cost_boxes", "unknown_probability", "region_min", "region_max", "obstacle_geometry")
_COLLIDE_BOXES = ("max_contacts", "compute_penetration")
_DISTANCE_BOXES = ("abs_err", "rel_err", "cutoff", "per_link", "signed_distance")

# Function objects without errcheck and result sizes, read once.
_collide = unchecked("opx_query_collide")
_distance = unchecked("opx_query_distance")
_COLLISION_RESULT_SIZE = ctypes.sizeof(s.CollisionResult)
_DISTANCE_RESULT_SIZE = ctypes.sizeof(s.DistanceResult)


class Query(Handle, SelfCollisionQueries, BatchQueries):
    """A query context: its engine, scratch memory and the results of its
    last queries (contacts, cost boxes, link distances).  Use one per
    thread; any number of queries may read one Octree and LinkSet at once.

    ``Query()`` uses the direct engine; ``Query("amortized")`` (or
    Engine.AMORTIZED) the amortized one, which gives the same answers and
    pays off when many queries run against one map.  refine_steps and
    morton_bits tune the amortized engine (refinement paths per query,
    default 1; Morton lattice bits per axis, 1 to 21, default 10).
    Raises ValueError for an unknown engine.
    """
    _destroy = "opx_query_destroy"
    _noun = "query"
    _no_pickle = "a query holds one thread's scratch memory; create one in each process"

    @api("Query")
    def __init__(self, engine: EngineLike = Engine.DIRECT, *, refine_steps: int = 1,
                 morton_bits: int = 10) -> None:
        """A new query context with this engine (see the class)."""
        options = init_struct(s.QueryOptions, engine=Engine.parse(engine, "Query", "engine"),
                              refine_steps=refine_steps, morton_bits=morton_bits)
        super().__init__(lambda out: lib.opx_query_create(options, out))
        self._map_result = self._self_result = None  # what contacts() and co. read
        self._collide_requests = RequestCache(s.CollisionRequest, _COLLIDE, "Query.collide")
        self._distance_requests = RequestCache(s.DistanceRequest, _DISTANCE, "Query.distance")
        self._path_requests = RequestCache(s.PathRequest, _PATH, "Query.path")
        self._box_collide_requests = RequestCache(s.CollisionRequest, _COLLIDE_BOXES,
                                                  "Query.collide_boxes")
        self._box_distance_requests = RequestCache(s.DistanceRequest, _DISTANCE_BOXES,
                                                   "Query.distance_boxes")
        self._init_self_collision()
        self._init_batch()

    @property
    @api("Query.stats")
    def stats(self) -> QueryStats:
        """What the context holds (amortized engine; zeros for the direct
        one): engine, boxes, builds, refine_steps_done, sah_ratio,
        extract_ms, build_ms (a QueryStats)."""
        out = init_struct(s.QueryStats)
        lib.opx_query_get_stats(self, out)
        return out

    def collide(self, tree: Optional[Octree], links: LinkSet, *,
                unknown_policy: UnknownPolicyLike = UnknownPolicy.FREE,
                occupancy_threshold: float = 0.0, max_contacts: int = 1,
                compute_cost: bool = False, max_cost_boxes: int = 16,
                unknown_probability: float = 0.5, region_min: Vector3 = _ZERO3,
                region_max: Vector3 = _ZERO3, compute_penetration: bool = False,
                obstacle_geometry: ObstacleGeometryLike = ObstacleGeometry.CELLS,
                world: Optional[World] = None) -> CollisionResult:
        """Does the link set collide with the octree (and the world's objects)?

        unknown_policy: UnknownPolicy.FREE (never-observed space is free,
          as MoveIt and FCL) or OCCUPIED (a link must lie in observed space).
        occupancy_threshold: cells with probability >= it are obstacles;
          0 takes the octree's occupied_threshold.
        max_contacts: 0 answers yes/no only; 1 stops at the first contact
          and reports it; N collects up to N (ALL_CONTACTS: every one).
        compute_cost: also the cost of uncertain and unknown space (paper
          IV.C): boxes where links overlap cells neither known free nor
          obstacles, each cell intersected with the link's bounding box, its
          cost probability x volume (m^3); max_cost_boxes (16) costliest
          kept, unknown space priced at unknown_probability (0.5) and
          counted inside region_min..region_max (map frame; the default
          zeros: the observed cells' bounds).
        compute_penetration: each contact also gets its depth, normal and
          point (EPA; exact for polytopes).
        obstacle_geometry: ObstacleGeometry.CELLS (an occupied cell is its
          cube) or POINT_EXTENTS (the box of its sensed points, where the
          map recorded one).
        world: a World whose enabled objects are checked too (tree may then
          be None); their contacts follow the cells', with object set.

        Returns a CollisionResult: collided (bool), contact_count,
        truncated, narrow_tests, total_cost, cost_box_count; contacts() and
        cost_boxes() give the rows.  Raises TypeError for operands of the
        wrong types or an unknown keyword, ValueError
        (InvalidArgumentError) for bad values or a closed handle.
        """
        key = (unknown_policy, occupancy_threshold, max_contacts, compute_cost, max_cost_boxes,
               unknown_probability, region_min, region_max, compute_penetration,
               obstacle_geometry)
        request = self._collide_requests.lookup(key)
        if world is not None or tree is None:
            out = s.CollisionResult(_COLLISION_RESULT_SIZE)
            self._map_result = None
            query_with_world(self, tree, links, world, "Query.collide",
                             lambda raw: _collide(self._raw, raw, links._raw, request, out))
            self._map_result = out
            return out
        if not isinstance(tree, Octree) or not isinstance(links, LinkSet):
            _check_operands(tree, links, "Query.collide")
        out = s.CollisionResult(_COLLISION_RESULT_SIZE)
        status = _collide(self._raw, tree._raw, links._raw, request, out)
        if status:
            self._map_result = None
            raise failure(status, "Query.collide", self, tree, links)
        self._map_result = out
        return out

    @api("Query.contacts")
    def contacts(self) -> np.ndarray:
        """The contacts of the last collide() or collide_boxes(), a
        structured array with the fields of Contact: link, shape,
        cell_class, cell_center (map frame), cell_size, cell_probability,
        and with compute_penetration depth, normal, position; object and
        object_shape (world objects, -1 for a cell), attached (the link's
        attached object whose shape touched, -1 for its own).  Empty after
        a path query."""
        count = getattr(self._map_result, "contact_count", 0)
        return self._rows(lib.opx_query_get_contact, CONTACT_DTYPE, count)

    @api("Query.cost_boxes")
    def cost_boxes(self) -> np.ndarray:
        """The cost boxes of the last collide(), path() or check_motion()
        with compute_cost, costliest first: a structured array with the
        fields of CostBox (link, cell_class, min, max, probability, cost,
        cell_center, cell_size; map frame, m and m^3)."""
        count = getattr(self._map_result, "cost_box_count", 0)
        return self._rows(lib.opx_query_get_cost_box, COST_BOX_DTYPE, count)

    def _rows(self, get, dtype, count):
        # Each row is written by the library straight into the array.
        rows = np.zeros(count, dtype=dtype)
        rows["struct_size"] = dtype.itemsize
        for i in range(count):
            get(self, i, rows.ctypes.data + i * dtype.itemsize)
        return rows

    def distance(self, tree: Optional[Octree], links: LinkSet, *,
                 unknown_policy: UnknownPolicyLike = UnknownPolicy.FREE,
                 occupancy_threshold: float = 0.0, abs_err: float = 0.0, rel_err: float = 0.0,
                 cutoff: float = 0.0, per_link: bool = False, signed_distance: bool = False,
                 obstacle_geometry: ObstacleGeometryLike = ObstacleGeometry.CELLS,
                 world: Optional[World] = None) -> DistanceResult:
        """The minimum distance between the enabled links (paddings
        included) and the obstacle cells, with witness points.

        unknown_policy, occupancy_threshold, obstacle_geometry: as collide().
        abs_err, rel_err: the distance may exceed the true minimum by at
          most max(abs_err, rel_err * distance); 0 and 0: exact.
        cutoff: obstacles farther than this (m) are not searched; the
          result is then found False and distance = cutoff.  0: none.
        per_link: also each link's minimum (link_distances()).
        signed_distance: overlapping links get minus their deepest
          penetration instead of 0.
        world: a World whose enabled objects are measured too (tree may
          then be None): the least of both; object names the nearest
          object (-1: a cell), point_on_cell then lying on it.

        Returns a DistanceResult: found, collided (distance <= 1e-9 m),
        distance (m), link, shape, point_on_link and point_on_cell (map
        frame), cell_center, cell_size, cell_probability, cell_class.
        Raises as collide().
        """
        key = (unknown_policy, occupancy_threshold, abs_err, rel_err, cutoff, per_link,
               signed_distance, obstacle_geometry)
        request = self._distance_requests.lookup(key)
        out = s.DistanceResult(_DISTANCE_RESULT_SIZE)
        if world is not None or tree is None:
            query_with_world(self, tree, links, world, "Query.distance",
                             lambda raw: _distance(self._raw, raw, links._raw, request, out))
            return out
        if not isinstance(tree, Octree) or not isinstance(links, LinkSet):
            _check_operands(tree, links, "Query.distance")
        status = _distance(self._raw, tree._raw, links._raw, request, out)
        if status:
            raise failure(status, "Query.distance", self, tree, links)
        return out

    @api("Query.link_distances")
    def link_distances(self) -> np.ndarray:
        """Each link's minimum distance (m) from the last distance query
        with per_link=True, in link order (+inf: disabled, or nothing
        within the cutoff); empty otherwise."""
        return read_array(lib.opx_query_get_link_distances, self)

    @api("Query.path")
    def path(self, tree: Optional[Octree], links: LinkSet, poses: ArrayLike, *,
             unknown_policy: UnknownPolicyLike = UnknownPolicy.FREE,
             occupancy_threshold: float = 0.0, compute_distance: bool = False,
             compute_cost: bool = False, max_cost_boxes: int = 16,
             unknown_probability: float = 0.5, region_min: Vector3 = _ZERO3,
             region_max: Vector3 = _ZERO3,
             obstacle_geometry: ObstacleGeometryLike = ObstacleGeometry.CELLS,
             world: Optional[World] = None) -> PathResult:
        """Checks a path of waypoints in order; the link set does not move.

        poses: shape (waypoints, links, 7), x y z qx qy qz qw of every link
          in the map frame, or (waypoints, links, 3) positions; a float64
          array is read in place by its strides.
        compute_distance: the minimum distance along the path.
        compute_cost: the cost of the uncertain and unknown space swept,
          each cell counted once (cost_boxes() gives the boxes); world
          objects have none (they are known), and it needs an octree.
        world: a World whose enabled objects are checked at every waypoint
          too (tree may then be None): collided when a link touches a cell
          or an object, the distance the least of both.
        Other keywords as collide().  Without distance or cost the check
        stops at the first colliding waypoint.

        Returns a PathResult: collided, first_colliding_waypoint (-1:
        none), min_distance, min_distance_waypoint, total_cost,
        cost_box_count.  Raises as collide(), and InvalidArgumentError for
        poses of the wrong shape.
        """
        _check_operands(tree, links, "Query.path", world)
        arr = pose_array(poses, "Query.path", 3)
        if arr.shape[1] != links.link_count:
            raise invalid(f"poses have {arr.shape[1]} links per waypoint, the link set has "
                          f"{links.link_count}", "Query.path")
        key = (unknown_policy, occupancy_threshold, compute_distance, compute_cost,
               max_cost_boxes, unknown_probability, region_min, region_max, obstacle_geometry)
        waypoint_stride, pose_stride = pose_strides(arr)
        out = init_struct(s.PathResult)
        self._map_result = None
        request = self._path_requests.lookup(key)
        call_with_world(self, world, "Query.path",
                        lambda: lib.opx_query_path(self, tree, links, arr.ctypes.data, arr.shape[0],
                                                   pose_stride, waypoint_stride, request, out))
        self._map_result = out
        return out

    @api("Query.bind_boxes")
    def bind_boxes(self, boxes: ArrayLike) -> None:
        """Binds a caller's boxes as the map (amortized engine only; a
        direct context raises InvalidArgumentError): an (N, 6) array of
        min x y z, max x y z, map frame, metres; copied.  collide_boxes()
        and distance_boxes() then query them, until the next bind_boxes or
        octree query."""
        arr = box_array(boxes, "Query.bind_boxes")
        stride = arr.strides[0] if len(arr) > 1 else 0
        lib.opx_query_bind_boxes(self, arr.ctypes.data if len(arr) else None, len(arr), stride)

    @api("Query.collide_boxes")
    def collide_boxes(self, links: LinkSet, *, max_contacts: int = 1,
                      compute_penetration: bool = False) -> CollisionResult:
        """collide() against the boxes of bind_boxes(): a contact's
        cell_center is the box's centre, cell_size its longest edge, its
        class OCCUPIED.  Keywords as collide()'s (boxes have no unknown or
        uncertain space, so no cost)."""
        self._check_links(links, "Query.collide_boxes")
        key = (max_contacts, compute_penetration)
        out = init_struct(s.CollisionResult)
        self._map_result = None
        lib.opx_query_collide_boxes(self, links, self._box_collide_requests.lookup(key), out)
        self._map_result = out
        return out

    @api("Query.distance_boxes")
    def distance_boxes(self, links: LinkSet, *, abs_err: float = 0.0, rel_err: float = 0.0,
                       cutoff: float = 0.0, per_link: bool = False,
                       signed_distance: bool = False) -> DistanceResult:
        """distance() against the boxes of bind_boxes(); keywords as
        distance()'s."""
        self._check_links(links, "Query.distance_boxes")
        key = (abs_err, rel_err, cutoff, per_link, signed_distance)
        out = init_struct(s.DistanceResult)
        lib.opx_query_distance_boxes(self, links, self._box_distance_requests.lookup(key), out)
        return out

    @staticmethod
    def _check_links(links, where):
        if not isinstance(links, LinkSet):
            raise TypeError(f"{where}: expected a LinkSet, got {type(links).__name__}")


def _default_request(method, cache: RequestCache) -> ctypes.Structure:
    """The request ``method`` builds when called without keywords."""
    return cache.build(keyword_defaults(method, cache._names))


# The usual call in C (octoprox._calls); the default requests it uses.
_DEFAULT_COLLIDE = _default_request(Query.collide, RequestCache(s.CollisionRequest, _COLLIDE,
                                                                 "Query.collide"))
_DEFAULT_DISTANCE = _default_request(Query.distance, RequestCache(s.DistanceRequest, _DISTANCE,
                                                                  "Query.distance"))
Query.collide = compiled_method(Query.collide, "opx_query_collide", _DEFAULT_COLLIDE,
                                s.CollisionResult, Query, Octree, LinkSet, "_map_result",
                                "_collide_requests", _COLLIDE)
Query.distance = compiled_method(Query.distance, "opx_query_distance", _DEFAULT_DISTANCE,
                                 s.DistanceResult, Query, Octree, LinkSet, None,
                                 "_distance_requests", _DISTANCE)
