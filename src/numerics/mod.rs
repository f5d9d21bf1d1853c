//! Small numerical building blocks, each tested on its own.
//!
//! * [`roots`]: a bracketed Newton iteration for monotone functions.
//! * [`ode`]: an adaptive Dormand–Prince 5(4) integrator with event location, used as the
//!   independent reference that every closed form and quadrature in this crate is checked against.
//! * [`gamma`]: Re ln Γ(a + ib), for the closed-form contact duration.
//! * [`gauss_jacobi`]: Gauss rules for the weight y^ν (the planned contact duration).
//! * [`jacobi_cc`]: ∫ y^ν f(y) dy by Clenshaw–Curtis with modified moments (the contact times).
//! * `lagrange8`: 8-point Lagrange stencils for the cumulative integral of equally spaced
//!   samples (the trajectory's times).
//! * `series`: the exponential of a power series, Horner evaluation.
//! * `trig`: sin and cos in plain arithmetic, the same bits in the library and the C header.
//! * [`taylor`]: Taylor-series (automatic differentiation) building blocks over real or complex
//!   numbers, for the viscoelastic reference integrator.

pub(crate) mod estrin;
pub mod gamma;
pub mod gauss_jacobi;
pub mod jacobi_cc;
pub(crate) mod lagrange8;
pub(crate) mod ln_dd;
pub mod ode;
pub(crate) mod pow;
// The x86-64 vector kernels (not under Miri, which runs no vector flavour).
#[cfg(all(target_arch = "x86_64", not(miri)))]
pub(crate) mod pow_avx2;
#[cfg(all(target_arch = "x86_64", not(miri)))]
pub(crate) mod pow_avx512;
pub(crate) mod pow_dd;
pub(crate) mod pow_fast;
#[cfg(all(target_arch = "x86_64", not(miri)))]
pub(crate) mod pow_fast_avx2;
#[cfg(all(target_arch = "x86_64", not(miri)))]
pub(crate) mod pow_fast_avx512;
pub(crate) mod pow_table;
pub(crate) mod reduce;
pub mod roots;
pub(crate) mod series;
pub(crate) mod simd;
pub mod taylor;
pub(crate) mod trig;

pub use roots::newton_bracketed;

/// |got − want| in units of the spacing of doubles at want (the subnormal spacing 2^−1074
/// below 2^−1022): the error measure of the libm-free kernels' tests (`pow_dd`, `trig`).
#[cfg(test)]
pub(crate) fn ulps(got: f64, want: f64) -> f64 {
    if got == want {
        return 0.0;
    }
    let e = want.abs().log2().floor().max(-1022.0);
    (got - want).abs() / 2f64.powf(e - 52.0)
}
