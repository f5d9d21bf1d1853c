//! LAMMPS `pair_style granular` (`src/GRANULAR/gran_sub_mod_damping.cpp`, `granular_model.cpp`).
//!
//! The damping force is `−damp·√(m* Fn/δ)·vn` for both `tsuji` and `coeff_restitution`
//! (`gran_damping_tsuji_prefactor`), where Fn is the elastic normal force, so √(m* Fn/δ) =
//! √(m* k) δ^{(p−1)/2}: `damp` *is* the Tsuji α.
//!
//! * `coeff_restitution`: damp = 2|L|/√(π² + L²) for `hooke` (α = 2ζ, p = 1) and
//!   √(3/2)·2√(5/6)·|L|/√(π² + L²) = √5 |L|/√(π² + L²) otherwise (p = 3/2), L = ln e: exactly
//!   ζ = ζ_O(e).
//! * `tsuji`: damp = η(e), Tsuji's polynomial fit (Marshall 2009 eq. 53)
//!   η = 1.2728 − 4.2783e + 11.087e² − 22.348e³ + 27.467e⁴ − 18.022e⁵ + 4.8218e⁶, so
//!   ζ = η(e)/√(2(p+1)). η falls strictly from 1.2728 (e = 0) to 0.0003 (e = 1) (η' ≤ −0.459 on
//!   [0, 1]), so it is inverted uniquely, and only α inside that range can be realised. Releases
//!   up to 22 Jul 2025 (the newest PyPI wheel the harness runs, measured 0.616 for 0.5) use η
//!   itself; from 2 Sep 2026 `damping tsuji` multiplies it by √2 ("effective mass convention, as
//!   in Tsuji 1992" in `GranSubModDampingTsuji::init`): damp = √2 η(e), the `*_SQRT2` builtins.
//!   [`release_scale`] tells which a release uses.
//! * `limit_damping`: `if (Fntot < 0) Fntot = 0` — the force-end criterion.
//!
//! Reachable with `tsuji` (e typed in (0, 1]): Hertz e ∈ (0.1136, 0.99958), with `limit_damping`
//! (0.2628, 0.99958); hooke (0.0749, 0.99953) and (0.2337, 0.99953). With η·√2: Hertz
//! (0.0141, 0.9994), with `limit_damping` (0.1784, 0.9994); hooke (0.0015, 0.99933) and
//! (0.1553, 0.99933).

use super::check_typed_e;
use crate::numerics::newton_bracketed;
use crate::powerlaw::transform::{damping_scale, zeta_from_alpha};
use crate::{Error, lsd};

/// Tsuji's fit coefficients, constant term first, as LAMMPS types them.
const TSUJI: [f64; 7] = [1.2728, -4.2783, 11.087, -22.348, 27.467, -18.022, 4.8218];

/// η(e) and η'(e) by Horner's scheme.
pub fn tsuji_eta(e: f64) -> (f64, f64) {
    let mut v = 0.0;
    let mut d = 0.0;
    for c in TSUJI.iter().rev() {
        d = d * e + v;
        v = v * e + c;
    }
    (v, d)
}

/// ζ of `damping coeff_restitution` for a typed e ∈ (0, 1].
pub fn coeff_restitution_zeta(e: f64) -> Result<f64, Error> {
    Ok(lsd::zeta_overlap(check_typed_e(e)?))
}

/// The last release known to use Tsuji's η unscaled (YYYYMMDD): 22 Jul 2025, run by the harness.
/// cbindgen:ignore
pub const TSUJI_PLAIN_UNTIL: i32 = 20250722;
/// The first release known to multiply η by √2 (YYYYMMDD): 2 Sep 2026.
/// cbindgen:ignore
pub const TSUJI_SQRT2_FROM: i32 = 20260902;

/// Which η a LAMMPS release's `damping tsuji` uses: `Ok(1.0)` for releases up to
/// [`TSUJI_PLAIN_UNTIL`], `Ok(√2)` from [`TSUJI_SQRT2_FROM`] on. [`Error::BuiltinVersion`] for a
/// date that is not a calendar date YYYYMMDD (years 2000–2099) or falls between the two, where
/// releases and development snapshots cannot be told apart by date: read `damp *= MY_SQRT2` (or
/// its absence) in that source's `GranSubModDampingTsuji::init` and pick the builtin directly.
pub fn release_scale(yyyymmdd: i32) -> Result<f64, Error> {
    let (y, m, d) = (yyyymmdd / 10_000, yyyymmdd / 100 % 100, yyyymmdd % 100);
    let leap = y % 4 == 0;
    let days = match m {
        2 if leap => 29,
        2 => 28,
        4 | 6 | 9 | 11 => 30,
        1..=12 => 31,
        _ => 0,
    };
    if !((2000..=2099).contains(&y) && d >= 1 && d <= days) {
        return Err(Error::BuiltinVersion);
    }
    if yyyymmdd <= TSUJI_PLAIN_UNTIL {
        Ok(1.0)
    } else if yyyymmdd >= TSUJI_SQRT2_FROM {
        Ok(core::f64::consts::SQRT_2)
    } else {
        Err(Error::BuiltinVersion)
    }
}

