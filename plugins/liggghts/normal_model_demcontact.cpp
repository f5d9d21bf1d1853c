/*
 * LIGGGHTS 3.8 normal contact model "demcontact", compiled against the installed LIGGGHTS headers
 * (Debian libliggghts-dev) and loaded into the stock `liggghts` executable with LD_PRELOAD:
 *
 *   pair_style gran model demcontact tangential history [limitForce on] [exponent 1.5] [stepExact on]
 *   fix wall wall/gran model demcontact tangential history primitive type 1 zplane 0.0 [stepExact on]
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
#include "tsuji_force.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace LIGGGHTS {
namespace ContactModels {

// 6-bit model id; the installed ids are 0..12 (NORMAL_OFF = 9). Checked at registration.
static const int DEMCONTACT = 42;

template<>
class NormalModel<DEMCONTACT> : public NormalModelBase
{
public:
    NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c)
        : NormalModelBase(lmp, hsetup, c), owner(c), Y(NULL), nu(NULL), Yeff(NULL), Geff(NULL), coeffRest(NULL),
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
    }

    // The tangential/rolling models of the same contact model find this normal model here.
    void postSettings(IContactHistorySetup *hsetup, ContactModelBase *)
    {
        demcontact_normals()[owner] = this;
        if (step_exact) step_offset = hsetup->add_history_value("dc_step", "0");
    }
    ~NormalModel()
    {
        if (demcontact_normals().count(owner) && demcontact_normals()[owner] == this) demcontact_normals().erase(owner);
    }

    /* The normal part of a full-contact spec for types i, j (body 1 of type i): the same law as
       this model's force (Hertz or viscoelastic Hertz; not other exponents). */
    bool full_spec(int i, int j, dc_contact_spec &s) const
    {
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
        registry.connect("coeffRest", coeffRest, "model demcontact");
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

        // LIGGGHTS' vn is negative while approaching; demcontact's is positive while compressing.
        // (units si/cgs: nktv2p = 1, as the builtin models assume for the force itself.)
        const double Fn = step_exact ? step_force(sidata, reff, meff)
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
        sidata.gamman = pair.model == DC_MODEL_HERTZ ? pair.c * std::sqrt(meff * sqrtval)
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

    void surfacesClose(SurfacesCloseData &scdata, ForceData &, ForceData &)
    {
        if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
        if (step_offset >= 0 && scdata.contact_history) // a new contact starts from zero
            scdata.contact_history[step_offset] = 0.0;
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
    bool step_exact = false;
    int step_offset = -1; // history index of "dc_step"; -1: off
    void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
    void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

private:
    /* The step-aware normal force of one contact (stepExact on): demcontact's full contact with no
       sub-model, on a state with the same overlap, normal speed, r_eff and m_eff (body 2 with
       infinite radius and mass, at rest: r_eff, m_eff exact), its slot "dc_step" in LIGGGHTS'
       contact history, advanced only when LIGGGHTS says so (computeflag && shearupdate). */
    double step_force(SurfacesIntersectData &sidata, double reff, double meff)
    {
        const double dt = update->dt;
        if (dt != step_dt) { // dt changed during the run (not at an init): follow it
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
        double *slot = &sidata.contact_history[step_offset], copy;
        if (!(sidata.computeflag && sidata.shearupdate)) { // evaluate without advancing the history
            copy = *slot;
            slot = &copy;
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

template<typename T>
PairStyles::IGranularPairStyle *create_pair(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::PairGran *parent, int64_t hash)
{
    return new T(lmp, parent, hash);
}

template<typename T>
Walls::IGranularWall *create_wall(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::FixWallGran *parent, int64_t hash)
{
    return new T(lmp, parent, hash);
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
