/* gpu_check: demcontact_inline.h on a GPU against the library, bit for bit, and its throughput.
 *
 * Built by scripts/gpu_check.sh with nvcc (device code from the header, -fmad=false), linked
 * against libdemcontact (the reference: dc_contact_force, dc_normal_force on the host CPU):
 *  1. normal forces: dc_normal_force_inline over structure-of-arrays contacts on the device
 *     against dc_normal_force, every kernel code (1..19), overlaps through contact, the DMT tail
 *     and separation;
 *  2. contact batch: dc_contact_force_inline over random valid contacts (random history: a
 *     contact already under way, or a new one) against dc_contact_force, for every model shape:
 *     19 kernel codes x 3 tangential x 4 rolling (none, constant, EPSD with k_r, EPSD by Ai's
 *     rule) x 2 twisting x 2 frame carries = 912 shapes;
 *  3. trajectories: each device thread carries one contact's history over many steps (the normal
 *     turning, overlap through contact and separation, velocities and spins random-walking), the
 *     library carrying its own on the host: every step's status, result and history bits;
 *  4. throughput of a Hertz-Mindlin batch (Hertz damped, force-clamped; Mindlin; projection
 *     carry) in contacts/s: the generic entry (dc_contact_force_inline, model read at run time),
 *     the shaped entry (dc_contact_force_shaped_inline, the shape as constants) and a
 *     hand-written CUDA loop of the same formula, each against its memory roofline: the
 *     device-to-device copy bandwidth measured in the same run (cudaMemcpy) divided by the bytes
 *     the kernel must move per contact (counted below, kernel by kernel). The timed kernels'
 *     first results are checked too (entries: bits; hand-written: same formula, relative 1e-9).
 *  5. the step-exact option: trajectories as in 3, each with its own model made step-aware by
 *     the library's dc_contact_model_set_step for that trajectory's dt (velocity Verlet and
 *     symplectic Euler alternately), every shape whose normal law the option takes (the damped
 *     Tsuji laws), the approach speed the drift that made each overlap (so that each contact's
 *     first step is an onset): every step's bits, and the steps the option changes (the library
 *     runs the plain model alongside).
 * Exit status: 0 all identical, 1 any bit difference or a regime not reached, 2 bad arguments,
 * 3 a CUDA or set-up error. Prints one table.
 *
 * The same file compiled by a host C++ compiler (no __CUDACC__) is the CPU smoke: the "device"
 * is a loop on the CPU over the same arrays (the same functors), so the generators, the
 * reference path, the comparisons and the table run without a GPU (ctest gpu_check_cpu_smoke,
 * --cpu-smoke). --plant-ulp adds one ulp to one value in each checked stage on the "device"
 * side: the run must then fail (ctest gpu_check_cpu_smoke_plant). */
#include <demcontact_inline.h>

#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#define TEST_RANDOM_SEED 0x6A09E667F3BCC909ull
#include "../../c_tests/inline/test_random.h"

#if defined(__CUDACC__)
#include <cuda_runtime.h>
#define GC_HD __host__ __device__
#define GC_DEV __device__
#define GC_MODE "CUDA"
#else
#define GC_HD
#define GC_DEV
#define GC_MODE "CPU stand-in"
#endif

enum { EXIT_DIFF = 1, EXIT_USAGE = 2, EXIT_SETUP = 3 };

static void die(const char *what) {
    fprintf(stderr, "gpu_check: %s\n", what);
    exit(EXIT_SETUP);
}

/* ---------------------------------------------------------------- device memory and launches */

#if defined(__CUDACC__)
static void cuda_ok(cudaError_t e, const char *what) {
    if (e != cudaSuccess) {
        fprintf(stderr, "gpu_check: CUDA error in %s: %s\n", what, cudaGetErrorString(e));
        exit(EXIT_SETUP);
    }
}
template <class T> static T *dev_alloc(size_t n) {
    void *p = nullptr;
    cuda_ok(cudaMalloc(&p, n * sizeof(T) + 8), "cudaMalloc");
    return static_cast<T *>(p);
}
template <class T> static void dev_free(T *p) { cuda_ok(cudaFree(p), "cudaFree"); }
template <class T> static void to_dev(T *d, const T *h, size_t n) {
    cuda_ok(cudaMemcpy(d, h, n * sizeof(T), cudaMemcpyHostToDevice), "copy to device");
}
template <class T> static void to_host(T *h, const T *d, size_t n) {
    cuda_ok(cudaMemcpy(h, d, n * sizeof(T), cudaMemcpyDeviceToHost), "copy to host");
}
/* one thread per index, grid-stride */
template <class F> __global__ void gc_each(size_t n, F f) {
    for (size_t i = blockIdx.x * (size_t)blockDim.x + threadIdx.x; i < n;
         i += (size_t)gridDim.x * blockDim.x)
        f(i);
}
template <class F> static void launch(size_t n, const F &f) {
    if (n == 0) return;
    const int block = 128;
    size_t grid = (n + block - 1) / block;
    if (grid > 65535u * 16u) grid = 65535u * 16u;
    gc_each<<<(unsigned)grid, block>>>(n, f);
    cuda_ok(cudaGetLastError(), "kernel launch");
}
static void dev_sync() { cuda_ok(cudaDeviceSynchronize(), "kernel run"); }
__device__ static void gc_first_bad(unsigned long long *first, size_t i) {
    atomicMin(first, (unsigned long long)i);
}
/* the best time of op() over `reps` runs after a warm-up, by CUDA events: seconds */
template <class Op> static double best_seconds(const Op &op, int reps) {
    cudaEvent_t a, b;
    cuda_ok(cudaEventCreate(&a), "event");
    cuda_ok(cudaEventCreate(&b), "event");
    float best = 1e30f;
    for (int r = 0; r < reps + 1; r++) {
        cuda_ok(cudaEventRecord(a), "event");
        op();
        cuda_ok(cudaEventRecord(b), "event");
        cuda_ok(cudaEventSynchronize(b), "event");
        float ms = 0;
        cuda_ok(cudaEventElapsedTime(&ms, a, b), "event");
        if (r > 0 && ms < best) best = ms; /* the first is the warm-up */
    }
    cudaEvent_t ev[2] = {a, b};
    for (cudaEvent_t e : ev) cuda_ok(cudaEventDestroy(e), "event");
    return best * 1e-3;
}
static void copy_bytes(char *dst, const char *src, size_t bytes) {
    cuda_ok(cudaMemcpy(dst, src, bytes, cudaMemcpyDeviceToDevice), "device copy");
}
static void device_name(char *out, size_t len) {
    cudaDeviceProp p;
    cuda_ok(cudaGetDeviceProperties(&p, 0), "cudaGetDeviceProperties");
    snprintf(out, len, "%s, sm_%d%d, %d SMs", p.name, p.major, p.minor, p.multiProcessorCount);
}
#else
/* The CPU stand-in: "device" buffers are host buffers, a launch is a loop. */
template <class T> static T *dev_alloc(size_t n) {
    T *p = static_cast<T *>(malloc(n * sizeof(T) + 8));
    if (!p) die("out of memory");
    return p;
}
template <class T> static void dev_free(T *p) { free(p); }
template <class T> static void to_dev(T *d, const T *h, size_t n) { memcpy(d, h, n * sizeof(T)); }
template <class T> static void to_host(T *h, const T *d, size_t n) { memcpy(h, d, n * sizeof(T)); }
template <class F> static void launch(size_t n, const F &f) {
    for (size_t i = 0; i < n; i++) f(i);
}
static void dev_sync() {}
static void gc_first_bad(unsigned long long *first, size_t i) {
    if (i < *first) *first = i;
}
static double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
template <class Op> static double best_seconds(const Op &op, int reps) {
    double best = 1e30;
    for (int r = 0; r < reps; r++) {
        const double t0 = now();
        op();
        const double t = now() - t0;
        best = t < best ? t : best;
    }
    return best;
}
static void copy_bytes(char *dst, const char *src, size_t bytes) { memcpy(dst, src, bytes); }
static void device_name(char *out, size_t len) { snprintf(out, len, "host CPU (no GPU: smoke only)"); }
#endif

/* device-to-device copy of `bytes`, and n launches of f: the best of `reps`, seconds */
static double copy_seconds(char *dst, const char *src, size_t bytes, int reps) {
    return best_seconds([&] { copy_bytes(dst, src, bytes); }, reps);
}
template <class F> static double kernel_seconds(size_t n, const F &f, int reps) {
    return best_seconds([&] { launch(n, f); }, reps);
}

/* ---------------------------------------------------------------- contact data, structure of arrays */

/* Field f of contact j lives at in[f * N + j]; vectors are 3 fields (x, y, z). */
enum {
    F_N = 0, F_OV = 3, F_V1 = 4, F_V2 = 7, F_W1 = 10, F_W2 = 13, F_R1 = 16, F_R2 = 17, F_M1 = 18,
    F_M2 = 19, F_DT = 20, NF = 21
};
/* Results: 13 doubles (R_*) and 3 ints (status, sliding, rolling_sliding) per contact. */
enum { R_FORCE = 0, R_T1 = 3, R_T2 = 6, R_FN = 9, R_FT = 10, NR = 13 };
enum { I_STATUS = 0, I_SLIDING = 1, I_ROLLING = 2, NI = 3 };
enum { NH = DC_CONTACT_HISTORY_MAX };

