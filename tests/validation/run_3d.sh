#!/usr/bin/env bash
# The 3-D validation runs (issue 23): the Lobovsky dam break in 3-D, H = 300 mm against the 2-D
# runs of the same scheme and resolution, H = 600 mm with the gate (the stabilized ISPH paper's
# sec 4.2 case) at two resolutions, the 2-D series that measures wcsph-riemann's surface rows'
# regularisations, and the 3-D lid-driven cavity; then RESULTS_3d.md and the sensor-1 chart.
# About 2.5 h on 2 cores alone (the n = 40 and n = 60 3-D runs are most of it).
#   tests/validation/run_3d.sh [BUILD_DIR]     (default build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
out=out/validation_3d
mkdir -p "$out"
source tests/validation/lib.sh
# 2-D, H = 300 mm, wcsph-riemann to t = 0.75 s (t* = 4.3: the impact and the plateau over t* 3-4),
# the surface rows off (the 2-D default), "tangential" and "pairs" (the 3-D default)
for n in 20 30 40 80; do
  run lobovsky_n${n}_riemann dam_break riemann=1 n=$n t_end=0.75 surf=0
  run lobovsky_n${n}_riemann_tangential dam_break riemann=1 n=$n t_end=0.75 surf=1
  run lobovsky_n${n}_riemann_pairs dam_break riemann=1 n=$n t_end=0.75 surf=2
done
# 3-D, H = 300 mm (the tank 150 mm wide), wcsph-riemann: n = 20 (clusters before the impact
# with the surface rows off), 30 and 40 with "pairs"; n = 30 off and with the gate
run lobovsky3d_n20_riemann_off dam_break dim=3 riemann=1 n=20 t_end=0.75 surf=0
run lobovsky3d_n20_riemann_tangential dam_break dim=3 riemann=1 n=20 t_end=0.75 surf=1
for n in 20 30 40; do
  run lobovsky3d_n${n}_riemann dam_break dim=3 riemann=1 n=$n t_end=0.75
done
run lobovsky3d_n30_riemann_off dam_break dim=3 riemann=1 n=30 t_end=0.75 surf=0
run lobovsky3d_n30_riemann_gate dam_break dim=3 riemann=1 gate=1 n=30 t_end=0.75
run lobovsky3d_n30_riemann_gate_off dam_break dim=3 riemann=1 gate=1 n=30 t_end=0.75 surf=0
# isph-stabilized in 3-D with its shifting (0.5, not the paper's) and wall_approach =
# "particles" (the 3-D default "impact" lets the tongue's tension pull particles through the floor
# at the impact), n = 20 and 30
for n in 20 30; do
  run lobovsky3d_n${n}_stab dam_break dim=3 stab=1 shift=0.5 approach=1 n=$n t_end=0.75
done
# H = 600 mm with the gate (lifted 0.7 m at 4.53 m/s) to t = 0.75 s (t* = 3.0), n = 40 and 60
for n in 40 60; do
  run lobovsky600_3d_n${n}_riemann_gate dam_break H=0.6 dim=3 riemann=1 gate=1 n=$n t_end=0.75
  run lobovsky600_3d_n${n}_riemann_gate_off dam_break H=0.6 dim=3 riemann=1 gate=1 n=$n \
    t_end=0.75 surf=0
done
for n in 40 60; do
  run lobovsky600_3d_n${n}_stab_gate dam_break H=0.6 dim=3 stab=1 shift=0.5 approach=1 gate=1 \
    n=$n t_end=0.75
done
# the lid-driven cavity at Re = 100 in a spanwise-periodic box, n = 30, t = 10
run cavity3d_n30_riemann cavity dim=3 riemann=1 n=30 t_end=10
python3 tests/validation/results.py "$out" tests/validation/RESULTS_3d.md
# H = 600 mm: sensor 1 of both schemes at both resolutions, the median peak marked
python3 tests/validation/lobovsky_chart.py --h600 tests/validation/lobovsky600_sensor1 \
  "wcsph-riemann (n 40)=$out/lobovsky600_3d_n40_riemann_gate" \
  "wcsph-riemann (n 60)=$out/lobovsky600_3d_n60_riemann_gate" \
  "wcsph-riemann surface rows off (n 60)=$out/lobovsky600_3d_n60_riemann_gate_off" \
  "isph-stabilized (n 40)=$out/lobovsky600_3d_n40_stab_gate" \
  "isph-stabilized (n 60)=$out/lobovsky600_3d_n60_stab_gate" || true
python3 tests/validation/lobovsky_chart.py tests/validation/lobovsky3d_sensor1 \
  "wcsph-riemann 3-D (n 30)=$out/lobovsky3d_n30_riemann" \
  "wcsph-riemann 3-D surface rows off (n 30)=$out/lobovsky3d_n30_riemann_off" \
  "wcsph-riemann 3-D (n 20)=$out/lobovsky3d_n20_riemann" \
  "wcsph-riemann 2-D (n 30)=$out/lobovsky_n30_riemann" \
  "isph-stabilized 3-D (n 20)=$out/lobovsky3d_n20_stab" \
  "isph-stabilized 3-D (n 30)=$out/lobovsky3d_n30_stab" || true
