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
 *   <law> v1 v2 ...                    the normal law of dc_contact_spec named by its keyword, with
 *                                      the values of the fields it reads, in the order of the
 *                                      generated table demcontact_laws.h (docs/laws.md): e.g.
 *                                      dmt w (work_of_adhesion), elastic_plastic p_y
 *                                      (yield_pressure), linear k_n, powerlaw p k_n,
 *                                      viscoelastic A, jkr w (work_of_adhesion). The adhesive laws
 *                                      (dmt, jkr) act beyond touching: see law_reach() below.
 *                                      Materials from E and nu; a law that takes no
 *                                      restitution target (elastic_plastic, viscoelastic) needs
 *                                      e = 1 (DC_DAMPING_NONE). Always demcontact's full contact.
 *   limit_damping                      clamp attractive normal force (also a pair_style keyword);
 *                                      alpha then comes from the force-zero calibration
 *   tangential mindlin NULL e_t mu     Mindlin k_t = 8 G* a from E, nu; tangential restitution e_t
 *                                      in the sticking regime (1: undamped), Coulomb limit mu
 *   tangential mindlin_rescale NULL e_t mu
 *                                      the same with the spring force rescaled when the contact
 *                                      radius changes (DC_TANGENTIAL_MINDLIN_RESCALE: no energy
 *                                      gained on unloading; docs/force.md)
 *   tangential linear_history k_t e_t mu    fixed k_t [force/length]
 *   rolling sds k_r eta_r mu_r         elastic-plastic spring-dashpot (EPSD), limit mu_r R* Fn;
 *                                      k_r = NULL or 0: Ai et al.'s rule from the normal stiffness
 *   rolling constant mu_r              constant torque mu_r R* Fn against the relative rolling
 *   twisting sds k_tw eta_tw mu_tw     twisting spring-dashpot-slider, limit mu_tw Fn
 *   carry rotate|project               how the history springs (tangential, EPSD rolling) follow the
 *                                      contact frame (dc_contact_model_set_carry): rotate (default,
 *                                      DC_CARRY_ROTATE: the pair's mean spin, then the tilt of the
 *                                      normal; objective) or project (DC_CARRY_PROJECT: projected on
 *                                      the new tangent plane and rescaled to the old length, as
 *                                      pair_style granular's mindlin/sds; cheaper, not objective
 *                                      about the normal). No effect without a history spring.
 *   step_exact                         realise e at the run's time step, not only in the continuous
 *                                      contact (dc_contact_model_set_step with LAMMPS' dt and
 *                                      velocity Verlet, DC_INTEGRATOR_VELOCITY_VERLET; docs/timestep.md):
 *                                      one more double of history per contact. Hertz with damping
 *                                      restitution only (viscoelastic: rejected, naming step_exact).
 *                                      The styles set the step at every run's init and again when
 *                                      LAMMPS changes dt during a run (fix dt/reset, timestep: reset_dt).
 *
 * With any tangential/rolling/twisting keyword or step_exact the contact is demcontact's full
 * contact (dc_contact_model_init / dc_contact_force, per-contact history); without, the normal law
 * alone (dc_pair / dc_normal_force, no history). The full contact needs the Hertz exponent 1.5.
 *
 * Mixing (pair_coeff I J not given, I != J): each body keeps its own type's E and nu (combined
 * exactly into E*); e, A, e_t, mu, k_t, mu_r, k_r, eta_r, mu_tw, k_tw, eta_tw and the normal law's
 * values are the geometric means of the two types' values; the exponent, the normal law, the
 * sub-model choices, the carry and step_exact must agree.
 */
#ifndef DEMCONTACT_LAMMPS_COEFF_H
#define DEMCONTACT_LAMMPS_COEFF_H

#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <demcontact.h>
#include "tsuji_force.h"
#include "demcontact_shaped.h"
#include "demcontact_laws.h"

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
    // full contact sub-models; NaN = unset
    int tangential = DC_TANGENTIAL_NONE, rolling = DC_ROLLING_NONE, twisting = DC_TWISTING_NONE;
    double mu = 0, k_t = NAN, e_t = 1, mu_r = 0, k_r = 0, eta_r = 0, mu_tw = 0, k_tw = NAN, eta_tw = 0;
    int carry = DC_CARRY_ROTATE; // frame carry of the history springs (keyword carry)
    // normal law given by keyword (<law> v1 v2 ...; demcontact_laws.h) and its values
    int normal = DC_NORMAL_HERTZ;
    double normal_param[DC_LAW_PARAMS_MAX] = {};
    bool step_exact = false;     // keyword step_exact: dc_contact_model_set_step at the run's dt
    bool full() const
    {
        return tangential != DC_TANGENTIAL_NONE || rolling != DC_ROLLING_NONE || twisting != DC_TWISTING_NONE ||
               step_exact || normal != DC_NORMAL_HERTZ;
    }
};

