/* A full contact driven through the C ABI the way a C DEM code would: a glass sphere hits a
 * rigid wall (E2 = +INFINITY, r2 = m2 = +INFINITY) obliquely, velocity-Verlet (LAMMPS order) for
 * translation and rotation, Hertz + calibrated damping + Mindlin tangential + Coulomb, history
 * owned here. Checks:
 *  - the realised normal restitution equals the target (DC_END_FORCE: clamped, force-zero alpha)
 *    within 2e-3 at ~2000 steps per contact;
 *  - gross sliding (incidence 80 deg from the normal): tangential impulse / normal impulse = mu
 *    within 1e-3 (the short initial stick phase of the spring is the difference), and
 *    |Ft| <= mu |Fn| at every step;
 *  - a near-normal impact (5 deg) sticks for most of the contact, its impulse ratio stays below
 *    mu, and the contact point's tangential speed drops (0 < ratio < 1: with nu = 0.23 the
 *    tangential spring does ~0.87 of an oscillation per contact, so the velocity is not
 *    reversed — Maw, Barber & Fawcett's regime);
 *  - dc_contact_force_batch equals dc_contact_force bit for bit on the same contacts;
 *  - statuses: NULL, wrong spec version, unset parameter, short history, non-unit normal. */
#include "check.h"
#include <demcontact.h>
#include <math.h>
#include <string.h>

typedef struct {
    double x[3], v[3], w[3], r, m, I;
} body;

typedef struct {
    double e_n, jt_over_jn, max_excess, vt_ratio;
    long steps, stick_steps;
} outcome;

static const double PI = 3.14159265358979323846;

static outcome impact(const dc_contact_model *model, double angle_deg, double v0, double dt) {
    const double R = 1e-3, rho = 2500.0;
    body b = {{0.0, R, 0.0}, {0}, {0}, R, 0, 0};
    b.m = rho * 4.0 / 3.0 * PI * R * R * R;
    b.I = 0.4 * b.m * R * R;
    double a = angle_deg * PI / 180.0;
    b.v[0] = v0 * sin(a);
    b.v[1] = -v0 * cos(a);
    double vn0 = -b.v[1], vt0 = b.v[0];
    double hist[DC_CONTACT_HISTORY_MAX] = {0};
    dc_contact_result res;
    memset(&res, 0, sizeof res);
    outcome o = {0, 0, 0, 0, 0, 0};
    double jn = 0.0, jt = 0.0;
    int touched = 0;
    for (long i = 0; i < 10000000L; i++) {
        for (int k = 0; k < 3; k++) {
            b.v[k] += 0.5 * dt * res.force[k] / b.m;
            b.w[k] += 0.5 * dt * res.torque1[k] / b.I;
            b.x[k] += dt * b.v[k];
        }
        dc_contact_state s = {.n = {0.0, 1.0, 0.0},
                              .overlap = b.r - b.x[1],
                              .v1 = {b.v[0], b.v[1], b.v[2]},
                              .v2 = {0.0, 0.0, 0.0},
                              .w1 = {b.w[0], b.w[1], b.w[2]},
                              .w2 = {0.0, 0.0, 0.0},
                              .r1 = b.r,
                              .r2 = INFINITY,
                              .m1 = b.m,
                              .m2 = INFINITY};
        int32_t st = dc_contact_force(model, &s, dt, hist, DC_CONTACT_HISTORY_MAX, &res);
        if (st != DC_OK) {
            CHECK(0, "dc_contact_force: %s", dc_status_str(st));
            return o;
        }
        for (int k = 0; k < 3; k++) {
            b.v[k] += 0.5 * dt * res.force[k] / b.m;
            b.w[k] += 0.5 * dt * res.torque1[k] / b.I;
        }
        if (s.overlap > 0.0) {
            touched = 1;
            o.steps++;
            o.stick_steps += res.sliding == 0 && res.f_n > 0.0;
            jn += res.f_n * dt;
            jt += -res.ft[0] * dt;
            double ft = hypot(res.ft[0], res.ft[2]);
            double excess = ft - model->mu * fabs(res.f_n);
            if (excess > o.max_excess) o.max_excess = excess;
        } else if (touched) {
            break;
        }
    }
    o.e_n = b.v[1] / vn0;
    o.jt_over_jn = jt / jn;
    /* contact point tangential velocity after / before (x direction; contact at -r n). */
    o.vt_ratio = (b.v[0] + b.w[2] * b.r) / vt0;
    return o;
}

