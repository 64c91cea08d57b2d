"""The base of the ctypes mirrors of the C structs: ``Struct`` (a readable
repr, ``to_dict``), ``Pose``, and typed views of int32 fields (flags read
as bool, class and kind codes as IntEnum members)."""
import ctypes
from ctypes import c_double
from typing import Any, Callable, Dict

D3 = c_double * 3
D3.__doc__ = "Three doubles: a point or a vector (x, y, z), metres unless a field says otherwise."


class Struct(ctypes.Structure):
    """A C struct with a readable repr and ``to_dict()``.  Fields have the
    C names; ``struct_size`` and ``reserved*`` are the ABI's own."""

    def to_dict(self) -> Dict[str, Any]:
        """Every field by name; arrays as tuples, nested structs as dicts."""
        out = {}
        for name, _ in self._fields_:
            value = getattr(self, name)
            if isinstance(value, ctypes.Array):
                value = tuple(value)
            elif isinstance(value, Struct):
                value = value.to_dict()
            out[name] = value
        return out

    def __repr__(self):
        fields = ", ".join(f"{k}={v!r}" for k, v in self.to_dict().items()
                           if not k.startswith("reserved") and k != "struct_size")
        return f"{type(self).__name__}({fields})"


class Pose(Struct):
    """A rigid transform: the pose of a child frame in a parent frame.
    ``position`` x y z in metres, ``orientation`` a unit quaternion qx qy
    qz qw (ROS order; the library normalises it, a zero or non-finite one
    is an invalid argument)."""
    _fields_ = [("position", D3), ("orientation", c_double * 4)]


class _TypedField:
    """An int32 field read through ``convert`` (bool, an IntEnum lookup)
    and written as an int.  It replaces the ctypes field descriptor on the
    class and keeps it for the bytes."""

    def __init__(self, field, convert: Callable[[int], Any]):
        self._field, self._convert = field, convert
        self.offset, self.size = field.offset, field.size

    def __get__(self, struct, owner=None):
        if struct is None:
            return self
        return self._convert(self._field.__get__(struct, owner))

    def __set__(self, struct, value):
        self._field.__set__(struct, int(value))


def typed_fields(struct_type, **converters: Callable[[int], Any]) -> None:
    """Reads the named int32 fields of ``struct_type`` through the
    converters: ``typed_fields(CollisionResult, collided=bool)``."""
    for name, convert in converters.items():
        field = struct_type.__dict__[name]
        setattr(struct_type, name, _TypedField(field, convert))
