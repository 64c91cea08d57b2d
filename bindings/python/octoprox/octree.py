"""The occupancy octree (opx_octree): sensor frames in, cells out.

Cells fall in four classes by their occupancy probability p (CellClass):
OCCUPIED p >= occupied_threshold, UNCERTAIN free_threshold <= p <
occupied_threshold, FREE p < free_threshold, UNKNOWN never observed.  With
the default thresholds (both 0.5) no observed cell is uncertain.  All
coordinates are in the map frame, in metres; the map is a cube of 2^16
cells per axis centred on the origin.
"""
from __future__ import annotations

import ctypes
import os
from typing import Any, Dict, Optional, Sequence, Tuple, Union

import numpy as np

from . import _structs as s
from ._arrays import LEAF_DTYPE, depth_view, needed_count, point_view, read_array
from ._enums import CellClass, CellMask, FileFormat, InsertMode
from ._handle import Handle, api
from ._library import init_struct, lib, make_pose
from ._structs import CellInfo, InsertReport, OctreeOptions, OctreeStats
from ._types import ArrayLike, FileFormatLike, InsertModeLike, PathLike, PoseLike, Vector3
from .linkset import LinkSet, _shape_struct

MASK_FREE, MASK_UNCERTAIN, MASK_OCCUPIED = CellMask.FREE, CellMask.UNCERTAIN, CellMask.OCCUPIED
MASK_ALL_KNOWN = CellMask.ALL_KNOWN
FORMAT_AUTO, FORMAT_BT, FORMAT_OT, FORMAT_OPX = FileFormat.AUTO, FileFormat.BT, FileFormat.OT, FileFormat.OPX
# The options a map file does not hold (its resolution it does).
_PROBABILITIES = ("prob_hit", "prob_miss", "clamp_min", "clamp_max", "occupied_threshold",
                  "free_threshold")


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


def _robot_address(robot, where):
    """The address of robot's opx_linkset (None: NULL, no filtering)."""
    if robot is None:
        return None
    if not isinstance(robot, LinkSet):
        raise TypeError(f"{where}: robot must be a LinkSet (e.g. LinkSet.from_urdf) or None, "
                        f"got {type(robot).__name__}")
    if robot.closed:  # NULL would mean "no robot": refuse it instead
        raise robot._closed_error(where)
    return robot._address


def _corner(value, where, argument):
    """A box corner (x, y, z) as the C calls take it."""
    try:
        values = [float(v) for v in value]
    except (TypeError, ValueError):
        raise TypeError(f"{where}: {argument} must be 3 numbers (x, y, z), got {value!r}") from None
    if len(values) != 3:
        raise ValueError(f"{where}: {argument} must be 3 numbers (x, y, z), got {len(values)}")
    return (ctypes.c_double * 3)(*values)


def _clear_target(to, where):
    """OPX_CELL_FREE or OPX_CELL_UNKNOWN from "free", "unknown" or a CellClass."""
    target = CellClass.parse(to, where, "to")
    if target not in (CellClass.FREE, CellClass.UNKNOWN):
        raise ValueError(f'{where}: to must be "free" or "unknown", got {to!r}')
    return int(target)


def _bounds_fields(bounds, where):
    """The InsertOptions fields of the bounds keyword: (box_min, box_max)."""
    if bounds is None:
        return {}
    try:
        box_min, box_max = bounds
    except (TypeError, ValueError):
        raise TypeError(f"{where}: bounds must be (box_min, box_max), two corners (x, y, z), "
                        f"got {bounds!r}") from None
    return dict(use_bounds=True, bounds_min=tuple(_corner(box_min, where, "bounds[0]")),
                bounds_max=tuple(_corner(box_max, where, "bounds[1]")))


