#!/bin/sh
# The LIGGGHTS quick start as a user runs it (README, docs/user/liggghts.md):
#   liggghts_quickstart.sh BUILD_DIR LIGGGHTS DECK LIBDIR WORKDIR
# installs BUILD_DIR into a scratch prefix (cmake --install), then runs the stock LIGGGHTS on DECK
# with only LD_PRELOAD=<prefix>/LIBDIR/demcontact/libdemcontact_liggghts.so set (no
# LD_LIBRARY_PATH). Passes when the installed plugin resolves the installed libdemcontact (not the
# build tree's), LIGGGHTS ran model demcontact, and the deck prints its realised e within 1e-3 of
# 0.5. Exit 77 (ctest SKIP) when LIGGGHTS is missing.
set -eu
build=$1 liggghts=$2 deck=$3 libdir=$4 work=$5
[ -x "$liggghts" ] || { echo "SKIPPED: liggghts_quickstart (no liggghts at $liggghts)"; exit 77; }
rm -rf "$work" && mkdir -p "$work/run"
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log"
plugin="$prefix/$libdir/demcontact/libdemcontact_liggghts.so"
[ -f "$plugin" ] || { echo "FAIL: $plugin not installed"; exit 1; }
lib=$(env -u LD_LIBRARY_PATH ldd "$plugin" | sed -n 's/.*libdemcontact\.so[^ ]* => \([^ ]*\).*/\1/p')
case "$lib" in
  "$prefix"/*) ;;
  *) echo "FAIL: the installed plugin resolves libdemcontact to '$lib', not under $prefix"; exit 1 ;;
esac
cp "$deck" "$work/run/in.demcontact"
cd "$work/run"
env -u LD_LIBRARY_PATH LD_PRELOAD="$plugin" \
  "$liggghts" -in in.demcontact -log log.liggghts >out.txt 2>&1 || { cat out.txt; echo "FAIL: liggghts exited $?"; exit 1; }
grep -q "^model demcontact: " out.txt || { cat out.txt; echo "FAIL: LIGGGHTS did not run model demcontact"; exit 1; }
e=$(sed -n 's/^realised e = //p' out.txt)
[ -n "$e" ] || { cat out.txt; echo "FAIL: no realised e printed"; exit 1; }
awk -v e="$e" 'BEGIN { d = e - 0.5; if (d < 0) d = -d; exit !(d <= 1e-3) }' ||
  { echo "FAIL: realised e = $e, not within 1e-3 of 0.5"; exit 1; }
echo "liggghts_quickstart: installed to $prefix, LD_PRELOAD of the installed plugin, libdemcontact from $lib, realised e = $e (target 0.5): ok"
