/*
 * LIGGGHTS 3.8 normal contact model "demcontact", compiled against the installed LIGGGHTS headers
 * (Debian libliggghts-dev) and loaded into the stock `liggghts` executable with LD_PRELOAD:
 *
 *   pair_style gran model demcontact tangential history [limitForce on] [exponent 1.5] [stepExact on]
 *              [law KEYWORD]
 *   fix wall wall/gran model demcontact tangential history primitive type 1 zplane 0.0 [stepExact on]
 *              [law KEYWORD]
 *
 * Force: F = k d^p + alpha sqrt(m k) d^((p-1)/2) vn (power-law Tsuji) from demcontact's dc_pair
 * and dc_normal_force_inline (header-only, see ../common/tsuji_force.h): at the default p = 1.5 a dc_pair_hertz of the two
 * types' youngsModulus and poissonsRatio (k = 4/3 E* sqrt(R*)); otherwise k = (4/3) E* R*^(2-p).
 * alpha is calibrated for coefficientRestitution (per type pair) with DC_END_FORCE when
 * `limitForce on` (the kernel clamps too), DC_END_OVERLAP otherwise: the realised restitution is
 * the target in both cases.
 * The tangential stiffness/damping handed to the tangential model are exactly those of the
 * builtin `model hertz`, so `tangential history` behaves identically.
 *
 * stepExact on: the restitution realised at the run's time step, not only in the continuous
 * contact (dc_contact_model_set_step with LIGGGHTS' dt, velocity Verlet: DC_INTEGRATOR_VELOCITY_VERLET;
 * docs/timestep.md). Hertz (exponent 1.5) with coefficientRestitution only (viscoelastic on:
 * rejected, naming stepExact). The normal force is then demcontact's full contact with no
 * sub-model (dc_contact_force_checked_inline, normal part r.f_n), whose history double
 * ("dc_step") is registered in postSettings; `tangential demcontact`'s full model is step-aware
 * too, its own step slot in its block (friction_models_demcontact.h), so that its Coulomb limit
 * sees the same step-aware normal force. The step follows update->dt: set at each run's init
 * (connectToProperties) and again at the first contact after dt changed.
 *
 * law KEYWORD: the registry's normal law of that keyword (plugins/common/demcontact_laws.h,
 * generated from src/force/registry.rs: hertz, powerlaw, linear, viscoelastic, dmt, elastic_plastic,
 * jkr; a law added there is a keyword here without an edit), evaluated as stepExact's force is: demcontact's
 * full contact with no sub-model (dc_contact_force_checked_inline), its history (the law's state,
 * e.g. elastic_plastic's largest overlap, then the step slot with stepExact on) in LIGGGHTS'
 * contact history ("dc_normal0", ...), zeroed when a contact starts. Its materials are
 * youngsModulus/poissonsRatio; coefficientRestitution where the law takes a target (required only
 * then); each other parameter a property/global named after its dc_contact_spec field in
 * camelCase (yield_pressure -> yieldPressure, k_n -> kN, visco_A -> viscoA, p -> p,
 * work_of_adhesion -> workOfAdhesion), peratomtypepair or scalar. With tangential/rolling_friction
 * demcontact the sub-models' full models take the same law.
 *
 * The adhesive laws (dmt, jkr: dc_contact_model_reach > 0) act beyond touching (DMT's tail, JKR's
 * formed neck): the model grows LIGGGHTS' contact distance factor to twice their reach at each
 * type's smallest radius (setup_reach) and evaluates the law in surfacesClose (close_adhesive) on
 * the same state as a touching contact, the neck state surviving the gap in the contact history
 * (kept across reneighbouring while set; the library zeroes it where the neck breaks). Pairs and
 * primitive walls (ctests liggghts_adhesion, liggghts_adhesion_mpi:
 *   python3 tests/simulators/liggghts_adhesion.py --check --plugin build/simulators/libdemcontact_liggghts.so [--np 2]).
 * With LIGGGHTS' tangential history the tangential force acts only while the spheres overlap, its
 * Coulomb limit LIGGGHTS' mu |Fn| (this model's Fn, attractive at small JKR overlaps), not the
 * library's adhesion-corrected limit; tangential/rolling_friction demcontact (whose full model
 * carries that limit) are refused with an adhesive law, their contact not being evaluated in the gap.
 *
 * Settings lines: the pair styles and walls registered here hand LIGGGHTS' parser a copy of the
 * line ended by a marker (checked_words): a keyword given last reads the marker, not a stale word
 * past the end (law: "a normal-law keyword must follow"; numeric settings end the run naming it).
 *
 * Registration: LIGGGHTS selects a compiled template instance by a hash of the model ids
 * (normal | tangential << 6 | ...). A static initializer adds the name "demcontact" to the contact
 * model factory and registers the pair-style and wall instances for the combinations below with
 * the process-wide pair and wall factories. LIGGGHTS itself is not modified.
 */

// The generated style_*.h (see gen_styles.cmake) must be found first; contact_models.h pulls in
// every installed model header, which in turn need pointers.h/lammps.h already declared.
#include "contact_models.h"
#include "granular_pair_style.h"
#include "granular_wall.h"
#include "fix_insert_stream.h" // fix_insert_stream_predefined.h (via pair_gran_base.h) needs it first
#include "pair_gran_base.h"
#include "fix_wall_gran_base.h"
#include "global_properties.h"
#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "update.h"

#include <demcontact.h>
#include <demcontact_inline.h>
#include "demcontact_laws.h"
#include "tsuji_force.h"
#include "fix_property_global.h"
#include "modify.h"
#include "fix.h"
#include "neighbor.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <vector>

/* `law KEYWORD`: a setting whose values are the registry's normal-law keywords (demcontact_laws.h,
   generated), so that a law added to the registry is a keyword here without an edit. LIGGGHTS 3.8's
   Settings offers on/off, yes/no and double settings only, its map of settings private: the map is
   reached through the standard's rule that an explicit instantiation may name a private member
   (Rob below), and the setting added to it is deleted by Settings' destructor as its own are. An
   unknown keyword ends the run with LIGGGHTS' error "while parsing 'law' argument: unknown normal
   law '...'", whose text lists the keywords. */
