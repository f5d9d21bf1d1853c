# C/C++/Fortran tests and examples, registered with ctest. Every c_tests/*.c and *.cpp is a test
# (c_<name>, and sanitize_<name> under ASan+UBSan); a test that needs more is one line:
#   dc_add_c_test(<name> <sources...> [LIBS <libraries...>])

set(DC_GNU_LIKE "$<OR:$<C_COMPILER_ID:GNU,Clang,AppleClang>,$<CXX_COMPILER_ID:GNU,Clang,AppleClang>>")
set(DC_TEST_WARNINGS
  "$<${DC_GNU_LIKE}:-Wall;-Wextra;-Werror>"
  "$<$<AND:${DC_GNU_LIKE},$<COMPILE_LANGUAGE:C>>:-std=c11>"
  "$<$<AND:${DC_GNU_LIKE},$<COMPILE_LANGUAGE:CXX>>:-std=c++17>")

# A C or C++ test program linked to the shared library, registered as c_<name>, and (with
# DEMCONTACT_SANITIZE and a GCC/Clang compiler) the same program under AddressSanitizer and
# UndefinedBehaviorSanitizer as sanitize_<name>: any report fails.
function(dc_add_c_test name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "LIBS")
  add_executable(${name} ${arg_UNPARSED_ARGUMENTS})
  target_link_libraries(${name} PRIVATE demcontact::demcontact ${DC_LIBM} Threads::Threads ${arg_LIBS})
  target_include_directories(${name} PRIVATE "${CMAKE_SOURCE_DIR}/c_tests")
  target_compile_options(${name} PRIVATE ${DC_TEST_WARNINGS})
  add_test(NAME c_${name} COMMAND ${name})
  if(DEMCONTACT_SANITIZE AND CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
    add_executable(${name}_asan ${arg_UNPARSED_ARGUMENTS})
    target_link_libraries(${name}_asan PRIVATE demcontact::demcontact ${DC_LIBM} Threads::Threads ${arg_LIBS})
    target_include_directories(${name}_asan PRIVATE "${CMAKE_SOURCE_DIR}/c_tests")
    target_compile_options(${name}_asan PRIVATE -fsanitize=address,undefined -fno-sanitize-recover=all
                                                -fno-omit-frame-pointer -g)
    target_link_options(${name}_asan PRIVATE -fsanitize=address,undefined)
    add_test(NAME sanitize_${name} COMMAND ${name}_asan)
    set_tests_properties(sanitize_${name} PROPERTIES
      ENVIRONMENT "ASAN_OPTIONS=detect_leaks=1:abort_on_error=1;UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
  endif()
endfunction()

file(GLOB DC_C_TESTS CONFIGURE_DEPENDS "${CMAKE_SOURCE_DIR}/c_tests/*.c" "${CMAKE_SOURCE_DIR}/c_tests/*.cpp")
foreach(src IN LISTS DC_C_TESTS)
  get_filename_component(name "${src}" NAME_WE)
  dc_add_c_test(${name} "${src}")
endforeach()

# Every top-level example is built and run as a test too (they check what they print).
file(GLOB DC_EXAMPLES CONFIGURE_DEPENDS "${CMAKE_SOURCE_DIR}/examples_cpp/*.cpp" "${CMAKE_SOURCE_DIR}/examples_cpp/*.c")
foreach(src IN LISTS DC_EXAMPLES)
  get_filename_component(name "${src}" NAME_WE)
  add_executable(${name} "${src}")
  target_link_libraries(${name} PRIVATE demcontact::demcontact)
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/examples_cpp")
  add_test(NAME example_${name} COMMAND ${name})
endforeach()

# Static linking, as HPC codes often do: the C consumer against the static library.
add_executable(static_c c_tests/consumer/main.c)
target_link_libraries(static_c PRIVATE demcontact::demcontact_static ${DC_LIBM})
add_test(NAME static_c COMMAND static_c)

if(TARGET demcontact_fortran)
  # The Fortran test (numbers, bad input through stat, constants and struct layouts against the
  # C compiler's view), linked dynamically and statically. Its sources are compiled once, into an
  # object library with its own module directory: two targets compiling abi_expect.f90 into one
  # module directory race under a parallel build ("Cannot rename module file").
  add_library(test_fortran_objects OBJECT
    c_tests/fortran/test_fortran.f90 c_tests/fortran/abi_expect.f90 c_tests/fortran/abi_probe.c)
  target_link_libraries(test_fortran_objects PRIVATE demcontact_fortran demcontact::demcontact)
  set_target_properties(test_fortran_objects PROPERTIES
    Fortran_MODULE_DIRECTORY "${CMAKE_BINARY_DIR}/fortran_test_modules")
  target_compile_options(test_fortran_objects PRIVATE
    "$<$<AND:$<COMPILE_LANGUAGE:Fortran>,$<Fortran_COMPILER_ID:GNU>>:-Wall;-std=f2018;-fimplicit-none>")
  foreach(kind IN ITEMS shared static)
    if(kind STREQUAL "shared")
      set(t test_fortran)
    else()
      set(t test_fortran_static)
    endif()
    add_executable(${t} $<TARGET_OBJECTS:test_fortran_objects>)
    target_link_libraries(${t} PRIVATE demcontact_fortran demcontact_${kind})
    set_target_properties(${t} PROPERTIES LINKER_LANGUAGE Fortran)
  endforeach()
  add_test(NAME fortran COMMAND test_fortran)
  add_test(NAME fortran_static COMMAND test_fortran_static)
  # The README's "From Fortran" program.
  add_executable(fortran_minimal c_tests/fortran/minimal.f90)
  target_link_libraries(fortran_minimal PRIVATE demcontact_fortran demcontact::demcontact)
  set_target_properties(fortran_minimal PROPERTIES LINKER_LANGUAGE Fortran
    Fortran_MODULE_DIRECTORY "${CMAKE_BINARY_DIR}/fortran_minimal_modules")
  add_test(NAME fortran_minimal COMMAND fortran_minimal)
  # C, C++ and Fortran must compute the same numbers, bit for bit.
  add_test(NAME cross_language_table
    COMMAND "${CMAKE_COMMAND}" "-DPROGRAMS=$<TARGET_FILE:common_table>;$<TARGET_FILE:test_cpp_wrapper>;$<TARGET_FILE:test_fortran>"
            -P "${CMAKE_SOURCE_DIR}/cmake/CompareTables.cmake")
endif()

# A user's view: install into a scratch prefix, then build a separate project against the
# installed package with find_package(demcontact CONFIG) and with pkg-config.
add_test(NAME installed_package
  COMMAND "${CMAKE_COMMAND}"
    -DBUILD_DIR=${CMAKE_BINARY_DIR}
    -DSOURCE_DIR=${CMAKE_SOURCE_DIR}
    -DPREFIX=${CMAKE_BINARY_DIR}/install-test
    -DGENERATOR=${CMAKE_GENERATOR}
    -DC_COMPILER=${CMAKE_C_COMPILER}
    -P "${CMAKE_SOURCE_DIR}/cmake/TestInstalled.cmake")
set_tests_properties(installed_package PROPERTIES SKIP_REGULAR_EXPRESSION "SKIPPED: ")
