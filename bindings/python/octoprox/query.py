"""Query contexts (opx_query): collision, distance and path queries, and
self-collision."""

import numpy as np

from . import _structs as s
from . import batch as _batch
from ._arrays import (CONTACT_DTYPE, COST_BOX_DTYPE, SELF_CONTACT_DTYPE, box_array, invalid,
                      pose_array, pose_strides, read_array)
from ._handle import Handle
from ._library import init_struct, lib
from .linkset import LinkSet
from .octree import Octree

ENGINE_DIRECT, ENGINE_AMORTIZED = 1, 2
UNKNOWN_FREE, UNKNOWN_OCCUPIED = 0, 1
_ENGINES = {"direct": ENGINE_DIRECT, "amortized": ENGINE_AMORTIZED}


def _check_operands(tree, links, where):
    # The C handles are untyped pointers to ctypes: a swapped argument would
    # reach the library as the wrong object, so check the Python types here.
    if not isinstance(tree, Octree) or not isinstance(links, LinkSet):
        raise TypeError(f"{where}: expected an Octree and a LinkSet, got "
                        f"{type(tree).__name__} and {type(links).__name__}")


def _check_links(links, where):
    if not isinstance(links, LinkSet):
        raise TypeError(f"{where}: expected a LinkSet, got {type(links).__name__}")


