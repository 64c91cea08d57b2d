"""ctypes mirrors of the query structs (include/octoprox/query.h,
self_collision.h, batch.h): options, requests, results and the rows of
contacts and cost boxes.  Same field names and order as the C structs;
units are metres and m^3 (costs), points are in the map frame.  Flags read
as bool, codes as IntEnum members.
"""
from ctypes import c_double, c_int32, c_uint32, c_uint64, c_int64

from ._enums import CellClass, Engine, JointOrder, ObstacleGeometry, UnknownPolicy, converter
from ._struct_base import D3, Struct, typed_fields


class QueryOptions(Struct):
    """The options of a new Query: engine (Engine, DIRECT), refine_steps
    (amortized engine: refinement paths per query, 1), morton_bits
    (amortized engine: lattice bits per axis, 1 to 21, 10)."""
    _fields_ = [("struct_size", c_uint32), ("engine", c_int32), ("refine_steps", c_uint32),
                ("morton_bits", c_uint32)]


class QueryStats(Struct):
    """What a query context holds (Query.stats; amortized engine, zeros
    for the direct one): engine, boxes (obstacle boxes in the bound tree),
    builds (trees built), refine_steps_done, sah_ratio (the tree's
    surface-area cost over a median-split tree's), extract_ms and
    build_ms (the last bind: cells to boxes, boxes to the tree)."""
    _fields_ = [("struct_size", c_uint32), ("engine", c_int32), ("boxes", c_uint64),
                ("builds", c_uint64), ("refine_steps_done", c_uint64),
                ("sah_ratio", c_double), ("extract_ms", c_double), ("build_ms", c_double)]


class CollisionRequest(Struct):
    """The options of a collision query (Query.collide keywords):
    unknown_policy (UnknownPolicy.FREE), occupancy_threshold (cells with
    p >= it are obstacles; 0: the octree's occupied_threshold),
    max_contacts (0: yes/no only; 1: the first contact, the default; N:
    up to N; 0xFFFFFFFF: all), compute_cost (the cost of uncertain and
    unknown space), max_cost_boxes (16), unknown_probability (0.5),
    region_min/max (where unknown space counts, map frame; zeros: the
    observed cells' bounds), compute_penetration (depth, normal and point
    of each contact), obstacle_geometry (ObstacleGeometry.CELLS)."""
    _fields_ = [("struct_size", c_uint32), ("unknown_policy", c_int32),
                ("occupancy_threshold", c_double), ("max_contacts", c_uint32),
                ("compute_cost", c_int32), ("max_cost_boxes", c_uint32),
                ("reserved0", c_uint32), ("unknown_probability", c_double),
                ("region_min", D3), ("region_max", D3), ("compute_penetration", c_int32),
                ("obstacle_geometry", c_int32)]


class CollisionResult(Struct):
    """The answer of a collision query: collided (bool), contact_count
    (contacts held by the query: Query.contacts()), truncated (a contact
    beyond max_contacts was left out), narrow_tests (exact tests run),
    total_cost (m^3, over all cost boxes), cost_box_count (held:
    Query.cost_boxes()), cost_boxes_found."""
    _fields_ = [("struct_size", c_uint32), ("collided", c_int32), ("contact_count", c_uint64),
                ("truncated", c_int32), ("reserved0", c_uint32), ("narrow_tests", c_uint64),
                ("total_cost", c_double), ("cost_box_count", c_uint64),
                ("cost_boxes_found", c_uint64)]


class Contact(Struct):
    """One contact (a row of Query.contacts()): link, shape, cell_class,
    cell_center (map frame, m), cell_size, cell_probability (0.5 for
    unknown cells); with compute_penetration depth (m, >= 0), normal
    (moving the link by -depth * normal separates it) and position (map
    frame); object and object_shape: the world object touched (its
    index; its cell fields are then zeros), object -1 for a cell;
    attached: the object attached to the link whose shape touched (its
    index, shape then its shape's index), -1 for the link's own."""
    _fields_ = [("struct_size", c_uint32), ("link", c_uint32), ("shape", c_uint32),
                ("cell_class", c_int32), ("cell_center", D3), ("cell_size", c_double),
                ("cell_probability", c_double), ("depth", c_double), ("normal", D3),
                ("position", D3), ("object", c_int32), ("object_shape", c_uint32),
                ("attached", c_int32), ("reserved1", c_uint32)]


