#!/usr/bin/env python3
"""Adhesive head-on impacts in LAMMPS (`pair_coeff ... jkr w`, `... dmt w`; fix demcontact/wall and
fix demcontact/wall/region) against the library's own contact integrated with the same
velocity-Verlet steps (adhesion_ref, dc_contact_force):

  adhesion.py --plugin demcontactplugin.so --ref adhesion_ref [--lmp lmp] [--np 2]
              [--newton on|off ...] [--walls] [--drift] [--restart] [--workdir DIR]

Silica-like spheres, R = 10 um, rho = 2500, E = 70 GPa, nu = 0.25, w = 0.2 J/m^2 (JKR sticking
speed of a pair v_s = sqrt(2W/m*), W = (2 pi)^(5/3) (6 + 4^(-1/3))/20 (w^5 R*^4/E*^2)^(1/3),
about 4 cm/s; of a sphere on a wall about 3 cm/s). Each run holds several impacts far apart, one
per speed; the spheres start 3 reaches apart (JKR |delta_c|, DMT d_c), dt = t_H(20 v_s)/200.

  jkr           undamped, v/v_s = 0.5, 0.9 (stick), 1.5, 3, 10 (separate)
  jkr damped    e_n = 0.5 with tangential mindlin (the neck state after the springs in the
                history), v/v_s = 0.5 (stick), 2, 5, 20 (separate at 5, 20)
  dmt           undamped (the tail is conservative: e = 1), v/v_s = 0.05, 0.5, 3, 10
  dmt damped    e_n = 0.3, v/v_s = 0.05, 3 (captured), 10 (separate)
  jkr pulled    e_n = 0.5, a pair at rest just touching, pulled apart by 1.4 pi w R* (fix
                addforce): held by the neck at negative overlap; on 2 ranks with --drift the
                side that evaluates it changes while it is held (deck()); with --restart
                also interrupted at half way by write_restart and continued after read_restart
                in a new process: its positions within 1e-9 R of the uninterrupted run's.
                With --walls also a sphere pulled off each flat wall the same way (R* = R),
                through the same restart (the fix and, for the region, its region defined again
                with the same IDs: the held neck comes back from the file's per-atom record)

Pairs: two spheres on the x axis, the first at x < 0 (with --np 2 and `processors 2 1 1` each
sphere on its own rank: every contact across the rank boundary), with the given `newton` settings.
--drift: both spheres of each pair also move at a common U along x, from x = -3e-5 to +3e-5 over
the run (with 2 ranks: on rank 0, then split across the boundary, then both migrated to rank 1,
the stuck necks held through every reneighbouring; the reference integrates the same
velocities).
--walls: a sphere on the plane z = 0 by fix demcontact/wall zplane and by fix
demcontact/wall/region on a `region plane` (the region's distance is z itself: the same bits),
each case also with a bystander of radius 3 R at rest 2 R off the plane (tag _big): the fixes
bound where an adhesive law is looked for (DMT's tail, the region's faces) by the reach at the
group's largest radius, the bystander's, and the impacts must keep the reference's bits;
the JKR impacts (jkr, jkr damped) also on the inside of fix demcontact/wall zcylinder Rc
(Rc = 5 R): the sphere at (Rc - R - gap, 0, z) moving along +x, against adhesion_ref's zcyl case,
which builds the contact as the fix does (rxy = |x|, n = -x/rxy, overlap = r - (Rc - rxy)), so
the same bits again (the cylinder's curvature is not used by the fix: the wall is flat at the
contact, r2 = inf).

Checks: (a) every impact's final position and velocity equal the reference's to 1e-12 relative
(the realised restitution too; measured: 0, bit-identical); (b, c) JKR: the impacts below v_s
end with the neck formed (the reference's state 1, the gap within |delta_c|), those above with it
broken and the bodies apart, and the undamped rebound within 2e-3 of e = sqrt(1 - v_s^2/v^2)
(the closed form of the continuous law; the step misplaces some of the work of the force's jumps
at formation and breakage); (d) DMT undamped e within 1e-3 of 1, the damped slow impact captured
and the fast ones apart; the pulled pair ends held (gap in (0, |delta_c|), the reference's state
1). Exit 1 on any failure, 77 (ctest SKIP) when LAMMPS is missing.
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile

import harness as H

R, RHO, E, NU, W = 1e-5, 2500.0, 7e10, 0.25, 0.2
TOL_BITS = 1e-12  # LAMMPS against the reference (relative; bit-identical expected)
TOL_E_JKR = 2e-3  # undamped JKR rebound against the closed form of the continuous law
TOL_E_DMT = 1e-3  # undamped DMT rebound against 1
TOL_RESTART = 1e-9  # the pulled pair after write/read_restart against the uninterrupted run (R)
SPAN = 1e-4       # distance between impacts (10 R; the cutoff is 2 R plus a few nm)
RCYL = SPAN / 2   # --walls: the z cylinder's radius (fix demcontact/wall zcylinder)

CASES = [  # (label, law, e_n, mu, speeds / v_s, outcome per speed: S stuck, A apart)
    ("jkr", "jkr", 1.0, 0.0, (0.5, 0.9, 1.5, 3.0, 10.0), "SSAAA"),
    ("jkr damped", "jkr", 0.5, 0.5, (0.5, 2.0, 5.0, 20.0), "SSAA"),
    ("dmt", "dmt", 1.0, 0.0, (0.05, 0.5, 3.0, 10.0), "AAAA"),
    ("dmt damped", "dmt", 0.3, 0.0, (0.05, 3.0, 10.0), "SSA"),
    # P: a pair pulled apart (pairs only): starting at rest at overlap 1e-3 |delta_c| (the neck
    # forms at once) under a constant load 1.4 pi w R* (fix addforce, apart), between the force at
    # zero overlap (4/3) and the pull-off force (3/2 pi w R*): it settles held by the neck at
    # negative overlap (the timing of a 0.5 v_s impact); with --drift on 2 ranks the side that
    # evaluates it changes while the neck holds it apart (deck())
    ("jkr pulled", "jkr", 0.5, 0.0, (0.5,), "P"),
]

def e_star():
    return E / (2.0 * (1.0 - NU * NU))


def reach(law, r_eff):
    es = e_star()
    if law == "jkr":
        return 0.75 * (math.pi ** 2 * W ** 2 * r_eff / es ** 2) ** (1.0 / 3.0)
    return (3.0 * math.pi * W * math.sqrt(r_eff) / (2.0 * es)) ** (2.0 / 3.0)


def sticking_speed(r_eff, m_eff):
    w_break = (2 * math.pi) ** (5.0 / 3.0) * (6 + 4 ** (-1.0 / 3.0)) / 20 * (W ** 5 * r_eff ** 4 / e_star() ** 2) ** (1.0 / 3.0)
    return math.sqrt(2.0 * w_break / m_eff)


def hertz_time(r_eff, m_eff, v):
    return 2.868 * (m_eff ** 2 / (r_eff * e_star() ** 2 * v)) ** 0.2


def coeff(law, e_n, mu):
    c = "hertz/material %.17g %.17g %.17g %s %.17g" % (E, e_n, NU, law, W)
    if mu > 0:
        c += " tangential mindlin NULL 1 %.17g" % mu
    return c


def plan(wall, law, e_n, speeds):
    """dt, steps and the bodies: (x or z, v) of the first sphere (and the second's, pairs)."""
    mass = RHO * 4.0 / 3.0 * math.pi * R ** 3
    r_eff, m_eff = (R, mass) if wall else (R / 2, mass / 2)
    vs = sticking_speed(r_eff, m_eff)
    dt = hertz_time(r_eff, m_eff, 20 * vs) / 200
    gap = 3 * reach(law, r_eff)
    vmin = min(speeds) * vs
    steps = int((gap / vmin + 12 * hertz_time(r_eff, m_eff, vmin)) / dt) + 1
    return vs, dt, steps, gap, r_eff


def pull_load(r_eff):
    return 1.4 * math.pi * W * r_eff


def deck(plugin, wall, law, e_n, mu, speeds, newton, np_, drift, pulled=False, big=False):
    vs, dt, steps, gap, r_eff = plan(wall, law, e_n, speeds)
    if pulled:
        gap = -1e-3 * reach(law, r_eff)
    # --drift: both spheres of a pair also move at U along x, from x = -X0 to +X0 over the run
    x0 = 0.3 * SPAN if drift else 0.0
    u = 2 * x0 / (steps * dt)
    # zcyl: the spheres one above the other along the cylinder's axis (z), each moving along x
    ybox, zbox = (SPAN, SPAN * (len(speeds) + 1)) if wall == "zcyl" else (SPAN * (len(speeds) + 1), SPAN)
    L = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "comm_modify vel yes",
         "newton %s" % newton, "processors %d 1 1" % np_ if np_ > 1 else "",
         "region box block %g %g %g %g %g %g units box" % (-SPAN, SPAN, -SPAN, ybox, -SPAN, zbox),
         "create_box 1 box", "plugin load %s" % os.path.abspath(plugin), "neighbor %g bin" % (R / 10),
         "neigh_modify delay 0"]
    if wall == "zplane":
        L.append("fix w all demcontact/wall %s zplane 0 NULL" % coeff(law, e_n, mu))
    elif wall == "zcyl":
        L.append("fix w all demcontact/wall %s zcylinder %.17g" % (coeff(law, e_n, mu), RCYL))
    elif wall == "region":
        L += ["region fl plane 0 0 0 0 0 1 side in units box",
              "fix w all demcontact/wall/region %s region fl" % coeff(law, e_n, mu)]
    else:
        L += ["pair_style demcontact", "pair_coeff * * " + coeff(law, e_n, mu)]
    n = 0
    for k, s in enumerate(speeds):
        v = s * vs
        y = SPAN * k
        if pulled:
            v = 0.0
        if wall == "zcyl":  # at (Rc - R - gap, 0, z), moving along +x towards the wall at Rc
            L += ["create_atoms 1 single %.17g 0 %.17g units box" % (RCYL - R - gap, y),
                  "set atom %d diameter %.17g density %.17g vx %.17g" % (n + 1, 2 * R, RHO, v)]
            n += 1
        elif wall:
            L += ["create_atoms 1 single %.17g %.17g %.17g units box" % (SPAN / 2, y, R + gap),
                  "set atom %d diameter %.17g density %.17g vz %.17g" % (n + 1, 2 * R, RHO, -v)]
            n += 1
        else:
            x = R + gap / 2
            L += ["create_atoms 1 single %.17g %.17g 0 units box" % (-x0 - x, y),
                  "create_atoms 1 single %.17g %.17g 0 units box" % (-x0 + x, y),
                  "set atom %d diameter %.17g density %.17g vx %.17g" % (n + 1, 2 * R, RHO, u + v / 2),
                  "set atom %d diameter %.17g density %.17g vx %.17g" % (n + 2, 2 * R, RHO, u - v / 2)]
            n += 2
    if big:  # a flat wall's bystander of radius 3 R at rest, 2 R off the plane (the last atom ID)
        L += ["create_atoms 1 single %.17g %.17g %.17g units box" % (-SPAN / 2, -SPAN / 2, 5 * R),
              "set atom %d diameter %.17g density %.17g" % (n + 1, 6 * R, RHO)]
    if pulled and wall:  # the sphere pulled off the wall (+z) by the load
        L += ["group pa id 1", "fix pa pa addforce 0 0 %.17g" % pull_load(r_eff)]
    elif pulled:
        p = pull_load(r_eff)
        L += ["group pa id 1", "group pb id 2", "fix pa pa addforce %.17g 0 0" % -p,
              "fix pb pb addforce %.17g 0 0" % p,
              # one neighbour bin, no sorting: the list owner of an owned pair is the atom of lower
              # index and of a ghost pair the one at smaller x, so once both spheres have migrated
              # (B first) B evaluates the contact that A's rank evaluated while they were split:
              # B's copy of the held neck must have come from A's rank (newton on: the exchange)
              "neigh_modify binsize %g" % (8 * SPAN), "atom_modify sort 0 0.0"]
    L += ["fix integr all nve/sphere", "timestep %.17g" % dt,
          "dump d all custom %d traj.dump id x y z vx vy vz mass radius" % steps,
          "dump_modify d format float %.17g sort id", "thermo %d" % steps, "run %d" % steps]
    return "\n".join(l for l in L if l) + "\n", dt, steps, vs


