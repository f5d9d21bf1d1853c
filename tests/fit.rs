//! The restitution fit: exact data recovered to 1e-10, the reported 95 % interval covers the true
//! β in 95 % of seeded noisy data sets (2000 each, σ known and from the scatter), degenerate input gets a status, Huber resists an
//! outlier, and the model choice follows the tolerance.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

use demcontact::fit::{Data, FitOptions, ModelChoice, fit_restitution, residuals};
use demcontact::viscoelastic::full_range::e_full;
use demcontact::{EndCriterion, Error};

/// xorshift64* and Box–Muller: a seeded normal generator without dependencies.
struct Rng(u64);
impl Rng {
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        ((self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    fn normal(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (2.0 * core::f64::consts::PI * v).cos()
    }
}

fn speeds(n: usize, lo: f64, hi: f64) -> Vec<f64> {
    (0..n)
        .map(|i| lo * (hi / lo).powf(i as f64 / (n - 1) as f64))
        .collect()
}

fn opts(c: EndCriterion) -> FitOptions {
    FitOptions {
        criterion: c,
        tol: 0.02,
        robust: false,
    }
}

#[test]
fn exact_data_recovered() {
    let mut worst: f64 = 0.0;
    for c in [EndCriterion::Overlap, EndCriterion::Force] {
        for beta in [1e-3, 0.05, 0.3, 1.0, 3.0] {
            let v = speeds(8, 0.1, 10.0);
            let e: Vec<f64> = v
                .iter()
                .map(|&v| e_full(beta * v.powf(0.2), c).unwrap())
                .collect();
            for robust in [false, true] {
                let d = Data {
                    v: &v,
                    e: &e,
                    sigma: None,
                };
                let f = fit_restitution(&d, &FitOptions { robust, ..opts(c) }).unwrap();
                let rel = (f.beta - beta).abs() / beta;
                assert!(
                    rel < 1e-10,
                    "{c:?} β={beta} robust={robust}: {} ({rel:e})",
                    f.beta
                );
                worst = worst.max(rel);
                assert!(f.max_residual_viscoelastic < 1e-12);
            }
        }
    }
    println!("exact data: worst relative error of β {worst:.1e}");
}

/// Wilson score interval (z = 1.96) of a binomial proportion k/n, for the printed summary.
fn wilson(k: usize, n: usize) -> (f64, f64) {
    let (k, n, z) = (k as f64, n as f64, 1.959963984540054);
    let p = k / n;
    let c = (p + z * z / (2.0 * n)) / (1.0 + z * z / n);
    let h = z / (1.0 + z * z / n) * (p * (1.0 - p) / n + z * z / (4.0 * n * n)).sqrt();
    (c - h, c + h)
}

/// Coverage of the reported 95 % interval [beta_lo95, beta_hi95] over seeded noisy data sets:
/// σ known (z quantile) and σ from the scatter (Student t, n − 1 degrees of freedom) at n = 12
/// and n = 6, both end criteria. 2000 replicates each: a binomial standard deviation of 4.9
/// counts at 95 %, so the band 1900 ± 35 (±7 SD: the data are seeded, the counts fixed) rejects
/// what ±2·SE gives with σ from the scatter (nominal 1858 at n = 12, 1796 at n = 6).
#[test]
fn interval_coverage() {
    const REPS: usize = 2000;
    let mut seed = 0x9E37_79B9_7F4A_7C15u64;
    for (c, with_sigma, n) in [
        (EndCriterion::Force, true, 12),
        (EndCriterion::Overlap, true, 12),
        (EndCriterion::Force, false, 12),
        (EndCriterion::Overlap, false, 12),
        (EndCriterion::Force, false, 6),
    ] {
        let beta = 0.4;
        let sigma = 0.01;
        let v = speeds(n, 0.05, 5.0);
        let s = vec![sigma; v.len()];
        let mut rng = Rng(seed);
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let (mut inside, mut inside_2se) = (0, 0);
        let mut q = f64::NAN;
        for _ in 0..REPS {
            let e: Vec<f64> = v
                .iter()
                .map(|&v| (e_full(beta * v.powf(0.2), c).unwrap() + sigma * rng.normal()).min(1.0))
                .collect();
            let d = Data {
                v: &v,
                e: &e,
                sigma: with_sigma.then_some(&s[..]),
            };
            let f = fit_restitution(&d, &opts(c))
                .unwrap_or_else(|err| panic!("{err:?}: v = {v:?}, e = {e:?}"));
            q = f.quantile95;
            if f.beta_lo95 <= beta && beta <= f.beta_hi95 {
                inside += 1;
            }
            if (f.beta - beta).abs() <= 2.0 * f.beta_se {
                inside_2se += 1;
            }
        }
        let (lo, hi) = wilson(inside, REPS);
        println!(
            "{c:?}, n = {n}, sigma {}: 95 % interval (q = {q:.4}) covers {inside}/{REPS} = {:.1} % \
             (Wilson 95 %: {:.1}-{:.1} %); +-2 SE would cover {inside_2se}/{REPS}",
            if with_sigma { "given" } else { "from scatter" },
            100.0 * inside as f64 / REPS as f64,
            100.0 * lo,
            100.0 * hi
        );
        assert!(
            (1900 - 35..=1900 + 35).contains(&inside),
            "{c:?} n={n} sigma given {with_sigma}: {inside}/{REPS}"
        );
        let want_q = demcontact::fit::quantile::two_sided_quantile(
            0.95,
            if with_sigma { 0 } else { n as u64 - 1 },
        )
        .unwrap();
        assert_eq!(q, want_q);
    }
}

#[test]
fn degenerate_input_gets_a_status() {
    let c = opts(EndCriterion::Force);
    let fit = |v: &[f64], e: &[f64]| fit_restitution(&Data { v, e, sigma: None }, &c).map(|_| ());
    assert_eq!(fit(&[1.0], &[0.5]), Err(Error::FitTooFew));
    assert_eq!(fit(&[], &[]), Err(Error::FitTooFew));
    assert_eq!(
        fit(&[1.0, 1.0, 1.0], &[0.5, 0.6, 0.55]),
        Err(Error::FitDegenerate)
    );
    assert_eq!(fit(&[1.0, 2.0], &[0.5, 1.2]), Err(Error::RestitutionRange));
    assert_eq!(fit(&[1.0, 2.0], &[0.0, 0.5]), Err(Error::RestitutionRange));
    assert_eq!(fit(&[1.0, 2.0], &[f64::NAN, 0.5]), Err(Error::NotFinite));
    assert_eq!(
        fit(&[1.0, f64::INFINITY], &[0.4, 0.5]),
        Err(Error::NotFinite)
    );
    assert_eq!(fit(&[-1.0, 2.0], &[0.4, 0.5]), Err(Error::NotPositive));
    assert_eq!(fit(&[1.0, 2.0], &[0.4]), Err(Error::BufferTooShort));
    let s = [0.01, 0.0];
    let d = Data {
        v: &[1.0, 2.0],
        e: &[0.5, 0.4],
        sigma: Some(&s),
    };
    assert_eq!(fit_restitution(&d, &c).map(|_| ()), Err(Error::NotPositive));
    let d = Data {
        v: &[1.0, 2.0],
        e: &[0.5, 0.4],
        sigma: None,
    };
    let bad_tol = FitOptions { tol: 0.0, ..c };
    assert_eq!(
        fit_restitution(&d, &bad_tol).map(|_| ()),
        Err(Error::NotPositive)
    );
    // Two distinct points are enough.
    assert!(fit_restitution(&d, &c).is_ok());
}

#[test]
fn huber_resists_an_outlier() {
    let c = EndCriterion::Force;
    let beta = 0.3;
    let v = speeds(15, 0.1, 10.0);
    let mut rng = Rng(42);
    let mut e: Vec<f64> = v
        .iter()
        .map(|&v| e_full(beta * v.powf(0.2), c).unwrap() + 0.003 * rng.normal())
        .collect();
    e[7] -= 0.15; // one bad measurement
    let d = Data {
        v: &v,
        e: &e,
        sigma: None,
    };
    let plain = fit_restitution(&d, &opts(c)).unwrap();
    let robust = fit_restitution(
        &d,
        &FitOptions {
            robust: true,
            ..opts(c)
        },
    )
    .unwrap();
    let (ep, er) = ((plain.beta - beta).abs(), (robust.beta - beta).abs());
    println!("outlier: |Δβ| plain {ep:.2e}, Huber {er:.2e}");
    assert!(er < 0.25 * ep, "plain {ep} robust {er}");
}

#[test]
fn model_choice_follows_the_tolerance() {
    let c = EndCriterion::Force;
    let v = speeds(6, 1.0, 2.0);
    // Weak damping over a narrow speed range: e varies by ~0.004.
    let e: Vec<f64> = v
        .iter()
        .map(|&v| e_full(0.01 * v.powf(0.2), c).unwrap())
        .collect();
    let d = Data {
        v: &v,
        e: &e,
        sigma: None,
    };
    let f = fit_restitution(
        &d,
        &FitOptions {
            tol: 0.02,
            ..opts(c)
        },
    )
    .unwrap();
    assert_eq!(f.model, ModelChoice::Constant, "{f:?}");
    let f = fit_restitution(
        &d,
        &FitOptions {
            tol: 1e-4,
            ..opts(c)
        },
    )
    .unwrap();
    assert_eq!(f.model, ModelChoice::Viscoelastic, "{f:?}");
    // Residuals: written on success, untouched on error.
    let mut rv = vec![7.0; 6];
    let mut rc = vec![7.0; 6];
    residuals(&d, &f, c, &mut rv, &mut rc).unwrap();
    assert!(rv.iter().all(|r| r.abs() < 1e-12));
    assert!((rc.iter().sum::<f64>()).abs() < 1e-12); // unweighted mean: residuals sum to 0
    let mut short = vec![7.0; 5];
    assert_eq!(
        residuals(&d, &f, c, &mut short, &mut []),
        Err(Error::BufferTooShort)
    );
    assert!(short.iter().all(|&x| x == 7.0));
}
