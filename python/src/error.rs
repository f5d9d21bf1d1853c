//! Status codes of the C ABI turned into Python exceptions.
//!
//! The exception classes live in `demcontact/_errors.py` (a plain Python hierarchy that `help()`
//! and `except` clauses see naturally); this file only builds the message and asks that module
//! for the instance matching the status code. The error path is the only place that imports it.

use std::ffi::CStr;

use demcontact::ffi::status::dc_status_str;
use pyo3::exceptions::{PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;

/// The library's own English message for a status code (static, from `dc_status_str`).
pub fn status_message(code: i32) -> String {
    let p = dc_status_str(code);
    if p.is_null() {
        return String::from("unknown demcontact status");
    }
    // SAFETY: dc_status_str returns a static NUL-terminated string, never NULL (checked anyway).
    unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned()
}

/// The `DemcontactError` subclass instance for `code`, with `detail` saying where it happened.
pub fn status_error(py: Python<'_>, code: i32, function: &str, detail: &str) -> PyErr {
    let message = status_message(code);
    let made = py
        .import("demcontact._errors")
        .and_then(|m| m.getattr("_from_status"))
        .and_then(|f| f.call1((code, message.as_str(), function, detail)));
    match made {
        Ok(instance) => PyErr::from_value(instance),
        // Only if the package is broken (the extension imported without its Python half).
        Err(_) => PyRuntimeError::new_err(format!(
            "{function}: {message} (status {code}){}",
            if detail.is_empty() {
                String::new()
            } else {
                format!(" {detail}")
            }
        )),
    }
}

/// A wrongly typed argument (never reaches the core, so there is no status code).
pub fn type_error(function: &str, name: &str, what: &str) -> PyErr {
    PyTypeError::new_err(format!("{function}: argument '{name}' {what}"))
}

/// A wrongly shaped argument or output.
pub fn value_error(function: &str, what: &str) -> PyErr {
    PyValueError::new_err(format!("{function}: {what}"))
}
