"""ctypes mirrors of the C structs of include/octoprox/ (same field names,
same order; the tests check every size against the library's own): the
octree's, the link set's, the robot's and the files' here, the queries' in
_query_structs (imported here too).

Units are metres, radians and m^3 (costs); points and poses are in the map
frame unless a docstring says otherwise.  Flags read as bool and class or
kind codes as IntEnum members (typed_fields at the end of each file).
"""
import ctypes
from ctypes import c_double, c_int32, c_size_t, c_uint32, c_uint64, c_void_p

from ._enums import CellClass, InsertMode, JointType, ShapeKind, converter
from ._query_structs import (BatchRequest, CollisionRequest, CollisionResult, Contact, CostBox,
                             DistanceRequest, DistanceResult, MotionRequest, MotionResult,
                             PathRequest, PathResult, QueryOptions, QueryStats,
                             SelfCollisionRequest, SelfCollisionResult, SelfContact,
                             SelfDistanceRequest, SelfDistanceResult, SphereDistanceRequest,
                             SphereRequest, TrajectoryCostRequest)
from ._struct_base import D3, Pose, Struct, typed_fields


class OctreeOptions(Struct):
    """The options of a new octree (Octree(...) keywords).  resolution:
    the edge of a finest cell, 1e-6 to 1e6 m (0.05); prob_hit, prob_miss:
    the updates of a cell holding an endpoint (0.7) and of one a ray
    passes (0.4); clamp_min, clamp_max: the clamping bounds (0.1192,
    0.971); occupied_threshold: occupied when p >= it (0.5);
    free_threshold: free when p < it (0.5; lower it, e.g. 0.3, for an
    uncertain band)."""
    _fields_ = [("struct_size", c_uint32), ("reserved0", c_uint32), ("resolution", c_double),
                ("prob_hit", c_double), ("prob_miss", c_double), ("clamp_min", c_double),
                ("clamp_max", c_double), ("occupied_threshold", c_double),
                ("free_threshold", c_double)]


class InsertOptions(Struct):
    """How a sensor frame is inserted: mode (InsertMode, RAYCAST),
    sensor_pose (the sensor frame in the map frame, identity), max_range
    (metres from the sensor; farther points give no occupied cell; <= 0:
    no limit, the default -1), max_threads (1: the caller's thread only,
    the default; 0: one per hardware thread; the map does not depend on
    it); self-filtering (Octree.insert_points' robot keywords): robot (the
    address of the robot's opx_linkset; None: no filtering),
    robot_padding (metres added to every link's padding for the filter,
    0), clear_robot_volume (cells inside the robot become free; False);
    use_bounds (only the cells of the box bounds_min..bounds_max, map
    frame, change; False)."""
    _fields_ = [("struct_size", c_uint32), ("mode", c_int32), ("sensor_pose", Pose),
                ("max_range", c_double), ("max_threads", c_uint32), ("reserved0", c_uint32),
                ("robot", c_void_p), ("robot_padding", c_double),
                ("clear_robot_volume", c_uint32), ("reserved1", c_uint32),
                ("use_bounds", c_uint32), ("reserved2", c_uint32),
                ("bounds_min", D3), ("bounds_max", D3)]


class InsertReport(Struct):
    """What one insert did; every point (or pixel) is counted once:
    points_used + points_nonfinite + points_out_of_range +
    points_outside_map + points_on_robot + points_shadowed +
    pixels_no_return.  cells_hit: cells updated as occupied; cells_missed:
    as free; cells_cleared: set free as inside the robot (self-filtering's
    clear_robot_volume)."""
    _fields_ = [("struct_size", c_uint32), ("reserved0", c_uint32),
                ("points_used", c_uint64), ("points_nonfinite", c_uint64),
                ("points_out_of_range", c_uint64), ("points_outside_map", c_uint64),
                ("cells_hit", c_uint64), ("cells_missed", c_uint64),
                ("pixels_no_return", c_uint64), ("points_on_robot", c_uint64),
                ("points_shadowed", c_uint64), ("cells_cleared", c_uint64)]


