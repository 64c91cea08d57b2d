"""The base of Octree, LinkSet and Query: owns one C handle, frees it on
close(), at the end of a ``with`` block, or (safety net) when collected."""
import ctypes
import weakref

from ._library import lib


class Handle:
    _destroy = None  # the name of the opx_x_destroy function

    def __init__(self, create):
        """``create(out)`` calls an opx_x_create-like function on out."""
        raw = ctypes.c_void_p()
        create(ctypes.byref(raw))
        self._raw = raw
        self._finalizer = weakref.finalize(self, getattr(lib, self._destroy), raw)

    @property
    def closed(self):
        return not self._finalizer.alive

    def close(self):
        """Frees the C object now.  Using it afterwards raises
        InvalidArgumentError (a ValueError): the library is handed NULL."""
        self._finalizer()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    @property
    def _as_parameter_(self):
        # ctypes passes this for a Handle argument: NULL once closed, which
        # the library rejects with a message naming the argument.
        return self._raw if self._finalizer.alive else None
