/*
 * Contact coefficients of the LAMMPS plugin styles (pair_style demcontact, fix demcontact/wall):
 * parsing of the `pair_coeff` / wall arguments, validation by demcontact itself (every rejected
 * value is named together with dc_status_str), the calibrated model of one type pair, and the one
 * per-contact function `contact_eval` both styles call.
 *
 * Arguments (after "I J" for pair_coeff; after the fix style name for fix demcontact/wall), close to
 * `pair_style granular`:
 *
 *   hertz/material E e nu              Hertz, k = 4/3 E* sqrt(R*), restitution e, Poisson ratio nu
 *   powerlaw/material E e nu p         power law, k = 4/3 E* R*^(2-p), exponent p >= 1
 *   E nu e [exponent p]                the original positional form (same as the two above)
 *   damping restitution                (default) alpha calibrated exactly for e (see limit_damping)
 *   damping viscoelastic v_ref r_ref rho_ref
 *                                      Brilliantov viscoelastic Hertz, speed-dependent e: the damping
 *                                      constant A is calibrated so that two spheres of radius r_ref
 *                                      and density rho_ref colliding head-on at v_ref rebound with e
 *   limit_damping                      clamp attractive normal force (also a pair_style keyword);
 *                                      alpha then comes from the force-zero calibration
 *
 * Mixing (pair_coeff I J not given, I != J): each body keeps its own type's E and nu (combined
 * exactly into E*); e, and the viscoelastic A, are the geometric means of the two types' values;
 * the exponent and damping law must agree.
 */
#ifndef DEMCONTACT_LAMMPS_COEFF_H
#define DEMCONTACT_LAMMPS_COEFF_H

#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <demcontact.h>
#include "tsuji_force.h"

#include <cmath>
#include <cstring>
#include <string>

