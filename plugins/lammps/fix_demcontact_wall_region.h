/*
 * fix demcontact/wall/region: a wall of any LAMMPS region (block, cylinder, cone, sphere, plane,
 * prism, union, intersect..., also moving and rotating ones: `region ... move/rotate`) with
 * demcontact's contact model, syntax as LAMMPS' `fix wall/gran/region ... granular`:
 *
 *   fix ID group demcontact/wall/region <contact arguments as pair_coeff after I J> region region-ID
 *
 * The contacts of an atom with the region's surface come from LAMMPS' region API, as for fix
 * wall/gran/region: Region::surface() at the atom's radius (every face within reach: a block's
 * corner is up to three contacts, each with its distance r, the vector from the surface point to
 * the atom's centre and its wall index iwall); the normal is that vector over r and the overlap is
 * radius - r. For a moving or rotating region, Region::velocity_contact() gives the velocity of the
 * surface at the contact point (Region::prematch/set_velocity once per step first). Each contact is
 * demcontact's (fix_demcontact_wall_base.h): the wall is rigid and flat at the contact (r2 = m2 =
 * +inf, the region's curvature not used), its material the contact's on both sides.
 *
 * History per atom and wall face, as fix wall/gran/region keeps it: up to the region's tmax slots
 * per atom, each keyed by the face's iwall, created zero when the atom touches the face, dropped
 * when it leaves it; they migrate with the atom and go into restart files, and the region's motion
 * state goes into the restart's global section (as fix wall/gran/region: after read_restart,
 * define the region and the fix again with the same IDs).
 *
 * The region is looked up by its ID at every run's init: it may be deleted and defined again
 * between runs (LAMMPS' in.granregion.box does so to start and stop its rotation); the histories
 * are kept while the new region has as many wall faces, cleared otherwise.
 *
 * Adhesive laws: the faces are asked for within the radius plus the law's reach at the group's
 * largest radius, fixed at init and raised when an atom grows past it (reach_of, as in fix
 * demcontact/wall: fix_demcontact_wall.h).
 */
#ifndef DEMCONTACT_LAMMPS_FIX_WALL_REGION_H
#define DEMCONTACT_LAMMPS_FIX_WALL_REGION_H

#include "fix_demcontact_wall_base.h"

#include "domain.h"
#include "region.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace demcontact_lammps {

using namespace LAMMPS_NS;

class FixDemcontactWallRegion : public FixDemcontactWallBase {
public:
    FixDemcontactWallRegion(LAMMPS *lmp, int narg, char **arg) : FixDemcontactWallBase(lmp, narg, arg)
    {
        int w = 3;
        while (w < narg && std::strcmp(arg[w], "region") != 0) w++;
        if (w >= narg - 1)
            error->all(FLERR, "fix {} demcontact/wall/region: missing 'region region-ID' after the contact arguments", id);
        if (w + 2 != narg)
            error->all(FLERR, "fix {} demcontact/wall/region: unexpected argument '{}' after region {}", id, arg[w + 2],
                       arg[w + 1]);
        idregion = arg[w + 1];
        region = find_region();
        setup_model(w - 3, arg + 3, region->tmax);
        restart_global = 1;
    }

    void init() override
    {
        FixDemcontactWallBase::init();
        region = find_region(); // the region may have been deleted and defined again
        if (nh > 0 && region->tmax != nslot) {
            if (comm->me == 0)
                error->warning(FLERR, "fix {} demcontact/wall/region: region {} now has {} wall faces, before {}: the "
                                      "wall contact histories restart at zero", id, idregion, region->tmax, nslot);
            resize_slots(region->tmax);
        }
        if (motion_reset) {
            if (comm->me == 0)
                error->warning(FLERR, "fix {} demcontact/wall/region: region {} is not the one of the restart file: its "
                                      "motion restarts", id, idregion);
            region->reset_vel();
            motion_reset = false;
        }
    }

