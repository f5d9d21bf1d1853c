/*
 * One contact's full evaluation compiled for the model's shape, for the simulator plugins
 * (LAMMPS pair/wall styles, LIGGGHTS sub-models).
 *
 * dc_contact_force_checked_inline reads the model's selectors (normal kernel, tangential,
 * rolling, twisting, carry) at run time, so one call site holds every kernel and every stage.
 * dc_contact_force_shaped_inline takes them as arguments: written here as template parameters,
 * each instantiation keeps only its own kernel and stages (constant history length, no selector
 * branches, a few KB instead of 15 KB of code). A plugin picks the instantiation once per model:
 * pick<V> returns V's code instantiated for the shape (the LIGGGHTS plugin: its whole per-contact
 * body, so that the result stays in registers), eval_for a pointer to the evaluation alone (the
 * LAMMPS styles); a shape with no instantiation gets the generic entry. Every instantiation gives
 * the bits of dc_contact_force_checked_inline (ctest inline_contact_* checks the header's shaped
 * entry with constant shapes against the library; ctest inline_shaped_pick checks this file's
 * choice). eval_deferred: the same with the header's deferred entry (a host that tests the
 * checks once per pass, as the LIGGGHTS plugin's pair loop).
 *
 * Instantiated: the Hertz kernel damped, or damped and force-clamped (hertz/material with
 * coeff_restitution, LIGGGHTS' model demcontact with exponent 1.5), tangential Mindlin or
 * linear, rolling none, constant or EPSD, twisting none, either carry: 24 shapes; the linear
 * kernel damped alone (hertz/material's `linear` spring-dashpot, gran/hooke's normal law, with no
 * tangential, rolling or twisting), either carry: 2 shapes. The others (viscoelastic, twisting,
 * general p, the linear kernel undamped, clamped or with a tangential or rolling stage) take the
 * generic entry, at its cost (the linear kernel with tangential linear, instantiated, measured no
 * faster than the generic entry on the box deck's wall: docs/lammps_examples.md).
 */
#ifndef DEMCONTACT_SHAPED_H
#define DEMCONTACT_SHAPED_H

#include <demcontact_inline.h>