int main(void) {
    const double e_target = 0.8, mu = 0.3;
    dc_contact_spec spec;
    CHECK_STATUS(dc_contact_spec_init(&spec), DC_OK);
    spec.normal = DC_NORMAL_HERTZ;
    spec.E1 = 63e9;
    spec.nu1 = 0.23;
    spec.E2 = INFINITY; /* rigid wall */
    spec.nu2 = 0.3;
    spec.damping = DC_DAMPING_RESTITUTION;
    spec.e_n = e_target;
    spec.criterion = DC_END_FORCE;
    spec.tangential = DC_TANGENTIAL_MINDLIN;
    spec.mu = mu;
    dc_contact_model model;
    CHECK_STATUS(dc_contact_model_init(&spec, &model), DC_OK);
    size_t len = 0;
    CHECK_STATUS(dc_contact_history_len(&model, &len), DC_OK);
    CHECK(len == 6, "history length %zu, want 6 (normal + tangential spring)", len);

    /* Contact time of a Hertz impact at 1 m/s: ~2.87 (m^2/(R E*^2 v))^(1/5); 2000 steps. */
    const double R = 1e-3, m = 2500.0 * 4.0 / 3.0 * PI * R * R * R;
    const double Es = 1.0 / ((1 - 0.23 * 0.23) / 63e9);
    const double tc = 2.87 * pow(m * m / (R * Es * Es * 1.0), 0.2);
    const double dt = tc / 2000.0;

    outcome g = impact(&model, 80.0, 1.0, dt);
    printf("80 deg: e_n %.6f, Jt/Jn %.6f (mu %.3f), stick steps %ld of %ld, max |Ft| - mu|Fn| %.2e N\n", g.e_n,
           g.jt_over_jn, mu, g.stick_steps, g.steps, g.max_excess);
    CHECK(fabs(g.e_n - e_target) < 2e-3, "realised e_n %.6f vs %.3f", g.e_n, e_target);
    CHECK(fabs(g.jt_over_jn / mu - 1.0) < 1e-3, "gross sliding: Jt/Jn = %.6f, mu = %.3f", g.jt_over_jn, mu);
    CHECK(g.max_excess <= 1e-15, "Coulomb limit exceeded by %.3e N", g.max_excess);

    outcome s = impact(&model, 5.0, 1.0, dt);
    printf("5 deg: e_n %.6f, contact point vt after/before %.4f, Jt/Jn %.4f, stick steps %ld of %ld\n", s.e_n,
           s.vt_ratio, s.jt_over_jn, s.stick_steps, s.steps);
    CHECK(fabs(s.e_n - e_target) < 2e-3, "realised e_n %.6f", s.e_n);
    CHECK(s.stick_steps > s.steps / 10, "a near-normal impact must stick (%ld of %ld)", s.stick_steps, s.steps);
    CHECK(fabs(s.jt_over_jn) < 0.9 * mu, "sticking impact: Jt/Jn %.4f must stay below mu", s.jt_over_jn);
    CHECK(s.vt_ratio > 0.0 && s.vt_ratio < 1.0, "contact point vt after/before %.4f", s.vt_ratio);

    /* Batch = scalar, bit for bit, on three contacts (one separated). */
    {
        double n[9] = {0, 1, 0, 0.6, 0.8, 0, 0, 0, 1}, d[3] = {2e-6, 1e-6, -1e-6};
        double v1[9] = {0.3, -0.1, 0, 0.1, 0.2, 0.3, 0, 0, -1}, v2[9] = {0};
        double w1[9] = {10, 0, 5, 0, 0, 40, 1, 2, 3}, w2[9] = {0};
        double r1[3] = {R, R, R}, r2[3] = {INFINITY, 2 * R, INFINITY};
        double m1[3] = {m, m, m}, m2[3] = {INFINITY, 8 * m, INFINITY};
        double hb[3 * 6] = {0}, hs[3][DC_CONTACT_HISTORY_MAX] = {{0}};
        double f_n[3], force[9], t1[9], t2[9];
        dc_contact_batch b = {.n = 3, .history_stride = 6, .normal = n, .overlap = d, .v1 = v1, .v2 = v2,
                              .w1 = w1, .w2 = w2, .r1 = r1, .r2 = r2, .m1 = m1, .m2 = m2, .history = hb,
                              .f_n = f_n, .force = force, .torque1 = t1, .torque2 = t2};
        for (int step = 0; step < 3; step++) {
            CHECK_STATUS(dc_contact_force_batch(&model, &b, dt), DC_OK);
            for (int i = 0; i < 3; i++) {
                dc_contact_state st = {.overlap = d[i], .r1 = r1[i], .r2 = r2[i], .m1 = m1[i], .m2 = m2[i]};
                memcpy(st.n, n + 3 * i, sizeof st.n);
                memcpy(st.v1, v1 + 3 * i, sizeof st.v1);
                memcpy(st.v2, v2 + 3 * i, sizeof st.v2);
                memcpy(st.w1, w1 + 3 * i, sizeof st.w1);
                memcpy(st.w2, w2 + 3 * i, sizeof st.w2);
                dc_contact_result r;
                CHECK_STATUS(dc_contact_force(&model, &st, dt, hs[i], DC_CONTACT_HISTORY_MAX, &r), DC_OK);
                CHECK(memcmp(&r.f_n, &f_n[i], sizeof(double)) == 0 && memcmp(r.force, force + 3 * i, 24) == 0 &&
                          memcmp(r.torque1, t1 + 3 * i, 24) == 0 && memcmp(r.torque2, t2 + 3 * i, 24) == 0 &&
                          memcmp(hs[i], hb + 6 * i, 6 * sizeof(double)) == 0,
                      "batch != scalar at step %d contact %d", step, i);
            }
        }
    }

    /* Statuses. */
    {
        dc_contact_state st = {.n = {0, 1, 0}, .overlap = 1e-6, .r1 = R, .r2 = INFINITY, .m1 = m, .m2 = INFINITY};
        double h[DC_CONTACT_HISTORY_MAX] = {0};
        dc_contact_result r;
        CHECK_STATUS(dc_contact_force(NULL, &st, dt, h, 10, &r), DC_ERR_NULL_POINTER);
        CHECK_STATUS(dc_contact_force(&model, &st, dt, h, 5, &r), DC_ERR_BUFFER_TOO_SHORT);
        st.n[1] = 0.9;
        CHECK_STATUS(dc_contact_force(&model, &st, dt, h, 10, &r), DC_ERR_NOT_UNIT);
        dc_contact_spec bad = spec;
        bad.version = 99;
        dc_contact_model mm;
        CHECK_STATUS(dc_contact_model_init(&bad, &mm), DC_ERR_SPEC_VERSION);
        bad = spec;
        bad.mu = NAN;
        CHECK_STATUS(dc_contact_model_init(&bad, &mm), DC_ERR_SPEC_UNSET);
        dc_contact_model zero;
        memset(&zero, 0, sizeof zero);
        CHECK_STATUS(dc_contact_history_len(&zero, &len), DC_ERR_CONTACT_MODEL_INVALID);
    }
    return dc_check_summary("test_contact");
}