namespace demcontact_law_setting {

/* What the settings parsers of model demcontact see after the last word of the line
   (settings_checked below): LIGGGHTS' Settings reads the word after a keyword without knowing how
   many words there are, and the arrays LIGGGHTS hands it end without a terminator (the word past
   the end is whatever an earlier, longer command left there). */
static const char MISSING_VALUE[] = "(missing value)";


class LawSetting : public Setting {
public:
    typedef int value_type;
    explicit LawSetting(const std::string &n) : Setting(n, 1) { current.setValue(-1); }
    void registerTarget(int &target) { current.registerTarget(target); }
    int parseArguments(char **args)
    {
        if (name != args[0]) return 0;
        if (!args[1] || !std::strcmp(args[1], MISSING_VALUE)) { // `law` the last word (settings_checked)
            error_message = "while parsing 'law' argument: a normal-law keyword must follow (" DC_NORMAL_LAW_KEYWORDS ")";
            return -1;
        }
        const dc_normal_law *law = dc_normal_law_find(args[1]);
        if (!law) {
            error_message = std::string("while parsing 'law' argument: unknown normal law '") + args[1] +
                            "' (demcontact's laws: " DC_NORMAL_LAW_KEYWORDS ")";
            return -1;
        }
        current.setValue(law->code);
        return 2;
    }
    void print_value(FILE *out)
    {
        const dc_normal_law *law = dc_normal_law_of(current.getValue());
        std::fputs(law ? law->keyword : "default", out);
    }

private:
    ValuePropagator<int> current;
};

typedef std::map<std::string, Setting *> SettingMap;
struct MapTag {
    typedef SettingMap Settings::*type;
    friend type settings_map(MapTag);
};
template <typename Tag, typename Tag::type M>
struct Rob {
    friend typename Tag::type settings_map(Tag) { return M; }
};
template struct Rob<MapTag, &Settings::settings>;

// register `law` (once per Settings; every model of a contact model shares the value)
inline void register_law(Settings &settings, int &target)
{
    SettingMap &m = settings.*settings_map(MapTag());
    if (m.find("law") == m.end()) m["law"] = new LawSetting("law");
    LawSetting *ls = dynamic_cast<LawSetting *>(m["law"]);
    if (ls) ls->registerTarget(target);
}

/* The LIGGGHTS property of a law parameter: the dc_contact_spec field in camelCase (yield_pressure
   -> yieldPressure, work_of_adhesion -> workOfAdhesion, visco_A -> viscoA, k_n -> kN, p -> p). */
inline std::string property_name(const char *field)
{
    std::string out;
    bool up = false;
    for (const char *c = field; *c; c++) {
        if (*c == '_') {
            up = true;
            continue;
        }
        out += up ? static_cast<char>(std::toupper(static_cast<unsigned char>(*c)))
                  : (out.empty() ? static_cast<char>(std::tolower(static_cast<unsigned char>(*c))) : *c);
        up = false;
    }
    return out;
}

} // namespace demcontact_law_setting

namespace LIGGGHTS {
namespace ContactModels {

// 6-bit model id; the installed ids are 0..12 (NORMAL_OFF = 9). Checked at registration.
static const int DEMCONTACT = 42;

template<>
class NormalModel<DEMCONTACT> : public NormalModelBase
{
public:
    NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c)
        : NormalModelBase(lmp, hsetup, c), is_wall_model(c->is_wall()), owner(c), Y(NULL), nu(NULL), Yeff(NULL), Geff(NULL), coeffRest(NULL),
          tangential_damping(true), limitForce(false), exponent(1.5), ntypes(0) {}

    void registerSettings(Settings &settings)
    {
        settings.registerOnOff("tangential_damping", tangential_damping, true);
        settings.registerOnOff("limitForce", limitForce);
        settings.registerDoubleSetting("exponent", exponent, 1.5);
        // viscoelastic on: Brilliantov viscoelastic Hertz, A calibrated so that two spheres of
        // radius rRef and density densityRef colliding at vRef rebound with coefficientRestitution
        settings.registerOnOff("viscoelastic", viscoelastic, false);
        settings.registerDoubleSetting("vRef", v_ref, 1.0);
        settings.registerDoubleSetting("rRef", r_ref, 0.0);
        settings.registerDoubleSetting("densityRef", rho_ref, 0.0);
        // stepExact on: dc_contact_model_set_step at LIGGGHTS' dt (see the top of this file)
        settings.registerOnOff("stepExact", step_exact, false);
        // law KEYWORD: the registry's normal law of that keyword, through demcontact's full contact
        demcontact_law_setting::register_law(settings, law_code);
    }

    // The tangential/rolling models of the same contact model find this normal model here.
    void postSettings(IContactHistorySetup *hsetup, ContactModelBase *)
    {
        demcontact_normals()[owner] = this;
        if (law_code >= 0) {
            // the law's own doubles (its state: elastic_plastic's largest overlap) and the step
            // slot: the length of a placeholder model of the law (the values do not change it)
            dc_contact_spec s;
            law_placeholder(s);
            dc_contact_model m;
            size_t len = 0;
            int32_t st = dc_contact_model_init(&s, &m);
            if (st == DC_OK && step_exact) st = dc_contact_model_set_step(&m, 1.0, DC_INTEGRATOR_VELOCITY_VERLET);
            if (st == DC_OK) st = dc_contact_history_len(&m, &len);
            if (st != DC_OK) { // the run's own values are rejected with their names at init
                const dc_normal_law *law = dc_normal_law_of(law_code);
                len = (law && law->state ? 1 : 0) + (step_exact ? 1 : 0);
            }
            law_nh = static_cast<int>(len);
            for (int k = 0; k < law_nh; k++) {
                const int off = hsetup->add_history_value("dc_normal" + std::to_string(k), "0");
                if (k == 0) step_offset = off;
            }
        } else if (step_exact) {
            step_offset = hsetup->add_history_value("dc_step", "0");
            law_nh = 1;
        }
    }

    /* law KEYWORD: a spec of the law with placeholder values (materials 1e7 Pa, 0.3; e_n 0.5; every
       parameter 1), for the history length and the sub-models' placeholders. */
    void law_placeholder(dc_contact_spec &s) const
    {
        dc_contact_spec_init(&s);
        const dc_normal_law *law = dc_normal_law_of(law_code);
        if (!law) {
            s.normal = DC_NORMAL_HERTZ;
            s.damping = DC_DAMPING_RESTITUTION;
            s.e_n = 0.5;
            s.E1 = s.E2 = 1e7;
            s.nu1 = s.nu2 = 0.3;
            return;
        }
        s.normal = law->code;
        s.criterion = DC_END_OVERLAP;
        s.E1 = s.E2 = 1e7;
        s.nu1 = s.nu2 = 0.3;
        if (law->restitution) {
            s.damping = DC_DAMPING_RESTITUTION;
            s.e_n = 0.5;
        } else {
            s.damping = DC_DAMPING_NONE;
        }
        for (int k = 0; k < law->nparams; k++)
            *reinterpret_cast<double *>(reinterpret_cast<char *>(&s) + law->params[k].offset) = 1.0;
    }
    ~NormalModel()
    {
        if (demcontact_normals().count(owner) && demcontact_normals()[owner] == this) demcontact_normals().erase(owner);
    }

