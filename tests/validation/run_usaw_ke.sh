#!/usr/bin/env bash
# The k-ε validation runs of the USAW schemes (Leroy et al. 2014 sec 5.1, the turbulent channel;
# about 1.5 h on 2 cores, two runs side by side), then RESULTS_usaw_ke.md and its chart.
#   tests/validation/run_usaw_ke.sh [BUILD_DIR]     (default build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
out=out/validation_usaw_ke
mkdir -p "$out"
run() { # name sets...
  local name=$1
  shift
  local args=()
  for s in "$@"; do args+=(--set "$s"); done
  "$build/clsph" run cases/channel_usaw_ke.lua "${args[@]}" --out "$out/$name" --quiet --overwrite || true
}
# e+ = 640 (the paper's), started from the 1-D reference: isph-usaw at 10, 14 and 20 (the paper's
# spacing) rows per half height to t = 40 s (settled by t = 20-30 s: the observed orders; the wall
# layer at y+ = 32, 23 and 16), at 40 rows (y+ = 8: the wall layer in the viscous sublayer, where
# the model fails with the paper's two-layer wall law; also with the scalable one) and at 20 rows
# to the paper's 100 s; wcsph-usaw at 10 and 20 rows; isph-usaw at Lee & Moser's
# Re_tau = 543.5 (against the DNS) and under flow-rate control (eqs 67-68)
(
  run isph_n40 n=40 t_end=40 every=10
  run isph_n10 n=10 t_end=40 every=10
  run isph_n14 n=14 t_end=40 every=10
  run isph_n40_scalable n=40 t_end=40 every=10 scalable=1
  run isph_n20_retau543 n=20 t_end=40 every=10 re_tau=543.5
) &
(
  run isph_n20_t100 n=20 t_end=100 every=10
  run isph_n20 n=20 t_end=40 every=10
  run wcsph_n10 n=10 t_end=40 every=10 weak=1
  run wcsph_n20 n=20 t_end=40 every=10 weak=1
  run isph_n20_control n=20 t_end=40 every=10 control=1
) &
wait
python3 tests/validation/results.py "$out" tests/validation/RESULTS_usaw_ke.md
python3 tests/validation/channel_usaw_ke_chart.py tests/validation \
  "isph-usaw n = 10=$out/isph_n10" "isph-usaw n = 20=$out/isph_n20_t100" \
  "isph-usaw n = 14=$out/isph_n14" "isph-usaw n = 40=$out/isph_n40" "isph-usaw n = 40 scalable=$out/isph_n40_scalable" "wcsph-usaw n = 20=$out/wcsph_n20" \
  "isph-usaw n = 20 Re_tau 543.5=$out/isph_n20_retau543"
