//! Verification beyond Chung & Ooi 1–4: the MFiX DEM verification problems DEM01–DEM05 and
//! Chung & Ooi (2011) tests 5–8, each run through the C ABI by a velocity-Verlet host
//! (tests/common/verification.rs) and checked against a reference computed without the library
//! (closed forms of the linear spring–dashpot with gravity, a matrix exponential, rigid-body
//! impulse limits, the no-slip Hill integration of tests/common/oblique.rs), tolerance stated
//! per check. Run: `cargo test --profile ci --test verification -- --nocapture` (prints every
//! figure quoted in docs/reference/verification.md).
#![allow(clippy::unwrap_used, clippy::indexing_slicing)]

#[path = "common/oblique.rs"]
mod oblique;
#[path = "common/verification.rs"]
mod verification;

use demcontact::ffi::contact::*;
use demcontact::ffi::status::*;
use std::f64::consts::PI;
use verification::*;

fn ball_mass(r: f64, rho: f64) -> f64 {
    rho * 4.0 / 3.0 * PI * r.powi(3)
}

/// DEM01: the centre height follows the exact three-stage solution (free fall, damped contact
/// with gravity, free flight). Velocity Verlet is exact in free fall; the error comes from the
/// contact's onset and end falling between steps, first order in dt. Asserted over 8 onset phases
/// (drop heights a fraction of a step apart), to 0.2 s after the rebound: the largest error
/// ≤ 5e-3 of the drop height at dt = t_c/200 (measured 3.1e-3 at e = 0.5), and ≥ 5× smaller
/// at t_c/2000.
#[test]
fn dem01_free_fall_and_bounce() {
    let kn = 1e6;
    let m = ball_mass(R01, RHO01);
    for e in [1.0, 0.9, 0.5] {
        let tc = PI / (kn / m).sqrt() / (1.0 - zeta_linear(e).powi(2)).sqrt();
        let err = |div: f64| {
            let dt = tc / div;
            (0..8)
                .map(|k| {
                    let h0 = 0.5 + f64::from(k) / 8.0 * 3.13 * dt;
                    let t_end = (2.0 * (h0 - R01) / G).sqrt() + tc + 0.2;
                    dem01(kn, e, h0, dt, t_end)
                        .iter()
                        .map(|&(_, y, x)| (y - x).abs())
                        .fold(0.0, f64::max)
                        / (h0 - R01)
                })
                .fold(0.0, f64::max)
        };
        let (e1, e2) = (err(200.0), err(2000.0));
        println!(
            "DEM01 e = {e}: max |y − y_exact|/(h0 − r) = {e1:.3e} at t_c/200, {e2:.3e} at t_c/2000 (8 onset phases)"
        );
        assert!(e1 < 5e-3, "DEM01 e = {e}: {e1:e}");
        assert!(e1 / e2 > 5.0, "DEM01 e = {e}: ratio {}", e1 / e2);
    }
}

/// DEM02: apex heights of the first five bounces. Against the exact linear-spring solution with
/// gravity in contact: ≤ 1e-3 of the drop height at dt = t_c/500 and ≥ 3× smaller at t_c/5000
/// (the onset error, first order in dt). Against the hard-sphere limit
/// (h0 − r) e^{2k} + r the difference is physical (gravity during the contact) and falls as
/// 1/√kn: printed, and asserted to shrink ≥ 5× from kn = 1e5 to 1e7.
#[test]
fn dem02_bouncing_particle() {
    let h0 = 0.5;
    let m = ball_mass(R01, RHO01);
    let mut hard_gap = Vec::new();
    for kn in [1e5, 1e7] {
        for e in [0.9, 0.7] {
            let tc = PI / (kn / m).sqrt() / (1.0 - zeta_linear(e).powi(2)).sqrt();
            let (exact, hard) = dem02_exact(kn, m, e, h0, 5);
            let worst_at = |div: f64| {
                dem02(kn, e, h0, tc / div, 5)
                    .iter()
                    .zip(&exact)
                    .map(|(g, x)| (g - x).abs() / (h0 - R01))
                    .fold(0.0, f64::max)
            };
            let (worst, fine) = (worst_at(500.0), worst_at(5000.0));
            let gap = exact
                .iter()
                .zip(&hard)
                .map(|(x, h)| (x - h).abs() / (h0 - R01))
                .fold(0.0, f64::max);
            println!(
                "DEM02 kn = {kn:e}, e = {e}: library vs exact {worst:.2e} at t_c/500, {fine:.2e} at t_c/5000, exact vs hard sphere {gap:.2e} (of h0 − r)"
            );
            assert!(worst < 1e-3, "DEM02 kn {kn} e {e}: {worst:e}");
            assert!(
                worst / fine > 3.0,
                "DEM02 kn {kn} e {e}: {worst:e} {fine:e}"
            );
            if e == 0.9 {
                hard_gap.push(gap);
            }
        }
    }
    assert!(
        hard_gap[0] / hard_gap[1] > 5.0,
        "hard-sphere limit: {hard_gap:?}"
    );
}

