/* Force-kernel benchmark: demcontact's batch (runtime CPU dispatch) and scalar kernels, called
 * from C through the ABI, and its header-only kernels (demcontact_inline.h) inlined into a C loop,
 * against hand-written C loops of the same expressions (force_baseline.c compiled with -O3, with
 * -O3 -fno-math-errno and with -O3 -march=native -fno-math-errno), and the memory roofline (a
 * STREAM copy and a loop with the Hertz batch's streams), all in the same run, in-cache and
 * streaming sizes.
 *
 *   force_bench            full run, prints a markdown table (ns per contact, ratios) and the
 *                          ratios the issue asks for
 *   force_bench --smoke    tiny sizes: checks that every variant computes the same forces (the
 *                          inline kernels: the library's bits)
 *
 * Timing: clock_gettime(CLOCK_THREAD_CPUTIME_ID) (CPU time of this thread: time slices lost to
 * other processes on a shared machine do not count); every variant is timed in each of TRIALS
 * rounds (variants interleaved, so machine noise hits all alike) and the fastest round is
 * reported. */
#define _POSIX_C_SOURCE 199309L
#include <demcontact.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define DECL(base)                                                                              \
    void hertz_loop_##base(size_t, double, double, const double *, const double *,              \
                           const double *, const double *, double *);                           \
    void pow_loop_##base(size_t, double, double, double, const double *, const double *,        \
                         const double *, double *);                                             \
    void hertz_inline_loop_##base(size_t, const dc_pair *, const double *, const double *,      \
                                  const double *, const double *, double *);                    \
    void hertz_kernel_loop_##base(size_t, const dc_pair *, const double *, const double *,      \
                                  const double *, const double *, double *);                    \
    void pow_kernel_loop_##base(size_t, const dc_pair *, const double *, const double *,        \
                                const double *, double *);                                      \
    void pow_inline_loop_##base(size_t, const dc_pair *, const double *, const double *,        \
                                const double *, double *);                                      \
    void copy_loop_##base(size_t, const double *, double *);                                    \
    void sum_loop_##base(size_t, const double *, const double *, const double *, const double *, \
                         double *);
DECL(plain)
DECL(fast)
DECL(native)
DECL(native_nofma)
DECL(v3)

typedef struct {
    size_t n;
    const double *d, *vn, *r, *m;
    double *out;
    const dc_pair *pair;
} job;

enum { H_PLAIN, H_FAST, H_NATIVE, H_NATIVE_NOFMA, H_V3, H_BATCH, H_BATCH_FAST, H_SCALAR, H_INL_PLAIN, H_INL_FAST, H_KER_FAST,
       P_PLAIN, P_FAST, P_NATIVE, P_BATCH, P_BATCH_FAST, P_SCALAR, P_INL_PLAIN, P_INL_FAST, P_KER_NATIVE,
       M_COPY, M_SUM, NVAR };
static const char *NAMES[NVAR] = {
    "Hertz: C loop, -O3",
    "Hertz: C loop, -O3 -fno-math-errno",
    "Hertz: C loop, -O3 -march=native -fno-math-errno",
    "Hertz: C loop, -O3 -march=native -fno-math-errno -ffp-contract=off (no FMA: the batch's rounding)",
#ifdef DC_V3_IS_NATIVE
    "Hertz: C loop, -O3 -march=native -fno-math-errno (the compiler has no -march=x86-64-v3)",
#else
    "Hertz: C loop, -O3 -march=x86-64-v3 -fno-math-errno (an AVX2 machine's native)",
#endif
    "Hertz: `dc_normal_force_batch` (runtime dispatch)",
    "Hertz: `dc_normal_force_batch_fast` (runtime dispatch; FMA)",
    "Hertz: `dc_normal_force` in a C loop",
    "Hertz: `dc_normal_force_inline` in the C loop, -O3",
    "Hertz: `dc_normal_force_inline` in the C loop, -O3 -fno-math-errno",
    "Hertz: `dc_normal_force_kernel_inline` (constant kernel) in the C loop, -O3 -fno-math-errno",
    "p = 1.7: C loop (pow), -O3",
    "p = 1.7: C loop (pow), -O3 -fno-math-errno",
    "p = 1.7: C loop (pow), -O3 -march=native -fno-math-errno",
    "p = 1.7: `dc_normal_force_batch` (runtime dispatch)",
    "p = 1.7: `dc_normal_force_batch_fast` (runtime dispatch; power within 4 ulp)",
    "p = 1.7: `dc_normal_force` in a C loop",
    "p = 1.7: `dc_normal_force_inline` in the C loop, -O3",
    "p = 1.7: `dc_normal_force_inline` in the C loop, -O3 -fno-math-errno",
    "p = 1.7: `dc_normal_force_kernel_inline` (constant kernel) in the C loop, -O3 -march=native -fno-math-errno",
    "memory: STREAM copy, per double copied",
    "memory: out = d + vn + r + m (the Hertz batch's 40 bytes)",
};
static int is_pow(int v) { return v >= P_PLAIN && v <= P_KER_NATIVE; }

