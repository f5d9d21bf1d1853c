//! Power-law observables that carry state or arrays: the duration plan and the trajectory.

use demcontact::ffi as c;
use demcontact::ffi::powerlaw::dc_duration_plan;
use numpy::PyArray1;
use pyo3::exceptions::PyMemoryError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use crate::args::{code, real};
use crate::error::status_error;
use crate::vectorize::{Cost, one, vectorize};

/// A contact-duration plan for one exponent p and accuracy level (a C `dc_duration_plan`):
/// the p-dependent part of contact_duration_level, built once by duration_plan_init and reused
/// for any alpha, v0, omega0 and criterion. Immutable, shareable between threads.
#[pyclass(frozen, module = "demcontact", name = "DurationPlan")]
pub struct DurationPlan {
    raw: dc_duration_plan,
}

#[pymethods]
impl DurationPlan {
    /// The exponent p of the plan.
    #[getter]
    fn p(&self) -> f64 {
        self.raw.p
    }
    /// The accuracy level of the plan.
    #[getter]
    fn level(&self) -> i32 {
        self.raw.level
    }
    fn __repr__(&self) -> String {
        format!("DurationPlan(p={:?}, level={})", self.raw.p, self.raw.level)
    }
    /// Same as demcontact.contact_duration_planned(self, ...).
    #[pyo3(signature = (alpha, v0, omega0, criterion))]
    fn contact_duration<'py>(
        slf: &Bound<'py, Self>,
        alpha: &Bound<'py, PyAny>,
        v0: &Bound<'py, PyAny>,
        omega0: &Bound<'py, PyAny>,
        criterion: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        planned(slf.get(), alpha, v0, omega0, criterion)
    }
}

/// Builds a duration plan for exponent p >= 1 at accuracy level (LEVEL_MIN..LEVEL_MAX), a few
/// microseconds; pass it to contact_duration_planned (C: dc_duration_plan_init).
#[pyfunction]
#[pyo3(signature = (p, level=None))]
pub fn duration_plan_init(
    py: Python<'_>,
    p: &Bound<'_, PyAny>,
    level: Option<&Bound<'_, PyAny>>,
) -> PyResult<DurationPlan> {
    const F: &str = "duration_plan_init";
    let p = real(F, "p", p)?;
    let level = level.map_or(Ok(c::powerlaw::DC_LEVEL_MAX), |l| code(F, "level", l))?;
    let mut raw = std::mem::MaybeUninit::<dc_duration_plan>::uninit();
    // SAFETY: `raw` is a live local.
    match unsafe { c::powerlaw::dc_duration_plan_init(p, level, raw.as_mut_ptr()) } {
        c::status::DC_OK => Ok(DurationPlan {
            // SAFETY: DC_OK means the whole plan was written.
            raw: unsafe { raw.assume_init() },
        }),
        s => Err(status_error(
            py,
            s,
            F,
            &format!("with p={p:?}, level={level}"),
        )),
    }
}

fn planned<'py>(
    plan: &DurationPlan,
    alpha: &Bound<'py, PyAny>,
    v0: &Bound<'py, PyAny>,
    omega0: &Bound<'py, PyAny>,
    criterion: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "contact_duration_planned";
    let crit = code(F, "criterion", criterion)?;
    let raw = plan.raw;
    let [r] = vectorize(
        alpha.py(),
        F,
        ["alpha", "v0", "omega0"],
        [alpha, v0, omega0],
        Cost::Cheap,
        |[a, v, w]| {
            one(|o| {
                // SAFETY: `raw` is a live local plan, `o` a live local double.
                unsafe { c::powerlaw::dc_contact_duration_planned(&raw, a, v, w, crit, o) }
            })
        },
    )?;
    Ok(r)
}

/// Contact duration tau [s] with a plan from duration_plan_init (its p is the exponent used);
/// agrees with contact_duration to 1e-13 at levels 3 and 4. Broadcasts over alpha, v0, omega0
/// (C: dc_contact_duration_planned).
#[pyfunction]
#[pyo3(signature = (plan, alpha, v0, omega0, criterion))]
pub fn contact_duration_planned<'py>(
    plan: &Bound<'py, DurationPlan>,
    alpha: &Bound<'py, PyAny>,
    v0: &Bound<'py, PyAny>,
    omega0: &Bound<'py, PyAny>,
    criterion: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    planned(plan.get(), alpha, v0, omega0, criterion)
}

/// One collision sampled at n points (uniform in the phase of the linear image, dense near
/// d = 0), from impact to the end event of `criterion`: Trajectory(t [s], delta [m], v [m/s],
/// force [N]) of four float64 arrays of length n >= 2. mass: effective mass > 0 [kg]
/// (k = mass omega0^2). Scalar inputs only (C: dc_contact_trajectory).
#[pyfunction]
#[pyo3(signature = (p, alpha, v0, omega0, mass, criterion, level=None, n=256))]
#[allow(clippy::too_many_arguments)]
pub fn contact_trajectory<'py>(
    py: Python<'py>,
    p: &Bound<'py, PyAny>,
    alpha: &Bound<'py, PyAny>,
    v0: &Bound<'py, PyAny>,
    omega0: &Bound<'py, PyAny>,
    mass: &Bound<'py, PyAny>,
    criterion: &Bound<'py, PyAny>,
    level: Option<&Bound<'py, PyAny>>,
    n: i64,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "contact_trajectory";
    let (p, a) = (real(F, "p", p)?, real(F, "alpha", alpha)?);
    let (v0, w, m) = (
        real(F, "v0", v0)?,
        real(F, "omega0", omega0)?,
        real(F, "mass", mass)?,
    );
    let crit = code(F, "criterion", criterion)?;
    let level = level.map_or(Ok(c::powerlaw::DC_LEVEL_MAX), |l| code(F, "level", l))?;
    let detail = format!(
        "with p={p:?}, alpha={a:?}, v0={v0:?}, omega0={w:?}, mass={m:?}, criterion={crit}, level={level}, n={n}"
    );
    // n < 2 is the library's to reject (DC_ERR_BUFFER_TOO_SHORT); negative n maps to 0.
    let len = usize::try_from(n).unwrap_or(0);
    let mut bufs: [Vec<f64>; 4] = Default::default();
    for b in &mut bufs {
        b.try_reserve_exact(len)
            .map_err(|_| PyMemoryError::new_err(format!("{F}: cannot allocate n={n} samples")))?;
        b.resize(len, 0.0);
    }
    let [t, d, v, f] = &mut bufs;
    let s = py.detach(|| {
        // SAFETY: four distinct buffers of `len` writable doubles each (NULL never passed:
        // an empty Vec's pointer is dangling but non-NULL, and n = len < 2 is rejected before
        // any write).
        unsafe {
            c::powerlaw::dc_contact_trajectory(
                p,
                a,
                v0,
                w,
                m,
                crit,
                level,
                len,
                t.as_mut_ptr(),
                d.as_mut_ptr(),
                v.as_mut_ptr(),
                f.as_mut_ptr(),
                len,
            )
        }
    });
    if s != c::status::DC_OK {
        return Err(status_error(py, s, F, &detail));
    }
    let arrays = bufs.map(|b| PyArray1::from_vec(py, b).into_any());
    py.import("demcontact._types")?
        .getattr("Trajectory")?
        .call1(PyTuple::new(py, arrays)?)
}
