/*
 * demcontact's tangential and rolling sub-models as LIGGGHTS models, registered next to the normal
 * model "demcontact" in LIGGGHTS' own factories (included by normal_model_demcontact.cpp):
 *
 *   pair_style gran model demcontact tangential demcontact [rolling_friction demcontact [surface demcontact]]
 *              [tangentialRestitution e_t] [rollingStiffness k_r] [rollingDamping eta_r] [rollingConstant on]
 *              [projectionCarry on|off] [tangentialRescale on|off]
 *   (surface demcontact: LIGGGHTS' relative velocities, unread by the combined evaluation, not
 *   computed; surface_model_demcontact.h)
 *   fix ID all wall/gran model demcontact tangential demcontact rolling_friction demcontact primitive ...
 *   materials: coefficientFriction (mu), coefficientRollingFriction (mu_r), peratomtypepair
 *
 * tangential demcontact = DC_TANGENTIAL_MINDLIN (k_t = 8 G* a from youngsModulus/poissonsRatio,
 * damping from e_t, Coulomb limit mu |Fn|); rolling_friction demcontact = DC_ROLLING_EPSD (k_r = 0:
 * Ai et al.'s rule, limit mu_r R* |Fn|; `rollingConstant on`: DC_ROLLING_CONSTANT, the constant torque
 * mu_r R* |Fn| against the relative rolling, as LIGGGHTS' cdt). Both need `model demcontact` with
 * exponent 1.5.
 *
 * projectionCarry (an on/off setting of both sub-models, default off): how the history springs
 * (tangential, EPSD rolling) follow the contact frame (dc_contact_model_set_carry). off =
 * DC_CARRY_ROTATE (the pair's mean spin, then the tilt of the normal: objective); on =
 * DC_CARRY_PROJECT (projected on the new tangent plane and rescaled to the old length, as LAMMPS'
 * granular; LIGGGHTS' own `tangential history` projects without rescaling: cheaper, not
 * objective about the normal). LIGGGHTS' settings
 * parser rejects any value but on/off with its own error naming the value.
 *
 * One library call per contact: LIGGGHTS keeps the tangential and the rolling model in separate
 * classes, called one after the other for each contact. When both are demcontact's, the rolling
 * class (whose connectToProperties runs last) hands the tangential class one combined model per
 * type pair (demcontact's normal law + tangential + rolling sub-models): the tangential class
 * evaluates it once (dc_contact_force_checked_inline: demcontact_inline.h's header-only copy of
 * the library's dc_contact_force, bit-identical, compiled into LIGGGHTS' pair loop, the model
 * checked once per run; compiled for the models' shape when they all have one of
 * demcontact_shaped.h's: no code for the stages the run does not use; in the pair loop the
 * header's deferred entry, its checks made once per pass: begin_pass, end_pass below) and adds the whole contact
 * force (normal + tangential) and the total torques; the normal model class then computes nothing (its normal force would be the same law
 * evaluated twice) and leaves sidata.Fn/kn/kt unset, which no class of this combination reads
 * (cohesion off, rolling passive, surface default or demcontact); the rolling class adds nothing. Alone (rolling off or LIGGGHTS' cdt), the tangential class evaluates
 * a model with its own sub-model only. Each class still validates its own parameters on its own
 * (so a rejected value is named).
 *
 * History: the sub-model's dc_contact_history_len doubles in LIGGGHTS' contact history, registered
 * with newton flag "0" (never negated for the partner): every evaluation puts the atom of smaller
 * ID as body 1, so the copies LIGGGHTS keeps for the two partners are the same numbers. The
 * history advances only when LIGGGHTS says so (computeflag && shearupdate), and is zeroed when the
 * spheres separate (surfacesClose). The combined model uses the tangential and the rolling block
 * as one: they are registered one after the other (checked), and its history (the contact normal
 * is shared, so shorter than the two blocks) must fit in them (checked).
 *
 * stepExact on (a setting of model demcontact): every model here is made step-aware too
 * (dc_contact_model_set_step at LIGGGHTS' dt, again when dt changes), so that the Coulomb limit
 * sees the normal force the normal model applies (its own step slot, the normal model's). Its one
 * more history double is in the tangential block, registered with the block's length known
 * (postSettings). tangentialRescale on (a setting of tangential demcontact):
 * DC_TANGENTIAL_MINDLIN_RESCALE instead of DC_TANGENTIAL_MINDLIN (the spring force rescaled when
 * the contact radius changes: no energy gained on unloading; docs/force.md); a longer history.
 */