GC_HD static inline void load_state(const double *in, size_t N, size_t j, dc_contact_state *s) {
    for (int a = 0; a < 3; a++) {
        s->n[a] = in[(F_N + a) * N + j];
        s->v1[a] = in[(F_V1 + a) * N + j];
        s->v2[a] = in[(F_V2 + a) * N + j];
        s->w1[a] = in[(F_W1 + a) * N + j];
        s->w2[a] = in[(F_W2 + a) * N + j];
    }
    s->overlap = in[F_OV * N + j];
    s->r1 = in[F_R1 * N + j];
    s->r2 = in[F_R2 * N + j];
    s->m1 = in[F_M1 * N + j];
    s->m2 = in[F_M2 * N + j];
}
/* a result the entries leave untouched on error: recognisable bits */
GC_HD static inline void sentinel(dc_contact_result *r) {
    memset(r, 0x5A, sizeof *r);
}
GC_HD static inline void store_result(double *res, int32_t *ires, size_t N, size_t j,
                                      const dc_contact_result *r, int32_t st) {
    for (int a = 0; a < 3; a++) {
        res[(R_FORCE + a) * N + j] = r->force[a];
        res[(R_T1 + a) * N + j] = r->torque1[a];
        res[(R_T2 + a) * N + j] = r->torque2[a];
        res[(R_FT + a) * N + j] = r->ft[a];
    }
    res[R_FN * N + j] = r->f_n;
    ires[I_STATUS * N + j] = st;
    ires[I_SLIDING * N + j] = r->sliding;
    ires[I_ROLLING * N + j] = r->rolling_sliding;
}
/* one ulp more (the planted difference of --plant-ulp) */
GC_HD static inline double ulp_up(double x) {
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    u++;
    memcpy(&x, &u, sizeof x);
    return x;
}

/* 1. normal forces: overlap, vn (field F_V1), r_eff (F_R1), m_eff (F_M1), the pair of model mi[j] */
struct NormalEach {
    const dc_contact_model *models;
    const int32_t *mi;
    const double *in;
    double *out;
    size_t N, plant;
    GC_DEV void operator()(size_t j) const {
        double f = dc_normal_force_inline(&models[mi[j]].normal, in[F_OV * N + j],
                                          in[F_V1 * N + j], in[F_R1 * N + j], in[F_M1 * N + j]);
        if (j == plant) f = ulp_up(f);
        out[j] = f;
    }
};

/* 2. one step of each contact from its own history (hist[k * N + j], updated in place) */
struct ContactEach {
    const dc_contact_model *models;
    const int32_t *mi;
    const double *in;
    double *hist, *res;
    int32_t *ires;
    size_t N, plant;
    GC_DEV void operator()(size_t j) const {
        dc_contact_state s;
        load_state(in, N, j, &s);
        double h[NH];
        for (int k = 0; k < NH; k++) h[k] = hist[k * N + j];
        dc_contact_result r;
        sentinel(&r);
        const int32_t st = dc_contact_force_inline(&models[mi[j]], &s, in[F_DT * N + j], h, NH, &r);
        if (j == plant) r.torque1[2] = ulp_up(r.torque1[2]);
        store_result(res, ires, N, j, &r, st);
        for (int k = 0; k < NH; k++) hist[k * N + j] = h[k];
    }
};

/* 3. and 5. trajectories: thread c runs contact c over T steps (step t is contact t * C + c of
 * the arrays, N = T * C) with model models[mi[c]] (stage 3) or its own models[c] (mi NULL:
 * stage 5, each made step-aware for its trajectory's dt), its history in registers; every step's
 * result and history stored. plant: one ulp on history double `slot` (the tangential spring, or
 * the step-aware state), carried on. */
struct TrajectoryEach {
    const dc_contact_model *models;
    const int32_t *mi;
    const double *in;
    double *hist_steps, *res;
    int32_t *ires;
    size_t C, T, plant;
    int slot;
    GC_DEV void operator()(size_t c) const {
        const size_t N = C * T;
        const dc_contact_model *m = mi ? &models[mi[c]] : &models[c];
        double h[NH];
        for (int k = 0; k < NH; k++) h[k] = 0.0;
        for (size_t t = 0; t < T; t++) {
            const size_t j = t * C + c;
            dc_contact_state s;
            load_state(in, N, j, &s);
            dc_contact_result r;
            sentinel(&r);
            const int32_t st = dc_contact_force_inline(m, &s, in[F_DT * N + j], h, NH, &r);
            if (j == plant) h[slot] = ulp_up(h[slot]);
            store_result(res, ires, N, j, &r, st);
            for (int k = 0; k < NH; k++) hist_steps[k * N + j] = h[k];
        }
    }
};

/* ---------------------------------------------------------------- the timed Hertz-Mindlin batch
 * Inputs: the 20 state fields (F_N .. F_M2; dt one value); history: 6 doubles per contact (the
 * last normal, the tangential spring), read and written; outputs: f_n, force, torque1, torque2
 * (10 doubles). Contacts with a non-OK status: the first index in *first_bad. */
enum { B_FN = 0, B_FORCE = 1, B_T1 = 4, B_T2 = 7, NB = 10, HB = 6, HS = HB + 1 };
struct BenchArgs {
    const dc_contact_model *model;
    const double *in;
    double *hist, *out;
    unsigned long long *first_bad;
    double dt;
    size_t N;
};
template <int H>
GC_HD static inline void bench_store(const BenchArgs &a, size_t j, const dc_contact_result &r,
                                     const double *h) {
    a.out[B_FN * a.N + j] = r.f_n;
    for (int k = 0; k < 3; k++) {
        a.out[(B_FORCE + k) * a.N + j] = r.force[k];
        a.out[(B_T1 + k) * a.N + j] = r.torque1[k];
        a.out[(B_T2 + k) * a.N + j] = r.torque2[k];
    }
    for (int k = 0; k < H; k++) a.hist[k * a.N + j] = h[k];
}
/* One timed contact through an entry: Entry::call evaluates it (the history's H doubles in h:
 * 6, or 7 for the step-aware model, whose last one is the step-aware slot) */
template <class Entry, int H = HB> struct BenchEntry {
    BenchArgs a;
    GC_DEV void operator()(size_t j) const {
        dc_contact_state s;
        load_state(a.in, a.N, j, &s);
        double h[H];
        for (int k = 0; k < H; k++) h[k] = a.hist[k * a.N + j];
        dc_contact_result r;
        if (Entry::call(a.model, &s, a.dt, h, H, &r) != DC_OK) {
            gc_first_bad(a.first_bad, j);
            return;
        }
        bench_store<H>(a, j, r, h);
    }
};
/* the generic entry: the model's selectors read at run time */
struct GenericCall {
    GC_HD static int32_t call(const dc_contact_model *m, const dc_contact_state *s, double dt,
                              double *h, size_t hl, dc_contact_result *r) {
        return dc_contact_force_inline(m, s, dt, h, hl, r);
    }
};
/* the shaped entry: Hertz damped clamped, Mindlin, no rolling, no twisting, projection carry as
 * constants (the host checked the model's shape with dc_contact_model_shape_inline) */
struct ShapedCall {
    GC_HD static int32_t call(const dc_contact_model *m, const dc_contact_state *s, double dt,
                              double *h, size_t, dc_contact_result *r) {
        return dc_contact_force_shaped_inline(m, DC_KERNEL_HERTZ_DAMPED_CLAMPED, DC_TANGENTIAL_MINDLIN,
                                              DC_ROLLING_NONE, DC_TWISTING_NONE, DC_CARRY_PROJECT, s,
                                              dt, h, r);
    }
};
typedef BenchEntry<GenericCall> BenchGeneric;
typedef BenchEntry<ShapedCall> BenchShaped;
typedef BenchEntry<GenericCall, HS> BenchStep; /* the step-aware model through the generic entry */
/* Hand-written: the same formula without the header (no checks, no statuses): Hertz
 * F = k sqrt(R d) d + c sqrt(m sqrt(R d)) vn clamped at 0; Mindlin k_t = kt0 sqrt(R d), dashpot
 * c_t = 2 zeta sqrt(kappa/(1+kappa) m k_t); the spring projected on the tangent plane and
 * rescaled (LAMMPS's rule), incremented by v_t dt, Coulomb-capped with the spring reset. It does
 * not read the old normal (the projection needs none) but writes the new one, as the entries do. */
