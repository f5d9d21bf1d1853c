//! Cost of the calibration exports, through the C ABI symbols, for both criteria. Each sample
//! calls the function for 8 restitutions from 0.01 to 0.999 (divan reports items/s; ns per call =
//! time / 8). Baseline in the same run: the bare `ln` that every calibration needs, so that ratios
//! survive a noisy shared machine. Run: `cargo bench --bench calibration`.

use demcontact::ffi::{calibration::*, status::*};
use divan::{Bencher, black_box, counter::ItemsCount};

fn main() {
    divan::main();
}

const ES: [f64; 8] = [0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999];

#[divan::bench]
fn baseline_ln(b: Bencher) {
    b.counter(ItemsCount::new(ES.len())).bench(|| {
        let mut s = 0.0;
        for &e in &ES {
            s += black_box(e).ln();
        }
        s
    });
}

#[divan::bench(args = [DC_END_OVERLAP, DC_END_FORCE])]
fn alpha_from_e(b: Bencher, criterion: i32) {
    b.counter(ItemsCount::new(ES.len())).bench(|| {
        let mut s = 0.0;
        for &e in &ES {
            let mut a = 0.0;
            unsafe { dc_alpha_from_e(black_box(e), black_box(1.5), criterion, &mut a) };
            s += a;
        }
        s
    });
}

#[divan::bench(args = [DC_END_OVERLAP, DC_END_FORCE])]
fn e_from_alpha(b: Bencher, criterion: i32) {
    b.counter(ItemsCount::new(ES.len())).bench(|| {
        let mut s = 0.0;
        for &e in &ES {
            let mut out = 0.0;
            unsafe {
                dc_e_from_alpha(
                    black_box(2.0 * (1.0 - e)),
                    black_box(1.5),
                    criterion,
                    &mut out,
                )
            };
            s += out;
        }
        s
    });
}

/// `dc_dt_for_accuracy` (one call per sample; it simulates collisions inside the call): the cheap
/// and the costly end of the range quoted in the README and docs/timestep.md (p = 1.5, both
/// criteria): e = 0.9 at tol = 1e-2, and e = 0.1 at tol = 1e-3.
#[divan::bench(args = [(DC_END_FORCE, 0.9, 1e-2), (DC_END_OVERLAP, 0.9, 1e-2), (DC_END_FORCE, 0.1, 1e-3), (DC_END_OVERLAP, 0.1, 1e-3)], sample_count = 5, sample_size = 1)]
fn dt_for_accuracy(b: Bencher, (criterion, e, tol): (i32, f64, f64)) {
    b.bench(|| {
        let mut dt = 0.0;
        let st = unsafe {
            demcontact::ffi::step_accuracy::dc_dt_for_accuracy(
                black_box(1.5),
                black_box(e),
                criterion,
                1.0,
                1.0,
                tol,
                &mut dt,
            )
        };
        assert_eq!(st, DC_OK);
        dt
    });
}
