"""Known objects beside the sensed map (opx_world): tables, shelves, walls
and bins, as MoveIt keeps them in its planning scene.

An object has a name, a pose in the map frame, an enabled flag and shapes
of the link-set kinds (linkset.py: sizes in metres, a box's FULL edges, a
cylinder's FULL length along z), each at a pose in the object frame.
Objects have no padding (a link's padding is the margin); a mesh is a
surface.  Poses are x y z qx qy qz qw.  Query.collide, Query.distance,
Query.path, check_configurations, check_motion and check_motions check a
world's enabled objects with ``world=``; the octree may then be None
(objects have no cost: a path's or motion's cost comes from the octree).
Removing an object moves every later one down by one index.

    world = octoprox.World.from_scene_file("kitchen.scene")
    world.add_box("crate", (0.4, 0.3, 0.3), pose=(1.0, 0.5, 0.15))
    hit = octoprox.Query().collide(tree, robot, world=world)
"""
from __future__ import annotations

import ctypes
import os
from types import SimpleNamespace
from typing import Callable, List, Optional, Sequence, TypeVar, Union

from . import _structs as s
from ._arrays import triangle_array, vertex_array
from ._enums import ShapeKind
from ._errors import invalid
from ._handle import Handle, api, failure
from ._library import init_struct, lib, make_pose
from ._types import ArrayLike, PathLike, PoseLike, Vector3
from .linkset import LinkRef, LinkSet, _name, _shape_view, touch_link_names
from .octree import Octree

ObjectRef = Union[int, str]  # an object's index or its name (the first so named)
_T = TypeVar("_T")
SCENE_FORMATS = {"yaml": 1, "scene": 2}  # OPX_SCENE_FORMAT_YAML, OPX_SCENE_FORMAT_TEXT


def _pose(value) -> s.Pose:
    return make_pose((0.0, 0.0, 0.0) if value is None else value)


