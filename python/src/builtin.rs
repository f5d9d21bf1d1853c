//! Corrected inputs for simulators' builtin contact models and the fit of measured
//! restitution data: calls of `dc_builtin_*` and `dc_fit_restitution`.

use demcontact::ffi as c;
use demcontact::ffi::fit::dc_fit_result;
use numpy::{PyArray1, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict};

use crate::args::{Arg, arg, code, real};
use crate::error::{status_error, type_error, value_error};
use crate::vectorize::{Cost, one, vectorize};

/// The clamp flag: a bool (or 0/1; other ints reach the library, which rejects them).
fn clamp_flag(function: &str, obj: &Bound<'_, PyAny>) -> PyResult<i32> {
    if obj.is_instance_of::<PyBool>() {
        return Ok(i32::from(obj.extract::<bool>()?));
    }
    code(function, "clamp", obj)
}

/// The value to type into a simulator's builtin model (a Builtin code) so that it realises
/// restitution e in a head-on collision at every impact speed; clamp: whether the code clamps
/// attractive forces (LIGGGHTS limitForce, LAMMPS limit_damping; YADE always: True);
/// wall=True: the particle hits a fixed wall (YADE ViscElMat calibrates with m/2 there; the other
/// builtins give the same value). Broadcasts over e. Raises BuiltinModelError,
/// BuiltinUnreachableError (the builtin's parameter saturates before e)
/// (C: dc_builtin_value_for_e_wall).
#[pyfunction]
#[pyo3(signature = (model, clamp, e, wall=false))]
pub fn builtin_value_for_e<'py>(
    py: Python<'py>,
    model: &Bound<'py, PyAny>,
    clamp: &Bound<'py, PyAny>,
    e: &Bound<'py, PyAny>,
    wall: bool,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "builtin_value_for_e";
    let (m, cl) = (code(F, "model", model)?, clamp_flag(F, clamp)?);
    let w = i32::from(wall);
    let [r] = vectorize(py, F, ["e"], [e], Cost::Cheap, |[e]| {
        one(|o| {
            // SAFETY: `o` points to a live local double.
            unsafe { c::builtin::dc_builtin_value_for_e_wall(m, cl, w, e, o) }
        })
    })?;
    Ok(r)
}

/// The restitution a builtin model realises when `value` is typed (the forward map of
/// builtin_value_for_e, e.g. what an uncorrected input gives); wall as there. Broadcasts over
/// value (C: dc_builtin_realised_e_wall).
#[pyfunction]
#[pyo3(signature = (model, clamp, value, wall=false))]
pub fn builtin_realised_e<'py>(
    py: Python<'py>,
    model: &Bound<'py, PyAny>,
    clamp: &Bound<'py, PyAny>,
    value: &Bound<'py, PyAny>,
    wall: bool,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "builtin_realised_e";
    let (m, cl) = (code(F, "model", model)?, clamp_flag(F, clamp)?);
    let w = i32::from(wall);
    let [r] = vectorize(py, F, ["value"], [value], Cost::Cheap, |[v]| {
        one(|o| {
            // SAFETY: `o` points to a live local double.
            unsafe { c::builtin::dc_builtin_realised_e_wall(m, cl, w, v, o) }
        })
    })?;
    Ok(r)
}

/// The Builtin code of a LAMMPS model as LAMMPS release `release` runs it: `damping tsuji`
/// multiplies Tsuji's eta by sqrt(2) from 2 Sep 2026 on (LAMMPS_TSUJI_HERTZ ->
/// LAMMPS_TSUJI_HERTZ_SQRT2 there). release: "2026-09-02", "20260902", "2Sep2026", "2 Sep 2026"
/// (as `lmp -h` prints it) or the int 20260902. Raises BuiltinVersionError for a release whose
/// formula is not known (after 22 Jul 2025 and before 2 Sep 2026) or that is not a date,
/// BuiltinModelError for a model of another code (C: dc_builtin_for_lammps_release).
#[pyfunction]
pub fn builtin_for_lammps_release(
    py: Python<'_>,
    model: &Bound<'_, PyAny>,
    release: &Bound<'_, PyAny>,
) -> PyResult<i32> {
    const F: &str = "builtin_for_lammps_release";
    let m = code(F, "model", model)?;
    let detail = format!("(release={})", release.repr()?);
    let date = if let Ok(text) = release.extract::<String>() {
        demcontact::builtin::lammps::parse_release(&text)
            .ok_or_else(|| status_error(py, c::status::DC_ERR_BUILTIN_VERSION, F, &detail))?
    } else {
        code(F, "release", release)?
    };
    let mut out = 0i32;
    // SAFETY: `out` is a live local.
    let s = unsafe { c::builtin::dc_builtin_for_lammps_release(m, date, &mut out) };
    if s != c::status::DC_OK {
        return Err(status_error(py, s, F, &detail));
    }
    Ok(out)
}

