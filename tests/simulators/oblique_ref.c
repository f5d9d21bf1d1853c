/*
 * The library's own oblique sphere-wall impact: one sphere onto a plane wall (normal +z), the
 * contact from dc_contact_force, integrated with the velocity-Verlet order of LAMMPS/LIGGGHTS
 * `fix nve/sphere` (half kick of v and omega, drift, force at the new position with the
 * half-step velocities, half kick). Prints, per incident angle, the rebound tangential velocity of
 * the contact point over the incident one (tangential restitution) and the rebound spin.
 *
 *   oblique_ref [--step-exact] [--rescale] E nu rho R e mu e_t v dt angle...
 *                                                  (angles from the wall normal, degrees)
 *   -> lines "angle e_t omega_y vz_out/vz_in"
 *
 * --step-exact: the model made step-aware for dt (dc_contact_model_set_step, velocity Verlet), as
 * the plugins' step_exact / stepExact on; --rescale: DC_TANGENTIAL_MINDLIN_RESCALE instead of
 * DC_TANGENTIAL_MINDLIN.
 *
 * The sphere starts with its surface 1e-3 R above the wall; the run ends when it has left the
 * wall (overlap < 0 after contact) for one more step. Exit 1 with the status text on error.
 */
#define _USE_MATH_DEFINES
#include <demcontact.h>

#include <math.h>
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    int step_exact = 0, rescale = 0;
    while (argc > 1 && strncmp(argv[1], "--", 2) == 0) {
        if (strcmp(argv[1], "--step-exact") == 0) {
            step_exact = 1;
        } else if (strcmp(argv[1], "--rescale") == 0) {
            rescale = 1;
        } else {
            fprintf(stderr, "oblique_ref: unknown option '%s' (--step-exact, --rescale)\n", argv[1]);
            return 2;
        }
        argv++;
        argc--;
    }
    if (argc < 10) {
        fprintf(stderr, "usage: %s [--step-exact] [--rescale] E nu rho R e mu e_t v dt angle...\n", argv[0]);
        return 2;
    }
    const double E = atof(argv[1]), nu = atof(argv[2]), rho = atof(argv[3]), R = atof(argv[4]);
    const double e = atof(argv[5]), mu = atof(argv[6]), e_t = atof(argv[7]), v = atof(argv[8]);
    const double dt = atof(argv[9]);
    dc_contact_spec s;
    dc_contact_spec_init(&s);
    s.normal = DC_NORMAL_HERTZ;
    s.damping = DC_DAMPING_RESTITUTION;
    s.criterion = DC_END_OVERLAP; /* as the plugins without limit_damping / limitForce */
    s.E1 = s.E2 = E;              /* wall of the sphere's material (as fix demcontact/wall) */
    s.nu1 = s.nu2 = nu;
    s.e_n = e;
    s.tangential = rescale ? DC_TANGENTIAL_MINDLIN_RESCALE : DC_TANGENTIAL_MINDLIN;
    s.mu = mu;
    s.e_t = e_t;
    dc_contact_model m;
    int32_t st = dc_contact_model_init(&s, &m);
    if (st == DC_OK && step_exact) st = dc_contact_model_set_step(&m, dt, DC_INTEGRATOR_VELOCITY_VERLET);
    size_t nh = 0;
    if (st == DC_OK) st = dc_contact_history_len(&m, &nh);
    if (st != DC_OK) {
        fprintf(stderr, "oblique_ref: %s\n", dc_status_str(st));
        return 1;
    }
    const double mass = rho * 4.0 / 3.0 * M_PI * R * R * R, inertia = 0.4 * mass * R * R;
    for (int a = 10; a < argc; a++) {
        const double th = atof(argv[a]) * M_PI / 180.0;
        double x[3] = {0.0, 0.0, R * 1.001}, vel[3] = {v * sin(th), 0.0, -v * cos(th)}, w[3] = {0, 0, 0};
        double f[3] = {0, 0, 0}, tq[3] = {0, 0, 0}, hist[DC_CONTACT_HISTORY_MAX] = {0};
        int touched = 0;
        for (long step = 0; step < 100000000L; step++) {
            for (int k = 0; k < 3; k++) {
                vel[k] += 0.5 * dt * f[k] / mass;
                x[k] += dt * vel[k];
                w[k] += 0.5 * dt * tq[k] / inertia;
            }
            const double overlap = R - x[2];
            for (int k = 0; k < 3; k++) f[k] = tq[k] = 0.0;
            if (overlap > 0.0) {
                touched = 1;
                dc_contact_state cs = {{0, 0, 1}, overlap, {vel[0], vel[1], vel[2]}, {0, 0, 0},
                                       {w[0], w[1], w[2]}, {0, 0, 0}, R, INFINITY, mass, INFINITY};
                dc_contact_result r;
                st = dc_contact_force(&m, &cs, dt, hist, nh, &r);
                if (st != DC_OK) {
                    fprintf(stderr, "oblique_ref: %s\n", dc_status_str(st));
                    return 1;
                }
                memcpy(f, r.force, sizeof f);
                memcpy(tq, r.torque1, sizeof tq);
            } else {
                memset(hist, 0, sizeof hist);
                if (touched) break;
            }
            for (int k = 0; k < 3; k++) {
                vel[k] += 0.5 * dt * f[k] / mass;
                w[k] += 0.5 * dt * tq[k] / inertia;
            }
        }
        /* contact point at -R z: its velocity v + w x (-R z); tangential part along x */
        const double vt_in = v * sin(th), vt_out = vel[0] - R * w[1];
        printf("%s %.12g %.12g %.12g\n", argv[a], vt_out / vt_in, w[1], vel[2] / (v * cos(th)));
    }
    return 0;
}
