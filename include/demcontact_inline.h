/*
 * demcontact_inline.h: the per-contact normal-force kernels and the closed-form calibrations of
 * demcontact as header-only static inline C99 (also C++17, and __host__ __device__ functions
 * under CUDA/HIP), for solvers that want the force inlined into their own loop, or that cannot
 * call a shared library at all (GPU device code). Nothing here needs libdemcontact to be linked.
 *
 *   #include <demcontact_inline.h>
 *   dc_pair pair;                          // from dc_pair_hertz() or dc_pair_hertz_inline()
 *   dc_pair_hertz_inline(63e9, 0.23, 63e9, 0.23, 0.5, DC_END_FORCE, &pair);
 *   double F = dc_normal_force_inline(&pair, overlap, vn, r_eff, m_eff);
 *   // in a loop over contacts of one pair, with the kernel code as a constant (vectorises):
 *   F = dc_normal_force_kernel_inline(DC_KERNEL_HERTZ_DAMPED_CLAMPED, &pair, d, vn, r, m);
 *
 * Contract: the same meaning, statuses and results as the library's functions of the same name
 * without `_inline` (dc_normal_force, dc_alpha_from_e, dc_e_from_alpha, dc_effective_modulus,
 * dc_pair_powerlaw, dc_pair_powerlaw_alpha, dc_pair_linear, dc_pair_hertz, dc_pair_viscoelastic),
 * reading and filling the same dc_pair (declared in demcontact.h). The results are bit-identical
 * to the library's for the same inputs (tested over 10^7 random inputs per kernel, C and C++):
 *  - the force kernels use only + - * / and sqrt (correctly rounded everywhere); the general-p
 *    power d^((p-1)/2) is the library's own branch-free kernel dc_pow_inline (within 2 ulp of
 *    glibc's pow for p <= 5), written out here, not libm's pow;
 *  - the calibrations call log, exp, sqrt, hypot and acos from <math.h>: bit-identical where the
 *    C library is the one the Rust library was linked with (glibc on Linux); with another libm
 *    they agree within that libm's error (calibrations run once per material pair, at set-up).
 *
 * Floating-point contraction: fusing a*b + c into one FMA would change roundings. The header
 * keeps every product rounded by itself: with GCC >= 12 through __builtin_assoc_barrier (which
 * also survives inlining into a caller compiled with -ffp-contract=fast -march=native), with
 * clang through `#pragma clang fp contract(off)` in each function, and in CUDA device code
 * through __dmul_rn. Other compilers: build with contraction off (-ffp-contract=off, /fp:precise
 * without /fp:contract); otherwise results may differ from the library by a few ulp of the
 * larger force term. Value-changing options (-ffast-math, -Ofast) void the bit-identity.
 *
 * Kernel codes (dc_pair.kernel, ABI): 1..17 as listed below; any other value gives NaN.
 * Not here yet: the tangential (Hertz-Mindlin) update of the full-contact ABI.
 */
#ifndef DEMCONTACT_INLINE_H
#define DEMCONTACT_INLINE_H

#include "demcontact.h"
#include <math.h>
#include <stdint.h>
#include <string.h>

#if defined(__CUDACC__) || defined(__HIPCC__)
#define DC_INLINE_FN static inline __host__ __device__
#else
#define DC_INLINE_FN static inline
#endif

/* A product rounded on its own, never fused with an addition (see the header comment). */
#if defined(__CUDA_ARCH__)
#define DCI_M(a, b) __dmul_rn((a), (b))
#elif defined(__clang__)
#define DCI_M(a, b) ((a) * (b))
#elif defined(__GNUC__) && __GNUC__ >= 12
#define DCI_M(a, b) __builtin_assoc_barrier((a) * (b))
#else
#define DCI_M(a, b) ((a) * (b))
#endif
/* Opens every function body: clang keeps its products unfused even after inlining. */
#if defined(__clang__)
#define DCI_NO_CONTRACT _Pragma("clang fp contract(off)")
#else
#define DCI_NO_CONTRACT
#endif

/* Kernel codes stored in dc_pair.kernel by the constructors (ABI: these values never change). */
#define DC_KERNEL_LIN_ELASTIC 1
#define DC_KERNEL_LIN_DAMPED 2
#define DC_KERNEL_LIN_DAMPED_CLAMPED 3
#define DC_KERNEL_P15_ELASTIC 4
#define DC_KERNEL_P15_DAMPED 5
#define DC_KERNEL_P15_DAMPED_CLAMPED 6
#define DC_KERNEL_P2_ELASTIC 7
#define DC_KERNEL_P2_DAMPED 8
#define DC_KERNEL_P2_DAMPED_CLAMPED 9
#define DC_KERNEL_GEN_ELASTIC 10
#define DC_KERNEL_GEN_DAMPED 11
#define DC_KERNEL_GEN_DAMPED_CLAMPED 12
#define DC_KERNEL_HERTZ_ELASTIC 13
#define DC_KERNEL_HERTZ_DAMPED 14
#define DC_KERNEL_HERTZ_DAMPED_CLAMPED 15
#define DC_KERNEL_VISCO_DAMPED 16
#define DC_KERNEL_VISCO_DAMPED_CLAMPED 17

