//! Errors: the C status code, its [`ErrorKind`], and the library's
//! message, which names the function and the argument that failed.
//!
//! ```
//! use octoprox::{ErrorKind, Octree, OctreeOptions};
//!
//! let error = Octree::load_file("/nonexistent/map.bt", &OctreeOptions::default()).unwrap_err();
//! assert_eq!(error.kind(), ErrorKind::Io);
//! assert!(error.message().contains("/nonexistent/map.bt"));
//! assert_eq!(error.status(), ErrorKind::Io.status());
//! ```
use crate::sys;
use std::ffi::{CStr, CString};
use std::fmt;
use std::os::raw::c_char;

/// A failed call: its [`ErrorKind`] (the C `opx_status`) and the message
/// naming the function and the argument, e.g.
/// `opx_octree_create: options->resolution nan is not finite`.  Errors the
/// bindings find before calling the library name the Rust function.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error {
    status: i32,
    message: String,
}

/// `std::result::Result` with this crate's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;

/// What went wrong: one variant per `OPX_ERROR_*` status of the C API.
/// The codes are never renumbered; a later library may add kinds, so
/// matches need a wildcard arm.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A NULL, NaN, out-of-range value, bad stride, unknown name or index
    /// (`OPX_ERROR_INVALID_ARGUMENT`).
    InvalidArgument,
    /// Memory ran out (`OPX_ERROR_OUT_OF_MEMORY`); the objects are unchanged.
    OutOfMemory,
    /// An unknown struct version, or a library these bindings do not serve
    /// ([`crate::check_version`]) (`OPX_ERROR_VERSION`).
    Version,
    /// A buffer was smaller than the data (`OPX_ERROR_BUFFER_TOO_SMALL`);
    /// the bindings size their buffers, so this is rare here.
    BufferTooSmall,
    /// A valid request the library does not handle, such as an unknown file
    /// extension or a URDF `<capsule>` (`OPX_ERROR_UNSUPPORTED`).
    Unsupported,
    /// A file could not be read or written (`OPX_ERROR_IO`).
    Io,
    /// Malformed or truncated input data: a map, URDF, SRDF or point cloud
    /// file (`OPX_ERROR_CORRUPT`).
    Corrupt,
    /// A defect of the library (`OPX_ERROR_INTERNAL`); a status code
    /// these bindings do not know is reported as this kind too, its code
    /// kept by [`Error::status`].
    Internal,
}

const KINDS: [(ErrorKind, i32); 8] = [
    (ErrorKind::InvalidArgument, sys::OPX_ERROR_INVALID_ARGUMENT),
    (ErrorKind::OutOfMemory, sys::OPX_ERROR_OUT_OF_MEMORY),
    (ErrorKind::Version, sys::OPX_ERROR_VERSION),
    (ErrorKind::BufferTooSmall, sys::OPX_ERROR_BUFFER_TOO_SMALL),
    (ErrorKind::Unsupported, sys::OPX_ERROR_UNSUPPORTED),
    (ErrorKind::Io, sys::OPX_ERROR_IO),
    (ErrorKind::Corrupt, sys::OPX_ERROR_CORRUPT),
    (ErrorKind::Internal, sys::OPX_ERROR_INTERNAL),
];

impl ErrorKind {
    /// The kind of a C status code; `None` for `OPX_OK` and codes these
    /// bindings do not know.
    pub fn from_status(status: i32) -> Option<ErrorKind> {
        KINDS.iter().find(|(_, code)| *code == status).map(|(kind, _)| *kind)
    }

    /// The C status code (negative), e.g. -6 for [`ErrorKind::Io`].
    pub fn status(self) -> i32 {
        KINDS.iter().find(|(kind, _)| *kind == self).map_or(sys::OPX_ERROR_INTERNAL, |(_, code)| *code)
    }

    /// The C name of the status, e.g. "OPX_ERROR_IO".
    pub fn name(self) -> String {
        status_name(self.status())
    }
}

impl Error {
    pub(crate) fn new(status: i32, message: String) -> Error {
        Error { status, message }
    }

    pub(crate) fn of_kind(kind: ErrorKind, message: String) -> Error {
        Error::new(kind.status(), message)
    }

    /// An invalid-argument error raised by the bindings themselves (before
    /// calling the library), in the library's message style.
    pub(crate) fn invalid(message: String) -> Error {
        Error::of_kind(ErrorKind::InvalidArgument, message)
    }

    /// What went wrong.
    pub fn kind(&self) -> ErrorKind {
        ErrorKind::from_status(self.status).unwrap_or(ErrorKind::Internal)
    }

    /// The C `opx_status` code (negative), as the library returned it.
    pub fn status(&self) -> i32 {
        self.status
    }

    /// The message, e.g. `opx_octree_load_file: path '/x.bt' cannot be read`.
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} ({})", self.message, status_name(self.status))
    }
}

impl std::error::Error for Error {}

/// The C name of a status code, e.g. "OPX_ERROR_IO" for -6;
/// "OPX_UNKNOWN_STATUS" for a code the library does not know.
pub fn status_name(status: i32) -> String {
    // SAFETY: opx_status_name returns a static string for any code.
    unsafe { c_string(sys::opx_status_name(status)) }
}

/// Ok for OPX_OK, else the error with this thread's last message.
pub(crate) fn check(status: sys::opx_status) -> Result<()> {
    if status == sys::OPX_OK {
        return Ok(());
    }
    // SAFETY: opx_last_error never returns NULL; the message is copied
    // before any other call on this thread can change it.
    let message = unsafe { c_string(sys::opx_last_error()) };
    Err(Error::new(status, message))
}

/// Copies a NUL-terminated C string.
///
/// # Safety
/// `text` must be NULL or point to a NUL-terminated string.
pub(crate) unsafe fn c_string(text: *const c_char) -> String {
    if text.is_null() {
        return String::new();
    }
    CStr::from_ptr(text).to_string_lossy().into_owned()
}

/// A C copy of `text`; an interior NUL is an invalid argument of `what`.
pub(crate) fn to_c_string(text: &str, what: &str) -> Result<CString> {
    CString::new(text).map_err(|_| Error::invalid(format!("{}: contains a NUL byte", what)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_status_has_its_kind_and_name() {
        for (kind, status) in KINDS {
            assert_eq!(ErrorKind::from_status(status), Some(kind));
            assert_eq!(kind.status(), status);
            assert_eq!(kind.name(), status_name(status));
            assert!(kind.name().starts_with("OPX_ERROR_"), "{}", kind.name());
        }
        assert_eq!(ErrorKind::from_status(sys::OPX_OK), None);
        assert_eq!(Error::new(-99, String::new()).kind(), ErrorKind::Internal);
    }
}