class CostBox(Struct):
    """A box of uncertain or unknown space overlapped by a link (a row of
    Query.cost_boxes()): link, cell_class, min and max (map frame, m),
    probability, cost (probability x volume, m^3), cell_center and
    cell_size of the whole cell."""
    _fields_ = [("struct_size", c_uint32), ("link", c_uint32), ("cell_class", c_int32),
                ("reserved0", c_uint32), ("min", D3), ("max", D3), ("probability", c_double),
                ("cost", c_double), ("cell_center", D3), ("cell_size", c_double)]


class DistanceRequest(Struct):
    """The options of a distance query (Query.distance keywords):
    unknown_policy, occupancy_threshold (as CollisionRequest), abs_err and
    rel_err (the reported distance exceeds the minimum by at most
    max(abs_err, rel_err * distance); 0 and 0: exact), cutoff (obstacles
    farther are not searched: found False, distance = cutoff; 0: none),
    per_link (also each link's minimum: Query.link_distances()),
    signed_distance (overlap as minus the deepest penetration),
    obstacle_geometry."""
    _fields_ = [("struct_size", c_uint32), ("unknown_policy", c_int32),
                ("occupancy_threshold", c_double), ("abs_err", c_double),
                ("rel_err", c_double), ("cutoff", c_double), ("per_link", c_int32),
                ("signed_distance", c_int32), ("obstacle_geometry", c_int32),
                ("reserved0", c_int32)]


class DistanceResult(Struct):
    """The answer of a distance query: found (an obstacle within the
    cutoff), collided (distance <= 1e-9 m), cell_class, link and shape
    (the closest), distance (m, padding included; >= 0 unless signed),
    point_on_link and point_on_cell (witnesses, map frame), cell_center,
    cell_size, cell_probability, narrow_tests; object and object_shape:
    the nearest world object (point_on_cell lies on it), object -1 for a
    cell; attached: the object attached to the link whose shape is the
    nearest (shape then its index in that object), -1 for the link's own."""
    _fields_ = [("struct_size", c_uint32), ("found", c_int32), ("collided", c_int32),
                ("cell_class", c_int32), ("link", c_uint32), ("shape", c_uint32),
                ("distance", c_double), ("point_on_link", D3), ("point_on_cell", D3),
                ("cell_center", D3), ("cell_size", c_double), ("cell_probability", c_double),
                ("narrow_tests", c_uint64), ("object", c_int32), ("object_shape", c_uint32),
                ("attached", c_int32), ("reserved0", c_uint32)]


class SelfCollisionRequest(Struct):
    """The options of Query.self_collide: max_contacts (0: yes/no; 1,
    the default: the first touching pair; N; 0xFFFFFFFF: all),
    compute_penetration."""
    _fields_ = [("struct_size", c_uint32), ("max_contacts", c_uint32),
                ("compute_penetration", c_int32), ("reserved0", c_int32)]


class SelfCollisionResult(Struct):
    """The answer of Query.self_collide: collided (bool),
    contact_count (held: Query.self_contacts()), truncated, link_pairs
    (checked pairs whose bounding boxes overlap), narrow_tests."""
    _fields_ = [("struct_size", c_uint32), ("collided", c_int32), ("contact_count", c_uint64),
                ("truncated", c_int32), ("reserved0", c_uint32), ("link_pairs", c_uint64),
                ("narrow_tests", c_uint64)]


class SelfContact(Struct):
    """Two touching shapes of two links (a row of Query.self_contacts()):
    link_a < link_b, shape_a, shape_b; with compute_penetration depth (m),
    normal (moving link_a by -depth * normal separates the pair) and
    position (map frame); attached_a and attached_b: the objects attached
    to the links whose shapes touch (shape_a or shape_b then the shape's
    index in that object), -1 for a link's own."""
    _fields_ = [("struct_size", c_uint32), ("link_a", c_uint32), ("shape_a", c_uint32),
                ("link_b", c_uint32), ("shape_b", c_uint32), ("reserved0", c_uint32),
                ("depth", c_double), ("normal", D3), ("position", D3),
                ("attached_a", c_int32), ("attached_b", c_int32)]


