#!/usr/bin/env bash
# The k-ε RANS validation runs of wcsph-riemann (Wang, Sun & Hu sec 5.1 to 5.3; about 4 h on
# 2 cores, two runs side by side), then RESULTS_rans.md and its charts.
#   tests/validation/run_rans.sh [BUILD_DIR]     (default build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
out=out/validation_rans
mkdir -p "$out"
source tests/validation/lib.sh
# The walls' pressure is the scheme's default under the k-ε model, the gradient (wall_pressure =
# "gradient"); the runs named _mirror, and those with wallp=0, take the mirror for comparison.
# The fully developed channel at Lee & Moser's U_b (flow-rate control), N_f = 20, 40 and 80 (N_f =
# 80: t = 300, from the 1-D profile); at N_f = 20 also eq 19's momentum dissipation and none; and
# at the DNS's u_τ (fixed body force) against the 1-D solver. The HCD channel: the comparison with
# OpenFOAM (N_f = 40, 60 s averaged over the last 20), and the stability map, ARD on and off at
# N_f = 40, 60, 80 (N_f = 60 and 80: 30 s, averaged over the last 10)
(
  run channel_ke_nf20_ub1 channel_ke nf=20 ub=1 t_end=1000 every=100
  run channel_ke_nf40_ub1 channel_ke nf=40 ub=1 t_end=600 every=100
  run channel_ke_nf80_ub1 channel_ke nf=80 ub=1 t_end=300 every=50
  run channel_ke_nf20_ub1_mirror channel_ke nf=20 ub=1 t_end=1000 every=100 wallp=0
  run channel_ke_nf20_ub1_riemann channel_ke nf=20 ub=1 t_end=1000 every=100 md=1 wallp=0
  run channel_ke_nf20_ub1_off channel_ke nf=20 ub=1 t_end=1000 every=100 md=0 wallp=0
  run channel_ke_nf20_fixed channel_ke nf=20 t_end=1000 every=100 wallp=0
  run channel_ke_nf40_ub1_mirror channel_ke nf=40 ub=1 t_end=600 every=100 wallp=0
  run channel_ke_nf40_ub1_off channel_ke nf=40 ub=1 t_end=600 every=100 md=0 wallp=0
  run channel_ke_nf80_ub1_mirror channel_ke nf=80 ub=1 t_end=300 every=50 wallp=0
  run channel_hcd_nf40_ard1_wallp channel_hcd nf=40 ard=1 t_end=60 avg=20 wallp=1
  run channel_hcd_nf40_ard0_wallp channel_hcd nf=40 ard=0 t_end=60 avg=20 wallp=1
  run channel_hcd_nf60_ard1_wallp channel_hcd nf=60 ard=1 t_end=30 avg=10 wallp=1
  run channel_hcd_nf60_ard0_wallp channel_hcd nf=60 ard=0 t_end=30 avg=10 wallp=1
  run channel_hcd_nf80_ard0_wallp channel_hcd nf=80 ard=0 t_end=30 avg=10 wallp=1
  run channel_hcd_nf40_ard1 channel_hcd nf=40 ard=1 t_end=60 avg=20 wallp=0
  run channel_hcd_nf40_ard0 channel_hcd nf=40 ard=0 t_end=60 avg=20 wallp=0
  run channel_hcd_nf60_ard1 channel_hcd nf=60 ard=1 t_end=30 avg=10 wallp=0
  run channel_hcd_nf60_ard0 channel_hcd nf=60 ard=0 t_end=30 avg=10 wallp=0
) &
# The curved channels at N_f = 20: the strong one over 1.5 transits averaged over the last 0.3, the
# mild one (80 H long) over one transit averaged over the last 0.2 (the fluid starts on the
# developed profile: what leaves at t has been in the bend since the start or has crossed it).
# At N_f = 40: tests/validation/run_rans_curved40.sh (hours; it resumes from checkpoints).
(
  run channel_hcd_nf80_ard1_wallp channel_hcd nf=80 ard=1 t_end=30 avg=10 wallp=1
  run channel_hcd_nf80_ard1 channel_hcd nf=80 ard=1 t_end=30 avg=10 wallp=0
  run channel_hcd_nf80_ard0 channel_hcd nf=80 ard=0 t_end=30 avg=10 wallp=0
  run channel_curved_strong_nf20_wallp channel_curved setting=2 nf=20 wallp=1
  run channel_curved_mild_nf20_wallp channel_curved setting=1 nf=20 t_end=5.08 avg=1 wallp=1
  run channel_curved_strong_nf20 channel_curved setting=2 nf=20 wallp=0
  run channel_curved_mild_nf20 channel_curved setting=1 nf=20 t_end=5.08 avg=1 wallp=0
) &
wait
python3 tests/validation/results.py "$out" tests/validation/RESULTS_rans.md
python3 tests/validation/channel_ke_chart.py tests/validation \
  "channel:SPH N_f = 20=$out/channel_ke_nf20_ub1" "channel:SPH N_f = 40=$out/channel_ke_nf40_ub1" \
  "channel:SPH N_f = 80=$out/channel_ke_nf80_ub1" \
  "hcd:SPH N_f = 40 ARD=$out/channel_hcd_nf40_ard1_wallp" \
  "hcd:SPH N_f = 40 no ARD=$out/channel_hcd_nf40_ard0_wallp" \
  "hcd:SPH N_f = 80 no ARD=$out/channel_hcd_nf80_ard0_wallp" \
  "hcd:SPH N_f = 40 ARD (mirror)=$out/channel_hcd_nf40_ard1" \
  "hcd:SPH N_f = 40 no ARD (mirror)=$out/channel_hcd_nf40_ard0" \
  "curved:SPH N_f = 20=$out/channel_curved_strong_nf20_wallp" \
  "curved:SPH N_f = 20=$out/channel_curved_mild_nf20_wallp" \
  "curved:SPH N_f = 20 (mirror)=$out/channel_curved_strong_nf20" \
  "curved:SPH N_f = 20 (mirror)=$out/channel_curved_mild_nf20" \
  "curved:SPH N_f = 40=$out/channel_curved_strong_nf40" "curved:SPH N_f = 40=$out/channel_curved_mild_nf40"
# the HCD channel's stability map (channel_hcd_map.png): run_rans_map.sh
