"""ctypes mirrors of the C structs of include/octoprox/ (same field names,
same order; the tests check every size against the library's own)."""
import ctypes
from ctypes import c_double, c_int32, c_size_t, c_uint32, c_uint64, c_int64, c_void_p

D3 = c_double * 3


class Struct(ctypes.Structure):
    """A C struct with a readable repr and ``to_dict()``."""

    def to_dict(self):
        out = {}
        for name, _ in self._fields_:
            value = getattr(self, name)
            if isinstance(value, ctypes.Array):
                value = tuple(value)
            elif isinstance(value, Struct):
                value = value.to_dict()
            out[name] = value
        return out

    def __repr__(self):
        fields = ", ".join(f"{k}={v!r}" for k, v in self.to_dict().items()
                           if not k.startswith("reserved") and k != "struct_size")
        return f"{type(self).__name__}({fields})"


class Pose(Struct):
    """position x y z (metres), orientation qx qy qz qw (ROS order)."""
    _fields_ = [("position", D3), ("orientation", c_double * 4)]


class OctreeOptions(Struct):
    _fields_ = [("struct_size", c_uint32), ("reserved0", c_uint32), ("resolution", c_double),
                ("prob_hit", c_double), ("prob_miss", c_double), ("clamp_min", c_double),
                ("clamp_max", c_double), ("occupied_threshold", c_double),
                ("free_threshold", c_double)]


class InsertOptions(Struct):
    _fields_ = [("struct_size", c_uint32), ("mode", c_int32), ("sensor_pose", Pose),
                ("max_range", c_double), ("max_threads", c_uint32), ("reserved0", c_uint32)]


class InsertReport(Struct):
    _fields_ = [("struct_size", c_uint32), ("reserved0", c_uint32),
                ("points_used", c_uint64), ("points_nonfinite", c_uint64),
                ("points_out_of_range", c_uint64), ("points_outside_map", c_uint64),
                ("cells_hit", c_uint64), ("cells_missed", c_uint64),
                ("pixels_no_return", c_uint64)]


class DepthImage(Struct):
    _fields_ = [("struct_size", c_uint32), ("scalar_type", c_int32), ("data", c_void_p),
                ("width", c_size_t), ("height", c_size_t), ("row_stride", c_size_t),
                ("depth_scale", c_double)]


class CameraIntrinsics(Struct):
    """A pinhole camera in pixels: fx, fy (focal lengths), cx, cy
    (principal point: column, row)."""
    _fields_ = [("struct_size", c_uint32), ("reserved0", c_uint32), ("fx", c_double),
                ("fy", c_double), ("cx", c_double), ("cy", c_double)]


class CellInfo(Struct):
    _fields_ = [("struct_size", c_uint32), ("cell_class", c_int32), ("probability", c_double),
                ("center", D3), ("size", c_double), ("depth", c_uint32),
                ("reserved0", c_uint32)]


class OctreeStats(Struct):
    _fields_ = [("struct_size", c_uint32), ("has_occupied", c_int32), ("resolution", c_double),
                ("leaves_occupied", c_uint64), ("leaves_uncertain", c_uint64),
                ("leaves_free", c_uint64), ("inner_nodes", c_uint64),
                ("memory_bytes", c_uint64), ("occupied_min", D3), ("occupied_max", D3),
                ("known_min", D3), ("known_max", D3), ("leaves_with_extent", c_uint64)]


class Leaf(Struct):
    _fields_ = [("center", D3), ("size", c_double), ("probability", c_double),
                ("cell_class", c_int32), ("depth", c_uint32)]


class Shape(Struct):
    _fields_ = [("struct_size", c_uint32), ("kind", c_int32), ("pose", Pose),
                ("radius", c_double), ("length", c_double), ("size", D3),
                ("vertices", c_void_p), ("vertex_count", c_size_t),
                ("vertex_stride", c_size_t), ("indices", c_void_p),
                ("triangle_count", c_size_t)]


