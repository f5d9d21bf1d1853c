/*
 * What the wall fixes of the LAMMPS plugin share (fix demcontact/wall, fix demcontact/wall/region):
 *
 *  - the contact model of the wall, read from the same arguments as pair_coeff after "I J"
 *    (dc_coeff.h: parse_coeff, make_model), the wall's material being the contact's on both sides;
 *  - the rigid wall as body 2 of every contact: r2 = m2 = +inf (r_eff = particle radius,
 *    m_eff = particle mass), no spin, the velocity of its surface at the contact point given;
 *  - per-atom contact histories, when the model has one: `nslot` slots per atom, each a key
 *    (which wall face: -1 = free) and nh doubles, that migrate with the atom (exchange) and are
 *    written to restart files (define the fix again with the same ID after read_restart);
 *  - one contact's evaluation (contact_eval) and the force and torque it adds to the atom.
 *
 * Restart record of an atom: [count, nh, nslot, nslot keys, nslot x nh doubles]. A restart written
 * with another history length or slot count restores no history (a warning; contacts restart at
 * zero).
 */
#ifndef DEMCONTACT_LAMMPS_FIX_WALL_BASE_H
#define DEMCONTACT_LAMMPS_FIX_WALL_BASE_H

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "group.h"
#include "memory.h"
#include "update.h"

#include "dc_coeff.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

namespace demcontact_lammps {

using namespace LAMMPS_NS;

class FixDemcontactWallBase : public Fix {
public:
    FixDemcontactWallBase(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg) {}

    ~FixDemcontactWallBase() override
    {
        if (registered) {
            atom->delete_callback(id, Atom::GROW);
            atom->delete_callback(id, Atom::RESTART);
        }
        memory->destroy(hist);
        memory->destroy(key);
    }

    int setmask() override { return FixConst::POST_FORCE; }

    void init() override
    {
        if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
            error->all(FLERR, "fix {} {} requires atom_style sphere", id, style);
        apply_dt();
        init_reach();
    }

    /* fix dt/reset, or timestep between runs: a step_exact model follows the new dt. */
    void reset_dt() override { apply_dt(); }

    void setup(int vflag) override { post_force(vflag); }

    void grow_arrays(int nmax) override
    {
        memory->grow(hist, nmax, nslot * nh, "demcontact/wall:hist");
        memory->grow(key, nmax, nslot, "demcontact/wall:key");
    }

    void copy_arrays(int i, int j, int) override
    {
        std::memcpy(hist[j], hist[i], sizeof(double) * nslot * nh);
        std::memcpy(key[j], key[i], sizeof(int) * nslot);
    }

    void set_arrays(int i) override { clear(i); }

    int pack_exchange(int i, double *buf) override
    {
        int m = 0;
        for (int s = 0; s < nslot; s++) buf[m++] = key[i][s];
        for (int k = 0; k < nslot * nh; k++) buf[m++] = hist[i][k];
        return m;
    }

    int unpack_exchange(int nlocal, double *buf) override
    {
        int m = 0;
        for (int s = 0; s < nslot; s++) key[nlocal][s] = static_cast<int>(buf[m++]);
        for (int k = 0; k < nslot * nh; k++) hist[nlocal][k] = buf[m++];
        return m;
    }

    int pack_restart(int i, double *buf) override
    {
        int m = 1;
        buf[m++] = nh;
        buf[m++] = nslot;
        for (int s = 0; s < nslot; s++) buf[m++] = key[i][s];
        for (int k = 0; k < nslot * nh; k++) buf[m++] = hist[i][k];
        buf[0] = m;
        return m;
    }

