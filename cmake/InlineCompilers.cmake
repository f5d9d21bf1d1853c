# Builds and runs c_tests/inline/test_inline.c with a second compiler or compiles the CUDA check.
#   -DMODE=clang   test_inline.c by clang -O3 -march=native (default contraction: bits), and with
#                  -ffp-contract=fast (clang then ignores the header's pragma: within 8 ulp)
#   -DMODE=clang_contact  test_inline_contact.c by clang -O3 -march=native (bits; its 240
#                  constant-shape instantiations make this the costliest compile of the suite,
#                  so it is its own ctest case, started first, beside the others)
#   -DMODE=cuda    nvcc (-DNVCC=<path>, else PATH): the checks of nvcc_checks() below for
#                  test_inline and the sm_90 cubins; else clang++ -x cuda with a CUDA
#                  installation: compile cuda_kernels.cu
#   -DMODE=cuda_contact  nvcc: the checks of nvcc_checks() below for test_inline_contact (its
#                  own ctest case for the same reason as clang_contact); skipped without nvcc
#   -DMODE=cuda_stub  clang++ -x cuda -nocudainc --cuda-device-only with cuda_stub.h: device PTX
#   -DMODE=gpu_check  nvcc builds examples_cpp/gpu/gpu_check.cu (the GPU check) and runs it briefly
# A missing compiler prints "SKIPPED: <name> (<reason>)" and stops; the test's
# SKIP_REGULAR_EXPRESSION turns that line into ctest's "Skipped" (never a pass).
# Inputs: SRC (source dir), LIBDIR (libdemcontact.so), OUT (scratch dir), N (inputs per kernel),
# NVCC (optional: the nvcc to use).
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
# The nvcc checks (no GPU here: device code is compiled, never run).
#  1. test_inline.c and test_inline_contact.c compiled by nvcc as CUDA (test_inline_nvcc.cu,
#     test_inline_contact_nvcc.cu, each with cuda_kernels.cu: device code through cicc to PTX and
#     ptxas to an sm_75 cubin in the same binary), and their host side run against the library:
#     every dc_pair kernel, constructors, calibrations, the full contact with its history, bit for
#     bit. Twice: nvcc -O2 (host: x86-64 baseline, no FMA), and with the host compiler on FMA
#     hardware (-Xcompiler -O3,-march=native,-ffp-contract=off: nvcc's front end lacks
#     __builtin_assoc_barrier, so the header's host side under nvcc needs contraction off).
#  2. dc_forces_arith (all 19 kernels: none needs libm) compiled to an sm_90 cubin with -fmad=true
#     (nvcc's default) and -fmad=false: its machine code must be the same bytes, i.e. nothing was
#     fused and every + - * / sqrt is rounded as on the host (prec-div, prec-sqrt on by default).
# nvcc_checks(CUBINS PROGRAMS...): each program's two nvcc builds and runs (item 1), and item 2
# where CUBINS is ON.
function(nvcc_checks cubins)
  get_filename_component(bindir "${NVCC}" DIRECTORY)
  set(nv ${NVCC} -std=c++17 -Werror all-warnings -Xcompiler -Wall,-Wextra,-Werror ${inc})
  set(link -L${bindir}/../lib -L${LIBDIR} -ldemcontact -lm -Xlinker -rpath,${LIBDIR})
  run(${NVCC} --version)
  # The FMA-host run at N/2: at N/4 its constant-shape steps fell below the coverage check's
  # tenth of the run-time ones (90041 against 910375, 144 shapes).
  math(EXPR half "${N} / 2")
  foreach(t IN LISTS ARGN)
    run(${nv} -O2 -arch=sm_75 ${SRC}/c_tests/inline/${t}_nvcc.cu ${link} -o ${OUT}/${t}_nvcc)
    run(${OUT}/${t}_nvcc ${N})
    run(${nv} -arch=sm_75 -Xcompiler -O3,-march=native,-ffp-contract=off
        ${SRC}/c_tests/inline/${t}_nvcc.cu ${link} -o ${OUT}/${t}_nvcc_native)
    run(${OUT}/${t}_nvcc_native ${half})
  endforeach()
  if(NOT cubins)
    return()
  endif()
  find_program(READELF readelf)
  if(NOT READELF)
    message(FATAL_ERROR "readelf (binutils) not found: cannot compare the cubins")
  endif()
  foreach(fmad true false)
    run(${nv} -arch=sm_90 -fmad=${fmad} -cubin ${SRC}/c_tests/inline/cuda_kernels.cu
        -o ${OUT}/cuda_kernels_fmad_${fmad}.cubin)
    execute_process(COMMAND ${READELF} -S -W ${OUT}/cuda_kernels_fmad_${fmad}.cubin
                    OUTPUT_VARIABLE sections ERROR_QUIET)
    string(REGEX MATCH "\\.text\\.[A-Za-z0-9_]*dc_forces_arith[A-Za-z0-9_]*" sec "${sections}")
    if(NOT sec)
      message(FATAL_ERROR "no dc_forces_arith code section in the -fmad=${fmad} cubin")
    endif()
    execute_process(COMMAND ${READELF} -x ${sec} ${OUT}/cuda_kernels_fmad_${fmad}.cubin
                    OUTPUT_VARIABLE hex_${fmad} ERROR_QUIET)
    string(LENGTH "${hex_${fmad}}" len_${fmad})
  endforeach()
  if(len_true LESS 1000 OR NOT hex_true STREQUAL hex_false)
    file(WRITE ${OUT}/dc_forces_arith_fmad_true.hex "${hex_true}")
    file(WRITE ${OUT}/dc_forces_arith_fmad_false.hex "${hex_false}")
    message(FATAL_ERROR "dc_forces_arith: the sm_90 machine code differs between -fmad=true and "
            "-fmad=false (a product fused with an addition; hex dumps in ${OUT})")
  endif()
  message("dc_forces_arith: sm_90 machine code identical with -fmad=true and -fmad=false "
          "(${len_true} characters of hex dump): no contraction in the 19 force kernels")
