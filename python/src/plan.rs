//! The scene planner for Python: `plan(...)` is `dc_plan_input_init`, the members given by
//! keyword, then `dc_plan`; the result is a dict with the fields (names and meanings) of
//! `demcontact plan --json` (docs/plan.md). Every number comes from the export; this file only
//! marshals the input, names the member a refusal is about, and turns codes into names.

use demcontact::ffi as c;
use demcontact::ffi::plan::{dc_plan, dc_plan_input, dc_plan_input_init, dc_plan_result};
use demcontact::plan::{Binding, PairKind, StepBinding};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict};

use crate::args::{code, real};
use crate::error::status_error;

/// The dc_plan_input members by DC_PLAN_FIELD_* code (index = code; 0 = no single member), with
/// their documented ranges (docs/plan.md) for the error message.
const FIELDS: [(&str, &str); 24] = [
    ("", ""),
    ("youngs", "must be > 0"),
    ("poisson", "must be in (-1, 0.5]"),
    ("density", "must be > 0"),
    ("restitution", "must be in (0, 1]"),
    ("radius_min", "must be > 0"),
    ("radius_max", "must be > 0 and >= radius_min"),
    ("v_max", "must be > 0"),
    ("depth", "must be >= 0"),
    ("gravity", "must be >= 0"),
    ("pressure", "must be >= 0"),
    ("solid_fraction", "must be in (0, 1)"),
    ("coordination", "must be > 0"),
    ("load_factor", "must be >= 1"),
    ("friction", "must be >= 0"),
    ("rolling_friction", "must be >= 0"),
    ("overlap_tol", "must be in (0, 1)"),
    ("e_tol", "must be in (0, 1)"),
    ("static_tol", "must be > 0 (math.inf: no bound)"),
    ("duration_tol", "must be > 0 (math.inf: no bound)"),
    ("criterion", "Criterion.FORCE or Criterion.OVERLAP"),
    ("stability_fraction", "must be in (0, 1]"),
    ("conventional_divisor", "must be >= 1"),
    ("walls", "True or False"),
];

fn binding_name(code: i32) -> &'static str {
    [Binding::Overlap, Binding::Static, Binding::Duration]
        .into_iter()
        .find(|b| *b as i32 == code)
        .map_or("unknown", Binding::name)
}

fn step_binding_name(code: i32) -> &'static str {
    [StepBinding::Restitution, StepBinding::Stability]
        .into_iter()
        .find(|b| *b as i32 == code)
        .map_or("unknown", StepBinding::name)
}

fn pair_name(code: i32) -> &'static str {
    PairKind::ALL
        .into_iter()
        .find(|k| *k as i32 == code)
        .map_or("unknown", PairKind::name)
}

