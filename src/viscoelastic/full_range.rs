//! Full-range tier: e(b) to 1e-10 relative for every b ≥ 0, at the cost of one Chebyshev sum.
//!
//! Layout (generated data in [`super::table`], by `examples/gen_viscoelastic_table.rs` from the
//! reference integrator):
//! * 0 ≤ b < 1: 4 pieces uniform in w = √b. Under the force criterion e is analytic in √b, not in
//!   b (the paper's series has odd powers of b^{1/2}); under the overlap criterion e is analytic in
//!   b, hence in w too, so one variable serves both.
//! * 1 ≤ b < 2^n: pieces per binade of b, selected and scaled exactly from the bits of b (no
//!   logarithm): force n = 20 (b < 2^20 ≈ 1.05e6), overlap n = 3 (b < 8), where e·b^5 is
//!   tabulated (overlap: 4 pieces per binade).
//! * beyond: the large-b laws measured with the reference (docs/viscoelastic.md):
//!   overlap e = C_O b^{−5} (exact up to terms below 1e-16 for b ≥ 8: the trajectory collapses onto
//!   one attracting solution whose exit speed is independent of the impact speed), force
//!   e = C_F b^{−5/3} (1 − D b^{−P}), C_F = (3/2)^{2/3}, P ≈ 1.59 and D ≈ 12.7 fitted (7e-12
//!   relative on [2^20, 2^21.5], at the reference's own accuracy there).

use super::table::*;
use crate::{EndCriterion, Error};

#[inline]
fn clenshaw(c: &[f64; DEG], x: f64) -> f64 {
    let (mut b1, mut b2) = (0.0, 0.0);
    let x2 = 2.0 * x;
    for &ck in c.iter().skip(1).rev() {
        let t = x2.mul_add(b1, ck - b2);
        b2 = b1;
        b1 = t;
    }
    let c0 = c.first().copied().unwrap_or(0.0);
    x.mul_add(b1, c0 - b2)
}

#[inline]
fn w_piece(pieces: &[[f64; DEG]; W_PIECES], b: f64) -> f64 {
    let s = b.sqrt() * W_PIECES as f64;
    let i = (s as usize).min(W_PIECES - 1);
    let x = 2.0 * (s - i as f64) - 1.0;
    pieces.get(i).map_or(f64::NAN, |c| clenshaw(c, x))
}

/// Binade piece for 1 ≤ b < 2^binades; None beyond.
#[inline]
fn binade_piece(pieces: &[[f64; DEG]], sub: usize, binades: usize, b: f64) -> Option<f64> {
    let bits = b.to_bits();
    let j = ((bits >> 52) & 0x7ff) as usize;
    let j = j.checked_sub(1023)?;
    if j >= binades {
        return None;
    }
    // mantissa m ∈ [1, 2), exact
    let m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | (1023u64 << 52));
    let s = (m - 1.0) * sub as f64;
    let k = (s as usize).min(sub - 1);
    let x = 2.0 * (s - k as f64) - 1.0;
    pieces.get(j * sub + k).map(|c| clenshaw(c, x))
}

/// Below this b the series around b = 0 replaces the first Chebyshev piece. That piece is accurate
/// to ~1.5e-15 *absolute*, which is all of 1 − e for tiny b: it gave e(0) = 1 − 1.7e-15 and a
/// non-monotone e below b ~ 1e-14 (tests/extremes.rs). The series gives e(0) = 1 exactly and keeps
/// 1 − e (the dissipated fraction) to full relative precision; at the switch e steps up by 1.0e-15
/// (overlap) / 1.1e-16 (force), the table's own absolute error there.
const SMALL_B: f64 = 1e-5;
/// C1 = (4/5) B(3/5, 3/2) (5/4)^{3/5} = 1.15344885809528…: to first order in the damping the loss
/// is ∫ γ ξ^{1/2} ξ'² dt along the elastic Hertz trajectory, 1 − e = ΔE/v² = C1 b (derived in
/// docs/robustness.md; the paper prints 1.153448856 and 1.153448854).
const C1: f64 = 1.153_448_858_095_288_4;
/// b² and b^{5/2} coefficients of the force-end series (Schwager & Pöschel Table V, h4, h5 = 4/15).
const FORCE_H4: f64 = 0.798_266_558_1;
const FORCE_H5: f64 = 0.266_666_666_7;
/// b² and b³ coefficients of the overlap-end series (their Table III, c2, c3).
const OVERLAP_C2: f64 = 0.798_266_555_3;
const OVERLAP_C3: f64 = -0.522_882_560_9;

/// Full-range restitution e(b), b = β v^{1/5} ≥ 0 finite. Relative error ≤ 1e-10 (measured
/// 6e-14 on 0 ≤ b ≤ 1e6 (force), 4e-15 on 0 ≤ b ≤ 3e3 (overlap) against the reference,
/// tests/viscoelastic_accuracy.rs).
pub fn e_full(b: f64, criterion: EndCriterion) -> Result<f64, Error> {
    if !b.is_finite() {
        return Err(Error::NotFinite);
    }
    if b < 0.0 {
        return Err(Error::Negative);
    }
    Ok(match criterion {
        EndCriterion::Force => {
            if b < SMALL_B {
                // 1 − C1 b + h4 b² + h5 b^{5/2}; truncation 0.52 b³ < 6e-16 absolute.
                1.0 - b * (C1 - b * (FORCE_H4 + FORCE_H5 * b.sqrt()))
            } else if b < 1.0 {
                w_piece(&FORCE_W, b)
            } else if let Some(e) = binade_piece(&FORCE_B, FORCE_SUB, FORCE_BINADES, b) {
                e
            } else {
                e_force_asymptotic(b)
            }
        }
        EndCriterion::Overlap => {
            if b < SMALL_B {
                // 1 − C1 b + c2 b² + c3 b³; truncation 0.35 b⁴ < 4e-21 absolute.
                1.0 - b * (C1 - b * (OVERLAP_C2 + OVERLAP_C3 * b))
            } else if b < 1.0 {
                w_piece(&OVERLAP_W, b)
            } else {
                let b2 = b * b;
                let b5 = b2 * b2 * b;
                match binade_piece(&OVERLAP_B, OVERLAP_SUB, OVERLAP_BINADES, b) {
                    Some(eb5) => eb5 / b5,
                    None => C_OVERLAP / b5,
                }
            }
        }
    })
}

/// Large-b law of the force criterion, e ≈ C_F b^{−5/3} (1 − D b^{−P}).
#[inline]
pub fn e_force_asymptotic(b: f64) -> f64 {
    let c = b.cbrt();
    C_FORCE / (b * c * c) * (1.0 - FORCE_CORR_D * b.powf(-FORCE_CORR_P))
}

/// Large-b law of the overlap criterion, e = C_O b^{−5}.
#[inline]
pub fn e_overlap_asymptotic(b: f64) -> f64 {
    let b2 = b * b;
    C_OVERLAP / (b2 * b2 * b)
}

/// The generated table, for the regeneration test: (w-pieces, binade pieces) of a criterion.
pub fn table_pieces(criterion: EndCriterion) -> (&'static [[f64; DEG]], &'static [[f64; DEG]]) {
    match criterion {
        EndCriterion::Force => (&FORCE_W, &FORCE_B),
        EndCriterion::Overlap => (&OVERLAP_W, &OVERLAP_B),
    }
}

/// The generated asymptotic constants (C_O, C_F, P, D).
pub fn asymptotic_constants() -> (f64, f64, f64, f64) {
    (C_OVERLAP, C_FORCE, FORCE_CORR_P, FORCE_CORR_D)
}
