/* Header-only full contact: a Hertz-Mindlin model with Coulomb friction (and EPSD rolling
 * resistance) built and evaluated with demcontact_inline.h alone, inside this program's own
 * time loop. Nothing of demcontact is linked (only libm); ctest builds it as C99 and, through
 * header_only_contact.cpp, as C++17, and runs it.
 *
 * A glass bead (R = 1 mm, E = 63 GPa, nu = 0.23, rho = 2500 kg/m^3) is set down on a rigid
 * wall (body 2: r2 = m2 = +inf) sliding at v0 = 0.5 m/s without spin, under gravity, mu = 0.3.
 * Rigid-body mechanics gives the checks (independent of the contact code):
 *  1. without rolling resistance, friction slows the sliding and spins the bead up until it rolls
 *     at v = v0 / (1 + kappa) = 5/7 v0 (kappa = I/(m R^2) = 2/5), after which it keeps rolling;
 *  2. with EPSD rolling resistance mu_r (torque mu_r R |Fn| once mobilised), the rolling bead
 *     decelerates at mu_r g / (1 + kappa).
 * Tolerances: 1% (the tangential spring's stick-slip transient and the bounce on landing). */
#include <demcontact_inline.h>
#include <math.h>
#include <stdio.h>

static const double R = 1e-3, RHO = 2500.0, E = 63e9, NU = 0.23, G = 9.81, MU = 0.3, V0 = 0.5;

/* Runs until t_end; returns the velocity along x at t_a and at t_end (rolling phase). */
static int run(double mu_r, double t_a, double t_end, double *v_a, double *v_end) {
    dc_contact_spec spec;
    dc_contact_model model;
    dc_contact_spec_init_inline(&spec);
    spec.normal = DC_NORMAL_HERTZ;
    spec.damping = DC_DAMPING_RESTITUTION;
    spec.e_n = 0.5;
    spec.E1 = E;
    spec.nu1 = NU;
    spec.E2 = (double)INFINITY; /* rigid wall */
    spec.nu2 = 0.0;
    spec.tangential = DC_TANGENTIAL_MINDLIN;
    spec.mu = MU;
    spec.e_t = 0.5;
    if (mu_r > 0.0) {
        spec.rolling = DC_ROLLING_EPSD;
        spec.mu_r = mu_r;
        spec.eta_r = 0.3;
    }
    int32_t st = dc_contact_model_init_inline(&spec, &model);
    if (st != DC_OK) {
        fprintf(stderr, "dc_contact_model_init_inline: %d\n", (int)st);
        return 1;
    }
    const double m = RHO * 4.0 / 3.0 * 3.141592653589793 * R * R * R;
    const double inertia = 0.4 * m * R * R;
    double hist[DC_CONTACT_HISTORY_MAX] = {0};
    double z = R, vz = 0.0, vx = V0, wy = 0.0;
    const double dt = 1e-6;
    dc_contact_state s = {{0.0, 0.0, 1.0}, 0.0, {0}, {0}, {0}, {0}, R, (double)INFINITY, m,
                          (double)INFINITY};
    const long n_a = (long)(t_a / dt), n_end = (long)(t_end / dt);
    for (long i = 1; i <= n_end; i++) {
        s.overlap = R - z;
        s.v1[0] = vx;
        s.v1[2] = vz;
        s.w1[1] = wy;
        dc_contact_result out;
        st = dc_contact_force_inline(&model, &s, dt, hist, DC_CONTACT_HISTORY_MAX, &out);
        if (st != DC_OK) {
            fprintf(stderr, "dc_contact_force_inline: %d at step %ld\n", (int)st, i);
            return 1;
        }
        /* semi-implicit Euler: forces at this step, then velocities, then positions */
        vx += dt * out.force[0] / m;
        vz += dt * (out.force[2] / m - G);
        wy += dt * out.torque1[1] / inertia;
        z += dt * vz;
        if (i == n_a) *v_a = vx;
    }
    *v_end = vx;
    return 0;
}

int main(void) {
    int failed = 0;
    double va, ve;
    /* 1. sliding ends at t = 2 v0 / (7 mu g) = 0.049 s; then pure rolling at 5/7 v0 */
    if (run(0.0, 0.06, 0.12, &va, &ve)) return 1;
    const double want = V0 / 1.4;
    printf("sliding -> rolling: v = %.6f m/s at 0.06 s, %.6f at 0.12 s (5/7 v0 = %.6f)\n", va, ve,
           want);
    if (!(fabs(va - want) < 0.01 * want && fabs(ve - want) < 0.01 * want)) failed = 1;
    /* 2. rolling resistance: deceleration between 0.06 s and 0.12 s */
    const double mu_r = 0.05;
    if (run(mu_r, 0.06, 0.12, &va, &ve)) return 1;
    const double decel = (va - ve) / 0.06, want_d = mu_r * G / 1.4;
    printf("EPSD rolling, mu_r = %.2f: deceleration %.5f m/s^2 (mu_r g / (1 + kappa) = %.5f)\n",
           mu_r, decel, want_d);
    if (!(fabs(decel - want_d) < 0.01 * want_d)) failed = 1;
    printf("%s\n", failed ? "FAILED" : "ok");
    return failed;
}