    void unpack_restart(int nlocal, int nth) override
    {
        double **extra = atom->extra;
        int m = 0;
        for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
        const double *rec = &extra[nlocal][m];
        clear(nlocal);
        const int rnh = static_cast<int>(rec[1]), rslot = static_cast<int>(rec[2]);
        if (rnh != nh || rslot != nslot) {
            if (!warned_restart && comm->me == 0)
                error->warning(FLERR, "fix {} {}: the restart file's wall contact histories have {} doubles in {} "
                                      "slots, the model now {} in {}: they restart at zero",
                               id, style, rnh, rslot, nh, nslot);
            warned_restart = true;
            return;
        }
        for (int s = 0; s < nslot; s++) key[nlocal][s] = static_cast<int>(rec[3 + s]);
        for (int k = 0; k < nslot * nh; k++) hist[nlocal][k] = rec[3 + nslot + k];
    }

    int size_restart(int) override { return 3 + nslot * (1 + nh); }
    int maxsize_restart() override { return 3 + nslot * (1 + nh); }

    double memory_usage() override { return (double)atom->nmax * nslot * (sizeof(int) + sizeof(double) * nh); }

protected:
    /* step_exact: the model follows update->dt (no-op otherwise; the history length is unchanged). */
    void apply_dt()
    {
        const int32_t s = set_model_dt(model, update->dt);
        if (s != DC_OK)
            error->all(FLERR, "fix {} {}: step_exact at timestep {} rejected by demcontact: {}", id, style,
                       update->dt, dc_status_str(s));
    }

    /* The wall's contact model from arg[0..narg) (what = "fix ID style" for messages), and per-atom
       history storage of `slots` slots when the model has a history. */
    void setup_model(int narg, char **arg, int slots)
    {
        const std::string what = fmt::format("fix {} {}", id, style);
        Coeff &c = coeff;
        parse_coeff(lmp, error, what, narg, arg, false, c);
        const int32_t s = make_model(c, c, c, model, update->dt);
        if (s != DC_OK)
            error->all(FLERR, "{}: {}{}", what,
                       c.step_exact ? fmt::format("step_exact at timestep {}: ", update->dt) : "", dc_status_str(s));
        nh = model.nh;
        if (nh > 32) error->all(FLERR, "{}: history of {} doubles exceeds 32", what, nh);
        if (nh > 0) {
            nslot = slots;
            create_attribute = 1;
            restart_peratom = 1;
            maxexchange = nslot * (1 + nh);
            atom->add_callback(Atom::GROW);
            atom->add_callback(Atom::RESTART);
            registered = true;
            grow_arrays(atom->nmax);
            for (int i = 0; i < atom->nlocal; i++) clear(i);
        }
    }

    /* A new slot count (the region's wall count changed between runs): every history restarts. */
    void resize_slots(int slots)
    {
        if (nh == 0 || slots == nslot) return;
        memory->destroy(hist);
        memory->destroy(key);
        nslot = slots;
        maxexchange = nslot * (1 + nh);
        grow_arrays(atom->nmax);
        for (int i = 0; i < atom->nlocal; i++) clear(i);
    }

    /* The contact of owned atom i with the wall: normal n (unit, from the wall to the atom), overlap
       (> 0, or <= 0 where an adhesive law acts), vwall the velocity of the wall's surface at the
       contact point, h the contact's nh doubles
       of history (nullptr when nh = 0). Adds the force and torque to the atom. */
    void apply(int i, const double n[3], double overlap, const double vwall[3], double *h)
    {
        double **v = atom->v, **f = atom->f, **omega = atom->omega, **torque = atom->torque;
        State s;
        s.r2 = s.m2 = std::numeric_limits<double>::infinity();
        for (int k = 0; k < 3; k++) {
            s.n[k] = n[k];
            s.v1[k] = v[i][k];
            s.w1[k] = omega[i][k];
            s.v2[k] = vwall[k];
            s.w2[k] = 0.0;
        }
        s.overlap = overlap;
        s.r1 = atom->radius[i];
        s.m1 = atom->rmass[i];
        Result out;
        const int32_t st = contact_eval(model, s, update->dt, h, out);
        if (st != DC_OK) error->one(FLERR, "fix {} {}: atom {}: {}", id, style, atom->tag[i], dc_status_str(st));
        for (int k = 0; k < 3; k++) {
            f[i][k] += out.force[k];
            torque[i][k] += out.torque1[k];
        }
    }