class SphereRequest(Struct):
    """The options of Query.collide_spheres: unknown_policy,
    occupancy_threshold (0: the octree's), obstacle_geometry."""
    _fields_ = [("struct_size", c_uint32), ("unknown_policy", c_int32),
                ("occupancy_threshold", c_double), ("obstacle_geometry", c_int32),
                ("reserved0", c_int32)]


class SphereDistanceRequest(Struct):
    """The options of Query.distance_spheres: unknown_policy,
    occupancy_threshold (0: the octree's), obstacle_geometry, max_threads
    (1: the caller's thread; 0: one per hardware thread), max_distance (m,
    > 0, inf allowed: spheres at least this far report it, a zero gradient
    and a NaN witness)."""
    _fields_ = [("struct_size", c_uint32), ("unknown_policy", c_int32),
                ("occupancy_threshold", c_double), ("obstacle_geometry", c_int32),
                ("max_threads", c_uint32), ("max_distance", c_double)]


class TrajectoryCostRequest(Struct):
    """The options of Query.trajectory_cost: unknown_policy,
    occupancy_threshold, obstacle_geometry, joint_order, activation (eps,
    m, > 0: CHOMP's activation distance)."""
    _fields_ = [("struct_size", c_uint32), ("unknown_policy", c_int32),
                ("occupancy_threshold", c_double), ("obstacle_geometry", c_int32),
                ("joint_order", c_int32), ("activation", c_double)]


class SelfDistanceRequest(Struct):
    """The options of Query.self_distance: signed_distance (overlap as
    minus the deepest penetration), cutoff (m; pairs farther are not
    measured; 0: none)."""
    _fields_ = [("struct_size", c_uint32), ("signed_distance", c_int32), ("cutoff", c_double)]


class SelfDistanceResult(Struct):
    """The answer of Query.self_distance: found, collided (distance <=
    1e-9 m), link_a < link_b and their shapes, distance (m, paddings
    included), point_on_a and point_on_b (witnesses, map frame),
    link_pairs, narrow_tests; attached_a and attached_b as in
    SelfContact."""
    _fields_ = [("struct_size", c_uint32), ("found", c_int32), ("collided", c_int32),
                ("link_a", c_uint32), ("shape_a", c_uint32), ("link_b", c_uint32),
                ("shape_b", c_uint32), ("reserved0", c_uint32), ("distance", c_double),
                ("point_on_a", D3), ("point_on_b", D3), ("link_pairs", c_uint64),
                ("narrow_tests", c_uint64), ("attached_a", c_int32), ("attached_b", c_int32)]


class PathRequest(Struct):
    """The options of Query.path: unknown_policy, occupancy_threshold (as
    CollisionRequest), compute_distance (the minimum distance along the
    path), compute_cost (the cost of uncertain and unknown space swept,
    each cell once), max_cost_boxes (16), obstacle_geometry,
    unknown_probability (0.5), region_min/max."""
    _fields_ = [("struct_size", c_uint32), ("unknown_policy", c_int32),
                ("occupancy_threshold", c_double), ("compute_distance", c_int32),
                ("compute_cost", c_int32), ("max_cost_boxes", c_uint32),
                ("obstacle_geometry", c_int32), ("unknown_probability", c_double),
                ("region_min", D3), ("region_max", D3)]


class PathResult(Struct):
    """The answer of Query.path: collided (bool),
    first_colliding_waypoint (-1: none), min_distance (m; +infinity
    without compute_distance), min_distance_waypoint, total_cost (m^3),
    cost_box_count (held: Query.cost_boxes()), cost_boxes_found,
    narrow_tests."""
    _fields_ = [("struct_size", c_uint32), ("collided", c_int32),
                ("first_colliding_waypoint", c_int64), ("min_distance", c_double),
                ("min_distance_waypoint", c_int64), ("total_cost", c_double),
                ("cost_box_count", c_uint64), ("cost_boxes_found", c_uint64),
                ("narrow_tests", c_uint64)]


class BatchRequest(Struct):
    """The options of Query.check_configurations: unknown_policy,
    occupancy_threshold, self_collision, compute_distance (the distance
    keyword), distance_cutoff (m; 0: none), max_threads (the threads
    keyword: 1, the caller's thread; 0: one per hardware thread),
    obstacle_geometry, joint_order (JointOrder: what a row holds)."""
    _fields_ = [("struct_size", c_uint32), ("unknown_policy", c_int32),
                ("occupancy_threshold", c_double), ("self_collision", c_int32),
                ("compute_distance", c_int32), ("distance_cutoff", c_double),
                ("max_threads", c_uint32), ("obstacle_geometry", c_int32),
                ("joint_order", c_int32), ("reserved0", c_int32)]