class World(Handle):
    """Named objects of shapes with poses in the map frame (see the module).

    Reading methods may run on many threads at once; changing ones need
    the world to themselves, and no query may run with it meanwhile.  A
    world cannot be pickled (read its scene file again in the other
    process).
    """
    _destroy = "opx_world_destroy"
    _noun = "world"
    _no_pickle = "read its scene file again, or build it again, in the other process"

    @api("World")
    def __init__(self) -> None:
        """An empty world: add objects with add_box, add_sphere..."""
        super().__init__(lib.opx_world_create)

    @classmethod
    @api("World.from_scene_file")
    def from_scene_file(cls, path: PathLike) -> World:
        """The objects of a MoveIt planning scene file, by its extension:
        .yaml or .yml (a moveit_msgs/PlanningScene as YAML: ADD, APPEND,
        REMOVE and MOVE in file order; BOX, SPHERE, CYLINDER primitives
        and meshes; robowflex's dialect too, as in MotionBenchMaker's
        scenes: poses as lists, primitive types and operations as words)
        or .scene (MoveIt's scene text).  header.frame_id is taken as the
        map frame unless it names one of the scene's
        fixed_frame_transforms; the robot state and the allowed collision
        matrix are ignored.  Raises IoError, CorruptDataError (the message
        names the file, the line and the field), UnsupportedError (cones,
        planes, mesh files)."""
        return cls._from(lambda out: lib.opx_world_load_scene_file(os.fsencode(path), out))

    @classmethod
    @api("World.from_scene_string")
    def from_scene_string(cls, text: Union[str, bytes], format: str = "yaml") -> World:
        """As from_scene_file, from text in format "yaml" or "scene"."""
        if format not in SCENE_FORMATS:
            raise invalid(f"format {format!r} is not one of {sorted(SCENE_FORMATS)}",
                          "World.from_scene_string")
        data = text.encode() if isinstance(text, str) else bytes(text)
        return cls._from(lambda out: lib.opx_world_load_scene_memory(data, len(data),
                                                                     SCENE_FORMATS[format], out))

    def _index(self, obj: ObjectRef) -> int:
        return self.find(obj) if isinstance(obj, str) else obj

    @api("World.add_object")
    def add_object(self, name: str, pose: Optional[PoseLike] = None) -> int:
        """Adds an object without shapes at pose (map frame; default the
        origin); returns its index.  add_shape gives it shapes."""
        index = ctypes.c_uint32()
        lib.opx_world_add_object(self, _name(name), _pose(pose), ctypes.byref(index))
        return index.value

    @api("World.add_shape")
    def add_shape(self, obj: ObjectRef, kind: Union[ShapeKind, int, str], pose: Optional[PoseLike] = None, *,
                  radius: float = 0.0, length: float = 0.0, size: Vector3 = (0.0, 0.0, 0.0),
                  vertices: Optional[ArrayLike] = None,
                  triangles: Optional[ArrayLike] = None) -> int:
        """Adds a shape of kind (ShapeKind: SPHERE, BOX, CYLINDER, CAPSULE,
        CONVEX, MESH) to an object, at pose in the object frame; the fields
        as LinkSet's add_* methods take them.  Returns its index in the
        object."""
        fields = dict(kind=ShapeKind.parse(kind, "World.add_shape", "kind"), radius=radius,
                      length=length, size=size)
        keep = []
        if vertices is not None:
            v = vertex_array(vertices, "World.add_shape")
            keep.append(v)
            fields.update(vertices=v.ctypes.data, vertex_count=len(v),
                          vertex_stride=v.strides[0] if len(v) > 1 else 0)
        if triangles is not None:
            t = triangle_array(triangles, "World.add_shape")
            keep.append(t)
            fields.update(indices=t.ctypes.data, triangle_count=len(t))
        shape = init_struct(s.Shape, **fields)
        if pose is not None:
            shape.pose = make_pose(pose)
        index = ctypes.c_uint32()
        lib.opx_world_add_shape(self, self._index(obj), shape, ctypes.byref(index))
        return index.value

    def _add_one(self, name, pose, kind, **fields) -> int:
        index = self.add_object(name, pose)
        try:
            self.add_shape(index, kind, **fields)
        except Exception:
            lib.opx_world_remove_object(self, index)  # no object without its shape
            raise
        return index

    @api("World.add_box")
    def add_box(self, name: str, size: Vector3, pose: Optional[PoseLike] = None) -> int:
        """Adds an object of one box of FULL edge lengths size = (x, y, z),
        centred at pose (map frame); returns the object's index."""
        return self._add_one(name, pose, ShapeKind.BOX, size=size)

    @api("World.add_sphere")
    def add_sphere(self, name: str, radius: float, pose: Optional[PoseLike] = None) -> int:
        """Adds an object of one sphere of radius centred at pose (map frame)."""
        return self._add_one(name, pose, ShapeKind.SPHERE, radius=radius)

    @api("World.add_cylinder")
    def add_cylinder(self, name: str, radius: float, length: float,
                     pose: Optional[PoseLike] = None) -> int:
        """Adds an object of one cylinder of radius and FULL length along
        its z axis, centred at pose (map frame).  (MoveIt gives
        [height, radius]: length is the height.)"""
        return self._add_one(name, pose, ShapeKind.CYLINDER, radius=radius, length=length)

    @api("World.add_mesh")
    def add_mesh(self, name: str, vertices: ArrayLike, triangles: ArrayLike,
                 pose: Optional[PoseLike] = None) -> int:
        """Adds an object of one triangle surface: (N, 3) vertices (m,
        object frame) and (M, 3) vertex indices, the object at pose."""
        return self._add_one(name, pose, ShapeKind.MESH, vertices=vertices, triangles=triangles)

    @api("World.remove")
    def remove(self, obj: ObjectRef) -> None:
        """Removes an object (index or name); later objects move down by one."""
        lib.opx_world_remove_object(self, self._index(obj))

    @api("World.set_pose")
    def set_pose(self, obj: ObjectRef, pose: PoseLike) -> None:
        """Moves an object: pose is its frame in the map frame."""
        lib.opx_world_set_object_pose(self, self._index(obj), make_pose(pose))

    @api("World.pose")
    def pose(self, obj: ObjectRef) -> tuple:
        """An object's pose in the map frame, (x, y, z, qx, qy, qz, qw)."""
        out = s.Pose()
        lib.opx_world_get_object_pose(self, self._index(obj), ctypes.byref(out))
        return tuple(out.position) + tuple(out.orientation)

    @api("World.set_enabled")
    def set_enabled(self, obj: ObjectRef, enabled: bool) -> None:
        """Disabled objects take part in no query (all start enabled)."""
        lib.opx_world_set_object_enabled(self, self._index(obj), 1 if enabled else 0)

    @api("World.enabled")
    def enabled(self, obj: ObjectRef) -> bool:
        """Whether an object takes part in queries."""
        out = ctypes.c_int32()
        lib.opx_world_get_object_enabled(self, self._index(obj), ctypes.byref(out))
        return bool(out.value)

    @api("World.find")
    def find(self, name: str) -> int:
        """The index of the first object named name (InvalidArgumentError if none)."""
        index = ctypes.c_uint32()
        lib.opx_world_find_object(self, _name(name), ctypes.byref(index))
        return index.value

    @api("World.name")
    def name(self, obj: int) -> str:
        """The name of object obj."""
        out = ctypes.c_char_p()
        lib.opx_world_get_object_name(self, obj, ctypes.byref(out))
        return out.value.decode("utf-8", "replace")

    @property
    @api("World.names")
    def names(self) -> List[str]:
        """Every object's name, in index order."""
        return [self.name(i) for i in range(len(self))]

    def __len__(self) -> int:
        """The number of objects."""
        count = ctypes.c_uint32()
        lib.opx_world_get_object_count(self, ctypes.byref(count))
        return count.value

    @api("World.shape_count")
    def shape_count(self, obj: ObjectRef) -> int:
        """The number of shapes of an object."""
        count = ctypes.c_uint32()
        lib.opx_world_get_shape_count(self, self._index(obj), ctypes.byref(count))
        return count.value

    @api("World.shape")
    def shape(self, obj: ObjectRef, shape: int) -> SimpleNamespace:
        """A shape as stored, as LinkSet.shape gives it (pose in the object
        frame)."""
        out = init_struct(s.Shape)
        lib.opx_world_get_shape(self, self._index(obj), shape, out)
        return _shape_view(out)

    @api("World.attach_to")
    def attach_to(self, obj: ObjectRef, links: LinkSet, link: LinkRef, *,
                  touch_links: Sequence[str] = ()) -> int:
        """Attaches a copy of object obj (its name and shapes) to a link
        of links where it stands now (its map pose seen from the link's
        current pose), as LinkSet.attach_object does; returns the attached
        object's index.  This world does not change: remove or disable the
        object here (as MoveIt moves an object it attaches out of its
        world), or the copy touches the original."""
        if not isinstance(links, LinkSet):
            raise TypeError(f"World.attach_to: expected a LinkSet, got {type(links).__name__}")
        names, count = touch_link_names(touch_links, "World.attach_to")
        index = ctypes.c_uint32()
        lib.opx_linkset_attach_world_object(links, links._link_index(link), self, self._index(obj),
                                            names, count, ctypes.byref(index))
        return index.value