#ifndef DEMCONTACT_LIGGGHTS_FRICTION_MODELS_H
#define DEMCONTACT_LIGGGHTS_FRICTION_MODELS_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "cpu_dispatch.h"
#include "demcontact_shaped.h"
#include "scan_bad_values.h"

namespace LIGGGHTS {
namespace ContactModels {

// 6-bit ids in LIGGGHTS' tangential and rolling id spaces (the installed ones are small).
static const int DEMCONTACT_TANGENTIAL = 42;
static const int DEMCONTACT_ROLLING = 42;

/* The machinery both sub-models share. */
class DemcontactSubModel {
public:
    DemcontactSubModel(LAMMPS *lmp_, IContactHistorySetup *, ContactModelBase *c, bool rolling_)
        : lmp(lmp_), owner(c), rolling(rolling_)
    {
        if (!rolling) tangentials()[owner] = this;
    }

    /* Register this sub-model's history block (postSettings: the settings are known by then, and
       the normal model's postSettings, which runs first, has said whether it is step-aware): the
       length of a placeholder model of the same kind (tangentialRescale: DC_TANGENTIAL_MINDLIN_RESCALE;
       stepExact: made step-aware, one more double). The tangential block, then the rolling block,
       one after the other (LIGGGHTS' order of postSettings). */
    void register_history(IContactHistorySetup *hsetup, const NormalModel<DEMCONTACT> *normal)
    {
        dc_contact_spec s;
        // the normal model's law (law KEYWORD: its state is in this block too), else Hertz
        if (normal) {
            normal->law_placeholder(s);
        } else {
            dc_contact_spec_init(&s);
            s.normal = DC_NORMAL_HERTZ;
            s.damping = DC_DAMPING_RESTITUTION;
            s.e_n = 0.5;
            s.E1 = s.E2 = 1e7;
            s.nu1 = s.nu2 = 0.3;
        }
        s.mu = 0.5;
        s.mu_r = 0.1;
        if (rolling) s.rolling = DC_ROLLING_EPSD;
        else s.tangential = rescale ? DC_TANGENTIAL_MINDLIN_RESCALE : DC_TANGENTIAL_MINDLIN;
        dc_contact_model m;
        size_t len = 0;
        int32_t st = dc_contact_model_init(&s, &m);
        // the rolling block alone is never evaluated with a step (rolling_friction demcontact comes
        // with tangential demcontact: combine_into's model, which fits in the two blocks)
        if (st == DC_OK && !rolling && normal && normal->step_exact)
            st = dc_contact_model_set_step(&m, 1.0, DC_INTEGRATOR_VELOCITY_VERLET);
        if (st == DC_OK) st = dc_contact_history_len(&m, &len);
        nh = static_cast<int>(len);
        const char *base = rolling ? "dc_roll" : "dc_tang";
        for (int k = 0; k < nh; k++) {
            const int off = hsetup->add_history_value(std::string(base) + std::to_string(k), "0");
            if (k == 0) offset = off;
        }
    }
    ~DemcontactSubModel()
    {
        if (!rolling && tangentials().count(owner) && tangentials()[owner] == this) tangentials().erase(owner);
    }

    // The tangential sub-model of each contact model (the rolling one of the same model finds it here).
    static std::map<const void *, DemcontactSubModel *> &tangentials()
    {
        static std::map<const void *, DemcontactSubModel *> m;
        return m;
    }

