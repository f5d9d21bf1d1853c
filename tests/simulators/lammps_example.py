#!/usr/bin/env python3
"""LAMMPS's own granular examples (Debian package lammps-examples), changed only in their pair and
wall lines, run to completion with pair_style demcontact, fix demcontact/wall and fix
demcontact/wall/region, serial and under mpirun -np N, next to the unchanged decks.

  lammps_example.py --plugin demcontactplugin.so [--lmp lmp] [--np 2] [--example NAME[,NAME..]|all]
                    [--short] [--reps 3] [--table]

Examples (EXAMPLES below): flatwall (granular/in.pour.flatwall), drum (granular/in.pour.drum),
box, funnel, mixer (granregion/in.granregion.*). The changes, printed for each: a `plugin load` line
before `pair_style`, `pair_style demcontact`, the example's pair_coeff lines as demcontact
coefficients (the first replaced, the others removed; mapping per example below), and every
`fix ... wall/gran ...` / `fix ... wall/gran/region ...` becomes `fix ... demcontact/wall ...` /
`fix ... demcontact/wall/region ...` with the same wall geometry / region. Continuation lines (`&`)
are joined first. Measurement lines are appended after the deck's last run (a `variable` and a
`print` of the bulk observable; the funnel's also a region below its outlet to count in); nothing
else changes, except with --short: the run lengths are cut
(and the deck's own step-based motion variables with them, listed in SHORT), for ctest.

Checks, per example: every run (builtin and demcontact, serial and N ranks) ends normally ("Loop
time"), all thermo values finite, no atom lost where the deck's walls are closed; the atoms kept
(KEPT below) equal the builtin's; the bulk observable of demcontact (mean of serial and N ranks)
within the tolerance of the builtin's: tol = max(floor x |builtin|, 3 x scatter), the scatter being
the larger serial-vs-N-ranks difference of either model (MPI changes the summation order, and the
pour's chaotic dynamics amplify it: the run-to-run scatter of the observable itself); the floor
(FLOOR, per example) covers the contact law's own difference (Hertz/Mindlin for Hooke).
--reps R: loop time (sum of the deck's "Loop time" lines) as the minimum of R alternating runs
(builtin, demcontact, builtin, ...) for each rank count; --table: a markdown row per example.
"""
import argparse
import math
import os
import re
import tempfile

import harness as H

EX_DIR = "/usr/share/lammps/examples"
DECK = EX_DIR + "/granular/in.pour.flatwall"  # (--deck: another copy of a deck)

