/* demcontact_inline.h in CUDA device code: a kernel per contact and the calibration on the device.
 * Compiled (not run: no GPU in CI) by ctest's inline_cuda (nvcc, or clang with a CUDA
 * installation; with nvcc also inside test_inline_nvcc.cu / test_inline_contact_nvcc.cu, whose
 * host side runs) and inline_cuda_stub (clang's CUDA mode without the SDK, cuda_stub.h standing in
 * for its headers). */
#include <demcontact_inline.h>

__global__ void dc_forces(const dc_pair *pair, int n, const double *d, const double *vn,
                          const double *r, const double *m, double *out) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) out[i] = dc_normal_force_inline(pair, d[i], vn[i], r[i], m[i]);
}

/* Every kernel code, 1 to 19 (none needs libm: only + - * / sqrt and dc_pow_inline, DMT's
 * reach included), each with its code as a constant: ctest inline_cuda compiles this one to a cubin with -fmad=true (nvcc's default) and
 * with -fmad=false and requires the same machine code, i.e. nothing in it was fused. */
#define DCI_CASE(K)                                                                   \
    case K: out[i] = dc_normal_force_kernel_inline(K, pair, d[i], vn[i], r[i], m[i]); \
        break;
__global__ void dc_forces_arith(const dc_pair *pair, int n, const double *d, const double *vn,
                                const double *r, const double *m, double *out) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    switch (pair->kernel) {
        DCI_CASE(1) DCI_CASE(2) DCI_CASE(3) DCI_CASE(4) DCI_CASE(5) DCI_CASE(6) DCI_CASE(7)
        DCI_CASE(8) DCI_CASE(9) DCI_CASE(10) DCI_CASE(11) DCI_CASE(12) DCI_CASE(13)
        DCI_CASE(14) DCI_CASE(15) DCI_CASE(16) DCI_CASE(17) DCI_CASE(18) DCI_CASE(19)
    default: out[i] = 0.0;
    }
}
#undef DCI_CASE

__global__ void dc_setup(double e, dc_pair *pair) {
    dc_pair_hertz_inline(63e9, 0.23, 63e9, 0.23, e, DC_END_FORCE, pair);
}

/* The full contact on the device: one thread per contact, its history in device memory. */
__global__ void dc_contacts(const dc_contact_model *model, int n, const dc_contact_state *state,
                            double dt, double *history, dc_contact_result *out, int *status) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n)
        status[i] = dc_contact_force_inline(model, &state[i], dt,
                                            history + (long)i * DC_CONTACT_HISTORY_MAX,
                                            DC_CONTACT_HISTORY_MAX, &out[i]);
}

/* The shaped fast entry on the device (Hertz, force-clamped, Mindlin, EPSD rolling, projection
 * carry as constants), after the shape check of the model. */
__global__ void dc_contacts_shaped(const dc_contact_model *model, int n, const dc_contact_state *state,
                                   double dt, double *history, dc_contact_result *out, int *status) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    if (dc_contact_model_shape_inline(model, DC_KERNEL_HERTZ_DAMPED_CLAMPED, DC_TANGENTIAL_MINDLIN,
                                      DC_ROLLING_EPSD, DC_TWISTING_NONE, DC_CARRY_PROJECT) != DC_OK) {
        status[i] = DC_ERR_CONTACT_MODEL_INVALID;
        return;
    }
    status[i] = dc_contact_force_shaped_inline(model, DC_KERNEL_HERTZ_DAMPED_CLAMPED, DC_TANGENTIAL_MINDLIN,
                                               DC_ROLLING_EPSD, DC_TWISTING_NONE, DC_CARRY_PROJECT, &state[i],
                                               dt, history + (long)i * DC_CONTACT_HISTORY_MAX, &out[i]);
}

/* The deferred entry on the device: each thread's checks in its slot (a host merges the slots
 * with dc_contact_checks_merge_inline and tests them with dc_contact_checks_status_inline after
 * the pass); the state check once per contact here, a host would check its arrays instead. */
__global__ void dc_contacts_deferred(const dc_contact_model *model, int n, const dc_contact_state *state,
                                     double dt, double *history, dc_contact_result *out, int *status,
                                     dc_contact_checks *checks) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    dc_contact_checks c;
    dc_contact_checks_init_inline(&c);
    status[i] = dc_contact_state_check_inline(&state[i], dt);
    dc_contact_force_shaped_deferred_inline(model, DC_KERNEL_HERTZ_DAMPED_CLAMPED, DC_TANGENTIAL_MINDLIN,
                                            DC_ROLLING_EPSD, DC_TWISTING_NONE, DC_CARRY_PROJECT, &state[i], dt,
                                            history + (long)i * DC_CONTACT_HISTORY_MAX, &out[i], &c);
    checks[i] = c;
}

__global__ void dc_contact_setup(const dc_contact_spec *spec, dc_contact_model *model, int *status) {
    *status = dc_contact_model_init_inline(spec, model);
}
