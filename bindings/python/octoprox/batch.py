"""Many configurations and joint-space motions per call (batch.h):
Query.check_configurations, check_motion and check_motions, and many
spheres per call (spheres.h): Query.collide_spheres,
Query.distance_spheres and Query.trajectory_cost (Query inherits them).

The robot is a LinkSet made from URDF.  Joint vectors are rows of the
active joints (LinkSet.active_joint_names: the moving joints that mimic
none, as MoveIt and planners hold them) or of every joint in model order
(LinkSet.joint_names), told apart by their length (joint_order=
JointOrder.BY_COUNT, the default; JointOrder.ACTIVE or MODEL insists on
one); radians or metres.  Forward kinematics runs on the query's own
copies: the robot does not move.  A configuration collides as
Query.collide would say after set_joint_positions (and, with
self_collision, as self_collide), whatever the thread count.  With
world=, a World's enabled objects are checked beside the octree (which may
then be None), as Query.collide checks them.  Arrays go in
by address and row stride when they are float64 with packed rows, else as
one copy.  The library runs without the GIL (ctypes releases it), so other
Python threads go on while a batch is checked.
"""
from __future__ import annotations

import ctypes
from typing import Optional, Tuple, Union

import numpy as np

from . import _structs as s
from ._arrays import pose_array
from ._enums import JointOrder, ObstacleGeometry, UnknownPolicy
from ._errors import invalid
from ._handle import api
from ._library import init_struct, lib, make_pose
from ._requests import RequestCache
from ._structs import MotionResult
from ._types import (ArrayLike, JointOrderLike, ObstacleGeometryLike, PoseLike, UnknownPolicyLike,
                     Vector3)
from .linkset import LinkSet
from .octree import Octree
from .world import World, call_with_world

JOINTS_BY_COUNT, JOINTS_MODEL, JOINTS_ACTIVE = JointOrder
_ZERO3 = (0.0, 0.0, 0.0)
_CONFIGURATIONS = ("max_threads", "self_collision", "compute_distance", "unknown_policy",
                   "occupancy_threshold", "distance_cutoff", "obstacle_geometry", "joint_order")
_MOTION = ("resolution", "self_collision", "unknown_policy", "occupancy_threshold",
           "compute_cost", "max_cost_boxes", "unknown_probability", "region_min", "region_max",
           "obstacle_geometry", "joint_order", "check", "tolerance")
_MOTIONS = ("resolution", "max_threads", "self_collision", "unknown_policy",
            "occupancy_threshold", "obstacle_geometry", "joint_order", "check", "tolerance")
_SPHERES = ("unknown_policy", "occupancy_threshold", "obstacle_geometry")
_TRAJECTORY = ("activation", "unknown_policy", "occupancy_threshold", "obstacle_geometry",
               "joint_order")
_SPHERE_DISTANCES = ("max_distance", "max_threads", "unknown_policy", "occupancy_threshold",
                     "obstacle_geometry")


def joint_rows(q, where):
    """(N, dof) float64 rows of contiguous values, by address and stride."""
    arr = q if isinstance(q, np.ndarray) else np.asarray(q, dtype=np.float64)
    if arr.ndim == 1:
        arr = arr.reshape(1, -1)
    if arr.ndim != 2:
        raise invalid(f"joint positions must have shape (N, dof), got {arr.shape}", where)
    if arr.dtype != np.float64 or not arr.dtype.isnative or \
            (arr.shape[1] > 1 and arr.strides[1] != 8) or \
            (len(arr) > 1 and arr.strides[0] < 8 * arr.shape[1]):
        arr = np.ascontiguousarray(arr, dtype=np.float64)
    return arr


def _row_stride(arr):
    return arr.strides[0] if len(arr) > 1 else 8 * arr.shape[1]


class _BasePoses:
    """base_pose as the C call takes it: None, one pose for every row (a Pose
    or 3/7 numbers), or an (N, 7) / (N, 3) array, one per row."""

    def __init__(self, base_pose, rows, where):
        self.address, self.count, self.stride, self.keep = None, 0, 0, None
        if base_pose is None:
            return
        if isinstance(base_pose, s.Pose) or np.ndim(base_pose) == 1:
            self.keep = make_pose(base_pose)
            self.address, self.count = ctypes.addressof(self.keep), 1
            return
        arr = pose_array(base_pose, where, 2)
        if len(arr) != rows:
            raise invalid(f"{len(arr)} base poses for {rows} rows (give one, or one per row)", where)
        self.keep, self.address, self.count = arr, arr.ctypes.data, len(arr)
        self.stride = arr.strides[0] if len(arr) > 1 else 0


