/*
 * `surface demcontact`: LIGGGHTS' surface model for runs whose whole contact is demcontact's
 * (model demcontact tangential demcontact rolling_friction demcontact). LIGGGHTS' `surface default`
 * computes the relative velocities of every touching pair (vn, the tangential and rotational
 * relative velocities vtr, wr: about 40 flops and 10 stores into sidata) for the builtin normal,
 * tangential and rolling models; demcontact's combined evaluation computes its own kinematics from
 * the atoms' velocities (as dc_contact_force does) and reads none of them. This model sets only what
 * the combined evaluation reads of the surface model's work, the overlap (deltan = radsum - r, as
 * `surface default`), so the run pays for the kinematics once.
 *
 *   pair_style gran model demcontact tangential demcontact rolling_friction demcontact surface demcontact ...
 *   fix ID all wall/gran model demcontact tangential demcontact rolling_friction demcontact surface demcontact ...
 *
 * Only that combination is registered (normal_model_demcontact.cpp): there the rolling class always
 * hands the tangential class the combined model and the normal model defers to it, so no class reads
 * the velocities this model leaves unset. LIGGGHTS refuses any other combination with its own error
 * ("Unknown surface model"; ctest liggghts_bad_input). Same forces, torques and histories as
 * `surface default`, bit for bit (scenes.py --check compares the dumps of 100 steps of the settled
 * bed, serial and 2 ranks: ctest liggghts_scene_smoke).
 */
#ifndef DEMCONTACT_LIGGGHTS_SURFACE_MODEL_H
#define DEMCONTACT_LIGGGHTS_SURFACE_MODEL_H

namespace LIGGGHTS {
namespace ContactModels {

// an id in LIGGGHTS' surface model id space (the installed ones are 0..3)
static const int DEMCONTACT_SURFACE = 42;

template<>
class SurfaceModel<DEMCONTACT_SURFACE> : public SurfaceModelBase {
public:
    SurfaceModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *cmb)
        : SurfaceModelBase(lmp, hsetup, cmb)
    {
    }
    inline void registerSettings(Settings &) {}
    inline void postSettings(IContactHistorySetup *, ContactModelBase *) {}
    inline void connectToProperties(PropertyRegistry &) {}
    inline bool checkSurfaceIntersect(SurfacesIntersectData &sidata)
    {
#ifdef SUPERQUADRIC_ACTIVE_FLAG
        sidata.is_non_spherical = false;
#endif
        return true;
    }
    inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &, ForceData &)
    {
        sidata.deltan = sidata.radsum - sidata.r;
        sidata.P_diss = 0.;
    }
    inline void endSurfacesIntersect(SurfacesIntersectData &, TriMesh *, double *const) {}
    inline void surfacesClose(SurfacesCloseData &, ForceData &, ForceData &) {}
    void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
    void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
    inline void tally_pp(double, int, int, int) {}
    inline void tally_pw(double, int, int, int) {}
};

} // namespace ContactModels
} // namespace LIGGGHTS

#endif
