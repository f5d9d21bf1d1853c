# Header-only kernels (include/demcontact_inline.h): bit-identical to the library over 10^7 random
# inputs per kernel, as C99 and as C++17 (-Wall -Wextra -Werror), once more with FMA contraction
# forced on (-march=native -ffp-contract=fast), with clang, and as CUDA where a CUDA compiler
# exists (nvcc: the host side run against the library, the device code compiled to cubins; else
# the test prints "SKIPPED: <name> (<reason>)" and ctest reports it skipped); the header-only example links nothing of demcontact (only libm), as C99 and C++17.

add_executable(test_inline_c c_tests/inline/test_inline.c)
target_compile_options(test_inline_c PRIVATE -std=c99 -pedantic -Wall -Wextra -Werror -O2)
add_executable(test_inline_cpp c_tests/inline/test_inline.cpp)
target_compile_options(test_inline_cpp PRIVATE -std=c++17 -Wall -Wextra -Werror -O2)
add_executable(test_inline_fma c_tests/inline/test_inline.c)
target_compile_options(test_inline_fma PRIVATE -std=gnu11 -O3 -march=native -ffp-contract=fast
                                               -Wall -Wextra -Werror)
# The full contact (dc_contact_force_inline, dc_contact_model_init_inline): bits of results and
# histories over many-step trajectories of random models, statuses of bad input.
add_executable(test_inline_contact_c c_tests/inline/test_inline_contact.c)
target_compile_options(test_inline_contact_c PRIVATE -std=c99 -pedantic -Wall -Wextra -Werror -O2)
add_executable(test_inline_contact_cpp c_tests/inline/test_inline_contact.cpp)
target_compile_options(test_inline_contact_cpp PRIVATE -std=c++17 -Wall -Wextra -Werror -O2)
add_executable(test_inline_contact_fma c_tests/inline/test_inline_contact.c)
target_compile_definitions(test_inline_contact_fma PRIVATE DC_TEST_CONTRACTED)
target_compile_options(test_inline_contact_fma PRIVATE -std=gnu11 -O3 -march=native
                                                       -ffp-contract=fast -Wall -Wextra -Werror)
# DEMCONTACT_INLINE_PLAIN_PRODUCTS (plain products, no per-product barrier) in a build with
# contraction off and FMA available: the library's bits (the plugins build this way).
add_executable(test_inline_contact_plain c_tests/inline/test_inline_contact.c)
target_compile_definitions(test_inline_contact_plain PRIVATE DEMCONTACT_INLINE_PLAIN_PRODUCTS)
target_compile_options(test_inline_contact_plain PRIVATE -std=gnu11 -O3 -march=native
                                                         -ffp-contract=off -Wall -Wextra -Werror)
# The plugins' choice of the shaped entry (plugins/common/demcontact_shaped.h): the right
# instantiation per model shape, the library's bits along trajectories.
add_executable(test_shaped_pick c_tests/inline/test_shaped_pick.cpp)
target_include_directories(test_shaped_pick PRIVATE plugins/common)
target_compile_options(test_shaped_pick PRIVATE -std=c++17 -Wall -Wextra -Werror -O2)
foreach(t test_inline_c test_inline_cpp test_inline_fma test_inline_contact_c
          test_inline_contact_cpp test_inline_contact_fma test_inline_contact_plain test_shaped_pick)
  target_link_libraries(${t} PRIVATE demcontact::demcontact ${DC_LIBM})
endforeach()
add_test(NAME inline_c COMMAND test_inline_c 10000000)
add_test(NAME inline_cpp COMMAND test_inline_cpp 10000000)
add_test(NAME inline_fma COMMAND test_inline_fma 2000000)
add_test(NAME inline_contact_c COMMAND test_inline_contact_c 10000000)
add_test(NAME inline_contact_cpp COMMAND test_inline_contact_cpp 10000000)
add_test(NAME inline_contact_fma COMMAND test_inline_contact_fma 2000000)
add_test(NAME inline_contact_plain COMMAND test_inline_contact_plain 2000000)
add_test(NAME inline_shaped_pick COMMAND test_shaped_pick 20000)
# The LIGGGHTS plugin's per-pass scan of atom arrays (plugins/common/scan_bad_values.h): each
# variant this CPU runs (baseline, AVX2) against std::isfinite and > 0.
add_executable(test_scan_bad_values c_tests/inline/test_scan_bad_values.cpp)
target_include_directories(test_scan_bad_values PRIVATE plugins/common)
target_compile_options(test_scan_bad_values PRIVATE -std=c++17 -Wall -Wextra -Werror -O2)
add_test(NAME sim_scan_bad_values COMMAND test_scan_bad_values 2000)
# nvcc for inline_cuda: from DEMCONTACT_CUDA_VENV (a venv holding NVIDIA's nvcc wheels, made by
# scripts/setup_cuda.sh; scripts/test.sh passes it), else PATH. Not found: inline_cuda tries clang,
# then says SKIPPED.
set(DEMCONTACT_CUDA_VENV "" CACHE PATH "venv with NVIDIA's nvcc wheels (scripts/setup_cuda.sh)")
set(_dc_nvcc_hints "")
if(DEMCONTACT_CUDA_VENV)
  file(GLOB _dc_nvcc_hints "${DEMCONTACT_CUDA_VENV}/lib/python3*/site-packages/nvidia/cu*/bin")
