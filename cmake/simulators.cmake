# demcontact inside real DEM codes: the LIGGGHTS contact-model plugin and the LAMMPS pair/wall
# plugin, each in its own directory with its install rule and the ctest cases that run it. With
# the tests, those are registered either way and SKIP (exit 77) with the reason where the
# simulator is missing (scripts/setup_simulators.sh installs both).

if(DEMCONTACT_BUILD_TESTS)
  # The library's own oblique sphere-wall impact, the reference of the simulators' oblique tests.
  add_executable(dc_oblique_ref tests/simulators/oblique_ref.c)
  target_link_libraries(dc_oblique_ref PRIVATE demcontact::demcontact m)
  set_target_properties(dc_oblique_ref PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/simulators")
  # The library's own adhesive (JKR, DMT) head-on impacts, the reference of tests/simulators/adhesion.py.
  add_executable(dc_adhesion_ref tests/simulators/adhesion_ref.c)
  target_link_libraries(dc_adhesion_ref PRIVATE demcontact::demcontact m)
  set_target_properties(dc_adhesion_ref PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/simulators")
  # The harness as a package: no sys.path edits, no import cycles, every module imports cleanly,
  # both simulators implement its interface (no simulator needed).
  find_package(Python3 COMPONENTS Interpreter QUIET)
  if(Python3_Interpreter_FOUND)
    add_test(NAME simulators_package COMMAND "${Python3_EXECUTABLE}" "${CMAKE_SOURCE_DIR}/tests/simulators/check_package.py")
  else()
    add_test(NAME simulators_package COMMAND sh -c "echo 'SKIPPED: simulators_package (no python3 interpreter)'; exit 77")
  endif()
  set_tests_properties(simulators_package PROPERTIES SKIP_RETURN_CODE 77)
endif()

# A plugin whose simulator is missing (the caller returns right after): the configure says what is
# missing; with the tests, each of the plugin's tests is registered as a SKIP (exit 77) naming it.
function(dc_plugin_missing simulator missing)
  message(STATUS "demcontact: ${simulator} plugin not built, missing: ${missing} (run scripts/setup_simulators.sh)")
  if(DEMCONTACT_BUILD_TESTS)
    foreach(t IN LISTS ARGN)
      add_test(NAME ${t} COMMAND sh -c "echo 'SKIPPED: ${t} (${simulator} not installed, missing: ${missing}; scripts/setup_simulators.sh installs it)'; exit 77")
      set_tests_properties(${t} PROPERTIES SKIP_RETURN_CODE 77)
    endforeach()
  endif()
endfunction()

# Where the installed plugins find the installed libdemcontact.so.0: <prefix>/lib/demcontact/..
set(DC_PLUGIN_DIR "${CMAKE_INSTALL_LIBDIR}/demcontact")
add_subdirectory(plugins/liggghts)
add_subdirectory(plugins/lammps)
if(DEMCONTACT_BUILD_TESTS)
  # The corrected builtin inputs of LIGGGHTS, LAMMPS and YADE in the real codes.
  include(tests/simulators/builtin_tests.cmake)
endif()