/// A release as a user writes it, as YYYYMMDD: `2026-09-02`, `20260902`, LAMMPS' own `2Sep2026`
/// or `2 Sep 2026` (as `lmp -h` and the log's first line print it). `None` if it is none of these
/// (the date itself is checked by [`release_scale`]). No allocation.
pub fn parse_release(s: &str) -> Option<i32> {
    const MONTHS: [&[u8; 3]; 12] = [
        b"jan", b"feb", b"mar", b"apr", b"may", b"jun", b"jul", b"aug", b"sep", b"oct", b"nov",
        b"dec",
    ];
    /// A run of 1..=`max` ASCII digits as a number.
    fn digits(t: &[u8], max: usize) -> Option<i32> {
        if t.is_empty() || t.len() > max || !t.iter().all(u8::is_ascii_digit) {
            return None;
        }
        Some(t.iter().fold(0, |n, &b| n * 10 + i32::from(b - b'0')))
    }
    let b = s.trim().as_bytes();
    // 2026-09-02
    if let [y0, y1, y2, y3, b'-', m0, m1, b'-', d0, d1] = *b {
        let (y, m, d) = (
            digits(&[y0, y1, y2, y3], 4)?,
            digits(&[m0, m1], 2)?,
            digits(&[d0, d1], 2)?,
        );
        return Some(y * 10_000 + m * 100 + d);
    }
    // 20260902
    if b.len() == 8 && b.iter().all(u8::is_ascii_digit) {
        return digits(b, 8);
    }
    // 2Sep2026, 2 Sep 2026: day, month name, year, blanks allowed between them.
    let day_len = b.iter().take_while(|c| c.is_ascii_digit()).count();
    let day = digits(b.get(..day_len)?, 2)?;
    let rest = b.get(day_len..)?.trim_ascii_start();
    let month = rest.get(..3)?;
    let m = MONTHS
        .iter()
        .position(|name| month.eq_ignore_ascii_case(*name))?;
    let year = digits(rest.get(3..)?.trim_ascii_start(), 4)?;
    if year < 1000 {
        return None;
    }
    Some(year * 10_000 + (m as i32 + 1) * 100 + day)
}

/// ζ of `damping tsuji` at exponent p for a typed e ∈ (0, 1], with damp = `scale`·η(e) (1 or √2,
/// [`release_scale`]).
pub fn tsuji_zeta(e: f64, p: f64, scale: f64) -> Result<f64, Error> {
    let e = check_typed_e(e)?;
    Ok(zeta_from_alpha(scale * tsuji_eta(e).0, p))
}

/// The e to type into `damping tsuji` (damp = `scale`·η(e)) for damping ratio ζ, or
/// [`Error::BuiltinUnreachable`] when α/scale, α = √(2(p+1)) ζ, lies outside η's range
/// [η(1), η(0)).
pub fn tsuji_value(zeta: f64, p: f64, scale: f64) -> Result<f64, Error> {
    let alpha = zeta * damping_scale(p) / scale;
    let (lo_alpha, _) = tsuji_eta(1.0);
    let (hi_alpha, _) = tsuji_eta(0.0);
    if !(alpha >= lo_alpha && alpha < hi_alpha) {
        return Err(Error::BuiltinUnreachable);
    }
    // η decreasing, so f = α − η(x) is increasing: f(0) < 0 ≤ f(1). Linear interpolation as
    // the start.
    let f = |x: f64| {
        let (v, d) = tsuji_eta(x);
        (alpha - v, -d)
    };
    let x0 = (hi_alpha - alpha) / (hi_alpha - lo_alpha);
    let x = newton_bracketed(f, 0.0, 1.0, x0, 100)?;
    if x > 0.0 && x <= 1.0 {
        Ok(x)
    } else {
        Err(Error::BuiltinUnreachable)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn releases_parse_and_choose_their_eta() {
        for (text, date) in [
            ("2026-09-02", 20260902),
            ("20260902", 20260902),
            ("2Sep2026", 20260902),
            (" 2 Sep 2026 ", 20260902),
            ("22Jul2025", 20250722),
            ("22 jul 2025", 20250722),
            ("29Aug2024", 20240829),
            ("23Jun2022", 20220623),
        ] {
            assert_eq!(parse_release(text), Some(date), "{text}");
        }
        for bad in [
            "",
            "2026",
            "2026-9-2",
            "2Sept2026",
            "2Sep26",
            "Sep2026",
            "x2Sep2026",
            "123Sep2026",
            "2026-09-0x",
            "2026/09/02",
            "stable",
        ] {
            assert_eq!(parse_release(bad), None, "{bad:?}");
        }
        assert_eq!(release_scale(20250722), Ok(1.0));
        assert_eq!(release_scale(20220623), Ok(1.0));
        assert_eq!(release_scale(20260902), Ok(core::f64::consts::SQRT_2));
        assert_eq!(release_scale(20270211), Ok(core::f64::consts::SQRT_2));
        // Between the last release known without the factor and the first with it: ambiguous.
        for d in [20250723, 20260211, 20260901] {
            assert_eq!(release_scale(d), Err(Error::BuiltinVersion), "{d}");
        }
        // Not calendar dates.
        for d in [
            20261301, 20260230, 20250229, 20260900, 19991231, 0, -20260902,
        ] {
            assert_eq!(release_scale(d), Err(Error::BuiltinVersion), "{d}");
        }
        assert_eq!(release_scale(20280229), Ok(core::f64::consts::SQRT_2));
    }

    #[test]
    fn eta_derivative_matches_difference() {
        for i in 0..=20 {
            let e = i as f64 / 20.0;
            let h = 1e-6;
            let fd = (tsuji_eta(e + h).0 - tsuji_eta(e - h).0) / (2.0 * h);
            assert!((fd - tsuji_eta(e).1).abs() < 1e-7);
        }
        assert!((tsuji_eta(1.0).0 - 0.0003).abs() < 1e-12);
    }
}
