"""Query.collide and Query.distance, the package's small and frequent
queries, as methods of the compiled module octoprox._fastcall when it can
be imported: ctypes' per-call conversions cost more than a tiny query.

    Query.collide = compiled_method(Query.collide, "opx_query_collide", default_request,
                                    CollisionResult, Query, Octree, LinkSet, "_map_result",
                                    "_collide_requests", names)

The compiled method serves `query.collide(tree, links)` with the default
request, and a call with keywords (no world) whose request the query's
RequestCache holds as its last; no Python frame is entered.  Every other
call, and a failing status, runs the Python method, which calls the
library through ctypes (and fills the cache); both give the same answers
and raise the same errors.

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
from typing import Callable, Optional, Sequence

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


def keyword_defaults(method: Callable, names: Sequence[str]) -> tuple:
    """The default values of ``method``'s keywords ``names``, in order: the
    key of its call without keywords."""
    return tuple(method.__kwdefaults__[keyword] for keyword in names)


def compiled_method(method: Callable, name: str, request: ctypes.Structure, result_type,
                    query_type, tree_type, links_type, result_attribute: Optional[str],
                    cache_attribute: str, names: Sequence[str]) -> Callable:
    """``method`` (a query class's function taking query, tree, links and
    the keywords ``names`` of its request key, and ``world``) with its usual
    call served by the extension (see the module): the library function
    ``name`` is called with ``request`` (the request of the defaults; the
    caller keeps it alive) or with the request of the query's cache
    ``cache_attribute`` whose last key equals the call's; the query's
    ``result_attribute`` (None: none) is set to the result.  Help,
    signature and docstring are ``method``'s.  Without the extension:
    ``method`` itself."""
    if EXTENSION is None:
        return method
    function = lib[name]  # item access makes a new object; lib.name keeps its errcheck
    return EXTENSION.method(method, ctypes.cast(function, c_void_p).value,
                            ctypes.addressof(request), result_type, query_type, tree_type,
                            links_type, result_attribute, cache_attribute, tuple(names),
                            keyword_defaults(method, names))
