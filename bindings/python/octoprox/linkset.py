"""The robot: a set of links with shapes (opx_linkset)."""
import ctypes
from types import SimpleNamespace

import numpy as np

from . import _structs as s
from ._arrays import pose_array, pose_strides, triangle_array, vertex_array
from ._handle import Handle
from ._library import init_struct, lib, make_pose
from .robot import RobotModel

SHAPE_SPHERE, SHAPE_BOX, SHAPE_CYLINDER, SHAPE_CAPSULE, SHAPE_CONVEX, SHAPE_MESH = range(1, 7)


def _name(text):
    return text.encode() if isinstance(text, str) else bytes(text)


class LinkSet(Handle, RobotModel):
    """A robot as links, each with shapes (metres, in the link frame), a
    padding, an enabled flag and a pose in the map frame; built by hand or
    from URDF (LinkSet.from_urdf).  Reading methods may run on many threads
    at once; changing ones need it to themselves.
    """
    _destroy = "opx_linkset_destroy"

    def __init__(self):
        super().__init__(lib.opx_linkset_create)

    @classmethod
    def _from(cls, create):
        links = cls.__new__(cls)
        Handle.__init__(links, create)
        return links

    def clone(self):
        """A deep copy (shapes, names, poses, paddings, enabled flags, joints)."""
        return LinkSet._from(lambda out: lib.opx_linkset_clone(self, out))

    def add_link(self, name):
        """Adds a link with an identity pose; returns its index."""
        index = ctypes.c_uint32()
        lib.opx_linkset_add_link(self, _name(name), ctypes.byref(index))
        return index.value

    def _add(self, link, kind, pose, **fields):
        shape = init_struct(s.Shape, kind=kind, **fields)
        if pose is not None:
            shape.pose = make_pose(pose)
        index = ctypes.c_uint32()
        lib.opx_linkset_add_shape(self, link, shape, ctypes.byref(index))
        return index.value

    def add_sphere(self, link, radius, pose=None):
        """A sphere centred at pose (in the link frame; default identity)."""
        return self._add(link, SHAPE_SPHERE, pose, radius=radius)

    def add_box(self, link, size, pose=None):
        """A box of FULL edge lengths size = (x, y, z)."""
        return self._add(link, SHAPE_BOX, pose, size=size)

    def add_cylinder(self, link, radius, length, pose=None):
        """A cylinder of FULL length along z."""
        return self._add(link, SHAPE_CYLINDER, pose, radius=radius, length=length)

    def add_capsule(self, link, radius, length, pose=None):
        """A capsule; length is its cylindrical part along z."""
        return self._add(link, SHAPE_CAPSULE, pose, radius=radius, length=length)

    def add_convex(self, link, vertices, pose=None):
        """The solid convex hull of (N, 3) vertices (read by stride)."""
        v = vertex_array(vertices, "LinkSet.add_convex")
        return self._add(link, SHAPE_CONVEX, pose, vertices=v.ctypes.data,
                         vertex_count=len(v), vertex_stride=v.strides[0] if len(v) > 1 else 0)

    def add_mesh(self, link, vertices, triangles, pose=None):
        """A triangle surface: (N, 3) vertices, (M, 3) vertex indices."""
        v = vertex_array(vertices, "LinkSet.add_mesh")
        t = triangle_array(triangles, "LinkSet.add_mesh")
        return self._add(link, SHAPE_MESH, pose, vertices=v.ctypes.data, vertex_count=len(v),
                         vertex_stride=v.strides[0] if len(v) > 1 else 0,
                         indices=t.ctypes.data, triangle_count=len(t))

    def __len__(self):
        return self.link_count

    @property
    def link_count(self):
        count = ctypes.c_uint32()
        lib.opx_linkset_get_link_count(self, ctypes.byref(count))
        return count.value

    def shape_count(self, link):
        count = ctypes.c_uint32()
        lib.opx_linkset_get_shape_count(self, link, ctypes.byref(count))
        return count.value

    def shape(self, link, shape):
        """Shape `shape` of `link` as stored: a namespace with kind
        (SHAPE_*), pose (7 floats, link frame), radius, length, size, and
        copies of vertices (N, 3) and triangles (M, 3) for convex hulls and
        meshes (a mesh keeps only the vertices its triangles use)."""
        out = init_struct(s.Shape)
        lib.opx_linkset_get_shape(self, link, shape, out)
        vertices = np.ctypeslib.as_array(ctypes.cast(out.vertices, ctypes.POINTER(
            ctypes.c_double)), (out.vertex_count, 3)).copy() if out.vertex_count else \
            np.zeros((0, 3))
        triangles = np.ctypeslib.as_array(ctypes.cast(out.indices, ctypes.POINTER(
            ctypes.c_uint32)), (out.triangle_count, 3)).copy() if out.triangle_count else \
            np.zeros((0, 3), dtype=np.uint32)
        return SimpleNamespace(kind=out.kind, pose=tuple(out.pose.position) +
                               tuple(out.pose.orientation), radius=out.radius,
                               length=out.length, size=tuple(out.size), vertices=vertices,
                               triangles=triangles)

    def link_name(self, link):
        name = ctypes.c_char_p()
        lib.opx_linkset_get_link_name(self, link, ctypes.byref(name))
        return name.value.decode("utf-8", "replace")

    @property
    def link_names(self):
        return [self.link_name(i) for i in range(self.link_count)]

    def find_link(self, name):
        """The index of the first link named name (InvalidArgumentError if none)."""
        index = ctypes.c_uint32()
        lib.opx_linkset_find_link(self, _name(name), ctypes.byref(index))
        return index.value

    def set_padding(self, padding):
        """The global padding in metres, added to every link's own."""
        lib.opx_linkset_set_padding(self, padding)

    def set_link_padding(self, link, padding):
        lib.opx_linkset_set_link_padding(self, link, padding)

    def set_link_enabled(self, link, enabled):
        lib.opx_linkset_set_link_enabled(self, link, int(bool(enabled)))

    def _link_index(self, link):
        return self.find_link(link) if isinstance(link, str) else link

    def set_pair_enabled(self, a, b, enabled):
        """Whether self-collision queries (Query.self_collide,
        Query.self_distance) check links a and b (indices or names; a != b).
        Every pair starts enabled but an SRDF's disabled pairs; links joined
        by a joint are not skipped unless disabled."""
        lib.opx_linkset_set_pair_enabled(self, self._link_index(a), self._link_index(b),
                                         int(bool(enabled)))

    def pair_enabled(self, a, b):
        """True when self-collision queries check links a and b."""
        enabled = ctypes.c_int32()
        lib.opx_linkset_get_pair_enabled(self, self._link_index(a), self._link_index(b),
                                         ctypes.byref(enabled))
        return bool(enabled.value)

    def set_poses(self, poses):
        """Every link's pose in the map frame: an (N, 7) array (x y z qx qy
        qz qw; a float64 array is read in place by row stride) or (N, 3)
        positions."""
        arr = pose_array(poses, "LinkSet.set_poses", 2)
        lib.opx_linkset_set_poses(self, arr.ctypes.data, len(arr), pose_strides(arr)[0])

    def pose(self, link):
        """A link's pose in the map frame, as a tuple of 7 floats."""
        out = s.Pose()
        lib.opx_linkset_get_pose(self, link, out)
        return tuple(out.position) + tuple(out.orientation)

