//! Library version.

use core::ffi::c_char;

const VERSION: &str = concat!(env!("CARGO_PKG_VERSION"), "\0");

/// The library version as a static NUL-terminated string, e.g. "0.1.0"; never NULL, never freed.
#[unsafe(no_mangle)]
pub extern "C" fn dc_version() -> *const c_char {
    VERSION.as_ptr().cast()
}
