/* libFuzzer target: the power-law calculus. Cases 0-4: maximum overlap and its time, the contact
 * duration (default and every level), the energy partition; 5: the trajectory with fuzzed n,
 * buf_len and NULL buffers; 6-8: the linearised and static time steps and omega0; 9: a duration
 * plan at every level and a duration from it. Inputs are eight raw
 * doubles and a criterion (fuzz_scalars); the quadrature level comes from the selector byte's
 * high bits (-1 .. 5: every level and one invalid code on each side). */
#define FUZZ_CASES 10
#include "fuzz_common.h"

/* The trajectory writes n samples into each of four buffers: at most 7 of 8 here (a host samples
 * a few hundred points at most, and the sampling code is the same for every n). */
#define TRAJ_BUF 8

static void fuzz_case(unsigned which, uint8_t sel, const uint8_t *data, size_t n) {
    double x[8];
    int32_t c;
    fuzz_scalars(data, n, x, &c);
    const int32_t level = (int32_t)(sel / FUZZ_CASES) % 7 - 1;
    double out = SENTINEL;
    switch (which) {
    case 0: verdict(dc_max_overlap(x[0], x[1], x[2], x[3], &out), out); break;
    case 1: verdict(dc_time_of_max_overlap(x[0], x[1], x[2], x[3], &out), out); break;
    case 2: verdict(dc_contact_duration(x[0], x[1], x[2], x[3], c, &out), out); break;
    case 3: verdict(dc_contact_duration_level(x[0], x[1], x[2], x[3], c, level, &out), out); break;
    case 4: {
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
    case 5: { /* trajectory: n, buf_len and the NULL mask come from the input's last byte */
        double bufs[4][TRAJ_BUF];
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < TRAJ_BUF; j++) bufs[i][j] = SENTINEL;
        uint8_t ctl = n > 0 ? data[n - 1] : 0;
        size_t np = ctl & 7u, len = (ctl >> 3) & 7u;
        if (ctl & 0x40u) np = (size_t)-1; /* a huge n must be refused before any sample */
        double *pt[4];
        for (int i = 0; i < 4; i++) pt[i] = (ctl & 0x80u) && i == (ctl & 3u) ? NULL : bufs[i];
        int32_t s = dc_contact_trajectory(x[0], x[1], x[2], x[3], x[4], c, level, np, pt[0], pt[1], pt[2], pt[3], len);
        if (!known(s)) abort();
        for (int i = 0; i < 4; i++)
            for (size_t j = 0; j < TRAJ_BUF; j++) {
                int written = memcmp(&bufs[i][j], &(double){SENTINEL}, sizeof(double)) != 0;
                if (s == DC_OK && j < np && !isfinite(bufs[i][j])) abort();
                /* The one documented exception to "untouched on error": DC_ERR_RESULT_RANGE found
                 * after sampling sets the first n samples of every buffer to NaN. */
                if (s == DC_ERR_RESULT_RANGE && j < np && written && !isnan(bufs[i][j])) abort();
                if (s != DC_OK && s != DC_ERR_RESULT_RANGE && written) abort();
                if (j >= np && written) abort();
            }
        break;
    }
    case 6: verdict(dc_dt_linearised(x[0], x[1], x[2], &out), out); break;
    case 7: verdict(dc_dt_static(x[0], x[1], x[2], x[3], &out), out); break;
    case 8: verdict(dc_omega0(x[0], x[1], &out), out); break;
    case 9: { /* a plan for p at a level, then a duration from it: the plan untouched on error */
        dc_duration_plan plan, plan0;
        memset(&plan, 0x5a, sizeof plan);
        plan0 = plan;
        int32_t s = dc_duration_plan_init(x[0], level, &plan);
        if (!known(s)) abort();
        if (s != DC_OK && memcmp(&plan, &plan0, sizeof plan) != 0) abort();
        /* with a refused plan the duration must refuse it too (DC_ERR_PLAN), never compute */
        s = dc_contact_duration_planned(&plan, x[1], x[2], x[3], c, &out);
        verdict(s, out);
        if (memcmp(&plan, &plan0, sizeof plan) == 0 && s != DC_ERR_PLAN) abort();
        break;
    }
    }
}
