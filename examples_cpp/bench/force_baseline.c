/* Hand-written C loops of the same force expressions as demcontact's kernels: what a host code
 * writes today. Compiled five times by CMake: plain -O3 (BASE = plain: sqrt keeps its errno
 * path, so gcc does not vectorise it), -O3 -fno-math-errno (BASE = fast: sqrtpd, vectorised),
 * -O3 -march=native -fno-math-errno (BASE = native: the host CPU's widest vectors), the same
 * with -ffp-contract=off (BASE = native_nofma: no FMA, the rounding of demcontact's exact batch)
 * and -O3 -march=x86-64-v3 -fno-math-errno (BASE = v3: an AVX2 machine's -march=native).
 * The same loops with the per-contact call replaced by dc_normal_force_inline from
 * demcontact_inline.h (inline_*): "the inline kernel in the host's own loop", same flags.
 * copy_loop / sum_loop: the memory roofline of the streaming runs (STREAM copy; the same four
 * input and one output streams as the Hertz batch).
 *
 * Hertz, clamped (DC_END_FORCE), k = kf sqrt(r) per contact, q = sqrt(r d):
 *   F = kf q d + c sqrt(m q) vn,  c = alpha sqrt(kf)
 * General p, clamped, fixed k, s = d^h, h = (p-1)/2:
 *   F = k d s^2 + c sqrt(m) s vn,  c = alpha sqrt(k)                                          */
#include <demcontact_inline.h>
#include <math.h>
#include <stddef.h>

#define CAT2(a, b) a##_##b
#define CAT(a, b) CAT2(a, b)

void CAT(hertz_loop, BASE)(size_t n, double kf, double c, const double *restrict d,
                           const double *restrict vn, const double *restrict r,
                           const double *restrict m, double *restrict out) {
    for (size_t i = 0; i < n; i++) {
        double q = sqrt(r[i] * d[i]);
        double f = kf * q * d[i] + c * sqrt(m[i] * q) * vn[i];
        f = f > 0.0 ? f : 0.0;
        out[i] = d[i] > 0.0 ? f : 0.0;
    }
}

void CAT(pow_loop, BASE)(size_t n, double k, double c, double h, const double *restrict d,
                         const double *restrict vn, const double *restrict m,
                         double *restrict out) {
    for (size_t i = 0; i < n; i++) {
        double s = pow(d[i], h);
        double f = k * d[i] * s * s + c * sqrt(m[i]) * s * vn[i];
        f = f > 0.0 ? f : 0.0;
        out[i] = d[i] > 0.0 ? f : 0.0;
    }
}

void CAT(hertz_inline_loop, BASE)(size_t n, const dc_pair *pair, const double *restrict d,
                                  const double *restrict vn, const double *restrict r,
                                  const double *restrict m, double *restrict out) {
    for (size_t i = 0; i < n; i++) out[i] = dc_normal_force_inline(pair, d[i], vn[i], r[i], m[i]);
}

/* The kernel code as a constant: the switch folds away, the loop is the hand-written one. */
void CAT(hertz_kernel_loop, BASE)(size_t n, const dc_pair *pair, const double *restrict d,
                                  const double *restrict vn, const double *restrict r,
                                  const double *restrict m, double *restrict out) {
    for (size_t i = 0; i < n; i++)
        out[i] = dc_normal_force_kernel_inline(DC_KERNEL_HERTZ_DAMPED_CLAMPED, pair, d[i], vn[i],
                                               r[i], m[i]);
}

void CAT(pow_kernel_loop, BASE)(size_t n, const dc_pair *pair, const double *restrict d,
                                const double *restrict vn, const double *restrict m,
                                double *restrict out) {
    for (size_t i = 0; i < n; i++)
        out[i] = dc_normal_force_kernel_inline(DC_KERNEL_GEN_DAMPED_CLAMPED, pair, d[i], vn[i], 0.0,
                                               m[i]);
}

void CAT(pow_inline_loop, BASE)(size_t n, const dc_pair *pair, const double *restrict d,
                                const double *restrict vn, const double *restrict m,
                                double *restrict out) {
    for (size_t i = 0; i < n; i++) out[i] = dc_normal_force_inline(pair, d[i], vn[i], 0.0, m[i]);
}

void CAT(copy_loop, BASE)(size_t n, const double *restrict a, double *restrict b) {
    for (size_t i = 0; i < n; i++) b[i] = a[i];
}

void CAT(sum_loop, BASE)(size_t n, const double *restrict a, const double *restrict b,
                         const double *restrict c, const double *restrict e,
                         double *restrict out) {
    for (size_t i = 0; i < n; i++) out[i] = (a[i] + b[i]) + (c[i] + e[i]);
}
