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
 *   // full contact (normal + tangential + rolling + twisting, caller-owned history):
 *   dc_contact_spec spec;  dc_contact_model model;
 *   dc_contact_spec_init_inline(&spec);    // then spec.normal = DC_NORMAL_HERTZ, ... as for the library
 *   dc_contact_model_init_inline(&spec, &model);   // or the library's dc_contact_model_init
 *   int32_t st = dc_contact_force_inline(&model, &state, dt, history, history_len, &result);
 *   // a host loop over many contacts: check the model once, then the fast entry per contact
 *   if (dc_contact_model_check_inline(&model) == DC_OK)
 *       st = dc_contact_force_checked_inline(&model, &state, dt, history, &result);
 *   // a host that ends its run on any bad value: the checks collected, tested once per pass
 *   dc_contact_checks checks;  dc_contact_checks_init_inline(&checks);
 *   // (per contact, or once on the arrays the states come from: dc_contact_state_check_inline)
 *   dc_contact_force_deferred_inline(&model, &state, dt, history, &result, &checks);
 *   // after the loop, before integrating: st = dc_contact_checks_status_inline(&checks);
 *
 * Contract: the same meaning, statuses and results as the library's functions of the same name
 * without `_inline` (dc_normal_force, dc_alpha_from_e, dc_e_from_alpha, dc_effective_modulus,
 * dc_pair_powerlaw, dc_pair_powerlaw_alpha, dc_pair_linear, dc_pair_hertz, dc_pair_viscoelastic,
 * and the full contact dc_contact_spec_init, dc_contact_model_init, dc_contact_force), reading and
 * filling the same dc_pair / dc_contact_model / dc_contact_result (declared in demcontact.h). The
 * results are bit-identical to the library's for the same inputs (tested over 10^7 random inputs
 * per kernel, C and C++; the full contact over 10^7 steps of random trajectories, the history
 * evolving, with the library and the header each carrying its own):
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
 * through __dmul_rn. nvcc's host side cannot use the barrier (its front end lacks it): with host
 * flags that enable FMA (-Xcompiler -march=...) add -Xcompiler -ffp-contract=off there.
 * One exception: in the deferred entries (dc_contact_force_deferred_inline), whose evaluation
 * has no branch, GCC's SLP vectoriser fuses products across that barrier under
 * -ffp-contract=fast (GCC's default in GNU C and C++ modes) when the target has FMA (x86 with
 * -march=haswell/native, aarch64 always): results then differ from the library's by up to 24
 * ulp of the largest value of a result (measured; ctest inline_contact_fma allows 64); build
 * such hosts with -ffp-contract=off (the LIGGGHTS plugin does).
 * Other compilers: build with contraction off (-ffp-contract=off, /fp:precise
 * without /fp:contract); otherwise results may differ from the library by a few ulp of the
 * larger force term. Value-changing options (-ffast-math, -Ofast) void the bit-identity.
 * DEMCONTACT_INLINE_PLAIN_PRODUCTS (define it before the include, or with -D): for a host
 * compiled with contraction off (GCC and clang: -ffp-contract=off, which also holds inside
 * target attributes). The products are then written as plain `*`, without the per-product
 * barrier GCC otherwise gets on x86-64 and aarch64, which keeps products in registers one by
 * one and from being vectorised together (the LAMMPS plugin's pair time 6 % lower on LAMMPS'
 * flatwall example: docs/lammps_examples.md, "Plain products"). Same bits as the library with
 * contraction off (ctest inline_contact_plain, -march=native); with contraction on it voids the
 * bit-identity. The simulator plugins define it.
 *
 * Kernel codes (dc_pair.kernel, ABI): 1..19 as listed below; any other value gives NaN.
 */
#ifndef DEMCONTACT_INLINE_H
#define DEMCONTACT_INLINE_H

#include "demcontact.h"
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#if defined(__CUDACC__) || defined(__HIPCC__)
#define DC_INLINE_FN static inline __host__ __device__
#else
#define DC_INLINE_FN static inline
#endif

/* The full contact's per-contact helpers (vector algebra, frame carry, kinematics, sub-models,
 * checks): always inlined. Inside a host's large pair loop GCC otherwise keeps some of them out of
 * line (in LIGGGHTS' loop dci_carry and the normal-kernel switch stayed calls, with 3-vectors
 * passed through memory, a measurable share of the scene's loop time: docs/simulators.md,
 * "Wall time"). Inlining changes no rounding (the products stay unfused as below), so no
 * result. The attribute goes after `inline` and before __host__ __device__, where
 * GCC, clang (also in CUDA mode) and nvcc accept it; compilers without GNU attributes get
 * MSVC's __forceinline or a plain inline. */
#if defined(__GNUC__) || defined(__clang__)
#if defined(__CUDACC__) || defined(__HIPCC__)
#define DCI_ALWAYS_INLINE_FN static inline __attribute__((always_inline)) __host__ __device__
#else
#define DCI_ALWAYS_INLINE_FN static inline __attribute__((always_inline))
#endif
#elif defined(_MSC_VER) && !defined(__CUDACC__)
#define DCI_ALWAYS_INLINE_FN static __forceinline
#else
#define DCI_ALWAYS_INLINE_FN DC_INLINE_FN
#endif

/* The checks' error paths as unlikely (GCC, clang, nvcc): laid out away from the hot path (2-3 %
 * less loop time in the LIGGGHTS scene, docs/simulators.md); a hint only, no other effect. */
#if defined(__GNUC__) || defined(__clang__)
#define DCI_UNLIKELY(x) __builtin_expect(!!(x), 0)
#define DCI_LIKELY(x) __builtin_expect(!!(x), 1)
#else
#define DCI_UNLIKELY(x) (x)
#define DCI_LIKELY(x) (x)
#endif

/* A product rounded on its own, never fused with an addition (see the header comment). */
#if defined(__CUDA_ARCH__)
#define DCI_M(a, b) __dmul_rn((a), (b))
#elif defined(DEMCONTACT_INLINE_PLAIN_PRODUCTS)
/* The host promises a build that cannot contract (see the header comment): plain products,
 * which the compiler may schedule and vectorise freely. */
#define DCI_M(a, b) ((a) * (b))
#elif defined(__clang__)
#define DCI_M(a, b) ((a) * (b))
#elif defined(__GNUC__) && !defined(__NVCC__) && defined(__x86_64__)
/* An empty asm that takes the product in an SSE register: GCC cannot fuse what it cannot see.
 * (__builtin_assoc_barrier did not stop GCC 12 from fusing DCI_M products with the sums of
 * dci_cross/dci_add/dci_sub once a large shaped entry was inlined: ctest inline_contact_fma.) */
#define DCI_M(a, b)                                                                              \
    __extension__({                                                                              \
        double dci_m_ = (a) * (b);                                                               \
        __asm__("" : "+x"(dci_m_));                                                              \
        dci_m_;                                                                                  \
    })
#elif defined(__GNUC__) && !defined(__NVCC__) && defined(__aarch64__)
#define DCI_M(a, b)                                                                              \
    __extension__({                                                                              \
        double dci_m_ = (a) * (b);                                                               \
        __asm__("" : "+w"(dci_m_));                                                              \
        dci_m_;                                                                                  \
    })
#elif defined(__GNUC__) && __GNUC__ >= 12 && !defined(__NVCC__)
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

/* BEGIN GENERATED codes */
/* Generated by `cargo run -p xtask -- all` from the registry of normal laws
 * (src/force/registry.rs): do not edit by hand. */
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
#define DC_KERNEL_DMT_ELASTIC 18
#define DC_KERNEL_DMT_DAMPED 19
/* Normal laws with state: contact models only, no dc_pair path. */
#define DC_KERNEL_ELASTIC_PLASTIC 20
#define DC_KERNEL_JKR 21

/* True for the kernel of a normal law with state (src/force/registry.rs `has_state`). */
DCI_ALWAYS_INLINE_FN int dci_has_state(int32_t kernel) {
    switch (kernel) {
    case DC_KERNEL_ELASTIC_PLASTIC:
    case DC_KERNEL_JKR:
        return 1;
    default: return 0;
    }
}

/* True for a kernel code of the registry, with or without state. */
DCI_ALWAYS_INLINE_FN int dci_kernel_known(int32_t kernel) {
    switch (kernel) {
    case DC_KERNEL_LIN_ELASTIC:
    case DC_KERNEL_LIN_DAMPED:
    case DC_KERNEL_LIN_DAMPED_CLAMPED:
    case DC_KERNEL_P15_ELASTIC:
    case DC_KERNEL_P15_DAMPED:
    case DC_KERNEL_P15_DAMPED_CLAMPED:
    case DC_KERNEL_P2_ELASTIC:
    case DC_KERNEL_P2_DAMPED:
    case DC_KERNEL_P2_DAMPED_CLAMPED:
    case DC_KERNEL_GEN_ELASTIC:
    case DC_KERNEL_GEN_DAMPED:
    case DC_KERNEL_GEN_DAMPED_CLAMPED:
    case DC_KERNEL_HERTZ_ELASTIC:
    case DC_KERNEL_HERTZ_DAMPED:
    case DC_KERNEL_HERTZ_DAMPED_CLAMPED:
    case DC_KERNEL_VISCO_DAMPED:
    case DC_KERNEL_VISCO_DAMPED_CLAMPED:
    case DC_KERNEL_DMT_ELASTIC:
    case DC_KERNEL_DMT_DAMPED:
    case DC_KERNEL_ELASTIC_PLASTIC:
    case DC_KERNEL_JKR:
        return 1;
    default: return 0;
    }
}
/* END GENERATED codes */

/* ------------------------------------------------------------------ bits of a double */

DCI_ALWAYS_INLINE_FN uint64_t dci_bits(double x) {
#if defined(__CUDA_ARCH__)
    return (uint64_t)__double_as_longlong(x);
#else
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
#endif
}

DCI_ALWAYS_INLINE_FN double dci_from_bits(uint64_t u) {
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
#define DCI_LN2_32_HI (DCI_LN2_HI / 32.0)    /* exact */
#define DCI_LN2_32_LO (DCI_LN2_LO / 32.0)    /* exact */
#define DCI_INV_LN2_32 (32.0 * 0x1.71547652b82fep+0) /* 32 log2(e), exact scaling */
#define DCI_SHIFTER 6755399441055744.0       /* 1.5 * 2^52 */
#define DCI_TWO52 4503599627370496.0
#define DCI_TWO54 18014398509481984.0
#define DCI_LN2 0x1.62e42fefa39efp-1
#define DCI_K_CLAMP 2044.0
#define DCI_DBL_MIN 0x1p-1022
#define DCI_POW_OFF UINT64_C(0x3fe5c00000000000) /* bits of 0.6796875 */

/* Tables (the power's 32-entry tables of src/numerics/pow_table.rs, the Hurwitz zeta series of
 * the step-aware onset): on the host, static const arrays local to their function; in CUDA/HIP
 * device code (DCI_DEVICE_PASS), arrays in device global memory at file scope, read through the
 * cache. A function-local const array in device code is built in each thread's local memory
 * (the kernels of examples_cpp/gpu/gpu_check.cu had a 1024-byte stack frame for these four). */
#if defined(__CUDA_ARCH__) || defined(__HIP_DEVICE_COMPILE__)
#define DCI_DEVICE_PASS 1
#endif
#if defined(__CUDACC__) || defined(__HIPCC__)
#define DCI_DEVICE_TABLE static __device__ const
#endif
#define DCI_POW_INVC { \
    0x1.745d1745d1746p+0, 0x1.6c16c16c16c17p+0, 0x1.642c8590b2164p+0, \
    0x1.5c9882b931057p+0, 0x1.5555555555555p+0, 0x1.4e5e0a72f0539p+0, \
    0x1.47ae147ae147bp+0, 0x1.4141414141414p+0, 0x1.3b13b13b13b14p+0, \
    0x1.3521cfb2b78c1p+0, 0x1.2f684bda12f68p+0, 0x1.29e4129e4129ep+0, \
    0x1.2492492492492p+0, 0x1.1f7047dc11f70p+0, 0x1.1a7b9611a7b96p+0, \
    0x1.15b1e5f75270dp+0, 0x1.1111111111111p+0, 0x1.0c9714fbcda3bp+0, \
    0x1.0842108421084p+0, 0x1.0410410410410p+0, 0x1.0000000000000p+0, \
    0x1.f07c1f07c1f08p-1, 0x1.e1e1e1e1e1e1ep-1, 0x1.d41d41d41d41dp-1, \
    0x1.c71c71c71c71cp-1, 0x1.bacf914c1bad0p-1, 0x1.af286bca1af28p-1, \
    0x1.a41a41a41a41ap-1, 0x1.999999999999ap-1, 0x1.8f9c18f9c18fap-1, \
    0x1.8618618618618p-1, 0x1.7d05f417d05f4p-1 \
    }
#define DCI_POW_LOGC { \
    -0x1.7fafa3bd8151cp-2, -0x1.68ac83e9c6a14p-2, -0x1.522ae0738a3d8p-2, \
    -0x1.3c25277333184p-2, -0x1.269621134db92p-2, -0x1.1178e8227e47cp-2, \
    -0x1.f991c6cb3b379p-3, -0x1.d1037f2655e7bp-3, -0x1.a93ed3c8ad9e3p-3, \
    -0x1.823c16551a3c2p-3, -0x1.5bf406b543db2p-3, -0x1.365fcb0159016p-3, \
    -0x1.1178e8227e47cp-3, -0x1.da727638446a2p-4, -0x1.9335e5d594989p-4, \
    -0x1.4d3115d207eacp-4, -0x1.08598b59e3a07p-4, -0x1.894aa149fb343p-5, \
    -0x1.0415d89e74444p-5, -0x1.0205658935847p-6, 0x0.0p+0, \
    0x1.f829b0e783300p-6, 0x1.f0a30c01162a6p-5, 0x1.6f0d28ae56b4cp-4, \
    0x1.e27076e2af2e6p-4, 0x1.29552f81ff523p-3, 0x1.5ff3070a793d4p-3, \
    0x1.9525a9cf456b4p-3, 0x1.c8ff7c79a9a22p-3, 0x1.fb9186d5e3e2bp-3, \
    0x1.1675cababa60ep-2, 0x1.2e8e2bae11d31p-2 \
    }
#define DCI_POW_EXP2_HI { \
    0x1.0000000000000p+0, 0x1.059b0d3158574p+0, 0x1.0b5586cf9890fp+0, \
    0x1.11301d0125b51p+0, 0x1.172b83c7d517bp+0, 0x1.1d4873168b9aap+0, \
    0x1.2387a6e756238p+0, 0x1.29e9df51fdee1p+0, 0x1.306fe0a31b715p+0, \
    0x1.371a7373aa9cbp+0, 0x1.3dea64c123422p+0, 0x1.44e086061892dp+0, \
    0x1.4bfdad5362a27p+0, 0x1.5342b569d4f82p+0, 0x1.5ab07dd485429p+0, \
    0x1.6247eb03a5585p+0, 0x1.6a09e667f3bcdp+0, 0x1.71f75e8ec5f74p+0, \
    0x1.7a11473eb0187p+0, 0x1.82589994cce13p+0, 0x1.8ace5422aa0dbp+0, \
    0x1.93737b0cdc5e5p+0, 0x1.9c49182a3f090p+0, 0x1.a5503b23e255dp+0, \
    0x1.ae89f995ad3adp+0, 0x1.b7f76f2fb5e47p+0, 0x1.c199bdd85529cp+0, \
    0x1.cb720dcef9069p+0, 0x1.d5818dcfba487p+0, 0x1.dfc97337b9b5fp+0, \
    0x1.ea4afa2a490dap+0, 0x1.f50765b6e4540p+0 \
    }
