"""Request structs built once per distinct set of keyword values.

A query method gathers its keywords into a tuple, the key, in the order of
``names``.  A Query keeps one cache per request kind: the struct for the
last key is compared first (the usual loop asks the same thing every
time), then a small dict, so a repeated query builds no ctypes struct and
calls no opx_x_init.  Keys holding unhashable values (a list or an array
as region_min) build a struct every time.
"""
import ctypes
from typing import Any, Dict, Optional, Sequence, Tuple, Type

from ._enums import ObstacleGeometry, UnknownPolicy
from ._library import init_struct

# Keywords whose values are IntEnum members (any member, value or name).
ENUMS = {"unknown_policy": UnknownPolicy, "obstacle_geometry": ObstacleGeometry}
_MAX_KEYS = 64  # distinct keys kept; more (a cutoff varied every call) start over


class RequestCache:
    """The request structs of one kind of query, by key.  ``key`` and
    ``request`` are the last ones (read inline by the query methods);
    ``request`` is a ctypes byref of the struct, ready to pass."""

    def __init__(self, struct_type: Type[ctypes.Structure], names: Sequence[str],
                 where: str, fixed: Optional[Dict[str, Any]] = None):
        self._type, self._names, self._where = struct_type, tuple(names), where
        self._fixed = fixed or {}
        self._by_key: Dict[Tuple, Any] = {}
        self.key: Optional[Tuple] = None
        self.request = None

    def lookup(self, key: Tuple):
        """The request for ``key``, built when new; it becomes the last."""
        try:
            request = self._by_key.get(key)
        except TypeError:  # an unhashable value: built, not kept
            return ctypes.byref(self.build(key))
        if request is None:
            if len(self._by_key) >= _MAX_KEYS:
                self._by_key.clear()
            request = self._by_key[key] = ctypes.byref(self.build(key))
        self.key, self.request = key, request
        return request

    def build(self, key: Tuple) -> ctypes.Structure:
        """A new struct with the library's defaults and the key's values;
        a bad value raises TypeError or ValueError naming the method and
        the keyword."""
        fields = dict(self._fixed)
        for name, value in zip(self._names, key):
            enum = ENUMS.get(name)
            fields[name] = enum.parse(value, self._where, name) if enum else value
        try:
            return init_struct(self._type, **fields)
        except (TypeError, ValueError) as error:
            raise type(error)(f"{self._where}: {error}") from None