    /* How far beyond touching the wall's law may act on owned atom i: the reach (law_reach, R* =
       the radius) at the largest radius of the group, computed at init (init_reach) and again on
       this rank when atom i is larger still (a radius grown during the run: fix adapt, a
       particle inserted by fix pour/deposit), never per atom and step. A bound: demcontact gives
       no force beyond the atom's own reach (DMT's tail ends at its d_c, a JKR neck breaks at its
       |delta_c|), so a bound from a larger radius changes no force. 0 for a law that acts only
       while overlapping. */
    double reach_of(int i)
    {
        if (model.adhesive == ADH_NONE) return 0.0;
        const double r = atom->radius[i];
        if (r > reach_radius) {
            const double rch = reach_at(r);
            if (!std::isfinite(rch))
                error->one(FLERR, "fix {} {}: atom {}: the adhesive law's reach at its radius {} is not a finite double: {}",
                           id, style, atom->tag[i], r, dc_status_str(reach_status));
            reach_radius = r;
            reach_bound = rch;
        }
        return reach_bound;
    }

    /* The reach at the group's largest radius (MPI max over the ranks; 0 for an empty group):
       every run's init. A reach that is not finite (the library's status: a radius or a work of
       adhesion too large for the law's length to be a double) is an error naming the radius. */
    void init_reach()
    {
        reach_radius = reach_bound = 0.0;
        if (model.adhesive == ADH_NONE) return;
        const double *radius = atom->radius;
        const int *mask = atom->mask;
        double r = 0.0, rall = 0.0;
        for (int i = 0; i < atom->nlocal; i++)
            if ((mask[i] & groupbit) && radius[i] > r) r = radius[i];
        MPI_Allreduce(&r, &rall, 1, MPI_DOUBLE, MPI_MAX, world);
        const double rch = reach_at(rall);
        if (!std::isfinite(rch))
            error->all(FLERR, "fix {} {}: the adhesive law's reach at radius {} (the largest of group {}) is not a finite "
                                  "double: {}", id, style, rall, group->names[igroup], dc_status_str(reach_status));
        reach_radius = rall;
        reach_bound = rch;
    }

    /* A contact with overlap <= 0 (or NaN), history slot h of the last step or nullptr (none, or
       not current): whether the law still acts on it through that history (JKR: at overlap 0 the
       neck forms; below, while h says it is formed). */
    bool held(double overlap, const double *h) const
    {
        if (model.adhesive != ADH_JKR) return false;
        return overlap >= 0.0 || (h != nullptr && h[model.state_at] != 0.0);
    }

    /* DMT's tail: the attraction at overlap in (-reach, 0], on zeroed history (the library resets
       a separated contact's history; the law has no state). */
    void apply_tail(int i, const double n[3], double overlap, const double vwall[3])
    {
        double zero[64] = {0.0};
        apply(i, n, overlap, vwall, nh > 0 ? zero : nullptr);
    }

    /* law_reach at radius r, its status kept in reach_status (NaN: not DC_OK). */
    double reach_at(double r)
    {
        double out = NAN;
        reach_status = law_reach_status(model, r, out);
        return reach_status == DC_OK ? out : NAN;
    }

    void clear(int i)
    {
        for (int s = 0; s < nslot; s++) key[i][s] = -1;
        for (int k = 0; k < nslot * nh; k++) hist[i][k] = 0.0;
    }

    Model model;
    Coeff coeff; // the wall's contact arguments
    // reach_of(): the reach bound and the radius it was computed at; the last law_reach_status
    double reach_radius = 0.0, reach_bound = 0.0;
    int32_t reach_status = DC_OK;
    int nh = 0, nslot = 0;
    double **hist = nullptr; // [nmax][nslot * nh]
    int **key = nullptr;     // [nmax][nslot]: the wall face of each slot, -1 = free
    bool registered = false, warned_restart = false;
};

} // namespace demcontact_lammps

#endif
