//! Extremes suite: every power-law, time-step, viscoelastic and force export over the edges of its
//! valid domain — e from 1e-12 to 1 − 1e-12, p from 1 to 20, impact speeds 1e-9 to 1e4, stiffness
//! and mass over many decades (ω0 accordingly), critically damped (ζ = 1 exactly and 1 ± 1e-12)
//! and strongly overdamped contacts, overlaps near underflow. Each export is compared with an
//! independent evaluation written here (closed forms derived another way, exact scaling laws,
//! round trips, the ODE reference of tests/common at moderate points); the worst relative error,
//! where it occurs and the count of unexpected non-finite results are printed as a table:
//!
//! `cargo test --release --test extremes -- --nocapture`
//!
//! Relative errors are measured against a reference evaluated with the same double ζ =
//! α/(√2·√(p+1)) the contract defines; the conditioning of the physics with respect to α itself
//! (e.g. τ ∝ 1/√(1−ζ²) near critical damping) is discussed in docs/robustness.md.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::indexing_slicing)]

mod common;
use common::collide;
use demcontact::EndCriterion;
use demcontact::ffi::{
    calibration::*, force::*, powerlaw::*, status::*, timestep::*, viscoelastic::*,
};
use std::f64::consts::{PI, SQRT_2};

/// Worst-case bookkeeping for one export (or one export × reference).
struct Stat {
    name: &'static str,
    reference: &'static str,
    tol: f64,
    points: usize,
    worst: f64,
    at: String,
    nonfinite: usize,
}

impl Stat {
    fn new(name: &'static str, reference: &'static str, tol: f64) -> Self {
        Self {
            name,
            reference,
            tol,
            points: 0,
            worst: 0.0,
            at: String::new(),
            nonfinite: 0,
        }
    }
    /// Records one comparison; `got` must be finite (a non-finite value is counted, not compared).
    fn add(&mut self, got: f64, want: f64, at: impl FnOnce() -> String) {
        self.points += 1;
        if !got.is_finite() {
            self.nonfinite += 1;
            if self.nonfinite == 1 {
                println!("{}: NON-FINITE {got} at {}", self.name, at());
            }
            return;
        }
        let rel = if want == got {
            0.0
        } else {
            ((got - want) / want).abs()
        };
        if rel > self.worst || rel.is_nan() {
            self.worst = if rel.is_nan() { f64::INFINITY } else { rel };
            self.at = at();
        }
    }
    fn ok(&self) -> bool {
        self.nonfinite == 0 && self.worst <= self.tol && self.points > 0
    }
}

fn print_table(title: &str, stats: &[Stat]) {
    println!("\n{title}");
    println!("| function | reference | points | non-finite | worst rel. error | bound | where |");
    println!("|---|---|---:|---:|---:|---:|---|");
    for s in stats {
        println!(
            "| {} | {} | {} | {} | {:.1e} | {:.0e} | {} |",
            s.name, s.reference, s.points, s.nonfinite, s.worst, s.tol, s.at
        );
    }
    let bad: Vec<_> = stats.iter().filter(|s| !s.ok()).map(|s| s.name).collect();
    assert!(bad.is_empty(), "failing: {bad:?}");
}

const PS: [f64; 10] = [1.0, 1.1, 1.5, 2.0, 2.5, 3.0, 5.0, 8.0, 12.0, 20.0];
const ES: [f64; 15] = [
    1e-12,
    1e-9,
    1e-6,
    1e-3,
    0.01,
    0.1,
    0.3,
    0.5,
    0.7,
    0.9,
    0.99,
    0.999,
    1.0 - 1e-6,
    1.0 - 1e-9,
    1.0 - 1e-12,
];
const ZETAS: [f64; 9] = [0.0, 0.5, 1.0 - 1e-12, 1.0, 1.0 + 1e-12, 1.5, 3.0, 10.0, 1e3];
const V0S: [f64; 6] = [1e-9, 1e-6, 1e-3, 1.0, 1e2, 1e4];
const KS: [f64; 4] = [1e-2, 1e3, 1e8, 1e12];
const MS: [f64; 4] = [1e-12, 1e-6, 1.0, 1e3];

fn scale(p: f64) -> f64 {
    SQRT_2 * (p + 1.0).sqrt()
}

/// Damping coefficients of the grid: α calibrated from every e under both criteria, and α of
/// prescribed damping ratios (ζ = 1 exactly in the contract's double arithmetic, 1 ± 1e-12,
/// strongly overdamped).
fn alphas(p: f64) -> Vec<f64> {
    let mut v = Vec::new();
    for &e in &ES {
        for c in [DC_END_OVERLAP, DC_END_FORCE] {
            let mut a = f64::NAN;
            assert_eq!(unsafe { dc_alpha_from_e(e, p, c, &mut a) }, DC_OK);
            v.push(a);
        }
    }
    for &z in &ZETAS {
        v.push(z * scale(p));
    }
    v
}

