/* dc_contact_force_inline / dc_contact_model_init_inline / dc_contact_spec_init_inline against the
 * library's dc_contact_force / dc_contact_model_init / dc_contact_spec_init, bit for bit. Compiled
 * as C99 and (test_inline_contact.cpp) as C++17 with -Wall -Wextra -Werror, and once more with
 * FMA contraction forced on (-O3 -march=native -ffp-contract=fast).
 *
 *  - specs: random models of every normal law (Hertz, power law incl. p = 1, 3/2, 2, linear,
 *    viscoelastic, DMT, elastic-plastic with its history state), damping, criterion, tangential (none, linear, Mindlin, rescaled Mindlin), rolling (none,
 *    constant, EPSD with given k_r or Ai's rule), twisting (none, SDS), rigid body 2 (E = inf),
 *    and random invalid ones (NaN = unset, inf, negative, out-of-range, bad selector, bad
 *    version): the same status, and on DC_OK the same model bytes;
 *  - trajectories: for each valid model a contact evolved over many steps, the library and the
 *    header each carrying its own history: the normal turns (small steps, and now and then by
 *    more than 120 degrees), the overlap goes through contact and separation, velocities and spins
 *    random-walk over decades (sticking and sliding; the frame's spin rotation on both of its
 *    branches, series and sin), sphere-sphere and sphere-wall. Every step:
 *    same status, same result bytes, same history bits. Argument 1: total steps (default 4e6);
 *    the test also requires that sliding, sticking, rolling-limit and separation steps occurred;
 *  - the fast entry dc_contact_force_checked_inline (model checked once by
 *    dc_contact_model_check_inline) along the same trajectories and bad inputs: same bits;
 *  - the shaped entry dc_contact_force_shaped_inline along the same trajectories: 240 shapes (Hertz damped, clamped, general p clamped, elastic-plastic, JKR)
 *    with their codes as compile-time constants (as the plugins instantiate it), the others as
 *    run-time codes: same statuses and bits; dc_contact_model_shape_inline accepts a model's own
 *    shape only;
 *  - the deferred entries dc_contact_force_deferred_inline and (constant shapes as above)
 *    dc_contact_force_shaped_deferred_inline along the same trajectories, each with its own
 *    history, a dc_contact_checks per step: the status of the checks equals the library's, and
 *    on DC_OK the same bits; dc_contact_state_check_inline gives the library's status for every
 *    bad dt or state, and the deferred entries the library's history/result statuses for the
 *    bad-input cases whose state it accepts (finite values whose sum overflows: the documented
 *    cautious difference only);
 *  - bad input: NULL pointers, short/misaligned history, dt NaN/0/<0, NaN/inf/zero/non-unit
 *    states, NaN in the history, corrupted models: the same status, outputs untouched.
 * Prints "test_inline_contact[...]: N passed, M failed". */
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

#define TEST_RANDOM_SEED 0xD1B54A32D192ED03ull
#include "test_random.h"

static long n_pass = 0, n_fail = 0;
static void fail(const char *what, long i) {
    if (n_fail < 20) fprintf(stderr, "FAIL (%s): %s at %ld\n", LANG, what, i);
    n_fail++;
}

/* A random spec; `bad` corrupts one field. */
static void random_spec(dc_contact_spec *s, int bad) {
    dc_contact_spec_init(s);
    s->normal = 1 + pick(7);
    s->damping = pick(2);
    s->criterion = s->normal == DC_NORMAL_DMT || s->normal == DC_NORMAL_JKR || uni() < 0.3
                       ? DC_END_OVERLAP
                       : DC_END_FORCE;
    s->E1 = logu(6, 11);
    s->nu1 = -0.5 + uni();
    s->E2 = uni() < 0.2 ? (double)INFINITY : logu(6, 11);
    s->nu2 = -0.5 + uni();
    const double ps[4] = {1.0, 1.5, 2.0, 1.0 + 2.0 * uni()};
    s->p = ps[pick(4)];
    s->k_n = logu(3, 9);
    s->e_n = uni() < 0.1 ? 1.0 : logu(-3, 0);
    if (s->normal == DC_NORMAL_VISCOELASTIC) {
        s->damping = DC_DAMPING_NONE;
        s->visco_A = uni() < 0.2 ? 0.0 : logu(-9, -5);
    }
    s->work_of_adhesion = uni() < 0.2 ? 0.0 : logu(-3, 1);
    if (s->normal == DC_NORMAL_ELASTIC_PLASTIC) s->damping = DC_DAMPING_NONE;
    /* p_y from 1e-4 to 1e-1 of E1: yield overlaps from far below to near the trajectories' */
    s->yield_pressure = s->E1 * logu(-4, -1);
    s->tangential = pick(4);
    s->mu = uni() < 0.1 ? 0.0 : 1.2 * uni();
    s->k_t = logu(3, 8);
    s->e_t = uni() < 0.3 ? 1.0 : logu(-2, 0);
    s->rolling = pick(3);
    s->mu_r = uni() < 0.1 ? 0.0 : 0.3 * uni();
    s->k_r = uni() < 0.5 ? 0.0 : logu(-6, 0);
    s->eta_r = uni() < 0.3 ? 0.0 : uni();
    s->twisting = pick(2);
    s->mu_tw = logu(-6, -3);
    s->k_tw = logu(-6, 0);
    s->eta_tw = uni() < 0.3 ? 0.0 : uni();
    s->inertia_factor = uni() < 0.7 ? 0.4 : 0.1 + 0.9 * uni();
    if (!bad) return;
    double *f[] = {&s->E1, &s->nu1, &s->E2, &s->nu2, &s->p, &s->k_n, &s->e_n, &s->visco_A,
                   &s->mu, &s->k_t, &s->e_t, &s->mu_r, &s->k_r, &s->eta_r, &s->mu_tw, &s->k_tw,
                   &s->eta_tw, &s->inertia_factor, &s->work_of_adhesion, &s->yield_pressure};
    const double vals[8] = {(double)NAN, (double)INFINITY, -(double)INFINITY, -1.0, 0.0, 2.0,
                            1e-320, 1e308};
    const int which = pick(26);
    if (which < 20) *f[which] = vals[pick(8)];
    else if (which == 20) s->normal = pick(2) ? 0 : 8;
    else if (which == 21) s->tangential = 4;
    else if (which == 22) s->rolling = -1;
    else if (which == 23) s->twisting = 2;
    else if (which == 24) s->criterion = 2;
    else s->damping = 2;
}

static int same_result(const dc_contact_result *a, const dc_contact_result *b) {
    return memcmp(a, b, sizeof *a) == 0;
}

/* dc_contact_force_shaped_inline with the model's shape as compile-time constants, as a host
 * instantiates it (one call per shape; the compiler keeps only that shape's kernel and stages):
 * Hertz damped, Hertz damped clamped and general p clamped, every tangential, rolling, twisting
 * and carry code. Other kernels: the shape passed as run-time values. Counts constant calls. */
