#!/usr/bin/env python3
"""The registry's normal laws in LIGGGHTS (`model demcontact ... law KEYWORD`, parameters from
property/global named after their dc_contact_spec fields in camelCase), head-on collisions.

  liggghts_laws.py --plugin libdemcontact_liggghts.so [--workdir DIR] [--check] [--np 2]
                   [--example plugins/liggghts/examples/in.elastic_plastic]

R = 1 mm, rho = 2500 kg/m^3, E = 1e7 Pa, nu = 0.3 (spheres and walls); one LIGGGHTS run per
geometry (two equal spheres; a sphere and a zplane wall of the same material), every collision in
it far apart from the others, the realised e from LIGGGHTS' own dump of the final velocities.

1. law elastic_plastic (yieldPressure P_Y): impact speeds SPEEDS_OVER_VY times the yield speed
   v_y (dc_elastic_plastic_yield_speed), dt = t_H(v_max)/STEPS. Compared with the library's own
   contact stepped the same way (velocity Verlet as LIGGGHTS' nve/sphere: half kick, drift, force
   at the new position and half-step velocity, half kick; the state of dc_contact_force the
   plugin builds: r_eff, m_eff, the other body infinite and at rest; its history double kept
   from step to step, zeroed when the contact ends): |e_liggghts - e_ref| <= TOL_REF. And with
   Thornton's closed form (dc_elastic_plastic_restitution), which assumes the continuous contact:
   |e - e_thornton| <= TOL_CLOSED. e < 1 at all requires the residual state to be carried from step
   to step in LIGGGHTS' contact history (with it lost each step the contact is elastic: e = 1).
2. law hertz against the default law (model demcontact, no law: dc_pair's Tsuji Hertz) and
   law linear (kN = 4/3 E* R*, the pair's) against the default law at exponent 1
   (k = 4/3 E* R*^(2-1)), target e 0.5, one speed: |e_law - e_default| <= TOL_SAME (two code
   paths, dc_pair's kernel and the full contact's normal law, with the same force formula).

3. A second impact of the same sphere on the same wall (gravity brings it back after it left the
   wall): the contact history starts from zero again, as the library's reference with the history
   zeroed at separation (TOL_REF); the reference that keeps it differs by more than 1e-3.
4. --example DECK (plugins/liggghts/examples/in.elastic_plastic): its printed e within TOL_CLOSED
   of Thornton's closed form.

With --check: exit 1 unless every comparison holds. Exit 77 when LIGGGHTS is not installed.
"""
import argparse
import ctypes as C
import math
import os
import sys
import tempfile

import harness as H

R, RHO, E, NU = 1e-3, 2500.0, 1e7, 0.3
P_Y = 2e5  # yield pressure [Pa]
SPEEDS_OVER_VY = (2.0, 5.0, 20.0, 100.0)
STEPS = 200  # time steps per elastic Hertz contact at the highest speed
SPACING = 4 * R
NP = 1  # MPI ranks (--np)
G = 9.81  # gravity of the second-impact run [m/s^2]
MODEL = "model demcontact tangential history"
TOL_REF, TOL_CLOSED, TOL_SAME = 1e-12, 1e-4, 1e-12
E_TARGET, V_SAME = 0.5, 0.5


def mass():
    return RHO * 4.0 / 3.0 * math.pi * R ** 3


def geometry(geom):
    """(r_eff, m_eff)"""
    return (R / 2, mass() / 2) if geom == "pair" else (R, mass())


def e_star():
    return E / (2 * (1 - NU * NU))


def t_hertz(geom, v):
    r_eff, m_eff = geometry(geom)
    return 2.868265699 * (m_eff ** 2 / (r_eff * e_star() ** 2 * v)) ** 0.2


