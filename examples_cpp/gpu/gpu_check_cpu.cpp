/* gpu_check.cu compiled as host C++ (no CUDA): the CPU stand-in of its device launches. */
#include "gpu_check.cu"