    /* Build one model per type pair (both orders) from the normal model's law and this
       sub-model's parameters; reject bad values with demcontact's status text. */
    void build(LAMMPS_NS::Error *error, int ntypes_, const NormalModel<DEMCONTACT> *normal, double **coeff,
               const char *coeff_name, double e_t, double k_r, double eta_r, bool rolling_constant = false)
    {
        ntypes = ntypes_;
        if (nh == 0) error->all(FLERR, "demcontact: the library reports no history for this sub-model");
        if (!normal)
            error->all(FLERR, rolling ? "rolling_friction demcontact needs model demcontact"
                                      : "tangential demcontact needs model demcontact");
        // an adhesive law acts beyond touching, where LIGGGHTS calls the normal model's
        // surfacesClose only: the sub-models' full model (its tangential force and the Coulomb limit
        // with the adhesion-corrected load) would be left out there, so the combination is refused
        if (normal->is_adhesive())
            error->all(FLERR, rolling ? "rolling_friction demcontact with an adhesive law (law dmt, law jkr): not "
                                        "supported (the sub-models are evaluated only while the spheres overlap; "
                                        "the law acts beyond touching): use LIGGGHTS' tangential history and rolling "
                                        "models"
                                      : "tangential demcontact with an adhesive law (law dmt, law jkr): not "
                                        "supported (the sub-models are evaluated only while the spheres overlap; "
                                        "the law acts beyond touching): use tangential history");
        const size_t np = (ntypes + 1) * (ntypes + 1);
        specs.assign(np, dc_contact_spec());
        models.assign(np, dc_contact_model());
        eval_nh = nh;
        step_slot_missing = false;
        step_normal = normal->step_exact ? normal : NULL;
        step_dt = lmp->update->dt;
        passive = false;
        full_force = false;
        for (int i = 1; i <= ntypes; i++)
            for (int j = 1; j <= ntypes; j++) {
                dc_contact_spec &s = specs[i * (ntypes + 1) + j];
                if (!normal->full_spec(i, j, s))
                    error->all(FLERR, "tangential/rolling_friction demcontact need model demcontact with exponent 1.5 "
                                      "(or a law KEYWORD)");
                if (rolling) {
                    s.rolling = rolling_constant ? DC_ROLLING_CONSTANT : DC_ROLLING_EPSD;
                    s.mu_r = coeff[i][j];
                    s.k_r = k_r;
                    s.eta_r = eta_r;
                } else {
                    s.tangential = rescale ? DC_TANGENTIAL_MINDLIN_RESCALE : DC_TANGENTIAL_MINDLIN;
                    s.mu = coeff[i][j];
                    s.e_t = e_t;
                }
                int32_t st = dc_contact_model_init(&s, &models[i * (ntypes + 1) + j]);
                if (st == DC_OK) st = dc_contact_model_set_carry(&models[i * (ntypes + 1) + j], carry());
                if (st == DC_OK && normal->step_exact) st = normal->set_step(models[i * (ntypes + 1) + j], lmp->update->dt);
                if (st == DC_OK) st = dc_contact_model_check_inline(&models[i * (ntypes + 1) + j]); // fast entry
                size_t len = 0;
                if (st == DC_OK) st = dc_contact_history_len(&models[i * (ntypes + 1) + j], &len);
                // the rolling block has no step slot: rolling_friction demcontact is evaluated by
                // combine_into's model, which fits in the two blocks
                if (st == DC_OK && static_cast<int>(len) > nh) step_slot_missing = true;
                if (st == DC_OK && !step_slot_missing) eval_nh = std::max(eval_nh, static_cast<int>(len));
                if (st != DC_OK) {
                    char msg[400];
                    if (rolling)
                        std::snprintf(msg, sizeof msg,
                                      "rolling_friction demcontact: types %d-%d (%s = %g, rollingStiffness = %g, "
                                      "rollingDamping = %g) rejected by demcontact: %s",
                                      i, j, coeff_name, coeff[i][j], k_r, eta_r, dc_status_str(st));
                    else
                        std::snprintf(msg, sizeof msg,
                                      "tangential demcontact: types %d-%d (%s = %g, tangentialRestitution = %g) "
                                      "rejected by demcontact: %s",
                                      i, j, coeff_name, coeff[i][j], e_t, dc_status_str(st));
                    error->all(FLERR, msg);
                }
            }
        choose_eval();
    }

    /* The evaluation for this run (demcontact_shaped.h): the instantiation of the models' shape
       when every type pair's model has the same one, else the generic entry (same bits). */
    void choose_eval()
    {
        // the type pairs (i, j), 1 <= i, j <= ntypes, of models[(ntypes + 1)^2]
        const int n = ntypes;
        const std::vector<dc_contact_model> &m = models;
        auto at = [&m, n](int k) -> const dc_contact_model & { return m[(k / n + 1) * (n + 1) + k % n + 1]; };
        // the x86-64-v4 variant where the CPU has it (cpu_dispatch.h): same bits, 11-13 % less loop
        // time on the settled bed; said once per process in the run's output (the tests compare the
        // variants' dumps and read which ran)
        const bool v4 = demcontact_dispatch::use_v4();
        static const bool said = [this, v4] {
            if (lmp->comm->me != 0) return true;
            const char *what = v4 ? "x86-64-v4 (AVX-512), chosen at run time"
                               : DC_DISPATCH_V4 ? "the baseline x86-64 (no x86-64-v4 here, or DEMCONTACT_DISPATCH=baseline or avx2)"
                                                : "the build's target (no run-time dispatch in this build)";
            const char *unknown = demcontact_dispatch::unknown_setting();
            for (FILE *f : {lmp->screen, lmp->logfile}) {
                if (!f) continue;
                if (unknown)
                    std::fprintf(f, "demcontact: WARNING: DEMCONTACT_DISPATCH = '%s' not understood (only 'baseline', 'avx2', "
                                    "'auto'): "
                                    "ignored\n", unknown);
                std::fprintf(f, "demcontact: contact body compiled for %s\n", what);
            }
            return true;
        }();
        (void)said;
        if (v4) {
            body = demcontact_shaped::pick_common<BodyOf<false, true> >(n * n, at);
            body_per_pass = demcontact_shaped::pick_common<BodyOf<true, true> >(n * n, at);
        } else {
            body = demcontact_shaped::pick_common<BodyOf<false, false> >(n * n, at);
            body_per_pass = demcontact_shaped::pick_common<BodyOf<true, false> >(n * n, at);
        }
    }

