#!/usr/bin/env python3
"""Like-for-like loop time on LAMMPS's granular examples box, drum, funnel and mixer (Debian
package lammps-examples): the builtin deck against demcontact with the same physics where demcontact
has it (the like-for-like table of docs/lammps_examples.md; example_timing.py does flatwall):

  example_matched.py --plugin demcontactplugin.so [--example box,drum,funnel,mixer] [--np 2]
                     [--reps 3] [--project] [--workdir DIR] [--lmp lmp]

The decks are lammps_example.py's (the same run lengths: box and drum whole, funnel and mixer
short, as its table), with these contact lines (MATCHED below says why each):
  box     builtin gran/hooke (kn 4000, gamma_n 100, no shear history; tangential a dashpot
          m_eff gamma_t |v_t| capped at mu F_n) and wall hooke/history (kt = 2/7 kn, shear
          history). demcontact: `linear 4000` normal law with the restitution the builtin
          realises (measured), pair without a tangential force (demcontact has no history-free
          tangential dashpot: the builtin evaluates one more capped dashpot per contact), wall
          `tangential linear_history 1142.857 1 0.5` (kt as the builtin's, undamped, mu 0.5).
  drum    builtin `pair_style granular` hertz/material + mindlin + tsuji damping, type 2 without
          its JKR cohesion, rolling and twisting (twisting marshall has no demcontact
          counterpart; demcontact's JKR neck breaks at delta_c, 9^(1/3) times farther than
          LAMMPS's JKR pull-off distance, so the two JKR laws are not like for like;
          docs/lammps_examples.md): hertz/material with tsuji on every type pair and wall.
          demcontact: hertz/material with the restitution the builtin's tsuji damping realises
          (measured, per type), mindlin, e_t = 1.
  funnel  builtin gran/hertz/history (kn = 4G/(3(1-nu)) is Hertz's 4/3 E*, kt = 4G/(2-nu) is
          Mindlin's 8 G*: the same springs as hertz/material E nu + tangential mindlin);
          demcontact: hertz/material ${EYoung} e ${Poisson} tangential mindlin NULL 1 mu, e the
          builtin's realised restitution (measured; its damping m_eff gamma_n v_n sqrt(R* d)
          gives a speed-dependent e).
  mixer   builtin gran/hertz/history kn 1e5, kt 0.2 kn; demcontact hertz/material 136500 e 0.3
          (E = 1.5 kn (1 - nu^2): Hertz's spring = kn sqrt(R*)) tangential mindlin: k_t =
          1.235 kn sqrt(R* d), 6.2x the builtin's (Mindlin's k_t/k_n = 3(1-nu)/(2-nu) cannot
          reach 0.2 with nu <= 0.5); e the builtin's realised restitution (measured).
Tangential damping: e_t = 1 (demcontact's dashpot is set by a restitution; the builtin's gamma_t
has no exact counterpart), as in example_timing.py's matched flatwall decks.

Restitution: two spheres of the example's mean diameter (density 1) head-on at relative speed 1,
and one onto a plane wall with the example's wall model at 1, in LAMMPS with the builtin lines
(builtin_collisions()); demcontact's e is that, rounded to 3 digits (printed).

Timed: the builtin, demcontact (default carry rotate) and with --project demcontact `carry
project`, alternately, --reps times for 1 and --np ranks; kept: the minimum loop time (sum of the
deck's "Loop time" lines) and the minimum user CPU time of the whole run (all ranks, start-up
included: getrusage of the children; less sensitive than wall-clock time to other work on a shared
machine). Printed per example and rank count: the atoms kept and the observable of each model
(lammps_example.py's), the ratios to the builtin, and the load average. Exit 77 when LAMMPS or
the decks are not installed; exit 1 when a run fails.
"""
import argparse
import os
import re
import resource
import tempfile

import harness as H
import lammps_example as LE

