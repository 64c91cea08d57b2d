"""Finds and loads liboctoprox, declares every exported function, and
checks the version.

The library is looked up, in order:
  1. $OPX_LIBRARY: the path of liboctoprox.so (nothing else is tried when
     it is set, so a wrong path is an error, not a silent fallback);
  2. next to this package (a wheel or a copy can ship the library inside);
  3. the system's library path (an installed liboctoprox.so.0.MINOR on 0.x,
     liboctoprox.so.MAJOR from 1.0 on: the library's SONAME).
"""
import ctypes
import ctypes.util
import os
from ctypes import POINTER, c_char_p, c_double, c_int32, c_size_t, c_uint32, c_void_p

from . import _structs as s
from ._errors import error_for

# The version of the headers these bindings mirror (include/octoprox/common.h;
# a test keeps them equal).
HEADER_VERSION = (0, 1, 0)

_ENV = "OPX_LIBRARY"
# The SONAME names the ABI: MAJOR.MINOR while MAJOR is 0, MAJOR from 1.0 on.
_SONAME = ("liboctoprox.so.%d.%d" % HEADER_VERSION[:2] if HEADER_VERSION[0] == 0
           else "liboctoprox.so.%d" % HEADER_VERSION[0])
_NAMES = ("liboctoprox.so", _SONAME, "liboctoprox.dylib", "octoprox.dll")


def _load():
    path = os.environ.get(_ENV)
    if path:
        try:
            return ctypes.CDLL(path)
        except OSError as error:
            raise ImportError(f"octoprox: ${_ENV}={path} cannot be loaded: {error}") from error
    here = os.path.dirname(os.path.abspath(__file__))
    candidates = [os.path.join(here, name) for name in _NAMES]
    candidates = [c for c in candidates if os.path.exists(c)]
    candidates += [ctypes.util.find_library("octoprox"), _NAMES[1]]
    errors = []
    for candidate in filter(None, candidates):
        try:
            return ctypes.CDLL(candidate)
        except OSError as error:
            errors.append(str(error))
    raise ImportError("octoprox: liboctoprox not found: set $%s to its path, put it next to "
                      "the package, or install it (%s)" % (_ENV, "; ".join(errors) or "none"))


status = c_int32
handle = c_void_p
P = POINTER


def _versioned_init(struct):
    return (status, [P(struct), c_size_t])


