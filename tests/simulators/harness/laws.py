"""Law elastic_plastic head-on impacts, shared by the LIGGGHTS and LAMMPS checks (liggghts_laws.py,
lammps_laws.py): the material and speeds, the library's own contact (ctypes: dc_contact_force of
the state the plugins build, stepped in fix nve/sphere's velocity-Verlet order), Thornton's closed
form, and the comparisons of checks 1 (impacts at SPEEDS_OVER_VY times the yield speed, two
spheres and a sphere on a wall) and 3 (a second impact on the wall starts from fresh history).
Spec, State, Result: the C structs dc_contact_spec, dc_contact_state, dc_contact_result (also
used by liggghts_adhesion.py).

R = 1 mm, rho = 2500 kg/m^3, E = 1e7 Pa, nu = 0.3 (spheres and walls), yield pressure P_Y.
"""
import ctypes as C
import math

from .common import demcontact_lib

R, RHO, E, NU = 1e-3, 2500.0, 1e7, 0.3
P_Y = 2e5  # yield pressure [Pa]
SPEEDS_OVER_VY = (2.0, 5.0, 20.0, 100.0)
STEPS = 200  # time steps per elastic Hertz contact at the highest speed
SPACING = 4 * R
G = 9.81  # gravity of the second-impact run [m/s^2]
TOL_REF, TOL_CLOSED = 1e-12, 1e-4


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


def plan(geom, speeds, dt, steps=None):
    """[(v, gap)]: each impact's speed and initial surface gap (contact onset 2.5 steps in), and the
    steps to run (default: 3 contact durations of the slowest impact after the onset)"""
    cols = [(v, 2.5 * v * dt) for v in speeds]
    if steps is None:
        steps = int(math.ceil(max(2.5 + 3.0 * t_hertz(geom, v) / dt for v in speeds))) + 5
    return cols, steps


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
        self.lib = demcontact_lib(plugin)
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
        """The collision stepped as LIGGGHTS and LAMMPS step it (fix nve/sphere): two spheres (symmetric: one coordinate, the
        right sphere at x, moving at -v/2) or a sphere above the wall (z, moving at -v; gravity g
        along -z, added after the contact force as fix gravity does). reset: the history zeroed
        when the contact ends (both plugins: a new contact starts from zero), else kept."""
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
        f = -m * g  # the run's setup computes the forces of step 0 (gravity)
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


# ------------------------------------------------------------------ the comparisons
def compare(lib, run, name, check, geoms=("pair", "wall"), second=True):
    """Checks 1 (geometries geoms) and 3 (if second) with run(label, geom, cols, dt, steps, g) -> {v: e} (the host's realised
    e: pair: (v2 - v1)/v along x after the run; wall: v_z/v) for impacts cols = [(v, gap)]
    (plan()), g > 0: under gravity g along -z (fix gravity after the wall); check(ok, what)."""
    print("## law elastic_plastic (yield pressure %g Pa), E %g, nu %g, R %g, rho %g; dt = t_H(v_max)/%d"
          % (P_Y, E, NU, R, RHO, STEPS))
    print("%-5s %8s %10s %18s %18s %10s %10s %10s" % ("geom", "v/v_y", "v [m/s]", "e " + name, "e library",
                                                    "|diff|", "Thornton", "|diff|"))
    for geom in geoms:
        vy = lib.yield_speed(geom)
        speeds = [x * vy for x in SPEEDS_OVER_VY]
        dt = t_hertz(geom, max(speeds)) / STEPS
        cols, steps = plan(geom, speeds, dt)
        got = run("elastic_plastic", geom, cols, dt, steps, 0.0)
        for (v, gap), x in zip(cols, SPEEDS_OVER_VY):
            ref = lib.reference_e(geom, v, gap, dt, steps)
            th = lib.thornton(x)
            d_ref, d_th = abs(got[v] - ref), abs(got[v] - th)
            print("%-5s %8g %10.4g %18.15f %18.15f %10.3g %10.6f %10.3g" % (geom, x, v, got[v], ref, d_ref, th, d_th))
            check(d_ref <= TOL_REF, "%s v/v_y %g: %s vs library %.3g > %g" % (geom, x, name, d_ref, TOL_REF))
            check(d_th <= TOL_CLOSED, "%s v/v_y %g: vs Thornton %.3g > %g" % (geom, x, d_th, TOL_CLOSED))
            check(got[v] < 0.99, "%s v/v_y %g: e = %.6f, no plastic loss" % (geom, x, got[v]))

    if not second:
        return
    # a second impact of the same sphere on the same wall (gravity G brings it back): the contact's
    # history starts again from zero (the law's state is that of one contact; both plugins drop the
    # history of a contact when it ends); with the first impact's largest overlap kept, the
    # second, slower impact would stay on the unloading curve (no loss)
    vy = lib.yield_speed("wall")
    v = 20 * vy
    dt = t_hertz("wall", v) / STEPS
    e1 = lib.thornton(20)
    e2 = lib.thornton(20 * e1)
    t_end = 3 * t_hertz("wall", v) + 2 * e1 * v / G + 3 * t_hertz("wall", e1 * v) + 0.5 * e1 * e2 * v / G
    cols, steps = plan("wall", [v], dt, int(t_end / dt))
    got = run("second_impact", "wall", cols, dt, steps, G)
    ref = lib.reference_e("wall", v, cols[0][1], dt, steps, G, True)
    keep = lib.reference_e("wall", v, cols[0][1], dt, steps, G, False)
    print("## second impact on the wall (gravity %g m/s^2, v/v_y 20, %d steps): v_z/v at the end" % (G, steps))
    print("%s %.15f  library (history reset) %.15f  |diff| %.3g  library (history kept) %.15f"
          % (name, got[v], ref, abs(got[v] - ref), keep))
    check(abs(got[v] - ref) <= TOL_REF, "second impact: %s vs library %.3g > %g" % (name, abs(got[v] - ref), TOL_REF))
    check(abs(got[v] - keep) > 1e-3, "second impact: %s within 1e-3 of the kept-history reference" % name)
    check(got[v] > 0, "second impact: not rebounding at the end (v_z/v = %g)" % got[v])