/* ------------------------------------------------------------------ bits of a double */

DC_INLINE_FN uint64_t dci_bits(double x) {
#if defined(__CUDA_ARCH__)
    return (uint64_t)__double_as_longlong(x);
#else
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
#endif
}

DC_INLINE_FN double dci_from_bits(uint64_t u) {
#if defined(__CUDA_ARCH__)
    return __longlong_as_double((long long)u);
#else
    double x;
    memcpy(&x, &u, sizeof x);
    return x;
#endif
}

/* ------------------------------------------------------------------ x^q (src/numerics/pow_dd.rs) */

#define DCI_LN2_HI 0x1.62e42fee00000p-1      /* ln 2 with its low 21 mantissa bits cleared */
#define DCI_LN2_LO 0x1.a39ef35793c76p-33     /* ln 2 - DCI_LN2_HI */
#define DCI_LOG2_E 0x1.71547652b82fep+0
#define DCI_SQRT_2 0x1.6a09e667f3bcdp+0
#define DCI_SHIFTER 6755399441055744.0       /* 1.5 * 2^52 */
#define DCI_TWO52 4503599627370496.0
#define DCI_TWO54 18014398509481984.0
#define DCI_LN2 0x1.62e42fefa39efp-1
#define DCI_K_CLAMP 2044.0
#define DCI_DBL_MIN 0x1p-1022

/* Sum_{k<10} x^k/(2k+3) by Estrin's scheme, in the library's order. */
DC_INLINE_FN double dci_atanh_tail(double x) {
    DCI_NO_CONTRACT
    const double x2 = DCI_M(x, x), x4 = DCI_M(x2, x2), x8 = DCI_M(x4, x4);
    const double b0 = 1.0 / 3.0 + DCI_M(1.0 / 5.0, x);
    const double b1 = 1.0 / 7.0 + DCI_M(1.0 / 9.0, x);
    const double b2 = 1.0 / 11.0 + DCI_M(1.0 / 13.0, x);
    const double b3 = 1.0 / 15.0 + DCI_M(1.0 / 17.0, x);
    const double b4 = 1.0 / 19.0 + DCI_M(1.0 / 21.0, x);
    const double c0 = b0 + DCI_M(b1, x2);
    const double c1 = b2 + DCI_M(b3, x2);
    const double d0 = c0 + DCI_M(c1, x4);
    return d0 + DCI_M(b4, x8);
}

/* Sum_{k<12} x^k/(k+2)! by Estrin's scheme, in the library's order. */
DC_INLINE_FN double dci_exp_tail(double x) {
    DCI_NO_CONTRACT
    const double x2 = DCI_M(x, x), x4 = DCI_M(x2, x2), x8 = DCI_M(x4, x4);
    const double b0 = 1.0 / 2.0 + DCI_M(1.0 / 6.0, x);
    const double b1 = 1.0 / 24.0 + DCI_M(1.0 / 120.0, x);
    const double b2 = 1.0 / 720.0 + DCI_M(1.0 / 5040.0, x);
    const double b3 = 1.0 / 40320.0 + DCI_M(1.0 / 362880.0, x);
    const double b4 = 1.0 / 3628800.0 + DCI_M(1.0 / 39916800.0, x);
    const double b5 = 1.0 / 479001600.0 + DCI_M(1.0 / 6227020800.0, x);
    const double c0 = b0 + DCI_M(b1, x2);
    const double c1 = b2 + DCI_M(b3, x2);
    const double c2 = b4 + DCI_M(b5, x2);
    const double d0 = c0 + DCI_M(c1, x4);
    return d0 + DCI_M(c2, x8);
}

/* 2^k for an integer-valued k in [-1022, 1023]. */
DC_INLINE_FN double dci_exp2i(double kf) {
    DCI_NO_CONTRACT
    return dci_from_bits((dci_bits(kf + (DCI_SHIFTER + 1023.0)) - dci_bits(DCI_SHIFTER)) << 52);
}

/* x^q for x >= 0 (subnormal and +inf included) and finite q > 0: branch-free, no libm; within
 * 2 ulp of glibc's pow for q <= 2 (p <= 5), 1 + q ulp beyond; subnormal results within one
 * subnormal ulp. Negative or NaN x give an unspecified number. x = 2^e m, m in [sqrt(1/2),
 * sqrt(2)); q e = P + Q exactly (q cut into 26 + 27 bits); x^q = 2^n e^t, n = round(P),
 * t = (P - n + Q) ln 2 + q ln m. */
