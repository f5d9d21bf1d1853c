//! Proves that `dc_plan` and `dc_plan_input_init` never allocate, on valid and invalid input.

mod alloc_counter;
use alloc_counter::{Counting, assert_counter_works, count_allocations};
use demcontact::ffi::{plan::*, status::*};

#[global_allocator]
static ALLOC: Counting = Counting;

#[test]
fn plan_does_not_allocate() {
    assert_counter_works();
    let mut base = dc_plan_input {
        version: 0,
        size: 0,
        youngs: 0.0,
        poisson: 0.0,
        density: 0.0,
        restitution: 0.0,
        radius_min: 0.0,
        radius_max: 0.0,
        v_max: 0.0,
        depth: 0.0,
        gravity: 0.0,
        pressure: 0.0,
        solid_fraction: 0.0,
        coordination: 0.0,
        load_factor: 0.0,
        friction: 0.0,
        rolling_friction: 0.0,
        overlap_tol: 0.0,
        e_tol: 0.0,
        static_tol: 0.0,
        duration_tol: 0.0,
        criterion: 0,
        walls: 0,
        stability_fraction: 0.0,
        conventional_divisor: 0.0,
    };
    // SAFETY: valid pointer.
    assert_eq!(unsafe { dc_plan_input_init(&mut base) }, DC_OK);
    let scene = dc_plan_input {
        youngs: 7e10,
        poisson: 0.22,
        density: 2500.0,
        restitution: 0.3,
        radius_min: 1e-3,
        radius_max: 4e-3,
        v_max: 2.0,
        depth: 0.5,
        overlap_tol: 0.01,
        e_tol: 0.01,
        duration_tol: 3.0,
        ..base
    };
    let cases = [
        scene,
        dc_plan_input {
            criterion: 0,
            walls: 0,
            ..scene
        },
        dc_plan_input {
            radius_max: 1e-4,
            ..scene
        },
        dc_plan_input {
            overlap_tol: 1e-5,
            ..scene
        },
        base,
    ];
    let mut codes = Vec::with_capacity(cases.len());
    let n = count_allocations(|| {
        for c in &cases {
            let mut out = dc_plan_result::default();
            let mut field = 0;
            // SAFETY: valid pointers.
            codes.push(unsafe { dc_plan(c, &mut out, &mut field) });
        }
    });
    assert_eq!(n, 0, "dc_plan allocated {n} times");
    assert_eq!(
        codes,
        [
            DC_OK,
            DC_OK,
            DC_ERR_PLAN_RANGE,
            DC_ERR_PLAN_INFEASIBLE,
            DC_ERR_NOT_FINITE
        ]
    );
}