/* dc_contact_spec of a contact between materials a (body 1) and b (body 2); the per-pair values
   (e, A, friction...) from m. */
inline dc_contact_spec full_spec(const Coeff &a, const Coeff &b, const Coeff &m)
{
    dc_contact_spec s;
    dc_contact_spec_init(&s);
    const bool clamp = a.clamp || b.clamp;
    s.criterion = clamp ? DC_END_FORCE : DC_END_OVERLAP;
    s.E1 = a.E;
    s.nu1 = a.nu;
    s.E2 = b.E;
    s.nu2 = b.nu;
    const dc_normal_law *law = dc_normal_law_of(m.normal);
    if (m.damping == DAMP_VISCOELASTIC) {
        s.normal = DC_NORMAL_VISCOELASTIC;
        s.damping = DC_DAMPING_NONE;
        s.visco_A = m.A;
    } else if (m.normal != DC_NORMAL_HERTZ && law) {
        // a law given by keyword: its fields by their offsets in dc_contact_spec
        s.normal = m.normal;
        s.damping = law->restitution ? DC_DAMPING_RESTITUTION : DC_DAMPING_NONE;
        s.e_n = m.e;
        for (int k = 0; k < law->nparams; k++)
            *reinterpret_cast<double *>(reinterpret_cast<char *>(&s) + law->params[k].offset) = m.normal_param[k];
    } else {
        s.normal = DC_NORMAL_HERTZ;
        s.damping = DC_DAMPING_RESTITUTION;
        s.e_n = m.e;
    }
    s.tangential = m.tangential;
    s.rolling = m.rolling;
    s.twisting = m.twisting;
    s.mu = m.mu;
    s.k_t = m.k_t;
    s.e_t = m.e_t;
    s.mu_r = m.mu_r;
    s.k_r = m.k_r;
    s.eta_r = m.eta_r;
    s.mu_tw = m.mu_tw;
    s.k_tw = m.k_tw;
    s.eta_tw = m.eta_tw;
    return s;
}

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
        error->all(FLERR, "{}: {} = {} rejected by demcontact: {}", what, name, value, dc_status_str(status));
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
        } else if (k == "tangential") {
            const std::string law = i + 1 < narg ? arg[i + 1] : "";
            if (law == "mindlin" || law == "mindlin_rescale") {
                c.tangential = law == "mindlin" ? DC_TANGENTIAL_MINDLIN : DC_TANGENTIAL_MINDLIN_RESCALE;
                if (i + 2 >= narg || std::strcmp(arg[i + 2], "NULL") != 0)
                    error->all(FLERR, "{}: tangential {} takes k_t from E and nu: write 'tangential {} NULL e_t mu'",
                               what, law, law);
            } else if (law == "linear_history") {
                c.tangential = DC_TANGENTIAL_LINEAR;
                c.k_t = num(i + 2, "k_t");
            } else {
                error->all(FLERR, "{}: unknown tangential model '{}' (mindlin, mindlin_rescale or linear_history)",
                           what, law);
            }
            c.e_t = num(i + 3, "e_t");
            c.mu = num(i + 4, "mu");
            i += 5;
        } else if (k == "rolling") {
            const std::string law = i + 1 < narg ? arg[i + 1] : "";
            if (law == "sds") {
                c.rolling = DC_ROLLING_EPSD;
                c.k_r = (i + 2 < narg && std::strcmp(arg[i + 2], "NULL") == 0) ? 0.0 : num(i + 2, "k_r");
                c.eta_r = num(i + 3, "eta_r");
                c.mu_r = num(i + 4, "mu_r");
                i += 5;
            } else if (law == "constant") {
                c.rolling = DC_ROLLING_CONSTANT;
                c.mu_r = num(i + 2, "mu_r");
                i += 3;
            } else {
                error->all(FLERR, "{}: unknown rolling model '{}' (sds or constant)", what, law);
            }
        } else if (k == "twisting") {
            if (i + 1 >= narg || std::strcmp(arg[i + 1], "sds") != 0)
                error->all(FLERR, "{}: unknown twisting model (sds k_tw eta_tw mu_tw)", what);
            c.twisting = DC_TWISTING_SDS;
            c.k_tw = num(i + 2, "k_tw");
            c.eta_tw = num(i + 3, "eta_tw");
            c.mu_tw = num(i + 4, "mu_tw");
            i += 5;
        } else if (k == "carry") {
            if (i + 1 >= narg) error->all(FLERR, "{}: missing value for carry (rotate or project)", what);
            const std::string v = arg[i + 1];
            if (v == "rotate") c.carry = DC_CARRY_ROTATE;
            else if (v == "project") c.carry = DC_CARRY_PROJECT;
            else // what dc_contact_model_set_carry answers for an unknown carry
                error->all(FLERR, "{}: carry '{}' rejected by demcontact: {} (carry rotate or carry project)", what,
                           v, dc_status_str(DC_ERR_SPEC_MODEL));
            i += 2;
        } else if (k == "step_exact") {
            c.step_exact = true;
            i += 1;
        } else if (const dc_normal_law *law = dc_normal_law_find(k.c_str())) {
            c.normal = law->code;
            for (int j = 0; j < law->nparams; j++) c.normal_param[j] = num(i + 1 + j, law->params[j].field);
            i += 1 + law->nparams;
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
    if (c.normal != DC_NORMAL_HERTZ) {
        const dc_normal_law *law = dc_normal_law_of(c.normal);
        if (c.damping == DAMP_VISCOELASTIC)
            error->all(FLERR, "{}: damping viscoelastic is a Hertz law of its own: drop it or the normal law '{}'", what,
                       law->keyword);
        if (!law->restitution && c.e != 1.0)
            error->all(FLERR, "{}: normal law '{}' takes no restitution target (its loss is its own): give e = 1, not {}",
                       what, law->keyword, c.e);
        if (!law->clamp && c.clamp)
            error->all(FLERR, "{}: normal law '{}' is never clamped (DC_END_OVERLAP only): drop limit_damping", what,
                       law->keyword);
        // the normal law alone, so that a rejected value is named
        dc_contact_model cm;
        Coeff n;
        n.E = c.E;
        n.nu = c.nu;
        n.e = c.e;
        n.clamp = c.clamp;
        n.normal = c.normal;
        for (int j = 0; j < DC_LAW_PARAMS_MAX; j++) n.normal_param[j] = c.normal_param[j];
        dc_contact_spec ns = full_spec(n, n, n);
        s = dc_contact_model_init(&ns, &cm);
        if (s != DC_OK) {
            if (law->nparams == 1) reject(law->params[0].field, c.normal_param[0], s);
            error->all(FLERR, "{}: normal law '{}' rejected by demcontact: {}", what, law->keyword, dc_status_str(s));
        }
    }
    if (c.step_exact && c.p != 1.5) error->all(FLERR, "{}: step_exact needs the Hertz exponent 1.5 (got {})", what, c.p);
    if (c.full()) {
        if (c.p != 1.5) error->all(FLERR, "{}: tangential/rolling/twisting need the Hertz exponent 1.5 (got {})", what, c.p);
        // the library validates the whole spec; on failure, name the first parameter that fails
        // on its own (each substituted into a spec known to be valid)
        dc_contact_model cm;
        dc_contact_spec sp = full_spec(c, c, c);
        s = dc_contact_model_init(&sp, &cm);
        if (s == DC_OK) {
            s = dc_contact_model_set_carry(&cm, c.carry);
            if (s != DC_OK)
                error->all(FLERR, "{}: carry {} rejected by demcontact: {}", what, c.carry, dc_status_str(s));
            // what the styles' init will ask with the run's dt: whether this model has a
            // step-aware form at all (its answer does not depend on dt, any dt > 0 asks it)
            if (c.step_exact) {
                s = dc_contact_model_set_step(&cm, 1.0, DC_INTEGRATOR_VELOCITY_VERLET);
                if (s != DC_OK)
                    error->all(FLERR, "{}: step_exact rejected by demcontact: {}", what, dc_status_str(s));
            }
        }
        if (s != DC_OK) {
            Coeff ok = c;
            ok.mu = 0.5;
            ok.k_t = 1.0;
            ok.e_t = 1.0;
            ok.mu_r = 0.1;
            ok.k_r = 0.0;
            ok.eta_r = 0.0;
            ok.mu_tw = 0.1;
            ok.k_tw = 1.0;
            ok.eta_tw = 0.0;
            struct { const char *name; double Coeff::*field; } fields[] = {
                {"mu", &Coeff::mu},       {"k_t", &Coeff::k_t},     {"e_t", &Coeff::e_t},
                {"mu_r", &Coeff::mu_r},   {"k_r", &Coeff::k_r},     {"eta_r", &Coeff::eta_r},
                {"mu_tw", &Coeff::mu_tw}, {"k_tw", &Coeff::k_tw},   {"eta_tw", &Coeff::eta_tw}};
            for (auto &f : fields) {
                Coeff t = ok;
                t.*(f.field) = c.*(f.field);
                dc_contact_spec ts = full_spec(t, t, t);
                const int32_t st = dc_contact_model_init(&ts, &cm);
                if (st != DC_OK) reject(f.name, c.*(f.field), st);
            }
            error->all(FLERR, "{}: contact model rejected by demcontact: {}", what, dc_status_str(s));
        }
    }
    c.set = true;
}

