//! Full contact (normal, tangential, rolling, twisting) for Python.
//!
//! `ContactSpec` is a `dc_contact_spec` built by keyword (unset fields keep the defaults of
//! `dc_contact_spec_init`), `ContactModel` the `dc_contact_model` of `dc_contact_model_init`,
//! `contact_force` / `contact_force_spheres` one contact (its history updated in place) and
//! `contact_force_batch` n contacts as a structure of arrays, zero-copy over C-contiguous float64
//! arrays, with the GIL released. Every number is computed by the library's exports; this file
//! only marshals arrays and turns statuses into exceptions.

use demcontact::ffi as c;
use demcontact::ffi::contact::{
    dc_contact_batch, dc_contact_energy, dc_contact_force, dc_contact_force_batch,
    dc_contact_force_energy, dc_contact_force_spheres, dc_contact_history_len, dc_contact_model,
    dc_contact_model_init, dc_contact_model_set_carry, dc_contact_model_set_step,
    dc_contact_result, dc_contact_spec, dc_contact_spec_init, dc_contact_state,
};
use numpy::{
    PyArray1, PyArray2, PyArrayDescrMethods, PyArrayDyn, PyArrayMethods, PyReadwriteArrayDyn,
    PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyFloat, PyInt, PyList, PyTuple, PyType};

use crate::args::{Arg, Run, arg, code, real, run, shape_str};
use crate::error::{status_error, type_error, value_error};
use crate::force::Pair;

/// Registers the contact classes, functions and constants in `demcontact._native`.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<ContactSpec>()?;
    m.add_class::<ContactModel>()?;
    m.add_function(wrap_pyfunction!(contact_spec_init, m)?)?;
    m.add_function(wrap_pyfunction!(contact_model_init, m)?)?;
    m.add_function(wrap_pyfunction!(contact_history_len, m)?)?;
    m.add_function(wrap_pyfunction!(contact_force, m)?)?;
    m.add_function(wrap_pyfunction!(contact_force_spheres, m)?)?;
    m.add_function(wrap_pyfunction!(contact_force_batch, m)?)?;
    m.add_function(wrap_pyfunction!(contact_force_energy, m)?)?;
    m.add_function(wrap_pyfunction!(contact_model_set_step, m)?)?;
    m.add(
        "INTEGRATOR_VELOCITY_VERLET",
        c::status::DC_INTEGRATOR_VELOCITY_VERLET,
    )?;
    m.add(
        "INTEGRATOR_SYMPLECTIC_EULER",
        c::status::DC_INTEGRATOR_SYMPLECTIC_EULER,
    )?;
    use c::contact::*;
    m.add("CONTACT_SPEC_VERSION", DC_CONTACT_SPEC_VERSION)?;
    m.add("CONTACT_HISTORY_MAX", DC_CONTACT_HISTORY_MAX)?;
    // Every law of every kind, from the registries (demcontact::laws): NORMAL_HERTZ, ...
    for k in demcontact::laws::KINDS {
        for l in k.laws {
            m.add(format!("{}_{}", k.prefix, l.name), l.code)?;
        }
    }
    Ok(())
}

fn library_defaults() -> dc_contact_spec {
    let mut s = std::mem::MaybeUninit::<dc_contact_spec>::uninit();
    // SAFETY: `s` is a live local; dc_contact_spec_init writes the whole struct on DC_OK, the
    // only status it returns for a non-NULL pointer.
    unsafe {
        let st = dc_contact_spec_init(s.as_mut_ptr());
        debug_assert_eq!(st, c::status::DC_OK);
        s.assume_init()
    }
}