struct BenchHand {
    BenchArgs a;
    double k, c, kt0, zeta, kappa, mu;
    GC_DEV void operator()(size_t j) const {
        const size_t N = a.N;
        const double *in = a.in;
        const double nx = in[(F_N + 0) * N + j], ny = in[(F_N + 1) * N + j], nz = in[(F_N + 2) * N + j];
        const double d = in[F_OV * N + j];
        const double r1 = in[F_R1 * N + j], r2 = in[F_R2 * N + j];
        const double m1 = in[F_M1 * N + j], m2 = in[F_M2 * N + j];
        const double vrx = in[(F_V1 + 0) * N + j] - in[(F_V2 + 0) * N + j];
        const double vry = in[(F_V1 + 1) * N + j] - in[(F_V2 + 1) * N + j];
        const double vrz = in[(F_V1 + 2) * N + j] - in[(F_V2 + 2) * N + j];
        const double a1 = r1 - 0.5 * d, a2 = r2 - 0.5 * d;
        const bool wall = r2 == (double)INFINITY;
        double ax = a1 * in[(F_W1 + 0) * N + j], ay = a1 * in[(F_W1 + 1) * N + j],
               az = a1 * in[(F_W1 + 2) * N + j];
        if (!wall) {
            ax += a2 * in[(F_W2 + 0) * N + j];
            ay += a2 * in[(F_W2 + 1) * N + j];
            az += a2 * in[(F_W2 + 2) * N + j];
        }
        const double vn = -(vrx * nx + vry * ny + vrz * nz);
        /* contact-point velocity vr - arm x n, its tangential part */
        const double vcx = vrx - (ay * nz - az * ny), vcy = vry - (az * nx - ax * nz),
                     vcz = vrz - (ax * ny - ay * nx);
        const double vcn = vcx * nx + vcy * ny + vcz * nz;
        const double vtx = vcx - vcn * nx, vty = vcy - vcn * ny, vtz = vcz - vcn * nz;
        const double R = wall ? r1 : r1 * (r2 / (r1 + r2));
        const double m = m2 == (double)INFINITY ? m1 : m1 * (m2 / (m1 + m2));
        double *h = a.hist, *out = a.out;
        if (!(d > 0.0)) {
            for (int q = 0; q < HB; q++) h[q * N + j] = 0.0;
            for (int q = 0; q < NB; q++) out[q * N + j] = 0.0;
            return;
        }
        const double q = sqrt(R * d);
        double f = k * q * d + c * sqrt(m * q) * vn;
        f = f > 0.0 ? f : 0.0;
        const double kt = kt0 * q;
        const double ct = zeta > 0.0 ? 2.0 * zeta * sqrt(kappa / (1.0 + kappa) * m * kt) : 0.0;
        double sx = h[3 * N + j], sy = h[4 * N + j], sz = h[5 * N + j];
        const double l2 = sx * sx + sy * sy + sz * sz, sn = sx * nx + sy * ny + sz * nz;
        sx -= sn * nx;
        sy -= sn * ny;
        sz -= sn * nz;
        const double p2 = sx * sx + sy * sy + sz * sz;
        if (p2 > 0.25 * l2) {
            const double g = sqrt(l2 / p2);
            sx *= g;
            sy *= g;
            sz *= g;
        }
        sx += a.dt * vtx;
        sy += a.dt * vty;
        sz += a.dt * vtz;
        double fx = -kt * sx - ct * vtx, fy = -kt * sy - ct * vty, fz = -kt * sz - ct * vtz;
        const double lim = mu * f, t2 = fx * fx + fy * fy + fz * fz;
        if (t2 > lim * lim) {
            const double g = lim / sqrt(t2);
            fx *= g;
            fy *= g;
            fz *= g;
            sx = -(fx + ct * vtx) / kt;
            sy = -(fy + ct * vty) / kt;
            sz = -(fz + ct * vtz) / kt;
        }
        h[0 * N + j] = nx;
        h[1 * N + j] = ny;
        h[2 * N + j] = nz;
        h[3 * N + j] = sx;
        h[4 * N + j] = sy;
        h[5 * N + j] = sz;
        /* torques: -a_i n x F_t */
        const double cx = ny * fz - nz * fy, cy = nz * fx - nx * fz, cz = nx * fy - ny * fx;
        out[B_FN * N + j] = f;
        out[(B_FORCE + 0) * N + j] = f * nx + fx;
        out[(B_FORCE + 1) * N + j] = f * ny + fy;
        out[(B_FORCE + 2) * N + j] = f * nz + fz;
        out[(B_T1 + 0) * N + j] = -a1 * cx;
        out[(B_T1 + 1) * N + j] = -a1 * cy;
        out[(B_T1 + 2) * N + j] = -a1 * cz;
        out[(B_T2 + 0) * N + j] = wall ? 0.0 : -a2 * cx;
        out[(B_T2 + 1) * N + j] = wall ? 0.0 : -a2 * cy;
        out[(B_T2 + 2) * N + j] = wall ? 0.0 : -a2 * cz;
    }
};

/* ---------------------------------------------------------------- models: every shape */

enum { N_KERNELS = 19, N_ROLLING = 4, N_SHAPES = N_KERNELS * 3 * N_ROLLING * 2 * 2 };
struct Shape {
    int kernel, tangential, rolling4, twisting, carry; /* rolling4: 0..3 (EPSD twice) */
};
static Shape shape_of(int s) {
    Shape h;
    h.kernel = 1 + s % N_KERNELS;
    s /= N_KERNELS;
    h.tangential = s % 3;
    s /= 3;
    h.rolling4 = s % N_ROLLING;
    s /= N_ROLLING;
    h.twisting = s % 2;
    h.carry = s / 2;
    return h;
}

/* A model of shape s by the library's dc_contact_model_init (random parameters), checked to
 * have the intended kernel code. */
static void make_model(int s, dc_contact_model *m) {
    const Shape sh = shape_of(s);
    dc_contact_spec sp;
    dc_contact_spec_init(&sp);
    const int k = sh.kernel, group = (k - 1) / 3, sub = (k - 1) % 3;
    sp.E1 = logu(6, 11);
    sp.nu1 = -0.5 + uni();
    sp.E2 = uni() < 0.2 ? (double)INFINITY : logu(6, 11);
    sp.nu2 = -0.5 + uni();
    sp.e_n = 0.02 + 0.97 * uni();
    sp.k_n = logu(3, 9);
    if (k <= 15) {
        const double ps[4] = {1.0, 1.5, 2.0, 1.05 + 1.9 * uni()};
        sp.normal = group == 4 ? DC_NORMAL_HERTZ
                    : group == 0 && uni() < 0.5 ? DC_NORMAL_LINEAR : DC_NORMAL_POWERLAW;
        sp.p = group < 4 ? ps[group] : 1.5;
        if (sp.p == 1.5 && group == 3) sp.p = 2.5;
        sp.damping = sub == 0 ? DC_DAMPING_NONE : DC_DAMPING_RESTITUTION;
        sp.criterion = sub == 2 ? DC_END_FORCE : sub == 1 ? DC_END_OVERLAP : (int32_t)pick(2);
    } else if (k <= 17) {
        sp.normal = DC_NORMAL_VISCOELASTIC;
        sp.damping = DC_DAMPING_NONE;
        sp.visco_A = logu(-9, -5);
        sp.criterion = k == 16 ? DC_END_OVERLAP : DC_END_FORCE;
    } else {
        sp.normal = DC_NORMAL_DMT;
        sp.damping = k == 18 ? DC_DAMPING_NONE : DC_DAMPING_RESTITUTION;
        sp.criterion = DC_END_OVERLAP;
        sp.work_of_adhesion = logu(-3, 1);
    }
    sp.tangential = sh.tangential;
    sp.mu = uni() < 0.1 ? 0.0 : 1.2 * uni();
    sp.k_t = logu(3, 8);
    sp.e_t = uni() < 0.3 ? 1.0 : logu(-2, 0);
    sp.rolling = sh.rolling4 >= 2 ? DC_ROLLING_EPSD : sh.rolling4;
    sp.mu_r = uni() < 0.1 ? 0.0 : 0.3 * uni();
    sp.k_r = sh.rolling4 == 2 ? logu(-6, 0) : 0.0; /* 0: Ai's rule */
    sp.eta_r = uni() < 0.3 ? 0.0 : uni();
    sp.twisting = sh.twisting;
    sp.mu_tw = logu(-6, -3);
    sp.k_tw = logu(-6, 0);
    sp.eta_tw = uni() < 0.3 ? 0.0 : uni();
    sp.inertia_factor = uni() < 0.7 ? 0.4 : 0.1 + 0.9 * uni();
    int32_t st = dc_contact_model_init(&sp, m);
    if (st == DC_OK) st = dc_contact_model_set_carry(m, sh.carry);
    if (st != DC_OK || m->normal.kernel != k) {
        fprintf(stderr, "gpu_check: shape %d: model status %d, kernel %d (wanted %d)\n", s,
                (int)st, (int)m->normal.kernel, k);
        exit(EXIT_SETUP);
    }
}

/* the DMT tail's reach d_c = (h sqrt(r)/k)^(2/3) of a pair (0 for other laws) */
static double dmt_reach(const dc_pair *p, double r) {
    return p->kernel >= 18 ? pow(p->h * sqrt(r) / p->k, 2.0 / 3.0) : 0.0;
}

/* ---------------------------------------------------------------- random contacts */