#define DCI_POW_EXP2_LO { \
    0x0.0p+0, 0x1.d73e2a475b465p-55, 0x1.8a62e4adc610bp-54, \
    -0x1.6c51039449b3ap-54, -0x1.19041b9d78a76p-55, 0x1.e016e00a2643cp-54, \
    0x1.9b07eb6c70573p-54, 0x1.612e8afad1255p-55, 0x1.6f46ad23182e4p-55, \
    -0x1.63aeabf42eae2p-54, 0x1.ada0911f09ebcp-55, 0x1.89b7a04ef80d0p-59, \
    0x1.d4397afec42e2p-56, -0x1.07abe1db13cadp-55, 0x1.6324c054647adp-54, \
    -0x1.383c17e40b497p-54, -0x1.bdd3413b26456p-54, -0x1.16e4786887a99p-55, \
    -0x1.41577ee04992fp-55, -0x1.d4c1dd41532d8p-54, 0x1.6e9f156864b27p-54, \
    -0x1.75fc781b57ebcp-57, 0x1.c7c46b071f2bep-56, -0x1.d2f6edb8d41e1p-54, \
    0x1.7a1cd345dcc81p-54, -0x1.5584f7e54ac3bp-56, 0x1.11065895048ddp-55, \
    0x1.503cbd1e949dbp-56, 0x1.2ed02d75b3707p-55, -0x1.1a5cd4f184b5cp-54, \
    -0x1.e9c23179c2893p-54, 0x1.9d3e12dd8a18bp-54 \
    }
#if defined(__CUDACC__) || defined(__HIPCC__)
DCI_DEVICE_TABLE double dci_dev_invc[32] = DCI_POW_INVC;
DCI_DEVICE_TABLE double dci_dev_logc[32] = DCI_POW_LOGC;
DCI_DEVICE_TABLE double dci_dev_exp2_hi[32] = DCI_POW_EXP2_HI;
DCI_DEVICE_TABLE double dci_dev_exp2_lo[32] = DCI_POW_EXP2_LO;
#endif

/* 2^k for an integer-valued k in [-1022, 1023]. */
DC_INLINE_FN double dci_exp2i(double kf) {
    DCI_NO_CONTRACT
    return dci_from_bits((dci_bits(kf + (DCI_SHIFTER + 1023.0)) - dci_bits(DCI_SHIFTER)) << 52);
}

/* x^q for x >= 0 (subnormal and +inf included) and finite q > 0: branch-free, no libm; within
 * 2 ulp of glibc's pow for q <= 2 (p <= 5), 1 + q ulp beyond; subnormal results within one
 * subnormal ulp. Negative or NaN x give an unspecified number. x = 2^e z, z in [0.6797, 1.3594);
 * ln z = ln c_i + ln(1 + u), u = (z - c_i) RN(1/c_i), c_i the middle of z's 1/32 of the range;
 * q e = P + Q exactly (q cut into 26 + 27 bits); x^q = 2^n e^t, n = round(P),
 * t = (P - n + Q) ln 2 + q ln z; e^t = 2^((k-j)/32) 2^(j/32) e^r, k = round(32 t/ln 2),
 * j = k mod 32. */
DC_INLINE_FN double dc_pow_inline(double x, double q) {
    DCI_NO_CONTRACT
#if defined(DCI_DEVICE_PASS)
    const double *const invc = dci_dev_invc, *const logc = dci_dev_logc;
    const double *const exp2_hi = dci_dev_exp2_hi, *const exp2_lo = dci_dev_exp2_lo;
#else
    static const double invc[32] = DCI_POW_INVC, logc[32] = DCI_POW_LOGC;
    static const double exp2_hi[32] = DCI_POW_EXP2_HI, exp2_lo[32] = DCI_POW_EXP2_LO;
#endif
    const int pos = x > 0.0 && x < (double)INFINITY;
    double safe = pos ? x : 1.0;
    const int sub = safe < DCI_DBL_MIN;
    safe = sub ? DCI_M(safe, DCI_TWO54) : safe;
    /* x = 2^e z, and ln z */
    const uint64_t ix = dci_bits(safe);
    const uint64_t tmp = ix - DCI_POW_OFF;
    const uint64_t eb = (tmp + (UINT64_C(1024) << 52)) >> 52;
    double e = dci_from_bits(UINT64_C(0x4330000000000000) | eb) - (DCI_TWO52 + 1024.0);
    const double z = dci_from_bits(ix - (tmp & (UINT64_C(0xfff) << 52)));
    const double c = dci_from_bits(DCI_POW_OFF + (tmp & (UINT64_C(31) << 47)) + (UINT64_C(1) << 46));
    const unsigned i = (unsigned)((tmp >> 47) & 31u);
    const double u = DCI_M(z - c, invc[i]);
    const double u2 = DCI_M(u, u), u4 = DCI_M(u2, u2);
    const double b0 = -1.0 / 2.0 + DCI_M(1.0 / 3.0, u);
    const double b1 = -1.0 / 4.0 + DCI_M(1.0 / 5.0, u);
    const double b2 = -1.0 / 6.0 + DCI_M(1.0 / 7.0, u);
    const double b3 = -1.0 / 8.0 + DCI_M(1.0 / 9.0, u);
    const double c0 = b0 + DCI_M(b1, u2);
    const double c1 = b2 + DCI_M(b3, u2);
    const double l = c0 + DCI_M(c1, u4);
    const double ln_z = logc[i] + (u + DCI_M(u2, l));
    e = sub ? e - 54.0 : e;
    /* q e = P + Q exactly; n = round(P) */
    const double qh = dci_from_bits(dci_bits(q) & ~((UINT64_C(1) << 27) - 1));
    const double ql = q - qh;
    const double big_p = DCI_M(qh, e);
    const double small_q = DCI_M(ql, e);
    const double n = (big_p + DCI_SHIFTER) - DCI_SHIFTER;
    const double frac = (big_p - n) + small_q;
    const double t = DCI_M(frac, DCI_LN2) + DCI_M(q, ln_z);
    /* e^t = 2^k_hi p */
    const double y = DCI_M(t, DCI_INV_LN2_32) + DCI_SHIFTER;
    const double kf = y - DCI_SHIFTER;
    const unsigned j = (unsigned)(dci_bits(y) & 31u);
    const double jf = dci_from_bits(UINT64_C(0x4330000000000000) | j) - DCI_TWO52;
    const double k_hi = DCI_M(kf - jf, 1.0 / 32.0);
    const double r = (t - DCI_M(kf, DCI_LN2_32_HI)) - DCI_M(kf, DCI_LN2_32_LO);
    const double r2 = DCI_M(r, r);
    const double e0 = 1.0 / 2.0 + DCI_M(1.0 / 6.0, r);
    const double e1 = 1.0 / 24.0 + DCI_M(1.0 / 120.0, r);
    const double e2 = e0 + DCI_M(e1, r2);
    const double w = r + DCI_M(r2, e2 + DCI_M(1.0 / 720.0, DCI_M(r2, r2)));
    const double hi = exp2_hi[j];
    const double poly = hi + (exp2_lo[j] + DCI_M(hi, w));
    double total = n + k_hi;
    total = total < -DCI_K_CLAMP ? -DCI_K_CLAMP : (total > DCI_K_CLAMP ? DCI_K_CLAMP : total);
    const double k1 = (DCI_M(0.5, total) + DCI_SHIFTER) - DCI_SHIFTER;
    const double v = DCI_M(DCI_M(poly, dci_exp2i(k1)), dci_exp2i(total - k1));
    return x == 0.0 ? 0.0 : (x == (double)INFINITY ? (double)INFINITY : v);
}

/* ------------------------------------------------------------------ the stateless force kernels
 * Raw forces of each law (src/force/{powerlaw,hertz,viscoelastic}.rs), k, c, h = dc_pair.k, .c,
 * .h; then dci_finish: zero without overlap (also for NaN d), clamp when the pair clamps. */

DCI_ALWAYS_INLINE_FN double dci_finish(double f, double d, int clamp) {
    if (clamp) f = f > 0.0 ? f : 0.0;
    return d > 0.0 ? f : 0.0;
}

/* BEGIN GENERATED kernels */
/* Generated by `cargo run -p xtask -- all` from the stateless kernels of the registry of
 * normal laws (src/force/registry.rs), each translated from the Rust function its comment
 * names (xtask/src/kernels.rs): do not edit by hand. */
/* src/force/hertz.rs `HertzElastic::raw` */
DCI_ALWAYS_INLINE_FN double dci_hertz_elastic(double k, double d, double r) {
    DCI_NO_CONTRACT
    return (k * sqrt(r * d)) * d;
}
/* src/force/hertz.rs `HertzDamped::raw` */
DCI_ALWAYS_INLINE_FN double dci_hertz_damped(double k, double c, double d, double vn, double r,
                                             double m) {
    DCI_NO_CONTRACT
    const double q = sqrt(r * d);
    return DCI_M(k * q, d) + DCI_M(c * sqrt(m * q), vn);
}
/* src/force/powerlaw.rs `LinElastic::raw` */
DCI_ALWAYS_INLINE_FN double dci_lin_elastic(double k, double d) {
    DCI_NO_CONTRACT
    return k * d;
}
/* src/force/powerlaw.rs `LinDamped::raw` */
DCI_ALWAYS_INLINE_FN double dci_lin_damped(double k, double c, double d, double vn, double m) {
    DCI_NO_CONTRACT
    return DCI_M(k, d) + DCI_M(c * sqrt(m), vn);
}
/* src/force/powerlaw.rs `P15Elastic::raw` */
DCI_ALWAYS_INLINE_FN double dci_p15_elastic(double k, double d) {
    DCI_NO_CONTRACT
    return (k * d) * sqrt(d);
}
/* src/force/powerlaw.rs `P15Damped::raw` */
DCI_ALWAYS_INLINE_FN double dci_p15_damped(double k, double c, double d, double vn, double m) {
    DCI_NO_CONTRACT
    const double q = sqrt(d);
    return DCI_M(k * d, q) + DCI_M(c * sqrt(m * q), vn);
}
/* src/force/powerlaw.rs `P2Elastic::raw` */
DCI_ALWAYS_INLINE_FN double dci_p2_elastic(double k, double d) {
    DCI_NO_CONTRACT
    return (k * d) * d;
}
/* src/force/powerlaw.rs `P2Damped::raw` */
DCI_ALWAYS_INLINE_FN double dci_p2_damped(double k, double c, double d, double vn, double m) {
    DCI_NO_CONTRACT
    return DCI_M(k * d, d) + DCI_M(c * sqrt(m * d), vn);
}
/* src/force/powerlaw.rs `GenElastic::raw` */
DC_INLINE_FN double dci_gen_elastic(double k, double h, double d) {
    DCI_NO_CONTRACT
    const double s = dc_pow_inline(d, h);
    return ((k * d) * s) * s;
}
/* src/force/powerlaw.rs `GenDamped::raw` */
DC_INLINE_FN double dci_gen_damped(double k, double c, double h, double d, double vn, double m) {
    DCI_NO_CONTRACT
    const double s = dc_pow_inline(d, h);
    return DCI_M((k * d) * s, s) + DCI_M((c * sqrt(m)) * s, vn);
}
/* src/force/viscoelastic.rs `Viscoelastic::raw` */
DCI_ALWAYS_INLINE_FN double dci_visco_damped(double k, double c, double d, double vn, double r) {
    DCI_NO_CONTRACT
    return (k * sqrt(r * d)) * (d + DCI_M(c, vn));
}
/* src/force/dmt.rs `reach` */
DC_INLINE_FN double dci_dmt_reach(double k, double h, double r) {
    DCI_NO_CONTRACT
    const double x = (h * sqrt(r)) / k;
    if (x >= 0.0) {
        return dc_pow_inline(x, 2.0 / 3.0);
    } else {
        return x;
    }
}
/* src/force/dmt.rs `tail` */
DC_INLINE_FN double dci_dmt_tail(double k, double h, double d, double r) {
    DCI_NO_CONTRACT
    const double dc = dci_dmt_reach(k, h, r);
    const double s = 1.0 + (d / dc);
    if (s > 0.0) {
        return ((-h) * r) * s;
    } else {
        return 0.0;
    }
}
/* src/force/dmt.rs `DmtElastic::raw` */
DC_INLINE_FN double dci_dmt_elastic(double k, double h, double d, double r) {
    DCI_NO_CONTRACT
    if (d > 0.0) {
        return DCI_M(k * sqrt(r * d), d) - DCI_M(h, r);
    } else {
        return dci_dmt_tail(k, h, d, r);
    }
}
/* src/force/dmt.rs `DmtDamped::raw` */
DC_INLINE_FN double dci_dmt_damped(double k, double c, double h, double d, double vn, double r,
                                   double m) {
    DCI_NO_CONTRACT
    if (d > 0.0) {
        const double q = sqrt(r * d);
        return (DCI_M(k * q, d) + DCI_M(c * sqrt(m * q), vn)) - DCI_M(h, r);
    } else {
        return dci_dmt_tail(k, h, d, r);
    }
}
/* src/force/dmt.rs `critical_load` */
DCI_ALWAYS_INLINE_FN double dci_dmt_critical_load(double h, double r, double f) {
    DCI_NO_CONTRACT
    return fabs(f + DCI_M(2.0, h * r));
}
/* END GENERATED kernels */

/* dc_normal_force_inline with the kernel code given separately (it must be pair->kernel, e.g.
 * DC_KERNEL_HERTZ_DAMPED_CLAMPED for a dc_pair_hertz(..., e < 1, DC_END_FORCE) pair): with a
 * constant `kernel` the switch folds away when inlined, and a host loop over contacts compiles to
 * the hand-written formula, vectorised where the flags allow (-fno-math-errno). A host that picks
 * the pair at run time switches once outside its loop: `switch (pair.kernel) { case
 * DC_KERNEL_HERTZ_DAMPED_CLAMPED: for (...) F[i] = dc_normal_force_kernel_inline(
 * DC_KERNEL_HERTZ_DAMPED_CLAMPED, &pair, ...); break; ... }`. Always inlined: in a large host
 * loop (LIGGGHTS' pair loop) GCC otherwise kept it out of line even with a constant kernel, one
 * call and the whole switch per contact. */