    typedef void (DemcontactSubModel::*Body)(const SurfacesIntersectData &, ForceData &, ForceData &);
    template <bool PER_PASS, bool V4>
    struct BodyOf { // demcontact_shaped::pick's visitor: intersect_with instantiated for a shape
        typedef Body type;
        template <class S>
        static type get()
        {
#if DC_DISPATCH_V4
            if (V4) return &DemcontactSubModel::intersect_with_v4<S, PER_PASS>;
#endif
            return &DemcontactSubModel::intersect_with<S, PER_PASS>;
        }
    };

    /* Rolling sub-model only, after both build()s: hand the tangential sub-model of the same
       contact model one combined model per type pair, so each contact costs one library call;
       this sub-model then adds nothing itself. */
    void combine_into(LAMMPS_NS::Error *error, DemcontactSubModel &t, const NormalModel<DEMCONTACT> *normal)
    {
        if (t.offset + t.nh != offset)
            error->all(FLERR, "tangential/rolling_friction demcontact: history blocks not adjacent");
        if (t.ntypes != ntypes || t.specs.size() != specs.size())
            error->all(FLERR, "tangential/rolling_friction demcontact: type counts differ");
        size_t len_max = 0;
        for (int i = 1; i <= ntypes; i++)
            for (int j = 1; j <= ntypes; j++) {
                const int p = i * (ntypes + 1) + j;
                dc_contact_spec s = t.specs[p];
                s.rolling = specs[p].rolling;
                s.mu_r = specs[p].mu_r;
                s.k_r = specs[p].k_r;
                s.eta_r = specs[p].eta_r;
                dc_contact_model m;
                size_t len = 0;
                int32_t st = dc_contact_model_init(&s, &m);
                if (st == DC_OK) st = dc_contact_model_set_carry(&m, t.carry()); // one setting for both classes
                if (st == DC_OK && t.step_normal) st = t.step_normal->set_step(m, lmp->update->dt);
                if (st == DC_OK) st = dc_contact_history_len(&m, &len);
                if (st == DC_OK) st = dc_contact_model_check_inline(&m); // for the fast entry
                if (st != DC_OK || static_cast<int>(len) > t.nh + nh || len > MAX_NH) {
                    char msg[300];
                    std::snprintf(msg, sizeof msg,
                                  "tangential + rolling_friction demcontact: combined model of types %d-%d: %s "
                                  "(history %d, more than the %d registered)",
                                  i, j, dc_status_str(st), static_cast<int>(len), t.nh + nh);
                    error->all(FLERR, msg);
                }
                t.models[p] = m;
                len_max = std::max(len_max, len);
            }
        t.eval_nh = static_cast<int>(len_max);
        t.step_slot_missing = false;
        t.choose_eval();
        passive = true;
        // the combined model's normal force is the normal model's (same law and calibration,
        // full_spec), so the tangential class applies the whole contact force and the normal
        // model computes nothing (one normal-force evaluation per contact instead of two; the
        // force on an atom then differs from the two-class sum by rounding only)
        if (normal) {
            t.full_force = true;
            normal->deferred = true;
        }
    }

    void intersect(const SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        if (passive) return; // evaluated with the tangential sub-model's combined model
        if (step_normal && (lmp->update->dt != step_dt || step_slot_missing)) follow_dt();
        (this->*(in_pass ? body_per_pass : body))(sidata, i_forces, j_forces);
    }

