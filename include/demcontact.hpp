// demcontact for C++17: header-only wrapper over the C API in demcontact.h.
//
//  * namespace demcontact; strong enums `status` and `criterion`;
//  * for every status-returning C function `dc_f(args..., T *out)`, a value-returning
//    `demcontact::f(args...)` that throws demcontact::error, and a `noexcept` overload
//    `demcontact::f(args..., T& out)` that returns the status (generated, in
//    demcontact_generated.hpp, from the C header by `cargo test --test bindings`);
//  * `span`-like views for batched kernels (C++17, no <span> needed);
//  * hand-written here: the contact-model helpers (contact_spec, set_step, contact_force,
//    contact_force_energy, the batches) and the planner (plan_input, plan);
//  * no RAII types: the library owns nothing that would need releasing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "demcontact.h"

namespace demcontact {

enum class status : std::int32_t;

/// Message of a status (static storage).
inline const char* status_str(status s) noexcept { return ::dc_status_str(static_cast<std::int32_t>(s)); }

/// Library version string.
inline const char* version() noexcept { return ::dc_version(); }

/// The exception thrown by the value-returning wrappers; carries the C status.
class error : public std::runtime_error {
public:
    explicit error(status s) : std::runtime_error(status_str(s)), status_(s) {}
    /// The status the C function returned.
    status code() const noexcept { return status_; }

private:
    status status_;
};

namespace detail {
inline void check(std::int32_t s) {
    if (s != DC_OK) throw error(static_cast<status>(s));
}
}  // namespace detail

/// A non-owning view of contiguous elements (the C++17 stand-in for std::span).
template <class T>
class span {
public:
    constexpr span() noexcept = default;
    constexpr span(T* data, std::size_t size) noexcept : data_(data), size_(size) {}
    template <class C>
    constexpr span(C& c) noexcept : data_(c.data()), size_(c.size()) {}
    constexpr T* data() const noexcept { return data_; }
    constexpr std::size_t size() const noexcept { return size_; }
    constexpr T& operator[](std::size_t i) const noexcept { return data_[i]; }
    constexpr T* begin() const noexcept { return data_; }
    constexpr T* end() const noexcept { return data_ + size_; }

private:
    T* data_ = nullptr;
    std::size_t size_ = 0;
};

}  // namespace demcontact

#include "demcontact_generated.hpp"

namespace demcontact {

namespace detail {
/// The C batch `f` (dc_normal_force_batch or dc_normal_force_batch_fast) over views.
template <class F>
inline void batch(F f, const ::dc_pair& pair, span<const double> overlap, span<const double> vn,
                  span<const double> r_eff, span<const double> m_eff, span<double> force_out) {
    const std::size_t n = overlap.size();
    auto fits = [n](std::size_t m) { return m == 0 || m >= n; };
    if (force_out.size() < n || !fits(vn.size()) || !fits(r_eff.size()) || !fits(m_eff.size()))
        throw error(status::buffer_too_short);
    check(f(&pair, n, overlap.data(), vn.size() ? vn.data() : nullptr, r_eff.size() ? r_eff.data() : nullptr,
            m_eff.size() ? m_eff.data() : nullptr, force_out.data()));
}
}  // namespace detail

/// Normal forces of n contacts of one pair (dc_normal_force_batch) from structure-of-arrays
/// views. Arrays the pair's model does not read may be empty views (passed as NULL). Throws
/// demcontact::error on a non-OK status (also when a non-empty view is shorter than `overlap`).
inline void normal_force_batch(const ::dc_pair& pair, span<const double> overlap, span<const double> vn,
                               span<const double> r_eff, span<const double> m_eff, span<double> force_out) {
    detail::batch(::dc_normal_force_batch, pair, overlap, vn, r_eff, m_eff, force_out);
}

/// The same with dc_normal_force_batch_fast: a few ulp from exact for speed (see the C docs).
inline void normal_force_batch_fast(const ::dc_pair& pair, span<const double> overlap, span<const double> vn,
                                    span<const double> r_eff, span<const double> m_eff, span<double> force_out) {
    detail::batch(::dc_normal_force_batch_fast, pair, overlap, vn, r_eff, m_eff, force_out);
}

/// 3-vector for the geometry helper.
struct vec3 {
    double x, y, z;
};

/// Normal force on sphere 1 (dc_normal_force_3d); sphere 2 receives the opposite. Throws on error.
inline vec3 normal_force_3d(const ::dc_pair& pair, const vec3& x1, const vec3& v1, double R1, double m1,
                            const vec3& x2, const vec3& v2, double R2, double m2) {
    const double a1[3] = {x1.x, x1.y, x1.z}, b1[3] = {v1.x, v1.y, v1.z};
    const double a2[3] = {x2.x, x2.y, x2.z}, b2[3] = {v2.x, v2.y, v2.z};
    double f[3] = {0, 0, 0};
    detail::check(::dc_normal_force_3d(&pair, a1, b1, R1, m1, a2, b2, R2, m2, f));
    return vec3{f[0], f[1], f[2]};
}

}  // namespace demcontact

