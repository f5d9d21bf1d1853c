/* Force-kernel benchmark: demcontact's batch and scalar kernels, called from C through the ABI,
 * against hand-written C loops of the same expressions (force_baseline.c compiled with -O3 and
 * with -O3 -fno-math-errno), all in the same run, in-cache and streaming sizes.
 *
 *   force_bench            full run, prints a markdown table (ns per contact, ratios)
 *   force_bench --smoke    tiny sizes: checks that every variant computes the same forces
 *
 * Timing: clock_gettime(CLOCK_THREAD_CPUTIME_ID) (CPU time of this thread: time slices lost to
 * other processes on a shared machine do not count); every variant is timed in each of TRIALS
 * rounds (variants interleaved, so machine noise hits all alike) and the fastest round is
 * reported. */
#define _POSIX_C_SOURCE 199309L
#include <demcontact.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

void hertz_loop_plain(size_t, double, double, const double *, const double *, const double *,
                      const double *, double *);
void hertz_loop_fast(size_t, double, double, const double *, const double *, const double *,
                     const double *, double *);
void pow_loop_plain(size_t, double, double, double, const double *, const double *,
                    const double *, double *);
void pow_loop_fast(size_t, double, double, double, const double *, const double *,
                   const double *, double *);

typedef struct {
    size_t n;
    const double *d, *vn, *r, *m;
    double *out;
    const dc_pair *pair;
} job;

enum { HERTZ_PLAIN, HERTZ_FAST, HERTZ_BATCH, HERTZ_SCALAR, POW_PLAIN, POW_FAST, POW_BATCH,
       POW_SCALAR, NVAR };
static const char *NAMES[NVAR] = {
    "Hertz: C loop, -O3",
    "Hertz: C loop, -O3 -fno-math-errno",
    "Hertz: dc_normal_force_batch",
    "Hertz: dc_normal_force in a C loop",
    "p = 1.7: C loop (pow), -O3",
    "p = 1.7: C loop (pow), -O3 -fno-math-errno",
    "p = 1.7: dc_normal_force_batch",
    "p = 1.7: dc_normal_force in a C loop",
};

