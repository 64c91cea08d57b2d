"""Link sets from URDF, their joints and forward kinematics (robot.h).
LinkSet inherits these methods."""
import ctypes
import os

import numpy as np

from . import _structs as s
from ._arrays import read_array
from ._library import init_struct, lib, make_pose

JOINT_FIXED, JOINT_REVOLUTE, JOINT_CONTINUOUS, JOINT_PRISMATIC, JOINT_FLOATING, \
    JOINT_PLANAR = range(6)
JOINT_NONE = 0xFFFFFFFF


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
    def from_urdf(cls, path, package_dirs=(), base_dir=None, srdf=None):
        """A link set from a URDF file: one link per <link> (same names, file
        order), one shape per <collision>, every joint at 0, the root at the
        map origin.  package_dirs resolve package:// mesh names: folders, or
        "NAME=DIR" entries; srdf: a file whose disabled pairs self-collision
        queries skip."""
        options, _keep = _urdf_options(package_dirs, base_dir, srdf)
        return cls._from(lambda out: lib.opx_linkset_load_urdf_file(os.fsencode(path),
                                                                    options, out))

    @classmethod
    def from_urdf_string(cls, xml, package_dirs=(), base_dir=None, srdf=None):
        """A link set from URDF XML text (relative meshes: base_dir)."""
        options, _keep = _urdf_options(package_dirs, base_dir, srdf)
        text = xml.encode() if isinstance(xml, str) else bytes(xml)
        return cls._from(lambda out: lib.opx_linkset_load_urdf_string(text, options, out))

    @property
    def joint_count(self):
        count = ctypes.c_uint32()
        lib.opx_linkset_get_joint_count(self, ctypes.byref(count))
        return count.value

    def find_joint(self, name):
        index = ctypes.c_uint32()
        lib.opx_linkset_find_joint(self, name.encode(), ctypes.byref(index))
        return index.value

    def joint_info(self, joint):
        """The JointInfo of a joint: type, name, links, axis, origin, limits."""
        out = init_struct(s.JointInfo)
        lib.opx_linkset_get_joint_info(self, joint, out)
        return out

    @property
    def joint_names(self):
        return [self.joint_info(j).name for j in range(self.joint_count)]

    def set_joint_positions(self, positions, base_pose=None):
        """FK: all joint positions in model order (radians or metres), the
        root link at base_pose in the map frame (default identity)."""
        values = np.ascontiguousarray(positions, dtype=np.float64).reshape(-1)
        lib.opx_linkset_set_joint_positions(self, values.ctypes.data, len(values),
                                            _base(base_pose))

    def set_named_joint_positions(self, positions, base_pose=None):
        """FK with only the joints of the {name: position} mapping changed."""
        names = [name.encode() for name in positions]
        array = (ctypes.c_char_p * max(len(names), 1))(*names)
        values = np.array([float(v) for v in positions.values()], dtype=np.float64)
        lib.opx_linkset_set_named_joint_positions(self, array, values.ctypes.data, len(values),
                                                  _base(base_pose))

    @property
    def joint_positions(self):
        """The joint positions in model order, as FK uses them."""
        return read_array(lib.opx_linkset_get_joint_positions, self)

    def disable_never_colliding_pairs(self, samples=10000, seed=1, also_always_colliding=False,
                                      also_colliding_now=False):
        """Disables every pair of links that never collides over `samples`
        random configurations (each moving joint uniform within its
        limits), as MoveIt's setup assistant does; with
        also_always_colliding=True also the pairs colliding in every sample
        (links meeting at their joint), with also_colliding_now=True those
        colliding at the current poses (the default configuration).  Poses
        and joints do not change.  Returns the PairSamplingResult: how many
        pairs each rule disabled (now, never, always)."""
        options = init_struct(s.PairSamplingOptions, samples=samples, seed=seed,
                              also_always_colliding=also_always_colliding,
                              also_colliding_now=also_colliding_now)
        out = init_struct(s.PairSamplingResult)
        lib.opx_linkset_disable_never_colliding_pairs(self, options, out)
        return out

    @property
    def disabled_pairs(self):
        """The SRDF <disable_collisions> pairs as (link, link) indices, as
        the file lists them (self-collision skips them; see pair_enabled)."""
        count, a, b = ctypes.c_uint32(), ctypes.c_uint32(), ctypes.c_uint32()
        lib.opx_linkset_get_disabled_pair_count(self, ctypes.byref(count))
        pairs = []
        for i in range(count.value):
            lib.opx_linkset_get_disabled_pair(self, i, ctypes.byref(a), ctypes.byref(b))
            pairs.append((a.value, b.value))
        return pairs