    void post_force(int) override
    {
        double **x = atom->x;
        const double *radius = atom->radius;
        const int *mask = atom->mask;
        const int nlocal = atom->nlocal;
        const bool advance = update->setupflag == 0;
        const bool moving = region->dynamic_check() != 0;
        if (moving) { // the region's current place and velocity (once per step for all its users)
            region->prematch();
            region->set_velocity();
        }
        double vwall[3] = {0.0, 0.0, 0.0};
        double scratch[64];
        for (int i = 0; i < nlocal; i++) {
            if (!(mask[i] & groupbit)) continue;
            int nc = 0;
            // the faces within the radius, plus an adhesive law's reach (as fix wall/gran/region
            // asks the region for its JKR pull-off distance)
            const double cut = radius[i] + reach_of(i);
            if (region->match(x[i][0], x[i][1], x[i][2])) nc = region->surface(x[i][0], x[i][1], x[i][2], cut);
            if (nc > region->tmax)
                error->one(FLERR, "fix {} demcontact/wall/region: atom {} touches {} faces of region {} (at most {})",
                           id, atom->tag[i], nc, idregion, region->tmax);
            if (nh > 0 && advance) drop_stale(i, nc);
            for (int ic = 0; ic < nc; ic++) {
                const Region::Contact &c = region->contact[ic];
                const double overlap = radius[i] - c.r;
                if (!(c.r > 0.0)) continue;
                const double n[3] = {c.delx / c.r, c.dely / c.r, c.delz / c.r};
                if (!(overlap > 0.0)) {
                    const int s = nh > 0 ? slot_of(i, c.iwall) : -1;
                    if (!held(overlap, s >= 0 ? hist[i] + s * nh : nullptr)) {
                        if (s >= 0 && advance) key[i][s] = -1; // the contact ended
                        if (model.adhesive == ADH_DMT && overlap > -reach_of(i)) {
                            if (moving) region->velocity_contact(vwall, x[i], ic);
                            apply_tail(i, n, overlap, vwall); // DMT's tail
                        }
                        continue;
                    }
                }
                if (moving) region->velocity_contact(vwall, x[i], ic);
                double *h = nullptr;
                if (nh > 0) {
                    int s = slot_of(i, c.iwall);
                    if (advance) {
                        if (s < 0) s = new_slot(i, c.iwall);
                        h = hist[i] + s * nh;
                    } else { // setup: evaluate on a copy
                        if (s >= 0) std::memcpy(scratch, hist[i] + s * nh, sizeof(double) * nh);
                        else std::memset(scratch, 0, sizeof(double) * nh);
                        h = scratch;
                    }
                }
                apply(i, n, overlap, vwall, h);
            }
        }
    }

    // global restart: the region's motion state, as fix wall/gran/region writes it ([size, record])
    void write_restart(FILE *fp) override
    {
        if (comm->me != 0) return;
        int len = 0;
        region->length_restart_string(len);
        std::fwrite(&len, sizeof(int), 1, fp);
        region->write_restart(fp);
    }

    void restart(char *buf) override
    {
        int n = 0;
        if (!region->restart(buf, n)) motion_reset = true;
    }

private:
    Region *find_region()
    {
        Region *r = domain->get_region_by_id(idregion);
        if (!r) error->all(FLERR, "fix {} demcontact/wall/region: region {} does not exist", id, idregion);
        if (r->tmax < 1 || r->contact == nullptr)
            error->all(FLERR, "fix {} demcontact/wall/region: region {} (style {}) has no surface contacts (tmax = {}): "
                              "it cannot be a wall", id, idregion, r->style, r->tmax);
        return r;
    }

    int slot_of(int i, int iwall) const
    {
        for (int s = 0; s < nslot; s++)
            if (key[i][s] == iwall) return s;
        return -1;
    }

    // a zeroed slot for face iwall (free slots exist: at most tmax faces touch, stale ones dropped)
    int new_slot(int i, int iwall)
    {
        for (int s = 0; s < nslot; s++)
            if (key[i][s] < 0) {
                key[i][s] = iwall;
                std::memset(hist[i] + s * nh, 0, sizeof(double) * nh);
                return s;
            }
        error->one(FLERR, "fix {} demcontact/wall/region: atom {}: no free contact slot", id, atom->tag[i]);
        return -1;
    }

    // free the slots of atom i whose face is not among the region's nc current contacts
    void drop_stale(int i, int nc)
    {
        for (int s = 0; s < nslot; s++) {
            if (key[i][s] < 0) continue;
            bool on = false;
            for (int ic = 0; ic < nc && !on; ic++) {
                const Region::Contact &c = region->contact[ic];
                // touching, or (JKR) at reach while the slot's neck is formed
                on = c.iwall == key[i][s] && c.r > 0.0 &&
                     (c.r < atom->radius[i] || held(atom->radius[i] - c.r, hist[i] + s * nh));
            }
            if (!on) key[i][s] = -1;
        }
    }

    std::string idregion;
    Region *region = nullptr;
    bool motion_reset = false;
};

} // namespace demcontact_lammps

#endif
