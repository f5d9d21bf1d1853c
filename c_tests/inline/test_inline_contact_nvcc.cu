/* test_inline_contact.c compiled by nvcc as CUDA C++ and run on the host: the full contact
 * (dc_contact_force_inline with its history, dc_contact_model_init_inline, the DMT kernels 18 and
 * 19) as nvcc's host compilation emits it, against the library bit for bit. cuda_kernels.cu rides
 * along so that the translation unit also carries the device code (PTX, cubin). */
#include "test_inline_contact.c"
#include "cuda_kernels.cu"
