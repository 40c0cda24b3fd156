#!/usr/bin/env bash
# The curved channels at the paper's second resolution, N_f = 40 (Wang, Sun & Hu sec 5.2: the
# mild one with y_p = 7e-4 m, the strong one with y_p = H/80; OpenFOAM's references hold both).
# On 2 CPU cores each takes hours (strong: 94k particles, about 9500 steps, some 2.5 h alone;
# mild: about twice that), so the runs write a checkpoint every 0.25 s of flow (mild: 0.1 s) and
# this script, run again, continues each from its last checkpoint (`clsph run --restart`) until it
# is done.
# Both use the walls' pressure gradient (wallp = 1), the wall model's default wall pressure.
# Then run tests/validation/run_rans.sh's report lines (results.py) to put them in RESULTS_rans.md.
#   tests/validation/run_rans_curved40.sh [BUILD_DIR] [strong|mild|both]   (default build, both)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
which=${2:-both}
out=out/validation_rans
mkdir -p "$out"
# name, then the case's parameters
curved40() {
  local name=$1
  shift
  local args=()
  for s in "$@"; do args+=(--set "$s"); done
  local dir="$out/$name"
  if [ -f "$dir/summary.json" ] && grep -q '"status":[[:space:]]*"ok"' "$dir/summary.json"; then
    echo "$name: done"
    return 0
  fi
  local last
  last=$(ls "$dir"/checkpoint_*.h5 2>/dev/null | sort | tail -n 1 || true)
  if [ -n "$last" ]; then
    echo "$name: continuing from $last"
    "$build/clsph" run cases/channel_curved.lua "${args[@]}" --out "$dir" --restart "$last" \
      --quiet || true
  else
    echo "$name: starting"
    "$build/clsph" run cases/channel_curved.lua "${args[@]}" --out "$dir" --quiet --overwrite ||
      true
  fi
}
if [ "$which" = strong ] || [ "$which" = both ]; then
  curved40 channel_curved_strong_nf40 setting=2 nf=40 y_p=0.0009525 wallp=1 checkpoint=0.25
fi
if [ "$which" = mild ] || [ "$which" = both ]; then
  curved40 channel_curved_mild_nf40 setting=1 nf=40 y_p=7e-4 t_end=5.08 avg=1 wallp=1 checkpoint=0.1
fi