/// DEM03: two particles compressed between two walls (linear, always in contact). Positions
/// against the matrix exponential of the linear system over 40 t_c: ≤ 5e-3 of the initial
/// overlap at dt = t_c/200 (a phase error that grows with time). No onset (the contacts are
/// closed from t = 0), so the order is the integrator's: second undamped (4× ± 1 smaller at
/// t_c/400), first damped (2× ± 0.5: the host's velocity Verlet feeds the dashpot the half-step
/// velocity, as LAMMPS does).
#[test]
fn dem03_stacked_particles() {
    let kn = 1e6;
    let m = ball_mass(R03, RHO03);
    for e in [1.0, 0.7, 0.3] {
        let tc = PI / (kn / m).sqrt();
        let d0 = 0.1 * R03;
        let worst_at = |div: f64| {
            dem03(kn, e, tc / div, 40.0 * tc)
                .iter()
                .map(|&(_, y1, y2, x1, x2)| (y1 - x1).abs().max((y2 - x2).abs()))
                .fold(0.0, f64::max)
                / d0
        };
        let (worst, fine) = (worst_at(200.0), worst_at(400.0));
        println!(
            "DEM03 e = {e}: max |y − y_exact| / δ0 = {worst:.2e} at t_c/200, {fine:.2e} at t_c/400"
        );
        assert!(worst < 5e-3, "DEM03 e {e}: {worst:e}");
        let want = if e < 1.0 { 2.0 } else { 4.0 };
        assert!(
            (worst / fine - want).abs() < want / 4.0,
            "DEM03 e {e}: order {}",
            worst / fine
        );
    }
}

/// DEM04: slip to roll. A ball settled on the floor is launched at v0 without spin. Rigid-body
/// theory with the contact's lever a = r − δ/2 (δ the static overlap m g/k_n, λ = r²/a²):
/// v = v0 − μ g t and ω a = (5/2) μ g t/λ while it slides, rolling from t_r = 2 v0/((2 + 5/λ) μ g)
/// at v = v0/(1 + 2λ/5) (λ = 1: the textbook 2 v0/(7 μ g) and (5/7) v0). The spring sticks
/// first, until k_t v0 t_s = μ m g: t is counted from t_s/2 (the ramp's delay). Asserted at
/// dt = t_c/100 (t_s is 1–2 steps): the sliding phase within 2e-3 v0 (measured ≤ 8.9e-4), the
/// onset of rolling (first |v − ω a| < 1e-3 v0) within 0.5 % of t_r, the final speed (mean over
/// the last quarter; the tangential dashpot damps the spring's oscillation) within 1e-5 of
/// v0/(1 + 2λ/5), which angular momentum about the contact point fixes exactly (measured ≤ 1e-6).
#[test]
fn dem04_slip_to_roll() {
    let (kn, v0) = (1e6, 1.0);
    let m = ball_mass(R01, RHO01);
    let tc = PI / (kn / m).sqrt();
    for mu in [0.1, 0.3, 0.6] {
        let a = R01 - 0.5 * m * G / kn;
        let lam = (R01 / a).powi(2);
        // the spring sticks until k_t v0 t = μ m g: the force ramps over t_s, a delay of t_s/2
        let ts = mu * m * G / (2.0 / 7.0 * kn * v0);
        let tr = 2.0 * v0 / ((2.0 + 5.0 / lam) * mu * G) + 0.5 * ts;
        let v_roll = v0 / (1.0 + 0.4 * lam);
        let run = dem04(kn, mu, v0, tc / 100.0, 3.0 * tr);
        let slide = run
            .iter()
            .filter(|r| r.0 > ts && r.0 < 0.8 * tr)
            .map(|&(t, v, wa)| {
                let t = t - 0.5 * ts;
                ((v - (v0 - mu * G * t)).abs()).max((wa - 2.5 * mu * G * t / lam).abs()) / v0
            })
            .fold(0.0, f64::max);
        let t_roll = run
            .iter()
            .find(|r| (r.1 - r.2).abs() < 1e-3 * v0)
            .map(|r| r.0)
            .unwrap();
        let tail: Vec<_> = run.iter().filter(|r| r.0 > 2.25 * tr).collect();
        let v_end = tail.iter().map(|r| r.1).sum::<f64>() / tail.len() as f64;
        println!(
            "DEM04 μ = {mu}: sliding phase {slide:.2e} v0, t_roll/t_r = {:.5}, v_end/v_roll − 1 = {:.2e}",
            t_roll / tr,
            v_end / v_roll - 1.0
        );
        assert!(slide < 2e-3, "DEM04 μ {mu}: sliding {slide:e}");
        assert!(
            (t_roll / tr - 1.0).abs() < 5e-3,
            "DEM04 μ {mu}: t_roll {t_roll}"
        );
        assert!(
            (v_end / v_roll - 1.0).abs() < 1e-5,
            "DEM04 μ {mu}: v_end {v_end}"
        );
    }
}