KT_BOX = 4000.0 * 2.0 / 7.0
MATCHED = {
    "box": dict(d=1.0, types=2,
                pair=["pair_coeff * * hertz/material 5460 {e_pair} 0.3 linear 4000"],
                wall="hertz/material 5460 {e_wall} 0.3 linear 4000 tangential linear_history %.10g 1.0 0.5" % KT_BOX,
                builtin_fix={}),
    "drum": dict(d=0.75, types=2,
                 pair=["pair_coeff * * hertz/material 1e5 {e_pair} 0.3 tangential mindlin NULL 1.0 0.5",
                       "pair_coeff 2 2 hertz/material 1e5 {e_pair2} 0.3 tangential mindlin NULL 1.0 0.5"],
                 wall="hertz/material 1e5 {e_wall} 0.3 tangential mindlin NULL 1.0 0.5",
                 builtin_fix={"jkr 1e5 0.1 0.3 50 tangential mindlin NULL 1.0 0.5 rolling sds 1e3 1e3 0.1 "
                              "twisting marshall damping tsuji":
                              "hertz/material 1e5 0.1 0.3 tangential mindlin NULL 1.0 0.5 damping tsuji"}),
    "funnel": dict(d=0.75, types=1,
                   pair=["pair_coeff * * hertz/material ${EYoung} {e_pair} ${Poisson} "
                         "tangential mindlin NULL 1.0 ${coeffFric}"],
                   wall="hertz/material ${EYoung} {e_wall} ${Poisson} tangential mindlin NULL 1.0 ${coeffFric}",
                   builtin_fix={}),
    "mixer": dict(d=0.9, types=1,
                  pair=["pair_coeff * * hertz/material 136500 {e_pair} 0.3 tangential mindlin NULL 1.0 ${coeffFric}"],
                  wall="hertz/material 136500 {e_wall} 0.3 tangential mindlin NULL 1.0 ${coeffFric}",
                  builtin_fix={}),
}

COLLISIONS = """atom_style sphere
atom_modify map array
boundary p p f
region dc_box block -5 5 -5 5 0 10 units box
create_box %(types)d dc_box
comm_modify vel yes
%(vars)s
%(pair)s
create_atoms %(t)d single 0 0 5 units box
create_atoms %(t)d single 0 0 %(z2)r units box
create_atoms %(t)d single 3 3 %(z3)r units box
set atom * diameter %(d)r
set atom * density 1.0
velocity all set 0 0 0
set atom 1 vz 0.5
set atom 2 vz -0.5
set atom 3 vz -1.0
fix 1 all nve/sphere
%(wall)s
neighbor 0.3 bin
timestep 0.00001
run 60000
variable e_pair equal vz[2]-vz[1]
variable e_wall equal vz[3]
print "E_PAIR ${e_pair} E_WALL ${e_wall}"
"""


def builtin_collisions(exe, env, d, name, builtin, t=1):
    """(pair e, wall e) the builtin deck's own pair and (first) wall lines realise for type t: two
    spheres of the example's mean diameter head-on at relative speed 1, and one onto a zplane wall
    with the deck's wall model at 1 (no gravity, dt 1e-5)."""
    lines = builtin.splitlines()
    keep = [l for l in lines if l.split()[:1] == ["variable"] and "step" not in l and "elapsed" not in l]
    pair = [l for l in lines if l.split()[:1] in (["pair_style"], ["pair_coeff"])]
    wall = next(l for l in lines if len(l.split()) > 3 and l.split()[3] in ("wall/gran", "wall/gran/region"))
    f = wall.split("#")[0].split()
    if f[3] == "wall/gran/region":
        f = f[:f.index("region")]
    else:
        f = f[:f.index(next(w for w in f if w in ("xplane", "yplane", "zplane", "zcylinder")))]
    ex = MATCHED[name]
    dd = ex["d"]
    text = COLLISIONS % dict(types=ex["types"], vars="\n".join(keep), pair="\n".join(pair), t=t, d=dd,
                             z2=5 + dd + 0.05, z3=dd / 2 + 0.025,
                             wall=" ".join(["fix", "dc_wall", "all", "wall/gran"] + f[4:] + ["zplane", "0", "NULL"]))
    cd = os.path.join(d, "collisions_%s_t%d" % (name, t))
    os.makedirs(cd, exist_ok=True)
    open(os.path.join(cd, "in.collisions"), "w").write(text)
    H.run([exe, "-in", "in.collisions", "-log", "log.collisions"], cd, env)
    m = re.search(r"^E_PAIR (\S+) E_WALL (\S+)", open(os.path.join(cd, "log.collisions")).read(), re.M)
    if not m:
        raise SystemExit("example_matched: no restitution in %s/log.collisions" % cd)
    return float(m.group(1)), float(m.group(2))