class QueryOptions(Struct):
    _fields_ = [("struct_size", c_uint32), ("engine", c_int32), ("refine_steps", c_uint32),
                ("morton_bits", c_uint32)]


class QueryStats(Struct):
    _fields_ = [("struct_size", c_uint32), ("engine", c_int32), ("boxes", c_uint64),
                ("builds", c_uint64), ("refine_steps_done", c_uint64),
                ("sah_ratio", c_double), ("extract_ms", c_double), ("build_ms", c_double)]


class CollisionRequest(Struct):
    _fields_ = [("struct_size", c_uint32), ("unknown_policy", c_int32),
                ("occupancy_threshold", c_double), ("max_contacts", c_uint32),
                ("compute_cost", c_int32), ("max_cost_boxes", c_uint32),
                ("reserved0", c_uint32), ("unknown_probability", c_double),
                ("region_min", D3), ("region_max", D3), ("compute_penetration", c_int32),
                ("obstacle_geometry", c_int32)]


class CollisionResult(Struct):
    _fields_ = [("struct_size", c_uint32), ("collided", c_int32), ("contact_count", c_uint64),
                ("truncated", c_int32), ("reserved0", c_uint32), ("narrow_tests", c_uint64),
                ("total_cost", c_double), ("cost_box_count", c_uint64),
                ("cost_boxes_found", c_uint64)]


class Contact(Struct):
    _fields_ = [("struct_size", c_uint32), ("link", c_uint32), ("shape", c_uint32),
                ("cell_class", c_int32), ("cell_center", D3), ("cell_size", c_double),
                ("cell_probability", c_double), ("depth", c_double), ("normal", D3),
                ("position", D3)]


class CostBox(Struct):
    _fields_ = [("struct_size", c_uint32), ("link", c_uint32), ("cell_class", c_int32),
                ("reserved0", c_uint32), ("min", D3), ("max", D3), ("probability", c_double),
                ("cost", c_double), ("cell_center", D3), ("cell_size", c_double)]


class DistanceRequest(Struct):
    _fields_ = [("struct_size", c_uint32), ("unknown_policy", c_int32),
                ("occupancy_threshold", c_double), ("abs_err", c_double),
                ("rel_err", c_double), ("cutoff", c_double), ("per_link", c_int32),
                ("signed_distance", c_int32), ("obstacle_geometry", c_int32),
                ("reserved0", c_int32)]


class DistanceResult(Struct):
    _fields_ = [("struct_size", c_uint32), ("found", c_int32), ("collided", c_int32),
                ("cell_class", c_int32), ("link", c_uint32), ("shape", c_uint32),
                ("distance", c_double), ("point_on_link", D3), ("point_on_cell", D3),
                ("cell_center", D3), ("cell_size", c_double), ("cell_probability", c_double),
                ("narrow_tests", c_uint64)]


class SelfCollisionRequest(Struct):
    _fields_ = [("struct_size", c_uint32), ("max_contacts", c_uint32),
                ("compute_penetration", c_int32), ("reserved0", c_int32)]


class SelfCollisionResult(Struct):
    _fields_ = [("struct_size", c_uint32), ("collided", c_int32), ("contact_count", c_uint64),
                ("truncated", c_int32), ("reserved0", c_uint32), ("link_pairs", c_uint64),
                ("narrow_tests", c_uint64)]


class SelfContact(Struct):
    _fields_ = [("struct_size", c_uint32), ("link_a", c_uint32), ("shape_a", c_uint32),
                ("link_b", c_uint32), ("shape_b", c_uint32), ("reserved0", c_uint32),
                ("depth", c_double), ("normal", D3), ("position", D3)]


class SelfDistanceRequest(Struct):
    _fields_ = [("struct_size", c_uint32), ("signed_distance", c_int32), ("cutoff", c_double)]