    /* intersect's body for the models' shape S (demcontact_shaped.h): S::eval inlined into it, the
       result in registers (through a pointer to the evaluation alone, the force was read back from
       memory right after the callee's stores: a store-to-load forwarding stall per contact). */
    template <class S, bool PER_PASS>
    void intersect_with(const SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        contact_body<S, PER_PASS>(sidata, i_forces, j_forces);
    }
#if DC_DISPATCH_V4
    /* The same body compiled for x86-64-v4 (AVX-512's 32 vector registers: the baseline build
       spills the contact's vectors to the stack), chosen at run time where the CPU has it
       (cpu_dispatch.h). Without GCC's SLP vectoriser: with it, the x86-64-v4 body packs the
       contact's 3-vectors into pairs and shuffles them, 15 % slower with the rotate carry than the
       baseline (docs/simulators.md). No 512-bit instructions (prefer-vector-width=256 here, and
       CMakeLists.txt's -mmove-max/-mstore-max=256 for block copies): on some Intel cores those
       lower the clock; ctest liggghts_plugin_code checks the plugin has none, and no FMA. Same bits:
       no contraction (the plugin's -ffp-contract=off holds in this function too), no reassociation.
       An attribute, not a second source file built with -march=x86-64-v4: there, the inline
       functions both files use could be linked in their AVX-512 copies for every caller. */
    template <class S, bool PER_PASS>
    __attribute__((target("arch=x86-64-v4,prefer-vector-width=256"), optimize("no-tree-slp-vectorize"))) void
    intersect_with_v4(const SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        contact_body<S, PER_PASS>(sidata, i_forces, j_forces);
    }
#endif

    template <class S, bool PER_PASS>
    __attribute__((always_inline)) inline void contact_body(const SurfacesIntersectData &sidata, ForceData &i_forces,
                                                              ForceData &j_forces)
    {
        const double inf = std::numeric_limits<double>::infinity();
        const int i = sidata.i, j = sidata.j;
        LAMMPS_NS::Atom *atom = lmp->atom;
        // body 1 = the sphere of smaller ID (walls: the sphere), so both partners' copies agree
        const bool swap = !sidata.is_wall && atom->tag[j] < atom->tag[i];
        const double sg = swap ? -1.0 : 1.0;
        dc_contact_state s;
        for (int k = 0; k < 3; k++) s.n[k] = sg * sidata.en[k];
        s.overlap = sidata.deltan;
        const double *vi = sidata.v_i ? sidata.v_i : atom->v[i];
        const double *wi = sidata.omega_i ? sidata.omega_i : atom->omega[i];
        static const double zero[3] = {0.0, 0.0, 0.0};
        const double *vj, *wj = zero;
        double rj = inf, mj = inf;
        if (sidata.is_wall) {
            vj = sidata.v_j ? sidata.v_j : zero; // the wall's velocity
        } else {
            vj = sidata.v_j ? sidata.v_j : atom->v[j];
            wj = sidata.omega_j ? sidata.omega_j : atom->omega[j];
            rj = sidata.radj;
            mj = sidata.mj;
        }
        const double *v1 = swap ? vj : vi, *v2 = swap ? vi : vj, *w1 = swap ? wj : wi, *w2 = swap ? wi : wj;
        for (int k = 0; k < 3; k++) {
            s.v1[k] = v1[k];
            s.v2[k] = v2[k];
            s.w1[k] = w1[k];
            s.w2[k] = w2[k];
        }
        s.r1 = swap ? rj : sidata.radi;
        s.r2 = swap ? sidata.radi : rj;
        s.m1 = swap ? mj : sidata.mi;
        s.m2 = swap ? sidata.mi : mj;
        const int t1 = swap ? sidata.jtype : sidata.itype, t2 = swap ? sidata.itype : sidata.jtype;

        double *h = &sidata.contact_history[offset];
        double copy[MAX_NH];
        if (!(sidata.computeflag && sidata.shearupdate)) { // evaluate without advancing the history
            for (int k = 0; k < eval_nh; k++) copy[k] = h[k];
            h = copy;
        }
        dc_contact_result r;
        // models[] passed dc_contact_model_check_inline in build/combine_into; h: eval_nh >= the
        // model's history length
        // S::eval: dc_contact_force_checked_inline, or its instantiation for the models' shape (same bits).
        // Inside the pair loop (PER_PASS: between begin_pass and end_pass) the deferred entry: the
        // states' values checked once per pass in begin_pass (the atoms' arrays they come from),
        // the history and result checks collected and tested in end_pass, before LIGGGHTS
        // integrates (the checked entry's bits, built without FMA contraction as CMakeLists.txt
        // does; 15-18 % of this body's time was the per-contact checks)
        const dc_contact_model *model = &models[t1 * (ntypes + 1) + t2];
        const int32_t st = PER_PASS ? S::eval_deferred(model, &s, lmp->update->dt, h, &r, &checks)
                                    : S::eval(model, &s, lmp->update->dt, h, &r);
        if (st != DC_OK) {
            char msg[200];
            std::snprintf(msg, sizeof msg, "%s demcontact: atom %ld: %s", rolling ? "rolling_friction" : "tangential",
                          (long)atom->tag[i], dc_status_str(st));
            lmp->error->one(FLERR, msg);
        }
        // the tangential force and the torques of the evaluated sub-models (tangential class: its
        // torques, or with the combined model those of both; rolling class alone: rolling torques)
        // (full_force: the normal force too, the normal model having deferred it). Values selected,
        // not pointers into r: 1 % fewer instructions in this body (callgrind, docs/simulators.md)
        const double scale = sidata.is_wall ? sidata.area_ratio : 1.0;
        for (int k = 0; k < 3; k++) {
            const double fr = full_force ? r.force[k] : r.ft[k];
            const double ti = swap ? r.torque2[k] : r.torque1[k], tj = swap ? r.torque1[k] : r.torque2[k];
            if (!rolling) {
                i_forces.delta_F[k] += sg * scale * fr;
                if (!sidata.is_wall) j_forces.delta_F[k] -= sg * fr;
            }
            i_forces.delta_torque[k] += scale * ti;
            if (!sidata.is_wall) j_forces.delta_torque[k] += tj;
        }
    }

