#!/usr/bin/env bash
# Real scenes in LIGGGHTS and LAMMPS with demcontact: the full pour/settle tables (2000 polydisperse
# spheres into a cylinder, ours vs each code's builtin Hertz-Mindlin, serial and 2 ranks, wall time
# as the minimum of three alternating runs, of the settled bed and of the whole pour), LAMMPS's own pour example with our styles, and the
# viscoelastic collisions, oblique impacts, the migration test and the LAMMPS restart test. Long (tens of minutes on a shared 2-core machine); the ctest *_smoke cases
# are the short versions.  Usage: scripts/scenes.sh [workdir]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/setup_simulators.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2 --target demcontact_liggghts demcontact_lammps dc_oblique_ref >/dev/null
out="${1:-build/simulators/scenes}"
mkdir -p "$out"
s=tests/simulators
lg=build/simulators/libdemcontact_liggghts.so
lm=build/simulators/demcontactplugin.so
python3 $s/scenes.py --sim liggghts --np 2 --check --pour-reps 3 --plugin $lg --workdir "$out/liggghts_scene"
echo
python3 $s/scenes.py --sim lammps --np 2 --check --pour-reps 3 --plugin $lm --workdir "$out/lammps_scene"
echo
python3 $s/lammps_example.py --np 2 --plugin $lm --workdir "$out/lammps_example"
echo
python3 $s/collision.py --sim liggghts --viscoelastic --check --plugin $lg --workdir "$out/liggghts_visco"
echo
python3 $s/collision.py --sim lammps --viscoelastic --check --plugin $lm --workdir "$out/lammps_visco"
echo
python3 $s/oblique.py --sim liggghts --plugin $lg --ref build/simulators/dc_oblique_ref --workdir "$out/liggghts_oblique"
echo
python3 $s/oblique.py --sim lammps --plugin $lm --ref build/simulators/dc_oblique_ref --workdir "$out/lammps_oblique"
echo
python3 $s/migration.py --sim liggghts --plugin $lg --workdir "$out/liggghts_migration"
echo
python3 $s/migration.py --sim lammps --plugin $lm --workdir "$out/lammps_migration"
echo
python3 $s/restart.py --np 2 --plugin $lm --workdir "$out/lammps_restart"