DC_INLINE_FN double dc_pow_inline(double x, double q) {
    DCI_NO_CONTRACT
    const int pos = x > 0.0 && x < (double)INFINITY;
    double safe = pos ? x : 1.0;
    const int sub = safe < DCI_DBL_MIN;
    safe = sub ? DCI_M(safe, DCI_TWO54) : safe;
    const uint64_t bits = dci_bits(safe);
    const double e_biased = dci_from_bits(UINT64_C(0x4330000000000000) | (bits >> 52)) - DCI_TWO52;
    double m = dci_from_bits((bits & UINT64_C(0x000fffffffffffff)) | UINT64_C(0x3ff0000000000000));
    const int big_m = m > DCI_SQRT_2;
    m = big_m ? DCI_M(0.5, m) : m;
    double e = big_m ? e_biased - 1022.0 : e_biased - 1023.0;
    e = sub ? e - 54.0 : e;
    /* ln m = 2 atanh s */
    const double f = m - 1.0;
    const double s = f / (2.0 + f);
    const double z = DCI_M(s, s);
    const double two_s = DCI_M(2.0, s);
    const double ln_m = two_s + DCI_M(two_s, DCI_M(z, dci_atanh_tail(z)));
    /* q e = P + Q exactly; n = round(P) */
    const double qh = dci_from_bits(dci_bits(q) & ~((UINT64_C(1) << 27) - 1));
    const double ql = q - qh;
    const double big_p = DCI_M(qh, e);
    const double small_q = DCI_M(ql, e);
    const double n = (big_p + DCI_SHIFTER) - DCI_SHIFTER;
    const double frac = (big_p - n) + small_q;
    const double t = DCI_M(frac, DCI_LN2) + DCI_M(q, ln_m);
    /* e^t = 2^k e^r */
    const double kf = (DCI_M(t, DCI_LOG2_E) + DCI_SHIFTER) - DCI_SHIFTER;
    const double r = (t - DCI_M(kf, DCI_LN2_HI)) - DCI_M(kf, DCI_LN2_LO);
    const double poly = 1.0 + (r + DCI_M(DCI_M(r, r), dci_exp_tail(r)));
    double total = n + kf;
    total = total < -DCI_K_CLAMP ? -DCI_K_CLAMP : (total > DCI_K_CLAMP ? DCI_K_CLAMP : total);
    const double k1 = (DCI_M(0.5, total) + DCI_SHIFTER) - DCI_SHIFTER;
    const double v = DCI_M(DCI_M(poly, dci_exp2i(k1)), dci_exp2i(total - k1));
    return x == 0.0 ? 0.0 : (x == (double)INFINITY ? (double)INFINITY : v);
}

/* ------------------------------------------------------------------ the 17 force kernels
 * Raw forces of each law (src/force/{powerlaw,hertz,viscoelastic}.rs), k, c, h = dc_pair.k, .c,
 * .h; then dci_finish: zero without overlap (also for NaN d), clamp when the pair clamps. */

DC_INLINE_FN double dci_finish(double f, double d, int clamp) {
    if (clamp) f = f > 0.0 ? f : 0.0;
    return d > 0.0 ? f : 0.0;
}

