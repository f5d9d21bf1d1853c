/*
 * The one place where the simulator plugins (LIGGGHTS normal model, LAMMPS pair style) get the
 * normal contact force. Everything else in the plugins is glue to the host code.
 *
 *   F = k d^p + alpha sqrt(m k) d^((p-1)/2) vn,   vn > 0 while compressing,
 *
 * alpha from dc_alpha_from_e(e, p, criterion) with criterion DC_END_FORCE when the host clamps the
 * force at zero (`clamp`), DC_END_OVERLAP otherwise, so that the realised restitution is the target
 * in both cases.
 */
#ifndef DEMCONTACT_SIM_TSUJI_FORCE_H
#define DEMCONTACT_SIM_TSUJI_FORCE_H

#include <demcontact.h>
#include <cmath>

namespace demcontact_sim {

/* Calibrated parameters of one material pair: set up once, used for every contact. */
struct TsujiPair {
    double p = 1.5;       /* force-law exponent */
    double alpha = 0.0;   /* Tsuji damping coefficient realising the target e */
    bool clamp = false;   /* host clamps attractive forces: DC_END_FORCE calibration */
};

/* Calibrates alpha for target restitution e; returns a demcontact status (DC_OK on success). */
inline int32_t tsuji_setup(double e, double p, bool clamp, TsujiPair *out) {
    double alpha = 0.0;
    const int32_t s = dc_alpha_from_e(e, p, clamp ? DC_END_FORCE : DC_END_OVERLAP, &alpha);
    if (s == DC_OK) {
        out->p = p;
        out->alpha = alpha;
        out->clamp = clamp;
    }
    return s;
}

/* Normal force [N] (positive = repulsive) for overlap d >= 0, stiffness k, effective mass m. */
inline double tsuji_force(const TsujiPair &c, double k, double d, double vn, double m) {
    double dp, dh; /* d^p and d^((p-1)/2) */
    if (c.p == 1.5) { /* Hertz: avoid pow on the hot path */
        const double s = std::sqrt(d);
        dp = d * s;
        dh = std::sqrt(s);
    } else {
        dp = std::pow(d, c.p);
        dh = std::pow(d, 0.5 * (c.p - 1.0));
    }
    const double f = k * dp + c.alpha * std::sqrt(m * k) * dh * vn;
    return (c.clamp && f < 0.0) ? 0.0 : f;
}

} // namespace demcontact_sim

#endif