# Every exported symbol (tests/abi/exported_symbols.txt): restype, argtypes.
SIGNATURES = {
    "opx_status_name": (c_char_p, [status]),
    "opx_last_error": (c_char_p, []),
    "opx_version": (c_char_p, []),
    "opx_version_number": (c_uint32, []),
    # octree.h
    "opx_octree_create": (status, [P(s.OctreeOptions), P(handle)]),
    "opx_octree_destroy": (None, [handle]),
    "opx_octree_clear": (status, [handle]),
    "opx_octree_get_options": (status, [handle, P(s.OctreeOptions)]),
    "opx_octree_insert_points": (status, [handle, c_void_p, c_size_t, c_size_t, c_int32,
                                          P(s.InsertOptions), P(s.InsertReport)]),
    "opx_octree_insert_depth_image": (status, [handle, P(s.DepthImage), P(s.CameraIntrinsics),
                                               P(s.InsertOptions), P(s.InsertReport)]),
    "opx_octree_clear_region": (status, [handle, P(c_double), P(c_double), c_int32]),
    "opx_octree_clear_shapes": (status, [handle, c_void_p, c_size_t, P(s.Pose), c_int32]),
    "opx_octree_decay": (status, [handle, c_double]),
    "opx_octree_crop": (status, [handle, P(c_double), P(c_double)]),
    "opx_octree_classify": (status, [handle, P(c_double), P(s.CellInfo)]),
    "opx_octree_get_stats": (status, [handle, P(s.OctreeStats)]),
    "opx_octree_get_leaves": (status, [handle, c_uint32, c_void_p, c_size_t, P(c_size_t)]),
    "opx_octree_load_file": (status, [c_char_p, P(s.OctreeOptions), P(handle)]),
    "opx_octree_load_memory": (status, [c_void_p, c_size_t, P(s.OctreeOptions), P(handle)]),
    "opx_octree_load_message": (status, [c_void_p, c_size_t, c_int32, c_double,
                                         P(s.OctreeOptions), P(handle)]),
    "opx_octree_save_file": (status, [handle, c_char_p, c_int32]),
    "opx_octree_save_memory": (status, [handle, c_int32, c_void_p, c_size_t, P(c_size_t)]),
    # linkset.h
    "opx_linkset_create": (status, [P(handle)]),
    "opx_linkset_destroy": (None, [handle]),
    "opx_linkset_clone": (status, [handle, P(handle)]),
    "opx_linkset_add_link": (status, [handle, c_char_p, P(c_uint32)]),
    "opx_linkset_add_shape": (status, [handle, c_uint32, P(s.Shape), P(c_uint32)]),
    "opx_linkset_get_link_count": (status, [handle, P(c_uint32)]),
    "opx_linkset_get_shape": (status, [handle, c_uint32, c_uint32, P(s.Shape)]),
    "opx_linkset_get_shape_count": (status, [handle, c_uint32, P(c_uint32)]),
    "opx_linkset_get_link_name": (status, [handle, c_uint32, P(c_char_p)]),
    "opx_linkset_find_link": (status, [handle, c_char_p, P(c_uint32)]),
    "opx_linkset_set_padding": (status, [handle, c_double]),
    "opx_linkset_set_link_padding": (status, [handle, c_uint32, c_double]),
    "opx_linkset_set_link_enabled": (status, [handle, c_uint32, c_int32]),
    "opx_linkset_set_poses": (status, [handle, c_void_p, c_size_t, c_size_t]),
    "opx_linkset_get_pose": (status, [handle, c_uint32, P(s.Pose)]),
    "opx_linkset_get_poses": (status, [handle, c_void_p, c_size_t, P(c_size_t)]),
    "opx_linkset_set_pair_enabled": (status, [handle, c_uint32, c_uint32, c_int32]),
    "opx_linkset_get_pair_enabled": (status, [handle, c_uint32, c_uint32, P(c_int32)]),
    "opx_linkset_attach_object": (status, [handle, c_uint32, c_char_p, c_void_p, c_size_t, P(s.Pose),
                                           P(c_char_p), c_size_t, P(c_uint32)]),
    "opx_linkset_detach_object": (status, [handle, c_uint32]),
    "opx_linkset_get_attached_count": (status, [handle, P(c_uint32)]),
    "opx_linkset_find_attached": (status, [handle, c_char_p, P(c_uint32)]),
    "opx_linkset_get_attached_name": (status, [handle, c_uint32, P(c_char_p)]),
    "opx_linkset_get_attached_link": (status, [handle, c_uint32, P(c_uint32)]),
    "opx_linkset_get_attached_pose": (status, [handle, c_uint32, P(s.Pose)]),
    "opx_linkset_get_attached_shape_count": (status, [handle, c_uint32, P(c_uint32)]),
    "opx_linkset_get_attached_shape": (status, [handle, c_uint32, c_uint32, P(s.Shape)]),
    "opx_linkset_get_attached_touch_links": (status, [handle, c_uint32, c_void_p, c_size_t,
                                                      P(c_size_t)]),
    # robot.h
    "opx_linkset_load_urdf_file": (status, [c_char_p, P(s.UrdfOptions), P(handle)]),
    "opx_linkset_load_urdf_string": (status, [c_char_p, P(s.UrdfOptions), P(handle)]),
    "opx_linkset_get_joint_count": (status, [handle, P(c_uint32)]),
    "opx_linkset_find_joint": (status, [handle, c_char_p, P(c_uint32)]),
    "opx_linkset_get_joint_info": (status, [handle, c_uint32, P(s.JointInfo)]),
    "opx_linkset_set_joint_positions": (status, [handle, c_void_p, c_size_t, P(s.Pose)]),
    "opx_linkset_set_named_joint_positions": (status, [handle, P(c_char_p), c_void_p, c_size_t,
                                                       P(s.Pose)]),
    "opx_linkset_get_joint_positions": (status, [handle, c_void_p, c_size_t, P(c_size_t)]),
    "opx_linkset_get_active_joint_count": (status, [handle, P(c_uint32)]),
    "opx_linkset_get_active_joints": (status, [handle, c_void_p, c_size_t, P(c_size_t)]),
    "opx_linkset_set_active_joint_positions": (status, [handle, c_void_p, c_size_t, P(s.Pose)]),
    "opx_linkset_get_disabled_pair_count": (status, [handle, P(c_uint32)]),
    "opx_linkset_get_disabled_pair": (status, [handle, c_uint32, P(c_uint32), P(c_uint32)]),
    # query.h
    "opx_query_create": (status, [P(s.QueryOptions), P(handle)]),
    "opx_query_destroy": (None, [handle]),
    "opx_query_get_stats": (status, [handle, P(s.QueryStats)]),
    "opx_query_collide": (status, [handle, handle, handle, P(s.CollisionRequest),
                                   P(s.CollisionResult)]),
    "opx_query_get_contact": (status, [handle, c_size_t, c_void_p]),
    "opx_query_get_cost_box": (status, [handle, c_size_t, c_void_p]),
    "opx_query_distance": (status, [handle, handle, handle, P(s.DistanceRequest),
                                    P(s.DistanceResult)]),
    "opx_query_get_link_distances": (status, [handle, c_void_p, c_size_t, P(c_size_t)]),
    "opx_query_path": (status, [handle, handle, handle, c_void_p, c_size_t, c_size_t, c_size_t,
                                P(s.PathRequest), P(s.PathResult)]),
    "opx_query_bind_boxes": (status, [handle, c_void_p, c_size_t, c_size_t]),
    "opx_query_collide_boxes": (status, [handle, handle, P(s.CollisionRequest),
                                         P(s.CollisionResult)]),
    "opx_query_distance_boxes": (status, [handle, handle, P(s.DistanceRequest),
                                          P(s.DistanceResult)]),
    # self_collision.h
    "opx_query_self_collide": (status, [handle, handle, P(s.SelfCollisionRequest),
                                        P(s.SelfCollisionResult)]),
    "opx_query_get_self_contact": (status, [handle, c_size_t, c_void_p]),
    "opx_query_self_distance": (status, [handle, handle, P(s.SelfDistanceRequest),
                                         P(s.SelfDistanceResult)]),
    "opx_linkset_disable_never_colliding_pairs": (status, [handle, P(s.PairSamplingOptions),
                                                           P(s.PairSamplingResult)]),
    # world.h
    "opx_world_create": (status, [P(handle)]),
    "opx_world_destroy": (None, [handle]),
    "opx_world_add_object": (status, [handle, c_char_p, P(s.Pose), P(c_uint32)]),
    "opx_world_add_shape": (status, [handle, c_uint32, P(s.Shape), P(c_uint32)]),
    "opx_world_remove_object": (status, [handle, c_uint32]),
    "opx_world_set_object_pose": (status, [handle, c_uint32, P(s.Pose)]),
    "opx_world_get_object_pose": (status, [handle, c_uint32, P(s.Pose)]),
    "opx_world_set_object_enabled": (status, [handle, c_uint32, c_int32]),
    "opx_world_get_object_enabled": (status, [handle, c_uint32, P(c_int32)]),
    "opx_world_get_object_count": (status, [handle, P(c_uint32)]),
    "opx_world_get_object_name": (status, [handle, c_uint32, P(c_char_p)]),
    "opx_world_find_object": (status, [handle, c_char_p, P(c_uint32)]),
    "opx_world_get_shape_count": (status, [handle, c_uint32, P(c_uint32)]),
    "opx_world_get_shape": (status, [handle, c_uint32, c_uint32, P(s.Shape)]),
    "opx_world_load_scene_file": (status, [c_char_p, P(handle)]),
    "opx_world_load_scene_memory": (status, [c_void_p, c_size_t, c_int32, P(handle)]),
    "opx_query_set_world": (status, [handle, handle]),
    "opx_linkset_attach_world_object": (status, [handle, c_uint32, handle, c_uint32, P(c_char_p),
                                                 c_size_t, P(c_uint32)]),
    # batch.h
    "opx_query_check_configurations": (status, [handle, handle, handle, c_void_p, c_size_t, c_size_t,
                                                c_size_t, c_void_p, c_size_t, c_size_t,
                                                P(s.BatchRequest), c_void_p, c_void_p, c_size_t]),
    "opx_query_check_motion": (status, [handle, handle, handle, c_void_p, c_void_p, c_size_t,
                                        P(s.Pose), P(s.MotionRequest), P(s.MotionResult)]),
    "opx_query_check_motions": (status, [handle, handle, handle, c_void_p, c_void_p, c_size_t,
                                         c_size_t, c_size_t, c_void_p, c_size_t, c_size_t,
                                         P(s.MotionRequest), c_void_p, c_void_p, c_size_t]),
    # spheres.h
    "opx_sphere_request_init": (status, [P(s.SphereRequest), c_size_t]),
    "opx_query_collide_spheres": (status, [handle, handle, c_void_p, c_size_t, c_size_t,
                                           P(s.SphereRequest), c_void_p, c_size_t]),
    "opx_sphere_distance_request_init": (status, [P(s.SphereDistanceRequest), c_size_t]),
    "opx_trajectory_cost_request_init": (status, [P(s.TrajectoryCostRequest), c_size_t]),
    "opx_query_trajectory_cost": (status, [handle, handle, handle, c_void_p, c_size_t, c_size_t,
                                           c_size_t, c_void_p, P(s.TrajectoryCostRequest), c_void_p,
                                           c_void_p, c_size_t]),
    "opx_query_distance_spheres": (status, [handle, handle, c_void_p, c_size_t, c_size_t,
                                            P(s.SphereDistanceRequest), c_void_p, c_void_p,
                                            c_void_p, c_size_t]),
    # io.h
    "opx_point_cloud_read_file": (status, [c_char_p, P(handle)]),
    "opx_point_cloud_destroy": (None, [handle]),
    "opx_point_cloud_get_info": (status, [handle, P(s.PointCloudInfo)]),
    "opx_point_cloud_get_points": (status, [handle, c_void_p, c_size_t, c_size_t, P(c_size_t)]),
}
SIGNATURES.update({init: _versioned_init(struct) for struct, init in s.VERSIONED.items()})
# Aliases the library keeps for compatibility (the package calls the names
# they stand for): alias -> name.
ALIASES = {
    "opx_linkset_link_count": "opx_linkset_get_link_count",
    "opx_linkset_shape_count": "opx_linkset_get_shape_count",
    "opx_linkset_link_name": "opx_linkset_get_link_name",
    "opx_linkset_joint_count": "opx_linkset_get_joint_count",
    "opx_linkset_joint_info": "opx_linkset_get_joint_info",
    "opx_linkset_disabled_pair_count": "opx_linkset_get_disabled_pair_count",
    "opx_linkset_disabled_pair": "opx_linkset_get_disabled_pair",
}
SIGNATURES.update({alias: SIGNATURES[name] for alias, name in ALIASES.items()})


