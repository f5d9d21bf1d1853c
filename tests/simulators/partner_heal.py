#!/usr/bin/env python3
"""The partner-heal path of pair_style demcontact (pair_demcontact.cpp heal_from_partner): a
contact whose history only the partner's copy holds, while the list owner has none.

  partner_heal.py --plugin demcontactplugin.so [--lmp lmp] [--workdir DIR]

fix demcontact/history keeps a contact's history in both atoms' copies, made, moved, synchronised
and restored together, so in a run the list owner always has its own copy when its partner has one.
The one way this test finds to give the partner the only copy is an atom that loses its per-atom
store while its ID comes back: `delete_atoms` of the atom with the largest ID, then `create_atoms`
in the same place (LAMMPS gives a new atom the largest ID + 1: the deleted atom's ID); the
partner's slot for that ID is still current. The pair style then heals the new atom's copy from
the partner's, at the setup force evaluation (read from the partner's copy) and at the first step
(copied into a new slot: heal_from_partner).

Scene (serial, lj units, no integration: positions and velocities stay fixed, the contact's
tangential spring grows by v_t dt a step, sticking): two spheres of diameter 1 (density 1,
E = 1e5, nu = 0.3, e = 0.5, Mindlin, e_t = 1, mu = 0.5) overlap 0.1 along z, atom 1 above
(z = 1.0) sliding at v_x = 0.01, atom 2 below (z = 0.1), in different neighbour bins, so that
atom 2 (the lower) owns the pair in LAMMPS' half list (the atom that lacks the copy must be the
list owner, or the path is not taken). Run A: `run 10`, atom 2 deleted and re-created with the same
ID, diameter, density and velocity, `run 10`. Reference: `run 10`, the same `set` lines, `run 10`.
Checks: the path is taken: the pair's counters (`compute heal all pair demcontact`, the copies
healed at a step and the setup evaluations that read the partner's copy) are (0, 1) at the second
run's setup and (1, 1) at each of its steps, (0, 0) throughout the first run and the reference (a
scene whose list owner keeps its own copy would pass the comparisons below without the path);
every thermo row of the second run (its setup and 10 steps: the forces on both atoms) equals the
reference's bit for bit (printed %.17g); and the tangential force at the end of the second run is
twice that at the end of the first within 1e-6 (the history carried on: a history restarted at
zero would give 1). Exit 1 on any failure, 77 (ctest SKIP) when LAMMPS is missing.
"""
import argparse
import os
import tempfile

import harness as H

RECREATE = """group dc_two id 2
delete_atoms group dc_two
create_atoms 1 single 0 0 0.1 units box
"""