/// Declares the ContactSpec class from one list of its fields (the C struct's names): the class,
/// its conversions from and to dc_contact_spec, its keyword constructor and its repr. A field
/// added to dc_contact_spec is named here once.
macro_rules! contact_spec_class {
    (codes: [$($i:ident),* $(,)?], reals: [$($r:ident),* $(,)?] $(,)?) => {
        /// What a contact model is made of (C: dc_contact_spec), built by keyword; every field
        /// left out keeps the library's default (dc_contact_spec_init): no normal law (`normal`
        /// must be given), Damping.NONE, Criterion.FORCE, no tangential/rolling/twisting part,
        /// every parameter unset (NaN) except e_t = 1, k_r = 0, eta_r = eta_tw = 0,
        /// inertia_factor = 0.4. Parameters of sub-models not chosen are ignored; one a chosen
        /// sub-model needs and left unset makes contact_model_init raise SpecUnsetError. Units
        /// and meanings: include/demcontact.h.
        ///
        /// >>> spec = ContactSpec(normal=Normal.HERTZ, damping=Damping.RESTITUTION, e_n=0.9,
        /// ...                    E1=7e10, nu1=0.3, E2=math.inf, nu2=0.3,
        /// ...                    tangential=Tangential.MINDLIN, mu=0.3)
        /// >>> model = contact_model_init(spec)
        #[pyclass(frozen, get_all, module = "demcontact", name = "ContactSpec")]
        #[allow(non_snake_case)]
        #[derive(Clone)]
        pub struct ContactSpec {
            $($i: i32,)*
            $($r: f64,)*
            /// Carry.* (not a field of the C spec: applied by dc_contact_model_set_carry).
            carry: i32,
        }

        impl ContactSpec {
            fn from_raw(s: &dc_contact_spec) -> Self {
                ContactSpec {
                    $($i: s.$i,)*
                    $($r: s.$r,)*
                    carry: c::contact::DC_CARRY_ROTATE,
                }
            }

            /// The C struct: version and size from dc_contact_spec_init, every field from self.
            fn raw(&self) -> dc_contact_spec {
                dc_contact_spec {
                    $($i: self.$i,)*
                    $($r: self.$r,)*
                    ..library_defaults()
                }
            }

            fn describe(&self) -> String {
                let mut parts: Vec<String> =
                    vec![$(format!("{}={}", stringify!($i), enum_name(stringify!($i), self.$i))),*];
                parts.push(format!("carry={}", enum_name("carry", self.carry)));
                // Unset (NaN) parameters are left out: they are what ContactSpec() gives anyway.
                $(
                    if !self.$r.is_nan() {
                        parts.push(format!("{}={:?}", stringify!($r), self.$r));
                    }
                )*
                parts.join(", ")
            }
        }

        #[pymethods]
        impl ContactSpec {
            #[new]
            #[pyo3(signature = (*, $($i = None,)* $($r = None,)* carry = None))]
            #[allow(non_snake_case, clippy::too_many_arguments)]
            fn new(
                $($i: Option<&Bound<'_, PyAny>>,)*
                $($r: Option<&Bound<'_, PyAny>>,)*
                carry: Option<&Bound<'_, PyAny>>,
            ) -> PyResult<Self> {
                const F: &str = "ContactSpec";
                let mut s = ContactSpec::from_raw(&library_defaults());
                if let Some(o) = carry {
                    s.carry = code(F, "carry", o)?;
                }
                $(
                    if let Some(o) = $i {
                        s.$i = code(F, stringify!($i), o)?;
                    }
                )*
                $(
                    if let Some(o) = $r {
                        s.$r = real(F, stringify!($r), o)?;
                    }
                )*
                Ok(s)
            }

            /// contact_model_init(self).
            fn model(&self, py: Python<'_>) -> PyResult<ContactModel> {
                model_init(py, self)
            }

            fn __repr__(&self) -> String {
                format!("ContactSpec({})", self.describe())
            }
        }
    };
}

contact_spec_class! {
    codes: [normal, damping, criterion, tangential, rolling, twisting],
    reals: [
        E1, nu1, E2, nu2, p, k_n, e_n, visco_A, mu, k_t, e_t, mu_r, k_r, eta_r, mu_tw, k_tw,
        eta_tw, inertia_factor, work_of_adhesion, yield_pressure,
    ],
}

/// A sub-model code as its Python enum member (`tangential`, 2 -> `Tangential.MINDLIN`), the
/// package's enum named after the field; the plain number for a code the enum does not have.
fn enum_name(field: &str, code: i32) -> String {
    let mut class = String::with_capacity(field.len());
    let mut chars = field.chars();
    if let Some(first) = chars.next() {
        class.extend(first.to_uppercase());
        class.extend(chars);
    }
    Python::attach(|py| {
        py.import("demcontact")
            .and_then(|m| m.getattr(class.as_str()))
            .and_then(|cls| cls.call1((code,)))
            .and_then(|member| member.getattr("name"))
            .and_then(|name| name.extract::<String>())
            .map_or_else(|_| code.to_string(), |name| format!("{class}.{name}"))
    })
}

/// The library's default spec (C: dc_contact_spec_init): the same as ContactSpec().
#[pyfunction]
pub fn contact_spec_init() -> ContactSpec {
    ContactSpec::from_raw(&library_defaults())
}

/// A composed contact model for one material pair (C: dc_contact_model), made by
/// contact_model_init (never directly); immutable, shareable between threads. Attributes mirror
/// the C struct; `normal` is its normal law as a Pair (usable with normal_force),
/// `history_len` the doubles of history one contact needs (dc_contact_history_len).
#[pyclass(frozen, module = "demcontact", name = "ContactModel")]
pub struct ContactModel {
    raw: dc_contact_model,
    /// Doubles of history per contact (0 for a normal-only or constant-rolling model of a
    /// stateless normal law that is not step-aware; set_step and a law with state such as
    /// elastic-plastic or JKR add one double each).
    #[pyo3(get)]
    history_len: usize,
}

impl ContactModel {
    /// The batch may be given no angular velocities and no torques (C: normal_only): no
    /// tangential, rolling or twisting stage, whatever the history (a step-aware model or a law
    /// with state keeps one double and is still normal-only).
    fn normal_only(&self) -> bool {
        self.raw.tangential == c::contact::DC_TANGENTIAL_NONE
            && self.raw.rolling == c::contact::DC_ROLLING_NONE
            && self.raw.twisting == c::contact::DC_TWISTING_NONE
    }
}

#[pymethods]
impl ContactModel {
    /// The normal law as a Pair (a valid dc_pair, usable with normal_force).
    #[getter]
    fn normal(&self) -> Pair {
        Pair::new(self.raw.normal)
    }
    /// Tangential.* chosen.
    #[getter]
    fn tangential(&self) -> i32 {
        self.raw.tangential
    }
    /// Rolling.* chosen.
    #[getter]
    fn rolling(&self) -> i32 {
        self.raw.rolling
    }
    /// Twisting.* chosen.
    #[getter]
    fn twisting(&self) -> i32 {
        self.raw.twisting
    }
    /// Carry.* chosen (how the history springs follow the contact frame).
    #[getter]
    fn carry(&self) -> i32 {
        self.raw.carry
    }
    /// Friction coefficient mu.
    #[getter]
    fn mu(&self) -> f64 {
        self.raw.mu
    }
    /// k_t [N/m] (linear) or 8 G* [Pa] (Mindlin).
    #[getter]
    fn kt(&self) -> f64 {
        self.raw.kt
    }
    /// Tangential damping ratio from e_t.
    #[getter]
    fn zeta_t(&self) -> f64 {
        self.raw.zeta_t
    }
    /// Inertia factor kappa.
    #[getter]
    fn kappa(&self) -> f64 {
        self.raw.kappa
    }
    /// Rolling friction coefficient.
    #[getter]
    fn mu_r(&self) -> f64 {
        self.raw.mu_r
    }
    /// Rolling stiffness (0: Ai's rule).
    #[getter]
    fn k_r(&self) -> f64 {
        self.raw.k_r
    }
    /// Rolling damping ratio.
    #[getter]
    fn eta_r(&self) -> f64 {
        self.raw.eta_r
    }
    /// Twisting friction coefficient [m].
    #[getter]
    fn mu_tw(&self) -> f64 {
        self.raw.mu_tw
    }
    /// Twisting stiffness.
    #[getter]
    fn k_tw(&self) -> f64 {
        self.raw.k_tw
    }
    /// Twisting damping ratio.
    #[getter]
    fn eta_tw(&self) -> f64 {
        self.raw.eta_tw
    }
    /// True once set_step made the model step-aware (C: reserved[0] != 0).
    #[getter]
    fn step_aware(&self) -> bool {
        self.raw.reserved[0].to_bits() != 0
    }
    /// This model made to realise its target e_n at the host's step `dt` [s] in the host's
    /// `integrator` (C: dc_contact_model_set_step): Integrator.VELOCITY_VERLET (default; also
    /// the string "velocity_verlet") or Integrator.SYMPLECTIC_EULER ("symplectic_euler"). Returns
    /// a new ContactModel (this one is immutable); making a model step-aware makes its
    /// history_len one double longer. An undamped normal law (e_n = 1) comes back unchanged.
    /// When the host's dt changes, call set_step again, on this model or on the step-aware one:
    /// a step-aware model keeps its calibration (it depends on p, the criterion and e_n only),
    /// takes the new dt and keeps its history_len. Pass the force calls the same dt: R is
    /// calibrated for the dt given here, the force call's dt sets the onset and end corrections
    /// (see contact_force). Raises NotFiniteError or NotPositiveError (dt), IntegratorError
    /// (unknown integrator), StepUnsupportedError (a normal law other than a Tsuji power law or
    /// Hertz: viscoelastic, DMT, elastic-plastic, JKR), StepUnreachableError (the explicit step
    /// cannot realise e_n: strong damping at a large step), ResultRangeError (dt so small that
    /// dt over the t_H prefactor underflows, e.g. 5e-324).
    #[pyo3(signature = (dt, integrator = None))]
    fn set_step(
        slf: &Bound<'_, Self>,
        dt: &Bound<'_, PyAny>,
        integrator: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<ContactModel> {
        model_set_step("set_step", slf, dt, integrator)
    }
    /// The C struct's bytes (sizeof(dc_contact_model)), to hand the model to C code.
    fn to_bytes<'py>(&self, py: Python<'py>) -> Bound<'py, pyo3::types::PyBytes> {
        let p = (&self.raw as *const dc_contact_model).cast::<u8>();
        // SAFETY: dc_contact_model is repr(C) plain data of u32/i32/f64 fields with no padding
        // (4 x u32/i32 + 2 x i32, then 8-byte fields), so all its bytes are initialised.
        let b = unsafe { std::slice::from_raw_parts(p, std::mem::size_of::<dc_contact_model>()) };
        pyo3::types::PyBytes::new(py, b)
    }

    fn __repr__(&self) -> String {
        format!(
            "ContactModel(tangential={}, rolling={}, twisting={}, history_len={}, mu={:?}, kt={:?}, zeta_t={:?}{})",
            enum_name("tangential", self.raw.tangential),
            enum_name("rolling", self.raw.rolling),
            enum_name("twisting", self.raw.twisting),
            self.history_len,
            self.raw.mu,
            self.raw.kt,
            self.raw.zeta_t,
            if self.step_aware() {
                ", step_aware=True"
            } else {
                ""
            }
        )
    }
}

fn model_init(py: Python<'_>, spec: &ContactSpec) -> PyResult<ContactModel> {
    const F: &str = "contact_model_init";
    let raw_spec = spec.raw();
    let mut raw = std::mem::MaybeUninit::<dc_contact_model>::uninit();
    // SAFETY: live locals; the spec carries the version and size of this library.
    let s = unsafe { dc_contact_model_init(&raw_spec, raw.as_mut_ptr()) };
    if s != c::status::DC_OK {
        return Err(status_error(py, s, F, &format!("with {}", spec.describe())));
    }
    // SAFETY: DC_OK means the whole struct was written.
    let mut raw = unsafe { raw.assume_init() };
    // SAFETY: live local, a model dc_contact_model_init accepted.
    let s = unsafe { dc_contact_model_set_carry(&mut raw, spec.carry) };
    if s != c::status::DC_OK {
        return Err(status_error(py, s, F, &format!("with {}", spec.describe())));
    }
    let mut len = 0usize;
    // SAFETY: live locals.
    let s = unsafe { dc_contact_history_len(&raw, &mut len) };
    if s != c::status::DC_OK {
        return Err(status_error(py, s, "contact_history_len", ""));
    }
    Ok(ContactModel {
        raw,
        history_len: len,
    })
}

/// Builds a contact model from a spec (C: dc_contact_model_init): validates every parameter the
/// chosen sub-models read and calibrates the damping. Raises SpecModelError (unknown selector,
/// viscoelastic with restitution damping, ...), SpecUnsetError (a needed parameter left unset),
/// RestitutionRangeError, NotFiniteError, ... naming the spec.
#[pyfunction]
pub fn contact_model_init(py: Python<'_>, spec: &Bound<'_, ContactSpec>) -> PyResult<ContactModel> {
    model_init(py, spec.get())
}

/// The integrator code of `integrator`: None (velocity Verlet), an Integrator member or int
/// (passed on: the library refuses unknown codes), or its name as a string.
fn integrator_code(
    py: Python<'_>,
    function: &str,
    obj: Option<&Bound<'_, PyAny>>,
) -> PyResult<i32> {
    use c::status::{DC_INTEGRATOR_SYMPLECTIC_EULER, DC_INTEGRATOR_VELOCITY_VERLET};
    let Some(o) = obj.filter(|o| !o.is_none()) else {
        return Ok(DC_INTEGRATOR_VELOCITY_VERLET);
    };
    if let Ok(name) = o.extract::<String>() {
        return match name.as_str() {
            "velocity_verlet" => Ok(DC_INTEGRATOR_VELOCITY_VERLET),
            "symplectic_euler" => Ok(DC_INTEGRATOR_SYMPLECTIC_EULER),
            _ => Err(status_error(
                py,
                c::status::DC_ERR_INTEGRATOR,
                function,
                &format!(
                    "(integrator={name:?}: expected \"velocity_verlet\", \"symplectic_euler\" or an Integrator member)"
                ),
            )),
        };
    }
    code(function, "integrator", o)
}

fn model_set_step(
    function: &str,
    model: &Bound<'_, ContactModel>,
    dt: &Bound<'_, PyAny>,
    integrator: Option<&Bound<'_, PyAny>>,
) -> PyResult<ContactModel> {
    let py = model.py();
    let dt = real(function, "dt", dt)?;
    let integ = integrator_code(py, function, integrator)?;
    let mut raw = model.get().raw;
    // SAFETY: live local, written by value on DC_OK only.
    let s = unsafe { dc_contact_model_set_step(&mut raw, dt, integ) };
    if s != c::status::DC_OK {
        return Err(status_error(
            py,
            s,
            function,
            &format!("(dt={dt:?}, integrator={integ})"),
        ));
    }
    let mut len = 0usize;
    // SAFETY: live locals.
    let s = unsafe { dc_contact_history_len(&raw, &mut len) };
    if s != c::status::DC_OK {
        return Err(status_error(py, s, "contact_history_len", ""));
    }
    Ok(ContactModel {
        raw,
        history_len: len,
    })
}

/// `model` made step-aware at `dt` (C: dc_contact_model_set_step); the same as
/// model.set_step(dt, integrator).
#[pyfunction]
#[pyo3(signature = (model, dt, integrator = None))]
pub fn contact_model_set_step(
    model: &Bound<'_, ContactModel>,
    dt: &Bound<'_, PyAny>,
    integrator: Option<&Bound<'_, PyAny>>,
) -> PyResult<ContactModel> {
    model_set_step("contact_model_set_step", model, dt, integrator)
}

/// Doubles of history one contact of `model` needs (C: dc_contact_history_len).
#[pyfunction]
pub fn contact_history_len(py: Python<'_>, model: &Bound<'_, ContactModel>) -> PyResult<usize> {
    let raw = model.get().raw;
    let mut len = 0usize;
    // SAFETY: live locals.
    let s = unsafe { dc_contact_history_len(&raw, &mut len) };
    if s != c::status::DC_OK {
        return Err(status_error(py, s, "contact_history_len", ""));
    }
    Ok(len)
}

fn vec3(function: &str, name: &str, obj: &Bound<'_, PyAny>) -> PyResult<[f64; 3]> {
    // Fast path for a list or tuple of three Python floats/ints (numpy.asarray costs ~1 us).
    let items = if let Ok(t) = obj.cast::<PyTuple>() {
        (t.len() == 3).then(|| [t.get_item(0), t.get_item(1), t.get_item(2)])
    } else if let Ok(l) = obj.cast::<PyList>() {
        (l.len() == 3).then(|| [l.get_item(0), l.get_item(1), l.get_item(2)])
    } else if let Ok(a) = obj.cast::<PyUntypedArray>()
        && a.shape() == [3]
        && a.dtype().is_equiv_to(&numpy::dtype::<f64>(obj.py()))
    {
        // A float64 3-vector: its items are numpy float64 scalars (float subclasses), read
        // through the sequence protocol (cheaper than a borrow-tracked view).
        let mut out = [0.0; 3];
        for (i, o) in out.iter_mut().enumerate() {
            *o = obj.get_item(i)?.extract::<f64>()?;
        }
        return Ok(out);
    } else {
        None
    };
    if let Some([Ok(a), Ok(b), Ok(c)]) = items {
        let plain = |x: &Bound<'_, PyAny>| {
            (x.is_exact_instance_of::<PyFloat>() || x.is_exact_instance_of::<PyInt>())
                .then(|| x.extract::<f64>().ok())
                .flatten()
        };
        if let (Some(a), Some(b), Some(c)) = (plain(&a), plain(&b), plain(&c)) {
            return Ok([a, b, c]);
        }
    }
    match arg(function, name, obj)? {
        Arg::Array(a) if a.shape() == [3] => {
            let mut out = [0.0; 3];
            for (o, x) in out.iter_mut().zip(a.as_array().iter()) {
                *o = *x;
            }
            Ok(out)
        }
        other => Err(value_error(
            function,
            &format!(
                "{name} must be a 3-vector, got shape {}",
                shape_str(other.shape())
            ),
        )),
    }
}

