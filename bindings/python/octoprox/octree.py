"""The occupancy octree (opx_octree)."""
import ctypes
import os


from . import _structs as s
from ._arrays import LEAF_DTYPE, depth_view, needed_count, point_view, read_array
from ._handle import Handle
from ._library import init_struct, lib

MASK_FREE, MASK_UNCERTAIN, MASK_OCCUPIED = 1 << 1, 1 << 2, 1 << 3
MASK_ALL_KNOWN = MASK_FREE | MASK_UNCERTAIN | MASK_OCCUPIED
FORMAT_AUTO, FORMAT_BT, FORMAT_OT = 0, 1, 2


def _path(path):
    return os.fsencode(path)


def _camera(intrinsics):
    """An initialised CameraIntrinsics from (fx, fy, cx, cy) or another one."""
    if isinstance(intrinsics, s.CameraIntrinsics):
        intrinsics = (intrinsics.fx, intrinsics.fy, intrinsics.cx, intrinsics.cy)
    values = [float(v) for v in intrinsics]
    if len(values) != 4:
        raise ValueError(f"intrinsics are 4 numbers (fx, fy, cx, cy), got {len(values)}")
    return init_struct(s.CameraIntrinsics, **dict(zip(("fx", "fy", "cx", "cy"), values)))


class Octree(Handle):
    """An occupancy octree in the map frame (OctoMap semantics).

    ``Octree(resolution=0.05, free_threshold=0.3, ...)``: any field of
    opx_octree_options as a keyword.  Methods reading the map may run on
    many threads at once; the others need the octree to themselves.
    """
    _destroy = "opx_octree_destroy"

    def __init__(self, **options):
        opts = init_struct(s.OctreeOptions, **options)
        super().__init__(lambda out: lib.opx_octree_create(ctypes.byref(opts), out))

    @classmethod
    def _wrap(cls, create):
        tree = cls.__new__(cls)
        Handle.__init__(tree, create)
        return tree

    @classmethod
    def load(cls, path, **options):
        """Loads a .bt or .ot file; its resolution comes from the file."""
        opts = init_struct(s.OctreeOptions, **options)
        return cls._wrap(lambda out: lib.opx_octree_load_file(_path(path), opts, out))

    @classmethod
    def from_bytes(cls, data, **options):
        """Loads the bytes of a .bt or .ot file."""
        data = bytes(data)
        opts = init_struct(s.OctreeOptions, **options)
        return cls._wrap(lambda out: lib.opx_octree_load_memory(data, len(data), opts, out))

    @classmethod
    def from_message(cls, data, binary, resolution, **options):
        """Loads the data of a ROS octomap_msgs/Octomap message."""
        data = bytes(data)
        opts = init_struct(s.OctreeOptions, **options)
        return cls._wrap(lambda out: lib.opx_octree_load_message(
            data, len(data), int(bool(binary)), resolution, opts, out))

    def clear(self):
        lib.opx_octree_clear(self)

    @property
    def options(self):
        out = init_struct(s.OctreeOptions)
        lib.opx_octree_get_options(self, out)
        return out

    def insert_points(self, points, sensor_pose=None, **options):
        """Inserts one sensor frame and returns its InsertReport.

        points: in the SENSOR frame; see octoprox._arrays for the layouts
        read in place.  sensor_pose: the sensor in the map frame, (x, y, z)
        or (x, y, z, qx, qy, qz, qw).  Other keywords: mode
        (INSERT_RAYCAST or INSERT_ENDPOINTS), max_range (metres),
        max_threads (1, the default: the caller's thread only; 0: one per
        hardware thread).
        """
        if sensor_pose is not None:
            options["sensor_pose"] = sensor_pose
        opts = init_struct(s.InsertOptions, **options)
        view = point_view(points, "Octree.insert_points")
        report = init_struct(s.InsertReport)
        lib.opx_octree_insert_points(self, view.address, view.count, view.stride,
                                     view.scalar_type, opts, report)
        return report

    def insert_depth_image(self, depth, intrinsics, depth_scale=1000.0, sensor_pose=None,
                           **options):
        """Inserts one depth frame and returns its InsertReport.

        depth: a 2-D array (rows, columns), read in place when it is uint16
        or float32 with adjacent pixels in a row (C-contiguous, or a view of
        rows and columns of a bigger array; see octoprox._arrays):
          * uint16: units of 1/depth_scale metres (depth_scale 1000 for
            millimetres, the default; 5000 for TUM RGB-D PNGs); 0 is no
            return;
          * float32 metres (other floating-point types: one float32 copy);
            0, NaN, infinite and negative values are no return.
        intrinsics: (fx, fy, cx, cy) in pixels, or a CameraIntrinsics.
        The pixel in column u, row v with depth z becomes the point
        ((u - cx) * z / fx, (v - cy) * z / fy, z) in the camera's optical
        frame (z forward, x right, y down); sensor_pose places that frame
        in the map frame, (x, y, z) or (x, y, z, qx, qy, qz, qw).  Other
        keywords as insert_points: mode, max_range, max_threads.  Pixels
        without a return are counted in the report's pixels_no_return.
        """
        if sensor_pose is not None:
            options["sensor_pose"] = sensor_pose
        opts = init_struct(s.InsertOptions, **options)
        camera = _camera(intrinsics)
        view = depth_view(depth, "Octree.insert_depth_image")
        image = init_struct(s.DepthImage, data=view.address, width=view.width,
                            height=view.height, row_stride=view.row_stride,
                            scalar_type=view.scalar_type, depth_scale=depth_scale)
        report = init_struct(s.InsertReport)
        lib.opx_octree_insert_depth_image(self, image, camera, opts, report)
        return report

    def classify(self, point):
        """The CellInfo of the cell holding point (x, y, z, map frame)."""
        xyz = (ctypes.c_double * 3)(*[float(v) for v in point])
        out = init_struct(s.CellInfo)
        lib.opx_octree_classify(self, xyz, out)
        return out

    @property
    def stats(self):
        out = init_struct(s.OctreeStats)
        lib.opx_octree_get_stats(self, out)
        return out

    def leaves(self, class_mask=MASK_OCCUPIED):
        """The leaves of these classes as a structured array (fields center,
        size, probability, cell_class, depth), depth-first."""
        return read_array(lib.opx_octree_get_leaves, self, class_mask, dtype=LEAF_DTYPE)

    def save(self, path, format=FORMAT_AUTO):
        """Saves to a .bt or .ot file (format: FORMAT_AUTO, _BT or _OT)."""
        lib.opx_octree_save_file(self, _path(path), format)

    def to_bytes(self, format=FORMAT_BT):
        """The bytes of a .bt (default) or .ot file."""
        size = ctypes.c_size_t(needed_count(lib.opx_octree_save_memory, self, format))
        buffer = ctypes.create_string_buffer(size.value)
        lib.opx_octree_save_memory(self, format, buffer, size.value, ctypes.byref(size))
        return buffer.raw[:size.value]
