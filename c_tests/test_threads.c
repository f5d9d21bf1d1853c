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