/// Why a float64 array cannot be written in place, as a Python exception.
fn writable<'py>(
    function: &str,
    name: &str,
    obj: &Bound<'py, PyAny>,
    shape: Option<&[usize]>,
) -> PyResult<PyReadwriteArrayDyn<'py, f64>> {
    let py = obj.py();
    let Ok(untyped) = obj.cast::<PyUntypedArray>() else {
        return Err(type_error(
            function,
            name,
            "must be a numpy float64 array (it is written in place)",
        ));
    };
    let dtype = untyped.dtype();
    if !dtype.is_equiv_to(&numpy::dtype::<f64>(py)) {
        let shown = dtype.str().map(|s| s.to_string()).unwrap_or_default();
        return Err(type_error(
            function,
            name,
            &format!(
                "has dtype {shown}; it must be float64 (it is written in place: a converted copy would lose the update)"
            ),
        ));
    }
    if let Some(want) = shape
        && untyped.shape() != want
    {
        return Err(value_error(
            function,
            &format!(
                "{name} has shape {}, expected {}",
                shape_str(untyped.shape()),
                shape_str(want)
            ),
        ));
    }
    if !untyped.is_c_contiguous() {
        return Err(value_error(
            function,
            &format!(
                "{name} must be C-contiguous (it is written in place; use numpy.ascontiguousarray and keep that array)"
            ),
        ));
    }
    let typed = untyped.cast::<PyArrayDyn<f64>>()?;
    match typed.try_readwrite() {
        Ok(rw) => Ok(rw),
        Err(numpy::BorrowError::NotWriteable) => Err(value_error(
            function,
            &format!("{name} is read-only (it is written in place)"),
        )),
        // Overlapping an input array (rust-numpy's borrow tracking) or written by another
        // thread right now.
        Err(e) => Err(status_error(
            py,
            c::status::DC_ERR_BUFFER_LAYOUT,
            function,
            &format!("({name}: {e})"),
        )),
    }
}

