//! Physics of the full contact through the C ABI: Coulomb limit and gross-sliding impulse ratio,
//! energy conservation of an elastic sticking collision, frame indifference, wall = sphere of
//! infinite radius and mass.

mod contact_sim;
use contact_sim::*;
use demcontact::ffi::contact::*;
use demcontact::ffi::status::*;

const RHO: f64 = 2500.0;
const R: f64 = 1e-3;

fn glass(spec: &mut dc_contact_spec) {
    spec.normal = DC_NORMAL_HERTZ;
    spec.E1 = 63e9;
    spec.nu1 = 0.23;
    spec.E2 = 63e9;
    spec.nu2 = 0.23;
}

/// Contact time scale of a Hertz impact (for dt): t_c ≈ 2.87 (m*²/(R* E*² v))^(1/5).
fn hertz_tc(m: f64, r: f64, es: f64, v: f64) -> f64 {
    2.87 * (m * m / (r * es * es * v)).powf(0.2)
}

#[test]
fn gross_sliding_impulse_ratio_is_mu_one_plus_e() {
    // Sphere onto a rigid wall at a shallow angle: sliding throughout, so J_t = mu J_n.
    for (mu, e_n, crit, tol) in [
        (0.1, 1.0, DC_END_FORCE, 1e-9),
        (0.3, 1.0, DC_END_OVERLAP, 1e-9),
        (0.1, 0.5, DC_END_FORCE, 1e-3),
        (0.3, 0.9, DC_END_OVERLAP, 3e-3),
        (0.092, 0.98, DC_END_FORCE, 1e-3),
    ] {
        let m = model(|s| {
            glass(s);
            s.E2 = f64::INFINITY;
            s.damping = if e_n < 1.0 {
                DC_DAMPING_RESTITUTION
            } else {
                DC_DAMPING_NONE
            };
            s.e_n = e_n;
            s.criterion = crit;
            s.tangential = DC_TANGENTIAL_MINDLIN;
            s.mu = mu;
        });
        let v0 = 1.0;
        let (vn, vt) = (v0 * 5f64.to_radians().sin(), v0 * 5f64.to_radians().cos());
        let mut b = Body::sphere([0.0, R, 0.0], [vt, -vn, 0.0], [0.0; 3], R, RHO);
        let es = 63e9 / (1.0 - 0.23 * 0.23);
        let dt = hertz_tc(b.m, R, es, vn) / 4000.0;
        let mut worst = 0.0f64;
        let (mut stick, mut steps) = (0usize, 0usize);
        let before = b;
        collide(&m, &mut b, &mut Other::Wall, dt, 1_000_000, |s, _, _| {
            let ft = norm(s.res.ft);
            worst = worst.max(ft - mu * s.res.f_n.abs());
            steps += 1;
            if s.res.sliding == 0 {
                stick += 1;
            }
        });
        assert!(worst <= 1e-12 * mu * 1e3, "|Ft| exceeds mu|Fn| by {worst}");
        println!("sticking steps {stick} of {steps}");
        let e_real = b.v[1] / vn;
        let dvt = before.v[0] - b.v[0];
        let ratio = dvt / (vn * (1.0 + e_real));
        println!(
            "mu {mu} e_n {e_n}: e realised {e_real:.6}, impulse ratio / mu = {:.12}",
            ratio / mu
        );
        assert!(
            (ratio / mu - 1.0).abs() < tol,
            "impulse ratio {ratio} vs mu {mu}"
        );
        assert!((e_real - e_n).abs() < 2e-3, "e_n {e_n} realised {e_real}");
    }
}