/* The model of one type pair: the normal law alone (dc_pair, no history) or demcontact's full
   contact (dc_contact_model, history of nh doubles per contact). */
enum Adhesion { ADH_NONE = 0, ADH_DMT = 1, ADH_JKR = 2 };

struct Model {
    bool full = false;
    int adhesive = ADH_NONE; // a law that acts at negative overlap (DMT's tail, JKR's neck)
    int state_at = -1;       // JKR: the history index of its state (0 no neck, 1 formed)
    bool step_exact = false; // step-aware (dc_contact_model_set_step): set_dt at every dt change
    int nh = 0;
    dc_pair pair{};
    dc_contact_model cm{};
    // the full contact's evaluation: the instantiation of cm's shape (demcontact_shaped.h) or the
    // generic entry; set by make_model
    demcontact_shaped::Eval eval = &demcontact_shaped::eval_fn<demcontact_shaped::Generic>;
};

/* law_reach() below with the library's status: DC_OK and out = the reach (finite), or the status of
   dc_contact_model_reach (out NaN; DC_ERR_SPEC_MODEL for an adhesive law without a full contact
   model, which make_model never builds), so that a caller can name why there is no reach. */
inline int32_t law_reach_status(const Model &mod, double reff, double &out)
{
    out = 0.0;
    if (mod.adhesive == ADH_NONE || reff == 0.0) return DC_OK; // reff 0: no particle of the types yet
    out = NAN;
    if (!mod.full) return DC_ERR_SPEC_MODEL;
    double r = NAN;
    const int32_t s = dc_contact_model_reach(&mod.cm, reff, &r);
    if (s != DC_OK) return s;
    out = r * (1.0 + 1e-6);
    return std::isfinite(out) ? DC_OK : DC_ERR_RESULT_RANGE;
}

