/* The inline tests' random inputs: a xorshift64 stream (the same numbers on every compiler and
 * platform, so a failing case can be replayed) and the draws built on it. Each test defines
 * TEST_RANDOM_SEED before including this (its own stream). C99 and C++. */
#ifndef DEMCONTACT_TEST_RANDOM_H
#define DEMCONTACT_TEST_RANDOM_H

#include <math.h>
#include <stdint.h>

static uint64_t rng_state = TEST_RANDOM_SEED;
/* uniform in [0, 1) */
static inline double uni(void) {
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (double)(rng_state >> 11) / 9007199254740992.0;
}
/* uniform integer in 0 .. n-1 */
static inline int pick(int n) { return (int)(uni() * n) % n; }
/* log-uniform between 10^lo and 10^hi */
static inline double logu(double lo, double hi) {
    return exp(2.302585092994046 * (lo + (hi - lo) * uni()));
}
/* n scaled to unit length */
static inline void unit(double n[3]) {
    const double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int i = 0; i < 3; i++) n[i] /= l;
}
/* components uniform in (-mag, mag) */
static inline void vec(double v[3], double mag) {
    for (int i = 0; i < 3; i++) v[i] = mag * (2.0 * uni() - 1.0);
}

#endif