class DepthImage(Struct):
    """A depth frame as the library reads it (Octree.insert_depth_image
    fills it from a numpy array): scalar_type (uint16 units of
    1/depth_scale m, or float32 metres), data, width, height, row_stride
    (bytes), depth_scale (units per metre, 1000)."""
    _fields_ = [("struct_size", c_uint32), ("scalar_type", c_int32), ("data", c_void_p),
                ("width", c_size_t), ("height", c_size_t), ("row_stride", c_size_t),
                ("depth_scale", c_double)]


class CameraIntrinsics(Struct):
    """A pinhole camera in pixels: fx, fy (focal lengths), cx, cy
    (principal point: column, row)."""
    _fields_ = [("struct_size", c_uint32), ("reserved0", c_uint32), ("fx", c_double),
                ("fy", c_double), ("cx", c_double), ("cy", c_double)]


class CellInfo(Struct):
    """The cell holding a point (Octree.classify): cell_class (CellClass),
    probability (0.5 when unknown), center (map frame, m), size (edge, m;
    for unknown space the largest unobserved cube holding the point),
    depth (0 for the root cube to 16 for the finest cells)."""
    _fields_ = [("struct_size", c_uint32), ("cell_class", c_int32), ("probability", c_double),
                ("center", D3), ("size", c_double), ("depth", c_uint32),
                ("reserved0", c_uint32)]


class OctreeStats(Struct):
    """Counts, bounds and memory of a map (Octree.stats): resolution (m),
    leaves_occupied, leaves_uncertain, leaves_free, inner_nodes,
    memory_bytes; occupied_min/max (tight bounds of the occupied cells,
    map frame; zeros unless has_occupied), known_min/max (of every
    observed cell); leaves_with_extent (occupied leaves keeping the box of
    their sensed points, for ObstacleGeometry.POINT_EXTENTS)."""
    _fields_ = [("struct_size", c_uint32), ("has_occupied", c_int32), ("resolution", c_double),
                ("leaves_occupied", c_uint64), ("leaves_uncertain", c_uint64),
                ("leaves_free", c_uint64), ("inner_nodes", c_uint64),
                ("memory_bytes", c_uint64), ("occupied_min", D3), ("occupied_max", D3),
                ("known_min", D3), ("known_max", D3), ("leaves_with_extent", c_uint64)]


class Leaf(Struct):
    """One leaf of the map (a row of Octree.leaves()): center (map frame,
    m), size (edge, m), probability, cell_class, depth (0 to 16)."""
    _fields_ = [("center", D3), ("size", c_double), ("probability", c_double),
                ("cell_class", c_int32), ("depth", c_uint32)]


class Shape(Struct):
    """One shape of a link as the library takes it (LinkSet.add_sphere and
    the other add_* methods fill it): kind (ShapeKind), pose (the shape
    frame in the link frame), radius, length (cylinder: full; capsule:
    the cylindrical part), size (box: full edge lengths), vertices and
    triangles of convex hulls and meshes.  Metres."""
    _fields_ = [("struct_size", c_uint32), ("kind", c_int32), ("pose", Pose),
                ("radius", c_double), ("length", c_double), ("size", D3),
                ("vertices", c_void_p), ("vertex_count", c_size_t),
                ("vertex_stride", c_size_t), ("indices", c_void_p),
                ("triangle_count", c_size_t)]


class PairSamplingOptions(Struct):
    """The options of LinkSet.disable_never_colliding_pairs: samples
    (10000), seed (1), also_always_colliding, also_colliding_now."""
    _fields_ = [("struct_size", c_uint32), ("samples", c_uint32), ("seed", c_uint64),
                ("also_always_colliding", c_int32), ("also_colliding_now", c_int32)]


class PairSamplingResult(Struct):
    """How many pairs each rule of
    LinkSet.disable_never_colliding_pairs disabled: now (colliding at the
    current poses), never (in no sample), always (in every sample)."""
    _fields_ = [("struct_size", c_uint32), ("now", c_uint32), ("never", c_uint32),
                ("always", c_uint32)]


class UrdfOptions(Struct):
    """The options of LinkSet.from_urdf: package_dirs (folders or
    "NAME=DIR" entries resolving package:// meshes), base_dir (relative
    meshes), srdf_path (its disabled pairs)."""
    _fields_ = [("struct_size", c_uint32), ("reserved0", c_uint32),
                ("package_dirs", ctypes.POINTER(ctypes.c_char_p)),
                ("package_dir_count", c_size_t), ("base_dir", ctypes.c_char_p),
                ("srdf_path", ctypes.c_char_p)]