namespace demcontact {

/// Samples one power-law collision at n = t.size() points (dc_contact_trajectory) into the four
/// views (each at least t.size() long). Throws demcontact::error on a non-OK status.
inline void contact_trajectory(double p, double alpha, double v0, double omega0, double mass, criterion c,
                               std::int32_t level, span<double> t, span<double> delta, span<double> v,
                               span<double> force) {
    const std::size_t n = t.size();
    std::size_t len = n;
    for (std::size_t m : {delta.size(), v.size(), force.size()}) len = m < len ? m : len;
    detail::check(::dc_contact_trajectory(p, alpha, v0, omega0, mass, static_cast<std::int32_t>(c), level, n,
                                          t.data(), delta.data(), v.data(), force.data(), len));
}

}  // namespace demcontact

namespace demcontact {

/// A dc_contact_spec filled by dc_contact_spec_init (version, size, defaults): set the fields
/// your scene needs by name, then call contact_model_init(spec).
inline ::dc_contact_spec contact_spec() {
    ::dc_contact_spec s{};
    detail::check(::dc_contact_spec_init(&s));
    return s;
}

/// The host's time integrator for set_step (DC_INTEGRATOR_*).
enum class integrator : std::int32_t {
    velocity_verlet = DC_INTEGRATOR_VELOCITY_VERLET,
    symplectic_euler = DC_INTEGRATOR_SYMPLECTIC_EULER,
};

/// `model` made to realise its target e_n at the host's step `dt` in `integ`
/// (dc_contact_model_set_step), returned as a new model; the argument is unchanged. Making a
/// model step-aware makes its history one double longer (contact_history_len); calling set_step
/// again on a step-aware model, as a host does when its dt changes, keeps the calibration and
/// the history length and stores the new dt. An undamped law (e_n = 1) is returned unchanged.
/// Pass the force calls this same dt (see contact_force). Throws demcontact::error (not_finite,
/// not_positive, integrator, step_unsupported: a normal law other than a Tsuji power law or
/// Hertz, i.e. viscoelastic, DMT, elastic-plastic, JKR; step_unreachable; result_range: dt so
/// small that dt over the t_H prefactor underflows, e.g. 5e-324; contact_model_invalid).
inline ::dc_contact_model set_step(const ::dc_contact_model& model, double dt,
                                   integrator integ = integrator::velocity_verlet) {
    ::dc_contact_model m = model;
    detail::check(::dc_contact_model_set_step(&m, dt, static_cast<std::int32_t>(integ)));
    return m;
}

/// noexcept form of set_step: returns the status; `out` written only on status::ok (it may be
/// `model` itself).
inline status set_step(const ::dc_contact_model& model, double dt, integrator integ,
                       ::dc_contact_model& out) noexcept {
    ::dc_contact_model m = model;
    const status s = static_cast<status>(::dc_contact_model_set_step(&m, dt, static_cast<std::int32_t>(integ)));
    if (s == status::ok) out = m;
    return s;
}

/// Doubles of history one contact of `model` needs (dc_contact_history_len). Throws on error.
inline std::size_t contact_history_len(const ::dc_contact_model& model) {
    std::size_t n = 0;
    detail::check(::dc_contact_history_len(&model, &n));
    return n;
}

/// One contact (dc_contact_force): `history` is this contact's state (zeros for a new contact),
/// updated in place. Throws demcontact::error on a non-OK status (history then untouched).
/// `dt` for a step-aware model (set_step) and in every force call below: the dt given to
/// set_step. R is calibrated for that dt, while this call's dt sets the onset test and the onset
/// and end corrections; a different dt is not detected and the realised e_n is then not the
/// calibrated one. Call set_step again when the host's dt changes.
inline ::dc_contact_result contact_force(const ::dc_contact_model& model, const ::dc_contact_state& state,
                                         double dt, span<double> history) {
    ::dc_contact_result r{};
    detail::check(::dc_contact_force(&model, &state, dt, history.data(), history.size(), &r));
    return r;
}

/// noexcept form of contact_force: returns the status; `out` written only on status::ok.
inline status contact_force(const ::dc_contact_model& model, const ::dc_contact_state& state, double dt,
                            span<double> history, ::dc_contact_result& out) noexcept {
    return static_cast<status>(::dc_contact_force(&model, &state, dt, history.data(), history.size(), &out));
}

/// One contact's force and its energy ledger (contact_force_energy).
struct contact_step {
    ::dc_contact_result result;
    ::dc_contact_energy energy;
};

/// dc_contact_force with the energy ledger of the step (dc_contact_force_energy): the same force
/// and history update bit for bit. Throws demcontact::error on a non-OK status (history then
/// untouched).
inline contact_step contact_force_energy(const ::dc_contact_model& model, const ::dc_contact_state& state, double dt,
                                         span<double> history) {
    contact_step r{};
    detail::check(
        ::dc_contact_force_energy(&model, &state, dt, history.data(), history.size(), &r.result, &r.energy));
    return r;
}

/// noexcept form of contact_force_energy: returns the status; `out`, `energy` written only on
/// status::ok.
inline status contact_force_energy(const ::dc_contact_model& model, const ::dc_contact_state& state, double dt,
                                   span<double> history, ::dc_contact_result& out,
                                   ::dc_contact_energy& energy) noexcept {
    return static_cast<status>(
        ::dc_contact_force_energy(&model, &state, dt, history.data(), history.size(), &out, &energy));
}

/// n contacts (dc_contact_force_batch). Throws demcontact::error on a non-OK status; nothing
/// is written then, except on result_range (a result overflowed): the overflowing contacts'
/// outputs are NaN and their history kept, every other contact is computed.
inline void contact_force_batch_checked(const ::dc_contact_model& model, const ::dc_contact_batch& batch,
                                        double dt) {
    detail::check(::dc_contact_force_batch(&model, &batch, dt));
}

/// n contacts, each input read from memory once (dc_contact_force_batch_fused). Returns the
/// status: on a per-contact status (not_finite, not_positive, not_unit, result_range) every other contact is
/// computed, the bad ones' outputs are NaN and `first_bad` is the first bad index; on an error
/// of the call itself (a NULL array, the model, buffer sizes or layout, a non-finite or
/// non-positive dt) nothing is written, `first_bad` included. not_finite and not_positive can be
/// either kind: preset `first_bad` (e.g. to SIZE_MAX) to tell them apart. noexcept: a non-OK
/// status always needs the caller's attention.
inline status contact_force_batch_fused(const ::dc_contact_model& model, const ::dc_contact_batch& batch, double dt,
                                        std::size_t& first_bad) noexcept {
    return static_cast<status>(::dc_contact_force_batch_fused(&model, &batch, dt, &first_bad));
}

}  // namespace demcontact

namespace demcontact {

/// A dc_plan_input filled by dc_plan_input_init (version, size, defaults; the required members
/// NaN): set the members by name, then call plan(input).
inline ::dc_plan_input plan_input() {
    ::dc_plan_input i{};
    detail::check(::dc_plan_input_init(&i));
    return i;
}

/// The scene planner (dc_plan, docs/plan.md). Throws demcontact::error on a non-OK status; the
/// noexcept form below also says which member is at fault.
inline ::dc_plan_result plan(const ::dc_plan_input& input) {
    ::dc_plan_result r{};
    detail::check(::dc_plan(&input, &r, nullptr));
    return r;
}

/// noexcept form of plan: returns the status; `out` written only on status::ok, `field` (a
/// DC_PLAN_FIELD_*) only on an error.
inline status plan(const ::dc_plan_input& input, ::dc_plan_result& out, std::int32_t& field) noexcept {
    return static_cast<status>(::dc_plan(&input, &out, &field));
}

}  // namespace demcontact