/* How far beyond touching (a separation, > 0) the normal law of a built contact model acts for
   the effective radius reff (a wall: the particle's radius); 0 for a law that acts only while the
   bodies overlap. The library's answer (dc_contact_model_reach): dmt: its tail's length d_c;
   jkr: |delta_c|, where its neck breaks. Both grow with R* (as R*^(1/3)), so the reach at the
   largest radii of a type pair bounds every pair of those types. Given 1e-6 larger: a bound, used
   to keep pairs in the neighbour list and to pick the pairs and wall contacts evaluated beyond
   touching (demcontact itself decides the force there, 0 beyond the law's range). NaN: the
   library refused (its status is not expected for a model make_model built). */
inline double law_reach(const Model &mod, double reff)
{
    double r = NAN;
    return law_reach_status(mod, reff, r) == DC_OK ? r : NAN;
}

/* Build the model of a contact between materials a (body 1) and b (body 2), per-pair values from m;
   dt: the run's time step, for step_exact (dc_contact_model_set_step, which also sets the history
   length: one more double). */
inline int32_t make_model(const Coeff &a, const Coeff &b, const Coeff &m, Model &out, double dt)
{
    const bool clamp = a.clamp || b.clamp;
    out.full = m.full();
    out.step_exact = m.step_exact;
    out.adhesive = m.damping == DAMP_VISCOELASTIC ? ADH_NONE
                   : m.normal == DC_NORMAL_DMT    ? ADH_DMT
                   : m.normal == DC_NORMAL_JKR    ? ADH_JKR
                                                  : ADH_NONE;
    out.state_at = -1;
    if (out.full) {
        dc_contact_spec sp = full_spec(a, b, m);
        int32_t s = dc_contact_model_init(&sp, &out.cm);
        if (s != DC_OK) return s;
        s = dc_contact_model_set_carry(&out.cm, m.carry); // keyword carry (default rotate)
        if (s != DC_OK) return s;
        if (m.step_exact) {
            s = dc_contact_model_set_step(&out.cm, dt, DC_INTEGRATOR_VELOCITY_VERLET);
            if (s != DC_OK) return s;
        }
        size_t len = 0;
        s = dc_contact_history_len(&out.cm, &len);
        out.nh = static_cast<int>(len);
        out.pair = out.cm.normal;
        if (s != DC_OK) return s;
        // a law with state keeps it after the springs, last (JKR has no step-aware double:
        // dc_contact_model_set_step refuses it): docs/force.md, "Normal laws with state"
        if (out.adhesive == ADH_JKR) out.state_at = out.nh - 1;
        // checked once here: contact_eval then takes the header's fast entry (no per-call model checks)
        s = dc_contact_model_check_inline(&out.cm);
        out.eval = demcontact_shaped::eval_for(out.cm);
        return s;
    }
    out.nh = 0;
    if (m.damping == DAMP_VISCOELASTIC)
        return dc_pair_viscoelastic(a.E, a.nu, b.E, b.nu, m.A, clamp ? DC_END_FORCE : DC_END_OVERLAP, &out.pair);
    return demcontact_sim::contact_setup(a.E, a.nu, b.E, b.nu, m.e, a.p, clamp, &out.pair);
}

