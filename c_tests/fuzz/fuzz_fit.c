/* libFuzzer target: the fit. Case 0: the fit (fuzzed n <= 8, arrays, NULL sigma and residual
 * buffers, robust, criterion, tol; residuals and result untouched on error, finite on success)
 * and its 95 % quantile; 1: the quantile for any n and flag. Inputs are 8 selector bytes and 24
 * raw doubles.
 * A target of its own: a fit costs 0.03 to 5 ms under the instrumentation (Gauss-Newton with a
 * step-halving line search, Huber reweighting up to 50 rounds), 100 to 1000 times the other
 * exports, so it would starve any case that shared a target with it. Its bound is the number of
 * points, n <= 8 (a host fits a few dozen measured speeds at most; the code is the same for every
 * n), and the per-target time share of scripts/fuzz.sh. */
#define FUZZ_CASES 2
#include "fuzz_common.h"

static void fuzz_case(unsigned which, uint8_t sel, const uint8_t *data, size_t n) {
    (void)sel;
    uint8_t d[8 + sizeof(double) * 24]; /* 8 selector bytes, then 24 doubles */
    fuzz_take(d, sizeof d, data, n);
    double y[24];
    memcpy(y, d + 8, sizeof y);
    double out = SENTINEL;
    int32_t s;
    switch (which) {
    case 0: { /* the fit: n, NULL sigma, robust, criterion, residual buffers from the input */
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
    case 1: { /* the quantile: any n (from 8 bytes), any flag */
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
