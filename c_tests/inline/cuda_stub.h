/* Stand-ins for the CUDA SDK's declarations (clang -nocudainc): attributes and the device
 * functions demcontact_inline.h calls. Declarations only: the check compiles to PTX, links nothing. */
#define __host__ __attribute__((host))
#define __device__ __attribute__((device))
#define __global__ __attribute__((global))
#define __CUDACC__ 1
struct dci_uint3 { unsigned x, y, z; };
extern const __device__ dci_uint3 threadIdx, blockIdx, blockDim;
#ifdef __CUDA_ARCH__
__device__ double __dmul_rn(double, double);
__device__ long long __double_as_longlong(double);
__device__ double __longlong_as_double(long long);
__device__ double sqrt(double);
__device__ double exp(double);
__device__ double log(double);
__device__ double hypot(double, double);
__device__ double acos(double);
__device__ int isfinite(double);
__device__ double fabs(double);
__device__ double floor(double);
__device__ double sin(double);
__device__ double copysign(double, double);
__device__ double pow(double, double);
__device__ void *memset(void *, int, unsigned long);
__device__ void *memcpy(void *, const void *, unsigned long);
#endif