/// The rigid-body prediction of one impact when the contact slides throughout: the tangential
/// impulse is −sign(u_in) μ (1 + e_n) m* v_n (solid spheres: the contact-point velocity changes
/// by 7/2 J/m*). Returns (Δv1x, Δω1, Δv2x, Δω2) for levers a1, a2 (wall: m2 = ∞).
fn sliding_impulse(
    mu: f64,
    e_n: f64,
    vn: f64,
    u_in: f64,
    b1: (f64, f64),
    b2: Option<(f64, f64)>,
) -> [f64; 4] {
    let (m1, a1) = b1;
    let m_eff = b2.map_or(m1, |(m2, _)| m1 * m2 / (m1 + m2));
    let j = -u_in.signum() * mu * (1.0 + e_n) * m_eff * vn;
    let i1 = 0.4 * m1 * a1 * a1;
    match b2 {
        None => [j / m1, a1 * j / i1, 0.0, 0.0],
        Some((m2, a2)) => {
            let i2 = 0.4 * m2 * a2 * a2;
            [j / m1, a1 * j / i1, -j / m2, a2 * j / i2]
        }
    }
}

/// DEM05: oblique impacts on the floor, linear springs (k_t = k_n/7), e_n = 1, δ_max/r = 3e-3.
/// Gross sliding (tan θ ≥ 1.2 · 7 μ: sliding from the first step and throughout): v_x and ω equal the rigid-body
/// impulse limit within 1e-3 of v_t. No slip (μ = ∞): the contact point's tangential velocity
/// leaves reversed by β0 = cos(π √(7/2 k_t/k_n)) = cos(π/√2) (the tangential and normal
/// oscillators are independent and linear), within 5e-3 (the lever r − δ/2 against the rigid
/// r). At every angle the Coulomb bounds hold and I ω − m r v_x is conserved (angular momentum
/// about the contact point) within 1e-3 of m r v.
#[test]
fn dem05_oblique_impacts() {
    let kn = 1e8;
    let (r, rho, v) = (R01, RHO01, 1.0);
    let m = ball_mass(r, rho);
    let tc = PI / (kn / m).sqrt();
    let mu = 0.1;
    let lin = |mu: f64| {
        linear_model(kn, 1.0, |s| {
            s.tangential = DC_TANGENTIAL_LINEAR;
            s.k_t = kn / 7.0;
            s.mu = mu;
        })
    };
    let mut worst = [0.0f64; 3];
    for deg in (5..=85).step_by(5) {
        let th = f64::from(deg).to_radians();
        let (vn, vt) = (v * th.cos(), v * th.sin());
        let o = wall_impact(lin(mu), r, rho, vn, vt, 0.0, tc / 400.0);
        let e_n = o.vy / vn;
        // Coulomb: |Δv_x| ≤ μ (1 + e_n) v_n, |Δω| a ≤ (5/2) μ (1 + e_n) v_n
        let p = mu * (1.0 + e_n) * vn;
        assert!(
            (vt - o.vx) <= p * (1.0 + 1e-9) && o.vx <= vt,
            "{deg}°: Coulomb v_x"
        );
        assert!(
            o.wz.abs() * r <= 2.5 * p * (1.0 + 1e-3),
            "{deg}°: Coulomb ω"
        );
        let l = (0.4 * m * r * r * o.wz - m * r * (o.vx - vt)).abs() / (m * r * v);
        worst[2] = worst[2].max(l);
        if th.tan() >= 1.2 * 7.0 * mu {
            let d = sliding_impulse(mu, e_n, vn, vt, (m, r), None);
            let err = ((o.vx - vt - d[0]).abs() / vt).max((o.wz - d[1]).abs() * r / vt);
            worst[0] = worst[0].max(err);
        }
        let ns = wall_impact(lin(1e12), r, rho, vn, vt, 0.0, tc / 400.0);
        let beta = (ns.vx + r * ns.wz) / vt; // u_c = v_x + a ω_z (ω_z < 0 rolling along +x)
        let b0 = (PI / 2f64.sqrt()).cos();
        worst[1] = worst[1].max((beta - b0).abs());
    }
    println!(
        "DEM05: gross sliding {:.2e} of v_t, no-slip β0 {:.2e} (β0 = {:.6}), angular momentum about the contact {:.2e}",
        worst[0],
        worst[1],
        (PI / 2f64.sqrt()).cos(),
        worst[2]
    );
    assert!(
        worst[0] < 1e-3 && worst[1] < 5e-3 && worst[2] < 1e-3,
        "DEM05 {worst:?}"
    );
}