/* A step_exact model made step-aware for a new time step dt (LAMMPS changed it: a run's init, fix
   dt/reset, timestep); no-op for the others. The history length and the model's shape do not
   change (the calibration is kept: cheap). On error the model is unchanged. */
inline int32_t set_model_dt(Model &m, double dt)
{
    if (!m.step_exact) return DC_OK;
    const int32_t s = dc_contact_model_set_step(&m.cm, dt, DC_INTEGRATOR_VELOCITY_VERLET);
    if (s != DC_OK) return s;
    return dc_contact_model_check_inline(&m.cm);
}

/* One contact's kinematics (demcontact's dc_contact_state): n points from body 2 to body 1; a wall
   is body 2 with r2 = m2 = +inf. */
typedef dc_contact_state State;

struct Result {
    double force[3];   // on body 1 (body 2: minus)
    double torque1[3]; // on body 1
    double torque2[3]; // on body 2
};

/* THE per-contact call of both styles (pair and wall). `history`: the caller-owned nh doubles of
   this contact, zero for a new contact, advanced in place. Returns the library status (the normal
   path cannot fail). The full contact is dc_contact_force_checked_inline from the header-only
   demcontact_inline.h (compiled into this loop, bit-identical to the library's dc_contact_force;
   the model checks run once, in make_model), through m.eval: compiled for the model's shape when
   demcontact_shaped.h has it (same bits). */
inline int32_t contact_eval(const Model &m, const State &s, double dt, double *history, Result &out)
{
    if (m.full) {
        dc_contact_result r;
        // m.cm passed dc_contact_model_check_inline in make_model; history: m.nh doubles
        const int32_t st = m.eval(&m.cm, &s, dt, history, &r);
        if (st != DC_OK) return st;
        for (int k = 0; k < 3; k++) {
            out.force[k] = r.force[k];
            out.torque1[k] = r.torque1[k];
            out.torque2[k] = r.torque2[k];
        }
        return DC_OK;
    }
    const double vn = (s.v2[0] - s.v1[0]) * s.n[0] + (s.v2[1] - s.v1[1]) * s.n[1] + (s.v2[2] - s.v1[2]) * s.n[2];
    const double reff = std::isinf(s.r2) ? s.r1 : s.r1 * s.r2 / (s.r1 + s.r2);
    const double meff = std::isinf(s.m2) ? s.m1 : s.m1 * s.m2 / (s.m1 + s.m2);
    const double F = demcontact_sim::contact_force(m.pair, s.overlap, vn, reff, meff);
    for (int k = 0; k < 3; k++) {
        out.force[k] = F * s.n[k];
        out.torque1[k] = 0.0;
        out.torque2[k] = 0.0;
    }
    return DC_OK;
}

} // namespace demcontact_lammps

#endif
