/* demcontact_inline.h against the library, bit for bit. Compiled as C99 and, through
 * test_inline.cpp, as C++17 (both with -Wall -Wextra -Werror), and once more with FMA
 * contraction forced on (-O3 -march=native -ffp-contract=fast) to show the header keeps its
 * products unfused.
 *
 *  - every constructor (pairs of all 17 kernel codes over random parameters): the dc_pair the
 *    inline constructor fills equals the library's field for field (bits);
 *  - dc_normal_force_inline = dc_normal_force over N random valid inputs per kernel (default
 *    10^7; argument 1 overrides): overlaps 1e-12..0.1 of radii 1e-5..0.1 m, 10% non-touching
 *    (0, -0, negative), |vn| 1e-3..1e3 m/s both signs and 0, masses 1e-12..10 kg; 0 differences;
 *  - dc_alpha_from_e / dc_e_from_alpha / dc_effective_modulus: bits over grids that include the
 *    extremes (e down to 1e-300 and 1, overdamped force calibration, p = 1..1000), and the same
 *    statuses for bad input with outputs untouched;
 *  - dc_pow_inline within its documented bound of libm's pow over the overlap range (2 ulp for
 *    q <= 2, 1 + q beyond; an independent check of the power kernel's transcription).
 * Prints "test_inline[...]: N passed, M failed". */
#include "../check.h"
#include <demcontact_inline.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__CUDACC__)
#define LANG "CUDA host"
#elif defined(__cplusplus)
#define LANG "C++"
#else
#define LANG "C"
#endif

#define TEST_RANDOM_SEED 0x9E3779B97F4A7C15ull
#include "test_random.h"

static uint64_t bits_of(double x) {
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}
static int same(double a, double b) { return bits_of(a) == bits_of(b) || (a != a && b != b); }

/* Builds whose compiler fuses a*b + c regardless of the header (clang -ffp-contract=fast ignores
 * `#pragma clang fp contract`): compiled with -DDCI_TEST_ULPS=n, a difference of at most n ulp of
 * `scale` (the larger force term, or the value itself) is accepted and the worst is reported.
 * Every other build requires identical bits (DCI_TEST_ULPS = 0). */
#ifndef DCI_TEST_ULPS
#define DCI_TEST_ULPS 0
#endif
static double worst_ulps = 0.0;
static double ulp_of(double x) {
    int ex;
    frexp(fabs(x), &ex);
    return ldexp(1.0, (ex < -1021 ? -1021 : ex) - 53);
}
static int close_to(double a, double b, double scale) {
    if (same(a, b)) return 1;
    const double u = fabs(a - b) / ulp_of(scale);
    if (u > worst_ulps) worst_ulps = u;
    return DCI_TEST_ULPS > 0 && u <= DCI_TEST_ULPS;
}
/* Calibrated values: e = exp(-2 g) turns an ulp of g into |ln e| ulp of e, so the tolerance of
 * tolerant builds is n (1 + |ln v|) ulp there. */
static int close_cal(double a, double b) {
    if (same(a, b)) return 1;
    const double u = fabs(a - b) / ulp_of(a) / (1.0 + fabs(log(fabs(a))));
    if (u > worst_ulps) worst_ulps = u;
    return DCI_TEST_ULPS > 0 && u <= DCI_TEST_ULPS;
}
static int same_pair(const dc_pair *a, const dc_pair *b) {
    return a->model == b->model && a->kernel == b->kernel && a->criterion == b->criterion &&
           a->clamp == b->clamp && same(a->p, b->p) && same(a->stiffness, b->stiffness) &&
           close_cal(a->alpha, b->alpha) && same(a->damping_a, b->damping_a) &&
           close_cal(a->e, b->e) && same(a->k, b->k) && close_cal(a->c, b->c) &&
           same(a->h, b->h);
}
static int unclamped(int kernel) {
    return kernel == DC_KERNEL_VISCO_DAMPED_CLAMPED ? DC_KERNEL_VISCO_DAMPED
           : (kernel % 3 == 0 && kernel <= 15) ? kernel - 1
                                                : kernel;
}


