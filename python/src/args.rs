//! Python arguments to doubles: scalars, numpy arrays of any layout, and array-likes.
//!
//! Rules (the same for every function, documented in python/README.md):
//! * Python `float`/`int` (and numpy float64 scalars, a `float` subclass) are scalars.
//! * float64 arrays are read in place, whatever their strides (no copy).
//! * Other real dtypes (float16/32, longdouble, signed/unsigned integers) are converted to
//!   float64 once (one copy), as numpy ufuncs do.
//! * bool, complex, object, string, datetime dtypes are rejected with `TypeError` naming the
//!   argument: a restitution of `True` or `1+0j` is a bug in the caller, not a number.
//! * Lists, tuples and other array-likes go through `numpy.asarray` first.

use ndarray::IxDyn;
use numpy::{
    PyArrayDescrMethods, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArray,
    PyUntypedArrayMethods,
};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyFloat, PyInt};

use crate::error::{status_error, type_error};

/// One converted argument.
pub enum Arg<'py> {
    /// A Python scalar.
    Scalar(f64),
    /// A float64 array (possibly converted from another real dtype), borrowed read-only.
    Array(PyReadonlyArrayDyn<'py, f64>),
}

impl Arg<'_> {
    pub fn shape(&self) -> &[usize] {
        match self {
            Arg::Scalar(_) => &[],
            Arg::Array(a) => a.shape(),
        }
    }
}

/// One batch input as a contiguous run of doubles of the target shape: the caller's memory when
/// it already is one (zero copy), else one copy of its broadcast.
pub enum Run<'a> {
    Borrowed(&'a [f64]),
    Owned(Vec<f64>),
}

impl Run<'_> {
    pub fn slice(&self) -> &[f64] {
        match self {
            Run::Borrowed(s) => s,
            Run::Owned(v) => v,
        }
    }
}

/// `a` as a run of `shape` (None when it does not broadcast to that shape).
pub fn run<'a>(a: &'a Arg<'_>, shape: &[usize]) -> Option<Run<'a>> {
    let view = match a {
        Arg::Scalar(x) => ndarray::aview0(x).into_dyn(),
        Arg::Array(ro) => ro.as_array(),
    };
    if view.shape() == shape
        && let Some(s) = view.to_slice()
    {
        return Some(Run::Borrowed(s));
    }
    let b = view.broadcast(IxDyn(shape))?;
    Some(Run::Owned(b.iter().copied().collect()))
}

/// A shape as Python prints it: (6,), (6, 3).
pub fn shape_str(s: &[usize]) -> String {
    match s {
        [n] => format!("({n},)"),
        _ => format!(
            "({})",
            s.iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// Converts a numeric argument (scalar or array-like).
pub fn arg<'py>(function: &str, name: &str, obj: &Bound<'py, PyAny>) -> PyResult<Arg<'py>> {
    if obj.is_instance_of::<PyBool>() {
        return Err(type_error(
            function,
            name,
            "is a bool; expected a real number or array",
        ));
    }
    if obj.is_instance_of::<PyFloat>() || obj.is_instance_of::<PyInt>() {
        return Ok(Arg::Scalar(obj.extract::<f64>()?));
    }
    let py = obj.py();
    let array = if obj.is_instance_of::<PyUntypedArray>() {
        obj.clone()
    } else {
        py.import("numpy")?.getattr("asarray")?.call1((obj,))?
    };
    let untyped = array.cast::<PyUntypedArray>()?;
    let dtype = untyped.dtype();
    match dtype.kind() {
        b'f' | b'i' | b'u' => {}
        _ => {
            let shown = dtype.str().map(|s| s.to_string()).unwrap_or_default();
            return Err(type_error(
                function,
                name,
                &format!("has dtype {shown}; expected real numbers (float or integer dtype)"),
            ));
        }
    }
    let f64_array = if dtype.is_equiv_to(&numpy::dtype::<f64>(py)) {
        array
    } else {
        // One conversion copy (integers, float32, non-native byte order, ...).
        array.call_method1("astype", ("float64",))?
    };
    let typed = f64_array.cast::<PyArrayDyn<f64>>()?;
    if typed.ndim() == 0 {
        // A 0-d array (or numpy scalar of another dtype) is a scalar, as for ufuncs.
        let ro = typed.try_readonly().map_err(|_| {
            status_error(
                py,
                demcontact::ffi::status::DC_ERR_BUFFER_LAYOUT,
                function,
                &format!("(argument '{name}' is being written elsewhere)"),
            )
        })?;
        return Ok(Arg::Scalar(
            ro.as_array().iter().next().copied().unwrap_or(f64::NAN),
        ));
    }
    match typed.try_readonly() {
        Ok(ro) => Ok(Arg::Array(ro)),
        // Another thread holds this array writable (e.g. as the `out` of a running batch call).
        Err(_) => Err(status_error(
            py,
            demcontact::ffi::status::DC_ERR_BUFFER_LAYOUT,
            function,
            &format!("(argument '{name}' is being written elsewhere)"),
        )),
    }
}

/// Converts an argument that must be one real number (pair parameters, trajectory inputs).
pub fn real(function: &str, name: &str, obj: &Bound<'_, PyAny>) -> PyResult<f64> {
    match arg(function, name, obj)? {
        Arg::Scalar(x) => Ok(x),
        Arg::Array(a) if a.ndim() == 0 => {
            Ok(a.as_array().iter().next().copied().unwrap_or(f64::NAN))
        }
        Arg::Array(a) => Err(type_error(
            function,
            name,
            &format!(
                "must be a single number, got an array of shape {:?}",
                a.shape()
            ),
        )),
    }
}

/// An integer code (criterion, level, count): Python ints, IntEnum members, numpy integers.
/// Values outside i32 are mapped to i32::MIN so that the core reports them as invalid codes.
pub fn code(function: &str, name: &str, obj: &Bound<'_, PyAny>) -> PyResult<i32> {
    if obj.is_instance_of::<PyBool>() {
        return Err(type_error(
            function,
            name,
            "is a bool; expected an integer code",
        ));
    }
    match obj.extract::<i64>() {
        Ok(v) => Ok(i32::try_from(v).unwrap_or(i32::MIN)),
        Err(_) => Err(type_error(
            function,
            name,
            &format!(
                "must be an integer code (e.g. demcontact.Criterion.FORCE), got {}",
                obj.get_type()
                    .name()
                    .map(|n| n.to_string())
                    .unwrap_or_default()
            ),
        )),
    }
}