/// Chung & Ooi tests 5–8 (spin at impact; Al2O3, R = 2.5 mm, v_n = 3.9 m/s, μ = 0.092, Hertz +
/// Mindlin through the library at dt = t_H/400): 5, a spinning sphere onto the wall without
/// tangential velocity; 6, the same with v_t = 1 m/s, spins of both signs; 7, two equal spheres
/// with equal spins; 8, spheres of radii R and 2R with spins ω and ω/2. Only the contact-point
/// velocity u_in = v_t + Σ r ω enters the contact, so each test sweeps it through the three
/// regimes. Asserted: (a) gross sliding (|u_in| ≥ 1.2 · 7/2 μ (1 + e_n) v_n): every velocity and
/// spin equals the rigid-body impulse limit within 3e-3 of |u_in| (e_n = 0.98); (b) no slip
/// (μ = ∞, e_n = 1): u_out/u_in equals β0 of the independent Hill integration
/// (tests/common/oblique.rs) within 3e-3; (c) Coulomb bound |ΔP_t| ≤ μ (1 + e_n) m* v_n at every
/// spin (walls 1e-6; pairs 5e-3, the turn of the normal).
#[test]
fn chung_ooi_tests_5_to_8() {
    use oblique::{AL2O3, Body2, End, Spec, TangentRule, k_ratio, no_slip_beta};
    let mat = AL2O3;
    let (r, vn, mu) = (0.0025, 3.9, 0.092);
    let m = ball_mass(r, mat.density);
    let (_, _, tau) = oblique::hertz_elastic(m, r, mat.young / (1.0 - mat.poisson.powi(2)), vn);
    let dt = tau / 400.0;
    // (name, r2 (0: wall), v_t, spin of 1 for a given u_in, spin of 2 for it)
    struct Case {
        name: &'static str,
        r2: f64,
        vt: f64,
        /// ω2 = k2 · ω1
        k2: f64,
    }
    let cases = [
        Case {
            name: "test 5 (wall, v_t = 0)",
            r2: 0.0,
            vt: 0.0,
            k2: 0.0,
        },
        Case {
            name: "test 6 (wall, v_t = 1 m/s)",
            r2: 0.0,
            vt: 1.0,
            k2: 0.0,
        },
        Case {
            name: "test 7 (equal spheres)",
            r2: r,
            vt: 0.0,
            k2: 1.0,
        },
        Case {
            name: "test 8 (R and 2R)",
            r2: 2.0 * r,
            vt: 0.0,
            k2: 0.5,
        },
    ];
    for c in &cases {
        let wall = c.r2 == 0.0;
        // ω1 for a wanted u_in: u_in = v_t + r ω1 + r2 k2 ω1
        let lever = r + c.r2 * c.k2;
        let run = |u_in: f64, mu: f64, e_n: f64| {
            let w1 = (u_in - c.vt) / lever;
            let model = hertz_mindlin(mat.young, mat.poisson, wall, mu, e_n);
            if wall {
                let o = wall_impact(model, r, mat.density, vn, c.vt, w1, dt);
                (o, None, slip_wall(o, r))
            } else {
                let (o1, o2) =
                    pair_impact(model, r, c.r2, mat.density, vn, c.vt, w1, c.k2 * w1, dt);
                (o1, Some(o2), slip_pair(o1, o2, r, c.r2))
            }
        };
        let m2 = ball_mass(c.r2, mat.density);
        let b2 = (!wall).then_some((m2, c.r2));
        let (mut w_slide, mut w_stick) = (0.0f64, 0.0f64);
        // (b) no slip: β0 from the Hill equation for this pair
        let sp = if wall {
            mat.on_wall(
                r,
                0.0,
                f64::INFINITY,
                End::Overlap,
                TangentRule::Displacement,
            )
        } else {
            let mut s = mat.pair(
                r,
                0.0,
                f64::INFINITY,
                End::Overlap,
                TangentRule::Displacement,
            );
            s.body2 = Some(Body2 {
                m: m2,
                r: c.r2,
                inertia: 0.4 * m2 * c.r2 * c.r2,
            });
            s
        };
        let sp: Spec = sp;
        let b0 = no_slip_beta(
            k_ratio(&sp, vn),
            0.0,
            End::Overlap,
            TangentRule::Displacement,
            1e-12,
        );
        for k in 1..=12 {
            for sign in [1.0, -1.0] {
                let u_in = sign * 0.5 * f64::from(k);
                let (o, o2, _) = run(u_in, mu, 0.98);
                // separation speed / approach speed
                let e_n = (o.vy - o2.map_or(0.0, |o2| o2.vy)) / vn;
                // (c) Coulomb: |ΔP_t| ≤ μ (1 + e_n) m* v_n
                let m_eff = b2.map_or(m, |(m2, _)| m * m2 / (m + m2));
                let dp = (o.vx - c.vt).abs() * m;
                // pairs: the normal turns during the contact and the velocities are read in the
                // first-touch frame, so the bound holds to that turn (measured ≤ 1.3e-3)
                let tol = if wall { 1e-6 } else { 5e-3 };
                assert!(
                    dp <= mu * (1.0 + e_n) * m_eff * vn * (1.0 + tol),
                    "{} u_in {u_in}: Coulomb {}",
                    c.name,
                    dp / (mu * (1.0 + e_n) * m_eff * vn)
                );
                // (a) gross sliding
                if u_in.abs() >= 1.2 * 3.5 * mu * (1.0 + e_n) * vn {
                    let w1 = (u_in - c.vt) / lever;
                    let d = sliding_impulse(mu, e_n, vn, u_in, (m, r), b2);
                    let mut err = (o.vx - c.vt - d[0]).abs().max((o.wz - w1 - d[1]).abs() * r);
                    if let Some(o2) = o2 {
                        err = err
                            .max((o2.vx - d[2]).abs())
                            .max((o2.wz - c.k2 * w1 - d[3]).abs() * c.r2);
                    }
                    w_slide = w_slide.max(err / u_in.abs());
                }
            }
        }
        for u_in in [-2.0, -0.5, 0.7, 3.0] {
            let (_, _, u_out) = run(u_in, 1e12, 1.0);
            w_stick = w_stick.max((u_out / u_in - b0).abs());
        }
        println!(
            "C&O {}: gross sliding {w_slide:.2e} of |u_in|, no slip |β − β0| {w_stick:.2e} (β0 = {b0:.6})",
            c.name
        );
        assert!(w_slide < 3e-3, "{}: sliding {w_slide:e}", c.name);
        assert!(w_stick < 3e-3, "{}: no slip {w_stick:e}", c.name);
    }
}
