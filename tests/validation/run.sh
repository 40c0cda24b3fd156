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
run cavity_re100_n120_isph_usaw cavity re=100 n=120 t_end=30
cmake -DRUNS="$out" -DOUT=tests/validation/RESULTS.md -P tests/validation/results.cmake
