/* libFuzzer harness for the C ABI. The first byte selects an export, the rest is decoded into
 * doubles (raw bit patterns, so NaN, inf, subnormals and huge values all occur) and an integer.
 * Every call must return a known status (never DC_ERR_INTERNAL), leave its output untouched on
 * error and produce a finite output on success; any violation aborts, which libFuzzer reports.
 * Cases 0-11: calibration, material, pair constructors and force kernels; 12-20: the power-law
 * calculus (durations at every level, energy partition, trajectories with fuzzed n, buf_len and
 * NULL buffers, time steps, omega0); 21-23: the viscoelastic exports; 24-28: the full-contact
 * exports (spec from fuzzed fields and selectors, scalar, spheres and batch with fuzzed states,
 * histories and NULL masks, arbitrary bytes as a dc_contact_model); 29-31: the builtin corrections
 * (every model code, clamp and wall flag, value -> realised e round trip to 1e-9, realised e in
 * [0, 1]) and the fit (fuzzed n <= 8, arrays, NULL sigma and residual buffers, robust, criterion,
 * tol; residuals and result untouched on error, finite on success) and its 95 % quantile.
 * Built and run by scripts/fuzz.sh (Rust code instrumented for coverage, ASan+UBSan on the C side).
 * DC_FUZZ_PLANT_CRASH=1 in the environment makes the first input abort: scripts/fuzz_selftest.sh
 * uses it to prove that scripts/fuzz.sh fails when the harness finds a crash. */
#include <demcontact.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define SENTINEL (-7.25e101)

static void verdict(int32_t s, double out) {
    /* The library's own status table decides what is documented: no hard-coded range here. */
    int known = dc_status_known(s) && s != DC_ERR_INTERNAL;
    if (!known) abort();
    if (s == DC_OK && !isfinite(out)) abort();
    if (s != DC_OK && memcmp(&out, &(double){SENTINEL}, sizeof out) != 0) abort();
}

/* ---------------------------------------------------------------- full contact (cases 24-28) */

static int known(int32_t s) { return dc_status_known(s) && s != DC_ERR_INTERNAL; }

