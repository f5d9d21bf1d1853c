/*
 * fix demcontact/wall: flat and cylindrical walls with demcontact's contact model, syntax as
 * LAMMPS' `fix wall/gran ... granular`:
 *
 *   fix ID group demcontact/wall <contact arguments as pair_coeff after I J> wallstyle args
 *     wallstyle = xplane lo hi | yplane lo hi | zplane lo hi   (lo, hi = position or NULL)
 *               | zcylinder R                                   (axis along z through x = y = 0,
 *                                                                 particles inside)
 *
 * The wall is body 2 of every contact with infinite radius and mass (r_eff = particle radius,
 * m_eff = particle mass) and the contact's material on both sides (as fix wall/gran granular).
 * Per-contact history, when the model has one, is kept per atom and per wall face (two faces for
 * a plane pair lo/hi), migrates with the atom and is written to restart files: define the fix
 * again with the same ID after read_restart and the histories are restored (a restart written with
 * another history length restores none, with a warning). Model, history storage and the contact's
 * evaluation: fix_demcontact_wall_base.h (shared with fix demcontact/wall/region).
 *
 * step_exact (as in pair_coeff): the model is made step-aware for update->dt when the fix is
 * defined (which fixes its history length), again at every run's init and in reset_dt() (fix
 * dt/reset, timestep during a run): fix_demcontact_wall_base.h, for both wall fixes.
 *
 * Adhesive laws (dmt, jkr): the reach that bounds where DMT's tail is looked for (the region fix:
 * the faces asked for) is dc_contact_model_reach at the group's largest radius, computed at every
 * run's init (an error naming the radius and the status if it is not a finite double), not per
 * atom and step: the library gives no force beyond an atom's own reach, so the bound of a larger
 * radius changes no force (and the same radius gives the same bits). A radius grown past that
 * one during the run (fix adapt, fix pour/deposit) makes the owning rank compute it again at that
 * radius (reach_of in fix_demcontact_wall_base.h), the same error if it is not finite; shrinking
 * radii keep the larger bound.
 */
#ifndef DEMCONTACT_LAMMPS_FIX_WALL_H
#define DEMCONTACT_LAMMPS_FIX_WALL_H

#include "fix_demcontact_wall_base.h"

#include <cmath>
#include <cstring>
#include <string>

namespace demcontact_lammps {

using namespace LAMMPS_NS;

class FixDemcontactWall : public FixDemcontactWallBase {
public:
    FixDemcontactWall(LAMMPS *lmp, int narg, char **arg) : FixDemcontactWallBase(lmp, narg, arg)
    {
        int w = 3;
        while (w < narg && !is_wallstyle(arg[w])) w++;
        if (w == narg) error->all(FLERR, "fix demcontact/wall: missing wall style (xplane, yplane, zplane, zcylinder)");
        const std::string ws = arg[w];
        if (ws == "zcylinder") {
            if (w + 2 != narg) error->all(FLERR, "fix demcontact/wall: zcylinder R");
            style_ = CYL;
            cyl_r = utils::numeric(FLERR, arg[w + 1], false, lmp);
            if (!(cyl_r > 0.0)) error->all(FLERR, "fix demcontact/wall: zcylinder radius = {} must be > 0", cyl_r);
        } else {
            if (w + 3 != narg) error->all(FLERR, "fix demcontact/wall: {} lo hi", ws);
            style_ = PLANE;
            dim = ws[0] - 'x';
            has_lo = std::strcmp(arg[w + 1], "NULL") != 0;
            has_hi = std::strcmp(arg[w + 2], "NULL") != 0;
            if (has_lo) lo = utils::numeric(FLERR, arg[w + 1], false, lmp);
            if (has_hi) hi = utils::numeric(FLERR, arg[w + 2], false, lmp);
            if (!has_lo && !has_hi) error->all(FLERR, "fix demcontact/wall: both {} walls NULL", ws);
        }
        // one slot per face (lo, hi); its key is the face while the atom touches it
        setup_model(w - 3, arg + 3, 2);
    }

    void post_force(int) override
    {
        double **x = atom->x;
        const double *radius = atom->radius;
        const int *mask = atom->mask;
        const int nlocal = atom->nlocal;
        const bool advance = update->setupflag == 0;
        const double still[3] = {0.0, 0.0, 0.0};
        double scratch[64];
        for (int i = 0; i < nlocal; i++) {
            if (!(mask[i] & groupbit)) continue;
            for (int face = 0; face < 2; face++) {
                double n[3] = {0.0, 0.0, 0.0}, gap;
                if (style_ == CYL) {
                    if (face == 1) break;
                    const double rxy = std::sqrt(x[i][0] * x[i][0] + x[i][1] * x[i][1]);
                    gap = cyl_r - rxy; // surface-to-centre distance
                    if (rxy > 0.0) {
                        n[0] = -x[i][0] / rxy;
                        n[1] = -x[i][1] / rxy;
                    }
                } else if (face == 0) {
                    if (!has_lo) continue;
                    gap = x[i][dim] - lo;
                    n[dim] = 1.0;
                } else {
                    if (!has_hi) continue;
                    gap = hi - x[i][dim];
                    n[dim] = -1.0;
                }
                const double overlap = radius[i] - gap;
                if (!(overlap > 0.0) &&
                    !held(overlap, nh > 0 && key[i][face] == face ? hist[i] + face * nh : nullptr)) {
                    if (nh > 0 && advance) key[i][face] = -1;
                    // DMT's tail: its attraction up to d_c beyond touching
                    if (model.adhesive == ADH_DMT && overlap > -reach_of(i)) apply_tail(i, n, overlap, still);
                    continue;
                }
                double *h = nullptr;
                if (nh > 0) {
                    h = hist[i] + face * nh;
                    if (key[i][face] != face) std::memset(h, 0, sizeof(double) * nh);
                    if (advance) {
                        key[i][face] = face;
                    } else { // setup: evaluate on a copy
                        std::memcpy(scratch, h, sizeof(double) * nh);
                        h = scratch;
                    }
                }
                apply(i, n, overlap, still, h);
            }
        }
    }

private:
    static bool is_wallstyle(const char *a)
    {
        return !std::strcmp(a, "xplane") || !std::strcmp(a, "yplane") || !std::strcmp(a, "zplane") ||
               !std::strcmp(a, "zcylinder");
    }

    enum { PLANE, CYL } style_ = PLANE;
    int dim = 2;
    bool has_lo = false, has_hi = false;
    double lo = 0.0, hi = 0.0, cyl_r = 0.0;
};

} // namespace demcontact_lammps

#endif
