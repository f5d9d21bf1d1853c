//! The force exports never allocate: constructors, scalar, checked, batch and 3D, on valid and
//! invalid input, counted by the per-thread counting allocator.

mod alloc_counter;
use alloc_counter::{Counting, assert_counter_works, count_allocations};
use demcontact::ffi::force::*;
use demcontact::ffi::status::*;
use std::hint::black_box;

#[global_allocator]
static ALLOC: Counting = Counting;

const V: [f64; 9] = [-1.0, 0.0, 1e-300, 1e-6, 0.5, 1.5, 2.0, 1e300, f64::NAN];

#[test]
fn force_exports_do_not_allocate() {
    assert_counter_works();
    let (d, vn, r, m) = ([1e-6; 64], [0.3; 64], [1e-3; 64], [1e-4; 64]);
    let mut out = [0.0f64; 64];
    let x = [[0.0, 0.0, 0.0], [1.9e-3, 0.0, 0.0]];
    let mut calls = 0usize;
    let n = count_allocations(|| {
        let mut pair: dc_pair = unsafe { std::mem::zeroed() };
        for &a in &V {
            for &b in &V {
                for crit in [DC_END_OVERLAP, DC_END_FORCE, 9] {
                    unsafe {
                        black_box(dc_pair_powerlaw(a, 1e6, b, crit, &mut pair));
                        black_box(dc_pair_powerlaw_alpha(1.5, a, b, crit, &mut pair));
                        black_box(dc_pair_linear(a, b, crit, &mut pair));
                        black_box(dc_pair_hertz(a, 0.3, 1e9, 0.2, b, crit, &mut pair));
                        black_box(dc_pair_viscoelastic(a, 0.3, 1e9, 0.2, b, crit, &mut pair));
                    }
                    calls += 5;
                }
            }
        }
        for kind in 0..4 {
            let s = unsafe {
                match kind {
                    0 => dc_pair_powerlaw(2.3, 1e6, 0.5, DC_END_FORCE, &mut pair),
                    1 => dc_pair_linear(1e6, 0.5, DC_END_OVERLAP, &mut pair),
                    2 => dc_pair_hertz(1e9, 0.3, 1e9, 0.3, 0.5, DC_END_FORCE, &mut pair),
                    _ => dc_pair_viscoelastic(1e9, 0.3, 1e9, 0.3, 1e-5, DC_END_FORCE, &mut pair),
                }
            };
            assert_eq!(s, DC_OK);
            for &a in &V {
                for &b in &V {
                    let mut f = 0.0;
                    unsafe {
                        black_box(dc_normal_force(&pair, a, b, 1e-3, 1e-4));
                        black_box(dc_normal_force_checked(&pair, a, b, 1e-3, b, &mut f));
                    }
                    calls += 2;
                }
            }
            for len in [0usize, 1, 64] {
                unsafe {
                    black_box(dc_normal_force_batch(
                        &pair,
                        len,
                        d.as_ptr(),
                        vn.as_ptr(),
                        r.as_ptr(),
                        m.as_ptr(),
                        out.as_mut_ptr(),
                    ));
                    black_box(dc_normal_force_batch(
                        &pair,
                        len,
                        d.as_ptr(),
                        std::ptr::null(),
                        r.as_ptr(),
                        m.as_ptr(),
                        out.as_mut_ptr(),
                    ));
                    // The fast batch too: its first general-p call on this thread builds the
                    // exponent's tables (thread-local storage, no heap).
                    black_box(dc_normal_force_batch_fast(
                        &pair,
                        len,
                        d.as_ptr(),
                        vn.as_ptr(),
                        r.as_ptr(),
                        m.as_ptr(),
                        out.as_mut_ptr(),
                    ));
                }
                calls += 3;
            }
            let mut f3 = [0.0; 3];
            for &rad in &V {
                unsafe {
                    black_box(dc_normal_force_3d(
                        &pair,
                        x[0].as_ptr(),
                        vn.as_ptr(),
                        rad,
                        1e-4,
                        x[1].as_ptr(),
                        r.as_ptr(),
                        1e-3,
                        1e-4,
                        f3.as_mut_ptr(),
                    ));
                }
                calls += 1;
            }
        }
    });
    assert_eq!(n, 0, "force exports allocated {n} times in {calls} calls");
    println!("no_alloc_force: {calls} calls, 0 allocations");
}
