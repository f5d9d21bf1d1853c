//! Force kernels: `Pair` objects (a `dc_pair` made by a C constructor), the checked ufunc-like
//! force, the zero-copy batch with the GIL released, and the two-sphere 3D helper.

use demcontact::ffi as c;
use demcontact::ffi::force::dc_pair;
use ndarray::IxDyn;
use numpy::{PyArray1, PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;

use crate::args::{Arg, Run, arg, code, real, run};
use crate::error::{status_error, type_error, value_error};
use crate::vectorize::{Cost, broadcast_shape, one, unravel, vectorize};

/// A calibrated normal-contact model for one material pair (a C `dc_pair`).
///
/// Made by pair_powerlaw, pair_powerlaw_alpha, pair_linear, pair_hertz or pair_viscoelastic
/// (never directly); immutable, shareable between threads. Attributes mirror the C struct
/// (model, kernel, criterion, clamp, p, stiffness, alpha, damping_a, e, k, c, h); `reads`
/// names the per-contact inputs its kernel reads besides the overlap.
#[pyclass(frozen, module = "demcontact", name = "Pair")]
pub struct Pair {
    pub raw: dc_pair,
    reads: [bool; 3],
}

/// The block [start, start + len) of an optional run.
fn block<'a>(r: &'a Option<Run<'_>>, start: usize, len: usize) -> Option<&'a [f64]> {
    r.as_ref().and_then(|r| r.slice().get(start..start + len))
}

/// True if every d, f, v is finite and every r, m (when given) finite and > 0: x * 0 is NaN
/// exactly for NaN and +-inf, and the flags are or-ed without branches so the loop vectorises.
fn screen(d: &[f64], f: &[f64], v: &[f64], r: Option<&[f64]>, m: Option<&[f64]>) -> bool {
    let n = d.len();
    if f.len() != n
        || v.len() != n
        || r.is_some_and(|r| r.len() != n)
        || m.is_some_and(|m| m.len() != n)
    {
        return false;
    }
    let (rs, need_r) = (r.unwrap_or(d), r.is_some());
    let (ms, need_m) = (m.unwrap_or(d), m.is_some());
    let mut bad = false;
    for ((((&d, &f), &v), &r), &m) in d.iter().zip(f).zip(v).zip(rs).zip(ms) {
        let s = d * 0.0 + f * 0.0 + v * 0.0 + r * 0.0 + m * 0.0;
        bad |= (s != 0.0) | (need_r & !(r > 0.0)) | (need_m & !(m > 0.0));
    }
    !bad
}

/// Contacts per block of the checked batch (5 arrays x 32 KiB: stays in L2).
const BLOCK: usize = 4096;

const INPUTS: [&str; 3] = ["vn", "r_eff", "m_eff"];

impl Pair {
    pub(crate) fn new(raw: dc_pair) -> Self {
        // Which of vn, r_eff, m_eff the kernel reads, asked of the library itself: the checked
        // force reports a NaN input as DC_ERR_NOT_FINITE only if the kernel reads it.
        let probe = |i: usize| {
            let mut x = [1.0, 1.0, 1.0];
            if let Some(slot) = x.get_mut(i) {
                *slot = f64::NAN;
            }
            let mut f = 0.0;
            // SAFETY: `raw` and `f` are live locals.
            let s =
                unsafe { c::force::dc_normal_force_checked(&raw, 1e-3, x[0], x[1], x[2], &mut f) };
            s == c::status::DC_ERR_NOT_FINITE
        };
        Pair {
            raw,
            reads: [probe(0), probe(1), probe(2)],
        }
    }

    fn model_name(&self) -> &'static str {
        match self.raw.model {
            c::force::DC_MODEL_POWERLAW => "powerlaw",
            c::force::DC_MODEL_HERTZ => "hertz",
            c::force::DC_MODEL_VISCOELASTIC => "viscoelastic",
            _ => "unknown",
        }
    }
}

fn enum_member<'py>(py: Python<'py>, class: &str, value: i32) -> PyResult<Bound<'py, PyAny>> {
    py.import("demcontact")?.getattr(class)?.call1((value,))
}