endfunction()

# NVCC: the build's DEMCONTACT_NVCC (scripts/setup_cuda.sh installs NVIDIA's nvcc wheels into
# .venv-cuda; scripts/test.sh passes it to CMake), else an nvcc on PATH.
macro(resolve_nvcc)
  if(NOT NVCC OR NOT EXISTS "${NVCC}")
    find_program(NVCC_ON_PATH nvcc)
    set(NVCC "${NVCC_ON_PATH}")
  endif()
endmacro()

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
elseif(MODE STREQUAL "clang_contact")
  find_program(CLANG clang)
  if(NOT CLANG)
    skip(inline_clang_contact "clang not installed")
  endif()
  set(link -L${LIBDIR} -ldemcontact -lm -Wl,-rpath,${LIBDIR})
  run(${CLANG} -std=c99 -O3 -march=native -Wall -Wextra -Werror ${inc}
      ${SRC}/c_tests/inline/test_inline_contact.c ${link} -o ${OUT}/test_inline_contact_clang)
  run(${OUT}/test_inline_contact_clang ${N})
elseif(MODE STREQUAL "cuda")
  resolve_nvcc()
  find_program(CLANGXX clang++)
  if(NVCC)
    nvcc_checks(ON test_inline)
  elseif(CLANGXX)
    execute_process(COMMAND ${CLANGXX} -x cuda -std=c++17 --cuda-gpu-arch=sm_70 ${inc}
                    -c ${SRC}/c_tests/inline/cuda_kernels.cu -o ${OUT}/cuda_kernels.o
                    RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
    if(NOT rc EQUAL 0 AND err MATCHES "cannot find (CUDA installation|libdevice)")
      skip(inline_cuda "no nvcc (scripts/setup_cuda.sh installs one), and clang finds no CUDA installation")
    elseif(NOT rc EQUAL 0)
      message(FATAL_ERROR "clang CUDA compile failed:\n${err}")
    endif()
    # Compiled, but none of nvcc_checks ran (the host-side bit-for-bit runs, the -fmad cubin
    # comparison): a skip, not a pass.
    skip(inline_cuda "no nvcc: clang++ compiled the device kernels; the nvcc checks did not run")
  else()
    skip(inline_cuda "neither nvcc (scripts/setup_cuda.sh installs one) nor clang++ installed")
  endif()
elseif(MODE STREQUAL "cuda_contact")
  resolve_nvcc()
  if(NOT NVCC)
    skip(inline_cuda_contact "no nvcc (scripts/setup_cuda.sh installs one)")
  endif()
  nvcc_checks(OFF test_inline_contact)
elseif(MODE STREQUAL "gpu_check")
  # examples_cpp/gpu/gpu_check.cu built by nvcc as scripts/gpu_check.sh builds it (sm_90,
  # -fmad=false), against the shared library. Without a GPU it must stop with its CUDA error
  # (exit 3), never pass; with one, a short run must pass.
  resolve_nvcc()
  if(NOT NVCC)
    skip(gpu_check_nvcc "no nvcc (scripts/setup_cuda.sh installs one)")
  endif()
  get_filename_component(bindir "${NVCC}" DIRECTORY)
  run(${NVCC} -std=c++17 -O3 -arch=sm_90 -fmad=false -Werror all-warnings
      -Xcompiler -Wall,-Wextra,-Werror,-ffp-contract=off ${inc} ${SRC}/examples_cpp/gpu/gpu_check.cu
      -L${bindir}/../lib -L${LIBDIR} -ldemcontact -lm -Xlinker -rpath,${LIBDIR} -o ${OUT}/gpu_check)
  execute_process(COMMAND ${OUT}/gpu_check --contacts 1000 --normals 1000 --trajectories 912
                          --steps 2 --bench 4096
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message("${out}gpu_check built by nvcc and run on this machine's GPU: passed")
  elseif(rc EQUAL 3 AND err MATCHES "gpu_check: CUDA error")
    message("gpu_check built by nvcc (sm_90 cubin, -fmad=false); no GPU here: it stopped with "
            "its CUDA error and exit 3, as it must (${err})")
  else()
    message(FATAL_ERROR "gpu_check (nvcc build): exit ${rc}\n${out}${err}")
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
