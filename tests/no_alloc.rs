//! Proves that the foundation exports never allocate on the heap: a counting global allocator is
//! armed around calls to every export, on valid and invalid inputs, and must count zero.
//! Later modules add their own `no_alloc_*.rs` files using the same `alloc_counter`.

mod alloc_counter;
use alloc_counter::{Counting, assert_counter_works, count_allocations};
use demcontact::ffi::{calibration::*, material::*, status::*, timestep::*, version::*};

#[global_allocator]
static ALLOC: Counting = Counting;

const INPUTS: [f64; 13] = [
    -1.0,
    0.0,
    1e-300,
    1e-6,
    0.3,
    0.5,
    1.0,
    1.5,
    2.0,
    7.0,
    1e300,
    f64::NAN,
    f64::INFINITY,
];

#[test]
fn foundation_exports_do_not_allocate() {
    assert_counter_works();
    let mut calls = 0usize;
    let n = count_allocations(|| {
        let mut out = 0.0f64;
        for &a in &INPUTS {
            for &b in &INPUTS {
                for crit in [DC_END_OVERLAP, DC_END_FORCE, 7] {
                    unsafe {
                        std::hint::black_box(dc_alpha_from_e(a, b, crit, &mut out));
                        std::hint::black_box(dc_e_from_alpha(a, b, crit, &mut out));
                        std::hint::black_box(dc_alpha_from_e(a, b, crit, std::ptr::null_mut()));
                    }
                    calls += 3;
                }
                for &c in &INPUTS {
                    unsafe { std::hint::black_box(dc_dt_crit(a, b, c, &mut out)) };
                    unsafe {
                        std::hint::black_box(dc_hertz_stiffness(a, 0.3, b, c, 0.2, 1e-3, &mut out))
                    };
                    unsafe { std::hint::black_box(dc_effective_modulus(a, 0.3, b, c, &mut out)) };
                    calls += 3;
                }
            }
        }
        for s in [DC_OK, DC_ERR_NULL_POINTER, DC_ERR_INTERNAL, -5, 123456] {
            std::hint::black_box(dc_status_str(s));
        }
        std::hint::black_box(dc_version());
    });
    assert_eq!(
        n, 0,
        "exported functions allocated {n} times in {calls} calls"
    );
    println!("no_alloc: {calls} calls, 0 allocations");
}
