"""Link sets from URDF, their joints and forward kinematics (robot.h).
LinkSet inherits these methods.

Frames: a link's frame is the URDF link frame (LinkSet.pose gives it in
the map frame); base_pose is the pose of the URDF root link in the map
frame (None: identity); a joint's origin is the child link frame in the
parent's at position 0, its axis in the child link frame.  Joint positions
are radians (revolute, continuous) or metres (prismatic), in model order
(the URDF file's joint order, fixed joints included) or in active order:
the active joints alone, the revolute, continuous and prismatic joints
that mimic none, in model order (MoveIt's active joints of a robot without
floating or planar joints; MoveIt and Pinocchio order joints along the
tree, so match them by name: active_joint_names).  Their values decide
every link pose: mimic joints follow their leaders, fixed joints do not
move, and floating and planar joints are held at their origin (place a
mobile base with base_pose).  Every <link> becomes a link (same name, file
order), every <collision> a shape (box, sphere, cylinder, or a mesh read
with assimp).
"""
from __future__ import annotations

import ctypes
import os
from typing import List, Mapping, Optional, Sequence, Union

import numpy as np

from . import _structs as s
from ._arrays import read_array
from ._enums import JointType
from ._errors import invalid
from ._handle import api
from ._library import init_struct, lib, make_pose
from ._structs import JointInfo, PairSamplingResult
from ._types import ArrayLike, PathLike, PoseLike

JOINT_FIXED, JOINT_REVOLUTE, JOINT_CONTINUOUS, JOINT_PRISMATIC, JOINT_FLOATING, \
    JOINT_PLANAR = JointType
JOINT_NONE = 0xFFFFFFFF  # no mimic joint, no link


def _urdf_options(package_dirs, base_dir, srdf):
    """The options struct and the buffers it points into (keep both alive)."""
    dirs = [os.fsencode(d) for d in package_dirs]
    array = (ctypes.c_char_p * max(len(dirs), 1))(*dirs)
    options = init_struct(s.UrdfOptions, package_dir_count=len(dirs))
    options.package_dirs = ctypes.cast(array, ctypes.POINTER(ctypes.c_char_p)) if dirs else None
    options.base_dir = os.fsencode(base_dir) if base_dir is not None else None
    options.srdf_path = os.fsencode(srdf) if srdf is not None else None
    return options, array


def _base(base_pose):
    return None if base_pose is None else ctypes.byref(make_pose(base_pose))


