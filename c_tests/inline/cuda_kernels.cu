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
