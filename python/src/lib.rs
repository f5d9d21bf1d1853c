//! `demcontact._native`: the Python extension module of demcontact (PyO3 + rust-numpy).
//!
//! Every function here calls the library's C exports (`demcontact::ffi::dc_*`, linked
//! statically from the core crate) on Rust values: one implementation, the same validation,
//! status codes and results bit for bit as a C host. What this crate adds is only marshalling:
//! numpy broadcasting and dtype rules (args.rs, vectorize.rs), Python objects for the C structs
//! (force.rs, powerlaw.rs), exceptions for statuses (error.rs). The Python half of the package
//! (demcontact/*.py) adds the enums, the exception classes and the named tuples.

mod args;
mod builtin;
mod contact;
mod error;
mod force;
mod functions;
mod plan;
mod powerlaw;
mod vectorize;

use demcontact::ffi as c;
use pyo3::prelude::*;
use pyo3::types::PyDict;

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    use functions::*;
    let py = m.py();
    for f in [
        wrap_pyfunction!(alpha_from_e, m)?,
        wrap_pyfunction!(e_from_alpha, m)?,
        wrap_pyfunction!(elastic_plastic_restitution, m)?,
        wrap_pyfunction!(elastic_plastic_yield_speed, m)?,
        wrap_pyfunction!(hertz_stiffness, m)?,
        wrap_pyfunction!(effective_modulus, m)?,
        wrap_pyfunction!(omega0, m)?,
        wrap_pyfunction!(max_overlap, m)?,
        wrap_pyfunction!(time_of_max_overlap, m)?,
        wrap_pyfunction!(contact_duration, m)?,
        wrap_pyfunction!(contact_duration_level, m)?,
        wrap_pyfunction!(energy_partition, m)?,
        wrap_pyfunction!(dt_crit, m)?,
        wrap_pyfunction!(dt_linearised, m)?,
        wrap_pyfunction!(dt_static, m)?,
        wrap_pyfunction!(dt_for_accuracy, m)?,
        wrap_pyfunction!(viscoelastic_e, m)?,
        wrap_pyfunction!(viscoelastic_e_series, m)?,
        wrap_pyfunction!(viscoelastic_e_reference, m)?,
        wrap_pyfunction!(viscoelastic_b, m)?,
        wrap_pyfunction!(viscoelastic_e_of_speed, m)?,
        wrap_pyfunction!(viscoelastic_k_gamma, m)?,
        wrap_pyfunction!(viscoelastic_b_from_e, m)?,
        wrap_pyfunction!(viscoelastic_beta_from_e, m)?,
        wrap_pyfunction!(viscoelastic_a_from_e, m)?,
        wrap_pyfunction!(viscoelastic_speed_for_e, m)?,
        wrap_pyfunction!(status_str, m)?,
        wrap_pyfunction!(status_known, m)?,
        wrap_pyfunction!(version, m)?,
        wrap_pyfunction!(force::pair_powerlaw, m)?,
        wrap_pyfunction!(force::pair_powerlaw_alpha, m)?,
        wrap_pyfunction!(force::pair_linear, m)?,
        wrap_pyfunction!(force::pair_hertz, m)?,
        wrap_pyfunction!(force::pair_viscoelastic, m)?,
        wrap_pyfunction!(force::normal_force, m)?,
        wrap_pyfunction!(force::normal_force_checked, m)?,
        wrap_pyfunction!(force::normal_force_batch, m)?,
        wrap_pyfunction!(force::normal_force_3d, m)?,
        wrap_pyfunction!(powerlaw::duration_plan_init, m)?,
        wrap_pyfunction!(powerlaw::contact_duration_planned, m)?,
        wrap_pyfunction!(powerlaw::contact_trajectory, m)?,
        wrap_pyfunction!(builtin::builtin_value_for_e, m)?,
        wrap_pyfunction!(builtin::builtin_realised_e, m)?,
        wrap_pyfunction!(builtin::builtin_for_lammps_release, m)?,
        wrap_pyfunction!(builtin::builtin_yade_viscel_cn, m)?,
        wrap_pyfunction!(builtin::fit_restitution, m)?,
    ] {
        m.add_function(f)?;
    }
    m.add_class::<force::Pair>()?;
    contact::register(m)?;
    plan::register(m)?;
    m.add_class::<powerlaw::DurationPlan>()?;

    // Constants straight from the core, so the Python enums cannot drift from the C header.
    m.add("END_OVERLAP", c::status::DC_END_OVERLAP)?;
    m.add("END_FORCE", c::status::DC_END_FORCE)?;
    m.add("LEVEL_MIN", c::powerlaw::DC_LEVEL_MIN)?;
    m.add("LEVEL_MAX", c::powerlaw::DC_LEVEL_MAX)?;
    m.add("MODEL_POWERLAW", c::force::DC_MODEL_POWERLAW)?;
    m.add("MODEL_HERTZ", c::force::DC_MODEL_HERTZ)?;
    m.add("MODEL_VISCOELASTIC", c::force::DC_MODEL_VISCOELASTIC)?;
    let builtins = PyDict::new(py);
    use c::builtin::*;
    for (name, code) in [
        ("LIGGGHTS_HOOKE", DC_BUILTIN_LIGGGHTS_HOOKE),
        ("LIGGGHTS_HERTZ", DC_BUILTIN_LIGGGHTS_HERTZ),
        (
            "LAMMPS_COEFF_RESTITUTION",
            DC_BUILTIN_LAMMPS_COEFF_RESTITUTION,
        ),
        ("LAMMPS_TSUJI_HERTZ", DC_BUILTIN_LAMMPS_TSUJI_HERTZ),
        ("LAMMPS_TSUJI_HOOKE", DC_BUILTIN_LAMMPS_TSUJI_HOOKE),
        ("YADE_VISCEL_EN", DC_BUILTIN_YADE_VISCEL_EN),
        ("YADE_MINDLIN_EN", DC_BUILTIN_YADE_MINDLIN_EN),
        ("YADE_MINDLIN_BETAN", DC_BUILTIN_YADE_MINDLIN_BETAN),
        (
            "LAMMPS_TSUJI_HERTZ_SQRT2",
            DC_BUILTIN_LAMMPS_TSUJI_HERTZ_SQRT2,
        ),
        (
            "LAMMPS_TSUJI_HOOKE_SQRT2",
            DC_BUILTIN_LAMMPS_TSUJI_HOOKE_SQRT2,
        ),
    ] {
        builtins.set_item(name, code)?;
    }
    m.add("BUILTIN_CODES", builtins)?;
    m.add("FIT_MODEL_CONSTANT", c::fit::DC_FIT_MODEL_CONSTANT)?;
    m.add("FIT_MODEL_VISCOELASTIC", c::fit::DC_FIT_MODEL_VISCOELASTIC)?;
    // Every status, from the library's own table (no hand-kept list).
    let statuses = PyDict::new(py);
    for st in c::status::dc_status::all() {
        let name = format!("{st:?}");
        statuses.set_item(name.trim_start_matches("DC_"), st.code())?;
    }
    m.add("STATUS_CODES", statuses)?;
    Ok(())
}