/// The history of one contact: None (model without history), or a writable C-contiguous
/// float64 numpy array whose first dc_contact_history_len doubles are used.
fn history_arg<'py>(
    function: &str,
    model: &ContactModel,
    history: Option<&Bound<'py, PyAny>>,
) -> PyResult<Option<PyReadwriteArrayDyn<'py, f64>>> {
    match history {
        None if model.history_len > 0 => Err(type_error(
            function,
            "history",
            &format!(
                "is required: this model keeps {n} doubles per contact (numpy.zeros({n}) for a new contact, then pass the same array every step)",
                n = model.history_len
            ),
        )),
        None => Ok(None),
        Some(h) if h.is_none() && model.history_len == 0 => Ok(None),
        Some(h) => writable(function, "history", h, None).map(Some),
    }
}

/// The named-tuple classes of demcontact._types, looked up once.
static CONTACT_RESULT: PyOnceLock<Py<PyType>> = PyOnceLock::new();
static CONTACT_BATCH_RESULT: PyOnceLock<Py<PyType>> = PyOnceLock::new();
static CONTACT_ENERGY: PyOnceLock<Py<PyType>> = PyOnceLock::new();

fn result_tuple<'py>(py: Python<'py>, r: &dc_contact_result) -> PyResult<Bound<'py, PyAny>> {
    CONTACT_RESULT
        .import(py, "demcontact._types", "ContactResult")?
        .call1((
            PyArray1::from_slice(py, &r.force),
            PyArray1::from_slice(py, &r.torque1),
            PyArray1::from_slice(py, &r.torque2),
            r.f_n,
            PyArray1::from_slice(py, &r.ft),
            r.sliding != 0,
            r.rolling_sliding != 0,
        ))
}