def _insert_options(sensor_pose, mode, max_range, max_threads, self_filter, where, bounds=None):
    """The InsertOptions of an insert; self_filter is (robot, robot_padding,
    clear_robot_volume).  The library checks the padding's range and the
    robot's poses."""
    robot, robot_padding, clear_robot_volume = self_filter
    try:
        robot_padding = float(robot_padding)
    except (TypeError, ValueError):
        raise TypeError(f"{where}: robot_padding must be a number of metres, "
                        f"got {robot_padding!r}") from None
    fields = dict(mode=InsertMode.parse(mode, where, "mode"), max_range=max_range,
                  max_threads=max_threads, robot=_robot_address(robot, where),
                  robot_padding=robot_padding, clear_robot_volume=bool(clear_robot_volume),
                  **_bounds_fields(bounds, where))
    if sensor_pose is not None:
        fields["sensor_pose"] = sensor_pose
    return init_struct(s.InsertOptions, **fields)


def _unpickle(data: bytes, options: Dict[str, float]) -> Octree:
    return Octree.from_bytes(data, **options)


class Octree(Handle):
    """An occupancy octree in the map frame (OctoMap semantics: log-odds
    per cell, hit and miss updates, clamping).

    resolution: the edge of a finest cell, 1e-6 to 1e6 m (0.05).
    prob_hit (0.7), prob_miss (0.4): the updates of a cell holding an
      endpoint and of one a ray passes (prob_miss < 0.5 < prob_hit).
    clamp_min (0.1192), clamp_max (0.971): the clamping bounds.
    occupied_threshold (0.5): occupied when p >= it; free_threshold (0.5):
      free when p < it (lower it, e.g. 0.3, for an uncertain band).
    Raises InvalidArgumentError for options out of range.

    Methods reading the map may run on many threads at once; the others
    need the octree to themselves.  An octree pickles as its .ot bytes and
    options: the copy has the same leaves and probabilities, but its
    occupied cells are whole cubes (the point extents insert_points records
    are not in the file).
    """
    _destroy = "opx_octree_destroy"
    _noun = "octree"

    @api("Octree")
    def __init__(self, resolution: float = 0.05, *, prob_hit: float = 0.7,
                 prob_miss: float = 0.4, clamp_min: float = 0.1192, clamp_max: float = 0.971,
                 occupied_threshold: float = 0.5, free_threshold: float = 0.5) -> None:
        """An empty octree with these options (see the class)."""
        opts = init_struct(s.OctreeOptions, resolution=resolution, prob_hit=prob_hit,
                           prob_miss=prob_miss, clamp_min=clamp_min, clamp_max=clamp_max,
                           occupied_threshold=occupied_threshold, free_threshold=free_threshold)
        super().__init__(lambda out: lib.opx_octree_create(ctypes.byref(opts), out))

    @classmethod
    @api("Octree.load")
    def load(cls, path: PathLike, *, prob_hit: float = 0.7, prob_miss: float = 0.4,
             clamp_min: float = 0.1192, clamp_max: float = 0.971,
             occupied_threshold: float = 0.5, free_threshold: float = 0.5) -> Octree:
        """Loads a .bt or .ot file (OctoMap 1.x, OcTree); the resolution
        comes from the file, the keywords (as Octree()'s) set the
        probabilities and thresholds.  Raises IoError (an OSError) when the
        file cannot be read, CorruptDataError (a ValueError) when it is
        malformed or truncated."""
        opts = init_struct(s.OctreeOptions, prob_hit=prob_hit, prob_miss=prob_miss,
                           clamp_min=clamp_min, clamp_max=clamp_max,
                           occupied_threshold=occupied_threshold, free_threshold=free_threshold)
        return cls._from(lambda out: lib.opx_octree_load_file(_path(path), opts, out))

    @classmethod
    @api("Octree.from_bytes")
    def from_bytes(cls, data: bytes, *, prob_hit: float = 0.7, prob_miss: float = 0.4,
                   clamp_min: float = 0.1192, clamp_max: float = 0.971,
                   occupied_threshold: float = 0.5, free_threshold: float = 0.5) -> Octree:
        """Loads the bytes of a .bt or .ot file (to_bytes() gives them);
        keywords and errors as load()."""
        data = bytes(data)
        opts = init_struct(s.OctreeOptions, prob_hit=prob_hit, prob_miss=prob_miss,
                           clamp_min=clamp_min, clamp_max=clamp_max,
                           occupied_threshold=occupied_threshold, free_threshold=free_threshold)
        return cls._from(lambda out: lib.opx_octree_load_memory(data, len(data), opts, out))

    @classmethod
    @api("Octree.from_message")
    def from_message(cls, data: bytes, binary: bool, resolution: float, *,
                     prob_hit: float = 0.7, prob_miss: float = 0.4, clamp_min: float = 0.1192,
                     clamp_max: float = 0.971, occupied_threshold: float = 0.5,
                     free_threshold: float = 0.5) -> Octree:
        """Loads the data field of a ROS octomap_msgs/Octomap message:
        binary True for a binary map (.bt body), False for a full one (.ot
        body); resolution the message's, metres.  Only "OcTree" maps (the
        message's id) are read correctly.  Keywords and errors as load()."""
        data = bytes(data)
        opts = init_struct(s.OctreeOptions, prob_hit=prob_hit, prob_miss=prob_miss,
                           clamp_min=clamp_min, clamp_max=clamp_max,
                           occupied_threshold=occupied_threshold, free_threshold=free_threshold)
        return cls._from(lambda out: lib.opx_octree_load_message(
            data, len(data), int(bool(binary)), resolution, opts, out))

    def __reduce__(self):
        options = self.options
        return (_unpickle, (self.to_bytes(FileFormat.OPX),
                            {name: getattr(options, name) for name in _PROBABILITIES}))

    @api("Octree.clear")
    def clear(self) -> None:
        """Removes every cell; the options stay."""
        lib.opx_octree_clear(self)

    @property
    @api("Octree.options")
    def options(self) -> OctreeOptions:
        """The octree's OctreeOptions (a loaded map's resolution included)."""
        out = init_struct(s.OctreeOptions)
        lib.opx_octree_get_options(self, out)
        return out

    @api("Octree.insert_points")
    def insert_points(self, points: ArrayLike, sensor_pose: Optional[PoseLike] = None, *,
                      mode: InsertModeLike = InsertMode.RAYCAST, max_range: float = -1.0,
                      max_threads: int = 1, robot: Optional[LinkSet] = None,
                      robot_padding: float = 0.0, clear_robot_volume: bool = False,
                      bounds: Optional[Tuple[Vector3, Vector3]] = None) -> InsertReport:
        """Inserts one sensor frame; successive frames accumulate.

        points: (N, 3) or wider, in the SENSOR frame, metres; float32 or
          float64 arrays (strided rows, ROS PointCloud2 buffers as
          structured arrays) are read in place, anything else copied once.
        sensor_pose: the sensor in the map frame, (x, y, z) or (x, y, z,
          qx, qy, qz, qw); None: identity.
        mode: InsertMode.RAYCAST (or "raycast", the default: free cells
          along each ray, the endpoint occupied) or ENDPOINTS ("endpoints":
          endpoint cells only).
        max_range: points farther from the sensor (m) give no occupied
          cell; <= 0: no limit.
        max_threads: 1 keeps the work on the caller's thread; 0 uses one
          per hardware thread; the map does not depend on it.
        robot: self-filtering: the LinkSet (a URDF robot or one built by
          hand) as it stood when the frame was captured, its poses as last
          set.  A point within a link's padding plus robot_padding of it
          (a robot point), or whose ray passes through the padded robot
          (a shadowed point), gives no occupied cell; its ray carves free
          space up to the robot.  None: no filtering.  The exact rules are
          the C header's (octree.h, "The robot in its own frame").
        robot_padding: metres added to every link's padding for the
          filter only; finite and >= 0.
        clear_robot_volume: True sets the cells lying entirely inside the
          robot's unpadded solids free in the same update (an obstacle
          where the arm now stands, its own earlier image); needs robot.
        bounds: (box_min, box_max), a box in the map frame: only its cells
          change (the frame's updates of other cells are dropped; a ray
          from outside still carves the cells it crosses inside).  Cells
          as clear_region takes them.  None: the whole map.

        Returns the InsertReport (points used, non-finite, out of range,
        outside the map, on the robot, shadowed; cells hit, missed and
        cleared).  On an invalid argument (InvalidArgumentError naming it:
        a bad robot_padding, clear_robot_volume without a robot, a robot
        whose poses were never set) the map is unchanged.
        """
        opts = _insert_options(sensor_pose, mode, max_range, max_threads,
                               (robot, robot_padding, clear_robot_volume), "Octree.insert_points",
                               bounds)
        view = point_view(points, "Octree.insert_points")
        report = init_struct(s.InsertReport)
        # robot, an argument, holds the link set (and its handle) for the call.
        lib.opx_octree_insert_points(self, view.address, view.count, view.stride,
                                     view.scalar_type, opts, report)
        return report

    @api("Octree.insert_depth_image")
    def insert_depth_image(self, depth: ArrayLike, intrinsics, depth_scale: float = 1000.0,
                           sensor_pose: Optional[PoseLike] = None, *,
                           mode: InsertModeLike = InsertMode.RAYCAST, max_range: float = -1.0,
                           max_threads: int = 1, robot: Optional[LinkSet] = None,
                           robot_padding: float = 0.0, clear_robot_volume: bool = False,
                           bounds: Optional[Tuple[Vector3, Vector3]] = None) -> InsertReport:
        """Inserts one depth frame, as insert_points inserts its points.

        depth: a 2-D array (rows, columns), read in place when it is uint16
        or float32 with adjacent pixels in a row (C-contiguous, or a view of
        rows and columns of a bigger array):
          * uint16: units of 1/depth_scale metres (depth_scale 1000 for
            millimetres, the default; 5000 for TUM RGB-D PNGs); 0 is no
            return;
          * float32 metres (other floating-point types: one float32 copy);
            0, NaN, infinite and negative values are no return.
        intrinsics: (fx, fy, cx, cy) in pixels, or a CameraIntrinsics.
        The pixel in column u, row v with depth z becomes the point
        ((u - cx) * z / fx, (v - cy) * z / fy, z) in the camera's optical
        frame (z forward, x right, y down); sensor_pose places that frame
        in the map frame.  mode, max_range (along the ray), max_threads and
        self-filtering (robot, robot_padding in metres,
        clear_robot_volume) and bounds as insert_points.  Pixels without a
        return are counted in the report's pixels_no_return.
        """
        where = "Octree.insert_depth_image"
        opts = _insert_options(sensor_pose, mode, max_range, max_threads,
                               (robot, robot_padding, clear_robot_volume), where, bounds)
        camera = _camera(intrinsics)
        view = depth_view(depth, where)
        image = init_struct(s.DepthImage, data=view.address, width=view.width,
                            height=view.height, row_stride=view.row_stride,
                            scalar_type=view.scalar_type, depth_scale=depth_scale)
        report = init_struct(s.InsertReport)
        lib.opx_octree_insert_depth_image(self, image, camera, opts, report)
        return report

    @api("Octree.clear_region")
    def clear_region(self, box_min: Vector3, box_max: Vector3, to: Union[CellClass, str] = "unknown") -> None:
        """Clears every cell of the box [box_min, box_max] (map frame,
        metres; a corner may be infinite) to "unknown" (removed from the
        map) or "free" (the free clamp, unknown cells included).  The box
        covers the cells holding a point of it, as classify finds them: a
        face on a cell face takes the cell above it too (at 0.1 m, x from
        0.2 to 0.5 covers the cells from [0.2, 0.3) to [0.5, 0.6)).  A NaN
        corner or box_min above box_max raises InvalidArgumentError and
        changes nothing."""
        where = "Octree.clear_region"
        lib.opx_octree_clear_region(self, _corner(box_min, where, "box_min"),
                                    _corner(box_max, where, "box_max"), _clear_target(to, where))

    @api("Octree.clear_shapes")
    def clear_shapes(self, shapes: Sequence[Any], pose: Optional[PoseLike] = None,
                     to: Union[CellClass, str] = "unknown") -> None:
        """Clears the cells an object occupies to "unknown" or "free" (as
        clear_region): shapes are descriptions as LinkSet.attach_object
        takes them (mappings or objects with kind, pose in the OBJECT
        frame, radius, length, size, vertices, triangles; World.shape and
        LinkSet.attached_shape give them), pose the object frame in the map
        frame (default identity).  A cell is cleared when a shape touches
        it, as a collision query decides it, so afterwards (to "unknown")
        the shapes collide with no cell.  Use it when an object joins the
        world (its sensed image would count it twice)."""
        where = "Octree.clear_shapes"
        keep: list = []
        structs = [_shape_struct(spec, where, keep) for spec in shapes]
        array = (s.Shape * max(1, len(structs)))(*structs)
        lib.opx_octree_clear_shapes(self, array, len(structs),
                                    None if pose is None else make_pose(pose), _clear_target(to, where))

    @api("Octree.decay")
    def decay(self, amount: float) -> None:
        """Moves every known cell's log-odds toward 0 by amount (>= 0),
        never across it; a cell that reaches 0 becomes unknown.  Called
        once a frame, obstacles that left the view fade.  NaN or a negative
        amount raises InvalidArgumentError and changes nothing."""
        lib.opx_octree_decay(self, float(amount))

    @api("Octree.crop")
    def crop(self, box_min: Vector3, box_max: Vector3) -> None:
        """Removes every cell outside the box [box_min, box_max] (map
        frame; cells as clear_region takes them) and gives their memory
        back: a mobile base keeps a window around itself."""
        where = "Octree.crop"
        lib.opx_octree_crop(self, _corner(box_min, where, "box_min"), _corner(box_max, where, "box_max"))

    @api("Octree.classify")
    def classify(self, point: Vector3) -> CellInfo:
        """The CellInfo of the cell holding point (x, y, z, map frame, m):
        cell_class, probability (0.5 when unknown), center, size, depth.  A
        point outside the map cube raises InvalidArgumentError."""
        xyz = (ctypes.c_double * 3)(*[float(v) for v in point])
        out = init_struct(s.CellInfo)
        lib.opx_octree_classify(self, xyz, out)
        return out

    @property
    @api("Octree.stats")
    def stats(self) -> OctreeStats:
        """Counts, tight bounds and memory of the map (an OctreeStats; one
        pass over the leaves)."""
        out = init_struct(s.OctreeStats)
        lib.opx_octree_get_stats(self, out)
        return out

    @api("Octree.leaves")
    def leaves(self, class_mask: int = CellMask.OCCUPIED) -> np.ndarray:
        """The leaves whose class is in class_mask (CellMask, e.g.
        CellMask.FREE | CellMask.OCCUPIED) as a structured array with the
        fields of Leaf (center, size, probability, cell_class, depth),
        depth-first: the paper's collision map."""
        return read_array(lib.opx_octree_get_leaves, self, class_mask, dtype=LEAF_DTYPE)

    @api("Octree.save")
    def save(self, path: PathLike, format: FileFormatLike = FileFormat.AUTO) -> None:
        """Saves to a .bt, .ot or .opx file (format AUTO: by the
        extension; .opx keeps the point extents).  Raises IoError when the
        file cannot be written."""
        lib.opx_octree_save_file(self, _path(path), FileFormat.parse(format, "Octree.save",
                                                                      "format"))

    @api("Octree.to_bytes")
    def to_bytes(self, format: FileFormatLike = FileFormat.BT) -> bytes:
        """The bytes of a .bt file (the default: classes only), with
        FileFormat.OT of a .ot file (every probability), with
        FileFormat.OPX of a .opx file (every probability and the occupied
        cells' point extents; pickling uses it)."""
        format = FileFormat.parse(format, "Octree.to_bytes", "format")
        size = ctypes.c_size_t(needed_count(lib.opx_octree_save_memory, self, format))
        buffer = ctypes.create_string_buffer(size.value)
        lib.opx_octree_save_memory(self, format, buffer, size.value, ctypes.byref(size))
        return buffer.raw[:size.value]