/// ω0 from stiffness and mass over many decades (through dc_omega0, itself checked).
fn omegas(stat: &mut Stat) -> Vec<f64> {
    let mut v = Vec::new();
    for &k in &KS {
        for &m in &MS {
            let mut w = f64::NAN;
            assert_eq!(unsafe { dc_omega0(k, m, &mut w) }, DC_OK);
            stat.add(w, (k / m).sqrt(), || format!("k={k:e} m={m:e}"));
            v.push(w);
        }
    }
    v
}

/// g(ζ) written from the definition: ζ acos ζ/√(1−ζ²), acosh above critical damping, 1 at ζ = 1
/// (1 − ζ and 1 + ζ are exact near ζ = 1, so the closed form is accurate right up to it). libm's
/// acosh (log1p form near 1), not std's ln(x + √(x²−1)), which loses 7e-11 at ζ = 1 + 1e-12.
fn g_ref(z: f64) -> f64 {
    if z == 1.0 {
        1.0
    } else if z < 1.0 {
        if z == 0.0 {
            0.0
        } else {
            z * libm::acos(z) / ((1.0 - z) * (1.0 + z)).sqrt()
        }
    } else {
        z * libm::acosh(z) / ((z - 1.0) * (z + 1.0)).sqrt()
    }
}

/// Phase of maximum overlap of the linear image: u_m = g/ζ (π/2 when undamped).
fn u_max_ref(z: f64) -> f64 {
    if z == 0.0 { PI / 2.0 } else { g_ref(z) / z }
}

fn zeta_of(alpha: f64, p: f64) -> f64 {
    alpha / scale(p)
}

fn call(f: impl FnOnce(*mut f64) -> i32) -> (i32, f64) {
    let mut o = f64::NAN;
    let s = f(&mut o);
    (s, o)
}

