"""OctoProx: collision and distance queries between robot links and
occupancy octrees built from point-cloud sensor frames (ctypes bindings of
liboctoprox; see the README and include/octoprox/ for the semantics).

    import octoprox
    with octoprox.Octree(resolution=0.05) as tree, octoprox.LinkSet() as robot:
        ...
        hit = octoprox.Query().collide(tree, robot)

The objects: Octree (the map, in the map frame), LinkSet (the robot's
links and shapes, from URDF or by hand), Query (one per thread: collide,
distance, path, self_collide, check_configurations...), World (known
objects beside the map, from MoveIt planning scenes or by hand; the
``world=`` keyword of Query.collide and Query.distance).  Units are metres
and radians; poses are x y z qx qy qz qw (ROS order).  Named values are
IntEnum classes (CellClass, Engine, UnknownPolicy, ObstacleGeometry,
JointOrder, ...),
also exported as constants (CELL_OCCUPIED, ENGINE_AMORTIZED, ...).
Failures raise OctoproxError subclasses that name the Python method, e.g.
"Query.collide: ...".  The library is found through $OPX_LIBRARY, next to
this package, or on the system's library path.
"""
from ._enums import (CellClass, CellMask, Engine, FileFormat, InsertMode, JointOrder, JointType,
                     ObstacleGeometry, ShapeKind, UnknownPolicy)
from ._errors import (BufferTooSmallError, CorruptDataError, InternalError,
                      InvalidArgumentError, IoError, OctoproxError, OutOfMemoryError,
                      UnsupportedError, VersionError)
from ._library import HEADER_VERSION, lib
from ._structs import (CameraIntrinsics, CellInfo, CollisionRequest, CollisionResult, Contact,
                       CostBox, DepthImage, DistanceRequest, DistanceResult, InsertOptions,
                       InsertReport, JointInfo, Leaf, OctreeOptions, OctreeStats,
                       PairSamplingOptions, PairSamplingResult, PathRequest, PathResult,
                       PointCloudInfo, Pose, QueryOptions, QueryStats, SelfCollisionRequest,
                       SelfCollisionResult, SelfContact, SelfDistanceRequest, SelfDistanceResult,
                       SphereDistanceRequest, SphereRequest, TrajectoryCostRequest,
                       UrdfOptions)
from .linkset import (SHAPE_BOX, SHAPE_CAPSULE, SHAPE_CONVEX, SHAPE_CYLINDER, SHAPE_MESH,
                      SHAPE_SPHERE, LinkSet)
from .octree import (FORMAT_AUTO, FORMAT_BT, FORMAT_OPX, FORMAT_OT, MASK_ALL_KNOWN, MASK_FREE,
                     MASK_OCCUPIED, MASK_UNCERTAIN, Octree)
from .robot import (JOINT_CONTINUOUS, JOINT_FIXED, JOINT_FLOATING, JOINT_NONE, JOINT_PLANAR,
                    JOINT_PRISMATIC, JOINT_REVOLUTE)
from .query import (ALL_CONTACTS, ENGINE_AMORTIZED, ENGINE_DIRECT, OBSTACLE_CELLS,
                    OBSTACLE_POINT_EXTENTS, UNKNOWN_FREE, UNKNOWN_OCCUPIED, Query)
from .world import World
from .batch import JOINTS_ACTIVE, JOINTS_BY_COUNT, JOINTS_MODEL
from . import io  # PCD and PLY files as numpy arrays: io.read_pcd, io.read_ply

CELL_UNKNOWN, CELL_FREE, CELL_UNCERTAIN, CELL_OCCUPIED = CellClass
INSERT_RAYCAST, INSERT_ENDPOINTS = InsertMode


def version() -> str:
    """The run-time library version, e.g. "0.1.0"."""
    return lib.opx_version().decode()


def version_number() -> int:
    """The run-time OPX_VERSION_NUMBER (major * 10000 + minor * 100 + patch)."""
    return lib.opx_version_number()


def status_name(status: int) -> str:
    """The name of a status code, e.g. "OPX_ERROR_IO"."""
    return lib.opx_status_name(status).decode()


__version__ = "%d.%d.%d" % HEADER_VERSION

__all__ = [
    "Octree", "LinkSet", "Query", "World", "io", "version", "version_number", "status_name",
    "HEADER_VERSION", "lib",
    # named values
    "CellClass", "CellMask", "Engine", "FileFormat", "InsertMode", "JointOrder", "JointType",
    "ObstacleGeometry", "ShapeKind", "UnknownPolicy",
    # results, requests and options (the C structs)
    "CameraIntrinsics", "CellInfo", "CollisionRequest", "CollisionResult", "Contact", "CostBox",
    "DepthImage", "DistanceRequest",
    "DistanceResult", "InsertOptions", "InsertReport", "JointInfo", "Leaf", "OctreeOptions",
    "OctreeStats", "PairSamplingOptions", "PairSamplingResult", "PathRequest", "PathResult", "PointCloudInfo", "Pose",
    "QueryOptions", "QueryStats", "SelfCollisionRequest", "SelfCollisionResult", "SelfContact",
    "SelfDistanceRequest", "SelfDistanceResult", "SphereDistanceRequest", "SphereRequest",
    "TrajectoryCostRequest", "UrdfOptions",
    # exceptions
    "OctoproxError", "InvalidArgumentError", "OutOfMemoryError", "VersionError",
    "BufferTooSmallError", "UnsupportedError", "IoError", "CorruptDataError", "InternalError",
    # constants (members of the named values above)
    "CELL_UNKNOWN", "CELL_FREE", "CELL_UNCERTAIN", "CELL_OCCUPIED", "INSERT_RAYCAST",
    "INSERT_ENDPOINTS", "MASK_FREE", "MASK_UNCERTAIN", "MASK_OCCUPIED", "MASK_ALL_KNOWN",
    "FORMAT_AUTO", "FORMAT_BT", "FORMAT_OT", "FORMAT_OPX", "ENGINE_DIRECT", "ENGINE_AMORTIZED",
    "UNKNOWN_FREE", "UNKNOWN_OCCUPIED", "OBSTACLE_CELLS", "OBSTACLE_POINT_EXTENTS",
    "ALL_CONTACTS", "JOINT_FIXED", "JOINT_REVOLUTE", "JOINT_CONTINUOUS",
    "JOINT_PRISMATIC", "JOINT_FLOATING", "JOINT_PLANAR", "JOINT_NONE", "SHAPE_SPHERE",
    "SHAPE_BOX", "SHAPE_CYLINDER", "SHAPE_CAPSULE", "SHAPE_CONVEX", "SHAPE_MESH",
    "JOINTS_BY_COUNT", "JOINTS_MODEL", "JOINTS_ACTIVE",
]
