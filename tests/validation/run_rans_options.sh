#!/usr/bin/env bash
# The curved and HCD channels of wcsph-riemann's k-ε model (Wang, Sun & Hu sec 5.2, 5.3) with the
# wall model's options that the straight channel's ensembles measured (run_rans_ensemble.sh): the
# velocity gradient in the log law's coordinate by the walls (grad = 1), k and ε diffused with the
# log mean and the walls' mirror (diff = 1), the wall's stress on the first row alone (shear = 2,
# wall_shear = "first_row") and the dummies' pressure force along the walls' normal (pforce = 1,
# wall_pressure_force = "normal"): the HCD channel at N_f = 40, ARD on and off, and the strongly
# curved channel at N_f = 20, each beside the paper's treatment run in the same session (the
# walls' pressure the gradient in both), and then each option alone on the HCD channel with ARD
# (N_f = 40, beside the paper's treatment again: the ARD indicator as a series mean); the mildly
# curved channel at N_f = 20 with the four options beside the paper's treatment; each option alone
# on the strongly curved channel (N_f = 20) and on the straight channel (N_f = 40, two members:
# seed 0 and 1, beside two of the paper's treatment; the fifth option there, offset_layer =
# "body_force", carry = 1, has no layer to carry in the curved and HCD channels); then
# RESULTS_rans_options.md and channel_hcd_floor.png (the first row along the floor). About 3 h on
# 2 cores, two runs side by side.
#   tests/validation/run_rans_options.sh [BUILD_DIR]     (default build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
out=out/validation_rans_options
mkdir -p "$out"
source tests/validation/lib.sh
opts=(grad=1 diff=1 shear=2 pforce=1)
(
  run channel_hcd_nf40_ard1_options channel_hcd nf=40 ard=1 t_end=60 avg=20 wallp=1 "${opts[@]}"
  run channel_hcd_nf40_ard1 channel_hcd nf=40 ard=1 t_end=60 avg=20 wallp=1
  run channel_hcd_nf40_ard0_options channel_hcd nf=40 ard=0 t_end=60 avg=20 wallp=1 "${opts[@]}"
  run channel_hcd_nf40_ard0 channel_hcd nf=40 ard=0 t_end=60 avg=20 wallp=1
) &
(
  run channel_curved_strong_nf20_options channel_curved setting=2 nf=20 wallp=1 "${opts[@]}"
  run channel_curved_strong_nf20 channel_curved setting=2 nf=20 wallp=1
) &
wait
(
  run channel_hcd_nf40_ard1_grad channel_hcd nf=40 ard=1 t_end=60 avg=20 wallp=1 grad=1
  run channel_hcd_nf40_ard1_diff channel_hcd nf=40 ard=1 t_end=60 avg=20 wallp=1 diff=1
  run channel_hcd_nf40_ard1 channel_hcd nf=40 ard=1 t_end=60 avg=20 wallp=1
) &
(
  run channel_hcd_nf40_ard1_shear channel_hcd nf=40 ard=1 t_end=60 avg=20 wallp=1 shear=2
  run channel_hcd_nf40_ard1_pforce channel_hcd nf=40 ard=1 t_end=60 avg=20 wallp=1 pforce=1
) &
wait
(
  run channel_curved_mild_nf20_options channel_curved setting=1 nf=20 t_end=5.08 avg=1 wallp=1 \
    "${opts[@]}"
) &
(
  run channel_curved_mild_nf20 channel_curved setting=1 nf=20 t_end=5.08 avg=1 wallp=1
) &
wait
(
  run channel_curved_strong_nf20_grad channel_curved setting=2 nf=20 wallp=1 grad=1
  run channel_curved_strong_nf20_diff channel_curved setting=2 nf=20 wallp=1 diff=1
  for s in 0 1; do run channel_ke_nf40_s$s channel_ke nf=40 ub=1 t_end=600 every=100 seed=$s; done
  for s in 0 1; do
    run channel_ke_nf40_shear_s$s channel_ke nf=40 ub=1 t_end=600 every=100 seed=$s shear=2
  done
  for s in 0 1; do
    run channel_ke_nf40_diff_s$s channel_ke nf=40 ub=1 t_end=600 every=100 seed=$s diff=1
  done
) &
(
  run channel_curved_strong_nf20_shear channel_curved setting=2 nf=20 wallp=1 shear=2
  run channel_curved_strong_nf20_pforce channel_curved setting=2 nf=20 wallp=1 pforce=1
  for s in 0 1; do
    run channel_ke_nf40_pforce_s$s channel_ke nf=40 ub=1 t_end=600 every=100 seed=$s pforce=1
  done
  for s in 0 1; do
    run channel_ke_nf40_carry_s$s channel_ke nf=40 ub=1 t_end=600 every=100 seed=$s carry=1
  done
  for s in 0 1; do
    run channel_ke_nf40_grad_s$s channel_ke nf=40 ub=1 t_end=600 every=100 seed=$s grad=1
  done
) &
wait
python3 tests/validation/results.py "$out" tests/validation/RESULTS_rans_options.md
python3 tests/validation/channel_ke_chart.py tests/validation \
  "floor:paper ARD=$out/channel_hcd_nf40_ard1" "floor:normal ARD=$out/channel_hcd_nf40_ard1_pforce" \
  "floor:log_mirror ARD=$out/channel_hcd_nf40_ard1_diff" \
  "floor:paper no ARD=$out/channel_hcd_nf40_ard0" \
  "floor:four options no ARD=$out/channel_hcd_nf40_ard0_options"
