/* libFuzzer target: the full-contact exports. Case 0: a spec from fuzzed fields and selectors
 * (and the frame carry of the model it gives); 1: one contact with a fuzzed state, dt and
 * history; 2: the spheres helper with fuzzed centres; 3: the batch of 2 contacts (checked or
 * fused) with fuzzed arrays, history stride and NULL masks; 4: arbitrary bytes as a
 * dc_contact_model; 5: dc_contact_model_set_step with a fuzzed dt and integrator on a
 * step-aware model; 6: dc_contact_force_energy as case 1 (cases 1-3 also run the step-aware model when d[8] is odd; cases 1 and 3 then,
 * when d[9] is odd, start each approaching contact fresh at a true onset: see at_onset). Inputs
 * are 40 raw doubles (zero-padded), their first bytes also read as selectors. */
#define FUZZ_CASES 7
#include "fuzz_common.h"

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

/* full_model made step-aware (dt 1e-7, velocity Verlet): calibrated once per criterion (a few
 * milliseconds), then copied; dc_contact_model_set_step on a step-aware model reuses its
 * calibration, so the fuzzed calls below stay cheap. */
static int step_model(dc_contact_model *m, int32_t crit) {
    static dc_contact_model cache[2];
    static int ready[2];
    const int i = crit ? 1 : 0;
    if (!ready[i]) {
        if (!full_model(&cache[i], crit)) return 0;
        if (dc_contact_model_set_step(&cache[i], 1e-7, DC_INTEGRATOR_VELOCITY_VERLET) != DC_OK) return 0;
        ready[i] = 1;
    }
    *m = cache[i];
    return 1;
}

/* A fuzzed value made usable: x where finite, else `dflt`; for `positive`, |x| and `dflt` for 0. */
static double usable(double x, double dflt, int positive) {
    if (!isfinite(x)) return dflt;
    if (positive) return x == 0.0 ? dflt : fabs(x);
    return x;
}

/* A fresh contact at its onset, as a host's drift makes it, in place in the arrays a state is
 * read from (n, v1, v2: 3 doubles each; w1, w2: spins; r, m: the two radii and the two masses,
 * each pair `gap` doubles apart): every value made usable (the normal a unit vector), then the
 * overlap a·v·dt, v the approach speed along the normal (1 where the fuzzed pair recedes), a in
 * (0, 2] from the byte `code`. Raw fuzzed states are rarely valid and their overlaps rarely that
 * shallow, so without this the step-aware onset correction (docs/timestep.md, "Derivation") would
 * seldom run. The overlap stays as it was where a·v·dt is not a normal double. */
static void at_onset(double *n, double *v1, double *v2, double *w1, double *w2, double *r, double *m, size_t gap,
                     double dt, uint8_t code, double *overlap) {
    double nn = 0.0;
    for (int k = 0; k < 3; k++) {
        n[k] = usable(n[k], 0.0, 0);
        v1[k] = usable(v1[k], 0.0, 0);
        v2[k] = usable(v2[k], 0.0, 0);
        w1[k] = usable(w1[k], 0.0, 0);
        w2[k] = usable(w2[k], 0.0, 0);
        nn += n[k] * n[k];
    }
    nn = sqrt(nn);
    for (int k = 0; k < 3; k++) n[k] = isnormal(nn) && isfinite(nn) ? n[k] / nn : (k == 2 ? 1.0 : 0.0);
    r[0] = usable(r[0], 1e-3, 1), r[gap] = usable(r[gap], 1e-3, 1);
    m[0] = usable(m[0], 1e-5, 1), m[gap] = usable(m[gap], 1e-5, 1);
    double vn = -((v1[0] - v2[0]) * n[0] + (v1[1] - v2[1]) * n[1] + (v1[2] - v2[2]) * n[2]);
    if (!(vn > 0.0) || !isfinite(vn)) { /* receding (or too fast): approach speed 1 along n */
        for (int k = 0; k < 3; k++) v2[k] = 0.0, v1[k] = -n[k];
        vn = 1.0;
    }
    const double d = ((double)code + 1.0) / 128.0 * vn * dt;
    if (isnormal(d)) *overlap = d;
}

/* After a call that returned `s` with the model's history of `len` doubles at h (h0: as it was
 * before, DC_CONTACT_HISTORY_MAX doubles): the doubles past the model's length are never
 * written, and on DC_OK the model's doubles are finite (the others may be any fuzzed bits). */
static int history_ok(int32_t s, const dc_contact_model *m, const double *h, const double *h0) {
    size_t len = 0;
    if (dc_contact_history_len(m, &len) != DC_OK || len > DC_CONTACT_HISTORY_MAX) abort();
    if (memcmp(h + len, h0 + len, (DC_CONTACT_HISTORY_MAX - len) * sizeof(double)) != 0) return 0;
    return s != DC_OK || all_finite(h, len);
}