    /* The pair loop's pass (LIGGGHTS' beginPass/endPass around it; fix wall/gran has none, so
       wall contacts keep the per-contact checks). begin_pass: the checks the deferred entry
       leaves to its caller (dc_contact_state_check_inline's), made on what the pass's states are
       built from: dt, and every local and ghost atom's radius and mass (finite, > 0), velocity
       and angular velocity (finite). Not checked here: the contact normal and overlap, which
       LIGGGHTS computes from positions (unit and finite unless two atoms (nearly) coincide or a
       position is not finite: coinciding atoms or a position not finite give results not finite,
       and end_pass ends the run; atoms closer than ~1e-154 m give a finite normal that is not unit,
       which the per-contact check would reject). */
    void begin_pass()
    {
        in_pass = false; // set again below only when this pass's checks are made
        if (passive || eval_nh == 0) return; // evaluated by the tangential class / not built
        dc_contact_checks_init_inline(&checks);
        const double dt = lmp->update->dt;
        if (!(std::isfinite(dt) && dt > 0.0)) {
            char msg[200];
            std::snprintf(msg, sizeof msg, "pair gran demcontact: timestep = %g: %s", dt,
                          dc_status_str(std::isfinite(dt) ? DC_ERR_NOT_POSITIVE : DC_ERR_NOT_FINITE));
            lmp->error->one(FLERR, msg);
        }
        LAMMPS_NS::Atom *atom = lmp->atom;
        // only where every state value comes from these arrays (per-atom masses, no rigid-body
        // masses, no multicontact radii) and the normal is LIGGGHTS' sphere normal (set only for
        // sphere atoms); else the per-contact checks, as on walls
        LAMMPS_NS::PairGran *pg = dynamic_cast<LAMMPS_NS::PairGran *>(lmp->force->pair);
        if (!pg || !atom->rmass || !atom->radius || !atom->v || !atom->omega || pg->fr_pair() ||
            pg->storeSumDelta() || atom->superquadric_flag || !atom->sphere_flag || atom->shapetype_flag)
            return;
        const int n = atom->nlocal + atom->nghost;
        // one flag over the arrays (scan_bad_values.h: integer bit tests, OR-reduced, vectorised);
        // the atom found only when the flag is set
        using demcontact_scan::bad_values;
        if (n == 0 || !(bad_values(atom->v[0], 3 * n, false) | bad_values(atom->omega[0], 3 * n, false) |
                        bad_values(atom->radius, n, true) | bad_values(atom->rmass, n, true))) {
            in_pass = true;
            return;
        }
        for (int i = 0; i < n; i++) {
            const double vals[8] = {atom->radius[i], atom->rmass[i], atom->v[i][0], atom->v[i][1], atom->v[i][2],
                                    atom->omega[i][0], atom->omega[i][1], atom->omega[i][2]};
            static const char *names[8] = {"radius", "mass", "vx", "vy", "vz", "omegax", "omegay", "omegaz"};
            // the state check's order: any value not finite first, then a radius or mass not > 0
            for (int k = 0; k < 16; k++) {
                const double x = vals[k % 8];
                const int32_t st = k < 8 ? (std::isfinite(x) ? DC_OK : DC_ERR_NOT_FINITE)
                                   : k % 8 < 2 && !(x > 0.0) ? DC_ERR_NOT_POSITIVE : DC_OK;
                if (st == DC_OK) continue;
                char msg[300];
                std::snprintf(msg, sizeof msg, "pair gran demcontact: atom %ld: %s = %g: %s", (long)atom->tag[i],
                              names[k % 8], x, dc_status_str(st));
                lmp->error->one(FLERR, msg);
            }
        }
        lmp->error->one(FLERR, "pair gran demcontact: internal error: atom check failed without a bad value");
    }

