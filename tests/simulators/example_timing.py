#!/usr/bin/env python3
"""Loop time of LAMMPS's own granular example examples/granular/in.pour.flatwall (Debian package
lammps-examples) without rolling resistance, demcontact against the builtin `pair_style granular`
with the same parameters (the speed rows of docs/lammps_examples.md):

  example_timing.py --plugin demcontactplugin.so [--before LABEL=old.so ...] [--np 2] [--reps 3]
                    [--steps N] [--workdir DIR] [--lmp lmp] [--deck in.pour.flatwall] [--count]
                    [--step-exact]

Decks (only the pair and wall lines of the example change; printed):
  granular            pair_style granular; pair_coeff * * hertz/material 1000.0 0.5 0.3 tangential
                      mindlin NULL 1.0 0.5 (the example's type-1 E, nu, mu; its damping coefficient
                      0.5, LAMMPS' default viscoelastic damping); the wall line unchanged
                      (hertz/material 1e5 1e3 0.3 tangential mindlin NULL 1.0 0.5 zplane 0 NULL)
  demcontact          pair_style demcontact; pair_coeff * * hertz/material 1000.0 0.5 0.3 tangential
                      mindlin NULL 1.0 0.5 (restitution e = 0.5, tangential e_t = 1, mu = 0.5; the
                      default carry); fix demcontact/wall hertz/material 1e5 0.5 0.3 tangential
                      mindlin NULL 1.0 0.5 zplane 0 NULL
  demcontact_project  the same with `carry project` on the pair and wall lines
  matched             (and matched_project) demcontact with the builtin's restitution: the builtin's
                      viscoelastic coefficient 0.5 is not a restitution; its law (eta = 0.5 a m_eff)
                      is nearly elastic between the deck's spheres (e = 0.994-0.999 over diameters
                      0.5-1 and speeds 0.1-15, builtin_restitution()). The decks take the e the
                      builtin realises in LAMMPS for two spheres of the mean diameter 0.75 at relative
                      speed 1, and for one of them onto the deck's wall at 1 (builtin_collisions(),
                      printed: pair 0.998, wall 0.640), so that both runs dissipate alike and
                      evaluate as many contacts (see --count). The pair's e is checked against
                      builtin_restitution() (within 1e-4: exit 1 otherwise).
  matched_step_exact  (--step-exact) matched with `step_exact` on the pair and wall lines: the
                      deck's own step, the cost of the step-aware option in a pour (its ratio to
                      matched is printed; docs/timestep.md, "Cost in a scene")

--count: one more (untimed) run per model with `compute contact/atom` every 10 steps: the contact
evaluations of the run (touching pairs summed over the sampled steps, x 10) in the table.

The models run alternately (granular, demcontact, demcontact_project, [LABEL, LABEL_project],
matched, matched_project, granular, ...), each --reps times for each rank count (1, and --np when > 1); the minimum is
kept. Printed per model: loop time ("Loop time"), pair, neighbour and modify time (LAMMPS' task
timing breakdown, average over ranks), neighbour-list builds, atoms at the end, the loop ratio
to the builtin, and the user CPU time of the whole run (all ranks, start-up included; less
sensitive than the wall-clock times to other work on the machine) and its ratio to the builtin.
Exit 77 when LAMMPS or the deck is not installed.
"""
import argparse
import os
import resource
import re
import tempfile

import harness as H

DECK = "/usr/share/lammps/examples/granular/in.pour.flatwall"
PAIR = "hertz/material 1000.0 0.5 0.3 tangential mindlin NULL 1.0 0.5"
WALL = "hertz/material 1e5 0.5 0.3 tangential mindlin NULL 1.0 0.5"
MATCHED = "hertz/material 1000.0 %.3f 0.3 tangential mindlin NULL 1.0 0.5"
MATCHED_WALL = "hertz/material 1e5 %.3f 0.3 tangential mindlin NULL 1.0 0.5"


