"""Realised e against target e in a solver that clamps attractive forces (docs/report.md,
figures/clamping_realised_e.png): alpha from the overlap-zero formula (what most codes use)
against demcontact's force-zero calibration. Lines: closed forms; markers: velocity-Verlet
collisions through demcontact's clamped force kernel (dt = tau/2000), integrated here with numpy
over all targets at once.
"""

import numpy as np

import demcontact as dc
from _common import plt, save

F, O = dc.Criterion.FORCE, dc.Criterion.OVERLAP
targets = np.linspace(0.05, 1.0, 96)
fig, ax = plt.subplots(figsize=(6, 5))
for p, style in ((1.0, "-"), (1.5, "--"), (2.5, ":")):
    wrong = dc.e_from_alpha(dc.alpha_from_e(targets, p, O), p, F)  # overlap alpha, clamped solver
    ax.plot(targets, wrong, style, color="tab:red", label=f"overlap-zero alpha, p = {p}")
ax.plot(targets, targets, color="tab:green", lw=2, label="demcontact (force-zero alpha), every p")


def simulate(pairs, v0=1.0, mass=1.0, steps_per_tau=2000):
    """Velocity-Verlet (LAMMPS order) of one collision per pair; returns exit speed / v0."""
    k = pairs[0].stiffness
    tau = dc.contact_duration(np.array([pp.p for pp in pairs]), np.array([pp.alpha for pp in pairs]), v0, np.sqrt(k / mass), F)
    dt = tau / steps_per_tau
    n = len(pairs)
    x, v = np.zeros(n), np.full(n, v0)  # x = overlap, v = its rate
    a = np.zeros(n)
    done, e = np.zeros(n, bool), np.zeros(n)
    for _ in range(4 * steps_per_tau):
        x = x + v * dt + 0.5 * a * dt * dt
        vh = v + 0.5 * a * dt
        f = np.array([dc.normal_force(pp, xi, vi, None, mass) for pp, xi, vi in zip(pairs, x, vh)])
        a = -f / mass
        v = vh + 0.5 * a * dt
        left = (~done) & (x < 0)
        e[left], done[left] = -v[left] / v0, True
        if done.all():
            return e
    raise RuntimeError("collision did not end")


sim_targets = np.array([0.1, 0.3, 0.5, 0.7, 0.9])
for crit, color, label in ((O, "tab:red", "simulated, overlap alpha (p = 1.5)"), (F, "tab:green", "simulated, demcontact (p = 1.5)")):
    # a clamped pair whose alpha is the one the criterion's formula gives
    pairs = [dc.pair_powerlaw_alpha(1.5, 1e4, dc.alpha_from_e(e, 1.5, crit), F) for e in sim_targets]
    ax.plot(sim_targets, simulate(pairs), "o", color=color, mfc="none", label=label)
ax.set_xlabel("target e")
ax.set_ylabel("realised e (force clamped)")
ax.set_title("Calibration in a clamping solver")
ax.legend(fontsize=8)
save(fig, "clamping_realised_e.png")
