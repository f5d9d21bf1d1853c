/* dc_dt_for_accuracy through the C ABI, checked by a velocity-Verlet simulation written here
 * (LAMMPS/LIGGGHTS order, force from the power-law formula, attractive force clamped for
 * DC_END_FORCE): at the returned step every one of 41 start phases realises e within tol, at
 * twice the step at least one does not. Plus the bad-input statuses. */
#include "check.h"
#include <demcontact.h>
#include <stdint.h>

static const double V0 = 1.3, W0 = 7.0;

static double realised_e(double p, double alpha, int clamp, double dt, double phase) {
    double d = -phase * V0 * dt, v = V0, a = 0.0;
    int touched = 0;
    for (long i = 0; i < 50000000L; i++) {
        d += v * dt + 0.5 * a * dt * dt;
        double vh = v + 0.5 * a * dt;
        a = 0.0;
        if (d > 0.0) {
            double f = W0 * W0 * pow(d, p) + alpha * W0 * pow(d, 0.5 * (p - 1.0)) * vh;
            if (clamp && f < 0.0) f = 0.0;
            a = -f;
        }
        v = vh + 0.5 * a * dt;
        if (d > 0.0) touched = 1;
        else if (touched) return -v / V0;
    }
    return NAN;
}

static double worst(double p, double e, int32_t crit, double dt) {
    double alpha = 0.0, w = 0.0;
    CHECK_STATUS(dc_alpha_from_e(e, p, crit, &alpha), DC_OK);
    for (int i = 0; i < 41; i++) {
        double er = realised_e(p, alpha, crit == DC_END_FORCE, dt, (i + 0.7) / 41.0);
        double r = fabs(er - e) / e;
        if (!(r <= w)) w = isnan(r) ? INFINITY : r;
    }
    return w;
}

int main(void) {
    const double ps[] = {1.0, 1.5, 3.0}, es[] = {0.1, 0.5, 0.9};
    for (int c = 0; c < 2; c++) {
        int32_t crit = c ? DC_END_FORCE : DC_END_OVERLAP;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double dt = NAN, tol = 1e-2;
                CHECK_STATUS(dc_dt_for_accuracy(ps[i], es[j], crit, V0, W0, tol, &dt), DC_OK);
                double at = worst(ps[i], es[j], crit, dt), twice = worst(ps[i], es[j], crit, 2.0 * dt);
                CHECK(at <= tol, "crit %d p %g e %g: E(dt) = %g > tol", crit, ps[i], es[j], at);
                CHECK(twice > tol, "crit %d p %g e %g: E(2dt) = %g <= tol", crit, ps[i], es[j], twice);
            }
    }
    double out = 42.0;
    CHECK_STATUS(dc_dt_for_accuracy(1.5, 0.5, DC_END_FORCE, 1.0, 1.0, 1e-2, NULL), DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_dt_for_accuracy(NAN, 0.5, DC_END_FORCE, 1.0, 1.0, 1e-2, &out), DC_ERR_NOT_FINITE);
    CHECK_STATUS(dc_dt_for_accuracy(0.9, 0.5, DC_END_FORCE, 1.0, 1.0, 1e-2, &out), DC_ERR_EXPONENT_RANGE);
    CHECK_STATUS(dc_dt_for_accuracy(1.5, 1.5, DC_END_FORCE, 1.0, 1.0, 1e-2, &out), DC_ERR_RESTITUTION_RANGE);
    CHECK_STATUS(dc_dt_for_accuracy(1.5, 0.5, 3, 1.0, 1.0, 1e-2, &out), DC_ERR_CRITERION);
    CHECK_STATUS(dc_dt_for_accuracy(1.5, 0.5, DC_END_FORCE, 1.0, 1.0, -1e-2, &out), DC_ERR_NOT_POSITIVE);
    CHECK(out == 42.0, "output touched on error: %g", out);
    return dc_check_summary("test_step_accuracy");
}