#[pymethods]
impl Pair {
    /// Model family: Model.POWERLAW (incl. linear), Model.HERTZ or Model.VISCOELASTIC.
    #[getter]
    fn model<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        enum_member(py, "Model", self.raw.model)
    }
    /// Internal kernel code chosen at construction (one of 17 monomorphised kernels).
    #[getter]
    fn kernel(&self) -> i32 {
        self.raw.kernel
    }
    /// End criterion the pair was calibrated for (also decides clamping).
    #[getter]
    fn criterion<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        enum_member(py, "Criterion", self.raw.criterion)
    }
    /// True if attractive forces are clamped to zero (Criterion.FORCE pairs).
    #[getter]
    fn clamp(&self) -> bool {
        self.raw.clamp != 0
    }
    /// Force-law exponent p.
    #[getter]
    fn p(&self) -> f64 {
        self.raw.p
    }
    /// Stiffness k [N m^-p] (power law) or E* [Pa] (Hertz, viscoelastic), as given.
    #[getter]
    fn stiffness(&self) -> f64 {
        self.raw.stiffness
    }
    /// Damping coefficient alpha (power law, Hertz).
    #[getter]
    fn alpha(&self) -> f64 {
        self.raw.alpha
    }
    /// Viscoelastic damping constant A [s].
    #[getter]
    fn damping_a(&self) -> f64 {
        self.raw.damping_a
    }
    /// Target restitution e (speed independent for power-law and Hertz pairs).
    #[getter]
    fn e(&self) -> f64 {
        self.raw.e
    }
    /// Kernel constant k (read by the force functions).
    #[getter]
    fn k(&self) -> f64 {
        self.raw.k
    }
    /// Kernel constant c (read by the force functions).
    #[getter]
    fn c(&self) -> f64 {
        self.raw.c
    }
    /// Kernel constant h (read by the force functions).
    #[getter]
    fn h(&self) -> f64 {
        self.raw.h
    }
    /// Names of the per-contact inputs the kernel reads besides the overlap.
    #[getter]
    fn reads(&self) -> Vec<&'static str> {
        INPUTS
            .iter()
            .zip(self.reads)
            .filter_map(|(n, r)| r.then_some(*n))
            .collect()
    }

    fn __repr__(&self) -> String {
        format!(
            "Pair(model={}, criterion={}, p={:?}, stiffness={:?}, e={:?}, alpha={:?}, damping_a={:?}, clamp={})",
            self.model_name(),
            if self.raw.criterion == c::status::DC_END_FORCE {
                "FORCE"
            } else {
                "OVERLAP"
            },
            self.raw.p,
            self.raw.stiffness,
            self.raw.e,
            self.raw.alpha,
            self.raw.damping_a,
            self.raw.clamp != 0
        )
    }

    /// Same as demcontact.normal_force(self, ...).
    #[pyo3(signature = (overlap, vn=None, r_eff=None, m_eff=None))]
    fn normal_force<'py>(
        slf: &Bound<'py, Self>,
        overlap: &Bound<'py, PyAny>,
        vn: Option<&Bound<'py, PyAny>>,
        r_eff: Option<&Bound<'py, PyAny>>,
        m_eff: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        checked_force(slf.get(), "normal_force", overlap, vn, r_eff, m_eff)
    }

    /// Same as demcontact.normal_force_batch(self, ...).
    #[pyo3(signature = (overlap, vn=None, r_eff=None, m_eff=None, *, out=None, check=true, fast=false))]
    #[allow(clippy::too_many_arguments)]
    fn normal_force_batch<'py>(
        slf: &Bound<'py, Self>,
        overlap: &Bound<'py, PyAny>,
        vn: Option<&Bound<'py, PyAny>>,
        r_eff: Option<&Bound<'py, PyAny>>,
        m_eff: Option<&Bound<'py, PyAny>>,
        out: Option<&Bound<'py, PyAny>>,
        check: bool,
        fast: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        batch(slf.get(), overlap, [vn, r_eff, m_eff], out, check, fast)
    }
}