namespace demcontact_shaped {
/* Internal linkage for everything here: the instantiations call the header's static (internal)
 * functions, so a definition with external linkage, included by two translation units (the LAMMPS
 * plugin's pair and wall styles), would refer to a different function in each: an ODR violation. */
namespace {

/* The generic entry: any model dc_contact_model_check_inline accepts. */
struct Generic {
    DCI_ALWAYS_INLINE_FN int32_t eval(const dc_contact_model *m, const dc_contact_state *s, double dt, double *h,
                                      dc_contact_result *r)
    {
        return dc_contact_force_checked_inline(m, s, dt, h, r);
    }
    /* the deferred entry (checks collected in c, tested once per pass by the host) */
    DCI_ALWAYS_INLINE_FN int32_t eval_deferred(const dc_contact_model *m, const dc_contact_state *s, double dt,
                                               double *h, dc_contact_result *r, dc_contact_checks *c)
    {
        return dc_contact_force_deferred_inline(m, s, dt, h, r, c);
    }
};

/* One shape: the header's shaped entry with the codes as constants (twisting none). */
template <int32_t KERNEL, int32_t TANGENTIAL, int32_t ROLLING, int32_t CARRY>
struct Shape {
    DCI_ALWAYS_INLINE_FN int32_t eval(const dc_contact_model *m, const dc_contact_state *s, double dt, double *h,
                                      dc_contact_result *r)
    {
        return dc_contact_force_shaped_inline(m, KERNEL, TANGENTIAL, ROLLING, DC_TWISTING_NONE, CARRY, s, dt, h, r);
    }
    DCI_ALWAYS_INLINE_FN int32_t eval_deferred(const dc_contact_model *m, const dc_contact_state *s, double dt,
                                               double *h, dc_contact_result *r, dc_contact_checks *c)
    {
        return dc_contact_force_shaped_deferred_inline(m, KERNEL, TANGENTIAL, ROLLING, DC_TWISTING_NONE, CARRY, s,
                                                       dt, h, r, c);
    }
};

/* pick<V>(m) returns V::get<S>() for the S (Generic or a Shape) that evaluates m: V::get is the
 * host's code instantiated for S (a function or member-function pointer, typically the host's
 * whole per-contact body with S::eval inlined into it, so the result stays in registers). */
template <class V, int32_t K, int32_t T, int32_t R>
typename V::type for_carry(int32_t carry)
{
    if (carry == DC_CARRY_PROJECT) return V::template get<Shape<K, T, R, DC_CARRY_PROJECT> >();
    return V::template get<Shape<K, T, R, DC_CARRY_ROTATE> >();
}

template <class V, int32_t K, int32_t T>
typename V::type for_rolling(int32_t rolling, int32_t carry)
{
    if (rolling == DC_ROLLING_NONE) return for_carry<V, K, T, DC_ROLLING_NONE>(carry);
    if (rolling == DC_ROLLING_CONSTANT) return for_carry<V, K, T, DC_ROLLING_CONSTANT>(carry);
    return for_carry<V, K, T, DC_ROLLING_EPSD>(carry);
}

template <class V, int32_t K>
typename V::type for_tangential(int32_t tangential, int32_t rolling, int32_t carry)
{
    if (tangential == DC_TANGENTIAL_LINEAR) return for_rolling<V, K, DC_TANGENTIAL_LINEAR>(rolling, carry);
    return for_rolling<V, K, DC_TANGENTIAL_MINDLIN>(rolling, carry);
}

/* True when m has one of the instantiated shapes (dc_contact_model_shape_inline against the
 * codes the for_* functions above pick, which also runs the model checks). */
inline bool instantiated(const dc_contact_model &m)
{
    const int32_t k = m.normal.kernel;
    if (k == DC_KERNEL_LIN_DAMPED) { // the linear spring-dashpot alone (no tangential, rolling, twisting)
        const int32_t c = m.carry == DC_CARRY_PROJECT ? DC_CARRY_PROJECT : DC_CARRY_ROTATE;
        return dc_contact_model_shape_inline(&m, k, DC_TANGENTIAL_NONE, DC_ROLLING_NONE, DC_TWISTING_NONE, c) == DC_OK;
    }
    if (k != DC_KERNEL_HERTZ_DAMPED && k != DC_KERNEL_HERTZ_DAMPED_CLAMPED) return false;
    const int32_t t = m.tangential == DC_TANGENTIAL_LINEAR ? DC_TANGENTIAL_LINEAR : DC_TANGENTIAL_MINDLIN;
    const int32_t r = m.rolling == DC_ROLLING_NONE       ? DC_ROLLING_NONE
                      : m.rolling == DC_ROLLING_CONSTANT ? DC_ROLLING_CONSTANT
                                                         : DC_ROLLING_EPSD;
    const int32_t c = m.carry == DC_CARRY_PROJECT ? DC_CARRY_PROJECT : DC_CARRY_ROTATE;
    return dc_contact_model_shape_inline(&m, k, t, r, DC_TWISTING_NONE, c) == DC_OK;
}

/* V::get<S>() for the model's shape S, or V::get<Generic>() when it has none of them (the
 * generic entry's contract, dc_contact_model_check_inline, is then the caller's to check). */
template <class V>
typename V::type pick(const dc_contact_model &m)
{
    if (!instantiated(m)) return V::template get<Generic>();
    if (m.normal.kernel == DC_KERNEL_LIN_DAMPED)
        return for_carry<V, DC_KERNEL_LIN_DAMPED, DC_TANGENTIAL_NONE, DC_ROLLING_NONE>(m.carry);
    if (m.normal.kernel == DC_KERNEL_HERTZ_DAMPED)
        return for_tangential<V, DC_KERNEL_HERTZ_DAMPED>(m.tangential, m.rolling, m.carry);
    return for_tangential<V, DC_KERNEL_HERTZ_DAMPED_CLAMPED>(m.tangential, m.rolling, m.carry);
}

/* pick<V> for a set of models one call site evaluates (a host that chooses once per run): their
 * common instantiation when every model has the same one, else V::get<Generic>(). at(i) gives
 * the i-th model, 0 <= i < count (count 0: Generic). */
template <class V, class At>
typename V::type pick_common(int count, At at)
{
    typename V::type common = V::template get<Generic>();
    for (int i = 0; i < count; i++) {
        const typename V::type t = pick<V>(at(i));
        if (i == 0) common = t;
        else if (t != common) return V::template get<Generic>();
    }
    return common;
}

/* A plain function per shape (hosts that want a pointer to the evaluation alone). */
typedef int32_t (*Eval)(const dc_contact_model *, const dc_contact_state *, double, double *,
                        dc_contact_result *);
template <class S>
int32_t eval_fn(const dc_contact_model *m, const dc_contact_state *s, double dt, double *h, dc_contact_result *r)
{
    return S::eval(m, s, dt, h, r);
}
struct EvalOf {
    typedef Eval type;
    template <class S>
    static type get()
    {
        return &eval_fn<S>;
    }
};
inline Eval eval_for(const dc_contact_model &m) { return pick<EvalOf>(m); }

} // namespace
} // namespace demcontact_shaped

#endif
