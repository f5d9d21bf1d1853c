/* The power-law observables through the C ABI: values against independent C computations
 * (energy balance and the Beta function for undamped contacts, a fine RK4 integration of the
 * equation of motion for damped ones), the trajectory's buffer rules, and every class of bad input. */
#include "check.h"
#include "rk4.h"
#include <demcontact.h>
#include <stdint.h>

int main(void) {
    const double ps[] = {1.0, 1.5, 2.0, 3.0};
    double out = 0.0, tau = 0.0, tmax = 0.0, dmax = 0.0;

    /* Undamped: delta_max from energy, tau from the Beta function (lgamma), t_max = tau/2. */
    for (int i = 0; i < 4; i++) {
        double p = ps[i], v0 = 0.8, w0 = 40.0;
        double dm = pow((p + 1.0) * v0 * v0 / (2.0 * w0 * w0), 1.0 / (p + 1.0));
        CHECK_STATUS(dc_max_overlap(p, 0.0, v0, w0, &dmax), DC_OK);
        CHECK(dc_rel(dmax, dm) < 1e-14, "p=%g delta_max %.17g vs %.17g", p, dmax, dm);
        double a = 1.0 / (p + 1.0);
        double beta = exp(lgamma(a) + lgamma(0.5) - lgamma(a + 0.5));
        double A = pow(0.5 * (p + 1.0), a);
        double t0 = 2.0 * A / ((p + 1.0) * w0) * pow(v0 / w0, -(p - 1.0) / (p + 1.0)) * beta;
        CHECK_STATUS(dc_contact_duration(p, 0.0, v0, w0, DC_END_OVERLAP, &tau), DC_OK);
        CHECK(dc_rel(tau, t0) < 1e-13, "p=%g tau %.17g vs Beta %.17g", p, tau, t0);
        CHECK_STATUS(dc_time_of_max_overlap(p, 0.0, v0, w0, &tmax), DC_OK);
        CHECK(dc_rel(2.0 * tmax, t0) < 1e-13, "p=%g 2 t_max %.17g vs %.17g", p, 2 * tmax, t0);
    }

    /* Damped, both criteria and one overdamped contact: RK4 reference. */
    for (int i = 0; i < 4; i++) {
        double p = ps[i], v0 = 0.5, w0 = 1.0;
        for (int c = 0; c < 3; c++) {
            int crit = c == 0 ? DC_END_OVERLAP : DC_END_FORCE;
            double alpha = 0.0;
            if (c < 2) CHECK_STATUS(dc_alpha_from_e(0.3, p, crit, &alpha), DC_OK);
            else alpha = 2.5 * sqrt(2.0 * (p + 1.0)); /* zeta = 2.5 */
            dc_rk4_collision ref = dc_rk4_collide(p, alpha, v0, w0, crit == DC_END_FORCE);
            double rd = ref.dmax, rt = ref.tmax, rtau = ref.tau;
            CHECK_STATUS(dc_max_overlap(p, alpha, v0, w0, &dmax), DC_OK);
            CHECK_STATUS(dc_time_of_max_overlap(p, alpha, v0, w0, &tmax), DC_OK);
            CHECK_STATUS(dc_contact_duration(p, alpha, v0, w0, crit, &tau), DC_OK);
            CHECK(dc_rel(dmax, rd) < 1e-6, "p=%g c=%d delta_max %.12g vs RK4 %.12g", p, c, dmax, rd);
            CHECK(dc_rel(tmax, rt) < 1e-5, "p=%g c=%d t_max %.12g vs RK4 %.12g", p, c, tmax, rt);
            CHECK(dc_rel(tau, rtau) < 1e-6, "p=%g c=%d tau %.12g vs RK4 %.12g", p, c, tau, rtau);
            dc_energy en;
            CHECK_STATUS(dc_energy_partition(p, alpha, crit, &en), DC_OK);
            double sum = en.loading + en.unloading + en.returned + en.clamped;
            CHECK(fabs(sum - 1.0) < 1e-14, "energy sums to %.17g", sum);
            /* loading dissipation from the delta_max energy balance */
            double stored = 2.0 * w0 * w0 * pow(dmax, p + 1.0) / ((p + 1.0) * v0 * v0);
            CHECK(fabs(en.loading - (1.0 - stored)) < 1e-13, "loading %.17g vs %.17g", en.loading, 1 - stored);
            CHECK(fabs(en.returned - en.e * en.e) < 1e-15, "returned = e^2");
        }
    }

    /* Overdamped overlap end never ends: DC_ERR_NO_EVENT, output untouched. */
    out = 42.0;
    CHECK_STATUS(dc_contact_duration(1.5, 3.0 * sqrt(5.0), 1.0, 1.0, DC_END_OVERLAP, &out), DC_ERR_NO_EVENT);
    CHECK_STATUS(dc_contact_duration(1.5, sqrt(5.0), 1.0, 1.0, DC_END_OVERLAP, &out), DC_ERR_NO_EVENT);

    /* Trajectory: buffer rules, first and last samples. */
    enum { N = 64 };
    double t[N], d[N], v[N], f[N];
    double alpha;
    CHECK_STATUS(dc_alpha_from_e(0.5, 1.5, DC_END_FORCE, &alpha), DC_OK);
    CHECK_STATUS(dc_contact_trajectory(1.5, alpha, 2.0, 300.0, 0.01, DC_END_FORCE, DC_LEVEL_MAX, N, t, d, v, f, N), DC_OK);
    CHECK_STATUS(dc_contact_duration(1.5, alpha, 2.0, 300.0, DC_END_FORCE, &tau), DC_OK);
    CHECK(t[0] == 0.0 && d[0] == 0.0 && v[0] == 2.0, "first sample");
    CHECK(t[N - 1] == tau, "last time %.17g vs tau %.17g", t[N - 1], tau);
    CHECK(fabs(-v[N - 1] / 2.0 - 0.5) < 1e-13, "exit speed %.17g", -v[N - 1] / 2.0);
    CHECK(fabs(f[N - 1]) < 1e-12 * f[N / 4], "force at the force end %.3g", f[N - 1]);
    CHECK_STATUS(dc_max_overlap(1.5, alpha, 2.0, 300.0, &dmax), DC_OK);
    double dm = 0.0;
    for (int j = 0; j < N; j++) dm = d[j] > dm ? d[j] : dm;
    CHECK(dm <= dmax * (1 + 1e-15) && dm > 0.99 * dmax, "sampled max %.17g vs %.17g", dm, dmax);
    t[0] = 42.0;
    CHECK_STATUS(dc_contact_trajectory(1.5, alpha, 2.0, 300.0, 0.01, DC_END_FORCE, 4, 0, t, d, v, f, N), DC_ERR_BUFFER_TOO_SHORT);
    CHECK_STATUS(dc_contact_trajectory(1.5, alpha, 2.0, 300.0, 0.01, DC_END_FORCE, 4, 1, t, d, v, f, N), DC_ERR_BUFFER_TOO_SHORT);
    CHECK_STATUS(dc_contact_trajectory(1.5, alpha, 2.0, 300.0, 0.01, DC_END_FORCE, 4, N + 1, t, d, v, f, N), DC_ERR_BUFFER_TOO_SHORT);
    CHECK_STATUS(dc_contact_trajectory(1.5, alpha, 2.0, 300.0, 0.01, DC_END_FORCE, 4, N, t, NULL, v, f, N), DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_contact_trajectory(1.5, alpha, 2.0, 300.0, 0.01, DC_END_FORCE, 9, N, t, d, v, f, N), DC_ERR_LEVEL);
    CHECK_STATUS(dc_contact_trajectory(1.5, alpha, 2.0, 300.0, -1.0, DC_END_FORCE, 4, N, t, d, v, f, N), DC_ERR_NOT_POSITIVE);
    CHECK_STATUS(dc_contact_trajectory(1.5, 9.0, 2.0, 300.0, 0.01, DC_END_OVERLAP, 4, N, t, d, v, f, N), DC_ERR_NO_EVENT);
    CHECK(t[0] == 42.0, "buffer touched on error");

    /* Accuracy knob: levels 3 and 4 agree to 1e-9, the cheap levels to 10%; range enforced. */
    for (int lv = DC_LEVEL_MIN; lv <= DC_LEVEL_MAX; lv++) {
        double tl;
        CHECK_STATUS(dc_contact_duration_level(1.5, alpha, 2.0, 300.0, DC_END_FORCE, lv, &tl), DC_OK);
        CHECK(dc_rel(tl, tau) < (lv >= 3 ? 1e-9 : 0.1), "level %d: %.17g vs %.17g", lv, tl, tau);
    }

    /* Bad input: statuses, output untouched. */
    out = 42.0;
    dc_energy en0 = {42.0, 42.0, 42.0, 42.0, 42.0};
    CHECK_STATUS(dc_max_overlap(NAN, 0.1, 1.0, 1.0, &out), DC_ERR_NOT_FINITE);
    CHECK_STATUS(dc_max_overlap(0.9, 0.1, 1.0, 1.0, &out), DC_ERR_EXPONENT_RANGE);
    CHECK_STATUS(dc_max_overlap(1.5, -0.1, 1.0, 1.0, &out), DC_ERR_NEGATIVE);
    CHECK_STATUS(dc_max_overlap(1.5, 0.1, 0.0, 1.0, &out), DC_ERR_NOT_POSITIVE);
    CHECK_STATUS(dc_max_overlap(1.5, 0.1, 1.0, -1.0, &out), DC_ERR_NOT_POSITIVE);
    CHECK_STATUS(dc_max_overlap(1.5, 0.1, 1.0, 1.0, NULL), DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_time_of_max_overlap(1.5, INFINITY, 1.0, 1.0, &out), DC_ERR_NOT_FINITE);
    CHECK_STATUS(dc_contact_duration(1.5, 0.1, 1.0, 1.0, 2, &out), DC_ERR_CRITERION);
    CHECK_STATUS(dc_contact_duration(1.5, 0.1, 1.0, 1.0, DC_END_FORCE, NULL), DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_contact_duration_level(1.5, 0.1, 1.0, 1.0, DC_END_FORCE, -1, &out), DC_ERR_LEVEL);
    CHECK_STATUS(dc_contact_duration_level(1.5, 0.1, 1.0, 1.0, DC_END_FORCE, DC_LEVEL_MAX + 1, &out), DC_ERR_LEVEL);
    CHECK_STATUS(dc_energy_partition(1.5, 0.1, 5, &en0), DC_ERR_CRITERION);
    CHECK_STATUS(dc_energy_partition(1.5, NAN, DC_END_FORCE, &en0), DC_ERR_NOT_FINITE);
    CHECK_STATUS(dc_energy_partition(1.5, 0.1, DC_END_FORCE, NULL), DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_omega0(0.0, 1.0, &out), DC_ERR_NOT_POSITIVE);
    CHECK(out == 42.0 && en0.e == 42.0, "output touched on error");

    /* Time steps: linearised bound = seed's / sqrt(2p/(p+1)); static bound, damped factor. */
    double dts = 0, dtl = 0, dtq = 0;
    CHECK_STATUS(dc_dt_crit(2.0, 0.3, 50.0, &dts), DC_OK);
    CHECK_STATUS(dc_dt_linearised(2.0, 0.3, 50.0, &dtl), DC_OK);
    CHECK(dc_rel(dts / dtl, sqrt(4.0 / 3.0)) < 1e-14, "seed/lin = %.17g", dts / dtl);
    CHECK_STATUS(dc_dt_static(2.0, 0.0, 50.0, 9.81, &dtq), DC_OK);
    {
        double deq = pow(9.81 / 2500.0, 0.5), weq = 50.0 * sqrt(2.0 * deq);
        CHECK(dc_rel(dtq, 2.0 / weq) < 1e-14, "static %.17g vs %.17g", dtq, 2.0 / weq);
        double z = 0.7 / (2.0 * sqrt(2.0));
        CHECK_STATUS(dc_dt_static(2.0, 0.7, 50.0, 9.81, &dtq), DC_OK);
        CHECK(dc_rel(dtq, 2.0 / weq * (sqrt(1 + z * z) - z)) < 1e-14, "damped static %.17g", dtq);
    }
    out = 42.0;
    CHECK_STATUS(dc_dt_static(2.0, -1.0, 50.0, 9.81, &out), DC_ERR_NEGATIVE);
    CHECK_STATUS(dc_dt_static(2.0, 0.1, 50.0, 0.0, &out), DC_ERR_NOT_POSITIVE);
    CHECK_STATUS(dc_dt_linearised(2.0, 0.3, NAN, &out), DC_ERR_NOT_FINITE);
    CHECK(out == 42.0, "output touched on error");

    /* omega0 with the Hertz helper: glass beads. */
    double k, w;
    CHECK_STATUS(dc_hertz_stiffness(63e9, 0.23, 1e-3, 63e9, 0.23, 1e-3, &k), DC_OK);
    CHECK_STATUS(dc_omega0(k, 2e-6, &w), DC_OK);
    CHECK(dc_rel(w, sqrt(k / 2e-6)) < 1e-15, "omega0");

    return dc_check_summary("test_powerlaw");
}
