/* Concurrency: every export called from 16 threads at once must give results bit-identical to a
 * single-threaded run (the library keeps no global mutable state). Each thread computes the
 * full table of outputs and statuses over a deterministic input grid. */
#include "check.h"
#include <demcontact.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define NTHREADS 16
#define REPEAT 20
#define MAXN 200000

typedef struct {
    double v[MAXN];
    int32_t s[MAXN];
    size_t n;
} table;

static void put(table *t, int32_t s, double v) {
    if (t->n < MAXN) {
        t->s[t->n] = s;
        t->v[t->n] = v;
        t->n++;
    }
}

static void compute(table *t) {
    static const double xs[] = {-1.0, 0.0, 1e-300, 1e-12, 1e-6, 0.01, 0.3, 0.5, 0.9, 1.0 - 1e-12, 1.0, 1.5,
                                2.0, 3.0, 20.0, 1e6, 1e300, 1.0 / 0.0};
    const size_t nx = sizeof xs / sizeof xs[0];
    t->n = 0;
    for (size_t i = 0; i < nx; i++)
        for (size_t j = 0; j < nx; j++) {
            for (int32_t c = -1; c <= 2; c++) {
                double o = -1.0;
                put(t, dc_alpha_from_e(xs[i], xs[j], c, &o), o);
                o = -1.0;
                put(t, dc_e_from_alpha(xs[i], xs[j], c, &o), o);
            }
            for (size_t k = 0; k < nx; k++) {
                double o = -1.0;
                put(t, dc_dt_crit(xs[i], xs[j], xs[k], &o), o);
                o = -1.0;
                put(t, dc_hertz_stiffness(xs[i], 0.3, xs[j], xs[k], 0.2, 1e-3, &o), o);
                o = -1.0;
                put(t, dc_effective_modulus(xs[i], 0.3, xs[k], 0.25, &o), o);
            }
        }
    /* Force kernels: constructors over the grid, then scalar, checked, batch and 3D forces. */
    for (size_t i = 0; i < nx; i++)
        for (size_t j = 0; j < nx; j++) {
            dc_pair pr;
            memset(&pr, 0, sizeof pr);
            put(t, dc_pair_powerlaw(xs[i], 1e4, xs[j] > 1.0 ? 0.5 : xs[j], (int32_t)(i % 2), &pr), pr.alpha);
            put(t, dc_pair_hertz(1e9 * xs[i], 0.3, 2e9, 0.25, 0.4, (int32_t)(j % 2), &pr), pr.k);
        }
    dc_pair pair;
    if (dc_pair_hertz(63e9, 0.23, 70e9, 0.3, 0.5, DC_END_FORCE, &pair) == DC_OK) {
        double d[64], vn[64], r[64], m[64], f[64];
        for (int i = 0; i < 64; i++) {
            d[i] = 1e-7 * (i - 8);
            vn[i] = 0.05 * (i - 32);
            r[i] = 1e-3;
            m[i] = 1e-5;
        }
        put(t, dc_normal_force_batch(&pair, 64, d, vn, r, m, f), 0.0);
        for (int i = 0; i < 64; i++) {
            double c = -1.0;
            put(t, dc_normal_force_checked(&pair, d[i], vn[i], r[i], m[i], &c), c);
            put(t, 0, dc_normal_force(&pair, d[i], vn[i], r[i], m[i]));
            put(t, 0, f[i]);
        }
        double x1[3] = {0, 0, 0}, v1[3] = {0.1, 0, 0}, x2[3] = {1.9e-3, 0, 0}, v2[3] = {-0.1, 0, 0}, f3[3] = {0, 0, 0};
        put(t, dc_normal_force_3d(&pair, x1, v1, 1e-3, 1e-5, x2, v2, 1e-3, 1e-5, f3), f3[0]);
    }
    /* Power-law calculus over a grid covering under-, critically and overdamped contacts,
     * invalid values and every criterion and level. */
    static const double ps[] = {1.0, 1.5, 2.0, 3.7, 20.0, 0.5, 0.0 / 0.0};
    static const double as[] = {0.0, 0.3, 2.0, 5.0, -1.0, 1.0 / 0.0};
    static const double vs[] = {1e-9, 1.0, 1e4, 0.0};
    static const double ws[] = {1e-3, 1e3, 1e9};
    for (size_t i = 0; i < sizeof ps / sizeof ps[0]; i++)
        for (size_t j = 0; j < sizeof as / sizeof as[0]; j++) {
            for (int32_t c = -1; c <= 2; c++) {
                dc_energy en = {-1, -1, -1, -1, -1};
                put(t, dc_energy_partition(ps[i], as[j], c, &en), en.e);
                put(t, 0, en.loading + 2.0 * en.unloading + 3.0 * en.returned + 4.0 * en.clamped);
            }
            for (size_t k = 0; k < sizeof vs / sizeof vs[0]; k++)
                for (size_t l = 0; l < sizeof ws / sizeof ws[0]; l++) {
                    double o = -1.0;
                    put(t, dc_max_overlap(ps[i], as[j], vs[k], ws[l], &o), o);
                    o = -1.0;
                    put(t, dc_time_of_max_overlap(ps[i], as[j], vs[k], ws[l], &o), o);
                    for (int32_t c = -1; c <= 2; c++) {
                        o = -1.0;
                        put(t, dc_contact_duration(ps[i], as[j], vs[k], ws[l], c, &o), o);
                        o = -1.0;
                        put(t, dc_contact_duration_level(ps[i], as[j], vs[k], ws[l], c, (c + 1) * 2 - 1, &o), o);
                    }
                    o = -1.0;
                    put(t, dc_dt_linearised(ps[i], vs[k], ws[l], &o), o);
                    o = -1.0;
                    put(t, dc_dt_static(ps[i], as[j], ws[l], vs[k], &o), o);
                    o = -1.0;
                    put(t, dc_omega0(vs[k], ws[l], &o), o);
                }
        }
    /* Trajectories: good and bad buffers. */
    for (size_t i = 0; i < sizeof ps / sizeof ps[0]; i++)
        for (size_t j = 0; j < sizeof as / sizeof as[0]; j++)
            for (int32_t c = 0; c <= 1; c++) {
                double tt[9], dd[9], vv[9], ff[9];
                for (int q = 0; q < 9; q++) tt[q] = dd[q] = vv[q] = ff[q] = -1.0;
                put(t, dc_contact_trajectory(ps[i], as[j], 0.7, 400.0, 0.02, c, 3, 9, tt, dd, vv, ff, 9), 0.0);
                for (int q = 0; q < 9; q++) {
                    put(t, 0, tt[q]);
                    put(t, 0, dd[q]);
                    put(t, 0, vv[q]);
                    put(t, 0, ff[q]);
                }
                put(t, dc_contact_trajectory(ps[i], as[j], 0.7, 400.0, 0.02, c, 3, 9, tt, dd, vv, ff, 8), 0.0);
                put(t, dc_contact_trajectory(ps[i], as[j], 0.7, 400.0, 0.02, c, 3, 0, tt, dd, vv, ff, 9), 0.0);
                put(t, dc_contact_trajectory(ps[i], as[j], 0.7, 400.0, 0.02, c, 3, 9, tt, NULL, vv, ff, 9), 0.0);
            }
    /* Viscoelastic exports. */
    static const double bs[] = {-1.0, 0.0, 1e-300, 1e-6, 0.1, 0.5, 1.0, 3.0, 8.0, 100.0, 1e6, 1e30, 1.0 / 0.0};
    static const double es[] = {-0.5, 0.0, 1e-12, 1e-3, 0.3, 0.9, 1.0 - 1e-12, 1.0, 1.5};
    for (size_t i = 0; i < sizeof bs / sizeof bs[0]; i++)
        for (int32_t c = -1; c <= 2; c++) {
            double o = -1.0;
            put(t, dc_viscoelastic_e(bs[i], c, &o), o);
            o = -1.0;
            put(t, dc_viscoelastic_e_series(bs[i], c, &o), o);
            if (!(bs[i] > 3.0)) { /* the reference integrator is slow for large b */
                o = -1.0;
                put(t, dc_viscoelastic_e_reference(bs[i], c, &o), o);
            }
            for (size_t j = 0; j < sizeof bs / sizeof bs[0]; j++) {
                o = -1.0;
                put(t, dc_viscoelastic_b(bs[i] * 1e5, bs[j], 0.5, &o), o);
                o = -1.0;
                put(t, dc_viscoelastic_e_of_speed(1e5, bs[i], bs[j], c, &o), o);
                double k = -1.0, g = -1.0;
                put(t, dc_viscoelastic_k_gamma(bs[i], bs[j], 0.01, &k, &g), k);
                put(t, 0, g);
            }
        }
    for (size_t i = 0; i < sizeof es / sizeof es[0]; i++)
        for (int32_t c = -1; c <= 2; c++) {
            double o = -1.0;
            put(t, dc_viscoelastic_b_from_e(es[i], c, &o), o);
            for (size_t j = 0; j < sizeof bs / sizeof bs[0]; j++) {
                o = -1.0;
                put(t, dc_viscoelastic_beta_from_e(es[i], bs[j], c, &o), o);
                o = -1.0;
                put(t, dc_viscoelastic_a_from_e(es[i], bs[j], 1e8, 1e-3, c, &o), o);
                o = -1.0;
                put(t, dc_viscoelastic_speed_for_e(es[i], bs[j], c, &o), o);
            }
        }
    put(t, (int32_t)strlen(dc_status_str(DC_ERR_NOT_FINITE)), 0.0);
    put(t, (int32_t)strlen(dc_version()), 0.0);
}