class RobotModel:
    """URDF loading, joints and FK (mixed into LinkSet)."""

    @classmethod
    @api("LinkSet.from_urdf")
    def from_urdf(cls, path: PathLike, package_dirs: Sequence[PathLike] = (),
                  base_dir: Optional[PathLike] = None, srdf: Optional[PathLike] = None):
        """A link set from a URDF file: one link per <link> (same names, file
        order), one shape per <collision>, every joint at 0, the root at the
        map origin.

        package_dirs: resolve package://NAME/rest mesh names: folders (DIR/
          NAME/rest, or DIR/rest when DIR ends in NAME), or "NAME=DIR"
          entries; the first existing file wins.
        base_dir: the folder of relative mesh paths (None: the URDF's).
        srdf: a file whose <disable_collisions> pairs self-collision
          queries skip.
        Raises IoError (a file or mesh cannot be read, an unknown package),
        CorruptDataError (malformed XML or URDF, bad geometry),
        UnsupportedError (collision geometry other than box, sphere,
        cylinder, mesh).
        """
        options, _keep = _urdf_options(package_dirs, base_dir, srdf)
        return cls._from(lambda out: lib.opx_linkset_load_urdf_file(os.fsencode(path),
                                                                    options, out))

    @classmethod
    @api("LinkSet.from_urdf_string")
    def from_urdf_string(cls, xml: str, package_dirs: Sequence[PathLike] = (),
                         base_dir: Optional[PathLike] = None, srdf: Optional[PathLike] = None):
        """A link set from URDF XML text; relative mesh paths are relative
        to base_dir (None: the current directory).  Otherwise as
        from_urdf."""
        options, _keep = _urdf_options(package_dirs, base_dir, srdf)
        text = xml.encode() if isinstance(xml, str) else bytes(xml)
        return cls._from(lambda out: lib.opx_linkset_load_urdf_string(text, options, out))

    @property
    @api("LinkSet.joint_count")
    def joint_count(self) -> int:
        """The number of joints (0 for a set not made from URDF)."""
        count = ctypes.c_uint32()
        lib.opx_linkset_get_joint_count(self, ctypes.byref(count))
        return count.value

    @api("LinkSet.find_joint")
    def find_joint(self, name: str) -> int:
        """The index of the joint named name (InvalidArgumentError if none)."""
        index = ctypes.c_uint32()
        lib.opx_linkset_find_joint(self, name.encode(), ctypes.byref(index))
        return index.value

    @api("LinkSet.joint_info")
    def joint_info(self, joint: int) -> JointInfo:
        """The JointInfo of a joint: type (JointType), name, parent and
        child links, axis, origin, limits, mimic."""
        out = init_struct(s.JointInfo)
        lib.opx_linkset_get_joint_info(self, joint, out)
        return out

    @property
    @api("LinkSet.joint_names")
    def joint_names(self) -> List[str]:
        """Every joint's name, in model order."""
        return [self.joint_info(j).name for j in range(self.joint_count)]

    @property
    @api("LinkSet.active_joint_count")
    def active_joint_count(self) -> int:
        """The number of active joints (see the module): the length of an
        active joint vector (0 for a set not made from URDF)."""
        count = ctypes.c_uint32()
        lib.opx_linkset_get_active_joint_count(self, ctypes.byref(count))
        return count.value

    @property
    @api("LinkSet.active_joints")
    def active_joints(self) -> List[int]:
        """The model indices of the active joints, in model order: value i
        of an active joint vector sets joint active_joints[i]."""
        return [int(j) for j in read_array(lib.opx_linkset_get_active_joints, self,
                                           dtype=np.uint32)]

    @property
    @api("LinkSet.active_joint_names")
    def active_joint_names(self) -> List[str]:
        """The active joints' names, in the order of an active joint vector
        (to match a MoveIt or Pinocchio vector by name)."""
        return [self.joint_info(j).name for j in self.active_joints]

    @api("LinkSet.set_joint_positions")
    def set_joint_positions(self, positions: Union[ArrayLike, Mapping[str, float]],
                            base_pose: Optional[PoseLike] = None) -> None:
        """Forward kinematics, the root link at base_pose in the map frame
        (None: identity); every link pose is set.  positions (radians or
        metres) is either
          * a vector of active_joint_count values, the active joints in
            order (active_joint_names), as MoveIt and planners hold them;
          * a vector of joint_count values, every joint in model order
            (joint_names; values of fixed, floating and planar joints
            ignored, mimic joints following their masters); when both
            counts are equal every joint is active and the two are one;
          * a {name: position} mapping: set_named_joint_positions.
        Raises InvalidArgumentError for a length that is neither count or
        a value that is not finite or beyond 1e6, UnsupportedError for a
        set not made from URDF; on error nothing changes."""
        if isinstance(positions, Mapping):
            self.set_named_joint_positions(positions, base_pose)
            return
        values = np.ascontiguousarray(positions, dtype=np.float64).reshape(-1)
        if len(values) != self.joint_count and len(values) == self.active_joint_count:
            lib.opx_linkset_set_active_joint_positions(self, values.ctypes.data, len(values),
                                                       _base(base_pose))
            return
        if len(values) != self.joint_count and self.joint_count:
            raise invalid(f"{len(values)} positions are neither the {self.active_joint_count} "
                          f"active joints nor the {self.joint_count} joints in model order",
                          "LinkSet.set_joint_positions")
        lib.opx_linkset_set_joint_positions(self, values.ctypes.data, len(values),
                                            _base(base_pose))

    @api("LinkSet.set_active_joint_positions")
    def set_active_joint_positions(self, positions: ArrayLike,
                                   base_pose: Optional[PoseLike] = None) -> None:
        """Forward kinematics from the active joints alone:
        active_joint_count values in the order of active_joint_names
        (mimic joints follow their leaders; fixed, floating and planar
        joints need none), the root link at base_pose (None: identity).
        The poses equal those of set_joint_positions with the same values
        in model order.  Raises InvalidArgumentError for another count or
        a bad value; on error nothing changes."""
        values = np.ascontiguousarray(positions, dtype=np.float64).reshape(-1)
        lib.opx_linkset_set_active_joint_positions(self, values.ctypes.data, len(values),
                                                   _base(base_pose))

    @api("LinkSet.set_named_joint_positions")
    def set_named_joint_positions(self, positions: Mapping[str, float],
                                  base_pose: Optional[PoseLike] = None) -> None:
        """Forward kinematics with only the joints of the {name: position}
        mapping changed (any subset); the others keep their last values
        (initially 0).  Naming the active joints alone sets every pose;
        values of mimic, fixed, floating and planar joints are ignored.
        An unknown name is an InvalidArgumentError naming it."""
        names = [name.encode() for name in positions]
        array = (ctypes.c_char_p * max(len(names), 1))(*names)
        values = np.array([float(v) for v in positions.values()], dtype=np.float64)
        lib.opx_linkset_set_named_joint_positions(self, array, values.ctypes.data, len(values),
                                                  _base(base_pose))

    @property
    @api("LinkSet.joint_positions")
    def joint_positions(self) -> np.ndarray:
        """The joint positions in model order, as FK uses them (mimic
        joints: their computed value; fixed, floating, planar: 0)."""
        return read_array(lib.opx_linkset_get_joint_positions, self)

    @property
    @api("LinkSet.active_joint_positions")
    def active_joint_positions(self) -> np.ndarray:
        """The active joints' positions, in the order of
        active_joint_names (set_active_joint_positions takes them back)."""
        return self.joint_positions[self.active_joints]

    @api("LinkSet.disable_never_colliding_pairs")
    def disable_never_colliding_pairs(self, samples: int = 10000, seed: int = 1,
                                      also_always_colliding: bool = False,
                                      also_colliding_now: bool = False) -> PairSamplingResult:
        """Disables every pair of links that never collides over `samples`
        random configurations (each moving joint uniform within its
        limits), as MoveIt's setup assistant does; with
        also_always_colliding=True also the pairs colliding in every sample
        (links meeting at their joint), with also_colliding_now=True those
        colliding at the current poses (the default configuration).  Poses
        and joints do not change.  Returns the PairSamplingResult: how many
        pairs each rule disabled (now, never, always).  Sampling can miss a
        rare colliding configuration: more samples, fewer misses.  Raises
        UnsupportedError for a set not made from URDF."""
        options = init_struct(s.PairSamplingOptions, samples=samples, seed=seed,
                              also_always_colliding=also_always_colliding,
                              also_colliding_now=also_colliding_now)
        out = init_struct(s.PairSamplingResult)
        lib.opx_linkset_disable_never_colliding_pairs(self, options, out)
        return out

    @property
    @api("LinkSet.disabled_pairs")
    def disabled_pairs(self) -> List[tuple]:
        """The SRDF <disable_collisions> pairs as (link, link) indices, as
        the file lists them (self-collision skips them; see pair_enabled)."""
        count, a, b = ctypes.c_uint32(), ctypes.c_uint32(), ctypes.c_uint32()
        lib.opx_linkset_get_disabled_pair_count(self, ctypes.byref(count))
        pairs = []
        for i in range(count.value):
            lib.opx_linkset_get_disabled_pair(self, i, ctypes.byref(a), ctypes.byref(b))
            pairs.append((a.value, b.value))
        return pairs