# ------------------------------------------------------------------ the library (ctypes)
class Spec(C.Structure):  # include/demcontact.h, dc_contact_spec
    _fields_ = ([("version", C.c_uint32), ("size", C.c_uint32)] +
                [(f, C.c_int32) for f in ["normal", "damping", "criterion", "tangential", "rolling", "twisting"]] +
                [(f, C.c_double) for f in ["E1", "nu1", "E2", "nu2", "p", "k_n", "e_n", "visco_A", "mu", "k_t",
                                           "e_t", "mu_r", "k_r", "eta_r", "mu_tw", "k_tw", "eta_tw",
                                           "inertia_factor", "work_of_adhesion", "yield_pressure"]])


V3 = C.c_double * 3


class State(C.Structure):
    _fields_ = [("n", V3), ("overlap", C.c_double), ("v1", V3), ("v2", V3), ("w1", V3), ("w2", V3),
                ("r1", C.c_double), ("r2", C.c_double), ("m1", C.c_double), ("m2", C.c_double)]


class Result(C.Structure):
    _fields_ = [("force", V3), ("torque1", V3), ("torque2", V3), ("f_n", C.c_double), ("ft", V3),
                ("sliding", C.c_int32), ("rolling_sliding", C.c_int32)]


DC_NORMAL_ELASTIC_PLASTIC, DC_DAMPING_NONE, DC_END_OVERLAP = 6, 0, 0


class Library:
    def __init__(self, plugin):
        self.lib = H.demcontact_lib(plugin)
        L = self.lib
        L.dc_contact_spec_init.argtypes = [C.POINTER(Spec)]
        L.dc_contact_spec_init.restype = C.c_int32
        s = Spec()
        assert L.dc_contact_spec_init(C.byref(s)) == 0
        assert s.size == C.sizeof(Spec), "dc_contact_spec layout changed: %d != %d" % (s.size, C.sizeof(Spec))
        self.model = (C.c_char * 4096)()  # dc_contact_model: opaque here, large enough
        s.normal, s.damping, s.criterion = DC_NORMAL_ELASTIC_PLASTIC, DC_DAMPING_NONE, DC_END_OVERLAP
        s.E1 = s.E2 = E
        s.nu1 = s.nu2 = NU
        s.yield_pressure = P_Y
        L.dc_contact_model_init.argtypes = [C.POINTER(Spec), C.c_void_p]
        L.dc_contact_model_init.restype = C.c_int32
        assert L.dc_contact_model_init(C.byref(s), self.model) == 0
        L.dc_contact_force.argtypes = [C.c_void_p, C.POINTER(State), C.c_double, C.POINTER(C.c_double),
                                       C.c_size_t, C.POINTER(Result)]
        L.dc_contact_force.restype = C.c_int32
        for f, n in (("dc_elastic_plastic_yield_speed", 5), ("dc_elastic_plastic_restitution", 2)):
            getattr(L, f).argtypes = [C.c_double] * (n - 1) + [C.POINTER(C.c_double)]
            getattr(L, f).restype = C.c_int32

    def yield_speed(self, geom):
        r_eff, m_eff = geometry(geom)
        out = C.c_double()
        assert self.lib.dc_elastic_plastic_yield_speed(e_star(), r_eff, m_eff, P_Y, C.byref(out)) == 0
        return out.value

    def thornton(self, x):
        out = C.c_double()
        assert self.lib.dc_elastic_plastic_restitution(x, C.byref(out)) == 0
        return out.value

    def normal_force(self, d, vn, r_eff, m_eff, dt, hist):
        """f_n of the plugin's state (normal +z, body 2 infinite, moving at vn toward body 1)."""
        inf = float("inf")
        s = State(V3(0, 0, 1), d, V3(0, 0, 0), V3(0, 0, vn), V3(0, 0, 0), V3(0, 0, 0), r_eff, inf, m_eff, inf)
        r = Result()
        st = self.lib.dc_contact_force(self.model, C.byref(s), dt, hist, 1, C.byref(r))
        assert st == 0, "dc_contact_force: status %d" % st
        return r.f_n

    def reference_e(self, geom, v, gap, dt, steps, g=0.0, reset=True):
        """The collision stepped as LIGGGHTS steps it: two spheres (symmetric: one coordinate, the
        right sphere at x, moving at -v/2) or a sphere above the wall (z, moving at -v; gravity g
        along -z, added after the contact force as fix gravity does). reset: the history zeroed
        when the contact ends (LIGGGHTS: a new contact starts from zero), else kept."""
        r_eff, m_eff = geometry(geom)
        m = mass()
        hist = (C.c_double * 1)(0.0)
        if geom == "pair":
            x, u = R + gap / 2, -v / 2  # right sphere
            f = 0.0
            for _ in range(steps):
                u += 0.5 * dt * f / m
                x += dt * u
                d = 2 * R - 2 * x
                if d > 0:
                    f = self.normal_force(d, -(2 * u), r_eff, m_eff, dt, hist)  # on the right sphere, +x
                else:
                    f, hist[0] = 0.0, 0.0
                u += 0.5 * dt * f / m
            return 2 * u / v
        z, u = R + gap, -v
        f = -m * g  # LIGGGHTS' setup computes the forces of step 0 (gravity)
        for _ in range(steps):
            u += 0.5 * dt * f / m
            z += dt * u
            d = R - z
            if d > 0:
                f = self.normal_force(d, -u, r_eff, m_eff, dt, hist)
            else:
                f = 0.0
                if reset:
                    hist[0] = 0.0
            f += m * -g
            u += 0.5 * dt * f / m
        return u / v


