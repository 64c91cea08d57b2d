"""Type aliases of the public signatures (for readers and type checkers)."""
import os
from typing import Sequence, Union

import numpy as np

from ._enums import Engine, FileFormat, InsertMode, JointOrder, ObstacleGeometry, UnknownPolicy
from ._struct_base import Pose

#: x, y, z in metres.
Vector3 = Sequence[float]
#: A Pose, (x, y, z), (x, y, z, qx, qy, qz, qw) or ((x, y, z), (qx, qy, qz, qw)).
PoseLike = Union[Pose, Sequence[float], Sequence[Sequence[float]]]
#: A numpy array or nested sequences of numbers.
ArrayLike = Union[np.ndarray, Sequence[Sequence[float]], Sequence[float]]
#: A file name: str, bytes or a path object.
PathLike = Union[str, bytes, os.PathLike]
EngineLike = Union[Engine, int, str]
InsertModeLike = Union[InsertMode, int, str]
FileFormatLike = Union[FileFormat, int, str]
UnknownPolicyLike = Union[UnknownPolicy, int, str]
ObstacleGeometryLike = Union[ObstacleGeometry, int, str]
JointOrderLike = Union[JointOrder, int, str]

__all__ = ["Vector3", "PoseLike", "ArrayLike", "PathLike", "EngineLike", "InsertModeLike",
           "FileFormatLike", "UnknownPolicyLike", "ObstacleGeometryLike", "JointOrderLike"]
