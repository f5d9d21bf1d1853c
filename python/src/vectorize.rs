//! Ufunc-like application of a scalar C export over broadcast arguments.
//!
//! The arguments broadcast with numpy's rules; the result has the broadcast shape (a Python
//! float when every argument is a scalar or a 0-d array). The loop runs with the GIL released. The first element whose status is not DC_OK stops the loop and raises the
//! `DemcontactError` subclass for that status, naming the element and its inputs; no partial
//! result is ever returned. Arrays are read in place when C-contiguous and of the broadcast
//! shape; a strided or partially broadcast input is first copied once by numpy.

use ndarray::{ArrayD, IxDyn};
use numpy::{IntoPyArray, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyFloat;

use crate::args::{Arg, arg};
use crate::error::{status_error, value_error};

/// The broadcast shape of `shapes` (numpy's rules), or None if they do not broadcast.
pub fn broadcast_shape(shapes: &[&[usize]]) -> Option<Vec<usize>> {
    let ndim = shapes.iter().map(|s| s.len()).max().unwrap_or(0);
    let mut out = vec![1usize; ndim];
    for s in shapes {
        let offset = ndim - s.len();
        for (i, &d) in s.iter().enumerate() {
            let o = out.get_mut(offset + i)?;
            if *o == 1 {
                *o = d;
            } else if d != 1 && d != *o {
                return None;
            }
        }
    }
    Some(out)
}

/// Multi-index of flat position `i` in a C-ordered array of `shape`.
pub fn unravel(mut i: usize, shape: &[usize]) -> Vec<usize> {
    let mut idx = vec![0; shape.len()];
    for (slot, &d) in idx.iter_mut().zip(shape).rev() {
        if d > 0 {
            *slot = i % d;
            i /= d;
        }
    }
    idx
}

fn describe(names: &[&str], x: &[f64]) -> String {
    names
        .iter()
        .zip(x)
        .map(|(n, v)| format!("{n}={v:?}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// How long one element takes: cheap calls keep the GIL for scalar arguments (releasing it
/// costs more than the call); expensive ones release it always.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Cost {
    Cheap,
    Expensive,
}

/// Applies `f` elementwise. `names`/`objs` are the numeric arguments in order.
pub fn vectorize<'py, const K: usize, const M: usize, F>(
    py: Python<'py>,
    function: &'static str,
    names: [&str; K],
    objs: [&Bound<'py, PyAny>; K],
    cost: Cost,
    f: F,
) -> PyResult<[Bound<'py, PyAny>; M]>
where
    F: Fn([f64; K]) -> Result<[f64; M], i32> + Sync,
{
    let mut args: Vec<Arg<'py>> = Vec::with_capacity(K);
    for (name, obj) in names.iter().zip(objs) {
        args.push(arg(function, name, obj)?);
    }
    let mut scalars = [f64::NAN; K];
    let mut all_scalar = true;
    for (s, a) in scalars.iter_mut().zip(&args) {
        match a {
            Arg::Scalar(x) => *s = *x,
            Arg::Array(_) => all_scalar = false,
        }
    }
    if all_scalar {
        let result = if cost == Cost::Expensive {
            py.detach(|| f(scalars))
        } else {
            f(scalars)
        };
        return match result {
            Ok(y) => Ok(y.map(|v| PyFloat::new(py, v).into_any())),
            Err(code) => Err(status_error(
                py,
                code,
                function,
                &format!("with {}", describe(&names, &scalars)),
            )),
        };
    }

    let shapes: Vec<&[usize]> = args.iter().map(Arg::shape).collect();
    let Some(shape) = broadcast_shape(&shapes) else {
        let shown: Vec<String> = names
            .iter()
            .zip(&shapes)
            .map(|(n, s)| format!("{n}: {s:?}"))
            .collect();
        return Err(value_error(
            function,
            &format!(
                "arguments could not be broadcast together ({})",
                shown.join(", ")
            ),
        ));
    };
    let dim = IxDyn(&shape);
    let n: usize = shape.iter().product();
    // Each input as a constant (a scalar, or an array of one element), a slice (a C-contiguous
    // array of the full shape: read in place), or else one contiguous copy of its broadcast made
    // by numpy (strided views and partial broadcasts), so the loop only ever reads slices.
    let np = py.import("numpy")?;
    let mut copies: Vec<Option<PyReadonlyArrayDyn<'py, f64>>> = Vec::with_capacity(K);
    for a in &args {
        let copy = match a {
            Arg::Array(ro)
                if ro.len() > 1 && !(ro.shape() == shape.as_slice() && ro.is_c_contiguous()) =>
            {
                let b = np
                    .getattr("broadcast_to")?
                    .call1((ro.as_any(), shape.clone()))?;
                let c = np.getattr("ascontiguousarray")?.call1((b,))?;
                Some(c.cast_into::<PyArrayDyn<f64>>()?.readonly())
            }
            _ => None,
        };
        copies.push(copy);
    }
    let mut src: Vec<Src<'_>> = Vec::with_capacity(K);
    for ((a, s), c) in args.iter().zip(&scalars).zip(&copies) {
        src.push(match (a, c) {
            (Arg::Scalar(_), _) => Src::Const(*s),
            (Arg::Array(_), Some(c)) => Src::Slice(
                c.as_slice()
                    .map_err(|e| value_error(function, &e.to_string()))?,
            ),
            (Arg::Array(ro), None) if ro.len() == 1 => {
                Src::Const(ro.as_array().iter().next().copied().unwrap_or(f64::NAN))
            }
            (Arg::Array(ro), None) => Src::Slice(
                ro.as_slice()
                    .map_err(|e| value_error(function, &e.to_string()))?,
            ),
        });
    }
    let run = || -> Result<[Vec<f64>; M], (usize, i32, [f64; K])> {
        let mut outs: [Vec<f64>; M] = std::array::from_fn(|_| Vec::with_capacity(n));
        for i in 0..n {
            let mut x = [f64::NAN; K];
            for (xk, s) in x.iter_mut().zip(&src) {
                *xk = match s {
                    Src::Const(c) => *c,
                    Src::Slice(sl) => sl.get(i).copied().unwrap_or(f64::NAN),
                };
            }
            match f(x) {
                Ok(y) => {
                    for (o, v) in outs.iter_mut().zip(y) {
                        o.push(v);
                    }
                }
                Err(code) => return Err((i, code, x)),
            }
        }
        Ok(outs)
    };
    match py.detach(run) {
        Ok(outs) => {
            let mut result = Vec::with_capacity(M);
            for o in outs {
                if shape.is_empty() {
                    let v = o.first().copied().unwrap_or(f64::NAN);
                    result.push(PyFloat::new(py, v).into_any());
                } else {
                    let a = ArrayD::from_shape_vec(dim.clone(), o)
                        .map_err(|e| value_error(function, &e.to_string()))?;
                    result.push(a.into_pyarray(py).into_any());
                }
            }
            result
                .try_into()
                .map_err(|_| value_error(function, "internal output count mismatch"))
        }
        Err((i, code, x)) => Err(status_error(
            py,
            code,
            function,
            &format!(
                "at index {:?} with {}",
                unravel(i, &shape),
                describe(&names, &x)
            ),
        )),
    }
}

/// A broadcast input in a form the loop reads cheaply.
enum Src<'a> {
    Const(f64),
    Slice(&'a [f64]),
}

/// One C call with one double output: DC_OK gives the value, any other status the code.
#[inline]
pub fn out1(f: impl FnOnce(*mut f64) -> i32) -> Result<f64, i32> {
    let mut x = f64::NAN;
    match f(&mut x) {
        demcontact::ffi::status::DC_OK => Ok(x),
        s => Err(s),
    }
}

/// `out1` for vectorize's one-output form.
#[inline]
pub fn one(f: impl FnOnce(*mut f64) -> i32) -> Result<[f64; 1], i32> {
    out1(f).map(|x| [x])
}
