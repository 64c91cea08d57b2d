//! Errors: the C status code and the library's message, which names the
//! function and the argument that failed.
use crate::sys;
use std::ffi::{CStr, CString};
use std::fmt;
use std::os::raw::c_char;

/// A failed call: `status` is one of the `OPX_ERROR_*` codes (see
/// [`crate::consts`]), `message` names the function and the argument.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error {
    status: i32,
    message: String,
}

pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    pub(crate) fn new(status: i32, message: String) -> Error {
        Error { status, message }
    }

    /// An invalid-argument error raised by the bindings themselves (before
    /// calling the library), in the library's message style.
    pub(crate) fn invalid(message: String) -> Error {
        Error::new(sys::OPX_ERROR_INVALID_ARGUMENT, message)
    }

    /// The `opx_status` code (negative).
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

/// The name of a status code, e.g. "OPX_ERROR_IO".
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
