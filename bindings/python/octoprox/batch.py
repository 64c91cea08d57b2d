"""Many configurations and joint-space motions per call (batch.h): the
bodies of Query.check_configurations, check_motion and check_motions.

Joint vectors are rows of every joint in model order (LinkSet.joint_names,
as set_joint_positions takes them).  Arrays go in by address and row stride
when they are float64 with packed rows, else as one copy.  The library
runs without the GIL (ctypes releases it), so other Python threads go on
while a batch is checked.
"""
import ctypes

import numpy as np

from . import _structs as s
from ._arrays import invalid, pose_array
from ._library import init_struct, lib, make_pose


def joint_rows(q, where):
    """(N, dof) float64 rows of contiguous values, by address and stride."""
    arr = q if isinstance(q, np.ndarray) else np.asarray(q, dtype=np.float64)
    if arr.ndim == 1:
        arr = arr.reshape(1, -1)
    if arr.ndim != 2:
        raise invalid(f"{where}: joint positions must have shape (N, dof), got {arr.shape}")
    if arr.dtype != np.float64 or not arr.dtype.isnative or \
            (arr.shape[1] > 1 and arr.strides[1] != 8) or \
            (len(arr) > 1 and arr.strides[0] < 8 * arr.shape[1]):
        arr = np.ascontiguousarray(arr, dtype=np.float64)
    return arr


def _row_stride(arr):
    return arr.strides[0] if len(arr) > 1 else 8 * arr.shape[1]


class _BasePoses:
    """base_pose as the C call takes it: None, one pose for every row (a Pose
    or 3/7 numbers), or an (N, 7) / (N, 3) array, one per row."""

    def __init__(self, base_pose, rows, where):
        self.address, self.count, self.stride, self.keep = None, 0, 0, None
        if base_pose is None:
            return
        if isinstance(base_pose, s.Pose) or np.ndim(base_pose) == 1:
            self.keep = make_pose(base_pose)
            self.address, self.count = ctypes.addressof(self.keep), 1
            return
        arr = pose_array(base_pose, where, 2)
        if len(arr) != rows:
            raise invalid(f"{where}: {len(arr)} base poses for {rows} rows (give one, or one per row)")
        self.keep, self.address, self.count = arr, arr.ctypes.data, len(arr)
        self.stride = arr.strides[0] if len(arr) > 1 else 0


def check_configurations(query, tree, robot, q, threads=1, self_collision=False, base_pose=None,
                         distance=False, **request):
    rows = joint_rows(q, "Query.check_configurations")
    n = len(rows)
    collided = np.zeros(n, dtype=np.bool_)
    distances = np.zeros(n, dtype=np.float64) if distance else None
    if n > 0:
        bases = _BasePoses(base_pose, n, "Query.check_configurations")
        req = init_struct(s.BatchRequest, max_threads=threads, self_collision=self_collision,
                          compute_distance=distance, **request)
        lib.opx_query_check_configurations(
            query, tree, robot, rows.ctypes.data, n, rows.shape[1], _row_stride(rows), bases.address,
            bases.count, bases.stride, req, collided.ctypes.data,
            None if distances is None else distances.ctypes.data, n)
    return (collided, distances) if distance else collided


def check_motion(query, tree, robot, start, goal, resolution=0.01, self_collision=False,
                 base_pose=None, **request):
    a = np.ascontiguousarray(start, dtype=np.float64).reshape(-1)
    b = np.ascontiguousarray(goal, dtype=np.float64).reshape(-1)
    if len(a) != len(b):
        raise invalid(f"Query.check_motion: start has {len(a)} joints, goal {len(b)}")
    req = init_struct(s.MotionRequest, resolution=resolution, self_collision=self_collision,
                      **request)
    out = init_struct(s.MotionResult)
    base = None if base_pose is None else ctypes.byref(make_pose(base_pose))
    lib.opx_query_check_motion(query, tree, robot, a.ctypes.data, b.ctypes.data, len(a), base, req,
                               out)
    return out


def check_motions(query, tree, robot, starts, goals, resolution=0.01, threads=1,
                  self_collision=False, base_pose=None, **request):
    a = joint_rows(starts, "Query.check_motions")
    b = joint_rows(goals, "Query.check_motions")
    if a.shape != b.shape:
        raise invalid(f"Query.check_motions: starts have shape {a.shape}, goals {b.shape}")
    if a.strides[0] != b.strides[0] and len(a) > 1:  # one stride for both
        a, b = np.ascontiguousarray(a), np.ascontiguousarray(b)
    n = len(a)
    collided = np.zeros(n, dtype=np.bool_)
    fractions = np.zeros(n, dtype=np.float64)
    if n > 0:
        bases = _BasePoses(base_pose, n, "Query.check_motions")
        req = init_struct(s.MotionRequest, resolution=resolution, max_threads=threads,
                          self_collision=self_collision, **request)
        lib.opx_query_check_motions(query, tree, robot, a.ctypes.data, b.ctypes.data, n, a.shape[1],
                                    _row_stride(a), bases.address, bases.count, bases.stride, req,
                                    collided.ctypes.data, fractions.ctypes.data, n)
    return collided, fractions