class Query(Handle):
    """A query context: use one per thread.  ``Query(engine="amortized")``
    or any field of opx_query_options as a keyword.

    Request fields are keywords of collide/distance/path, e.g.
    ``query.collide(tree, robot, unknown_policy=UNKNOWN_OCCUPIED,
    max_contacts=10)``; results are the C result structs.
    """
    _destroy = "opx_query_destroy"

    def __init__(self, engine=ENGINE_DIRECT, **options):
        engine = _ENGINES.get(engine, engine)
        opts = init_struct(s.QueryOptions, engine=engine, **options)
        super().__init__(lambda out: lib.opx_query_create(opts, out))
        self._contact_count = self._cost_box_count = self._self_contact_count = 0

    @property
    def stats(self):
        out = init_struct(s.QueryStats)
        lib.opx_query_get_stats(self, out)
        return out

    def collide(self, tree, links, **request):
        """Does the link set collide with the octree?  Read the contacts and
        cost boxes with contacts() and cost_boxes()."""
        _check_operands(tree, links, "Query.collide")
        req = init_struct(s.CollisionRequest, **request)
        out = init_struct(s.CollisionResult)
        self._contact_count = self._cost_box_count = 0
        lib.opx_query_collide(self, tree, links, req, out)
        self._contact_count, self._cost_box_count = out.contact_count, out.cost_box_count
        return out

    def contacts(self):
        """The contacts of the last collision query, a structured array with
        the fields of opx_contact (link, shape, cell_class, cell_center, ...)."""
        return self._rows(lib.opx_query_get_contact, CONTACT_DTYPE, self._contact_count)

    def cost_boxes(self):
        """The cost boxes of the last collision or path query, costliest
        first, a structured array with the fields of opx_cost_box."""
        return self._rows(lib.opx_query_get_cost_box, COST_BOX_DTYPE, self._cost_box_count)

    def _rows(self, get, dtype, count):
        # Each row is written by the library straight into the array.
        rows = np.zeros(count, dtype=dtype)
        rows["struct_size"] = dtype.itemsize
        for i in range(count):
            get(self, i, rows.ctypes.data + i * dtype.itemsize)
        return rows

    def distance(self, tree, links, **request):
        """The minimum distance between the enabled links and the obstacles;
        with per_link=True, link_distances() gives each link's."""
        _check_operands(tree, links, "Query.distance")
        req = init_struct(s.DistanceRequest, **request)
        out = init_struct(s.DistanceResult)
        lib.opx_query_distance(self, tree, links, req, out)
        return out

    def link_distances(self):
        """Each link's minimum distance from the last distance query."""
        return read_array(lib.opx_query_get_link_distances, self)

    def path(self, tree, links, poses, **request):
        """Checks a path: poses of shape (waypoints, links, 7) (or 3:
        positions), map frame; a float64 array is read in place by stride."""
        _check_operands(tree, links, "Query.path")
        arr = pose_array(poses, "Query.path", 3)
        if arr.shape[1] != links.link_count:
            raise invalid(f"Query.path: poses have {arr.shape[1]} links per waypoint, the "
                          f"link set has {links.link_count}")
        waypoint_stride, pose_stride = pose_strides(arr)
        req = init_struct(s.PathRequest, **request)
        out = init_struct(s.PathResult)
        self._contact_count = self._cost_box_count = 0
        lib.opx_query_path(self, tree, links, arr.ctypes.data, arr.shape[0], pose_stride,
                           waypoint_stride, req, out)
        self._cost_box_count = out.cost_box_count
        return out

    def self_collide(self, links, **request):
        """Does the link set collide with itself at its current poses?  Every
        pair of two enabled links with shapes is checked but the disabled
        pairs (an SRDF's, LinkSet.set_pair_enabled); paddings included.
        Keywords are fields of opx_self_collision_request: max_contacts (0:
        yes/no; 1, the default: the first contact; N; 0xFFFFFFFF: all) and
        compute_penetration.  Returns the SelfCollisionResult (collided,
        contact_count, truncated, link_pairs, narrow_tests); self_contacts()
        gives the contacts."""
        _check_links(links, "Query.self_collide")
        req = init_struct(s.SelfCollisionRequest, **request)
        out = init_struct(s.SelfCollisionResult)
        self._self_contact_count = 0
        lib.opx_query_self_collide(self, links, req, out)
        self._self_contact_count = out.contact_count
        return out

    def self_contacts(self):
        """The contacts of the last self_collide, a structured array with the
        fields of opx_self_contact: link_a < link_b, shape_a, shape_b, and
        with compute_penetration depth, normal (moving link_a by -depth *
        normal separates the pair) and position (map frame)."""
        return self._rows(lib.opx_query_get_self_contact, SELF_CONTACT_DTYPE,
                          self._self_contact_count)

    def self_distance(self, links, **request):
        """The minimum distance between the link set's checked pairs of links
        (paddings included), with the two links and shapes and the witness
        points point_on_a, point_on_b (map frame).  Keywords: cutoff (0:
        none; beyond it found = 0 and distance = cutoff) and
        signed_distance (overlap as minus the deepest penetration)."""
        _check_links(links, "Query.self_distance")
        req = init_struct(s.SelfDistanceRequest, **request)
        out = init_struct(s.SelfDistanceResult)
        lib.opx_query_self_distance(self, links, req, out)
        return out

    def check_configurations(self, tree, robot, q, threads=1, self_collision=False, base_pose=None,
                             distance=False, **request):
        """Checks many joint vectors of a robot made from URDF at once: q is
        an (N, dof) array, every joint in model order (robot.joint_names).
        Returns a numpy bool array of N collided flags (the map, and the
        robot itself with self_collision=True); with distance=True, a tuple
        (collided, distances), each configuration's minimum distance.
        base_pose: the root link in the map frame, one for all rows or an
        (N, 7) array, one per row.  threads: 1 runs on the calling thread,
        0 on every core; the answers do not depend on it.  The robot does
        not move; the GIL is released during the call.  Other keywords are
        fields of opx_batch_request (unknown_policy, occupancy_threshold,
        distance_cutoff)."""
        _check_operands(tree, robot, "Query.check_configurations")
        return _batch.check_configurations(self, tree, robot, q, threads, self_collision, base_pose,
                                           distance, **request)

    def check_motion(self, tree, robot, start, goal, resolution=0.01, self_collision=False,
                     base_pose=None, **request):
        """Checks the straight joint-space motion from start to goal (joint
        vectors in model order) at configurations no joint step farther
        apart than resolution (rad or m).  Returns the MotionResult:
        collided, first_collision_fraction (-1: none), steps,
        configurations_checked; with compute_cost=True also the swept cost
        (cost_boxes() then gives its boxes)."""
        _check_operands(tree, robot, "Query.check_motion")
        self._contact_count = self._cost_box_count = 0
        out = _batch.check_motion(self, tree, robot, start, goal, resolution, self_collision,
                                  base_pose, **request)
        self._cost_box_count = out.cost_box_count
        return out

    def check_motions(self, tree, robot, starts, goals, resolution=0.01, threads=1,
                      self_collision=False, base_pose=None, **request):
        """Many motions (a planner's edges): row m of starts to row m of
        goals, (M, dof) arrays.  Returns (collided, first_fractions): a bool
        array and each motion's first colliding fraction (-1: none)."""
        _check_operands(tree, robot, "Query.check_motions")
        return _batch.check_motions(self, tree, robot, starts, goals, resolution, threads,
                                    self_collision, base_pose, **request)

    def bind_boxes(self, boxes):
        """Binds a caller's boxes as the map (amortized contexts only): an
        (N, 6) array of min x y z, max x y z, map frame, metres; copied.
        collide_boxes() and distance_boxes() then query them."""
        arr = box_array(boxes, "Query.bind_boxes")
        stride = arr.strides[0] if len(arr) > 1 else 0
        lib.opx_query_bind_boxes(self, arr.ctypes.data if len(arr) else None, len(arr), stride)

    def collide_boxes(self, links, **request):
        """collide() against the boxes of bind_boxes(); a contact's
        cell_center is the box's centre, cell_size its longest edge."""
        if not isinstance(links, LinkSet):
            raise TypeError(f"Query.collide_boxes: expected a LinkSet, got {type(links).__name__}")
        req = init_struct(s.CollisionRequest, **request)
        out = init_struct(s.CollisionResult)
        self._contact_count = self._cost_box_count = 0
        lib.opx_query_collide_boxes(self, links, req, out)
        self._contact_count = out.contact_count
        return out

    def distance_boxes(self, links, **request):
        """distance() against the boxes of bind_boxes()."""
        if not isinstance(links, LinkSet):
            raise TypeError(f"Query.distance_boxes: expected a LinkSet, got {type(links).__name__}")
        req = init_struct(s.DistanceRequest, **request)
        out = init_struct(s.DistanceResult)
        lib.opx_query_distance_boxes(self, links, req, out)
        return out