def builtin_restitution(E, nu, eta0, d, v, wall=False):
    """Normal restitution of LAMMPS' `hertz/material E eta0 nu` with its default viscoelastic
    damping (F = 4/3 E* sqrt(R) x^1.5 + eta0 a m_eff x', a = sqrt(R x), E* = E / (2 (1 - nu^2)),
    the same material on both sides, as the builtin's wall mixes its coefficients with themselves)
    for two spheres of diameter d and density 1 (wall: one sphere on a plane) meeting at speed v:
    RK4 in 20000 steps of the contact time, until the overlap or the force ends."""
    import math
    Es = E / (2.0 * (1.0 - nu * nu))
    R = d / 2.0 if wall else d / 4.0
    m = math.pi * d ** 3 / 6.0
    meff = m if wall else m / 2.0

    def acc(x, u):
        return (-(4.0 / 3.0) * Es * math.sqrt(R) * x ** 1.5 - eta0 * meff * math.sqrt(R * x) * u) / meff if x > 0 else 0.0

    x, u = 0.0, v
    h = 2.87 * (meff ** 2 / (R * Es ** 2 * v)) ** 0.2 / 20000.0
    for _ in range(1000000):
        k1x, k1u = u, acc(x, u)
        k2x, k2u = u + h / 2 * k1u, acc(x + h / 2 * k1x, u + h / 2 * k1u)
        k3x, k3u = u + h / 2 * k2u, acc(x + h / 2 * k2x, u + h / 2 * k2u)
        k4x, k4u = u + h * k3u, acc(x + h * k3x, u + h * k3u)
        x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x)
        u += h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u)
        if x <= 0.0 or (u < 0.0 and acc(x, u) >= 0.0):
            return -u / v
    raise SystemExit("example_timing: builtin_restitution did not end")


COLLISIONS = """atom_style sphere
atom_modify map array
units lj
boundary p p f
region box block -5 5 -5 5 0 10
create_box 1 box
comm_modify vel yes
pair_style granular
pair_coeff * * %(pair)s
create_atoms 1 single 0 0 5
create_atoms 1 single 0 0 5.8
create_atoms 1 single 3 3 0.4
set atom * diameter 0.75
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


def builtin_collisions(exe, d, env, deck_text):
    """(pair e, wall e) the builtin realises with the deck's own pair (PAIR) and wall lines: two
    spheres of diameter 0.75, density 1, head-on at relative speed 1, and one onto the wall at 1
    (no gravity, dt 1e-5: over 4000 steps per contact)."""
    wall = next(l for l in deck_text.splitlines() if l.split()[:1] == ["fix"] and "wall/gran" in l)
    f = wall.split()
    open(os.path.join(d, "in.collisions"), "w").write(
        COLLISIONS % {"pair": PAIR, "wall": " ".join(["fix", f[1], "all"] + f[3:])})
    out, _ = H.run([exe, "-in", "in.collisions", "-log", "log.collisions"], d, env)
    m = re.search(r"^E_PAIR (\S+) E_WALL (\S+)", open(os.path.join(d, "log.collisions")).read(), re.M)
    if not m:
        raise SystemExit("example_timing: no restitution in %s/log.collisions" % d)
    return float(m.group(1)), float(m.group(2))


def decks(text, plugin, carry, steps, pair=PAIR, wall=WALL, step_exact=False):
    """(builtin deck, our deck) of the example: only the pair and wall lines (and `run` with
    --steps) changed; `pair` and `wall` are our lines' coefficients."""
    b, o = [], []
    extra = (" carry %s" % carry if carry else "") + (" step_exact" if step_exact else "")
    for line in text.splitlines():
        f = line.split()
        if f[:1] == ["pair_style"]:
            b.append(line)
            o.append("plugin load %s\npair_style demcontact" % os.path.abspath(plugin))
        elif f[:1] == ["pair_coeff"]:
            if not any(l.startswith("pair_coeff * *") for l in b):
                b.append("pair_coeff * * " + PAIR)
                o.append("pair_coeff * * " + pair + extra)
        elif len(f) > 4 and f[0] == "fix" and f[3] == "wall/gran":
            m = re.search(r"\b(xplane|yplane|zplane|zcylinder)\b.*$", line)
            b.append(line)
            o.append("fix %s %s demcontact/wall %s%s %s" % (f[1], f[2], wall, extra, m.group(0)))
        elif f[:1] == ["run"] and steps:
            b.append("run %d" % steps)
            o.append("run %d" % steps)
        else:
            b.append(line)
            o.append(line)
    return "\n".join(b) + "\n", "\n".join(o) + "\n"


