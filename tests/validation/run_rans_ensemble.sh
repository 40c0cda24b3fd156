#!/usr/bin/env bash
# The k-ε channel of wcsph-riemann as ensembles (cases/channel_ke.lua, Lee & Moser's U_b = 1):
# members that differ only in a ±0.1 u_τ perturbation of their starting velocity (seed), at
# N_f = 20 (t = 1000 δ/U_b, four members) and 40 (t = 600, three), with the wall model's shear at
# y_p (the paper's) and at each particle's distance (wall_shear = "distance"), and with the
# velocity gradient in the log law's coordinate by the walls (velocity_gradient = "log"), and with
# it the diffusion of k and ε with the logarithmic mean and the walls' mirror (turbulent_diffusion =
# "log_mirror"), and at N_f = 40 with these the layer below the offset walls passing its body force
# to the first row (offset_layer = "body_force"; at N_f = 20 there is no layer: y_p = dr/2), and
# with these the dummies' pressure force along the walls' normal (wall_pressure_force = "normal"),
# and with that the wall's stress on the first row alone (wall_shear = "first_row"; also at N_f =
# 80, t = 300, two members); then RESULTS_rans_ensemble.md. About 150 min on 2 cores, two runs
# side by side.
#   tests/validation/run_rans_ensemble.sh [BUILD_DIR]     (default build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
out=out/validation_rans_ensemble
mkdir -p "$out"
source tests/validation/lib.sh
(
  for s in 0 1 2 3; do run channel_ke_nf20_s$s channel_ke nf=20 ub=1 t_end=1000 every=100 seed=$s; done
  for s in 0 1 2; do run channel_ke_nf40_s$s channel_ke nf=40 ub=1 t_end=600 every=100 seed=$s; done
  for s in 0 1 2 3; do
    run channel_ke_nf20_grad_s$s channel_ke nf=20 ub=1 t_end=1000 every=100 seed=$s grad=1
  done
  for s in 0 1 2 3; do
    run channel_ke_nf20_diff_s$s channel_ke nf=20 ub=1 t_end=1000 every=100 seed=$s grad=1 diff=1
  done
  run channel_ke_nf40_diff_s0 channel_ke nf=40 ub=1 t_end=600 every=100 seed=0 grad=1 diff=1
  run channel_ke_nf40_layer_s0 channel_ke nf=40 ub=1 t_end=600 every=100 seed=0 grad=1 diff=1 \
    carry=1
  for s in 0 1; do
    run channel_ke_nf20_pnormal_s$s channel_ke nf=20 ub=1 t_end=1000 every=100 seed=$s grad=1 \
      diff=1 pforce=1
  done
  for s in 0 1; do
    run channel_ke_nf40_pnormal_s$s channel_ke nf=40 ub=1 t_end=600 every=100 seed=$s grad=1 \
      diff=1 carry=1 pforce=1
  done
  for s in 2 3; do
    run channel_ke_nf20_first_s$s channel_ke nf=20 ub=1 t_end=1000 every=100 seed=$s grad=1 \
      diff=1 pforce=1 shear=2
  done
  for s in 1 2; do
    run channel_ke_nf40_first_s$s channel_ke nf=40 ub=1 t_end=600 every=100 seed=$s grad=1 \
      diff=1 carry=1 pforce=1 shear=2
  done
  run channel_ke_nf80_first_s0 channel_ke nf=80 ub=1 t_end=300 every=50 seed=0 grad=1 diff=1 \
    carry=1 pforce=1 shear=2
) &
(
  for s in 0 1 2 3; do
    run channel_ke_nf20_distance_s$s channel_ke nf=20 ub=1 t_end=1000 every=100 seed=$s shear=1
  done
  for s in 0 1 2; do
    run channel_ke_nf40_distance_s$s channel_ke nf=40 ub=1 t_end=600 every=100 seed=$s shear=1
  done
  for s in 0 1 2; do
    run channel_ke_nf40_grad_s$s channel_ke nf=40 ub=1 t_end=600 every=100 seed=$s grad=1
  done
  for s in 1 2; do
    run channel_ke_nf40_diff_s$s channel_ke nf=40 ub=1 t_end=600 every=100 seed=$s grad=1 diff=1
  done
  for s in 1 2; do
    run channel_ke_nf40_layer_s$s channel_ke nf=40 ub=1 t_end=600 every=100 seed=$s grad=1 diff=1 \
      carry=1
  done
  for s in 2 3; do
    run channel_ke_nf20_pnormal_s$s channel_ke nf=20 ub=1 t_end=1000 every=100 seed=$s grad=1 \
      diff=1 pforce=1
  done
  for s in 0 1; do
    run channel_ke_nf20_first_s$s channel_ke nf=20 ub=1 t_end=1000 every=100 seed=$s grad=1 \
      diff=1 pforce=1 shear=2
  done
  run channel_ke_nf40_first_s0 channel_ke nf=40 ub=1 t_end=600 every=100 seed=0 grad=1 diff=1 \
    carry=1 pforce=1 shear=2
  run channel_ke_nf40_pnormal_s2 channel_ke nf=40 ub=1 t_end=600 every=100 seed=2 grad=1 diff=1 \
    carry=1 pforce=1
  run channel_ke_nf80_first_s1 channel_ke nf=80 ub=1 t_end=300 every=50 seed=1 grad=1 diff=1 \
    carry=1 pforce=1 shear=2
) &
wait
python3 tests/validation/results.py "$out" tests/validation/RESULTS_rans_ensemble.md
