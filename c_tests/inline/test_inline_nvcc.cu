/* test_inline.c compiled by nvcc as CUDA C++ and run on the host: the header's __host__ __device__
 * functions, as nvcc's host compilation emits them, against the library bit for bit (every dc_pair
 * kernel 1..17, the constructors, the calibrations). cuda_kernels.cu rides along so that the same
 * translation unit also carries the device code (cicc to PTX, ptxas to a cubin). */
#include "test_inline.c"
#include "cuda_kernels.cu"
