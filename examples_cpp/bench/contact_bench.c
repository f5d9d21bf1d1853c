/* Full-contact benchmark: dc_contact_force_batch (normal only, + Mindlin tangential, + EPSD
 * rolling), called from C through the ABI, against hand-written C loops of the same formulas
 * (contact_baseline.c, -O3 and -O3 -fno-math-errno) and against the normal-force-only path
 * (host computes vn, R*, m* + dc_normal_force_batch + host forms F n), all in the same run; and
 * the step-aware models (dc_contact_model_set_step at the run's dt, velocity Verlet) against the
 * plain ones, batch and per contact, normal-only and Mindlin, each on its own histories laid out
 * as dc_contact_history_len says (the inputs do not change between calls, so after the first
 * call every contact is past its onset: the steady cost, which a contact pays on all its steps
 * but the first; benches/step_exact.rs adds contacts at their onset).
 *
 *   contact_bench            full run, prints a markdown table (ns per contact, ratios)
 *   contact_bench --smoke    small sizes: checks that the C loops and the ABI agree
 *
 * Inputs: sphere pairs, radii 0.1-1 mm, ~9 % not touching, random unit normals, relative
 * velocities up to 1 m/s, spins up to 500 rad/s, glass (E 63 GPa, nu 0.23), e = 0.5 clamped,
 * mu = 0.5, e_t = 0.5. Timing as force_bench.c: thread CPU time, variants interleaved, fastest
 * of TRIALS rounds. Every call advances the history (a real time step). */
#define _POSIX_C_SOURCE 199309L
#include <demcontact.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct {
    double kf, c, g8, zeta, mt, mu, dt;
} hmc_params;

#define DECL(B)                                                                                          \
    void normal_loop_##B(size_t, const hmc_params *, const double *, const double *, const double *,    \
                         const double *, const double *, const double *, const double *, const double *, \
                         double *, double *);                                                            \
    void hmc_loop_##B(size_t, const hmc_params *, const double *, const double *, const double *,       \
                      const double *, const double *, const double *, const double *, const double *,    \
                      const double *, const double *, double *, double *, double *, double *, double *);
DECL(plain)
DECL(fast)

static const dc_contact_model *MODELS[5]; /* normal, Mindlin, Mindlin + EPSD; step-aware normal, Mindlin */
static size_t STEP_LEN[2];                 /* their history lengths (the strides of their own buffers) */
static double *STEP_HIST[2];
static hmc_params P;

typedef struct {
    size_t n;
    double *nv, *ov, *v1, *v2, *w1, *w2, *r1, *r2, *m1, *m2, *hist, *f_n, *force, *t1, *t2, *vn, *reff, *meff;
} arrays;

/* Contact i's overlap rate as the library computes it ((v2 - v1) . n, > 0 approaching). */
static double overlap_rate(const arrays *a, size_t i) {
    const double *e = a->nv + 3 * i, *x = a->v1 + 3 * i, *y = a->v2 + 3 * i;
    return (y[0] - x[0]) * e[0] + (y[1] - x[1]) * e[1] + (y[2] - x[2]) * e[2];
}

enum {
    N_C_PLAIN,
    N_C_FAST,
    N_TODAY,
    N_KERNEL,
    N_BATCH,
    N_FUSED,
    N_SCALAR_TODAY,
    N_SCALAR,
    T_C_PLAIN,
    T_C_FAST,
    T_BATCH,
    T_FUSED,
    T_SCALAR,
    R_BATCH,
    R_FUSED,
    R_SCALAR,
    NS_BATCH,
    NS_SCALAR,
    TS_BATCH,
    TS_SCALAR,
    NVAR
};
static const char *NAMES[NVAR] = {
    "normal: C loop, -O3",
    "normal: C loop, -O3 -fno-math-errno",
    "normal: host vn/R*/m* + dc_normal_force_batch + F n",
    "normal: dc_normal_force_batch alone (vn, R*, m* precomputed)",
    "normal: dc_contact_force_batch",
    "normal: dc_contact_force_batch_fused",
    "normal: host vn/R*/m* + dc_normal_force (unchecked) per contact + F n",
    "normal: dc_contact_force per contact",
    "+ Mindlin tangential: C loop, -O3",
    "+ Mindlin tangential: C loop, -O3 -fno-math-errno",
    "+ Mindlin tangential: dc_contact_force_batch",
    "+ Mindlin tangential: dc_contact_force_batch_fused",
    "+ Mindlin tangential: dc_contact_force per contact",
    "+ Mindlin + EPSD rolling: dc_contact_force_batch",
    "+ Mindlin + EPSD rolling: dc_contact_force_batch_fused",
    "+ Mindlin + EPSD rolling: dc_contact_force per contact",
    "normal, step-aware: dc_contact_force_batch",
    "normal, step-aware: dc_contact_force per contact",
    "+ Mindlin tangential, step-aware: dc_contact_force_batch",
    "+ Mindlin tangential, step-aware: dc_contact_force per contact",
};