/* bodies, velocities and spins of contact j (a quarter against a wall) */
static void random_bodies(double *in, size_t N, size_t j) {
    const int wall = uni() < 0.25;
    const double r1 = logu(-5, -1), r2 = wall ? (double)INFINITY : logu(-5, -1);
    in[F_R1 * N + j] = r1;
    in[F_R2 * N + j] = r2;
    in[F_M1 * N + j] = 2500.0 * 4.18879 * r1 * r1 * r1;
    in[F_M2 * N + j] = wall ? (uni() < 0.5 ? (double)INFINITY : logu(-3, 3))
                            : 2500.0 * 4.18879 * r2 * r2 * r2;
    in[F_DT * N + j] = logu(-8, -4);
    /* speeds over decades; spins up to where the frame's rotation takes its sin branch */
    const double vs = logu(-5, 1), ws = vs / r1 * logu(-2, 1.5);
    for (int a = 0; a < 3; a++) {
        in[(F_V1 + a) * N + j] = vs * (2.0 * uni() - 1.0);
        in[(F_V2 + a) * N + j] = vs * (2.0 * uni() - 1.0);
        in[(F_W1 + a) * N + j] = ws * (2.0 * uni() - 1.0);
        in[(F_W2 + a) * N + j] = ws * (2.0 * uni() - 1.0);
    }
    if (uni() < 0.01)
        for (int a = 0; a < 3; a++) in[(F_W1 + a) * N + j] = in[(F_W2 + a) * N + j] = 0.0;
}
static void random_unit(double *in, size_t N, size_t j) {
    double n[3];
    vec(n, 1.0);
    unit(n);
    for (int a = 0; a < 3; a++) in[(F_N + a) * N + j] = n[a];
}
static double r_eff_of(const double *in, size_t N, size_t j) {
    const double r1 = in[F_R1 * N + j], r2 = in[F_R2 * N + j];
    return r2 == (double)INFINITY ? r1 : r1 * r2 / (r1 + r2);
}
/* an overlap for the model's law: mostly touching, else separated (within the DMT tail) */
static double random_overlap(const dc_contact_model *m, double r) {
    const double u = uni();
    if (u < 0.03) return 0.0;
    if (u < 0.1) {
        const double dc = dmt_reach(&m->normal, r);
        return dc > 0.0 ? -2.0 * dc * uni() : -r * logu(-9, -3);
    }
    return r * logu(-9, -1.5);
}

/* batch contact j of model m, with a history: a new contact (zeros) or one under way (its last
 * normal near the current one or anywhere, springs of random size) */
static void random_contact(double *in, double *hist, size_t N, size_t j, const dc_contact_model *m) {
    random_bodies(in, N, j);
    random_unit(in, N, j);
    in[F_OV * N + j] = random_overlap(m, r_eff_of(in, N, j));
    for (int k = 0; k < NH; k++) hist[k * N + j] = 0.0;
    if (m->history_len == 0 || uni() < 0.2) return;
    double n[3];
    const double tilt = uni() < 0.1 ? 2.0 : logu(-8, -1);
    for (int a = 0; a < 3; a++) n[a] = in[(F_N + a) * N + j] + tilt * (2.0 * uni() - 1.0);
    unit(n);
    for (int a = 0; a < 3; a++) hist[a * N + j] = n[a];
    const double size = logu(-10, -3);
    for (int k = 3; k < (int)m->history_len; k++) hist[k * N + j] = size * (2.0 * uni() - 1.0);
}

/* trajectory c of model m over T steps (contact t * C + c): the overlap oscillating through
 * contact and separation, the normal turning a little each step and now and then by a lot,
 * velocities and spins random-walking */
static void random_trajectory(double *in, size_t C, size_t T, size_t c, const dc_contact_model *m) {
    const size_t N = C * T;
    random_bodies(in, N, c);
    random_unit(in, N, c);
    const double r = r_eff_of(in, N, c);
    const double dc = dmt_reach(&m->normal, r);
    /* DMT: half the amplitudes of the order of the tail's reach, so that steps land in it */
    const double amp = dc > 0.0 && uni() < 0.5 ? dc * logu(0, 1) : r * logu(-6, -1.5);
    const double phase = 6.3 * uni(), freq = 0.02 + 0.3 * uni();
    const double base = dc > 0.0 ? 0.5 * dc / amp : 0.0; /* DMT: separations into the tail */
    double vs = 0.0, ws = 0.0;
    for (int a = 0; a < 3; a++) {
        vs = fmax(vs, fabs(in[(F_V1 + a) * N + c]));
        ws = fmax(ws, fabs(in[(F_W1 + a) * N + c]));
    }
    for (size_t t = 1; t < T; t++) {
        const size_t j = t * C + c, p = (t - 1) * C + c;
        for (int f = 0; f < NF; f++) in[f * N + j] = in[f * N + p];
        double n[3];
        if (uni() < 0.003) {
            vec(n, 1.0);
        } else {
            const double tilt = uni() < 0.5 ? 0.0 : logu(-8, -2);
            for (int a = 0; a < 3; a++) n[a] = in[(F_N + a) * N + p] + tilt * (2.0 * uni() - 1.0);
        }
        unit(n);
        for (int a = 0; a < 3; a++) {
            in[(F_N + a) * N + j] = n[a];
            in[(F_V1 + a) * N + j] += 0.05 * vs * (2.0 * uni() - 1.0);
            in[(F_V2 + a) * N + j] += 0.05 * vs * (2.0 * uni() - 1.0);
            in[(F_W1 + a) * N + j] += 0.05 * ws * (2.0 * uni() - 1.0);
            in[(F_W2 + a) * N + j] += 0.05 * ws * (2.0 * uni() - 1.0);
        }
        if (uni() < 0.01)
            for (int a = 0; a < 3; a++) in[(F_W1 + a) * N + j] = 0.0;
    }
    for (size_t t = 0; t < T; t++)
        in[F_OV * N + t * C + c] = amp * (0.3 - base + sin(phase + freq * (double)t));
}

/* the damped Tsuji kernel codes, the laws dc_contact_model_set_step accepts (linear, p = 3/2,
 * p = 2, general p <= 3, Hertz: damped, and damped and force-clamped) */
static int step_kernel(int k) { return k <= 15 && (k - 1) % 3 != 0; }

/* step-exact trajectory c: as random_trajectory, with contacts of a few steps (the overlap's
 * phase advancing 0.2-1.2 rad a step) and body 1's velocity along n set so that the approach
 * speed (v2 - v1).n is the one that drifted the overlap to its value: a collision as a host
 * integrates it, so that each contact's first step is an onset (overlap <= speed x dt) */
static void step_trajectory(double *in, size_t C, size_t T, size_t c, const dc_contact_model *m) {
    const size_t N = C * T;
    random_trajectory(in, C, T, c, m);
    const double r = r_eff_of(in, N, c), amp = r * logu(-6, -2);
    const double phase = 6.3 * uni(), freq = 0.2 + uni(), base = 0.6 * uni() - 0.3;
    const double dt = in[F_DT * N + c];
    for (size_t t = 0; t < T; t++) {
        const size_t j = t * C + c;
        const double d = amp * (base + sin(phase + freq * (double)t)),
                     prev = amp * (base + sin(phase + freq * ((double)t - 1.0)));
        in[F_OV * N + j] = d;
        /* approach speed u = (d - prev)/dt, the drift that made this step's overlap (velocity
         * Verlet: the force from the new position and the half-step velocity): v1.n = v2.n - u */
        const double u = (d - prev) / dt;
        double v1n = 0.0, v2n = 0.0;
        for (int a = 0; a < 3; a++) {
            v1n += in[(F_V1 + a) * N + j] * in[(F_N + a) * N + j];
            v2n += in[(F_V2 + a) * N + j] * in[(F_N + a) * N + j];
        }
        for (int a = 0; a < 3; a++)
            in[(F_V1 + a) * N + j] += (v2n - u - v1n) * in[(F_N + a) * N + j];
    }
}

/* ---------------------------------------------------------------- the host reference and comparisons */

struct Counts {
    long compared = 0, differ = 0, ok = 0, sliding = 0, rolling = 0, separated = 0, sin_branch = 0,
         dmt_tail = 0, errors = 0;
    long shape_ok[N_SHAPES] = {0};
    long kernel_diff[N_KERNELS + 1] = {0};
};

static int bits_differ(double a, double b) { return memcmp(&a, &b, sizeof a) != 0; }

/* the regimes a reference step went through */
static void tally(Counts &c, const dc_contact_model *m, int shape, const dc_contact_state *s,
                  double dt, const dc_contact_result *r, int32_t st) {
    if (st != DC_OK) {
        c.errors++;
        return;
    }
    c.ok++;
    c.shape_ok[shape]++;
    c.sliding += r->sliding;
    c.rolling += r->rolling_sliding;
    c.separated += !(s->overlap > 0.0);
    if (m->normal.kernel >= 18 && !(s->overlap > 0.0) && r->f_n != 0.0) c.dmt_tail++;
    double q2 = 0.0;
    for (int a = 0; a < 3; a++) q2 += 0.25 * dt * dt * (s->w1[a] + s->w2[a]) * (s->w1[a] + s->w2[a]);
    if (m->carry == DC_CARRY_ROTATE && m->history_len > 0 && s->overlap > 0.0 && q2 >= 1e-3)
        c.sin_branch++;
}

