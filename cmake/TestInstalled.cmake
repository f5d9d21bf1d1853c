# ctest case "installed_package": what a user does. Installs the build into PREFIX, builds
# c_tests/consumer against it with find_package(demcontact CONFIG) (shared and static), runs it,
# and compiles the same program with the flags from the installed pkg-config file.
file(REMOVE_RECURSE "${PREFIX}" "${BUILD_DIR}/consumer-build")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()

run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}")
run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}/c_tests/consumer" -B "${BUILD_DIR}/consumer-build"
    -G "${GENERATOR}" "-DCMAKE_PREFIX_PATH=${PREFIX}" "-DCMAKE_C_COMPILER=${C_COMPILER}")
run("${CMAKE_COMMAND}" --build "${BUILD_DIR}/consumer-build")
run("${BUILD_DIR}/consumer-build/consumer")
run("${BUILD_DIR}/consumer-build/consumer_static")

find_program(PKG_CONFIG pkg-config)
if(PKG_CONFIG)
  file(GLOB_RECURSE pcfile "${PREFIX}/*/demcontact.pc")
  get_filename_component(pcdir "${pcfile}" DIRECTORY)
  set(ENV{PKG_CONFIG_PATH} "${pcdir}")
  execute_process(COMMAND "${PKG_CONFIG}" --cflags --libs demcontact OUTPUT_VARIABLE flags
                  OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pkg-config cannot find the installed demcontact.pc")
  endif()
  separate_arguments(flags UNIX_COMMAND "${flags}")
  run("${C_COMPILER}" "${SOURCE_DIR}/c_tests/consumer/main.c" ${flags} -lm -o "${BUILD_DIR}/consumer-build/consumer_pc")
  set(ENV{LD_LIBRARY_PATH} "${pcdir}/..")
  run("${BUILD_DIR}/consumer-build/consumer_pc")
else()
  # The CMake consumer above passed; the pkg-config one did not run: a skip, not a pass.
  message(FATAL_ERROR "SKIPPED: installed_package's pkg-config check (pkg-config not installed; "
                      "the find_package consumer passed)")
endif()
