#!/usr/bin/env python3
"""LAMMPS's own granular example examples/granular/in.pour.flatwall (Debian package lammps-examples),
changed only in its pair and wall lines, runs to completion with pair_style demcontact and fix
demcontact/wall, serial and under mpirun -np 2, next to the unchanged deck.

  lammps_example.py --plugin demcontactplugin.so [--lmp lmp] [--np 2] [--deck in.pour.flatwall]

The changes (printed): a `plugin load` line before the first pair_coeff, `pair_style demcontact`,
one `pair_coeff * * hertz/material E e nu tangential mindlin NULL 0.5 0.5 rolling sds NULL 0 0.5`
(E, nu, mu, mu_r of the example's type 1; its cohesive JKR has no demcontact counterpart; e = 0.5),
and each `fix ... wall/gran granular hertz/material E d nu tangential mindlin NULL 1.0 0.5 ...`
becomes `fix ... demcontact/wall hertz/material E 0.5 nu tangential mindlin NULL 0.5 0.5 <same wall>`. Every other line is the example's.

Checks: both runs end normally ("Loop time"), the same number of atoms as the unchanged deck
(fix pour inserts the same particles whatever the contact model), all thermo values finite.
"""
import argparse
import math
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import harness as H  # noqa: E402

DECK = "/usr/share/lammps/examples/granular/in.pour.flatwall"
OURS = "hertz/material 1000.0 0.5 0.3"  # pair: E and nu of the example's type-1 material, e = 0.5
E_REST = 0.5                            # walls: the wall line's own E and nu, e = 0.5
# the example's friction and rolling resistance (mu = 0.5, mu_r = 0.5) with our sub-models
# (tangential restitution 0.5, EPSD rolling with Ai's stiffness rule)
FRICTION = " tangential mindlin NULL 0.5 0.5 rolling sds NULL 0 0.5"
WALL_FRICTION = " tangential mindlin NULL 0.5 0.5"


def convert(text, plugin, extra="", wall_extra=""):
    out, changed, loaded = [], [], False
    for line in text.splitlines():
        f = line.split()
        new = line
        if f[:1] == ["pair_style"]:
            new = "plugin load %s\npair_style demcontact" % os.path.abspath(plugin)
            loaded = True
        elif f[:1] == ["pair_coeff"]:
            new = None if any(l.startswith("pair_coeff * *") for l in out) else "pair_coeff * * " + OURS + extra
        elif len(f) > 4 and f[0] == "fix" and f[3] == "wall/gran" and f[4] == "granular":
            m = re.search(r"\b(xplane|yplane|zplane|zcylinder)\b.*$", line)
            k = f.index("hertz/material")  # hertz/material E damping nu
            wall = "hertz/material %s %g %s" % (f[k + 1], E_REST, f[k + 3])
            new = "fix %s %s demcontact/wall %s%s %s" % (f[1], f[2], wall, wall_extra, m.group(0))
        if new != line:
            changed.append((line, new))
        if new is not None:
            out.append(new)
    if not loaded or not changed:
        raise SystemExit("lammps_example: no pair_style/wall lines found in the deck")
    return "\n".join(out) + "\n", changed


def thermo(log):
    rows, cols = [], None
    for line in open(log).read().splitlines():
        f = line.split()
        if f[:1] == ["Step"]:
            cols = f
        elif cols and len(f) == len(cols) and re.match(r"^\d+$", f[0]):
            rows.append(dict(zip(cols, f)))
        else:
            cols = None if line.startswith("Loop time") else cols
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--lmp")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--deck", default=DECK)
    ap.add_argument("--workdir")
    a = ap.parse_args()
    import lammps_runs
    exe = lammps_runs.find_lmp(a.lmp)
    if not os.path.exists(a.deck):
        print("SKIPPED: lammps_example (%s missing: apt-get install lammps-examples; "
              "scripts/setup_simulators.sh installs it)" % a.deck)
        raise SystemExit(H.SKIP)
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_lmpex_"))
    env = H.mpi_env()
    mpirun = os.path.join(os.path.dirname(exe), "mpirun")
    text = open(a.deck).read()
    ours, changed = convert(text, a.plugin, FRICTION, WALL_FRICTION)
    print("Changed lines of %s:" % a.deck)
    for old, new in changed:
        print("  - %s\n  + %s" % (old, (new or "(removed)").replace("\n", "\n  + ")))
    runs = [("builtin", text, 1)] + [("demcontact", ours, np_) for np_ in sorted({1, a.np})]
    result, ok = {}, True
    for label, deck, np_ in runs:
        d = os.path.join(workdir, "%s_np%d" % (label, np_))
        os.makedirs(d, exist_ok=True)
        open(os.path.join(d, "in.deck"), "w").write(deck)
        out, wall = H.run(H.mpi_prefix(np_, mpirun) + [exe, "-in", "in.deck", "-log", "log.lammps"], d, env)
        rows = thermo(os.path.join(d, "log.lammps"))
        last = rows[-1]
        finite = all(math.isfinite(float(v)) for r in rows for v in r.values())
        logtext = open(os.path.join(d, "log.lammps")).read()
        done = "Loop time" in logtext
        if "Lost atoms" in logtext:
            print("%s np=%d: LOST ATOMS" % (label, np_))
            done = False
        result[(label, np_)] = last
        print("%-10s np=%d: step %s, atoms %s, KE %s, finite %s, completed %s, wall %.1f s"
              % (label, np_, last["Step"], last["Atoms"], last.get("KinEng"), finite, done, wall))
        ok &= finite and done
    n_ref = result[("builtin", 1)]["Atoms"]
    for key, last in result.items():
        if last["Atoms"] != n_ref:
            print("MISMATCH %s np=%d: %s atoms, builtin %s" % (key[0], key[1], last["Atoms"], n_ref))
            ok = False
    if not ok:
        raise SystemExit("FAIL: the example deck did not run to completion with demcontact")
    print("ok: the example runs to completion with demcontact, serial and %d ranks" % a.np)


if __name__ == "__main__":
    main()
