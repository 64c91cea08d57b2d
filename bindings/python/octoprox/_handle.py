"""The base of Octree, LinkSet and Query: owns one C handle, frees it on
close(), at the end of a ``with`` block, or (safety net) when collected;
and ``api``, which makes errors name the Python method called."""
import ctypes
import functools
import weakref

from ._errors import ERROR_INVALID_ARGUMENT, OctoproxError, error_for, invalid
from ._library import lib


class Handle:
    """One C object (opx_octree, opx_linkset, opx_query) owned by Python.

    ``close()`` (or the end of a ``with`` block) frees it at once; using it
    afterwards raises InvalidArgumentError (a ValueError) saying so, e.g.
    "Octree.insert_points: the octree is closed".
    """
    _destroy = None  # the name of the opx_x_destroy function
    _noun = "object"  # what a closed-handle message calls it

    def __init__(self, create):
        """``create(out)`` calls an opx_x_create-like function on out."""
        raw = ctypes.c_void_p()
        create(ctypes.byref(raw))
        # The C pointer, None once closed (the library then gets NULL and
        # refuses it); the finalizer keeps its own reference to free it.
        self._raw = raw
        # The same pointer as an int, 0 once closed (what octoprox._calls
        # passes; an int costs nothing to convert).
        self._address = raw.value or 0
        self._finalizer = weakref.finalize(self, getattr(lib, self._destroy), raw)

    @classmethod
    def _from(cls, create):
        """An object of this class around the C object ``create(out)``
        makes (a copy, a file read), bypassing the class's own __init__."""
        handle = cls.__new__(cls)
        Handle.__init__(handle, create)
        return handle

    @property
    def closed(self) -> bool:
        """True once close() ran (or the ``with`` block ended)."""
        return self._raw is None

    def close(self) -> None:
        """Frees the C object now.  Closing twice is harmless."""
        self._raw = None
        self._address = 0
        self._finalizer()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    @property
    def _as_parameter_(self):
        # ctypes passes this for a Handle argument: NULL once closed.
        return self._raw

    def __reduce__(self):
        raise TypeError(f"{type(self).__name__} objects cannot be pickled: {self._no_pickle}")

    _no_pickle = "they hold a C object"

    def _closed_error(self, where: str) -> OctoproxError:
        """The error of a call on this closed handle."""
        return invalid(f"the {self._noun} is closed", where)


def closed_among(values):
    """The first closed Handle among values, or None (a handle whose
    creation failed has no _raw and is not closed)."""
    return next((v for v in values
                 if isinstance(v, Handle) and getattr(v, "_raw", False) is None), None)


def named(error: OctoproxError, where: str, arguments) -> OctoproxError:
    """``error`` as raised by the Python method ``where``: a closed handle
    among ``arguments`` (the library saw NULL) is named as such."""
    handle = closed_among(arguments) if error.status == ERROR_INVALID_ARGUMENT else None
    if handle is not None:
        return handle._closed_error(where)
    error.where = where
    return error


def api(where: str):
    """Decorator of a public method: its errors name ``where`` (e.g.
    "Octree.insert_points"; the outermost method called wins) and a closed
    handle among its arguments is reported as closed."""
    def decorate(function):
        if "." in where:  # a mixin's method: Python's own errors name the class users see
            function.__qualname__ = where

        @functools.wraps(function)
        def method(*args, **keywords):
            try:
                return function(*args, **keywords)
            except OctoproxError as error:
                raise named(error, where, args + tuple(keywords.values())) from None
        return method
    return decorate


def failure(status: int, where: str, *arguments) -> OctoproxError:
    """The error of a status returned by a function called without
    errcheck (the query methods' fast path), named as ``api`` names it."""
    message = lib.opx_last_error().decode("utf-8", "replace")
    return named(error_for(status, message), where, arguments)
