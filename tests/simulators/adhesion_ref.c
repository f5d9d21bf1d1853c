/*
 * The library's own adhesive head-on impacts (JKR, DMT): two spheres on the x axis, or one sphere
 * on a plane wall (normal +z, at z = 0), the contact from dc_contact_force, integrated with the
 * velocity-Verlet order of LAMMPS `fix nve/sphere` (half kick, drift, force at the new positions
 * with the half-step velocities, half kick; dtfm = (dt/2)/m). The kinematics are built as the
 * LAMMPS plugin builds them (body 1 = the atom of smaller ID = the first sphere, n = (x1 - x2)/r,
 * overlap = r1 + r2 - r; the wall: body 2 with r2 = m2 = inf, n = +z, overlap = r1 - z; zcyl: the
 * inside of fix demcontact/wall's `zcylinder Rc`, the sphere at (x1, 0) moving along x, as the
 * plugin builds it: rxy = sqrt(x1^2 + y^2), n = (-x1/rxy, -y/rxy, 0), overlap = r1 - (Rc - rxy)), and the
 * contact is evaluated at every step (the library decides where the law acts), so a host that
 * evaluates it where the law acts gives the same bits.
 *
 * One case per input line (stdin):
 *   pair LAW E nu w e_n mu dt nsteps fext  r1 m1 x1 v1  r2 m2 x2 v2
 *   wall LAW E nu w e_n mu dt nsteps fext  r1 m1 z1 v1
 *   zcyl LAW E nu w e_n mu dt nsteps fext  r1 m1 x1 v1  Rc
 *   LAW = jkr | dmt; e_n = 1: undamped (DC_DAMPING_NONE), else DC_DAMPING_RESTITUTION with e_n;
 *   mu > 0: with tangential Mindlin (e_t = 1, Coulomb mu), so the history holds springs too;
 *   fext: a constant external force on body 1 along the axis (body 2 of a pair: -fext), added
 *   after the contact force as LAMMPS `fix addforce` adds it. The force of the step before the
 *   first (LAMMPS's `run` setup) is the contact's on a copy of the fresh (zero) history.
 * Output, one line per case: "x1 v1 x2 v2 state" (%.17g; the walls: x2 = v2 = 0; state: the law's
 * history state at the end, JKR 1 = neck formed, -1 for DMT). Exit 1 naming the status on error.
 */
#define _USE_MATH_DEFINES
#include <demcontact.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int fail(const char *what, int32_t s)
{
    fprintf(stderr, "adhesion_ref: %s: %s\n", what, dc_status_str(s));
    return 1;
}

int main(void)
{
    char kind[16], law[16];
    double E, nu, w, e_n, mu, dt, fext;
    long nsteps;
    while (scanf("%15s %15s %lf %lf %lf %lf %lf %lf %ld %lf", kind, law, &E, &nu, &w, &e_n, &mu, &dt, &nsteps,
                 &fext) == 10) {
        const int pair = strcmp(kind, "pair") == 0, cyl = strcmp(kind, "zcyl") == 0;
        if (!pair && !cyl && strcmp(kind, "wall") != 0) return fail("input: kind not pair, wall or zcyl", DC_ERR_NULL_POINTER);
        double r1, m1, x1, v1, r2 = INFINITY, m2 = INFINITY, x2 = 0.0, v2 = 0.0, rc = 0.0;
        if (scanf("%lf %lf %lf %lf", &r1, &m1, &x1, &v1) != 4) return fail("input", DC_ERR_NULL_POINTER);
        if (pair && scanf("%lf %lf %lf %lf", &r2, &m2, &x2, &v2) != 4) return fail("input", DC_ERR_NULL_POINTER);
        if (cyl && scanf("%lf", &rc) != 1) return fail("input", DC_ERR_NULL_POINTER);
        dc_contact_spec s;
        dc_contact_spec_init(&s);
        s.normal = strcmp(law, "jkr") == 0 ? DC_NORMAL_JKR : DC_NORMAL_DMT;
        s.damping = e_n == 1.0 ? DC_DAMPING_NONE : DC_DAMPING_RESTITUTION;
        s.e_n = e_n;
        s.criterion = DC_END_OVERLAP;
        s.E1 = s.E2 = E;
        s.nu1 = s.nu2 = nu;
        s.work_of_adhesion = w;
        if (mu > 0.0) {
            s.tangential = DC_TANGENTIAL_MINDLIN;
            s.mu = mu;
            s.e_t = 1.0;
        }
        dc_contact_model m;
        int32_t st = dc_contact_model_init(&s, &m);
        if (st != DC_OK) return fail("dc_contact_model_init", st);
        size_t nh = 0;
        st = dc_contact_history_len(&m, &nh);
        if (st != DC_OK) return fail("dc_contact_history_len", st);
        double h[DC_CONTACT_HISTORY_MAX] = {0.0}, copy[DC_CONTACT_HISTORY_MAX] = {0.0};
        const double dtfm1 = 0.5 * dt / m1, dtfm2 = pair ? 0.5 * dt / m2 : 0.0;
        double f = 0.0; /* the contact force on body 1 (body 2: -f) */
        for (long n = -1; n < nsteps; n++) {
            if (n >= 0) { /* n = -1: the setup's force only */
                v1 += dtfm1 * (f + fext);
                x1 += dt * v1;
                if (pair) {
                    v2 += dtfm2 * (-f + -fext);
                    x2 += dt * v2;
                }
            }
            dc_contact_state c;
            memset(&c, 0, sizeof c);
            if (pair) {
                const double dx = x1 - x2;
                const double r = sqrt(dx * dx + 0.0 + 0.0), rinv = 1.0 / r;
                c.n[0] = dx * rinv;
                c.overlap = r1 + r2 - r;
            } else if (cyl) {
                const double y = 0.0;
                const double rxy = sqrt(x1 * x1 + y * y);
                if (rxy > 0.0) {
                    c.n[0] = -x1 / rxy;
                    c.n[1] = -y / rxy;
                }
                c.overlap = r1 - (rc - rxy);
            } else {
                c.n[2] = 1.0;
                c.overlap = r1 - x1;
            }
            c.v1[pair || cyl ? 0 : 2] = v1;
            c.v2[0] = v2;
            c.r1 = r1;
            c.r2 = r2;
            c.m1 = m1;
            c.m2 = m2;
            dc_contact_result out;
            st = dc_contact_force(&m, &c, dt, n >= 0 ? h : copy, nh, &out);
            if (st != DC_OK) return fail("dc_contact_force", st);
            f = out.force[pair || cyl ? 0 : 2];
            if (n < 0) continue;
            v1 += dtfm1 * (f + fext);
            if (pair) v2 += dtfm2 * (-f + -fext);
        }
        const double state = s.normal == DC_NORMAL_JKR ? h[nh - 1] : -1.0;
        printf("%.17g %.17g %.17g %.17g %.17g\n", x1, v1, x2, v2, state);
    }
    return 0;
}
