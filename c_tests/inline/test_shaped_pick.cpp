/* plugins/common/demcontact_shaped.h, the plugins' choice of the shaped entry, against the
 * library: for random models of every shape (Hertz damped or clamped, power law p = 1.7,
 * viscoelastic, linear; every tangential, rolling, twisting and carry code), the evaluation eval_for(m)
 * picks (and pick<V> through a visitor) gives dc_contact_force's status, result and history bits
 * at every step of a contact's trajectory; a model of an instantiated shape (Hertz kernel,
 * tangential linear or Mindlin, twisting none; linear kernel damped with tangential, rolling and
 * twisting none) gets its instantiation, any other the generic
 * entry. pick_common (the LIGGGHTS plugin's choice for all its type pairs): a set of models of
 * one instantiated shape gets it, whatever their parameters; a set with two shapes, or with one
 * model of no instantiated shape, gets the generic entry. The deferred evaluation picked the
 * same way (S::eval_deferred, the LIGGGHTS plugin's pair loop) along the same trajectories: its
 * checks give the library's status and, on DC_OK, the same bits.
 * Argument 1: models (default 20000). Prints "test_shaped_pick: N passed, M failed". */
#include "demcontact_shaped.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#define TEST_RANDOM_SEED 0x9E3779B97F4A7C15ull
#include "test_random.h"

static long n_pass = 0, n_fail = 0;
static void fail(const char *what, long i)
{
    if (n_fail < 10) std::fprintf(stderr, "FAIL %s (%ld)\n", what, i);
    n_fail++;
}

/* A visitor of demcontact_shaped::pick: the shape's name, to count what was picked. */
struct IsGeneric {
    typedef bool type;
    template <class S>
    static type get()
    {
        return false;
    }
};
template <>
IsGeneric::type IsGeneric::get<demcontact_shaped::Generic>()
{
    return true;
}

/* The deferred evaluation per shape (what the LIGGGHTS plugin's pair loop picks): S::eval_deferred. */
typedef int32_t (*EvalDeferred)(const dc_contact_model *, const dc_contact_state *, double, double *,
                                dc_contact_result *, dc_contact_checks *);
template <class S>
int32_t deferred_fn(const dc_contact_model *m, const dc_contact_state *s, double dt, double *h, dc_contact_result *r,
                    dc_contact_checks *c)
{
    return S::eval_deferred(m, s, dt, h, r, c);
}
struct EvalDeferredOf {
    typedef EvalDeferred type;
    template <class S>
    static type get()
    {
        return &deferred_fn<S>;
    }
};