/* A random pair of kernel code `kernel`, built by the library (lib) and by the header (inl). */
static void make_pair(int kernel, dc_pair *lib, dc_pair *inl) {
    const int group = (kernel - 1) / 3, sub = (kernel - 1) % 3;
    const int32_t crit = sub == 2 ? DC_END_FORCE : (uni() < 0.5 ? DC_END_OVERLAP : DC_END_FORCE);
    const int32_t crit_d = sub == 1 ? DC_END_OVERLAP : crit;
    const double e = sub == 0 ? 1.0 : 0.02 + 0.97 * uni();
    const double k = logu(2.0, 10.0);
    const double E1 = logu(6.0, 11.0), E2 = logu(6.0, 11.0);
    const double nu1 = -0.5 + uni(), nu2 = -0.5 + uni();
    int32_t s1 = -1, s2 = -2;
    if (kernel == DC_KERNEL_VISCO_DAMPED || kernel == DC_KERNEL_VISCO_DAMPED_CLAMPED) {
        const double A = logu(-7.0, -3.0);
        const int32_t c = kernel == DC_KERNEL_VISCO_DAMPED ? DC_END_OVERLAP : DC_END_FORCE;
        s1 = dc_pair_viscoelastic(E1, nu1, E2, nu2, A, c, lib);
        s2 = dc_pair_viscoelastic_inline(E1, nu1, E2, nu2, A, c, inl);
    } else if (group == 4) {
        if (sub == 0 && uni() < 0.5) { /* elastic Hertz also from a viscoelastic pair, A = 0 */
            s1 = dc_pair_viscoelastic(E1, nu1, E2, nu2, 0.0, crit, lib);
            s2 = dc_pair_viscoelastic_inline(E1, nu1, E2, nu2, 0.0, crit, inl);
        } else {
            s1 = dc_pair_hertz(E1, nu1, E2, nu2, e, crit_d, lib);
            s2 = dc_pair_hertz_inline(E1, nu1, E2, nu2, e, crit_d, inl);
        }
    } else {
        double p = group == 0 ? 1.0 : group == 1 ? 1.5 : group == 2 ? 2.0 : 1.0 + 5.0 * uni();
        if (group == 3 && (p == 1.0 || p == 1.5 || p == 2.0)) p = 2.7;
        if (group == 0 && uni() < 0.3) {
            s1 = dc_pair_linear(k, e, crit_d, lib);
            s2 = dc_pair_linear_inline(k, e, crit_d, inl);
        } else if (uni() < 0.3) { /* from alpha directly */
            double alpha = 0.0;
            if (sub != 0 && dc_alpha_from_e(e, p, crit_d, &alpha) != DC_OK) abort();
            s1 = dc_pair_powerlaw_alpha(p, k, alpha, crit_d, lib);
            s2 = dc_pair_powerlaw_alpha_inline(p, k, alpha, crit_d, inl);
        } else {
            s1 = dc_pair_powerlaw(p, k, e, crit_d, lib);
            s2 = dc_pair_powerlaw_inline(p, k, e, crit_d, inl);
        }
    }
    if (s1 != DC_OK || s2 != DC_OK || lib->kernel != kernel) {
        fprintf(stderr, "make_pair(%d): statuses %d %d, kernel %d\n", kernel, (int)s1, (int)s2,
                (int)lib->kernel);
        abort();
    }
}