#[test]
fn powerlaw_calculus_extremes() {
    let mut s_omega = Stat::new("dc_omega0", "sqrt(k/m)", 4e-16);
    let ws = omegas(&mut s_omega);
    let mut s_alpha = Stat::new("dc_alpha_from_e", "e -> alpha -> e round trip", 5e-13);
    let mut s_alpha_cf = Stat::new("dc_alpha_from_e (overlap)", "closed form via ln e", 4e-16);
    let mut s_e = Stat::new(
        "dc_e_from_alpha",
        "exp(-2g), exp(-pi zeta/omega) here",
        1e-13,
    );
    let mut s_dmax = Stat::new("dc_max_overlap", "A (v0/w0)^q e^(-q g), powf", 2e-14);
    let mut s_tmax = Stat::new(
        "dc_time_of_max_overlap",
        "p=1: u_m/w0; alpha=0: Beta fn",
        1e-12,
    );
    let mut s_tmax_sc = Stat::new("dc_time_of_max_overlap", "scaling (v0/w0)^(q-1)/w0", 1e-13);
    let mut s_to = Stat::new(
        "dc_contact_duration (overlap)",
        "p=1: pi/(w w0); alpha=0: Beta",
        1e-12,
    );
    let mut s_to_sc = Stat::new("dc_contact_duration (overlap)", "scaling", 1e-13);
    let mut s_tf = Stat::new(
        "dc_contact_duration (force)",
        "p=1: 2u_m/w0; alpha=0: Beta",
        1e-12,
    );
    let mut s_tf_sc = Stat::new("dc_contact_duration (force)", "scaling", 1e-13);
    let mut s_lvl = Stat::new("dc_contact_duration_level 0", "level 4", 1e-5);
    let mut s_en = Stat::new("dc_energy_partition", "closed forms via g here", 1e-13);
    let mut s_dtl = Stat::new(
        "dc_dt_linearised",
        "2/(w0 sqrt(p) d0^((p-1)/2)), powf",
        2e-14,
    );
    let mut s_dtl_crit = Stat::new("dc_dt_linearised", "dc_dt_crit / sqrt(2p/(p+1))", 2e-14);
    let mut s_dts = Stat::new("dc_dt_static", "(2/w_eq)/(sqrt(1+z^2)+z), powf", 2e-14);
    let mut no_event = 0usize;
    let mut overflow = 0usize;

    for &p in &PS {
        let q = 2.0 / (p + 1.0);
        let amp = (0.5 * (p + 1.0)).powf(1.0 / (p + 1.0));
        // ∫_0^1 du/√(1−u^{p+1}) = B(1/(p+1), 1/2)/(p+1), through libm's lgamma.
        let a = 1.0 / (p + 1.0);
        let beta = (libm::lgamma(a) + libm::lgamma(0.5) - libm::lgamma(a + 0.5)).exp() / (p + 1.0);
        for alpha in alphas(p) {
            let z = zeta_of(alpha, p);
            let g = g_ref(z);
            // Calibration and energy: independent of v0, omega0.
            for c in [DC_END_OVERLAP, DC_END_FORCE] {
                let (s, e) = call(|o| unsafe { dc_e_from_alpha(alpha, p, c, o) });
                assert_eq!(s, DC_OK);
                let e_want = if c == DC_END_FORCE {
                    (-2.0 * g).exp()
                } else if z < 1.0 {
                    // From α and s = √2·√(p+1) directly: 1 − ζ² = (s − α)(s + α)/s² with s − α
                    // exact, so the steep e(α) near critical damping is not fed a rounded ζ.
                    let sc = scale(p);
                    (-PI * alpha / ((sc - alpha) * (sc + alpha)).sqrt()).exp()
                } else {
                    0.0
                };
                if e_want > 0.0 {
                    s_e.add(e, e_want, || format!("p={p} zeta={z:e} crit={c}"));
                    let (s, a2) = call(|o| unsafe { dc_alpha_from_e(e, p, c, o) });
                    assert_eq!(s, DC_OK);
                    let (_, e2) = call(|o| unsafe { dc_e_from_alpha(a2, p, c, o) });
                    s_alpha.add(e2, e, || format!("p={p} e={e:e} crit={c}"));
                    if c == DC_END_OVERLAP {
                        let l = -e.ln();
                        s_alpha_cf.add(a2, scale(p) * l / (PI * PI + l * l).sqrt(), || {
                            format!("p={p} e={e:e}")
                        });
                    }
                } else {
                    assert_eq!(e, 0.0, "overdamped overlap end must give e = 0");
                }
                let mut en = dc_energy::default();
                assert_eq!(unsafe { dc_energy_partition(p, alpha, c, &mut en) }, DC_OK);
                let ef = (-2.0 * g).exp();
                let at = || format!("p={p} zeta={z:e} crit={c}");
                s_en.add(en.loading, -(-2.0 * g).exp_m1(), at);
                if c == DC_END_FORCE {
                    s_en.add(en.returned, ef * ef, at);
                    if z > 0.0 {
                        s_en.add(en.clamped, 4.0 * z * z * ef * ef, at);
                    }
                    // unloading = e_F − e_F² − clamped: compared where the subtraction is benign.
                    let unl = ef - ef * ef * (1.0 + 4.0 * z * z);
                    if unl > 0.1 * ef {
                        s_en.add(en.unloading, unl, at);
                    }
                } else if z < 1.0 {
                    let eo = e_want;
                    s_en.add(en.returned, eo * eo, at);
                    if ef - eo * eo > 0.1 * ef {
                        s_en.add(en.unloading, ef - eo * eo, at);
                    }
                }
                let sum = en.loading + en.unloading + en.returned + en.clamped;
                s_en.add(sum, 1.0, at);
            }
            for &w0 in &ws {
                for &v0 in &V0S {
                    let x = v0 / w0;
                    let at = || format!("p={p} zeta={z:e} v0={v0:e} w0={w0:.1e}");
                    // δ_max: A x^q e^{−q g}, with x^q by powf (not through logarithms).
                    let (s, d) = call(|o| unsafe { dc_max_overlap(p, alpha, v0, w0, o) });
                    assert_eq!(s, DC_OK);
                    let d_want = amp * x.powf(q) * (-q * g).exp();
                    s_dmax.add(d, d_want, at);
                    // Times: t = (v0/w0)^{q−1}/w0 × (the same at v0 = w0 = 1).
                    let tscale = x.powf(q - 1.0) / w0;
                    let (s, tm) = call(|o| unsafe { dc_time_of_max_overlap(p, alpha, v0, w0, o) });
                    assert_eq!(s, DC_OK);
                    let (_, tm1) =
                        call(|o| unsafe { dc_time_of_max_overlap(p, alpha, 1.0, 1.0, o) });
                    s_tmax_sc.add(tm, tm1 * tscale, at);
                    let (sf, tf) =
                        call(|o| unsafe { dc_contact_duration(p, alpha, v0, w0, DC_END_FORCE, o) });
                    assert_eq!(sf, DC_OK);
                    let (_, tf1) = call(|o| unsafe {
                        dc_contact_duration(p, alpha, 1.0, 1.0, DC_END_FORCE, o)
                    });
                    s_tf_sc.add(tf, tf1 * tscale, at);
                    let (so, to) = call(|o| unsafe {
                        dc_contact_duration(p, alpha, v0, w0, DC_END_OVERLAP, o)
                    });
                    if z >= 1.0 {
                        assert_eq!(so, DC_ERR_NO_EVENT, "{}", at());
                        no_event += 1;
                    } else {
                        // Near critical damping a p > 1 contact creeps back to zero overlap: with
                        // c = (1−q)ζ/ω, Stirling on the closed form gives
                        // ln τ ≈ ln(A q x^{q−1}/ω0) − q ln ω + πc + lnΓ(q) − q ln c, which exceeds
                        // ln(DBL_MAX) ≈ 709.8 already for 1 − ζ ~ 4e-7 at p = 1.5. The export must
                        // report DC_ERR_RESULT_RANGE exactly when τ overflows.
                        let om = ((1.0 - z) * (1.0 + z)).sqrt();
                        let cc = (1.0 - q) * z / om;
                        let ln_tau = (amp * q).ln() + (q - 1.0) * x.ln() - w0.ln() - q * om.ln()
                            + PI * cc
                            + libm::lgamma(q)
                            - q * cc.ln();
                        if so == DC_ERR_RESULT_RANGE {
                            assert!(
                                cc > 100.0 && ln_tau > 709.0,
                                "RESULT_RANGE at ln tau ~ {ln_tau}: {}",
                                at()
                            );
                            overflow += 1;
                        } else {
                            assert_eq!(so, DC_OK, "{}", at());
                            assert!(
                                !(cc > 100.0 && ln_tau > 711.0),
                                "finite tau at ln tau ~ {ln_tau}: {}",
                                at()
                            );
                            let (s1, to1) = call(|o| unsafe {
                                dc_contact_duration(p, alpha, 1.0, 1.0, DC_END_OVERLAP, o)
                            });
                            if s1 == DC_OK && (to1 * tscale).is_finite() {
                                s_to_sc.add(to, to1 * tscale, at);
                            }
                        }
                    }
                    // Closed forms: linear law, and undamped contacts of any p.
                    if p == 1.0 {
                        let um = if z < 1.0 && z != 0.0 {
                            libm::acos(z) / ((1.0 - z) * (1.0 + z)).sqrt()
                        } else if z > 1.0 {
                            libm::acosh(z) / ((z - 1.0) * (z + 1.0)).sqrt()
                        } else {
                            u_max_ref(z)
                        };
                        s_tmax.add(tm, um / w0, at);
                        s_tf.add(tf, 2.0 * um / w0, at);
                        if z < 1.0 {
                            s_to.add(to, PI / (((1.0 - z) * (1.0 + z)).sqrt() * w0), at);
                        }
                    } else if alpha == 0.0 {
                        let t_half = d_want / v0 * beta;
                        s_tmax.add(tm, t_half, at);
                        s_to.add(to, 2.0 * t_half, at);
                        s_tf.add(tf, 2.0 * t_half, at);
                    }
                    // Accuracy levels: the cheapest against the most accurate.
                    let (_, t0) = call(|o| unsafe {
                        dc_contact_duration_level(p, alpha, v0, w0, DC_END_FORCE, 0, o)
                    });
                    s_lvl.add(t0, tf, at);
                    // Time steps.
                    let (s, dtl) = call(|o| unsafe { dc_dt_linearised(p, v0, w0, o) });
                    assert_eq!(s, DC_OK);
                    let d0 = ((p + 1.0) / 2.0).powf(1.0 / (p + 1.0)) * x.powf(q);
                    s_dtl.add(dtl, 2.0 / (w0 * p.sqrt() * d0.powf(0.5 * (p - 1.0))), at);
                    let (_, dtc) = call(|o| unsafe { dc_dt_crit(p, v0, w0, o) });
                    s_dtl_crit.add(dtl, dtc / (2.0 * p / (p + 1.0)).sqrt(), at);
                    // Static step: accel = v0 stands in for a load over many decades.
                    let (s, dts) = call(|o| unsafe { dc_dt_static(p, alpha, w0, v0, o) });
                    assert_eq!(s, DC_OK);
                    let deq = (v0 / (w0 * w0)).powf(1.0 / p);
                    let zl = alpha / (2.0 * p.sqrt());
                    let weq = w0 * p.sqrt() * deq.powf(0.5 * (p - 1.0));
                    if weq.is_finite() && weq > 0.0 {
                        s_dts.add(dts, 2.0 / weq / ((1.0 + zl * zl).sqrt() + zl), at);
                    }
                }
            }
        }
    }
    println!("overdamped/critical overlap-end durations rejected with DC_ERR_NO_EVENT: {no_event}");
    println!(
        "near-critical overlap-end durations beyond DBL_MAX, DC_ERR_RESULT_RANGE as predicted: {overflow}"
    );
    print_table(
        "Power-law calculus and time steps (cargo test --release --test extremes -- --nocapture)",
        &[
            s_omega, s_alpha, s_alpha_cf, s_e, s_dmax, s_tmax, s_tmax_sc, s_to, s_to_sc, s_tf,
            s_tf_sc, s_lvl, s_en, s_dtl, s_dtl_crit, s_dts,
        ],
    );
}