/* p = 1: k d [+ c sqrt(m) vn] */
DC_INLINE_FN double dci_lin_elastic(double k, double d) {
    DCI_NO_CONTRACT
    return k * d;
}
DC_INLINE_FN double dci_lin_damped(double k, double c, double d, double vn, double m) {
    DCI_NO_CONTRACT
    return DCI_M(k, d) + DCI_M(c * sqrt(m), vn);
}
/* p = 3/2, fixed k: q = sqrt(d); k d q [+ c sqrt(m q) vn] */
DC_INLINE_FN double dci_p15_elastic(double k, double d) {
    DCI_NO_CONTRACT
    return k * d * sqrt(d);
}
DC_INLINE_FN double dci_p15_damped(double k, double c, double d, double vn, double m) {
    DCI_NO_CONTRACT
    const double q = sqrt(d);
    return DCI_M(k * d, q) + DCI_M(c * sqrt(m * q), vn);
}
/* p = 2: k d^2 [+ c sqrt(m d) vn] */
DC_INLINE_FN double dci_p2_elastic(double k, double d) {
    DCI_NO_CONTRACT
    return k * d * d;
}
DC_INLINE_FN double dci_p2_damped(double k, double c, double d, double vn, double m) {
    DCI_NO_CONTRACT
    return DCI_M(k * d, d) + DCI_M(c * sqrt(m * d), vn);
}
/* other p: s = d^h, h = (p-1)/2; k d s^2 [+ c sqrt(m) s vn] */
DC_INLINE_FN double dci_gen_elastic(double k, double h, double d) {
    DCI_NO_CONTRACT
    const double s = dc_pow_inline(d, h);
    return k * d * s * s;
}
DC_INLINE_FN double dci_gen_damped(double k, double c, double h, double d, double vn, double m) {
    DCI_NO_CONTRACT
    const double s = dc_pow_inline(d, h);
    return DCI_M(k * d * s, s) + DCI_M(c * sqrt(m) * s, vn);
}
/* Hertz, k = (4/3) E*: q = sqrt(r d); k q d [+ c sqrt(m q) vn] */
DC_INLINE_FN double dci_hertz_elastic(double k, double d, double r) {
    DCI_NO_CONTRACT
    return k * sqrt(r * d) * d;
}
DC_INLINE_FN double dci_hertz_damped(double k, double c, double d, double vn, double r, double m) {
    DCI_NO_CONTRACT
    const double q = sqrt(r * d);
    return DCI_M(k * q, d) + DCI_M(c * sqrt(m * q), vn);
}
/* viscoelastic: k sqrt(r d) (d + c vn), c = (3/2) A */
DC_INLINE_FN double dci_visco(double k, double c, double d, double vn, double r) {
    DCI_NO_CONTRACT
    return k * sqrt(r * d) * (d + DCI_M(c, vn));
}

/* dc_normal_force_inline with the kernel code given separately (it must be pair->kernel, e.g.
 * DC_KERNEL_HERTZ_DAMPED_CLAMPED for a dc_pair_hertz(..., e < 1, DC_END_FORCE) pair): with a
 * constant `kernel` the switch folds away when inlined, and a host loop over contacts compiles to
 * the hand-written formula, vectorised where the flags allow (-fno-math-errno). A host that picks
 * the pair at run time switches once outside its loop: `switch (pair.kernel) { case
 * DC_KERNEL_HERTZ_DAMPED_CLAMPED: for (...) F[i] = dc_normal_force_kernel_inline(
 * DC_KERNEL_HERTZ_DAMPED_CLAMPED, &pair, ...); break; ... }`. */
DC_INLINE_FN double dc_normal_force_kernel_inline(int32_t kernel, const dc_pair *pair,
                                                  double overlap, double vn, double r_eff,
                                                  double m_eff) {
    if (!pair) return (double)NAN;
    const double k = pair->k, c = pair->c, h = pair->h, d = overlap;
    switch (kernel) {
    case DC_KERNEL_LIN_ELASTIC: return dci_finish(dci_lin_elastic(k, d), d, 0);
    case DC_KERNEL_LIN_DAMPED: return dci_finish(dci_lin_damped(k, c, d, vn, m_eff), d, 0);
    case DC_KERNEL_LIN_DAMPED_CLAMPED: return dci_finish(dci_lin_damped(k, c, d, vn, m_eff), d, 1);
    case DC_KERNEL_P15_ELASTIC: return dci_finish(dci_p15_elastic(k, d), d, 0);
    case DC_KERNEL_P15_DAMPED: return dci_finish(dci_p15_damped(k, c, d, vn, m_eff), d, 0);
    case DC_KERNEL_P15_DAMPED_CLAMPED: return dci_finish(dci_p15_damped(k, c, d, vn, m_eff), d, 1);
    case DC_KERNEL_P2_ELASTIC: return dci_finish(dci_p2_elastic(k, d), d, 0);
    case DC_KERNEL_P2_DAMPED: return dci_finish(dci_p2_damped(k, c, d, vn, m_eff), d, 0);
    case DC_KERNEL_P2_DAMPED_CLAMPED: return dci_finish(dci_p2_damped(k, c, d, vn, m_eff), d, 1);
    case DC_KERNEL_GEN_ELASTIC: return dci_finish(dci_gen_elastic(k, h, d), d, 0);
    case DC_KERNEL_GEN_DAMPED: return dci_finish(dci_gen_damped(k, c, h, d, vn, m_eff), d, 0);
    case DC_KERNEL_GEN_DAMPED_CLAMPED:
        return dci_finish(dci_gen_damped(k, c, h, d, vn, m_eff), d, 1);
    case DC_KERNEL_HERTZ_ELASTIC: return dci_finish(dci_hertz_elastic(k, d, r_eff), d, 0);
    case DC_KERNEL_HERTZ_DAMPED:
        return dci_finish(dci_hertz_damped(k, c, d, vn, r_eff, m_eff), d, 0);
    case DC_KERNEL_HERTZ_DAMPED_CLAMPED:
        return dci_finish(dci_hertz_damped(k, c, d, vn, r_eff, m_eff), d, 1);
    case DC_KERNEL_VISCO_DAMPED: return dci_finish(dci_visco(k, c, d, vn, r_eff), d, 0);
    case DC_KERNEL_VISCO_DAMPED_CLAMPED: return dci_finish(dci_visco(k, c, d, vn, r_eff), d, 1);
    default: return (double)NAN;
    }
}