static void forces(long n_per_kernel) {
    for (int kernel = 1; kernel <= 17; kernel++) {
        dc_pair lib, inl;
        long diff = 0, pair_diff = 0, npairs = 0;
        double shown = 0;
        for (long i = 0; i < n_per_kernel; i++) {
            if ((i & 0xFFFF) == 0) {
                make_pair(kernel, &lib, &inl);
                npairs++;
                if (!same_pair(&lib, &inl)) {
                    pair_diff++;
                    if (pair_diff <= 3)
                        fprintf(stderr, "kernel %d: pair differs: k %a/%a c %a/%a alpha %a/%a\n",
                                kernel, lib.k, inl.k, lib.c, inl.c, lib.alpha, inl.alpha);
                }
            }
            const double r = logu(-5.0, -1.0);
            const double u = uni();
            const double d = u < 0.03 ? 0.0 : u < 0.05 ? -0.0 : u < 0.1 ? -r * uni() * 1e-3
                                                                 : r * logu(-12.0, -1.0);
            const double w = uni();
            const double vn = w < 0.05 ? 0.0 : (w < 0.525 ? -1.0 : 1.0) * logu(-3.0, 3.0);
            const double m = logu(-12.0, 1.0);
            const double a = dc_normal_force(&lib, d, vn, r, m);
            const double b = dc_normal_force_inline(&lib, d, vn, r, m);
            double scale = 0.0;
            if (!same(a, b)) { /* |elastic| + |damping| of the unclamped law, for the ulps */
                dc_pair raw = lib;
                raw.kernel = unclamped(kernel);
                const double el = dc_normal_force(&raw, d, 0.0, r, m);
                scale = fabs(el) + fabs(dc_normal_force(&raw, d, vn, r, m) - el);
            }
            if (!close_to(a, b, scale)) {
                if (diff < 3 || (diff < 10 && shown == 0))
                    fprintf(stderr, "kernel %d: d=%a vn=%a r=%a m=%a: lib %a inline %a\n", kernel,
                            d, vn, r, m, a, b);
                diff++;
            }
        }
        CHECK(diff == 0 && pair_diff == 0,
              "kernel %d: %ld of %ld forces and %ld of %ld pairs differ", kernel, diff,
              n_per_kernel, pair_diff, npairs);
        printf("kernel %2d: %ld forces, %ld pairs: %ld and %ld differences\n", kernel,
               n_per_kernel, npairs, diff, pair_diff);
    }
    /* Non-contacts, NaN, unknown kernel, NULL: the documented values. */
    dc_pair h;
    if (dc_pair_hertz_inline(1e9, 0.3, 1e9, 0.3, 0.5, DC_END_FORCE, &h) != DC_OK) abort();
    const double odd[] = {0.0, -0.0, -1e-300, -1e-3, -1e300, (double)NAN, -(double)INFINITY};
    for (size_t i = 0; i < sizeof odd / sizeof odd[0]; i++)
        CHECK(dc_normal_force_inline(&h, odd[i], 1.0, 1e-3, 1e-3) == 0.0, "d=%g", odd[i]);
    CHECK(isnan(dc_normal_force_inline(NULL, 1e-6, 1.0, 1e-3, 1e-3)), "NULL pair");
    dc_pair z;
    memset(&z, 0, sizeof z);
    CHECK(isnan(dc_normal_force_inline(&z, 1e-6, 1.0, 1e-3, 1e-3)), "zero pair");
    z.kernel = 20; /* the first code no law has (18, 19: DMT, tested in test_inline_contact.c) */
    CHECK(isnan(dc_normal_force_inline(&z, 1e-6, 1.0, 1e-3, 1e-3)), "kernel 20");
    CHECK(isnan(dc_normal_force(&z, 1e-6, 1.0, 1e-3, 1e-3)), "library, kernel 20");
    /* Extreme inputs that stay finite: the library and the header agree there too. */
    dc_pair g;
    if (dc_pair_powerlaw_inline(2.7, 1e6, 0.5, DC_END_OVERLAP, &g) != DC_OK) abort();
    const double ext[] = {5e-324, 1e-310, 2.2250738585072014e-308, 1e-200, 1e3, 1e100};
    for (size_t i = 0; i < sizeof ext / sizeof ext[0]; i++) {
        const double a = dc_normal_force(&g, ext[i], -1e6, 1.0, 1.0);
        const double b = dc_normal_force_inline(&g, ext[i], -1e6, 1.0, 1.0);
        CHECK(same(a, b), "gen p=2.7 d=%g: lib %a inline %a", ext[i], a, b);
    }
}