/// Contact damping cn [N s/m] for YADE `ViscElMat(kn=, cn=)` (linear law, always clamped) that
/// realises restitution e: cn = 2 zeta_F(e) sqrt(m_reduced kn). YADE combines two materials in
/// series: for two equal materials type 2 kn and 2 cn on each. m_reduced: m1 m2/(m1 + m2), the
/// sphere's mass against a wall (C: dc_builtin_yade_viscel_cn).
#[pyfunction]
#[pyo3(signature = (e, kn, m_reduced))]
pub fn builtin_yade_viscel_cn<'py>(
    py: Python<'py>,
    e: &Bound<'py, PyAny>,
    kn: &Bound<'py, PyAny>,
    m_reduced: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "builtin_yade_viscel_cn";
    let [r] = vectorize(
        py,
        F,
        ["e", "kn", "m_reduced"],
        [e, kn, m_reduced],
        Cost::Cheap,
        |[e, k, m]| {
            one(|o| {
                // SAFETY: `o` points to a live local double.
                unsafe { c::builtin::dc_builtin_yade_viscel_cn(e, k, m, o) }
            })
        },
    )?;
    Ok(r)
}

fn vector(function: &str, name: &str, obj: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    match arg(function, name, obj)? {
        Arg::Array(a) if a.ndim() == 1 => Ok(a.as_array().iter().copied().collect()),
        other => Err(value_error(
            function,
            &format!("{name} must be a 1-D array, got shape {:?}", other.shape()),
        )),
    }
}

/// Fits measured restitution e_i at impact speeds v_i (optional uncertainties sigma_i) with the
/// viscoelastic model (one constant beta, b = beta v^(1/5)) and with a constant e by weighted
/// least squares, and says which the data require (the constant when the two differ by at most
/// tol over [v_min, v_max]). robust=True: Huber IRLS. Returns a FitResult (the C struct's
/// fields, model as FitModel) with the residual arrays resid_viscoelastic and resid_constant
/// (C: dc_fit_restitution).
#[pyfunction]
#[pyo3(signature = (v, e, sigma=None, criterion=None, tol=None, robust=false))]
#[allow(clippy::too_many_arguments)]
pub fn fit_restitution<'py>(
    py: Python<'py>,
    v: &Bound<'py, PyAny>,
    e: &Bound<'py, PyAny>,
    sigma: Option<&Bound<'py, PyAny>>,
    criterion: Option<&Bound<'py, PyAny>>,
    tol: Option<&Bound<'py, PyAny>>,
    robust: bool,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "fit_restitution";
    let (Some(criterion), Some(tol)) = (criterion, tol) else {
        return Err(type_error(F, "criterion/tol", "are required"));
    };
    let crit = code(F, "criterion", criterion)?;
    let tol = real(F, "tol", tol)?;
    let vs = vector(F, "v", v)?;
    let es = vector(F, "e", e)?;
    let ss = sigma.map(|s| vector(F, "sigma", s)).transpose()?;
    let n = vs.len();
    if es.len() != n || ss.as_ref().is_some_and(|s| s.len() != n) {
        return Err(value_error(F, "v, e (and sigma) must have the same length"));
    }
    let mut rv = vec![0.0; n];
    let mut rc = vec![0.0; n];
    let mut out = std::mem::MaybeUninit::<dc_fit_result>::uninit();
    let s = py.detach(|| {
        // SAFETY: v, e, sigma hold n doubles; the residual buffers n writable doubles each;
        // `out` is a live local.
        unsafe {
            c::fit::dc_fit_restitution(
                n,
                vs.as_ptr(),
                es.as_ptr(),
                ss.as_ref().map_or(std::ptr::null(), |s| s.as_ptr()),
                crit,
                tol,
                i32::from(robust),
                rv.as_mut_ptr(),
                rc.as_mut_ptr(),
                out.as_mut_ptr(),
            )
        }
    });
    if s != c::status::DC_OK {
        return Err(status_error(
            py,
            s,
            F,
            &format!("with n={n}, criterion={crit}, tol={tol:?}, robust={robust}"),
        ));
    }
    // SAFETY: DC_OK means the result was written.
    let r = unsafe { out.assume_init() };
    let kw = PyDict::new(py);
    for (k, x) in [
        ("beta", r.beta),
        ("beta_se", r.beta_se),
        ("e_const", r.e_const),
        ("e_const_se", r.e_const_se),
        ("chi2_viscoelastic", r.chi2_viscoelastic),
        ("chi2_constant", r.chi2_constant),
        ("max_residual_viscoelastic", r.max_residual_viscoelastic),
        ("max_residual_constant", r.max_residual_constant),
        ("v_min", r.v_min),
        ("v_max", r.v_max),
        ("e_viscoelastic_at_v_min", r.e_viscoelastic_at_v_min),
        ("e_viscoelastic_at_v_max", r.e_viscoelastic_at_v_max),
        ("max_model_deviation", r.max_model_deviation),
    ] {
        kw.set_item(k, x)?;
    }
    let module = py.import("demcontact")?;
    kw.set_item("model", module.getattr("FitModel")?.call1((r.model,))?)?;
    kw.set_item("se_from_scatter", r.se_from_scatter != 0)?;
    kw.set_item("iterations", r.iterations)?;
    kw.set_item("robust", r.robust != 0)?;
    kw.set_item("resid_viscoelastic", PyArray1::from_vec(py, rv))?;
    kw.set_item("resid_constant", PyArray1::from_vec(py, rc))?;
    py.import("demcontact._types")?
        .getattr("FitResult")?
        .call((), Some(&kw))
}
