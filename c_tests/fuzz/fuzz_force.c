/* libFuzzer target: the normal-force exports. Cases 0-4: a pair from each constructor (power law,
 * Hertz, viscoelastic, linear, power law from alpha) with fuzzed inputs, then the checked and the
 * unchecked force; 5: arbitrary bytes as a pair; 6: the batch of 4 contacts, exact and fast;
 * 7: the 3D helper with fuzzed geometry. Inputs are eight raw doubles and a criterion. */
#define FUZZ_CASES 8
#include "fuzz_common.h"

/* The fast batch builds power tables per exponent (about 45 us each) and a thread keeps its last
 * 8: a host uses a handful of exponents, so the fast batch takes its p from these 8 (the exact
 * Hertz and p = 2 paths, general p, and p > 9, which falls back to the exact batch). A fuzzed
 * continuous p would rebuild the tables on every input and starve every other case. */
static const double fast_p[8] = {1.0, 1.25, 1.5, 1.7, 2.0, 2.5, 3.0, 9.5};

static void fuzz_case(unsigned which, uint8_t sel, const uint8_t *data, size_t n) {
    double x[8];
    int32_t c;
    fuzz_scalars(data, n, x, &c);
    double out = SENTINEL;
    dc_pair pair;
    double v3[3] = {SENTINEL, SENTINEL, SENTINEL};
    switch (which) {
    case 0: /* a pair from a constructor with fuzzed inputs, then a checked force */
    case 1:
    case 2:
    case 3:
    case 4: {
        int32_t s;
        if (which == 0) s = dc_pair_powerlaw(x[0], x[1], x[2], c, &pair);
        else if (which == 1) s = dc_pair_hertz(x[0], x[1], x[0], x[1], x[2], c, &pair);
        else if (which == 2) s = dc_pair_viscoelastic(x[0], x[1], x[0], x[1], x[2], c, &pair);
        else if (which == 3) s = dc_pair_linear(x[1], x[2], c, &pair);
        else s = dc_pair_powerlaw_alpha(x[0], x[1], x[2], c, &pair);
        if (!known(s)) abort();
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
    case 5: /* arbitrary bytes as a pair: the checked paths must reject or compute, never crash */
        fuzz_take(&pair, sizeof pair, data, n);
        verdict(dc_normal_force_checked(&pair, x[0], x[1], x[2], x[3], &out), out);
        (void)dc_normal_force(&pair, x[0], x[1], x[2], x[3]);
        break;
    case 6: { /* batch of 4 contacts from fuzzed doubles; exact or fast (high bit of the selector) */
        const int fast = sel & 0x80u;
        const double p = fast ? fast_p[(sel >> 4) & 7u] : 1.0 + fabs(fmod(x[0], 4.0));
        if (dc_pair_powerlaw(p, 1e3, 0.5, c & 1, &pair) != DC_OK) break;
        double f4[4] = {SENTINEL, SENTINEL, SENTINEL, SENTINEL};
        int32_t s = fast ? dc_normal_force_batch_fast(&pair, 4, x, x + 4, x, x + 4, f4)
                         : dc_normal_force_batch(&pair, 4, x, x + 4, x, x + 4, f4);
        if (!known(s)) abort();
        if (s != DC_OK && f4[0] != SENTINEL) abort();
        if (fast) {
            const int32_t level = dc_dispatch_level(); /* one of the DC_DISPATCH_* codes */
            if (level != DC_DISPATCH_BASELINE && level != DC_DISPATCH_AVX2 && level != DC_DISPATCH_AVX512) abort();
        }
        break;
    }
    case 7: /* 3D helper with fuzzed geometry */
        if (dc_pair_hertz(1e9, 0.3, 1e9, 0.3, 0.5, c & 1, &pair) != DC_OK) break;
        verdict(dc_normal_force_3d(&pair, x, x + 3, x[6], x[7], x + 1, x + 4, x[7], x[6], v3), v3[0]);
        break;
    }
}