def frames(path):
    out = []
    for block in open(path).read().split("ITEM: TIMESTEP")[1:]:
        lines = block.strip().splitlines()
        i = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
        cols = lines[i].split()[2:]
        atoms = {}
        for l in lines[i + 1:]:
            f = dict(zip(cols, map(float, l.split())))
            bad = [c for c, v in f.items() if not math.isfinite(v)]
            if bad:
                raise SystemExit("FAIL: %s: atom %d has non-finite %s" % (path, int(f["id"]), ", ".join(bad)))
            atoms[int(f["id"])] = f
        out.append(atoms)
    return out


def rel(a, b, scale):
    return abs(a - b) / scale


def run_case(a, exe, env, mpirun, wall, label, law, e_n, mu, speeds, outcome, newton, np_, big=False):
    tag = "%s_%s_%s_np%d%s%s" % (wall or "pair", label.replace(" ", "_"), newton, np_,
                                 "_drift" if a.drift and not wall else "", "_big" if big else "")
    d = os.path.join(a.workdir, tag)
    os.makedirs(d, exist_ok=True)
    pulled = outcome == "P"
    text, dt, steps, vs = deck(a.plugin, wall, law, e_n, mu, speeds, newton, np_, a.drift and not wall, pulled,
                               big)
    open(os.path.join(d, "in.deck"), "w").write(text)
    H.run(H.mpi_prefix(np_, mpirun) + [exe, "-in", "in.deck", "-log", "log.lammps"], d, env)
    fr = frames(os.path.join(d, "traj.dump"))
    if len(fr) != 2:
        raise SystemExit("FAIL: %s: %d dump frames, expected 2" % (tag, len(fr)))
    first, last = fr
    if a.drift and not wall and not all(first[i]["x"] < 0 < last[i]["x"] for i in first):
        raise SystemExit("FAIL: %s: the pairs did not drift through x = 0" % tag)
    # the reference: the same bodies from LAMMPS's own step-0 values (mass as LAMMPS computed it)
    lines, bodies = [], []
    ax = "z" if wall in ("zplane", "region") else "x"
    for k, s in enumerate(speeds):
        if wall:
            b = [first[k + 1]]
            lines.append("%s %s %.17g %.17g %.17g %.17g %.17g %.17g %d %.17g %.17g %.17g %.17g %.17g%s" % (
                "zcyl" if wall == "zcyl" else "wall", law, E, NU, W, e_n, mu, dt, steps,
                pull_load(R) if pulled else 0.0, b[0]["radius"], b[0]["mass"], b[0][ax], b[0]["v" + ax],
                " %.17g" % RCYL if wall == "zcyl" else ""))
        else:
            b = [first[2 * k + 1], first[2 * k + 2]]
            lines.append("pair %s %.17g %.17g %.17g %.17g %.17g %.17g %d %.17g %s %s" % (
                law, E, NU, W, e_n, mu, dt, steps, -pull_load(R / 2) if pulled else 0.0,
                " ".join("%.17g" % b[0][c] for c in ("radius", "mass", "x", "vx")),
                " ".join("%.17g" % b[1][c] for c in ("radius", "mass", "x", "vx"))))
        bodies.append(b)
    p = subprocess.run([a.ref], input="\n".join(lines) + "\n", stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       text=True)
    if p.returncode != 0:
        raise SystemExit("FAIL: %s: adhesion_ref: %s" % (tag, p.stderr.strip()))
    refs = [list(map(float, l.split())) for l in p.stdout.strip().splitlines()]
    ok = True
    _, _, _, _, r_eff = plan(wall, law, e_n, speeds)
    rch = reach(law, r_eff)
    if pulled and a.restart:
        # the same run interrupted at half way: write_restart, then a new process reads it and
        # runs to the end; the held neck must come back from the restart file (a lost one lets the
        # load pull the pair apart). Not bit-exact: the second run's setup evaluates the contact
        # with the velocities after the half step's kick (the damping force of a settled pair, ~0)
        half = steps // 2
        d2 = os.path.join(a.workdir, tag + "_restart")
        os.makedirs(d2, exist_ok=True)
        first_part = text[:text.rindex("run %d" % steps)] + "run %d\nwrite_restart r.bin\n" % half
        open(os.path.join(d2, "in.write"), "w").write(first_part)
        H.run(H.mpi_prefix(np_, mpirun) + [exe, "-in", "in.write", "-log", "log.write"], d2, env)
        # (regions are not in restart files: the wall's region is defined again before its fix)
        keep = [l for l in text.splitlines() if l.split()[:1] in (["plugin"], ["pair_style"], ["pair_coeff"],
                                                                    ["neighbor"], ["neigh_modify"],
                                                                    ["comm_modify"], ["timestep"], ["dump"],
                                                                    ["dump_modify"], ["thermo"])
                or l.startswith("fix ") or l.startswith("atom_modify sort") or l.startswith("region fl ")]
        second = ["processors %d 1 1" % np_ if np_ > 1 else "", "read_restart r.bin"] + keep + \
            ["run %d" % (steps - half)]
        open(os.path.join(d2, "in.read"), "w").write("\n".join(l for l in second if l) + "\n")
        out, _ = H.run(H.mpi_prefix(np_, mpirun) + [exe, "-in", "in.read", "-log", "log.read"], d2, env)
        fin = frames(os.path.join(d2, "traj.dump"))[-1]
        if wall:  # the sphere's gap to the plane z = 0
            gap_u, gap_r = last[1]["z"] - R, fin[1]["z"] - R
            d_x = rel(fin[1]["z"], last[1]["z"], R)
        else:
            gap_u = last[2]["x"] - last[1]["x"] - 2 * R
            gap_r = fin[2]["x"] - fin[1]["x"] - 2 * R
            d_x = H.worst_of(rel(fin[i]["x"], last[i]["x"], R) for i in (1, 2))
        good = 0.0 < gap_r < rch and d_x <= TOL_RESTART
        print("%s %-26s restart at step %d: gap %.6g m (uninterrupted %.6g), positions within %.2g R of the "
              "uninterrupted run (tolerance %g)" % ("ok  " if good else "FAIL", tag, half, gap_r, gap_u, d_x,
                                                     TOL_RESTART))
        if not good:
            return False
    if pulled:
        if wall:  # one sphere at rest on the wall: position and velocity against the reference
            x1, v1, _, _, state = refs[0]
            g = last[1]
            d_bits = H.worst_of(rel(g["z"], x1, R), rel(g["vz"], v1, max(abs(g["vz"]), 1e-300)))
            gap = g["z"] - R
        else:  # one pair, at rest relative to each other: positions and velocities against the reference
            x1, v1, x2, v2, state = refs[0]
            g = [last[1], last[2]]
            scale_v = max(abs(g[0]["vx"]), 1e-300)
            d_bits = H.worst_of(rel(g[0]["x"], x1, R), rel(g[1]["x"], x2, R), rel(g[0]["vx"], v1, scale_v),
                         rel(g[1]["vx"], v2, scale_v))
            gap = g[1]["x"] - g[0]["x"] - 2 * R
        msg = []
        if not d_bits <= TOL_BITS:
            msg.append("differs from the reference by %.3g (tolerance %g)" % (d_bits, TOL_BITS))
        if not (0.0 < gap < rch and state == 1.0):  # separated, within the neck's reach
            msg.append("not held by the neck at negative overlap (gap %.3g, |delta_c| %.3g, state %g)"
                       % (gap, rch, state))
        print("%s %-26s pulled by %.4g N: gap %.6g m (|delta_c| %.3g), ref state %g, |d| = %.2g%s" % (
            "ok  " if not msg else "FAIL", tag, pull_load(r_eff), gap, rch, state, d_bits,
            "" if not msg else ": " + "; ".join(msg)))
        return not msg
    for k, s in enumerate(speeds):
        v = s * vs
        x1, v1, x2, v2, state = refs[k]
        ids = [k + 1] if wall else [2 * k + 1, 2 * k + 2]
        g = [last[i] for i in ids]
        d_bits = H.worst_of(rel(g[0][ax], x1, R), rel(g[0]["v" + ax], v1, v))
        if not wall:
            d_bits = H.worst_of(d_bits, rel(g[1]["x"], x2, R), rel(g[1]["vx"], v2, v))
        # realised restitution (relative speed after over before) and the final surface gap
        if wall == "zcyl":  # moving along +x into the wall at Rc
            e_lmp, e_ref = -g[0]["vx"] / v, -v1 / v
            gap = RCYL - g[0]["x"] - R
        else:
            e_lmp = (g[0]["vz"] if wall else g[1]["vx"] - g[0]["vx"]) / v
            e_ref = (v1 if wall else v2 - v1) / v
            gap = g[0]["z"] - R if wall else g[1]["x"] - g[0]["x"] - 2 * R
        d_e = abs(e_lmp - e_ref) / max(abs(e_ref), 1e-300)
        stuck = gap <= rch and state != 0.0 if law == "jkr" else gap <= rch
        apart = gap > rch and e_lmp > 0
        msg = []
        if not (d_bits <= TOL_BITS and (d_e <= TOL_BITS or e_ref == e_lmp)):
            msg.append("differs from the reference by %.3g (e by %.3g; tolerance %g)" % (d_bits, d_e, TOL_BITS))
        expect = None
        want = outcome[k]
        if want == "S" and not stuck:
            msg.append("not stuck (gap %.3g, reach %.3g, state %g)" % (gap, rch, state))
        if want == "A" and not (apart and state <= 0.0):
            msg.append("not apart (gap %.3g, reach %.3g, e %.3g, state %g)" % (gap, rch, e_lmp, state))
        if e_n == 1.0 and want == "A":
            expect = math.sqrt(1.0 - 1.0 / s ** 2) if law == "jkr" else 1.0
            tol = TOL_E_JKR if law == "jkr" else TOL_E_DMT
            if not abs(e_lmp - expect) <= tol:
                msg.append("e = %.6g, expected %.6g (tolerance %g)" % (e_lmp, expect, tol))
        ok &= not msg
        print("%s %-26s v/v_s = %-5g e = %-20.17g ref %-20.17g %s |d| = %.2g%s%s" % (
            "ok  " if not msg else "FAIL", tag, s, e_lmp, e_ref,
            "stuck" if stuck else ("apart" if apart else "?"), d_bits,
            "" if expect is None else ", expected %.6g" % expect, "" if not msg else ": " + "; ".join(msg)))
    return ok


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--ref", required=True, help="adhesion_ref (tests/simulators/adhesion_ref.c)")
    ap.add_argument("--lmp")
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--newton", nargs="+", default=["on"], choices=["on", "off"])
    ap.add_argument("--drift", action="store_true",
                    help="the pairs also drift along x through x = 0 (with --np 2: the rank boundary)")
    ap.add_argument("--restart", action="store_true",
                    help="the pulled pair also through write_restart / read_restart at half way")
    ap.add_argument("--walls", action="store_true", help="also the sphere-wall impacts (both wall fixes)")
    ap.add_argument("--workdir")
    a = ap.parse_args()
    from harness import lammps as lammps_runs
    exe = lammps_runs.find_lmp(a.lmp)
    env = H.mpi_env()
    mpirun = os.path.join(os.path.dirname(exe), "mpirun")
    a.workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_adhesion_"))
    a.ref = os.path.abspath(a.ref)
    ok = True
    for label, law, e_n, mu, speeds, outcome in CASES:
        for newton in a.newton:
            ok &= run_case(a, exe, env, mpirun, None, label, law, e_n, mu, speeds, outcome, newton, a.np)
        if a.walls:
            # every case on both flat walls (the pulled sphere held by its neck, through a restart
            # with --restart); the JKR impacts also on the inside of the z cylinder
            walls = ("zplane", "region") + (("zcyl",) if law == "jkr" and outcome != "P" else ())
            for wall in walls:
                ok &= run_case(a, exe, env, mpirun, wall, label, law, e_n, mu, speeds, outcome, "on", a.np)
            # the impacts again with a larger bystander in the group: the wall fixes' reach bound
            # (the group's largest radius) is then the bystander's, and the impacts' bits must not
            # change (the library gives no force beyond an atom's own reach)
            for wall in ("zplane", "region") if outcome != "P" else ():
                ok &= run_case(a, exe, env, mpirun, wall, label, law, e_n, mu, speeds, outcome, "on", a.np,
                               big=True)
    print("ok" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
