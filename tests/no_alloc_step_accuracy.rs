//! Proves that `dc_dt_for_accuracy` never allocates, on valid and invalid input.

mod alloc_counter;
use alloc_counter::{Counting, assert_counter_works, count_allocations};
use demcontact::ffi::{status::*, step_accuracy::*};

#[global_allocator]
static ALLOC: Counting = Counting;

#[test]
fn dt_for_accuracy_does_not_allocate() {
    assert_counter_works();
    let mut calls = 0usize;
    let n = count_allocations(|| {
        let mut out = 0.0f64;
        // Under Miri (scripts/miri.sh) loose tolerances, far cheaper than the native cases (up to
        // millions of force calls each) yet reaching every region of src/ they reach
        // (scripts/miri_coverage.sh): the kernels of p = 1, 2, 1.5 and the general one, the
        // force-end root below e = exp(-2), and e = 0.1 at tol 0.2, whose search halves the step
        // down to the extrapolation floor.
        let cases: &[(f64, f64, f64, f64, f64)] = if cfg!(miri) {
            &[
                (1.0, 0.9, 2.0, 10.0, 0.5),
                (2.0, 1.0, 1.0, 1.0, 0.5),
                (1.5, 0.5, 1.0, 1.0, 0.5),
                (3.0, 0.1, 0.5, 3.0, 0.2),
                (f64::NAN, 0.5, 1.0, 1.0, 1e-2),
                (1.5, 0.0, 1.0, 1.0, 1e-2),
                (1.5, 0.5, -1.0, 1.0, 1e-2),
            ]
        } else {
            &[
                (1.5, 0.5, 1.0, 1.0, 1e-2),
                (1.0, 0.9, 2.0, 10.0, 1e-3),
                (3.0, 0.1, 0.5, 3.0, 0.5),
                (2.0, 1.0, 1.0, 1.0, 1e-5),
                // below the search's floor: the extrapolated step and its check
                (1.0, 0.1, 1.0, 1.0, 1e-4),
                (f64::NAN, 0.5, 1.0, 1.0, 1e-2),
                (1.5, 0.0, 1.0, 1.0, 1e-2),
                (1.5, 0.5, -1.0, 1.0, 1e-2),
            ]
        };
        for &(p, e, v0, w0, tol) in cases {
            for crit in [DC_END_OVERLAP, DC_END_FORCE, 9] {
                unsafe {
                    std::hint::black_box(dc_dt_for_accuracy(p, e, crit, v0, w0, tol, &mut out));
                    std::hint::black_box(dc_dt_for_accuracy(
                        p,
                        e,
                        crit,
                        v0,
                        w0,
                        tol,
                        std::ptr::null_mut(),
                    ));
                }
                calls += 2;
            }
        }
    });
    assert_eq!(
        n, 0,
        "dc_dt_for_accuracy allocated {n} times in {calls} calls"
    );
    println!("no_alloc_step_accuracy: {calls} calls, 0 allocations");
}
