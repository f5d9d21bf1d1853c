//! Duration plans: everything the force-end and overlap-end durations need from the exponent p
//! and the accuracy level alone (transform constants, ln Γ(q), the Gauss–Jacobi rule of the
//! integrand's end singularity), built once per p and reused for any α, v0, ω0 and criterion.
//!
//! The plan is plain data of fixed size (no allocation) so that the C ABI's `dc_duration_plan`
//! is a field-for-field copy of [`DurationPlan`]; the FFI only converts.

use super::contact::Contact;
use super::duration::{PLAN_NODES, Plan, Rule, contact_duration_planned};
use super::transform::{check_exponent, transform_a, transform_q};
use crate::numerics::gauss_jacobi::{MAX_NODES, gauss_jacobi};
use crate::{EndCriterion, Error};

/// Marks a plan built by [`DurationPlan::new`] ("DCPLAN02": the layout without the
/// Gauss–Legendre rule; a plan with the older layout is rejected).
///
/// cbindgen:ignore
pub const PLAN_TAG: u64 = 0x4443_504C_414E_3032;

/// Lowest quadrature accuracy level.
///
/// cbindgen:ignore
pub const LEVEL_MIN: i32 = 0;
/// Highest quadrature accuracy level (used where no level is given).
///
/// cbindgen:ignore
pub const LEVEL_MAX: i32 = 4;

/// An accuracy level from a caller's integer: `LEVEL_MIN..=LEVEL_MAX`, else [`Error::Level`].
pub fn level(l: i32) -> Result<u32, Error> {
    if (LEVEL_MIN..=LEVEL_MAX).contains(&l) {
        Ok(l.unsigned_abs())
    } else {
        Err(Error::Level)
    }
}

/// Gauss nodes a plan of this level holds.
fn nodes_of(level: i32) -> Result<usize, Error> {
    let lv = self::level(level)?;
    PLAN_NODES.get(lv as usize).copied().ok_or(Error::Level)
}

/// A contact-duration plan for one exponent p at one accuracy level. Build with
/// [`DurationPlan::new`]; fields are public only so the C ABI can copy them.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DurationPlan {
    /// [`PLAN_TAG`] when built by [`DurationPlan::new`].
    pub tag: u64,
    /// Force-law exponent p >= 1.
    pub p: f64,
    /// q = 2/(p+1).
    pub q: f64,
    /// A = ((p+1)/2)^(1/(p+1)).
    pub amp: f64,
    /// ln Γ(q).
    pub lgamma_q: f64,
    /// ln(A q).
    pub ln_aq: f64,
    /// Accuracy level.
    pub level: i32,
    /// Nodes in use: 5, 6, 7, 9, 12 for levels 0..4.
    pub n: i32,
    /// Gauss–Jacobi nodes in (0, 1) for the weight y^(q−1).
    pub nodes: [f64; MAX_NODES],
    /// Their weights.
    pub weights: [f64; MAX_NODES],
}

impl DurationPlan {
    /// Builds the plan for exponent `p` at accuracy `level` (Gauss–Jacobi rule by Newton
    /// iteration; a few microseconds).
    pub fn new(p: f64, level: i32) -> Result<Self, Error> {
        check_exponent(p)?;
        let n = nodes_of(level)?;
        let q = transform_q(p);
        let amp = transform_a(p);
        let mut plan = DurationPlan {
            tag: PLAN_TAG,
            p,
            q,
            amp,
            lgamma_q: libm::lgamma(q),
            ln_aq: (amp * q).ln(),
            level,
            n: i32::try_from(n).map_err(|_| Error::Level)?,
            ..Default::default()
        };
        let (Some(x), Some(w)) = (plan.nodes.get_mut(..n), plan.weights.get_mut(..n)) else {
            return Err(Error::Level);
        };
        gauss_jacobi(q - 1.0, x, w)?;
        if !(plan.amp.is_finite() && plan.lgamma_q.is_finite() && plan.ln_aq.is_finite()) {
            return Err(Error::ResultRange);
        }
        Ok(plan)
    }

    /// The rule and constants of a plan that passes the consistency checks, else
    /// [`Error::Plan`] (not built by [`DurationPlan::new`], or modified afterwards).
    fn checked(&self) -> Result<Plan<'_>, Error> {
        let n = nodes_of(self.level).map_err(|_| Error::Plan)?;
        let p = self.p;
        if self.tag != PLAN_TAG
            || self.n != i32::try_from(n).map_err(|_| Error::Plan)?
            || !(p.is_finite() && p >= 1.0)
            || self.q != transform_q(p)
            || !(self.amp.is_finite()
                && self.amp > 0.0
                && self.lgamma_q.is_finite()
                && self.ln_aq.is_finite())
        {
            return Err(Error::Plan);
        }
        let (Some(nodes), Some(weights)) = (self.nodes.get(..n), self.weights.get(..n)) else {
            return Err(Error::Plan);
        };
        Ok(Plan {
            q: self.q,
            amp: self.amp,
            lgamma_q: self.lgamma_q,
            ln_aq: self.ln_aq,
            singular: Rule { nodes, weights },
        })
    }

    /// The contact (α, v0, ω0) at the plan's exponent, with its transform constants taken from
    /// the plan: checks the plan first ([`Error::Plan`]), then the inputs exactly as
    /// [`Contact::new`] does (same errors, same order).
    pub fn contact(&self, alpha: f64, v0: f64, omega0: f64) -> Result<Contact, Error> {
        self.checked()?;
        Contact::with_constants(self.p, alpha, v0, omega0, Some((self.q, self.amp)))
    }

    /// Contact duration τ [s] of a contact made by [`DurationPlan::contact`] under `criterion`:
    /// the result of [`super::contact_duration`] at the plan's level, at a fraction of the cost.
    pub fn duration(&self, c: &Contact, criterion: EndCriterion) -> Result<f64, Error> {
        contact_duration_planned(&self.checked()?, c, criterion)
    }
}

/// ω0 = √(k/m) from a stiffness k > 0 and an effective mass m > 0.
pub fn omega0(k: f64, m: f64) -> Result<f64, Error> {
    if !(k.is_finite() && m.is_finite()) {
        return Err(Error::NotFinite);
    }
    if !(k > 0.0 && m > 0.0) {
        return Err(Error::NotPositive);
    }
    let w = k.sqrt() / m.sqrt();
    if !(w.is_finite() && w > 0.0) {
        return Err(Error::ResultRange);
    }
    Ok(w)
}
