"""numpy arrays in and out, by address and stride.

Points go to the library without a copy when they are
  * a 2-D float32 or float64 array of shape (N, >=3) whose rows may be
    strided (a view of a bigger array) but whose x, y, z are adjacent, or
  * a 1-D structured array with float32 or float64 fields x, y, z at
    consecutive offsets (a ROS PointCloud2 buffer viewed with its
    point_step as itemsize: ``np.frombuffer(msg.data, dtype)``).
Anything else (lists, other dtypes, byte-swapped or column-strided arrays)
is converted once to a packed float64 (N, 3) array: the one documented copy.

Depth images go in without a copy when they are a 2-D native uint16 or
float32 array whose pixels are adjacent in a row and whose rows are at
least a row apart (C-contiguous, or a view of rows and columns of a bigger
image).  Other floating-point arrays are converted once to float32 metres,
other layouts of uint16 once to packed uint16.
"""
import ctypes

import numpy as np

from . import _structs as s
from ._errors import BufferTooSmallError, invalid

SCALAR_FLOAT32 = 1
SCALAR_FLOAT64 = 2
SCALAR_UINT16 = 3
_SCALARS = {np.dtype(np.float32): SCALAR_FLOAT32, np.dtype(np.float64): SCALAR_FLOAT64}

# Result rows as numpy structured arrays, laid out exactly as the C structs.
CONTACT_DTYPE = np.dtype(s.Contact)
COST_BOX_DTYPE = np.dtype(s.CostBox)
SELF_CONTACT_DTYPE = np.dtype(s.SelfContact)
LEAF_DTYPE = np.dtype(s.Leaf)
POSE_SIZE = 7 * 8


class PointView:
    """What the library is handed: address, count, stride (bytes), scalar
    type; ``owner`` keeps the memory alive for the call."""

    def __init__(self, address, count, stride, scalar_type, owner):
        """The view's fields as given."""
        self.address, self.count, self.stride = address, count, stride
        self.scalar_type, self.owner = scalar_type, owner


def point_view(points, where):
    """The points as the library reads them, copying only when unavoidable."""
    if isinstance(points, np.ndarray):
        view = _direct_matrix(points) if points.dtype.names is None else _direct_fields(points)
        if view is not None:
            return view
    packed = _packed_xyz(points, where)
    return PointView(packed.ctypes.data, len(packed), packed.strides[0], SCALAR_FLOAT64, packed)


def _direct_matrix(arr):
    scalar = _SCALARS.get(arr.dtype) if arr.dtype.isnative else None
    if scalar is None or arr.ndim != 2 or arr.shape[1] < 3 or arr.strides[1] != arr.itemsize:
        return None
    stride = arr.strides[0]
    if len(arr) > 1 and stride < 3 * arr.itemsize:
        return None  # negative, zero (broadcast) or overlapping rows
    stride = stride if len(arr) > 1 else 3 * arr.itemsize
    return PointView(arr.ctypes.data, len(arr), stride, scalar, arr)


def _direct_fields(arr):
    fields = arr.dtype.fields
    if arr.ndim != 1 or not all(name in fields for name in "xyz"):
        return None
    (tx, ox), (ty, oy), (tz, oz) = (fields[name][:2] for name in "xyz")
    scalar = _SCALARS.get(tx) if tx.isnative else None
    if scalar is None or not tx == ty == tz or (oy, oz) != (ox + tx.itemsize, ox + 2 * tx.itemsize):
        return None
    stride = arr.strides[0] if len(arr) > 1 else arr.itemsize
    if stride < 3 * tx.itemsize:
        return None
    return PointView(arr.ctypes.data + ox, len(arr), stride, scalar, arr)


def _packed_xyz(points, where):
    if isinstance(points, np.ndarray) and points.dtype.names is not None:
        if not all(name in points.dtype.names for name in "xyz"):
            raise invalid("a structured array needs fields x, y and z", where)
        points = np.stack([points["x"], points["y"], points["z"]], axis=-1)
    try:
        packed = np.ascontiguousarray(points, dtype=np.float64)
    except (TypeError, ValueError) as error:
        raise invalid(f"points are not numbers ({error})", where) from error
    if packed.ndim != 2 or packed.shape[1] < 3:
        raise invalid(f"points must have shape (N, 3) or more columns, "
                      f"got {packed.shape}", where)
    return np.ascontiguousarray(packed[:, :3])


class DepthView:
    """A depth image as the library reads it: address, width, height, row
    stride (bytes), scalar type; ``owner`` keeps the memory alive."""

    def __init__(self, arr, scalar_type):
        """The view of a 2-D array the library can read as it is."""
        self.height, self.width = arr.shape
        self.address, self.scalar_type, self.owner = arr.ctypes.data, scalar_type, arr
        packed = self.width * arr.itemsize
        self.row_stride = arr.strides[0] if self.height > 1 else packed


