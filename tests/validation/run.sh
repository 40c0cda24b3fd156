#!/usr/bin/env bash
# Validation runs at the papers' resolutions (long: not part of CI), then RESULTS.md.
#   tests/validation/run.sh [BUILD_DIR]     (default build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
out=out/validation
mkdir -p "$out"
run() { # name case sets...
  local name=$1 case=$2
  shift 2
  local args=()
  for s in "$@"; do args+=(--set "$s"); done
  "$build/clsph" run "cases/$case.lua" "${args[@]}" --out "$out/$name" --quiet || true
}
run hydrostatic_isph_usaw hydrostatic
for n in 20 30 40 60 120; do # convergence study, Re = 100 (the paper's resolution: 120)
  run cavity_re100_n${n}_isph_usaw cavity re=100 n=$n t_end=10
done
for n in 20 40; do
  run cavity_re100_n${n}_wcsph_usaw cavity re=100 n=$n t_end=10 wcsph=1
done
for n in 20 30 40; do # cylinder array, L = 6 (the paper's resolution: 120), steady from ~10 s
  run cylinder_array_n${n}_isph_usaw cylinder_array n=$n t_end=24
  run cylinder_array_n${n}_wcsph_usaw cylinder_array n=$n t_end=24 wcsph=1
done
python3 tests/validation/results.py "$out" tests/validation/RESULTS.md