    /* The normal part of a full-contact spec for types i, j (body 1 of type i): the same law as
       this model's force (Hertz or viscoelastic Hertz; not other exponents). */
    bool full_spec(int i, int j, dc_contact_spec &s) const
    {
        if (law_code >= 0) { // law KEYWORD: built and checked in calibrate_law
            s = law_specs[i * (ntypes + 1) + j];
            return true;
        }
        if (exponent != 1.5) return false;
        const dc_pair &pr = pairs[i * (ntypes + 1) + j];
        dc_contact_spec_init(&s);
        s.criterion = limitForce ? DC_END_FORCE : DC_END_OVERLAP;
        s.E1 = Y[i];
        s.nu1 = nu[i];
        s.E2 = Y[j];
        s.nu2 = nu[j];
        if (viscoelastic) {
            s.normal = DC_NORMAL_VISCOELASTIC;
            s.damping = DC_DAMPING_NONE;
            s.visco_A = pr.damping_a;
        } else {
            s.normal = DC_NORMAL_HERTZ;
            s.damping = DC_DAMPING_RESTITUTION;
            s.e_n = coeffRest[i][j];
        }
        return true;
    }

    void connectToProperties(PropertyRegistry &registry)
    {
        // Material values are validated by demcontact in calibrate() (the message names the value
        // and gives dc_status_str), not by LIGGGHTS' sanity checks: sanity_checks = false.
        registry.registerProperty("youngsModulus", &MODEL_PARAMS::createYoungsModulus, false);
        registry.registerProperty("poissonsRatio", &MODEL_PARAMS::createPoissonsRatio, false);
        registry.registerProperty("Yeff", &MODEL_PARAMS::createYeff, false);
        registry.registerProperty("Geff", &MODEL_PARAMS::createGeff, false);
        registry.registerProperty("coeffRest", &MODEL_PARAMS::createCoeffRest, false);
        registry.connect("youngsModulus", Y, "model demcontact");
        registry.connect("poissonsRatio", nu, "model demcontact");
        registry.connect("Yeff", Yeff, "model demcontact");
        registry.connect("Geff", Geff, "model demcontact");
        // a law without a restitution target (elastic_plastic, viscoelastic: their loss is their
        // own) does not read coefficientRestitution: not required then
        const dc_normal_law *law = dc_normal_law_of(law_code);
        if (!law || law->restitution) registry.connect("coeffRest", coeffRest, "model demcontact");
        else coeffRest = NULL;
        deferred = false; // set again by rolling_friction demcontact's combine_into at this init
        // Called on every rank at each run's init, after the material fixes exist: calibrate here
        // (error->all is collective) rather than lazily at a first contact that not all ranks see.
        calibrate();
    }

    double stressStrainExponent() { return exponent; }
    static std::map<const void *, const NormalModel *> &demcontact_normals()
    {
        static std::map<const void *, const NormalModel *> m;
        return m;
    }

    __attribute__((always_inline)) inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces,
                                                                 ForceData &j_forces)
    {
        if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
        // tangential + rolling_friction demcontact: the combined evaluation of the tangential class
        // applies the normal force too (nothing between reads sidata.Fn, kn, kt; see
        // friction_models_demcontact.h), so it is computed once per contact, not twice
        if (deferred) return;
        intersect_body(sidata, i_forces, j_forces);
    }

    /* The normal force itself, out of line: inlined, its kernels (the general-p power among them)
       made LIGGGHTS' contact-model glue too large for GCC to inline into the pair loop in runs
       where it is deferred, which cost those runs 3 % of their loop time (LIGGGHTS scene,
       docs/simulators.md); runs of the normal model alone measured the same pair time either way
       (its builtin counterpart, NormalModel<3>, is out of line too). */
    __attribute__((noinline)) void intersect_body(SurfacesIntersectData &sidata, ForceData &i_forces,
                                                  ForceData &j_forces)
    {
        const int itype = sidata.itype, jtype = sidata.jtype;
        const double reff = sidata.is_wall ? sidata.radi
                                           : sidata.radi * sidata.radj / (sidata.radi + sidata.radj);
        const double meff = sidata.meff;
        const double deltan = sidata.deltan;
        const dc_pair &pair = pairs[itype * (ntypes + 1) + jtype];
        if (adhesive) {
            check_radius(sidata.i, sidata.radi, itype);
            if (!sidata.is_wall) check_radius(sidata.j, sidata.radj, jtype);
        }

        // LIGGGHTS' vn is negative while approaching; demcontact's is positive while compressing.
        // (units si/cgs: nktv2p = 1, as the builtin models assume for the force itself.)
        const double Fn = (step_exact || law_code >= 0) ? step_force(sidata, reff, meff)
                                           : demcontact_sim::contact_force(pair, deltan, -sidata.vn, reff, meff);

        // What the tangential model reads: identical to the builtin `model hertz`.
        const double sqrtval = std::sqrt(reff * deltan);
        const double St = 8. * Geff[itype][jtype] * sqrtval;
        const double sqrtFiveOverSix = 0.91287092917527685576161630466800355658790782499663875;
        sidata.Fn = Fn;
        sidata.kn = 4. / 3. * Yeff[itype][jtype] * sqrtval / force->nktv2p;
        sidata.kt = St / force->nktv2p;
        // gamman: the Tsuji damping coefficient of this contact (no LIGGGHTS 3.8 sub-model reads
        // it; kept for diagnostics). Hertz: alpha sqrt(m k0 sqrt(R*)) d^(1/4) = c sqrt(m sqrtval)
        // with c = alpha sqrt(k0): the root the force kernel takes too (the same operands, so the
        // compiler computes it once; the exact value, rounded differently than three roots).
        // Viscoelastic pairs have no Tsuji damping (alpha = 0).
        sidata.gamman = law_code >= 0 ? 0.0 // law KEYWORD: its own loss (no Tsuji coefficient)
                        : pair.model == DC_MODEL_HERTZ ? pair.c * std::sqrt(meff * sqrtval)
                        : pair.model == DC_MODEL_POWERLAW
                            ? pair.alpha * std::sqrt(meff * demcontact_sim::contact_stiffness(pair, reff)) *
                                  std::pow(deltan, 0.5 * (pair.p - 1.0))
                            : 0.0;
        sidata.gammat = tangential_damping
                            ? -2. * sqrtFiveOverSix * beta[itype * (ntypes + 1) + jtype] * std::sqrt(St * meff) : 0.0;

        if (sidata.is_wall) {
            const double Fn_ = Fn * sidata.area_ratio;
            i_forces.delta_F[0] += Fn_ * sidata.en[0];
            i_forces.delta_F[1] += Fn_ * sidata.en[1];
            i_forces.delta_F[2] += Fn_ * sidata.en[2];
        } else {
            i_forces.delta_F[0] += Fn * sidata.en[0];
            i_forces.delta_F[1] += Fn * sidata.en[1];
            i_forces.delta_F[2] += Fn * sidata.en[2];
            j_forces.delta_F[0] -= Fn * sidata.en[0];
            j_forces.delta_F[1] -= Fn * sidata.en[1];
            j_forces.delta_F[2] -= Fn * sidata.en[2];
        }
    }