def depth_view(depth, where):
    """A 2-D depth image (rows, columns): uint16 or float32 in place, other
    floating-point types as one float32 copy, anything else refused."""
    arr = depth if isinstance(depth, np.ndarray) else np.asarray(depth)
    if arr.ndim != 2:
        raise invalid(f"a depth image has 2 dimensions (rows, columns), "
                      f"got shape {arr.shape}", where)
    if arr.dtype.kind == "u" and arr.dtype.itemsize == 2:
        target, scalar = np.dtype(np.uint16), SCALAR_UINT16
    elif arr.dtype.kind == "f":
        target, scalar = np.dtype(np.float32), SCALAR_FLOAT32
    else:
        raise invalid(f"depth must be uint16 (with depth_scale) or floating-point "
                      f"metres, got {arr.dtype}", where)
    adjacent = arr.shape[1] < 2 or arr.strides[1] == arr.itemsize
    rows_apart = arr.shape[0] < 2 or arr.strides[0] >= arr.shape[1] * arr.itemsize
    if arr.dtype != target or not adjacent or not rows_apart:
        arr = np.ascontiguousarray(arr, dtype=target)
    return DepthView(arr, scalar)


def pose_array(poses, where, ndim):
    """Poses as a float64 array of shape (..., 7) with ndim dimensions (7
    doubles are one opx_pose, so rows go in by address and stride).  Rows
    of 3 numbers get the identity orientation (a copy)."""
    arr = poses if isinstance(poses, np.ndarray) else np.asarray(poses, dtype=np.float64)
    if arr.ndim != ndim or arr.shape[-1] not in (3, 7):
        raise invalid(f"poses must have {ndim} dimensions, the last of 7 "
                      f"(x y z qx qy qz qw) or 3 numbers; got shape {arr.shape}", where)
    if arr.shape[-1] == 3:
        identity = np.zeros(arr.shape[:-1] + (4,))
        identity[..., 3] = 1.0
        arr = np.concatenate([np.asarray(arr, dtype=np.float64), identity], axis=-1)
    if arr.dtype != np.float64 or not arr.dtype.isnative or arr.strides[-1] != 8 or \
            any(st < POSE_SIZE for st, n in zip(arr.strides[:-1], arr.shape[:-1]) if n > 1):
        arr = np.ascontiguousarray(arr, dtype=np.float64)
    return arr


def pose_strides(arr):
    """The byte strides of the leading dimensions; a dimension of length 1
    gets the packed stride (numpy may give it any stride, even 0)."""
    strides, packed = [], POSE_SIZE
    for n, st in reversed(list(zip(arr.shape[:-1], arr.strides[:-1]))):
        strides.insert(0, st if n > 1 else packed)
        packed *= n
    return strides


def vertex_array(vertices, where):
    """(N, 3) float64 vertices by address and row stride (else one copy)."""
    arr = vertices if isinstance(vertices, np.ndarray) else np.asarray(vertices, np.float64)
    if arr.ndim != 2 or arr.shape[1] != 3:
        raise invalid(f"vertices must have shape (N, 3), got {arr.shape}", where)
    if arr.dtype != np.float64 or not arr.dtype.isnative or arr.strides[1] != 8 or \
            (len(arr) > 1 and arr.strides[0] < 24):
        arr = np.ascontiguousarray(arr, dtype=np.float64)
    return arr


def box_array(boxes, where):
    """(N, 6) float64 boxes (min x y z, max x y z) by address and row
    stride (else one copy)."""
    arr = boxes if isinstance(boxes, np.ndarray) else np.asarray(boxes, np.float64)
    if arr.ndim != 2 or arr.shape[1] != 6:
        raise invalid(f"boxes must have shape (N, 6): min x y z, max x y z; "
                      f"got {arr.shape}", where)
    if arr.dtype != np.float64 or not arr.dtype.isnative or arr.strides[1] != 8 or \
            (len(arr) > 1 and arr.strides[0] < 48):
        arr = np.ascontiguousarray(arr, dtype=np.float64)
    return arr


def triangle_array(triangles, where):
    """(M, 3) packed uint32 vertex indices (a copy unless already so)."""
    arr = np.asarray(triangles)
    if arr.ndim != 2 or arr.shape[1] != 3:
        raise invalid(f"triangles must have shape (M, 3), got {arr.shape}", where)
    if arr.size and (arr.min() < 0 or arr.max() > 0xFFFFFFFF):
        raise invalid("a triangle index is out of the uint32 range", where)
    return np.ascontiguousarray(arr, dtype=np.uint32)


def needed_count(function, *leading):
    """What a sized call ``function(*leading, buffer, capacity, out_count)``
    needs: it is asked with no buffer and reports the count."""
    count = ctypes.c_size_t()
    try:
        function(*leading, None, 0, ctypes.byref(count))
    except BufferTooSmallError:
        pass
    return count.value


def read_array(function, *leading, dtype=np.float64):
    """The whole output of a sized call as a numpy array of ``dtype``."""
    out = np.zeros(needed_count(function, *leading), dtype=dtype)
    count = ctypes.c_size_t()
    function(*leading, out.ctypes.data, len(out), ctypes.byref(count))
    return out[:count.value]