/* One dc_contact_force call per contact, as a host's pair loop does: state from the arrays,
 * history at stride, force and torques stored. */
static void scalar_loop(const dc_contact_model *m, const arrays *a, size_t stride) {
    for (size_t i = 0; i < a->n; i++) {
        dc_contact_state st;
        memcpy(st.n, a->nv + 3 * i, sizeof st.n);
        st.overlap = a->ov[i];
        memcpy(st.v1, a->v1 + 3 * i, sizeof st.v1);
        memcpy(st.v2, a->v2 + 3 * i, sizeof st.v2);
        memcpy(st.w1, a->w1 + 3 * i, sizeof st.w1);
        memcpy(st.w2, a->w2 + 3 * i, sizeof st.w2);
        st.r1 = a->r1[i], st.r2 = a->r2[i], st.m1 = a->m1[i], st.m2 = a->m2[i];
        dc_contact_result r;
        double *h = stride ? a->hist + stride * i : NULL;
        if (dc_contact_force(m, &st, P.dt, h, stride, &r) != DC_OK) abort();
        memcpy(a->force + 3 * i, r.force, sizeof r.force);
        memcpy(a->t1 + 3 * i, r.torque1, sizeof r.torque1);
        memcpy(a->t2 + 3 * i, r.torque2, sizeof r.torque2);
        a->f_n[i] = r.f_n;
    }
}