static long n_shaped_const = 0, n_shaped_runtime = 0;
/* steps per constant shape: index kernel (0-4) * 48 + tangential * 12 + rolling * 4 +
 * twisting * 2 + carry (the model's own codes, all in range for a valid model) */
static long shape_hits[240];
static int shape_index(const dc_contact_model *m) {
    const int k = m->normal.kernel == DC_KERNEL_HERTZ_DAMPED           ? 0
                  : m->normal.kernel == DC_KERNEL_HERTZ_DAMPED_CLAMPED ? 1
                  : m->normal.kernel == DC_KERNEL_ELASTIC_PLASTIC      ? 3
                  : m->normal.kernel == DC_KERNEL_JKR                  ? 4
                                                                       : 2;
    return k * 48 + m->tangential * 12 + m->rolling * 4 + m->twisting * 2 + m->carry;
}
#define SH_C(K, T, R, TW)                                                                          \
    n_shaped_const++;                                                                              \
    shape_hits[shape_index(m)]++;                                                                  \
    if (m->carry == DC_CARRY_ROTATE) return SH_CALL(K, T, R, TW, DC_CARRY_ROTATE);                  \
    return SH_CALL(K, T, R, TW, DC_CARRY_PROJECT);
/* ck NULL: the shaped entry; else the shaped deferred entry collecting into ck */
#define SH_CALL(K, T, R, TW, C)                                                                    \
    (ck ? dc_contact_force_shaped_deferred_inline(m, K, T, R, TW, C, s, dt, h, o, ck)               \
        : dc_contact_force_shaped_inline(m, K, T, R, TW, C, s, dt, h, o))
#define SH_TW(K, T, R)                                                                             \
    if (m->twisting == DC_TWISTING_NONE) {                                                         \
        SH_C(K, T, R, DC_TWISTING_NONE)                                                            \
    }                                                                                              \
    SH_C(K, T, R, DC_TWISTING_SDS)
#define SH_R(K, T)                                                                                 \
    switch (m->rolling) {                                                                          \
    case DC_ROLLING_NONE: SH_TW(K, T, DC_ROLLING_NONE)                                             \
    case DC_ROLLING_CONSTANT: SH_TW(K, T, DC_ROLLING_CONSTANT)                                     \
    default: SH_TW(K, T, DC_ROLLING_EPSD)                                                          \
    }
/* One function per (kernel, tangential) pair, each holding its 12 rolling x twisting x carry
 * instantiations (twice: plain and deferred), kept out of line: one function holding all 480 made
 * clang's SLP vectoriser take about 10 minutes (-ftime-report: 624 of 929 s), its cost growing
 * faster than the function's size. The instantiations and what each computes are unchanged. */
#if defined(__GNUC__) || defined(__clang__)
#define SH_NOINLINE __attribute__((noinline))
#else
#define SH_NOINLINE
#endif
#define SH_FN(NAME, K, T)                                                                          \
    static SH_NOINLINE int32_t NAME(const dc_contact_model *m, const dc_contact_state *s, double dt, \
                                    double *h, dc_contact_result *o, dc_contact_checks *ck) {      \
        SH_R(K, T)                                                                                 \
    }
