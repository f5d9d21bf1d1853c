/* libFuzzer target: the step and scene planners, the slow set-up exports (milliseconds to a
 * second a valid call). Case 0: dc_dt_for_accuracy; 1: dc_dt_for_accuracy_step_aware (each on a
 * valid collision with a fuzzed subset of its arguments); 2:
 * dc_plan_input_init and dc_plan on a valid scene with a fuzzed subset of its members (and now
 * and then a fuzzed version or size, or a NULL output). Inputs are raw doubles (zero-padded),
 * their first bytes also read as selectors.
 *
 * The work a valid input may request is bounded as a host's would be, each bound applied where
 * the case builds its call: a tolerance on e of at least 1e-2 (dt_for_accuracy's search and the
 * planner's grow as the tolerance shrinks: ~200 ms at 1e-3, e ~ 0.1; hosts plan once at
 * set-up) and, for the step-aware search with DC_END_OVERLAP, e >= 1e-6, so that the fuzzer
 * spends its share on many inputs, the invalid ones included. */
#define FUZZ_CASES 3
#include "fuzz_common.h"

/* A tolerance on e no tighter than 1e-2 where it is a valid one (finite, > 0); any other value
 * as fuzzed, for the error paths. */
static double loose(double tol) { return isfinite(tol) && tol > 0.0 && tol < 1e-2 ? 1e-2 : tol; }

static void fuzz_case(unsigned which, uint8_t sel, const uint8_t *data, size_t n) {
    (void)sel;
    switch (which) {
    case 0:
    case 1: {
        double x[8];
        int32_t c;
        fuzz_scalars(data, n, x, &c);
        /* a valid collision (Hertz, e 0.5, 1 m/s), each argument replaced by its fuzzed value
         * when its selector bit is set: raw doubles alone are almost never a valid call */
        const uint8_t pick = n > 68 ? data[68] : 0; /* the byte after fuzz_scalars' 68 */
        const double base[6] = {1.5, 0.5, 1.0, 1e3, 0.0, 0.05}; /* p e v0 omega0 - tol */
        for (int i = 0; i < 6; i++)
            if (!(pick & (1u << i))) x[i] = base[i];
        if (!(pick & 64)) c = (pick & 128) ? DC_END_FORCE : DC_END_OVERLAP;
        double out = SENTINEL;
        const double tol = loose(x[5]);
        if (which == 0) {
            verdict(dc_dt_for_accuracy(x[0], x[1], c, x[2], x[3], tol, &out), out);
        } else {
            /* the step-aware search at e -> 0 with DC_END_OVERLAP takes seconds below 1e-9 (its
             * doc; scripts/extreme_restitution.sh): e no smaller than 1e-6 there */
            const double e = c == DC_END_OVERLAP && isfinite(x[1]) && x[1] > 0.0 && x[1] < 1e-6 ? 1e-6 : x[1];
            verdict(dc_dt_for_accuracy_step_aware(x[0], e, c, x[2], x[3], tol, &out), out);
        }
        if (out != SENTINEL && !(out > 0.0)) abort(); /* a step is positive */
        break;
    }
    case 2: {
        uint8_t d[8 * 24];
        fuzz_take(d, sizeof d, data, n);
        double y[24];
        memcpy(y, d, sizeof y);
        dc_plan_input in;
        memset(&in, 0x5a, sizeof in);
        if (dc_plan_input_init(&in) != DC_OK) abort();
        if (dc_plan_input_init(NULL) != DC_ERR_NULL_POINTER) abort();
        /* a valid scene: glass beads of 1-4 mm at up to 2 m/s in a 0.5 m bed */
        in.youngs = 7e10, in.poisson = 0.22, in.density = 2500.0, in.restitution = 0.3;
        in.radius_min = 1e-3, in.radius_max = 4e-3, in.v_max = 2.0, in.depth = 0.5;
        in.overlap_tol = 0.01, in.e_tol = 0.01, in.duration_tol = 3.0;
        /* the 19 doubles youngs .. duration_tol, then the criterion, the walls, and the two
         * doubles after them: each replaced by its fuzzed value when its selector bit is set */
        const uint32_t pick = (uint32_t)d[0] | (uint32_t)d[1] << 8 | (uint32_t)d[2] << 16;
        double *f = &in.youngs;
        for (int i = 0; i < 19; i++)
            if (pick & (1u << i)) f[i] = y[1 + i];
        if (pick & (1u << 19)) in.criterion = (int32_t)d[3] % 4 - 1;
        if (pick & (1u << 20)) in.walls = (int32_t)d[4] % 4 - 1;
        if (pick & (1u << 21)) in.stability_fraction = y[20];
        if (pick & (1u << 22)) in.conventional_divisor = y[21];
        if (d[5] == 1) in.version ^= 1u;
        if (d[5] == 2) in.size = (uint32_t)d[6];
        in.e_tol = loose(in.e_tol);
        dc_plan_result out, out0;
        memset(&out, 0x33, sizeof out);
        out0 = out;
        int32_t field = -77;
        const int null_out = d[7] == 1;
        const int32_t s = dc_plan(&in, null_out ? NULL : &out, (d[8] & 1) ? NULL : &field);
        if (!known(s)) abort();
        if (null_out && s != DC_ERR_NULL_POINTER) abort();
        if (s != DC_OK) {
            if (memcmp(&out, &out0, sizeof out) != 0) abort(); /* untouched on error */
            if (!(d[8] & 1) && field == -77) abort(); /* an error names its field (NONE: none) */
        } else {
            if (field != -77) abort(); /* untouched on DC_OK */
            /* every figure a number (dt_stability may be +inf: no static load) and a
             * positive step */
            const double *o = &out.youngs_soft;
            if (isnan(o[0]) || isnan(o[1]) || !(out.dt > 0.0) || !isfinite(out.dt)) abort();
            if (isnan(out.dt_restitution) || isnan(out.dt_stability) || isnan(out.speedup) ||
                isnan(out.max_overlap_ratio) || isnan(out.duration) || isnan(out.e_plain_at_dt))
                abort();
        }
        break;
    }
    }
}
