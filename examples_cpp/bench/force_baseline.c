/* Hand-written C loops of the same force expressions as demcontact's kernels: what a host code
 * writes today. Compiled twice by CMake: plain -O3 (BASE = plain: sqrt keeps its errno path, so
 * gcc does not vectorise it) and -O3 -fno-math-errno (BASE = fast: sqrtpd, vectorised).
 *
 * Hertz, clamped (DC_END_FORCE), k = kf sqrt(r) per contact, q = sqrt(r d):
 *   F = kf q d + c sqrt(m q) vn,  c = alpha sqrt(kf)
 * General p, clamped, fixed k, s = d^h, h = (p-1)/2:
 *   F = k d s^2 + c sqrt(m) s vn,  c = alpha sqrt(k)                                          */
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