    /* After the pair loop: the collected history and result checks (dc_contact_checks_status_inline);
       on an error the run ends here, before LIGGGHTS integrates the pass's forces. The atom named
       is one whose force or torque is not finite, when there is one. */
    void end_pass()
    {
        if (!in_pass) return;
        in_pass = false;
        const int32_t st = dc_contact_checks_status_inline(&checks);
        if (st == DC_OK) return;
        LAMMPS_NS::Atom *atom = lmp->atom;
        long who = -1;
        for (int i = 0; i < atom->nlocal + atom->nghost && who < 0; i++) // ghosts: newton on
            for (int k = 0; k < 3; k++)
                if (!std::isfinite(atom->f[i][k]) || !std::isfinite(atom->torque[i][k])) who = (long)atom->tag[i];
        char msg[300];
        if (who >= 0)
            std::snprintf(msg, sizeof msg, "%s demcontact: step %ld: %s (atom %ld: force or torque not finite)",
                          rolling ? "rolling_friction" : "tangential", (long)lmp->update->ntimestep,
                          dc_status_str(st), who);
        else
            std::snprintf(msg, sizeof msg, "%s demcontact: step %ld: %s (in a contact's results or history)",
                          rolling ? "rolling_friction" : "tangential", (long)lmp->update->ntimestep,
                          dc_status_str(st));
        lmp->error->one(FLERR, msg);
    }

    /* stepExact: dt changed during the run (not at an init): the models follow it. */
    __attribute__((noinline)) void follow_dt()
    {
        if (step_slot_missing) // not met by the combinations registered (normal_model_demcontact.cpp)
            lmp->error->one(FLERR, "demcontact: stepExact: this sub-model's history block has no step slot");
        const double dt = lmp->update->dt;
        for (int i = 1; i <= ntypes; i++)
            for (int j = 1; j <= ntypes; j++) {
                const int32_t s = step_normal->set_step(models[i * (ntypes + 1) + j], dt);
                if (s != DC_OK) step_normal->step_error(dt, s, false);
            }
        step_dt = dt;
    }

    void close(SurfacesCloseData &scdata)
    {
        if (!scdata.contact_history) return;
        std::memset(&scdata.contact_history[offset], 0, sizeof(double) * nh);
    }

    int32_t carry() const { return project ? DC_CARRY_PROJECT : DC_CARRY_ROTATE; }

    static const size_t MAX_NH = 32;
    LAMMPS *lmp;
    bool project = false; // setting projectionCarry (registered by both classes: one value)
    const void *owner;
    bool rolling;
    bool passive = false; // rolling: evaluated by the tangential sub-model (combined model)
    bool in_pass = false; // inside the pair loop's pass: the deferred entry (begin_pass/end_pass)
    dc_contact_checks checks; // the pass's collected checks
    bool full_force = false; // tangential with the combined model: applies the normal force too
    int nh = 0, offset = 0, ntypes = 0;
    int eval_nh = 0; // history doubles of the evaluated model (nh, or tangential + rolling combined)
    const NormalModel<DEMCONTACT> *step_normal = NULL; // stepExact on: its normal model (set_step)
    double step_dt = 0.0;                              // the dt the models are set for
    bool step_slot_missing = false; // stepExact: this sub-model alone would have no step slot
    bool rescale = false; // setting tangentialRescale: DC_TANGENTIAL_MINDLIN_RESCALE
    Body body = &DemcontactSubModel::intersect_with<demcontact_shaped::Generic, false>; // choose_eval
    Body body_per_pass = &DemcontactSubModel::intersect_with<demcontact_shaped::Generic, true>; // in a pass
    std::vector<dc_contact_spec> specs;
    std::vector<dc_contact_model> models;
};

template<>
class TangentialModel<DEMCONTACT_TANGENTIAL> : public TangentialModelBase {
public:
    TangentialModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c)
        : TangentialModelBase(lmp, hsetup, c), sub(lmp, hsetup, c, false), coeffFrict(NULL), e_t(1.0) {}

