/* Per-contact cost of one contact called at a time from a C loop (as the LAMMPS/LIGGGHTS plugins
 * do): the library's dc_contact_force against the header-only dc_contact_force_inline, its
 * checked entry dc_contact_force_checked_inline (the model checked once, as the plugins' generic
 * path) and its shaped entry dc_contact_force_shaped_inline with the shape as constants (the
 * plugins' instantiated path), all the same bits (ctest inline_contact_*), in the same run. Two
 * models: Hertz + Mindlin, and Hertz alone (normal-only: no history, no frame step). Thread CPU
 * time, the variants interleaved, fastest of 9 rounds of 20 x 10,000 contacts (each call
 * advances its history). Model as the settled bed of docs/benchmarks.md (E = 5 MPa, nu = 0.3,
 * e = 0.5, Mindlin, mu = 0.5, e_t = 0.5); overlaps up to 1e-5 m of 1 mm spheres, random normals,
 * spins up to 0.5 rad/s.
 * Run: cmake --build build --target contact_inline_bench && build/bench/contact_inline_bench. */
#define _POSIX_C_SOURCE 199309L
#include <demcontact_inline.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}
static unsigned long long s = 88172645463325252ull;
static double u(void) {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    return (s >> 11) / 9007199254740992.0;
}
enum { N = 10000, V = 4 };
static dc_contact_state st[N];
static double h[V][N][10];
static const char *const NAMES[V] = {"dc_contact_force", "dc_contact_force_inline", "dc_contact_force_checked_inline",
                                     "dc_contact_force_shaped_inline"};

static int32_t call(int v, const dc_contact_model *m, int i, dc_contact_result *r) {
    const double dt = 6e-6;
    switch (v) {
    case 0: return dc_contact_force(m, &st[i], dt, h[v][i], 10, r);
    case 1: return dc_contact_force_inline(m, &st[i], dt, h[v][i], 10, r);
    case 2: return dc_contact_force_checked_inline(m, &st[i], dt, h[v][i], r);
    default:
        if (m->tangential == DC_TANGENTIAL_MINDLIN)
            return dc_contact_force_shaped_inline(m, DC_KERNEL_HERTZ_DAMPED_CLAMPED, DC_TANGENTIAL_MINDLIN,
                                                  DC_ROLLING_NONE, DC_TWISTING_NONE, DC_CARRY_ROTATE, &st[i], dt,
                                                  h[v][i], r);
        return dc_contact_force_shaped_inline(m, DC_KERNEL_HERTZ_DAMPED_CLAMPED, DC_TANGENTIAL_NONE, DC_ROLLING_NONE,
                                              DC_TWISTING_NONE, DC_CARRY_ROTATE, &st[i], dt, h[v][i], r);
    }
}

int main(void) {
    for (int i = 0; i < N; i++) {
        double *n = st[i].n;
        n[0] = u() - .5;
        n[1] = u() - .5;
        n[2] = u() - .5;
        const double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int j = 0; j < 3; j++) {
            n[j] /= l;
            st[i].v1[j] = 0.01 * (u() - .5);
            st[i].v2[j] = 0;
            st[i].w1[j] = (u() - .5);
            st[i].w2[j] = (u() - .5);
        }
        st[i].overlap = 1e-5 * u();
        st[i].r1 = st[i].r2 = 1e-3;
        st[i].m1 = st[i].m2 = 1.05e-5;
    }
    printf("| model | entry | ns/contact | ratio to dc_contact_force |\n|---|---|---|---|\n");
    for (int tang = 0; tang < 2; tang++) {
        dc_contact_spec sp;
        dc_contact_spec_init(&sp);
        sp.normal = DC_NORMAL_HERTZ;
        sp.damping = DC_DAMPING_RESTITUTION;
        sp.e_n = 0.5;
        sp.E1 = sp.E2 = 5e6;
        sp.nu1 = sp.nu2 = 0.3;
        sp.tangential = tang == 0 ? DC_TANGENTIAL_MINDLIN : DC_TANGENTIAL_NONE;
        sp.mu = 0.5;
        sp.e_t = 0.5;
        dc_contact_model m;
        if (dc_contact_model_init(&sp, &m) != DC_OK || dc_contact_model_check_inline(&m) != DC_OK ||
            dc_contact_model_shape_inline(&m, DC_KERNEL_HERTZ_DAMPED_CLAMPED, sp.tangential, DC_ROLLING_NONE,
                                          DC_TWISTING_NONE, DC_CARRY_ROTATE) != DC_OK) {
            fprintf(stderr, "contact_inline_bench: model not made as expected\n");
            return 1;
        }
        double best[V] = {1e9, 1e9, 1e9, 1e9}, sink = 0;
        for (int t = 0; t < 9; t++)
            for (int v = 0; v < V; v++) {
                const double t0 = now();
                for (int k = 0; k < 20; k++)
                    for (int i = 0; i < N; i++) {
                        dc_contact_result r;
                        const int32_t q = call(v, &m, i, &r);
                        if (q != DC_OK) {
                            fprintf(stderr, "contact_inline_bench: %s returned %" PRId32 "\n", NAMES[v], q);
                            return 1;
                        }
                        sink += r.force[0];
                    }
                const double ns = (now() - t0) * 1e9 / (20.0 * N);
                if (ns < best[v]) best[v] = ns;
            }
        for (int v = 0; v < V; v++)
            printf("| %s | `%s` | %.1f | %.2f |\n", tang == 0 ? "Hertz + Mindlin" : "Hertz, normal-only", NAMES[v],
                   best[v], best[v] / best[0]);
        if (!(sink == sink)) return 1;
    }
    return 0;
}
