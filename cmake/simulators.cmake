# demcontact inside real DEM codes: the LIGGGHTS normal-model plugin and the LAMMPS pair-style
# plugin, each in its own directory with the ctest cases that run it. Their tests are registered
# either way and SKIP (exit 77) with the reason where the simulator is missing
# (scripts/setup_simulators.sh installs both).

add_subdirectory(examples_cpp/liggghts)
add_subdirectory(examples_cpp/lammps)