static void fuzz_case(unsigned which, uint8_t byte0, const uint8_t *data, size_t n) {
    (void)byte0;
    uint8_t d[sizeof(double) * 40];
    fuzz_take(d, sizeof d, data, n);
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
    case 0: { /* spec: fuzzed selectors and parameters */
        dc_contact_spec sp;
        if (dc_contact_spec_init(&sp) != DC_OK) abort();
        sp.normal = sel[0] % 9 - 1, sp.damping = sel[1] % 4 - 1, sp.criterion = sel[2] % 4 - 1;
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
            /* the reach at a fuzzed radius: finite and >= 0, or a status with nothing written */
            double reach = 12345.0;
            const int32_t sr = dc_contact_model_reach(&m, y[2], &reach);
            if (!known(sr)) abort();
            if (sr == DC_OK ? !(isfinite(reach) && reach >= 0.0) : reach != 12345.0) abort();
            if ((sr == DC_ERR_NOT_FINITE) != !isfinite(y[2])) abort();
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
    case 1: /* one contact, fuzzed state, dt, history */
    case 2: /* the spheres helper, fuzzed centres */
        if (!((d[8] & 1) ? step_model(&m, d[0] & 1) : full_model(&m, d[0] & 1))) abort();
        if ((d[7] & 1) && dc_contact_model_set_carry(&m, DC_CARRY_PROJECT) != DC_OK) abort();
        if (which == 1 && (d[8] & 1) && (d[9] & 1)) { /* a fresh contact at its onset, at a usable dt */
            y[30] = usable(y[30], 1e-7, 1);
            at_onset(st.n, st.v1, st.v2, st.w1, st.w2, &st.r1, &st.m1, 1, y[30], d[10], &st.overlap);
            memset(h, 0, sizeof h);
            memcpy(h0, h, sizeof h);
        }
        if (which == 1)
            s = dc_contact_force(&m, &st, y[30], (d[1] & 1) ? h : NULL, (size_t)(d[2] % 12), &r);
        else
            s = dc_contact_force_spheres(&m, y + 30, y + 33, &st, y[36], h, DC_CONTACT_HISTORY_MAX, &r);
        if (!known(s)) abort();
        if (s != DC_OK && (memcmp(&r, &r0, sizeof r) != 0 || memcmp(h, h0, sizeof h) != 0)) abort();
        if (s == DC_OK && !(all_finite(r.force, 3) && all_finite(r.torque1, 3) && all_finite(r.torque2, 3) &&
                            all_finite(&r.f_n, 1)))
            abort();
        if (!history_ok(s, &m, h, h0)) abort();
        break;
    case 3: { /* batch of 2 contacts: fuzzed arrays (aliasing the fuzzed doubles), NULL mask;
                * checked or fused (d[6] & 1) */
        if (!((d[8] & 1) ? step_model(&m, d[0] & 1) : full_model(&m, d[0] & 1))) abort();
        if ((d[7] & 1) && dc_contact_model_set_carry(&m, DC_CARRY_PROJECT) != DC_OK) abort();
        /* history: 2 contacts at a stride of up to 11 doubles */
        double out[2 + 6 + 6 + 6], out0[20], hb[22];
        for (int i = 0; i < 20; i++) out[i] = SENTINEL;
        for (int i = 0; i < 22; i++) hb[i] = y[i];
        if ((d[8] & 1) && (d[9] & 1)) { /* both contacts fresh, each at its onset (arrays below) */
            y[39] = usable(y[39], 1e-7, 1); /* dt, also the second contact's m2 */
            for (int c = 0; c < 2; c++)
                at_onset(y + 3 * c, y + 8 + 3 * c, y + 14 + 3 * c, y + 20 + 3 * c, y + 26 + 3 * c, y + 32 + c,
                         y + 36 + c, 2, y[39], d[10 + c], y + 6 + c);
            memset(hb, 0, sizeof hb);
        }
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
    case 5: { /* set_step: any dt and integrator; accepted (finite dt > 0, integrator 0 or 1:
               * the calibration kept, the scale dt/T_p) or refused with the model untouched */
        if (!step_model(&m, d[0] & 1)) abort();
        dc_contact_model ms = m;
        const double dt = y[30];
        const int32_t integ = sel[5] % 4 - 1;
        s = dc_contact_model_set_step(&ms, dt, integ);
        if (!known(s)) abort();
        if (s == DC_OK) {
            if (!(isfinite(dt) && dt > 0.0) || (integ != 0 && integ != 1) || ms.history_len != m.history_len ||
                !(ms.reserved[0] > 0.0) || memcmp(&ms.reserved[1], &m.reserved[1], 5 * sizeof(double)) != 0)
                abort();
        } else if (memcmp(&ms, &m, sizeof m) != 0) {
            abort();
        }
        break;
    }
    case 6: { /* the energy ledger: one contact as case 1 (plain or step-aware model) */
        if (!((d[8] & 1) ? step_model(&m, d[0] & 1) : full_model(&m, d[0] & 1))) abort();
        dc_contact_energy en, en0;
        memset(&en, 0x44, sizeof en);
        en0 = en;
        s = dc_contact_force_energy(&m, &st, y[30], (d[1] & 1) ? h : NULL, (size_t)(d[2] % 12), &r,
                                    (d[3] & 1) ? NULL : &en);
        if (!known(s)) abort();
        if ((d[3] & 1) && s != DC_ERR_NULL_POINTER) abort();
        if (s != DC_OK && (memcmp(&r, &r0, sizeof r) != 0 || memcmp(h, h0, sizeof h) != 0 ||
                           memcmp(&en, &en0, sizeof en) != 0))
            abort();
        if (s == DC_OK && !(all_finite(r.force, 3) && all_finite(&en.dissipated, sizeof en / sizeof(double))))
            abort();
        if (!history_ok(s, &m, h, h0)) abort();
        break;
    }
    case 4: /* arbitrary bytes as a model: rejected or computed, never a crash */
        fuzz_take(&m, sizeof m, d, sizeof d);
        s = dc_contact_force(&m, &st, 1e-7, h, DC_CONTACT_HISTORY_MAX, &r);
        if (!known(s)) abort();
        if (s != DC_OK && memcmp(&r, &r0, sizeof r) != 0) abort();
        break;
    }
}