static int all_finite(const double *v, size_t n) {
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

/* A model with every stage switched on (history length 10), from valid parameters. */
static int full_model(dc_contact_model *m, int32_t crit) {
    dc_contact_spec s;
    if (dc_contact_spec_init(&s) != DC_OK) abort();
    s.normal = DC_NORMAL_HERTZ;
    s.damping = DC_DAMPING_RESTITUTION;
    s.criterion = crit;
    s.E1 = 7e10, s.nu1 = 0.3, s.E2 = INFINITY, s.nu2 = 0.25, s.e_n = 0.6;
    s.tangential = DC_TANGENTIAL_MINDLIN, s.mu = 0.4, s.e_t = 0.5;
    s.rolling = DC_ROLLING_EPSD, s.mu_r = 0.1, s.eta_r = 0.3;
    s.twisting = DC_TWISTING_SDS, s.mu_tw = 1e-5, s.k_tw = 1e-4;
    return dc_contact_model_init(&s, m) == DC_OK;
}

static void fuzz_contact(int which, const uint8_t *data, size_t n) {
    /* Zero-padded copy: short inputs read zeros, never past the end. */
    uint8_t d[sizeof(double) * 40] = {0};
    memcpy(d, data, n < sizeof d ? n : sizeof d);
    n = sizeof d;
    double y[40];
    memcpy(y, d, sizeof y);
    int32_t sel[6];
    memcpy(sel, d, sizeof sel);
    dc_contact_model m, m0;
    memset(&m, 0x5a, sizeof m);
    m0 = m;
    dc_contact_result r, r0;
    memset(&r, 0x33, sizeof r);
    r0 = r;
    double h[DC_CONTACT_HISTORY_MAX], h0[DC_CONTACT_HISTORY_MAX];
    memcpy(h, y + 20, sizeof h);
    memcpy(h0, h, sizeof h);
    dc_contact_state st;
    memcpy(&st, y, sizeof st); /* 20 doubles */
    int32_t s;
    switch (which) {
    case 24: { /* spec: fuzzed selectors and parameters */
        dc_contact_spec sp;
        if (dc_contact_spec_init(&sp) != DC_OK) abort();
        sp.normal = sel[0] % 7 - 1, sp.damping = sel[1] % 4 - 1, sp.criterion = sel[2] % 4 - 1;
        sp.tangential = sel[3] % 5 - 1, sp.rolling = sel[4] % 5 - 1, sp.twisting = sel[5] % 4 - 1;
        double *f = &sp.E1; /* the 18 consecutive doubles E1 .. inertia_factor */
        for (int i = 0; i < 18; i++)
            if (d[i] & 1) f[i] = y[3 + i];
        if (d[0] & 2) sp.version ^= (uint32_t)(y[1] != 0);
        s = dc_contact_model_init(&sp, &m);
        if (!known(s)) abort();
        if (s != DC_OK && memcmp(&m, &m0, sizeof m) != 0) abort();
        if (s == DC_OK) {
            size_t len = 99;
            if (dc_contact_history_len(&m, &len) != DC_OK || len > DC_CONTACT_HISTORY_MAX) abort();
            /* the frame carry: any code; accepted (0, 1) or refused with the model untouched */
            dc_contact_model mc = m;
            const int32_t carry = sel[5] / 4;
            s = dc_contact_model_set_carry(&mc, carry);
            if (!known(s)) abort();
            if (s == DC_OK ? (carry != DC_CARRY_ROTATE && carry != DC_CARRY_PROJECT) || mc.carry != carry
                           : s != DC_ERR_SPEC_MODEL || memcmp(&mc, &m, sizeof m) != 0)
                abort();
        }
        break;
    }
    case 25: /* one contact, fuzzed state, dt, history */
    case 26: /* the spheres helper, fuzzed centres */
        if (!full_model(&m, d[0] & 1)) abort();
        if ((d[7] & 1) && dc_contact_model_set_carry(&m, DC_CARRY_PROJECT) != DC_OK) abort();
        if (which == 25)
            s = dc_contact_force(&m, &st, y[30], (d[1] & 1) ? h : NULL, (size_t)(d[2] % 12), &r);
        else
            s = dc_contact_force_spheres(&m, y + 30, y + 33, &st, y[36], h, DC_CONTACT_HISTORY_MAX, &r);
        if (!known(s)) abort();
        if (s != DC_OK && (memcmp(&r, &r0, sizeof r) != 0 || memcmp(h, h0, sizeof h) != 0)) abort();
        if (s == DC_OK && !(all_finite(r.force, 3) && all_finite(r.torque1, 3) && all_finite(r.torque2, 3) &&
                            all_finite(&r.f_n, 1) && all_finite(h, DC_CONTACT_HISTORY_MAX)))
            abort();
        break;
    case 27: { /* batch of 2 contacts: fuzzed arrays (aliasing the fuzzed doubles), NULL mask;
                * checked or fused (d[6] & 1) */
        if (!full_model(&m, d[0] & 1)) abort();
        if ((d[7] & 1) && dc_contact_model_set_carry(&m, DC_CARRY_PROJECT) != DC_OK) abort();
        /* history: 2 contacts at a stride of up to 11 doubles */
        double out[2 + 6 + 6 + 6], out0[20], hb[22];
        for (int i = 0; i < 20; i++) out[i] = SENTINEL;
        for (int i = 0; i < 22; i++) hb[i] = y[i];
        memcpy(out0, out, sizeof out);
        double hb0[22];
        memcpy(hb0, hb, sizeof hb);
        uint32_t mask = (uint32_t)d[3] | ((uint32_t)d[4] << 8);
        const double *in[10] = {y, y + 6, y + 8, y + 14, y + 20, y + 26, y + 32, y + 34, y + 36, y + 38};
        for (int i = 0; i < 10; i++)
            if (mask & (1u << i)) in[i] = NULL;
        dc_contact_batch b = {.n = 2, .history_stride = (size_t)(d[5] % 12), .normal = in[0], .overlap = in[1],
                              .v1 = in[2], .v2 = in[3], .w1 = in[4], .w2 = in[5], .r1 = in[6], .r2 = in[7],
                              .m1 = in[8], .m2 = in[9], .history = (mask & 1024) ? NULL : hb, .f_n = out,
                              .force = out + 2, .torque1 = out + 8, .torque2 = out + 14};
        size_t bad = 7;
        int fused = d[6] & 1;
        s = fused ? dc_contact_force_batch_fused(&m, &b, y[39], &bad) : dc_contact_force_batch(&m, &b, y[39]);
        if (!known(s)) abort();
        if (fused && bad != 7) {
            /* a bad contact: its outputs NaN, its history (10 doubles) untouched */
            if (s == DC_OK || bad > 1 || !isnan(out[bad])) abort();
            for (int k = 0; k < 3; k++)
                if (!isnan(out[2 + 3 * bad + k]) || !isnan(out[8 + 3 * bad + k]) || !isnan(out[14 + 3 * bad + k]))
                    abort();
            if (memcmp(hb + bad * b.history_stride, hb0 + bad * b.history_stride, 10 * sizeof(double)) != 0) abort();
        } else if (!fused && s == DC_ERR_RESULT_RANGE) {
            /* an overflow (found only by computing): every contact written; an overflowing one
             * NaN with its history untouched, the other finite */
            int nan_seen = 0;
            for (size_t i = 0; i < 2; i++) {
                double o3[9] = {out[2 + 3 * i], out[3 + 3 * i], out[4 + 3 * i], out[8 + 3 * i], out[9 + 3 * i],
                                out[10 + 3 * i], out[14 + 3 * i], out[15 + 3 * i], out[16 + 3 * i]};
                if (isnan(out[i])) {
                    nan_seen = 1;
                    for (int k = 0; k < 9; k++)
                        if (!isnan(o3[k])) abort();
                    if (memcmp(hb + i * b.history_stride, hb0 + i * b.history_stride, 10 * sizeof(double)) != 0)
                        abort();
                } else if (!all_finite(out + i, 1) || !all_finite(o3, 9)) {
                    abort();
                }
            }
            if (!nan_seen) abort();
        } else {
            if (s != DC_OK && (memcmp(out, out0, sizeof out) != 0 || memcmp(hb, hb0, sizeof hb) != 0)) abort();
            if (s == DC_OK && !all_finite(out, 20)) abort();
        }
        break;
    }
    case 28: /* arbitrary bytes as a model: rejected or computed, never a crash */
        memset(&m, 0, sizeof m);
        memcpy(&m, d, n < sizeof m ? n : sizeof m);
        s = dc_contact_force(&m, &st, 1e-7, h, DC_CONTACT_HISTORY_MAX, &r);
        if (!known(s)) abort();
        if (s != DC_OK && memcmp(&r, &r0, sizeof r) != 0) abort();
        break;
    }
}

/* ------------------------------------------------ builtin corrections and fit (cases 29-31) */

static void fuzz_builtin_fit(int which, const uint8_t *data, size_t n) {
    uint8_t d[8 + sizeof(double) * 24] = {0}; /* 8 selector bytes, then 24 doubles */
    memcpy(d, data, n < sizeof d ? n : sizeof d);
    double y[24];
    memcpy(y, d + 8, sizeof y);
    int32_t model = (int32_t)(d[0] % 11) - 1; /* -1 .. 9: every DC_BUILTIN_* and unknown codes */
    int32_t clamp = (int32_t)(d[1] % 4) - 1, wall = (int32_t)(d[2] % 4) - 1; /* -1, 0, 1, 2 */
    double out = SENTINEL, back = SENTINEL;
    int32_t s;
    switch (which) {
    case 29: /* value to type, and its forward map: the round trip must give e back */
        s = dc_builtin_value_for_e(model, clamp, y[0], &out);
        verdict(s, out);
        if (s == DC_OK) {
            s = dc_builtin_realised_e(model, clamp, out, &back);
            if (s != DC_OK || !(fabs(back - y[0]) <= 1e-9)) abort();
        }
        out = SENTINEL, back = SENTINEL;
        s = dc_builtin_value_for_e_wall(model, clamp, wall, y[0], &out);
        verdict(s, out);
        if (s == DC_OK) {
            s = dc_builtin_realised_e_wall(model, clamp, wall, out, &back);
            if (s != DC_OK || !(fabs(back - y[0]) <= 1e-9)) abort();
        }
        out = SENTINEL;
        s = dc_builtin_realised_e(model, clamp, y[1], &out);
        verdict(s, out);
        if (s == DC_OK && !(out >= 0.0 && out <= 1.0)) abort();
        out = SENTINEL;
        s = dc_builtin_realised_e_wall(model, clamp, wall, y[1], &out);
        verdict(s, out);
        if (s == DC_OK && !(out >= 0.0 && out <= 1.0)) abort();
        out = SENTINEL;
        verdict(dc_builtin_yade_viscel_cn(y[2], y[3], y[4], &out), out);
        break;
    case 30: { /* the fit: n, NULL sigma, robust, criterion, residual buffers from the input */
        size_t np = d[3] % 9; /* 0 .. 8 points */
        double v[8], e[8], sg[8];
        memcpy(v, y, sizeof v);
        memcpy(e, y + 8, sizeof e);
        memcpy(sg, y + 16, sizeof sg);
        if (d[4] & 1) /* plausible data half the time, so the success paths are reached */
            for (size_t i = 0; i < 8; i++) {
                v[i] = 0.05 + 0.3 * (double)i + fabs(fmod(v[i], 10.0)); /* distinct for zero input */
                e[i] = 0.05 + 0.9 * fabs(fmod(e[i], 1.0));
                sg[i] = 1e-3 + fabs(fmod(sg[i], 0.1));
                if (!isfinite(v[i]) || !isfinite(e[i]) || !isfinite(sg[i])) v[i] = 1.0 + (double)i, e[i] = 0.5, sg[i] = 0.01;
            }
        dc_fit_result r, r0;
        memset(&r, 0x5a, sizeof r);
        r0 = r;
        double rv[8], rc[8], rv0[8], rc0[8];
        for (int i = 0; i < 8; i++) rv[i] = rc[i] = SENTINEL;
        memcpy(rv0, rv, sizeof rv);
        memcpy(rc0, rc, sizeof rc);
        int32_t crit = (int32_t)(d[5] % 4) - 1;
        double tol = (d[4] & 2) ? y[23] : 0.02;
        s = dc_fit_restitution(np, v, e, (d[4] & 4) ? NULL : sg, crit, tol, d[4] & 8,
                               (d[4] & 16) ? NULL : rv, (d[4] & 32) ? NULL : rc, &r);
        if (!known(s)) abort();
        if (s != DC_OK && (memcmp(&r, &r0, sizeof r) != 0 || memcmp(rv, rv0, sizeof rv) != 0 ||
                           memcmp(rc, rc0, sizeof rc) != 0))
            abort();
        if (s == DC_OK) {
            const double f[] = {r.beta, r.beta_se, r.e_const, r.e_const_se, r.chi2_viscoelastic,
                                r.chi2_constant, r.max_residual_viscoelastic, r.max_residual_constant,
                                r.v_min, r.v_max, r.e_viscoelastic_at_v_min, r.e_viscoelastic_at_v_max,
                                r.max_model_deviation};
            if (!all_finite(f, sizeof f / sizeof f[0]) || r.beta < 0.0 || r.beta_se < 0.0) abort();
            if (!(d[4] & 16) && !all_finite(rv, np)) abort();
            if (!(d[4] & 32) && !all_finite(rc, np)) abort();
            /* the 95 % multiplier for this fit */
            double q = SENTINEL;
            if (dc_fit_quantile95(np, r.se_from_scatter, &q) != DC_OK || !(q >= 1.959 && q <= 12.71)) abort();
        }
        break;
    }
    case 31: { /* the quantile: any n (from 8 bytes), any flag */
        uint64_t nn;
        memcpy(&nn, d + 8, sizeof nn);
        if (d[3] & 1) nn %= 2048; /* small n half the time (the incomplete-beta path) */
        s = dc_fit_quantile95((size_t)nn, (int32_t)d[4] - 128, &out);
        verdict(s, out);
        if (s == DC_OK && !(out >= 1.959 && out <= 12.71)) abort();
        break;
    }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    static int planted = -1;
    if (planted < 0) planted = getenv("DC_FUZZ_PLANT_CRASH") != NULL;
    if (planted) abort(); /* the self-test's planted crash */
    if (size < 1) return 0;
    double x[8] = {0};
    uint8_t buf[sizeof x + 4] = {0};
    memcpy(buf, data + 1, size - 1 < sizeof buf ? size - 1 : sizeof buf);
    memcpy(x, buf, sizeof x);
    int32_t c;
    memcpy(&c, buf + sizeof x, sizeof c);
    c = (c % 4 + 4) % 4 - 1; /* -1, 0, 1, 2: valid and invalid criteria */
    double out = SENTINEL;
    dc_pair pair;
    double v3[3] = {SENTINEL, SENTINEL, SENTINEL};
    switch (data[0] % 32) {
    case 0: verdict(dc_alpha_from_e(x[0], x[1], c, &out), out); break;
    case 1: verdict(dc_e_from_alpha(x[0], x[1], c, &out), out); break;
    case 2: verdict(dc_dt_crit(x[0], x[1], x[2], &out), out); break;
    case 3: verdict(dc_hertz_stiffness(x[0], x[1], x[2], x[3], x[4], x[5], &out), out); break;
    case 4: verdict(dc_effective_modulus(x[0], x[1], x[2], x[3], &out), out); break;
    case 5:
        if (!dc_status_str(c) || !dc_version()) abort();
        if (dc_alpha_from_e(x[0], x[1], c, NULL) != DC_ERR_NULL_POINTER) abort();
        break;
    case 6: /* a pair from a constructor with fuzzed inputs, then a checked force */
    case 7:
    case 8: {
        int32_t s;
        if (data[0] % 32 == 6) s = dc_pair_powerlaw(x[0], x[1], x[2], c, &pair);
        else if (data[0] % 32 == 7) s = dc_pair_hertz(x[0], x[1], x[0], x[1], x[2], c, &pair);
        else s = dc_pair_viscoelastic(x[0], x[1], x[0], x[1], x[2], c, &pair);
        verdict(s == DC_OK ? DC_OK : s, s == DC_OK ? 0.0 : SENTINEL);
        if (s == DC_OK) {
            verdict(dc_normal_force_checked(&pair, x[3], x[4], x[5], x[6], &out), out);
            /* The unchecked kernel must not crash and must give a finite force for finite input. */
            double f = dc_normal_force(&pair, x[3], x[4], x[5], x[6]);
            if (isfinite(x[3]) && isfinite(x[4]) && isfinite(x[5]) && isfinite(x[6]) && x[5] > 0 && x[6] > 0 &&
                out != SENTINEL && !isfinite(f))
                abort();
        }
        break;
    }
    case 9: /* arbitrary bytes as a pair: the checked paths must reject or compute, never crash */
        memset(&pair, 0, sizeof pair);
        memcpy(&pair, data + 1, size - 1 < sizeof pair ? size - 1 : sizeof pair);
        verdict(dc_normal_force_checked(&pair, x[0], x[1], x[2], x[3], &out), out);
        (void)dc_normal_force(&pair, x[0], x[1], x[2], x[3]);
        break;
    case 10: { /* batch of 4 contacts from fuzzed doubles */
        if (dc_pair_powerlaw(1.0 + fabs(fmod(x[0], 4.0)), 1e3, 0.5, c & 1, &pair) != DC_OK) break;
        double f4[4] = {SENTINEL, SENTINEL, SENTINEL, SENTINEL};
        int32_t s = dc_normal_force_batch(&pair, 4, x, x + 4, x, x + 4, f4);
        if (!dc_status_known(s) || s == DC_ERR_INTERNAL) abort();
        if (s != DC_OK && f4[0] != SENTINEL) abort();
        break;
    }
    case 11: /* 3D helper with fuzzed geometry */
        if (dc_pair_hertz(1e9, 0.3, 1e9, 0.3, 0.5, c & 1, &pair) != DC_OK) break;
        verdict(dc_normal_force_3d(&pair, x, x + 3, x[6], x[7], x + 1, x + 4, x[7], x[6], v3), v3[0]);
        break;
    /* Power-law calculus. */
    case 12: verdict(dc_max_overlap(x[0], x[1], x[2], x[3], &out), out); break;
    case 13: verdict(dc_time_of_max_overlap(x[0], x[1], x[2], x[3], &out), out); break;
    case 14: verdict(dc_contact_duration(x[0], x[1], x[2], x[3], c, &out), out); break;
    case 15: verdict(dc_contact_duration_level(x[0], x[1], x[2], x[3], c, (int32_t)(data[0] / 32) % 7 - 1, &out), out); break;
    case 16: {
        dc_energy en = {SENTINEL, SENTINEL, SENTINEL, SENTINEL, SENTINEL};
        int32_t s = dc_energy_partition(x[0], x[1], c, &en);
        verdict(s, en.e);
        verdict(s, en.loading);
        verdict(s, en.unloading);
        verdict(s, en.returned);
        verdict(s, en.clamped);
        if (s == DC_OK && fabs(en.loading + en.unloading + en.returned + en.clamped - 1.0) > 1e-14) abort();
        break;
    }
    case 17: { /* trajectory: n, buf_len and the NULL mask come from the input */
        double bufs[4][8];
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 8; j++) bufs[i][j] = SENTINEL;
        uint8_t ctl = size > 1 ? data[size - 1] : 0;
        size_t n = ctl & 7u, len = (ctl >> 3) & 7u;
        if (ctl & 0x40u) n = (size_t)-1;
        double *pt[4];
        for (int i = 0; i < 4; i++) pt[i] = (ctl & 0x80u) && i == (ctl & 3u) ? NULL : bufs[i];
        int32_t s = dc_contact_trajectory(x[0], x[1], x[2], x[3], x[4], c, (int32_t)(data[0] / 32) % 7 - 1, n, pt[0],
                                          pt[1], pt[2], pt[3], len);
        if (!dc_status_known(s) || s == DC_ERR_INTERNAL) abort();
        for (int i = 0; i < 4; i++)
            for (size_t j = 0; j < 8; j++) {
                int written = memcmp(&bufs[i][j], &(double){SENTINEL}, sizeof(double)) != 0;
                if (s == DC_OK && j < n && !isfinite(bufs[i][j])) abort();
                /* The one documented exception to "untouched on error": DC_ERR_RESULT_RANGE found
                 * after sampling sets the first n samples of every buffer to NaN. */
                if (s == DC_ERR_RESULT_RANGE && j < n && written && !isnan(bufs[i][j])) abort();
                if (s != DC_OK && s != DC_ERR_RESULT_RANGE && written) abort();
                if (j >= n && written) abort();
            }
        break;
    }
    case 18: verdict(dc_dt_linearised(x[0], x[1], x[2], &out), out); break;
    case 19: verdict(dc_dt_static(x[0], x[1], x[2], x[3], &out), out); break;
    case 20: verdict(dc_omega0(x[0], x[1], &out), out); break;
    /* Viscoelastic exports (the reference integrator only for b <= 10: its cost grows with b). */
    case 21:
        verdict(dc_viscoelastic_e(x[0], c, &out), out);
        out = SENTINEL;
        verdict(dc_viscoelastic_e_series(x[0], c, &out), out);
        out = SENTINEL;
        verdict(dc_viscoelastic_b_from_e(x[1], c, &out), out);
        if (!(isfinite(x[0]) && x[0] > 10.0)) {
            out = SENTINEL;
            verdict(dc_viscoelastic_e_reference(x[0], c, &out), out);
        }
        break;
    case 22: {
        verdict(dc_viscoelastic_b(x[0], x[1], x[2], &out), out);
        out = SENTINEL;
        verdict(dc_viscoelastic_e_of_speed(x[0], x[1], x[2], c, &out), out);
        double k = SENTINEL, g = SENTINEL;
        int32_t s = dc_viscoelastic_k_gamma(x[3], x[4], x[5], &k, &g);
        verdict(s, k);
        verdict(s, g);
        break;
    }
    case 23:
        verdict(dc_viscoelastic_beta_from_e(x[0], x[1], c, &out), out);
        out = SENTINEL;
        verdict(dc_viscoelastic_a_from_e(x[0], x[1], x[2], x[3], c, &out), out);
        out = SENTINEL;
        verdict(dc_viscoelastic_speed_for_e(x[0], x[1], c, &out), out);
        break;
    case 24:
    case 25:
    case 26:
    case 27:
    case 28: fuzz_contact(data[0] % 32, data + 1, size - 1); break;
    case 29:
    case 30:
    case 31: fuzz_builtin_fit(data[0] % 32, data + 1, size - 1); break;
    }
    return 0;
}