static void calibrations(void) {
    long n = 0, diff = 0;
    const double ps[] = {1.0, 1.1, 1.25, 1.5, 1.7, 2.0, 2.5, 3.0, 5.0, 10.0, 1000.0};
    for (size_t ip = 0; ip < sizeof ps / sizeof ps[0]; ip++)
        for (int crit = 0; crit <= 1; crit++) {
            for (double e = 1.0; e > 1e-300; e *= 0.97) {
                double a1 = -1, a2 = -2, e1 = -1, e2 = -2;
                const int32_t s1 = dc_alpha_from_e(e, ps[ip], crit, &a1);
                const int32_t s2 = dc_alpha_from_e_inline(e, ps[ip], crit, &a2);
                const int32_t t1 = dc_e_from_alpha(a1, ps[ip], crit, &e1);
                const int32_t t2 = dc_e_from_alpha_inline(a1, ps[ip], crit, &e2);
                n++;
                if (s1 != s2 || !close_cal(a1, a2) || t1 != t2 || !close_cal(e1, e2)) {
                    if (diff < 5)
                        fprintf(stderr, "p=%g crit=%d e=%a: alpha %a/%a (%d/%d) e %a/%a\n", ps[ip],
                                crit, e, a1, a2, (int)s1, (int)s2, e1, e2);
                    diff++;
                }
            }
            for (int i = 0; i < 2000; i++) { /* e_from_alpha over alpha = 0..50, overdamped */
                const double alpha = i < 1000 ? 0.002 * i : logu(0.0, 8.0);
                double e1 = -1, e2 = -2;
                const int32_t t1 = dc_e_from_alpha(alpha, ps[ip], crit, &e1);
                const int32_t t2 = dc_e_from_alpha_inline(alpha, ps[ip], crit, &e2);
                n++;
                if (t1 != t2 || !close_cal(e1, e2)) {
                    if (diff < 5)
                        fprintf(stderr, "e_from_alpha(%a, %g, %d): %a/%a\n", alpha, ps[ip], crit,
                                e1, e2);
                    diff++;
                }
            }
        }
    for (int i = 0; i < 100000; i++) {
        const double E1 = logu(3.0, 12.0), E2 = logu(3.0, 12.0), nu1 = -0.99 + 1.49 * uni(),
                     nu2 = -0.99 + 1.49 * uni();
        double a = -1, b = -2;
        const int32_t s1 = dc_effective_modulus(E1, nu1, E2, nu2, &a);
        const int32_t s2 = dc_effective_modulus_inline(E1, nu1, E2, nu2, &b);
        n++;
        if (s1 != s2 || !close_cal(a, b)) diff++;
    }
    CHECK(diff == 0, "%ld of %ld calibration values differ", diff, n);
    printf("calibrations: %ld values, %ld differences\n", n, diff);

    /* Bad input: the same status as the library, output untouched. */
    const double bad_e[] = {0.0, -0.1, 1.0000001, (double)NAN, (double)INFINITY, 5e-324};
    const double bad_p[] = {1.5, 0.999, (double)NAN, -(double)INFINITY};
    const int32_t crits[] = {DC_END_OVERLAP, DC_END_FORCE, 7, -1};
    for (size_t i = 0; i < 6; i++)
        for (size_t j = 0; j < 4; j++)
            for (size_t c = 0; c < 4; c++) {
                double a1 = 42.0, a2 = 42.0;
                const int32_t s1 = dc_alpha_from_e(bad_e[i], bad_p[j], crits[c], &a1);
                const int32_t s2 = dc_alpha_from_e_inline(bad_e[i], bad_p[j], crits[c], &a2);
                CHECK(s1 == s2 && same(a1, a2), "alpha_from_e(%g, %g, %d): %d/%d", bad_e[i],
                      bad_p[j], (int)crits[c], (int)s1, (int)s2);
                dc_pair l, m;
                memset(&l, 0x5a, sizeof l);
                memset(&m, 0x5a, sizeof m);
                CHECK(dc_pair_powerlaw(bad_p[j], 1e6, bad_e[i], crits[c], &l) ==
                              dc_pair_powerlaw_inline(bad_p[j], 1e6, bad_e[i], crits[c], &m) &&
                          memcmp(&l, &m, sizeof l) == 0,
                      "pair_powerlaw(%g, %g, %d)", bad_p[j], bad_e[i], (int)crits[c]);
                memset(&l, 0x5a, sizeof l);
                memset(&m, 0x5a, sizeof m);
                CHECK(dc_pair_hertz(1e9, bad_p[j] - 1.0, 1e9, 0.3, bad_e[i], crits[c], &l) ==
                              dc_pair_hertz_inline(1e9, bad_p[j] - 1.0, 1e9, 0.3, bad_e[i],
                                                   crits[c], &m) &&
                          memcmp(&l, &m, sizeof l) == 0,
                      "pair_hertz(nu=%g, e=%g, %d)", bad_p[j] - 1.0, bad_e[i], (int)crits[c]);
                memset(&l, 0x5a, sizeof l);
                memset(&m, 0x5a, sizeof m);
                CHECK(dc_pair_viscoelastic(1e9, 0.3, bad_e[i] * 1e9, 0.3, bad_p[j] - 1.5,
                                           crits[c], &l) ==
                              dc_pair_viscoelastic_inline(1e9, 0.3, bad_e[i] * 1e9, 0.3,
                                                          bad_p[j] - 1.5, crits[c], &m) &&
                          memcmp(&l, &m, sizeof l) == 0,
                      "pair_viscoelastic(E2=%g, A=%g, %d)", bad_e[i] * 1e9, bad_p[j] - 1.5,
                      (int)crits[c]);
                memset(&l, 0x5a, sizeof l);
                memset(&m, 0x5a, sizeof m);
                CHECK(dc_pair_powerlaw_alpha(bad_p[j], 1e6, bad_e[i] - 0.5, crits[c], &l) ==
                              dc_pair_powerlaw_alpha_inline(bad_p[j], 1e6, bad_e[i] - 0.5,
                                                            crits[c], &m) &&
                          memcmp(&l, &m, sizeof l) == 0,
                      "pair_powerlaw_alpha(%g, alpha=%g, %d)", bad_p[j], bad_e[i] - 0.5,
                      (int)crits[c]);
            }
    const double bad_k[] = {0.0, -1.0, (double)NAN, (double)INFINITY, 1e300};
    for (size_t i = 0; i < 5; i++) {
        dc_pair l, m;
        memset(&l, 0x5a, sizeof l);
        memset(&m, 0x5a, sizeof m);
        const int32_t s1 = dc_pair_powerlaw(1.7, bad_k[i], 0.01, DC_END_FORCE, &l);
        const int32_t s2 = dc_pair_powerlaw_inline(1.7, bad_k[i], 0.01, DC_END_FORCE, &m);
        CHECK(s1 == s2 && memcmp(&l, &m, sizeof l) == 0, "k=%g: %d/%d", bad_k[i], (int)s1,
              (int)s2);
    }
    CHECK_STATUS(dc_alpha_from_e_inline(0.5, 1.5, DC_END_FORCE, NULL), DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_e_from_alpha_inline(0.5, 1.5, DC_END_FORCE, NULL), DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_effective_modulus_inline(1e9, 0.3, 1e9, 0.3, NULL), DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_pair_hertz_inline(1e9, 0.3, 1e9, 0.3, 0.5, DC_END_FORCE, NULL),
                 DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_pair_powerlaw_inline(1.5, 1e6, 0.5, DC_END_FORCE, NULL), DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_pair_viscoelastic_inline(1e9, 0.3, 1e9, 0.3, 1e-4, DC_END_FORCE, NULL),
                 DC_ERR_NULL_POINTER);
}