#[allow(clippy::too_many_arguments)]
fn state_of(
    function: &str,
    n: Option<&Bound<'_, PyAny>>,
    overlap: Option<&Bound<'_, PyAny>>,
    v1: &Bound<'_, PyAny>,
    v2: &Bound<'_, PyAny>,
    w1: &Bound<'_, PyAny>,
    w2: &Bound<'_, PyAny>,
    r1: &Bound<'_, PyAny>,
    r2: &Bound<'_, PyAny>,
    m1: &Bound<'_, PyAny>,
    m2: &Bound<'_, PyAny>,
) -> PyResult<dc_contact_state> {
    Ok(dc_contact_state {
        n: match n {
            Some(n) => vec3(function, "n", n)?,
            None => [1.0, 0.0, 0.0],
        },
        overlap: match overlap {
            Some(d) => real(function, "overlap", d)?,
            None => 0.0,
        },
        v1: vec3(function, "v1", v1)?,
        v2: vec3(function, "v2", v2)?,
        w1: vec3(function, "w1", w1)?,
        w2: vec3(function, "w2", w2)?,
        r1: real(function, "r1", r1)?,
        r2: real(function, "r2", r2)?,
        m1: real(function, "m1", m1)?,
        m2: real(function, "m2", m2)?,
    })
}

fn describe_state(s: &dc_contact_state) -> String {
    format!(
        "n={:?}, overlap={:?}, v1={:?}, v2={:?}, w1={:?}, w2={:?}, r1={:?}, r2={:?}, m1={:?}, m2={:?}",
        s.n, s.overlap, s.v1, s.v2, s.w1, s.w2, s.r1, s.r2, s.m1, s.m2
    )
}

/// Force and torques of one sphere-sphere or sphere-wall contact, advancing its history by one
/// step dt (C: dc_contact_force). Returns ContactResult(force, torque1, torque2, f_n, ft,
/// sliding, rolling_sliding): vectors as numpy 3-vectors, forces on body 1.
///
/// n: unit normal from body 2 to body 1; overlap [m] (> 0 in contact; <= 0 resets the history);
/// v1, v2, w1, w2: centre and angular velocities (3-vectors); r1, r2 radii [m] and m1, m2
/// masses [kg] (a wall: r2 = m2 = math.inf, v2 its velocity at the contact point, w2 its
/// angular velocity); dt the host's time step [s] (a step-aware model: the dt given to set_step;
/// R is calibrated for that dt and this dt sets the onset and end corrections, a mismatch is not
/// detected and the realised e_n is then not the calibrated one). history: this contact's numpy
/// float64 array (at least model.history_len doubles, zeros for a new contact), updated in place
/// on success; None only for a model without history. On error nothing is written.
#[pyfunction]
#[pyo3(signature = (model, n, overlap, v1, v2, w1, w2, r1, r2, m1, m2, dt, history=None))]
#[allow(clippy::too_many_arguments)]
pub fn contact_force<'py>(
    model: &Bound<'py, ContactModel>,
    n: &Bound<'py, PyAny>,
    overlap: &Bound<'py, PyAny>,
    v1: &Bound<'py, PyAny>,
    v2: &Bound<'py, PyAny>,
    w1: &Bound<'py, PyAny>,
    w2: &Bound<'py, PyAny>,
    r1: &Bound<'py, PyAny>,
    r2: &Bound<'py, PyAny>,
    m1: &Bound<'py, PyAny>,
    m2: &Bound<'py, PyAny>,
    dt: &Bound<'py, PyAny>,
    history: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "contact_force";
    let state = state_of(F, Some(n), Some(overlap), v1, v2, w1, w2, r1, r2, m1, m2)?;
    let dt = real(F, "dt", dt)?;
    one_contact(
        F,
        model,
        history,
        |m, hp, hl, out| {
            // SAFETY: model, state and out are live locals; history is NULL with length 0 or a
            // borrowed-for-writing contiguous run of `hl` doubles (one_contact).
            unsafe { dc_contact_force(m, &state, dt, hp, hl, out) }
        },
        |hl| {
            format!(
                "with {}, dt={dt:?}, history of {hl} doubles",
                describe_state(&state)
            )
        },
    )
}

/// contact_force for two spheres given by their centres x1, x2 (C: dc_contact_force_spheres):
/// n = (x1 - x2)/|x1 - x2| and overlap = r1 + r2 - |x1 - x2| are computed by the library.
#[pyfunction]
#[pyo3(signature = (model, x1, x2, v1, v2, w1, w2, r1, r2, m1, m2, dt, history=None))]
#[allow(clippy::too_many_arguments)]
pub fn contact_force_spheres<'py>(
    model: &Bound<'py, ContactModel>,
    x1: &Bound<'py, PyAny>,
    x2: &Bound<'py, PyAny>,
    v1: &Bound<'py, PyAny>,
    v2: &Bound<'py, PyAny>,
    w1: &Bound<'py, PyAny>,
    w2: &Bound<'py, PyAny>,
    r1: &Bound<'py, PyAny>,
    r2: &Bound<'py, PyAny>,
    m1: &Bound<'py, PyAny>,
    m2: &Bound<'py, PyAny>,
    dt: &Bound<'py, PyAny>,
    history: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "contact_force_spheres";
    let (a, b) = (vec3(F, "x1", x1)?, vec3(F, "x2", x2)?);
    let state = state_of(F, None, None, v1, v2, w1, w2, r1, r2, m1, m2)?;
    let dt = real(F, "dt", dt)?;
    one_contact(
        F,
        model,
        history,
        |m, hp, hl, out| {
            // SAFETY: as contact_force; x1, x2 are live local 3-vectors.
            unsafe { dc_contact_force_spheres(m, a.as_ptr(), b.as_ptr(), &state, dt, hp, hl, out) }
        },
        |_| {
            format!(
                "with x1={a:?}, x2={b:?}, v1={:?}, v2={:?}, w1={:?}, w2={:?}, r1={:?}, r2={:?}, m1={:?}, m2={:?}, dt={dt:?}",
                state.v1, state.v2, state.w1, state.w2, state.r1, state.r2, state.m1, state.m2
            )
        },
    )
}