#[test]
fn powerlaw_vs_ode_reference_near_critical_damping() {
    // The adaptive Dormand–Prince reference of tests/common at moderate (v0, ω0), around and at
    // critical damping and strongly overdamped, including p = 20.
    let mut s_d = Stat::new("dc_max_overlap", "ODE reference", 1e-10);
    let mut s_t = Stat::new("dc_time_of_max_overlap", "ODE reference", 1e-9);
    let mut s_f = Stat::new("dc_contact_duration (force)", "ODE reference", 1e-9);
    let mut s_e = Stat::new("dc_e_from_alpha (force)", "ODE reference", 1e-9);
    let mut s_o = Stat::new("dc_contact_duration (overlap)", "ODE reference", 1e-9);
    for p in [1.0, 1.5, 2.0, 3.0, 20.0] {
        for z in [0.3, 0.9, 1.0 - 1e-12, 1.0, 1.0 + 1e-12, 2.0, 10.0] {
            let alpha = z * scale(p);
            let (v0, w0) = (0.7, 300.0);
            let r = collide(p, alpha, v0, w0, EndCriterion::Force, 1e-12);
            let at = || format!("p={p} zeta={z:e}");
            s_d.add(
                call(|o| unsafe { dc_max_overlap(p, alpha, v0, w0, o) }).1,
                r.delta_max,
                at,
            );
            s_t.add(
                call(|o| unsafe { dc_time_of_max_overlap(p, alpha, v0, w0, o) }).1,
                r.t_max,
                at,
            );
            s_f.add(
                call(|o| unsafe { dc_contact_duration(p, alpha, v0, w0, DC_END_FORCE, o) }).1,
                r.tau,
                at,
            );
            s_e.add(
                call(|o| unsafe { dc_e_from_alpha(alpha, p, DC_END_FORCE, o) }).1,
                r.e,
                at,
            );
            if z < 0.95 {
                let r = collide(p, alpha, v0, w0, EndCriterion::Overlap, 1e-12);
                s_o.add(
                    call(|o| unsafe { dc_contact_duration(p, alpha, v0, w0, DC_END_OVERLAP, o) }).1,
                    r.tau,
                    at,
                );
            }
        }
    }
    print_table(
        "Power-law calculus vs the ODE reference (rtol 1e-12)",
        &[s_d, s_t, s_f, s_e, s_o],
    );
}