    void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
    {
        if (adhesive) {
            close_adhesive(scdata, i_forces, j_forces);
            return;
        }
        if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
        if (step_offset >= 0 && scdata.contact_history) // a new contact starts from zero
            for (int k = 0; k < law_nh; k++) scdata.contact_history[step_offset + k] = 0.0;
    }

    /* stepExact on: the dt the step-aware models were set for; follows update->dt (error: the
       run ends naming stepExact and demcontact's status). full: a full contact model of the same
       contact model (friction_models_demcontact.h) set the same way. */
    int32_t set_step(dc_contact_model &m, double dt) const
    {
        const int32_t s = dc_contact_model_set_step(&m, dt, DC_INTEGRATOR_VELOCITY_VERLET);
        return s == DC_OK ? dc_contact_model_check_inline(&m) : s;
    }
    void step_error(double dt, int32_t s, bool all) const
    {
        char msg[320];
        std::snprintf(msg, sizeof msg, "model demcontact: stepExact at timestep %g rejected by demcontact: %s", dt,
                      dc_status_str(s));
        if (all) error->all(FLERR, msg);
        error->one(FLERR, msg);
    }
    /* An adhesive law in the gap (setup_reach): the law's force at the negative overlap, on the
       same state as a touching contact's (step_force), its history advanced as there. LIGGGHTS 3.8's
       pair loop and wall fix both hand surfacesClose their SurfacesIntersectData: the wall has
       filled its geometry (en, deltan < 0, m_eff) before the call; the pair loop has not, so the
       geometry is computed here as its loop and surface model compute it for a touching pair (r,
       en from delta; deltan = radsum - r; vn from v_i - v_j; m_eff from the atoms' masses and fix
       freeze, not from a fix rigid's bodies) and written into it for LIGGGHTS' later readers. The
       pair keeps its contact history (CONTACT_NORMAL_MODEL) while the law's state is set (JKR's
       formed neck), else lets LIGGGHTS drop it. */
    __attribute__((noinline)) void close_adhesive(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
    {
        SurfacesIntersectData &sd = static_cast<SurfacesIntersectData &>(scdata);
        const int itype = sd.itype, jtype = sd.jtype;
        double reff;
        check_radius(sd.i, sd.radi, itype);
        if (sd.is_wall) {
            reff = sd.radi;
        } else {
            check_radius(sd.j, sd.radj, jtype);
            reff = sd.radi * sd.radj / (sd.radi + sd.radj);
            const double r = std::sqrt(sd.rsq), rinv = 1.0 / r;
            sd.r = r;
            sd.rinv = rinv;
            sd.en[0] = sd.delta[0] * rinv;
            sd.en[1] = sd.delta[1] * rinv;
            sd.en[2] = sd.delta[2] * rinv;
            sd.deltan = sd.radsum - r;
            const double *rmass = atom->rmass;
            const double mi = rmass ? rmass[sd.i] : atom->mass[itype];
            const double mj = rmass ? rmass[sd.j] : atom->mass[jtype];
            double meff = mi * mj / (mi + mj);
            if (atom->mask[sd.i] & freeze_bit) meff = mj;
            if (atom->mask[sd.j] & freeze_bit) meff = mi;
            sd.mi = mi;
            sd.mj = mj;
            sd.meff = meff;
        }
        const double vr1 = sd.v_i[0] - sd.v_j[0];
        const double vr2 = sd.v_i[1] - sd.v_j[1];
        const double vr3 = sd.v_i[2] - sd.v_j[2];
        sd.vn = vr1 * sd.en[0] + vr2 * sd.en[1] + vr3 * sd.en[2];
        const double Fn = step_force(sd, reff, sd.meff);
        sd.Fn = Fn;
        if (sd.contact_flags) {
            bool held = false;
            for (int k = 0; k < law_nh; k++) held = held || sd.contact_history[step_offset + k] != 0.0;
            if (held) *sd.contact_flags |= CONTACT_NORMAL_MODEL;
            else *sd.contact_flags &= ~CONTACT_NORMAL_MODEL;
        }
        if (Fn == 0.0) return;
        sd.has_force_update = true;
        const double Fn_ = sd.is_wall ? Fn * sd.area_ratio : Fn;
        i_forces.delta_F[0] += Fn_ * sd.en[0];
        i_forces.delta_F[1] += Fn_ * sd.en[1];
        i_forces.delta_F[2] += Fn_ * sd.en[2];
        if (!sd.is_wall) {
            j_forces.delta_F[0] -= Fn * sd.en[0];
            j_forces.delta_F[1] -= Fn * sd.en[1];
            j_forces.delta_F[2] -= Fn * sd.en[2];
        }
    }
    bool is_adhesive() const { return adhesive; }
    bool step_exact = false;
    int step_offset = -1; // history index of "dc_step" / "dc_normal0"; -1: neither stepExact nor law
    int law_nh = 0;       // history doubles from step_offset on
    int law_code = -1;    // law KEYWORD: its DC_NORMAL_*; -1: the default law (Hertz/exponent/viscoelastic)
    void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
    void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

private:
    /* The normal force of one contact with stepExact on or law KEYWORD (step-aware or not, by
       step_models[]): demcontact's full contact with no sub-model, on a state with the same
       overlap, normal speed, r_eff and m_eff (body 2 with infinite radius and mass, at rest:
       r_eff, m_eff exact), its law_nh doubles from step_offset in LIGGGHTS' contact history ("dc_step";
       law KEYWORD: "dc_normal0", ...: the law's state, then the step slot), advanced only when
       LIGGGHTS says so (computeflag && shearupdate). */
    double step_force(SurfacesIntersectData &sidata, double reff, double meff)
    {
        const double dt = update->dt;
        if (step_exact && dt != step_dt) { // dt changed during the run (not at an init): follow it
            for (dc_contact_model &m : step_models) {
                if (m.magic == 0) continue; // type 0 rows (unused)
                const int32_t s = set_step(m, dt);
                if (s != DC_OK) step_error(dt, s, false);
            }
            step_dt = dt;
        }
        const double inf = std::numeric_limits<double>::infinity();
        const double vn = -sidata.vn;
        dc_contact_state s;
        for (int k = 0; k < 3; k++) {
            s.n[k] = sidata.en[k];
            s.v1[k] = 0.0;
            s.v2[k] = vn * sidata.en[k];
            s.w1[k] = s.w2[k] = 0.0;
        }
        s.overlap = sidata.deltan;
        s.r1 = reff;
        s.r2 = inf;
        s.m1 = meff;
        s.m2 = inf;
        double copy[MAX_LAW_NH];
        double *slot = law_nh > 0 ? &sidata.contact_history[step_offset] : copy; // law_nh 0: no history read
        if (law_nh > 0 && !(sidata.computeflag && sidata.shearupdate)) { // evaluate without advancing the history
            for (int k = 0; k < law_nh; k++) copy[k] = slot[k];
            slot = copy;
        }
        dc_contact_result r;
        const int32_t st =
            dc_contact_force_checked_inline(&step_models[sidata.itype * (ntypes + 1) + sidata.jtype], &s, dt, slot, &r);
        if (st != DC_OK) {
            char msg[200];
            std::snprintf(msg, sizeof msg, "model demcontact (stepExact): atom %ld: %s", (long)atom->tag[sidata.i],
                          dc_status_str(st));
            error->one(FLERR, msg);
        }
        return r.f_n;
    }

    // One calibrated dc_pair for every type pair, once (calibration costs ~0.2 us per pair).
    void reject(const char *what, int t, double value, int32_t status)
    {
        char msg[320];
        std::snprintf(msg, sizeof msg, "model demcontact: %s of type %d = %g rejected by demcontact: %s", what, t,
                      value, dc_status_str(status));
        error->all(FLERR, msg);
    }

    void calibrate()
    {
        if (law_code >= 0) {
            calibrate_law();
            return;
        }
        const int n = atom->ntypes;
        const int32_t crit = limitForce ? DC_END_FORCE : DC_END_OVERLAP;
        double es = 0.0, a = 0.0;
        // one value at a time, so that the message names it
        for (int i = 1; i <= n; i++) {
            int32_t s = dc_effective_modulus(Y[i], 0.25, Y[i], 0.25, &es);
            if (s != DC_OK) reject("youngsModulus", i, Y[i], s);
            s = dc_effective_modulus(1.0, nu[i], 1.0, nu[i], &es);
            if (s != DC_OK) reject("poissonsRatio", i, nu[i], s);
        }
        {
            const int32_t s = dc_alpha_from_e(0.5, exponent, crit, &a);
            if (s != DC_OK) reject("exponent (all types)", 1, exponent, s);
        }
        if (viscoelastic) {
            if (exponent != 1.5) reject("exponent (viscoelastic needs 1.5)", 1, exponent, DC_ERR_EXPONENT_RANGE);
            if (!(v_ref > 0.0) || !std::isfinite(v_ref)) reject("vRef", 1, v_ref, DC_ERR_NOT_POSITIVE);
            if (!(r_ref > 0.0) || !std::isfinite(r_ref)) reject("rRef (set it with viscoelastic on)", 1, r_ref, DC_ERR_NOT_POSITIVE);
            if (!(rho_ref > 0.0) || !std::isfinite(rho_ref))
                reject("densityRef (set it with viscoelastic on)", 1, rho_ref, DC_ERR_NOT_POSITIVE);
        }
        pairs.assign((n + 1) * (n + 1), dc_pair());
        beta.assign((n + 1) * (n + 1), 0.0);
        for (int i = 1; i <= n; i++)
            for (int j = 1; j <= n; j++) {
                int32_t s = dc_alpha_from_e(coeffRest[i][j], exponent, crit, &a);
                if (s != DC_OK) {
                    char msg[320];
                    std::snprintf(msg, sizeof msg,
                                  "model demcontact: coefficientRestitution of types %d-%d = %g rejected by demcontact: %s",
                                  i, j, coeffRest[i][j], dc_status_str(s));
                    error->all(FLERR, msg);
                }
                // the tangential damping of the builtin `model hertz` (computed here rather than
                // through LIGGGHTS' betaeff property, whose creator re-enables the sanity checks)
                const double lne = std::log(coeffRest[i][j]);
                beta[i * (n + 1) + j] = lne / std::sqrt(lne * lne + M_PI * M_PI);
                dc_pair &pr = pairs[i * (n + 1) + j];
                if (viscoelastic) {
                    // A: material constant of the pair, from one measured (vRef, e) of two equal
                    // reference spheres (rRef, densityRef) of the pair's effective modulus
                    s = dc_effective_modulus(Y[i], nu[i], Y[j], nu[j], &es);
                    double A = 0.0;
                    if (s == DC_OK) {
                        const double rho_h = 4.0 / 3.0 * es * std::sqrt(0.5 * r_ref);
                        const double m_ref = rho_ref * 4.0 / 3.0 * M_PI * r_ref * r_ref * r_ref;
                        s = dc_viscoelastic_a_from_e(coeffRest[i][j], v_ref, rho_h, 0.5 * m_ref, crit, &A);
                    }
                    if (s == DC_OK) s = dc_pair_viscoelastic(Y[i], nu[i], Y[j], nu[j], A, crit, &pr);
                } else {
                    s = demcontact_sim::contact_setup(Y[i], nu[i], Y[j], nu[j], coeffRest[i][j], exponent,
                                                      limitForce, &pr);
                }
                if (s != DC_OK) {
                    char msg[320];
                    std::snprintf(msg, sizeof msg, "model demcontact: types %d-%d (e = %g, exponent = %g): %s", i, j,
                                  coeffRest[i][j], exponent, dc_status_str(s));
                    error->all(FLERR, msg);
                }
            }
        if (step_exact) { // the step-aware normal-only models, at this run's dt
            if (exponent != 1.5) reject("exponent (stepExact needs 1.5)", 1, exponent, DC_ERR_STEP_UNSUPPORTED);
            step_models.assign((n + 1) * (n + 1), dc_contact_model());
            for (int i = 1; i <= n; i++)
                for (int j = 1; j <= n; j++) {
                    dc_contact_spec sp;
                    full_spec(i, j, sp);
                    dc_contact_model &m = step_models[i * (n + 1) + j];
                    int32_t s = dc_contact_model_init(&sp, &m);
                    if (s == DC_OK) s = set_step(m, update->dt);
                    if (s != DC_OK) {
                        char msg[320];
                        std::snprintf(msg, sizeof msg,
                                      "model demcontact: stepExact (types %d-%d, coefficientRestitution = %g, timestep "
                                      "%g) rejected by demcontact: %s",
                                      i, j, coeffRest[i][j], update->dt, dc_status_str(s));
                        error->all(FLERR, msg);
                    }
                }
            step_dt = update->dt;
        }
        static bool reported = false; // one line per process, not one per wall/pair instance
        if (comm->me == 0 && !reported) {
            reported = true;
            char msg[256];
            std::snprintf(msg, sizeof msg,
                          "model demcontact: %s, exponent %g, limitForce %s, alpha(1,1) = %.15g, A(1,1) = %.6g s (%s), "
                          "stepExact %s\n",
                          viscoelastic ? "viscoelastic" : "restitution", exponent, limitForce ? "on" : "off",
                          pairs[(n + 1) + 1].alpha, pairs[(n + 1) + 1].damping_a,
                          limitForce ? "DC_END_FORCE" : "DC_END_OVERLAP", step_exact ? "on" : "off");
            if (screen) std::fputs(msg, screen);
            if (logfile) std::fputs(msg, logfile);
        }
        ntypes = n;
    }

    /* law KEYWORD: one normal-only contact model per type pair (step_models, evaluated by
       step_force) from the law's spec: materials youngsModulus/poissonsRatio, coefficientRestitution
       where the law takes a target, and each parameter from the property/global named after its
       field (law_property), peratomtypepair or scalar. Every value checked by demcontact, named. */
    void calibrate_law()
    {
        const int n = atom->ntypes;
        const dc_normal_law *law = dc_normal_law_of(law_code);
        char msg[512];
        if (!law) error->all(FLERR, "model demcontact: law: unknown law code"); // cannot happen: the setting checks
        if (viscoelastic)
            error->all(FLERR, "model demcontact: viscoelastic on is a normal law of its own: drop it, or give law "
                              "viscoelastic (parameter viscoA) instead");
        if (exponent != 1.5) {
            std::snprintf(msg, sizeof msg,
                          "model demcontact: exponent %g is the default law's: with law %s drop it (law powerlaw "
                          "takes its exponent from the property p)",
                          exponent, law->keyword);
            error->all(FLERR, msg);
        }
        if (!law->clamp && limitForce) {
            std::snprintf(msg, sizeof msg,
                          "model demcontact: law %s is never clamped (DC_END_OVERLAP only): drop limitForce on",
                          law->keyword);
            error->all(FLERR, msg);
        }
        double es = 0.0;
        for (int i = 1; i <= n; i++) {
            int32_t s = dc_effective_modulus(Y[i], 0.25, Y[i], 0.25, &es);
            if (s != DC_OK) reject("youngsModulus", i, Y[i], s);
            s = dc_effective_modulus(1.0, nu[i], 1.0, nu[i], &es);
            if (s != DC_OK) reject("poissonsRatio", i, nu[i], s);
        }
        // the parameters: [k][i * (n + 1) + j]
        std::vector<std::vector<double> > par(law->nparams, std::vector<double>((n + 1) * (n + 1), 0.0));
        for (int k = 0; k < law->nparams; k++) {
            const std::string name = demcontact_law_setting::property_name(law->params[k].field);
            FixPropertyGlobal *f = static_cast<FixPropertyGlobal *>(
                modify->find_fix_property(name.c_str(), "property/global", "peratomtypepair", n, n, "model demcontact", false));
            bool scalar = false;
            if (!f) {
                f = static_cast<FixPropertyGlobal *>(
                    modify->find_fix_property(name.c_str(), "property/global", "scalar", 0, 0, "model demcontact", false));
                scalar = f != NULL;
            }
            if (!f) {
                std::snprintf(msg, sizeof msg,
                              "model demcontact: law %s needs its parameter %s [%s] (%s): fix ID all property/global "
                              "%s peratomtypepair %d v11 v12 ... (or scalar v)",
                              law->keyword, name.c_str(), law->params[k].unit, law->params[k].field, name.c_str(), n);
                error->all(FLERR, msg);
            }
            for (int i = 1; i <= n; i++)
                for (int j = 1; j <= n; j++)
                    par[k][i * (n + 1) + j] = scalar ? f->compute_scalar() : f->compute_array(i - 1, j - 1);
        }
        law_specs.assign((n + 1) * (n + 1), dc_contact_spec());
        step_models.assign((n + 1) * (n + 1), dc_contact_model());
        beta.assign((n + 1) * (n + 1), 0.0);
        pairs.assign((n + 1) * (n + 1), dc_pair());
        size_t len_max = 0;
        for (int i = 1; i <= n; i++)
            for (int j = 1; j <= n; j++) {
                const int ij = i * (n + 1) + j;
                dc_contact_spec &s = law_specs[ij];
                dc_contact_spec_init(&s);
                s.normal = law->code;
                s.criterion = limitForce ? DC_END_FORCE : DC_END_OVERLAP;
                s.E1 = Y[i];
                s.nu1 = nu[i];
                s.E2 = Y[j];
                s.nu2 = nu[j];
                if (law->restitution) {
                    s.damping = DC_DAMPING_RESTITUTION;
                    s.e_n = coeffRest[i][j];
                    // the builtin `model hertz`'s tangential damping, as the default law's
                    const double lne = std::log(coeffRest[i][j]);
                    beta[ij] = lne / std::sqrt(lne * lne + M_PI * M_PI);
                } else {
                    s.damping = DC_DAMPING_NONE;
                }
                for (int k = 0; k < law->nparams; k++)
                    *reinterpret_cast<double *>(reinterpret_cast<char *>(&s) + law->params[k].offset) = par[k][ij];
                // each parameter on its own first (so that the message names it), in a copy whose
                // other parameters are the placeholder's
                for (int k = 0; k < law->nparams; k++) {
                    dc_contact_spec one;
                    law_placeholder(one);
                    one.criterion = s.criterion;
                    one.E1 = s.E1;
                    one.nu1 = s.nu1;
                    one.E2 = s.E2;
                    one.nu2 = s.nu2;
                    const size_t off = law->params[k].offset;
                    *reinterpret_cast<double *>(reinterpret_cast<char *>(&one) + off) = par[k][ij];
                    dc_contact_model m;
                    const int32_t st = dc_contact_model_init(&one, &m);
                    if (st != DC_OK && st != DC_ERR_RESTITUTION_RANGE) {
                        std::snprintf(msg, sizeof msg,
                                      "model demcontact: law %s: %s of types %d-%d = %g rejected by demcontact: %s",
                                      law->keyword,
                                      demcontact_law_setting::property_name(law->params[k].field).c_str(), i, j,
                                      par[k][ij], dc_status_str(st));
                        error->all(FLERR, msg);
                    }
                }
                dc_contact_model &m = step_models[ij];
                int32_t st = dc_contact_model_init(&s, &m);
                if (st == DC_OK && step_exact) {
                    st = set_step(m, update->dt);
                    if (st != DC_OK) {
                        std::snprintf(msg, sizeof msg,
                                      "model demcontact: stepExact with law %s (types %d-%d, timestep %g) rejected by "
                                      "demcontact: %s",
                                      law->keyword, i, j, update->dt, dc_status_str(st));
                        error->all(FLERR, msg);
                    }
                }
                if (st == DC_OK) st = dc_contact_model_check_inline(&m);
                size_t len = 0;
                if (st == DC_OK) st = dc_contact_history_len(&m, &len);
                if (st != DC_OK) {
                    std::snprintf(msg, sizeof msg,
                                  "model demcontact: law %s (types %d-%d, coefficientRestitution = %g) rejected by "
                                  "demcontact: %s",
                                  law->keyword, i, j, law->restitution ? coeffRest[i][j] : 1.0, dc_status_str(st));
                    error->all(FLERR, msg);
                }
                len_max = std::max(len_max, len);
            }
        if (static_cast<int>(len_max) > law_nh || len_max > MAX_LAW_NH) {
            std::snprintf(msg, sizeof msg, "model demcontact: law %s needs %d history doubles, %d registered",
                          law->keyword, static_cast<int>(len_max), law_nh);
            error->all(FLERR, msg);
        }
        step_dt = update->dt;
        ntypes = n;
        setup_reach(law);
        static bool reported = false; // one line per process, not one per wall/pair instance
        if (comm->me == 0 && !reported) {
            reported = true;
            std::snprintf(msg, sizeof msg, "model demcontact: law %s, %d history double(s), limitForce %s, stepExact %s\n",
                          law->keyword, law_nh, limitForce ? "on" : "off", step_exact ? "on" : "off");
            if (screen) std::fputs(msg, screen);
            if (logfile) std::fputs(msg, logfile);
        }
    }

    /* An adhesive law (dmt, jkr: dc_contact_model_reach > 0 on the built model) acts up to its
       reach beyond touching (DMT's tail d_c, JKR's formed neck down to |delta_c|). LIGGGHTS calls
       surfacesClose for the pairs closer than f (r_i + r_j) that do not overlap, and for the wall
       contacts whose gap is below (f - 1) r_i, f = neighbor->contactDistanceFactor (the largest any
       model registered; the pair style's neighbour cutoff and the history kept across
       reneighbouring scale with it): f is grown here to cover the reach. The reach grows as
       R*^(1/3) while f is relative to the radii, so reach / (r_i + r_j) is largest for the two
       smallest spheres (reach / r_i for a wall): each type's smallest radius (its atoms at this
       init, and what the insertion fixes will insert: Fix::min_rad) sizes f, with a margin of 2:
       a formed neck is evaluated at some step past its breakage gap (where the library zeroes its
       state) as long as the spheres' relative normal displacement per step stays below the reach.
       A sphere smaller than its type's smallest radius at init is refused when it touches
       (check_radius), since f does not cover its reach. */
    void setup_reach(const dc_normal_law *law)
    {
        const int n = atom->ntypes;
        const double inf = std::numeric_limits<double>::infinity();
        double need = 0.0;
        std::vector<double> reach((n + 1) * (n + 1), 0.0);
        adhesive = false;
        for (int i = 1; i <= n; i++)
            for (int j = 1; j <= n; j++) {
                // the reach at r_eff 1 m only tells whether the law acts beyond touching at all
                const int32_t st = dc_contact_model_reach(&step_models[i * (n + 1) + j], 1.0, &reach[i * (n + 1) + j]);
                if (st != DC_OK) reject("reach (dc_contact_model_reach) at r_eff 1 m", i, 1.0, st);
                if (reach[i * (n + 1) + j] > 0.0) adhesive = true;
            }
        if (!adhesive) return;
        std::vector<double> mine(n + 1, inf);
        rad_floor.assign(n + 1, inf);
        for (int i = 0; i < atom->nlocal; i++) mine[atom->type[i]] = std::min(mine[atom->type[i]], atom->radius[i]);
        for (int k = 0; k < modify->nfix; k++) {
            Fix *f = modify->fix[k];
            if (!f->use_rad_for_cut_neigh_and_ghost()) continue;
            for (int t = 1; t <= n; t++) {
                const double r = f->min_rad(t);
                if (r > 0.0) mine[t] = std::min(mine[t], r);
            }
        }
        MPI_Allreduce(&mine[1], &rad_floor[1], n, MPI_DOUBLE, MPI_MIN, world);
        freeze_bit = 0;
        for (int k = 0; k < modify->nfix; k++)
            if (std::strcmp(modify->fix[k]->style, "freeze") == 0) {
                freeze_bit = modify->fix[k]->groupbit;
                break;
            }
        for (int i = 1; i <= n; i++)
            for (int j = 1; j <= n; j++) {
                const double ri = rad_floor[i], rj = is_wall_model ? ri : rad_floor[j];
                if (!(ri < inf) || !(rj < inf)) continue; // no sphere of the type: any that comes is refused
                const double reff = is_wall_model ? ri : ri * rj / (ri + rj);
                double r = 0.0;
                const int32_t st = dc_contact_model_reach(&step_models[i * (n + 1) + j], reff, &r);
                if (st != DC_OK) reject("reach (dc_contact_model_reach) at the smallest radius", i, ri, st);
                need = std::max(need, r / (is_wall_model ? ri : ri + rj));
            }
        dist_factor = 1.0 + 2.0 * need;
        neighbor->register_contact_dist_factor(dist_factor);
        if (comm->me == 0) {
            char msg[300];
            std::snprintf(msg, sizeof msg,
                          "model demcontact: law %s (%s) acts beyond touching: contact distance factor %.9g "
                          "(twice its reach at the smallest radii), LIGGGHTS' now %.9g\n",
                          law->keyword, is_wall_model ? "wall" : "pairs", dist_factor, neighbor->contactDistanceFactor);
            if (screen) std::fputs(msg, screen);
            if (logfile) std::fputs(msg, logfile);
        }
    }

    // adhesive law: a sphere below its type's smallest radius at init (setup_reach) is refused
    void check_radius(int i, double rad, int type) const
    {
        if (rad < rad_floor[type]) {
            char msg[320];
            std::snprintf(msg, sizeof msg,
                          "model demcontact: atom %ld of type %d (radius %g) is smaller than the type's smallest radius "
                          "at the run's init (%g), which sized the contact distance of the adhesive law: start the "
                          "run with it (or an insertion fix that inserts it) present",
                          (long)atom->tag[i], type, rad, rad_floor[type]);
            error->one(FLERR, msg);
        }
    }

    static const int MAX_LAW_NH = 4;
    std::vector<dc_contact_spec> law_specs; // law KEYWORD: per type pair (full_spec)
    bool is_wall_model;                     // this model is a wall's (fix wall/gran)
    bool adhesive = false;                  // law KEYWORD of a law that acts beyond touching (setup_reach)
    std::vector<double> rad_floor;          // adhesive: each type's smallest radius at init
    double dist_factor = 1.0;               // adhesive: the contact distance factor registered
    int freeze_bit = 0;                     // fix freeze's group (m_eff of a pair, as LIGGGHTS' pair loop)

    const void *owner;
    double *Y, *nu;
    double **Yeff, **Geff, **coeffRest;
    std::vector<double> beta; // LIGGGHTS' betaeff = ln e / sqrt(ln^2 e + pi^2), per type pair
    bool tangential_damping, limitForce, viscoelastic = false;
    double exponent, v_ref = 1.0, r_ref = 0.0, rho_ref = 0.0;
    int ntypes;
    std::vector<dc_pair> pairs;
    std::vector<dc_contact_model> step_models; // stepExact on: per type pair, set for step_dt
    double step_dt = 0.0;

public:
    // the tangential class's combined model applies this model's normal force (set at each init)
    mutable bool deferred = false;
};

} // namespace ContactModels
} // namespace LIGGGHTS