/// contact_force with the energy ledger of the step (C: dc_contact_force_energy): the same
/// force, torques, history update and errors bit for bit, and a ContactEnergy [J] of what the
/// step's dashpots and slips dissipated and what the history springs hold after it. Returns
/// (ContactResult, ContactEnergy). Over a whole contact the kinetic energy lost is the sum of
/// `dissipated` to the integrator's error (docs/force.md has the definitions).
#[pyfunction]
#[pyo3(signature = (model, n, overlap, v1, v2, w1, w2, r1, r2, m1, m2, dt, history=None))]
#[allow(clippy::too_many_arguments)]
pub fn contact_force_energy<'py>(
    model: &Bound<'py, ContactModel>,
    n: &Bound<'py, PyAny>,
    overlap: &Bound<'py, PyAny>,
    v1: &Bound<'py, PyAny>,
    v2: &Bound<'py, PyAny>,
    w1: &Bound<'py, PyAny>,
    w2: &Bound<'py, PyAny>,
    r1: &Bound<'py, PyAny>,
    r2: &Bound<'py, PyAny>,
    m1: &Bound<'py, PyAny>,
    m2: &Bound<'py, PyAny>,
    dt: &Bound<'py, PyAny>,
    history: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyTuple>> {
    const F: &str = "contact_force_energy";
    let py = model.py();
    let state = state_of(F, Some(n), Some(overlap), v1, v2, w1, w2, r1, r2, m1, m2)?;
    let dt = real(F, "dt", dt)?;
    let mut energy = std::mem::MaybeUninit::<dc_contact_energy>::uninit();
    let eptr = energy.as_mut_ptr();
    let result = one_contact(
        F,
        model,
        history,
        |m, hp, hl, out| {
            // SAFETY: as contact_force; `eptr` points to the live local `energy`.
            unsafe { dc_contact_force_energy(m, &state, dt, hp, hl, out, eptr) }
        },
        |hl| {
            format!(
                "with {}, dt={dt:?}, history of {hl} doubles",
                describe_state(&state)
            )
        },
    )?;
    // SAFETY: one_contact returned Ok, so the export returned DC_OK and wrote the ledger.
    let e = unsafe { energy.assume_init() };
    let ledger = CONTACT_ENERGY
        .import(py, "demcontact._types", "ContactEnergy")?
        .call1((
            e.dissipated,
            e.normal_damping,
            e.tangential_damping,
            e.tangential_slip,
            e.tangential_elastic,
            e.rolling_damping,
            e.rolling_slip,
            e.rolling_elastic,
            e.twisting_damping,
            e.twisting_slip,
            e.twisting_elastic,
        ))?;
    PyTuple::new(py, [result, ledger])
}

/// What contact_force and contact_force_spheres share: the history borrowed for writing (NULL
/// and 0 without one), the export run by `call(model, history, len, out)`, its status turned
/// into an exception with `detail(len)`, and the result as a ContactResult.
fn one_contact<'py>(
    function: &str,
    model: &Bound<'py, ContactModel>,
    history: Option<&Bound<'py, PyAny>>,
    call: impl FnOnce(&dc_contact_model, *mut f64, usize, *mut dc_contact_result) -> i32,
    detail: impl FnOnce(usize) -> String,
) -> PyResult<Bound<'py, PyAny>> {
    let py = model.py();
    let m = model.get();
    let mut hist = history_arg(function, m, history)?;
    let (hp, hl) = match hist.as_mut() {
        Some(h) => {
            let s = h
                .as_slice_mut()
                .map_err(|e| value_error(function, &e.to_string()))?;
            (s.as_mut_ptr(), s.len())
        }
        None => (std::ptr::null_mut(), 0),
    };
    let mut out = std::mem::MaybeUninit::<dc_contact_result>::uninit();
    let s = call(&m.raw, hp, hl, out.as_mut_ptr());
    drop(hist);
    if s != c::status::DC_OK {
        return Err(status_error(py, s, function, &detail(hl)));
    }
    // SAFETY: DC_OK means the whole result was written.
    result_tuple(py, &unsafe { out.assume_init() })
}

/// `a` as a run of `shape`, or the error naming it.
fn run_of<'a>(function: &str, name: &str, a: &'a Arg<'_>, shape: &[usize]) -> PyResult<Run<'a>> {
    run(a, shape).ok_or_else(|| {
        value_error(
            function,
            &format!(
                "{name} has shape {}, expected {} (or one that broadcasts to it)",
                shape_str(a.shape()),
                shape_str(shape)
            ),
        )
    })
}

/// Raw pointers of one batch, moved into the GIL-free closure.
struct Job {
    model: dc_contact_model,
    batch: dc_contact_batch,
    dt: f64,
}
// SAFETY: the pointers refer to arrays borrowed (rust-numpy borrow flags or owned Vecs) for the
// whole closure; the closure runs on this thread (detach does not move work elsewhere).
unsafe impl Send for Job {}

/// Statuses that come from a value of one contact (the batch is then rerun contact by contact
/// to name the first offending one).
fn per_contact(s: i32) -> bool {
    use c::status::*;
    matches!(
        s,
        DC_ERR_NOT_FINITE | DC_ERR_NOT_POSITIVE | DC_ERR_NOT_UNIT | DC_ERR_RESULT_RANGE
    )
}

