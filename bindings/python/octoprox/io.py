"""Point clouds from PCD and PLY files as numpy arrays.

The files are read by the library (``opx_point_cloud_read_file``,
include/octoprox/io.h), with the readers of the ``octoprox`` command-line
tool, so a file reads the same everywhere:

* ``.pcd``: PCD v0.7, DATA ascii, binary and binary_compressed (LZF);
  fields x y z as float32 or float64, other fields skipped;
* ``.ply``: the vertices of an ascii or binary_little_endian PLY file.

Points are float32, in the file's order (an organized cloud row after
row), non-finite points (no depth return) included, in the file's frame:
a camera's cloud is usually in its optical frame (z forward, x right,
y down). ::

    from octoprox import io
    cloud = io.read_pcd("frame.pcd")       # PcdCloud: points (N, 3), width, height, ...
    rows = cloud.grid()                    # (height, width, 3) view of an organized cloud
    vertices = io.read_ply("scan.ply")     # (N, 3) float32
"""
import ctypes
import os
from typing import NamedTuple, Tuple

import numpy as np

from ._errors import OctoproxError
from ._library import init_struct, lib
from ._structs import PointCloudInfo
from ._types import PathLike

# include/octoprox/io.h
CLOUD_FORMAT_PCD = 1
CLOUD_FORMAT_PLY = 2
CLOUD_ENCODING_ASCII = 1
CLOUD_ENCODING_BINARY = 2
CLOUD_ENCODING_BINARY_COMPRESSED = 3

_PCD_ENCODINGS = {CLOUD_ENCODING_ASCII: "ascii", CLOUD_ENCODING_BINARY: "binary",
                  CLOUD_ENCODING_BINARY_COMPRESSED: "binary_compressed"}


class PcdCloud(NamedTuple):
    """A PCD file's points and header.

    ``points``: (width * height, 3) float32, the file's frame.
    ``width``, ``height``: an organized cloud's columns and rows (an
    unorganized one: the point count and 1).
    ``viewpoint``: the VIEWPOINT as x, y, z, qx, qy, qz, qw (ROS order; the
    file writes tx ty tz qw qx qy qz): the pose of the cloud's (sensor's)
    frame in the frame it is to be placed in, as PCL's viewer applies it;
    identity without a VIEWPOINT line (``has_viewpoint`` False).
    ``encoding``: "ascii", "binary" or "binary_compressed".
    """
    points: np.ndarray
    width: int
    height: int
    viewpoint: Tuple[float, float, float, float, float, float, float]
    has_viewpoint: bool
    encoding: str

    def grid(self) -> np.ndarray:
        """The points as a (height, width, 3) view (no copy)."""
        return self.points.reshape(self.height, self.width, 3)


def _read(path: PathLike, function: str, expected_format: int) -> Tuple[np.ndarray, PointCloudInfo]:
    """Reads a cloud through the library; the points and the info."""
    handle = ctypes.c_void_p()
    try:
        lib.opx_point_cloud_read_file(os.fsencode(os.fspath(path)), ctypes.byref(handle))
        info = init_struct(PointCloudInfo)
        lib.opx_point_cloud_get_info(handle, ctypes.byref(info))
        if info.format != expected_format:
            wanted, other = ("PCD", "read_ply") if expected_format == CLOUD_FORMAT_PCD else ("PLY", "read_pcd")
            raise ValueError(f"{function}: {os.fspath(path)!r} is not a {wanted} file (use {other})")
        points = np.empty((info.point_count, 3), dtype=np.float32)
        count = ctypes.c_size_t()
        lib.opx_point_cloud_get_points(handle, points.ctypes.data, len(points), 0, ctypes.byref(count))
        return points, info
    except OctoproxError as error:
        error.where = function
        raise
    finally:
        lib.opx_point_cloud_destroy(handle)


def read_pcd(path: PathLike) -> PcdCloud:
    """Reads a .pcd file: its points, organized size, VIEWPOINT and
    encoding (see PcdCloud).  Raises IoError (an OSError) when the file
    cannot be opened, CorruptDataError (a ValueError) when it is malformed
    or truncated, UnsupportedError for layouts the reader does not take
    (x y z stored as integers), ValueError for a file not ending in .pcd."""
    points, info = _read(path, "read_pcd", CLOUD_FORMAT_PCD)
    position, orientation = tuple(info.viewpoint.position), tuple(info.viewpoint.orientation)
    return PcdCloud(points, int(info.width), int(info.height), position + orientation,
                    bool(info.has_viewpoint), _PCD_ENCODINGS.get(info.encoding, "binary"))


def read_ply(path: PathLike) -> np.ndarray:
    """Reads the vertices of a .ply file (ascii or binary_little_endian) as
    a (N, 3) float32 array.  Errors as read_pcd's."""
    points, _ = _read(path, "read_ply", CLOUD_FORMAT_PLY)
    return points


__all__ = ["read_pcd", "read_ply", "PcdCloud", "CLOUD_FORMAT_PCD", "CLOUD_FORMAT_PLY",
           "CLOUD_ENCODING_ASCII", "CLOUD_ENCODING_BINARY", "CLOUD_ENCODING_BINARY_COMPRESSED"]
