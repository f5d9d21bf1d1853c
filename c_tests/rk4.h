/* Reference collision shared by the C tests: classical RK4 on the power-law contact's equation of
 * motion, written here in C independently of the library,
 *     d'' = -alpha w0 |d|^((p-1)/2) d' - w0^2 |d|^p sign(d),   d(0) = 0, d'(0) = v0
 * (m = 1, k = w0^2), with the fixed step h = 2e-5/w0 (accuracy ~1e-7 relative on delta_max and
 * tau). The end event (delta = 0, or total force = 0 for force_end) is located by linear
 * interpolation between the two steps that bracket it; the turning point by a quadratic fit. */
#ifndef DC_RK4_H
#define DC_RK4_H
#include <math.h>

typedef struct {
    double dmax;     /* maximum overlap */
    double tmax;     /* time of the maximum overlap (NaN if never reached) */
    double tau;      /* contact duration (NaN if the end event was not reached) */
    double v_exit;   /* exit speed -d' at the end event, > 0 for a rebound (NaN if not reached) */
} dc_rk4_collision;

static inline double dc_rk4_acc(double p, double alpha, double w0, double d, double v) {
    return -alpha * w0 * pow(fabs(d), 0.5 * (p - 1.0)) * v - w0 * w0 * copysign(pow(fabs(d), p), d);
}

static inline double dc_rk4_force(double p, double alpha, double w0, double d, double v) {
    return w0 * w0 * copysign(pow(fabs(d), p), d) + alpha * w0 * pow(fabs(d), 0.5 * (p - 1.0)) * v;
}

static dc_rk4_collision dc_rk4_collide(double p, double alpha, double v0, double w0, int force_end) {
    dc_rk4_collision r = {0.0, NAN, NAN, NAN};
    double d = 0.0, v = v0, t = 0.0, h = 2e-5 / w0;
    for (long i = 0; i < 200000000L; i++) {
        double k1d = v, k1v = dc_rk4_acc(p, alpha, w0, d, v);
        double k2d = v + 0.5 * h * k1v, k2v = dc_rk4_acc(p, alpha, w0, d + 0.5 * h * k1d, v + 0.5 * h * k1v);
        double k3d = v + 0.5 * h * k2v, k3v = dc_rk4_acc(p, alpha, w0, d + 0.5 * h * k2d, v + 0.5 * h * k2v);
        double k4d = v + h * k3v, k4v = dc_rk4_acc(p, alpha, w0, d + h * k3d, v + h * k3v);
        double nd = d + h / 6.0 * (k1d + 2 * k2d + 2 * k3d + k4d);
        double nv = v + h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
        if (v > 0.0 && nv <= 0.0) { /* turning point: quadratic peak from the two samples */
            double s = v / (v - nv);
            r.tmax = t + s * h;
            r.dmax = nd > d ? nd : d;
            double a = 0.5 * (v - nv) / h; /* d(t) ~ d + v tau - a tau^2 */
            double peak = d + v * v / (4.0 * a);
            if (peak > r.dmax) r.dmax = peak;
        }
        if (v < 0.0) { /* unloading: look for the end event */
            double g0 = force_end ? dc_rk4_force(p, alpha, w0, d, v) : d;
            double g1 = force_end ? dc_rk4_force(p, alpha, w0, nd, nv) : nd;
            if (g1 <= 0.0) {
                double s = g0 / (g0 - g1);
                r.tau = t + h * g0 / (g0 - g1);
                r.v_exit = -(v + s * (nv - v));
                return r;
            }
        }
        d = nd;
        v = nv;
        t += h;
    }
    return r;
}
#endif