impl Job {
    /// The first contact whose own dc_contact_force fails, with its status (history copied).
    /// After DC_ERR_RESULT_RANGE the batch has advanced every other contact's history, so the
    /// overflowing contact is found by its NaN f_n instead of by rerunning the others.
    fn locate(&self, overflow: bool) -> Option<(usize, i32, dc_contact_state)> {
        let b = &self.batch;
        let len = self.model.history_len as usize;
        for i in 0..b.n {
            // SAFETY: f_n holds n doubles, written by the batch.
            if overflow && !unsafe { b.f_n.add(i).read() }.is_nan() {
                continue;
            }
            // SAFETY: every pointer is valid for its documented length (checked by the caller
            // and by dc_contact_force_batch's layout checks before the per-value ones).
            let st = unsafe {
                let v = |p: *const f64| -> [f64; 3] {
                    if p.is_null() {
                        [0.0; 3]
                    } else {
                        p.add(3 * i).cast::<[f64; 3]>().read()
                    }
                };
                dc_contact_state {
                    n: v(b.normal),
                    overlap: b.overlap.add(i).read(),
                    v1: v(b.v1),
                    v2: v(b.v2),
                    w1: v(b.w1),
                    w2: v(b.w2),
                    r1: b.r1.add(i).read(),
                    r2: b.r2.add(i).read(),
                    m1: b.m1.add(i).read(),
                    m2: b.m2.add(i).read(),
                }
            };
            let mut h = [0.0f64; c::contact::DC_CONTACT_HISTORY_MAX];
            if len > 0 && !b.history.is_null() {
                for (k, slot) in h.iter_mut().take(len).enumerate() {
                    // SAFETY: contact i's history is history_stride >= len doubles.
                    *slot = unsafe { b.history.add(i * b.history_stride + k).read() };
                }
            }
            let mut r = std::mem::MaybeUninit::<dc_contact_result>::uninit();
            // SAFETY: live locals.
            let s = unsafe {
                dc_contact_force(
                    &self.model,
                    &st,
                    self.dt,
                    h.as_mut_ptr(),
                    h.len(),
                    r.as_mut_ptr(),
                )
            };
            if overflow {
                return Some((i, c::status::DC_ERR_RESULT_RANGE, st));
            }
            if s != c::status::DC_OK {
                return Some((i, s, st));
            }
        }
        None
    }
}

