"""The robot: a set of links with shapes (opx_linkset).

Shapes are in metres, in the shape frame, which sits at the shape's pose
in the link frame: a sphere's radius; a box's FULL edge lengths (as URDF
and FCL); a cylinder's radius and FULL length along z; a capsule's radius
and the length of its cylindrical part along z (FCL's convention); the
solid convex hull of vertices; a triangle mesh (a surface: a cell wholly
inside a closed mesh touches no triangle).  Padding is a safety margin: a
padded shape is the shape grown by a ball of that radius (exact rounding).
The library copies vertices, indices and names.

Objects attached to links (attach_object, attach_box..., MoveIt's attached
collision objects) move with their link and are checked as its shapes
against the octree and world objects; against the robot they skip their
own link and the touch links named when attaching.
"""
from __future__ import annotations

import ctypes
from types import SimpleNamespace
from typing import Any, List, Mapping, Optional, Sequence, Union

import numpy as np

from . import _structs as s
from ._arrays import needed_count, pose_array, pose_strides, triangle_array, vertex_array
from ._enums import ShapeKind
from ._handle import Handle, api
from ._library import init_struct, lib, make_pose
from ._types import ArrayLike, PoseLike, Vector3
from .robot import RobotModel

SHAPE_SPHERE, SHAPE_BOX, SHAPE_CYLINDER, SHAPE_CAPSULE, SHAPE_CONVEX, SHAPE_MESH = ShapeKind
LinkRef = Union[int, str]  # a link's index, or its name where the docstring says so


def _name(text):
    return text.encode() if isinstance(text, str) else bytes(text)


def _field(spec, name, default):
    return spec.get(name, default) if isinstance(spec, Mapping) else getattr(spec, name, default)


def _shape_struct(spec, where, keep):
    """An opx_shape of a shape description (a mapping or an object with
    kind, pose, radius, length, size, vertices, triangles, as
    LinkSet.shape gives them); arrays it points to are appended to keep."""
    fields = dict(kind=ShapeKind.parse(_field(spec, "kind", None), where, "kind"),
                  radius=_field(spec, "radius", 0.0), length=_field(spec, "length", 0.0),
                  size=tuple(_field(spec, "size", (0.0, 0.0, 0.0))))
    vertices, triangles = _field(spec, "vertices", None), _field(spec, "triangles", None)
    if vertices is not None and len(vertices):
        v = vertex_array(vertices, where)
        keep.append(v)
        fields.update(vertices=v.ctypes.data, vertex_count=len(v),
                      vertex_stride=v.strides[0] if len(v) > 1 else 0)
    if triangles is not None and len(triangles):
        t = triangle_array(triangles, where)
        keep.append(t)
        fields.update(indices=t.ctypes.data, triangle_count=len(t))
    shape = init_struct(s.Shape, **fields)
    pose = _field(spec, "pose", None)
    if pose is not None:
        shape.pose = make_pose(pose)
    return shape


def touch_link_names(names, where):
    """The touch links as the C call takes them: a char* array and its length."""
    if isinstance(names, (str, bytes)):
        raise TypeError(f"{where}: touch_links must be a sequence of link names, not one string")
    encoded = [_name(n) for n in names]
    return (ctypes.c_char_p * max(1, len(encoded)))(*encoded), len(encoded)


def _array(address, ctype, shape, empty_dtype):
    """A copy of shape rows at address (library memory), or an empty array."""
    if not shape[0]:
        return np.zeros((0, 3), dtype=empty_dtype)
    return np.ctypeslib.as_array(ctypes.cast(address, ctypes.POINTER(ctype)), shape).copy()


