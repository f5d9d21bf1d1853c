// C++ test of include/demcontact.hpp: value-returning wrappers throw demcontact::error on bad
// input, noexcept overloads return the status, and the numbers are those of the C API
// (with --table it prints the common table compared bit for bit with C and Fortran).
#include <demcontact.hpp>

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace dc = demcontact;

static int passed = 0, failed = 0;
#define CHECK(cond)                                                      \
    do {                                                                 \
        if (cond) {                                                      \
            passed++;                                                    \
        } else {                                                         \
            failed++;                                                    \
            std::fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
        }                                                                \
    } while (0)

static std::int64_t bits(double x) {
    std::int64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

static int table() {
    const double ps[] = {1.0, 1.5, 2.0, 3.0};
    const double es[] = {0.1, 0.3, 0.5, 0.7, 0.9};
    for (auto c : {dc::criterion::overlap, dc::criterion::force})
        for (double p : ps)
            for (double e : es) {
                double a = 0, back = 0;
                auto s1 = dc::alpha_from_e(e, p, c, a);
                auto s2 = dc::e_from_alpha(a, p, c, back);
                std::printf("%d %d %d %" PRId64 " %" PRId64 "\n", static_cast<int>(c), static_cast<int>(s1),
                            static_cast<int>(s2), bits(a), bits(back));
            }
    double k = 0, dt = 0, out = 0;
    // Call before printing: argument evaluation order is unspecified.
    auto sk = dc::hertz_stiffness(63e9, 0.23, 1e-3, 70e9, 0.3, 2e-3, k);
    auto sd = dc::dt_crit(1.5, 2.0, 1e4, dt);
    std::printf("%d %" PRId64 "\n", static_cast<int>(sk), bits(k));
    std::printf("%d %" PRId64 "\n", static_cast<int>(sd), bits(dt));
    std::printf("%d\n", static_cast<int>(dc::alpha_from_e(1.5, 1.5, dc::criterion::force, out)));
    return 0;
}

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "--table") == 0) return table();

    // Value-returning form agrees with the C call.
    double a_c = 0;
    CHECK(dc_alpha_from_e(0.5, 1.5, DC_END_FORCE, &a_c) == DC_OK);
    CHECK(dc::alpha_from_e(0.5, 1.5, dc::criterion::force) == a_c);
    CHECK(std::fabs(dc::e_from_alpha(a_c, 1.5, dc::criterion::force) - 0.5) < 1e-15);

    // Bad input throws demcontact::error carrying the status ...
    bool threw = false;
    try {
        (void)dc::alpha_from_e(0.0, 1.5, dc::criterion::overlap);
    } catch (const dc::error& err) {
        threw = err.code() == dc::status::restitution_range &&
                std::strcmp(err.what(), dc::status_str(dc::status::restitution_range)) == 0;
    }
    CHECK(threw);
    // ... and the noexcept overload returns it, leaving the output untouched.
    double out = 42.0;
    CHECK(dc::alpha_from_e(0.5, 0.9, dc::criterion::force, out) == dc::status::exponent_range);
    CHECK(out == 42.0);
    static_assert(noexcept(dc::alpha_from_e(0.5, 0.9, dc::criterion::force, out)), "status overload is noexcept");

    // Hertz helper through the wrapper.
    double k = dc::hertz_stiffness(63e9, 0.23, 1e-3, 63e9, 0.23, 1e-3);
    CHECK(std::fabs(k - 4.0 / 3.0 * 63e9 / (2.0 * (1.0 - 0.23 * 0.23)) * std::sqrt(0.5e-3)) < 1e-14 * k);

    // Force kernels: constructor, scalar, batch over spans, 3D helper.
    ::dc_pair pair = dc::pair_hertz(63e9, 0.23, 63e9, 0.23, 0.5, dc::criterion::force);
    std::vector<double> d{1e-6, 2e-6, 0.0}, vn{0.1, -0.2, 0.1}, r(3, 0.5e-3), m(3, 1e-5), f(3);
    dc::normal_force_batch(pair, dc::span<const double>(d.data(), 3), dc::span<const double>(vn.data(), 3),
                           dc::span<const double>(r.data(), 3), dc::span<const double>(m.data(), 3), dc::span<double>(f));
    CHECK(f[0] == dc::normal_force(pair, d[0], vn[0], r[0], m[0]) && f[2] == 0.0);
    bool short_threw = false;
    try {
        dc::normal_force_batch(pair, dc::span<const double>(d.data(), 3), dc::span<const double>(vn.data(), 2), {}, {}, dc::span<double>(f));
    } catch (const dc::error& err) {
        short_threw = err.code() == dc::status::buffer_too_short;
    }
    CHECK(short_threw);
    {
        // The fast batch through the wrapper: the C function's bits (not the exact batch's: for
        // these pairs some force differs), within the documented 8 ulp of the exact force's terms.
        ::dc_pair gen = dc::pair_powerlaw(1.7, 1e8, 0.4, dc::criterion::force);
        const std::size_t n = 256;
        std::vector<double> dd(n), vv(n), rr(n, 0.5e-3), mm(n, 1e-5), g(n), want(n), exact(n);
        for (std::size_t i = 0; i < n; i++) {
            dd[i] = i % 8 == 0 ? 0.0 : 1e-7 * double(i);
            vv[i] = 0.01 * double(i % 13) - 0.06;
        }
        auto view = [](const std::vector<double>& v) { return dc::span<const double>(v.data(), v.size()); };
        for (const ::dc_pair* p : {&pair, &gen}) {
            dc::normal_force_batch_fast(*p, view(dd), view(vv), view(rr), view(mm), dc::span<double>(g));
            CHECK(::dc_normal_force_batch_fast(p, n, dd.data(), vv.data(), rr.data(), mm.data(), want.data()) == DC_OK);
            CHECK(std::memcmp(g.data(), want.data(), n * sizeof(double)) == 0);
            dc::normal_force_batch(*p, view(dd), view(vv), view(rr), view(mm), dc::span<double>(exact));
            CHECK(std::memcmp(g.data(), exact.data(), n * sizeof(double)) != 0);
            for (std::size_t i = 0; i < n; i++) {
                const double q = p == &pair ? std::sqrt(rr[i] * dd[i]) : std::pow(dd[i], p->h);
                const double terms = p == &pair ? p->k * q * dd[i] + std::fabs(p->c * std::sqrt(mm[i] * q) * vv[i])
                                                : p->k * dd[i] * q * q + std::fabs(p->c * std::sqrt(mm[i]) * q * vv[i]);
                CHECK(std::fabs(g[i] - exact[i]) <= 8 * 2.220446049250313e-16 * terms);
                if (dd[i] == 0.0) CHECK(g[i] == 0.0);
            }
        }
    }
    dc::vec3 F = dc::normal_force_3d(pair, {0, 0, 0}, {0, 0, 0}, 1e-3, 1e-5, {1.999e-3, 0, 0}, {-0.1, 0, 0}, 1e-3, 1e-5);
    CHECK(F.x < 0.0 && F.y == 0.0 && F.z == 0.0);  // sphere 1 pushed away from sphere 2 (at +x)

    // Trajectory into vectors through spans; ends at the contact duration.
    {
        const double alpha = dc::alpha_from_e(0.5, 1.5, dc::criterion::overlap);
        std::vector<double> t(65), dl(65), vel(65), fo(65);
        dc::contact_trajectory(1.5, alpha, 1.0, 100.0, 1e-3, dc::criterion::overlap, DC_LEVEL_MAX, dc::span<double>(t),
                               dc::span<double>(dl), dc::span<double>(vel), dc::span<double>(fo));
        const double tau = dc::contact_duration(1.5, alpha, 1.0, 100.0, dc::criterion::overlap);
        CHECK(std::fabs(t[64] - tau) <= 1e-13 * tau);
        CHECK(std::fabs(vel[64] + 0.5) <= 1e-12);
    }

    // Full contact: spec by field, model, history, one step, bad input throws with its status.
    {
        ::dc_contact_spec spec = dc::contact_spec();
        spec.normal = DC_NORMAL_HERTZ;
        spec.E1 = 63e9;
        spec.nu1 = 0.23;
        spec.E2 = INFINITY;
        spec.nu2 = 0.3;
        spec.tangential = DC_TANGENTIAL_MINDLIN;
        spec.mu = 0.3;
        ::dc_contact_model model = dc::contact_model_init(spec);
        std::vector<double> hist(dc::contact_history_len(model), 0.0);
        CHECK(hist.size() == 6);
        ::dc_contact_state st{};
        st.n[1] = 1.0;
        st.overlap = 1e-6;
        st.v1[0] = 0.5;
        st.r1 = 1e-3;
        st.r2 = INFINITY;
        st.m1 = 1e-5;
        st.m2 = INFINITY;
        ::dc_contact_result r = dc::contact_force(model, st, 1e-8, dc::span<double>(hist));
        CHECK(r.f_n > 0.0 && r.ft[0] < 0.0 && r.force[1] == r.f_n && r.torque2[2] == 0.0);
        CHECK(hist[3] > 0.0);  // the tangential spring moved with the contact point (+x)
        bool threw = false;
        try {
            st.n[1] = 0.5;
            dc::contact_force(model, st, 1e-8, dc::span<double>(hist));
        } catch (const dc::error& err) {
            threw = err.code() == dc::status::not_unit;
        }
        CHECK(threw);
        ::dc_contact_result out{};
        CHECK(dc::contact_force(model, st, 1e-8, dc::span<double>(hist.data(), 2), out) == dc::status::buffer_too_short);
        // Two contacts through the fused batch: the second has a NaN overlap, the first is
        // computed exactly as dc_contact_force, the second's outputs are NaN.
        {
            st.n[1] = 1.0;
            std::vector<double> nv{0, 1, 0, 0, 1, 0}, ov{1e-6, NAN}, v1{0.5, 0, 0, 0.5, 0, 0}, z(6, 0.0);
            std::vector<double> r1{1e-3, 1e-3}, r2{INFINITY, INFINITY}, m1{1e-5, 1e-5}, m2{INFINITY, INFINITY};
            std::vector<double> h(12, 0.0), fn(2, 0.0), f(6, 0.0), t1(6, 0.0), t2(6, 0.0);
            ::dc_contact_batch b{2, 6, nv.data(), ov.data(), v1.data(), z.data(), z.data(), z.data(), r1.data(),
                                 r2.data(), m1.data(), m2.data(), h.data(), fn.data(), f.data(), t1.data(), t2.data()};
            std::size_t bad = 99;
            CHECK(dc::contact_force_batch_fused(model, b, 1e-8, bad) == dc::status::not_finite && bad == 1);
            std::vector<double> h1(6, 0.0);
            ::dc_contact_result r0 = dc::contact_force(model, st, 1e-8, dc::span<double>(h1));
            CHECK(fn[0] == r0.f_n && f[0] == r0.force[0] && h[3] == h1[3] && std::isnan(fn[1]) && std::isnan(t2[5]) &&
                  h[6] == 0.0);
            b.n = 1;
            bad = 99;
            CHECK(dc::contact_force_batch_fused(model, b, 1e-8, bad) == dc::status::ok && bad == 99);
        }
        // Step-aware damping (a damped model with the rescaled Mindlin law): the same model as
        // the C call, one more double of history; the argument unchanged; the statuses through
        // the exception and the noexcept form.
        {
            ::dc_contact_spec sp = spec;
            sp.damping = DC_DAMPING_RESTITUTION;
            sp.e_n = 0.5;
            sp.tangential = DC_TANGENTIAL_MINDLIN_RESCALE;
            const ::dc_contact_model dm = dc::contact_model_init(sp);
            ::dc_contact_model c = dm;
            CHECK(::dc_contact_model_set_step(&c, 2e-7, DC_INTEGRATOR_VELOCITY_VERLET) == DC_OK);
            ::dc_contact_model s = dc::set_step(dm, 2e-7);
            CHECK(std::memcmp(&s, &c, sizeof c) == 0);
            CHECK(dc::contact_history_len(s) == dc::contact_history_len(dm) + 1);
            ::dc_contact_model e = dm;
            c = dm;
            CHECK(::dc_contact_model_set_step(&c, 2e-7, DC_INTEGRATOR_SYMPLECTIC_EULER) == DC_OK);
            CHECK(dc::set_step(dm, 2e-7, dc::integrator::symplectic_euler, e) == dc::status::ok);
            CHECK(std::memcmp(&e, &c, sizeof c) == 0);
            ::dc_contact_model bad = dm;
            CHECK(dc::set_step(dm, -1.0, dc::integrator::velocity_verlet, bad) == dc::status::not_positive);
            CHECK(std::memcmp(&bad, &dm, sizeof dm) == 0);
            CHECK(dc::set_step(dm, 2e-7, static_cast<dc::integrator>(7), bad) == dc::status::integrator);
            bool threw = false;
            try {
                dc::set_step(dm, NAN);
            } catch (const dc::error& err) {
                threw = err.code() == dc::status::not_finite;
            }
            CHECK(threw);
            // The energy ledger: the same force and history as contact_force, and the C ledger.
            ::dc_contact_state ws = st;
            std::vector<double> ha(dc::contact_history_len(s), 0.0), hb(ha.size(), 0.0), hc(ha.size(), 0.0);
            ::dc_contact_result rc{};
            ::dc_contact_energy ec{};
            CHECK(::dc_contact_force_energy(&s, &ws, 2e-7, hc.data(), hc.size(), &rc, &ec) == DC_OK);
            dc::contact_step cs = dc::contact_force_energy(s, ws, 2e-7, dc::span<double>(ha));
            ::dc_contact_result rf = dc::contact_force(s, ws, 2e-7, dc::span<double>(hb));
            CHECK(std::memcmp(&cs.result, &rc, sizeof rc) == 0 && std::memcmp(&cs.energy, &ec, sizeof ec) == 0);
            CHECK(std::memcmp(&rf, &rc, sizeof rc) == 0 && ha == hb && ha == hc);
            CHECK(cs.energy.dissipated >= 0.0);
        }
        spec.mu = NAN;
        CHECK(dc::contact_model_init(spec, model) == dc::status::spec_unset);
    }

    // The planner: the C result bit for bit, the member at fault on an error.
    {
        ::dc_plan_input in = dc::plan_input();
        in.youngs = 7e10;
        in.poisson = 0.22;
        in.density = 2500;
        in.restitution = 0.5;
        in.radius_min = 1e-3;
        in.radius_max = 2e-3;
        in.v_max = 2;
        in.depth = 0.5;
        in.overlap_tol = 0.01;
        in.e_tol = 0.01;
        ::dc_plan_result c{};
        CHECK(::dc_plan(&in, &c, nullptr) == DC_OK);
        ::dc_plan_result r = dc::plan(in);
        CHECK(std::memcmp(&r, &c, sizeof c) == 0 && r.youngs_soft > 0.0 && r.dt > 0.0);
        in.radius_max = 5e-4;
        std::int32_t field = -1;
        ::dc_plan_result untouched{};
        CHECK(dc::plan(in, untouched, field) == dc::status::plan_range && field == DC_PLAN_FIELD_RADIUS_MAX);
        bool threw = false;
        try {
            dc::plan(in);
        } catch (const dc::error& err) {
            threw = err.code() == dc::status::plan_range;
        }
        CHECK(threw);
    }

    // span view over a vector.
    std::vector<double> v{1.0, 2.0, 3.0};
    dc::span<double> s(v);
    CHECK(s.size() == 3 && s[2] == 3.0);
    CHECK(std::string(dc::version()) == "0.1.0");

    std::printf("test_cpp_wrapper: %d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
