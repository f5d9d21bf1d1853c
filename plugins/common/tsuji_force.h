/*
 * The one place where the simulator plugins (LIGGGHTS normal model, LAMMPS pair style) get the
 * normal contact force: demcontact's dc_pair constructors (calibration, once per type pair) and
 * dc_normal_force_inline from the header-only demcontact_inline.h (kernel: inlined into the host's
 * pair loop, no call through the shared library per contact; bit-identical to dc_normal_force).
 * Everything else in the plugins is glue to the host code.
 *
 *   F = k d^p + alpha sqrt(m k) d^((p-1)/2) vn,   vn > 0 while compressing,
 *
 * alpha calibrated by demcontact with DC_END_FORCE when the host clamps the force at zero
 * (`clamp`: dc_normal_force then clamps too), DC_END_OVERLAP otherwise, so that the realised
 * restitution is the target in both cases.
 *
 * Stiffness: Hertz (p = 3/2) pairs come from the two materials, k = (4/3) E* sqrt(R*) per contact
 * (dc_pair_hertz). Other exponents use k = (4/3) E* R*^(2-p), the dimensionally consistent
 * generalisation (force = E* R*^2 (d/R*)^p), through a power-law pair with k0 = (4/3) E* and the
 * exact rescaling F(k0 s) = s F(k0; m/s) (s = R*^(2-p); clamping commutes with s > 0).
 */
#ifndef DEMCONTACT_SIM_TSUJI_FORCE_H
#define DEMCONTACT_SIM_TSUJI_FORCE_H

#include <demcontact.h>
#include <demcontact_inline.h>
#include <cmath>

namespace demcontact_sim {

/* Calibrated pair of two materials (E, nu each), target restitution e, exponent p. */
inline int32_t contact_setup(double E1, double nu1, double E2, double nu2, double e, double p,
                             bool clamp, dc_pair *out) {
    const int32_t criterion = clamp ? DC_END_FORCE : DC_END_OVERLAP;
    if (p == 1.5) return dc_pair_hertz(E1, nu1, E2, nu2, e, criterion, out);
    double e_star = 0.0;
    const int32_t s = dc_effective_modulus(E1, nu1, E2, nu2, &e_star);
    if (s != DC_OK) return s;
    return dc_pair_powerlaw(p, 4.0 / 3.0 * e_star, e, criterion, out);
}

/* Stiffness k of one contact [N m^-p] (for hosts that also report kn/gamman). */
inline double contact_stiffness(const dc_pair &c, double r_eff) {
    return c.model != DC_MODEL_POWERLAW ? c.stiffness * std::sqrt(r_eff)
                                        : c.stiffness * std::pow(r_eff, 2.0 - c.p);
}

/* Normal force of the other pairs: the header's kernel switch; power-law pairs rescaled. */
inline double contact_force_general(const dc_pair &c, double d, double vn, double r_eff, double m_eff) {
    // Hertz and viscoelastic pairs carry sqrt(r_eff) themselves
    if (c.model != DC_MODEL_POWERLAW) return dc_normal_force_inline(&c, d, vn, r_eff, m_eff);
    const double s = std::pow(r_eff, 2.0 - c.p);
    return s * dc_normal_force_inline(&c, d, vn, r_eff, m_eff / s);
}

/* Normal force [N] (positive = repulsive) for overlap d, normal speed vn (> 0 compressing). The
 * two damped Hertz kernels (what both codes' scenes use) with a constant kernel code, so that the
 * header's switch over 19 kernels folds away and the force is compiled into the host's pair loop
 * (the same kernel, the same bits); every other pair through contact_force_general. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
inline double contact_force(const dc_pair &c, double d, double vn, double r_eff, double m_eff) {
    if (c.kernel == DC_KERNEL_HERTZ_DAMPED)
        return dc_normal_force_kernel_inline(DC_KERNEL_HERTZ_DAMPED, &c, d, vn, r_eff, m_eff);
    if (c.kernel == DC_KERNEL_HERTZ_DAMPED_CLAMPED)
        return dc_normal_force_kernel_inline(DC_KERNEL_HERTZ_DAMPED_CLAMPED, &c, d, vn, r_eff, m_eff);
    return contact_force_general(c, d, vn, r_eff, m_eff);
}

} // namespace demcontact_sim

#endif