# Contact parameters of each example in demcontact's syntax (plugins/lammps/dc_coeff.h), each
# chosen from the example's own: E and nu where the example gives them; for a linear/Hertz spring
# constant kn (gran/hooke, gran/hertz/history), E = 1.5 kn (1 - nu^2) (then 4/3 E* sqrt(R*) = kn
# sqrt(R*), the gran/hertz spring; nu = 0.3); the restitution where the example states it
# (coeffRes, tsuji's e), else the one of its linear damping (box: gamma_n = 100 between two unit
# spheres, e = exp(-pi z / sqrt(1 - z^2)), z = gamma_n / (2 sqrt(kn / m_eff)): 0.25 pair, 0.11
# wall); friction mu as the example's; tangential mindlin (k_t from E, nu), e_t = 1 (the examples'
# tangential damping has no restitution counterpart). Twisting (marshall) has no demcontact
# counterpart and is left out. Cohesion (JKR) is left out too although demcontact has a JKR law
# (pair_coeff ... jkr w): its neck breaks at delta_c, 9^(1/3) times farther than LAMMPS's JKR
# contact ends (its pull-off distance), so the two decks would not compute the same physics
# (docs/lammps_examples.md).
EXAMPLES = {
    "flatwall": dict(
        deck="granular/in.pour.flatwall",
        # E and nu of the example's type-1 material, e = 0.5; the example's friction and rolling
        # resistance (mu = 0.5, mu_r = 0.5) with tangential restitution 0.5 and EPSD rolling
        pair=["pair_coeff * * hertz/material 1000.0 0.5 0.3 tangential mindlin NULL 0.5 0.5 rolling sds NULL 0 0.5"],
        wall="hertz/material 1e5 0.5 0.3 tangential mindlin NULL 0.5 0.5",
        # floor 10 %: the example's type 1 is cohesive (JKR, surface energy 10) and its type 2 another
        # material (E = 200, linear tangential), which the demcontact deck does not have: its bed
        # (one non-cohesive material) packs lower, 5.5 % in the whole deck
        obs="xcm(all,z)", obs_name="bed centre height z_cm", kept="final", floor=0.10,
        short={"run             5000": "run             1500"}),
    "drum": dict(
        deck="granular/in.pour.drum",
        # tsuji's damping value is the restitution; type 1 for all pairs, type 2's rolling kept
        pair=["pair_coeff * * hertz/material 1e5 0.2 0.3 tangential mindlin NULL 1.0 0.5",
              "pair_coeff 2 2 hertz/material 1e5 0.1 0.3 tangential mindlin NULL 1.0 0.5 rolling sds NULL 0 0.1"],
        wall="hertz/material 1e5 0.1 0.3 tangential mindlin NULL 1.0 0.5",
        # the bed's centre of mass across the turning drum (x, from the drum's axis): the rotation
        # drags the bed up the wall
        obs="xcm(all,x)-${xc}", obs_name="bed centre's offset x_cm - x_c in the turning drum", kept="lastrun",
        floor=0.05,
        short={"run             3000": "run             1000"},
        # LAMMPS since 2023 refuses the deck's type-2 line ("Cannot use tsuji model with a cohesive
        # normal model, jkr"): the builtin reference runs it with JKR's default damping
        builtin_fix={"twisting marshall damping tsuji": "twisting marshall"}),
    "box": dict(
        deck="granregion/in.granregion.box",
        pair=["pair_coeff * * hertz/material 5460 0.25 0.3 tangential mindlin NULL 1.0 0.5"],
        wall="hertz/material 5460 0.11 0.3 tangential mindlin NULL 1.0 0.5",
        obs="xcm(all,z)+6", obs_name="bed centre height above the floor", kept="final", floor=0.05,
        short={"run	        5000": "run 1000", "run             5000": "run 1000",
               "(step-5000)*(4.0*PI/5000)": "(step-1000)*(4.0*PI/1000)",
               "(step-15000)*(4.0*PI/5000)": "(step-3000)*(4.0*PI/1000)"}),
    "funnel": dict(
        deck="granregion/in.granregion.funnel",
        pair=["pair_coeff * * hertz/material ${EYoung} ${coeffRes} ${Poisson} "
              "tangential mindlin NULL 1.0 ${coeffFric}"],
        wall="hertz/material ${EYoung} ${coeffRes} ${Poisson} tangential mindlin NULL 1.0 ${coeffFric}",
        # the atoms still in the funnel at the end (above its outlet z = 0: poured minus discharged)
        obs_region="block INF INF INF INF INF 0 units box",
        obs="count(all)-count(all,dc_obs)", obs_name="atoms left in the funnel after discharge",
        kept="inserted", floor=0.10, open_walls=True,
        # (short: 300 atoms; the pour's particles need ~75000 steps to reach the cone)
        short={"pour 2000 1": "pour 300 1", "run		150000": "run		80000", "run		100000": "run		40000"}),
    "mixer": dict(
        deck="granregion/in.granregion.mixer",
        pair=["pair_coeff * * hertz/material 136500 ${coeffRes} 0.3 tangential mindlin NULL 1.0 ${coeffFric}"],
        wall="hertz/material 136500 ${coeffRes} 0.3 tangential mindlin NULL 1.0 ${coeffFric}",
        obs="ke", obs_name="kinetic energy at the end (blades turning)", kept="final", floor=0.25,
        # (short: 200 atoms, 0.4 turn of the blades at the deck's rate; they need ~95000 steps to land)
        short={"pour 1000 1": "pour 200 1", "run		200000 ": "run		120000 ", "run		200000\n": "run		40000\n"}),
}
PAIR_STYLES = ("gran/hooke", "gran/hooke/history", "gran/hertz/history", "granular", "hybrid")


def join_continuations(text):
    out, cur = [], ""
    for line in text.splitlines():
        s = line.rstrip()
        if s.endswith("&"):
            cur += s[:-1] + " "
            continue
        out.append(cur + line if cur else line)
        cur = ""
    if cur:
        out.append(cur)
    return out