static void run(int var, const arrays *a) {
    size_t n = a->n;
    dc_contact_batch b = {.n = n, .history_stride = DC_CONTACT_HISTORY_MAX, .normal = a->nv, .overlap = a->ov,
                          .v1 = a->v1, .v2 = a->v2, .w1 = a->w1, .w2 = a->w2, .r1 = a->r1, .r2 = a->r2,
                          .m1 = a->m1, .m2 = a->m2, .history = a->hist, .f_n = a->f_n, .force = a->force,
                          .torque1 = a->t1, .torque2 = a->t2};
    switch (var) {
    case N_C_PLAIN: normal_loop_plain(n, &P, a->nv, a->ov, a->v1, a->v2, a->r1, a->r2, a->m1, a->m2, a->f_n, a->force); break;
    case N_C_FAST: normal_loop_fast(n, &P, a->nv, a->ov, a->v1, a->v2, a->r1, a->r2, a->m1, a->m2, a->f_n, a->force); break;
    case N_TODAY:
        for (size_t i = 0; i < n; i++) {
            a->vn[i] = overlap_rate(a, i);
            a->reff[i] = 1.0 / (1.0 / a->r1[i] + 1.0 / a->r2[i]);
            a->meff[i] = 1.0 / (1.0 / a->m1[i] + 1.0 / a->m2[i]);
        }
        /* fall through */
    case N_KERNEL:
        if (dc_normal_force_batch(&MODELS[0]->normal, n, a->ov, a->vn, a->reff, a->meff, a->f_n) != DC_OK) abort();
        if (var == N_TODAY)
            for (size_t i = 0; i < n; i++)
                for (int k = 0; k < 3; k++) a->force[3 * i + k] = a->f_n[i] * a->nv[3 * i + k];
        break;
    case N_SCALAR_TODAY:
        for (size_t i = 0; i < n; i++) {
            const double *e = a->nv + 3 * i;
            double vn = overlap_rate(a, i);
            double reff = 1.0 / (1.0 / a->r1[i] + 1.0 / a->r2[i]);
            double meff = 1.0 / (1.0 / a->m1[i] + 1.0 / a->m2[i]);
            double f = dc_normal_force(&MODELS[0]->normal, a->ov[i], vn, reff, meff);
            a->f_n[i] = f;
            for (int k = 0; k < 3; k++) a->force[3 * i + k] = f * e[k];
        }
        break;
    case N_SCALAR: scalar_loop(MODELS[0], a, 0); break;
    case T_SCALAR: scalar_loop(MODELS[1], a, 6); break;
    case R_SCALAR: scalar_loop(MODELS[2], a, DC_CONTACT_HISTORY_MAX); break;
    case NS_SCALAR:
    case TS_SCALAR: {
        const int k = var == NS_SCALAR ? 0 : 1;
        arrays d = *a;
        d.hist = STEP_HIST[k];
        scalar_loop(MODELS[3 + k], &d, STEP_LEN[k]);
        break;
    }
    case NS_BATCH:
    case TS_BATCH: {
        const int k = var == NS_BATCH ? 0 : 1;
        b.history = STEP_HIST[k];
        b.history_stride = STEP_LEN[k];
        if (k == 0) {
            b.w1 = b.w2 = NULL;
            b.torque1 = b.torque2 = NULL;
        }
        const int32_t s = dc_contact_force_batch(MODELS[3 + k], &b, P.dt);
        if (s != DC_OK) {
            fprintf(stderr, "%s: %s\n", NAMES[var], dc_status_str(s));
            abort();
        }
        break;
    }
    case T_C_PLAIN:
    case T_C_FAST: {
        /* the C loops keep a 6-double history: use the tail of the same buffer layout */
        void (*f)(size_t, const hmc_params *, const double *, const double *, const double *, const double *,
                  const double *, const double *, const double *, const double *, const double *, const double *,
                  double *, double *, double *, double *, double *) = var == T_C_PLAIN ? hmc_loop_plain : hmc_loop_fast;
        f(n, &P, a->nv, a->ov, a->v1, a->v2, a->w1, a->w2, a->r1, a->r2, a->m1, a->m2, a->hist, a->f_n, a->force,
          a->t1, a->t2);
        break;
    }
    default: {
        int m = (var == N_BATCH || var == N_FUSED) ? 0 : (var == T_BATCH || var == T_FUSED) ? 1 : 2;
        int fused = var == N_FUSED || var == T_FUSED || var == R_FUSED;
        if (m == 0) {
            b.w1 = b.w2 = NULL;
            b.torque1 = b.torque2 = NULL;
            b.history = NULL;
            b.history_stride = 0;
        }
        if (m == 1) b.history_stride = 6;
        size_t bad = 0;
        int32_t s = fused ? dc_contact_force_batch_fused(MODELS[m], &b, P.dt, &bad) : dc_contact_force_batch(MODELS[m], &b, P.dt);
        if (s != DC_OK) {
            fprintf(stderr, "%s: %s\n", NAMES[var], dc_status_str(s));
            abort();
        }
    }
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

static int make(dc_contact_model *m, int tangential, int rolling) {
    dc_contact_spec s;
    if (dc_contact_spec_init(&s) != DC_OK) return 0;
    s.normal = DC_NORMAL_HERTZ;
    s.E1 = s.E2 = 63e9;
    s.nu1 = s.nu2 = 0.23;
    s.damping = DC_DAMPING_RESTITUTION;
    s.e_n = 0.5;
    s.criterion = DC_END_FORCE;
    s.tangential = tangential;
    s.mu = 0.5;
    s.e_t = 0.5;
    s.rolling = rolling;
    s.mu_r = 0.1;
    s.eta_r = 0.3;
    return dc_contact_model_init(&s, m) == DC_OK;
}

int main(int argc, char **argv) {
    int smoke = argc > 1 && strcmp(argv[1], "--smoke") == 0;
    dc_contact_model normal, hm, hmr;
    if (!make(&normal, DC_TANGENTIAL_NONE, DC_ROLLING_NONE) || !make(&hm, DC_TANGENTIAL_MINDLIN, DC_ROLLING_NONE) ||
        !make(&hmr, DC_TANGENTIAL_MINDLIN, DC_ROLLING_EPSD)) {
        fprintf(stderr, "model construction failed\n");
        return 1;
    }
    MODELS[0] = &normal, MODELS[1] = &hm, MODELS[2] = &hmr;
    P = (hmc_params){.kf = hm.normal.k, .c = hm.normal.c, .g8 = hm.kt, .zeta = hm.zeta_t,
                     .mt = hm.kappa / (1.0 + hm.kappa), .mu = hm.mu, .dt = 1e-8};
    dc_contact_model normal_step = normal, hm_step = hm;
    if (dc_contact_model_set_step(&normal_step, P.dt, DC_INTEGRATOR_VELOCITY_VERLET) != DC_OK ||
        dc_contact_model_set_step(&hm_step, P.dt, DC_INTEGRATOR_VELOCITY_VERLET) != DC_OK ||
        dc_contact_history_len(&normal_step, &STEP_LEN[0]) != DC_OK ||
        dc_contact_history_len(&hm_step, &STEP_LEN[1]) != DC_OK) {
        fprintf(stderr, "step-aware model construction failed\n");
        return 1;
    }
    MODELS[3] = &normal_step, MODELS[4] = &hm_step;
    const size_t sizes[2] = {smoke ? 37 : 1024, smoke ? 1000 : (size_t)1 << 18};
    const size_t nmax = sizes[1];
    STEP_HIST[0] = calloc(STEP_LEN[0] * nmax, sizeof(double));
    STEP_HIST[1] = calloc(STEP_LEN[1] * nmax, sizeof(double));
    if (!STEP_HIST[0] || !STEP_HIST[1]) return 1;
    /* one allocation, arrays staggered by 72 doubles against 4K aliasing */
    const size_t per[18] = {3, 1, 3, 3, 3, 3, 1, 1, 1, 1, DC_CONTACT_HISTORY_MAX, 1, 3, 3, 3, 1, 1, 1};
    size_t total = 0;
    for (int k = 0; k < 18; k++) total += per[k] * nmax + 72;
    double *buf = calloc(total, sizeof(double));
    if (!buf) return 1;
    double *ptr[18];
    for (int k = 0, at = 0; k < 18; k++) {
        ptr[k] = buf + at;
        at += (int)(per[k] * nmax + 72);
    }
    arrays a = {nmax, ptr[0], ptr[1], ptr[2], ptr[3], ptr[4], ptr[5], ptr[6], ptr[7], ptr[8], ptr[9],
                ptr[10], ptr[11], ptr[12], ptr[13], ptr[14], ptr[15], ptr[16], ptr[17]};
    for (size_t i = 0; i < nmax; i++) {
        double z = 2.0 * uni() - 1.0, ph = 6.283185307179586 * uni(), s = sqrt(1.0 - z * z);
        a.nv[3 * i] = s * cos(ph), a.nv[3 * i + 1] = s * sin(ph), a.nv[3 * i + 2] = z;
        a.r1[i] = 1e-4 * (1.0 + 9.0 * uni());
        a.r2[i] = 1e-4 * (1.0 + 9.0 * uni());
        a.m1[i] = 2500.0 * 4.18879 * a.r1[i] * a.r1[i] * a.r1[i];
        a.m2[i] = 2500.0 * 4.18879 * a.r2[i] * a.r2[i] * a.r2[i];
        a.ov[i] = a.r1[i] * (0.011 * uni() - 0.001);
        for (int k = 0; k < 3; k++) {
            a.v1[3 * i + k] = uni() - 0.5;
            a.v2[3 * i + k] = uni() - 0.5;
            a.w1[3 * i + k] = 1000.0 * (uni() - 0.5);
            a.w2[3 * i + k] = 1000.0 * (uni() - 0.5);
        }
    }

    /* Agreement: the C HMC loop and the ABI over 3 steps from zero history (1e-12 of the largest
     * force term); the normal C loop and both normal ABI paths. */
    {
        size_t n = sizes[0];
        double *ref = malloc(4 * 3 * n * sizeof(double)), *hist = calloc(DC_CONTACT_HISTORY_MAX * n, sizeof(double));
        double *hist2 = calloc(DC_CONTACT_HISTORY_MAX * n, sizeof(double));
        double *hist3 = calloc(DC_CONTACT_HISTORY_MAX * n, sizeof(double));
        if (!ref || !hist || !hist2 || !hist3) return 1;
        arrays c = a;
        c.n = n;
        c.hist = hist;
        memset(a.hist, 0, DC_CONTACT_HISTORY_MAX * n * sizeof(double));
        for (int step = 0; step < 3; step++) {
            run(T_C_FAST, &c);
            memcpy(ref, c.force, 3 * n * sizeof(double));
            memcpy(ref + 3 * n, c.t1, 3 * n * sizeof(double));
            /* dc_contact_force_batch with stride 6 (same layout as the C loop's history), then
             * dc_contact_force per contact on its own history */
            for (int v = T_BATCH; v <= T_SCALAR; v++) {
                arrays d = a;
                d.n = n;
                if (v == T_SCALAR) d.hist = hist2;
                if (v == T_FUSED) d.hist = hist3;
                run(v, &d);
                for (size_t i = 0; i < 3 * n; i++) {
                    double scale = fabs(c.f_n[i / 3]) + 1e-30;
                    if (fabs(ref[i] - d.force[i]) > 1e-12 * scale ||
                        fabs(ref[3 * n + i] - d.t1[i]) > 1e-12 * scale * a.r1[i / 3]) {
                        fprintf(stderr, "step %d: HMC C loop and %s differ at %zu: %.17g vs %.17g\n", step,
                                NAMES[v], i, ref[i], d.force[i]);
                        return 1;
                    }
                }
            }
        }
        arrays d = a;
        d.n = n;
        run(N_C_FAST, &d);
        memcpy(ref, d.force, 3 * n * sizeof(double));
        for (int v = N_TODAY; v <= N_SCALAR; v++) {
            if (v == N_KERNEL) continue;
            run(v, &d);
            for (size_t i = 0; i < 3 * n; i++)
                if (fabs(ref[i] - d.force[i]) > 1e-14 * fabs(d.f_n[i / 3])) {
                    fprintf(stderr, "%s differs from the C loop at %zu\n", NAMES[v], i);
                    return 1;
                }
        }
        /* The step-aware batch and per-contact paths: the same bits over 3 steps from zero
         * history (the first step is every contact's first: deep random overlaps, which take
         * R = 1 and no onset correction), each on its own histories. */
        for (int k = 0; k < 2; k++) {
            double *hb = calloc(STEP_LEN[k] * n, sizeof(double)), *hs = calloc(STEP_LEN[k] * n, sizeof(double));
            double *fb = malloc(3 * n * sizeof(double));
            if (!hb || !hs || !fb) return 1;
            double *keep = STEP_HIST[k];
            for (int step = 0; step < 3; step++) {
                arrays d = a;
                d.n = n;
                STEP_HIST[k] = hb;
                run(k == 0 ? NS_BATCH : TS_BATCH, &d);
                memcpy(fb, d.force, 3 * n * sizeof(double));
                STEP_HIST[k] = hs;
                run(k == 0 ? NS_SCALAR : TS_SCALAR, &d);
                if (memcmp(fb, d.force, 3 * n * sizeof(double)) != 0 ||
                    memcmp(hb, hs, STEP_LEN[k] * n * sizeof(double)) != 0) {
                    fprintf(stderr, "step %d: %s and %s differ\n", step, NAMES[k == 0 ? NS_BATCH : TS_BATCH],
                            NAMES[k == 0 ? NS_SCALAR : TS_SCALAR]);
                    return 1;
                }
            }
            /* the step-aware model acts: its onset force differs from the plain model's, with
             * each approaching contact at an overlap a drift reaches (a = overlap/(vn dt) = 1/2,
             * an onset; the random overlaps are far deeper) */
            double *onset_ov = malloc(n * sizeof(double));
            if (!onset_ov) return 1;
            for (size_t i = 0; i < n; i++) {
                const double vn = overlap_rate(&a, i);
                onset_ov[i] = vn > 0.0 ? 0.5 * vn * P.dt : a.ov[i];
            }
            arrays d = a;
            d.n = n;
            d.ov = onset_ov;
            memset(hb, 0, STEP_LEN[k] * n * sizeof(double));
            STEP_HIST[k] = hb;
            run(k == 0 ? NS_BATCH : TS_BATCH, &d);
            memcpy(fb, d.force, 3 * n * sizeof(double));
            memset(a.hist, 0, DC_CONTACT_HISTORY_MAX * n * sizeof(double));
            run(k == 0 ? N_BATCH : T_BATCH, &d);
            if (memcmp(fb, d.force, 3 * n * sizeof(double)) == 0) {
                fprintf(stderr, "%s: the same forces as the plain model at the onset\n", NAMES[k == 0 ? NS_BATCH : TS_BATCH]);
                return 1;
            }
            STEP_HIST[k] = keep;
            free(onset_ov);
            free(hb);
            free(hs);
            free(fb);
        }
        free(ref);
        free(hist);
        free(hist2);
        free(hist3);
    }
    if (smoke) {
        for (int v = 0; v < NVAR; v++) {
            arrays d = a;
            d.n = sizes[1];
            run(v, &d);
        }
        printf("contact_bench --smoke: the C loops and the ABI agree, the step-aware batch and per-contact calls "
               "agree bit for bit\n");
        free(buf);
        free(STEP_HIST[0]);
        free(STEP_HIST[1]);
        return 0;
    }
    const int TRIALS = 7;
    double best[2][NVAR];
    for (int s = 0; s < 2; s++) {
        size_t n = sizes[s];
        for (int v = 0; v < NVAR; v++) best[s][v] = 1e30;
        arrays d = a;
        d.n = n;
        run(N_TODAY, &d); /* vn, R*, m* arrays for the kernel-alone variant */
        for (int t = 0; t < TRIALS; t++)
            for (int v = 0; v < NVAR; v++) {
                size_t reps = ((size_t)4 << 20) / n;
                if (reps == 0) reps = 1;
                run(v, &d);
                double t0 = now();
                for (size_t k = 0; k < reps; k++) run(v, &d);
                double ns = (now() - t0) * 1e9 / (double)(reps * n);
                if (ns < best[s][v]) best[s][v] = ns;
            }
    }
    printf("| variant | ns/contact in-cache (n = %zu) | ratio | ns/contact streaming (n = %zu) | ratio |\n", sizes[0],
           sizes[1]);
    printf("|---|---|---|---|---|\n");
    for (int v = 0; v < NVAR; v++) {
        int base = (v < T_C_PLAIN || v == NS_BATCH || v == NS_SCALAR) ? N_C_FAST : T_C_FAST;
        printf("| %s | %.2f | %.2f | %.2f | %.2f |\n", NAMES[v], best[0][v], best[0][v] / best[0][base], best[1][v],
               best[1][v] / best[1][base]);
    }
    printf("\nratios: to the -O3 -fno-math-errno C loop of the same stages. normal-only batch / today's path "
           "(host prepass + dc_normal_force_batch + F n): %.2f in-cache, %.2f streaming\n",
           best[0][N_BATCH] / best[0][N_TODAY], best[1][N_BATCH] / best[1][N_TODAY]);
    printf("normal-only fused batch / today's path: %.2f in-cache, %.2f streaming; fused / checked batch: normal "
           "%.2f / %.2f, Mindlin %.2f / %.2f, Mindlin + EPSD %.2f / %.2f (in-cache / streaming)\n",
           best[0][N_FUSED] / best[0][N_TODAY], best[1][N_FUSED] / best[1][N_TODAY], best[0][N_FUSED] / best[0][N_BATCH],
           best[1][N_FUSED] / best[1][N_BATCH], best[0][T_FUSED] / best[0][T_BATCH], best[1][T_FUSED] / best[1][T_BATCH],
           best[0][R_FUSED] / best[0][R_BATCH], best[1][R_FUSED] / best[1][R_BATCH]);
    printf("per-contact calls: dc_contact_force normal-only / host + dc_normal_force: %.2f in-cache, %.2f streaming; "
           "dc_contact_force Mindlin / C loop: %.2f in-cache, %.2f streaming\n",
           best[0][N_SCALAR] / best[0][N_SCALAR_TODAY], best[1][N_SCALAR] / best[1][N_SCALAR_TODAY],
           best[0][T_SCALAR] / best[0][T_C_FAST], best[1][T_SCALAR] / best[1][T_C_FAST]);
    printf("step-aware / plain (same entry, steady contacts): normal batch %.3f / %.3f, normal per contact %.3f / %.3f, "
           "Mindlin batch %.3f / %.3f, Mindlin per contact %.3f / %.3f (in-cache / streaming)\n",
           best[0][NS_BATCH] / best[0][N_BATCH], best[1][NS_BATCH] / best[1][N_BATCH],
           best[0][NS_SCALAR] / best[0][N_SCALAR], best[1][NS_SCALAR] / best[1][N_SCALAR],
           best[0][TS_BATCH] / best[0][T_BATCH], best[1][TS_BATCH] / best[1][T_BATCH],
           best[0][TS_SCALAR] / best[0][T_SCALAR], best[1][TS_SCALAR] / best[1][T_SCALAR]);
    free(buf);
    free(STEP_HIST[0]);
    free(STEP_HIST[1]);
    return 0;
}