static table *reference;
static int mismatches[NTHREADS];

static void *worker(void *arg) {
    int id = (int)(intptr_t)arg;
    table *t = malloc(sizeof *t);
    if (!t) return NULL;
    for (int r = 0; r < REPEAT; r++) {
        compute(t);
        if (t->n != reference->n || memcmp(t->v, reference->v, t->n * sizeof(double)) != 0 ||
            memcmp(t->s, reference->s, t->n * sizeof(int32_t)) != 0)
            mismatches[id]++;
    }
    free(t);
    return NULL;
}

int main(void) {
    reference = malloc(sizeof *reference);
    if (!reference) return 1;
    compute(reference);
    pthread_t th[NTHREADS];
    for (int i = 0; i < NTHREADS; i++) CHECK(pthread_create(&th[i], NULL, worker, (void *)(intptr_t)i) == 0, "create");
    for (int i = 0; i < NTHREADS; i++) pthread_join(th[i], NULL);
    for (int i = 0; i < NTHREADS; i++) CHECK(mismatches[i] == 0, "thread %d: %d mismatching runs", i, mismatches[i]);
    printf("test_threads: %d threads x %d runs x %zu results compared\n", NTHREADS, REPEAT, reference->n);
    free(reference);
    return dc_check_summary("test_threads");
}