/// What every pair constructor does: reads the real parameters (`params`: name and object) and
/// the criterion, runs the C constructor as `make(values, criterion, out)`, and turns its status
/// into an exception naming every parameter.
fn pair_from<const N: usize>(
    py: Python<'_>,
    function: &str,
    params: [(&str, &Bound<'_, PyAny>); N],
    criterion: &Bound<'_, PyAny>,
    make: impl FnOnce([f64; N], i32, *mut dc_pair) -> i32,
) -> PyResult<Pair> {
    let mut x = [0.0; N];
    for (slot, (name, obj)) in x.iter_mut().zip(params) {
        *slot = real(function, name, obj)?;
    }
    let crit = code(function, "criterion", criterion)?;
    let mut raw = std::mem::MaybeUninit::<dc_pair>::uninit();
    match make(x, crit, raw.as_mut_ptr()) {
        c::status::DC_OK => {
            // SAFETY: DC_OK means the constructor wrote the whole struct.
            Ok(Pair::new(unsafe { raw.assume_init() }))
        }
        s => {
            let given: Vec<String> = params
                .iter()
                .zip(x)
                .map(|((name, _), v)| format!("{name}={v:?}"))
                .collect();
            let detail = format!("with {}, criterion={crit}", given.join(", "));
            Err(status_error(py, s, function, &detail))
        }
    }
}

/// Power-law Tsuji pair F = k d^p + alpha sqrt(m_eff k) d^((p-1)/2) vn with alpha calibrated so
/// that every collision rebounds with e under `criterion` (Criterion.FORCE also clamps
/// attractive forces). p >= 1, k > 0 [N m^-p], e in (0, 1] (C: dc_pair_powerlaw).
#[pyfunction]
#[pyo3(signature = (p, k, e, criterion))]
pub fn pair_powerlaw(
    py: Python<'_>,
    p: &Bound<'_, PyAny>,
    k: &Bound<'_, PyAny>,
    e: &Bound<'_, PyAny>,
    criterion: &Bound<'_, PyAny>,
) -> PyResult<Pair> {
    let params = [("p", p), ("k", k), ("e", e)];
    pair_from(
        py,
        "pair_powerlaw",
        params,
        criterion,
        |[p, k, e], crit, o| {
            // SAFETY: `o` points to a live local dc_pair.
            unsafe { c::force::dc_pair_powerlaw(p, k, e, crit, o) }
        },
    )
}

/// Power-law Tsuji pair from its damping coefficient alpha >= 0 directly; its `e` is the
/// restitution alpha realises under `criterion` (C: dc_pair_powerlaw_alpha).
#[pyfunction]
#[pyo3(signature = (p, k, alpha, criterion))]
pub fn pair_powerlaw_alpha(
    py: Python<'_>,
    p: &Bound<'_, PyAny>,
    k: &Bound<'_, PyAny>,
    alpha: &Bound<'_, PyAny>,
    criterion: &Bound<'_, PyAny>,
) -> PyResult<Pair> {
    let params = [("p", p), ("k", k), ("alpha", alpha)];
    pair_from(
        py,
        "pair_powerlaw_alpha",
        params,
        criterion,
        |[p, k, a], crit, o| {
            // SAFETY: `o` points to a live local dc_pair.
            unsafe { c::force::dc_pair_powerlaw_alpha(p, k, a, crit, o) }
        },
    )
}

/// Linear spring-dashpot pair F = k d + alpha sqrt(m_eff k) vn (the power law with p = 1),
/// alpha exact for e under `criterion` (C: dc_pair_linear).
#[pyfunction]
#[pyo3(signature = (k, e, criterion))]
pub fn pair_linear(
    py: Python<'_>,
    k: &Bound<'_, PyAny>,
    e: &Bound<'_, PyAny>,
    criterion: &Bound<'_, PyAny>,
) -> PyResult<Pair> {
    pair_from(
        py,
        "pair_linear",
        [("k", k), ("e", e)],
        criterion,
        |[k, e], crit, o| {
            // SAFETY: `o` points to a live local dc_pair.
            unsafe { c::force::dc_pair_linear(k, e, crit, o) }
        },
    )
}

/// Hertz pair of two materials: F = k d^(3/2) + alpha sqrt(m_eff k) d^(1/4) vn with
/// k = (4/3) E* sqrt(r_eff) per contact and alpha exact for p = 3/2. E > 0 [Pa],
/// nu in (-1, 0.5], e in (0, 1] (C: dc_pair_hertz).
#[pyfunction]
#[pyo3(signature = (E1, nu1, E2, nu2, e, criterion))]
#[allow(non_snake_case)]
#[allow(clippy::too_many_arguments)]
pub fn pair_hertz(
    py: Python<'_>,
    E1: &Bound<'_, PyAny>,
    nu1: &Bound<'_, PyAny>,
    E2: &Bound<'_, PyAny>,
    nu2: &Bound<'_, PyAny>,
    e: &Bound<'_, PyAny>,
    criterion: &Bound<'_, PyAny>,
) -> PyResult<Pair> {
    let params = [("E1", E1), ("nu1", nu1), ("E2", E2), ("nu2", nu2), ("e", e)];
    pair_from(
        py,
        "pair_hertz",
        params,
        criterion,
        |[e1, n1, e2, n2, e], crit, o| {
            // SAFETY: `o` points to a live local dc_pair.
            unsafe { c::force::dc_pair_hertz(e1, n1, e2, n2, e, crit, o) }
        },
    )
}

/// Viscoelastic Hertz pair (Brilliantov et al.): F = rho d^(3/2) + (3/2) A rho sqrt(d) vn,
/// rho = (4/3) E* sqrt(r_eff); the damping constant A >= 0 [s] is given directly, so e depends
/// on the impact speed (see viscoelastic_a_from_e) (C: dc_pair_viscoelastic).
#[pyfunction]
#[pyo3(signature = (E1, nu1, E2, nu2, A, criterion))]
#[allow(non_snake_case)]
#[allow(clippy::too_many_arguments)]
pub fn pair_viscoelastic(
    py: Python<'_>,
    E1: &Bound<'_, PyAny>,
    nu1: &Bound<'_, PyAny>,
    E2: &Bound<'_, PyAny>,
    nu2: &Bound<'_, PyAny>,
    A: &Bound<'_, PyAny>,
    criterion: &Bound<'_, PyAny>,
) -> PyResult<Pair> {
    let params = [("E1", E1), ("nu1", nu1), ("E2", E2), ("nu2", nu2), ("A", A)];
    pair_from(
        py,
        "pair_viscoelastic",
        params,
        criterion,
        |[e1, n1, e2, n2, a], crit, o| {
            // SAFETY: `o` points to a live local dc_pair.
            unsafe { c::force::dc_pair_viscoelastic(e1, n1, e2, n2, a, crit, o) }
        },
    )
}

fn missing(function: &str, pair: &Pair, name: &str) -> PyErr {
    type_error(
        function,
        name,
        &format!(
            "is required: this {} pair reads {}",
            pair.model_name(),
            pair.reads().join(", ")
        ),
    )
}

fn checked_force<'py>(
    pair: &Pair,
    function: &'static str,
    overlap: &Bound<'py, PyAny>,
    vn: Option<&Bound<'py, PyAny>>,
    r_eff: Option<&Bound<'py, PyAny>>,
    m_eff: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let py = overlap.py();
    // Inputs the kernel does not read may be omitted; they are then NaN, which it never sees.
    let nan = pyo3::types::PyFloat::new(py, f64::NAN).into_any();
    let given = [vn, r_eff, m_eff];
    let mut objs: [Bound<'py, PyAny>; 3] = [nan.clone(), nan.clone(), nan];
    for ((slot, g), (name, read)) in objs
        .iter_mut()
        .zip(given)
        .zip(INPUTS.iter().zip(pair.reads))
    {
        match g {
            Some(o) => *slot = o.clone(),
            None if read => return Err(missing(function, pair, name)),
            None => {}
        }
    }
    let raw = pair.raw;
    let [r] = vectorize(
        py,
        function,
        ["overlap", "vn", "r_eff", "m_eff"],
        [overlap, &objs[0], &objs[1], &objs[2]],
        Cost::Cheap,
        |[d, v, r, m]| {
            one(|o| {
                // SAFETY: `raw` is a live local dc_pair, `o` a live local double.
                unsafe { c::force::dc_normal_force_checked(&raw, d, v, r, m, o) }
            })
        },
    )?;
    Ok(r)
}

/// Normal force [N] of contacts of one pair, every input checked (C: dc_normal_force_checked).
///
/// overlap d [m] (> 0 in contact; d <= 0 gives 0), vn = dd/dt [m/s] (positive while
/// compressing), r_eff [m], m_eff [kg]; inputs the pair does not read (see Pair.reads) may be
/// omitted. Broadcasts like a ufunc; raises on the first invalid contact (NotFiniteError,
/// NotPositiveError, ResultRangeError) instead of returning NaN. For millions of contacts use
/// normal_force_batch.
#[pyfunction]
#[pyo3(signature = (pair, overlap, vn=None, r_eff=None, m_eff=None))]
pub fn normal_force<'py>(
    pair: &Bound<'py, Pair>,
    overlap: &Bound<'py, PyAny>,
    vn: Option<&Bound<'py, PyAny>>,
    r_eff: Option<&Bound<'py, PyAny>>,
    m_eff: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    checked_force(pair.get(), "normal_force", overlap, vn, r_eff, m_eff)
}

/// The same function under the C name (Python's normal_force is always checked).
#[pyfunction]
#[pyo3(signature = (pair, overlap, vn=None, r_eff=None, m_eff=None))]
pub fn normal_force_checked<'py>(
    pair: &Bound<'py, Pair>,
    overlap: &Bound<'py, PyAny>,
    vn: Option<&Bound<'py, PyAny>>,
    r_eff: Option<&Bound<'py, PyAny>>,
    m_eff: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    checked_force(
        pair.get(),
        "normal_force_checked",
        overlap,
        vn,
        r_eff,
        m_eff,
    )
}