/* Normal force [N] of one contact, positive = repulsive: the library's dc_normal_force (same
 * sign conventions, same behaviour on every input: overlap <= 0 or NaN -> 0, pair NULL or not
 * made by a constructor -> NaN), bit for bit. A switch on pair->kernel, then branch-free code.
 * In a loop over many contacts of one pair prefer dc_normal_force_kernel_inline (the switch per
 * call keeps compilers from vectorising the loop). */
DC_INLINE_FN double dc_normal_force_inline(const dc_pair *pair, double overlap, double vn,
                                           double r_eff, double m_eff) {
    if (!pair) return (double)NAN;
    return dc_normal_force_kernel_inline(pair->kernel, pair, overlap, vn, r_eff, m_eff);
}

/* ------------------------------------------------------------------ calibrations (set-up time)
 * src/lsd/{restitution,decay}.rs, src/powerlaw/{calibration,transform}.rs, src/numerics/roots.rs,
 * src/material.rs: the same operations in the same order. */

#define DCI_PI 0x1.921fb54442d18p+1
#define DCI_EPS 0x1p-52

/* Rust's f64::acosh: ln(x + sqrt(x - 1) sqrt(x + 1)) (x >= 1 here). */
DC_INLINE_FN double dci_acosh(double x) {
    DCI_NO_CONTRACT
    return log(x + DCI_M(sqrt(x - 1.0), sqrt(x + 1.0)));
}

/* g(zeta) and dg/dzeta: the log decay to the turning point of the linear spring-dashpot. */
DC_INLINE_FN void dci_decay(double zeta, double *g_out, double *dg_out) {
    DCI_NO_CONTRACT
    if (zeta > 1e8) {
        const double r = 1.0 / zeta;
        const double one_minus_r2 = (1.0 - r) * (1.0 + r);
        const double g = dci_acosh(zeta) / sqrt(one_minus_r2);
        const double hh = g * r;
        *g_out = g;
        *dg_out = (1.0 - DCI_M(hh, r)) / (zeta * one_minus_r2);
        return;
    }
    const double w = (1.0 - zeta) * (1.0 + zeta);
    if ((w < 0.0 ? -w : w) <= 0.125) {
        /* h(w) = sum_{n<21} c_n w^n, c_{n+1} = c_n (2n+1)^2/((2n+2)(2n+3)), by Horner */
        double coef[21];
        coef[0] = 1.0;
        for (int n = 0; n + 1 < 21; n++) {
            const double kk = (double)n;
            coef[n + 1] = coef[n] * (2.0 * kk + 1.0) * (2.0 * kk + 1.0) /
                          ((2.0 * kk + 2.0) * (2.0 * kk + 3.0));
        }
        double hs = 0.0, dh = 0.0;
        for (int n = 20; n >= 0; n--) {
            dh = DCI_M(dh, w) + hs;
            hs = DCI_M(hs, w) + coef[n];
        }
        *g_out = zeta * hs;
        *dg_out = hs - DCI_M(2.0 * zeta * zeta, dh);
        return;
    }
    const double hh = w > 0.0 ? acos(zeta) / sqrt(w) : dci_acosh(zeta) / sqrt(-w);
    *g_out = zeta * hh;
    *dg_out = (hh - zeta) / w;
}

DC_INLINE_FN double dci_zeta_overlap(double e) {
    const double l = -log(e);
    return l / hypot(DCI_PI, l);
}

/* The library's bracketed Newton iteration on g(zeta) - target. 0 on success, else status. */
DC_INLINE_FN int32_t dci_newton(double target, double lo, double hi, double x0, int max_iter,
                                double *out) {
    DCI_NO_CONTRACT
    if (!(lo <= hi) || !isfinite(lo) || !isfinite(hi)) return DC_ERR_NO_CONVERGENCE;
    double x = x0 < lo ? lo : (x0 > hi ? hi : x0);
    double prev_step = (double)INFINITY;
    double best_x = x, best_f = (double)INFINITY;
    for (int it = 0; it < max_iter; it++) {
        double g, dg;
        dci_decay(x, &g, &dg);
        const double fx = g - target;
        if (fx == 0.0) {
            *out = x;
            return DC_OK;
        }
        if ((fx < 0.0 ? -fx : fx) < best_f) {
            best_x = x;
            best_f = fx < 0.0 ? -fx : fx;
        }
        if (fx < 0.0) lo = x;
        else hi = x;
        const double newton = x - fx / dg;
        const int is_newton = isfinite(newton) && newton >= lo && newton <= hi;
        const double next = is_newton ? newton
                            : (lo > 0.0 && hi > 4.0 * lo) ? sqrt(lo * hi)
                                                          : 0.5 * (lo + hi);
        const double step = next - x < 0.0 ? -(next - x) : next - x;
        x = next;
        const double ax = x < 0.0 ? -x : x;
        if (step <= DCI_M(2.0 * DCI_EPS, ax) || hi - lo <= DCI_M(2.0 * DCI_EPS, ax)) {
            *out = x;
            return DC_OK;
        }
        if (is_newton && step < 1e-9 * ax && step > 0.5 * prev_step) {
            *out = best_x;
            return DC_OK;
        }
        prev_step = step;
    }
    return DC_ERR_NO_CONVERGENCE;
}

