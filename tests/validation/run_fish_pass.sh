#!/usr/bin/env bash
# The fish-pass (Leroy et al. 2014 sec 5.2, cases/fish_pass.lua) for RESULTS_fish_pass.md:
# isph-usaw (the paper's production of k, eq 20, and the standard one, OpenFOAM's) and wcsph-usaw
# to the paper's 20 s at n = 10 (the slot in spacings: 7550 fluid particles), their frames and
# movies (speed), the profiles against OpenFOAM's (tests/data/openfoam_fish_pass.csv) on one
# chart, and short runs at the paper's count (n = 28, 5.9e4 particles), with and without the k-ε
# model, for the cost of 20 s.
#   tests/validation/run_fish_pass.sh [BUILD_DIR]   (default build; about 1.2 h on 2 cores)
# FISH_SKIP_RUNS=1 only redraws the chart and the table from the runs in out/validation_fish_pass.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
out=out/validation_fish_pass
mkdir -p "$out"
run() { # name sets...
  local name=$1
  shift
  local args=()
  for s in "$@"; do args+=(--set "$s"); done
  "$build/clsph" run cases/fish_pass.lua "${args[@]}" --out "$out/$name" --quiet --overwrite || true
}
if [ "${FISH_SKIP_RUNS:-0}" != 1 ]; then
  # the 20-s runs on one core each (POCL_MAX_PTHREAD_COUNT=1), side by side: wcsph-usaw on one;
  # isph-usaw with the paper's production of k (eq 20), then with the standard one, on the other
  (
    export POCL_MAX_PTHREAD_COUNT=1
    run wcsph_n10 n=10 weak=1 &
    (
      run isph_n10 n=10
      run isph_n10_standard n=10 prod=1
    ) &
    wait
  )
  # the paper's count (n = 28, 5.9e4 particles), alone on the 2 cores, with and without the k-ε
  # model: the cost per step (its first steps: the flow starting from rest, which takes isph-usaw
  # 18 solver iterations a step against the developed flow's 10)
  run isph_n28_cost n=28 t_end=0.5 every=0.5
  run isph_n28_cost_laminar n=28 t_end=0.5 every=0.5 turb=0
  run wcsph_n28_cost n=28 t_end=0.02 every=0.02 weak=1
  run wcsph_n28_cost_laminar n=28 t_end=0.02 every=0.02 weak=1 turb=0
  for r in isph_n10 isph_n10_standard wcsph_n10; do
    "$build/clsph" render "$out/$r" --field speed --range 0,5 --out "$out/$r" || true
  done
fi
python3 tests/validation/fish_pass_chart.py tests/validation "isph-usaw n=10=$out/isph_n10" \
  "isph-usaw n=10 standard production=$out/isph_n10_standard" "wcsph-usaw n=10=$out/wcsph_n10"
python3 tests/validation/results.py "$out" tests/validation/RESULTS_fish_pass.md