def _check_operands(tree, robot, where, world=None):
    bad_tree = not isinstance(tree, Octree) and (world is None or tree is not None)
    if bad_tree or not isinstance(robot, LinkSet):
        raise TypeError(f"{where}: expected an Octree and a LinkSet (the octree may be None "
                        f"with a world), got {type(tree).__name__} and {type(robot).__name__}")


class BatchQueries:
    """Query.check_configurations, check_motion and check_motions (mixed
    into Query)."""

    def _init_batch(self):
        self._configuration_requests = RequestCache(s.BatchRequest, _CONFIGURATIONS,
                                                    "Query.check_configurations")
        self._motion_requests = RequestCache(s.MotionRequest, _MOTION, "Query.check_motion")
        self._motions_requests = RequestCache(s.MotionRequest, _MOTIONS, "Query.check_motions")
        self._sphere_requests = RequestCache(s.SphereRequest, _SPHERES, "Query.collide_spheres")
        self._trajectory_requests = RequestCache(s.TrajectoryCostRequest, _TRAJECTORY,
                                                 "Query.trajectory_cost")
        self._sphere_distance_requests = RequestCache(s.SphereDistanceRequest, _SPHERE_DISTANCES,
                                                      "Query.distance_spheres")

    @api("Query.collide_spheres")
    def collide_spheres(self, tree: Octree, spheres: ArrayLike, *,
                        unknown_policy: UnknownPolicyLike = UnknownPolicy.FREE,
                        occupancy_threshold: float = 0.0,
                        obstacle_geometry: ObstacleGeometryLike = ObstacleGeometry.CELLS
                        ) -> np.ndarray:
        """Checks spheres against the map, each on its own, as
        Query.collide answers a LinkSet holding that sphere alone, without
        a LinkSet to place: the robot model of sphere-based planners.

        spheres: an (N, 4) array of rows x, y, z, radius (map frame,
          metres; radius >= 0: 0 is a point).
        unknown_policy, occupancy_threshold, obstacle_geometry: as
          Query.collide.  The query's engine and world play no part.

        Returns a numpy bool array of N collided flags.  Raises
        InvalidArgumentError naming the row of a non-finite value or a
        negative radius, and for an empty array.
        """
        if not isinstance(tree, Octree):
            raise TypeError(f"Query.collide_spheres: expected an Octree, got {type(tree).__name__}")
        rows = np.ascontiguousarray(spheres, dtype=np.float64)
        if rows.ndim == 1:
            rows = rows.reshape(1, -1)
        if rows.ndim != 2 or rows.shape[1] != 4:
            raise invalid(f"spheres must have shape (N, 4) (x, y, z, radius), got {rows.shape}",
                          "Query.collide_spheres")
        n = len(rows)
        collided = np.zeros(n, dtype=np.bool_)
        request = self._sphere_requests.lookup((unknown_policy, occupancy_threshold, obstacle_geometry))
        lib.opx_query_collide_spheres(self, tree, rows.ctypes.data, n, 0, request,
                                      collided.ctypes.data, n)
        return collided

    @api("Query.distance_spheres")
    def distance_spheres(self, tree: Optional[Octree], spheres: ArrayLike,
                         max_distance: float = 0.1, world: Optional[World] = None, *,
                         threads: int = 1,
                         unknown_policy: UnknownPolicyLike = UnknownPolicy.FREE,
                         occupancy_threshold: float = 0.0,
                         obstacle_geometry: ObstacleGeometryLike = ObstacleGeometry.CELLS
                         ) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Signed distances of spheres to the map's obstacles and (with
        world=) a World's enabled objects, for trajectory optimizers
        (spheres.h: opx_query_distance_spheres states the rules).

        spheres: an (N, 4) array of rows x, y, z, radius (map frame,
          metres; radius >= 0).
        max_distance: metres (> 0, inf allowed); spheres at least this far
          report it, a zero gradient and a NaN witness.
        threads: 1 (the caller's), 0 (one per hardware thread) or N.

        Returns (distance (N,), gradient (N, 3), witness (N, 3)): each
        sphere's signed distance (surface to the nearest obstacle;
        negative: minus the depth of its centre plus its radius), the unit
        gradient of the distance with respect to the centre (away from
        the nearest obstacle) and the witness (the nearest obstacle point,
        or inside, the nearest point outside every obstacle).
        """
        if not isinstance(tree, Octree) and (world is None or tree is not None):
            raise TypeError(f"Query.distance_spheres: expected an Octree (None with a world), "
                            f"got {type(tree).__name__}")
        rows = np.ascontiguousarray(spheres, dtype=np.float64)
        if rows.ndim == 1:
            rows = rows.reshape(1, -1)
        if rows.ndim != 2 or rows.shape[1] != 4:
            raise invalid(f"spheres must have shape (N, 4) (x, y, z, radius), got {rows.shape}",
                          "Query.distance_spheres")
        n = len(rows)
        distance = np.zeros(n)
        gradient = np.zeros((n, 3))
        witness = np.zeros((n, 3))
        request = self._sphere_distance_requests.lookup(
            (max_distance, threads, unknown_policy, occupancy_threshold, obstacle_geometry))
        call_with_world(self, world, "Query.distance_spheres", lambda: lib.opx_query_distance_spheres(
            self, tree, rows.ctypes.data, n, 0, request, distance.ctypes.data, gradient.ctypes.data,
            witness.ctypes.data, n))
        return distance, gradient, witness

    @api("Query.trajectory_cost")
    def trajectory_cost(self, tree: Optional[Octree], robot: LinkSet, q: ArrayLike,
                        activation: float = 0.05, world: Optional[World] = None, *,
                        base_pose: Optional[PoseLike] = None,
                        unknown_policy: UnknownPolicyLike = UnknownPolicy.FREE,
                        occupancy_threshold: float = 0.0,
                        obstacle_geometry: ObstacleGeometryLike = ObstacleGeometry.CELLS,
                        joint_order: JointOrderLike = JointOrder.BY_COUNT
                        ) -> Tuple[float, np.ndarray]:
        """The obstacle cost of a trajectory of a robot made of spheres (a
        LinkSet from a spherized URDF) and its gradient, for trajectory
        optimizers (spheres.h: opx_query_trajectory_cost states the rules).

        q: a (T, dof) array of waypoints (active joints or every joint, as
          joint_order says). activation: eps (m); the cost sums CHOMP's
          penalty of each sphere's signed distance d: -d + eps/2 inside,
          (d - eps)^2 / (2 eps) up to eps, 0 beyond.

        Returns (cost, gradient (T, dof)).  Raises InvalidArgumentError for
        a robot with a shape that is not a sphere.
        """
        _check_operands(tree, robot, "Query.trajectory_cost", world)
        rows = joint_rows(q, "Query.trajectory_cost")
        n = len(rows)
        gradient = np.zeros(rows.shape)
        cost = ctypes.c_double(0.0)
        base = None if base_pose is None else make_pose(base_pose)
        request = self._trajectory_requests.lookup(
            (activation, unknown_policy, occupancy_threshold, obstacle_geometry, joint_order))
        call_with_world(self, world, "Query.trajectory_cost", lambda: lib.opx_query_trajectory_cost(
            self, tree, robot, rows.ctypes.data, n, rows.shape[1], _row_stride(rows),
            None if base is None else ctypes.addressof(base), request, ctypes.addressof(cost),
            gradient.ctypes.data, n))
        return cost.value, gradient

    @api("Query.check_configurations")
    def check_configurations(self, tree: Optional[Octree], robot: LinkSet, q: ArrayLike,
                             threads: int = 1, self_collision: bool = False,
                             base_pose: Optional[PoseLike] = None, distance: bool = False, *,
                             unknown_policy: UnknownPolicyLike = UnknownPolicy.FREE,
                             occupancy_threshold: float = 0.0, distance_cutoff: float = 0.0,
                             obstacle_geometry: ObstacleGeometryLike = ObstacleGeometry.CELLS,
                             joint_order: JointOrderLike = JointOrder.BY_COUNT,
                             world: Optional[World] = None
                             ) -> Union[np.ndarray, Tuple[np.ndarray, np.ndarray]]:
        """Checks many joint vectors of a robot made from URDF at once.

        q: an (N, dof) array: dof = robot.active_joint_count, the active
          joints (robot.active_joint_names), or dof = robot.joint_count,
          every joint in model order (joint_order: JointOrder, BY_COUNT
          tells them by dof; ACTIVE or MODEL insists on one).
        threads: 1 runs on the calling thread, 0 on every core, N on N
          (opx_batch_request.max_threads); the answers do not depend on it.
        self_collision: also the robot's own enabled pairs.
        base_pose: the root link in the map frame, one pose for every row
          or an (N, 7) array, one per row (None: the map origin).
        distance: also each configuration's minimum distance (m, padding
          included, 0 when touching; with self_collision the smaller of
          that and the self distance); no check then stops at the first
          contact.  distance_cutoff: obstacles farther than it (m) are not
          searched, the distance is then the cutoff (0: none).
        unknown_policy, occupancy_threshold, obstacle_geometry: as
          Query.collide.
        world: a World whose enabled objects are checked too (tree may then
          be None): collided when a link touches a cell or an object, the
          distance the least of both.

        A robot made of spheres alone, asked for collisions with the map
        only (no distance, self_collision or world; unknown space free), is
        checked sphere by sphere on the map's obstacle grid, with the same
        answers: about 10 ns a sphere; the first such call after the map
        changed builds the grid.

        Returns a numpy bool array of N collided flags; with distance=True
        a tuple (collided, distances).  Raises InvalidArgumentError naming
        the row and joint of a bad value or a dof that is neither count,
        UnsupportedError for a robot not made from URDF, TypeError for
        swapped operands.
        """
        _check_operands(tree, robot, "Query.check_configurations", world)
        rows = joint_rows(q, "Query.check_configurations")
        n = len(rows)
        collided = np.zeros(n, dtype=np.bool_)
        distances = np.zeros(n, dtype=np.float64) if distance else None
        if n > 0:
            bases = _BasePoses(base_pose, n, "Query.check_configurations")
            request = self._configuration_requests.lookup(
                (threads, self_collision, distance, unknown_policy, occupancy_threshold,
                 distance_cutoff, obstacle_geometry, joint_order))
            call_with_world(self, world, "Query.check_configurations",
                            lambda: lib.opx_query_check_configurations(
                                self, tree, robot, rows.ctypes.data, n, rows.shape[1],
                                _row_stride(rows), bases.address, bases.count, bases.stride,
                                request, collided.ctypes.data,
                                None if distances is None else distances.ctypes.data, n))
        return (collided, distances) if distance else collided

    @api("Query.check_motion")
    def check_motion(self, tree: Optional[Octree], robot: LinkSet, start: ArrayLike,
                     goal: ArrayLike, resolution: float = 0.01, self_collision: bool = False,
                     base_pose: Optional[PoseLike] = None, *,
                     unknown_policy: UnknownPolicyLike = UnknownPolicy.FREE,
                     occupancy_threshold: float = 0.0, compute_cost: bool = False,
                     max_cost_boxes: int = 16, unknown_probability: float = 0.5,
                     region_min: Vector3 = _ZERO3, region_max: Vector3 = _ZERO3,
                     obstacle_geometry: ObstacleGeometryLike = ObstacleGeometry.CELLS,
                     joint_order: JointOrderLike = JointOrder.BY_COUNT,
                     world: Optional[World] = None, certified: bool = False,
                     tolerance: float = 1e-3
                     ) -> MotionResult:
        """Checks the straight joint-space motion from start to goal (joint
        vectors of the active joints or of every joint in model order, as
        check_configurations takes rows; joint_order as there).

        resolution: the largest step of any joint between two checked
          configurations (rad or m, > 0): n = ceil(max |goal - start| /
          resolution) steps, n + 1 configurations, the ends first.
        self_collision, base_pose (one pose): as check_configurations.
        compute_cost: also the cost of the uncertain and unknown space the
          motion sweeps, every configuration checked (cost_boxes() gives
          the boxes; max_cost_boxes, unknown_probability, region_min,
          region_max as Query.collide); world objects add none, and it
          needs an octree.
        world: a World whose enabled objects are checked too, as
          check_configurations checks them (tree may then be None).
        certified: check every configuration of the segment, not samples
          (conservative advancement on exact distances; resolution does
          not apply, compute_cost is refused): collided False means no
          configuration of the motion collides; when True,
          first_collision_fraction f is a configuration within 1e-8 m of
          an obstacle and none before f - tolerance collides.
        tolerance: with certified, that bracket (a fraction of the
          motion, in (0, 1]).
        Other keywords as Query.collide.

        Returns a MotionResult: collided (bool), first_collision_fraction
        (i / n of the first colliding configuration, -1: none), steps,
        configurations_checked, total_cost.  Raises InvalidArgumentError
        for a bad resolution or joint vectors of different lengths.
        """
        _check_operands(tree, robot, "Query.check_motion", world)
        a = np.ascontiguousarray(start, dtype=np.float64).reshape(-1)
        b = np.ascontiguousarray(goal, dtype=np.float64).reshape(-1)
        if len(a) != len(b):
            raise invalid(f"start has {len(a)} joints, goal {len(b)}", "Query.check_motion")
        request = self._motion_requests.lookup(
            (resolution, self_collision, unknown_policy, occupancy_threshold, compute_cost,
             max_cost_boxes, unknown_probability, region_min, region_max, obstacle_geometry,
             joint_order, 1 if certified else 0, tolerance))
        out = init_struct(s.MotionResult)
        base = None if base_pose is None else ctypes.byref(make_pose(base_pose))
        if compute_cost:
            self._map_result = None  # the call replaces the query's results
        call_with_world(self, world, "Query.check_motion",
                        lambda: lib.opx_query_check_motion(self, tree, robot, a.ctypes.data,
                                                           b.ctypes.data, len(a), base, request,
                                                           out))
        if compute_cost:
            self._map_result = out
        return out

    @api("Query.check_motions")
    def check_motions(self, tree: Optional[Octree], robot: LinkSet, starts: ArrayLike,
                      goals: ArrayLike, resolution: float = 0.01, threads: int = 1,
                      self_collision: bool = False, base_pose: Optional[PoseLike] = None, *,
                      unknown_policy: UnknownPolicyLike = UnknownPolicy.FREE,
                      occupancy_threshold: float = 0.0,
                      obstacle_geometry: ObstacleGeometryLike = ObstacleGeometry.CELLS,
                      joint_order: JointOrderLike = JointOrder.BY_COUNT,
                      world: Optional[World] = None, certified: bool = False,
                      tolerance: float = 1e-3
                      ) -> Tuple[np.ndarray, np.ndarray]:
        """Checks many motions (a planner's edges): row m of starts to row m
        of goals, (M, dof) arrays of active joints or of every joint, as
        check_motion does (no cost here).  threads, base_pose (one, or one
        per row), joint_order and world as check_configurations; other
        keywords (certified, tolerance among them) as check_motion.

        Returns (collided, first_fractions): a bool array and each
        motion's first colliding fraction (-1: none).
        """
        _check_operands(tree, robot, "Query.check_motions", world)
        a = joint_rows(starts, "Query.check_motions")
        b = joint_rows(goals, "Query.check_motions")
        if a.shape != b.shape:
            raise invalid(f"starts have shape {a.shape}, goals {b.shape}", "Query.check_motions")
        if a.strides[0] != b.strides[0] and len(a) > 1:  # one stride for both
            a, b = np.ascontiguousarray(a), np.ascontiguousarray(b)
        n = len(a)
        collided = np.zeros(n, dtype=np.bool_)
        fractions = np.zeros(n, dtype=np.float64)
        if n > 0:
            bases = _BasePoses(base_pose, n, "Query.check_motions")
            request = self._motions_requests.lookup(
                (resolution, threads, self_collision, unknown_policy, occupancy_threshold,
                 obstacle_geometry, joint_order, 1 if certified else 0, tolerance))
            call_with_world(self, world, "Query.check_motions",
                            lambda: lib.opx_query_check_motions(
                                self, tree, robot, a.ctypes.data, b.ctypes.data, n, a.shape[1],
                                _row_stride(a), bases.address, bases.count, bases.stride, request,
                                collided.ctypes.data, fractions.ctypes.data, n))
        return collided, fractions