/// The softest Young's modulus and the largest velocity-Verlet step that meet a scene's
/// tolerances, and what every contact then realises (C: dc_plan; docs/plan.md). Keyword-only
/// arguments named as the members of dc_plan_input (SI units): required youngs, poisson,
/// density, restitution, radius_min, radius_max, v_max, depth, overlap_tol, e_tol; optional
/// gravity (9.81), pressure (0), solid_fraction (0.6), coordination (6), load_factor (1),
/// friction (0), rolling_friction (0), static_tol (math.inf: no bound; the CLI's default is
/// overlap_tol), duration_tol (math.inf), criterion (Criterion.FORCE), walls (True),
/// stability_fraction (0.5), conventional_divisor (50) (the defaults of dc_plan_input_init).
///
/// Returns a dict with the fields of `demcontact plan --json` (without "command"): youngs_soft,
/// softening, binding ("overlap-tol", ...), dt, binding_dt, dt_restitution, dt_stability (inf
/// without static load, where the JSON has null), ..., e_plain_mean, tolerances, mu, mu_r,
/// criterion ("force"/"overlap"), walls. Raises PlanRangeError, NotPositiveError, ... or
/// PlanInfeasibleError (the real material itself misses the tolerance) naming the member at
/// fault in the message and in the exception's `field` attribute (None when no single member
/// is).
#[pyfunction]
#[pyo3(signature = (
    *, youngs, poisson, density, restitution, radius_min, radius_max, v_max, depth, overlap_tol,
    e_tol, gravity=None, pressure=None, solid_fraction=None, coordination=None, load_factor=None,
    friction=None, rolling_friction=None, static_tol=None, duration_tol=None, criterion=None,
    walls=None, stability_fraction=None, conventional_divisor=None
))]
#[allow(clippy::too_many_arguments)]
pub fn plan<'py>(
    py: Python<'py>,
    youngs: &Bound<'py, PyAny>,
    poisson: &Bound<'py, PyAny>,
    density: &Bound<'py, PyAny>,
    restitution: &Bound<'py, PyAny>,
    radius_min: &Bound<'py, PyAny>,
    radius_max: &Bound<'py, PyAny>,
    v_max: &Bound<'py, PyAny>,
    depth: &Bound<'py, PyAny>,
    overlap_tol: &Bound<'py, PyAny>,
    e_tol: &Bound<'py, PyAny>,
    gravity: Option<&Bound<'py, PyAny>>,
    pressure: Option<&Bound<'py, PyAny>>,
    solid_fraction: Option<&Bound<'py, PyAny>>,
    coordination: Option<&Bound<'py, PyAny>>,
    load_factor: Option<&Bound<'py, PyAny>>,
    friction: Option<&Bound<'py, PyAny>>,
    rolling_friction: Option<&Bound<'py, PyAny>>,
    static_tol: Option<&Bound<'py, PyAny>>,
    duration_tol: Option<&Bound<'py, PyAny>>,
    criterion: Option<&Bound<'py, PyAny>>,
    walls: Option<&Bound<'py, PyAny>>,
    stability_fraction: Option<&Bound<'py, PyAny>>,
    conventional_divisor: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    const F: &str = "plan";
    let mut i = std::mem::MaybeUninit::<dc_plan_input>::uninit();
    // SAFETY: live local; dc_plan_input_init writes the whole struct on DC_OK, the only status
    // it returns for a non-NULL pointer (checked).
    let mut i = unsafe {
        if dc_plan_input_init(i.as_mut_ptr()) != c::status::DC_OK {
            return Err(status_error(py, c::status::DC_ERR_INTERNAL, F, ""));
        }
        i.assume_init()
    };
    for (slot, name, obj) in [
        (&mut i.youngs, "youngs", youngs),
        (&mut i.poisson, "poisson", poisson),
        (&mut i.density, "density", density),
        (&mut i.restitution, "restitution", restitution),
        (&mut i.radius_min, "radius_min", radius_min),
        (&mut i.radius_max, "radius_max", radius_max),
        (&mut i.v_max, "v_max", v_max),
        (&mut i.depth, "depth", depth),
        (&mut i.overlap_tol, "overlap_tol", overlap_tol),
        (&mut i.e_tol, "e_tol", e_tol),
    ] {
        *slot = real(F, name, obj)?;
    }
    for (slot, name, obj) in [
        (&mut i.gravity, "gravity", gravity),
        (&mut i.pressure, "pressure", pressure),
        (&mut i.solid_fraction, "solid_fraction", solid_fraction),
        (&mut i.coordination, "coordination", coordination),
        (&mut i.load_factor, "load_factor", load_factor),
        (&mut i.friction, "friction", friction),
        (
            &mut i.rolling_friction,
            "rolling_friction",
            rolling_friction,
        ),
        (&mut i.static_tol, "static_tol", static_tol),
        (&mut i.duration_tol, "duration_tol", duration_tol),
        (
            &mut i.stability_fraction,
            "stability_fraction",
            stability_fraction,
        ),
        (
            &mut i.conventional_divisor,
            "conventional_divisor",
            conventional_divisor,
        ),
    ] {
        if let Some(o) = obj.filter(|o| !o.is_none()) {
            *slot = real(F, name, o)?;
        }
    }
    if let Some(o) = criterion.filter(|o| !o.is_none()) {
        i.criterion = code(F, "criterion", o)?;
    }
    if let Some(o) = walls.filter(|o| !o.is_none()) {
        i.walls = if let Ok(b) = o.cast::<PyBool>() {
            i32::from(b.is_true())
        } else {
            code(F, "walls", o)?
        };
    }
    let mut out = dc_plan_result::default();
    let mut field = c::plan::DC_PLAN_FIELD_NONE;
    // The planner's cost (up to ~0.2 s) runs without the GIL: plain locals only.
    let (s, out, field) = py.detach(move || {
        // SAFETY: live locals of the documented types.
        let s = unsafe { dc_plan(&i, &mut out, &mut field) };
        (s, out, field)
    });
    if s != c::status::DC_OK {
        let (name, range) = usize::try_from(field)
            .ok()
            .and_then(|k| FIELDS.get(k).copied())
            .unwrap_or(("", ""));
        let detail = match name {
            "" => String::new(),
            "criterion" => format!("(field criterion = {}: {range})", i.criterion),
            "walls" => format!("(field walls = {}: {range})", i.walls),
            _ => {
                let value = input_value(&i, name);
                if s == c::status::DC_ERR_PLAN_INFEASIBLE {
                    format!(
                        "(field {name} = {value:?}: the real material (youngs = {:?}) misses it)",
                        i.youngs
                    )
                } else {
                    format!("(field {name} = {value:?}: {range})")
                }
            }
        };
        let err = status_error(py, s, F, &detail);
        let field_obj = if name.is_empty() {
            py.None().into_bound(py)
        } else {
            name.into_pyobject(py)?.into_any()
        };
        err.value(py).setattr("field", field_obj)?;
        return Err(err);
    }
    let crit = if i.criterion == c::status::DC_END_OVERLAP {
        "overlap"
    } else {
        "force"
    };
    let d = PyDict::new(py);
    d.set_item("criterion", crit)?;
    d.set_item("walls", i.walls == 1)?;
    d.set_item("youngs_real", i.youngs)?;
    d.set_item("youngs_soft", out.youngs_soft)?;
    d.set_item("softening", out.softening)?;
    d.set_item("binding", binding_name(out.binding))?;
    d.set_item("dt", out.dt)?;
    d.set_item("binding_dt", step_binding_name(out.binding_dt))?;
    for (name, v) in [
        ("dt_restitution", out.dt_restitution),
        ("dt_stability", out.dt_stability),
        ("dt_conventional", out.dt_conventional),
        ("speedup", out.speedup),
        ("alpha", out.alpha),
        ("max_overlap_ratio", out.max_overlap_ratio),
    ] {
        d.set_item(name, v)?;
    }
    d.set_item("max_overlap_pair", pair_name(out.max_overlap_pair))?;
    d.set_item("max_overlap_ratio_real", out.max_overlap_ratio_real)?;
    d.set_item("static_overlap_ratio", out.static_overlap_ratio)?;
    d.set_item("static_pair", pair_name(out.static_pair))?;
    for (name, v) in [
        ("static_overlap_ratio_real", out.static_overlap_ratio_real),
        ("stress", out.stress),
        ("static_force", out.static_force),
        ("duration", out.duration),
        ("duration_real", out.duration_real),
        ("duration_change", out.duration_change),
        ("t_hertz", out.t_hertz),
        ("dt_over_t_hertz", out.dt_over_t_hertz),
        ("steps_per_contact", out.steps_per_contact),
        ("e_target", i.restitution),
        ("e_plain_at_dt", out.e_plain_at_dt),
        ("e_plain_min", out.e_plain_min),
        ("e_plain_max", out.e_plain_max),
        ("e_plain_mean", out.e_plain_mean),
    ] {
        d.set_item(name, v)?;
    }
    let tol = PyDict::new(py);
    tol.set_item("overlap_tol", i.overlap_tol)?;
    tol.set_item("e_tol", i.e_tol)?;
    tol.set_item("static_tol", i.static_tol)?;
    tol.set_item("duration_tol", i.duration_tol)?;
    d.set_item("tolerances", tol)?;
    d.set_item("mu", i.friction)?;
    d.set_item("mu_r", i.rolling_friction)?;
    Ok(d)
}

/// The value of a real member of `i` by name (NaN for a name that is not one).
fn input_value(i: &dc_plan_input, name: &str) -> f64 {
    match name {
        "youngs" => i.youngs,
        "poisson" => i.poisson,
        "density" => i.density,
        "restitution" => i.restitution,
        "radius_min" => i.radius_min,
        "radius_max" => i.radius_max,
        "v_max" => i.v_max,
        "depth" => i.depth,
        "gravity" => i.gravity,
        "pressure" => i.pressure,
        "solid_fraction" => i.solid_fraction,
        "coordination" => i.coordination,
        "load_factor" => i.load_factor,
        "friction" => i.friction,
        "rolling_friction" => i.rolling_friction,
        "overlap_tol" => i.overlap_tol,
        "e_tol" => i.e_tol,
        "static_tol" => i.static_tol,
        "duration_tol" => i.duration_tol,
        "stability_fraction" => i.stability_fraction,
        "conventional_divisor" => i.conventional_divisor,
        _ => f64::NAN,
    }
}

/// Registers plan and its constants in `demcontact._native`.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(plan, m)?)?;
    m.add("PLAN_INPUT_VERSION", c::plan::DC_PLAN_INPUT_VERSION)?;
    Ok(())
}