DC_INLINE_FN int32_t dci_zeta_force(double e, double *out) {
    DCI_NO_CONTRACT
    const double target = -0.5 * log(e);
    if (target == 0.0) {
        *out = 0.0;
        return DC_OK;
    }
    if (target <= 1.0) {
        const double lo = dci_zeta_overlap(e);
        return dci_newton(target, lo, 1.0, lo, 60, out);
    }
    const double hi = 0.5 * exp(target);
    const double z0 = hi;
    double x0 = z0 * exp(-(target - 0.5) / (2.0 * z0 * z0));
    x0 = x0 < 1.0 ? 1.0 : (x0 > hi ? hi : x0);
    return dci_newton(target, 1.0, hi, x0, 200, out);
}

DC_INLINE_FN int32_t dci_check_exponent(double p) {
    if (!isfinite(p)) return DC_ERR_NOT_FINITE;
    if (!(p >= 1.0)) return DC_ERR_EXPONENT_RANGE;
    return DC_OK;
}

/* sqrt(2(p+1)) = alpha/zeta */
DC_INLINE_FN double dci_damping_scale(double p) {
    return 0x1.6a09e667f3bcdp+0 * sqrt(p + 1.0);
}

DC_INLINE_FN int32_t dci_alpha_from_e(double e, double p, int32_t criterion, double *alpha) {
    if (criterion != DC_END_OVERLAP && criterion != DC_END_FORCE) return DC_ERR_CRITERION;
    if (!isfinite(e)) return DC_ERR_NOT_FINITE;
    const int32_t sp = dci_check_exponent(p);
    if (sp != DC_OK) return sp;
    if (!(e > 0.0 && e <= 1.0)) return DC_ERR_RESTITUTION_RANGE;
    double zeta;
    if (criterion == DC_END_OVERLAP) {
        zeta = dci_zeta_overlap(e);
    } else {
        const int32_t s = dci_zeta_force(e, &zeta);
        if (s != DC_OK) return s;
    }
    const double a = zeta * dci_damping_scale(p);
    if (!isfinite(a)) return DC_ERR_RESULT_RANGE;
    *alpha = a;
    return DC_OK;
}

/* Damping coefficient alpha of the power-law (Tsuji) contact with exponent p that realises
 * restitution e under `criterion`: the library's dc_alpha_from_e (overlap end in closed form,
 * force end by the same safeguarded Newton iteration). alpha_out is written only on DC_OK. */
DC_INLINE_FN int32_t dc_alpha_from_e_inline(double e, double p, int32_t criterion,
                                            double *alpha_out) {
    if (!alpha_out) return DC_ERR_NULL_POINTER;
    return dci_alpha_from_e(e, p, criterion, alpha_out);
}

DC_INLINE_FN int32_t dci_e_from_alpha(double alpha, double p, int32_t criterion, double *e_out) {
    DCI_NO_CONTRACT
    if (criterion != DC_END_OVERLAP && criterion != DC_END_FORCE) return DC_ERR_CRITERION;
    if (!isfinite(alpha)) return DC_ERR_NOT_FINITE;
    const int32_t sp = dci_check_exponent(p);
    if (sp != DC_OK) return sp;
    if (alpha < 0.0) return DC_ERR_NEGATIVE;
    const double s = dci_damping_scale(p);
    if (criterion == DC_END_OVERLAP) {
        *e_out = alpha >= s ? 0.0 : exp(-DCI_PI * alpha / sqrt((s - alpha) * (s + alpha)));
    } else {
        double g, dg;
        dci_decay(alpha / s, &g, &dg);
        *e_out = exp(-2.0 * g);
    }
    return DC_OK;
}

/* Restitution realised by damping coefficient alpha >= 0 (the library's dc_e_from_alpha). */
DC_INLINE_FN int32_t dc_e_from_alpha_inline(double alpha, double p, int32_t criterion,
                                            double *e_out) {
    if (!e_out) return DC_ERR_NULL_POINTER;
    return dci_e_from_alpha(alpha, p, criterion, e_out);
}