static void run(int var, const job *j) {
    const dc_pair *p = j->pair;
    switch (var) {
    case HERTZ_PLAIN: hertz_loop_plain(j->n, p->k, p->c, j->d, j->vn, j->r, j->m, j->out); break;
    case HERTZ_FAST: hertz_loop_fast(j->n, p->k, p->c, j->d, j->vn, j->r, j->m, j->out); break;
    case POW_PLAIN: pow_loop_plain(j->n, p->k, p->c, p->h, j->d, j->vn, j->m, j->out); break;
    case POW_FAST: pow_loop_fast(j->n, p->k, p->c, p->h, j->d, j->vn, j->m, j->out); break;
    case HERTZ_BATCH:
    case POW_BATCH:
        if (dc_normal_force_batch(p, j->n, j->d, j->vn, j->r, j->m, j->out) != DC_OK) abort();
        break;
    default:
        for (size_t i = 0; i < j->n; i++)
            j->out[i] = dc_normal_force(p, j->d[i], j->vn[i], j->r[i], j->m[i]);
    }
}

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static uint64_t rng = 0x243F6A8885A308D3ull;
static double uni(void) {
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

int main(int argc, char **argv) {
    int smoke = argc > 1 && strcmp(argv[1], "--smoke") == 0;
    dc_pair hertz, gen;
    /* Glass beads, e = 0.5, clamped (DC_END_FORCE); general p = 1.7 with a fixed k. */
    if (dc_pair_hertz(63e9, 0.23, 63e9, 0.23, 0.5, DC_END_FORCE, &hertz) != DC_OK ||
        dc_pair_powerlaw(1.7, 1e8, 0.5, DC_END_FORCE, &gen) != DC_OK) {
        fprintf(stderr, "pair construction failed\n");
        return 1;
    }
    const size_t sizes[2] = {smoke ? 37 : 1024, smoke ? 1000 : (size_t)4 << 20};
    const size_t nmax = sizes[1];
    /* Arrays staggered by 72 doubles (576 bytes) so that they do not share address bits mod
     * 4 KiB (4K aliasing between the store stream and the load streams would distort timings). */
    const size_t stride = nmax + 72;
    double *buf = malloc(6 * stride * sizeof(double));
    if (!buf) return 1;
    double *d = buf, *vn = buf + stride, *r = buf + 2 * stride, *m = buf + 3 * stride;
    double *out = buf + 4 * stride, *ref = buf + 5 * stride;
    memset(out, 0, 2 * stride * sizeof(double)); /* fault the pages in before timing */
    for (size_t i = 0; i < nmax; i++) {
        r[i] = 1e-4 * (1.0 + 9.0 * uni());            /* polydisperse radii 0.1..1 mm */
        d[i] = r[i] * (0.011 * uni() - 0.001);        /* ~9% not touching */
        vn[i] = 2.0 * uni() - 1.0;                    /* compressing and unloading */
        m[i] = 1e-6 * (1.0 + 99.0 * uni());           /* effective masses */
    }

    /* Every variant computes the same forces: same expression; rounding may differ by ulps of
     * the larger term (gcc contracts to FMA with -march=native, Rust never does). */
    int bad = 0;
    for (int v = 0; v < NVAR; v++) {
        job j = {sizes[0], d, vn, r, m, out, v < POW_PLAIN ? &hertz : &gen};
        if (v == HERTZ_PLAIN || v == POW_PLAIN) {
            j.out = ref;
            run(v, &j);
            continue;
        }
        run(v, &j);
        const dc_pair *p = j.pair;
        for (size_t i = 0; i < sizes[0]; i++) {
            double s = d[i] <= 0.0 ? 0.0
                       : v < POW_PLAIN ? p->k * sqrt(r[i] * d[i]) * d[i] +
                                              p->c * sqrt(m[i] * sqrt(r[i] * d[i])) * fabs(vn[i])
                                        : p->k * pow(d[i], p->p) +
                                              p->c * sqrt(m[i]) * pow(d[i], p->h) * fabs(vn[i]);
            if (fabs(out[i] - ref[i]) > 1e-14 * s) {
                fprintf(stderr, "%s: contact %zu: %.17g vs C %.17g\n", NAMES[v], i, out[i], ref[i]);
                bad = 1;
                break;
            }
        }
    }
    if (bad) return 1;
    if (smoke) {
        for (int v = 0; v < NVAR; v++) {
            job j = {sizes[1], d, vn, r, m, out, v < POW_PLAIN ? &hertz : &gen};
            run(v, &j);
        }
        printf("force_bench --smoke: all %d variants agree\n", NVAR);
        free(buf);
        return 0;
    }

    const int TRIALS = 9;
    double best[2][NVAR];
    for (int s = 0; s < 2; s++) {
        size_t n = sizes[s];
        for (int v = 0; v < NVAR; v++) best[s][v] = 1e30;
        for (int t = 0; t < TRIALS; t++)
            for (int v = 0; v < NVAR; v++) {
                job j = {n, d, vn, r, m, out, v < POW_PLAIN ? &hertz : &gen};
                /* ~16M contacts per Hertz measurement, ~4M for the pow path */
                size_t total = v < POW_PLAIN ? (size_t)16 << 20 : (size_t)4 << 20;
                size_t reps = total / n ? total / n : 1;
                run(v, &j); /* warm */
                double t0 = now();
                for (size_t k = 0; k < reps; k++) run(v, &j);
                double ns = (now() - t0) * 1e9 / (double)(reps * n);
                if (ns < best[s][v]) best[s][v] = ns;
            }
    }
    printf("| variant | ns/contact in-cache (n = %zu) | ratio | ns/contact streaming (n = %zu) | ratio |\n",
           sizes[0], sizes[1]);
    printf("|---|---|---|---|---|\n");
    for (int v = 0; v < NVAR; v++) {
        int base = v < POW_PLAIN ? HERTZ_PLAIN : POW_PLAIN;
        printf("| %s | %.2f | %.2f | %.2f | %.2f |\n", NAMES[v], best[0][v], best[0][v] / best[0][base],
               best[1][v], best[1][v] / best[1][base]);
    }
    printf("\nratios: to the plain -O3 C loop of the same law. Targets: batch vs vectorised C "
           "(Hertz, in-cache) %.2f (<= 1), scalar vs plain C %.2f (<= 1.3)\n",
           best[0][HERTZ_BATCH] / best[0][HERTZ_FAST], best[0][HERTZ_SCALAR] / best[0][HERTZ_PLAIN]);
    free(buf);
    return 0;
}
