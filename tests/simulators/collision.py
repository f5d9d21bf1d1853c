#!/usr/bin/env python3
"""Two-sphere head-on collisions in a real DEM code, demcontact next to the code's builtin models.

  collision.py --sim liggghts --plugin libdemcontact_liggghts.so [--check] [--np 2]
  collision.py --sim lammps   --plugin demcontactplugin.so      [--check] [--lmp LMP]

R = 1 mm, rho = 2500, nu = 0.3 at impact speeds 0.1, 1, 10 m/s, E in {5e6, 2.5e7, 1e8} Pa, target
e in {0.3, 0.5, 0.9}. All 27 pairs collide in one simulator run per contact model (pairs far
apart, one atom type per (E, e)); the realised e is read from the simulator's own dump of the final
velocities. With --check, exits 1 unless demcontact (clamped and unclamped) realises every target
within TOL (1e-3); with --viscoelastic, the library's own e(b) at each speed instead of the target.

Exit code 77 (ctest SKIP_RETURN_CODE) when the simulator is not installed.
"""
import harness as H


def main():
    a, workdir = H.arguments("collision", __doc__.splitlines()[0])
    sim = H.simulator(a.sim, a.plugin, a.lmp)
    dt, pairs, results, models = sim.collision(workdir, a.np, a.steps_per_contact, a.exponent, a.viscoelastic)
    expected = None
    if a.viscoelastic:
        expected = {}
        for m, ours in models:
            clamp = "limit" in m
            ev = H.visco_expected(a.plugin, clamp)
            expected[m] = {(E, e, v): ev[(e, v)] for E in H.MODULI for e in H.TARGETS for v in H.SPEEDS}
    worst = H.print_collision("%s, %d MPI rank%s%s" % (a.sim, a.np, "s" if a.np > 1 else "",
                                                      ", viscoelastic" if a.viscoelastic else ""),
                              dt, pairs, results, models, a.steps_per_contact, expected)
    if a.check and not worst <= H.TOL:
        raise SystemExit("FAIL: demcontact misses a target by %.3g > %g" % (worst, H.TOL))


if __name__ == "__main__":
    main()