DC_INLINE_FN int32_t dci_check_modulus(double E, double nu) {
    if (!isfinite(E) || !isfinite(nu)) return DC_ERR_NOT_FINITE;
    if (!(E > 0.0 && nu > -1.0 && nu <= 0.5)) return DC_ERR_NOT_POSITIVE;
    return DC_OK;
}

DC_INLINE_FN int32_t dci_effective_modulus(double E1, double nu1, double E2, double nu2,
                                           double *out) {
    DCI_NO_CONTRACT
    int32_t s = dci_check_modulus(E1, nu1);
    if (s != DC_OK) return s;
    s = dci_check_modulus(E2, nu2);
    if (s != DC_OK) return s;
    const double c1 = (1.0 - nu1) * (1.0 + nu1) / E1;
    const double c2 = (1.0 - nu2) * (1.0 + nu2) / E2;
    const double es = 1.0 / (c1 + c2);
    if (!isfinite(es)) return DC_ERR_RESULT_RANGE;
    *out = es;
    return DC_OK;
}

/* Effective modulus E*, 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 (the library's dc_effective_modulus). */
DC_INLINE_FN int32_t dc_effective_modulus_inline(double E1, double nu1, double E2, double nu2,
                                                 double *e_star_out) {
    if (!e_star_out) return DC_ERR_NULL_POINTER;
    return dci_effective_modulus(E1, nu1, E2, nu2, e_star_out);
}

DC_INLINE_FN int32_t dci_pick(int damped, int32_t criterion, int32_t elastic, int32_t free_,
                              int32_t clamped) {
    return !damped ? elastic : (criterion == DC_END_OVERLAP ? free_ : clamped);
}

DC_INLINE_FN void dci_fill(dc_pair *o, int32_t model, int32_t kernel, int32_t criterion, double p,
                           double stiffness, double alpha, double a, double e, double k, double c,
                           double h) {
    o->model = model;
    o->kernel = kernel;
    o->criterion = criterion;
    o->clamp = criterion == DC_END_FORCE;
    o->p = p;
    o->stiffness = stiffness;
    o->alpha = alpha;
    o->damping_a = a;
    o->e = e;
    o->k = k;
    o->c = c;
    o->h = h;
}

DC_INLINE_FN int32_t dci_check_stiffness(double k) {
    if (!isfinite(k)) return DC_ERR_NOT_FINITE;
    if (!(k > 0.0)) return DC_ERR_NOT_POSITIVE;
    return DC_OK;
}

DC_INLINE_FN int32_t dci_powerlaw_from_alpha(double p, double k, double alpha, int32_t criterion,
                                             dc_pair *out) {
    int32_t s = dci_check_exponent(p);
    if (s != DC_OK) return s;
    if ((s = dci_check_stiffness(k)) != DC_OK) return s;
    double e;
    if ((s = dci_e_from_alpha(alpha, p, criterion, &e)) != DC_OK) return s;
    const double c = alpha * sqrt(k);
    if (!isfinite(c)) return DC_ERR_RESULT_RANGE;
    const int damped = alpha > 0.0;
    int32_t kernel;
    if (p == 1.0)
        kernel = dci_pick(damped, criterion, DC_KERNEL_LIN_ELASTIC, DC_KERNEL_LIN_DAMPED,
                          DC_KERNEL_LIN_DAMPED_CLAMPED);
    else if (p == 1.5)
        kernel = dci_pick(damped, criterion, DC_KERNEL_P15_ELASTIC, DC_KERNEL_P15_DAMPED,
                          DC_KERNEL_P15_DAMPED_CLAMPED);
    else if (p == 2.0)
        kernel = dci_pick(damped, criterion, DC_KERNEL_P2_ELASTIC, DC_KERNEL_P2_DAMPED,
                          DC_KERNEL_P2_DAMPED_CLAMPED);
    else
        kernel = dci_pick(damped, criterion, DC_KERNEL_GEN_ELASTIC, DC_KERNEL_GEN_DAMPED,
                          DC_KERNEL_GEN_DAMPED_CLAMPED);
    dci_fill(out, DC_MODEL_POWERLAW, kernel, criterion, p, k, alpha, 0.0, e, k, c,
             0.5 * (p - 1.0));
    return DC_OK;
}

/* The library's dc_pair_powerlaw_alpha: power-law pair from alpha >= 0 directly. */
DC_INLINE_FN int32_t dc_pair_powerlaw_alpha_inline(double p, double k, double alpha,
                                                   int32_t criterion, dc_pair *out) {
    if (!out) return DC_ERR_NULL_POINTER;
    if (criterion != DC_END_OVERLAP && criterion != DC_END_FORCE) return DC_ERR_CRITERION;
    dc_pair tmp;
    const int32_t s = dci_powerlaw_from_alpha(p, k, alpha, criterion, &tmp);
    if (s == DC_OK) *out = tmp;
    return s;
}