/* |a - b| in ulps of b (normal range). */
static double ulps(double a, double b) {
    if (a == b) return 0.0;
    int ex;
    frexp(b, &ex);
    return fabs(a - b) / ldexp(1.0, ex - 53);
}

static void power(void) {
    double worst = 0.0;
    long n = 0, fails = 0;
    const double qs[] = {0.05, 0.25, 0.35, 0.5, 0.75, 1.0, 2.0, 4.5};
    for (size_t iq = 0; iq < sizeof qs / sizeof qs[0]; iq++)
        for (int i = 0; i < 200000; i++) {
            const double x = logu(-15.0, 0.0);
            const double u = ulps(dc_pow_inline(x, qs[iq]), pow(x, qs[iq]));
            /* the documented bound: 2 ulp for q <= 2 (p <= 5), 1 + q beyond */
            const double bound = qs[iq] <= 2.0 ? 2.0 : 1.0 + qs[iq];
            if (u > bound) fails++;
            worst = u > worst ? u : worst;
            n++;
        }
    CHECK(fails == 0, "dc_pow_inline: %ld beyond the bound, worst %g ulp from pow", fails, worst);
    printf("dc_pow_inline: %ld points, worst %g ulp from libm pow\n", n, worst);
}

int main(int argc, char **argv) {
    const long n = argc > 1 ? atol(argv[1]) : 10000000L;
    printf("test_inline (" LANG "): %ld random inputs per kernel, tolerance %d ulp\n", n,
           DCI_TEST_ULPS);
    forces(n);
    printf("forces: worst difference %g ulp of the larger force term\n", worst_ulps);
    worst_ulps = 0.0;
    calibrations();
    printf("calibrations: worst difference %g ulp of the value / (1 + |ln value|)\n", worst_ulps);
    power();
    return dc_check_summary("test_inline[" LANG "]");
}