endif()
find_program(DEMCONTACT_NVCC nvcc HINTS ${_dc_nvcc_hints} DOC "nvcc for ctest inline_cuda")
foreach(mode clang clang_contact cuda cuda_contact cuda_stub)
  add_test(NAME inline_${mode}
    COMMAND "${CMAKE_COMMAND}" -DMODE=${mode} -DSRC=${CMAKE_SOURCE_DIR} -DLIBDIR=${DC_LIB_DIR}
            -DNVCC=${DEMCONTACT_NVCC}
            -DOUT=${CMAKE_BINARY_DIR}/inline_${mode} -DN=2000000
            -P "${CMAKE_SOURCE_DIR}/cmake/InlineCompilers.cmake")
  set_tests_properties(inline_${mode} PROPERTIES SKIP_REGULAR_EXPRESSION "SKIPPED: ")
endforeach()
# ctest starts the costliest tests first. A fresh clone has no timing history
# (Testing/Temporary/CTestCostData.txt), so the long ones carry their seconds (a CI run at -j2 on
# 2 loaded cores; the CUDA halves by their CPU seconds). docs/ci.md: scripts/ctest_replay.py.
set_tests_properties(inline_clang_contact PROPERTIES COST 500)
set_tests_properties(inline_cuda_contact PROPERTIES COST 260)
set_tests_properties(inline_cuda PROPERTIES COST 35)

# The GPU check (examples_cpp/gpu/gpu_check.cu, scripts/gpu_check.sh, docs/gpu.md). Here, without
# a GPU: its CPU smoke (the same source as host C++, each device launch a loop on the CPU: the
# generators, the library reference, the comparisons and the table over all 912 model shapes);
# the same run with one ulp planted on the "device" side in each checked stage, which must end
# with exit 1 and 4 stages reported; bad arguments (exit 2); and the nvcc build (gpu_check_nvcc,
# skipped without nvcc as inline_cuda is).
add_executable(gpu_check_cpu examples_cpp/gpu/gpu_check_cpu.cpp)
target_compile_options(gpu_check_cpu PRIVATE -std=c++17 -Wall -Wextra -Werror -O2 -ffp-contract=off)
target_link_libraries(gpu_check_cpu PRIVATE demcontact::demcontact ${DC_LIBM})
add_test(NAME gpu_check_cpu_smoke COMMAND gpu_check_cpu --cpu-smoke)
add_test(NAME gpu_check_cpu_smoke_plant COMMAND sh -c [=[
out=$("$0" --cpu-smoke --plant-ulp 2>&1); rc=$?; printf '%s\n' "$out"
n=$(printf '%s\n' "$out" | grep -c '^DIFFERENCES: ')
[ "$rc" = 1 ] && [ "$n" = 4 ] || { echo "FAIL: exit $rc with $n stages differing (want exit 1, 4 stages)"; exit 1; }
echo "the planted one-ulp differences were caught: exit 1, 4 stages"]=] $<TARGET_FILE:gpu_check_cpu>)
add_test(NAME gpu_check_cpu_args COMMAND sh -c [=[
for args in "" "--cpu-smoke --steps x" "--cpu-smoke --bench" "--cpu-smoke --trajectories 10" "--cpu-smoke --what"; do
  "$0" $args >/dev/null 2>&1; rc=$?
  [ "$rc" = 2 ] || { echo "FAIL: '$args': exit $rc, want 2"; exit 1; }
done
echo "bad arguments: exit 2 each"]=] $<TARGET_FILE:gpu_check_cpu>)
add_test(NAME gpu_check_nvcc
  COMMAND "${CMAKE_COMMAND}" -DMODE=gpu_check -DSRC=${CMAKE_SOURCE_DIR} -DLIBDIR=${DC_LIB_DIR}
          -DNVCC=${DEMCONTACT_NVCC} -DOUT=${CMAKE_BINARY_DIR}/gpu_check_nvcc
          -P "${CMAKE_SOURCE_DIR}/cmake/InlineCompilers.cmake")
set_tests_properties(gpu_check_nvcc PROPERTIES SKIP_REGULAR_EXPRESSION "SKIPPED: ")

add_executable(header_only_c examples_cpp/inline/header_only.c)
target_compile_options(header_only_c PRIVATE -std=c99 -pedantic -Wall -Wextra -Werror)
target_link_libraries(header_only_c PRIVATE ${DC_LIBM})
add_executable(header_only_cpp examples_cpp/inline/header_only.cpp)
target_compile_options(header_only_cpp PRIVATE -std=c++17 -Wall -Wextra -Werror)
add_executable(header_only_contact_c examples_cpp/inline/header_only_contact.c)
target_compile_options(header_only_contact_c PRIVATE -std=c99 -pedantic -Wall -Wextra -Werror)
target_link_libraries(header_only_contact_c PRIVATE ${DC_LIBM})
add_executable(header_only_contact_cpp examples_cpp/inline/header_only_contact.cpp)
target_compile_options(header_only_contact_cpp PRIVATE -std=c++17 -Wall -Wextra -Werror)
foreach(t header_only_c header_only_cpp header_only_contact_c header_only_contact_cpp)
  target_include_directories(${t} PRIVATE "${CMAKE_SOURCE_DIR}/include")
  set_target_properties(${t} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/examples_cpp")
  add_test(NAME example_${t} COMMAND ${t})
endforeach()