class SelfDistanceResult(Struct):
    _fields_ = [("struct_size", c_uint32), ("found", c_int32), ("collided", c_int32),
                ("link_a", c_uint32), ("shape_a", c_uint32), ("link_b", c_uint32),
                ("shape_b", c_uint32), ("reserved0", c_uint32), ("distance", c_double),
                ("point_on_a", D3), ("point_on_b", D3), ("link_pairs", c_uint64),
                ("narrow_tests", c_uint64)]


class PairSamplingOptions(Struct):
    _fields_ = [("struct_size", c_uint32), ("samples", c_uint32), ("seed", c_uint64),
                ("also_always_colliding", c_int32), ("also_colliding_now", c_int32)]


class PairSamplingResult(Struct):
    _fields_ = [("struct_size", c_uint32), ("now", c_uint32), ("never", c_uint32),
                ("always", c_uint32)]


class PathRequest(Struct):
    _fields_ = [("struct_size", c_uint32), ("unknown_policy", c_int32),
                ("occupancy_threshold", c_double), ("compute_distance", c_int32),
                ("compute_cost", c_int32), ("max_cost_boxes", c_uint32),
                ("obstacle_geometry", c_int32), ("unknown_probability", c_double),
                ("region_min", D3), ("region_max", D3)]


class PathResult(Struct):
    _fields_ = [("struct_size", c_uint32), ("collided", c_int32),
                ("first_colliding_waypoint", c_int64), ("min_distance", c_double),
                ("min_distance_waypoint", c_int64), ("total_cost", c_double),
                ("cost_box_count", c_uint64), ("cost_boxes_found", c_uint64),
                ("narrow_tests", c_uint64)]


class BatchRequest(Struct):
    _fields_ = [("struct_size", c_uint32), ("unknown_policy", c_int32),
                ("occupancy_threshold", c_double), ("self_collision", c_int32),
                ("compute_distance", c_int32), ("distance_cutoff", c_double),
                ("max_threads", c_uint32), ("obstacle_geometry", c_int32)]


class MotionRequest(Struct):
    _fields_ = [("struct_size", c_uint32), ("unknown_policy", c_int32),
                ("occupancy_threshold", c_double), ("resolution", c_double),
                ("self_collision", c_int32), ("compute_cost", c_int32),
                ("max_cost_boxes", c_uint32), ("max_threads", c_uint32),
                ("unknown_probability", c_double), ("region_min", D3), ("region_max", D3),
                ("obstacle_geometry", c_int32), ("reserved0", c_int32)]


class MotionResult(Struct):
    _fields_ = [("struct_size", c_uint32), ("collided", c_int32),
                ("first_collision_fraction", c_double), ("steps", c_uint64),
                ("configurations_checked", c_uint64), ("total_cost", c_double),
                ("cost_box_count", c_uint64), ("cost_boxes_found", c_uint64)]


class UrdfOptions(Struct):
    _fields_ = [("struct_size", c_uint32), ("reserved0", c_uint32),
                ("package_dirs", ctypes.POINTER(ctypes.c_char_p)),
                ("package_dir_count", c_size_t), ("base_dir", ctypes.c_char_p),
                ("srdf_path", ctypes.c_char_p)]


class JointInfo(Struct):
    """One URDF joint; ``name`` is decoded to str, link indices and
    ``mimic_joint`` are JOINT_NONE when absent."""
    _fields_ = [("struct_size", c_uint32), ("type", c_int32), ("_name", ctypes.c_char_p),
                ("parent_link", c_uint32), ("child_link", c_uint32), ("axis", D3),
                ("origin", Pose), ("has_limits", c_int32), ("mimic_joint", c_uint32),
                ("lower", c_double), ("upper", c_double), ("velocity", c_double),
                ("effort", c_double), ("mimic_multiplier", c_double),
                ("mimic_offset", c_double)]

    @property
    def name(self):
        return (self._name or b"").decode("utf-8", "replace")

    def to_dict(self):
        out = super().to_dict()
        out["name"] = self.name
        del out["_name"]
        return out


class PointCloudInfo(Struct):
    """What a PCD or PLY file holds (include/octoprox/io.h)."""
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
