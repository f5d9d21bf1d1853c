//! Cost of the viscoelastic restitution tiers through the C ABI symbols. Each sample evaluates 8
//! values of b from 0.01 to 1000 (divan reports items/s; ns per call = time / 8). Baseline in the
//! same run: `powf(v, 0.2)`, the one power every physical-units call needs anyway.
//! The reference tier is measured on b ≤ 1 only (its cost grows with b; see docs/viscoelastic.md).
//! Run: `cargo bench --bench viscoelastic`.

use demcontact::ffi::{status::*, viscoelastic::*};
use divan::{Bencher, black_box, counter::ItemsCount};

fn main() {
    divan::main();
}

const BS: [f64; 8] = [0.01, 0.1, 0.5, 1.0, 3.0, 10.0, 100.0, 1000.0];
const BS_SMALL: [f64; 4] = [0.01, 0.1, 0.5, 1.0];

#[divan::bench]
fn baseline_powf(b: Bencher) {
    b.counter(ItemsCount::new(BS.len())).bench(|| {
        let mut s = 0.0;
        for &x in &BS {
            s += black_box(x).powf(0.2);
        }
        s
    });
}

#[divan::bench(args = [DC_END_OVERLAP, DC_END_FORCE])]
fn full_range(b: Bencher, criterion: i32) {
    b.counter(ItemsCount::new(BS.len())).bench(|| {
        let mut s = 0.0;
        for &x in &BS {
            let mut e = 0.0;
            unsafe { dc_viscoelastic_e(black_box(x), criterion, &mut e) };
            s += e;
        }
        s
    });
}

#[divan::bench(args = [DC_END_OVERLAP, DC_END_FORCE])]
fn series(b: Bencher, criterion: i32) {
    b.counter(ItemsCount::new(BS.len())).bench(|| {
        let mut s = 0.0;
        for &x in &BS {
            let mut e = 0.0;
            unsafe { dc_viscoelastic_e_series(black_box(x), criterion, &mut e) };
            s += e;
        }
        s
    });
}

#[divan::bench(args = [DC_END_OVERLAP, DC_END_FORCE])]
fn reference_small_b(b: Bencher, criterion: i32) {
    b.counter(ItemsCount::new(BS_SMALL.len())).bench(|| {
        let mut s = 0.0;
        for &x in &BS_SMALL {
            let mut e = 0.0;
            unsafe { dc_viscoelastic_e_reference(black_box(x), criterion, &mut e) };
            s += e;
        }
        s
    });
}

#[divan::bench(args = [DC_END_OVERLAP, DC_END_FORCE])]
fn b_from_e(b: Bencher, criterion: i32) {
    const ES: [f64; 8] = [0.999, 0.99, 0.9, 0.7, 0.5, 0.3, 0.1, 0.01];
    b.counter(ItemsCount::new(ES.len())).bench(|| {
        let mut s = 0.0;
        for &e in &ES {
            let mut out = 0.0;
            unsafe { dc_viscoelastic_b_from_e(black_box(e), criterion, &mut out) };
            s += out;
        }
        s
    });
}