#[test]
fn trajectory_extremes() {
    // Sampled collisions at the extremes: every sample finite, the first at impact, the last at the
    // end event with exit speed e·v0 (e from dc_e_from_alpha), the end time equal to
    // dc_contact_duration, and each force equal to the law recomputed here from (δ, v).
    let mut s_e = Stat::new("dc_contact_trajectory", "exit speed vs e v0", 1e-11);
    let mut s_t = Stat::new(
        "dc_contact_trajectory",
        "end time vs duration (level 4)",
        1e-13,
    );
    let mut s_f = Stat::new("dc_contact_trajectory", "force vs law from (d, v)", 1e-12);
    const N: usize = 33;
    for p in [1.0, 1.5, 2.0, 5.0, 20.0] {
        for z in [
            0.0,
            1e-6,
            0.5,
            0.99,
            1.0 - 1e-12,
            1.0,
            1.0 + 1e-12,
            10.0,
            100.0,
            1e4,
        ] {
            let alpha = z * scale(p);
            for c in [DC_END_OVERLAP, DC_END_FORCE] {
                for (v0, w0, m) in [
                    (1e-9, 1e-1, 1e3),
                    (1.0, 1e3, 1e-6),
                    (1e4, 1e6, 1e-12),
                    (1e-3, 1e9, 1.0),
                ] {
                    let mut b = [[0.0f64; N]; 4];
                    let [t, d, v, f] = &mut b;
                    let s = unsafe {
                        dc_contact_trajectory(
                            p,
                            alpha,
                            v0,
                            w0,
                            m,
                            c,
                            4,
                            N,
                            t.as_mut_ptr(),
                            d.as_mut_ptr(),
                            v.as_mut_ptr(),
                            f.as_mut_ptr(),
                            N,
                        )
                    };
                    let at = || format!("p={p} zeta={z:e} v0={v0:e} w0={w0:e} crit={c}");
                    if c == DC_END_OVERLAP && z >= 1.0 {
                        assert_eq!(s, DC_ERR_NO_EVENT, "{}", at());
                        continue;
                    }
                    if c == DC_END_OVERLAP && p > 1.0 && z == 1.0 - 1e-12 {
                        // τ beyond DBL_MAX (see powerlaw_calculus_extremes).
                        assert_eq!(s, DC_ERR_RESULT_RANGE, "{}", at());
                        continue;
                    }
                    assert_eq!(s, DC_OK, "{}", at());
                    assert!(b.iter().flatten().all(|x| x.is_finite()), "{}", at());
                    assert_eq!((b[0][0], b[1][0], b[2][0]), (0.0, 0.0, v0));
                    let (_, e) = call(|o| unsafe { dc_e_from_alpha(alpha, p, c, o) });
                    s_e.add(-b[2][N - 1] / v0, e, at);
                    let (_, tau) = call(|o| unsafe { dc_contact_duration(p, alpha, v0, w0, c, o) });
                    s_t.add(b[0][N - 1], tau, at);
                    let k = m * w0 * w0;
                    for i in 1..N - 1 {
                        let (di, vi) = (b[1][i], b[2][i]);
                        let el = k * di.powf(p);
                        let da = alpha * (m * k).sqrt() * di.powf(0.5 * (p - 1.0)) * vi;
                        // Relative to the larger term: the total passes through zero.
                        let got = b[3][i];
                        // Near critical damping at p = 1 the interior samples underflow to 0
                        // (x ~ e^{−ζu} at phases u ~ 1e5): then the force must be exactly 0.
                        let big = el.abs().max(da.abs());
                        let err = if big == 0.0 {
                            got.abs()
                        } else {
                            (got - (el + da)).abs() / big
                        };
                        s_f.add(1.0 + err, 1.0, || format!("{} sample {i}", at()));
                    }
                }
            }
        }
    }
    print_table("Trajectories", &[s_e, s_t, s_f]);
}