namespace demcontact_lammps {

using LAMMPS_NS::Error;
using LAMMPS_NS::LAMMPS;

enum Damping { DAMP_RESTITUTION = 0, DAMP_VISCOELASTIC = 1 };

struct Coeff {
    double E = 0, nu = 0, e = 0, p = 1.5;
    int damping = DAMP_RESTITUTION;
    double v_ref = 0, r_ref = 0, rho_ref = 0; // viscoelastic calibration point
    double A = 0;                              // viscoelastic damping constant [s] (calibrated)
    bool clamp = false;                        // limit_damping
    bool set = false;
};

/* The viscoelastic damping constant A for which two equal spheres (r_ref, rho_ref) of material
   (E, nu) colliding at v_ref rebound with e under the criterion of `clamp`. */
inline int32_t viscoelastic_A(const Coeff &c, bool clamp, double *A)
{
    double es = 0.0;
    int32_t s = dc_effective_modulus(c.E, c.nu, c.E, c.nu, &es);
    if (s != DC_OK) return s;
    if (!(c.r_ref > 0.0) || !(c.rho_ref > 0.0) || !std::isfinite(c.r_ref) || !std::isfinite(c.rho_ref))
        return DC_ERR_NOT_POSITIVE;
    const double rho_hertz = 4.0 / 3.0 * es * std::sqrt(0.5 * c.r_ref);
    const double m_ref = c.rho_ref * 4.0 / 3.0 * M_PI * c.r_ref * c.r_ref * c.r_ref;
    return dc_viscoelastic_a_from_e(c.e, c.v_ref, rho_hertz, 0.5 * m_ref, clamp ? DC_END_FORCE : DC_END_OVERLAP, A);
}

/* Parse arguments arg[0..narg) into c; `what` prefixes error messages ("pair_coeff 1 1"). Every
   value is checked by demcontact as soon as it is read, and a rejected one ends the run with
   LAMMPS' error naming it and demcontact's status text. */
inline void parse_coeff(LAMMPS *lmp, Error *error, const std::string &what, int narg, char **arg,
                        bool style_clamp, Coeff &c)
{
    using LAMMPS_NS::utils::numeric;
    auto num = [&](int i, const char *name) -> double {
        if (i >= narg) error->all(FLERR, "{}: missing value for {}", what, name);
        return numeric(FLERR, arg[i], false, lmp);
    };
    auto reject = [&](const char *name, double value, int32_t status) {
        error->all(FLERR, "{}: {} = {} rejected by demcontact: {}{}", what, name, value, dc_status_str(status),
                   std::strcmp(name, "nu") == 0 ? " (Poisson ratio must be in (-1, 0.5])" : "");
    };
    int i = 0;
    if (narg < 1) error->all(FLERR, "{}: missing arguments", what);
    if (std::strcmp(arg[0], "hertz/material") == 0 || std::strcmp(arg[0], "powerlaw/material") == 0) {
        const bool pl = arg[0][0] == 'p';
        c.E = num(1, "E");
        c.e = num(2, "e");
        c.nu = num(3, "nu");
        if (pl) c.p = num(4, "p");
        i = pl ? 5 : 4;
    } else {
        c.E = num(0, "E");
        c.nu = num(1, "nu");
        c.e = num(2, "e");
        i = 3;
    }
    c.clamp = style_clamp;
    while (i < narg) {
        const std::string k = arg[i];
        if (k == "exponent") {
            c.p = num(i + 1, "exponent");
            i += 2;
        } else if (k == "limit_damping") {
            c.clamp = true;
            i += 1;
        } else if (k == "damping") {
            if (i + 1 >= narg) error->all(FLERR, "{}: damping needs a law (restitution or viscoelastic)", what);
            const std::string law = arg[i + 1];
            if (law == "restitution" || law == "coeff_restitution") {
                c.damping = DAMP_RESTITUTION;
                i += 2;
            } else if (law == "viscoelastic") {
                c.damping = DAMP_VISCOELASTIC;
                c.v_ref = num(i + 2, "v_ref");
                c.r_ref = num(i + 3, "r_ref");
                c.rho_ref = num(i + 4, "rho_ref");
                i += 5;
            } else {
                error->all(FLERR, "{}: unknown damping law '{}' (restitution or viscoelastic)", what, law);
            }
        } else {
            error->all(FLERR, "{}: unknown keyword '{}'", what, k);
        }
    }
    // Validation by the library, one value at a time so that the message names it.
    double es = 0.0, a = 0.0;
    const int32_t crit = c.clamp ? DC_END_FORCE : DC_END_OVERLAP;
    int32_t s = dc_effective_modulus(c.E, 0.25, c.E, 0.25, &es);
    if (s != DC_OK) reject("E", c.E, s);
    s = dc_effective_modulus(1.0, c.nu, 1.0, c.nu, &es);
    // demcontact accepts nu = 0.5 (incompressible); the physical range is (-1, 0.5]
    if (s != DC_OK) reject("nu", c.nu, s);
    s = dc_alpha_from_e(0.5, c.p, crit, &a);
    if (s != DC_OK) reject("exponent p", c.p, s);
    s = dc_alpha_from_e(c.e, c.p, crit, &a);
    if (s != DC_OK) reject("e", c.e, s);
    if (c.damping == DAMP_VISCOELASTIC) {
        if (c.p != 1.5) error->all(FLERR, "{}: damping viscoelastic needs the Hertz exponent 1.5 (got {})", what, c.p);
        double b = 0.0;
        s = dc_viscoelastic_beta_from_e(c.e, c.v_ref, crit, &b);
        if (s != DC_OK) reject("v_ref", c.v_ref, s);
        if (!std::isfinite(c.r_ref)) reject("r_ref", c.r_ref, DC_ERR_NOT_FINITE);
        if (!(c.r_ref > 0.0)) reject("r_ref", c.r_ref, DC_ERR_NOT_POSITIVE);
        if (!std::isfinite(c.rho_ref)) reject("rho_ref", c.rho_ref, DC_ERR_NOT_FINITE);
        if (!(c.rho_ref > 0.0)) reject("rho_ref", c.rho_ref, DC_ERR_NOT_POSITIVE);
        s = viscoelastic_A(c, c.clamp, &c.A);
        if (s != DC_OK) reject("e (viscoelastic calibration)", c.e, s);
    }
    c.set = true;
}

/* The calibrated normal law of one contact between materials a and b (a == b for one type). */
inline int32_t make_pair(const Coeff &a, const Coeff &b, double e, double A, dc_pair *out)
{
    const bool clamp = a.clamp || b.clamp;
    if (a.damping == DAMP_VISCOELASTIC)
        return dc_pair_viscoelastic(a.E, a.nu, b.E, b.nu, A, clamp ? DC_END_FORCE : DC_END_OVERLAP, out);
    return demcontact_sim::contact_setup(a.E, a.nu, b.E, b.nu, e, a.p, clamp, out);
}

/* One contact's kinematics, in the layout of demcontact's full-contact state: n points from body 2
   to body 1; a wall is body 2 with r2 = m2 = +inf. */
struct State {
    double n[3];
    double overlap;
    double v1[3], v2[3];
    double w1[3], w2[3];
    double r1, r2, m1, m2;
};

struct Result {
    double force[3];   // on body 1
    double torque1[3]; // on body 1
    double torque2[3]; // on body 2
};

/* The one per-contact call of both styles. Normal force only: F n on body 1. `history` (not read:
   the normal law has none) is the caller-owned per-contact storage, zero for a new contact. */
inline void contact_eval(const dc_pair &pair, const State &s, double /*dt*/, double * /*history*/, Result &out)
{
    const double vn = (s.v2[0] - s.v1[0]) * s.n[0] + (s.v2[1] - s.v1[1]) * s.n[1] + (s.v2[2] - s.v1[2]) * s.n[2];
    const double reff = std::isinf(s.r2) ? s.r1 : s.r1 * s.r2 / (s.r1 + s.r2);
    const double meff = std::isinf(s.m2) ? s.m1 : s.m1 * s.m2 / (s.m1 + s.m2);
    const double F = demcontact_sim::contact_force(pair, s.overlap, vn, reff, meff);
    for (int k = 0; k < 3; k++) {
        out.force[k] = F * s.n[k];
        out.torque1[k] = 0.0;
        out.torque2[k] = 0.0;
    }
}

/* Doubles of per-contact history the model needs (0: normal law only). */
inline int history_len() { return 0; }

} // namespace demcontact_lammps

#endif