def _shape_view(out: s.Shape) -> SimpleNamespace:
    """A stored shape (an opx_shape the library filled) as the shape
    getters return it: kind (ShapeKind), pose (7 floats), radius, length,
    size, and copies of its vertices and triangles."""
    vertices = _array(out.vertices, ctypes.c_double, (out.vertex_count, 3), np.float64)
    triangles = _array(out.indices, ctypes.c_uint32, (out.triangle_count, 3), np.uint32)
    return SimpleNamespace(kind=ShapeKind(out.kind), pose=tuple(out.pose.position) +
                           tuple(out.pose.orientation), radius=out.radius,
                           length=out.length, size=tuple(out.size), vertices=vertices,
                           triangles=triangles)


class LinkSet(Handle, RobotModel):
    """A robot as links, each with shapes (metres, in the link frame), a
    padding, an enabled flag and a pose in the map frame; built by hand
    (LinkSet(), add_link, add_sphere...) or from URDF (LinkSet.from_urdf).

    Reading methods may run on many threads at once; changing ones need
    the link set to themselves.  A link set cannot be pickled (build it
    again in the other process; clone() copies one).
    """
    _destroy = "opx_linkset_destroy"
    _noun = "link set"
    _no_pickle = "build the link set again in the other process (clone() copies one here)"

    @api("LinkSet")
    def __init__(self) -> None:
        """An empty link set: add links with add_link, shapes with add_sphere..."""
        super().__init__(lib.opx_linkset_create)

    @api("LinkSet.clone")
    def clone(self) -> LinkSet:
        """A deep copy (shapes, names, poses, paddings, enabled flags,
        pairs, joints)."""
        return LinkSet._from(lambda out: lib.opx_linkset_clone(self, out))

    @api("LinkSet.add_link")
    def add_link(self, name: str) -> int:
        """Adds a link with an identity pose; returns its index.  Names need
        not be unique (find_link returns the first)."""
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

    @api("LinkSet.add_sphere")
    def add_sphere(self, link: int, radius: float, pose: Optional[PoseLike] = None) -> int:
        """Adds a sphere of radius (m) centred at pose (the shape frame in
        the link frame; default identity); returns its index in the link.
        Raises InvalidArgumentError for a bad link or radius."""
        return self._add(link, ShapeKind.SPHERE, pose, radius=radius)

    @api("LinkSet.add_box")
    def add_box(self, link: int, size: Vector3, pose: Optional[PoseLike] = None) -> int:
        """Adds a box of FULL edge lengths size = (x, y, z) in metres,
        centred at pose; returns its index in the link."""
        return self._add(link, ShapeKind.BOX, pose, size=size)

    @api("LinkSet.add_cylinder")
    def add_cylinder(self, link: int, radius: float, length: float,
                     pose: Optional[PoseLike] = None) -> int:
        """Adds a cylinder of radius and FULL length along z (m), centred at
        pose; returns its index in the link."""
        return self._add(link, ShapeKind.CYLINDER, pose, radius=radius, length=length)

    @api("LinkSet.add_capsule")
    def add_capsule(self, link: int, radius: float, length: float,
                    pose: Optional[PoseLike] = None) -> int:
        """Adds a capsule: radius, and length of its cylindrical part along
        z (the distance between the sphere centres), centred at pose."""
        return self._add(link, ShapeKind.CAPSULE, pose, radius=radius, length=length)

    @api("LinkSet.add_convex")
    def add_convex(self, link: int, vertices: ArrayLike, pose: Optional[PoseLike] = None) -> int:
        """Adds the solid convex hull of (N, 3) vertices (m, shape frame;
        read by row stride, copied by the library)."""
        v = vertex_array(vertices, "LinkSet.add_convex")
        return self._add(link, ShapeKind.CONVEX, pose, vertices=v.ctypes.data,
                         vertex_count=len(v), vertex_stride=v.strides[0] if len(v) > 1 else 0)

    @api("LinkSet.add_mesh")
    def add_mesh(self, link: int, vertices: ArrayLike, triangles: ArrayLike,
                 pose: Optional[PoseLike] = None) -> int:
        """Adds a triangle surface: (N, 3) vertices (m, shape frame) and
        (M, 3) vertex indices; its triangle tree is built here, once."""
        v = vertex_array(vertices, "LinkSet.add_mesh")
        t = triangle_array(triangles, "LinkSet.add_mesh")
        return self._add(link, ShapeKind.MESH, pose, vertices=v.ctypes.data, vertex_count=len(v),
                         vertex_stride=v.strides[0] if len(v) > 1 else 0,
                         indices=t.ctypes.data, triangle_count=len(t))

    def __len__(self) -> int:
        return self.link_count

    @property
    @api("LinkSet.link_count")
    def link_count(self) -> int:
        """The number of links (len() too)."""
        count = ctypes.c_uint32()
        lib.opx_linkset_get_link_count(self, ctypes.byref(count))
        return count.value

    @api("LinkSet.shape_count")
    def shape_count(self, link: int) -> int:
        """The number of shapes of a link."""
        count = ctypes.c_uint32()
        lib.opx_linkset_get_shape_count(self, link, ctypes.byref(count))
        return count.value

    @api("LinkSet.shape")
    def shape(self, link: int, shape: int) -> SimpleNamespace:
        """Shape `shape` of `link` as stored: a namespace with kind
        (ShapeKind), pose (7 floats, link frame), radius, length, size, and
        copies of vertices (N, 3) and triangles (M, 3) for convex hulls and
        meshes (a mesh keeps only the vertices its triangles use)."""
        out = init_struct(s.Shape)
        lib.opx_linkset_get_shape(self, link, shape, out)
        return _shape_view(out)

    @api("LinkSet.link_name")
    def link_name(self, link: int) -> str:
        """The name of a link."""
        name = ctypes.c_char_p()
        lib.opx_linkset_get_link_name(self, link, ctypes.byref(name))
        return name.value.decode("utf-8", "replace")

    @property
    @api("LinkSet.link_names")
    def link_names(self) -> List[str]:
        """Every link's name, in link order."""
        return [self.link_name(i) for i in range(self.link_count)]

    @api("LinkSet.find_link")
    def find_link(self, name: str) -> int:
        """The index of the first link named name (InvalidArgumentError if none)."""
        index = ctypes.c_uint32()
        lib.opx_linkset_find_link(self, _name(name), ctypes.byref(index))
        return index.value

    @api("LinkSet.set_padding")
    def set_padding(self, padding: float) -> None:
        """The global padding in metres (>= 0), added to every link's own."""
        lib.opx_linkset_set_padding(self, padding)

    @api("LinkSet.set_link_padding")
    def set_link_padding(self, link: int, padding: float) -> None:
        """A link's own padding in metres (>= 0), added to the global one."""
        lib.opx_linkset_set_link_padding(self, link, padding)

    @api("LinkSet.set_link_enabled")
    def set_link_enabled(self, link: int, enabled: bool) -> None:
        """Disabled links take part in no query (links the sensor cannot
        see, a gripper holding an object).  All links start enabled."""
        lib.opx_linkset_set_link_enabled(self, link, int(bool(enabled)))

    def _link_index(self, link):
        return self.find_link(link) if isinstance(link, str) else link

    @api("LinkSet.set_pair_enabled")
    def set_pair_enabled(self, a: LinkRef, b: LinkRef, enabled: bool) -> None:
        """Whether self-collision queries (Query.self_collide,
        Query.self_distance) check links a and b (indices or names; a != b).
        Every pair starts enabled but an SRDF's disabled pairs; links joined
        by a joint are not skipped unless disabled."""
        lib.opx_linkset_set_pair_enabled(self, self._link_index(a), self._link_index(b),
                                         int(bool(enabled)))

    @api("LinkSet.pair_enabled")
    def pair_enabled(self, a: LinkRef, b: LinkRef) -> bool:
        """True when self-collision queries check links a and b."""
        enabled = ctypes.c_int32()
        lib.opx_linkset_get_pair_enabled(self, self._link_index(a), self._link_index(b),
                                         ctypes.byref(enabled))
        return bool(enabled.value)

    @api("LinkSet.set_poses")
    def set_poses(self, poses: ArrayLike) -> None:
        """Every link's pose in the map frame: an (N, 7) array (x y z qx qy
        qz qw; a float64 array is read in place by row stride) or (N, 3)
        positions, N the link count.  On an invalid pose nothing changes."""
        arr = pose_array(poses, "LinkSet.set_poses", 2)
        lib.opx_linkset_set_poses(self, arr.ctypes.data, len(arr), pose_strides(arr)[0])

    @api("LinkSet.pose")
    def pose(self, link: int) -> tuple:
        """A link's pose in the map frame, as a tuple of 7 floats (x y z qx
        qy qz qw)."""
        out = s.Pose()
        lib.opx_linkset_get_pose(self, link, out)
        return tuple(out.position) + tuple(out.orientation)

    @api("LinkSet.poses")
    def poses(self) -> np.ndarray:
        """Every link's pose in the map frame, in link order: a new float64
        array of shape (link_count, 7), rows x y z qx qy qz qw (row i is
        pose(i)); set_poses takes it back."""
        out = np.zeros((needed_count(lib.opx_linkset_get_poses, self), 7), dtype=np.float64)
        count = ctypes.c_size_t()
        lib.opx_linkset_get_poses(self, out.ctypes.data, len(out), ctypes.byref(count))
        return out[:count.value]

    # ---- attached objects ---------------------------------------------------

    @api("LinkSet.attach_object")
    def attach_object(self, link: LinkRef, name: str, shapes: Sequence[Any],
                      pose: Optional[PoseLike] = None, *, touch_links: Sequence[str] = ()) -> int:
        """Attaches an object to a link (MoveIt's attached collision object:
        a part the gripper holds): it moves with the link, is checked as the
        link's own shapes against the octree and world objects, and against
        the robot with every link but its own and touch_links (names of
        links it may touch, e.g. the fingers).

        link: the link's index or name.  shapes: one or more descriptions,
          mappings or objects with kind (ShapeKind), pose (in the OBJECT
          frame), radius, length, size, vertices, triangles (as shape()
          and attached_shape() give them; absent fields 0 or none).
        pose: the object frame in the link frame (default identity).
        Returns the object's index (detaching moves later ones down by
        one).  Raises InvalidArgumentError for a bad link, shape or pose or
        an unknown touch link name (nothing changes then).
        """
        keep: list = []
        structs = [_shape_struct(spec, "LinkSet.attach_object", keep) for spec in shapes]
        array = (s.Shape * max(1, len(structs)))(*structs)
        names, count = touch_link_names(touch_links, "LinkSet.attach_object")
        index = ctypes.c_uint32()
        lib.opx_linkset_attach_object(self, self._link_index(link), _name(name), array,
                                      len(structs), None if pose is None else make_pose(pose),
                                      names, count, ctypes.byref(index))
        return index.value

    @api("LinkSet.attach_box")
    def attach_box(self, link: LinkRef, name: str, size: Vector3, pose: Optional[PoseLike] = None,
                   *, touch_links: Sequence[str] = ()) -> int:
        """Attaches an object of one box of FULL edge lengths size = (x, y,
        z) centred at pose (in the link frame); as attach_object."""
        return self.attach_object(link, name, [dict(kind=ShapeKind.BOX, size=size)], pose,
                                  touch_links=touch_links)

    @api("LinkSet.attach_sphere")
    def attach_sphere(self, link: LinkRef, name: str, radius: float,
                      pose: Optional[PoseLike] = None, *, touch_links: Sequence[str] = ()) -> int:
        """Attaches an object of one sphere of radius centred at pose (in
        the link frame); as attach_object."""
        return self.attach_object(link, name, [dict(kind=ShapeKind.SPHERE, radius=radius)], pose,
                                  touch_links=touch_links)

    @api("LinkSet.attach_cylinder")
    def attach_cylinder(self, link: LinkRef, name: str, radius: float, length: float,
                        pose: Optional[PoseLike] = None, *,
                        touch_links: Sequence[str] = ()) -> int:
        """Attaches an object of one cylinder of radius and FULL length
        along its z axis, centred at pose (in the link frame); as
        attach_object."""
        return self.attach_object(link, name,
                                  [dict(kind=ShapeKind.CYLINDER, radius=radius, length=length)],
                                  pose, touch_links=touch_links)

    def _attached_index(self, obj):
        return self.find_attached(obj) if isinstance(obj, str) else obj

    @api("LinkSet.detach")
    def detach(self, obj: Union[int, str]) -> None:
        """Detaches (removes) an attached object (index or name); later
        ones move down by one."""
        lib.opx_linkset_detach_object(self, self._attached_index(obj))

    @property
    @api("LinkSet.attached_count")
    def attached_count(self) -> int:
        """The number of attached objects."""
        count = ctypes.c_uint32()
        lib.opx_linkset_get_attached_count(self, ctypes.byref(count))
        return count.value

    @api("LinkSet.find_attached")
    def find_attached(self, name: str) -> int:
        """The index of the first attached object named name
        (InvalidArgumentError if none)."""
        index = ctypes.c_uint32()
        lib.opx_linkset_find_attached(self, _name(name), ctypes.byref(index))
        return index.value

    @api("LinkSet.attached_name")
    def attached_name(self, obj: int) -> str:
        """The name of attached object obj."""
        out = ctypes.c_char_p()
        lib.opx_linkset_get_attached_name(self, obj, ctypes.byref(out))
        return out.value.decode("utf-8", "replace")

    @property
    @api("LinkSet.attached_names")
    def attached_names(self) -> List[str]:
        """Every attached object's name, in index order."""
        return [self.attached_name(i) for i in range(self.attached_count)]

    @api("LinkSet.attached_link")
    def attached_link(self, obj: Union[int, str]) -> int:
        """The index of the link an attached object hangs on."""
        out = ctypes.c_uint32()
        lib.opx_linkset_get_attached_link(self, self._attached_index(obj), ctypes.byref(out))
        return out.value

    @api("LinkSet.attached_pose")
    def attached_pose(self, obj: Union[int, str]) -> tuple:
        """An attached object's frame in its link's frame, (x, y, z, qx,
        qy, qz, qw)."""
        out = s.Pose()
        lib.opx_linkset_get_attached_pose(self, self._attached_index(obj), ctypes.byref(out))
        return tuple(out.position) + tuple(out.orientation)

    @api("LinkSet.attached_shape_count")
    def attached_shape_count(self, obj: Union[int, str]) -> int:
        """The number of shapes of an attached object."""
        count = ctypes.c_uint32()
        lib.opx_linkset_get_attached_shape_count(self, self._attached_index(obj),
                                                 ctypes.byref(count))
        return count.value

    @api("LinkSet.attached_shape")
    def attached_shape(self, obj: Union[int, str], shape: int) -> SimpleNamespace:
        """A shape of an attached object as shape() gives a link's (pose in
        the OBJECT frame)."""
        out = init_struct(s.Shape)
        lib.opx_linkset_get_attached_shape(self, self._attached_index(obj), shape, out)
        return _shape_view(out)

    @api("LinkSet.attached_touch_links")
    def attached_touch_links(self, obj: Union[int, str]) -> List[int]:
        """The indices of an attached object's touch links, ascending (its
        own link is never among them: it may always touch it)."""
        index = self._attached_index(obj)
        count = ctypes.c_size_t()
        out = (ctypes.c_uint32 * max(1, self.link_count))()
        lib.opx_linkset_get_attached_touch_links(self, index, out, len(out), ctypes.byref(count))
        return list(out[:count.value])
