"""The usual call of Query.collide and Query.distance, the package's small
and frequent queries (the keywords of the call before, no world), through
the compiled module octoprox._fastcall when it can be imported: ctypes'
per-call conversions cost more than a tiny query.  Without it, and for
every other call, the methods call the library through ctypes; both paths
give the same answers and raise the same errors.

    collide = cached_call("opx_query_collide", CollisionResult, Octree, LinkSet)
    out = collide(tree, links, query._address, tree._address, links._address,
                  cache.address, cache.key, *key)
    # a new CollisionResult (status 0), the status (a negative int), or None:
    # not the usual call (another key, other operand types), ctypes serves it

The module is looked up in the package (a wheel carries it), then next to
the library $OPX_LIBRARY names (a build tree puts it there, named
octoprox_fastcall<EXT_SUFFIX>, e.g. octoprox_fastcall.cpython-311-x86_64-linux-gnu.so).
$OPX_CTYPES_ONLY=1 makes the package use ctypes alone.
"""
import ctypes
import importlib.util
import os
import sysconfig
from ctypes import c_void_p
from types import ModuleType
from typing import Callable, Optional

from ._library import lib

_OFF = "OPX_CTYPES_ONLY"
_BUILD_TREE_NAME = "octoprox_fastcall" + (sysconfig.get_config_var("EXT_SUFFIX") or ".so")


def _from_file(path: str) -> ModuleType:
    spec = importlib.util.spec_from_file_location(__package__ + "._fastcall", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _find_extension() -> Optional[ModuleType]:
    """octoprox._fastcall, or None: switched off, not built, or built for
    another Python (ctypes then serves)."""
    if os.environ.get(_OFF, "0") not in ("", "0"):
        return None
    try:
        from . import _fastcall
        return _fastcall
    except ImportError:
        pass
    library = os.environ.get("OPX_LIBRARY")
    path = library and os.path.join(os.path.dirname(os.path.abspath(library)), _BUILD_TREE_NAME)
    if path and os.path.exists(path):
        try:
            return _from_file(path)
        except ImportError:
            return None
    return None


EXTENSION = _find_extension()


def cached_call(name: str, result_type, tree_type, links_type) -> Optional[Callable]:
    """The extension's call (see the module) for the library function
    ``name`` (the shape of opx_query_collide), or None without the
    extension.  It serves a call whose operands are a ``tree_type`` and a
    ``links_type`` and whose key equals the cached key: a new
    ``result_type`` (status 0) or the status (a negative int); any other
    call gets None and the method's own ctypes path serves it."""
    if EXTENSION is None:
        return None
    function = lib[name]  # item access makes a new object; lib.name keeps its errcheck
    return EXTENSION.bind(ctypes.cast(function, c_void_p).value, result_type, tree_type,
                          links_type)
