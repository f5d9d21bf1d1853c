#!/usr/bin/env bash
# The speed/accuracy trade at the scale of a scene (docs/report.md, "Speed/accuracy at the scale of
# a scene"): three small LAMMPS scenes with pair_style demcontact (settle into a box, hopper
# discharge, a freely cooling granular gas) over stiffness x step x model parts, 3 seeds each, the
# planner's choices (demcontact plan, plain and --step-aware) run and marked; the planner's
# step-aware choice also on 2 ranks. Writes runs.csv, summary.csv, summary.md and
# pareto_<scene>.svg to the output folder (default build/scene_trade) and copies the figures to
# docs/figures/. Not in CI (about 15-25 minutes on a shared 2-core machine; one process at a time);
# the ctest lammps_scene_trade_smoke is the short version.  Usage: scripts/scene_trade.sh [outdir]
# (DC_SCENE_RESUME=1: reuse the runs already complete in outdir, rerun only the rest).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup_simulators.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j1 --target demcontact_lammps demcontact_liggghts >/dev/null
out="${1:-build/scene_trade}"
python3 tests/simulators/scene_trade.py --scene settle,hopper,gas --seeds 3 --np 2 \
    ${DC_SCENE_RESUME:+--resume} \
    --plugin build/simulators/demcontactplugin.so --plan target/release/demcontact --out "$out"
# the settle scene once in LIGGGHTS 3.8 (its own output folder); without LIGGGHTS (exit 77) it is
# skipped and says so, every other failure ends the script
lg=ran
python3 tests/simulators/scene_trade.py --sim liggghts --seeds 3 ${DC_SCENE_RESUME:+--resume} \
    --plugin build/simulators/libdemcontact_liggghts.so --plan target/release/demcontact --out "$out/liggghts" \
    || { rc=$?; [ "$rc" = 77 ] || exit "$rc"; lg=skipped; echo "LIGGGHTS part SKIPPED (not installed)"; }
mkdir -p docs/figures
for s in settle hopper gas; do cp "$out/pareto_$s.svg" "docs/figures/scene_trade_$s.svg"; done
[ "$lg" = skipped ] || cp "$out/liggghts/pareto_settle.svg" docs/figures/scene_trade_settle_liggghts.svg