class JointInfo(Struct):
    """One URDF joint (LinkSet.joint_info): type (JointType), name,
    parent_link and child_link (link indices), axis (unit, child link
    frame), origin (the child link frame in the parent's at 0),
    has_limits, mimic_joint, lower and upper (m or rad), velocity,
    effort, mimic_multiplier and mimic_offset; link indices and
    mimic_joint are JOINT_NONE when absent."""
    _fields_ = [("struct_size", c_uint32), ("type", c_int32), ("_name", ctypes.c_char_p),
                ("parent_link", c_uint32), ("child_link", c_uint32), ("axis", D3),
                ("origin", Pose), ("has_limits", c_int32), ("mimic_joint", c_uint32),
                ("lower", c_double), ("upper", c_double), ("velocity", c_double),
                ("effort", c_double), ("mimic_multiplier", c_double),
                ("mimic_offset", c_double)]

    @property
    def name(self) -> str:
        """The joint's name."""
        return (self._name or b"").decode("utf-8", "replace")

    def to_dict(self):
        """Every field by name, ``name`` as str."""
        out = super().to_dict()
        out["name"] = self.name
        del out["_name"]
        return out


class PointCloudInfo(Struct):
    """What a PCD or PLY file holds (octoprox.io reads it): format,
    encoding, has_viewpoint, point_count, finite_count, width and height
    (an organized cloud's columns and rows), viewpoint (PCD VIEWPOINT)."""
    _fields_ = [("struct_size", c_uint32), ("format", c_int32), ("encoding", c_int32),
                ("has_viewpoint", c_int32), ("point_count", c_uint64), ("finite_count", c_uint64),
                ("width", c_uint64), ("height", c_uint64), ("viewpoint", Pose)]


# Each versioned struct and the name of its opx_x_init function.
VERSIONED = {
    OctreeOptions: "opx_octree_options_init",
    InsertOptions: "opx_insert_options_init",
    InsertReport: "opx_insert_report_init",
    DepthImage: "opx_depth_image_init",
    CameraIntrinsics: "opx_camera_intrinsics_init",
    CellInfo: "opx_cell_info_init",
    OctreeStats: "opx_octree_stats_init",
    Shape: "opx_shape_init",
    QueryOptions: "opx_query_options_init",
    QueryStats: "opx_query_stats_init",
    CollisionRequest: "opx_collision_request_init",
    CollisionResult: "opx_collision_result_init",
    Contact: "opx_contact_init",
    CostBox: "opx_cost_box_init",
    DistanceRequest: "opx_distance_request_init",
    DistanceResult: "opx_distance_result_init",
    SelfCollisionRequest: "opx_self_collision_request_init",
    SelfCollisionResult: "opx_self_collision_result_init",
    SelfContact: "opx_self_contact_init",
    SelfDistanceRequest: "opx_self_distance_request_init",
    SphereRequest: "opx_sphere_request_init",
    SphereDistanceRequest: "opx_sphere_distance_request_init",
    TrajectoryCostRequest: "opx_trajectory_cost_request_init",
    SelfDistanceResult: "opx_self_distance_result_init",
    PairSamplingOptions: "opx_pair_sampling_options_init",
    PairSamplingResult: "opx_pair_sampling_result_init",
    PathRequest: "opx_path_request_init",
    PathResult: "opx_path_result_init",
    BatchRequest: "opx_batch_request_init",
    MotionRequest: "opx_motion_request_init",
    MotionResult: "opx_motion_result_init",
    UrdfOptions: "opx_urdf_options_init",
    JointInfo: "opx_joint_info_init",
    PointCloudInfo: "opx_point_cloud_info_init",
}

# Flags read as bool, codes as IntEnum members (written back as ints).
typed_fields(InsertOptions, mode=converter(InsertMode), clear_robot_volume=bool, use_bounds=bool)
typed_fields(CellInfo, cell_class=converter(CellClass))
typed_fields(OctreeStats, has_occupied=bool)
typed_fields(Shape, kind=converter(ShapeKind))
typed_fields(PairSamplingOptions, also_always_colliding=bool, also_colliding_now=bool)
typed_fields(JointInfo, type=converter(JointType), has_limits=bool)
typed_fields(PointCloudInfo, has_viewpoint=bool)
