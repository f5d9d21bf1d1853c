/* Header-only use of demcontact: calibration and per-contact force from demcontact_inline.h,
 * inlined into this program's own loop. Nothing of demcontact is linked (only libm); ctest builds
 * it as C99 and, through header_only.cpp, as C++17, and runs it.
 *
 * A head-on collision of two glass beads (R = 1 mm, E = 63 GPa, nu = 0.23), integrated with
 * velocity Verlet in LAMMPS order (the damping force reads the half-step velocity), for a Hertz
 * pair in a solver that clamps attractive forces (DC_END_FORCE) and a p = 1.7 power-law pair that
 * does not (DC_END_OVERLAP). The realised restitution must be the target: exact calibration, and
 * the integrator's first-order error at 2000 steps per contact scale is ~1e-4 (docs/force.md). */
#include <demcontact_inline.h>
#include <math.h>
#include <stdio.h>

/* Realised restitution of one collision at impact speed v0 [m/s]. */
static double collide(const dc_pair *pair, double k_contact, double r_eff, double m_eff,
                      double v0) {
    /* t_s = delta_s / v0 with delta_s = (v0/omega0)^(2/(p+1)): the contact's time scale. */
    const double omega0 = sqrt(k_contact / m_eff);
    const double t_s = pow(v0 / omega0, 2.0 / (pair->p + 1.0)) / v0;
    const double dt = t_s / 2000.0;
    double d = 0.0, v = v0, f = 0.0; /* overlap, its rate (> 0 compressing), force */
    for (long step = 0; step < 100000000L; step++) {
        v -= 0.5 * dt * f / m_eff;
        d += dt * v;
        if (d <= 0.0 && step > 0) return -v / v0; /* separated */
        f = dc_normal_force_inline(pair, d, v, r_eff, m_eff);
        v -= 0.5 * dt * f / m_eff;
    }
    return -1.0;
}

int main(void) {
    const double R = 1e-3, rho = 2500.0, E = 63e9, nu = 0.23;
    const double m = rho * 4.0 / 3.0 * 3.141592653589793 * R * R * R;
    const double r_eff = 0.5 * R, m_eff = 0.5 * m;
    int failed = 0;

    dc_pair hertz, gen;
    if (dc_pair_hertz_inline(E, nu, E, nu, 0.5, DC_END_FORCE, &hertz) != DC_OK ||
        dc_pair_powerlaw_inline(1.7, 1e8, 0.3, DC_END_OVERLAP, &gen) != DC_OK) {
        printf("pair construction failed\n");
        return 1;
    }
    printf("Hertz, clamped: alpha = %.15f (kernel %d)\n", hertz.alpha, (int)hertz.kernel);
    printf("p = 1.7, unclamped: alpha = %.15f (kernel %d)\n", gen.alpha, (int)gen.kernel);
    const double speeds[3] = {0.1, 1.0, 10.0};
    for (int i = 0; i < 3; i++) {
        const double eh = collide(&hertz, hertz.k * sqrt(r_eff), r_eff, m_eff, speeds[i]);
        const double eg = collide(&gen, gen.k, r_eff, m_eff, speeds[i]);
        printf("v0 = %5.1f m/s: e(Hertz) = %.6f (target 0.5), e(p = 1.7) = %.6f (target 0.3)\n",
               speeds[i], eh, eg);
        if (fabs(eh - 0.5) > 1e-3 || fabs(eg - 0.3) > 1e-3) failed = 1;
    }
    /* The clamp: at the end of a clamped contact the force is zero, never attractive. */
    if (dc_normal_force_inline(&hertz, 1e-9, -10.0, r_eff, m_eff) != 0.0) failed = 1;
    if (!(dc_normal_force_inline(&gen, 1e-9, -10.0, r_eff, m_eff) < 0.0)) failed = 1;
    printf(failed ? "FAILED\n" : "ok\n");
    return failed;
}
