"""Exceptions raised for the library's status codes.

Every exception carries ``status`` (the negative ``opx_status``),
``message`` (the library's text, naming the C function and the argument)
and ``where`` (the Python method called, e.g. "Query.collide"; None for a
direct call of ``octoprox.lib``); ``str(error)`` is ``where: message``.
Where a builtin exception fits, the class also derives from it, so
``except ValueError`` catches invalid arguments and corrupt data,
``except MemoryError`` out-of-memory and ``except OSError`` I/O errors.
"""
from typing import Optional

OK = 0
ERROR_INVALID_ARGUMENT = -1
ERROR_OUT_OF_MEMORY = -2
ERROR_VERSION = -3
ERROR_BUFFER_TOO_SMALL = -4
ERROR_UNSUPPORTED = -5
ERROR_IO = -6
ERROR_CORRUPT = -7
ERROR_INTERNAL = -8


class OctoproxError(Exception):
    """A failed call: ``status`` (the negative opx_status), ``message``
    (what failed, as the library says it) and ``where`` (the Python
    method, or None)."""

    def __init__(self, status: int, message: str, where: Optional[str] = None) -> None:
        """An error of this status, message and (optional) Python method."""
        # Only the message goes to the base classes: OSError would take two
        # arguments as errno and strerror.
        super().__init__(message)
        self.status = status
        self.message = message
        self.where = where

    def __str__(self) -> str:
        return f"{self.where}: {self.message}" if self.where else self.message

    def __reduce__(self):
        return (type(self), (self.status, self.message, self.where))


class InvalidArgumentError(OctoproxError, ValueError):
    """NULL, NaN, out of range, bad stride... (OPX_ERROR_INVALID_ARGUMENT)."""


class OutOfMemoryError(OctoproxError, MemoryError):
    """OPX_ERROR_OUT_OF_MEMORY."""


class VersionError(OctoproxError):
    """A struct_size the library does not know, or an incompatible library."""


class BufferTooSmallError(OctoproxError):
    """OPX_ERROR_BUFFER_TOO_SMALL (the bindings size their buffers, so this
    only reaches callers on a bug)."""


class UnsupportedError(OctoproxError, NotImplementedError):
    """A valid request the library does not handle (OPX_ERROR_UNSUPPORTED)."""


class IoError(OctoproxError, OSError):
    """A file could not be read or written (OPX_ERROR_IO)."""


class CorruptDataError(OctoproxError, ValueError):
    """Malformed or truncated input data (OPX_ERROR_CORRUPT)."""


class InternalError(OctoproxError, RuntimeError):
    """A bug in the library (OPX_ERROR_INTERNAL): please report it."""


_BY_STATUS = {
    ERROR_INVALID_ARGUMENT: InvalidArgumentError,
    ERROR_OUT_OF_MEMORY: OutOfMemoryError,
    ERROR_VERSION: VersionError,
    ERROR_BUFFER_TOO_SMALL: BufferTooSmallError,
    ERROR_UNSUPPORTED: UnsupportedError,
    ERROR_IO: IoError,
    ERROR_CORRUPT: CorruptDataError,
    ERROR_INTERNAL: InternalError,
}


def error_for(status: int, message: str, where: Optional[str] = None) -> OctoproxError:
    """The exception for a status code (OctoproxError for unknown codes)."""
    return _BY_STATUS.get(status, OctoproxError)(status, message, where)


def invalid(message: str, where: Optional[str] = None) -> OctoproxError:
    """An InvalidArgumentError raised by the bindings themselves."""
    return InvalidArgumentError(ERROR_INVALID_ARGUMENT, message, where)