#include "friction_models_demcontact.h"
#include "surface_model_demcontact.h"

namespace {

using namespace LIGGGHTS;
using namespace LIGGGHTS::ContactModels;

/* The words of a settings line (after `pair_style gran` / the wall's model words) as LIGGGHTS'
   Settings parse them: a copy ended by MISSING_VALUE, so that a keyword given last reads that
   word, not a stale one past the end (an on/off keyword: LIGGGHTS' error "unknown option or wrong
   keyword order: '(missing value)'"; law: "a normal-law keyword must follow"). Our keywords whose
   value is a number end the run here when given last, naming the keyword: a number parser (atof)
   would read the marker as 0. */
std::vector<char *> checked_words(LAMMPS_NS::Error *error, int nargs, char **args)
{
    static const char *const numeric[] = {"exponent", "vRef", "rRef", "densityRef", "tangentialRestitution",
                                          "rollingStiffness", "rollingDamping"};
    if (nargs > 0)
        for (const char *kw : numeric)
            if (!std::strcmp(args[nargs - 1], kw)) {
                char msg[200];
                std::snprintf(msg, sizeof msg, "model demcontact: '%s' is the last word of the line: its value is missing",
                              kw);
                error->all(FLERR, msg);
            }
    std::vector<char *> words(args, args + std::max(nargs, 0));
    words.push_back(const_cast<char *>(demcontact_law_setting::MISSING_VALUE));
    return words;
}

template<typename Base>
class CheckedPair : public Base {
public:
    CheckedPair(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::PairGran *parent, int64_t hash) : Base(lmp, parent, hash), lmp_(lmp) {}
    void settings(int nargs, char **args, IContactHistorySetup *hsetup)
    {
        std::vector<char *> words = checked_words(lmp_->error, nargs, args);
        Base::settings(nargs, words.data(), hsetup);
    }

private:
    LAMMPS_NS::LAMMPS *lmp_;
};

template<typename Base>
class CheckedWall : public Base {
public:
    CheckedWall(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::FixWallGran *parent, int64_t hash) : Base(lmp, parent, hash), lmp_(lmp) {}
    void settings(int nargs, char **args, IContactHistorySetup *hsetup)
    {
        std::vector<char *> words = checked_words(lmp_->error, nargs, args);
        Base::settings(nargs, words.data(), hsetup);
    }

private:
    LAMMPS_NS::LAMMPS *lmp_;
};

template<typename T>
PairStyles::IGranularPairStyle *create_pair(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::PairGran *parent, int64_t hash)
{
    return new CheckedPair<T>(lmp, parent, hash);
}

template<typename T>
Walls::IGranularWall *create_wall(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::FixWallGran *parent, int64_t hash)
{
    return new CheckedWall<T>(lmp, parent, hash);
}

template<int TANGENTIAL, int ROLLING, int SURFACE = SURFACE_DEFAULT>
void register_combination()
{
    typedef GranStyle<DEMCONTACT, TANGENTIAL, COHESION_OFF, ROLLING, SURFACE> Style;
    typedef ContactModel<Style> CModel;
    PairStyles::Factory::instance().addStyle("gran", Style::HASHCODE,
                                             &create_pair<PairStyles::Granular<CModel> >);
    Walls::Factory::instance().addStyle("gran", Style::HASHCODE, &create_wall<Walls::Granular<CModel> >);
}

struct RegisterDemcontact {
    RegisterDemcontact()
    {
        Factory &f = Factory::instance();
        f.addNormalModel("demcontact", DEMCONTACT);
        register_combination<TANGENTIAL_OFF, ROLLING_OFF>();
        register_combination<TANGENTIAL_NO_HISTORY, ROLLING_OFF>();
        register_combination<TANGENTIAL_HISTORY, ROLLING_OFF>();
        register_combination<TANGENTIAL_HISTORY, ROLLING_CDT>();
        register_combination<TANGENTIAL_HISTORY, ROLLING_EPSD2>();
        // demcontact's own tangential and rolling models (friction_models_demcontact.h)
        f.addTangentialModel("demcontact", DEMCONTACT_TANGENTIAL);
        f.addRollingModel("demcontact", DEMCONTACT_ROLLING);
        register_combination<DEMCONTACT_TANGENTIAL, ROLLING_OFF>();
        register_combination<DEMCONTACT_TANGENTIAL, DEMCONTACT_ROLLING>();
        register_combination<DEMCONTACT_TANGENTIAL, ROLLING_CDT>();
        // the whole contact demcontact's: LIGGGHTS' relative velocities not computed (surface_model_demcontact.h)
        f.addSurfaceModel("demcontact", DEMCONTACT_SURFACE);
        register_combination<DEMCONTACT_TANGENTIAL, DEMCONTACT_ROLLING, DEMCONTACT_SURFACE>();
    }
};

RegisterDemcontact register_demcontact;

} // namespace