    void registerSettings(Settings &settings)
    {
        settings.registerDoubleSetting("tangentialRestitution", e_t, 1.0);
        settings.registerOnOff("projectionCarry", sub.project, false);
        settings.registerOnOff("tangentialRescale", sub.rescale, false);
    }
    void postSettings(IContactHistorySetup *hsetup, ContactModelBase *)
    {
        const auto &normals = NormalModel<DEMCONTACT>::demcontact_normals();
        auto it = normals.find(sub.owner);
        sub.register_history(hsetup, it == normals.end() ? NULL : it->second);
    }
    void connectToProperties(PropertyRegistry &registry)
    {
        registry.registerProperty("coeffFrict", &MODEL_PARAMS::createCoeffFrict, false);
        registry.connect("coeffFrict", coeffFrict, "tangential_model demcontact");
        const auto &normals = NormalModel<DEMCONTACT>::demcontact_normals();
        auto it = normals.find(sub.owner);
        sub.build(error, atom->ntypes, it == normals.end() ? NULL : it->second, coeffFrict, "coefficientFriction",
                  e_t, 0.0, 0.0);
    }
    void surfacesIntersect(const SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_TANGENTIAL_MODEL;
        sub.intersect(sidata, i_forces, j_forces);
    }
    void surfacesClose(SurfacesCloseData &scdata, ForceData &, ForceData &)
    {
        if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_TANGENTIAL_MODEL;
        sub.close(scdata);
    }
    void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) { sub.begin_pass(); }
    void endPass(SurfacesIntersectData &, ForceData &, ForceData &) { sub.end_pass(); }

private:
    DemcontactSubModel sub;
    double **coeffFrict;
    double e_t;
};

template<>
class RollingModel<DEMCONTACT_ROLLING> : public RollingModelBase {
public:
    RollingModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c)
        : RollingModelBase(lmp, hsetup, c), sub(lmp, hsetup, c, true), coeffRollFrict(NULL), k_r(0.0), eta_r(0.0) {}

    void registerSettings(Settings &settings)
    {
        settings.registerDoubleSetting("rollingStiffness", k_r, 0.0);
        settings.registerDoubleSetting("rollingDamping", eta_r, 0.0);
        settings.registerOnOff("rollingConstant", constant, false);
        settings.registerOnOff("projectionCarry", sub.project, false);
    }
    void postSettings(IContactHistorySetup *hsetup, ContactModelBase *) { sub.register_history(hsetup, NULL); }
    void connectToProperties(PropertyRegistry &registry)
    {
        registry.registerProperty("coeffRollFrict", &MODEL_PARAMS::createCoeffRollFrict, false);
        registry.connect("coeffRollFrict", coeffRollFrict, "rolling_model demcontact");
        const auto &normals = NormalModel<DEMCONTACT>::demcontact_normals();
        auto it = normals.find(sub.owner);
        sub.build(error, atom->ntypes, it == normals.end() ? NULL : it->second, coeffRollFrict,
                  "coefficientRollingFriction", 1.0, k_r, eta_r, constant);
        // the tangential model of the same contact model connected before this one (LIGGGHTS'
        // order: normal, cohesion, tangential, rolling): one combined evaluation per contact
        const auto &tangentials = DemcontactSubModel::tangentials();
        auto t = tangentials.find(sub.owner);
        if (t != tangentials.end()) sub.combine_into(error, *t->second, it == normals.end() ? NULL : it->second);
    }
    void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
        sub.intersect(sidata, i_forces, j_forces);
    }
    void surfacesClose(SurfacesCloseData &scdata, ForceData &, ForceData &) { sub.close(scdata); }
    void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) { sub.begin_pass(); }
    void endPass(SurfacesIntersectData &, ForceData &, ForceData &) { sub.end_pass(); }

private:
    DemcontactSubModel sub;
    double **coeffRollFrict;
    double k_r, eta_r;
    bool constant = false;
};

} // namespace ContactModels
} // namespace LIGGGHTS

#endif