def times(log):
    t = open(log).read()
    loop = float(re.search(r"Loop time of ([0-9.eE+-]+) on", t).group(1))
    sec = {}
    for name in ("Pair", "Neigh", "Modify"):
        m = re.search(r"^%s\s*\|\s*[0-9.eE+-]+\s*\|\s*([0-9.eE+-]+)" % name, t, re.M)
        if not m:
            raise SystemExit("example_timing: no %s time in %s" % (name, log))
        sec[name] = float(m.group(1))
    builds = int(re.search(r"Neighbor list builds = (\d+)", t).group(1))
    atoms = int(re.search(r"for \d+ steps with (\d+) atoms", t).group(1))
    return loop, sec["Pair"], sec["Neigh"], sec["Modify"], builds, atoms


def contacts(log):
    """Contact evaluations of a --count run: touching pairs (thermo column c_dc_cs, normalised
    per atom in lj units: times atoms / 2) summed over the steps sampled every 10."""
    t = open(log).read()
    rows = [l.split() for l in t.splitlines() if re.match(r"^\s*\d+\s+\d+\s+\S+\s+\S+\s*$", l)]
    if not rows:
        raise SystemExit("example_timing: no contact counts in %s" % log)
    return 10 * sum(float(r[3]) * int(r[1]) / 2.0 for r in rows)