def decks(name, a, exe, env, d):
    """(builtin deck, {label: our deck}, restitutions) of example `name`, with lammps_example's
    measurement lines."""
    ex = dict(LE.EXAMPLES[name])
    mt = MATCHED[name]
    short = name in ("funnel", "mixer")
    text = open(os.path.join(LE.EX_DIR, ex["deck"])).read()
    builtin = "\n".join(LE.join_continuations(text)) + "\n"
    for old, new in mt["builtin_fix"].items():
        if old not in builtin:
            raise SystemExit("example_matched: '%s' not in the %s deck" % (old, name))
        builtin = builtin.replace(old, new)
    if short:
        for old, new in ex["short"].items():
            builtin = builtin.replace(old, new)
    e_pair, e_wall = builtin_collisions(exe, env, d, name, builtin)
    e = dict(e_pair="%.3f" % e_pair, e_wall="%.3f" % e_wall)
    if "{e_pair2}" in " ".join(mt["pair"]):
        e["e_pair2"] = "%.3f" % builtin_collisions(exe, env, d, name, builtin, t=2)[0]
    def fill(line):
        for k, v in e.items():
            line = line.replace("{%s}" % k, v)
        return line

    ours = {}
    for carry in [""] + (["project"] if a.project else []):
        extra = " carry " + carry if carry else ""
        ex["pair"] = [fill(l) + extra for l in mt["pair"]]
        ex["wall"] = fill(mt["wall"]) + extra
        if name == "box":  # the pair has no history spring: no carry on its line
            ex["pair"] = [fill(l) for l in mt["pair"]]
        o, changed = LE.convert(text, a.plugin, ex, short)
        ours["demcontact" + ("_" + carry if carry else "")] = LE.measured(o, ex)
    return LE.measured(builtin, ex), ours, e, changed


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--lmp")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--example", default="box,drum,funnel,mixer")
    ap.add_argument("--project", action="store_true", help="also time demcontact with carry project")
    ap.add_argument("--workdir")
    a = ap.parse_args()
    if a.reps < 1 or a.np < 1:
        ap.error("--reps and --np must be >= 1")
    names = a.example.split(",")
    for n in names:
        if n not in MATCHED:
            ap.error("--example: unknown example '%s' (%s)" % (n, ", ".join(sorted(MATCHED))))
    if not os.path.exists(a.plugin):
        raise SystemExit("example_matched: no plugin %s" % a.plugin)
    from harness import lammps as lammps_runs
    exe = lammps_runs.find_lmp(a.lmp)
    for n in names:
        if not os.path.exists(os.path.join(LE.EX_DIR, LE.EXAMPLES[n]["deck"])):
            print("SKIPPED: example_matched (%s missing: apt-get install lammps-examples)" % LE.EXAMPLES[n]["deck"])
            raise SystemExit(H.SKIP)
    mpirun = os.path.join(os.path.dirname(exe), "mpirun")
    env = H.mpi_env()
    d = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_example_matched_"))
    os.makedirs(d, exist_ok=True)
    nps = sorted({1, a.np})
    rows = []
    for name in names:
        builtin, ours, e, changed = decks(name, a, exe, env, d)
        print("== %s: builtin's realised restitution (diameter %g, speed 1): %s" % (
            name, MATCHED[name]["d"], ", ".join("%s %s" % kv for kv in sorted(e.items()))))
        for old, new in changed:
            print("  - %s\n  + %s" % (old.strip(), (new or "(removed)").replace("\n", "\n  + ")))
        models = [("builtin", builtin)] + sorted(ours.items())
        best, first = {}, {}
        load0 = open("/proc/loadavg").read().split()[0]
        for rep in range(a.reps):
            for np_ in nps:
                for lab, deck in models:
                    rd = os.path.join(d, name, "%s_np%d_r%d" % (lab, np_, rep))
                    u0 = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
                    r = LE.run_deck(exe, mpirun, env, rd, deck, np_)
                    user = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - u0
                    if not (r["done"] and r["finite"]):
                        raise SystemExit("example_matched: %s %s np=%d did not complete (see %s)" % (name, lab, np_, rd))
                    b = best.get((lab, np_))
                    best[(lab, np_)] = (r["loop"], user) if b is None else (min(b[0], r["loop"]), min(b[1], user))
                    first.setdefault((lab, np_), r)
        load1 = open("/proc/loadavg").read().split()[0]
        ex = LE.EXAMPLES[name]
        for np_ in nps:
            ref = best[("builtin", np_)]
            for lab, _ in models:
                b, r = best[(lab, np_)], first[(lab, np_)]
                row = "| %s | %d | %s | %d | %.4g | %.3f | %.3f | %.3f | %.3f | %s-%s |" % (
                    name, np_, lab, LE.kept(r, ex["kept"]), r["obs"], b[0], b[0] / ref[0], b[1], b[1] / ref[1],
                    load0, load1)
                print(row)
                rows.append(row)
    print()
    print("## like for like, minimum of %d alternating runs (%s)" % (a.reps, ", ".join(names)))
    print("| example | ranks | model | atoms kept | observable | loop [s] | loop ratio | user [s] | user ratio "
          "| load average |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