def query_with_world(query, tree: Optional[Octree], links: LinkSet, world: Optional[World],
                     where: str, call: Callable[[object], int]) -> None:
    """Runs ``call(tree handle or None)`` (a C query returning a status)
    with ``world`` set on ``query``, detached again after, so the query
    never keeps a world Python may free; a failing status raises the
    library's error named by ``where``."""
    if (tree is not None and not isinstance(tree, Octree)) or not isinstance(links, LinkSet) or \
            (world is not None and not isinstance(world, World)):
        raise TypeError(f"{where}: expected an Octree (or None), a LinkSet and a World (or None), "
                        f"got {type(tree).__name__}, {type(links).__name__} and "
                        f"{type(world).__name__}")
    if world is not None:
        lib.opx_query_set_world(query, world)
    try:
        status = call(None if tree is None else tree._raw)
    finally:
        if world is not None:
            lib.opx_query_set_world(query, None)
    if status:
        raise failure(status, where, query, tree, links, world)


def call_with_world(query, world: Optional[World], where: str, call: Callable[[], _T]) -> _T:
    """Returns ``call()`` (a library call raising its own errors) run with
    ``world`` set on ``query`` and detached again after, so the query never
    keeps a world Python may free; world None: ``call()`` as it is."""
    if world is None:
        return call()
    if not isinstance(world, World):
        raise TypeError(f"{where}: expected a World (or None) for world, "
                        f"got {type(world).__name__}")
    lib.opx_query_set_world(query, world)
    try:
        return call()
    finally:
        lib.opx_query_set_world(query, None)
