/* demcontact_inline.h in CUDA device code: a kernel per contact and the calibration on the device.
 * Compiled (not run) by ctest's inline_cuda (nvcc, or clang with a CUDA installation) and
 * inline_cuda_stub (clang's CUDA mode without the SDK, cuda_stub.h standing in for its headers). */
#include <demcontact_inline.h>

__global__ void dc_forces(const dc_pair *pair, int n, const double *d, const double *vn,
                          const double *r, const double *m, double *out) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) out[i] = dc_normal_force_inline(pair, d[i], vn[i], r[i], m[i]);
}

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

__global__ void dc_contact_setup(const dc_contact_spec *spec, dc_contact_model *model, int *status) {
    *status = dc_contact_model_init_inline(spec, model);
}