#[test]
fn trajectory_huge_exponent() {
    // p → ∞ (q = 2/(p+1) → 0, where q − 1 rounds to −1 from p ≈ 2e16 on): an undamped contact is
    // time-symmetric, so the middle sample of an odd n lies at exactly τ/2 (independent of any
    // quadrature). Found by proptest_ffi at p = 7.58e195, v0 = 1.1e-308: the middle time was NaN
    // with DC_OK (the weight's leading moment 1/(ν+1) with ν + 1 recomputed as 0).
    let mut s_t = Stat::new(
        "dc_contact_trajectory",
        "middle time vs tau/2 (undamped, huge p)",
        1e-12,
    );
    for p in [1e10, 1e17, 1e50, 1e195, 7.5784214180818e195, 1e300] {
        for v0 in [1.0, 1e-300, 1.1125369292536293e-308] {
            for n in [3usize, 65, 1001] {
                let mut b = vec![vec![0.0f64; n]; 4];
                let (t, rest) = b.split_at_mut(1);
                let (d, rest) = rest.split_at_mut(1);
                let (v, f) = rest.split_at_mut(1);
                let (t, d, v, f) = (&mut t[0], &mut d[0], &mut v[0], &mut f[0]);
                let at = || format!("p={p:e} v0={v0:e} n={n}");
                for crit in [DC_END_OVERLAP, DC_END_FORCE] {
                    let s = unsafe {
                        dc_contact_trajectory(
                            p,
                            0.0,
                            v0,
                            1.0,
                            1.0,
                            crit,
                            2,
                            n,
                            t.as_mut_ptr(),
                            d.as_mut_ptr(),
                            v.as_mut_ptr(),
                            f.as_mut_ptr(),
                            n,
                        )
                    };
                    assert_eq!(s, DC_OK, "{}", at());
                    assert!(
                        t.iter()
                            .chain(d.iter())
                            .chain(v.iter())
                            .chain(f.iter())
                            .all(|x| x.is_finite()),
                        "{}",
                        at()
                    );
                    s_t.add(t[n / 2], 0.5 * t[n - 1], at);
                }
            }
        }
    }
    print_table("Trajectories at huge p", &[s_t]);
}

