"""Chung & Ooi (2011) test 4 through the full-contact model: a sphere (R = 2.5 mm, 3.9 m/s, no
spin) hits a rigid wall (E = inf) at incident angles 1..89 deg; Hertz with damping for
e_n = 0.98 (Criterion.FORCE), Mindlin tangential spring, Coulomb mu = 0.092.

All angles are integrated together: each is one contact of a contact_force_batch call per step
(velocity-Verlet, dt = tau_Hertz/4000, as the library's C test and report). The lines are the
repository's independent reference (c_tests/data/chung_ooi_ref.csv: adaptive Dormand-Prince with
stick/slip as events, rtol 1e-11). Writes chung_ooi_oblique.png and exits non-zero if the
tangential restitution or the rebound spin deviate from the reference by more than the stated
tolerance (|d e_t| <= 1e-4, |d omega| <= 1e-4 of its maximum; seen: 6e-6 and 3e-6).
"""

import csv
import math
import pathlib
import sys

import numpy as np

import demcontact as dc
from _common import plt, save

R, V, MU, EN = 0.0025, 3.9, 0.092, 0.98
MATERIALS = {"Al2O3": (3.8e11, 0.23, 4000.0), "Al alloy": (7.0e10, 0.33, 2700.0)}
REF = pathlib.Path(__file__).resolve().parents[2] / "c_tests" / "data" / "chung_ooi_ref.csv"


def impacts(E, nu, rho, theta_deg, steps=4000):
    """(e_t, omega [rad/s], rebound angle [deg], e_n) per incident angle, all in one batch."""
    model = dc.ContactSpec(
        normal=dc.Normal.HERTZ, damping=dc.Damping.RESTITUTION, e_n=EN, criterion=dc.Criterion.FORCE,
        E1=E, nu1=nu, E2=math.inf, nu2=nu, tangential=dc.Tangential.MINDLIN, mu=MU,
    ).model()
    n = theta_deg.size
    m = rho * 4.0 / 3.0 * math.pi * R**3
    inertia = 0.4 * m * R * R
    k = 4.0 / 3.0 * E / (1.0 - nu * nu) * math.sqrt(R)  # F = k d^1.5 on a rigid wall
    tau = 3.2145 * (m / k) ** 0.4 * V**-0.2  # elastic Hertz contact duration
    dt = tau / steps
    th = np.radians(theta_deg)
    vn, vt = V * np.cos(th), V * np.sin(th)
    z = R + 0.37 * vn * dt
    v = np.stack([vt, np.zeros(n), -vn], axis=1)
    w = np.zeros((n, 3))
    f, t = np.zeros((n, 3)), np.zeros((n, 3))
    normal = np.tile([0.0, 0.0, 1.0], (n, 1))
    zeros = np.zeros((n, 3))
    hist = np.zeros((n, model.history_len))
    touched = np.zeros(n, bool)
    done = np.zeros(n, bool)
    out = np.full((n, 4), np.nan)
    for _ in range(20 * steps):
        v += 0.5 * dt * f / m
        w += 0.5 * dt * t / inertia
        z = z + dt * v[:, 2]
        overlap = R - z
        r = dc.contact_force_batch(model, normal, overlap, v, zeros, w, zeros, R, math.inf, m, math.inf, dt, hist)
        f, t = r.force, r.torque1
        v += 0.5 * dt * f / m
        w += 0.5 * dt * t / inertia
        touched |= overlap > 0
        ended = touched & (overlap <= 0) & ~done
        if ended.any():
            i = ended
            out[i, 0] = v[i, 0] / vt[i]
            out[i, 1] = w[i, 1]
            out[i, 2] = np.degrees(np.arctan((v[i, 0] - R * w[i, 1]) / v[i, 2]))
            out[i, 3] = v[i, 2] / vn[i]
            done |= ended
        if done.all():
            return out
    raise RuntimeError("some impacts never separated")


def reference():
    rows = {}
    with open(REF) as fh:
        for row in csv.DictReader(line for line in fh if not line.startswith("#")):
            if row["case"] == "t4":
                rows.setdefault(row["material"], []).append(
                    (float(row["theta_deg"]), float(row["e_t"]), float(row["omega"]), float(row["rebound_deg"]))
                )
    return {k: np.array(v) for k, v in rows.items()}


ref = reference()
theta = np.arange(1.0, 90.0)
fig, axes = plt.subplots(1, 3, figsize=(14, 4.3))
worst_et = worst_w = 0.0
for (name, (E, nu, rho)), color in zip(MATERIALS.items(), ("tab:blue", "tab:red")):
    res = impacts(E, nu, rho, theta)
    assert np.all(np.abs(res[:, 3] - EN) < 2e-3), f"{name}: e_n {res[:, 3].min()}..{res[:, 3].max()}"
    rf = ref[name]
    for ax, col, rcol in zip(axes, (0, 1, 2), (1, 2, 3)):
        ax.plot(rf[:, 0], rf[:, rcol], "-", color=color, lw=1.2, label=f"reference, {name}")
        ax.plot(theta, res[:, col], "o", ms=3, mfc="none", color=color, label=f"contact_force_batch, {name}")
    at = np.searchsorted(theta, rf[:, 0])
    worst_et = max(worst_et, float(np.max(np.abs(res[at, 0] - rf[:, 1]))))
    worst_w = max(worst_w, float(np.max(np.abs(res[at, 1] - rf[:, 2])) / np.max(np.abs(rf[:, 2]))))
    print(f"{name}: max |e_t - ref| = {np.max(np.abs(res[at, 0] - rf[:, 1])):.2e}, "
          f"max |omega - ref| = {np.max(np.abs(res[at, 1] - rf[:, 2])):.3g} rad/s over {len(at)} reference angles")
axes[0].set(xlabel="incident angle [deg]", ylabel="e_t = u_out / u_in", title="tangential restitution")
axes[1].set(xlabel="incident angle [deg]", ylabel="omega [rad/s]", title="rebound angular velocity")
axes[2].set(xlabel="incident angle [deg]", ylabel="atan((u - R omega)/v_n) [deg]", title="rebound angle of the contact point")
for ax in axes:
    ax.grid(alpha=0.3)
axes[0].legend(fontsize=7)
fig.suptitle("Chung & Ooi (2011) test 4: oblique impacts on a rigid wall, demcontact full contact (Python batch)")
save(fig, "chung_ooi_oblique.png")
print(f"worst: |d e_t| = {worst_et:.2e} (tolerance 1e-4), |d omega|/max omega = {worst_w:.2e} (tolerance 1e-4)")
if not (worst_et <= 1e-4 and worst_w <= 1e-4):
    sys.exit("deviation from the reference above tolerance")
