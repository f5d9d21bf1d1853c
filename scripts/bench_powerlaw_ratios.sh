#!/usr/bin/env bash
# The two speed ratios of the power-law calculus against its ODE reference, from `cargo bench --bench powerlaw`: the planned
# force-end duration (plan level 2: measured 2.1e-11 from dc_contact_duration, asserted <= 5e-11
# by tests/powerlaw_plan.rs) and the 1000-point trajectory, each against the adaptive
# Dormand-Prince reference at the loosest tolerance reaching 1e-10 on the same quantity (asserted by
# tests/powerlaw_vs_ode.rs reference_tolerance_for_benchmark), measured in the same run. Prints one line per run with the ratio of medians and of fastest samples.
#   scripts/bench_powerlaw_ratios.sh [runs]     (default 3)
set -euo pipefail
cd "$(dirname "$0")/.."
runs="${1:-3}"
# Divan prints "name  fastest │ slowest │ median │ mean │ samples │ iters"; convert a time to ns.
to_ns='function ns(v, u) { return u == "ns" ? v : u == "µs" ? v * 1e3 : u == "ms" ? v * 1e6 : v * 1e9 }'
for r in $(seq 1 "$runs"); do
  out=$(cargo bench --quiet --bench powerlaw -- duration_force_end_planned duration_force_end_ode_reference 'trajectory_1000' 2>/dev/null)
  echo "$out" | awk -v run="$r" "$to_ns"'
    /duration_force_end_ode_reference/ { ref_d_min = ns($3, $4); ref_d_med = ns($9, $10) }
    /trajectory_1000_ode_reference/    { ref_t_min = ns($3, $4); ref_t_med = ns($9, $10); next }
    /trajectory_1000/                  { tr_min = ns($3, $4); tr_med = ns($9, $10) }
    /duration_force_end_planned/       { inplan = 1; next }
    inplan && $3 == "2"                { pl_min = ns($4, $5); pl_med = ns($10, $11); inplan = 0 }
    END {
      printf "run %d: planned duration (level 2) %.0fx median, %.0fx fastest; 1000-point trajectory %.0fx median, %.0fx fastest\n",
        run, ref_d_med / pl_med, ref_d_min / pl_min, ref_t_med / tr_med, ref_t_min / tr_min
    }'
done