class MotionRequest(Struct):
    """The options of Query.check_motion and check_motions:
    unknown_policy, occupancy_threshold, resolution (the largest joint
    step between checked configurations, rad or m, 0.01), self_collision,
    compute_cost (check_motion only), max_cost_boxes, max_threads
    (check_motions), unknown_probability, region_min/max,
    obstacle_geometry, joint_order (JointOrder: what start and goal hold),
    check (MotionCheck: SAMPLED or CERTIFIED, the whole segment), tolerance
    (CERTIFIED: the bracket of the first colliding fraction, 1e-3)."""
    _fields_ = [("struct_size", c_uint32), ("unknown_policy", c_int32),
                ("occupancy_threshold", c_double), ("resolution", c_double),
                ("self_collision", c_int32), ("compute_cost", c_int32),
                ("max_cost_boxes", c_uint32), ("max_threads", c_uint32),
                ("unknown_probability", c_double), ("region_min", D3), ("region_max", D3),
                ("obstacle_geometry", c_int32), ("reserved0", c_int32),
                ("joint_order", c_int32), ("reserved1", c_int32),
                ("check", c_int32), ("reserved2", c_int32), ("tolerance", c_double)]


class MotionResult(Struct):
    """The answer of Query.check_motion: collided (bool),
    first_collision_fraction (i / n of the first colliding configuration;
    -1: none), steps (n: n + 1 configurations), configurations_checked,
    total_cost (m^3, with compute_cost), cost_box_count, cost_boxes_found."""
    _fields_ = [("struct_size", c_uint32), ("collided", c_int32),
                ("first_collision_fraction", c_double), ("steps", c_uint64),
                ("configurations_checked", c_uint64), ("total_cost", c_double),
                ("cost_box_count", c_uint64), ("cost_boxes_found", c_uint64)]


# Flags read as bool, codes as IntEnum members (written back as ints).
_CELL, _POLICY, _GEOMETRY = converter(CellClass), converter(UnknownPolicy), converter(ObstacleGeometry)
_ORDER = converter(JointOrder)
typed_fields(QueryOptions, engine=converter(Engine))
typed_fields(QueryStats, engine=converter(Engine))
typed_fields(CollisionRequest, unknown_policy=_POLICY, compute_cost=bool, compute_penetration=bool,
             obstacle_geometry=_GEOMETRY)
typed_fields(CollisionResult, collided=bool, truncated=bool)
typed_fields(DistanceRequest, unknown_policy=_POLICY, per_link=bool, signed_distance=bool,
             obstacle_geometry=_GEOMETRY)
typed_fields(DistanceResult, found=bool, collided=bool, cell_class=_CELL)
typed_fields(SelfCollisionRequest, compute_penetration=bool)
typed_fields(SelfCollisionResult, collided=bool, truncated=bool)
typed_fields(SelfDistanceRequest, signed_distance=bool)
typed_fields(SphereRequest, unknown_policy=_POLICY, obstacle_geometry=_GEOMETRY)
typed_fields(SphereDistanceRequest, unknown_policy=_POLICY, obstacle_geometry=_GEOMETRY)
typed_fields(TrajectoryCostRequest, unknown_policy=_POLICY, obstacle_geometry=_GEOMETRY)
typed_fields(SelfDistanceResult, found=bool, collided=bool)
typed_fields(PathRequest, unknown_policy=_POLICY, compute_distance=bool, compute_cost=bool,
             obstacle_geometry=_GEOMETRY)
typed_fields(PathResult, collided=bool)
typed_fields(BatchRequest, unknown_policy=_POLICY, self_collision=bool, compute_distance=bool,
             obstacle_geometry=_GEOMETRY, joint_order=_ORDER)
typed_fields(MotionRequest, unknown_policy=_POLICY, self_collision=bool, compute_cost=bool,
             obstacle_geometry=_GEOMETRY, joint_order=_ORDER)
typed_fields(MotionResult, collided=bool)
