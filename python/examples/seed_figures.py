"""The seeds' figures recomputed with demcontact (docs/report.md section 3): alpha(e), the
force-time history, delta_max(e), tau(zeta), the phase portrait and the viscoelastic e(b) tiers."""

import numpy as np

import demcontact as dc
from _common import plt, save

F, O = dc.Criterion.FORCE, dc.Criterion.OVERLAP
ps = (1.0, 1.5, 2.0, 3.0)
e = np.linspace(0.01, 1.0, 200)

fig, ax = plt.subplots(figsize=(6, 4.5))
for p in ps:
    ax.plot(e, dc.alpha_from_e(e, p, O), label=f"p = {p}, overlap end")
    ax.plot(e, dc.alpha_from_e(e, p, F), "--", label=f"p = {p}, force end")
ax.set(xlabel="e", ylabel="alpha", yscale="log", title="damping coefficient against restitution")
ax.legend(fontsize=7, ncol=2)
save(fig, "seed_alpha_vs_e.png")

fig, ax = plt.subplots(figsize=(6, 4.5))
for en in (0.9, 0.5, 0.1):
    a = dc.alpha_from_e(en, 1.5, O)
    tr = dc.contact_trajectory(1.5, a, 1.0, 1.0, 1.0, O, n=400)
    ax.plot(tr.t / tr.t[-1], tr.force / tr.force.max(), label=f"e = {en}")
ax.axhline(0, color="k", lw=0.5)
ax.set(xlabel="t / tau", ylabel="F / F_max", title="force history, Hertz (p = 3/2), overlap end")
ax.legend()
save(fig, "seed_force_history.png")

fig, ax = plt.subplots(figsize=(6, 4.5))
for p in ps:
    ax.plot(e, dc.max_overlap(p, dc.alpha_from_e(e, p, O), 1.0, 1.0) / dc.max_overlap(p, 0.0, 1.0, 1.0), label=f"p = {p}")
ax.set(xlabel="e (overlap end)", ylabel="delta_max / delta_max(e = 1)", title="maximum overlap")
ax.legend()
save(fig, "seed_dmax_vs_e.png")

zeta = np.linspace(0.0, 3.0, 301)
fig, ax = plt.subplots(figsize=(6, 4.5))
for p in ps:
    alpha = zeta * np.sqrt(2 * (p + 1))
    t0 = dc.contact_duration(p, 0.0, 1.0, 1.0, F)
    ax.plot(zeta, dc.contact_duration(p, alpha, 1.0, 1.0, F) / t0, label=f"p = {p}, force end")
    under = zeta < 0.95
    ax.plot(zeta[under], dc.contact_duration(p, alpha[under], 1.0, 1.0, O) / t0, ":", label=f"p = {p}, overlap end")
ax.set(xlabel="zeta", ylabel="tau / tau(0)", yscale="log", title="contact duration")
ax.legend(fontsize=7, ncol=2)
save(fig, "seed_tau_vs_zeta.png")

fig, ax = plt.subplots(figsize=(6, 4.5))
for en in (0.9, 0.6, 0.3, 0.1):
    tr = dc.contact_trajectory(1.5, dc.alpha_from_e(en, 1.5, O), 1.0, 1.0, 1.0, O, n=400)
    ax.plot(tr.delta, tr.v, label=f"e = {en}")
ax.set(xlabel="delta", ylabel="d delta / dt", title="phase portrait, Hertz (p = 3/2)")
ax.legend()
save(fig, "seed_phase_portrait.png")

b = np.logspace(-3, 2, 300)
fig, ax = plt.subplots(figsize=(6, 4.5))
for crit, name in ((O, "overlap end"), (F, "force end")):
    full = dc.viscoelastic_e(b, crit)
    ax.plot(b, full, label=f"full range, {name}")
    ax.plot(b, np.clip(dc.viscoelastic_e_series(b, crit), -0.5, 1.5), ":", label=f"published series, {name}")
    ref_b = np.logspace(-2, 1.5, 12)
    ax.plot(ref_b, dc.viscoelastic_e_reference(ref_b, crit), "o", mfc="none", label=f"reference integration, {name}")
ax.set(xscale="log", ylim=(-0.1, 1.1), xlabel="b = beta v^(1/5)", ylabel="e", title="viscoelastic spheres")
ax.legend(fontsize=7)
save(fig, "seed_viscoelastic_e.png")