fn batch<'py>(
    pair: &Pair,
    overlap: &Bound<'py, PyAny>,
    optional: [Option<&Bound<'py, PyAny>>; 3],
    out: Option<&Bound<'py, PyAny>>,
    check: bool,
    fast: bool,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "normal_force_batch";
    // The C batch (both have the same arguments, statuses and array rules).
    let kernel = if fast {
        c::force::dc_normal_force_batch_fast
    } else {
        c::force::dc_normal_force_batch
    };
    let py = overlap.py();
    let d = arg(F, "overlap", overlap)?;
    let mut others: [Option<Arg<'py>>; 3] = [None, None, None];
    for ((slot, g), (name, read)) in others
        .iter_mut()
        .zip(optional)
        .zip(INPUTS.iter().zip(pair.reads))
    {
        match g {
            // Arrays the kernel does not read are not even converted (the C reads them not).
            Some(o) if read => *slot = Some(arg(F, name, o)?),
            Some(_) => {}
            None if read => return Err(missing(F, pair, name)),
            None => {}
        }
    }
    let mut shapes: Vec<&[usize]> = vec![d.shape()];
    shapes.extend(others.iter().flatten().map(Arg::shape));
    let Some(shape) = broadcast_shape(&shapes) else {
        return Err(value_error(
            F,
            &format!("arrays could not be broadcast together: {shapes:?}"),
        ));
    };
    let n: usize = shape.iter().product();
    let bad = || value_error(F, "internal broadcast failure");
    let rd = run(&d, &shape).ok_or_else(bad)?;
    let mut ro: [Option<Run<'_>>; 3] = [None, None, None];
    for (slot, a) in ro.iter_mut().zip(&others) {
        if let Some(a) = a {
            *slot = Some(run(a, &shape).ok_or_else(bad)?);
        }
    }

    // The output: the caller's float64 C-contiguous array of the broadcast shape, or a new one.
    let out_array: Bound<'py, PyArrayDyn<f64>> = match out {
        Some(o) => {
            let Ok(a) = o.cast::<PyArrayDyn<f64>>() else {
                return Err(type_error(F, "out", "must be a float64 numpy array"));
            };
            if a.shape() != shape.as_slice() {
                return Err(value_error(
                    F,
                    &format!(
                        "out has shape {:?}, the inputs broadcast to {:?}",
                        a.shape(),
                        shape
                    ),
                ));
            }
            if !a.is_c_contiguous() {
                return Err(value_error(F, "out must be C-contiguous"));
            }
            a.clone()
        }
        // SAFETY: uninitialised, but every element is written before it is returned; on error
        // the array is dropped unread.
        None => unsafe { PyArrayDyn::<f64>::new(py, IxDyn(&shape), false) },
    };
    if n == 0 {
        return Ok(out_array.into_any());
    }
    let mut rw = match out_array.try_readwrite() {
        Ok(rw) => rw,
        Err(e) => {
            // Not writeable, or overlapping an input array (rust-numpy's borrow tracking),
            // or written by another thread right now.
            return Err(status_error(
                py,
                c::status::DC_ERR_BUFFER_LAYOUT,
                F,
                &format!("(out: {e})"),
            ));
        }
    };
    let out_slice = rw
        .as_slice_mut()
        .map_err(|e| value_error(F, &e.to_string()))?;
    let raw = pair.raw;
    let ptr = |r: &Option<Run<'_>>| r.as_ref().map_or(std::ptr::null(), |r| r.slice().as_ptr());
    let (pd, pv, pr, pm) = (rd.slice(), &ro[0], &ro[1], &ro[2]);
    let reads = pair.reads;
    let outcome = py.detach(|| {
        if !check {
            // SAFETY: every non-NULL input points to n doubles (a run of the broadcast shape),
            // the output to n writable doubles; the pair is a live local.
            let s = unsafe {
                kernel(
                    &raw,
                    n,
                    pd.as_ptr(),
                    ptr(pv),
                    ptr(pr),
                    ptr(pm),
                    out_slice.as_mut_ptr(),
                )
            };
            return if s == c::status::DC_OK {
                Ok(())
            } else {
                Err((s, None))
            };
        }
        // Checked: blocks small enough to stay in cache, each computed by the C batch and then
        // screened; a screened contact is judged by the library's checked kernel (its status is
        // the answer; the screen only has to catch a superset of what that kernel rejects).
        let mut start = 0;
        while start < n {
            let len = BLOCK.min(n - start);
            let sub = |r: &Option<Run<'_>>| {
                r.as_ref()
                    .map_or(std::ptr::null(), |r| r.slice()[start..].as_ptr())
            };
            let out_block = &mut out_slice[start..start + len];
            // SAFETY: as above, for the block [start, start + len) of every array.
            let s = unsafe {
                kernel(
                    &raw,
                    len,
                    pd[start..].as_ptr(),
                    sub(pv),
                    sub(pr),
                    sub(pm),
                    out_block.as_mut_ptr(),
                )
            };
            if s != c::status::DC_OK {
                return Err((s, None));
            }
            // Fast screen over the block (one branch-free pass, in cache): every input the
            // kernel reads finite (r_eff, m_eff also > 0) and every force finite. Only a failing
            // block is examined contact by contact.
            let db = pd.get(start..start + len).unwrap_or(&[]);
            let clean = screen(
                db,
                out_block,
                block(pv, start, len).filter(|_| reads[0]).unwrap_or(db),
                block(pr, start, len).filter(|_| reads[1]),
                block(pm, start, len).filter(|_| reads[2]),
            );
            if !clean {
                let at = |r: &Option<Run<'_>>, i: usize| {
                    r.as_ref()
                        .map_or(1.0, |r| r.slice().get(i).copied().unwrap_or(f64::NAN))
                };
                for (j, f) in out_block.iter().enumerate() {
                    let i = start + j;
                    let d = pd.get(i).copied().unwrap_or(f64::NAN);
                    let (v, r, m) = (at(pv, i), at(pr, i), at(pm, i));
                    let suspicious = !d.is_finite()
                        || (reads[0] && !v.is_finite())
                        || (reads[1] && !(r.is_finite() && r > 0.0))
                        || (reads[2] && !(m.is_finite() && m > 0.0))
                        || !f.is_finite();
                    if suspicious {
                        let mut g = 0.0;
                        // SAFETY: live locals.
                        let s =
                            unsafe { c::force::dc_normal_force_checked(&raw, d, v, r, m, &mut g) };
                        if s != c::status::DC_OK {
                            return Err((s, Some(i)));
                        }
                    }
                }
            }
            start += len;
        }
        Ok(())
    });
    drop(rw);
    match outcome {
        Ok(()) => Ok(out_array.into_any()),
        Err((s, None)) => Err(status_error(py, s, F, "")),
        Err((s, Some(i))) => {
            let at = |r: &Option<Run<'_>>| {
                r.as_ref()
                    .and_then(|r| r.slice().get(i).copied())
                    .unwrap_or(f64::NAN)
            };
            let x = [
                pd.get(i).copied().unwrap_or(f64::NAN),
                at(pv),
                at(pr),
                at(pm),
            ];
            Err(status_error(
                py,
                s,
                F,
                &format!(
                    "at index {:?} with overlap={:?}, vn={:?}, r_eff={:?}, m_eff={:?} (out holds partial results)",
                    unravel(i, &shape),
                    x[0],
                    x[1],
                    x[2],
                    x[3]
                ),
            ))
        }
    }
}