#define SH_FN4(PREFIX, K)                                                                          \
    SH_FN(PREFIX##_none, K, DC_TANGENTIAL_NONE)                                                    \
    SH_FN(PREFIX##_linear, K, DC_TANGENTIAL_LINEAR)                                                \
    SH_FN(PREFIX##_mindlin, K, DC_TANGENTIAL_MINDLIN)                                              \
    SH_FN(PREFIX##_rescale, K, DC_TANGENTIAL_MINDLIN_RESCALE)
SH_FN4(sh_hertz, DC_KERNEL_HERTZ_DAMPED)
SH_FN4(sh_hertz_clamped, DC_KERNEL_HERTZ_DAMPED_CLAMPED)
SH_FN4(sh_gen_clamped, DC_KERNEL_GEN_DAMPED_CLAMPED)
SH_FN4(sh_elastic_plastic, DC_KERNEL_ELASTIC_PLASTIC)
SH_FN4(sh_jkr, DC_KERNEL_JKR)
#define SH_T(PREFIX)                                                                               \
    switch (m->tangential) {                                                                       \
    case DC_TANGENTIAL_NONE: return PREFIX##_none(m, s, dt, h, o, ck);                             \
    case DC_TANGENTIAL_LINEAR: return PREFIX##_linear(m, s, dt, h, o, ck);                         \
    case DC_TANGENTIAL_MINDLIN: return PREFIX##_mindlin(m, s, dt, h, o, ck);                       \
    default: return PREFIX##_rescale(m, s, dt, h, o, ck);                                          \
    }
static int32_t shaped(const dc_contact_model *m, const dc_contact_state *s, double dt, double *h,
                      dc_contact_result *o, dc_contact_checks *ck) {
    switch (m->normal.kernel) {
    case DC_KERNEL_HERTZ_DAMPED: SH_T(sh_hertz)
    case DC_KERNEL_HERTZ_DAMPED_CLAMPED: SH_T(sh_hertz_clamped)
    case DC_KERNEL_GEN_DAMPED_CLAMPED: SH_T(sh_gen_clamped)
    case DC_KERNEL_ELASTIC_PLASTIC: SH_T(sh_elastic_plastic)
    case DC_KERNEL_JKR: SH_T(sh_jkr)
    default:
        n_shaped_runtime++;
        return SH_CALL(m->normal.kernel, m->tangential, m->rolling, m->twisting, m->carry);
    }
}

/* dc_contact_model_shape_inline: DC_OK for the model's own shape only. */
static void shape_check(const dc_contact_model *m) {
    const int32_t k = m->normal.kernel, t = m->tangential, r = m->rolling, tw = m->twisting,
                  c = m->carry;
    if (dc_contact_model_shape_inline(m, k, t, r, tw, c) != DC_OK) fail("shape of its own model", 0);
    const int32_t other[5][5] = {{k == DC_KERNEL_HERTZ_DAMPED ? DC_KERNEL_HERTZ_DAMPED_CLAMPED
                                                              : DC_KERNEL_HERTZ_DAMPED, t, r, tw, c},
                                 {k, (t + 1) % 4, r, tw, c},
                                 {k, t, (r + 1) % 3, tw, c},
                                 {k, t, r, 1 - tw, c},
                                 {k, t, r, tw, 1 - c}};
    for (int i = 0; i < 5; i++)
        if (dc_contact_model_shape_inline(m, other[i][0], other[i][1], other[i][2], other[i][3],
                                          other[i][4]) != DC_ERR_CONTACT_MODEL_INVALID)
            fail("shape of another model", i);
    dc_contact_model bad = *m;
    bad.mu = -1.0;
    if (dc_contact_model_shape_inline(&bad, k, t, r, tw, c) != DC_ERR_CONTACT_MODEL_INVALID ||
        dc_contact_model_shape_inline(NULL, k, t, r, tw, c) != DC_ERR_NULL_POINTER)
        fail("shape of an invalid model / NULL", 0);
}

/* The deferred entries for one step: the generic one with history hd, the shaped one (constant
 * shapes) with hsd, each with fresh checks; their checks' status must be the library's (sl, with
 * result rl and history hl after the step; h0 the history before it) and on DC_OK the bits the
 * same. `overflow_ok`: a status of not finite / result range where the library says DC_OK is
 * allowed when every value is finite but their sum is not (the documented difference). On an
 * error the failed step's outputs are the caller's to drop: both histories restart from hl. */
static long n_deferred = 0, n_deferred_err = 0, n_deferred_bad[2], n_deferred_contracted = 0;
#if defined(DC_TEST_CONTRACTED)
/* a[i] and b[i] within DC_TEST_CONTRACTED_ULPS ulp of the largest |a[i]| (the doubles of a
 * result or of a history); the largest difference seen, in those units, in worst_ulps */
#define DC_TEST_CONTRACTED_ULPS 64.0
static double worst_ulps = 0.0;
static int close_values(const double *a, const double *b, int n) {
    double scale = 0.0;
    for (int i = 0; i < n; i++) scale = fabs(a[i]) > scale ? fabs(a[i]) : scale;
    for (int i = 0; i < n; i++) {
        if (memcmp(a + i, b + i, sizeof *a) == 0) continue;
        const double u = fabs(a[i] - b[i]) / (2.220446049250313e-16 * scale);
        if (!(u <= DC_TEST_CONTRACTED_ULPS)) return 0;
        worst_ulps = u > worst_ulps ? u : worst_ulps;
    }
    return 1;
}
#endif
static int deferred_step(const dc_contact_model *m, const dc_contact_state *s, double dt,
                         const double *h0, int32_t sl, const dc_contact_result *rl,
                         const double *hl, double *hd, double *hsd, int overflow_ok) {
    dc_contact_checks c1, c2;
    dc_contact_checks_init_inline(&c1);
    dc_contact_checks_init_inline(&c2);
    dc_contact_result r1, r2;
    memset(&r1, 0x5A, sizeof r1);
    memset(&r2, 0x5A, sizeof r2);
    const int32_t e1 = dc_contact_force_deferred_inline(m, s, dt, hd, &r1, &c1);
    const int32_t e2 = shaped(m, s, dt, hsd, &r2, &c2);
    const int32_t s1 = dc_contact_checks_status_inline(&c1), s2 = dc_contact_checks_status_inline(&c2);
    int ok = e1 == DC_OK && e2 == DC_OK;
    if (s1 != sl || s2 != sl) {
        /* the sums alone: finite values whose sum overflows */
        const int n = (int)m->history_len;
        double sin_ = 0.0, sout = rl->f_n, mask = 0.0;
        for (int k = 0; k < n; k++) sin_ += h0[k], mask += (h0[k] - h0[k]) + (hl[k] - hl[k]);
        for (int k = 0; k < 3; k++) {
            sout += rl->force[k] + rl->ft[k] + rl->torque1[k] + rl->torque2[k];
            mask += (rl->force[k] - rl->force[k]) + (rl->ft[k] - rl->ft[k]) +
                    (rl->torque1[k] - rl->torque1[k]) + (rl->torque2[k] - rl->torque2[k]);
        }
        for (int k = 0; k < n; k++) sout += hl[k];
        const int over = sl == DC_OK && mask == 0.0 && !(isfinite(sin_) && isfinite(sout));
        ok = ok && overflow_ok && over && s1 == s2 && s1 != DC_OK;
    }
    if (sl == DC_OK && s1 == DC_OK) {
#if defined(DC_TEST_CONTRACTED)
        /* built with -ffp-contract=fast -march=native: GCC's SLP vectoriser fuses products of
         * the deferred entries across __builtin_assoc_barrier (the header's documented limit):
         * within DC_TEST_CONTRACTED_ULPS ulp of the largest value of the result / of the history, each step from the
         * library's history (no drift) */
        ok = ok && close_values((const double *)rl, (const double *)&r1, 13) &&
             close_values((const double *)rl, (const double *)&r2, 13) &&
             /* the sliding flags: the same where the 13 doubles are */
             (memcmp(rl, &r1, 13 * sizeof(double)) != 0 ||
              (rl->sliding == r1.sliding && rl->rolling_sliding == r1.rolling_sliding)) &&
             (memcmp(rl, &r2, 13 * sizeof(double)) != 0 ||
              (rl->sliding == r2.sliding && rl->rolling_sliding == r2.rolling_sliding)) &&
             close_values(hl, hd, DC_CONTACT_HISTORY_MAX) && close_values(hl, hsd, DC_CONTACT_HISTORY_MAX);
        memcpy(hd, hl, sizeof(double) * DC_CONTACT_HISTORY_MAX);
        memcpy(hsd, hl, sizeof(double) * DC_CONTACT_HISTORY_MAX);
        n_deferred_contracted += !(same_result(rl, &r1) && same_result(rl, &r2));
#else
        ok = ok && same_result(rl, &r1) && same_result(rl, &r2) &&
             memcmp(hl, hd, sizeof(double) * DC_CONTACT_HISTORY_MAX) == 0 &&
             memcmp(hl, hsd, sizeof(double) * DC_CONTACT_HISTORY_MAX) == 0;
#endif
    } else {
        n_deferred_err++;
        if (sl == DC_ERR_NOT_FINITE || sl == DC_ERR_RESULT_RANGE) n_deferred_bad[sl == DC_ERR_RESULT_RANGE]++;
        memcpy(hd, hl, sizeof(double) * DC_CONTACT_HISTORY_MAX);
        memcpy(hsd, hl, sizeof(double) * DC_CONTACT_HISTORY_MAX);
    }
    n_deferred++;
    if (!ok && n_fail < 3)
        fprintf(stderr, "  deferred: library %d, checks %d / %d (entries %d %d), f_n %.17g / %.17g / %.17g\n",
                (int)sl, (int)s1, (int)s2, (int)e1, (int)e2, rl->f_n, r1.f_n, r2.f_n);
    if (!ok && n_fail < 3) {
        const double *a = (const double *)rl, *b = (const double *)&r1, *c = (const double *)&r2;
        for (int k = 0; k < 13; k++)
            if (memcmp(a + k, b + k, 8) || memcmp(a + k, c + k, 8))
                fprintf(stderr, "    result double %d: %.17g %.17g %.17g\n", k, a[k], b[k], c[k]);
        for (int k = 0; k < DC_CONTACT_HISTORY_MAX; k++)
            if (memcmp(hl + k, hd + k, 8) || memcmp(hl + k, hsd + k, 8))
                fprintf(stderr, "    history %d: %.17g %.17g %.17g\n", k, hl[k], hd[k], hsd[k]);
    }
    return ok;
}

/* One contact evolved over `steps` steps of `m`; counts of regimes seen added to `seen`. */
/* step-aware steps compared, first contact steps with the onset correction (R from the impact
 * speed), first contact steps without it (inserted overlapping or receding: R = 1), end
 * corrections fired */
static long n_step_steps = 0, n_step_onsets = 0, n_step_deep = 0, n_step_ends = 0;
/* bad-input cases with the step fields set on a law with state */
static long n_step_fields_state = 0;
/* elastic-plastic steps in contact, and those on the unloading/reloading curve after yield */
static long n_ep_steps = 0, n_ep_unload = 0;
/* JKR steps with the neck formed at overlap <= 0, and steps on which the neck broke */
static long n_jkr_neck = 0, n_jkr_break = 0;

static void trajectory(const dc_contact_model *m, long steps, long *seen) {
    double hl[DC_CONTACT_HISTORY_MAX] = {0}, hi[DC_CONTACT_HISTORY_MAX] = {0};
    double hc[DC_CONTACT_HISTORY_MAX] = {0}; /* dc_contact_force_checked_inline's own history */
    double hs[DC_CONTACT_HISTORY_MAX] = {0}; /* dc_contact_force_shaped_inline's */
    double hd[DC_CONTACT_HISTORY_MAX] = {0}, hsd[DC_CONTACT_HISTORY_MAX] = {0}; /* the deferred entries' */
    shape_check(m);
    if (dc_contact_model_check_inline(m) != DC_OK) {
        fail("model_check of a valid model", 0);
        return;
    }
    dc_contact_state s;
    memset(&s, 0, sizeof s);
    const int wall = uni() < 0.25;
    s.r1 = logu(-5, -1);
    s.r2 = wall ? (double)INFINITY : logu(-5, -1);
    s.m1 = 2500.0 * 4.18879 * s.r1 * s.r1 * s.r1;
    s.m2 = wall ? (uni() < 0.5 ? (double)INFINITY : logu(-3, 3)) : 2500.0 * 4.18879 * s.r2 * s.r2 * s.r2;
    vec(s.n, 1.0);
    unit(s.n);
    const double dt = logu(-8, -4);
    const double amp = s.r1 * logu(-5, -1.5);       /* overlap amplitude */
    const double vscale = logu(-5, 1);              /* tangential speeds over decades */
    const double wscale = vscale / s.r1 * logu(-2, 1);
    const double phase = 2.0 * uni(), freq = 0.01 + 0.2 * uni();
    vec(s.v1, vscale);
    vec(s.v2, vscale);
    vec(s.w1, wscale);
    vec(s.w2, wscale);
    for (long i = 0; i < steps; i++) {
        /* overlap: mostly in contact, with separations (history reset, DMT tail) */
        s.overlap = amp * (0.3 + sin(phase + freq * (double)i));
        /* the normal turns a little each step; now and then by a lot */
        if (uni() < 0.002) {
            vec(s.n, 1.0);
            unit(s.n);
        } else {
            const double tilt = uni() < 0.5 ? 0.0 : logu(-8, -2);
            for (int j = 0; j < 3; j++) s.n[j] += tilt * (2.0 * uni() - 1.0);
            unit(s.n);
        }
        for (int j = 0; j < 3; j++) {
            s.v1[j] += 0.05 * vscale * (2.0 * uni() - 1.0);
            s.v2[j] += 0.05 * vscale * (2.0 * uni() - 1.0);
            s.w1[j] += 0.05 * wscale * (2.0 * uni() - 1.0);
            s.w2[j] += 0.05 * wscale * (2.0 * uni() - 1.0);
        }
        if (uni() < 0.01) vec(s.w1, 0.0); /* exactly zero spins: t = 0 twist, w_r = 0 */
        dc_contact_result rl, ri;
        memset(&rl, 0x5A, sizeof rl);
        memset(&ri, 0x5A, sizeof ri);
        double h0[DC_CONTACT_HISTORY_MAX];
        memcpy(h0, hl, sizeof h0);
        const int32_t sl = dc_contact_force(m, &s, dt, hl, DC_CONTACT_HISTORY_MAX, &rl);
        const int32_t si = dc_contact_force_inline(m, &s, dt, hi, DC_CONTACT_HISTORY_MAX, &ri);
        dc_contact_result rc;
        memset(&rc, 0x5A, sizeof rc);
        const int32_t sc = dc_contact_force_checked_inline(m, &s, dt, hc, &rc);
        dc_contact_result rs;
        memset(&rs, 0x5A, sizeof rs);
        const int32_t ss = shaped(m, &s, dt, hs, &rs, NULL);
        /* the deferred entries, for states the state check accepts (their contract) */
        const int32_t sst = dc_contact_state_check_inline(&s, dt);
        if (sst != DC_OK && sst != sl) {
            fail("state check status", i);
            return;
        }
        if (sst == DC_OK && !deferred_step(m, &s, dt, h0, sl, &rl, hl, hd, hsd, 0)) {
            fail("deferred entries: checks status/result/history bits", i);
            return;
        }
        if (sl != si || sl != sc || sl != ss) {
            fail("contact status", i);
            return;
        }
        if (!same_result(&rl, &rs) || memcmp(hl, hs, sizeof hl) != 0) {
            fail("shaped entry: contact result/history bits", i);
            return;
        }
        if (!same_result(&rl, &rc) || memcmp(hl, hc, sizeof hl) != 0) {
            fail("checked entry: contact result/history bits", i);
            return;
        }
        if (!same_result(&rl, &ri) || memcmp(hl, hi, sizeof hl) != 0) {
            if (n_fail < 5)
                fprintf(stderr, "  step %ld: f_n %.17g vs %.17g, force[0] %.17g vs %.17g, "
                        "hist[3] %.17g vs %.17g\n", i, rl.f_n, ri.f_n, rl.force[0], ri.force[0],
                        hl[3], hi[3]);
            fail("contact result/history bits", i);
            return;
        }
        n_pass++;
        if (dci_bits(m->reserved[0]) != 0 && sl == DC_OK) {
            const int at = (int)m->history_len - 1; /* the step slot is last */
            n_step_steps++;
            n_step_onsets += h0[at] == 0.0 && s.overlap > 0.0 && hl[at] != 1.0;
            n_step_deep += h0[at] == 0.0 && s.overlap > 0.0 && hl[at] == 1.0;
            n_step_ends += hl[at] < 0.0;
        }
        if (m->normal.kernel == DC_KERNEL_ELASTIC_PLASTIC && sl == DC_OK && s.overlap > 0.0) {
            const int at = (int)m->history_len - 1; /* the state slot is last */
            const double r = s.r2 == (double)INFINITY ? s.r1 : s.r1 * s.r2 / (s.r1 + s.r2);
            n_ep_steps++;
            n_ep_unload += hl[at] > m->normal.h * r && s.overlap < hl[at] && rl.f_n > 0.0;
        }
        if (m->normal.kernel == DC_KERNEL_JKR && sl == DC_OK) {
            const int at = (int)m->history_len - 1; /* the state slot is last */
            n_jkr_neck += !(s.overlap > 0.0) && hl[at] > 0.0;
            n_jkr_break += h0[at] > 0.0 && !(hl[at] > 0.0);
        }
        if (sl == DC_OK) {
            seen[0]++;
            seen[1] += rl.sliding;
            seen[2] += s.overlap > 0.0 && !rl.sliding && m->tangential != DC_TANGENTIAL_NONE;
            seen[3] += rl.rolling_sliding;
            seen[4] += !(s.overlap > 0.0);
            /* the frame's spin q = (w1 + w2)/2 dt: series branch (|q|^2 < 1e-3) and sin branch */
            double q2 = 0.0;
            for (int j = 0; j < 3; j++) q2 += 0.25 * dt * dt * (s.w1[j] + s.w2[j]) * (s.w1[j] + s.w2[j]);
            if (s.overlap > 0.0 && m->history_len > 0) seen[q2 < 1e-3 ? 6 : 7]++;
        } else {
            seen[5]++;
        }
    }
}

static void bad_inputs(const dc_contact_model *m) {
    dc_contact_state s;
    memset(&s, 0, sizeof s);
    s.n[2] = 1.0;
    s.overlap = 1e-6;
    s.r1 = s.r2 = 1e-3;
    s.m1 = s.m2 = 1e-5;
    s.v1[0] = 0.1;
    double hbuf[DC_CONTACT_HISTORY_MAX + 1] = {0};
    const double dt = 1e-6;
    /* each case: (model, state, dt, history, len) */
    for (int c = 0; c < 54; c++) {
        dc_contact_model mm = *m;
        dc_contact_state ss = s;
        double hist[DC_CONTACT_HISTORY_MAX + 1];
        for (int i = 0; i <= DC_CONTACT_HISTORY_MAX; i++) hist[i] = 1e-9 * i;
        double *hp = hist;
        size_t len = DC_CONTACT_HISTORY_MAX;
        double d = dt;
        const dc_contact_model *mp = &mm;
        const dc_contact_state *sp = &ss;
        int null_out = 0;
        switch (c) {
        case 0: mp = NULL; break;
        case 1: sp = NULL; break;
        case 2: null_out = 1; break;
        case 3: hp = NULL; break;
        case 4: len = m->history_len ? m->history_len - 1 : 0; break;
        case 5: hp = (double *)(void *)((char *)hbuf + 4); break; /* misaligned */
        case 6: d = (double)NAN; break;
        case 7: d = 0.0; break;
        case 8: d = -1e-6; break;
        case 9: d = (double)INFINITY; break;
        case 10: ss.n[0] = (double)NAN; break;
        case 11: ss.n[0] = 0.5; break; /* not unit */
        case 12: ss.overlap = (double)INFINITY; break;
        case 13: ss.r1 = 0.0; break;
        case 14: ss.m2 = -1.0; break;
        case 15: ss.r2 = (double)INFINITY; ss.m2 = (double)INFINITY; break; /* wall: valid */
        case 16: ss.r1 = (double)INFINITY; break;
        case 17: ss.w2[1] = -(double)INFINITY; break;
        case 18: hist[m->history_len ? m->history_len - 1 : 0] = (double)NAN; break;
        case 19: mm.magic ^= 1u; break;
        case 20: mm.history_len += 1; break;
        case 21: mm.reserved[3] = -0.0; break;
        case 22: mm.carry = pick(2) ? 2 : -1; break;
        case 23: mm.normal.kernel = 99; break;
        case 24: mm.normal.clamp = !mm.normal.clamp; break;
        case 25: mm.mu = -1.0; break;
        case 26: mm.kt = 0.0; break;
        case 27: mm.kappa = 0.0; break;
        case 28: mm.tangential = 7; break;
        case 29: mm.rolling = 5; break;
        case 30: mm.normal.k = (double)NAN; break;
        case 31: mm.eta_tw = (double)INFINITY; break;
        case 32: ss.v1[0] = 1e300; ss.overlap = 1e-1; break; /* result overflow? */
        case 33: ss.overlap = -1e-3; break;                  /* separated: valid */
        case 34: ss.overlap = 0.0; break;
        case 35: ss.n[2] = 1.0 + 2e-6; break;
        case 36: ss.n[2] = 1.0 + 5e-7; break;
        case 37: mm.normal.criterion = 2; break;
        case 38: ss.m1 = 1e-300; ss.v1[0] = 1e150; break;
        /* the finiteness masks: each non-finite kind in body 2's +inf-allowed values, the
         * overlap and the history's first entry; a NaN among finite values elsewhere */
        case 40: ss.r2 = (double)NAN; break;
        case 41: ss.m2 = -(double)INFINITY; break;
        case 42: ss.r2 = -(double)INFINITY; ss.m2 = (double)INFINITY; break;
        case 43: ss.overlap = (double)NAN; break;
        case 44: hist[0] = -(double)INFINITY; break;
        case 45: ss.v2[2] = (double)NAN; ss.w1[0] = (double)INFINITY; break;
        /* an invalid model value together with a bad history buffer: the model's status first,
         * as the library checks the model before the buffer */
        case 46: mm.mu = -1.0; hp = NULL; break;
        case 47: mm.kappa = 0.0; len = 0; break;
        case 48: mm.normal.k = (double)NAN; hp = (double *)(void *)((char *)hbuf + 4); break;
        /* finite values whose sum overflows (the checks' fast sums are not finite there; the
         * masks must decide, as the library's per-value checks): a separated contact (valid,
         * history reset) with huge velocities, with a huge history; a touching one with huge
         * spins */
        case 49: ss.overlap = -1e-3; ss.v1[0] = ss.v1[1] = 1.5e308; break;
        case 50:
            ss.overlap = -1e-3;
            for (int i = 0; i < (int)m->history_len; i++) hist[i] = 1.5e308;
            break;
        case 51: ss.w1[0] = ss.w1[2] = 1.5e308; break;
        /* the history written overflows while every result is finite: heavy bodies sliding
         * fast with a tiny overlap (|trial force|^2 = inf, so F_t = 0; the spring kept with the
         * damping, -(F_t + c_t v_t)/k_t, beyond 1e308): DC_ERR_RESULT_RANGE from the history */
        case 52: ss.m1 = ss.m2 = 1e10; ss.overlap = 1e-18; ss.v1[0] = 1e303; break;
        /* the step fields set on a model that is not yet step-aware: valid for a damped Tsuji
         * law (R = 1), invalid for a law with state (elastic-plastic, JKR) and for the others */
        case 53:
            if (dci_bits(mm.reserved[0]) == 0) {
                mm.reserved[0] = 1e-9;
                mm.history_len += 1;
                n_step_fields_state += dci_has_state(mm.normal.kernel);
            }
            break;
        default: len = 0; break;
        }
        double hl[DC_CONTACT_HISTORY_MAX + 1], hi2[DC_CONTACT_HISTORY_MAX + 1];
        double *hlp = hp, *hip = hp;
        if (hp == hist) {
            memcpy(hl, hist, sizeof hl);
            memcpy(hi2, hist, sizeof hi2);
            hlp = hl;
            hip = hi2;
        }
        dc_contact_result rl, ri;
        memset(&rl, 0x5A, sizeof rl);
        memset(&ri, 0x5A, sizeof ri);
        const int32_t sl = dc_contact_force(mp, sp, d, hlp, len, null_out ? NULL : &rl);
        const int32_t si = dc_contact_force_inline(mp, sp, d, hip, len, null_out ? NULL : &ri);
        /* the fast entry: the model status of dc_contact_model_check_inline, and for an accepted
         * model with a valid history buffer (not cases 3-5, 39: NULL, short, misaligned) the library's status,
         * outputs and history */
        const int32_t mc = dc_contact_model_check_inline(mp);
        if (mc != DC_OK && mc != sl) {
            fprintf(stderr, "  bad case %d: library %d, model_check %d\n", c, (int)sl, (int)mc);
            fail("model_check status", c);
            continue;
        }
        if (mc == DC_OK && hp == hist && len >= mp->history_len) {
            double hc[DC_CONTACT_HISTORY_MAX + 1];
            memcpy(hc, hist, sizeof hc);
            dc_contact_result rc;
            memset(&rc, 0x5A, sizeof rc);
            const int32_t sc = dc_contact_force_checked_inline(mp, sp, d, hc, null_out ? NULL : &rc);
            if (sc != sl || !same_result(&rl, &rc) || memcmp(hl, hc, sizeof hc) != 0) {
                fprintf(stderr, "  bad case %d: library %d, checked entry %d\n", c, (int)sl, (int)sc);
                fail("checked entry: bad-input status/outputs", c);
                continue;
            }
            /* the shaped entry (constant shapes where the test instantiates them): the same */
            double hs[DC_CONTACT_HISTORY_MAX + 1];
            memcpy(hs, hist, sizeof hs);
            dc_contact_result rs;
            memset(&rs, 0x5A, sizeof rs);
            const int32_t ss = sp ? shaped(mp, sp, d, hs, null_out ? NULL : &rs, NULL)
                                  : dc_contact_force_shaped_inline(mp, mp->normal.kernel, mp->tangential,
                                                                   mp->rolling, mp->twisting, mp->carry,
                                                                   NULL, d, hs, &rs);
            if (ss != sl || !same_result(&rl, &rs) || memcmp(hl, hs, sizeof hs) != 0) {
                fprintf(stderr, "  bad case %d: library %d, shaped entry %d\n", c, (int)sl, (int)ss);
                fail("shaped entry: bad-input status/outputs", c);
                continue;
            }
            /* the state check: the library's status for a bad dt or state; else the deferred
             * entries (NULL out: DC_ERR_NULL_POINTER, nothing evaluated) */
            const int32_t sst = dc_contact_state_check_inline(sp, d);
            if (sst != DC_OK && sst != sl) {
                fprintf(stderr, "  bad case %d: library %d, state check %d\n", c, (int)sl, (int)sst);
                fail("state check: bad-input status", c);
                continue;
            }
            if (sst == DC_OK && null_out) {
                dc_contact_checks ck;
                dc_contact_checks_init_inline(&ck);
                double hd[DC_CONTACT_HISTORY_MAX + 1];
                memcpy(hd, hist, sizeof hd);
                if (dc_contact_force_deferred_inline(mp, sp, d, hd, NULL, &ck) != sl ||
                    dc_contact_force_deferred_inline(mp, sp, d, hd, &rs, NULL) != sl ||
                    memcmp(hd, hist, sizeof hd) != 0 || dc_contact_checks_status_inline(&ck) != DC_OK)
                    fail("deferred entry: NULL out/checks", c);
            } else if (sst == DC_OK) {
                double hd[DC_CONTACT_HISTORY_MAX + 1], hsd[DC_CONTACT_HISTORY_MAX + 1];
                memcpy(hd, hist, sizeof hd);
                memcpy(hsd, hist, sizeof hsd);
                if (!deferred_step(mp, sp, d, hist, sl, &rl, hl, hd, hsd, c >= 49)) {
                    fprintf(stderr, "  bad case %d: library %d: deferred entries differ\n", c, (int)sl);
                    fail("deferred entries: bad-input checks", c);
                    continue;
                }
            }
        }
        if (sl != si) {
            fprintf(stderr, "  bad case %d: library %d, inline %d\n", c, (int)sl, (int)si);
            fail("bad-input status", c);
            continue;
        }
        if (!same_result(&rl, &ri) || (hp == hist && memcmp(hl, hi2, sizeof hl) != 0)) {
            fail("bad-input outputs", c);
            continue;
        }
        if (sl != DC_OK && hp == hist) {
            dc_contact_result untouched;
            memset(&untouched, 0x5A, sizeof untouched);
            if (!same_result(&ri, &untouched) || memcmp(hi2, hist, sizeof hist) != 0) {
                fail("outputs written on error", c);
                continue;
            }
        }
        n_pass++;
    }
}

/* The checks' fast sums (demcontact_inline.h, dci_fin): a finite sum proves every value finite;
 * finite values whose sum overflows, and non-finite ones, go to the exact masks, which decide. */
static void sum_checks(void) {
    dc_contact_result r;
    memset(&r, 0, sizeof r);
    r.f_n = 1e308;
    r.force[2] = 1e308; /* finite; f_n + force overflows */
    double h[7] = {1.5e308, 1.5e308, 0, 0, 0, 0, 0}, d[7];
    int ok = dci_result_finite(&r, NULL, 0) && dci_result_finite(&r, h, 7);
    ok = ok && dci_copy_finite(d, h, 7) && memcmp(d, h, sizeof h) == 0;
    r.torque2[1] = (double)NAN;
    ok = ok && !dci_result_finite(&r, h, 7);
    r.torque2[1] = 0.0;
    r.force[0] = (double)INFINITY;
    r.force[1] = -(double)INFINITY; /* the sum NaN */
    ok = ok && !dci_result_finite(&r, NULL, 0);
    r.force[0] = r.force[1] = 0.0;
    h[6] = (double)INFINITY;
    ok = ok && !dci_result_finite(&r, h, 7) && !dci_copy_finite(d, h, 7);
    dc_contact_state s;
    memset(&s, 0, sizeof s);
    s.n[2] = 1.0;
    s.r1 = s.r2 = 1e-3;
    s.m1 = s.m2 = 1e-5;
    s.v1[0] = s.v2[0] = s.w1[2] = 1e308; /* finite; the sum overflows */
    ok = ok && dci_check_contact_state(&s) == DC_OK;
    s.w2[1] = (double)NAN;
    ok = ok && dci_check_contact_state(&s) == DC_ERR_NOT_FINITE;
    if (ok) n_pass++;
    else fail("fast finiteness sums", 0);
}

/* dc_contact_checks: init, merge (threads, ranks) and the status order (history first). */
static void checks_unit(void) {
    dc_contact_checks a, b;
    memset(&a, 0x5A, sizeof a);
    dc_contact_checks_init_inline(&a);
    dc_contact_checks_init_inline(&b);
    dc_contact_checks_init_inline(NULL);
    int ok = dc_contact_checks_status_inline(&a) == DC_OK &&
             dc_contact_checks_status_inline(NULL) == DC_ERR_NULL_POINTER;
    b.result = (double)NAN;
    dc_contact_checks_merge_inline(&a, &b);
    dc_contact_checks_merge_inline(&a, NULL);
    dc_contact_checks_merge_inline(NULL, &b);
    ok = ok && dc_contact_checks_status_inline(&a) == DC_ERR_RESULT_RANGE &&
         dc_contact_checks_status_inline(&b) == DC_ERR_RESULT_RANGE;
    b.result = 0.0;
    b.history = (double)NAN;
    dc_contact_checks_merge_inline(&a, &b);
    ok = ok && dc_contact_checks_status_inline(&a) == DC_ERR_NOT_FINITE;
    if (ok) n_pass++;
    else fail("dc_contact_checks init/merge/status", 0);
}

/* The DMT kernels (codes 18, 19) of dc_normal_force_inline against dc_normal_force, bit for bit:
 * overlaps from deep contact through the attractive tail (-2 d_c .. 0) and beyond, NaN. */
static void dmt_forces(long n) {
    long diff = 0, done = 0;
    while (done < n) {
        dc_contact_spec s;
        random_spec(&s, 0);
        s.normal = DC_NORMAL_DMT;
        s.criterion = DC_END_OVERLAP;
        dc_contact_model m;
        if (dc_contact_model_init(&s, &m) != DC_OK) continue;
        for (int i = 0; i < 1000; i++, done++) {
            const double r = logu(-5, -1), mm = logu(-12, 1), vn = (2.0 * uni() - 1.0) * logu(-3, 3);
            const double dc = pow(m.normal.h * sqrt(r) / m.normal.k, 2.0 / 3.0);
            const double d = i % 97 == 0 ? (double)NAN
                             : i % 3 == 0 ? -2.0 * dc * uni()
                                          : r * logu(-12, -1) * (uni() < 0.1 ? -1.0 : 1.0);
            const double a = dc_normal_force(&m.normal, d, vn, r, mm);
            const double b = dc_normal_force_inline(&m.normal, d, vn, r, mm);
            if (memcmp(&a, &b, sizeof a) != 0) diff++;
        }
    }
    if (diff) fail("DMT forces", diff);
    else n_pass++;
    printf("test_inline_contact[%s]: DMT kernels: %ld forces, %ld differences\n", LANG, done, diff);
}

int main(int argc, char **argv) {
    const long total = argc > 1 ? atol(argv[1]) : 4000000L;
    const long per = 1000;
    long seen[8] = {0};
    long specs_ok = 0, specs_bad = 0, models = 0, projected = 0;

    sum_checks();
    checks_unit();
    /* spec_init */
    {
        dc_contact_spec a, b;
        memset(&a, 0x11, sizeof a);
        memset(&b, 0x11, sizeof b);
        if (dc_contact_spec_init(&a) != dc_contact_spec_init_inline(&b) ||
            memcmp(&a, &b, sizeof a) != 0)
            fail("spec_init", 0);
        else
            n_pass++;
        if (dc_contact_spec_init_inline(NULL) != DC_ERR_NULL_POINTER) fail("spec_init NULL", 0);
    }
    /* model_init: statuses and bytes over random valid and invalid specs */
    for (long i = 0; i < 200000; i++) {
        dc_contact_spec s;
        random_spec(&s, i % 2);
        if (i % 1000 == 999) s.version = 2;
        if (i % 1000 == 998) s.size -= 8;  /* before yield_pressure: accepted, the field unset */
        if (i % 1000 == 997) s.size -= 16; /* no version's size */
        dc_contact_model a, b;
        memset(&a, 0x77, sizeof a);
        memset(&b, 0x77, sizeof b);
        const int32_t sa = dc_contact_model_init(&s, &a);
        const int32_t sb = dc_contact_model_init_inline(&s, &b);
        if (sa != sb || memcmp(&a, &b, sizeof a) != 0) {
            if (n_fail < 5)
                fprintf(stderr, "  spec %ld: normal %d status %d vs %d\n", i, s.normal, (int)sa,
                        (int)sb);
            fail("model_init", i);
            continue;
        }
        n_pass++;
        if (sa == DC_OK) specs_ok++;
        else specs_bad++;
    }
    {
        dc_contact_spec s;
        dc_contact_model a;
        random_spec(&s, 0);
        if (dc_contact_model_init_inline(NULL, &a) != DC_ERR_NULL_POINTER ||
            dc_contact_model_init_inline(&s, NULL) != DC_ERR_NULL_POINTER ||
            dc_contact_model_init(&s, NULL) != DC_ERR_NULL_POINTER)
            fail("model_init NULL", 0);
    }
    /* set_carry: the same statuses and bytes for valid and invalid models and carry codes */
    for (long i = 0; i < 20000; i++) {
        dc_contact_spec s;
        random_spec(&s, 0);
        dc_contact_model a;
        if (dc_contact_model_init(&s, &a) != DC_OK) continue;
        const int32_t carries[5] = {DC_CARRY_ROTATE, DC_CARRY_PROJECT, 2, -1, 1 << 30};
        const int32_t c = carries[pick(5)];
        switch (pick(4)) {
        case 0: a.magic ^= 4u; break;
        case 1: a.carry = 3; break;
        case 2: a.mu = (double)NAN; break;
        default: break;
        }
        dc_contact_model b = a, a0 = a;
        const int32_t sa = dc_contact_model_set_carry(&a, c);
        const int32_t sb = dc_contact_model_set_carry_inline(&b, c);
        if (sa != sb || memcmp(&a, &b, sizeof a) != 0 ||
            (sa != DC_OK && memcmp(&a, &a0, sizeof a) != 0) || (sa == DC_OK && a.carry != c))
            fail("set_carry statuses", i);
        else
            n_pass++;
    }
    if (dc_contact_model_set_carry(NULL, DC_CARRY_PROJECT) != DC_ERR_NULL_POINTER ||
        dc_contact_model_set_carry_inline(NULL, DC_CARRY_PROJECT) != DC_ERR_NULL_POINTER)
        fail("set_carry NULL", 0);
    dmt_forces(total / 4);
    /* the step-aware model: coefficients of R(h) from the library for one Hertz model (the
     * calibration takes milliseconds), then copied into 1 model in 3 below (the evaluation does
     * not depend on where they came from); set_step's statuses and untouched output on error */
    double step_coef[5] = {0};
    {
        dc_contact_spec s;
        dc_contact_spec_init(&s);
        s.normal = DC_NORMAL_HERTZ;
        s.damping = DC_DAMPING_RESTITUTION;
        s.criterion = DC_END_OVERLAP;
        s.E1 = s.E2 = 1e9;
        s.nu1 = s.nu2 = 0.3;
        s.e_n = 0.3;
        dc_contact_model a, a0;
        if (dc_contact_model_init(&s, &a) != DC_OK) fail("step model init", 0);
        a0 = a;
        const double bad_dt[4] = {0.0, -1e-6, (double)NAN, (double)INFINITY};
        const int32_t bad_st[4] = {DC_ERR_NOT_POSITIVE, DC_ERR_NOT_POSITIVE, DC_ERR_NOT_FINITE,
                                   DC_ERR_NOT_FINITE};
        for (int i = 0; i < 4; i++)
            if (dc_contact_model_set_step(&a, bad_dt[i], DC_INTEGRATOR_VELOCITY_VERLET) != bad_st[i] ||
                memcmp(&a, &a0, sizeof a) != 0)
                fail("set_step bad dt", i);
        if (dc_contact_model_set_step(&a, 1e-6, 2) != DC_ERR_INTEGRATOR ||
            memcmp(&a, &a0, sizeof a) != 0 ||
            dc_contact_model_set_step(NULL, 1e-6, 0) != DC_ERR_NULL_POINTER)
            fail("set_step bad integrator / NULL", 0);
        if (dc_contact_model_set_step(&a, 1e-6, DC_INTEGRATOR_SYMPLECTIC_EULER) != DC_OK ||
            a.history_len != a0.history_len + 1 || !(a.reserved[0] > 0.0))
            fail("set_step", 0);
        for (int i = 0; i < 5; i++) step_coef[i] = a.reserved[i + 1];
        size_t len = 0;
        if (dc_contact_history_len(&a, &len) != DC_OK || len != a.history_len)
            fail("set_step history_len", 0);
        /* a viscoelastic law has no step-aware form */
        s.normal = DC_NORMAL_VISCOELASTIC;
        s.damping = DC_DAMPING_NONE;
        s.visco_A = 1e-6;
        if (dc_contact_model_init(&s, &a) != DC_OK) fail("visco init", 0);
        a0 = a;
        if (dc_contact_model_set_step(&a, 1e-6, 0) != DC_ERR_STEP_UNSUPPORTED ||
            memcmp(&a, &a0, sizeof a) != 0)
            fail("set_step viscoelastic", 0);
        n_pass++;
    }
    long stepped = 0;
    /* trajectories */
    while (models * per < total) {
        dc_contact_spec s;
        random_spec(&s, 0);
        dc_contact_model m;
        if (dc_contact_model_init(&s, &m) != DC_OK) continue;
        if (models % 5 < 2) {
            /* the projection carry on 2 models in 5: set by the library and by the header */
            dc_contact_model mi = m;
            if (dc_contact_model_set_carry(&m, DC_CARRY_PROJECT) != DC_OK ||
                dc_contact_model_set_carry_inline(&mi, DC_CARRY_PROJECT) != DC_OK ||
                memcmp(&m, &mi, sizeof m) != 0 || m.carry != DC_CARRY_PROJECT)
                fail("set_carry", models);
            projected++;
        }
        if (models % 3 == 2 && (m.normal.model == DC_MODEL_POWERLAW || m.normal.model == DC_MODEL_HERTZ) &&
            m.normal.alpha > 0.0) {
            /* step-aware: what dc_contact_model_set_step writes, with the template's R(h) */
            m.reserved[0] = logu(-9, -3);
            for (int i = 0; i < 5; i++) m.reserved[i + 1] = step_coef[i];
            m.history_len += 1;
            stepped++;
        }
        trajectory(&m, per, seen);
        if (models % 50 == 0) bad_inputs(&m);
        models++;
    }
    printf("test_inline_contact[%s]: %ld models built (%ld specs rejected with the same status), "
           "%ld trajectories x %ld steps: %ld ok steps (%ld sliding, %ld sticking, %ld at the "
           "rolling/twisting limit, %ld separated; frame spin by series %ld, by sin %ld), %ld error "
           "steps\n",
           LANG, specs_ok, specs_bad, models, per, seen[0], seen[1], seen[2], seen[3], seen[4],
           seen[6], seen[7], seen[5]);
    printf("test_inline_contact[%s]: %ld of the trajectories with the projection carry\n", LANG,
           projected);
    printf("test_inline_contact[%s]: step-aware: %ld trajectories, %ld steps (%ld contact onsets, "
           "%ld first steps too deep or receding for one, %ld end corrections)\n", LANG, stepped,
           n_step_steps, n_step_onsets, n_step_deep, n_step_ends);
    printf("test_inline_contact[%s]: elastic-plastic: %ld steps in contact, %ld on the "
           "unloading/reloading curve after yield\n", LANG, n_ep_steps, n_ep_unload);
    printf("test_inline_contact[%s]: JKR: %ld steps with the neck at overlap <= 0, %ld breakages\n",
           LANG, n_jkr_neck, n_jkr_break);
    int shapes_hit = 0;
    for (int i = 0; i < 240; i++) shapes_hit += shape_hits[i] > 0;
    printf("test_inline_contact[%s]: shaped entry: %ld steps with a constant shape (%d of the 240 "
           "shapes), %ld with a run-time one\n", LANG, n_shaped_const, shapes_hit, n_shaped_runtime);
    printf("test_inline_contact[%s]: deferred entries: %ld steps (%ld with an error status), the "
           "history not finite %ld, results out of range %ld; %ld steps not bit-identical (only "
           "in the contracted build)\n",
           LANG, n_deferred, n_deferred_err, n_deferred_bad[0], n_deferred_bad[1], n_deferred_contracted);
#if defined(DC_TEST_CONTRACTED)
    printf("test_inline_contact[%s]: deferred entries, contracted: largest difference %.1f ulp of the "
           "largest value of a result or history (bound %.0f)\n", LANG, worst_ulps, DC_TEST_CONTRACTED_ULPS);
#endif
    /* the comparison must have exercised every regime */
    if (!(seen[1] > 1000 && seen[2] > 1000 && seen[3] > 1000 && seen[4] > 1000 && seen[6] > 1000 &&
          seen[7] > 1000 && specs_bad > 1000 && projected * 4 > models &&
          n_step_steps > 1000 && n_step_onsets > 10 && n_step_deep > 10 && n_step_ends > 10 && n_step_fields_state > 0 && n_ep_unload > 1000 &&
          n_jkr_neck > 1000 && n_jkr_break > 100 &&
          n_shaped_const * 10 > n_shaped_runtime && n_shaped_runtime > 1000 &&
          n_deferred * 2 > seen[0] && n_deferred_bad[0] > 0 && n_deferred_bad[1] > 0 &&
          /* every constant shape in the long runs (10^7 steps; shorter runs reach fewer) */
          shapes_hit >= (total >= 10000000L ? 136 : total >= 2000000L ? 60 : 20)))
        fail("coverage of regimes", 0);
    printf("test_inline_contact[%s]: %ld passed, %ld failed\n", LANG, n_pass, n_fail);
    return n_fail ? 1 : 0;
}