/// Forces and torques of n contacts of one model, one call of the library's batch
/// (C: dc_contact_force_batch), with the GIL released. Returns ContactBatchResult(f_n (n,),
/// force (n, 3), torque1 (n, 3), torque2 (n, 3)).
///
/// Structure of arrays: `overlap` is 1-D of n contacts; normal, v1, v2, w1, w2 are (n, 3)
/// (3 consecutive doubles per contact); r1, r2, m1, m2 are (n,). float64 C-contiguous arrays of
/// exactly these shapes are read in place (zero copy); anything else that broadcasts to them
/// (a scalar such as r2=math.inf for walls, a 3-vector, another real dtype, a strided view) is
/// copied once. w1 and w2 may be None for a model without tangential/rolling/twisting parts.
/// history: float64, C-contiguous, writable, shape (n, L) with L >= model.history_len (zeros for
/// new contacts), updated in place; None only for a model without history. out: optionally
/// (f_n, force, torque1, torque2) arrays of those shapes to write into. Every value is checked
/// before anything is written: on error (NotFiniteError, NotUnitError, ... naming the first bad
/// contact) outputs and history are untouched. One exception, ResultRangeError (valid inputs
/// whose result overflows, e.g. an overlap of 1e300 m): every other contact is computed and its
/// history advanced, and the overflowing contacts get NaN outputs (in `out`, if given) and keep
/// their history; the error names the first one. An empty batch (n = 0) returns empty arrays.
/// dt: the host's time step [s], as for contact_force (a step-aware model: the dt given to
/// set_step).
#[pyfunction]
#[pyo3(signature = (model, normal, overlap, v1, v2, w1, w2, r1, r2, m1, m2, dt, history=None, *, out=None))]
#[allow(clippy::too_many_arguments)]
pub fn contact_force_batch<'py>(
    model: &Bound<'py, ContactModel>,
    normal: &Bound<'py, PyAny>,
    overlap: &Bound<'py, PyAny>,
    v1: &Bound<'py, PyAny>,
    v2: &Bound<'py, PyAny>,
    w1: Option<&Bound<'py, PyAny>>,
    w2: Option<&Bound<'py, PyAny>>,
    r1: &Bound<'py, PyAny>,
    r2: &Bound<'py, PyAny>,
    m1: &Bound<'py, PyAny>,
    m2: &Bound<'py, PyAny>,
    dt: &Bound<'py, PyAny>,
    history: Option<&Bound<'py, PyAny>>,
    out: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "contact_force_batch";
    let py = model.py();
    let m = model.get();
    let dt = real(F, "dt", dt)?;
    let d = arg(F, "overlap", overlap)?;
    let n = match d.shape() {
        [n] => *n,
        s => {
            return Err(value_error(
                F,
                &format!(
                    "overlap must be a 1-D array of the n contacts, got shape {}",
                    shape_str(s)
                ),
            ));
        }
    };
    let (s1, s3) = ([n], [n, 3]);
    // Angular velocities: required unless the model is normal-only (the C reads them not).
    let w = |name: &str, o: Option<&Bound<'py, PyAny>>| -> PyResult<Option<Arg<'py>>> {
        match o {
            Some(o) if !o.is_none() => Ok(Some(arg(F, name, o)?)),
            _ if m.normal_only() => Ok(None),
            _ => Err(type_error(
                F,
                name,
                "is required: this model has tangential, rolling or twisting parts",
            )),
        }
    };
    let args3 = [
        ("normal", Some(arg(F, "normal", normal)?)),
        ("v1", Some(arg(F, "v1", v1)?)),
        ("v2", Some(arg(F, "v2", v2)?)),
        ("w1", w("w1", w1)?),
        ("w2", w("w2", w2)?),
    ];
    let args1 = [
        ("r1", arg(F, "r1", r1)?),
        ("r2", arg(F, "r2", r2)?),
        ("m1", arg(F, "m1", m1)?),
        ("m2", arg(F, "m2", m2)?),
    ];
    let rd = run_of(F, "overlap", &d, &s1)?;
    let mut r3: Vec<Option<Run<'_>>> = Vec::with_capacity(5);
    for (name, a) in &args3 {
        r3.push(match a {
            Some(a) => Some(run_of(F, name, a, &s3)?),
            None => None,
        });
    }
    let mut r1v: Vec<Run<'_>> = Vec::with_capacity(4);
    for (name, a) in &args1 {
        r1v.push(run_of(F, name, a, &s1)?);
    }

    // History: (n, L) float64, C-contiguous, writable (the library checks L >= history_len).
    let mut hist = match history {
        Some(h) if !h.is_none() => {
            let rw = writable(F, "history", h, None)?;
            match rw.shape() {
                [hn, _] if *hn == n => {}
                s => {
                    return Err(value_error(
                        F,
                        &format!(
                            "history has shape {}, expected ({n}, L) with L >= {} (one row per contact)",
                            shape_str(s),
                            m.history_len
                        ),
                    ));
                }
            }
            Some(rw)
        }
        _ if m.history_len > 0 => {
            return Err(type_error(
                F,
                "history",
                &format!(
                    "is required: this model keeps {l} doubles per contact (numpy.zeros((n, {l})) for new contacts)",
                    l = m.history_len
                ),
            ));
        }
        _ => None,
    };
    let stride = hist
        .as_ref()
        .and_then(|h| h.shape().get(1).copied())
        .unwrap_or(0);

    // Outputs: the caller's arrays, or new ones.
    let outs: [Bound<'py, PyAny>; 4] = match out {
        Some(o) if !o.is_none() => {
            let t = o.cast::<PyTuple>().map_err(|_| {
                type_error(
                    F,
                    "out",
                    "must be a tuple (f_n, force, torque1, torque2) of float64 arrays",
                )
            })?;
            if t.len() != 4 {
                return Err(type_error(
                    F,
                    "out",
                    "must be a tuple (f_n, force, torque1, torque2) of float64 arrays",
                ));
            }
            [
                t.get_item(0)?,
                t.get_item(1)?,
                t.get_item(2)?,
                t.get_item(3)?,
            ]
        }
        _ => [
            // SAFETY (all four): uninitialised, but fully written on success; dropped unread on
            // error.
            unsafe { PyArray1::<f64>::new(py, [n], false) }.into_any(),
            unsafe { PyArray2::<f64>::new(py, [n, 3], false) }.into_any(),
            unsafe { PyArray2::<f64>::new(py, [n, 3], false) }.into_any(),
            unsafe { PyArray2::<f64>::new(py, [n, 3], false) }.into_any(),
        ],
    };
    let names = [
        "out[0] (f_n)",
        "out[1] (force)",
        "out[2] (torque1)",
        "out[3] (torque2)",
    ];
    let shapes: [&[usize]; 4] = [&s1, &s3, &s3, &s3];
    let mut rws = Vec::with_capacity(4);
    for ((o, name), shape) in outs.iter().zip(names).zip(shapes) {
        rws.push(writable(F, name, o, Some(shape))?);
    }
    let result = CONTACT_BATCH_RESULT.import(py, "demcontact._types", "ContactBatchResult")?;
    if n == 0 {
        drop(rws);
        return result.call1((
            outs[0].clone(),
            outs[1].clone(),
            outs[2].clone(),
            outs[3].clone(),
        ));
    }
    let mut optr = [std::ptr::null_mut::<f64>(); 4];
    for (p, rw) in optr.iter_mut().zip(rws.iter_mut()) {
        *p = rw
            .as_slice_mut()
            .map_err(|e| value_error(F, &e.to_string()))?
            .as_mut_ptr();
    }
    let hptr = match hist.as_mut() {
        Some(h) => h
            .as_slice_mut()
            .map_err(|e| value_error(F, &e.to_string()))?
            .as_mut_ptr(),
        None => std::ptr::null_mut(),
    };
    let p3 = |i: usize| {
        r3.get(i)
            .and_then(Option::as_ref)
            .map_or(std::ptr::null(), |r| r.slice().as_ptr())
    };
    let p1 = |i: usize| r1v.get(i).map_or(std::ptr::null(), |r| r.slice().as_ptr());
    let job = Job {
        model: m.raw,
        batch: dc_contact_batch {
            n,
            history_stride: stride,
            normal: p3(0),
            overlap: rd.slice().as_ptr(),
            v1: p3(1),
            v2: p3(2),
            w1: p3(3),
            w2: p3(4),
            r1: p1(0),
            r2: p1(1),
            m1: p1(2),
            m2: p1(3),
            history: hptr,
            f_n: optr[0],
            force: optr[1],
            torque1: optr[2],
            torque2: optr[3],
        },
        dt,
    };
    let outcome = py.detach(move || {
        // SAFETY: every pointer refers to an array borrowed above for this whole call, of the
        // documented length (shapes checked); outputs and history are borrowed for writing, so
        // no other Python thread touches them meanwhile.
        let s = unsafe { dc_contact_force_batch(&job.model, &job.batch, job.dt) };
        if s == c::status::DC_OK {
            Ok(())
        } else if per_contact(s) {
            Err((
                s,
                job.locate(s == c::status::DC_ERR_RESULT_RANGE)
                    .map(Box::new),
            ))
        } else {
            Err((s, None))
        }
    });
    drop(rws);
    drop(hist);
    match outcome {
        Ok(()) => result.call1((
            outs[0].clone(),
            outs[1].clone(),
            outs[2].clone(),
            outs[3].clone(),
        )),
        Err((s, None)) => Err(status_error(
            py,
            s,
            F,
            &format!("(n={n}, history stride {stride}, dt={dt:?}; outputs and history untouched)"),
        )),
        Err((s, Some(located))) => {
            let (i, _, st) = *located;
            let what = if s == c::status::DC_ERR_RESULT_RANGE {
                "its result overflowed: the overflowing contacts' outputs are NaN and their \
                 history untouched; every other contact was computed and its history advanced"
            } else {
                "outputs and history untouched"
            };
            Err(status_error(
                py,
                s,
                F,
                &format!(
                    "at contact {i} with {}, dt={dt:?} ({what})",
                    describe_state(&st)
                ),
            ))
        }
    }
}