/// Normal forces [N] of many contacts of one pair, zero-copy: the C batch kernel runs directly
/// on the caller's arrays with the GIL released (C: dc_normal_force_batch).
///
/// float64 C-contiguous inputs of the broadcast shape are read in place; any other input
/// (another dtype, strided, or smaller and broadcast) is copied once. `out`, if given, must be
/// a float64 C-contiguous array of the broadcast shape and not overlap an input. The kernel
/// checks no value (that is its speed). check=True (default): every input the pair reads must
/// be finite (r_eff, m_eff > 0) and every force finite, else the status the checked kernel
/// gives for the first such contact is raised with its index (`out` then holds partial
/// results); the one case left to the kernel is a clamped pair whose force terms overflow
/// (> 1e308 N), which gives 0 as in C (normal_force checks that too). check=False is the C
/// batch exactly (NaN or, for clamped pairs, 0 for r_eff <= 0 etc.). An empty input gives an
/// empty result. fast=True runs dc_normal_force_batch_fast instead: general-p and damped Hertz
/// forces within 8 ulp of the terms of the exact ones, several times faster for general p.
#[pyfunction]
#[pyo3(signature = (pair, overlap, vn=None, r_eff=None, m_eff=None, *, out=None, check=true, fast=false))]
#[allow(clippy::too_many_arguments)]
pub fn normal_force_batch<'py>(
    pair: &Bound<'py, Pair>,
    overlap: &Bound<'py, PyAny>,
    vn: Option<&Bound<'py, PyAny>>,
    r_eff: Option<&Bound<'py, PyAny>>,
    m_eff: Option<&Bound<'py, PyAny>>,
    out: Option<&Bound<'py, PyAny>>,
    check: bool,
    fast: bool,
) -> PyResult<Bound<'py, PyAny>> {
    batch(pair.get(), overlap, [vn, r_eff, m_eff], out, check, fast)
}

