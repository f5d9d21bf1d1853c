#!/bin/sh
# The LAMMPS quick start as a user runs it (README, docs/user/lammps.md):
#   lammps_quickstart.sh BUILD_DIR LMP DECK LIBDIR WORKDIR
# installs BUILD_DIR into a scratch prefix (cmake --install), then runs the unmodified LMP on DECK
# with only LAMMPS_PLUGIN_PATH=<prefix>/LIBDIR/demcontact set: no plugin load line, no
# LD_LIBRARY_PATH or LD_PRELOAD. Passes when LAMMPS autoloaded the plugin, the installed plugin
# resolves the installed libdemcontact (not the build tree's), and the deck prints its realised e
# within 1e-3 of 0.5. Exit 77 (ctest SKIP) when LMP is missing.
set -eu
build=$1 lmp=$2 deck=$3 libdir=$4 work=$5
[ -x "$lmp" ] || { echo "SKIPPED: lammps_quickstart (no lmp at $lmp)"; exit 77; }
rm -rf "$work" && mkdir -p "$work/run"
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log"
plugin="$prefix/$libdir/demcontact/demcontactplugin.so"
[ -f "$plugin" ] || { echo "FAIL: $plugin not installed"; exit 1; }
# The installed plugin must find the installed library through its own RUNPATH.
lib=$(env -u LD_LIBRARY_PATH ldd "$plugin" | sed -n 's/.*libdemcontact\.so[^ ]* => \([^ ]*\).*/\1/p')
case "$lib" in
  "$prefix"/*) ;;
  *) echo "FAIL: the installed plugin resolves libdemcontact to '$lib', not under $prefix"; exit 1 ;;
esac
cp "$deck" "$work/run/in.demcontact"
cd "$work/run"
env -u LD_LIBRARY_PATH -u LD_PRELOAD LAMMPS_PLUGIN_PATH="$prefix/$libdir/demcontact" \
  "$lmp" -in in.demcontact -log log.lammps >out.txt 2>&1 || { cat out.txt; echo "FAIL: lmp exited $?"; exit 1; }
grep -q "^Loaded 1 plugins from $prefix/$libdir/demcontact" out.txt || { cat out.txt; echo "FAIL: the plugin was not autoloaded"; exit 1; }
e=$(sed -n 's/^realised e = //p' out.txt)
[ -n "$e" ] || { cat out.txt; echo "FAIL: no realised e printed"; exit 1; }
awk -v e="$e" 'BEGIN { d = e - 0.5; if (d < 0) d = -d; exit !(d <= 1e-3) }' ||
  { echo "FAIL: realised e = $e, not within 1e-3 of 0.5"; exit 1; }
echo "lammps_quickstart: installed to $prefix, autoloaded by LAMMPS_PLUGIN_PATH, libdemcontact from $lib, realised e = $e (target 0.5): ok"
