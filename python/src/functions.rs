//! The scalar C exports as ufunc-like Python functions (names without `dc_`).
//!
//! Each wrapper converts and broadcasts its numeric arguments (see vectorize.rs), reads integer
//! codes (criterion, level) as scalars, and calls the C export itself (`demcontact::ffi::dc_*`,
//! linked statically from the core crate): the same validation, the same status codes and the
//! same results bit for bit as a C host gets. Nothing is computed here.

use demcontact::ffi as c;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use crate::args::code;
use crate::vectorize::{Cost, one, out1, vectorize};

/// Defines a one-output ufunc: numeric args broadcast, trailing integer-code args, then the C
/// export's output pointer.
macro_rules! ufunc {
    ($(#[$m:meta])* $name:ident, $cost:ident, ($($a:ident),+), ($($i:ident),*), $cfn:path) => {
        $(#[$m])*
        #[pyfunction]
        #[allow(non_snake_case)]
        #[pyo3(signature = ($($a),+ $(, $i)*))]
        pub fn $name<'py>(
            py: Python<'py>,
            $($a: &Bound<'py, PyAny>,)+
            $($i: &Bound<'py, PyAny>,)*
        ) -> PyResult<Bound<'py, PyAny>> {
            const F: &str = stringify!($name);
            $(let $i = code(F, stringify!($i), $i)?;)*
            let [r] = vectorize(py, F, [$(stringify!($a)),+], [$($a),+], Cost::$cost,
                |[$($a),+]| one(|o| {
                    // SAFETY: `o` points to a live local double; every other argument is a value.
                    unsafe { $cfn($($a,)+ $($i,)* o) }
                }))?;
            Ok(r)
        }
    };
}

// ---- calibration ----------------------------------------------------------------------------

ufunc!(
    /// Damping coefficient alpha that makes a power-law Tsuji contact
    /// m d'' + alpha sqrt(m k) d^((p-1)/2) d' + k d^p = 0 rebound with restitution e.
    ///
    /// Exact for every p >= 1, independent of impact speed, mass and stiffness.
    /// criterion: Criterion.OVERLAP (contact ends when the overlap returns to 0; closed form) or
    /// Criterion.FORCE (ends when the total force first reaches 0: solvers that clamp attractive
    /// forces, e.g. LIGGGHTS limitForce, LAMMPS limit_damping, YADE).
    /// e in (0, 1], p >= 1. Broadcasts over e and p like a numpy ufunc.
    /// Raises RestitutionRangeError, ExponentRangeError, NotFiniteError, CriterionError,
    /// ResultRangeError (C: dc_alpha_from_e).
    alpha_from_e, Cheap, (e, p), (criterion), c::calibration::dc_alpha_from_e
);

ufunc!(
    /// Restitution e realised by a power-law Tsuji contact with damping coefficient alpha >= 0.
    ///
    /// Criterion.OVERLAP: e = exp(-pi z/sqrt(1-z^2)) for z < 1, 0 for z >= 1 (no rebound),
    /// z = alpha/sqrt(2(p+1)). Criterion.FORCE: e = exp(-2 z acos(z)/sqrt(1-z^2)), continued as
    /// acosh above critical damping. Broadcasts over alpha and p (C: dc_e_from_alpha).
    e_from_alpha, Cheap, (alpha, p), (criterion), c::calibration::dc_e_from_alpha
);

ufunc!(
    /// Restitution of a head-on impact with the elastic-plastic normal law
    /// (Normal.ELASTIC_PLASTIC; Thornton 1997) from x = v/v_y: 1 for x <= 1, else Thornton's
    /// closed form (exact for the law). x >= 0, finite. Broadcasts over x
    /// (C: dc_elastic_plastic_restitution).
    elastic_plastic_restitution, Cheap, (x), (), c::calibration::dc_elastic_plastic_restitution
);

ufunc!(
    /// Yield speed v_y [m/s] of the elastic-plastic normal law: 1/2 m* v_y^2 =
    /// (8/15) E* sqrt(R*) d_y^(5/2), d_y = (pi p_y/(2 E*))^2 R*. All finite > 0. Broadcasts
    /// (C: dc_elastic_plastic_yield_speed).
    elastic_plastic_yield_speed, Cheap, (e_star, r_eff, m_eff, p_y), (),
    c::calibration::dc_elastic_plastic_yield_speed
);

// ---- material -------------------------------------------------------------------------------

ufunc!(
    /// Hertz stiffness k = (4/3) E* sqrt(R*) [N m^-3/2] of two elastic spheres,
    /// 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2, R* = R1 R2/(R1 + R2). One radius may be inf (a flat
    /// wall). E > 0 [Pa], nu in (-1, 0.5], R > 0 [m] (C: dc_hertz_stiffness).
    hertz_stiffness, Cheap, (E1, nu1, R1, E2, nu2, R2), (), c::material::dc_hertz_stiffness
);

ufunc!(
    /// Effective modulus E* [Pa]: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 (C: dc_effective_modulus).
    effective_modulus, Cheap, (E1, nu1, E2, nu2), (), c::material::dc_effective_modulus
);

ufunc!(
    /// omega0 = sqrt(k/m) from a stiffness k > 0 [N m^-p] and an effective mass m > 0 [kg]
    /// (C: dc_omega0).
    omega0, Cheap, (k, m), (), c::powerlaw::dc_omega0
);

// ---- observables of one power-law collision -------------------------------------------------

ufunc!(
    /// Maximum overlap [m] of a power-law Tsuji collision, closed form for every p >= 1 and
    /// every alpha >= 0 (under-, critically and overdamped). v0 > 0 [m/s] impact speed,
    /// omega0 = sqrt(k/m) > 0. Precision 1e-12 relative (C: dc_max_overlap).
    max_overlap, Cheap, (p, alpha, v0, omega0), (), c::powerlaw::dc_max_overlap
);

ufunc!(
    /// Time from impact to maximum overlap [s], at the highest accuracy level
    /// (C: dc_time_of_max_overlap).
    time_of_max_overlap, Cheap, (p, alpha, v0, omega0), (), c::powerlaw::dc_time_of_max_overlap
);

ufunc!(
    /// Contact duration tau [s] under `criterion`, at the highest accuracy level.
    ///
    /// Criterion.OVERLAP: closed form (complex Gamma functions); an overdamped contact never
    /// returns to zero overlap and raises NoEventError. Criterion.FORCE: exact quadrature,
    /// finite for every alpha. Precision 1e-12 (closed forms), 1e-10 (quadrature)
    /// (C: dc_contact_duration).
    contact_duration, Cheap, (p, alpha, v0, omega0), (criterion), c::powerlaw::dc_contact_duration
);

ufunc!(
    /// contact_duration with an accuracy knob: level in LEVEL_MIN..LEVEL_MAX (0..4) selects the
    /// Chebyshev order 6, 8, 12, 16, 24; errors per level in docs/powerlaw.md. Raises LevelError
    /// outside (C: dc_contact_duration_level).
    contact_duration_level, Cheap, (p, alpha, v0, omega0), (criterion, level),
    c::powerlaw::dc_contact_duration_level
);

// ---- time steps -----------------------------------------------------------------------------

ufunc!(
    /// The seed's critical time step (4/(p+1)) A (1/omega0) (v0/omega0)^(-(p-1)/(p+1)),
    /// A = ((p+1)/2)^(1/(p+1)); sqrt(2p/(p+1)) times the linearised bound, i.e. less
    /// conservative than it (C: dc_dt_crit).
    dt_crit, Cheap, (p, v0, omega0), (), c::timestep::dc_dt_crit
);

ufunc!(
    /// The linearised step bound 2/omega_lin at the undamped maximum overlap
    /// (2/omega0 for p = 1) (C: dc_dt_linearised).
    dt_linearised, Cheap, (p, v0, omega0), (), c::timestep::dc_dt_linearised
);

ufunc!(
    /// Velocity-Verlet stability limit of a resting contact pressed by a constant load:
    /// (2/omega_eq)(sqrt(1 + z^2) - z); accel = load / effective mass, e.g. g (C: dc_dt_static).
    dt_static, Cheap, (p, alpha, omega0, accel), (), c::timestep::dc_dt_static
);

/// The largest velocity-Verlet time step [s] for which a power-law Tsuji collision realises its
/// restitution e within relative tolerance tol, whatever the phase at which contact starts.
///
/// Simulates the dimensionless collision inside the call (tens of ms; the GIL is released):
/// call it once per material pair at set-up. v0: the largest impact speed expected [m/s];
/// omega0 = sqrt(k/m). Broadcasts over p, e, v0, omega0, tol (C: dc_dt_for_accuracy).
#[pyfunction]
#[pyo3(signature = (p, e, criterion, v0, omega0, tol))]
pub fn dt_for_accuracy<'py>(
    py: Python<'py>,
    p: &Bound<'py, PyAny>,
    e: &Bound<'py, PyAny>,
    criterion: &Bound<'py, PyAny>,
    v0: &Bound<'py, PyAny>,
    omega0: &Bound<'py, PyAny>,
    tol: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "dt_for_accuracy";
    let crit = code(F, "criterion", criterion)?;
    let [r] = vectorize(
        py,
        F,
        ["p", "e", "v0", "omega0", "tol"],
        [p, e, v0, omega0, tol],
        Cost::Expensive,
        |[p, e, v0, w, tol]| {
            one(|o| {
                // SAFETY: `o` points to a live local double.
                unsafe { c::step_accuracy::dc_dt_for_accuracy(p, e, crit, v0, w, tol, o) }
            })
        },
    )?;
    Ok(r)
}

// ---- viscoelastic spheres -------------------------------------------------------------------

ufunc!(
    /// Restitution e(b) of colliding viscoelastic spheres, full-range tier: within 1e-10 for
    /// every b >= 0 (measured 6e-14), ~40-60 ns per element (C: dc_viscoelastic_e).
    viscoelastic_e, Cheap, (b), (criterion), c::viscoelastic::dc_viscoelastic_e
);

ufunc!(
    /// Restitution e(b) from the published series of Schwager & Poschel (2008): good to 1e-6
    /// only for b <= 0.48 (force) / 0.41 (overlap); prefer viscoelastic_e
    /// (C: dc_viscoelastic_e_series).
    viscoelastic_e_series, Cheap, (b), (criterion), c::viscoelastic::dc_viscoelastic_e_series
);

ufunc!(
    /// Restitution e(b) by order-30 Taylor integration of the equation of motion, reference
    /// tier (~30 us for b <= 10, up to 0.8 s at b = 3e3 under OVERLAP; the GIL is released)
    /// (C: dc_viscoelastic_e_reference).
    viscoelastic_e_reference, Expensive, (b), (criterion),
    c::viscoelastic::dc_viscoelastic_e_reference
);

ufunc!(
    /// b = gamma k^(-3/5) v^(1/5) from k = rho/m_eff > 0, gamma = 3 A rho/(2 m_eff) >= 0 and
    /// the impact speed v > 0 (C: dc_viscoelastic_b).
    viscoelastic_b, Cheap, (k, gamma, v), (), c::viscoelastic::dc_viscoelastic_b
);

ufunc!(
    /// Restitution at impact speed v in physical units, e(gamma k^(-3/5) v^(1/5))
    /// (C: dc_viscoelastic_e_of_speed).
    viscoelastic_e_of_speed, Cheap, (k, gamma, v), (criterion),
    c::viscoelastic::dc_viscoelastic_e_of_speed
);

ufunc!(
    /// The b at which the restitution equals e in (0, 1] (inverse of viscoelastic_e)
    /// (C: dc_viscoelastic_b_from_e).
    viscoelastic_b_from_e, Cheap, (e), (criterion), c::viscoelastic::dc_viscoelastic_b_from_e
);

ufunc!(
    /// Calibration: beta = gamma k^(-3/5) such that a collision at v_ref rebounds with e
    /// (C: dc_viscoelastic_beta_from_e).
    viscoelastic_beta_from_e, Cheap, (e, v_ref), (criterion),
    c::viscoelastic::dc_viscoelastic_beta_from_e
);

ufunc!(
    /// Calibration for a material: the dissipative constant A [s] such that a collision at v_ref
    /// rebounds with e, for Hertz constant rho and effective mass m_eff
    /// (C: dc_viscoelastic_a_from_e).
    viscoelastic_a_from_e, Cheap, (e, v_ref, rho, m_eff), (criterion),
    c::viscoelastic::dc_viscoelastic_a_from_e
);

ufunc!(
    /// The impact speed [m/s] at which the restitution equals e, for beta > 0
    /// (C: dc_viscoelastic_speed_for_e).
    viscoelastic_speed_for_e, Cheap, (e, beta), (criterion),
    c::viscoelastic::dc_viscoelastic_speed_for_e
);

/// Stiffness and damping per unit mass (k, gamma) = (rho/m_eff, 3 A rho/(2 m_eff)) from the
/// material law F = rho xi^(3/2) + (3/2) A rho sqrt(xi) xi'. Returns a tuple; broadcasts
/// (C: dc_viscoelastic_k_gamma).
#[pyfunction]
#[pyo3(signature = (rho, a, m_eff))]
pub fn viscoelastic_k_gamma<'py>(
    py: Python<'py>,
    rho: &Bound<'py, PyAny>,
    a: &Bound<'py, PyAny>,
    m_eff: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyTuple>> {
    let [k, g] = vectorize(
        py,
        "viscoelastic_k_gamma",
        ["rho", "a", "m_eff"],
        [rho, a, m_eff],
        Cost::Cheap,
        |[rho, a, m]| {
            let mut k = f64::NAN;
            let g = out1(|go| {
                // SAFETY: both pointers point to live local doubles.
                unsafe { c::viscoelastic::dc_viscoelastic_k_gamma(rho, a, m, &mut k, go) }
            })?;
            Ok([k, g])
        },
    )?;
    PyTuple::new(py, [k, g])
}

// ---- energy ---------------------------------------------------------------------------------

/// Energy partition of a collision as fractions of m v0^2/2 (independent of v0, m and k):
/// EnergyPartition(e, loading, unloading, returned, clamped); loading + unloading + returned +
/// clamped = 1. Broadcasts over p and alpha (C: dc_energy_partition).
#[pyfunction]
#[pyo3(signature = (p, alpha, criterion))]
pub fn energy_partition<'py>(
    py: Python<'py>,
    p: &Bound<'py, PyAny>,
    alpha: &Bound<'py, PyAny>,
    criterion: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "energy_partition";
    let crit = code(F, "criterion", criterion)?;
    let parts = vectorize(
        py,
        F,
        ["p", "alpha"],
        [p, alpha],
        Cost::Cheap,
        |[p, alpha]| {
            let mut en = c::powerlaw::dc_energy::default();
            // SAFETY: `en` is a live local dc_energy.
            match unsafe { c::powerlaw::dc_energy_partition(p, alpha, crit, &mut en) } {
                c::status::DC_OK => Ok([en.e, en.loading, en.unloading, en.returned, en.clamped]),
                s => Err(s),
            }
        },
    )?;
    py.import("demcontact._types")?
        .getattr("EnergyPartition")?
        .call1(PyTuple::new(py, parts)?)
}

// ---- status and version ---------------------------------------------------------------------

/// The library's English message for a status code (C: dc_status_str).
#[pyfunction]
pub fn status_str(status: i64) -> String {
    crate::error::status_message(i32::try_from(status).unwrap_or(i32::MIN))
}

/// True if `status` is DC_OK or one of the documented DC_ERR_* codes (C: dc_status_known).
#[pyfunction]
pub fn status_known(status: i64) -> bool {
    i32::try_from(status).is_ok_and(|s| c::status::dc_status_known(s) == 1)
}

/// The library version, e.g. "0.1.0" (C: dc_version).
#[pyfunction]
pub fn version() -> String {
    let p = c::version::dc_version();
    if p.is_null() {
        return String::new();
    }
    // SAFETY: dc_version returns a static NUL-terminated string.
    unsafe { std::ffi::CStr::from_ptr(p) }
        .to_string_lossy()
        .into_owned()
}
