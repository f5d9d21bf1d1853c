import numpy as np
import demcontact as dc

# Damping for e = 0.5 in a Hertz contact (p = 1.5) of a solver that clamps attractive forces.
alpha = dc.alpha_from_e(0.5, 1.5, dc.Criterion.FORCE)
print("alpha =", alpha)

# Forces of many contacts at once: one pair model (glass on glass), numpy arrays in and out.
pair = dc.pair_hertz(63e9, 0.23, 63e9, 0.23, 0.5, dc.Criterion.FORCE)
overlap = np.array([1e-7, 1e-6, 1e-5])
vn = np.array([0.1, -0.1, 0.0])
force = dc.normal_force_batch(pair, overlap, vn, np.full(3, 5e-4), np.full(3, 2.6e-6))
print("force [N] =", force)
