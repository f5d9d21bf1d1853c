//! Maximum overlap, in closed form for every p and every damping.
//!
//! At the turning point X = e^{−g(ζ)} (g from [`crate::lsd::decay_to_turning_point`], valid for
//! all ζ ≥ 0), so `δ_max = A·((v0/ω0)·e^{−g})^q`, evaluated in logarithms so that extreme but valid
//! inputs do not overflow on the way. Undamped: δ_max^{p+1} = (p+1) v0²/(2ω0²), the energy balance.

use super::contact::Contact;
use crate::Error;

/// δ_max of the collision.
pub fn max_overlap(c: &Contact) -> Result<f64, Error> {
    let d = c.amp * (c.q * (c.ln_x0 - c.g())).exp();
    if !(d.is_finite() && d > 0.0) {
        return Err(Error::ResultRange);
    }
    Ok(d)
}