/* The library's dc_pair_powerlaw: F = k d^p + alpha sqrt(m k) d^((p-1)/2) vn, alpha from e. */
DC_INLINE_FN int32_t dc_pair_powerlaw_inline(double p, double k, double e, int32_t criterion,
                                             dc_pair *out) {
    if (!out) return DC_ERR_NULL_POINTER;
    if (criterion != DC_END_OVERLAP && criterion != DC_END_FORCE) return DC_ERR_CRITERION;
    int32_t s = dci_check_exponent(p);
    if (s != DC_OK) return s;
    if ((s = dci_check_stiffness(k)) != DC_OK) return s;
    double alpha;
    if ((s = dci_alpha_from_e(e, p, criterion, &alpha)) != DC_OK) return s;
    dc_pair tmp;
    if ((s = dci_powerlaw_from_alpha(p, k, alpha, criterion, &tmp)) != DC_OK) return s;
    tmp.e = e; /* the caller's target, as the library keeps it */
    *out = tmp;
    return DC_OK;
}

/* The library's dc_pair_linear (p = 1). */
DC_INLINE_FN int32_t dc_pair_linear_inline(double k, double e, int32_t criterion, dc_pair *out) {
    return dc_pair_powerlaw_inline(1.0, k, e, criterion, out);
}

DC_INLINE_FN int32_t dci_hertz_factor(double E1, double nu1, double E2, double nu2, double *kf) {
    double es;
    const int32_t s = dci_effective_modulus(E1, nu1, E2, nu2, &es);
    if (s != DC_OK) return s;
    const double v = 4.0 / 3.0 * es;
    if (!isfinite(v)) return DC_ERR_RESULT_RANGE;
    *kf = v;
    return DC_OK;
}

/* The library's dc_pair_hertz: k = (4/3) E* sqrt(r_eff) per contact, alpha for p = 3/2. */
DC_INLINE_FN int32_t dc_pair_hertz_inline(double E1, double nu1, double E2, double nu2, double e,
                                          int32_t criterion, dc_pair *out) {
    if (!out) return DC_ERR_NULL_POINTER;
    if (criterion != DC_END_OVERLAP && criterion != DC_END_FORCE) return DC_ERR_CRITERION;
    double kf, alpha;
    int32_t s = dci_hertz_factor(E1, nu1, E2, nu2, &kf);
    if (s != DC_OK) return s;
    if ((s = dci_alpha_from_e(e, 1.5, criterion, &alpha)) != DC_OK) return s;
    const double c = alpha * sqrt(kf);
    if (!isfinite(c)) return DC_ERR_RESULT_RANGE;
    const int32_t kernel = dci_pick(alpha > 0.0, criterion, DC_KERNEL_HERTZ_ELASTIC,
                                    DC_KERNEL_HERTZ_DAMPED, DC_KERNEL_HERTZ_DAMPED_CLAMPED);
    dci_fill(out, DC_MODEL_HERTZ, kernel, criterion, 1.5, kf, alpha, 0.0, e, kf, c, 0.25);
    return DC_OK;
}

/* The library's dc_pair_viscoelastic: rho = (4/3) E* sqrt(r_eff), damping constant A [s]. */
DC_INLINE_FN int32_t dc_pair_viscoelastic_inline(double E1, double nu1, double E2, double nu2,
                                                 double A, int32_t criterion, dc_pair *out) {
    if (!out) return DC_ERR_NULL_POINTER;
    if (criterion != DC_END_OVERLAP && criterion != DC_END_FORCE) return DC_ERR_CRITERION;
    double kf;
    const int32_t s = dci_hertz_factor(E1, nu1, E2, nu2, &kf);
    if (s != DC_OK) return s;
    if (!isfinite(A)) return DC_ERR_NOT_FINITE;
    if (!(A >= 0.0)) return DC_ERR_NEGATIVE;
    const double c = 1.5 * A;
    if (!isfinite(c)) return DC_ERR_RESULT_RANGE;
    const int32_t kernel = dci_pick(A > 0.0, criterion, DC_KERNEL_HERTZ_ELASTIC,
                                    DC_KERNEL_VISCO_DAMPED, DC_KERNEL_VISCO_DAMPED_CLAMPED);
    dci_fill(out, DC_MODEL_VISCOELASTIC, kernel, criterion, 1.5, kf, 0.0, A, (double)NAN, kf, c,
             0.25);
    return DC_OK;
}

#endif /* DEMCONTACT_INLINE_H */