def _raise_on_error(result, function, arguments):
    """errcheck of every status-returning function: raise on a negative code."""
    if result != 0:
        message = lib.opx_last_error().decode("utf-8", "replace")
        raise error_for(result, message)
    return result


def _declare(library):
    for name, (restype, argtypes) in SIGNATURES.items():
        function = getattr(library, name)
        function.restype = restype
        function.argtypes = argtypes
        if restype is status:
            function.errcheck = _raise_on_error


def _compatible(major, minor):
    """A library of version major.minor serves these bindings: the same
    major and a minor at least as new, but on 0.x (where a minor may change
    the ABI, as the SONAME says) the same minor."""
    if major != HEADER_VERSION[0]:
        return False
    return minor == HEADER_VERSION[1] if major == 0 else minor >= HEADER_VERSION[1]


def _check_version(library):
    number = library.opx_version_number()
    if not _compatible(number // 10000, number // 100 % 100):
        wanted = "%d.%d" % HEADER_VERSION[:2]
        wanted += "" if HEADER_VERSION[0] == 0 else " or a later minor"
        raise ImportError("octoprox: the library is version %s, these bindings need %s"
                          % (library.opx_version().decode(), wanted))


lib = _load()
_declare(lib)
_check_version(lib)


def unchecked(name):
    """A second function object for ``name``, with its argtypes and
    restype but no errcheck: the query methods test the status themselves
    (one Python call less on every query).  ``lib.name`` stays checked."""
    function = lib[name]  # item access makes a new object; attributes are cached
    function.restype, function.argtypes = SIGNATURES[name]
    return function


def init_struct(struct_type, **fields):
    """A struct filled with the library's defaults (its opx_x_init), then
    with ``fields``; an unknown field name is a TypeError."""
    value = struct_type()
    init = s.VERSIONED.get(struct_type)
    if init is not None:
        getattr(lib, init)(ctypes.byref(value), ctypes.sizeof(value))
    for name, field in fields.items():
        set_field(value, name, field)
    return value


def set_field(struct, name, value):
    """Sets one field: sequences into arrays, poses from 3 or 7 numbers,
    booleans as 0/1."""
    if name.startswith("reserved") or name == "struct_size" or \
            name not in dict(struct._fields_):
        raise TypeError(f"{type(struct).__name__} has no field {name!r}")
    current = getattr(struct, name)
    if isinstance(current, s.Pose):
        setattr(struct, name, make_pose(value))
    elif isinstance(current, ctypes.Array):
        values = [float(v) for v in value]
        if len(values) != len(current):
            raise ValueError(f"{type(struct).__name__}.{name}: {len(current)} values needed, "
                             f"got {len(values)}")
        current[:] = values
    else:
        setattr(struct, name, int(value) if isinstance(value, bool) else value)


def make_pose(value):
    """A Pose from a Pose, (x, y, z), (x, y, z, qx, qy, qz, qw) or
    ((x, y, z), (qx, qy, qz, qw))."""
    if isinstance(value, s.Pose):
        return value
    flat = [float(v) for part in value for v in (part if hasattr(part, "__len__") else [part])]
    if len(flat) == 3:
        flat += [0.0, 0.0, 0.0, 1.0]
    if len(flat) != 7:
        raise ValueError(f"a pose is 3 or 7 numbers (x y z [qx qy qz qw]), got {len(flat)}")
    return s.Pose(s.D3(*flat[:3]), (c_double * 4)(*flat[3:]))
