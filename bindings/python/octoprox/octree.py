"""The occupancy octree (opx_octree)."""
import ctypes
import os


from . import _structs as s
from ._arrays import LEAF_DTYPE, needed_count, point_view, read_array
from ._handle import Handle
from ._library import init_struct, lib

MASK_FREE, MASK_UNCERTAIN, MASK_OCCUPIED = 1 << 1, 1 << 2, 1 << 3
MASK_ALL_KNOWN = MASK_FREE | MASK_UNCERTAIN | MASK_OCCUPIED
FORMAT_AUTO, FORMAT_BT, FORMAT_OT = 0, 1, 2


def _path(path):
    return os.fsencode(path)


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
        (INSERT_RAYCAST or INSERT_ENDPOINTS), max_range.
        """
        if sensor_pose is not None:
            options["sensor_pose"] = sensor_pose
        opts = init_struct(s.InsertOptions, **options)
        view = point_view(points, "Octree.insert_points")
        report = init_struct(s.InsertReport)
        lib.opx_octree_insert_points(self, view.address, view.count, view.stride,
                                     view.scalar_type, opts, report)
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