def deck(plugin, recreate):
    return "\n".join([
        "units lj", "atom_style sphere", "atom_modify map array", "boundary f f f", "comm_modify vel yes",
        "region box block -2 2 -2 2 -2 2 units box", "create_box 1 box",
        "plugin load %s" % os.path.abspath(plugin), "pair_style demcontact",
        "pair_coeff * * hertz/material 1e5 0.5 0.3 tangential mindlin NULL 1.0 0.5",
        "create_atoms 1 single 0 0 1.0 units box", "create_atoms 1 single 0 0 0.1 units box",
        "set atom * diameter 1.0", "set atom * density 1.0",
        "velocity all set 0 0 0", "set atom 1 vx 0.01",
        "neighbor 0.3 bin", "timestep 0.001",
        "thermo 1"] + ["variable f%s%d equal f%s[%d]" % (c, i, c, i) for i in (1, 2) for c in "xyz"] + [
        # the pair's partner-heal counters (pair_demcontact.cpp): [1] copies healed at a step,
        # [2] setup evaluations that read the partner's copy; counts, not normalised by atoms
        "compute heal all pair demcontact",
        "thermo_style custom step atoms v_fx1 v_fy1 v_fz1 v_fx2 v_fy2 v_fz2 c_heal[1] c_heal[2]",
        "thermo_modify format float %.17g norm no",
        "run 10",
        RECREATE if recreate else "",
        "set atom 2 diameter 1.0", "set atom 2 density 1.0", "set atom 2 vx 0 vy 0 vz 0",
        "set atom 2 omega 0 0 0",
        "run 10", ""])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--lmp")
    ap.add_argument("--workdir")
    a = ap.parse_args()
    from harness import lammps as lammps_runs
    exe = lammps_runs.find_lmp(a.lmp)
    d = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_partner_heal_"))
    runs = {}
    for lab, rec in (("reference", False), ("recreated", True)):
        rd = os.path.join(d, lab)
        os.makedirs(rd, exist_ok=True)
        open(os.path.join(rd, "in.heal"), "w").write(deck(a.plugin, rec))
        H.run([exe, "-in", "in.heal", "-log", "log.lammps"], rd, H.mpi_env())
        runs[lab] = H.parse_thermo(open(os.path.join(rd, "log.lammps")).read())
    ok = True
    ref, rec = runs["reference"], runs["recreated"]
    if len(ref) != 2 or len(rec) != 2 or len(ref[1]) != 11 or len(rec[1]) != 11:
        raise SystemExit("FAIL partner_heal: expected 2 runs of 11 thermo rows (got %s and %s)"
                         % ([len(r) for r in ref], [len(r) for r in rec]))
    if int(rec[1][-1]["Atoms"]) != 2:
        raise SystemExit("FAIL partner_heal: the re-created deck does not have 2 atoms")
    cols = [k for k in ref[1][0] if k.startswith("v_f")]
    diff = 0
    for r0, r1 in zip(ref[1], rec[1]):
        same = all(r0[k] == r1[k] for k in cols)
        diff += not same
        print("%s step %s: %s" % ("ok  " if same else "FAIL", r1["Step"], " ".join(
            "%s %s%s" % (k, r1[k], "" if r0[k] == r1[k] else " (reference %s)" % r0[k]) for k in cols)))
    if diff:
        print("FAIL partner_heal: %d of 11 rows of the run after the re-creation differ from the reference" % diff)
        ok = False
    # the path itself: the pair's counters (compute pair demcontact) say the partner's copy was
    # read at the second run's setup and healed into the list owner's new slot at its first step,
    # once, and never in the first run or the reference (a scene whose list owner has its own copy,
    # e.g. other binning, passes the comparisons above without taking the path: this fails it)
    def counts(rows):
        return [(int(float(r["c_heal[1]"])), int(float(r["c_heal[2]"]))) for r in rows]
    want = [(0, 0)] * 11, [(0, 1)] + [(1, 1)] * 10
    got = counts(rec[0]), counts(rec[1])
    seen = [c for r in ref for c in counts(r)]
    reached = got[0] == want[0] and got[1] == want[1] and set(seen) == {(0, 0)}
    print("%s heal path (compute pair demcontact: healed at a step, read at setup): second run %s, expected %s; "
          "first run %s; reference %s" % ("ok  " if reached else "FAIL", got[1], want[1], sorted(set(got[0])),
                                          sorted(set(seen))))
    if not reached:
        print("FAIL partner_heal: the plugin's heal_from_partner path was not taken as expected")
        ok = False
    f1, f2 = float(rec[0][-1]["v_fx1"]), float(rec[1][-1]["v_fx1"])
    growth = f2 / f1 if f1 else float("nan")
    good = abs(growth - 2.0) <= 1e-6 * 2.0
    print("%s tangential force on atom 1: %.17g after run 1, %.17g after run 2: ratio %.9f (expected 2, "
          "tolerance 1e-6 relative; a history restarted at zero gives 1)" % ("ok  " if good else "FAIL", f1, f2,
                                                                           growth))
    ok &= good
    if not ok:
        raise SystemExit("FAIL partner_heal")
    print("ok: the re-created atom's contact history was healed from its partner's copy")


if __name__ == "__main__":
    main()