/* compare contact j of the device's results/history with the reference's; report the first few */
struct Side {
    double *res;
    int32_t *ires;
    double *hist;
};
static void compare_contact(Counts &c, const char *stage, size_t j, size_t shown, int kernel,
                            const Side &dev, const Side &ref, size_t N) {
    const double *dres = dev.res, *dhist = dev.hist, *rres = ref.res, *rhist = ref.hist;
    const int32_t *dires = dev.ires, *rires = ref.ires;
    int diff = -1;
    for (int f = 0; f < NR && diff < 0; f++)
        if (bits_differ(dres[f * N + j], rres[f * N + j])) diff = f;
    for (int f = 0; f < NI && diff < 0; f++)
        if (dires[f * N + j] != rires[f * N + j]) diff = 100 + f;
    for (int k = 0; k < NH && diff < 0; k++)
        if (bits_differ(dhist[k * N + j], rhist[k * N + j])) diff = 200 + k;
    c.compared++;
    if (diff < 0) return;
    if (c.differ < 5) {
        const double a = diff < 100 ? dres[diff * N + j] : diff >= 200 ? dhist[(diff - 200) * N + j] : 0;
        const double b = diff < 100 ? rres[diff * N + j] : diff >= 200 ? rhist[(diff - 200) * N + j] : 0;
        fprintf(stderr, "gpu_check: %s: contact %zu (kernel %d): %s %d differs: device %a, library %a "
                        "(status %d / %d)\n", stage, shown, kernel,
                diff < 100 ? "result double" : diff < 200 ? "result int" : "history", diff % 100,
                a, b, (int)dires[j], (int)rires[j]);
    }
    c.differ++;
    c.kernel_diff[kernel]++;
}

/* the device's results, statuses and histories of n contacts, copied into the host buffers of
 * `host` */
static void fetch(const Side &host, const double *d_res, const int32_t *d_ires, const double *d_hist,
                  size_t n) {
    to_host(host.res, d_res, NR * n);
    to_host(host.ires, d_ires, NI * n);
    to_host(host.hist, d_hist, NH * n);
}

/* the library's step of contact j (its history h in and out), stored in ref, the regimes
 * tallied, compared with the device's */
static void reference_step(Counts &c, const char *stage, size_t shown, const dc_contact_model *m,
                           int shape, const double *in, size_t N, size_t j, double *h,
                           const Side &dev, const Side &ref) {
    dc_contact_state s;
    load_state(in, N, j, &s);
    dc_contact_result r;
    sentinel(&r);
    const double dt = in[F_DT * N + j];
    const int32_t st = dc_contact_force(m, &s, dt, h, NH, &r);
    store_result(ref.res, ref.ires, N, j, &r, st);
    for (int k = 0; k < NH; k++) ref.hist[k * N + j] = h[k];
    tally(c, m, shape, &s, dt, &r, st);
    compare_contact(c, stage, j, shown, (int)m->normal.kernel, dev, ref, N);
}

/* ---------------------------------------------------------------- the run */

struct Options {
    int cpu_smoke = 0, plant = 0;
    long contacts = 10000000L, normals = 10000000L, traj_contacts = 2 * N_SHAPES, steps = 550,
         bench = 1L << 24, reps = 2;
};

static void usage(const char *msg) {
    fprintf(stderr,
            "gpu_check: %s\n"
            "usage: gpu_check [--cpu-smoke] [--contacts N] [--normals N] [--trajectories C]\n"
            "                 [--steps T] [--bench N] [--plant-ulp]\n"
            "  --cpu-smoke      the CPU stand-in (required by, and only accepted by, a host build)\n"
            "  --contacts N     random contacts of the batch check (default 1e7; smoke 2e4)\n"
            "  --normals N      random normal-force inputs (default 1e7; smoke 2e4)\n"
            "  --trajectories C contacts carried over --steps T steps (default %d x 550;\n"
            "                   smoke %d x 12); C >= %d so that every shape runs\n"
            "  --bench N        contacts of the timed batch (default 2^24; smoke 4096)\n"
            "  --plant-ulp      add one ulp on the device side in each checked stage (must fail)\n",
            msg, 2 * N_SHAPES, N_SHAPES, N_SHAPES);
    exit(EXIT_USAGE);
}
static long count_arg(int argc, char **argv, int &i) {
    if (i + 1 >= argc) usage("a count is missing after an option");
    char *end = nullptr;
    const double v = strtod(argv[++i], &end);
    if (!end || *end || !(v >= 1.0 && v <= 4e9) || v != floor(v))
        usage("a count must be an integer from 1 to 4e9");
    return (long)v;
}
static Options parse(int argc, char **argv) {
    Options o;
    long set[5] = {-1, -1, -1, -1, -1};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--cpu-smoke")) o.cpu_smoke = 1;
        else if (!strcmp(a, "--plant-ulp")) o.plant = 1;
        else if (!strcmp(a, "--contacts")) set[0] = count_arg(argc, argv, i);
        else if (!strcmp(a, "--normals")) set[1] = count_arg(argc, argv, i);
        else if (!strcmp(a, "--trajectories")) set[2] = count_arg(argc, argv, i);
        else if (!strcmp(a, "--steps")) set[3] = count_arg(argc, argv, i);
        else if (!strcmp(a, "--bench")) set[4] = count_arg(argc, argv, i);
        else {
            fprintf(stderr, "gpu_check: unknown argument '%s'\n", a);
            usage("bad arguments");
        }
    }
#if defined(__CUDACC__)
    if (o.cpu_smoke) usage("--cpu-smoke is the host build's mode (this build runs on the GPU)");
#else
    if (!o.cpu_smoke)
        usage("this build has no CUDA: only --cpu-smoke runs (scripts/gpu_check.sh builds the GPU one)");
    o.contacts = o.normals = 20000;
    o.traj_contacts = N_SHAPES;
    o.steps = 12;
    o.bench = 4096;
#endif
    long *dst[5] = {&o.contacts, &o.normals, &o.traj_contacts, &o.steps, &o.bench};
    for (int k = 0; k < 5; k++)
        if (set[k] > 0) *dst[k] = set[k];
    if (o.traj_contacts < N_SHAPES) usage("--trajectories must be at least the number of shapes (912)");
    if (o.contacts < N_SHAPES) usage("--contacts must be at least the number of shapes (912)");
    if (o.steps < 2) usage("--steps must be at least 2");
    return o;
}

/* The timed batch's reference: the library's step of each contact from hist0 (H doubles per
 * contact), its 10 outputs into ref and its history into rhist. */
static void bench_reference(const dc_contact_model &m, const double *in, const double *hist0, int H,
                            size_t N, double dt, double *ref, double *rhist) {
    for (size_t j = 0; j < N; j++) {
        dc_contact_state s;
        load_state(in, N, j, &s);
        double h[NH];
        for (int k = 0; k < H; k++) h[k] = hist0[k * N + j];
        dc_contact_result r;
        if (dc_contact_force(&m, &s, dt, h, (size_t)H, &r) != DC_OK) die("timed batch: a reference contact failed");
        ref[B_FN * N + j] = r.f_n;
        for (int k = 0; k < 3; k++) {
            ref[(B_FORCE + k) * N + j] = r.force[k];
            ref[(B_T1 + k) * N + j] = r.torque1[k];
            ref[(B_T2 + k) * N + j] = r.torque2[k];
        }
        for (int k = 0; k < H; k++) rhist[k * N + j] = h[k];
    }
}
/* An entry's first pass against the reference, bit for bit (outputs and H history doubles). */
static void bench_compare(const double *out, const double *dh, const double *ref, const double *rhist,
                          int H, size_t N, const char *entry, long &differ, long &compared) {
    for (size_t j = 0; j < N; j++) {
        int d = 0;
        for (int f = 0; f < NB; f++) d |= bits_differ(out[f * N + j], ref[f * N + j]);
        for (int k = 0; k < H; k++) d |= bits_differ(dh[k * N + j], rhist[k * N + j]);
        if (d && differ < 5) fprintf(stderr, "gpu_check: timed batch (%s entry): contact %zu differs\n", entry, j);
        differ += d;
        compared++;
    }
}

/* chunk size of the batch checks (device and host buffers reused) */
static const size_t CHUNK = 1u << 21;