#[test]
fn viscoelastic_extremes() {
    let mut s_rt = Stat::new("dc_viscoelastic_b_from_e + _e", "e -> b -> e", 1e-12);
    let mut s_ref = Stat::new("dc_viscoelastic_e", "dc_viscoelastic_e_reference", 1e-10);
    let mut s_ser = Stat::new(
        "dc_viscoelastic_e_series",
        "reference, b <= 0.4 (abs.)",
        1e-6,
    );
    let mut s_b = Stat::new("dc_viscoelastic_b", "gamma k^-0.6 v^0.2, powf", 2e-15);
    let mut s_kg = Stat::new("dc_viscoelastic_k_gamma", "rho/m, 1.5 A rho/m", 4e-16);
    let mut s_es = Stat::new(
        "dc_viscoelastic_e_of_speed",
        "e(b) with b computed here",
        2e-14,
    );
    let mut s_beta = Stat::new("dc_viscoelastic_beta_from_e", "b(e)/v^0.2", 2e-15);
    let mut s_a = Stat::new(
        "dc_viscoelastic_a_from_e",
        "beta/(1.5 rho^0.4 m^-0.4)",
        4e-15,
    );
    let mut s_v = Stat::new("dc_viscoelastic_speed_for_e", "(b(e)/beta)^5", 4e-15);
    let mut s_mono = Stat::new("dc_viscoelastic_e", "monotone in b (violations)", 0.0);
    for c in [DC_END_OVERLAP, DC_END_FORCE] {
        // Round trip over e from 1e-12 to 1 − 1e-12 (log-spaced in e and in 1 − e).
        let mut es: Vec<f64> = (0..=240)
            .map(|i| 10f64.powf(-12.0 + 12.0 * i as f64 / 240.0))
            .collect();
        es.extend((1..=240).map(|i| 1.0 - 10f64.powf(-12.0 + 11.0 * i as f64 / 240.0)));
        for &e in &es {
            if e >= 1.0 {
                continue;
            }
            let (s, b) = call(|o| unsafe { dc_viscoelastic_b_from_e(e, c, o) });
            assert_eq!(s, DC_OK, "e={e}");
            let (_, back) = call(|o| unsafe { dc_viscoelastic_e(b, c, o) });
            s_rt.add(back, e, || format!("e={e:e} crit={c}"));
            for v in [1e-9, 1e-3, 1.0, 1e4] {
                let (_, beta) = call(|o| unsafe { dc_viscoelastic_beta_from_e(e, v, c, o) });
                s_beta.add(beta, b / v.powf(0.2), || format!("e={e:e} v={v:e}"));
                let (_, vv) = call(|o| unsafe { dc_viscoelastic_speed_for_e(e, beta, c, o) });
                s_v.add(vv, (b / beta).powf(5.0), || format!("e={e:e} v={v:e}"));
                for (rho, m) in [(1e2, 1e-12), (1e8, 1e-3), (1e12, 1e3)] {
                    let (_, a) = call(|o| unsafe { dc_viscoelastic_a_from_e(e, v, rho, m, c, o) });
                    s_a.add(a, beta / (1.5 * rho.powf(0.4) * m.powf(-0.4)), || {
                        format!("e={e:e} rho={rho:e} m={m:e}")
                    });
                }
            }
        }
        // Full-range tier against the reference integrator where the latter is affordable.
        let bmax: f64 = if c == DC_END_OVERLAP { 30.0 } else { 300.0 };
        for i in 0..=60 {
            let b = if i == 0 {
                0.0
            } else {
                1e-6 * (bmax / 1e-6).powf(i as f64 / 60.0)
            };
            let (_, e) = call(|o| unsafe { dc_viscoelastic_e(b, c, o) });
            let (s, r) = call(|o| unsafe { dc_viscoelastic_e_reference(b, c, o) });
            assert_eq!(s, DC_OK);
            s_ref.add(e, r, || format!("b={b:e} crit={c}"));
            if b <= 0.4 {
                let (_, se) = call(|o| unsafe { dc_viscoelastic_e_series(b, c, o) });
                s_ser.add(1.0 + (se - r).abs(), 1.0, || format!("b={b:e} crit={c}"));
            }
        }
        // Monotone and positive over 1e-300 .. 1e300.
        let mut prev = 1.0;
        for i in 0..=600 {
            let b = 10f64.powf(-300.0 + i as f64);
            let (s, e) = call(|o| unsafe { dc_viscoelastic_e(b, c, o) });
            assert_eq!(s, DC_OK);
            s_mono.add(1.0 + if e > prev { 1.0 } else { 0.0 }, 1.0, || {
                format!("b={b:e}")
            });
            assert!((0.0..=1.0).contains(&e));
            prev = e;
        }
        // Physical units over many decades.
        for &k in &[1e-3, 1.0, 1e6, 1e12] {
            for &gamma in &[0.0, 1e-6, 1.0, 1e5] {
                for &v in &V0S {
                    let at = || format!("k={k:e} gamma={gamma:e} v={v:e}");
                    let (s, b) = call(|o| unsafe { dc_viscoelastic_b(k, gamma, v, o) });
                    assert_eq!(s, DC_OK);
                    let b_want = gamma * k.powf(-0.6) * v.powf(0.2);
                    if gamma > 0.0 {
                        s_b.add(b, b_want, at);
                    } else {
                        assert_eq!(b, 0.0);
                    }
                    let (_, e) = call(|o| unsafe { dc_viscoelastic_e_of_speed(k, gamma, v, c, o) });
                    let (_, e_want) = call(|o| unsafe { dc_viscoelastic_e(b_want, c, o) });
                    s_es.add(e, e_want, at);
                }
            }
        }
    }
    for &rho in &[1e-3, 1e5, 1e12] {
        for &a in &[0.0, 1e-9, 1e-3] {
            for &m in &[1e-12, 1e-3, 1e3] {
                let (mut k, mut g) = (f64::NAN, f64::NAN);
                assert_eq!(
                    unsafe { dc_viscoelastic_k_gamma(rho, a, m, &mut k, &mut g) },
                    DC_OK
                );
                s_kg.add(k, rho / m, || format!("rho={rho:e} m={m:e}"));
                if a > 0.0 {
                    s_kg.add(g, 1.5 * a * rho / m, || {
                        format!("rho={rho:e} a={a:e} m={m:e}")
                    });
                }
            }
        }
    }
    print_table(
        "Viscoelastic exports",
        &[
            s_rt, s_ref, s_ser, s_b, s_kg, s_es, s_beta, s_a, s_v, s_mono,
        ],
    );
}

