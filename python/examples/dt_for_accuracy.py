"""The velocity-Verlet step demcontact.dt_for_accuracy returns for a tolerance on the realised
restitution, relative to the contact duration (docs/report.md, figures/dt_for_accuracy.png)."""

import numpy as np

import demcontact as dc
from _common import plt, save

tols = np.logspace(-3, -1, 5)
fig, ax = plt.subplots(figsize=(6, 4.5))
for crit, style in ((dc.Criterion.FORCE, "-o"), (dc.Criterion.OVERLAP, "--s")):
    for e, color in ((0.1, "tab:red"), (0.5, "tab:blue"), (0.9, "tab:green")):
        p, v0, w = 1.5, 1.0, 1.0
        tau = dc.contact_duration(p, dc.alpha_from_e(e, p, crit), v0, w, crit)
        dt = dc.dt_for_accuracy(p, e, crit, v0, w, tols)  # broadcasts over tol, GIL released
        ax.plot(tols, dt / tau, style, color=color, mfc="none", label=f"e = {e}, {crit.name.lower()} end")
ax.plot(tols, tols, "k:", lw=0.8, label="dt/tau = tol")
ax.set(xscale="log", yscale="log", xlabel="relative tolerance on e", ylabel="dt / tau", title="dt_for_accuracy, Hertz (p = 3/2)")
ax.legend(fontsize=7)
save(fig, "dt_for_accuracy.png")