DCI_ALWAYS_INLINE_FN double dc_normal_force_kernel_inline(int32_t kernel, const dc_pair *pair,
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
    case DC_KERNEL_VISCO_DAMPED: return dci_finish(dci_visco_damped(k, c, d, vn, r_eff), d, 0);
    case DC_KERNEL_VISCO_DAMPED_CLAMPED: return dci_finish(dci_visco_damped(k, c, d, vn, r_eff), d, 1);
    case DC_KERNEL_DMT_ELASTIC: return dci_dmt_elastic(k, h, d, r_eff);
    case DC_KERNEL_DMT_DAMPED: return dci_dmt_damped(k, c, h, d, vn, r_eff, m_eff);
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

/* The normal force f of one contact and, in the same pass, fe: the force the same pair gives at
 * vn = 0, bit for bit dc_normal_force_kernel_inline(pair->kernel, pair, d, 0.0, r, m) (the EPSD
 * rolling's Ai stiffness rule needs the elastic force p F_el/d; evaluating the kernel a second
 * time repeated its square roots). Each damped kernel is el + c' vn (el, c' rounded as in the
 * kernel), so fe = el + c' 0.0, rounded and finished as the kernel would (c' 0.0 is kept: it is
 * -0 or NaN for some c'; no compiler folds it without -ffast-math); the elastic kernels and
 * unknown codes do not read vn, so fe = f. */
DCI_ALWAYS_INLINE_FN double dci_normal_force_fe(const dc_pair *pair, int32_t kernel, double d,
                                                double vn, double r, double m, double *fe) {
    DCI_NO_CONTRACT
    const double k = pair->k, c = pair->c, h = pair->h;
    double el, cd;
    int clamp;
    switch (kernel) {
    case DC_KERNEL_LIN_DAMPED:
    case DC_KERNEL_LIN_DAMPED_CLAMPED:
        el = DCI_M(k, d);
        cd = c * sqrt(m);
        break;
    case DC_KERNEL_P15_DAMPED:
    case DC_KERNEL_P15_DAMPED_CLAMPED: {
        const double q = sqrt(d);
        el = DCI_M(k * d, q);
        cd = c * sqrt(m * q);
        break;
    }
    case DC_KERNEL_P2_DAMPED:
    case DC_KERNEL_P2_DAMPED_CLAMPED:
        el = DCI_M(k * d, d);
        cd = c * sqrt(m * d);
        break;
    case DC_KERNEL_GEN_DAMPED:
    case DC_KERNEL_GEN_DAMPED_CLAMPED: {
        const double s = dc_pow_inline(d, h);
        el = DCI_M(k * d * s, s);
        cd = c * sqrt(m) * s;
        break;
    }
    case DC_KERNEL_HERTZ_DAMPED:
    case DC_KERNEL_HERTZ_DAMPED_CLAMPED: {
        const double q = sqrt(r * d);
        el = DCI_M(k * q, d);
        cd = c * sqrt(m * q);
        break;
    }
    case DC_KERNEL_VISCO_DAMPED:
    case DC_KERNEL_VISCO_DAMPED_CLAMPED: {
        /* k sqrt(r d) (d + c vn) */
        clamp = kernel == DC_KERNEL_VISCO_DAMPED_CLAMPED;
        const double g = k * sqrt(r * d);
        *fe = dci_finish(g * (d + DCI_M(c, 0.0)), d, clamp);
        return dci_finish(g * (d + DCI_M(c, vn)), d, clamp);
    }
    case DC_KERNEL_DMT_DAMPED: {
        if (!(d > 0.0)) return *fe = dci_dmt_tail(k, h, d, r);
        const double q = sqrt(r * d);
        const double a = DCI_M(k * q, d), b = c * sqrt(m * q), hr = DCI_M(h, r);
        *fe = (a + DCI_M(b, 0.0)) - hr;
        return (a + DCI_M(b, vn)) - hr;
    }
    default: /* elastic kernels (vn not read) and unknown codes (NaN) */
        return *fe = dc_normal_force_kernel_inline(kernel, pair, d, vn, r, m);
    }
    /* the clamped codes of the damped kernels above */
    clamp = kernel == DC_KERNEL_LIN_DAMPED_CLAMPED || kernel == DC_KERNEL_P15_DAMPED_CLAMPED ||
            kernel == DC_KERNEL_P2_DAMPED_CLAMPED || kernel == DC_KERNEL_GEN_DAMPED_CLAMPED ||
            kernel == DC_KERNEL_HERTZ_DAMPED_CLAMPED;
    *fe = dci_finish(el + DCI_M(cd, 0.0), d, clamp);
    return dci_finish(el + DCI_M(cd, vn), d, clamp);
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
        /* The roots apart only where the product overflows (p beyond ~9e307): as the library. */
        const double d = (s - alpha) * (s + alpha);
        const double root = isfinite(d) ? sqrt(d) : sqrt(s - alpha) * sqrt(s + alpha);
        *e_out = alpha >= s ? 0.0 : exp(-DCI_PI * alpha / root);
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
    /* the ratio first, then the modulus: as the library's check_material */
    if (!(nu > -1.0 && nu <= 0.5)) return DC_ERR_POISSON_RANGE;
    if (!(E > 0.0)) return DC_ERR_NOT_POSITIVE;
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

/* ------------------------------------------------------------------ full contact
 * dc_contact_model_init_inline and dc_contact_force_inline: the library's dc_contact_model_init
 * and dc_contact_force (src/contact/{spec,kinematics,frame,tangential*,rolling*,twisting*,
 * evaluate}.rs, src/ffi/contact.rs), the same operations in the same order, bit for bit (the
 * spin/tilt frame carry of the history springs, the Coulomb truncation, the rolling and
 * twisting springs), the same statuses in the same order, outputs written only on DC_OK. */

#define DCI_CONTACT_MAGIC UINT32_C(0x44434d31) /* dc_contact_model.magic (src/ffi/contact.rs) */

typedef struct dci_v3 {
    double x, y, z;
} dci_v3;

DCI_ALWAYS_INLINE_FN dci_v3 dci_v(double x, double y, double z) {
    dci_v3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}
DCI_ALWAYS_INLINE_FN dci_v3 dci_load3(const double a[3]) { return dci_v(a[0], a[1], a[2]); }
DCI_ALWAYS_INLINE_FN void dci_store3(double a[3], dci_v3 v) {
    a[0] = v.x;
    a[1] = v.y;
    a[2] = v.z;
}
DCI_ALWAYS_INLINE_FN dci_v3 dci_add(dci_v3 a, dci_v3 b) {
    return dci_v(a.x + b.x, a.y + b.y, a.z + b.z);
}
DCI_ALWAYS_INLINE_FN dci_v3 dci_sub(dci_v3 a, dci_v3 b) {
    return dci_v(a.x - b.x, a.y - b.y, a.z - b.z);
}
DCI_ALWAYS_INLINE_FN dci_v3 dci_scale(double s, dci_v3 a) {
    return dci_v(DCI_M(s, a.x), DCI_M(s, a.y), DCI_M(s, a.z));
}
DCI_ALWAYS_INLINE_FN double dci_dot(dci_v3 a, dci_v3 b) {
    DCI_NO_CONTRACT
    return DCI_M(a.x, b.x) + DCI_M(a.y, b.y) + DCI_M(a.z, b.z);
}
DCI_ALWAYS_INLINE_FN dci_v3 dci_cross(dci_v3 a, dci_v3 b) {
    DCI_NO_CONTRACT
    return dci_v(DCI_M(a.y, b.z) - DCI_M(a.z, b.y), DCI_M(a.z, b.x) - DCI_M(a.x, b.z),
                 DCI_M(a.x, b.y) - DCI_M(a.y, b.x));
}
DCI_ALWAYS_INLINE_FN double dci_norm2(dci_v3 a) { return dci_dot(a, a); }
/* a - (a.n) n */
DCI_ALWAYS_INLINE_FN dci_v3 dci_tangential(dci_v3 a, dci_v3 n) {
    return dci_sub(a, dci_scale(dci_dot(a, n), n));
}
/* Finiteness masks: x - x is +0 for a finite x and NaN for an infinity or a NaN, so a sum of such
 * terms is 0 exactly when all its x are finite (a NaN term makes the sum NaN; finite terms are
 * zeros, which cannot overflow). One comparison for many values instead of a test and a branch
 * per value; the sums are written as trees (the adds may not be reassociated by the compiler). */
DCI_ALWAYS_INLINE_FN double dci_nf(double x) { return x - x; }
DCI_ALWAYS_INLINE_FN double dci_nf3(const double a[3]) {
    return (dci_nf(a[0]) + dci_nf(a[1])) + dci_nf(a[2]);
}
/* Finiteness sums, the fast path of the masks: a sum is finite only when every term is (an
 * infinite term makes every later partial sum infinite or NaN, a NaN term NaN), so a finite sum
 * proves its terms finite at one add per term, where the masks take two (x - x, then the add).
 * The converse can fail: finite terms may overflow the sum. So a check takes the sum first and
 * only when it is not finite the masks, which decide: same answer, same status, half the
 * arithmetic on the hot path (6 % fewer instructions in the LIGGGHTS plugin's contact body,
 * docs/simulators.md). dci_fin(s): s finite. */
DCI_ALWAYS_INLINE_FN int dci_fin(double s) { return s - s == 0.0; }
DCI_ALWAYS_INLINE_FN double dci_sum3(const double a[3]) { return (a[0] + a[1]) + a[2]; }
/* The history: copy n doubles from src to dst (dst may be NULL: no copy) and return their mask
 * (mask = 1) or their sum (mask = 0). n is a layout length (0, 4, 6, 7, 9, 10 for a valid
 * model; 1, 5, 7, 8, 10, 11 when step-aware): the switch gives each a constant trip count, which the compiler unrolls, because loops
 * over the run-time n (copy in, mask, mask out, copy out) were a hot spot of the LAMMPS scene's
 * profile (docs/simulators.md, "Wall time"). Any other n takes the loop. */
/* GCC (12+) cannot tie the history copy's run-time length (one more with the step-aware
 * damping) to the slots read after it and warns "may be used uninitialized" on the copy and the
 * step slot; every slot read is one the copy wrote (lay.len covers lay.step). */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
DCI_ALWAYS_INLINE_FN double dci_copy_sum_k(double *dst, const double *src, int n, int mask) {
    double s = 0.0;
    for (int i = 0; i < n; i++) {
        if (dst) dst[i] = src[i];
        s += mask ? dci_nf(src[i]) : src[i];
    }
    return s;
}
DCI_ALWAYS_INLINE_FN double dci_copy_sum(double *dst, const double *src, int n, int mask) {
    switch (n) {
    case 0: return 0.0;
    case 1: return dci_copy_sum_k(dst, src, 1, mask);
    case 4: return dci_copy_sum_k(dst, src, 4, mask);
    case 5: return dci_copy_sum_k(dst, src, 5, mask);
    case 6: return dci_copy_sum_k(dst, src, 6, mask);
    case 7: return dci_copy_sum_k(dst, src, 7, mask);
    case 8: return dci_copy_sum_k(dst, src, 8, mask);
    case 9: return dci_copy_sum_k(dst, src, 9, mask);
    case 10: return dci_copy_sum_k(dst, src, 10, mask);
    case 11: return dci_copy_sum_k(dst, src, 11, mask);
    default: return dci_copy_sum_k(dst, src, n, mask);
    }
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
/* n history doubles all finite, copied to dst unless NULL: the sum, the mask when it is not finite */
DCI_ALWAYS_INLINE_FN int dci_copy_finite(double *dst, const double *src, int n) {
    if (DCI_LIKELY(dci_fin(dci_copy_sum(dst, src, n, 0)))) return 1;
    return dci_copy_sum(NULL, src, n, 1) == 0.0;
}
/* every value of a contact result, and the n history doubles h, finite (the sum, then the masks) */
DCI_ALWAYS_INLINE_FN int dci_result_finite(const dc_contact_result *r, const double *h, int n) {
    const double a = r->f_n + dci_sum3(r->force);
    const double b = dci_sum3(r->ft) + (dci_sum3(r->torque1) + dci_sum3(r->torque2));
    if (DCI_LIKELY(dci_fin((a + b) + dci_copy_sum(NULL, h, n, 0)))) return 1;
    const double ma = dci_nf(r->f_n) + dci_nf3(r->force);
    const double mb = dci_nf3(r->ft) + (dci_nf3(r->torque1) + dci_nf3(r->torque2));
    return ma + mb == 0.0 && dci_copy_sum(NULL, h, n, 1) == 0.0;
}
/* f n with +0 components when f = 0 (as every library path) */
DCI_ALWAYS_INLINE_FN dci_v3 dci_normal_vector(double f, dci_v3 n) {
    return f == 0.0 ? dci_v(0.0, 0.0, 0.0) : dci_scale(f, n);
}
/* a b/(a + b), an infinite b (wall, fixed body) giving a */
DCI_ALWAYS_INLINE_FN double dci_harmonic(double a, double b) {
    return b == (double)INFINITY ? a : a * (b / (a + b));
}

/* src/numerics/trig.rs `sin_cos`: sin x and cos x in + - * and floor only (no libm: CUDA's sin
 * is not glibc's), |x| < 2^19, else NaN: a Cody-Waite reduction by pi/2 in three parts (the
 * first two of 33 bits: exact products for |k| < 2^20), Taylor series to r^17 and r^16 on
 * |r| <= pi/4 with the reduction's rounding error rl carried, the quadrant k mod 4. Within
 * 1 ulp of glibc; the library's bits. */
DCI_ALWAYS_INLINE_FN void dci_sin_cos(double x, double *sin_out, double *cos_out) {
    DCI_NO_CONTRACT
    if (!(fabs(x) < 524288.0)) {
        *sin_out = *cos_out = (double)NAN;
        return;
    }
    const double k = floor(DCI_M(x, 0x1.45f306dc9c883p-1) + 0.5);
    /* r + rl = x - k pi/2 (t exact; (t - u) - k P2 is u's rounding error exactly) */
    const double t = x - DCI_M(k, 0x1.921fb544p+0);
    const double u = t - DCI_M(k, 0x1.0b4611a6p-34);
    const double v = ((t - u) - DCI_M(k, 0x1.0b4611a6p-34)) - DCI_M(k, 0x1.3198a2e037073p-69);
    const double r = u + v;
    const double rl = (u - r) + v;
    const double z = r * r;
    const double ps =
        -0x1.5555555555555p-3 +
        DCI_M(z, 0x1.1111111111111p-7 +
                     DCI_M(z, -0x1.a01a01a01a01ap-13 +
                                  DCI_M(z, 0x1.71de3a556c734p-19 +
                                               DCI_M(z, -0x1.ae64567f544e4p-26 +
                                                            DCI_M(z, 0x1.6124613a86d09p-33 +
                                                                         DCI_M(z, -0x1.ae7f3e733b81fp-41 +
                                                                                      DCI_M(z, 0x1.952c77030ad4ap-49)))))));
    const double pc =
        0x1.5555555555555p-5 +
        DCI_M(z, -0x1.6c16c16c16c17p-10 +
                     DCI_M(z, 0x1.a01a01a01a01ap-16 +
                                  DCI_M(z, -0x1.27e4fb7789f5cp-22 +
                                               DCI_M(z, 0x1.1eed8eff8d898p-29 +
                                                            DCI_M(z, -0x1.93974a8c07c9dp-37 +
                                                                         DCI_M(z, 0x1.ae7f3e733b81fp-45))))));
    const double s = r + (rl + DCI_M(r * z, ps));
    const double hz = DCI_M(0.5, z), w = 1.0 - hz; /* (1 - w) - hz: w's rounding error, exactly */
    const double c = w + (((1.0 - w) - hz) + (DCI_M(z * z, pc) - DCI_M(r, rl)));
    const double q = k - DCI_M(4.0, floor(DCI_M(0.25, k)));
    if (q == 0.0) {
        *sin_out = s;
        *cos_out = c;
    } else if (q == 1.0) {
        *sin_out = c;
        *cos_out = -s;
    } else if (q == 2.0) {
        *sin_out = -s;
        *cos_out = -c;
    } else {
        *sin_out = -c;
        *cos_out = s;
    }
}

/* The frame motion of one step (src/contact/frame.rs `FrameStep::new`): the rotation by the
 * mean spin q = (w1 + w2)/2 dt (Rodrigues, s = sin|q|/|q|, c = (1 - cos|q|)/|q|^2, Taylor series for
 * |q|^2 < 1e-3, else dci_sin_cos of |q|/2, as the library), then the minimal tilt from the spun old
 * normal to n, then the projection on the plane normal to n. DC_CARRY_PROJECT (project = 1):
 * the projection alone, rescaled to the old length. */
typedef struct dci_frame {
    dci_v3 q, tk, n;
    double s, c, tc;
    int carry, project;
} dci_frame;

/* v + s q x v + c q x (q x v) */
DCI_ALWAYS_INLINE_FN dci_v3 dci_spin(dci_v3 q, double s, double c, dci_v3 v) {
    const dci_v3 qv = dci_cross(q, v);
    const dci_v3 qqv = dci_cross(q, qv);
    return dci_add(v, dci_add(dci_scale(s, qv), dci_scale(c, qqv)));
}
DCI_ALWAYS_INLINE_FN void dci_rodrigues(double q2, double *s, double *c) {
    DCI_NO_CONTRACT
    if (q2 < 1e-3) {
        *s = 1.0 - DCI_M(q2 / 6.0, 1.0 - DCI_M(q2 / 20.0, 1.0 - q2 / 42.0));
        *c = 0.5 * (1.0 - DCI_M(q2 / 12.0, 1.0 - DCI_M(q2 / 30.0, 1.0 - q2 / 56.0)));
    } else {
        /* sin = 2 sin(th/2) cos(th/2), 1 - cos = 2 sin^2(th/2): one reduction, no cancellation */
        const double th = sqrt(q2);
        double sh, ch;
        dci_sin_cos(0.5 * th, &sh, &ch);
        *s = 2.0 * (sh * ch) / th;
        *c = 2.0 * (sh * sh) / q2;
    }
}
DCI_ALWAYS_INLINE_FN dci_frame dci_frame_new(dci_v3 n_old, dci_v3 n, dci_v3 q) {
    dci_frame f;
    dci_rodrigues(dci_norm2(q), &f.s, &f.c);
    const dci_v3 spun = dci_spin(q, f.s, f.c, n_old);
    f.q = q;
    f.tc = dci_dot(spun, n);
    f.tk = dci_cross(spun, n);
    f.carry = f.tc > -0.5 && dci_norm2(n_old) > 0.25;
    f.n = n;
    f.project = 0;
    return f;
}
DCI_ALWAYS_INLINE_FN dci_frame dci_frame_projection(dci_v3 n) {
    dci_frame f;
    f.q = f.tk = dci_v(0.0, 0.0, 0.0);
    f.s = f.c = f.tc = 0.0;
    f.carry = 0;
    f.n = n;
    f.project = 1;
    return f;
}
/* Rodrigues about k = a x b: c v + k x v + (k.v)/(1 + c) k */
DCI_ALWAYS_INLINE_FN dci_v3 dci_tilt(double c, dci_v3 k, dci_v3 v) {
    return dci_add(dci_add(dci_scale(c, v), dci_cross(k, v)),
                   dci_scale(dci_dot(k, v) / (1.0 + c), k));
}
DCI_ALWAYS_INLINE_FN dci_v3 dci_carry(const dci_frame *f, dci_v3 v) {
    DCI_NO_CONTRACT
    if (f->project) {
        /* |v|^2/|w|^2 in one division and one root, rescaled only while more than half the length stays in
         * the plane (src/contact/frame.rs: same rule, same order) */
        const double l2 = dci_norm2(v);
        const dci_v3 w = dci_tangential(v, f->n);
        const double p2 = dci_norm2(w);
        return p2 > 0.25 * l2 ? dci_scale(sqrt(l2 / p2), w) : w;
    }
    const dci_v3 w = f->carry ? dci_tilt(f->tc, f->tk, dci_spin(f->q, f->s, f->c, v)) : v;
    return dci_tangential(w, f->n);
}

/* Kinematics of one contact (src/contact/kinematics.rs `Kin::of`). */
typedef struct dci_kin {
    dci_v3 n, vt, w_roll, w_rel;
    double d, vn, r_eff, m_eff, a1, a2, m1, m2, r1, r2;
    int wall;
} dci_kin;

/* stages = 0 (a model with no tangential, rolling or twisting stage): the relative motion of the
 * contact point (vt, w_roll, w_rel) is left at zero, unread */
DCI_ALWAYS_INLINE_FN dci_kin dci_kin_of(const dc_contact_state *s, dci_v3 n_old, double dt,
                                        int32_t carry, int stages, dci_frame *frame) {
    DCI_NO_CONTRACT
    dci_kin k;
    const dci_v3 n = dci_load3(s->n), v1 = dci_load3(s->v1), v2 = dci_load3(s->v2);
    const dci_v3 w1 = dci_load3(s->w1), w2 = dci_load3(s->w2);
    *frame = carry == DC_CARRY_PROJECT ? dci_frame_projection(n)
                                       : dci_frame_new(n_old, n, dci_scale(0.5 * dt, dci_add(w1, w2)));
    const double d = s->overlap;
    k.wall = s->r2 == (double)INFINITY;
    k.a1 = s->r1 - DCI_M(0.5, d);
    k.a2 = s->r2 - DCI_M(0.5, d);
    const dci_v3 vr = dci_sub(v1, v2);
    k.vn = -dci_dot(vr, n);
    k.n = n;
    k.d = d;
    k.r_eff = dci_harmonic(s->r1, s->r2);
    k.m_eff = dci_harmonic(s->m1, s->m2);
    if (stages) {
        const dci_v3 arm = k.wall ? dci_scale(k.a1, w1) : dci_add(dci_scale(k.a1, w1), dci_scale(k.a2, w2));
        const dci_v3 vc = dci_sub(vr, dci_cross(arm, n));
        k.w_rel = dci_sub(w1, w2);
        k.vt = dci_tangential(vc, n);
        k.w_roll = dci_tangential(k.w_rel, n);
    } else {
        k.vt = k.w_roll = k.w_rel = dci_v(0.0, 0.0, 0.0);
    }
    k.m1 = s->m1;
    k.m2 = s->m2;
    k.r1 = s->r1;
    k.r2 = s->r2;
    return k;
}

/* Tangential stage (src/contact/tangential.rs `step`): spring carried, incremented by v_t dt, dashpot,
 * Coulomb truncation with LAMMPS's spring reset. kt: the law's stiffness of this contact. */
DCI_ALWAYS_INLINE_FN dci_v3 dci_tangential_step(const dc_contact_model *m, const dci_kin *k,
                                                double kt, double f_crit, double dt,
                                                const dci_frame *frame, dci_v3 *xi, int *sliding) {
    DCI_NO_CONTRACT
    const double ct = m->zeta_t > 0.0
                          ? 2.0 * m->zeta_t * sqrt(m->kappa / (1.0 + m->kappa) * k->m_eff * kt)
                          : 0.0;
    const dci_v3 spring = dci_add(dci_carry(frame, *xi), dci_scale(dt, k->vt));
    const dci_v3 trial = dci_sub(dci_scale(-kt, spring), dci_scale(ct, k->vt));
    const double limit = m->mu * f_crit;
    const double t2 = dci_norm2(trial);
    if (t2 > limit * limit) {
        const dci_v3 ft = dci_scale(limit / sqrt(t2), trial);
        *xi = kt > 0.0 ? dci_scale(-1.0 / kt, dci_add(ft, dci_scale(ct, k->vt))) : spring;
        *sliding = 1;
        return ft;
    }
    *xi = spring;
    *sliding = 0;
    return trial;
}

/* Rescaled incremental Mindlin stage (src/contact/tangential_mindlin_rescale.rs `run`): the force
 * history fs carried, scaled by a/a_old when the contact radius shrank, incremented by
 * -k_t v_t dt; dashpot, Coulomb truncation with LAMMPS's reset; a_old <- a. */
DCI_ALWAYS_INLINE_FN dci_v3 dci_tangential_rescale_step(const dc_contact_model *m,
                                                        const dci_kin *k, double f_crit,
                                                        double dt, const dci_frame *frame,
                                                        dci_v3 *fs, double *a_old, int *sliding) {
    DCI_NO_CONTRACT
    const double a = sqrt(k->r_eff * k->d);
    const double kt = m->kt * a;
    const double ct = m->zeta_t > 0.0
                          ? 2.0 * m->zeta_t * sqrt(m->kappa / (1.0 + m->kappa) * k->m_eff * kt)
                          : 0.0;
    dci_v3 carried = dci_carry(frame, *fs);
    if (a < *a_old) carried = dci_scale(a / *a_old, carried);
    const dci_v3 spring = dci_sub(carried, dci_scale(kt * dt, k->vt));
    const dci_v3 trial = dci_sub(spring, dci_scale(ct, k->vt));
    const double limit = m->mu * f_crit;
    const double t2 = dci_norm2(trial);
    *a_old = a;
    if (t2 > limit * limit) {
        const dci_v3 ft = dci_scale(limit / sqrt(t2), trial);
        *fs = dci_add(ft, dci_scale(ct, k->vt));
        *sliding = 1;
        return ft;
    }
    *fs = spring;
    *sliding = 0;
    return trial;
}

/* Constant rolling torque (src/contact/rolling_constant.rs `torque`). */
DCI_ALWAYS_INLINE_FN dci_v3 dci_rolling_constant(const dc_contact_model *m, const dci_kin *k,
                                                 double f_crit, int *on) {
    const double w2 = dci_norm2(k->w_roll);
    if (w2 > 0.0) {
        const double mag = m->mu_r * k->r_eff * f_crit;
        *on = 1;
        return dci_scale(-mag / sqrt(w2), k->w_roll);
    }
    *on = 0;
    return dci_v(0.0, 0.0, 0.0);
}

/* EPSD rolling (src/contact/rolling_epsd.rs `step`); kn: the normal law's elastic tangent stiffness. */
DCI_ALWAYS_INLINE_FN dci_v3 dci_rolling_epsd(const dc_contact_model *m, const dci_kin *k,
                                             double f_crit, double kn, double dt,
                                             const dci_frame *frame, dci_v3 *mk, int *lim) {
    DCI_NO_CONTRACT
    const dci_v3 wr = k->w_roll;
    /* Ai's rule with kn clamped at 0 from below (rolling_epsd.rs `stiffness`) */
    const double kn_pos = kn > 0.0 ? kn : 0.0;
    const double kr = m->k_r > 0.0 ? m->k_r : 2.25 * kn_pos * m->mu_r * m->mu_r * k->r_eff * k->r_eff;
    const dci_v3 spring = dci_add(dci_carry(frame, *mk), dci_scale(-kr * dt, wr));
    const double limit = m->mu_r * k->r_eff * f_crit;
    const double s2 = dci_norm2(spring);
    if (s2 > limit * limit) {
        const dci_v3 at = dci_scale(limit / sqrt(s2), spring);
        *mk = at;
        *lim = 1;
        return at;
    }
    *mk = spring;
    *lim = 0;
    const double i1 = (1.0 + m->kappa) * k->m1 * k->r1 * k->r1;
    const double i2 = (1.0 + m->kappa) * k->m2 * k->r2 * k->r2;
    const double ir = 1.0 / (1.0 / i1 + 1.0 / i2);
    const double cr = 2.0 * m->eta_r * sqrt(ir * kr);
    return dci_add(spring, dci_scale(-cr, wr));
}

/* Twisting spring-dashpot-slider (src/contact/twisting_sds.rs `step`): torque about n on body 1. */
DCI_ALWAYS_INLINE_FN double dci_twisting(const dc_contact_model *m, const dci_kin *k,
                                         double f_crit, double dt, double *mk, int *lim) {
    DCI_NO_CONTRACT
    const double wt = dci_dot(k->w_rel, k->n);
    const double spring = *mk - DCI_M(m->k_tw * wt, dt);
    const double limit = m->mu_tw * f_crit;
    if (fabs(spring) > limit) {
        const double at = copysign(limit, spring);
        *mk = at;
        *lim = 1;
        return at;
    }
    *mk = spring;
    *lim = 0;
    const double i1 = m->kappa * k->m1 * k->r1 * k->r1;
    const double i2 = m->kappa * k->m2 * k->r2 * k->r2;
    const double it = 1.0 / (1.0 / i1 + 1.0 / i2);
    const double c = 2.0 * m->eta_tw * sqrt(it * m->k_tw);
    return spring - DCI_M(c, wt);
}

/* History layout (src/contact/model.rs `Layout::of_model`): normal of the last step at 0, then the
 * tangential spring (3; 4 for DC_TANGENTIAL_MINDLIN_RESCALE: force and last contact radius), the
 * rolling spring (3, EPSD only), the twisting spring (1), the step-aware damping state (1, after
 * dc_contact_model_set_step). -1: absent. nrm: the normal is stored (Layout::has_normal). */
typedef struct dci_layout {
    int len, tangential, rolling, twisting, step, nrm, nstate;
} dci_layout;

DCI_ALWAYS_INLINE_FN dci_layout dci_layout_of(int32_t tangential, int32_t rolling,
                                              int32_t twisting) {
    dci_layout l;
    const int has_t = tangential != DC_TANGENTIAL_NONE;
    const int has_r = rolling == DC_ROLLING_EPSD;
    const int has_tw = twisting != DC_TWISTING_NONE;
    l.len = has_t || has_r || has_tw ? 3 : 0;
    l.tangential = has_t ? l.len : -1;
    l.len += has_t ? (tangential == DC_TANGENTIAL_MINDLIN_RESCALE ? 4 : 3) : 0;
    l.rolling = has_r ? l.len : -1;
    l.len += has_r ? 3 : 0;
    l.twisting = has_tw ? l.len : -1;
    l.len += has_tw ? 1 : 0;
    l.step = -1;
    l.nstate = -1;
    l.nrm = has_t || has_r || has_tw;
    return l;
}

/* The layout of model m: the state of a normal law with state after the springs (its kernel:
 * src/contact/model.rs `Layout::of_model`), then the step-aware slot (reserved[0] not +0:
 * src/ffi/contact.rs `model_of`) if any. */
DCI_ALWAYS_INLINE_FN dci_layout dci_layout_step(dci_layout l, const dc_contact_model *m) {
    if (dci_has_state(m->normal.kernel)) {
        l.nstate = l.len;
        l.len += 1;
    }
    if (dci_bits(m->reserved[0]) != 0) {
        l.step = l.len;
        l.len += 1;
    }
    return l;
}

/* The reserved fields as model_of accepts them: all +0 (not step-aware), or set by
 * dc_contact_model_set_step (scale > 0, all finite, a damped Tsuji law). */
DCI_ALWAYS_INLINE_FN int dci_step_fields_ok(const dc_contact_model *m) {
    int ok = 1;
    if (dci_bits(m->reserved[0]) != 0) {
        ok = m->reserved[0] > 0.0;
        for (int i = 0; i < 6; i++) ok = ok && isfinite(m->reserved[i]);
        ok = ok && (m->normal.model == DC_MODEL_POWERLAW || m->normal.model == DC_MODEL_HERTZ) &&
             m->normal.alpha > 0.0;
    } else {
        for (int i = 0; i < 6; i++) ok = ok && dci_bits(m->reserved[i]) == 0;
    }
    return ok;
}

/* ---- step-aware normal damping (src/contact/step_exact.rs; same operations, same bits) */

/* x^b, 0 <= b <= 1 (pow_b: square roots for b = 1/4 and 1/2) */
DCI_ALWAYS_INLINE_FN double dci_pow_b(double x, double b) {
    if (b == 0.25) return sqrt(sqrt(x));
    if (b == 0.5) return sqrt(x);
    return b > 0.0 ? dc_pow_inline(x, b) : 1.0;
}

/* P(t) by Horner's rule (horner14) */
DCI_ALWAYS_INLINE_FN double dci_horner14(const double *c, double t) {
    DCI_NO_CONTRACT
    double r = 0.0;
    for (int i = 13; i >= 0; i--) r = c[i] + DCI_M(t, r);
    return r;
}

/* acc + zeta(-b, X) by Euler-Maclaurin at X (euler_maclaurin) */
DCI_ALWAYS_INLINE_FN double dci_euler_maclaurin(double b, double acc, double xx) {
    DCI_NO_CONTRACT
    const double xb = dci_pow_b(xx, b);
    acc += -DCI_M(xx, xb) / (1.0 + b) + DCI_M(0.5, xb);
    const double s = -b;
    const double inv = 1.0 / xx;
    const double inv2 = inv * inv;
    double poch = s;
    double pw = xb * inv;
    acc += DCI_M(DCI_M(1.0 / 12.0, poch), pw);
    poch *= DCI_M(s + 1.0, s + 2.0);
    pw *= inv2;
    acc += DCI_M(DCI_M(-1.0 / 720.0, poch), pw);
    poch *= DCI_M(s + 3.0, s + 4.0);
    pw *= inv2;
    acc += DCI_M(DCI_M(1.0 / 30240.0, poch), pw);
    poch *= DCI_M(s + 5.0, s + 6.0);
    pw *= inv2;
    acc += DCI_M(DCI_M(-1.0 / 1209600.0, poch), pw);
    return acc;
}

/* The Hurwitz series' coefficients (tables: see DCI_POW_INVC) */
#define DCI_HURWITZ_Q { \
    -0.7899114703787721, \
    -0.5035045668819903, \
    -0.029871702822718397, \
    0.003350820175184365, \
    -0.0006291463053583874, \
    0.00014330484309451767, \
    -3.603711518903692e-05, \
    9.61171113531629e-06, \
    -2.6718054638719184e-06, \
    7.606060861039445e-07, \
    -2.088381669309575e-07, \
    6.139160979448287e-08, \
    -2.6962573574681468e-08, \
    8.154777349940339e-09 \
    }
#define DCI_HURWITZ_H { \
    -0.6462183156061935, \
    -0.5047780514486088, \
    -0.06087846318918256, \
    0.004611378001305343, \
    -0.0007497468708554522, \
    0.00015652782761019915, \
    -3.69837684257766e-05, \
    9.39590269177627e-06, \
    -2.5082644438857636e-06, \
    6.901610637606485e-07, \
    -1.849878904556762e-07, \
    5.295304614101252e-08, \
    -2.229009773544556e-08, \
    6.602811603891717e-09 \
    }
#if defined(__CUDACC__) || defined(__HIPCC__)
DCI_DEVICE_TABLE double dci_dev_hurwitz_q[14] = DCI_HURWITZ_Q;
DCI_DEVICE_TABLE double dci_dev_hurwitz_h[14] = DCI_HURWITZ_H;
#endif
/* Hurwitz zeta(-b, x), x >= 1, 0 <= b <= 1 (hurwitz_neg) */
DCI_ALWAYS_INLINE_FN double dci_hurwitz_neg(double b, double x) {
    DCI_NO_CONTRACT
    /* zeta(-1/4, x) and zeta(-1/2, x) ~ P(2x - 3) on x in [1, 2] (HURWITZ_Q, HURWITZ_H) */
#if defined(DCI_DEVICE_PASS)
    const double *const dci_hurwitz_q = dci_dev_hurwitz_q, *const dci_hurwitz_h = dci_dev_hurwitz_h;
#else
    static const double dci_hurwitz_q[14] = DCI_HURWITZ_Q, dci_hurwitz_h[14] = DCI_HURWITZ_H;
#endif
    if (x <= 2.0 && b == 0.25) return dci_horner14(dci_hurwitz_q, 2.0 * x - 3.0);
    if (x <= 2.0 && b == 0.5) return dci_horner14(dci_hurwitz_h, 2.0 * x - 3.0);
    if (x >= 5.0) return dci_euler_maclaurin(b, 0.0, x);
    double acc = dci_pow_b(x, b) + dci_pow_b(x + 1.0, b) + dci_pow_b(x + 2.0, b);
    acc += dci_pow_b(x + 3.0, b);
    return dci_euler_maclaurin(b, acc, x + 4.0);
}

/* the damping factor R(h) (r_of_h) */
DCI_ALWAYS_INLINE_FN double dci_step_r(const double *c, double h) {
    DCI_NO_CONTRACT
    h = h < 0.1 ? h : 0.1;
    h = h > 0.0 ? h : 0.0;
    double r = 1.0 + DCI_M(h, c[0] + DCI_M(h, c[1] + DCI_M(h, c[2] + DCI_M(h, c[3] + DCI_M(h, c[4])))));
    if (r < 0.25) r = 0.25;
    if (r > 2.0) r = 2.0;
    return r;
}

/* the unclamped twin of a kernel code (registry::unclamped) */
DCI_ALWAYS_INLINE_FN int32_t dci_unclamped(int32_t kernel) {
    switch (kernel) {
    case DC_KERNEL_LIN_DAMPED_CLAMPED: return DC_KERNEL_LIN_DAMPED;
    case DC_KERNEL_P15_DAMPED_CLAMPED: return DC_KERNEL_P15_DAMPED;
    case DC_KERNEL_P2_DAMPED_CLAMPED: return DC_KERNEL_P2_DAMPED;
    case DC_KERNEL_GEN_DAMPED_CLAMPED: return DC_KERNEL_GEN_DAMPED;
    case DC_KERNEL_HERTZ_DAMPED_CLAMPED: return DC_KERNEL_HERTZ_DAMPED;
    case DC_KERNEL_VISCO_DAMPED_CLAMPED: return DC_KERNEL_VISCO_DAMPED;
    default: return kernel;
    }
}

/* the law's unclamped force at overlap d > 0, rate v, damping scaled by r */
DCI_ALWAYS_INLINE_FN double dci_step_raw(const dc_pair *pair, int32_t kernel, double r, double d,
                                         double v, double r_eff, double m_eff) {
    dc_pair pc = *pair;
    pc.c = pair->c * r;
    return dc_normal_force_kernel_inline(kernel, &pc, d, v, r_eff, m_eff);
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
/* src/contact/step_exact.rs ONSET_A_MAX */
#define DCI_ONSET_A_MAX 2.0
/* The step-aware normal force of one contact in contact (contact_normal + normal_force);
 * slot: its history double (0 fresh, +R, -R after the end correction). */
DCI_ALWAYS_INLINE_FN double dci_step_normal(const dc_contact_model *m, double d, double v,
                                            double r_eff, double m_eff, double dt, double *slot) {
    DCI_NO_CONTRACT
    const dc_pair *pair = &m->normal;
    const int32_t kernel = dci_unclamped(pair->kernel);
    const double beta = 0.5 * (pair->p - 1.0);
    const int first = *slot == 0.0;
    /* an onset: a = d/(v dt) <= DCI_ONSET_A_MAX (a drift from outside gives a <= 1); a pair
     * created deeper takes R = 1 and no onset correction */
    const int onset = first && v > 0.0 && d <= DCI_ONSET_A_MAX * v * dt;
    if (first) {
        if (onset) {
            const double kc = pair->model == DC_MODEL_HERTZ ? pair->k * sqrt(r_eff) : pair->k;
            const double h = m->reserved[0] * v /
                             dc_pow_inline(m_eff * v * v / kc, 1.0 / (pair->p + 1.0));
            *slot = dci_step_r(&m->reserved[1], h);
        } else {
            *slot = 1.0;
        }
    }
    const double r = fabs(*slot);
    const int flagged = *slot < 0.0;
    double f;
    if (onset) {
        const double fel = dci_step_raw(pair, kernel, r, d, 0.0, r_eff, m_eff);
        const double fdv = dci_step_raw(pair, kernel, r, d, v, r_eff, m_eff) - fel;
        const double a = d / (v * dt);
        f = fel - DCI_M(fdv / dci_pow_b(a, beta), dci_hurwitz_neg(beta, 1.0 + a));
    } else {
        f = dci_step_raw(pair, kernel, r, d, v, r_eff, m_eff);
    }
    if (pair->criterion == DC_END_FORCE) return f > 0.0 ? f : 0.0;
    if (flagged) {
        *slot = r;
        return v < 0.0 ? 0.0 : f;
    }
    const double vp = v - dt * f / m_eff;
    if (!first && d + DCI_M(dt, vp) <= 0.0) {
        const double fel = dci_step_raw(pair, kernel, r, d, 0.0, r_eff, m_eff);
        const double fdp = dci_step_raw(pair, kernel, r, d, vp, r_eff, m_eff) - fel;
        const double b = d / (fabs(vp) * dt);
        *slot = -r;
        return fel - DCI_M(fdp / dci_pow_b(b, beta), dci_hurwitz_neg(beta, 1.0 + b));
    }
    return f;
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

/* Elastic-plastic normal force (src/force/elastic_plastic.rs `force`; same operations, same
 * bits): overlap d, effective radius r, *dmax the largest overlap of the contact so far (its
 * history slot, updated); out of contact (d <= 0 or NaN) 0, the state reset to 0.
 * Constants: k = (4/3) E*, c = pi p_y, h = (pi p_y/(2 E*))^2 (yield overlap h r). */
DCI_ALWAYS_INLINE_FN double dci_elastic_plastic_force(const dc_pair *p, double d, double vn,
                                                      double r, double m_eff, double *dmax) {
    DCI_NO_CONTRACT
    (void)vn;
    (void)m_eff;
    const double k = p->k, c = p->c, h = p->h;
    if (!(d > 0.0)) {
        *dmax = 0.0;
        return 0.0;
    }
    const double m = d > *dmax ? d : *dmax;
    *dmax = m;
    const double dy = h * r;
    if (m <= dy) return k * sqrt(r * d) * d;
    const double fy = k * sqrt(r * dy) * dy;
    if (d >= m) return fy + DCI_M(c * r, d - dy);
    /* unloading/reloading: F = k sqrt(R_p) (d - d_p)^(3/2), R_p = k a_p^3/F_max,
     * d_p = d_max - F_max/(k a_p), a_p = sqrt(r d_max) */
    const double fmax = fy + DCI_M(c * r, m - dy);
    const double ap = sqrt(r * m);
    const double rp = k * ap * ap * ap / fmax;
    const double dp = m - fmax / (k * ap);
    const double kp = k * sqrt(rp);
    const double s = d - dp;
    return s > 0.0 ? kp * sqrt(s) * s : 0.0;
}

/* JKR (adhesive, with state; src/force/jkr.rs): same operations in the same order as the Rust
 * law, so the same bits (sqrt is correctly rounded in both; no libm cbrt, whose bits differ
 * from Rust's f64::cbrt by an ulp: the law's own cube root dci_jkr_cbrt_pos). Constants of the
 * pair: k = (4/3) E*, c = alpha sqrt(k) (0 undamped), h = 2 pi w/E* [m]. State (one double of
 * history): 0 no neck, 1 neck formed. The f64 values of the Rust constants UC, UC2, SC, A,
 * A2, B2, B3: */
#define DCI_JKR_UC 0.6299605249474366    /* u_c = 4^(-1/3) */
#define DCI_JKR_UC2 0.3968502629920499   /* UC * UC */
#define DCI_JKR_SC (-0.4724703937105774) /* s_c = -(3/4) u_c */
#define DCI_JKR_A 2.381101577952299      /* 6 u_c^2 */
#define DCI_JKR_A2 4.762203155904598     /* 2 A */
#define DCI_JKR_B2 5.039684199579493     /* 2 B, B = 4 u_c */
#define DCI_JKR_B3 7.559526299369239     /* 3 B */

/* u = sqrt(a/a0) on the stable branch for s = d/d0; s below s_c (or NaN) taken as s_c.
 * src/force/jkr.rs `branch_root` */
DC_INLINE_FN double dci_jkr_branch_root(double s) {
    DCI_NO_CONTRACT
    s = s > DCI_JKR_SC ? s : DCI_JKR_SC;
    const double sig = s - DCI_JKR_SC;
    const double v1 = sqrt(sig / DCI_JKR_A);
    const double v2 = sqrt(DCI_JKR_UC2 + sqrt(sig)) - DCI_JKR_UC;
    double v = v1 < v2 ? v1 : v2;
    for (int i = 0; i < 4; i++) {
        const double num =
            DCI_M(DCI_M(v, v), DCI_JKR_A + DCI_M(v, DCI_JKR_B2 + DCI_M(3.0, v))) + sig;
        const double den = DCI_M(v, DCI_JKR_A2 + DCI_M(v, DCI_JKR_B3 + DCI_M(4.0, v)));
        v = den > 0.0 ? num / den : v;
    }
    return DCI_JKR_UC + v;
}

/* cbrt(x) for a normal x in [2.2e-308, 1e300]: the exponent divided by 3 in the bits, then
 * three Halley steps. src/force/jkr.rs `cbrt_pos` */
DC_INLINE_FN double dci_jkr_cbrt_pos(double x) {
    DCI_NO_CONTRACT
    double y = dci_from_bits(dci_bits(x) / 3u + UINT64_C(0x2A9F7893782DA1CE));
    for (int i = 0; i < 3; i++) {
        const double y3 = y * y * y;
        y *= (y3 + DCI_M(2.0, x)) / (DCI_M(2.0, y3) + x);
    }
    return y;
}

/* (a0, d0) of a contact: a0 = cbrt(h r^2), d0 = a0^2/r; 0 outside the cube root's range.
 * src/force/jkr.rs `scales` */
DC_INLINE_FN double dci_jkr_scales(double h, double r, double *d0) {
    DCI_NO_CONTRACT
    const double x = h * r * r;
    if (!(x >= DCI_DBL_MIN && x <= 1e300)) {
        *d0 = 0.0;
        return 0.0;
    }
    const double a0 = dci_jkr_cbrt_pos(x);
    *d0 = a0 * a0 / r;
    return a0;
}

/* The elastic force at overlap d with the state updated; *a the contact radius (0 without a
 * neck). src/force/jkr.rs `contact` */
DC_INLINE_FN double dci_jkr_contact(double k, double h, double d, double r, double *state,
                                    double *a) {
    DCI_NO_CONTRACT
    *a = 0.0;
    if (!(d >= 0.0 || *state > 0.0)) {
        *state = 0.0;
        return 0.0;
    }
    double d0;
    const double a0 = dci_jkr_scales(h, r, &d0);
    if (!(d >= DCI_JKR_SC * d0 && d0 > 0.0)) {
        *state = 0.0;
        return 0.0;
    }
    *state = 1.0;
    const double u = dci_jkr_branch_root(d / d0);
    const double u3 = u * u * u;
    const double f0 = 0.75 * k * h * r;
    *a = a0 * u * u;
    return f0 * u3 * (DCI_M(4.0 / 3.0, u3) - 2.0);
}

/* JKR normal force (the kernel), with the dashpot c sqrt(m a) vn while the neck is formed
 * (c = 0: the elastic force's bits); *state the neck (0 none, 1 formed; updated).
 * src/force/jkr.rs `Jkr::force` (= `force_damped`; same operations, same bits) */
DCI_ALWAYS_INLINE_FN double dci_jkr_force(const dc_pair *p, double d, double vn, double r,
                                          double m_eff, double *state) {
    DCI_NO_CONTRACT
    double a;
    const double f = dci_jkr_contact(p->k, p->h, d, r, state, &a);
    const double c = p->c;
    return c > 0.0 ? f + DCI_M(c * sqrt(m_eff * a), vn) : f;
}

/* JKR's critical load of the Coulomb limits for the applied force f: |f + 2 F_po|,
 * F_po = (3/2) pi w R* = 0.75 (0.75 k h) r. src/force/jkr.rs `critical_load` */
DCI_ALWAYS_INLINE_FN double dci_jkr_critical_load(const dc_pair *p, double r, double f) {
    DCI_NO_CONTRACT
    const double po = DCI_M(0.75 * (0.75 * p->k * p->h), r);
    return fabs(f + DCI_M(2.0, po));
}

/* BEGIN GENERATED state */
/* Generated by `cargo run -p xtask -- all` from the registry of normal laws
 * (src/force/registry.rs): do not edit by hand. */
/* The force of a normal law with state (src/force/registry.rs `state_force`): its
 * dci_<keyword>_force, reading and updating *state; NaN for another kernel. */
DCI_ALWAYS_INLINE_FN double dci_state_force(const dc_pair *p, int32_t kernel, double d,
                                            double vn, double r, double m_eff,
                                            double *state) {
    switch (kernel) {
    case DC_KERNEL_ELASTIC_PLASTIC: return dci_elastic_plastic_force(p, d, vn, r, m_eff, state);
    case DC_KERNEL_JKR: return dci_jkr_force(p, d, vn, r, m_eff, state);
    default: return (double)NAN;
    }
}
/* END GENERATED state */

/* The load of the Coulomb limits (tangential mu F_c, rolling mu_r R* F_c, twisting mu_tw F_c)
 * of a touching contact with applied normal force f: |f|, or |f + 2 F_po| for an adhesive law
 * (docs/force.md, "Friction with adhesion"). src/force/registry.rs `critical_load` */
DCI_ALWAYS_INLINE_FN double dci_critical_load(const dc_pair *p, int32_t kernel, double r,
                                              double f) {
    switch (kernel) {
    case DC_KERNEL_DMT_ELASTIC:
    case DC_KERNEL_DMT_DAMPED: return dci_dmt_critical_load(p->h, r, f);
    case DC_KERNEL_JKR: return dci_jkr_critical_load(p, r, f);
    default: return fabs(f);
    }
}

/* A model's selectors: its normal kernel, sub-model codes and frame carry (the fields
 * normal.kernel, tangential, rolling, twisting, carry). The evaluation reads them from here, not
 * from the model, so that a host passing constants gets code for that shape alone. */
typedef struct dci_shape {
    int32_t kernel, tangential, rolling, twisting, carry;
} dci_shape;

DCI_ALWAYS_INLINE_FN dci_shape dci_shape_from(int32_t kernel, int32_t tangential, int32_t rolling,
                                              int32_t twisting, int32_t carry) {
    dci_shape sh;
    sh.kernel = kernel;
    sh.tangential = tangential;
    sh.rolling = rolling;
    sh.twisting = twisting;
    sh.carry = carry;
    return sh;
}
DCI_ALWAYS_INLINE_FN dci_shape dci_shape_of(const dc_contact_model *m) {
    return dci_shape_from(m->normal.kernel, m->tangential, m->rolling, m->twisting, m->carry);
}

/* One contact through every stage (src/contact/evaluate.rs `evaluate`); h: the history, its
 * first lay.len entries read and written, no others (the library's history is lay.len long; a
 * model without history (lay.len = 0) starts from a zero normal, as from a zeroed buffer).
 * sh: the model's own selectors (dci_shape_of, or the same values as constants). */
DCI_ALWAYS_INLINE_FN void dci_contact_evaluate(const dc_contact_model *m, dci_shape sh,
                                               dci_layout lay, const dc_contact_state *s,
                                               double dt, double *h, dc_contact_result *out) {
    DCI_NO_CONTRACT
    dci_frame frame;
    const dci_v3 n_old = lay.len >= 3 && lay.nrm ? dci_v(h[0], h[1], h[2]) : dci_v(0.0, 0.0, 0.0);
    /* the frame step only where a stage carries a vector spring (tangential, EPSD rolling), as
     * the library (src/contact/evaluate.rs); the contact point's relative motion only where a
     * stage reads it (the stages branch below; the library computes it always, unread there) */
    const int carried = lay.tangential >= 0 || lay.rolling >= 0;
    const int stages = lay.nrm || sh.rolling != DC_ROLLING_NONE;
    const dci_kin k = dci_kin_of(s, n_old, dt, carried ? sh.carry : DC_CARRY_PROJECT, stages, &frame);
    const dc_pair *pair = &m->normal;
    /* fe: the force at vn = 0, for Ai's rolling stiffness rule below (same pass, same bits) */
    double fe;
    double f;
    if (lay.nstate >= 0) {
        /* a law with state: no dashpot, its force is elastic (fe = f) */
        f = fe = dci_state_force(pair, sh.kernel, k.d, k.vn, k.r_eff, k.m_eff, &h[lay.nstate]);
    } else {
        f = dci_normal_force_fe(pair, sh.kernel, k.d, k.vn, k.r_eff, k.m_eff, &fe);
        if (lay.step >= 0 && s->overlap > 0.0)
            f = dci_step_normal(m, k.d, k.vn, k.r_eff, k.m_eff, dt, &h[lay.step]);
    }
    dci_v3 ft = dci_v(0.0, 0.0, 0.0), t1 = dci_v(0.0, 0.0, 0.0), t2 = dci_v(0.0, 0.0, 0.0);
    dci_v3 force;
    int sliding = 0, rolling_sliding = 0;
    out->f_n = f;
    if (!(s->overlap > 0.0)) {
        /* not touching: history reset (but for the state a law with state left in its slot),
         * only an adhesive normal law acts */
        const double keep = lay.nstate >= 0 ? h[lay.nstate] : 0.0;
        for (int i = 0; i < lay.len; i++) h[i] = 0.0;
        if (lay.nstate >= 0) h[lay.nstate] = keep;
        force = dci_normal_vector(f, k.n);
    } else if (!stages) {
        force = dci_normal_vector(f, k.n);
    } else {
        if (lay.nrm) {
            h[0] = k.n.x;
            h[1] = k.n.y;
            h[2] = k.n.z;
        }
        force = dci_normal_vector(f, k.n);
        /* the load of the Coulomb limits: |f|, or |f + 2 F_po| for an adhesive law */
        const double fc = dci_critical_load(pair, sh.kernel, k.r_eff, f);
        if (lay.tangential >= 0) {
            dci_v3 xi = dci_v(h[lay.tangential], h[lay.tangential + 1], h[lay.tangential + 2]);
            const double kt = sh.tangential == DC_TANGENTIAL_MINDLIN ? m->kt * sqrt(k.r_eff * k.d)
                                                                    : m->kt;
            if (sh.tangential == DC_TANGENTIAL_LINEAR || sh.tangential == DC_TANGENTIAL_MINDLIN)
                ft = dci_tangential_step(m, &k, kt, fc, dt, &frame, &xi, &sliding);
            else if (sh.tangential == DC_TANGENTIAL_MINDLIN_RESCALE)
                ft = dci_tangential_rescale_step(m, &k, fc, dt, &frame, &xi,
                                                 &h[lay.tangential + 3], &sliding);
            h[lay.tangential] = xi.x;
            h[lay.tangential + 1] = xi.y;
            h[lay.tangential + 2] = xi.z;
            force = dci_add(force, ft);
            const dci_v3 nft = dci_cross(k.n, ft);
            t1 = dci_scale(-k.a1, nft);
            if (!k.wall) t2 = dci_scale(-k.a2, nft);
        }
        if (sh.rolling == DC_ROLLING_CONSTANT) {
            const dci_v3 mr = dci_rolling_constant(m, &k, fc, &rolling_sliding);
            t1 = dci_add(t1, mr);
            if (!k.wall) t2 = dci_sub(t2, mr);
        } else if (sh.rolling == DC_ROLLING_EPSD && lay.rolling >= 0) {
            double kn = 0.0;
            if (!(m->k_r > 0.0)) {
                /* the normal law's elastic tangent stiffness p F_el/d (vn = 0: no damping) */
                kn = pair->p * fe / k.d;
            }
            dci_v3 mk = dci_v(h[lay.rolling], h[lay.rolling + 1], h[lay.rolling + 2]);
            const dci_v3 mr = dci_rolling_epsd(m, &k, fc, kn, dt, &frame, &mk, &rolling_sliding);
            h[lay.rolling] = mk.x;
            h[lay.rolling + 1] = mk.y;
            h[lay.rolling + 2] = mk.z;
            t1 = dci_add(t1, mr);
            if (!k.wall) t2 = dci_sub(t2, mr);
        }
        if (lay.twisting >= 0) {
            int lim;
            const double t = dci_twisting(m, &k, fc, dt, &h[lay.twisting], &lim);
            const dci_v3 mr = dci_scale(t, k.n);
            t1 = dci_add(t1, mr);
            if (!k.wall) t2 = dci_sub(t2, mr);
            rolling_sliding |= lim;
        }
    }
    dci_store3(out->force, force);
    dci_store3(out->torque1, t1);
    dci_store3(out->torque2, t2);
    dci_store3(out->ft, ft);
    out->sliding = sliding;
    out->rolling_sliding = rolling_sliding;
}

/* The structural and value checks of dc_contact_force on a model (DC_OK or
 * DC_ERR_CONTACT_MODEL_INVALID). */
DC_INLINE_FN int32_t dci_check_contact_model(const dc_contact_model *m, dci_layout lay) {
    const dc_pair *p = &m->normal;
    int ok = ((p->criterion == DC_END_OVERLAP && p->clamp == 0) ||
              (p->criterion == DC_END_FORCE && p->clamp == 1)) &&
             m->magic == DCI_CONTACT_MAGIC && m->history_len == (uint32_t)lay.len &&
             (m->carry == DC_CARRY_ROTATE || m->carry == DC_CARRY_PROJECT);
    ok = ok && dci_step_fields_ok(m);
    if (!ok) return DC_ERR_CONTACT_MODEL_INVALID;
    ok = dci_kernel_known(p->kernel);
    ok = ok && (m->tangential == DC_TANGENTIAL_NONE || m->tangential == DC_TANGENTIAL_LINEAR ||
                m->tangential == DC_TANGENTIAL_MINDLIN ||
                m->tangential == DC_TANGENTIAL_MINDLIN_RESCALE);
    ok = ok && (m->rolling == DC_ROLLING_NONE || m->rolling == DC_ROLLING_CONSTANT ||
                m->rolling == DC_ROLLING_EPSD);
    ok = ok && (m->twisting == DC_TWISTING_NONE || m->twisting == DC_TWISTING_SDS);
    const double c[13] = {p->k,     p->c,  p->h,   m->mu,    m->kt,   m->zeta_t, m->kappa,
                          m->mu_r,  m->k_r, m->eta_r, m->mu_tw, m->k_tw, m->eta_tw};
    for (int i = 0; i < 13; i++) ok = ok && isfinite(c[i]) && c[i] >= 0.0;
    ok = ok && m->kappa > 0.0;
    ok = ok && (m->tangential == DC_TANGENTIAL_NONE || m->kt > 0.0);
    return ok ? DC_OK : DC_ERR_CONTACT_MODEL_INVALID;
}

DCI_ALWAYS_INLINE_FN int32_t dci_check_contact_state(const dc_contact_state *s) {
    /* body 2's radius and mass: finite or +inf (a wall, a fixed body), i.e. > -inf (false for
     * NaN and -inf only); every other value finite (one sum, see dci_fin; the masks when the
     * sum is not finite) */
    const int body2 = s->r2 > -(double)INFINITY && s->m2 > -(double)INFINITY;
    const double sa = (dci_sum3(s->n) + s->overlap) + (s->r1 + s->m1);
    const double sb = (dci_sum3(s->v1) + dci_sum3(s->v2)) + (dci_sum3(s->w1) + dci_sum3(s->w2));
    if (DCI_UNLIKELY(!(dci_fin(sa + sb) && body2))) { /* the sum not finite: the masks decide */
        const double a = (dci_nf3(s->n) + dci_nf(s->overlap)) + (dci_nf(s->r1) + dci_nf(s->m1));
        const double b = (dci_nf3(s->v1) + dci_nf3(s->v2)) + (dci_nf3(s->w1) + dci_nf3(s->w2));
        if (!(a + b == 0.0 && body2)) return DC_ERR_NOT_FINITE;
    }
    if (DCI_UNLIKELY(!(s->r1 > 0.0 && s->r2 > 0.0 && s->m1 > 0.0 && s->m2 > 0.0)))
        return DC_ERR_NOT_POSITIVE;
    const double u = dci_norm2(dci_load3(s->n)) - 1.0;
    if (DCI_UNLIKELY(!(fabs(u) <= 1e-6))) return DC_ERR_NOT_UNIT;
    return DC_OK;
}

/* Force and torques of one sphere-sphere or sphere-wall contact, advancing its history by one
 * step dt: the library's dc_contact_force (same arguments, meaning, statuses; same bits).
 * `model` from dc_contact_model_init or dc_contact_model_init_inline; `history`:
 * history_len >= model->history_len doubles, all zero for a new contact, updated in place on
 * success (NULL allowed when the model needs none). On error `out` and `history` are untouched. */
DC_INLINE_FN int32_t dc_contact_force_inline(const dc_contact_model *model,
                                             const dc_contact_state *state, double dt,
                                             double *history, size_t history_len,
                                             dc_contact_result *out) {
    if (!state || !model || !out) return DC_ERR_NULL_POINTER;
    const dci_layout lay =
        dci_layout_step(dci_layout_of(model->tangential, model->rolling, model->twisting), model);
    const dc_pair *p = &model->normal;
    int ok = ((p->criterion == DC_END_OVERLAP && p->clamp == 0) ||
              (p->criterion == DC_END_FORCE && p->clamp == 1)) &&
             model->magic == DCI_CONTACT_MAGIC && model->history_len == (uint32_t)lay.len &&
             (model->carry == DC_CARRY_ROTATE || model->carry == DC_CARRY_PROJECT);
    ok = ok && dci_step_fields_ok(model);
    if (!ok) return DC_ERR_CONTACT_MODEL_INVALID;
    /* the model's values before the history buffer, as the library (model_of) checks them */
    int32_t st = dci_check_contact_model(model, lay);
    if (st != DC_OK) return st;
    const size_t need = (size_t)lay.len;
    if (need > 0 && !history) return DC_ERR_NULL_POINTER;
    if (history_len < need) return DC_ERR_BUFFER_TOO_SHORT;
    if (need > 0 && ((uintptr_t)history % sizeof(double)) != 0) return DC_ERR_BUFFER_LAYOUT;
    if (!isfinite(dt)) return DC_ERR_NOT_FINITE;
    if (!(dt > 0.0)) return DC_ERR_NOT_POSITIVE;
    if ((st = dci_check_contact_state(state)) != DC_OK) return st;
    /* the model's lay.len doubles only: the evaluation reads and writes no others (the library's
     * history is that long), so the rest of the caller's buffer is neither copied nor checked */
    const int n = lay.len;
    /* zeroed: only lay.len values are copied in and read; GCC's host pass under nvcc cannot
     * prove it across the slots a runtime layout may hold (-Wmaybe-uninitialized) */
    double h[DC_CONTACT_HISTORY_MAX] = {0.0};
    if (!dci_copy_finite(h, history, n)) return DC_ERR_NOT_FINITE;
    dc_contact_result r;
    dci_contact_evaluate(model, dci_shape_of(model), lay, state, dt, h, &r);
    if (!dci_result_finite(&r, h, n)) return DC_ERR_RESULT_RANGE;
    dci_copy_sum(history, h, n, 0);
    *out = r;
    return DC_OK;
}

/* ---- validated-model fast entry (a host's per-contact loop: check the model once, not per call) */

/* The model checks of dc_contact_force / dc_contact_force_inline alone: DC_OK when they accept
 * `model` (given a long enough history), else the status they return for it
 * (DC_ERR_NULL_POINTER, DC_ERR_CONTACT_MODEL_INVALID). */
DC_INLINE_FN int32_t dc_contact_model_check_inline(const dc_contact_model *model) {
    if (!model) return DC_ERR_NULL_POINTER;
    const dci_layout lay =
        dci_layout_step(dci_layout_of(model->tangential, model->rolling, model->twisting), model);
    const dc_pair *p = &model->normal;
    int ok = ((p->criterion == DC_END_OVERLAP && p->clamp == 0) ||
              (p->criterion == DC_END_FORCE && p->clamp == 1)) &&
             model->magic == DCI_CONTACT_MAGIC && model->history_len == (uint32_t)lay.len &&
             (model->carry == DC_CARRY_ROTATE || model->carry == DC_CARRY_PROJECT);
    ok = ok && dci_step_fields_ok(model);
    if (!ok) return DC_ERR_CONTACT_MODEL_INVALID;
    return dci_check_contact_model(model, lay);
}

/* The checks dc_contact_force_checked_inline makes of its dt and state (it calls this), in its
 * order: DC_ERR_NULL_POINTER (state NULL), DC_ERR_NOT_FINITE / DC_ERR_NOT_POSITIVE (dt),
 * DC_ERR_NOT_FINITE (a state value; r2 and m2 may be +inf), DC_ERR_NOT_POSITIVE (a radius or
 * mass), DC_ERR_NOT_UNIT (|n|^2 off 1 by more than 1e-6), else DC_OK. Always inlined. */
DCI_ALWAYS_INLINE_FN int32_t dc_contact_state_check_inline(const dc_contact_state *state, double dt) {
    if (DCI_UNLIKELY(!state)) return DC_ERR_NULL_POINTER;
    if (DCI_UNLIKELY(!isfinite(dt))) return DC_ERR_NOT_FINITE;
    if (DCI_UNLIKELY(!(dt > 0.0))) return DC_ERR_NOT_POSITIVE;
    return dci_check_contact_state(state);
}

/* dc_contact_force_inline for a model that dc_contact_model_check_inline accepted (and that has
 * not changed since), with `history` holding model->history_len doubles, 8-byte aligned (NULL
 * allowed when history_len is 0). It skips the model checks and the history pointer, length and
 * alignment checks (the caller's contract above); it keeps every check of the call's own
 * inputs (NULL state/out, dt, the state's values, the history's values, the results' range), in
 * the same order. For such a model and history: the same status, result and history bits as
 * dc_contact_force (ctest inline_contact_*); outputs untouched on error. */
DCI_ALWAYS_INLINE_FN int32_t dci_force_checked(const dc_contact_model *model, dci_shape sh,
                                               const dc_contact_state *state, double dt,
                                               double *history, dc_contact_result *out) {
    if (DCI_UNLIKELY(!out)) return DC_ERR_NULL_POINTER;
    const dci_layout lay = dci_layout_step(dci_layout_of(sh.tangential, sh.rolling, sh.twisting), model);
    const int32_t st = dc_contact_state_check_inline(state, dt); /* NULL state included */
    if (DCI_UNLIKELY(st != DC_OK)) return st;
    /* the model's lay.len doubles only (the evaluation reads and writes no others) */
    const int need = lay.len;
    /* zeroed: only lay.len values are copied in and read; GCC's host pass under nvcc cannot
     * prove it across the slots a runtime layout may hold (-Wmaybe-uninitialized) */
    double h[DC_CONTACT_HISTORY_MAX] = {0.0};
    if (DCI_UNLIKELY(!dci_copy_finite(h, history, need))) return DC_ERR_NOT_FINITE;
    dc_contact_result r;
    dci_contact_evaluate(model, sh, lay, state, dt, h, &r);
    if (DCI_UNLIKELY(!dci_result_finite(&r, h, need))) return DC_ERR_RESULT_RANGE;
    dci_copy_sum(history, h, need, 0);
    *out = r;
    return DC_OK;
}

DC_INLINE_FN int32_t dc_contact_force_checked_inline(const dc_contact_model *model,
                                                     const dc_contact_state *state, double dt,
                                                     double *history, dc_contact_result *out) {
    return dci_force_checked(model, dci_shape_of(model), state, dt, history, out);
}

/* ---- shaped fast entry (one instantiation per model shape a host runs) */

/* DC_OK when dc_contact_model_check_inline accepts `model` and its normal.kernel, tangential,
 * rolling, twisting and carry equal the five codes given (the model's shape); else
 * DC_ERR_NULL_POINTER or DC_ERR_CONTACT_MODEL_INVALID. A host checks this once per model before
 * it calls dc_contact_force_shaped_inline with the same codes. */
DC_INLINE_FN int32_t dc_contact_model_shape_inline(const dc_contact_model *model, int32_t kernel,
                                                   int32_t tangential, int32_t rolling,
                                                   int32_t twisting, int32_t carry) {
    const int32_t st = dc_contact_model_check_inline(model);
    if (st != DC_OK) return st;
    const int same = model->normal.kernel == kernel && model->tangential == tangential &&
                     model->rolling == rolling && model->twisting == twisting &&
                     model->carry == carry;
    return same ? DC_OK : DC_ERR_CONTACT_MODEL_INVALID;
}

/* dc_contact_force_checked_inline with the model's shape given by the caller: kernel,
 * tangential, rolling, twisting, carry must be the model's own (dc_contact_model_shape_inline
 * returned DC_OK for them; the caller's contract, not checked here). Written with constants (a
 * C++ template parameter, a switch case per shape), the compiler keeps only the kernel and the
 * stages of that shape: no selector branches, a constant history length, a smaller function.
 * Same statuses, results and history bits as dc_contact_force_checked_inline (ctest
 * inline_contact_*). Always inlined. */
DCI_ALWAYS_INLINE_FN int32_t dc_contact_force_shaped_inline(
    const dc_contact_model *model, int32_t kernel, int32_t tangential, int32_t rolling,
    int32_t twisting, int32_t carry, const dc_contact_state *state, double dt, double *history,
    dc_contact_result *out) {
    return dci_force_checked(model, dci_shape_from(kernel, tangential, rolling, twisting, carry), state,
                             dt, history, out);
}

/* ---- deferred checks (a host loop that ends its run on any error: one test per pass) */

/* The checked entries test every contact's results with a branch on the last values computed;
 * in the LIGGGHTS scene that test and the per-contact state check cost 15-18 % of the loop
 * time, well predicted or not (docs/simulators.md). A host that stops its run on any bad value
 * (a simulation: the error ends the run, so a failed step's outputs are never used) can check
 * the states where they come from (its atom arrays, once per pass), evaluate each contact
 * without a branch, collect the history and result checks in a dc_contact_checks, and test that
 * once per pass, after its pair loop and before it integrates. */

/* What the deferred entry collects: zero it with dc_contact_checks_init_inline, test it with
 * dc_contact_checks_status_inline, combine two (threads, GPU blocks, MPI ranks) with
 * dc_contact_checks_merge_inline. Each field is a sum of s - s over contacts, s the sum of the
 * contact's values: 0 while every s was finite, else NaN (so the total cannot overflow). */
typedef struct dc_contact_checks {
    double history; /* the history as read */
    double result;  /* the results and the history as written */
} dc_contact_checks;

DC_INLINE_FN void dc_contact_checks_init_inline(dc_contact_checks *c) {
    if (!c) return;
    c->history = 0.0;
    c->result = 0.0;
}

/* `into` += `from`: the checks of both sets of contacts (NULL: nothing). */
DC_INLINE_FN void dc_contact_checks_merge_inline(dc_contact_checks *into,
                                                 const dc_contact_checks *from) {
    if (!into || !from) return;
    into->history += from->history;
    into->result += from->result;
}

/* DC_OK when every contact collected passed the history and result checks of
 * dc_contact_force_checked_inline; else the status that entry returns first for one of them:
 * DC_ERR_NOT_FINITE (a history value), DC_ERR_RESULT_RANGE (a result or history value written).
 * One difference, on the cautious side: the checked entry proves finiteness by a sum and, when
 * that sum is not finite, by per-value masks; the checks here have the sums only, so finite
 * values whose sum overflows (magnitudes near 1e308) count as not finite. NULL c:
 * DC_ERR_NULL_POINTER. */
DC_INLINE_FN int32_t dc_contact_checks_status_inline(const dc_contact_checks *c) {
    if (!c) return DC_ERR_NULL_POINTER;
    if (!(c->history == 0.0)) return DC_ERR_NOT_FINITE;
    if (!(c->result == 0.0)) return DC_ERR_RESULT_RANGE;
    return DC_OK;
}

DCI_ALWAYS_INLINE_FN int32_t dci_force_deferred(const dc_contact_model *model, dci_shape sh,
                                                const dc_contact_state *state, double dt,
                                                double *history, dc_contact_result *out,
                                                dc_contact_checks *c) {
    if (DCI_UNLIKELY(!state || !out || !c)) return DC_ERR_NULL_POINTER;
    const dci_layout lay = dci_layout_step(dci_layout_of(sh.tangential, sh.rolling, sh.twisting), model);
    /* straight through: the evaluation is + - * / sqrt and selects on any doubles (no trap,
     * no index from a value), so a bad value gives bad values, caught below or by the caller */
    /* zeroed: only lay.len values are copied in and read; GCC's host pass under nvcc cannot
     * prove it across the slots a runtime layout may hold (-Wmaybe-uninitialized) */
    double h[DC_CONTACT_HISTORY_MAX] = {0.0};
    c->history += dci_nf(dci_copy_sum(h, history, lay.len, 0));
    dc_contact_result r;
    dci_contact_evaluate(model, sh, lay, state, dt, h, &r);
    const double a = r.f_n + dci_sum3(r.force);
    const double b = dci_sum3(r.ft) + (dci_sum3(r.torque1) + dci_sum3(r.torque2));
    c->result += dci_nf((a + b) + dci_copy_sum(history, h, lay.len, 0));
    *out = r;
    return DC_OK;
}

/* One contact as dc_contact_force_checked_inline, its history and result checks collected in
 * `checks` instead of returned. The caller's contract: `model` accepted by
 * dc_contact_model_check_inline; `state` and `dt` accepted by dc_contact_state_check_inline
 * (per contact, or once per pass on the arrays the states are built from); `history`:
 * model->history_len doubles, 8-byte aligned (NULL when that is 0), overlapping neither *state
 * nor *out nor *checks. The history is advanced in place and `out` written whatever the
 * values: when dc_contact_checks_status_inline then reports an error, that pass's outputs and
 * histories are not to be used (the host ends its run). When it reports DC_OK for the contact,
 * the result and history bits are those of dc_contact_force_checked_inline (ctest
 * inline_contact_*; without FMA contraction, see the top of this file). A state outside the
 * contract is no undefined behaviour (the evaluation is arithmetic only); its outputs are
 * meaningless, and usually not finite. Returns
 * DC_ERR_NULL_POINTER when model, state, out or checks is NULL (nothing evaluated), else DC_OK. */
DC_INLINE_FN int32_t dc_contact_force_deferred_inline(const dc_contact_model *model,
                                                      const dc_contact_state *state, double dt,
                                                      double *history, dc_contact_result *out,
                                                      dc_contact_checks *checks) {
    if (!model) return DC_ERR_NULL_POINTER;
    return dci_force_deferred(model, dci_shape_of(model), state, dt, history, out, checks);
}

/* dc_contact_force_deferred_inline with the model's shape given as to
 * dc_contact_force_shaped_inline (the caller's contract: dc_contact_model_shape_inline accepted
 * these codes for this model). Always inlined. */
DCI_ALWAYS_INLINE_FN int32_t dc_contact_force_shaped_deferred_inline(
    const dc_contact_model *model, int32_t kernel, int32_t tangential, int32_t rolling,
    int32_t twisting, int32_t carry, const dc_contact_state *state, double dt, double *history,
    dc_contact_result *out, dc_contact_checks *checks) {
    return dci_force_deferred(model, dci_shape_from(kernel, tangential, rolling, twisting, carry), state,
                              dt, history, out, checks);
}

/* ---- dc_contact_model_init_inline (src/contact/spec.rs `contact_model`) */

/* NaN = unset (DC_ERR_SPEC_UNSET) */
DC_INLINE_FN int32_t dci_set(double x) { return x != x ? DC_ERR_SPEC_UNSET : DC_OK; }
DC_INLINE_FN int32_t dci_non_negative(double x, double *out) {
    if (x != x) return DC_ERR_SPEC_UNSET;
    if (!isfinite(x)) return DC_ERR_NOT_FINITE;
    if (!(x >= 0.0)) return DC_ERR_NEGATIVE;
    *out = x;
    return DC_OK;
}
DC_INLINE_FN int32_t dci_positive(double x, double *out) {
    if (x != x) return DC_ERR_SPEC_UNSET;
    if (!isfinite(x)) return DC_ERR_NOT_FINITE;
    if (!(x > 0.0)) return DC_ERR_NOT_POSITIVE;
    *out = x;
    return DC_OK;
}
/* (1 - nu^2)/E of one material, E = +inf allowed (rigid) */
DC_INLINE_FN int32_t dci_compliance(double e, double nu, double *out) {
    if (e != e || nu != nu) return DC_ERR_SPEC_UNSET;
    if (!isfinite(nu)) return DC_ERR_NOT_FINITE;
    if (!(nu > -1.0 && nu <= 0.5)) return DC_ERR_POISSON_RANGE;
    if (!(e > 0.0)) return DC_ERR_NOT_POSITIVE;
    *out = (1.0 - nu) * (1.0 + nu) / e;
    return DC_OK;
}
DC_INLINE_FN int32_t dci_spec_hertz_factor(const dc_contact_spec *s, double *kf) {
    double c1, c2;
    int32_t st = dci_compliance(s->E1, s->nu1, &c1);
    if (st != DC_OK) return st;
    if ((st = dci_compliance(s->E2, s->nu2, &c2)) != DC_OK) return st;
    const double v = 4.0 / 3.0 * (1.0 / (c1 + c2));
    if (!isfinite(v)) return DC_ERR_NOT_FINITE;
    if (!(v > 0.0)) return DC_ERR_RESULT_RANGE;
    *kf = v;
    return DC_OK;
}
DC_INLINE_FN int32_t dci_hertz_from_factor(double kf, double e, int32_t criterion, dc_pair *out) {
    double alpha;
    const int32_t st = dci_alpha_from_e(e, 1.5, criterion, &alpha);
    if (st != DC_OK) return st;
    const double c = alpha * sqrt(kf);
    if (!isfinite(c)) return DC_ERR_RESULT_RANGE;
    const int32_t kernel = dci_pick(alpha > 0.0, criterion, DC_KERNEL_HERTZ_ELASTIC,
                                    DC_KERNEL_HERTZ_DAMPED, DC_KERNEL_HERTZ_DAMPED_CLAMPED);
    dci_fill(out, DC_MODEL_HERTZ, kernel, criterion, 1.5, kf, alpha, 0.0, e, kf, c, 0.25);
    return DC_OK;
}

/* The normal laws' own checks and pairs from a specification: one function per law,
 * dci_spec_<keyword>(s, kf, e_n, crit, out), kf = (4/3) E* for a law that reads the materials
 * (else NaN), called by the generated dci_spec_normal below. */

/* src/force/hertz.rs `Hertz::build` */
DC_INLINE_FN int32_t dci_spec_hertz(const dc_contact_spec *s, double kf, double e_n, int32_t crit,
                                    dc_pair *out) {
    (void)s;
    return dci_hertz_from_factor(kf, e_n, crit, out);
}

/* src/force/powerlaw.rs `Powerlaw::build` */
DC_INLINE_FN int32_t dci_spec_powerlaw(const dc_contact_spec *s, double kf, double e_n,
                                       int32_t crit, dc_pair *out) {
    int32_t st;
    (void)kf;
    if ((st = dci_set(s->p)) != DC_OK) return st;
    if ((st = dci_set(s->k_n)) != DC_OK) return st;
    return dc_pair_powerlaw_inline(s->p, s->k_n, e_n, crit, out);
}

/* src/force/powerlaw.rs `Linear::build` */
DC_INLINE_FN int32_t dci_spec_linear(const dc_contact_spec *s, double kf, double e_n, int32_t crit,
                                     dc_pair *out) {
    int32_t st;
    (void)kf;
    if ((st = dci_set(s->k_n)) != DC_OK) return st;
    return dc_pair_powerlaw_inline(1.0, s->k_n, e_n, crit, out);
}

/* src/force/viscoelastic.rs `Visco::build` */
DC_INLINE_FN int32_t dci_spec_viscoelastic(const dc_contact_spec *s, double kf, double e_n,
                                           int32_t crit, dc_pair *out) {
    int32_t st;
    (void)e_n;
    if ((st = dci_set(s->visco_A)) != DC_OK) return st;
    const double A = s->visco_A;
    if (!isfinite(A)) return DC_ERR_NOT_FINITE;
    if (!(A >= 0.0)) return DC_ERR_NEGATIVE;
    const double c = 1.5 * A;
    if (!isfinite(c)) return DC_ERR_RESULT_RANGE;
    const int32_t kernel = dci_pick(A > 0.0, crit, DC_KERNEL_HERTZ_ELASTIC, DC_KERNEL_VISCO_DAMPED,
                                    DC_KERNEL_VISCO_DAMPED_CLAMPED);
    dci_fill(out, DC_MODEL_VISCOELASTIC, kernel, crit, 1.5, kf, 0.0, A, (double)NAN, kf, c, 0.25);
    return DC_OK;
}

/* src/force/dmt.rs `Dmt::build` */
DC_INLINE_FN int32_t dci_spec_dmt(const dc_contact_spec *s, double kf, double e_n, int32_t crit,
                                  dc_pair *out) {
    int32_t st;
    if ((st = dci_set(s->work_of_adhesion)) != DC_OK) return st;
    const double w = s->work_of_adhesion;
    if (!isfinite(w)) return DC_ERR_NOT_FINITE;
    if (!(w >= 0.0)) return DC_ERR_NEGATIVE;
    if (crit != DC_END_OVERLAP) return DC_ERR_SPEC_MODEL;
    double alpha;
    if ((st = dci_alpha_from_e(e_n, 1.5, crit, &alpha)) != DC_OK) return st;
    const double c = alpha * sqrt(kf);
    const double h = 2.0 * DCI_PI * w;
    if (!(isfinite(c) && isfinite(h))) return DC_ERR_RESULT_RANGE;
    dci_fill(out, DC_MODEL_DMT, alpha > 0.0 ? DC_KERNEL_DMT_DAMPED : DC_KERNEL_DMT_ELASTIC, crit,
             1.5, kf, alpha, 0.0, e_n, kf, c, h);
    return DC_OK;
}

/* src/force/elastic_plastic.rs `ElasticPlastic::build` */
DC_INLINE_FN int32_t dci_spec_elastic_plastic(const dc_contact_spec *s, double kf, double e_n,
                                              int32_t crit, dc_pair *out) {
    int32_t st;
    (void)e_n;
    if ((st = dci_set(s->yield_pressure)) != DC_OK) return st;
    const double py = s->yield_pressure;
    if (!isfinite(py)) return DC_ERR_NOT_FINITE;
    if (!(py > 0.0)) return DC_ERR_NOT_POSITIVE;
    const double c = DCI_PI * py;
    const double q = c * (2.0 / 3.0) / kf;
    const double h = q * q;
    if (!(isfinite(c) && isfinite(h) && h > 0.0)) return DC_ERR_RESULT_RANGE;
    dci_fill(out, DC_MODEL_ELASTIC_PLASTIC, DC_KERNEL_ELASTIC_PLASTIC, crit, 1.5, kf, 0.0, 0.0,
             (double)NAN, kf, c, h);
    return DC_OK;
}

/* src/force/jkr.rs `Jkr::build` (and `jkr_from_factor`) */
DC_INLINE_FN int32_t dci_spec_jkr(const dc_contact_spec *s, double kf, double e_n, int32_t crit,
                                  dc_pair *out) {
    int32_t st;
    if ((st = dci_set(s->work_of_adhesion)) != DC_OK) return st;
    const double w = s->work_of_adhesion;
    if (!isfinite(w)) return DC_ERR_NOT_FINITE;
    if (!(w > 0.0)) return DC_ERR_NOT_POSITIVE;
    if (crit != DC_END_OVERLAP) return DC_ERR_SPEC_MODEL;
    double alpha;
    if ((st = dci_alpha_from_e(e_n, 1.5, crit, &alpha)) != DC_OK) return st;
    const double c = alpha * sqrt(kf);
    const double h = 2.0 * DCI_PI * w * (4.0 / 3.0) / kf;
    if (!(isfinite(c) && isfinite(h) && h >= DCI_DBL_MIN)) return DC_ERR_RESULT_RANGE;
    dci_fill(out, DC_MODEL_JKR, DC_KERNEL_JKR, crit, 1.5, kf, alpha, 0.0, e_n, kf, c, h);
    return DC_OK;
}

/* BEGIN GENERATED spec */
/* Generated by `cargo run -p xtask -- all` from the registry of normal laws
 * (src/force/registry.rs): do not edit by hand. */
/* The specification's normal law (src/force/registry.rs `from_spec`). */
DC_INLINE_FN int32_t dci_spec_normal(const dc_contact_spec *s, int32_t crit, dc_pair *out) {
    double e_n, kf = (double)NAN;
    int32_t st;
    if (s->damping == DC_DAMPING_NONE) e_n = 1.0;
    else if (s->damping == DC_DAMPING_RESTITUTION) {
        if ((st = dci_set(s->e_n)) != DC_OK) return st;
        e_n = s->e_n;
    } else
        return DC_ERR_SPEC_MODEL;
    switch (s->normal) {
    case DC_NORMAL_HERTZ:
        if ((st = dci_spec_hertz_factor(s, &kf)) != DC_OK) return st;
        return dci_spec_hertz(s, kf, e_n, crit, out);
    case DC_NORMAL_POWERLAW:
        return dci_spec_powerlaw(s, kf, e_n, crit, out);
    case DC_NORMAL_LINEAR:
        return dci_spec_linear(s, kf, e_n, crit, out);
    case DC_NORMAL_VISCOELASTIC:
        if (s->damping != DC_DAMPING_NONE) return DC_ERR_SPEC_MODEL;
        if ((st = dci_spec_hertz_factor(s, &kf)) != DC_OK) return st;
        return dci_spec_viscoelastic(s, kf, e_n, crit, out);
    case DC_NORMAL_DMT:
        if ((st = dci_spec_hertz_factor(s, &kf)) != DC_OK) return st;
        return dci_spec_dmt(s, kf, e_n, crit, out);
    case DC_NORMAL_ELASTIC_PLASTIC:
        if (s->damping != DC_DAMPING_NONE) return DC_ERR_SPEC_MODEL;
        if ((st = dci_spec_hertz_factor(s, &kf)) != DC_OK) return st;
        return dci_spec_elastic_plastic(s, kf, e_n, crit, out);
    case DC_NORMAL_JKR:
        if ((st = dci_spec_hertz_factor(s, &kf)) != DC_OK) return st;
        return dci_spec_jkr(s, kf, e_n, crit, out);
    default: return DC_ERR_SPEC_MODEL;
    }
}
/* END GENERATED spec */

/* zeta_t = L/sqrt(pi^2 + L^2), L = -ln e_t */
DC_INLINE_FN int32_t dci_zeta_from_e_t(double e_t, double *out) {
    DCI_NO_CONTRACT
    if (!isfinite(e_t)) return DC_ERR_NOT_FINITE;
    if (!(e_t > 0.0 && e_t <= 1.0)) return DC_ERR_RESTITUTION_RANGE;
    const double l = 0.0 - log(e_t); /* +0, not -0, at e_t = 1: as the library */
    *out = l / sqrt(DCI_M(DCI_PI, DCI_PI) + DCI_M(l, l));
    return DC_OK;
}

/* 8 G*, 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2 (src/contact/tangential_mindlin.rs `eight_g_star`) */
DC_INLINE_FN int32_t dci_eight_g_star(double e1, double nu1, double e2, double nu2, double *out) {
    const double c1 = 2.0 * (2.0 - nu1) * (1.0 + nu1) / e1;
    const double c2 = 2.0 * (2.0 - nu2) * (1.0 + nu2) / e2;
    const double v = 8.0 * (1.0 / (c1 + c2));
    if (!isfinite(v)) return DC_ERR_NOT_FINITE;
    if (!(v > 0.0)) return DC_ERR_RESULT_RANGE;
    *out = v;
    return DC_OK;
}

DC_INLINE_FN int32_t dci_contact_model(const dc_contact_spec *s, dc_contact_model *m) {
    int32_t st;
    if (s->criterion != DC_END_OVERLAP && s->criterion != DC_END_FORCE) return DC_ERR_CRITERION;
    memset(m, 0, sizeof *m);
    if ((st = dci_spec_normal(s, s->criterion, &m->normal)) != DC_OK) return st;
    if ((st = dci_positive(s->inertia_factor, &m->kappa)) != DC_OK) return st;
    if (!(m->kappa <= 1.0)) return DC_ERR_SPEC_MODEL;
    if (s->tangential == DC_TANGENTIAL_LINEAR || s->tangential == DC_TANGENTIAL_MINDLIN ||
        s->tangential == DC_TANGENTIAL_MINDLIN_RESCALE) {
        if ((st = dci_non_negative(s->mu, &m->mu)) != DC_OK) return st;
        if ((st = dci_set(s->e_t)) != DC_OK) return st;
        if ((st = dci_zeta_from_e_t(s->e_t, &m->zeta_t)) != DC_OK) return st;
        if (s->tangential == DC_TANGENTIAL_LINEAR) {
            if ((st = dci_positive(s->k_t, &m->kt)) != DC_OK) return st;
        } else {
            double c;
            if ((st = dci_compliance(s->E1, s->nu1, &c)) != DC_OK) return st;
            if ((st = dci_compliance(s->E2, s->nu2, &c)) != DC_OK) return st;
            if ((st = dci_eight_g_star(s->E1, s->nu1, s->E2, s->nu2, &m->kt)) != DC_OK) return st;
        }
    } else if (s->tangential != DC_TANGENTIAL_NONE)
        return DC_ERR_SPEC_MODEL;
    if (s->rolling == DC_ROLLING_CONSTANT || s->rolling == DC_ROLLING_EPSD) {
        if ((st = dci_non_negative(s->mu_r, &m->mu_r)) != DC_OK) return st;
        if (s->rolling == DC_ROLLING_EPSD) {
            if ((st = dci_non_negative(s->k_r, &m->k_r)) != DC_OK) return st;
            if ((st = dci_non_negative(s->eta_r, &m->eta_r)) != DC_OK) return st;
        }
    } else if (s->rolling != DC_ROLLING_NONE)
        return DC_ERR_SPEC_MODEL;
    if (s->twisting == DC_TWISTING_SDS) {
        if ((st = dci_non_negative(s->mu_tw, &m->mu_tw)) != DC_OK) return st;
        if ((st = dci_positive(s->k_tw, &m->k_tw)) != DC_OK) return st;
        if ((st = dci_non_negative(s->eta_tw, &m->eta_tw)) != DC_OK) return st;
    } else if (s->twisting != DC_TWISTING_NONE)
        return DC_ERR_SPEC_MODEL;
    m->magic = DCI_CONTACT_MAGIC;
    m->history_len = (uint32_t)dci_layout_of(s->tangential, s->rolling, s->twisting).len +
                     (dci_has_state(m->normal.kernel) ? 1u : 0u);
    m->tangential = s->tangential;
    m->rolling = s->rolling;
    m->twisting = s->twisting;
    return DC_OK;
}

/* A dc_contact_spec with its version, size and defaults: the library's dc_contact_spec_init. */
DC_INLINE_FN int32_t dc_contact_spec_init_inline(dc_contact_spec *spec) {
    if (!spec) return DC_ERR_NULL_POINTER;
    const double u = (double)NAN;
    memset(spec, 0, sizeof *spec);
    spec->version = DC_CONTACT_SPEC_VERSION;
    spec->size = (uint32_t)sizeof *spec;
    spec->normal = 0;
    spec->damping = DC_DAMPING_NONE;
    spec->criterion = DC_END_FORCE;
    spec->tangential = DC_TANGENTIAL_NONE;
    spec->rolling = DC_ROLLING_NONE;
    spec->twisting = DC_TWISTING_NONE;
    spec->E1 = spec->nu1 = spec->E2 = spec->nu2 = spec->p = spec->k_n = spec->e_n = u;
    spec->visco_A = spec->mu = spec->k_t = spec->mu_r = spec->mu_tw = spec->k_tw = u;
    spec->work_of_adhesion = u;
    spec->yield_pressure = u;
    spec->e_t = 1.0;
    spec->k_r = 0.0;
    spec->eta_r = spec->eta_tw = 0.0;
    spec->inertia_factor = 0.4;
    return DC_OK;
}

/* The library's dc_contact_model_set_carry: DC_CARRY_ROTATE or DC_CARRY_PROJECT on a valid
 * model (same statuses; `model` written only on DC_OK). */
DC_INLINE_FN int32_t dc_contact_model_set_carry_inline(dc_contact_model *model, int32_t carry) {
    const int32_t st = dc_contact_model_check_inline(model);
    if (st != DC_OK) return st;
    if (carry != DC_CARRY_ROTATE && carry != DC_CARRY_PROJECT) return DC_ERR_SPEC_MODEL;
    model->carry = carry;
    return DC_OK;
}

/* A validated contact model from a spec: the library's dc_contact_model_init (same statuses,
 * the same model bits). `out` is written only on DC_OK. */
DC_INLINE_FN int32_t dc_contact_model_init_inline(const dc_contact_spec *spec,
                                                  dc_contact_model *out) {
    if (!spec) return DC_ERR_NULL_POINTER;
    /* the size before yield_pressure was appended: a caller compiled then (the field unset) */
    const uint32_t old_size = (uint32_t)offsetof(dc_contact_spec, yield_pressure);
    if (spec->version != DC_CONTACT_SPEC_VERSION ||
        (spec->size != (uint32_t)sizeof(dc_contact_spec) && spec->size != old_size))
        return out ? DC_ERR_SPEC_VERSION : DC_ERR_NULL_POINTER;
    if (!out) return DC_ERR_NULL_POINTER;
    dc_contact_spec full;
    const dc_contact_spec *s = spec;
    if (spec->size != (uint32_t)sizeof(dc_contact_spec)) {
        dc_contact_spec_init_inline(&full);
        memcpy(&full, spec, spec->size);
        s = &full;
    }
    dc_contact_model m;
    const int32_t st = dci_contact_model(s, &m);
    if (st == DC_OK) *out = m;
    return st;
}

#endif /* DEMCONTACT_INLINE_H */