#[test]
fn force_kernels_near_underflow() {
    // Overlaps down to subnormals: the force must be finite, never NaN, and equal to the law
    // evaluated here with powf (relative to the larger of its two terms; terms that underflow in
    // both are 0).
    let mut stats = Vec::new();
    let ds = [
        1e-3,
        1e-30,
        1e-150,
        1e-300,
        f64::MIN_POSITIVE,
        1e-310,
        5e-324,
    ];
    let mut sub = Stat::new(
        "dc_normal_force_checked p=2, m d < 2.2e-308",
        "same (documented loss)",
        1.0,
    );
    for p in [1.0, 1.5, 2.0, 3.7, 20.0] {
        let name: &'static str = match p {
            x if x == 1.0 => "dc_normal_force_checked p=1",
            x if x == 1.5 => "dc_normal_force_checked p=1.5",
            x if x == 2.0 => "dc_normal_force_checked p=2",
            x if x == 3.7 => "dc_normal_force_checked p=3.7",
            _ => "dc_normal_force_checked p=20",
        };
        let mut st = Stat::new(name, "k d^p + c d^h vn, powf", 4e-15);
        for c in [DC_END_OVERLAP, DC_END_FORCE] {
            for &k in &[1e-3, 1e4, 1e12] {
                let mut pair: dc_pair = unsafe { std::mem::zeroed() };
                assert_eq!(unsafe { dc_pair_powerlaw(p, k, 0.3, c, &mut pair) }, DC_OK);
                for &d in &ds {
                    for &vn in &[-1e3, -1.0, 0.0, 1e-6, 1.0, 1e3] {
                        let m = 1e-3;
                        let (s, f) =
                            call(|o| unsafe { dc_normal_force_checked(&pair, d, vn, 1e-3, m, o) });
                        assert_eq!(s, DC_OK);
                        let g = unsafe { dc_normal_force(&pair, d, vn, 1e-3, m) };
                        assert_eq!(f.to_bits(), g.to_bits());
                        let el = k * d.powf(p);
                        let da = pair.alpha * (m * k).sqrt() * d.powf(0.5 * (p - 1.0)) * vn;
                        let mut want = el + da;
                        if c == DC_END_FORCE {
                            want = want.max(0.0);
                        }
                        let big = el.abs().max(da.abs());
                        let err = if big == 0.0 {
                            f.abs()
                        } else {
                            (f - want).abs() / big
                        };
                        // Subnormal terms carry absolute rounding ~5e-324: measured relative to
                        // the smallest normal number there.
                        let err = if big < f64::MIN_POSITIVE {
                            (f - want).abs() / f64::MIN_POSITIVE
                        } else {
                            err
                        };
                        let at = || format!("k={k:e} d={d:e} vn={vn:e} crit={c}");
                        if p == 2.0 && m * d < f64::MIN_POSITIVE && vn != 0.0 {
                            // The p = 2 kernel forms √(m d) with one square root: the product
                            // underflows first (documented in docs/robustness.md).
                            sub.add(1.0 + err, 1.0, at);
                        } else {
                            st.add(1.0 + err, 1.0, at);
                        }
                    }
                }
            }
        }
        stats.push(st);
    }
    stats.push(sub);
    // Hertz and viscoelastic pairs: forces at subnormal overlaps are finite and non-negative
    // when compressing.
    let mut st = Stat::new(
        "Hertz/viscoelastic kernels",
        "finite, >= 0 when compressing",
        0.0,
    );
    for c in [DC_END_OVERLAP, DC_END_FORCE] {
        let mut h: dc_pair = unsafe { std::mem::zeroed() };
        let mut ve: dc_pair = unsafe { std::mem::zeroed() };
        assert_eq!(
            unsafe { dc_pair_hertz(70e9, 0.3, 70e9, 0.3, 0.5, c, &mut h) },
            DC_OK
        );
        assert_eq!(
            unsafe { dc_pair_viscoelastic(70e9, 0.3, 70e9, 0.3, 1e-6, c, &mut ve) },
            DC_OK
        );
        for pr in [&h, &ve] {
            for &d in &ds {
                for &r in &[1e-300, 1e-6, 1.0] {
                    let (s, f) =
                        call(|o| unsafe { dc_normal_force_checked(pr, d, 1.0, r, 1e-3, o) });
                    assert_eq!(s, DC_OK);
                    st.add(1.0 + if f >= 0.0 { 0.0 } else { 1.0 }, 1.0, || {
                        format!("d={d:e} r={r:e}")
                    });
                }
            }
        }
    }
    stats.push(st);
    print_table("Force kernels at overlaps near underflow", &stats);
}
