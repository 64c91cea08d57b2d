"""Request structs built once per distinct set of keyword values.

A query method gathers its keywords into a tuple, the key, in the order of
``names``.  A Query keeps one cache per request kind: the key of the last
request is compared first (the usual loop asks the same thing every time),
then a small dict, so a repeated query builds no ctypes struct and calls no
opx_x_init.  Keys holding a list or an array (region_min) build a struct
every time.  The last kept request's address, an int, is what the
compiled call path (octoprox._calls) passes.
"""
import ctypes
from typing import Any, Dict, Optional, Sequence, Tuple, Type

from ._enums import JointOrder, ObstacleGeometry, UnknownPolicy
from ._library import init_struct, set_field

# Keywords whose values are IntEnum members (any member, value or name).
ENUMS = {"unknown_policy": UnknownPolicy, "obstacle_geometry": ObstacleGeometry,
         "joint_order": JointOrder}
_MAX_KEYS = 64  # distinct keys kept; more (a cutoff varied every call) start over


class RequestCache:
    """The request structs of one kind of query, by key.  ``key``,
    ``request`` and ``address`` are the last ones (the compiled call path
    reads ``key`` and ``address``); ``request`` is a ctypes byref of the
    struct, ready to pass, ``address`` the struct's address."""

    def __init__(self, struct_type: Type[ctypes.Structure], names: Sequence[str], where: str):
        """An empty cache of ``struct_type`` requests whose keys hold the
        fields ``names``, for the method ``where``."""
        self._type, self._names, self._where = struct_type, tuple(names), where
        self._by_key: Dict[Tuple, Any] = {}
        self.key: Optional[Tuple] = None
        self.request = None
        self.address = 0

    def lookup(self, key: Tuple):
        """The request for ``key``, built when new; it becomes the last."""
        try:
            if key == self.key:
                return self.request
            request = self._by_key.get(key)
        except (ValueError, TypeError):  # an array or a list: built, not kept
            return ctypes.byref(self.build(key))
        if request is None:
            if len(self._by_key) >= _MAX_KEYS:
                self._by_key.clear()
            request = self._by_key[key] = ctypes.byref(self.build(key))
        self.key, self.request = key, request
        self.address = ctypes.addressof(request._obj)
        return request

    def build(self, key: Tuple) -> ctypes.Structure:
        """A new struct with the library's defaults and the key's values;
        a bad value raises TypeError or ValueError naming the method and
        the keyword."""
        request = init_struct(self._type)
        for name, value in zip(self._names, key):
            enum = ENUMS.get(name)
            if enum is not None:
                value = enum.parse(value, self._where, name)
            try:
                set_field(request, name, value)
            except (TypeError, ValueError) as error:
                kind = TypeError if isinstance(error, TypeError) else ValueError
                text = str(error) if name in str(error) else f"{name}: {error}"
                raise kind(f"{self._where}: {text}") from None
        return request

