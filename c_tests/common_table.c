/* The common table that the C, C++ and Fortran programs must compute bit for bit alike
 * (compared by the ctest case `cross_language_table`): for p in {1, 1.5, 2, 3}, e in
 * {0.1, 0.3, 0.5, 0.7, 0.9} and both criteria, the bits of alpha(e) and of e(alpha(e)); then the
 * Hertz stiffness of two glass beads and dt_crit. Also the status of one bad input. */
#include <demcontact.h>
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

static int64_t bits(double x) {
    int64_t b;
    memcpy(&b, &x, sizeof b);
    return b;
}

int main(void) {
    const double ps[] = {1.0, 1.5, 2.0, 3.0};
    const double es[] = {0.1, 0.3, 0.5, 0.7, 0.9};
    for (int c = 0; c < 2; c++)
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 5; j++) {
                double a = 0, e = 0;
                int32_t s1 = dc_alpha_from_e(es[j], ps[i], c, &a);
                int32_t s2 = dc_e_from_alpha(a, ps[i], c, &e);
                printf("%d %d %d %" PRId64 " %" PRId64 "\n", c, (int)s1, (int)s2, bits(a), bits(e));
            }
    double k = 0, dt = 0, out = 0;
    /* Call before printing: argument evaluation order is unspecified. */
    int32_t sk = dc_hertz_stiffness(63e9, 0.23, 1e-3, 70e9, 0.3, 2e-3, &k);
    int32_t sd = dc_dt_crit(1.5, 2.0, 1e4, &dt);
    printf("%d %" PRId64 "\n", (int)sk, bits(k));
    printf("%d %" PRId64 "\n", (int)sd, bits(dt));
    printf("%d\n", (int)dc_alpha_from_e(1.5, 1.5, DC_END_FORCE, &out));
    return 0;
}