int main(int argc, char **argv)
{
    const long want = argc > 1 ? std::atol(argv[1]) : 20000L;
    const demcontact_shaped::Eval generic = &demcontact_shaped::eval_fn<demcontact_shaped::Generic>;
    long models = 0, shaped = 0, shaped_linear = 0, generic_models = 0, steps_ok = 0, steps_err = 0, steps_deferred = 0;
    while (models < want) {
        dc_contact_spec s;
        dc_contact_spec_init(&s);
        const int normals[5] = {DC_NORMAL_HERTZ, DC_NORMAL_HERTZ, DC_NORMAL_POWERLAW, DC_NORMAL_VISCOELASTIC,
                                DC_NORMAL_LINEAR};
        s.normal = normals[pick(5)];
        s.damping = s.normal == DC_NORMAL_VISCOELASTIC ? DC_DAMPING_NONE
                    : uni() < 0.9                      ? DC_DAMPING_RESTITUTION
                                                       : DC_DAMPING_NONE;
        s.criterion = pick(2) ? DC_END_FORCE : DC_END_OVERLAP;
        s.E1 = logu(6, 11);
        s.nu1 = 0.3;
        s.E2 = uni() < 0.2 ? (double)INFINITY : logu(6, 11);
        s.nu2 = 0.25;
        s.p = 1.7;
        s.k_n = logu(3, 9);
        s.e_n = logu(-2, 0);
        s.visco_A = logu(-9, -5);
        s.tangential = pick(3);
        s.mu = 0.8 * uni();
        s.k_t = logu(3, 8);
        s.e_t = uni() < 0.3 ? 1.0 : logu(-2, 0);
        s.rolling = pick(3);
        s.mu_r = 0.3 * uni();
        s.k_r = uni() < 0.5 ? 0.0 : logu(-6, 0);
        s.eta_r = uni();
        s.twisting = uni() < 0.2 ? DC_TWISTING_SDS : DC_TWISTING_NONE;
        s.mu_tw = logu(-6, -3);
        s.k_tw = logu(-6, 0);
        s.eta_tw = uni();
        dc_contact_model m;
        if (dc_contact_model_init(&s, &m) != DC_OK) continue;
        if (pick(2) && dc_contact_model_set_carry(&m, DC_CARRY_PROJECT) != DC_OK) fail("set_carry", models);
        models++;
        if (dc_contact_model_check_inline(&m) != DC_OK) {
            fail("model check", models);
            continue;
        }
        // what pick must choose
        const int32_t k = m.normal.kernel;
        const bool linear_shape = k == DC_KERNEL_LIN_DAMPED && m.tangential == DC_TANGENTIAL_NONE &&
                                  m.rolling == DC_ROLLING_NONE && m.twisting == DC_TWISTING_NONE;
        const bool instantiated = ((k == DC_KERNEL_HERTZ_DAMPED || k == DC_KERNEL_HERTZ_DAMPED_CLAMPED) &&
                                   m.tangential != DC_TANGENTIAL_NONE && m.twisting == DC_TWISTING_NONE) ||
                                  linear_shape;
        const demcontact_shaped::Eval e = demcontact_shaped::eval_for(m);
        const EvalDeferred ed = demcontact_shaped::pick<EvalDeferredOf>(m);
        if ((ed == &deferred_fn<demcontact_shaped::Generic>) != !instantiated) {
            fail("picked the wrong deferred entry", models);
            continue;
        }
        const bool is_generic = demcontact_shaped::pick<IsGeneric>(m);
        if ((e == generic) == instantiated || is_generic == instantiated || demcontact_shaped::instantiated(m) != instantiated) {
            fail("picked the wrong entry", models);
            continue;
        }
        if (instantiated) shaped++;
        else generic_models++;
        if (linear_shape) shaped_linear++;
        // pick_common over a set of type-pair models: this one, the same shape with other
        // parameters, and (every third model) one of another shape
        {
            dc_contact_spec s2 = s;
            s2.mu = 0.8 * uni();
            s2.e_n = logu(-2, 0);
            s2.E1 = logu(6, 11);
            dc_contact_model set[3];
            set[0] = m;
            if (dc_contact_model_init(&s2, &set[1]) != DC_OK ||
                dc_contact_model_set_carry(&set[1], m.carry) != DC_OK) {
                fail("second model", models);
                continue;
            }
            dc_contact_spec s3 = s;
            s3.tangential = s.tangential == DC_TANGENTIAL_MINDLIN ? DC_TANGENTIAL_LINEAR : DC_TANGENTIAL_MINDLIN;
            const bool mixed = models % 3 == 0;
            if (mixed && (dc_contact_model_init(&s3, &set[2]) != DC_OK ||
                          dc_contact_model_set_carry(&set[2], m.carry) != DC_OK)) {
                fail("third model", models);
                continue;
            }
            const int count = mixed ? 3 : 2;
            const demcontact_shaped::Eval c = demcontact_shaped::pick_common<demcontact_shaped::EvalOf>(
                count, [&set](int i) -> const dc_contact_model & { return set[i]; });
            const demcontact_shaped::Eval expect = mixed ? generic : e;
            if (c != expect || demcontact_shaped::pick_common<demcontact_shaped::EvalOf>(
                                   0, [&set](int i) -> const dc_contact_model & { return set[i]; }) != generic) {
                fail("pick_common", models);
                continue;
            }
            n_pass++;
        }
        // a trajectory: the library and the picked entry, each with its own history
        double hl[DC_CONTACT_HISTORY_MAX] = {0}, hp[DC_CONTACT_HISTORY_MAX] = {0}, hd[DC_CONTACT_HISTORY_MAX] = {0};
        dc_contact_state st;
        std::memset(&st, 0, sizeof st);
        const bool wall = uni() < 0.25;
        st.r1 = logu(-5, -1);
        st.r2 = wall ? (double)INFINITY : logu(-5, -1);
        st.m1 = 2500.0 * 4.18879 * st.r1 * st.r1 * st.r1;
        st.m2 = wall ? (double)INFINITY : 2500.0 * 4.18879 * st.r2 * st.r2 * st.r2;
        vec(st.n, 1.0);
        unit(st.n);
        const double dt = logu(-8, -5), amp = st.r1 * logu(-5, -2), vs = logu(-4, 1), ws = vs / st.r1;
        vec(st.v1, vs);
        vec(st.v2, vs);
        vec(st.w1, ws);
        vec(st.w2, ws);
        for (int i = 0; i < 200; i++) {
            st.overlap = amp * (0.3 + std::sin(0.05 * i));
            for (int j = 0; j < 3; j++) {
                st.n[j] += 1e-3 * (2.0 * uni() - 1.0);
                st.v1[j] += 0.05 * vs * (2.0 * uni() - 1.0);
                st.w2[j] += 0.05 * ws * (2.0 * uni() - 1.0);
            }
            unit(st.n);
            if (i == 150) st.v1[1] = (double)NAN; // a bad input: the same status, nothing written
            if (i == 151) st.v1[1] = 0.0;
            dc_contact_result rl, rp;
            std::memset(&rl, 0x5A, sizeof rl);
            std::memset(&rp, 0x5A, sizeof rp);
            const int32_t sl = dc_contact_force(&m, &st, dt, hl, DC_CONTACT_HISTORY_MAX, &rl);
            const int32_t sp = e(&m, &st, dt, hp, &rp);
            if (sl != sp || std::memcmp(&rl, &rp, sizeof rl) != 0 || std::memcmp(hl, hp, sizeof hl) != 0) {
                fail("picked entry: status/result/history bits", models);
                break;
            }
            // the picked deferred entry, for states the state check accepts (its contract): the
            // library's status from its checks, on DC_OK the same bits; else it restarts from hl
            if (dc_contact_state_check_inline(&st, dt) == DC_OK) {
                dc_contact_checks ck;
                dc_contact_checks_init_inline(&ck);
                dc_contact_result rd;
                std::memset(&rd, 0x5A, sizeof rd);
                const int32_t sd = ed(&m, &st, dt, hd, &rd, &ck);
                const int32_t sc = dc_contact_checks_status_inline(&ck);
                if (sd != DC_OK || sc != sl ||
                    (sl == DC_OK && (std::memcmp(&rl, &rd, sizeof rl) != 0 || std::memcmp(hl, hd, sizeof hl) != 0))) {
                    fail("picked deferred entry: checks/result/history bits", models);
                    break;
                }
                steps_deferred++;
            }
            if (sl != DC_OK) std::memcpy(hd, hl, sizeof hd);
            if (sl == DC_OK) steps_ok++;
            else steps_err++;
            n_pass++;
        }
    }
    std::printf("test_shaped_pick: %ld models (%ld with an instantiated shape, %ld of them the linear "
                "kernel's; %ld generic), %ld ok steps, %ld error steps; the deferred entry in %ld steps\n",
                models, shaped, shaped_linear, generic_models, steps_ok, steps_err, steps_deferred);
    if (!(shaped * 10 > models && shaped_linear * 200 > models && generic_models * 10 > models && steps_err >= models &&
          steps_deferred * 10 > steps_ok * 9))
        fail("coverage", 0);
    std::printf("test_shaped_pick: %ld passed, %ld failed\n", n_pass, n_fail);
    return n_fail ? 1 : 0;
}
