# demcontact inside real DEM codes: the LIGGGHTS contact-model plugin and the LAMMPS pair/wall
# plugin, each in its own directory with the ctest cases that run it. Their tests are registered
# either way and SKIP (exit 77) with the reason where the simulator is missing
# (scripts/setup_simulators.sh installs both).

# The library's own oblique sphere-wall impact, the reference of the simulators' oblique tests.
add_executable(dc_oblique_ref tests/simulators/oblique_ref.c)
target_link_libraries(dc_oblique_ref PRIVATE demcontact::demcontact m)
set_target_properties(dc_oblique_ref PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/simulators")

add_subdirectory(plugins/liggghts)
add_subdirectory(plugins/lammps)
# The corrected builtin inputs of LIGGGHTS, LAMMPS and YADE in the real codes.
include(tests/simulators/builtin_tests.cmake)
