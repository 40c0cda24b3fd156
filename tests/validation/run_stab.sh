#!/usr/bin/env bash
# The validation runs of isph-stabilized (the stabilized ISPH paper, sec 4.1 and 4.2) beside
# isph-usaw and wcsph-riemann on the same cases, then RESULTS_isph_stabilized.md, the sensor-1
# chart and the chart of sensors 1 to 4. About 2.5 hours on 2 cores (the n = 80 and 160 dam breaks are
# most of it).
#   tests/validation/run_stab.sh [BUILD_DIR]     (default build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
out=out/validation_stab
mkdir -p "$out"
source tests/validation/lib.sh
# The hydrostatic tank of S sec 4.1 (0.2 m of water, 0.2 m wide) at its two resolutions, 2 s:
# the modified virtual marker, the pseudo-Neumann walls, isph-usaw
for dr in 0.01 0.005; do
  run tank_dr${dr}_stab_neumann hydrostatic stab=1 depth=0.2 width=0.2 dr=$dr t_end=2
  run tank_dr${dr}_stab_pseudo hydrostatic stab=1 neumann=0 depth=0.2 width=0.2 dr=$dr t_end=2
  run tank_dr${dr}_isph_usaw hydrostatic depth=0.2 width=0.2 dr=$dr t_end=2
done
# pressure_form = "dynamic" (the pressure equation solved for p − ρ0 g·x) on the same tanks
for dr in 0.01 0.005; do
  run tank_dr${dr}_stab_dynamic hydrostatic stab=1 dyn=1 depth=0.2 width=0.2 dr=$dr t_end=2
done
# The shaped floors (S fig 4 in 2-D) at dr = 0.005, 2 s
for shape in 1 2; do
  run shapes${shape}_stab_neumann hydrostatic_shapes shape=$shape t_end=2
  run shapes${shape}_stab_pseudo hydrostatic_shapes shape=$shape neumann=0 t_end=2
  run shapes${shape}_isph_usaw hydrostatic_shapes shape=$shape stab=0 t_end=2
  run shapes${shape}_stab_dynamic hydrostatic_shapes shape=$shape dyn=1 t_end=2
done
# The Lobovsky dam break (S sec 4.2) to t = 1.1 s (t* = 6.3): isph-usaw and wcsph-riemann at
# n = 40 and 80
for n in 40 80; do
  run lobovsky_n${n}_isph_usaw dam_break n=$n t_end=1.1
  run lobovsky_n${n}_wcsph_riemann dam_break riemann=1 n=$n t_end=1.1
done
# isph-stabilized with and without the gate at n = 40 and 80 (fluid thrown over the tank's walls
# is dropped and counted: summary.json escaped)
for n in 40 80; do
  run lobovsky_n${n}_stab dam_break stab=1 n=$n t_end=1.1
  run lobovsky_n${n}_stab_gate dam_break stab=1 gate=1 n=$n t_end=1.1
done
# the gate at n = 160 (dr = 1.875 mm), the paper's scheme (it clusters after the impact, at
# t* = 3) and with shifting 0.5 (about an hour alone)
run lobovsky_n160_stab_gate dam_break stab=1 gate=1 n=160 t_end=1.1 checkpoint=0.1
run lobovsky_n160_stab_shift_gate dam_break stab=1 gate=1 n=160 t_end=1.1 shift=0.5 checkpoint=0.1
# the same at n = 40 with pressure_form = "dynamic"
run lobovsky_n40_stab_dynamic dam_break stab=1 dyn=1 n=40 t_end=1.1
run lobovsky_n40_stab_dynamic_gate dam_break stab=1 dyn=1 gate=1 n=40 t_end=1.1
# particle shifting (shifting = 0.5, not the paper's) to t = 1.1 s, with and without the gate
run lobovsky_n40_stab_shift dam_break stab=1 n=40 t_end=1.1 shift=0.5
run lobovsky_n40_stab_shift_gate dam_break stab=1 gate=1 n=40 t_end=1.1 shift=0.5
python3 tests/validation/results.py "$out" tests/validation/RESULTS_isph_stabilized.md
python3 tests/validation/lobovsky_chart.py tests/validation/lobovsky_sensor1 \
  "isph-stabilized (n 40)=$out/lobovsky_n40_stab" \
  "isph-stabilized with gate (n 40)=$out/lobovsky_n40_stab_gate" \
  "isph-stabilized with gate (n 80)=$out/lobovsky_n80_stab_gate" \
  "isph-stabilized with gate and shifting 0.5 (n 160)=$out/lobovsky_n160_stab_shift_gate" \
  "isph-usaw (n 40)=$out/lobovsky_n40_isph_usaw" \
  "wcsph-riemann (n 80)=$out/lobovsky_n80_wcsph_riemann" || true
# sensors 1 to 4 (3, 15, 30 and 80 mm above the bed) against the experiment's event 5
python3 tests/validation/lobovsky_sensors_chart.py tests/validation/lobovsky_sensors \
  "isph-stabilized shifting 0.5 (n 40)=$out/lobovsky_n40_stab_shift" \
  "isph-usaw (n 40)=$out/lobovsky_n40_isph_usaw" \
  "wcsph-riemann (n 40)=$out/lobovsky_n40_wcsph_riemann" \
  "wcsph-riemann (n 80)=$out/lobovsky_n80_wcsph_riemann" || true
# where the dam break fails over α and the time step (tests/harness/studies.txt)
python3 tests/harness/harness.py stability stab_dam_break --build "$build" \
  --results tests/validation || true