# ------------------------------------------------------------------ LIGGGHTS
def deck(geom, cols, dt, steps, model, settings, props, extra=()):
    """cols: [(atom ids, y, v, gap)]"""
    L = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
         "communicate single vel yes", "units si"] + (["processors 2 1 1"] if NP == 2 else []) + [
         "region box block -0.01 0.01 -0.01 %.17g -0.002 0.01 units box" % (cols[-1][1] + 0.01),
         "create_box 1 box", "neighbor 0.0002 bin", "neigh_modify delay 0",
         "fix m1 all property/global youngsModulus peratomtype %.17g" % E,
         "fix m2 all property/global poissonsRatio peratomtype %.17g" % NU,
         "fix m3 all property/global coefficientRestitution peratomtypepair 1 %.17g" % E_TARGET,
         "fix m4 all property/global coefficientFriction peratomtypepair 1 0.5"] + props + [
         ("pair_style gran %s %s" % (model, settings)).strip(), "pair_coeff * *", "timestep %.17g" % dt]
    for ids, y, v, gap in cols:
        if geom == "pair":
            x = R + gap / 2
            L += ["create_atoms 1 single %.17g %.17g 0 units box" % (-x, y),
                  "create_atoms 1 single %.17g %.17g 0 units box" % (x, y),
                  "set atom %d diameter %.17g density %.17g vx %.17g" % (ids[0], 2 * R, RHO, v / 2),
                  "set atom %d diameter %.17g density %.17g vx %.17g" % (ids[1], 2 * R, RHO, -v / 2)]
        else:
            L += ["create_atoms 1 single 0 %.17g %.17g units box" % (y, R + gap),
                  "set atom %d diameter %.17g density %.17g vz %.17g" % (ids[0], 2 * R, RHO, -v)]
    if geom == "wall":
        # a wall takes its model settings after the wall
        L.append(("fix w all wall/gran %s primitive type 1 zplane 0.0 %s" % (model, settings)).strip())
    L += list(extra) + ["fix integr all nve/sphere", "thermo 1000", "run %d" % steps,
          "dump fin all custom 1 final.dump id type vx vy vz",
          "dump_modify fin format \"%d %d %.17g %.17g %.17g\"", "run 0"]
    return "\n".join(L) + "\n"


