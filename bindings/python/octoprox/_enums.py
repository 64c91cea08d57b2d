"""The library's named integers as IntEnum classes (the #defines of
include/octoprox/).

Every member is an int, so it goes wherever the C value goes and compares
equal to it.  Arguments taking one of these accept the member, its integer
value or its name in any case ("amortized", "ENDPOINTS"); anything else is
a ValueError listing the valid values.
"""
import enum
from typing import Type, TypeVar, Union

_E = TypeVar("_E", bound=enum.IntEnum)


class _Named(enum.IntEnum):
    # int's own hash, in C: request keywords are cache keys (see
    # _requests.py), and Enum's __hash__ is a Python function.
    __hash__ = int.__hash__

    @classmethod
    def parse(cls: Type[_E], value: Union[_E, int, str], where: str, argument: str) -> _E:
        """The member for a member, its value or its name; a ValueError
        naming ``where`` and ``argument`` otherwise."""
        try:
            if isinstance(value, str):
                return cls[value.upper()]
            if not isinstance(value, bool) and int(value) == value:
                return cls(int(value))
        except (KeyError, ValueError, TypeError):
            pass
        names = ", ".join(f'"{m.name.lower()}" ({m.value})' for m in cls)
        raise ValueError(f"{where}: {argument} must be one of {names}; got {value!r}")


class CellClass(_Named):
    """The class of an octree cell by its occupancy probability p
    (include/octoprox/octree.h): OCCUPIED p >= occupied_threshold,
    UNCERTAIN free_threshold <= p < occupied_threshold, FREE
    p < free_threshold, UNKNOWN never observed."""
    UNKNOWN = 0
    FREE = 1
    UNCERTAIN = 2
    OCCUPIED = 3


class CellMask(enum.IntFlag):
    """Sets of cell classes for Octree.leaves: FREE | OCCUPIED and so on;
    ALL_KNOWN is every observed class."""
    FREE = 1 << CellClass.FREE
    UNCERTAIN = 1 << CellClass.UNCERTAIN
    OCCUPIED = 1 << CellClass.OCCUPIED
    ALL_KNOWN = FREE | UNCERTAIN | OCCUPIED


class InsertMode(_Named):
    """How Octree.insert_points and insert_depth_image update the map.
    RAYCAST (the default): cells along each ray become more free, the
    endpoint cell more occupied (OctoMap's insertPointCloud).  ENDPOINTS:
    each endpoint cell gets one hit; no free space."""
    RAYCAST = 0
    ENDPOINTS = 1


class FileFormat(_Named):
    """Map file formats.  AUTO: loading reads the header, saving picks by
    the extension (.bt, .ot or .opx; BT for bytes).  BT: OctoMap binary,
    per leaf only occupied or free.  OT: OctoMap full, the log-odds of
    every node.  OPX: OctoProx map, the .ot content and every occupied
    cell's point extent (ObstacleGeometry.POINT_EXTENTS), which .bt and
    .ot cannot hold."""
    AUTO = 0
    BT = 1
    OT = 2
    OPX = 3


class Engine(_Named):
    """The engine of a Query.  DIRECT (the default): the octree as it is,
    no per-frame preprocessing.  AMORTIZED: the first query on a frame
    turns its obstacle cells into boxes in a Morton-built tree that every
    query then refines; the same answers; the only engine that takes
    caller boxes (Query.bind_boxes)."""
    DIRECT = 1
    AMORTIZED = 2


class UnknownPolicy(_Named):
    """What never-observed space is during a query.  FREE (the default):
    optimistic, as MoveIt and FCL.  OCCUPIED: safe, a link must lie in
    observed space.  Only the map cube is searched either way."""
    FREE = 0
    OCCUPIED = 1


class ObstacleGeometry(_Named):
    """What an occupied cell is as an obstacle.  CELLS (the default): its
    whole cube, as FCL and MoveIt.  POINT_EXTENTS: the box of the sensed
    points that made it occupied, where the map recorded one (cells hit by
    insert_points or insert_depth_image; a cell read from a file or a
    message is its whole cube).  Uncertain and unknown space are whole
    cubes in both."""
    CELLS = 0
    POINT_EXTENTS = 1


class ShapeKind(_Named):
    """The kind of a link's shape (LinkSet.shape)."""
    SPHERE = 1
    BOX = 2
    CYLINDER = 3
    CAPSULE = 4
    CONVEX = 5
    MESH = 6


class JointType(_Named):
    """URDF joint types.  FLOATING and PLANAR joints are not moved by
    forward kinematics: they stay at their origin and their positions are
    ignored."""
    FIXED = 0
    REVOLUTE = 1
    CONTINUOUS = 2
    PRISMATIC = 3
    FLOATING = 4
    PLANAR = 5


class JointOrder(_Named):
    """What a row of joint values holds in Query.check_configurations,
    check_motion and check_motions.  BY_COUNT (the default): told by its
    length, every joint (model order, LinkSet.joint_names) or the active
    joints alone (LinkSet.active_joint_names); never ambiguous, as the two
    lengths are equal only when every joint is active and the two orders
    are then one.  MODEL and ACTIVE insist on one of them (another length
    raises InvalidArgumentError)."""
    BY_COUNT = 0
    MODEL = 1
    ACTIVE = 2


def converter(cls):
    """A function giving the member of ``cls`` for a value the library
    reports, or the value itself when no member has it."""
    by_value = {m.value: m for m in cls}
    return lambda value: by_value.get(value, value)
