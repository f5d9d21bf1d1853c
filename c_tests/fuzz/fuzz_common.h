/* Shared part of the libFuzzer targets in this folder (one target per export family, built and
 * run by scripts/fuzz.sh). A target defines
 *     #define FUZZ_CASES <number of cases>
 *     static void fuzz_case(unsigned which, uint8_t sel, const uint8_t *data, size_t n);
 * before including this header; the header supplies LLVMFuzzerTestOneInput, which picks the case
 * from the first input byte (which = byte % FUZZ_CASES, sel = the whole byte, whose high bits a
 * case may use as a selector) and hands the rest of the input to it.
 *
 * Every call must return a known status (never DC_ERR_INTERNAL, the caught panic), leave its
 * output untouched on error and produce a finite output on success; any violation aborts, which
 * libFuzzer reports as a crash.
 *
 * DC_FUZZ_NAME (set by scripts/fuzz.sh to the target's name): with DC_FUZZ_PLANT_CRASH=<that
 * name> in the environment the target aborts on its first input, so scripts/fuzz_selftest.sh can
 * prove that a crash in any one target fails scripts/fuzz.sh.
 * DC_FUZZ_PROFILE=1 prints, at exit, the calls and the mean time per call of every case: how the
 * slow cases were found, and how to check that a change keeps every case cheap. */
#ifndef DC_FUZZ_COMMON_H
#define DC_FUZZ_COMMON_H

#include <demcontact.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef DC_FUZZ_NAME
#error "DC_FUZZ_NAME (the target's name) must be defined: scripts/fuzz.sh passes -DDC_FUZZ_NAME"
#endif

/* An output that no export writes: "untouched on error" is a bitwise compare with it. */
#define SENTINEL (-7.25e101)

/* A documented status, and not the caught panic. The library's own status table decides what
 * is documented: no hard-coded range here. */
static inline int known(int32_t s) { return dc_status_known(s) && s != DC_ERR_INTERNAL; }

static inline int all_finite(const double *v, size_t n) {
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

/* The contract of a scalar export: a known status; finite output on success; the sentinel
 * untouched on error. */
static inline void verdict(int32_t s, double out) {
    if (!known(s)) abort();
    if (s == DC_OK && !isfinite(out)) abort();
    if (s != DC_OK && memcmp(&out, &(double){SENTINEL}, sizeof out) != 0) abort();
}

/* Copies the input into a fixed-size buffer, zero-padded: a case reads fixed offsets and a short
 * input reads zeros, never past its end. */
static inline void fuzz_take(void *dst, size_t cap, const uint8_t *data, size_t n) {
    memset(dst, 0, cap);
    memcpy(dst, data, n < cap ? n : cap);
}

/* An end criterion from any integer: -1, 0, 1, 2 (the two valid codes and two invalid ones). */
static inline int32_t fuzz_criterion(int32_t raw) { return (raw % 4 + 4) % 4 - 1; }

/* The scalar decoding of most cases: eight doubles from the raw bit patterns (so NaN, inf,
 * subnormals and huge values all occur) and an end criterion from the next four bytes. */
static inline void fuzz_scalars(const uint8_t *data, size_t n, double x[8], int32_t *criterion) {
    uint8_t buf[8 * sizeof(double) + sizeof(int32_t)];
    fuzz_take(buf, sizeof buf, data, n);
    memcpy(x, buf, 8 * sizeof(double));
    memcpy(criterion, buf + 8 * sizeof(double), sizeof *criterion);
    *criterion = fuzz_criterion(*criterion);
}

static void fuzz_case(unsigned which, uint8_t sel, const uint8_t *data, size_t n);

static double fuzz_seconds[FUZZ_CASES];
static unsigned long fuzz_calls[FUZZ_CASES];

static void fuzz_profile_report(void) {
    double total = 0.0;
    for (unsigned i = 0; i < FUZZ_CASES; i++) total += fuzz_seconds[i];
    for (unsigned i = 0; i < FUZZ_CASES; i++)
        fprintf(stderr, "%s case %2u: %9lu calls %9.2f us/call %5.1f %% of the time\n", DC_FUZZ_NAME, i,
                fuzz_calls[i], fuzz_calls[i] ? 1e6 * fuzz_seconds[i] / (double)fuzz_calls[i] : 0.0,
                total > 0.0 ? 100.0 * fuzz_seconds[i] / total : 0.0);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    static int planted = -1, profile = 0;
    if (planted < 0) {
        const char *p = getenv("DC_FUZZ_PLANT_CRASH");
        planted = p != NULL && strcmp(p, DC_FUZZ_NAME) == 0;
        profile = getenv("DC_FUZZ_PROFILE") != NULL;
        if (profile) atexit(fuzz_profile_report);
    }
    if (planted) abort(); /* the self-test's planted crash */
    if (size < 1) return 0;
    const unsigned which = data[0] % FUZZ_CASES;
    if (!profile) {
        fuzz_case(which, data[0], data + 1, size - 1);
        return 0;
    }
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    fuzz_case(which, data[0], data + 1, size - 1);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    fuzz_seconds[which] += (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    fuzz_calls[which]++;
    return 0;
}

#endif
