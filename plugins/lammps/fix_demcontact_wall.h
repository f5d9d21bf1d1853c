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
 * another history length restores none, with a warning).
 *
 * step_exact (as in pair_coeff): the model is made step-aware for update->dt when the fix is
 * defined (which fixes its history length), again at every run's init and in reset_dt() (fix
 * dt/reset, timestep during a run).
 */
#ifndef DEMCONTACT_LAMMPS_FIX_WALL_H
#define DEMCONTACT_LAMMPS_FIX_WALL_H

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "memory.h"
#include "update.h"

#include "dc_coeff.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

namespace demcontact_lammps {

using namespace LAMMPS_NS;

class FixDemcontactWall : public Fix {
public:
    FixDemcontactWall(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
    {
        int w = 3;
        while (w < narg && !is_wallstyle(arg[w])) w++;
        if (w == narg) error->all(FLERR, "fix demcontact/wall: missing wall style (xplane, yplane, zplane, zcylinder)");
        Coeff c;
        parse_coeff(lmp, error, fmt::format("fix {} demcontact/wall", id), w - 3, arg + 3, false, c);
        const int32_t s = make_model(c, c, c, model, update->dt);
        if (s != DC_OK)
            error->all(FLERR, "fix {} demcontact/wall: {}{}", id,
                       c.step_exact ? fmt::format("step_exact at timestep {}: ", update->dt) : "", dc_status_str(s));
        const std::string ws = arg[w];
        if (ws == "zcylinder") {
            if (w + 2 != narg) error->all(FLERR, "fix demcontact/wall: zcylinder R");
            style = CYL;
            cyl_r = utils::numeric(FLERR, arg[w + 1], false, lmp);
            if (!(cyl_r > 0.0)) error->all(FLERR, "fix demcontact/wall: zcylinder radius = {} must be > 0", cyl_r);
        } else {
            if (w + 3 != narg) error->all(FLERR, "fix demcontact/wall: {} lo hi", ws);
            style = PLANE;
            dim = ws[0] - 'x';
            has_lo = std::strcmp(arg[w + 1], "NULL") != 0;
            has_hi = std::strcmp(arg[w + 2], "NULL") != 0;
            if (has_lo) lo = utils::numeric(FLERR, arg[w + 1], false, lmp);
            if (has_hi) hi = utils::numeric(FLERR, arg[w + 2], false, lmp);
            if (!has_lo && !has_hi) error->all(FLERR, "fix demcontact/wall: both {} walls NULL", ws);
        }
        nh = model.nh;
        if (nh > 32) error->all(FLERR, "fix demcontact/wall: history of {} doubles exceeds 32", nh);
        if (nh > 0) {
            create_attribute = 1;
            restart_peratom = 1;
            maxexchange = 2 * nh + 2;
            atom->add_callback(Atom::GROW);
            atom->add_callback(Atom::RESTART);
            grow_arrays(atom->nmax);
            for (int i = 0; i < atom->nlocal; i++) clear(i);
        }
    }

    ~FixDemcontactWall() override
    {
        if (nh > 0) {
            atom->delete_callback(id, Atom::GROW);
            atom->delete_callback(id, Atom::RESTART);
        }
        memory->destroy(hist);
        memory->destroy(touch);
    }

    int setmask() override { return FixConst::POST_FORCE; }

    void init() override
    {
        if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
            error->all(FLERR, "fix demcontact/wall requires atom_style sphere");
        apply_dt();
    }

    void reset_dt() override { apply_dt(); }

    void setup(int vflag) override { post_force(vflag); }

    void post_force(int) override
    {
        double **x = atom->x, **v = atom->v, **f = atom->f, **omega = atom->omega, **torque = atom->torque;
        const double *radius = atom->radius, *rmass = atom->rmass;
        const int *mask = atom->mask;
        const int nlocal = atom->nlocal;
        const double dt = update->dt;
        const bool advance = update->setupflag == 0;
        const double inf = std::numeric_limits<double>::infinity();
        double scratch[64];
        State s;
        s.r2 = s.m2 = inf;
        for (int k = 0; k < 3; k++) s.v2[k] = s.w2[k] = 0.0;
        for (int i = 0; i < nlocal; i++) {
            if (!(mask[i] & groupbit)) continue;
            for (int face = 0; face < 2; face++) {
                double n[3] = {0.0, 0.0, 0.0}, gap;
                if (style == CYL) {
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
                if (!(overlap > 0.0)) {
                    if (nh > 0) touch[i][face] = 0;
                    continue;
                }
                for (int k = 0; k < 3; k++) {
                    s.n[k] = n[k];
                    s.v1[k] = v[i][k];
                    s.w1[k] = omega[i][k];
                }
                s.overlap = overlap;
                s.r1 = radius[i];
                s.m1 = rmass[i];
                double *h = nullptr;
                if (nh > 0) {
                    h = hist[i] + face * nh;
                    if (!touch[i][face]) std::memset(h, 0, sizeof(double) * nh);
                    if (advance) {
                        touch[i][face] = 1;
                    } else { // setup: evaluate on a copy
                        std::memcpy(scratch, h, sizeof(double) * nh);
                        h = scratch;
                    }
                }
                Result out;
                const int32_t st = contact_eval(model, s, dt, h, out);
                if (st != DC_OK)
                    error->one(FLERR, "fix {} demcontact/wall: atom {}: {}", id, atom->tag[i], dc_status_str(st));
                for (int k = 0; k < 3; k++) {
                    f[i][k] += out.force[k];
                    torque[i][k] += out.torque1[k];
                }
            }
        }
    }

    void grow_arrays(int nmax) override
    {
        memory->grow(hist, nmax, 2 * nh, "demcontact/wall:hist");
        memory->grow(touch, nmax, 2, "demcontact/wall:touch");
    }

    void copy_arrays(int i, int j, int) override
    {
        std::memcpy(hist[j], hist[i], sizeof(double) * 2 * nh);
        touch[j][0] = touch[i][0];
        touch[j][1] = touch[i][1];
    }

    void set_arrays(int i) override { clear(i); }

    int pack_exchange(int i, double *buf) override
    {
        int m = 0;
        buf[m++] = touch[i][0];
        buf[m++] = touch[i][1];
        for (int k = 0; k < 2 * nh; k++) buf[m++] = hist[i][k];
        return m;
    }

    int unpack_exchange(int nlocal, double *buf) override
    {
        int m = 0;
        touch[nlocal][0] = static_cast<int>(buf[m++]);
        touch[nlocal][1] = static_cast<int>(buf[m++]);
        for (int k = 0; k < 2 * nh; k++) hist[nlocal][k] = buf[m++];
        return m;
    }

    // restart record of atom i: [count, nh, touch lo, touch hi, 2 nh doubles]
    int pack_restart(int i, double *buf) override
    {
        int m = 1;
        buf[m++] = nh;
        buf[m++] = touch[i][0];
        buf[m++] = touch[i][1];
        for (int k = 0; k < 2 * nh; k++) buf[m++] = hist[i][k];
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
        if (static_cast<int>(rec[1]) != nh) {
            if (!warned_restart && comm->me == 0)
                error->warning(FLERR, "fix {} demcontact/wall: the restart file's wall contact histories have {} "
                                      "doubles, the model now {}: they restart at zero", id, static_cast<int>(rec[1]), nh);
            warned_restart = true;
            return;
        }
        touch[nlocal][0] = static_cast<int>(rec[2]);
        touch[nlocal][1] = static_cast<int>(rec[3]);
        for (int k = 0; k < 2 * nh; k++) hist[nlocal][k] = rec[4 + k];
    }

    int size_restart(int) override { return 4 + 2 * nh; }
    int maxsize_restart() override { return 4 + 2 * nh; }

private:
    /* step_exact: the model follows update->dt (no-op otherwise; the history length is unchanged). */
    void apply_dt()
    {
        const int32_t s = set_model_dt(model, update->dt);
        if (s != DC_OK)
            error->all(FLERR, "fix {} demcontact/wall: step_exact at timestep {} rejected by demcontact: {}", id,
                       update->dt, dc_status_str(s));
    }
    static bool is_wallstyle(const char *a)
    {
        return !std::strcmp(a, "xplane") || !std::strcmp(a, "yplane") || !std::strcmp(a, "zplane") ||
               !std::strcmp(a, "zcylinder");
    }
    void clear(int i)
    {
        touch[i][0] = touch[i][1] = 0;
        for (int k = 0; k < 2 * nh; k++) hist[i][k] = 0.0;
    }

    enum { PLANE, CYL } style = PLANE;
    int dim = 2;
    bool has_lo = false, has_hi = false;
    double lo = 0.0, hi = 0.0, cyl_r = 0.0;
    Model model;
    int nh = 0;
    double **hist = nullptr;
    int **touch = nullptr;
    bool warned_restart = false;
};

} // namespace demcontact_lammps

#endif