fn vec3(function: &str, name: &str, obj: &Bound<'_, PyAny>) -> PyResult<[f64; 3]> {
    match arg(function, name, obj)? {
        Arg::Array(a) if a.shape() == [3] => {
            let v = a.as_array();
            let mut out = [0.0; 3];
            for (o, x) in out.iter_mut().zip(v.iter()) {
                *o = *x;
            }
            Ok(out)
        }
        other => Err(value_error(
            function,
            &format!("{name} must be a 3-vector, got shape {:?}", other.shape()),
        )),
    }
}

/// Normal contact force [N] on sphere 1 (a numpy 3-vector) between two spheres from their
/// centres x, velocities v, radii R and masses m; n = (x1 - x2)/|x1 - x2|, overlap
/// R1 + R2 - |x1 - x2|, vn = (v2 - v1).n; not in contact: zeros (C: dc_normal_force_3d).
#[pyfunction]
#[pyo3(signature = (pair, x1, v1, R1, m1, x2, v2, R2, m2))]
#[allow(non_snake_case)]
#[allow(clippy::too_many_arguments)]
pub fn normal_force_3d<'py>(
    pair: &Bound<'py, Pair>,
    x1: &Bound<'py, PyAny>,
    v1: &Bound<'py, PyAny>,
    R1: &Bound<'py, PyAny>,
    m1: &Bound<'py, PyAny>,
    x2: &Bound<'py, PyAny>,
    v2: &Bound<'py, PyAny>,
    R2: &Bound<'py, PyAny>,
    m2: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    const F: &str = "normal_force_3d";
    let py = pair.py();
    let (a1, b1, a2, b2) = (
        vec3(F, "x1", x1)?,
        vec3(F, "v1", v1)?,
        vec3(F, "x2", x2)?,
        vec3(F, "v2", v2)?,
    );
    let (r1, q1, r2, q2) = (
        real(F, "R1", R1)?,
        real(F, "m1", m1)?,
        real(F, "R2", R2)?,
        real(F, "m2", m2)?,
    );
    let raw = pair.get().raw;
    let mut f = [0.0f64; 3];
    // SAFETY: all vectors are live local [f64; 3]; the pair a live local.
    let s = unsafe {
        c::force::dc_normal_force_3d(
            &raw,
            a1.as_ptr(),
            b1.as_ptr(),
            r1,
            q1,
            a2.as_ptr(),
            b2.as_ptr(),
            r2,
            q2,
            f.as_mut_ptr(),
        )
    };
    if s != c::status::DC_OK {
        return Err(status_error(
            py,
            s,
            F,
            &format!(
                "with x1={a1:?}, v1={b1:?}, R1={r1:?}, m1={q1:?}, x2={a2:?}, v2={b2:?}, R2={r2:?}, m2={q2:?}"
            ),
        ));
    }
    Ok(PyArray1::from_slice(py, &f))
}