def convert(text, plugin, ex, short=False):
    """The deck with its pair/wall lines changed (and, with short, its run lengths cut)."""
    out, changed, loaded = [], [], False
    lines = join_continuations(text)
    for line in lines:
        f = line.split("#")[0].split()
        new = line
        if f[:1] == ["pair_style"] and f[1] in PAIR_STYLES:
            new = "plugin load %s\npair_style demcontact" % os.path.abspath(plugin)
            loaded = True
        elif f[:1] == ["pair_coeff"]:
            new = None if any(l.startswith("pair_coeff") for l in out) else "\n".join(ex["pair"])
        elif len(f) > 3 and f[0] == "fix" and f[3] == "wall/gran":
            m = re.search(r"\b(xplane|yplane|zplane|zcylinder)\b.*$", line)
            new = "fix %s %s demcontact/wall %s %s" % (f[1], f[2], ex["wall"], m.group(0))
        elif len(f) > 3 and f[0] == "fix" and f[3] == "wall/gran/region":
            k = f.index("region")
            new = "fix %s %s demcontact/wall/region %s region %s" % (f[1], f[2], ex["wall"], f[k + 1])
        if new != line:
            changed.append((line, new))
        if new is not None:
            out.append(new)
    if not loaded or not changed:
        raise SystemExit("lammps_example: no pair_style/wall lines found in the deck")
    text = "\n".join(out) + "\n"
    if short:
        for old, new in ex["short"].items():
            if old not in text:
                raise SystemExit("lammps_example: short version: '%s' not in the deck" % old)
            text = text.replace(old, new)
    return text, changed


def measured(text, ex):
    """The deck plus the measurement lines after its last run (a region to count in, where the
    observable needs one; a variable; its print)."""
    pre = "region dc_obs %s\n" % ex["obs_region"] if "obs_region" in ex else ""
    return text + pre + "variable dc_obs equal %s\nprint \"DC_OBS ${dc_obs}\"\n" % ex["obs"]


def thermo(log):
    """The thermo rows of each run: a list per run of dicts."""
    return H.parse_thermo(open(log).read())


def run_deck(exe, mpirun, env, d, deck, np_):
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, "in.deck"), "w").write(deck)
    out, wall = H.run(H.mpi_prefix(np_, mpirun) + [exe, "-in", "in.deck", "-log", "log.lammps"], d, env)
    log = open(os.path.join(d, "log.lammps")).read()
    runs = thermo(os.path.join(d, "log.lammps"))
    loop = sum(float(m) for m in re.findall(r"^Loop time of (\S+)", log, re.M))
    obs = re.findall(r"^DC_OBS (\S+)", log, re.M)
    rows = [r for rr in runs for r in rr]
    return dict(runs=runs, rows=rows, loop=loop, log=log, wall=wall,
                obs=float(obs[-1]) if obs else float("nan"),
                # the measurement line follows the last run: printed = the deck ran to its end
                done="Loop time" in log and bool(obs) and "ERROR" not in log,
                lost="Lost atoms" in log or "Out of range atoms" in log,
                finite=all(math.isfinite(float(v)) for r in rows for k, v in r.items() if k != "CPU"))


def kept(res, how):
    """The atoms a deck keeps (compared with the builtin's)."""
    if how == "inserted":
        return max(int(r["Atoms"]) for r in res["rows"])
    if how == "lastrun":  # the last run's atoms (none lost while it runs)
        last = res["runs"][-1]
        counts = {int(r["Atoms"]) for r in last}
        return counts.pop() if len(counts) == 1 else -1
    return int(res["rows"][-1]["Atoms"])


