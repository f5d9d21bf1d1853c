# Builds and runs c_tests/inline/test_inline.c with a second compiler or compiles the CUDA check.
#   -DMODE=clang   clang -O3 -march=native (default contraction: bits), and with
#                  -ffp-contract=fast (clang then ignores the header's pragma: within 8 ulp)
#   -DMODE=cuda    nvcc, or clang++ -x cuda with a CUDA installation: compile cuda_kernels.cu
#   -DMODE=cuda_stub  clang++ -x cuda -nocudainc --cuda-device-only with cuda_stub.h: device PTX
# A missing compiler prints "SKIPPED: <name> (<reason>)" and stops; the test's
# SKIP_REGULAR_EXPRESSION turns that line into ctest's "Skipped" (never a pass).
# Inputs: SRC (source dir), LIBDIR (libdemcontact.so), OUT (scratch dir), N (inputs per kernel).
function(skip name reason)
  message(FATAL_ERROR "SKIPPED: ${name} (${reason})")
endfunction()
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}")
  endif()
endfunction()
file(MAKE_DIRECTORY "${OUT}")
set(inc "-I${SRC}/include")
if(MODE STREQUAL "clang")
  find_program(CLANG clang)
  if(NOT CLANG)
    skip(inline_clang "clang not installed")
  endif()
  set(link -L${LIBDIR} -ldemcontact -lm -Wl,-rpath,${LIBDIR})
  run(${CLANG} -std=c99 -O3 -march=native -Wall -Wextra -Werror ${inc}
      ${SRC}/c_tests/inline/test_inline.c ${link} -o ${OUT}/test_inline_clang)
  run(${OUT}/test_inline_clang ${N})
  run(${CLANG} -std=c99 -O3 -march=native -ffp-contract=fast -DDCI_TEST_ULPS=8 -Wall -Wextra
      -Werror ${inc} ${SRC}/c_tests/inline/test_inline.c ${link} -o ${OUT}/test_inline_clang_fast)
  run(${OUT}/test_inline_clang_fast ${N})
  run(${CLANG} -std=c99 -O3 -march=native -Wall -Wextra -Werror ${inc}
      ${SRC}/c_tests/inline/test_inline_contact.c ${link} -o ${OUT}/test_inline_contact_clang)
  run(${OUT}/test_inline_contact_clang ${N})
elseif(MODE STREQUAL "cuda")
  find_program(NVCC nvcc)
  find_program(CLANGXX clang++)
  if(NVCC)
    run(${NVCC} -std=c++17 ${inc} -c ${SRC}/c_tests/inline/cuda_kernels.cu -o ${OUT}/cuda_kernels.o)
  elseif(CLANGXX)
    execute_process(COMMAND ${CLANGXX} -x cuda -std=c++17 --cuda-gpu-arch=sm_70 ${inc}
                    -c ${SRC}/c_tests/inline/cuda_kernels.cu -o ${OUT}/cuda_kernels.o
                    RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
    if(NOT rc EQUAL 0 AND err MATCHES "cannot find (CUDA installation|libdevice)")
      skip(inline_cuda "no nvcc, and clang finds no CUDA installation")
    elseif(NOT rc EQUAL 0)
      message(FATAL_ERROR "clang CUDA compile failed:\n${err}")
    endif()
  else()
    skip(inline_cuda "neither nvcc nor clang++ installed")
  endif()
elseif(MODE STREQUAL "cuda_stub")
  find_program(CLANGXX clang++)
  if(NOT CLANGXX)
    skip(inline_cuda_stub "clang++ not installed")
  endif()
  run(${CLANGXX} -x cuda -std=c++17 --cuda-gpu-arch=sm_70 -nocudainc -nocudalib
      --cuda-device-only -Wall -Wextra -Werror -include ${SRC}/c_tests/inline/cuda_stub.h ${inc}
      -S ${SRC}/c_tests/inline/cuda_kernels.cu -o ${OUT}/cuda_kernels.ptx)
  file(READ "${OUT}/cuda_kernels.ptx" ptx)
  if(NOT ptx MATCHES "dc_forces" OR NOT ptx MATCHES "dc_contacts" OR NOT ptx MATCHES "__dmul_rn")
    message(FATAL_ERROR "PTX lacks the kernel or the unfused products (__dmul_rn)")
  endif()
  message("device PTX for dc_forces/dc_setup/dc_contacts generated (products through __dmul_rn)")
else()
  message(FATAL_ERROR "unknown MODE ${MODE}")
endif()
