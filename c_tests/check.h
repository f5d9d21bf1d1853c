/* Tiny check harness shared by the C tests: counts checks and ends with the plain
 * "N passed, M failed" line that ctest logs and CI read. */
#ifndef DC_CHECK_H
#define DC_CHECK_H
#include <math.h>
#include <stdio.h>

static int dc_passed = 0, dc_failed = 0;

#define CHECK(cond, ...)                                                        \
    do {                                                                        \
        if (cond) {                                                             \
            dc_passed++;                                                        \
        } else {                                                                \
            dc_failed++;                                                        \
            fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond); \
            fprintf(stderr, __VA_ARGS__);                                       \
            fprintf(stderr, "\n");                                              \
        }                                                                       \
    } while (0)

#define CHECK_STATUS(call, want)                                                \
    do {                                                                        \
        int32_t got_ = (call);                                                  \
        CHECK(got_ == (want), "%s returned %d (%s), want %d", #call, (int)got_, \
              dc_status_str(got_), (int)(want));                                \
    } while (0)

static inline int dc_check_summary(const char *name) {
    printf("%s: %d passed, %d failed\n", name, dc_passed, dc_failed);
    return dc_failed == 0 ? 0 : 1;
}

static inline double dc_rel(double a, double b) { return fabs(a - b) / fabs(b); }
#endif
