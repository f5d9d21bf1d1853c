/* Hand-written C loops of the same contact formulas as demcontact's full-contact batch: what a
 * host code would write. Compiled twice by CMake: -O3 (BASE = plain) and -O3 -fno-math-errno
 * (BASE = fast). Spheres only (no walls), clamped Hertz normal force with calibrated damping.
 *
 * normal_loop: per contact, vn = (v2 - v1).n, R* and m* from the radii and masses,
 *   F = max(kf q d + c sqrt(m* q) vn, 0), q = sqrt(R* d); force = F n.
 * hmc_loop: the same normal force plus the Hertz-Mindlin-Coulomb tangential history spring
 *   exactly as in src/contact (the spring carried into the current tangent plane by the
 *   rotation by the mean spin over dt, the minimal tilt from the spun stored normal and the
 *   projection, incremented by v_t dt, k_t = 8 G* sqrt(R* d), dashpot 2 zeta sqrt(m_t k_t), Coulomb cap mu F with LAMMPS's
 *   reset), torques -a_i n x F_t, history = (n, xi) per contact (6 doubles).                  */
#include <math.h>
#include <stddef.h>

#define CAT2(a, b) a##_##b
#define CAT(a, b) CAT2(a, b)

typedef struct {
    double kf, c, g8, zeta, mt, mu, dt;
} hmc_params;

void CAT(normal_loop, BASE)(size_t n, const hmc_params *p, const double *restrict nv,
                            const double *restrict ov, const double *restrict v1,
                            const double *restrict v2, const double *restrict r1,
                            const double *restrict r2, const double *restrict m1,
                            const double *restrict m2, double *restrict f_n,
                            double *restrict force) {
    const double kf = p->kf, c = p->c;
    for (size_t i = 0; i < n; i++) {
        const double *e = nv + 3 * i, *a = v1 + 3 * i, *b = v2 + 3 * i;
        double d = ov[i];
        double vn = (b[0] - a[0]) * e[0] + (b[1] - a[1]) * e[1] + (b[2] - a[2]) * e[2];
        double r = 1.0 / (1.0 / r1[i] + 1.0 / r2[i]);
        double m = 1.0 / (1.0 / m1[i] + 1.0 / m2[i]);
        double q = sqrt(r * d);
        double f = kf * q * d + c * sqrt(m * q) * vn;
        f = f > 0.0 ? f : 0.0;
        f = d > 0.0 ? f : 0.0;
        f_n[i] = f;
        force[3 * i] = d > 0.0 ? f * e[0] : 0.0;
        force[3 * i + 1] = d > 0.0 ? f * e[1] : 0.0;
        force[3 * i + 2] = d > 0.0 ? f * e[2] : 0.0;
    }
}

static inline void cross(const double *a, const double *b, double *o) {
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}
static inline double dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void CAT(hmc_loop, BASE)(size_t n, const hmc_params *p, const double *restrict nv,
                         const double *restrict ov, const double *restrict v1,
                         const double *restrict v2, const double *restrict w1,
                         const double *restrict w2, const double *restrict r1,
                         const double *restrict r2, const double *restrict m1,
                         const double *restrict m2, double *restrict hist, double *restrict f_n,
                         double *restrict force, double *restrict t1, double *restrict t2) {
    for (size_t i = 0; i < n; i++) {
        const double *e = nv + 3 * i;
        double *h = hist + 6 * i, *fo = force + 3 * i, *to1 = t1 + 3 * i, *to2 = t2 + 3 * i;
        double d = ov[i];
        if (!(d > 0.0)) {
            for (int k = 0; k < 6; k++) h[k] = 0.0;
            f_n[i] = 0.0;
            for (int k = 0; k < 3; k++) fo[k] = to1[k] = to2[k] = 0.0;
            continue;
        }
        double vr[3], arm[3], ax[3], vt[3];
        for (int k = 0; k < 3; k++) vr[k] = v1[3 * i + k] - v2[3 * i + k];
        double vn = -dot(vr, e);
        double r = 1.0 / (1.0 / r1[i] + 1.0 / r2[i]);
        double m = 1.0 / (1.0 / m1[i] + 1.0 / m2[i]);
        double q = sqrt(r * d);
        double f = p->kf * q * d + p->c * sqrt(m * q) * vn;
        f = f > 0.0 ? f : 0.0;
        double a1 = r1[i] - 0.5 * d, a2 = r2[i] - 0.5 * d;
        for (int k = 0; k < 3; k++) arm[k] = a1 * w1[3 * i + k] + a2 * w2[3 * i + k];
        cross(arm, e, ax);
        for (int k = 0; k < 3; k++) vt[k] = vr[k] - ax[k];
        double vcn = dot(vt, e);
        for (int k = 0; k < 3; k++) vt[k] -= vcn * e[k];
        /* carry the spring: rotate by the mean spin q = (w1 + w2) dt/2 (Rodrigues), tilt from the
         * spun stored normal to n, project */
        double xi[3] = {h[3], h[4], h[5]};
        double qv[3], q2, sq, cq;
        for (int k = 0; k < 3; k++) qv[k] = 0.5 * p->dt * (w1[3 * i + k] + w2[3 * i + k]);
        q2 = dot(qv, qv);
        if (q2 < 1e-3) {
            sq = 1.0 - q2 / 6.0 * (1.0 - q2 / 20.0 * (1.0 - q2 / 42.0));
            cq = 0.5 * (1.0 - q2 / 12.0 * (1.0 - q2 / 30.0 * (1.0 - q2 / 56.0)));
        } else {
            double th = sqrt(q2), hs = sin(0.5 * th);
            sq = sin(th) / th;
            cq = 2.0 * hs * hs / q2;
        }
        double sp[3], x1[3], x2[3];
        cross(qv, h, x1);
        cross(qv, x1, x2);
        for (int k = 0; k < 3; k++) sp[k] = h[k] + sq * x1[k] + cq * x2[k];
        double cth = dot(sp, e), kk[3];
        cross(sp, e, kk);
        if (cth > -0.5 && dot(h, h) > 0.25) {
            double kx[3];
            cross(qv, xi, x1);
            cross(qv, x1, x2);
            for (int k = 0; k < 3; k++) xi[k] += sq * x1[k] + cq * x2[k];
            cross(kk, xi, kx);
            double s = dot(kk, xi) / (1.0 + cth);
            for (int k = 0; k < 3; k++) xi[k] = cth * xi[k] + kx[k] + s * kk[k];
        }
        double xn = dot(xi, e);
        for (int k = 0; k < 3; k++) xi[k] -= xn * e[k];
        double kt = p->g8 * q;
        double ct = p->zeta > 0.0 ? 2.0 * p->zeta * sqrt(p->mt * m * kt) : 0.0;
        double ft[3];
        for (int k = 0; k < 3; k++) {
            xi[k] += p->dt * vt[k];
            ft[k] = -kt * xi[k] - ct * vt[k];
        }
        double lim = p->mu * fabs(f), t2n = dot(ft, ft);
        if (t2n > lim * lim) {
            double s = lim / sqrt(t2n);
            for (int k = 0; k < 3; k++) {
                ft[k] *= s;
                xi[k] = -(ft[k] + ct * vt[k]) / kt;
            }
        }
        double nft[3];
        cross(e, ft, nft);
        f_n[i] = f;
        for (int k = 0; k < 3; k++) {
            fo[k] = f * e[k] + ft[k];
            to1[k] = -a1 * nft[k];
            to2[k] = -a2 * nft[k];
            h[k] = e[k];
            h[3 + k] = xi[k];
        }
    }
}
