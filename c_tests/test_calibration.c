/* Calls every foundation export through the C ABI: valid values against independent C
 * computations (closed forms evaluated here, and a fine RK4 integration of the equation of
 * motion for the force-zero criterion), and every class of bad input. */
#include "check.h"
#include "rk4.h"
#include <demcontact.h>
#include <stdint.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

/* Realised restitution of the reference collision (rk4.h) with m = k = 1 and v0 = 1. */
static double rk4_restitution(double p, double alpha, int force_end) {
    return dc_rk4_collide(p, alpha, 1.0, 1.0, force_end).v_exit;
}

int main(void) {
    const double ps[] = {1.0, 1.5, 2.0, 3.0};
    const double es[] = {0.1, 0.3, 0.5, 0.7, 0.9};
    double a = 0, e = 0;

    /* Overlap criterion: the closed form, computed here independently. */
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 5; j++) {
            double p = ps[i], L = -log(es[j]);
            double want = sqrt(2.0 * (p + 1.0)) * L / sqrt(PI * PI + L * L);
            CHECK_STATUS(dc_alpha_from_e(es[j], p, DC_END_OVERLAP, &a), DC_OK);
            CHECK(dc_rel(a, want) < 1e-14, "p=%g e=%g: %.17g vs %.17g", p, es[j], a, want);
            CHECK_STATUS(dc_e_from_alpha(a, p, DC_END_OVERLAP, &e), DC_OK);
            CHECK(dc_rel(e, es[j]) < 1e-14, "round trip %g -> %.17g", es[j], e);
        }

    /* Force criterion: realised e by direct RK4 integration (accuracy ~1e-6 with this step). */
    for (int i = 0; i < 4; i++) {
        double p = ps[i];
        for (int j = 0; j < 5; j += 2) {
            CHECK_STATUS(dc_alpha_from_e(es[j], p, DC_END_FORCE, &a), DC_OK);
            double got = rk4_restitution(p, a, 1);
            CHECK(dc_rel(got, es[j]) < 2e-5, "force end p=%g e=%g: RK4 realises %.9f", p, es[j], got);
            /* and the overlap-calibrated alpha overshoots in a clamping solver */
            CHECK_STATUS(dc_alpha_from_e(es[j], p, DC_END_OVERLAP, &a), DC_OK);
            double clamped = rk4_restitution(p, a, 1);
            CHECK(clamped > es[j] + 1e-3, "overlap alpha in clamping solver should overshoot: %g", clamped);
            double unclamped = rk4_restitution(p, a, 0);
            CHECK(dc_rel(unclamped, es[j]) < 2e-5, "overlap end p=%g e=%g: %.9f", p, es[j], unclamped);
        }
    }

    /* Critical damping: force-end restitution exp(-2) at zeta = 1, no rebound for overlap end. */
    CHECK_STATUS(dc_e_from_alpha(sqrt(5.0), 1.5, DC_END_FORCE, &e), DC_OK);
    CHECK(dc_rel(e, exp(-2.0)) < 1e-15, "e_F(zeta=1) = %.17g", e);
    CHECK_STATUS(dc_e_from_alpha(sqrt(5.0), 1.5, DC_END_OVERLAP, &e), DC_OK);
    CHECK(e == 0.0, "e_O(zeta=1) = %g", e);

    /* dt_crit: 2/omega0 for p = 1, and the seed's scaling for p = 1.5. */
    double dt = 0;
    CHECK_STATUS(dc_dt_crit(1.0, 2.0, 100.0, &dt), DC_OK);
    CHECK(dc_rel(dt, 0.02) < 1e-15, "dt = %g", dt);
    CHECK_STATUS(dc_dt_crit(1.5, 2.0, 100.0, &dt), DC_OK);
    double want = 4.0 / 2.5 * pow(1.25, 0.4) / 100.0 * pow(2.0 / 100.0, -0.2);
    CHECK(dc_rel(dt, want) < 1e-14, "dt = %.17g vs %.17g", dt, want);

    /* Bad input: statuses, and the output stays untouched. */
    double out = 42.0;
    CHECK_STATUS(dc_alpha_from_e(0.0, 1.5, DC_END_FORCE, &out), DC_ERR_RESTITUTION_RANGE);
    CHECK_STATUS(dc_alpha_from_e(1.5, 1.5, DC_END_FORCE, &out), DC_ERR_RESTITUTION_RANGE);
    CHECK_STATUS(dc_alpha_from_e(NAN, 1.5, DC_END_FORCE, &out), DC_ERR_NOT_FINITE);
    CHECK_STATUS(dc_alpha_from_e(0.5, INFINITY, DC_END_FORCE, &out), DC_ERR_NOT_FINITE);
    CHECK_STATUS(dc_alpha_from_e(0.5, 0.5, DC_END_FORCE, &out), DC_ERR_EXPONENT_RANGE);
    CHECK_STATUS(dc_alpha_from_e(0.5, 1.5, 3, &out), DC_ERR_CRITERION);
    CHECK_STATUS(dc_alpha_from_e(0.5, 1.5, DC_END_FORCE, NULL), DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_e_from_alpha(-1.0, 1.5, DC_END_FORCE, &out), DC_ERR_NEGATIVE);
    CHECK_STATUS(dc_e_from_alpha(NAN, 1.5, DC_END_FORCE, &out), DC_ERR_NOT_FINITE);
    CHECK_STATUS(dc_e_from_alpha(1.0, 1.5, -7, &out), DC_ERR_CRITERION);
    CHECK_STATUS(dc_e_from_alpha(1.0, 1.5, DC_END_FORCE, NULL), DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_dt_crit(1.5, -1.0, 1.0, &out), DC_ERR_NOT_POSITIVE);
    CHECK_STATUS(dc_dt_crit(1.5, 1.0, 0.0, &out), DC_ERR_NOT_POSITIVE);
    CHECK_STATUS(dc_dt_crit(1.5, NAN, 1.0, &out), DC_ERR_NOT_FINITE);
    CHECK_STATUS(dc_dt_crit(0.0, 1.0, 1.0, &out), DC_ERR_EXPONENT_RANGE);
    CHECK_STATUS(dc_dt_crit(1.5, 1.0, 1.0, NULL), DC_ERR_NULL_POINTER);
    CHECK(out == 42.0, "output touched on error: %g", out);

    /* Hertz helper: two equal glass beads, E* = E/(2(1-nu^2)), R* = R/2. */
    double k = 0;
    CHECK_STATUS(dc_hertz_stiffness(63e9, 0.23, 1e-3, 63e9, 0.23, 1e-3, &k), DC_OK);
    double kw = 4.0 / 3.0 * 63e9 / (2.0 * (1.0 - 0.23 * 0.23)) * sqrt(0.5e-3);
    CHECK(dc_rel(k, kw) < 1e-14, "k = %.17g vs %.17g", k, kw);
    CHECK_STATUS(dc_hertz_stiffness(63e9, 0.23, INFINITY, 63e9, 0.23, 1e-3, &k), DC_OK);
    CHECK(dc_rel(k, 4.0 / 3.0 * 63e9 / (2.0 * (1.0 - 0.23 * 0.23)) * sqrt(1e-3)) < 1e-14, "wall k = %g", k);
    CHECK_STATUS(dc_hertz_stiffness(-1.0, 0.23, 1e-3, 63e9, 0.23, 1e-3, &out), DC_ERR_NOT_POSITIVE);
    CHECK_STATUS(dc_hertz_stiffness(63e9, 0.7, 1e-3, 63e9, 0.23, 1e-3, &out), DC_ERR_POISSON_RANGE);
    CHECK_STATUS(dc_hertz_stiffness(63e9, 0.23, 1e-3, 63e9, -1.0, 1e-3, &out), DC_ERR_POISSON_RANGE);
    CHECK_STATUS(dc_hertz_stiffness(-1.0, 0.7, 1e-3, 63e9, 0.23, 1e-3, &out), DC_ERR_POISSON_RANGE);
    CHECK_STATUS(dc_hertz_stiffness(NAN, 0.2, 1e-3, 63e9, 0.23, 1e-3, &out), DC_ERR_NOT_FINITE);
    CHECK_STATUS(dc_hertz_stiffness(63e9, 0.2, 1e-3, 63e9, 0.23, 1e-3, NULL), DC_ERR_NULL_POINTER);
    double estar = 0;
    CHECK_STATUS(dc_effective_modulus(1e9, 0.5, 3e9, 0.0, &estar), DC_OK);
    CHECK(dc_rel(estar, 1.0 / (0.75 / 1e9 + 1.0 / 3e9)) < 1e-15, "E* = %g", estar);
    CHECK(out == 42.0, "output touched on error: %g", out);

    /* Strings. */
    CHECK(strcmp(dc_status_str(DC_OK), "ok") == 0, "%s", dc_status_str(DC_OK));
    CHECK(strlen(dc_status_str(DC_ERR_NULL_POINTER)) > 0, "empty message");
    CHECK(strcmp(dc_status_str(-99), "unknown demcontact status") == 0, "%s", dc_status_str(-99));
    CHECK(strcmp(dc_version(), "0.1.0") == 0, "version %s", dc_version());

    return dc_check_summary("test_calibration");
}