def check_example(name, a, exe, mpirun, env, workdir):
    ex = EXAMPLES[name]
    path = a.deck if (a.deck and name == "flatwall") else os.path.join(EX_DIR, ex["deck"])
    if not os.path.exists(path):
        print("SKIPPED: lammps_example %s (%s missing: apt-get install lammps-examples; "
              "scripts/setup_simulators.sh installs it)" % (name, path))
        raise SystemExit(H.SKIP)
    text = open(path).read()
    ours, changed = convert(text, a.plugin, ex, a.short)
    builtin = "\n".join(join_continuations(text)) + "\n"
    for old, new in ex.get("builtin_fix", {}).items():
        print("builtin reference: '%s' -> '%s'" % (old, new))
        builtin = builtin.replace(old, new)
    if a.short:
        for old, new in ex["short"].items():
            builtin = builtin.replace(old, new)
    print("== %s (%s%s): changed lines" % (name, path, ", short" if a.short else ""))
    for old, new in changed:
        print("  - %s\n  + %s" % (old.strip(), (new or "(removed)").replace("\n", "\n  + ")))
    nps = sorted({1, a.np})
    res, ok, loops = {}, True, {}
    for rep in range(a.reps):
        for np_ in nps:
            for label, deck in (("builtin", builtin), ("demcontact", ours)):
                d = os.path.join(workdir, name, "%s_np%d_r%d" % (label, np_, rep))
                r = run_deck(exe, mpirun, env, d, measured(deck, ex), np_)
                loops.setdefault((label, np_), []).append(r["loop"])
                if rep == 0:
                    res[(label, np_)] = r
    for (label, np_), r in sorted(res.items()):
        good = r["done"] and r["finite"] and not (r["lost"] and not ex.get("open_walls"))
        last = r["rows"][-1] if r["rows"] else {}
        print("%-10s np=%d: step %s, atoms %s kept %d, %s = %.6g, finite %s, lost %s, completed %s, loop %.2f s"
              % (label, np_, last.get("Step"), last.get("Atoms"), kept(r, ex["kept"]) if r["rows"] else -1,
                 ex["obs"], r["obs"], r["finite"], r["lost"], r["done"], r["loop"]))
        print("%-10s np=%d: last thermo row: %s" % (label, np_, " ".join(
            "%s %s" % (k, v) for k, v in last.items() if k not in ("Step", "CPU"))))
        if not good:
            print("FAIL %s %s np=%d: did not run to completion cleanly (see %s)" % (name, label, np_, workdir))
        ok &= good
    if not ok:
        return False, None
    n_ref = kept(res[("builtin", 1)], ex["kept"])
    for key, r in res.items():
        if kept(r, ex["kept"]) != n_ref:
            print("MISMATCH %s %s np=%d: %d atoms kept, builtin serial %d" % (name, key[0], key[1],
                                                                             kept(r, ex["kept"]), n_ref))
            ok = False
    b = [res[("builtin", n)]["obs"] for n in nps]
    o = [res[("demcontact", n)]["obs"] for n in nps]
    scatter = max(abs(max(b) - min(b)), abs(max(o) - min(o)))
    bm, om = sum(b) / len(b), sum(o) / len(o)
    tol = max(ex["floor"] * abs(bm), 3 * scatter)
    within = abs(om - bm) <= tol
    print("%s %s: %s demcontact %.6g vs builtin %.6g (difference %.3g, tolerance %.3g = max(%g x |builtin|, "
          "3 x scatter %.3g))" % ("ok  " if within else "FAIL", name, ex["obs_name"], om, bm, abs(om - bm), tol,
                                 ex["floor"], scatter))
    ok &= within
    if len(set(o + b)) == 1:
        print("FAIL %s: the observable is the same in every run: the contacts never acted" % name)
        ok = False
    ratios = {n: min(loops[("demcontact", n)]) / min(loops[("builtin", n)]) for n in nps}
    print("%s: loop time demcontact / builtin (minimum of %d alternating runs): %s" % (
        name, a.reps, ", ".join("%d rank%s %.2f" % (n, "s" if n > 1 else "", ratios[n]) for n in nps)))
    row = "| %s | %d | %s | %.4g / %.4g (tol %.2g)%s | %s |" % (
        name, n_ref, ex["obs_name"], om, bm, tol, "" if within else " FAIL",
        " / ".join("%.2f" % ratios[n] for n in nps))
    return ok, row


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--lmp")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--deck", help="another copy of in.pour.flatwall (example flatwall)")
    ap.add_argument("--example", default="flatwall", help="one of %s, a comma-separated list, or all"
                    % ", ".join(sorted(EXAMPLES)))
    ap.add_argument("--short", action="store_true", help="cut run lengths (ctest)")
    ap.add_argument("--reps", type=int, default=1, help="alternating runs for the loop-time minimum")
    ap.add_argument("--table", action="store_true")
    ap.add_argument("--workdir")
    a = ap.parse_args()
    from harness import lammps as lammps_runs
    exe = lammps_runs.find_lmp(a.lmp)
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_lmpex_"))
    env = H.mpi_env()
    mpirun = os.path.join(os.path.dirname(exe), "mpirun")
    names = sorted(EXAMPLES) if a.example == "all" else a.example.split(",")
    for name in names:
        if name not in EXAMPLES:
            ap.error("--example: unknown example '%s' (%s)" % (name, ", ".join(sorted(EXAMPLES))))
    failed, rows = [], []
    for name in names:
        good, row = check_example(name, a, exe, mpirun, env, workdir)
        if not good:
            failed.append(name)
        rows.append(row or "| %s | FAIL | | | |" % name)
    if a.table:
        print("| example | atoms kept | observable | demcontact / builtin | loop time ratio 1 / %d ranks |" % a.np)
        print("|---|---|---|---|---|")
        print("\n".join(rows))
    if failed:
        raise SystemExit("FAIL: %s" % ", ".join(failed))
    print("ok: %s run to completion with demcontact, serial and %d ranks" % (", ".join(names), a.np))


if __name__ == "__main__":
    main()
