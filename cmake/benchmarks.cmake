# Force-kernel benchmark: demcontact's kernels through the C ABI and its header-only kernels in a C
# loop, against hand-written C loops of the same expressions, compiled as host codes do (-O3),
# with -fno-math-errno (vectorised sqrt) and with -march=native -fno-math-errno (the host CPU's
# widest vectors, also in the portable build: the baseline of the runtime dispatch), and the
# memory roofline. Run it with scripts/bench_force.sh; ctest only runs its --smoke check.

set(DC_BENCH_COPTS -O3)
if(DEMCONTACT_NATIVE)
  list(APPEND DC_BENCH_COPTS -march=native)
endif()
add_library(force_baseline_plain OBJECT examples_cpp/bench/force_baseline.c)
target_compile_definitions(force_baseline_plain PRIVATE BASE=plain)
target_compile_options(force_baseline_plain PRIVATE ${DC_BENCH_COPTS})
add_library(force_baseline_fast OBJECT examples_cpp/bench/force_baseline.c)
target_compile_definitions(force_baseline_fast PRIVATE BASE=fast)
target_compile_options(force_baseline_fast PRIVATE ${DC_BENCH_COPTS} -fno-math-errno)
add_library(force_baseline_native OBJECT examples_cpp/bench/force_baseline.c)
target_compile_definitions(force_baseline_native PRIVATE BASE=native)
target_compile_options(force_baseline_native PRIVATE -O3 -march=native -fno-math-errno)
# the same without FMA contraction: the rounding of the batch (whose bits equal the scalar call's),
# to tell the contraction's share of the gap to the native loop from the rest
add_library(force_baseline_native_nofma OBJECT examples_cpp/bench/force_baseline.c)
target_compile_definitions(force_baseline_native_nofma PRIVATE BASE=native_nofma)
target_compile_options(force_baseline_native_nofma PRIVATE -O3 -march=native -fno-math-errno -ffp-contract=off)
# an AVX2 machine's -march=native (x86-64-v3: AVX2, FMA), to compare with the batches capped at
# AVX2 (DEMCONTACT_DISPATCH=avx2) on a wider CPU; -march=native where the compiler lacks the name
include(CheckCCompilerFlag)
check_c_compiler_flag(-march=x86-64-v3 DC_CC_HAS_X86_64_V3)
if(DC_CC_HAS_X86_64_V3)
  set(DC_V3_ARCH -march=x86-64-v3)
else()
  set(DC_V3_ARCH -march=native)
endif()
add_library(force_baseline_v3 OBJECT examples_cpp/bench/force_baseline.c)
target_compile_definitions(force_baseline_v3 PRIVATE BASE=v3)
target_compile_options(force_baseline_v3 PRIVATE -O3 ${DC_V3_ARCH} -fno-math-errno)
foreach(b plain fast native native_nofma v3)
  target_include_directories(force_baseline_${b} PRIVATE "${CMAKE_SOURCE_DIR}/include")
endforeach()
foreach(kind IN ITEMS shared static)
  set(bench force_bench_${kind})
  add_executable(${bench} examples_cpp/bench/force_bench.c
    $<TARGET_OBJECTS:force_baseline_plain> $<TARGET_OBJECTS:force_baseline_fast>
    $<TARGET_OBJECTS:force_baseline_native> $<TARGET_OBJECTS:force_baseline_native_nofma>
    $<TARGET_OBJECTS:force_baseline_v3>)
  target_compile_options(${bench} PRIVATE ${DC_BENCH_COPTS} -Wall -Wextra -Werror)
  target_link_libraries(${bench} PRIVATE demcontact_${kind} ${DC_LIBM})
  if(NOT DC_CC_HAS_X86_64_V3)
    target_compile_definitions(${bench} PRIVATE DC_V3_IS_NATIVE=1)
  endif()
  set_target_properties(${bench} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/bench")
  add_test(NAME bench_${bench}_smoke COMMAND ${bench} --smoke)
endforeach()

# Full-contact benchmark (dc_contact_force_batch against hand-written Hertz-Mindlin-Coulomb C
# loops, -O3 and -O3 -fno-math-errno). Run it with scripts/bench_contact.sh; ctest only runs its
# --smoke correctness check (the C loops and the ABI agree).
add_library(contact_baseline_plain OBJECT examples_cpp/bench/contact_baseline.c)
target_compile_definitions(contact_baseline_plain PRIVATE BASE=plain)
target_compile_options(contact_baseline_plain PRIVATE ${DC_BENCH_COPTS})
add_library(contact_baseline_fast OBJECT examples_cpp/bench/contact_baseline.c)
target_compile_definitions(contact_baseline_fast PRIVATE BASE=fast)
target_compile_options(contact_baseline_fast PRIVATE ${DC_BENCH_COPTS} -fno-math-errno)
add_executable(contact_bench examples_cpp/bench/contact_bench.c
  $<TARGET_OBJECTS:contact_baseline_plain> $<TARGET_OBJECTS:contact_baseline_fast>)
target_compile_options(contact_bench PRIVATE ${DC_BENCH_COPTS} -Wall -Wextra -Werror)
target_link_libraries(contact_bench PRIVATE demcontact_shared ${DC_LIBM})
set_target_properties(contact_bench PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/bench")
add_test(NAME bench_contact_bench_smoke COMMAND contact_bench --smoke)

# Scalar full contact, library call vs header-only inline (examples_cpp/bench/contact_inline_bench.c;
# a benchmark, not a test: the bits are compared by ctest inline_contact_*).
add_executable(contact_inline_bench examples_cpp/bench/contact_inline_bench.c)
target_compile_options(contact_inline_bench PRIVATE ${DC_BENCH_COPTS} -Wall -Wextra -Werror)
target_link_libraries(contact_inline_bench PRIVATE demcontact_shared ${DC_LIBM})
set_target_properties(contact_inline_bench PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/bench")
