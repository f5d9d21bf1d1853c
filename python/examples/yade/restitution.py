"""A real client: YADE 2023.02a (Debian python3-yade) with parameters computed by demcontact.

Run with YADE's own interpreter (Debian's /usr/bin/python3), demcontact on its path:

    PYTHONPATH=<dir with demcontact> yade -n -x python/examples/yade/restitution.py [e ...]

YADE's ViscElMat + Law2_ScGeom_ViscElPhys_Basic is a linear spring-dashpot F = kn d + cn vn whose
total normal force is clamped at zero (`if (normForceReal < 0) normalForce = 0`), so a contact ends
when the force first vanishes: demcontact's Criterion.FORCE with p = 1. For a target e this
script takes the damping from demcontact (the exact force-zero calibration; the corrected-builtin
function `builtin_yade_viscel_cn` when the package has it) and the time step from
demcontact.dt_for_accuracy (YADE's leapfrog NewtonIntegrator is the velocity-Verlet scheme that
function simulates: forces from x_n and v_(n-1/2)). Two scenes: a sphere hitting a fixed wall and
two equal spheres colliding head-on. For contrast it also runs YADE's own calibrations
(`ViscElMat(tc, en, et)` and `ViscElMat(young, poisson, en)`).

Output: one line per run, `RESULT <scene> <route> <e_target> <e_realised>`.
"""

import math
import sys

import demcontact as dc
from yade import O, utils
from yade.wrapper import (
    Bo1_Sphere_Aabb,
    Bo1_Wall_Aabb,
    ForceResetter,
    Ig2_Sphere_Sphere_ScGeom,
    Ig2_Wall_Sphere_ScGeom,
    InsertionSortCollider,
    InteractionLoop,
    Ip2_ViscElMat_ViscElMat_ViscElPhys,
    Law2_ScGeom_ViscElPhys_Basic,
    NewtonIntegrator,
    ViscElMat,
)

R = 1e-3  # sphere radius [m]
RHO = 2500.0  # density [kg/m^3]
V0 = 0.5  # impact (relative) speed [m/s]
KN = 1e4  # contact normal stiffness [N/m]
TOL = 2e-4  # relative tolerance on e handed to dt_for_accuracy
MASS = 4.0 / 3.0 * math.pi * R**3 * RHO


def damping_cn(e, kn, m_reduced):
    """Contact damping cn [N s/m] realising e in YADE's clamped linear law, from demcontact."""
    corrected = getattr(dc, "builtin_yade_viscel_cn", None)
    if corrected is not None:  # the library's corrected-builtin function, where this build has it
        return corrected(e, kn, m_reduced)
    # The law is the linear spring-dashpot F = kn d + alpha sqrt(m kn) vn with the force clamped:
    # alpha from the exact force-zero calibration at p = 1.
    return dc.alpha_from_e(e, 1.0, dc.Criterion.FORCE) * math.sqrt(m_reduced * kn)


def engines():
    return [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
        InteractionLoop(
            [Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
            [Ip2_ViscElMat_ViscElMat_ViscElPhys()],
            [Law2_ScGeom_ViscElPhys_Basic()],
        ),
        NewtonIntegrator(damping=0.0, gravity=(0, 0, 0)),
    ]


def run(scene, material, dt):
    """One collision; returns the realised restitution |relative exit speed| / V0."""
    O.reset()
    mat = O.materials.append(material)
    if scene == "sphere-wall":
        O.bodies.append(utils.wall(0.0, axis=2, sense=1, material=mat))
        b = O.bodies.append(utils.sphere((0, 0, R * 1.001), R, material=mat))
        O.bodies[b].state.vel = (0, 0, -V0)
        ids = [b]
    else:
        b1 = O.bodies.append(utils.sphere((-R * 1.001, 0, 0), R, material=mat))
        b2 = O.bodies.append(utils.sphere((R * 1.001, 0, 0), R, material=mat))
        O.bodies[b1].state.vel = (V0 / 2, 0, 0)
        O.bodies[b2].state.vel = (-V0 / 2, 0, 0)
        ids = [b1, b2]
    O.engines = engines()
    O.dt = dt
    # Until the bodies have separated (a margin of 1 % of R after contact).
    for _ in range(2000):
        O.run(200, True)
        if scene == "sphere-wall":
            s = O.bodies[ids[0]].state
            if s.vel[2] > 0 and s.pos[2] > R * 1.01:
                return s.vel[2] / V0
        else:
            s1, s2 = O.bodies[ids[0]].state, O.bodies[ids[1]].state
            if s2.vel[0] - s1.vel[0] > 0 and s2.pos[0] - s1.pos[0] > 2.02 * R:
                return (s2.vel[0] - s1.vel[0]) / V0
    raise RuntimeError(f"{scene}: the bodies did not separate")


def main(targets):
    for scene, m_reduced in (("sphere-wall", MASS), ("sphere-sphere", MASS / 2)):
        omega0 = dc.omega0(KN, m_reduced)
        for e in targets:
            cn = damping_cn(e, KN, m_reduced)
            dt = dc.dt_for_accuracy(1.0, e, dc.Criterion.FORCE, V0, omega0, TOL)
            # Each of two equal materials carries 2 kn and 2 cn: YADE combines them in series.
            mat = ViscElMat(kn=2 * KN, cn=2 * cn, ks=0.0, cs=0.0, frictionAngle=0.0, density=RHO)
            print(f"RESULT {scene} demcontact {e:.6f} {run(scene, mat, dt):.9f}", flush=True)
            # YADE's own calibrations, same stiffness scale and step, for contrast.
            tau = math.pi / omega0
            mat = ViscElMat(tc=tau, en=e, et=1.0, frictionAngle=0.0, density=RHO)
            print(f"RESULT {scene} yade_tc_en {e:.6f} {run(scene, mat, dt):.9f}", flush=True)
            builtin_en = getattr(dc, "builtin_value_for_e", None)
            if builtin_en is not None and e >= 0.14:
                # the library's corrected en for ViscElMat(tc, en): right where YADE's reduced mass
                # is the true one (two spheres), see the wall case in python/README.md.
                en = builtin_en(dc.Builtin.YADE_VISCEL_EN, True, e)
                mat = ViscElMat(tc=tau, en=en, et=1.0, frictionAngle=0.0, density=RHO)
                print(f"RESULT {scene} yade_tc_en_corrected {e:.6f} {run(scene, mat, dt):.9f}", flush=True)
            young = KN / R  # kn_i = 2 E R per material, in series: kn = E R
            mat = ViscElMat(young=young, poisson=0.0, en=e, frictionAngle=0.0, density=RHO)
            print(f"RESULT {scene} yade_young_en {e:.6f} {run(scene, mat, dt):.9f}", flush=True)


if __name__ == "__main__" or True:  # `yade -x` runs the file as a script
    args = [float(a) for a in sys.argv[1:]] or [0.3, 0.5, 0.9]
    main(args)
    sys.stdout.flush()
    O.exitNoBacktrace() if hasattr(O, "exitNoBacktrace") else None