int main(int argc, char **argv) {
    const Options o = parse(argc, argv);
    char dev[400];
    device_name(dev, sizeof dev);

    /* models: every shape twice over in a full run (other random parameters), once in the smoke */
    const int n_models = (int)(o.traj_contacts < 2 * N_SHAPES ? N_SHAPES : 2 * N_SHAPES);
    std::vector<dc_contact_model> models((size_t)n_models);
    for (int i = 0; i < n_models; i++) make_model(i % N_SHAPES, &models[(size_t)i]);
    dc_contact_model *d_models = dev_alloc<dc_contact_model>((size_t)n_models);
    to_dev(d_models, models.data(), (size_t)n_models);
    const size_t none = (size_t)-1;
    int failed_stages = 0;

    /* ---- 1. normal forces */
    Counts cn;
    {
        const size_t cap = CHUNK < (size_t)o.normals ? CHUNK : (size_t)o.normals;
        std::vector<double> in(NF * cap), out(cap);
        std::vector<int32_t> mi(cap);
        double *d_in = dev_alloc<double>(NF * cap), *d_out = dev_alloc<double>(cap);
        int32_t *d_mi = dev_alloc<int32_t>(cap);
        for (size_t done = 0; done < (size_t)o.normals;) {
            const size_t n = (size_t)o.normals - done < cap ? (size_t)o.normals - done : cap;
            for (size_t j = 0; j < n; j++) {
                const int32_t m = (int32_t)((done + j) % (size_t)n_models);
                const dc_pair *p = &models[(size_t)m].normal;
                mi[j] = m;
                const double r = logu(-5, -1);
                const double u = uni();
                const double dc = dmt_reach(p, r);
                in[F_OV * n + j] = u < 0.03 ? 0.0 : u < 0.05 ? -0.0
                                 : u < 0.12 ? (dc > 0.0 ? -2.0 * dc * uni() : -r * uni() * 1e-3)
                                            : r * logu(-12, -1);
                const double w = uni();
                in[F_V1 * n + j] = w < 0.05 ? 0.0 : (w < 0.525 ? -1.0 : 1.0) * logu(-3, 3);
                in[F_R1 * n + j] = r;
                in[F_M1 * n + j] = logu(-12, 1);
            }
            to_dev(d_in, in.data(), NF * n);
            to_dev(d_mi, mi.data(), n);
            const size_t plant = o.plant && done == 0 ? n / 2 : none;
            launch(n, NormalEach{d_models, d_mi, d_in, d_out, n, plant});
            dev_sync();
            to_host(out.data(), d_out, n);
            for (size_t j = 0; j < n; j++) {
                const dc_pair *p = &models[(size_t)mi[j]].normal;
                const double ref = dc_normal_force(p, in[F_OV * n + j], in[F_V1 * n + j],
                                                   in[F_R1 * n + j], in[F_M1 * n + j]);
                cn.compared++;
                cn.ok++;
                cn.shape_ok[p->kernel]++; /* per kernel code here */
                cn.dmt_tail += p->kernel >= 18 && !(in[F_OV * n + j] > 0.0) && ref != 0.0;
                if (bits_differ(ref, out[j])) {
                    if (cn.differ < 5)
                        fprintf(stderr, "gpu_check: normal forces: input %zu (kernel %d): device %a, "
                                        "library %a\n", done + j, (int)p->kernel, out[j], ref);
                    cn.differ++;
                    cn.kernel_diff[p->kernel]++;
                }
            }
            done += n;
        }
        dev_free(d_in);
        dev_free(d_out);
        dev_free(d_mi);
    }

    /* ---- 2. contact batch */
    Counts cb;
    {
        const size_t cap = CHUNK < (size_t)o.contacts ? CHUNK : (size_t)o.contacts;
        std::vector<double> in(NF * cap), hist0(NH * cap), dhist(NH * cap), rhist(NH * cap),
            dres(NR * cap), rres(NR * cap);
        std::vector<int32_t> mi(cap), dires(NI * cap), rires(NI * cap);
        double *d_in = dev_alloc<double>(NF * cap), *d_hist = dev_alloc<double>(NH * cap),
               *d_res = dev_alloc<double>(NR * cap);
        int32_t *d_mi = dev_alloc<int32_t>(cap), *d_ires = dev_alloc<int32_t>(NI * cap);
        for (size_t done = 0; done < (size_t)o.contacts;) {
            const size_t n = (size_t)o.contacts - done < cap ? (size_t)o.contacts - done : cap;
            for (size_t j = 0; j < n; j++) {
                mi[j] = (int32_t)((done + j) % (size_t)n_models);
                random_contact(in.data(), hist0.data(), n, j, &models[(size_t)mi[j]]);
            }
            to_dev(d_in, in.data(), NF * n);
            to_dev(d_hist, hist0.data(), NH * n);
            to_dev(d_mi, mi.data(), n);
            const size_t plant = o.plant && done == 0 ? n / 3 : none;
            launch(n, ContactEach{d_models, d_mi, d_in, d_hist, d_res, d_ires, n, plant});
            dev_sync();
            const Side dev{dres.data(), dires.data(), dhist.data()}, ref{rres.data(), rires.data(), rhist.data()};
            fetch(dev, d_res, d_ires, d_hist, n);
            for (size_t j = 0; j < n; j++) {
                double h[NH];
                for (int k = 0; k < NH; k++) h[k] = hist0[k * n + j];
                reference_step(cb, "contact batch", done + j, &models[(size_t)mi[j]],
                               (int)(mi[j] % N_SHAPES), in.data(), n, j, h, dev, ref);
            }
            done += n;
        }
        dev_free(d_in);
        dev_free(d_hist);
        dev_free(d_res);
        dev_free(d_mi);
        dev_free(d_ires);
    }

    /* ---- 3. trajectories */
    Counts ct;
    {
        const size_t C = (size_t)o.traj_contacts, T = (size_t)o.steps, N = C * T;
        std::vector<double> in(NF * N), dres(NR * N), rres(NR * N), dhist(NH * N), rhist(NH * N);
        std::vector<int32_t> mi(C), dires(NI * N), rires(NI * N);
        for (size_t c = 0; c < C; c++) {
            mi[c] = (int32_t)(c % (size_t)n_models);
            random_trajectory(in.data(), C, T, c, &models[(size_t)mi[c]]);
        }
        double *d_in = dev_alloc<double>(NF * N), *d_res = dev_alloc<double>(NR * N),
               *d_hist = dev_alloc<double>(NH * N);
        int32_t *d_mi = dev_alloc<int32_t>(C), *d_ires = dev_alloc<int32_t>(NI * N);
        to_dev(d_in, in.data(), NF * N);
        to_dev(d_mi, mi.data(), C);
        /* planted: halfway along the first trajectory whose model has a tangential spring */
        size_t pc = 0;
        while (pc + 1 < C && models[(size_t)mi[pc]].tangential == DC_TANGENTIAL_NONE) pc++;
        const size_t plant = o.plant ? (T / 2) * C + pc : none;
        launch(C, TrajectoryEach{d_models, d_mi, d_in, d_hist, d_res, d_ires, C, T, plant, 3});
        dev_sync();
        const Side dev{dres.data(), dires.data(), dhist.data()}, ref{rres.data(), rires.data(), rhist.data()};
        fetch(dev, d_res, d_ires, d_hist, N);
        for (size_t c = 0; c < C; c++) {
            double h[NH] = {0};
            for (size_t t = 0; t < T; t++)
                reference_step(ct, "trajectories", t * C + c, &models[(size_t)mi[c]],
                               (int)(mi[c] % N_SHAPES), in.data(), N, t * C + c, h, dev, ref);
        }
        dev_free(d_in);
        dev_free(d_res);
        dev_free(d_hist);
        dev_free(d_mi);
        dev_free(d_ires);
    }

    /* ---- 4. the timed Hertz-Mindlin batch */
    const size_t NBn = (size_t)o.bench;
    double sec_copy = 0, sec_gen = 0, sec_shaped = 0, sec_hand = 0, sec_step = 0, copy_bw = 0;
    long bench_diff = 0, bench_compared = 0;
    double hand_rel = 0.0;
    dc_contact_model hm;
    {
        dc_contact_spec sp;
        dc_contact_spec_init(&sp);
        sp.normal = DC_NORMAL_HERTZ;
        sp.damping = DC_DAMPING_RESTITUTION;
        sp.criterion = DC_END_FORCE;
        sp.e_n = 0.5;
        sp.E1 = sp.E2 = 63e9;
        sp.nu1 = sp.nu2 = 0.23;
        sp.tangential = DC_TANGENTIAL_MINDLIN;
        sp.mu = 0.3;
        sp.e_t = 0.5;
        if (dc_contact_model_init(&sp, &hm) != DC_OK ||
            dc_contact_model_set_carry(&hm, DC_CARRY_PROJECT) != DC_OK ||
            dc_contact_model_shape_inline(&hm, DC_KERNEL_HERTZ_DAMPED_CLAMPED, DC_TANGENTIAL_MINDLIN,
                                          DC_ROLLING_NONE, DC_TWISTING_NONE, DC_CARRY_PROJECT) != DC_OK ||
            hm.history_len != HB)
            die("the Hertz-Mindlin model of the timed batch");
    }
    {
        const size_t N = NBn;
        const double dt = 1e-6;
        /* glass beads of 0.1-1 mm touching, a tenth of them against a wall; the history a contact
         * under way (last normal near the current one, a spring of up to 1e-7 m) */
        std::vector<double> in(NF * N), hist0(HB * N), out(NB * N), ref(NB * N), rhist(HB * N), dh(HB * N);
        for (size_t j = 0; j < N; j++) {
            random_unit(in.data(), N, j);
            const int wall = uni() < 0.1;
            const double r1 = 1e-4 * logu(0, 1), r2 = wall ? (double)INFINITY : 1e-4 * logu(0, 1);
            in[F_R1 * N + j] = r1;
            in[F_R2 * N + j] = r2;
            in[F_M1 * N + j] = 2500.0 * 4.18879 * r1 * r1 * r1;
            in[F_M2 * N + j] = wall ? (double)INFINITY : 2500.0 * 4.18879 * r2 * r2 * r2;
            in[F_OV * N + j] = r1 * logu(-5, -2);
            for (int a = 0; a < 3; a++) {
                in[(F_V1 + a) * N + j] = 2.0 * uni() - 1.0;
                in[(F_V2 + a) * N + j] = 2.0 * uni() - 1.0;
                in[(F_W1 + a) * N + j] = (2.0 * uni() - 1.0) / r1;
                in[(F_W2 + a) * N + j] = (2.0 * uni() - 1.0) / r1;
                hist0[a * N + j] = in[(F_N + a) * N + j] + 1e-4 * (2.0 * uni() - 1.0);
                hist0[(3 + a) * N + j] = 1e-7 * (2.0 * uni() - 1.0);
            }
        }
        double *d_in = dev_alloc<double>(NF * N), *d_hist = dev_alloc<double>(HB * N),
               *d_out = dev_alloc<double>(NB * N);
        unsigned long long *d_first = dev_alloc<unsigned long long>(1);
        to_dev(d_in, in.data(), NF * N);
        const unsigned long long no_bad = ~0ull;
        dc_contact_model *d_hm = dev_alloc<dc_contact_model>(1);
        to_dev(d_hm, &hm, 1);
        const BenchArgs a{d_hm, d_in, d_hist, d_out, d_first, dt, N};
        /* the reference: the library from the same history */
        bench_reference(hm, in.data(), hist0.data(), HB, N, dt, ref.data(), rhist.data());
        /* each kernel once from the starting history, checked; then timed (the history evolving) */
        const BenchGeneric gen{a};
        const BenchShaped shp{a};
        const BenchHand hand{a, hm.normal.k, hm.normal.c, hm.kt, hm.zeta_t, hm.kappa, hm.mu};
        for (int kind = 0; kind < 3; kind++) {
            to_dev(d_hist, hist0.data(), HB * N);
            to_dev(d_first, &no_bad, 1);
            if (kind == 0) launch(N, gen);
            else if (kind == 1) launch(N, shp);
            else launch(N, hand);
            dev_sync();
            unsigned long long first = 0;
            to_host(&first, d_first, 1);
            to_host(out.data(), d_out, NB * N);
            to_host(dh.data(), d_hist, HB * N);
            if (kind < 2 && first != no_bad) die("timed batch: a device contact returned an error status");
            if (kind < 2) {
                bench_compare(out.data(), dh.data(), ref.data(), rhist.data(), HB, N,
                              kind ? "shaped" : "generic", bench_diff, bench_compared);
                continue;
            }
            /* the hand loop: the same formula, so within a few ulp of the force's size */
            for (size_t j = 0; j < N; j++) {
                const double scale = fabs(ref[B_FN * N + j]) + 1e-300;
                for (int f = 0; f < NB; f++) {
                    const double e = fabs(out[f * N + j] - ref[f * N + j]) /
                                     (f < B_T1 ? scale : scale * in[F_R1 * N + j]);
                    hand_rel = e > hand_rel || e != e ? e : hand_rel;
                }
            }
        }
        /* the same batch with the model made step-aware at dt (velocity Verlet): its history
         * has the step-aware slot after the 6 (zero: each contact's first step here, an onset
         * where the overlap is within a drift; the timed passes after it are steady steps) */
        dc_contact_model hs = hm;
        if (dc_contact_model_set_step(&hs, dt, DC_INTEGRATOR_VELOCITY_VERLET) != DC_OK ||
            hs.history_len != HS)
            die("the step-aware Hertz-Mindlin model of the timed batch");
        dc_contact_model *d_hs = dev_alloc<dc_contact_model>(1);
        to_dev(d_hs, &hs, 1);
        double *d_hist_s = dev_alloc<double>(HS * N);
        const BenchStep stp{BenchArgs{d_hs, d_in, d_hist_s, d_out, d_first, dt, N}};
        {
            std::vector<double> hist0s(HS * N, 0.0), rhs(HS * N), dhs(HS * N);
            for (size_t q = 0; q < HB * N; q++) hist0s[q] = hist0[q];
            bench_reference(hs, in.data(), hist0s.data(), HS, N, dt, ref.data(), rhs.data());
            to_dev(d_hist_s, hist0s.data(), HS * N);
            to_dev(d_first, &no_bad, 1);
            launch(N, stp);
            dev_sync();
            unsigned long long first = 0;
            to_host(&first, d_first, 1);
            to_host(out.data(), d_out, NB * N);
            to_host(dhs.data(), d_hist_s, HS * N);
            if (first != no_bad) die("timed batch: a step-aware device contact returned an error status");
            bench_compare(out.data(), dhs.data(), ref.data(), rhs.data(), HS, N, "step-aware generic",
                          bench_diff, bench_compared);
        }
        const int reps = o.cpu_smoke ? 1 : 10;
        sec_gen = kernel_seconds(N, gen, reps);
        sec_shaped = kernel_seconds(N, shp, reps);
        sec_hand = kernel_seconds(N, hand, reps);
        sec_step = kernel_seconds(N, stp, reps);
        dev_free(d_hist_s);
        dev_free(d_hs);
        /* the copy roofline: a buffer as large as the batch's inputs, device to device */
        const size_t bytes = NF * N * sizeof(double);
        char *d_copy = dev_alloc<char>(bytes);
        sec_copy = copy_seconds(d_copy, reinterpret_cast<const char *>(d_in), bytes, reps);
        copy_bw = 2.0 * (double)bytes / sec_copy; /* read + written */
        dev_free(d_copy);
        dev_free(d_in);
        dev_free(d_hist);
        dev_free(d_out);
        dev_free(d_first);
        dev_free(d_hm);
    }
    dev_free(d_models);

    /* ---- 5. the step-exact option (dc_contact_model_set_step): trajectories as stage 3, each
     * with its own step-aware model (made by the library for that trajectory's dt, velocity
     * Verlet and symplectic Euler alternately), over every shape whose normal law the option
     * takes; the library also runs each trajectory with the plain model, to count the steps the
     * option changes (the onset steps among them). */
    Counts cs;
    long step_onsets = 0, step_onset_changed = 0, step_changed = 0, step_integrator[2] = {0, 0};
    long step_k_onset[N_KERNELS + 1] = {0}, step_k_changed[N_KERNELS + 1] = {0};
    std::vector<int> step_shapes;
    for (int sh = 0; sh < N_SHAPES; sh++)
        if (step_kernel(shape_of(sh).kernel)) step_shapes.push_back(sh);
    size_t step_C = 0;
    {
        const size_t per = o.traj_contacts < 2 * N_SHAPES ? 1 : 2; /* as stage 3's models */
        const size_t C = step_shapes.size() * per, T = (size_t)o.steps, N = C * T;
        step_C = C;
        std::vector<dc_contact_model> plain(C), stepm(C);
        std::vector<double> in(NF * N), dres(NR * N), rres(NR * N), dhist(NH * N), rhist(NH * N);
        std::vector<int32_t> dires(NI * N), rires(NI * N);
        for (size_t c = 0; c < C; c++) {
            const int sh = step_shapes[c % step_shapes.size()];
            make_model(sh, &plain[c]);
            step_trajectory(in.data(), C, T, c, &plain[c]);
            const double dt = in[F_DT * N + c];
            const int32_t integ = (int32_t)(c % 2);
            int32_t st = DC_ERR_STEP_UNREACHABLE;
            /* a model whose e_n the explicit step cannot realise (e_n well below 0.1): redrawn */
            for (int attempt = 0; attempt < 100 && st == DC_ERR_STEP_UNREACHABLE; attempt++) {
                if (attempt > 0) make_model(sh, &plain[c]);
                stepm[c] = plain[c];
                st = dc_contact_model_set_step(&stepm[c], dt, integ);
            }
            if (st != DC_OK || stepm[c].history_len != plain[c].history_len + 1) {
                fprintf(stderr, "gpu_check: step-exact shape %d: dc_contact_model_set_step status %d, "
                                "history %u (plain %u)\n", sh, (int)st, stepm[c].history_len,
                        plain[c].history_len);
                exit(EXIT_SETUP);
            }
        }
        dc_contact_model *d_step = dev_alloc<dc_contact_model>(C);
        to_dev(d_step, stepm.data(), C);
        double *d_in = dev_alloc<double>(NF * N), *d_res = dev_alloc<double>(NR * N),
               *d_hist = dev_alloc<double>(NH * N);
        int32_t *d_ires = dev_alloc<int32_t>(NI * N);
        to_dev(d_in, in.data(), NF * N);
        const size_t pc = C / 2;
        const size_t plant = o.plant ? (T / 2) * C + pc : none;
        const int slot = (int)stepm[pc].history_len - 1;
        launch(C, TrajectoryEach{d_step, nullptr, d_in, d_hist, d_res, d_ires, C, T, plant, slot});
        dev_sync();
        const Side dev{dres.data(), dires.data(), dhist.data()}, ref{rres.data(), rires.data(), rhist.data()};
        fetch(dev, d_res, d_ires, d_hist, N);
        for (size_t c = 0; c < C; c++) {
            const dc_contact_model *m = &stepm[c];
            const int k = (int)m->normal.kernel, sl = (int)m->history_len - 1;
            double h[NH] = {0}, hp[NH] = {0};
            for (size_t t = 0; t < T; t++) {
                const size_t j = t * C + c;
                dc_contact_state s;
                load_state(in.data(), N, j, &s);
                const double dt = in[F_DT * N + j];
                double u = 0.0; /* approach speed (v2 - v1).n */
                for (int a = 0; a < 3; a++) u += (s.v2[a] - s.v1[a]) * s.n[a];
                const int onset = h[sl] == 0.0 && s.overlap > 0.0 && u > 0.0 && s.overlap <= u * dt;
                reference_step(cs, "step-exact trajectories", j, m, step_shapes[c % step_shapes.size()],
                               in.data(), N, j, h, dev, ref);
                dc_contact_result rp;
                const int32_t sp = dc_contact_force(&plain[c], &s, dt, hp, NH, &rp);
                if (rires[I_STATUS * N + j] != DC_OK || sp != DC_OK) continue;
                step_integrator[c % 2]++;
                const int changed = bits_differ(rres[R_FN * N + j], rp.f_n);
                step_changed += changed;
                step_k_changed[k] += changed;
                step_onsets += onset;
                step_onset_changed += onset && changed;
                step_k_onset[k] += onset && changed;
            }
        }
        dev_free(d_step);
        dev_free(d_in);
        dev_free(d_res);
        dev_free(d_hist);
        dev_free(d_ires);
    }

    /* ---- the table */
    /* bytes each timed kernel must move per contact: 20 state doubles read, the history (6) read
     * and written, 10 results written; the hand loop skips the old normal (3 doubles read) */
    const double bytes_entry = (20 + HB + HB + NB) * 8.0, bytes_hand = bytes_entry - 3 * 8.0;
    const double rate_gen = (double)NBn / sec_gen, rate_shaped = (double)NBn / sec_shaped,
                 rate_hand = (double)NBn / sec_hand, rate_step = (double)NBn / sec_step;
    const double bytes_step = bytes_entry + 2 * 8.0; /* the step-aware slot read and written */
    int coverage_ok = 1;
    for (int s = 0; s < N_SHAPES; s++) coverage_ok &= cb.shape_ok[s] > 0 && ct.shape_ok[s] > 0;
    for (int k = 1; k <= N_KERNELS; k++) coverage_ok &= cn.shape_ok[k] > 0;
    /* step-exact: every shape it takes ran, and in each of its kernel codes the option changed
     * onset forces and other steps; both integrators ran */
    for (int sh : step_shapes) coverage_ok &= cs.shape_ok[sh] > 0;
    for (int k = 1; k <= N_KERNELS; k++)
        if (step_kernel(k)) coverage_ok &= step_k_onset[k] > 0 && step_k_changed[k] > step_k_onset[k];
    coverage_ok &= step_integrator[0] > 0 && step_integrator[1] > 0;
    coverage_ok &= cb.sliding > 0 && cb.rolling > 0 && cb.separated > 0 && cb.sin_branch > 0 &&
                   ct.sliding > 0 && ct.rolling > 0 && ct.separated > 0 && ct.sin_branch > 0 &&
                   cn.dmt_tail > 0 && ct.dmt_tail > 0;
    const int hand_ok = hand_rel <= 1e-9;

    printf("\ngpu_check (%s; %s; %d models of %d shapes)\n", GC_MODE, dev, n_models, N_SHAPES);
    printf("| check | compared | bit differences | regimes / figures |\n");
    printf("|---|---:|---:|---|\n");
    printf("| normal forces: dc_normal_force_inline vs dc_normal_force, kernels 1-%d | %ld | %ld | "
           "DMT tail %ld |\n", N_KERNELS, cn.compared, cn.differ, cn.dmt_tail);
    printf("| contact batch: dc_contact_force_inline vs dc_contact_force, random history | %ld | %ld "
           "| ok %ld, errors %ld, sliding %ld, rolling/twisting limit %ld, separated %ld, frame sin "
           "branch %ld |\n", cb.compared, cb.differ, cb.ok, cb.errors, cb.sliding, cb.rolling,
           cb.separated, cb.sin_branch);
    printf("| trajectories: %ld contacts x %ld steps, history carried on the device | %ld | %ld | ok "
           "%ld, errors %ld, sliding %ld, rolling/twisting limit %ld, separated %ld, frame sin branch "
           "%ld, DMT tail %ld |\n", o.traj_contacts, o.steps, ct.compared, ct.differ, ct.ok, ct.errors,
           ct.sliding, ct.rolling, ct.separated, ct.sin_branch, ct.dmt_tail);
    printf("| timed batch, first pass: generic, shaped and step-aware entries vs dc_contact_force | %ld | %ld | "
           "hand-written loop within %.2g (relative; same formula if <= 1e-9) |\n",
           bench_compared, bench_diff, hand_rel);
    printf("| step-exact trajectories: %zu contacts x %ld steps, models made step-aware by "
           "dc_contact_model_set_step (%zu shapes, velocity Verlet / symplectic Euler) | %ld | %ld | "
           "ok %ld (VV %ld, SE %ld), errors %ld, onsets %ld (force changed by the option: %ld), "
           "steps changed by the option %ld, sliding %ld, separated %ld |\n",
           step_C, o.steps, step_shapes.size(), cs.compared, cs.differ, cs.ok, step_integrator[0],
           step_integrator[1], cs.errors, step_onsets, step_onset_changed, step_changed, cs.sliding,
           cs.separated);
    printf("| copy roofline: %s | - | - | %.1f GB/s (read + written) |\n",
           o.cpu_smoke ? "memcpy (CPU stand-in)" : "cudaMemcpy device to device", copy_bw * 1e-9);
    /* the throughput target (a figure to report, not a pass condition of the exit status) */
    const double roof_gen = rate_gen * bytes_entry / copy_bw,
                 roof_shaped = rate_shaped * bytes_entry / copy_bw;
    const char *unit_note = o.cpu_smoke ? " (CPU stand-in: not a GPU figure)" : "";
    printf("| Hertz-Mindlin batch, dc_contact_force_inline | %zu | - | %.3g contacts/s, %.0f B/contact, "
           "%.2f of roofline (target 0.8: %s)%s |\n", NBn, rate_gen, bytes_entry, roof_gen,
           roof_gen >= 0.8 ? "met" : "NOT met", unit_note);
    printf("| Hertz-Mindlin batch, dc_contact_force_shaped_inline | %zu | - | %.3g contacts/s, %.0f "
           "B/contact, %.2f of roofline (target 0.8: %s)%s |\n", NBn, rate_shaped, bytes_entry,
           roof_shaped, roof_shaped >= 0.8 ? "met" : "NOT met", unit_note);
    printf("| Hertz-Mindlin batch, hand-written CUDA | %zu | - | %.3g contacts/s, %.0f B/contact, %.2f "
           "of roofline; entries at %.2f (generic) and %.2f (shaped) of it%s |\n", NBn, rate_hand,
           bytes_hand, rate_hand * bytes_hand / copy_bw, rate_gen / rate_hand, rate_shaped / rate_hand,
           unit_note);
    printf("| Hertz-Mindlin batch, step-aware (dc_contact_model_set_step), dc_contact_force_inline | %zu "
           "| - | %.3g contacts/s, %.0f B/contact, %.2f of roofline; time per contact %.3f x the plain "
           "generic entry's%s |\n", NBn, rate_step, bytes_step, rate_step * bytes_step / copy_bw,
           rate_gen / rate_step, unit_note);

    const long total_cmp = cn.compared + cb.compared + ct.compared + cs.compared + bench_compared;
    const long total_diff = cn.differ + cb.differ + ct.differ + cs.differ + bench_diff;
    const Counts *stage[4] = {&cn, &cb, &ct, &cs};
    const char *names[4] = {"normal forces", "contact batch", "trajectories", "step-exact trajectories"};
    for (int s = 0; s < 4; s++) {
        if (!stage[s]->differ) continue;
        failed_stages++;
        printf("DIFFERENCES: %s: %ld of %ld; by kernel code:", names[s], stage[s]->differ,
               stage[s]->compared);
        for (int k = 1; k <= N_KERNELS; k++)
            if (stage[s]->kernel_diff[k]) printf(" %d:%ld", k, stage[s]->kernel_diff[k]);
        printf("\n");
    }
    if (bench_diff) {
        failed_stages++;
        printf("DIFFERENCES: timed batch: %ld of %ld\n", bench_diff, bench_compared);
    }
    if (o.plant) printf("gpu_check: --plant-ulp: one ulp planted in each of the 4 checked stages\n");
    if (!coverage_ok) printf("gpu_check: FAILED: a shape, kernel code or regime was not reached (see the table)\n");
    if (!hand_ok) printf("gpu_check: FAILED: the hand-written loop is not the entries' formula\n");
    printf("gpu_check: %ld values compared, %ld differences (%d stages differ)\n", total_cmp,
           total_diff, failed_stages);
    return total_diff || !coverage_ok || !hand_ok ? EXIT_DIFF : 0;
}