def run_collisions(plugin, workdir, label, geom, speeds, dt, settings, props, steps=None, extra=()):
    """{v: realised e}, and the steps run"""
    exe, env = H.liggghts_cmd(plugin)
    cols, atom, y = [], 1, 0.0
    for v in speeds:
        ids = (atom, atom + 1) if geom == "pair" else (atom,)
        cols.append((ids, y, v, 2.5 * v * dt))  # contact onset 2.5 steps in
        atom += len(ids)
        y += SPACING
    if steps is None:
        steps = int(math.ceil(max(2.5 + 3.0 * t_hertz(geom, v) / dt for v in speeds))) + 5
    d = os.path.join(workdir, "%s_%s" % (label, geom))
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, "in.laws"), "w").write(deck(geom, cols, dt, steps, MODEL, settings, props, extra))
    H.run(H.mpi_prefix(NP) + [exe, "-in", "in.laws", "-log", "log.liggghts"], d, env)
    final = H.read_last_dump(os.path.join(d, "final.dump"))
    out = {}
    for ids, y, v, gap in cols:
        if geom == "pair":
            out[v] = (float(final[ids[1]]["vx"]) - float(final[ids[0]]["vx"])) / v
        else:
            out[v] = float(final[ids[0]]["vz"]) / v
    return out, cols, steps


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--workdir")
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--np", type=int, default=1, choices=(1, 2),
                    help="2: mpirun -np 2, processors 2 1 1 (the pairs straddle the rank boundary)")
    ap.add_argument("--example", help="plugins/liggghts/examples/in.elastic_plastic: run it, its printed e "
                                      "within TOL_CLOSED of Thornton's at its 0.2 m/s")
    a = ap.parse_args()
    global NP
    NP = a.np
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_laws_"))
    os.makedirs(workdir, exist_ok=True)
    lib = Library(a.plugin)
    bad = []

    def check(ok, what):
        if not ok:
            bad.append(what)

    print("## law elastic_plastic (yieldPressure %g Pa), E %g, nu %g, R %g, rho %g; dt = t_H(v_max)/%d"
          % (P_Y, E, NU, R, RHO, STEPS))
    print("%-5s %8s %10s %18s %18s %10s %10s %10s" % ("geom", "v/v_y", "v [m/s]", "e LIGGGHTS", "e library",
                                                    "|diff|", "Thornton", "|diff|"))
    ep = "law elastic_plastic"
    prop = ["fix m6 all property/global yieldPressure peratomtypepair 1 %.17g" % P_Y]
    for geom in ("pair", "wall"):
        vy = lib.yield_speed(geom)
        speeds = [x * vy for x in SPEEDS_OVER_VY]
        dt = t_hertz(geom, max(speeds)) / STEPS
        got, cols, steps = run_collisions(a.plugin, workdir, "elastic_plastic", geom, speeds, dt, ep, prop)
        for (ids, y, v, gap), x in zip(cols, SPEEDS_OVER_VY):
            ref = lib.reference_e(geom, v, gap, dt, steps)
            th = lib.thornton(x)
            d_ref, d_th = abs(got[v] - ref), abs(got[v] - th)
            print("%-5s %8g %10.4g %18.15f %18.15f %10.3g %10.6f %10.3g" % (geom, x, v, got[v], ref, d_ref, th, d_th))
            check(d_ref <= TOL_REF, "%s v/v_y %g: LIGGGHTS vs library %.3g > %g" % (geom, x, d_ref, TOL_REF))
            check(d_th <= TOL_CLOSED, "%s v/v_y %g: vs Thornton %.3g > %g" % (geom, x, d_th, TOL_CLOSED))
            check(got[v] < 0.99, "%s v/v_y %g: e = %.6f, no plastic loss" % (geom, x, got[v]))

    # a second impact of the same sphere on the same wall (gravity G brings it back): the contact's
    # history starts again from zero (the law's state is that of one contact; LIGGGHTS drops the
    # history of a pair when it separates); with the first impact's largest overlap kept, the
    # second, slower impact would stay on the unloading curve (no loss)
    vy = lib.yield_speed("wall")
    v = 20 * vy
    dt = t_hertz("wall", v) / STEPS
    e1 = lib.thornton(20)
    e2 = lib.thornton(20 * e1)
    t_end = 3 * t_hertz("wall", v) + 2 * e1 * v / G + 3 * t_hertz("wall", e1 * v) + 0.5 * e1 * e2 * v / G
    steps = int(t_end / dt)
    got, cols, _ = run_collisions(a.plugin, workdir, "second_impact", "wall", [v], dt, ep, prop, steps,
                                  ["fix gravi all gravity %.17g vector 0 0 -1" % G])
    ref = lib.reference_e("wall", v, cols[0][3], dt, steps, G, True)
    keep = lib.reference_e("wall", v, cols[0][3], dt, steps, G, False)
    print("## second impact on the wall (gravity %g m/s^2, v/v_y 20, %d steps): v_z/v at the end" % (G, steps))
    print("LIGGGHTS %.15f  library (history reset) %.15f  |diff| %.3g  library (history kept) %.15f"
          % (got[v], ref, abs(got[v] - ref), keep))
    check(abs(got[v] - ref) <= TOL_REF, "second impact: LIGGGHTS vs library %.3g > %g" % (abs(got[v] - ref), TOL_REF))
    check(abs(got[v] - keep) > 1e-3, "second impact: the kept-history reference is not distinguishable")
    check(got[v] > 0, "second impact: not rebounding at the end (v_z/v = %g)" % got[v])

    print("## law hertz / law linear against the default law (e %g at %g m/s)" % (E_TARGET, V_SAME))
    print("%-5s %-8s %18s %18s %10s" % ("geom", "law", "e law", "e default", "|diff|"))
    for geom in ("pair", "wall"):
        r_eff, _ = geometry(geom)
        dt = t_hertz(geom, V_SAME) / STEPS
        for law, default, props in (
                ("hertz", "", []),
                ("linear", "exponent 1", ["fix m6 all property/global kN scalar %.17g" % (4.0 / 3.0 * e_star() * r_eff)])):
            e_law, _, _ = run_collisions(a.plugin, workdir, law, geom, [V_SAME], dt,
                                         "law " + law, props)
            e_def, _, _ = run_collisions(a.plugin, workdir, law + "_default", geom, [V_SAME], dt,
                                         default, [])
            diff = abs(e_law[V_SAME] - e_def[V_SAME])
            print("%-5s %-8s %18.15f %18.15f %10.3g" % (geom, law, e_law[V_SAME], e_def[V_SAME], diff))
            check(diff <= TOL_SAME, "%s law %s vs default: %.3g > %g" % (geom, law, diff, TOL_SAME))
    if a.example:
        # the documented example deck as a user runs it: two spheres of the "pair" geometry at 0.2 m/s
        exe, env = H.liggghts_cmd(a.plugin)
        d = os.path.join(workdir, "example")
        os.makedirs(d, exist_ok=True)
        out, _ = H.run([exe, "-in", os.path.abspath(a.example), "-log", "log.liggghts"], d, env)
        e = [float(l.split("=")[1]) for l in out.splitlines() if l.startswith("realised e = ")]
        th = lib.thornton(0.2 / lib.yield_speed("pair"))
        print("## example %s: realised e %s, Thornton %.6f" % (os.path.basename(a.example), e, th))
        check(len(e) == 1 and abs(e[0] - th) <= TOL_CLOSED, "example: e %s vs Thornton %.6f" % (e, th))

    print("tolerances: library %g, Thornton %g, default law %g" % (TOL_REF, TOL_CLOSED, TOL_SAME))
    if bad:
        print("FAIL:\n  " + "\n  ".join(bad))
        if a.check:
            sys.exit(1)
    else:
        print("all comparisons within tolerance")


if __name__ == "__main__":
    main()