def counting(deck):
    out = []
    for line in deck.splitlines():
        f = line.split()
        if f[:1] == ["thermo_style"]:
            out += ["compute dc_cc all contact/atom", "compute dc_cs all reduce sum c_dc_cc",
                    "thermo_style custom step atoms ke c_dc_cs"]
        elif f[:1] == ["thermo"]:
            out.append("thermo 10")
        else:
            out.append(line)
    return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--before", action="append", default=[],
                    help="an older build of the plugin (LABEL=PATH), timed in the same alternation; repeatable")
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--steps", type=int, default=0, help="run length (default: the deck's own, 5000)")
    ap.add_argument("--workdir")
    ap.add_argument("--lmp")
    ap.add_argument("--deck", default=DECK)
    ap.add_argument("--count", action="store_true", help="count the contact evaluations (one untimed run per model)")
    ap.add_argument("--step-exact", action="store_true",
                    help="also time matched with step_exact on the pair and wall lines")
    a = ap.parse_args()
    if a.reps < 1 or a.steps < 0 or a.np < 1:
        raise SystemExit("example_timing: --reps and --np must be >= 1, --steps >= 0")
    from harness import lammps as lammps_runs
    exe = lammps_runs.find_lmp(a.lmp)
    if not os.path.exists(a.deck):
        print("SKIPPED: example_timing (%s missing: apt-get install lammps-examples)" % a.deck)
        raise SystemExit(H.SKIP)
    mpirun = os.path.join(os.path.dirname(exe), "mpirun")
    env = H.mpi_env()
    d = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_example_timing_"))
    os.makedirs(d, exist_ok=True)
    text = open(a.deck).read()
    plugins = [("demcontact", a.plugin)]
    for b in a.before:
        lab, sep, p = b.partition("=")
        if not sep or not lab or lab in ("granular", "demcontact", "demcontact_project") \
                or lab in [q[0] for q in plugins]:
            raise SystemExit("example_timing: --before wants LABEL=PATH with a new label, got %r" % b)
        plugins.append((lab, p))
    models = []
    builtin, _ = decks(text, a.plugin, None, a.steps)
    models.append(("granular", builtin))
    for lab, p in plugins:
        if not os.path.exists(p):
            raise SystemExit("example_timing: no plugin %s" % p)
        models.append((lab, decks(text, p, None, a.steps)[1]))
        models.append((lab + "_project", decks(text, p, "project", a.steps)[1]))
    e_pair, e_wall = builtin_collisions(exe, d, env, text)
    e_law = builtin_restitution(1000.0, 0.3, 0.5, 0.75, 1.0)
    print("builtin restitution at diameter 0.75, speed 1 (LAMMPS): pair %.6f (its law integrated: %.6f), "
          "wall %.6f" % (e_pair, e_law, e_wall))
    span = [builtin_restitution(1000.0, 0.3, 0.5, dd, v) for dd in (0.5, 0.75, 1.0) for v in (0.1, 1.0, 5.0, 15.0)]
    print("builtin pair restitution over diameters 0.5-1 and speeds 0.1-15 (its law): %.4f-%.4f"
          % (min(span), max(span)))
    if not abs(e_pair - e_law) <= 1e-4:
        raise SystemExit("example_timing: the builtin's pair restitution %.6f is not its law's %.6f (tolerance 1e-4)"
                         % (e_pair, e_law))
    e_pair, e_wall = round(e_pair, 3), round(e_wall, 3)
    for carry in (None, "project"):
        models.append(("matched" + ("_" + carry if carry else ""),
                       decks(text, a.plugin, carry, a.steps, MATCHED % e_pair, MATCHED_WALL % e_wall)[1]))
    if a.step_exact:
        models.append(("matched_step_exact",
                       decks(text, a.plugin, None, a.steps, MATCHED % e_pair, MATCHED_WALL % e_wall, True)[1]))
    for lab, deck in models:
        open(os.path.join(d, "in.%s" % lab), "w").write(deck)
    print("Decks in %s; lines changed against %s:" % (d, a.deck))
    for lab, deck in models[:3] + models[-1:]:
        old = set(text.splitlines())
        print("  %s: %s" % (lab, " | ".join(l for l in deck.splitlines() if l not in old)))
    nps = [1] + ([a.np] if a.np > 1 else [])
    best = {}
    load0 = open("/proc/loadavg").read().split()[:3]
    for np_ in nps:
        for r in range(a.reps):
            for lab, _ in models:
                log = "log.%s.np%d.%d" % (lab, np_, r)
                u0 = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
                H.run(H.mpi_prefix(np_, mpirun) + [exe, "-in", "in.%s" % lab, "-log", log], d, env)
                t = times(os.path.join(d, log)) + (resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - u0,)
                b = best.get((lab, np_))
                best[(lab, np_)] = t if b is None else tuple(min(x, y) for x, y in zip(b[:4], t[:4])) + t[4:6] + (
                    min(b[6], t[6]),)
    load1 = open("/proc/loadavg").read().split()[:3]
    count = {}
    if a.count:
        for lab, deck in models:
            open(os.path.join(d, "in.count.%s" % lab), "w").write(counting(deck))
            H.run([exe, "-in", "in.count.%s" % lab, "-log", "log.count.%s" % lab], d, env)
            count[lab] = contacts(os.path.join(d, "log.count.%s" % lab))
    print()
    print("## in.pour.flatwall without rolling, %s steps, minimum of %d alternating runs "
          "(load average at the start: %s; at the end: %s)"
          % (a.steps or "the deck's", a.reps, " ".join(load0), " ".join(load1)))
    print()
    print("| model | ranks | loop [s] | pair [s] | neigh [s] | modify [s] | builds | atoms | loop ratio | user [s] "
          "| user ratio |" + (" contacts [1e6] |" if a.count else ""))
    print("|---|---|---|---|---|---|---|---|---|---|---|" + ("---|" if a.count else ""))
    for np_ in nps:
        ref, uref = best[("granular", np_)][0], best[("granular", np_)][6]
        for lab, _ in models:
            b = best[(lab, np_)]
            print("| %s | %d | %.3f | %.3f | %.3f | %.3f | %d | %d | %.3f | %.3f | %.3f |"
                  % (lab, np_, b[0], b[1], b[2], b[3], b[4], b[5], b[0] / ref, b[6], b[6] / uref)
                  + (" %.2f |" % (count[lab] / 1e6) if a.count else ""))
    if a.step_exact:
        print()
        for np_ in nps:
            s, m = best[("matched_step_exact", np_)], best[("matched", np_)]
            print("step_exact / matched, %d rank(s): loop %.3f, pair %.3f, modify %.3f, user %.3f"
                  % (np_, s[0] / m[0], s[1] / m[1], s[3] / m[3], s[6] / m[6]))


if __name__ == "__main__":
    main()