/// Total energy of an elastic, undamped, sticking oblique collision of two spheres (linear
/// normal and tangential springs, e_n = 1, μ huge): kinetic + rotational + ½ k_n δ² + ½ k_t |ξ|²
/// at every step of the contact, against the energy before. Returns (worst relative error
/// during the contact, relative error after separation counting the spring energy left at the
/// last contact step, spring share of the energy).
fn energy_error(dt_div: f64) -> (f64, f64, f64) {
    let (kn, kt) = (1.0e5, 2.0e4);
    let m = model(|s| {
        s.normal = DC_NORMAL_LINEAR;
        s.k_n = kn;
        s.criterion = DC_END_OVERLAP;
        s.tangential = DC_TANGENTIAL_LINEAR;
        s.k_t = kt;
        s.mu = 1e6;
    });
    let mut b1 = Body::sphere([0.0, 0.0, 0.0], [0.3, 0.0, 0.05], [0.0, 0.0, 40.0], R, RHO);
    let b2 = Body::sphere(
        [2.3 * R * 0.6f64.cos(), 2.3 * R * 0.6f64.sin(), 0.0],
        [-0.2, 0.1, 0.0],
        [10.0, 0.0, -30.0],
        1.3 * R,
        RHO,
    );
    let mut other = Other::Sphere(b2);
    let e0 = b1.kinetic() + b2.kinetic();
    let tc = std::f64::consts::PI * (b1.m * b2.m / (b1.m + b2.m) / kn).sqrt();
    let dt = tc / dt_div;
    let mut last_spring = 0.0;
    let mut max_spring = 0.0f64;
    let mut worst = 0.0f64;
    let mut stuck = true;
    collide(&m, &mut b1, &mut other, dt, 10_000_000, |s, b1, o| {
        let Other::Sphere(b2) = o else { unreachable!() };
        let xi = [s.hist[3], s.hist[4], s.hist[5]];
        last_spring = 0.5 * kt * dot(xi, xi);
        max_spring = max_spring.max(last_spring);
        let e = b1.kinetic() + b2.kinetic() + 0.5 * kn * s.overlap * s.overlap + last_spring;
        worst = worst.max((e - e0).abs() / e0);
        stuck &= s.res.sliding == 0;
    });
    assert!(stuck, "not sticking");
    let Other::Sphere(b2) = other else {
        unreachable!()
    };
    let e1 = b1.kinetic() + b2.kinetic() + last_spring;
    (worst, (e1 - e0).abs() / e0, max_spring / e0)
}

#[test]
fn elastic_sticking_collision_conserves_energy_to_second_order() {
    let mut prev: Option<(f64, f64)> = None;
    for div in [200.0, 400.0, 800.0, 1600.0] {
        let (during, after, frac) = energy_error(div);
        println!(
            "dt = tc/{div}: worst relative energy error during contact {during:.3e}, after \
             separation {after:.3e}; spring share {frac:.3}"
        );
        assert!(
            frac > 0.05,
            "the tangential spring must store a real share of the energy"
        );
        if let Some((d, _)) = prev {
            // Second order during the contact: halving dt divides the error by ≈ 4.
            assert!(d / during > 3.5, "order: ratio {}", d / during);
        }
        prev = Some((during, after));
    }
    let (during, _) = prev.unwrap_or_default();
    assert!(during < 1e-6, "energy error {during}");
}

#[test]
fn zz_probe_energy_normal_only() {
    for div in [200.0, 400.0, 800.0] {
        let m = model(|s| {
            s.normal = DC_NORMAL_LINEAR;
            s.k_n = 1.0e5;
            s.criterion = DC_END_OVERLAP;
        });
        let mut b1 = Body::sphere([0.0, 0.0, 0.0], [0.3, 0.0, 0.05], [0.0, 0.0, 40.0], R, RHO);
        let b2 = Body::sphere(
            [2.3 * R * 0.6f64.cos(), 2.3 * R * 0.6f64.sin(), 0.0],
            [-0.2, 0.1, 0.0],
            [10.0, 0.0, -30.0],
            1.3 * R,
            RHO,
        );
        let mut other = Other::Sphere(b2);
        let e0 = b1.kinetic() + b2.kinetic();
        let tc = std::f64::consts::PI * (b1.m * b2.m / (b1.m + b2.m) / 1e5).sqrt();
        collide(&m, &mut b1, &mut other, tc / div, 10_000_000, |_, _, _| {});
        let Other::Sphere(b2) = other else {
            unreachable!()
        };
        println!(
            "normal only {div}: {:.3e}",
            (b1.kinetic() + b2.kinetic() - e0) / e0
        );
    }
}