static void run(int var, const job *j) {
    const dc_pair *p = j->pair;
    switch (var) {
    case H_PLAIN: hertz_loop_plain(j->n, p->k, p->c, j->d, j->vn, j->r, j->m, j->out); break;
    case H_FAST: hertz_loop_fast(j->n, p->k, p->c, j->d, j->vn, j->r, j->m, j->out); break;
    case H_NATIVE: hertz_loop_native(j->n, p->k, p->c, j->d, j->vn, j->r, j->m, j->out); break;
    case H_NATIVE_NOFMA:
        hertz_loop_native_nofma(j->n, p->k, p->c, j->d, j->vn, j->r, j->m, j->out);
        break;
    case H_V3: hertz_loop_v3(j->n, p->k, p->c, j->d, j->vn, j->r, j->m, j->out); break;
    case H_INL_PLAIN: hertz_inline_loop_plain(j->n, p, j->d, j->vn, j->r, j->m, j->out); break;
    case H_INL_FAST: hertz_inline_loop_fast(j->n, p, j->d, j->vn, j->r, j->m, j->out); break;
    case H_KER_FAST: hertz_kernel_loop_fast(j->n, p, j->d, j->vn, j->r, j->m, j->out); break;
    case P_KER_NATIVE: pow_kernel_loop_native(j->n, p, j->d, j->vn, j->m, j->out); break;
    case P_PLAIN: pow_loop_plain(j->n, p->k, p->c, p->h, j->d, j->vn, j->m, j->out); break;
    case P_FAST: pow_loop_fast(j->n, p->k, p->c, p->h, j->d, j->vn, j->m, j->out); break;
    case P_NATIVE: pow_loop_native(j->n, p->k, p->c, p->h, j->d, j->vn, j->m, j->out); break;
    case P_INL_PLAIN: pow_inline_loop_plain(j->n, p, j->d, j->vn, j->m, j->out); break;
    case P_INL_FAST: pow_inline_loop_fast(j->n, p, j->d, j->vn, j->m, j->out); break;
    case M_COPY: copy_loop_native(j->n, j->d, j->out); break;
    case M_SUM: sum_loop_native(j->n, j->d, j->vn, j->r, j->m, j->out); break;
    case H_BATCH:
    case P_BATCH:
        if (dc_normal_force_batch(p, j->n, j->d, j->vn, j->r, j->m, j->out) != DC_OK) abort();
        break;
    case H_BATCH_FAST:
    case P_BATCH_FAST:
        if (dc_normal_force_batch_fast(p, j->n, j->d, j->vn, j->r, j->m, j->out) != DC_OK)
            abort();
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
     * the larger term (gcc contracts to FMA with -march=native, Rust never does). The inline
     * kernels must give the library's bits exactly (whatever the flags). */
    int bad = 0;
    for (int v = 0; v < M_COPY; v++) {
        job j = {sizes[0], d, vn, r, m, out, is_pow(v) ? &gen : &hertz};
        if (v == H_PLAIN || v == P_PLAIN) {
            j.out = ref;
            run(v, &j);
            continue;
        }
        run(v, &j);
        const dc_pair *p = j.pair;
        /* (the no-FMA native loop: the library's bits too, the same operations rounded alike) */
        const int exact = v == H_NATIVE_NOFMA || v == H_INL_PLAIN || v == H_INL_FAST || v == H_KER_FAST ||
                          v == P_INL_PLAIN || v == P_INL_FAST || v == P_KER_NATIVE;
        for (size_t i = 0; i < sizes[0]; i++) {
            double s = d[i] <= 0.0 ? 0.0
                       : !is_pow(v) ? p->k * sqrt(r[i] * d[i]) * d[i] +
                                          p->c * sqrt(m[i] * sqrt(r[i] * d[i])) * fabs(vn[i])
                                    : p->k * pow(d[i], p->p) +
                                          p->c * sqrt(m[i]) * pow(d[i], p->h) * fabs(vn[i]);
            const double lib = dc_normal_force(p, d[i], vn[i], r[i], m[i]);
            /* The fast batch: within its stated 8 ulp of the terms of the library's force. */
            const int off = (v == P_BATCH_FAST || v == H_BATCH_FAST) &&
                            fabs(out[i] - lib) > 8.0 * DBL_EPSILON * s;
            if (off || (exact ? memcmp(&out[i], &lib, sizeof lib) != 0
                              : fabs(out[i] - ref[i]) > 1e-14 * s)) {
                fprintf(stderr, "%s: contact %zu: %.17g vs C %.17g, library %.17g\n", NAMES[v], i,
                        out[i], ref[i], lib);
                bad = 1;
                break;
            }
        }
    }
    if (bad) return 1;
    if (smoke) {
        for (int v = 0; v < NVAR; v++) {
            job j = {sizes[1], d, vn, r, m, out, is_pow(v) ? &gen : &hertz};
            run(v, &j);
        }
        printf("force_bench --smoke: all %d force variants agree (inline kernels bit for bit)\n",
               M_COPY);
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
                job j = {n, d, vn, r, m, out, is_pow(v) ? &gen : &hertz};
                /* ~16M contacts per Hertz/memory measurement, ~4M for the pow path */
                size_t total = is_pow(v) ? (size_t)4 << 20 : (size_t)16 << 20;
                size_t reps = total / n ? total / n : 1;
                run(v, &j); /* warm */
                double t0 = now();
                for (size_t k = 0; k < reps; k++) run(v, &j);
                double ns = (now() - t0) * 1e9 / (double)(reps * n);
                if (ns < best[s][v]) best[s][v] = ns;
            }
    }
    static const char *const FLAVOURS[3] = {"baseline x86-64", "AVX2 + FMA", "AVX-512F"};
    const int level = dc_dispatch_level();
    printf("batches' vector flavour: %s (dc_dispatch_level; DEMCONTACT_DISPATCH=baseline or =avx2 caps it)\n\n",
           level >= 0 && level <= 2 ? FLAVOURS[level] : "unknown");
    printf("| variant | ns/contact in-cache (n = %zu) | ratio | ns/contact streaming (n = %zu) | ratio |\n",
           sizes[0], sizes[1]);
    printf("|---|---|---|---|---|\n");
    for (int v = 0; v < NVAR; v++) {
        int base = is_pow(v) ? P_PLAIN : H_PLAIN;
        printf("| %s | %.2f | %.2f | %.2f | %.2f |\n", NAMES[v], best[0][v], best[0][v] / best[0][base],
               best[1][v], best[1][v] / best[1][base]);
    }
    printf("\nratios: to the plain -O3 C loop of the same law (memory rows: to the Hertz one).\n\n");
    /* The summary figures (ratios to the baselines of this run) quoted in docs/reference/benchmarks.md. */
    /* Memory traffic per contact of the Hertz batch: 4 loads + 1 store + the store's
     * write-allocate read = 48 bytes; of the copy, per double: 24 bytes (load, write-allocate,
     * store). The roofline is the copy's bandwidth applied to the batch's traffic. */
    const double roof = best[1][M_COPY] * 48.0 / 24.0;
    printf("| ratio (same run) | in-cache | streaming | target |\n|---|---|---|---|\n");
    printf("| Hertz batch / C loop -O3 -fno-math-errno | %.2f | %.2f | <= 1.0 |\n",
           best[0][H_BATCH] / best[0][H_FAST], best[1][H_BATCH] / best[1][H_FAST]);
    printf("| Hertz batch / C loop -O3 -march=native -fno-math-errno | %.2f | %.2f | <= 1.0 |\n",
           best[0][H_BATCH] / best[0][H_NATIVE], best[1][H_BATCH] / best[1][H_NATIVE]);
    printf("| Hertz batch / the same -march=native loop without FMA contraction | %.2f | %.2f | |\n",
           best[0][H_BATCH] / best[0][H_NATIVE_NOFMA], best[1][H_BATCH] / best[1][H_NATIVE_NOFMA]);
    printf("| Hertz fast batch (FMA) / C loop -O3 -march=native -fno-math-errno | %.2f | %.2f | <= 1.0 |\n",
           best[0][H_BATCH_FAST] / best[0][H_NATIVE], best[1][H_BATCH_FAST] / best[1][H_NATIVE]);
    printf("| Hertz fast batch (FMA) / C loop -O3 -march=x86-64-v3 -fno-math-errno | %.2f | %.2f | <= 1.0 with DEMCONTACT_DISPATCH=avx2 |\n",
           best[0][H_BATCH_FAST] / best[0][H_V3], best[1][H_BATCH_FAST] / best[1][H_V3]);
    printf("| Hertz batch / C loop -O3 -march=x86-64-v3 -fno-math-errno | %.2f | %.2f | |\n",
           best[0][H_BATCH] / best[0][H_V3], best[1][H_BATCH] / best[1][H_V3]);
    printf("| p = 1.7 batch / Hertz batch | %.2f | %.2f | <= 1.5 |\n",
           best[0][P_BATCH] / best[0][H_BATCH], best[1][P_BATCH] / best[1][H_BATCH]);
    printf("| p = 1.7 batch / C loop with pow -O3 | %.2f | %.2f | <= 0.5 |\n",
           best[0][P_BATCH] / best[0][P_PLAIN], best[1][P_BATCH] / best[1][P_PLAIN]);
    printf("| p = 1.7 fast batch (power within 4 ulp) / Hertz batch | %.2f | %.2f | <= 1.5 |\n",
           best[0][P_BATCH_FAST] / best[0][H_BATCH], best[1][P_BATCH_FAST] / best[1][H_BATCH]);
    printf("| p = 1.7 fast batch / Hertz fast batch | %.2f | %.2f | |\n",
           best[0][P_BATCH_FAST] / best[0][H_BATCH_FAST], best[1][P_BATCH_FAST] / best[1][H_BATCH_FAST]);
    printf("| p = 1.7 fast batch / C loop with pow -O3 | %.2f | %.2f | <= 0.5 |\n",
           best[0][P_BATCH_FAST] / best[0][P_PLAIN], best[1][P_BATCH_FAST] / best[1][P_PLAIN]);
    printf("| Hertz inline in the C loop / hand-written formula, -O3 | %.2f | %.2f | <= 1.0 |\n",
           best[0][H_INL_PLAIN] / best[0][H_PLAIN], best[1][H_INL_PLAIN] / best[1][H_PLAIN]);
    printf("| Hertz inline in the C loop / hand-written formula, -O3 -fno-math-errno | %.2f | %.2f | <= 1.0 |\n",
           best[0][H_INL_FAST] / best[0][H_FAST], best[1][H_INL_FAST] / best[1][H_FAST]);
    printf("| Hertz constant-kernel inline / hand-written formula, -O3 -fno-math-errno | %.2f | %.2f | <= 1.0 |\n",
           best[0][H_KER_FAST] / best[0][H_FAST], best[1][H_KER_FAST] / best[1][H_FAST]);
    printf("| p = 1.7 inline in the C loop / hand-written formula with pow, -O3 | %.2f | %.2f | |\n",
           best[0][P_INL_PLAIN] / best[0][P_PLAIN], best[1][P_INL_PLAIN] / best[1][P_PLAIN]);
    printf("| p = 1.7 constant-kernel inline / C loop with pow, both -O3 -march=native -fno-math-errno | %.2f | %.2f | |\n",
           best[0][P_KER_NATIVE] / best[0][P_NATIVE], best[1][P_KER_NATIVE] / best[1][P_NATIVE]);
    printf("\nstreaming roofline (4 M contacts, 48 bytes of traffic each): STREAM copy %.1f GB/s "
           "(24 bytes per double incl. write-allocate) -> %.2f ns/contact; Hertz batch %.2f "
           "ns/contact = %.2f of the roofline (target >= 0.8); the loop with the same streams "
           "(out = d + vn + r + m, -march=native): %.2f ns = %.2f of the roofline, batch / it: %.2f\n",
           24.0 / best[1][M_COPY], roof, best[1][H_BATCH], roof / best[1][H_BATCH],
           best[1][M_SUM], roof / best[1][M_SUM], best[1][M_SUM] / best[1][H_BATCH]);
    free(buf);
    return 0;
}
