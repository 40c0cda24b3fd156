# Case scripts, runs and their outputs. Every shipped case loads and `clsph info` succeeds; each
# kind of bad input is refused with its message and a non-zero exit; small runs end to end.
set(CASE_DIR ${CMAKE_CURRENT_SOURCE_DIR}/case)
file(GLOB shipped_cases CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/cases/*.lua)
foreach(c IN LISTS shipped_cases)
  get_filename_component(n ${c} NAME_WE)
  clsph_cli_test(case_info_${n} ARGS info ${c} ${case_info_sets_${n}} RC 0
                 REGEX "particles: [0-9]+ \\(fluid [1-9]" REGEX2 "memory: [0-9]+ B per particle")
endforeach()

clsph_cli_test(case_lua_error ARGS info ${CASE_DIR}/bad_syntax.lua RC 2
               REGEX "bad_syntax.lua:[0-9]+:")
clsph_cli_test(case_unknown_key ARGS info ${CASE_DIR}/bad_key.lua RC 2
               REGEX "bad_key.lua:5: fill: unknown key 'nmae'; did you mean 'name'\\?")
clsph_cli_test(case_unknown_set ARGS info ${CMAKE_SOURCE_DIR}/cases/free_fall.lua --set dx=0.1
               RC 2 REGEX "--set dx: .*declares no parameter 'dx'; did you mean 'dr'\\?")
clsph_cli_test(case_bad_set_value ARGS info ${CMAKE_SOURCE_DIR}/cases/free_fall.lua --set dr=fine
               RC 2 REGEX "--set dr=fine: 'fine' is not a number")
clsph_cli_test(case_bad_dr ARGS info ${CASE_DIR}/bad_dr.lua RC 2
               REGEX "bad_dr.lua:3: particles: dr must be a positive spacing")
clsph_cli_test(case_sandbox_io ARGS info ${CASE_DIR}/bad_sandbox.lua RC 2
               REGEX "bad_sandbox.lua:2: .*global 'io'")
clsph_cli_test(case_sandbox_os ARGS info ${CASE_DIR}/bad_os.lua RC 2
               REGEX "bad_os.lua:1: .*global 'os'")
clsph_cli_test(case_sandbox_load ARGS info ${CASE_DIR}/bad_load.lua RC 2
               REGEX "bad_load.lua:1: .*global 'load'")
clsph_cli_test(case_unknown_scheme ARGS info ${CASE_DIR}/bad_scheme.lua RC 2
               REGEX "bad_scheme.lua:5: scheme: unknown scheme 'isph-magic' \\(schemes: none, ballistic, isph-usaw, wcsph-usaw")
clsph_cli_test(case_misspelt_scheme ARGS info ${CASE_DIR}/bad_scheme.lua --set which=2 RC 2
               REGEX "bad_scheme.lua:5: scheme: unknown scheme 'wcsph-usw'; did you mean 'wcsph-usaw'\\?")
# run { t_end } is what runs, whether or not the case declares a parameter t_end
clsph_cli_test(case_run_t_end ARGS info ${CASE_DIR}/run_t_end.lua --set t_end=0.2 RC 0
               REGEX "t_end = 0.6 s")
clsph_cli_test(case_run_t_end_negative ARGS info ${CASE_DIR}/run_t_end.lua --set which=2 RC 2
               REGEX "run_t_end.lua:12: run: t_end must be a positive time, not -1")
clsph_cli_test(case_run_t_end_missing ARGS info ${CASE_DIR}/run_t_end.lua --set which=3 RC 2
               REGEX "run_t_end.lua:14: run: needs t_end")
clsph_cli_test(case_bad_h_over_dr ARGS info ${CASE_DIR}/bad_h_over_dr.lua RC 2
               REGEX "bad_h_over_dr.lua:3: particles: h_over_dr must be in .0, 10., not 0")
clsph_cli_test(case_unknown_option ARGS info ${CASE_DIR}/bad_option.lua RC 2
               REGEX "scheme 'none' has no option 'shifting'")
clsph_cli_test(case_empty_region ARGS info ${CASE_DIR}/bad_empty_region.lua RC 2
               REGEX "bad_empty_region.lua:5:.*'speck'")
clsph_cli_test(case_fluid_in_wall ARGS info ${CASE_DIR}/bad_overlap.lua RC 2
               REGEX "bad_overlap.lua:[56]:.*everywhere")
clsph_cli_test(case_short_wall ARGS info ${CASE_DIR}/bad_wall.lua RC 2
               REGEX "bad_wall.lua:4: wall: a polyline needs at least 2 points")
clsph_cli_test(case_outflow_no_fluid ARGS info ${CASE_DIR}/bad_outflow.lua RC 2
               REGEX "bad_outflow.lua:7:.*exit")
# Containers that do not close: a cavity without its lid (no gravity) and a tank whose floor
# stops short of its wall (the water would leak out below).
clsph_cli_test(case_open_box ARGS info ${CASE_DIR}/bad_open_box.lua RC 2
               REGEX "walls do not close the fluid in: it can reach the top \\(y max\\) side.*needs a lid")
clsph_cli_test(case_tank_gap ARGS info ${CASE_DIR}/bad_tank_gap.lua RC 2
               REGEX "walls do not close the fluid in: it can reach the right \\(x max\\) side of the domain near \\(0.98")
# The case sandbox's instruction budget (a count hook) and memory ceiling (its allocator): each
# message names the file, the line and what ran out. The budget is lowered to 1e7 instructions
# (0.02 s) but for the first, which shows that the default stops an endless loop (1e9: ~2 s).
clsph_cli_test(case_sandbox_loop ARGS info ${CASE_DIR}/bad_sandbox_limits.lua RC 2
               REGEX "bad_sandbox_limits.lua:21: the case script ran out of instructions: more than its budget of 1000000000")
clsph_cli_test(case_sandbox_loop_fill ARGS info ${CASE_DIR}/bad_sandbox_limits.lua --set which=2
               --case-instructions 1e7 RC 2
               REGEX "bad_sandbox_limits.lua:16: the velocity function of fill 1 ran out of instructions")
clsph_cli_test(case_sandbox_loop_meta ARGS info ${CASE_DIR}/bad_sandbox_limits.lua --set which=4
               --case-instructions 1e7 RC 2
               REGEX "bad_sandbox_limits.lua:7: the case script ran out of instructions")
clsph_cli_test(case_sandbox_memory ARGS info ${CASE_DIR}/bad_sandbox_limits.lua --set which=5
               RC 2 REGEX "bad_sandbox_limits.lua:23: the case script ran out of memory: a block of 1907 MiB would take it past the case sandbox's ceiling of 512 MiB")
clsph_cli_test(case_sandbox_memory_table ARGS info ${CASE_DIR}/bad_sandbox_limits.lua --set which=6
               --case-memory 64 RC 2
               REGEX "bad_sandbox_limits.lua:26: the case script ran out of memory: .*ceiling of 64 MiB")
# An endless metrics() after the run: summary.json is written, "metrics failed"
clsph_add_test(case_sandbox_loop_metrics LABELS case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CASE_DIR}/bad_sandbox_limits.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/sandbox_metrics -DSETS=which=3
               "-DARGS=--case-instructions|1e7" -DRC=2 -DFAILURE=metrics "-DREGEX=metrics failed"
               "-DMESSAGE=bad_sandbox_limits.lua:29: metrics\\(\\) ran out of instructions"
               -P ${CASE_DIR}/run_failure.cmake)
# Output intervals that would flood the disk are refused before the folder is touched.
clsph_cli_test(case_output_flood ARGS run ${CASE_DIR}/bad_output_every.lua --quiet
               --out ${CMAKE_CURRENT_BINARY_DIR}/runs/output_flood RC 2
               REGEX "bad_output_every.lua:11: run: output_every and checkpoint_every ask for 1000000000000 snapshots")
clsph_cli_test(case_output_too_many ARGS run ${CASE_DIR}/bad_output_every.lua --quiet
               --set every=0.05 --set t_end=1000
               --out ${CMAKE_CURRENT_BINARY_DIR}/runs/output_too_many RC 2
               REGEX "ask for 20000 snapshots and checkpoints up to t_end = 1000 s .*max_snapshots = 10000")
# A wall that crosses itself or turns back on itself, and a probe or profile outside the domain
# (they would read NaN), are refused with the file and line.
clsph_cli_test(case_wall_crosses ARGS info ${CASE_DIR}/bad_wall_cross.lua RC 2
               REGEX "bad_wall_cross.lua:10: wall: the polyline crosses itself: its segment 1, .* meets its segment 3")
clsph_cli_test(case_wall_turns_back ARGS info ${CASE_DIR}/bad_wall_cross.lua --set which=2 RC 2
               REGEX "bad_wall_cross.lua:12: wall: the polyline turns back on itself at its point 2, .0.9, 0.5.")
clsph_cli_test(case_probe_outside ARGS info ${CASE_DIR}/bad_wall_cross.lua --set which=3 RC 2
               REGEX "bad_wall_cross.lua:15: probe 'outside' at .1.5, 0.5. lies outside the domain")
# Bad face probes (tests/case/bad_probe.lua), each refused with its line: three points, points =
# on a point probe, a face whose ends coincide, a fractional count, a face's end outside the
# domain, a name used twice, from = without to =.
clsph_cli_test(case_probe_three_points ARGS info ${CASE_DIR}/bad_probe.lua --set which=1 RC 2
               REGEX "bad_probe.lua:10: probe 'three': 3 points given; a probe is a point")
clsph_cli_test(case_probe_point_points ARGS info ${CASE_DIR}/bad_probe.lua --set which=2 RC 2
               REGEX "bad_probe.lua:11: probe 'point': points = 3 belongs to a face")
clsph_cli_test(case_probe_face_same_ends ARGS info ${CASE_DIR}/bad_probe.lua --set which=3 RC 2
               REGEX "bad_probe.lua:12: probe 'same': the face's two ends are the same point")
clsph_cli_test(case_probe_face_points ARGS info ${CASE_DIR}/bad_probe.lua --set which=4 RC 2
               REGEX "bad_probe.lua:13: probe 'half': points = 2.5 must be a whole number")
clsph_cli_test(case_probe_face_outside ARGS info ${CASE_DIR}/bad_probe.lua --set which=5 RC 2
               REGEX "bad_probe.lua:14: probe 'long': the face's end .0.5, 1.5. lies outside")
clsph_cli_test(case_probe_twice ARGS info ${CASE_DIR}/bad_probe.lua --set which=6 RC 2
               REGEX "bad_probe.lua:17: probe 'twice' is declared twice .first at line 16.")
clsph_cli_test(case_probe_face_one_end ARGS info ${CASE_DIR}/bad_probe.lua --set which=7 RC 2
               REGEX "bad_probe.lua:19: probe 'open': a face needs both ends")
clsph_cli_test(case_profile_outside ARGS info ${CASE_DIR}/bad_wall_cross.lua --set which=4 RC 2
               REGEX "bad_wall_cross.lua:16: profile 'long' from .0.5, 0. to .0.5, 2. leaves the domain")
# fill { pressure, density }: refused where the scheme takes no such field, or for a bad value
clsph_cli_test(case_fill_pressure_refused ARGS info ${CASE_DIR}/bad_fill_fields.lua RC 2
               REGEX "bad_fill_fields.lua:10: fill \\{ pressure \\}: scheme 'ballistic' takes no initial pressure")
clsph_cli_test(case_fill_density_refused ARGS info ${CASE_DIR}/bad_fill_fields.lua --set which=2
               RC 2 REGEX "bad_fill_fields.lua:10: fill \\{ density \\}: scheme 'isph-usaw' takes no initial density")
clsph_cli_test(case_fill_pressure_function ARGS info ${CASE_DIR}/bad_fill_fields.lua --set which=3
               RC 2 REGEX "the pressure function returned string.*its pressure at .0.15, 0.15. failed")
clsph_cli_test(case_fill_density_negative ARGS info ${CASE_DIR}/bad_fill_fields.lua --set which=4
               RC 2 REGEX "fill 'fill 1': density must be positive, not -1")
clsph_cli_test(case_missing_file ARGS info ${CASE_DIR}/no_such_case.lua RC 2
               REGEX "cannot read case .*no_such_case.lua: No such file")
clsph_cli_test(case_folder ARGS run ${CASE_DIR} RC 2 REGEX "case .*/case is a folder: name a case script")
clsph_cli_test(case_unwritable_out RC 1
               ARGS run ${CMAKE_SOURCE_DIR}/cases/free_fall.lua --out /proc/clsph-cannot-write
               REGEX "output folder /proc/clsph-cannot-write cannot be")

# Runs end to end (ballistic: exact answers known; the bounds are O(dt/t) Euler errors).
function(clsph_run_test name case)
  cmake_parse_arguments(T "" "" "SETS;BOUNDS;LABELS" ${ARGN})
  string(REPLACE ";" "|" sets "${T_SETS}")
  string(REPLACE ";" "|" bounds "${T_BOUNDS}")
  set(timeout 300)
  if("slow" IN_LIST T_LABELS)
    set(timeout 14400) # the papers' resolutions run for up to an hour or two on 2 cores
  endif()
  clsph_add_test(${name} LABELS case ${T_LABELS} TIMEOUT ${timeout} COMMAND ${CMAKE_COMMAND} -DCLSPH=$<TARGET_FILE:clsph>
                 -DCASE=${case} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/${name} "-DSETS=${sets}"
                 "-DBOUNDS=${bounds}" -P ${CASE_DIR}/run_case.cmake)
endfunction()
# Face probes (tests/case/probe_face.lua, a shear layer u = y that the ballistic scheme carries):
# a face reads the mean of the interpolation at the midpoints of its equal parts (24 from dr: at
# dr/4), which for u = y is the exact mean over the face (measured 6e-17 in double, 6e-9 in
# float); the points with no fluid within the support are left out (a face across the layer's
# surface), and a face with none reads NaN; a point probe reads sim.sample's value. The face and
# sim.sample agree to 1.8e-9 in float (launches of 24 points and of 1 round differently).
clsph_run_test(run_probe_face ${CASE_DIR}/probe_face.lua
               BOUNDS "face_error<1e-6" "face_exact<1e-5" "points_error<1e-6" "dry>0.5"
                      "point_error<1e-6")
# A pressure sensor on a wall's face (cases/hydrostatic.lua, the probe "side_wall" on the right
# wall from 0.4 to 0.6 of the depth, dr = H/20): on a vertical wall the one-sided interpolation of
# the fluid reads the pressure at the same depth inside. isph-usaw (vertex particles on the wall):
# 3.0e-5 of ρ g H/2 from the exact, 1.6e-5 from the centre line at the same depths (7.5e-6 and
# 4.1e-6 in float); wcsph-riemann (dummy walls, fluid on one side only): 9.6e-4 from the centre
# line (1.5e-3 in float) and 4.1% from the exact (2.5% in float), the lift of the whole tank by
# its surface rows (4.0% on the centre line; 2.1% at dr = H/40).
clsph_run_test(run_probe_wall_usaw ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua SETS dr=0.05 t_end=1
               BOUNDS "side_wall_error<1e-3" "side_wall_vs_centre<1e-3")
clsph_run_test(run_probe_wall_riemann ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               SETS riemann=1 dr=0.05 t_end=2
               BOUNDS "side_wall_vs_centre<0.005" "side_wall_error<0.06")
# sample(sim) writes a row of series.csv with each of the 5 snapshots, which sim.series reads
# back (as recorded, 9 digits); sim.max over a region that holds particles, and nil for one that
# holds none yet (written -1 by the case).
clsph_run_test(run_free_fall ${CMAKE_SOURCE_DIR}/cases/free_fall.lua SETS dr=0.04
               BOUNDS "drop_error<0.15" "speed_error<1e-4" "samples>4.5" "samples<5.5"
                      "sample_last_error<1e-8" "top_below<1.6" "top_below>1.5")
clsph_run_test(run_periodic_drift ${CMAKE_SOURCE_DIR}/cases/periodic_drift.lua SETS dr=0.05
               BOUNDS "speed_error<1e-4" "x_min>-1e-9" "x_max<1")
clsph_run_test(run_geometry_showcase ${CMAKE_SOURCE_DIR}/cases/geometry_showcase.lua)
# Initial velocities of the fluid (fill { velocity = function | {u, v} }), carried unchanged by
# the ballistic scheme: each particle keeps exactly what it was given (a missed or misplaced
# velocity reads 0.25 or more).
clsph_run_test(run_fill_velocity ${CASE_DIR}/fill_velocity.lua
               BOUNDS "shear_error<1e-6" "block_error<1e-6" "shear_particles>100")
clsph_cli_test(case_fill_velocity_function ARGS info ${CASE_DIR}/bad_fill_velocity.lua RC 2
               REGEX "velocity function returned number, nil.*bad_fill_velocity.lua:10: fluid region 'layer': its velocity at \\(0.05, 0.05\\) failed")
clsph_cli_test(case_fill_velocity_value ARGS info ${CASE_DIR}/bad_fill_velocity.lua --set which=2
               RC 2 REGEX "fill 'layer': velocity must be \\{u, v\\}")

clsph_add_test(restart_bit_for_bit LABELS case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CMAKE_SOURCE_DIR}/cases/free_fall.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/restart "-DSETS=dr=0.04|t_end=0.1"
               -P ${CASE_DIR}/restart.cmake)
clsph_add_test(long_out LABELS case COMMAND ${CMAKE_COMMAND} -DCLSPH=$<TARGET_FILE:clsph>
               -DCASE=${CMAKE_SOURCE_DIR}/cases/free_fall.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/long_out -P ${CASE_DIR}/long_out.cmake)
clsph_add_test(out_reuse LABELS case COMMAND ${CMAKE_COMMAND} -DCLSPH=$<TARGET_FILE:clsph>
               -DCASE=${CASE_DIR}/outputs.lua -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/out_reuse
               -P ${CASE_DIR}/out_reuse.cmake)
if(Python3_Interpreter_FOUND)
  clsph_add_test(restart_scene LABELS case COMMAND ${CMAKE_COMMAND} -DCLSPH=$<TARGET_FILE:clsph>
                 -DCASE=${CMAKE_SOURCE_DIR}/cases/periodic_drift.lua -DPYTHON=${Python3_EXECUTABLE}
                 -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/restart_scene
                 -P ${CASE_DIR}/restart_scene.cmake)
endif()
if(Python3_Interpreter_FOUND)
  clsph_add_test(interrupt LABELS case COMMAND ${Python3_EXECUTABLE} ${CASE_DIR}/interrupt.py
                 $<TARGET_FILE:clsph> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/runs/interrupt)
endif()
# A scene far too large is refused before its particles are made (4e8 of them here: minutes of
# geometry and gigabytes of host memory otherwise).
clsph_cli_test(case_fluid_too_large ARGS info ${CMAKE_SOURCE_DIR}/cases/cavity.lua --set n=20000
               --device-memory 100 RC 2
               REGEX "the fluid regions hold about 4e\\+08 particles at dr = 5e-05: their positions and velocities alone need [0-9]+ MiB")
# sample() values that cannot go into series.csv stop the run with the reason (status "sample()
# failed", class "metrics")
foreach(which 1 2 3)
  clsph_add_test(case_bad_sample_${which} LABELS case COMMAND ${CMAKE_COMMAND}
                 -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CASE_DIR}/bad_sample.lua
                 -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/bad_sample_${which} -DSETS=which=${which}
                 -DRC=2 -DFAILURE=metrics "-DREGEX=sample\\(\\) failed at step"
                 "-DMESSAGE=is not a column name|returned other names than at its first call|every entry must be name = number"
                 -P ${CASE_DIR}/run_failure.cmake)
endforeach()
clsph_add_test(memory_refused LABELS case COMMAND ${CMAKE_COMMAND} -DCLSPH=$<TARGET_FILE:clsph>
               -DCASE=${CMAKE_SOURCE_DIR}/cases/cavity.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/memory_refused -P ${CASE_DIR}/memory.cmake)
clsph_add_test(restart_refused LABELS case COMMAND ${CMAKE_COMMAND} -DCLSPH=$<TARGET_FILE:clsph>
               -DCASE_A=${CMAKE_SOURCE_DIR}/cases/periodic_drift.lua
               -DCASE_B=${CMAKE_SOURCE_DIR}/cases/free_fall.lua
               -DNOT_CHECKPOINT=${CMAKE_SOURCE_DIR}/README.md
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/restart_refused -P ${CASE_DIR}/restart_refused.cmake)
# A run that blows up stops with the step and the reason and exits non-zero (ballistic particles
# fall through the floor, which they do not see, and leave the domain).
clsph_cli_test(run_blowup_escape RC 1
               ARGS run ${CMAKE_SOURCE_DIR}/cases/free_fall.lua --set t_end=3 --set dr=0.05
                    --quiet --overwrite --out ${CMAKE_CURRENT_BINARY_DIR}/runs/blowup
               REGEX "blow-up: [0-9]+ fluid particle\\(s\\), [0-9.]+% of the fluid, left the domain by step [0-9]+")
clsph_cli_test(run_needs_case ARGS run RC 2 REGEX "run: name the case script")

# isph-usaw: the hydrostatic tank at a coarse resolution (20 x 20 particles, 1 s). The paper's
# figures (dr = 0.02 m, 5 s: pressure within 0.03%) are a validation run outside CI. Bounds: the
# speed criterion of the validation (1e-3 √(gH)); the pressure within 3% of ρg(H − z) (the
# coarse lattice's interpolation error at the sample points: 1.9% measured).
clsph_run_test(run_hydrostatic_coarse ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               SETS dr=0.05 t_end=1
               BOUNDS "speed_ratio<1e-3" "pressure_error<0.03" "crossed_wall<0.5")

# wcsph-usaw on the same tank (pressure_form = "dynamic", the case's default for the baseline):
# measured 1.4% and 6.4e-4 √(gH) at 1 s; the same bounds. Its density diffusion once diffused the
# hydrostatic stratification instead of leaving it out, and the tank sank through its bottom.
clsph_run_test(run_hydrostatic_coarse_wcsph ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               SETS dr=0.05 t_end=1 wcsph=1
               BOUNDS "speed_ratio<1e-3" "pressure_error<0.03" "crossed_wall<0.5")

# wcsph-usaw's default sound speed, c0 = 10 U (solvers/wcsph_usaw/wcsph_usaw.c), printed when the
# scheme is created, by `clsph info` and `clsph run` alike: a tank of water 0.4 m deep gets
# U = √(2 g D) from the water's depth, the same with side walls 1 m and 2.5 m high (it took
# 10 √(g H) from the domain's height H before: 31.32 and 49.52 m/s), and the time step 0.2 h/c0
# follows; set going at 4 m/s it gets U = 4 m/s (before: 31.32 m/s again). A case that sets
# sound_speed is told the default it overrides.
set(c0_message "sound speed c0 = 28.01 m/s = 10 U, U = 2.801 m/s from .*D = 0.4 m the fluid's depth")
clsph_cli_test(case_wcsph_sound_speed ARGS info ${CASE_DIR}/sound_speed.lua RC 0
               REGEX "${c0_message}" REGEX2 "time step 0.000713922 s")
clsph_cli_test(case_wcsph_sound_speed_walls ARGS info ${CASE_DIR}/sound_speed.lua --set top=2.5
               RC 0 REGEX "${c0_message}" REGEX2 "time step 0.000713922 s")
clsph_cli_test(case_wcsph_sound_speed_velocity ARGS info ${CASE_DIR}/sound_speed.lua --set u=4
               RC 0 REGEX "sound speed c0 = 40 m/s = 10 U, U = 4 m/s from the initial fluid speed"
               REGEX2 "time step 0.0005 s")
clsph_cli_test(case_wcsph_sound_speed_run RC 0
               ARGS run ${CASE_DIR}/sound_speed.lua --set top=2.5 --overwrite
                    --out ${CMAKE_CURRENT_BINARY_DIR}/runs/wcsph_sound_speed
               REGEX "${c0_message}" REGEX2 "done: t = 0.001 s")
clsph_cli_test(case_wcsph_sound_speed_given ARGS info ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               --set wcsph=1 RC 0
               REGEX "sound speed c0 = 34.31 m/s \\(scheme option sound_speed; the default 10 U would be 24.26 m/s, U = 2.426 m/s from .*D = 0.3 m")

# isph-usaw: the lid-driven cavity at Re = 100, coarse (20 particles per side, 10 s): the
# centreline velocities against Ghia et al. 1982 within the coarse run's deviation (measured
# RMS 0.091 U for u and 0.021 U for v at this resolution; 0.116 U and 0.031 U with the paper's
# wall_distance_floor of 1, whose lid drags the first row at half its shear; the bounds leave 30%
# for the float build and the time stepping). Sampled by first-order moving least squares
# (interpolation = "linear"), which does not lag next to the walls as Shepard's average does:
# 0.029 U and 0.017 U; bounds 40% above. The paper's resolutions are validation runs outside CI.
# The particles' own u on x = 1/2 against Ghia's table read by cubics (no interpolation of ours):
# RMS 0.018 U (float 0.019 U), and the two rows under the lid lag it by 0.046 U (float 0.049 U):
# most of the error of the coarse cavity is there (tests/validation/RESULTS_cavity_causes.md);
# bounds 40% above, the lag between 0 and 0.07 U.
clsph_run_test(run_cavity_coarse ${CMAKE_SOURCE_DIR}/cases/cavity.lua SETS n=20 t_end=10
               BOUNDS "u_rms_vs_ghia<0.12" "v_rms_vs_ghia<0.029" "wall_crossing_steps<0.5"
                      "u_rms_linear<0.042" "v_rms_linear<0.024" "u_rms_particles<0.027"
                      "u_lid_rows<0" "u_lid_rows>-0.07")

# wcsph-usaw, the baseline, on the same coarse cavity (measured RMS 0.131 U for u, 0.045 U for v,
# its wall term at u* (usaw/viscous.cl); before, 0.137 U for u, 0.039 U for v;
# 0.121 U and 0.043 U with dρ/dt from u^n, and at 32 across 0.070 U and 0.026 U against 0.074 U and
# 0.028 U).
# Its particles do cross the walls near the lid's corners (about 870 of 5000 steps have one or two
# fluid particles behind a wall; the deepest 0.21 dr): measured and reported, not bounded here.
clsph_run_test(run_cavity_coarse_wcsph ${CMAKE_SOURCE_DIR}/cases/cavity.lua SETS n=20 t_end=10 wcsph=1
               BOUNDS "u_rms_vs_ghia<0.16" "v_rms_vs_ghia<0.06")
clsph_cli_test(case_time_step_above_bound RC 2
               ARGS run ${CASE_DIR}/bad_dt.lua --quiet --overwrite
                    --out ${CMAKE_CURRENT_BINARY_DIR}/runs/bad_dt
               REGEX "fixed time step 0.5 s exceeds the stability bound [0-9.e-]+ s of isph-usaw")

# --profile: the device time per kernel of a tiny isph-usaw run, printed (not under --quiet) and
# in summary.json; grid_bin sorts the particles every step.
clsph_add_test(run_profile LABELS case COMMAND ${CMAKE_COMMAND} -DCLSPH=$<TARGET_FILE:clsph>
               -DCASE=${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/profile "-DSETS=dr=0.1|t_end=0.05"
               -DKERNEL=grid_bin -P ${CASE_DIR}/profile.cmake)

# Issue 22's budget of an isph-usaw step with the solver's kernels fused (solver_fuse = "fused",
# the default on a GPU), the 40² cavity from t = 1 to 2 s: at most 100 kernel launches a step (98.8
# measured in double, 77.3 in float, with 6.6 and 4.1 solver iterations a step) and 2 blocking
# reads, its flags and the solve's state, plus a second read of the state in the steps whose solve
# ran past its batch (the last solve's iterations): 2.205 a step measured in double and 2.130 in
# float, at most 2.3 asked.
clsph_add_test(step_budget LABELS case COMMAND ${CMAKE_COMMAND} -DCLSPH=$<TARGET_FILE:clsph>
               -DCASE=${CMAKE_SOURCE_DIR}/cases/cavity.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/step_budget "-DSETS=n=40|fuse=1" -DSHORT=1
               -DLONG=2 -DMAX_LAUNCHES=100 -DMAX_READS_K=2300 -P ${CASE_DIR}/step_budget.cmake)

# The viscous wall force (Leroy et al. 2014 eqs 69-70) on a plane Couette flow (10 particles
# across, 1 viscous time): the fluid drags the fixed floor by +µUL/H and the sliding ceiling by
# −µUL/H; a flat wall feels no x pressure force; the particles' velocity is U y/H. The sign is
# checked exactly (a wrong sign is an error of 2). With the paper's viscous wall term (eq 15 with
# δr_as = max(r_as·n_s, δr), eq 17; wall_distance_floor = 1, wcsph-usaw's default) the first row,
# δr/2 off the wall, feels half its wall shear: it slips by 0.038 U (isph-usaw; 0.037 U
# wcsph-usaw), the interior's slope is 0.94 U/H, and the force reads 18% high (0.181, 0.187)
# because G− at the wall sees the first row's steeper step. With δr_as floored at δr/2
# (isph-usaw's default, usaw/viscous.cl) the slip is 0.0024 U (0.0006 U) and the force is within
# 0.04% (0.34%). Same figures in float. Bounds: about 3 times the measured errors; the paper's form
# must show its slip (> 0.02 U), which also checks that the option reaches the kernel.
# Sampling the same flow: Shepard's average lags by up to 0.080 U within h of the walls, the
# first-order moving least squares fit (interpolation = "linear") reads 0.0026 U, the particles'
# own error (kernels/common/probe.cl); the Shepard bound shows the lag it corrects.
clsph_run_test(run_couette_force ${CASE_DIR}/couette_force.lua
               BOUNDS "floor_error<0.002" "ceiling_error<0.002" "floor_pressure_x<1e-12"
                      "slip<0.007" "u_err_max<0.007" "interp_linear<0.008" "interp_shepard>0.04")
clsph_run_test(run_couette_force_paper ${CASE_DIR}/couette_force.lua SETS floor=1
               BOUNDS "floor_error<0.25" "ceiling_error<0.25" "slip>0.02")
clsph_run_test(run_couette_force_wcsph ${CASE_DIR}/couette_force.lua SETS wcsph=1
               BOUNDS "floor_error<0.25" "ceiling_error<0.25" "floor_pressure_x<1e-12" "slip>0.02")
clsph_run_test(run_couette_force_wcsph_half ${CASE_DIR}/couette_force.lua SETS wcsph=1 floor=0.5
               BOUNDS "floor_error<0.01" "ceiling_error<0.01" "slip<0.002" "u_err_max<0.005")
set(bad_floor ${CASE_DIR}/bad_wall_distance_floor.lua)
set(floor_range "wall_distance_floor must be in .0, 1. spacings .*1 is the paper.s eq 17")
clsph_cli_test(case_wall_distance_floor_zero ARGS info ${bad_floor} RC 2
               REGEX "bad_wall_distance_floor.lua: ${floor_range}.*, not 0")
clsph_cli_test(case_wall_distance_floor_above ARGS info ${bad_floor} --set what=1 RC 2
               REGEX "${floor_range}.*, not 1.5")
clsph_cli_test(case_wall_distance_floor_text ARGS info ${bad_floor} --set what=2 RC 2
               REGEX "wall_distance_floor must be a number of spacings, not \"half\"")
clsph_cli_test(case_wall_distance_floor_wcsph ARGS info ${bad_floor} --set what=3 RC 2
               REGEX "${floor_range}")
clsph_cli_test(case_wall_distance_floor_nan ARGS info ${bad_floor} --set what=4 RC 2
               REGEX "${floor_range}.*, not -?nan")

# The segment cache (usaw/gamma.cl): usaw_gamma keeps each particle's segments of non-zero ∇γ_as
# and their quadrature for the sweeps, which otherwise walk the segment grid; both ways must give
# the same bits, with 8 slots (the default) and with 2 (most particles by the wavy floor overflow
# and walk). The case's sloped segments cross the periodic seam: a wrong image in a slot (the x
# shift taken as 0) fails all three (measured).
foreach(v isph wcsph)
  set(w 0)
  if(v STREQUAL "wcsph")
    set(w 1)
  endif()
  foreach(k 8 2)
    clsph_add_test(seg_cache_${v}_${k} LABELS case COMMAND ${CMAKE_COMMAND}
                   -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CASE_DIR}/seg_cache.lua
                   -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/seg_cache_${v}_${k} "-DSETS=wcsph=${w}"
                   -DSETS_A=segment_cache=0 -DSETS_B=segment_cache=${k} "-DEXACT=pos|vel|p"
                   -P ${CASE_DIR}/same_state.cmake)
  endforeach()
endforeach()
set(bad_cache ${CASE_DIR}/bad_segment_cache.lua)
set(cache_range "segment_cache must be a whole number of segments a particle from 0 .none. to 64")
clsph_cli_test(case_segment_cache_fraction ARGS info ${bad_cache} RC 2
               REGEX "bad_segment_cache.lua: ${cache_range}, not 2.5")
clsph_cli_test(case_segment_cache_negative ARGS info ${bad_cache} --set what=1 RC 2
               REGEX "${cache_range}, not -1")
clsph_cli_test(case_segment_cache_text ARGS info ${bad_cache} --set what=2 RC 2
               REGEX "segment_cache must be a whole number of segments a particle, not \"many\"")
clsph_cli_test(case_segment_cache_wcsph ARGS info ${bad_cache} --set what=3 RC 2
               REGEX "${cache_range}, not 65")
clsph_cli_test(case_segment_cache_nan ARGS info ${bad_cache} --set what=4 RC 2
               REGEX "${cache_range}, not -?nan")

# The infinite array of cylinders in a channel (Leroy et al. 2014 sec 4.2), coarse: 20 particles
# across the channel (the paper's 120), 12 s (the drag is steady within 0.1% from 8 s on at this
# resolution), flow-rate control of the body force (eqs 67-68), C_D = F_D/(µ⟨v⟩) against
# 106.77 (Liu et al.). Measured C_D: isph-usaw 85.9 (error 0.196; 79.2 and 0.258 with the paper's
# wall_distance_floor of 1, usaw/viscous.cl); wcsph-usaw 49.3 (error 0.539; 49.6 with the wall term
# explicit;
# its pressure drag is a third of isph-usaw's: with the paper's equal time steps its sound speed
# is 1.6 ν/h = 0.02 m/s, and ρc0² = 0.4 Pa is only 20 times the flow's pressure differences;
# 25 times that sound speed gives 74.4) and it is not steady: its viscous drag keeps falling
# (C_D 52 at 6 s, 40 at 24 s), so this bound holds the 12 s value only.
# The paper's convergence study is a validation run (tests/validation/run.sh).
clsph_run_test(run_cylinder_array_coarse ${CMAKE_SOURCE_DIR}/cases/cylinder_array.lua
               SETS n=20 t_end=12 BOUNDS "cd_error<0.25")
clsph_run_test(run_cylinder_array_coarse_wcsph ${CMAKE_SOURCE_DIR}/cases/cylinder_array.lua
               SETS n=20 t_end=12 wcsph=1 BOUNDS "cd_error<0.56")
# The flow-rate control's state (F, ṽ^{n−1}, ṽ^{n−2}) travels in the checkpoint: a resumed run
# ends bit for bit where the uninterrupted one ended.
clsph_add_test(restart_flow_control LABELS case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CMAKE_SOURCE_DIR}/cases/cylinder_array.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/restart_flow "-DSETS=n=12|t_end=1"
               -P ${CASE_DIR}/restart.cmake)
# The same with wcsph-usaw (its temporaries: u*, the viscous term, dρ/dt, ∇γ and the collision
# marks, made in every step before they are read; a checkpoint that lacks one still restarts:
# test io).
clsph_add_test(restart_wcsph LABELS case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CMAKE_SOURCE_DIR}/cases/cylinder_array.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/restart_wcsph "-DSETS=n=12|t_end=1|wcsph=1"
               -P ${CASE_DIR}/restart.cmake)
clsph_cli_test(case_bad_flow_control ARGS info ${CASE_DIR}/bad_flow_control.lua RC 2
               REGEX "bad_flow_control.lua:4: fluid: flow_rate_control: needs slice")

# The dam break over a wedge (Leroy et al. 2014 sec 4.3), isph-usaw, coarse: δr = 0.02 m (1500
# particles, the paper's δr is 0.01 m), the paper's 2 s. No particle may cross a wall (the
# issue's criterion). The largest speed at 2 s, when the water sloshes in the pool, stays below
# √(gH) (measured 0.41 in double, 0.39 in float); a particle thrown by a bad pressure (as once by
# the eq 38 velocity correction, 13.6 m/s = 4.4 √(gH)) fails it. The normal pressure force on the
# wedge's left side averaged over 0.25-2 s: measured 1109 N/m in double and 1098 N/m in float at
# the case's C_CFL = 0.2 (0.49 and 0.48 √(gH) at 2 s; at 0.1, `cfl=1`: 1153 and 1145 N/m, and
# 1132 and 1145 N/m before the no-tension bound of isph_usaw/ppe.cl; at rest the water would push
# with 811 N/m); the bounds are ±20%. The run itself must reach
# 2 s: a blow-up (a clump, a kick out of the pool) fails the test.
clsph_run_test(run_wedge_coarse ${CMAKE_SOURCE_DIR}/cases/dam_break_wedge.lua SETS dr=0.02
               BOUNDS "crossed_wall<0.5" "max_speed_over_sqrt_gH<1" "wedge_force_mean>900"
                      "wedge_force_mean<1400")

# The free-surface kernel makes the pressure equation's right-hand side in its own loops where
# density_relaxation is 0 (free_surface.cl); a relaxation of 1e-300 (a term under the rounding of
# every row but the exact zeros, 0 in float) takes the separate kernel, isph_ppe_rhs. A released
# column's first 0.1 s both ways (tests/case/rhs_fused.lua, 23 steps: its top and side rows
# Dirichlet, the rest falling): the same free-surface flags, and the rest within what the rows at
# rest, 1e-292 in place of 0, make of the solves, which then stop a rounding apart inside their
# tolerance (measured: bit for bit in float; in double P and positions to 1e-11 relative, D{r} to
# 1e-10, the right-hand side (up to 4e9) to 1e-5 absolute; the wall term 0.1% off fails at P).
clsph_add_test(rhs_fused LABELS case COMMAND ${CMAKE_COMMAND} -DCLSPH=$<TARGET_FILE:clsph>
               -DCASE=${CASE_DIR}/rhs_fused.lua -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/rhs_fused
               -DSETS=t_end=0.1 -DSETS_A=relax=0 -DSETS_B=relax=1e-300 -DEXACT=free_surface
               "-DREL=P|pos|div_r" -DABS=rhs -DABS_TOL=1e-3 -P ${CASE_DIR}/same_state.cmake)

# The same with wcsph-usaw (its wall guard and collisions of u*, usaw/common.cl; without them the
# meniscus crept through the left wall from 0.087 s and pairs clumped at 0.67 s): measured 0 wall
# crossings, 0.31 √(gH) at 2 s and 1046 N/m (9% below isph-usaw; 0.30 and 1042 N/m in float, and
# 0.51 and 1075 N/m with dρ/dt from u^n, before the symplectic density update); the same bounds.
clsph_run_test(run_wedge_coarse_wcsph ${CMAKE_SOURCE_DIR}/cases/dam_break_wedge.lua
               SETS dr=0.02 wcsph=1
               BOUNDS "crossed_wall<0.5" "max_speed_over_sqrt_gH<1" "wedge_force_mean>900"
                      "wedge_force_mean<1400")
# wcsph-usaw's momentum = "fused" (the default without k-ε: u* and the pressure force in one
# sweep, then the collisions and the wall guard, wcsph_usaw/update.cl)
# against "separate" (usaw_predict and wcsph_velocity, the k-ε model's path): the same bits. The
# coarse wedge to 0.5 s collides (with the collisions left out of wcsph_finish the fused run stops
# at t = 0.428 s, particles clustered: measured), so the marks of wcsph_momentum are tested too.
clsph_add_test(wcsph_momentum_fused LABELS case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CMAKE_SOURCE_DIR}/cases/dam_break_wedge.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/wcsph_momentum "-DSETS=wcsph=1|dr=0.02|t_end=0.5"
               -DSETS_A=momentum=1 -DSETS_B=momentum=2 "-DEXACT=pos|vel|p"
               -P ${CASE_DIR}/same_state.cmake)
set(momentum_values "momentum must be \"fused\" .*, \"separate\" or \"auto\" .*")
clsph_cli_test(momentum_word ARGS info ${CASE_DIR}/bad_momentum.lua --set what=1 RC 2
               REGEX "bad_momentum.lua: ${momentum_values}, not \"merged\"")
clsph_cli_test(momentum_number ARGS info ${CASE_DIR}/bad_momentum.lua --set what=2 RC 2
               REGEX "bad_momentum.lua: ${momentum_values}, not the number 1")
clsph_cli_test(momentum_fused_ke ARGS info ${CASE_DIR}/bad_momentum.lua --set what=3 RC 2
               REGEX "bad_momentum.lua: momentum = \"fused\" has no form under the k-epsilon model")

# Validation runs at the papers' resolutions (label "slow": not in CI; tests/validation/run.sh
# runs them with the rest and regenerates RESULTS.md). The bounds are the issue's criteria or the
# measured errors with a margin; the wall times are in RESULTS.md.
# Hydrostatic tank, δr = 0.02 m, 5 s: pressure within 1% below 3 δr (measured 2.2e-6), largest
# speed below 1e-3 √(gH) (measured 2.5e-5; 0.025 while the implicit wall term dragged on u*
# itself, usaw/viscous.cl), no particle through a wall. In CI (3 s): labelled slow, it failed
# unseen from 64a2674 to d11dd0d.
clsph_run_test(validate_hydrostatic ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               BOUNDS "pressure_error<0.01" "speed_ratio<1e-3" "crossed_wall<0.5")
# The same with wcsph-usaw (measured 0.45% and 8.5e-4 √(gH), 19580 steps).
clsph_run_test(validate_hydrostatic_wcsph ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua LABELS slow
               SETS wcsph=1
               BOUNDS "pressure_error<0.01" "speed_ratio<1e-3" "crossed_wall<0.5")
# Cavity, Re = 100, 120² (the paper's), 10 s: measured u RMS 0.00126 U, v RMS 0.0043 U (527 s
# alone, 9.9 BiCGStab iterations a step); 0.0064 U and 0.0048 U with the paper's
# wall_distance_floor of 1 (usaw/viscous.cl).
clsph_run_test(validate_cavity_re100 ${CMAKE_SOURCE_DIR}/cases/cavity.lua LABELS slow
               SETS re=100 n=120 t_end=10
               BOUNDS "u_rms_vs_ghia<0.0025" "v_rms_vs_ghia<0.0055" "wall_crossing_steps<0.5")
# Cylinder array, 40 across the channel, 24 s: measured C_D 98.9 (error 0.073; 22 s alone); 95.1
# (0.110) with the paper's wall_distance_floor of 1 (usaw/viscous.cl).
clsph_run_test(validate_cylinder_array ${CMAKE_SOURCE_DIR}/cases/cylinder_array.lua LABELS slow
               SETS n=40 t_end=24 BOUNDS "cd_error<0.09")

# Dam break over a wedge at the paper's δr = 0.01 m, 2 s, both schemes: no wall crossing (the
# issue's criterion); mean normal force on the wedge's left side from 0.25 s measured 1082 N/m
# (isph-usaw at the case's C_CFL = 0.2, 1891 steps; 1127 N/m in 3922 steps at 0.1) and 1052 N/m
# (wcsph-usaw; 1072 N/m with dρ/dt from u^n), within 5% of the coarse runs: ±20% as in CI.
clsph_run_test(validate_wedge ${CMAKE_SOURCE_DIR}/cases/dam_break_wedge.lua LABELS slow
               BOUNDS "crossed_wall<0.5" "wedge_force_mean>900" "wedge_force_mean<1400")
clsph_run_test(validate_wedge_wcsph ${CMAKE_SOURCE_DIR}/cases/dam_break_wedge.lua LABELS slow
               SETS wcsph=1
               BOUNDS "crossed_wall<0.5" "wedge_force_mean>900" "wedge_force_mean<1400")

# The dam break of Lobovsky et al. 2014 (cases/dam_break.lua), wcsph-riemann at n = 160 (dr =
# 1.875 mm, 51200 fluid particles) to t = 1.1 s (t* = 6.3), about 8 minutes alone on 2 cores:
# sensor 1 against one repetition of the experiment (event 5). Measured in double (float):
# impact at t* = 2.460 (2.466), 0.66% (0.90%) late (the issue's criterion: 2%; 1.8% at n = 120,
# 3.2% at 80); largest sample 4.05 (3.62), 1.33 (1.19) × 3.044; mean over 0.1 after the impact
# 1.05 (0.89) × the experiment's; plateaus 0.674 (0.666) on t* ∈ [3, 4], 0.84 (0.83) × 0.80, the
# same at n = 80 and 120, and 0.644 (0.652) on [4, 5], 0.99 (1.00) × 0.65; RMS 0.120 (0.117) over
# [2.6, 5.5] in bins of 0.1. The paper's spread of the peak is not in our data (the paper was not
# at hand; event 5 is one repetition, and the paper's point is that impact peaks scatter widely
# between repetitions): the band is a factor 2 either way, also as a sample each ms puts two
# samples on the experiment's 2 ms rise. The mean over 0.1 after the impact is held to a third
# either way, the plateaus to ±20% (the experiment swings 0.6 to 0.9 along its plateau), the RMS
# below 0.15 (that swing).
clsph_run_test(validate_lobovsky_riemann ${CMAKE_SOURCE_DIR}/cases/dam_break.lua LABELS slow
               SETS riemann=1 n=160 t_end=1.1
               BOUNDS "impact_time_error>-0.02" "impact_time_error<0.02" "peak_ratio>0.5"
                      "peak_ratio<2" "impact_mean_ratio>0.75" "impact_mean_ratio<1.33"
                      "plateau_ratio>0.8" "plateau_ratio<1.2" "plateau2_ratio>0.8"
                      "plateau2_ratio<1.2" "rms_p_star<0.15" "volume_ratio>0.999")

# The health checks of the time loop (host/sim/checks.c): each failure class stops the run with exit
# status 1, its reason in the message and in summary.json, and its class in "failure".
# BOUNDS: bounds on the metrics of the state the run stopped in (summary.json metrics_at_stop);
# NO_METRICS: none written (metrics() failed there).
function(clsph_failure_test name case failure regex)
  cmake_parse_arguments(T "NO_METRICS" "MESSAGE" "SETS;BOUNDS" ${ARGN})
  string(REPLACE ";" "|" sets "${T_SETS}")
  string(REPLACE ";" "|" bounds "${T_BOUNDS}")
  clsph_add_test(${name} LABELS case COMMAND ${CMAKE_COMMAND} -DCLSPH=$<TARGET_FILE:clsph>
                 -DCASE=${case} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/${name} "-DSETS=${sets}"
                 -DFAILURE=${failure} "-DREGEX=${regex}" "-DMESSAGE=${T_MESSAGE}"
                 "-DBOUNDS=${bounds}" -DNO_METRICS=${T_NO_METRICS} -P ${CASE_DIR}/run_failure.cmake)
endfunction()
# Every stop message names the run { checks = { ... } } setting that sets its limit, with its
# value, or says what to look at where no setting controls the check.
# Clustering: on a still lattice (scheme "none", h = 2 dr) every nearest fluid neighbour is
# dr = h/2 away; counted as clustered below 0.505 h = 1.01 dr, the whole fluid is (100% > 0.5%)
# and the run stops at its first check; below 0.495 h none is, and the run ends "ok" (the distance
# and the threshold are compared exactly).
clsph_failure_test(health_clustering ${CASE_DIR}/still_lattice.lua clustering
                   "particles cluster: 100% of the fluid has a fluid neighbour closer than 0.505 h = 1.01 dr .*\\(run { checks = { cluster_h = 0.505, cluster_fraction = 0.005 } } sets these limits\\)"
                   SETS cluster=0.505)
clsph_run_test(health_clustering_below ${CASE_DIR}/still_lattice.lua SETS cluster=0.495)
# A recorded clustering failure (study cavity_re_cfl): isph-usaw without shifting on the 16²
# cavity at Re = 400 packs pairs closer than h/8 = 0.25 dr from t = 1.25 s (4 of 256 particles,
# 0.16 dr at the check that stops it); with the check off it goes on clumping until a particle
# goes through a wall at step 181, t = 2.26 s (81 steps later).
clsph_failure_test(health_clustering_cavity ${CMAKE_SOURCE_DIR}/cases/cavity.lua clustering
                   "particles cluster: [0-9.]+% of the fluid has a fluid neighbour closer than 0.125 h = 0.25 dr .*\\(run { checks = { cluster_h = 0.125, cluster_fraction = 0.005 } } sets these limits\\)"
                   SETS n=16 re=400 cfl=1 shift=0 t_end=2)
# The clustering distance was cluster_spacing, in dr; a script that still sets it is refused with
# what replaced it and the equivalent value.
clsph_cli_test(health_cluster_spacing_refused ARGS info ${CASE_DIR}/health_cluster_spacing.lua
               RC 2 REGEX "health_cluster_spacing.lua:[0-9]+: run: checks: cluster_spacing \\(a distance in dr\\) was replaced by cluster_h.*cluster_spacing = 0.25 is cluster_h = 0.125 where h = 2 dr")
# Energy growth: ballistic particles under a body force that nothing resists (periodic in x, no
# viscosity) gain f t of speed; the scene's velocity scale is the free-fall speed √(2 f L) over
# the domain's diagonal L, so the mean square speed passes 4 U² at f t = 4.2 m/s, t = 2.1 s
# (run_periodic_drift stops at 1 s, at 0.9 U²).
clsph_failure_test(health_energy ${CMAKE_SOURCE_DIR}/cases/periodic_drift.lua energy
                   "kinetic energy grew to [0-9.]+ times .*\\(run { checks = { energy = 4 } } sets this limit\\)"
                   SETS dr=0.05 t_end=3)
# Wall crossing: isph-usaw at four times its CFL bound (the stability map of the cavity, README)
# lets a particle through a wall within 13 steps; a particle more than
# dr/2 behind a wall stops the run. (Shallower crossings are counted: the wcsph-usaw cavity,
# run_cavity_coarse_wcsph, has some and ends "ok".)
clsph_failure_test(health_wall_crossing ${CMAKE_SOURCE_DIR}/cases/cavity.lua wall_crossing
                   "a fluid particle crossed a wall \\([0-9.]+ dr behind it.*\\(run { checks = { wall_depth = 0.5 } } sets this limit, in dr\\)"
                   SETS n=20 cfl=4 t_end=5)
# The cavity's switches of the study cavity_re100_causes are 0 or 1, hdr (h/δr) 0 or in (0, 10],
# floor (δr) 0 or in (0, 1].
clsph_cli_test(case_cavity_bad_switch ARGS info ${CMAKE_SOURCE_DIR}/cases/cavity.lua --set corners=2
               RC 2 REGEX "cavity.lua:[0-9]+: cavity: corners must be 0 or 1, not 2")
# isph-usaw's pressure_guess: the solve started from the last two steps' pressures extrapolated
# in time takes fewer iterations than from the last step's (30² cavity, Re 100, to t = 2 s: 6.34
# against 6.72 a step in double, 0.944; 4.11 against 4.45 in float, 0.924; RATIO 0.98 asks for a
# third of the double's gain; with the runs swapped the test fails)
clsph_add_test(pressure_guess_iterations LABELS case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CMAKE_SOURCE_DIR}/cases/cavity.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/pressure_guess_iterations
               "-DSETS_A=n=30|t_end=2" "-DSETS_B=n=30|t_end=2|guess=0" -DRATIO=0.98
               -P ${CASE_DIR}/fewer_iterations.cmake)
clsph_cli_test(case_pressure_guess ARGS info ${CASE_DIR}/bad_pressure_guess.lua RC 2
               REGEX "bad_pressure_guess.lua: pressure_guess must be \"linear\" .* or \"last\"")
clsph_cli_test(case_pressure_guess_number ARGS info ${CASE_DIR}/bad_pressure_guess.lua --set what=2
               RC 2 REGEX "bad_pressure_guess.lua: pressure_guess must be \"linear\"")
clsph_cli_test(case_cavity_bad_fuse ARGS info ${CMAKE_SOURCE_DIR}/cases/cavity.lua --set fuse=0.5
               RC 2 REGEX "cavity.lua:[0-9]+: cavity: fuse must be 0, 1 or 2, not 0.5")
clsph_cli_test(case_cavity_bad_hdr ARGS info ${CMAKE_SOURCE_DIR}/cases/cavity.lua --set hdr=-1
               RC 2 REGEX "cavity: hdr \\(h/δr\\) must be 0 \\(the scheme.s\\) or in \\(0, 10.*, not -1")
clsph_cli_test(case_cavity_bad_floor ARGS info ${CMAKE_SOURCE_DIR}/cases/cavity.lua --set floor=2
               RC 2 REGEX "cavity: floor \\(in δr\\) must be 0 \\(the scheme.s\\) or in \\(0, 1.*, not 2")
# The lid's corner vertices moving with the lid (cases/cavity.lua corners = 1) drag the fluid
# under them into the side walls: through the right one at step 20, t = 0.2 s, at 20² (both
# precisions; 0.12 s at 30², 0.085 s at 40²). The cavity's corners stay at rest.
clsph_failure_test(health_wall_crossing_corners ${CMAKE_SOURCE_DIR}/cases/cavity.lua wall_crossing
                   "a fluid particle crossed a wall \\([0-9.]+ dr behind it.* at step [0-9]+, t = 0\\.[0-9]+ s"
                   SETS n=20 corners=1 t_end=2)
# Fluid leaving the domain is dropped and counted (host/sim/checks.c); when more than
# checks.escaped of it (1%) has gone, the run stops as escaped: the free-falling block through the
# floor of its box (12 of its 96 particles in the first step that loses any, in both precisions).
clsph_failure_test(health_escaped ${CMAKE_SOURCE_DIR}/cases/free_fall.lua escaped
                   "[0-9]+ fluid particle\\(s\\), [0-9.]+% of the fluid, left the domain by step [0-9]+, t = [0-9.]+ s \\(the first at step [0-9]+\\), more than run { checks = { escaped = 0.01 } } lets go; look in blowup.h5"
                   SETS t_end=3 dr=0.05)
# Escape: a fluid particle more than dr beyond the domain's box has left (domain.cl), at
# t = 0.575 s here (the block's front row, 4 of its 16), long before the cell grid's edge; with
# no walls and no periodic axis the scene is refused before it runs.
clsph_failure_test(health_escaped_dr ${CASE_DIR}/escape.lua escaped
                   "4 fluid particle\\(s\\), 25% of the fluid, left the domain by step [0-9]+, t = 0\\.(5[78]|6)")
# The whole fluid at once (one column of 4): the message says it was thrown out in one step.
clsph_failure_test(health_escaped_burst ${CASE_DIR}/escape.lua escaped
                   "4 fluid particle\\(s\\), 100% of the fluid, left the domain by step [0-9]+, .* 4 of them in this step: the fluid thrown out at once"
                   SETS width=0.05)
# Water spilling over the 0.22 m walls of an open tank (tests/case/spill.lua, a 0.2 m column,
# dr = 0.01 m, 200 particles, to 0.6 s): isph-usaw drops 2 particles of the run-up jet (at 0.42
# and 0.54 s; 1 in float) and runs on, every missing particle counted, none left outside the
# tank, no wall crossing (before, the first stopped the run); isph-stabilized drops 3 in both
# precisions (its coarse surge pairs 2% of the fluid at 0.02 dr: the clustering limit is raised
# to 5% here). A particle over the rim leaves at once, before it falls behind the wall: let to
# stray dr beyond the box, the isph-usaw run at dr = 0.005 m read one 0.93 dr behind the right
# wall at 0.52 s and stopped as a wall crossing.
foreach(method 0 1)
  set(extra "")
  if(method EQUAL 1)
    set(extra cluster=0.05)
  endif()
  clsph_run_test(run_spill_${method} ${CASE_DIR}/spill.lua SETS method=${method} ${extra}
                 BOUNDS "escaped>0.5" "escaped<10" "lost_vs_escaped>-0.5" "lost_vs_escaped<0.5"
                        "outside<0.5" "wall_crossings.steps<0.5" "escaped.particles>0.5")
endforeach()
# A splash above the cell grid falls back (tests/case/rise.lua: a block thrown up to 2.1 m over
# an open 1 m tank whose grid ends at 1.3 m, back at its start at t = 2 v/g): the side gravity
# points away from is open. Before, the grid's edge stopped the run at t = 0.26 s. rise_error,
# the block's distance from its start over the peak height: 0.037, semi-implicit Euler's
# g dt t/2 over the peak is 0.026 (dt = 7.9 ms); bound 0.06.
clsph_run_test(run_rise_open_top ${CASE_DIR}/rise.lua
               BOUNDS "rise_error<0.06" "escaped<0.5" "top<0.5" "escaped.particles<0.5")
# isph-stabilized's spray rule: fewer neighbours than a quarter of a full lattice support's make a
# free-surface row (5 of 20 in 2-D at h = 1.2 dr, 14 of 56 in 3-D), in the set-up's debug line.
clsph_cli_test(stab_spray_rule_2d RC 0
               ARGS run ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua --set stab=1 --set t_end=0.001
                    --verbose --overwrite --out ${CMAKE_CURRENT_BINARY_DIR}/runs/spray_rule_2d
               REGEX "free surface below rho\\*/rho0 = 0.97 or with fewer than 5 neighbours")
clsph_cli_test(stab_spray_rule_3d RC 0
               ARGS run ${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua --set t_end=0.001
                    --verbose --overwrite --out ${CMAKE_CURRENT_BINARY_DIR}/runs/spray_rule_3d
               REGEX "free surface below rho\\*/rho0 = 0.9 or with fewer than 14 neighbours")
# The rule on a clump of spray (tests/case/clump.lua: five particles 0.55 dr from the middle one,
# falling above a tank at rest): all five are free surface though they read s*/σ0 1.018 and more
# (double and float), and the solves converge in 8 iterations (double; 5 in float). With the rule
# off (fs_min = 0, tried in a build) none is, and every solve ran to its 1000 iterations with the
# residual at 4e47: the clump's block of rows has no given value.
clsph_run_test(run_stab_spray_clump ${CASE_DIR}/clump.lua
               BOUNDS "clump_surface>4.5" "clump_rho_min>0.97" "solver.iterations_max<30")
# With none allowed to leave, the first that does stops the run; metrics() still runs on the state
# it stopped in (summary.json metrics_at_stop, sim.stopped = "escaped"): the one particle dropped,
# none missing uncounted, none outside the tank.
clsph_failure_test(health_escaped_none ${CASE_DIR}/spill.lua escaped
                   "1 fluid particle\\(s\\), 0.5% of the fluid, left the domain by step [0-9]+, t = 0\\.[0-9]+ s \\(the first at step [0-9]+\\), more than run { checks = { escaped = 0 } } lets go"
                   SETS escaped=0
                   BOUNDS "stopped>0.5" "escaped>0.5" "escaped<1.5" "fluid_now>198.5"
                          "fluid_now<199.5" "lost_vs_escaped>-0.5" "lost_vs_escaped<0.5"
                          "outside<0.5")
# A metrics() that fails there is a warning: the stop's class and status stay, no metrics.
clsph_failure_test(health_escaped_metrics_error ${CASE_DIR}/spill.lua escaped
                   "left the domain by step [0-9]+.*more than run { checks = { escaped = 0 } } lets go"
                   SETS escaped=0 bad_metrics=1 NO_METRICS
                   MESSAGE "metrics\\(\\) refuses the state.*metrics\\(\\) of the state the run stopped in \\(escaped\\) failed: summary.json has none")
clsph_cli_test(case_checks_escaped ARGS info ${CASE_DIR}/spill.lua --set escaped=2 RC 2
               REGEX "run: checks: escaped is the fraction of the fluid that may leave the domain before the run stops: from 0 \\(none\\) to 1, not 2")
# A restart across the drops: from the checkpoint at 0.45 s (one particle dropped before it, and
# in double one after) the run ends bit for bit where the whole run did, with the same counts in
# its summary.
clsph_add_test(restart_escaped LABELS case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CASE_DIR}/spill.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/restart_escaped -P ${CASE_DIR}/restart.cmake)
clsph_cli_test(case_no_walls ARGS info ${CASE_DIR}/bad_no_walls.lua RC 2
               REGEX "bad_no_walls.lua: the walls do not close the fluid in: it can reach the")
# The pressure solver: ten solves in a row that do not converge stop the run.
clsph_failure_test(health_solver ${CASE_DIR}/solver_starved.lua solver
                   "the pressure solve failed at step 10,"
                   MESSAGE "the pressure solve failed 10 times in a row .*: stopping; the scheme options solver_rtol, solver_max_it and solver_precond")
# Solver options that no solve can meet are refused before the run, naming the option: a
# tolerance below 4 ε of the build's precision, not a number, 1, and no iteration at all.
clsph_cli_test(solver_rtol_below_eps ARGS info ${CASE_DIR}/bad_solver.lua --set what=1 RC 2
               REGEX "solver_rtol = 1e-20 is below what a (double|float) build can reach \\(4 ε = [0-9.e-]+\\).*bad_solver.lua: in scheme option solver_rtol")
clsph_cli_test(solver_rtol_nan ARGS info ${CASE_DIR}/bad_solver.lua --set what=2 RC 2
               REGEX "solver_rtol must be in \\(0, 1\\).*bad_solver.lua: in scheme option solver_rtol")
clsph_cli_test(solver_max_it_zero ARGS info ${CASE_DIR}/bad_solver.lua --set what=3 RC 2
               REGEX "solver_max_it must be 1 to 1e6.*bad_solver.lua: in scheme option solver_max_it")
clsph_cli_test(solver_rtol_one ARGS info ${CASE_DIR}/bad_solver.lua --set what=4 RC 2
               REGEX "solver_rtol must be in \\(0, 1\\).*bad_solver.lua: in scheme option solver_rtol")
clsph_cli_test(solver_group_max_negative ARGS info ${CASE_DIR}/bad_solver.lua --set what=5 RC 2
               REGEX "solver_group_max must be a whole number of unknowns from 0 \\(never\\) to 1e7.*bad_solver.lua: in scheme option solver_group_max")
clsph_cli_test(solver_fuse_unknown ARGS info ${CASE_DIR}/bad_solver.lua --set what=6 RC 2
               REGEX "solver_fuse must be \"separate\", \"fused\" or \"auto\".*bad_solver.lua: in scheme option solver_fuse")
# Healthy runs that the clustering check lets through with the default checks: flows that press
# particles together as they should, and reach their end (health.* bounds read summary.json's
# health block). Both came within the old limit, 0.5 dr, and were stopped there.
# The Taylor-Green vortex (isph-usaw, n = 32, Re = 100, to t = 1): the saddle points press pairs
# to 0.41 dr at t = 0.2 (12.5% of the fluid closer than 0.5 dr), then shifting spreads them. Its
# velocity error against the exact solution, in units of the exact amplitude, measured 0.0279 RMS
# and 0.0373 largest in double (0.0279 and 0.0379 in float), the kinetic energy 7.1% low (both);
# at n = 16 the same run gives 0.085, 0.110 and −20%, at n = 64 0.012, 0.016 and −3.0%. The
# bounds (0.04, 0.055, −10%) fail a run that has lost half the gain of one halving of dr.
# fill { pressure }: the Taylor-Green vortex starts from the exact pressure, which its sample() at
# t = 0 reads back at the particles (RMS error over ρU², mean-free: 0 up to round-off; 0.25 from
# p = 0, start_p=0), with isph-rotational, whose first predictions use it: over 4 steps (16², to
# t = 0.05) it keeps the kinetic energy within 0.064% of the exact decay, where the start from
# p = 0 loses 0.27%.
clsph_run_test(run_taylor_green_start_p ${CMAKE_SOURCE_DIR}/cases/taylor_green.lua
               SETS n=16 t_end=0.05 rotational=1
               BOUNDS "p_rms_start<1e-6" "energy_error>-0.0015" "energy_error<0.0015")
# And wcsph-usaw, whose density the fill's pressure sets through its equation of state: started
# from the exact pressure, the first acoustic waves (L/c0 = 0.1 s) are small: at t = 0.02 s (32²,
# 16 steps) the pressure error is 0.029 ρU² RMS and the kinetic energy 0.078% low; from p = 0
# (start_p=0) 0.099 ρU² and 0.32% low.
clsph_run_test(run_taylor_green_start_p_wcsph ${CMAKE_SOURCE_DIR}/cases/taylor_green.lua
               SETS n=32 t_end=0.02 wcsph=1
               BOUNDS "p_rms_start<1e-6" "p_rms<0.05" "energy_error>-0.0015" "energy_error<0.0015")
# fill { density } for wcsph-usaw: the density given, and the pressure of its equation of state,
# read back at t = 0 (exact in double; float: round-off of ρ ≈ 1000, 6e-8 relative)
clsph_run_test(run_fill_density ${CASE_DIR}/fill_density.lua
               BOUNDS "rho_error<1e-6" "p_error<1e-3")
clsph_run_test(health_taylor_green ${CMAKE_SOURCE_DIR}/cases/taylor_green.lua
               BOUNDS "vel_rms<0.04" "vel_max<0.055" "energy_error>-0.1" "energy_error<0"
                      "health.nearest_spacing_min_dr<0.45")
# The coarse dam break runs with the default checks (below, run_dam_break_coarse): the old
# clustering check stopped it at t = 0.354 s with 2.4% of the fluid closer than 0.5 dr, isph-usaw's
# collision distance (closest pairs 0.495 dr in double, 0.491 dr in float).

# Body-force Poiseuille flow at Re = 1 with isph-rotational (Hosseini & Feng 2011 sec 4.1), both
# projections, against the Morris et al. 1997 series (errors in units of U0 over the particle
# rows). dr = 0.1 H, to t = 1 (600 steps, ~7 s): measured in double, both projections alike as
# the paper says (n·∇p = 0 on every boundary): RMS 0.0049, 0.0016, 0.0070 and 0.038 at t = 0.02,
# 0.05, 0.1 and 1, largest 0.039 at t = 1 (the steady profile is 3.9% low: the odd extension of
# the velocity into the dummies, Morris et al., is first order at the wall).
# The walls' force (eqs 31-32, kernels/isph_rotational/force.cl) carries the body force at t = 1:
# measured 20% low with these dummies (their odd-reflected velocity slows the first rows; with
# wall_velocity = "image" 10% at dr = 0.1 and 5.4% at 0.05); no x pressure force on a flat wall.
foreach(proj IN ITEMS 0 1)
  clsph_run_test(run_poiseuille_rot_h${proj} ${CMAKE_SOURCE_DIR}/cases/poiseuille_periodic.lua
                 SETS dr=0.1 homogeneous=${proj}
                 BOUNDS "u_rms_t0p02<0.01" "u_rms_t0p05<0.005" "u_rms_t0p1<0.012"
                        "u_rms_t1<0.05" "u_max_t1<0.05" "wall_drag_error<0.25"
                        "wall_pressure_x<1e-9")
endforeach()
# The implicit viscous prediction (viscous = "implicit", not the paper's): the steps are bound by
# the body force and the outputs instead of 0.125 h²/ν (100 steps instead of 600), the walls'
# extrapolation is part of the solved system (kernels/isph_rotational/viscous.cl). Measured in
# double, rotational: RMS 0.0039, 0.0048, 0.011 and 0.038 at t = 0.02, 0.05, 0.1 and 1, largest
# 0.039 at t = 1: the steady profile is the explicit one's to 3 digits, the start-up is first order
# in the longer step (0.0049 at t = 0.02 from a step of 0.01). Without the viscous term the body
# force would accelerate the fluid without bound (u = g t = 8 U0 at t = 1).
clsph_run_test(run_poiseuille_rot_implicit ${CMAKE_SOURCE_DIR}/cases/poiseuille_periodic.lua
               SETS dr=0.1 implicit=1
               BOUNDS "u_rms_t0p02<0.006" "u_rms_t0p1<0.015" "u_rms_t1<0.05" "u_max_t1<0.05"
                      "wall_drag_error<0.25" "wall_pressure_x<1e-9")
# The paper's finer resolution, dr = 0.05 H (2300 steps, 44 s on 2 cores), measured in double:
# RMS 0.00077, 0.0041, 0.0093 and 0.027 at t = 0.02, 0.05, 0.1 and 1, largest 0.028 at t = 1.
foreach(proj IN ITEMS 0 1)
  clsph_run_test(run_poiseuille_rot_fine_h${proj} ${CMAKE_SOURCE_DIR}/cases/poiseuille_periodic.lua
                 SETS dr=0.05 homogeneous=${proj} LABELS slow
                 BOUNDS "u_rms_t0p02<0.002" "u_rms_t0p1<0.015" "u_rms_t1<0.035" "u_max_t1<0.035")
endforeach()

# The square cylinder (Hosseini & Feng 2011 sec 4.3), Re = 1, coarse: H/40 (the cylinder 5
# particles wide), to t = 2 D/U0 (280 steps), C_D averaged from t = 1. Measured in double: C_D
# 15.9 (Breuer et al. 2000: 24.0; the paper's rotational scheme is within 5% at H/40 and 2% at
# H/160: ours is 35% low here and 5% low at H/80, a validation run), the pressure 71% of it (the
# paper: about 2/3), lift 2e-5 (double) and 0.038 (float, the rounding of p ≈ 5 summed over the
# 181 wall points) against 15.9. Bounds: the measured C_D ± 25% (a change of the wall or force
# treatment moves it by more), the pressure share 0.6 to 0.8, and a lift that the symmetric flow
# keeps below 0.6% of the drag in both precisions; no fluid upstream of the entry.
clsph_run_test(run_square_cylinder_coarse ${CMAKE_SOURCE_DIR}/cases/square_cylinder.lua
               SETS n=40 t_end=2
               BOUNDS "cd>12" "cd<20" "pressure_share>0.6" "pressure_share<0.8" "cl<0.1"
                      "cl>-0.1" "upstream<1e-9")
# The same with the implicit viscous prediction: 40 steps instead of 280, C_D 15.67 (the explicit
# run's 15.91 over 1 <= t <= 2; over 1 <= t <= 10 they agree within 0.1%: 15.71 and 15.70, a
# validation run), the pressure 69% of it. Bounds: within 3% of the explicit run's C_D, which
# the step's transient error stays inside, and the same share and symmetry.
clsph_run_test(run_square_cylinder_coarse_implicit ${CMAKE_SOURCE_DIR}/cases/square_cylinder.lua
               SETS n=40 t_end=2 implicit=1
               BOUNDS "cd>15.43" "cd<16.39" "pressure_share>0.6" "pressure_share<0.8" "cl<0.1"
                      "cl>-0.1" "upstream<1e-9")

# isph-rotational with an entry and an exit (Hosseini & Feng 2011 sec 4.2): fully developed
# Poiseuille flow at Re = 1, parabolic entry, natural exit, dummies with the velocity of the
# particle at their image (the case's default), to t = 1 H/U0, 10 particles across (560 steps, 3
# to 10 s here), both projections. Measured, double and float alike to 3 digits: rotational
# p_err_max 0.065, u_err_max 0.014, u_err_rms 0.0074, v_max 0.0070; homogeneous 0.18, 0.032,
# 0.018, 0.0094. Bounds about 1.4 times those. The homogeneous pressure is that of one step's
# ∇·ũ/δt: at this resolution its bulk gradient swings between −22% and +17% from one output to
# the next, so its bound says little more than "it holds"; the rotational one accumulates φ and is
# steady. The fluid keeps its 100 particles give or take the recycled ones in flight.
# isph-rotational restarts bit for bit: BDF2's last step length travels in the checkpoint (the
# scheme's host state), with vel_prev, p and φ among the fields (0.2 s of the coarse channel with
# its entry and exit, 120 steps, resumed from step 60). Without the step length it resumed with a
# BDF1 step and differed.
clsph_add_test(restart_rotational LABELS case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CMAKE_SOURCE_DIR}/cases/poiseuille_open.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/restart_rotational
               "-DSETS=dr=0.1|t_end=0.2|checkpoint=0.1" -P ${CASE_DIR}/restart.cmake)
# the same with the implicit viscous prediction (its solve starts from u^k: nothing else to carry)
clsph_add_test(restart_rotational_implicit LABELS case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CMAKE_SOURCE_DIR}/cases/poiseuille_open.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/restart_rotational_implicit
               "-DSETS=dr=0.1|t_end=0.2|checkpoint=0.1|implicit=1" -P ${CASE_DIR}/restart.cmake)
clsph_run_test(run_poiseuille_open_h0 ${CMAKE_SOURCE_DIR}/cases/poiseuille_open.lua
               SETS dr=0.1 homogeneous=0
               BOUNDS "p_err_max<0.09" "u_err_max<0.02" "u_err_rms<0.011" "v_max<0.01"
                      "fluid>96.5" "fluid<103.5")
clsph_run_test(run_poiseuille_open_h1 ${CMAKE_SOURCE_DIR}/cases/poiseuille_open.lua
               SETS dr=0.1 homogeneous=1
               BOUNDS "p_err_max<0.25" "u_err_max<0.045" "u_err_rms<0.026" "v_max<0.014"
                      "fluid>96.5" "fluid<103.5")
# The implicit viscous prediction with an entry and an exit (their rows in the viscous system:
# the entry prescribed, the exit copying its progenitor), rotational: 40 steps instead of 560.
# Measured in double: p_err_max 0.118, u_err_max 0.024, u_err_rms 0.011, v_max 0.014 (the
# explicit's 0.065, 0.014, 0.0074, 0.0070: the exit's pressure follows the 14 times longer step).
# The homogeneous projection's error grows with the step as its splitting error should (dpdx_err
# −0.40 at this step): not a test, a reason to keep its steps short.
clsph_run_test(run_poiseuille_open_implicit ${CMAKE_SOURCE_DIR}/cases/poiseuille_open.lua
               SETS dr=0.1 implicit=1
               BOUNDS "p_err_max<0.17" "u_err_max<0.035" "u_err_rms<0.016" "v_max<0.02"
                      "fluid>96.5" "fluid<103.5")
# The parabolic exit profile (outflow { profile = "parabolic" }, the paper's choice above Re = 10,
# sec 4.3.3), rotational: measured p_err_max 0.096, u_err_max 0.014, u_err_rms 0.0061.
clsph_run_test(run_poiseuille_open_exit_parabolic ${CMAKE_SOURCE_DIR}/cases/poiseuille_open.lua
               SETS dr=0.1 exit_parabolic=1
               BOUNDS "p_err_max<0.14" "u_err_max<0.02" "u_err_rms<0.009" "fluid>96.5"
                      "fluid<103.5")
# The paper's resolution, L0 = 0.025 H (1600 fluid particles, 8890 steps; 490 s and 375 s on 2
# shared cores), labelled slow. Measured in double: rotational p_err_max 0.126 (a 2δr
# checkerboard in p next to the walls just before the exit, ±1 of the drop of 8; the bulk is
# within 0.4%: the paper reports 0.04%), u_err_max 0.0033, u_err_rms 0.00072, v_max 0.0024,
# dpdx_err −0.002; homogeneous p_err_max 0.0133 (the entry's corners; the paper: 0.3%),
# 0.0028, 0.0013, 0.00074, −0.005. Bounds about 1.4 times those (1.9 for the homogeneous
# pressure, whose bulk gradient swings by ±1% from one output to the next).
clsph_run_test(run_poiseuille_open_fine_h0 ${CMAKE_SOURCE_DIR}/cases/poiseuille_open.lua
               SETS dr=0.025 homogeneous=0 LABELS slow
               BOUNDS "p_err_max<0.18" "u_err_max<0.005" "u_err_rms<0.0011" "v_max<0.0035"
                      "dpdx_err<0.01" "dpdx_err>-0.01" "fluid>1589.5" "fluid<1610.5")
clsph_run_test(run_poiseuille_open_fine_h1 ${CMAKE_SOURCE_DIR}/cases/poiseuille_open.lua
               SETS dr=0.025 homogeneous=1 LABELS slow
               BOUNDS "p_err_max<0.025" "u_err_max<0.0045" "u_err_rms<0.002" "v_max<0.0012"
                      "dpdx_err<0.02" "dpdx_err>-0.02" "fluid>1589.5" "fluid<1610.5")
# Sections: a scheme without them refuses them; isph-rotational needs an entry and an exit
# together (it recycles what leaves into what enters); a prescribed exit profile needs its speed.
clsph_cli_test(case_sections_refused ARGS info ${CASE_DIR}/bad_open_scheme.lua RC 2
               REGEX "bad_open_scheme.lua: isph-usaw has no inflow or outflow sections")
clsph_cli_test(case_entry_without_exit ARGS info ${CASE_DIR}/bad_open_scheme.lua --set usaw=0
               RC 2 REGEX "isph-rotational needs an inflow and an outflow section together")
clsph_cli_test(case_outflow_profile_speed ARGS info ${CASE_DIR}/bad_outflow_profile.lua RC 2
               REGEX "bad_outflow_profile.lua:8: outflow: profile = \"parabolic\" needs velocity")
clsph_cli_test(case_wall_velocity ARGS info ${CASE_DIR}/bad_wall_velocity.lua RC 2
               REGEX "bad_wall_velocity.lua: wall_velocity must be \"shepard\".* or \"image\"")
clsph_cli_test(case_viscous ARGS info ${CASE_DIR}/bad_viscous.lua RC 2
               REGEX "bad_viscous.lua: viscous must be \"explicit\".* or \"implicit\"")
clsph_cli_test(density_relaxation_range ARGS info ${CASE_DIR}/bad_density_relaxation.lua
               --set what=1 RC 2
               REGEX "bad_density_relaxation.lua: density_relaxation must be a coefficient from 0 .* to 1, not 2")
clsph_cli_test(density_relaxation_text ARGS info ${CASE_DIR}/bad_density_relaxation.lua
               --set what=2 RC 2
               REGEX "bad_density_relaxation.lua: density_relaxation must be a number .*, not \"strong\"")
clsph_cli_test(density_relaxation_nan ARGS info ${CASE_DIR}/bad_density_relaxation.lua
               --set what=3 RC 2
               REGEX "bad_density_relaxation.lua: density_relaxation must be a coefficient .* not (nan|-nan)")
clsph_cli_test(wall_guard_word ARGS info ${CASE_DIR}/bad_wall_guard.lua --set what=1 RC 2
               REGEX "bad_wall_guard.lua: wall_guard must be \"auto\" .*, \"on\" or \"off\", not \"always\"")
clsph_cli_test(wall_guard_number ARGS info ${CASE_DIR}/bad_wall_guard.lua --set what=2 --set weak=1
               RC 2 REGEX "bad_wall_guard.lua: wall_guard must be \"auto\" .* not the number 1")
clsph_cli_test(case_shift_velocity ARGS info ${CASE_DIR}/bad_shift_velocity.lua RC 2
               REGEX "bad_shift_velocity.lua: shift_velocity must be \"on\".* or \"off\"")

# The dam break of Lobovsky et al. 2014 (cases/dam_break.lua), isph-usaw, coarse: 20 particles
# across the column (800), to t = 0.42 s, before the front reaches the downstream wall (about
# 0.46 s at this resolution), with the default health checks. Nothing on the floor may outrun
# Ritter's ideal front: the largest speed along the floor of the fluid within 2 dr of it, sampled
# by the case's sample() every 0.002 s (about every step: a particle thrown along the floor
# outruns the front for 0.002 to 0.17 s), stays below 0.95 × 2 √(gH). Without the no-tension
# bound of kernels/isph_usaw/ppe.cl, floor particles under the thin front took −3e3 to −9e3 Pa
# and were thrown ahead: this run read 0.990 (0.90 to 1.36 over nine runs that differed in their
# time steps, 1.46 in float); with it 0.867 (0.835 to 0.913 over those nine, 0.904 in float),
# where the front itself runs at 0.75 to 0.8. Also no fluid lost, and the front's mean speed
# below Ritter's (measured 0.61). About 4 s.
clsph_run_test(run_dam_break_coarse ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS n=20 t_end=0.42 every=0.002
               BOUNDS "floor_speed_max<0.95" "volume_ratio>0.999" "front_over_ritter<1")

# The same with wcsph-usaw (c0 = 10 × 2 √(gH)). Nothing on the floor may outrun Ritter's front
# (floor_speed_max < 1) and the front must keep running (its mean speed over Ritter's above 0.62).
# With dρ/dt taken from u^n (forward Euler for density and velocity) the thin tongue under the
# front breathed with a growing amplitude from t = 0.29 s (density 0.80 to 1.26 ρ0), threw
# particles along the floor at 2.83 × 2 √(gH) (3.36 in float) and stalled the front
# (front_over_ritter 0.581, 0.608 in float); with dρ/dt from u^{n+1} (symplectic Euler,
# solvers/wcsph_usaw/wcsph_usaw.c) the floor's largest speed is the front's tip, 0.915 (0.907 in
# float; 0.91 to 0.94 at cfl 0.5 to 0.9), and front_over_ritter is 0.663 (0.663). About 6 s.
clsph_run_test(run_dam_break_coarse_wcsph ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS n=20 t_end=0.42 every=0.002 wcsph=1
               BOUNDS "floor_speed_max<1" "front_over_ritter>0.62" "front_over_ritter<1"
                      "volume_ratio>0.999")

# DualSPHysics's CaseDambreakVal2D (cases/dam_break_dsph.lua) with wcsph-usaw (riemann=0), coarse
# (dp = 0.05 m, 800 fluid particles) to 0.05 s (221 steps): status ok, and the front (the largest
# x of the fluid on the floor: 0.975 m at rest) has started out (1.0009 m) but not past Ritter's
# ideal front, 1 m + 2 √(g · 2 m) t = 1.44 m. Under a second.
clsph_run_test(run_dam_break_dsph ${CMAKE_SOURCE_DIR}/cases/dam_break_dsph.lua
               SETS riemann=0 dp=0.05 t_end=0.05 BOUNDS "front>0.98" "front<1.44")

# `clsph bench dambreak` on the same coarse case to 0.02 s (89 steps, under a second): every
# figure printed and positive, its temporary output folder removed (bench_dambreak.cmake).
clsph_add_test(bench_dambreak LABELS cl TIMEOUT 120 COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/bench_dambreak
               -DPRECISION=${CLSPH_REAL} -DSCHEME=wcsph-usaw
               "-DARGS=--set|dp=0.05|--set|t_end=0.02|--set|riemann=0"
               -P ${CASE_DIR}/bench_dambreak.cmake)
# Bad input to the bench: an unknown option and a --set the case does not declare exit with the
# input error status (2) and say why, before any run or folder.
clsph_cli_test(bench_dambreak_bad_option ARGS bench dambreak --bench-foo 3 RC 2
               REGEX "unknown option --bench-foo")
clsph_cli_test(bench_dambreak_bad_set ARGS bench dambreak --set dq=0.05 --set riemann=0 RC 2
               REGEX "--set dq: .*declares no parameter 'dq'; did you mean 'dp'\\?")
clsph_cli_test(bench_dambreak_bad_value ARGS bench dambreak --set dp=fine --set riemann=0 RC 2
               REGEX "--set dp=fine: 'fine' is not a number")
clsph_cli_test(bench_case_elsewhere ARGS run ${CMAKE_SOURCE_DIR}/cases/free_fall.lua --case x.lua
               RC 2 REGEX "--case belongs to `clsph bench dambreak`")

# wcsph-riemann (solvers/wcsph_riemann/). Bad input: a sound speed too low for the scene's
# velocity scale states the Mach number (the cavity's lid, U = 1 m/s, c0 = 2 m/s: Mach 0.5); CFL
# numbers that make the advection step shorter than the acoustic one; an unknown choice; ard
# other than 0 or 1.
clsph_cli_test(riemann_mach ARGS info ${CMAKE_SOURCE_DIR}/cases/cavity.lua --set riemann=1
               --set c0=2 RC 2 REGEX "sound_speed = 2 m/s is too low .*Mach U/c0 = 0.5")
clsph_cli_test(riemann_dual_ratio ARGS info ${CASE_DIR}/bad_riemann_dual.lua RC 2
               REGEX "advection_cfl = 0.01 and acoustic_cfl = 1 make the advection step 0.11")
clsph_cli_test(riemann_bad_choice ARGS info ${CASE_DIR}/bad_riemann_choice.lua RC 2
               REGEX "transport_velocity must be one of \"off\", \"full\", \"limited\"")
clsph_cli_test(riemann_bad_ard ARGS info ${CMAKE_SOURCE_DIR}/cases/cavity.lua --set riemann=1
               --set ard=2 RC 2 REGEX "option ard must be 1 \\(on\\) or 0 \\(off\\)")
# Body-force Poiseuille flow from rest against Morris et al.'s series (cases/poiseuille_periodic.lua)
# at dr = H/10 and H/20, t = 1 (steady): measured RMS errors 0.0091 and 0.0021 U0 in double and
# float, second order. Bounds 1.5 times those: the two runs together fail if the order drops
# below 1.5 (0.0091 / 0.0032 = 2^1.5). At t = 0.1 (0.0084, 0.0025) the transient. The walls
# carry the body force within 0.03% and 0.02% (1.2% at H/10 when their record was the pairs at
# the end of a step instead of the sub-steps' mean, force.cl). 2 and 3 s.
clsph_run_test(run_poiseuille_riemann ${CMAKE_SOURCE_DIR}/cases/poiseuille_periodic.lua
               SETS riemann=1 dr=0.1
               BOUNDS "u_rms_t1<0.014" "u_rms_t0p1<0.013" "wall_drag_error<0.002")
clsph_run_test(run_poiseuille_riemann_fine ${CMAKE_SOURCE_DIR}/cases/poiseuille_periodic.lua
               SETS riemann=1 dr=0.05
               BOUNDS "u_rms_t1<0.0032" "u_rms_t0p1<0.0038" "wall_drag_error<0.002")
# The walls' force record against the fluid's momentum (tests/case/wall_momentum.lua: a periodic
# channel under a fixed body force from a jittered start, every step sampled). The fluid pairs
# cancel, so M ΔU = Δt (M f − F_x) step by step when F_x is what the sub-steps' wall pairs did
# (force.cl): measured 5e-8 of M f in double (the CSV's 9 digits) and 5e-6 to 1.1e-5 in float (the
# fluid pairs cancel to float round-off), laminar, k-ε (eq 39's shear) and ARD alike; bounds 1e-6
# and 1e-4. The walls' pairs evaluated once at the end of a step instead (the record before)
# left 0.037 of M f (0.115 with ARD, 0.037 under k-ε); the viscous sum with the volumes from
# before the summation's re-set (vol[j] instead of m/ρ_j, advection.cl) left 3.8e-4, a momentum
# the scheme made up. wall_share: the walls' mean |F_x| over M f (2.3 laminar, 3.2 with ARD, 0.035
# under k-ε), so that the balance is not trivial. 1 s each.
if(CLSPH_REAL STREQUAL "float")
  set(momentum_bound "balance_max<1e-4")
else()
  set(momentum_bound "balance_max<1e-6")
endif()
clsph_run_test(run_wall_momentum ${CASE_DIR}/wall_momentum.lua
               BOUNDS ${momentum_bound} "wall_share>1" "steps_checked>20")
clsph_run_test(run_wall_momentum_ard ${CASE_DIR}/wall_momentum.lua SETS ard=1
               BOUNDS ${momentum_bound} "wall_share>1" "steps_checked>20")
clsph_run_test(run_wall_momentum_ke ${CASE_DIR}/wall_momentum.lua SETS turb=1
               BOUNDS ${momentum_bound} "wall_share>0.02" "steps_checked>20")
# A tank at rest (cases/hydrostatic.lua, dr = H/20, 2 s): pressure within 8.8% of ρ g (H − z)
# below 3 dr (the largest error is at the shallowest points, 1.5e3 Pa: the surface rows take no
# tension, and their p >= 0 lifts the pressure under them), surface particles jostling at
# 0.08 √(gH) (measured); bounds 12% and 0.15, no particle behind a wall.
clsph_run_test(run_hydrostatic_riemann ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               SETS riemann=1 dr=0.05 t_end=2
               BOUNDS "pressure_error<0.12" "speed_ratio<0.15" "crossed_wall<0.5")
# The lid-driven cavity at Re = 100, 30², t = 10 against Ghia et al.: u RMS 0.018 U, v 0.011 U
# (measured, double; the instantaneous field's particle noise moves them by ±0.01 from one output
# to the next). Bounds 0.03 and 0.02. 3 s.
clsph_run_test(run_cavity_riemann ${CMAKE_SOURCE_DIR}/cases/cavity.lua
               SETS riemann=1 n=30 t_end=10
               BOUNDS "u_rms_vs_ghia<0.03" "v_rms_vs_ghia<0.02" "wall_crossing_steps<0.5")
# DualSPHysics's dam break (cases/dam_break_dsph.lua) with wcsph-riemann, coarse (dp = 0.05 m),
# to 0.3 s: the front at 1.73 m (measured); Ritter's ideal front 1 + 2 √(2g) 0.3 = 2.88 m bounds
# it, and it must have left the column's foot well behind (> 1.5 m).
clsph_run_test(run_dam_break_dsph_riemann ${CMAKE_SOURCE_DIR}/cases/dam_break_dsph.lua
               SETS dp=0.05 t_end=0.3 BOUNDS "front>1.5" "front<2.88")
# The Lobovsky dam break (cases/dam_break.lua), n = 20: front at t = 0.4 s 0.55 of Ritter's mean
# speed (measured); nothing on the floor outruns Ritter; the volume kept. (Before the surface
# rows took no tension, pairs under the surface of the collapsing column closed up and the
# clustering check stopped it at t = 0.35 s.)
clsph_run_test(run_dam_break_riemann ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS riemann=1
               BOUNDS "front_over_ritter>0.5" "front_over_ritter<1" "floor_speed_max<1"
                      "volume_ratio>0.999")
# Sensor 1 of the Lobovsky dam break (cases/dam_break.lua: the mean pressure over the sensor's face
# on the downstream wall, 0.9 to 5.1 mm, against one repetition of the experiment, "event 5",
# tests/data/lobovsky2014_sensor1.csv), wcsph-riemann at n = 40 (dr = 7.5 mm, 3200 fluid
# particles) to t = 0.72 s (t* = 4.1), about 7 s. Measured in double and float:
#   impact_time_error  0.085 and 0.086: at this resolution the front arrives late (0.18 at n = 20,
#                      0.032 at 80, 0.018 at 120, 0.0066 at 160: validate_lobovsky_riemann). The
#                      band, ±0.025 around it, fails a change in the arrival of more than 2.5% of
#                      the impact time, a little more than the issue's criterion (2%).
#   peak_ratio         3.14 and 4.53 (3.2 at n = 20, 4.7 at 80): the largest sample is one particle
#                      of the front's tongue striking the wall, which varies from run to run. Above
#                      half the experiment's peak (the lower edge of the validation's band: the
#                      impact must load the sensor), below the water hammer of the front,
#                      ρ c0 u = 33 ρ g H at u = 0.83 · 2 √(gH) (11 times 3.044): above it no flow
#                      loads the sensor, a blow-up does.
#   impact_mean_ratio  1.02 and 1.06: the mean pressure over 0.1 after the impact against the
#                      experiment's 2.26 over 0.1 after its own; the validation's band, a third
#                      either way (0.80 to 1.15 at every resolution from n = 20 to 160).
#   plateau_ratio      0.98 and 1.05: the mean over t* ∈ [3, 4] against the experiment's 0.80;
#                      ±20%, the experiment's own swing along its plateau (0.6 to 0.9).
# Sensors 2, 3 and 4 (15, 30 and 80 mm above the bed; the experiment's event 5 at 2 kHz,
# tests/data/lobovsky2014_H300_event5_all_sensors.csv):
#   sensor_2/3_plateau_ratio  0.98 / 0.98 in double, 1.03 / 1.02 in float: ±20% as sensor 1's.
#   sensor_2/3_time_error     0.079 / 0.057 and 0.080 / 0.058 (the front's arrival, as sensor 1's):
#                             the same band of ±0.025.
#   sensor_4_plateau_ratio    0.50 and 0.51: at this resolution the run-up along the wall is a jet
#                             one or two particles thick that reaches 80 mm late (sensor_4_time_
#                             error 0.14 and 0.18, against the experiment's water piled up at the
#                             wall); bounds 0.35-0.7, and 0.08-0.25 on its time: a change that
#                             thickens or thins the run-up moves them.
clsph_run_test(run_dam_break_sensor_riemann ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS riemann=1 n=40 t_end=0.72
               BOUNDS "impact_time_error>0.06" "impact_time_error<0.11" "peak_ratio>0.5"
                      "peak_ratio<11" "impact_mean_ratio>0.75" "impact_mean_ratio<1.33"
                      "plateau_ratio>0.8" "plateau_ratio<1.2" "volume_ratio>0.999"
                      "sensor_2_plateau_ratio>0.8" "sensor_2_plateau_ratio<1.2"
                      "sensor_3_plateau_ratio>0.8" "sensor_3_plateau_ratio<1.2"
                      "sensor_2_time_error>0.055" "sensor_2_time_error<0.105"
                      "sensor_3_time_error>0.033" "sensor_3_time_error<0.083"
                      "sensor_4_plateau_ratio>0.35" "sensor_4_plateau_ratio<0.7"
                      "sensor_4_time_error>0.08" "sensor_4_time_error<0.25")
clsph_cli_test(riemann_bad_pressure ARGS info ${CASE_DIR}/bad_riemann_pressure.lua RC 2
               REGEX "background_pressure must be a pressure in Pa, from 0 to 1e\\+12")
# The entry and exit sections (solvers/open) with wcsph-riemann: Poiseuille flow between an entry
# and an exit at Re = 1 (cases/poiseuille_open.lua, dr = H/10, c0 = 30 U0: the default 10 U0 lets
# the density vary by 8% over the channel's drop), the paper's fixed p = 0 at the exit. Measured
# in double: u_err_rms 0.0062, u_err_max 0.016, p_err_max 0.093, p_err_exit_max 0.072, v_max
# 0.010 (float the same to 2 digits); the bounds leave about 50%, the particle count ±3.5 as
# isph-rotational's (the exit's park lends the entry what the compressed fluid holds: 102 at
# t = 1). p_err_max is the largest error of one particle at one instant, and the acoustic noise
# moves it from 0.03 to 0.26 between t = 0.9 and 1.1 (0.028 to 0.26 before the park): its bound
# catches only a gross error; u_err_rms is the measure.
clsph_run_test(run_poiseuille_open_riemann ${CMAKE_SOURCE_DIR}/cases/poiseuille_open.lua
               SETS riemann=1 dr=0.1 c0=30
               BOUNDS "u_err_rms<0.011" "u_err_max<0.035" "p_err_max<0.15" "p_err_exit_max<0.1"
                      "v_max<0.012" "fluid>96.5" "fluid<103.5")
# The same with the scheme's default exit, outlet = "characteristic" (p = ρ0 c0 (<u_n> − ū)):
# measured u_err_rms 0.010, p_err_exit_max 0.12 (its mean holds p = 0 only on average).
clsph_run_test(run_poiseuille_open_riemann_characteristic ${CMAKE_SOURCE_DIR}/cases/poiseuille_open.lua
               SETS riemann=1 dr=0.1 c0=30 characteristic=1
               BOUNDS "u_err_rms<0.015" "u_err_max<0.035" "p_err_exit_max<0.18" "v_max<0.012"
                      "fluid>96.5" "fluid<103.5")
# The same with the walls' pressure extrapolated along them with the particles' pressure gradient
# (wall_pressure = "gradient", acoustic.cl): in this steady laminar flow the mirror's a_prior
# (the viscous force, which the pressure gradient balances) already carries it, and the two agree
# to 3 digits (u_err_rms 0.0062, dpdx_err −1.2%; float the same); the bounds are the mirror's.
clsph_run_test(run_poiseuille_open_riemann_wallp ${CMAKE_SOURCE_DIR}/cases/poiseuille_open.lua
               SETS riemann=1 dr=0.1 c0=30 wallp=1
               BOUNDS "u_err_rms<0.011" "u_err_max<0.035" "p_err_max<0.15" "p_err_exit_max<0.1"
                      "v_max<0.012" "fluid>96.5" "fluid<103.5")
clsph_cli_test(riemann_bad_wall_pressure ARGS info ${CASE_DIR}/bad_riemann_choice.lua --set what=2 RC 2
               REGEX "wcsph-riemann option wall_pressure must be one of \"mirror\", \"gradient\"")
# The square cylinder at Re = 20 in Breuer's geometry (32 D long, cylinder 8 D from the entry,
# natural exit) with wcsph-riemann at H/40 (the cylinder 5 particles across), 30 D/U0, C_D
# averaged from 15, the density from the continuity equation (the case's choice for this
# scheme): measured C_D = 2.80 double, 2.81 float, against Breuer's 2.40 (+16.8% and +17.2%), 8 s
# on 2 shared cores; +2.3% at H/80 (validate_square_cylinder_riemann). The band, +8% to +26%, is
# half the error either side: it fails a lost wall force, a start-up transient left in the
# average, and the density re-set by summation (+43%, the pressure then c0² times the particles'
# disorder). Before the exit's target was delayed by the start-up wave's transit (wcsph_riemann.c,
# open_exits) the exit's corner by the floor could flow back at H/80 and throw a particle out.
clsph_run_test(run_square_cylinder_riemann ${CMAKE_SOURCE_DIR}/cases/square_cylinder.lua
               SETS riemann=1 n=40 re=20 t_end=30 length=32 xc=8 average_from=15
               BOUNDS "cd_dev>0.08" "cd_dev<0.26" "upstream<0.5" "pressure_share>0.6")
# The same at H/80 (the cylinder 10 particles across), 45 s: C_D = 2.455, +2.3% of Breuer's
# (isph-rotational -3.3% at this resolution in 320 s). Breuer's values are digitised to ±4-6%:
# the bound is 6%.
clsph_run_test(validate_square_cylinder_riemann ${CMAKE_SOURCE_DIR}/cases/square_cylinder.lua
               LABELS slow
               SETS riemann=1 n=80 re=20 t_end=30 length=32 xc=8 average_from=15 outputs=6
               BOUNDS "cd_error<0.06" "upstream<0.5" "pressure_share>0.6")
# Re = 100 at H/80 to t = 200 D/U0, 300 s: the wake sheds from t = 20, and its lift grows until
# about t = 120 (C_L amplitude 0.07 at t = 50, 0.13 at 100, 0.17 from 120 on, peak to peak
# over a sliding D/U0; OpenFOAM's, from a kicked start, saturates by t = 90), C_D with it (1.38
# over 40 <= t < 60, 1.45 from 100 on). Over 100 <= t <= 200 (the case's window: from
# min(average_from, t_end / 2)) measured St = 0.1337 (-3.9%), C_D = 1.4505 (+5.4%) and the
# spectral C_L amplitude 0.1245 (-39%, the growth in the window) against OpenFOAM's 0.1391,
# 1.3756 and 0.204 in the same geometry (tests/data/openfoam_square_cylinder.csv, D/50 at the
# cylinder; no published value at this Re in tests/data; isph-rotational at H/80: 0.135, 1.44,
# 0.30). Bounds: St within 8% (the spectrum of 100 D/U0 resolves it to about ±0.005), C_D within
# 8%, the amplitude above half OpenFOAM's: they fail a wake that does not shed or sheds at the
# wrong frequency, and a drag that the density or the walls shift.
clsph_run_test(validate_square_cylinder_re100_riemann ${CMAKE_SOURCE_DIR}/cases/square_cylinder.lua
               LABELS slow
               SETS riemann=1 n=80 re=100 t_end=200 length=32 xc=8 average_from=120 outputs=5
               BOUNDS "strouhal_dev_openfoam>-0.08" "strouhal_dev_openfoam<0.08"
                      "cd_dev_openfoam>-0.08" "cd_dev_openfoam<0.08" "cl_amplitude>0.102"
                      "cl_amplitude<0.255" "upstream<0.5")
# The square cylinder's density switch takes 0 or 1, not anything else silently.
clsph_cli_test(case_square_cylinder_bad_summation
               ARGS info ${CMAKE_SOURCE_DIR}/cases/square_cylinder.lua --set riemann=1
                    --set summation=2 RC 2
               REGEX "square_cylinder.lua:[0-9]+: summation = 2.0: 1 \\(density re-set by summation\\) or 0")
# Bad ramps: negative; on a natural exit (it takes the fluid's velocity).
clsph_cli_test(case_ramp_negative ARGS info ${CASE_DIR}/bad_ramp.lua RC 2
               REGEX "bad_ramp.lua:11: inflow: ramp must be a time of 0 s or more")
clsph_cli_test(case_ramp_natural_exit ARGS info ${CASE_DIR}/bad_ramp.lua --set natural=1 RC 2
               REGEX "bad_ramp.lua:12: outflow: ramp = 0.5+ needs a prescribed profile")
clsph_cli_test(case_outflow_natural_speed ARGS info ${CASE_DIR}/bad_ramp.lua --set natural=2 RC 2
               REGEX "bad_ramp.lua:12: outflow: velocity = 2.0 needs a prescribed profile")

# turbulence { } refused where it cannot hold: a scheme without a model, a y_p whose y+ (eq 10,
# from the declared k) is in the viscous sublayer (0.01 · 0.548 · 0.1 / 1e-4 = 5.5), k without ε,
# a length scale C_μ^¾ k^{3/2}/ε = 164 m in a 1 m domain, nu_t without a delay, k < 0
set(bad_turb ${CASE_DIR}/bad_turbulence.lua)
clsph_cli_test(turbulence_no_model ARGS info ${bad_turb} --set what=1 RC 2
               REGEX "turbulence: model = \"k-epsilon\": scheme isph-rotational has no turbulence")
clsph_cli_test(turbulence_sublayer ARGS info ${bad_turb} --set what=2 RC 2
               REGEX "turbulence: y_p = 0.01 m puts the first particles in the viscous sublayer"
               REGEX2 "y\\+ = y_p C_mu\\^1/4 k\\^1/2 / nu = 5.48")
clsph_cli_test(turbulence_missing_epsilon ARGS info ${bad_turb} --set what=3 RC 2
               REGEX "turbulence: needs both k .* epsilon is missing")
clsph_cli_test(turbulence_length_scale ARGS info ${bad_turb} --set what=4 RC 2
               REGEX "k = 0.01 and epsilon = 1e-07 imply a turbulence length scale")
clsph_cli_test(turbulence_nu_t_alone ARGS info ${bad_turb} --set what=5 RC 2
               REGEX "turbulence: nu_t is the eddy viscosity of the delay: give delay")
clsph_cli_test(turbulence_negative_k ARGS info ${bad_turb} --set what=6 RC 2
               REGEX "turbulence: k must be positive, not -0.010*")

# The k-ε channel of wcsph-riemann (cases/channel_ke.lua: Lee & Moser's U_b = 1, ν = 1e-4,
# y_p = 0.05, 20 rows, periodic, the bulk held at U_b by flow-rate control, started from the 1-D
# reference) against OpenFOAM's straight channel with the same model, wall function, U_b and
# cells (tests/data/openfoam_channel_straight.csv) and Lee & Moser's DNS, at t = 100 δ/U_b, the
# walls' pressure the scheme's default under the model (the gradient), the walls' friction
# sampled every δ/U_b. Measured (double / float): u_τ from the walls' friction +2.1% / +2.3% of
# OpenFOAM's (the paper: +0.94% of its FVM's), u+ within 2.4% / 2.5% of OpenFOAM's on every row
# and within 1.1% / 1.0% of the DNS from the second row on (the first row, 3.0% / 3.4%, is the
# log law's at y+ = 27, above the DNS's buffer layer, as OpenFOAM's is). With the mirror (wallp =
# 0, one force sample per output): +1.8%, 2.1% and 1.7%. With eq 19's Riemann dissipation
# between the fluid pairs (momentum_dissipation = "riemann") u_τ was +4.4% and u+ 5.1% off
# OpenFOAM's: the bounds fail it. Against the 1-D solver on the same 20 rows
# (tests/data/channel1d_rows20.csv, the rows' mean held at U_b): u_τ +4.5% / +4.8%, u within
# 4.3% / 4.9% on every row (1.5% / 1.6% RMS), k 15% / 14% RMS over it (the second row's high:
# the kernel sums' velocity gradient across the log layer's curvature; eq 19's dissipation puts a
# row 12% off); the reference's own u+ is 6.5% off the DNS (the model's error, which
# the bounds pin: the file was read). The rows' u and k are averages over t = 50-100 (51
# samples, sample()); those of the last instant gave u+ 1.6% / 1.1% off the DNS and the rows' u
# 4.0% / 5.3% (averaged, in this disordered state: 1.4% / 1.2% and 4.9% / 4.5%). The drive, the
# flow-rate control's mean body force, implies u_τ +3.3% / +2.0% of the 1-D solver's; the walls
# record 1.5% / 4.7% more friction than that, and a pressure force along x of −1.1% / −2.9% of it
# (a thrust: the dummies' pair forces on a disordered first row), so that their whole x force is
# the drive's within 0.4% / 1.7% (wall_over_drive: the bulk's changes at the sampled steps; the
# record of the pairs at a step's end read a pressure drag of 8% / 17% instead, 10% / 21% over
# the drive in all: force.cl). Bounded as measured. 7-25 s.
clsph_run_test(run_channel_ke ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua SETS nf=20 t_end=100 ub=1
               every=5
               BOUNDS "u_tau_dev_fv>-0.01" "u_tau_dev_fv<0.03" "u_plus_fv_dev_max<0.03"
               "u_plus_dns_dev_max<0.03" "u_plus_dns_dev_row1<0.06" "u_tau_dev_rows>-0.02"
               "u_tau_dev_rows<0.06" "u_rows_dev_max<0.07" "u_rows_rms<0.025" "k_rows_rms<0.2"
               "u_plus_model_dns_dev_max>0.064" "u_plus_model_dns_dev_max<0.066"
               "profile_samples>50" "profile_samples<52" "u_tau_drive_dev_1d>0.01"
               "u_tau_drive_dev_1d<0.05" "friction_over_drive>-0.02" "friction_over_drive<0.06"
               "wall_over_drive>-0.03" "wall_over_drive<0.03")
# The same with the velocity gradient in the log law's coordinate next to the walls
# (velocity_gradient = "log", turbulence.cl; grad = 1): the production of the second to fourth
# rows no longer reads the log profile's ∂u/∂y high, and k on the rows comes within 4.8% / 3.8%
# RMS of the 1-D solver's on the same rows (15% / 14% with the kernel sums' gradient, above), u+
# within 0.6% / 0.6% of OpenFOAM's on every row (2.4% / 2.5%), u_τ +0.06% / +0.1% of OpenFOAM's
# (+2.1% / +2.3%), the rows' u within 1.1% / 1.2% RMS of the 1-D solver's (1.5% / 1.6%); u+ against
# the DNS moves to the model's own (3.6% / 3.7% from the second row on: the 1-D solver's is 6.5%,
# and the kernel sums' 1.1% / 1.0% is its error cancelling the model's). Bounds about twice the
# measured ones, below the kernel sums' figures: k_rows_rms and u_plus_fv_dev_max fail those.
# 24-28 s.
clsph_run_test(run_channel_ke_log ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua SETS nf=20 t_end=100
               ub=1 every=5 grad=1
               BOUNDS "k_rows_rms<0.08" "u_plus_fv_dev_max<0.012" "u_tau_dev_fv>-0.01"
               "u_tau_dev_fv<0.012" "u_rows_rms<0.02" "wall_over_drive>-0.03" "wall_over_drive<0.03"
               "profile_samples>50")
clsph_cli_test(channel_ke_grad_two ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua --set grad=2
               RC 2 REGEX "channel_ke: grad must be 0 .the kernel sums' velocity gradient. or 1")
# The first row's diffusion of k against the 1-D solver's on the same rows: started from the 1-D
# solver's steady solution on the rows (init = 2: tests/data/channel1d_rows20.csv, the particles
# on their rows), where the first row's production and ε are the wall function's in both (eqs
# 13-14), the first step's dk/dt of the first row is the particles' diffusion sum less the 1-D
# solver's, whose flux through the first face (the faces' mean ν_t) it reads as a ratio
# (k_row1_diffusion). The paper's sums (the harmonic mean of D over the fluid neighbours) carry
# 0.835 of it at 20 rows (0.880 at 40): ν_t nearly doubles from the first row to the second, where
# the harmonic mean stands under the two points' conductance, and the wall cuts the pairs across
# it. turbulent_diffusion = "log_mirror" (the logarithmic mean and the wall's mirror images,
# turbulence.cl): 0.932 (0.945 at 40); with the log mean alone 0.896, the mirror alone 0.864, from
# the same sums over the first snapshot (tests/validation/channel_ke_diffusion.py), which also
# reads the 0.835 and 0.932; the rest is the profile's curvature across the pairs at two
# spacings. Double and float alike to 4 digits; bounds that part the four.
clsph_run_test(run_channel_ke_diffusion ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua SETS nf=20 init=2
               ub=1 t_end=0.1 every=0.1 sample_dt=1e-6 grad=1
               BOUNDS "k_row1_diffusion>0.82" "k_row1_diffusion<0.85" "profile_samples>2")
clsph_run_test(run_channel_ke_diffusion_log_mirror ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua SETS
               nf=20 init=2 ub=1 t_end=0.1 every=0.1 sample_dt=1e-6 grad=1 diff=1
               BOUNDS "k_row1_diffusion>0.92" "k_row1_diffusion<0.945" "profile_samples>2")
clsph_cli_test(channel_ke_diff_two ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua --set diff=2
               RC 2 REGEX "channel_ke: diff must be 0 .the harmonic mean over the fluid neighbours. or 1")
# The layer below the offset walls (sec 4.4's boundary offset, y_p − dr/2 = 0.026 δ at 40 rows):
# started from the 1-D solver's steady solution on the rows (init = 2, tests/data/
# channel1d_rows40.csv: the channel's own momentum balance), over 30 δ/U_b the particles move
# towards their own. With the layer empty (offset_layer = "none", the paper's) the flow between
# the offset walls takes the wall's whole stress, 1/(1 − 0.026) times the channel's in the stream,
# and k, which follows the stress, rises: +2.44% / +2.93% (double / float) over the rows' k, +0.31%
# / +0.79% over the same solver's under that momentum balance (channel1d_rows40_offset.csv:
# --offset-momentum). With the layer's body force passed to the first row (offset_layer =
# "body_force") +1.19% / +1.42%. The walls' whole x force over the drive on each one's height,
# f (δ − y_p + dr/2) and f δ: −0.31% / −0.58% and −0.44% / +0.50% (a layer that passed nothing
# would read −2.6% in the second). 20 s each.
clsph_run_test(run_channel_ke_offset_none ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua SETS nf=40
               init=2 ub=1 t_end=30 every=30 grad=1 diff=1
               BOUNDS "k_rows_mean>0.019" "k_rows_offset_mean>-0.01" "k_rows_offset_mean<0.015"
               "wall_over_drive>-0.013" "wall_over_drive<0.013" "profile_samples>10")
clsph_run_test(run_channel_ke_offset_body_force ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua SETS
               nf=40 init=2 ub=1 t_end=30 every=30 grad=1 diff=1 carry=1
               BOUNDS "k_rows_mean<0.019" "wall_over_drive>-0.013" "wall_over_drive<0.013"
               "profile_samples>10")
# The dummies' pressure force along the walls' normal (wall_pressure_force = "normal": a uniform
# pressure's pair sum along the normal, the share of ∇p along the wall as it is), the same start
# and window with the layer's body force: the walls' friction over the drive +0.11% / +0.31%
# (double / float) and their pressure force along x −0.05% / +0.30% of it (the float's ∇p the
# noisier). With eq 19's correction matrix on the wall pairs (the paper's;
# run_channel_ke_offset_body_force) a first row that is not a lattice over the dummies turns part
# of the walls' normal push along them: pressure along x +0.81% / +1.45% of the friction here
# (−1.0% over 300-600 δ/U_b of the N_f = 40 runs: RESULTS_rans_ensemble.md), friction over the
# drive −1.24% / −0.94%. Bounds of ±0.6% and ±0.5% part the two in both precisions. 20 s.
clsph_run_test(run_channel_ke_pressure_normal ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua SETS
               nf=40 init=2 ub=1 t_end=30 every=30 grad=1 diff=1 carry=1 pforce=1
               BOUNDS "friction_over_drive>-0.006" "friction_over_drive<0.006"
               "wall_pressure_x>-0.005" "wall_pressure_x<0.005" "profile_samples>10")
clsph_cli_test(channel_ke_carry_two ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua --set carry=2
               RC 2 REGEX "channel_ke: carry must be 0 .no fluid below the offset walls. or 1")
clsph_cli_test(channel_ke_carry_laminar ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua
               --set carry=1 --set turb=0 RC 2
               REGEX "channel_ke: carry = 1 is the k-ε wall model's offset layer: it needs turb = 1")
clsph_cli_test(channel_ke_pforce_two ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua --set pforce=2
               RC 2 REGEX "channel_ke: pforce must be 0 .the walls' pressure force with the correction matrix. or 1")
clsph_cli_test(channel_ke_pforce_laminar ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua
               --set pforce=1 --set turb=0 RC 2
               REGEX "channel_ke: pforce = 1 is the k-ε wall model's wall pressure force: it needs turb = 1")
clsph_cli_test(channel_ke_init_three ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua --set init=3
               RC 2 REGEX "channel_ke: init must be 0 .the power law., 1 .the 1-D reference. or 2")
clsph_cli_test(channel_ke_init_rows_fixed ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua
               --set init=2 RC 2
               REGEX "channel_ke: init = 2 starts from the 1-D solver on 20, 40 or 80 rows under flow-rate control")
# The walls' friction over the channel's first half second (17 steps from the 1-D reference
# scaled to U_b = 1, the rows on the lattice). With the wall model's shear at y_p (the paper's)
# the second row, 1.5 dr from the boundary, inside P_ext, reads the log law from its own velocity
# (19% over the first row's at 20 rows), and the two rows' eq 39 weights Σ_b V_b ∂W/∂n sum to
# 0.974 of τ_w (Wendland C2, h = 1.3 dr): the walls carry 0.986 of the first row's log law. With
# wcsph-riemann's wall_shear = "distance" each row reads it at its own distance and eq 39 is
# divided by its lattice sum: all of it. Measured (double and float alike): u_τ −0.02% and
# +0.61% of the 1-D solver's (the scaled start stands 0.7% over it); the difference, 1.3% in τ_w,
# is the two quadrature errors, which the bounds separate.
clsph_run_test(run_channel_ke_start ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua SETS nf=20 t_end=0.5
               ub=1 every=0.5 sample_dt=0.05
               BOUNDS "u_tau_dev_1d>-0.002" "u_tau_dev_1d<0.004" "profile_samples>5")
clsph_run_test(run_channel_ke_start_distance ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua SETS nf=20
               t_end=0.5 ub=1 every=0.5 sample_dt=0.05 shear=1
               BOUNDS "u_tau_dev_1d>0.005" "u_tau_dev_1d<0.009" "profile_samples>5")
# wall_shear = "first_row": the wall's stress on the first row alone, each particle taking τ_w
# over its share of the wall (the first dummy layer's, handed out by the kernel: 1 on the
# lattice, as eq 39 over the first row's lattice sum 0.9046), so that the walls carry the first
# row's whole log law as with "distance": u_τ +0.69% (double and float alike; "distance" +0.61%,
# "y_p" −0.02%).
clsph_run_test(run_channel_ke_start_first_row ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua SETS nf=20
               t_end=0.5 ub=1 every=0.5 sample_dt=0.05 shear=2
               BOUNDS "u_tau_dev_1d>0.005" "u_tau_dev_1d<0.009" "profile_samples>5")
# A first row short of particles (tests/case/row1_share.lua: u, k uniform, the floor's first row
# without two of its ten particles, the ceiling's whole, a particle of the floor's at 1.7 dr,
# beyond P_ext in the dummies' reach; one step): with "first_row" each wall records τ_w ρ L
# within 1e-7 (double and float), where eq 39's sums lose the missing particles' share: "y_p"
# −21.1% (floor) and −2.6% (ceiling: the two rows' lattice sum, 0.974); the lifted particle's
# no-slip drag alone, were it kept, +0.33%. Bounds ±0.1%.
clsph_run_test(run_row1_share ${CASE_DIR}/row1_share.lua SETS holes=2 lift=1
               BOUNDS "floor_over_law>-0.001" "floor_over_law<0.001" "ceiling_over_law>-0.001"
               "ceiling_over_law<0.001" "first_row>7.5" "first_row<8.5")
clsph_cli_test(row1_share_holes ARGS info ${CASE_DIR}/row1_share.lua --set holes=1.5 RC 2
               REGEX "row1_share: holes must be a whole number from 0 to 5, not 1.5")
clsph_cli_test(row1_share_lift ARGS info ${CASE_DIR}/row1_share.lua --set lift=2 RC 2
               REGEX "row1_share: lift must be 0 or 1, not 2")
clsph_cli_test(row1_share_shear ARGS info ${CASE_DIR}/row1_share.lua --set shear=3 RC 2
               REGEX "row1_share: shear must be 0 .y_p., 1 .distance. or 2 .first_row., not 3")
clsph_cli_test(channel_ke_shear_two ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua
               --set shear=3 RC 2
               REGEX "channel_ke: shear must be 0 \\(the wall's shear from the log law at y_p\\), 1 .* or 2")
clsph_cli_test(channel_ke_seed_negative ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua
               --set seed=-1 RC 2
               REGEX "channel_ke: seed must be 0 \\(no perturbation\\) or a positive integer below 2\\^31, not -1")
clsph_cli_test(channel_ke_seed_huge ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua
               --set seed=1e300 RC 2
               REGEX "channel_ke: seed must be 0 \\(no perturbation\\) or a positive integer below 2\\^31, not 1e\\+300")
clsph_cli_test(channel_ke_wallp_two ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua
               --set wallp=2 RC 2
               REGEX "channel_ke: wallp must be -1 \\(the scheme's default\\), 0 \\(the mirror\\) or 1 \\(the gradient\\), not 2")
clsph_cli_test(channel_ke_sample_zero ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua
               --set sample_dt=0 RC 2
               REGEX "channel_ke: sample_dt must be a positive time between force samples, not 0")
# The k-ε channel of the USAW schemes (cases/channel_usaw_ke.lua: Leroy et al. sec 5.1, e+ = 640,
# the body force u*²/e, periodic), 10 rows per half height (y+ = 32 at the first row; the paper
# has 20), started from the 1-D reference of the same model and wall law (eq 23;
# tests/data/channel1d_leroy640.csv) and run to t = 20 s, past the settling of its first rows.
# Measured, isph-usaw (double and float alike to 4 digits): u+ within 2.4% of the reference on
# every row (1.4% RMS), the first row 1.8% under it, k 6.5% and ε 17% RMS off it, the particles'
# mean velocity 1.1% under the reference's, no k or ε clipped. Without the wall layer's wall
# function (kernels/usaw/turbulence.cl) the first row's k and ε fell to 0.64 and 0.35 of the
# reference's and u+ to 4% under it; with eq 38's shift correction taking the walls' velocity
# the rows along the walls broke up at t = 12 s. 20-40 s.
clsph_run_test(run_channel_usaw_ke ${CMAKE_SOURCE_DIR}/cases/channel_usaw_ke.lua
               SETS n=10 t_end=20 every=5
               BOUNDS "u_plus_dev_max<0.03" "u_plus_rms<0.02" "u_plus_dev_row1>-0.03"
               "u_plus_dev_row1<0.01" "k_plus_rms<0.09" "eps_plus_rms<0.22" "bulk_dev>-0.02"
               "bulk_dev<0.01" "turbulence.k_clipped<0.5" "turbulence.epsilon_clipped<0.5"
               "health.nearest_spacing_min_dr>0.9")
# wcsph-usaw on the same channel (sound speed 10 times the centreline's, a background pressure of
# 5% of ρ c0²) to t = 4 s: its rows stay in place (without the background pressure the first two
# rows broke up at t = 3 s). Measured: u+ within 1.8% (1.0% RMS), k 11% and ε 19% RMS off the
# reference. 15-30 s.
clsph_run_test(run_channel_usaw_ke_weak ${CMAKE_SOURCE_DIR}/cases/channel_usaw_ke.lua
               SETS n=10 t_end=4 every=2 weak=1
               BOUNDS "u_plus_dev_max<0.025" "u_plus_rms<0.015" "k_plus_rms<0.15"
               "eps_plus_rms<0.25" "health.nearest_spacing_min_dr>0.9")
# 40 rows per half height put the wall layer at y+ = 9.5, in the viscous sublayer, where the wall
# law is no log law and the model has no buffer layer (u+ 10-14% low at t = 40 s): warned of
clsph_cli_test(channel_usaw_ke_sublayer_warned ARGS run ${CMAKE_SOURCE_DIR}/cases/channel_usaw_ke.lua
               --quiet --overwrite --set n=40 --set t_end=0.02 --set every=0.01
               --out ${CMAKE_CURRENT_BINARY_DIR}/runs/usaw_ke_sublayer RC 0
               REGEX "the particles within dr of the walls stand at y\\+ = 9\\.5[0-9]* on average .* in the viscous sublayer")
# The scalable wall law (turbulence { wall_law = "scalable" }) at the same 40 rows, to t = 3 s from
# the 1-D reference: u+ within 0.8% of it (0.5% RMS), the mean velocity +0.3%, k 4.2% RMS; with
# the two-layer law the same run is 5.3% off (k 17% RMS) and drifting (10-14% by t = 40 s; the
# scalable law 1.7% at t = 20 s). Double and float. 40-80 s.
clsph_run_test(run_channel_usaw_ke_scalable ${CMAKE_SOURCE_DIR}/cases/channel_usaw_ke.lua
               SETS n=40 t_end=3 every=1 scalable=1
               BOUNDS "u_plus_dev_max<0.015" "u_plus_rms<0.01" "bulk_dev>-0.01" "bulk_dev<0.01"
               "k_plus_rms<0.07" "turbulence.wall_layer_y_plus_mean<11")
clsph_cli_test(channel_usaw_ke_rows_fraction ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_usaw_ke.lua
               --set n=2.5 RC 2
               REGEX "channel_usaw_ke: n must be a whole number of particle rows per half height from 4 to 400, not 2.5")
clsph_cli_test(channel_usaw_ke_control_two ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_usaw_ke.lua
               --set control=2 RC 2
               REGEX "channel_usaw_ke: control must be 0 \\(the body force")
# The strongly curved channel's start (cases/channel_curved.lua, N_f = 20, to t = 0.1 s of its 5.4
# s): started on the developed entry profile, the particles in rows along the walls. Measured
# (double and float, the walls' pressure the gradient, the default; the mirror's differ by 0.1%
# of U_b): u against OpenFOAM's curved profiles RMS 1.9% (bend) and 2.9% (outlet) of U_b (the
# straight profile the fluid started with: the bend has not yet reshaped it), k RMS 8.5% and 9.7%
# of the largest, nearest spacing 0.90 dr. On the Cartesian lattice (fitted = 0) the bend's mean
# speed fell to 0.86 U_b by t = 0.09 and speeds scattered by ±15%; with the exit holding the
# fluid back at the start the outlet read 66% RMS. 16 s.
clsph_run_test(run_channel_curved_start ${CMAKE_SOURCE_DIR}/cases/channel_curved.lua
               SETS setting=2 t_end=0.1 every=0.05 avg=0.05
               BOUNDS "u_rms_bend<0.03" "u_rms_outlet<0.04" "u_max_outlet<0.08" "k_rms_bend<0.13"
               "k_rms_outlet<0.14" "health.nearest_spacing_min_dr>0.8")
clsph_cli_test(channel_curved_wallp_two ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_curved.lua
               --set wallp=2 RC 2
               REGEX "channel_curved: wallp must be 0 \\(the mirror\\) or 1 \\(the gradient\\), not 2")
# The HCD channel's start with its particles fitted to the lower wall (cases/channel_hcd.lua,
# fitted = 1: six rows parallel to the ramps and the platform, round at the convex corners,
# trimmed at the concave ones, the lattice above, the floor's dummy layers in rows): no particle
# crosses the wall, and the band's junction with the lattice closes to 0.71 dr (double and float;
# it starts at 0.89 dr; the Cartesian lattice alone reaches 0.67 dr). The ARD indicator's mean
# over the four outputs (the series sample() records: 0.05 on the lattice at t = 0, then 2.2, 2.1
# and 4.0 as the start shears the rows by the walls) is 2.09 (float 2.10), its last output's 3.98
# (4.00): the metric is the series' mean, not the last output's. 2-4 s.
clsph_run_test(run_channel_hcd_fitted_start ${CMAKE_SOURCE_DIR}/cases/channel_hcd.lua
               SETS fitted=1 t_end=0.3 every=0.1 avg=0.3
               BOUNDS "health.nearest_spacing_min_dr>0.65" "wall_crossings.steps<0.5"
               "ard_mean>1.8" "ard_mean<2.4" "ard_now>3.5" "ard_now<4.5")
clsph_cli_test(channel_hcd_band_too_thin ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_hcd.lua
               --set fitted=1 --set band=1 RC 2
               REGEX "channel_hcd: band = 1: the fitted rows must be a whole number from 2")
clsph_cli_test(channel_hcd_fitted_two ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_hcd.lua
               --set fitted=2 RC 2 REGEX "channel_hcd: fitted must be 0 or 1, not 2")
clsph_cli_test(channel_hcd_wallp_two ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_hcd.lua
               --set wallp=2 RC 2
               REGEX "channel_hcd: wallp must be 0 \\(the mirror\\) or 1 \\(the gradient\\), not 2")
clsph_cli_test(channel_hcd_diff_two ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_hcd.lua
               --set diff=2 RC 2
               REGEX "channel_hcd: diff must be 0 .the harmonic mean over the fluid neighbours. or 1")
clsph_cli_test(channel_curved_grad_two ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_curved.lua
               --set grad=2 RC 2
               REGEX "channel_curved: grad must be 0 .the kernel sums' velocity gradient. or 1")
clsph_cli_test(channel_curved_shear_three ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_curved.lua
               --set shear=3 RC 2
               REGEX "channel_curved: shear must be 0 .the wall's shear from the log law at y_p., 1 .at each particle's distance. or 2 .on the first row only., not 3")
clsph_cli_test(channel_hcd_pforce_two ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_hcd.lua
               --set pforce=2 RC 2
               REGEX "channel_hcd: pforce must be 0 .the walls' pressure force with the correction matrix. or 1 .along the walls' normal., not 2")
# md reaches the scheme: md = 0 takes the Riemann dissipation off the fluid pairs
clsph_cli_test(channel_hcd_md_off ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_hcd.lua
               --set ard=0 --set md=0 RC 0
               REGEX "ARD off, density summation, walls' dissipation limited, fluid pairs' momentum dissipation off")
clsph_cli_test(channel_hcd_md_three ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_hcd.lua
               --set ard=0 --set md=3 RC 2
               REGEX "channel_hcd: md must be -1 .the scheme's default., 0 .no Riemann dissipation., 1 .eq 19's full jump. or 2 .the reconstructed jump., not 3")
clsph_cli_test(channel_hcd_md_with_ard ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_hcd.lua
               --set md=0 RC 2
               REGEX "channel_hcd: md = 0 with ard = 1: ARD sets the momentum's dissipation itself")
clsph_cli_test(channel_ke_md_seven ARGS info ${CMAKE_SOURCE_DIR}/cases/channel_ke.lua
               --set md=7 RC 2
               REGEX "channel_ke: md must be -1 .the scheme's default., 0 .off., 1 .riemann. or 2 .reconstructed., not 7")
# fill { k, epsilon } needs a turbulence model; k and ε of a fill must be positive
clsph_cli_test(turbulence_fill_without_model ARGS info ${bad_turb} --set what=7 RC 2
               REGEX "fill \\{ k, epsilon \\}: the case declares no turbulence")
clsph_cli_test(turbulence_unknown_model ARGS info ${bad_turb} --set what=9 RC 2
               REGEX "turbulence: 'k-omega' is not a valid model; known: k-epsilon")
clsph_cli_test(turbulence_k_not_number ARGS info ${bad_turb} --set what=10 RC 2
               REGEX "turbulence: 'k' must be a number")
clsph_cli_test(case_reference_missing ARGS info ${bad_turb} --set what=11 RC 2
               REGEX "reference: cannot read .*tests/data/no_such_table.csv")
clsph_cli_test(turbulence_fill_negative ARGS info ${bad_turb} --set what=8 RC 2
               REGEX "fill 'fill 1': epsilon must be positive, not -1")
# the USAW schemes' k-ε (Leroy et al. eqs 22-29) has no use for wcsph-riemann's wall-model keys
clsph_cli_test(turbulence_usaw_y_p ARGS info ${bad_turb} --set what=12 RC 2
               REGEX "turbulence: y_p belongs to wcsph-riemann's wall model; isph-usaw applies the log law at each particle's own distance")
clsph_cli_test(turbulence_usaw_wall_weight ARGS info ${bad_turb} --set what=13 RC 2
               REGEX "turbulence: wall_weight belongs to wcsph-riemann's wall model .*isph-usaw has none")
clsph_cli_test(turbulence_usaw_delay ARGS info ${bad_turb} --set what=14 RC 2
               REGEX "turbulence: delay .* is wcsph-riemann's; isph-usaw starts the model at once")
clsph_cli_test(turbulence_wall_law_misspelt ARGS info ${bad_turb} --set what=16 RC 2
               REGEX "turbulence: 'scaleable' is not a valid wall_law.*scalable")
clsph_cli_test(turbulence_wall_law_riemann ARGS info ${bad_turb} --set what=17 RC 2
               REGEX "turbulence: wall_law belongs to the USAW schemes' wall law .* wcsph-riemann's wall model")
clsph_cli_test(turbulence_production_unknown ARGS info ${bad_turb} --set what=18 RC 2
               REGEX "turbulence: 'linear' is not a valid production.*semi-linear")
clsph_cli_test(turbulence_production_riemann ARGS info ${bad_turb} --set what=19 RC 2
               REGEX "turbulence: production belongs to the USAW schemes' model .* drop it")
clsph_cli_test(turbulence_wcsph_usaw_y_p ARGS info ${bad_turb} --set what=15 RC 2
               REGEX "turbulence: y_p belongs to wcsph-riemann's wall model; wcsph-usaw applies")
# an entry's k and ε (inflow { k, epsilon }): only under the model, together, consistent
set(bad_inflow_turb ${CASE_DIR}/bad_inflow_turbulence.lua)
clsph_cli_test(turbulence_inflow_without_model ARGS info ${bad_inflow_turb} --set what=1 RC 2
               REGEX "inflow 'entry': k and epsilon belong to the k-epsilon model")
clsph_cli_test(turbulence_inflow_k_alone ARGS info ${bad_inflow_turb} --set what=2 RC 2
               REGEX "inflow 'entry': give k and epsilon together \\(k alone")
clsph_cli_test(turbulence_inflow_inconsistent ARGS info ${bad_inflow_turb} --set what=3 RC 2
               REGEX "inflow 'entry': k = 0.01 and epsilon = 1e-06 are inconsistent: their length scale")
clsph_cli_test(turbulence_inflow_negative ARGS info ${bad_inflow_turb} --set what=4 RC 2
               REGEX "inflow 'entry': epsilon = -1.0* must be a positive dissipation rate")
clsph_cli_test(riemann_reconstructed_laminar ARGS info ${bad_inflow_turb} --set what=5 RC 2
               REGEX "momentum_dissipation = \"reconstructed\" needs the velocity gradient")
clsph_cli_test(riemann_dissipation_off_with_ard ARGS info ${bad_inflow_turb} --set what=6 RC 2
               REGEX "momentum_dissipation = \"off\" contradicts ard = 1")
clsph_cli_test(riemann_wall_shear_laminar ARGS info ${bad_inflow_turb} --set what=15 RC 2
               REGEX "wall_shear = \"distance\" belongs to the k-ε model .*: where its wall model reads the log law")
clsph_cli_test(riemann_wall_shear_unknown ARGS info ${bad_inflow_turb} --set what=16 RC 2
               REGEX "wcsph-riemann option wall_shear must be one of \"y_p\", \"distance\", \"first_row\"")
clsph_cli_test(riemann_velocity_gradient_laminar ARGS info ${bad_inflow_turb} --set what=17 RC 2
               REGEX "velocity_gradient = \"log\" belongs to the k-ε model .*: its velocity gradient next to a wall")
clsph_cli_test(riemann_velocity_gradient_unknown ARGS info ${bad_inflow_turb} --set what=18 RC 2
               REGEX "wcsph-riemann option velocity_gradient must be one of \"kernel\", \"log\"")
clsph_cli_test(riemann_turbulent_diffusion_laminar ARGS info ${bad_inflow_turb} --set what=19 RC 2
               REGEX "turbulent_diffusion = \"log_mirror\" belongs to the k-ε model .*: its diffusion of k and ε")
clsph_cli_test(riemann_turbulent_diffusion_unknown ARGS info ${bad_inflow_turb} --set what=20 RC 2
               REGEX "wcsph-riemann option turbulent_diffusion must be one of \"harmonic\", \"log_mirror\"")
clsph_cli_test(riemann_offset_layer_laminar ARGS info ${bad_inflow_turb} --set what=21 RC 2
               REGEX "offset_layer = \"body_force\" belongs to the k-ε model .*: its wall model's layer below the offset boundary")
clsph_cli_test(riemann_offset_layer_unknown ARGS info ${bad_inflow_turb} --set what=22 RC 2
               REGEX "wcsph-riemann option offset_layer must be one of \"none\", \"body_force\"")
clsph_cli_test(riemann_offset_layer_no_layer ARGS info ${bad_inflow_turb} --set what=23 RC 2
               REGEX "turbulence: y_p = 0.02 is under half the particle spacing \\(dr = 0.1\\), so there is no layer")
clsph_cli_test(riemann_wall_pressure_force_laminar ARGS info ${bad_inflow_turb} --set what=24 RC 2
               REGEX "wall_pressure_force = \"normal\" belongs to the k-ε model .*: the direction of the walls' pressure force next to its wall model")
clsph_cli_test(riemann_wall_pressure_force_unknown ARGS info ${bad_inflow_turb} --set what=25 RC 2
               REGEX "wcsph-riemann option wall_pressure_force must be one of \"corrected\", \"normal\"")
clsph_cli_test(inflow_function_not_number ARGS info ${bad_inflow_turb} --set what=7 RC 2
               REGEX "inflow 'entry': the velocity function returned string at s = 0(\\.0)?: it must return a number")
clsph_cli_test(inflow_function_k_negative ARGS info ${bad_inflow_turb} --set what=8 RC 2
               REGEX "inflow 'entry': the k function gives 0(\\.0)? at s = 0\\.5: it must be positive")
clsph_cli_test(inflow_function_with_profile ARGS info ${bad_inflow_turb} --set what=9 RC 2
               REGEX "inflow 'entry': profile = belongs to a velocity number")
clsph_cli_test(inflow_function_with_ramp ARGS info ${bad_inflow_turb} --set what=10 RC 2
               REGEX "inflow 'entry': ramp = 0\\.5 needs a uniform or parabolic profile")
clsph_cli_test(inflow_function_flows_out ARGS info ${bad_inflow_turb} --set what=11 RC 2
               REGEX "inflow 'entry': the velocity function's mean over the section is -0\\.3")
clsph_cli_test(inflow_function_inconsistent ARGS info ${bad_inflow_turb} --set what=12 RC 2
               REGEX "inflow 'entry': k = 0\\.01 and epsilon = 1e-06 at s = 0\\.9[0-9]* m are inconsistent")
clsph_cli_test(inflow_function_k_alone ARGS info ${bad_inflow_turb} --set what=13 RC 2
               REGEX "inflow 'entry': give k and epsilon together \\(k alone")
clsph_cli_test(inflow_function_nan ARGS info ${bad_inflow_turb} --set what=14 RC 2
               REGEX "inflow 'entry': the velocity function gives -?nan at s = 0(\\.0)?: it must be finite")
# decaying turbulence carried in from an entry through a periodic stream to a natural exit
# (tests/case/inflow_ke.lua): k and ε against the exact homogeneous decay. Measured (dr = 0.1,
# t = 6, double and float): k RMS 0.22%, largest 0.56%, ε RMS 0.45% of the entry's, the exit's k
# 1.0009 of the exact; bounds at 4 times (the source linearisation is first order in Δt ε/k,
# 0.8% a step); an entry that lost its k0 to the recycled exit particles would be 50% off.
clsph_run_test(run_inflow_ke ${CASE_DIR}/inflow_ke.lua
               BOUNDS "k_err_rms<0.01" "k_err_max<0.025" "eps_err_rms<0.02" "k_exit_ratio>0.98"
               "k_exit_ratio<1.02")
# An entry given as functions of s (tests/case/inflow_profile.lua): the first row of fluid
# carries the entry's u(s), k(s), ε(s), and the stream its mean. Measured (dr = 0.05, t = 1,
# double): u RMS 0.12% of U (largest 0.30%), k RMS 0.48% (largest 1.2%) of k0, ε RMS 1.3% of ε0
# (the first row is up to dr/U = 0.05 s old: ε/k = 0.2/s and the shear's production change k by
# about 1% meanwhile), the flux 0.9994 of the mean; bounds at about 4 times. An entry that took
# its largest speed uniformly would read 12% in u, one that fell back on turbulence { }'s k 300%,
# one that read s from the other end 70% in k.
clsph_run_test(run_inflow_profile ${CASE_DIR}/inflow_profile.lua
               BOUNDS "u_err_rms<0.005" "u_err_max<0.015" "k_err_rms<0.02" "k_err_max<0.05"
               "eps_err_rms<0.05" "flux_ratio>0.99" "flux_ratio<1.01" "first_row>19")
# Circular Couette flow between a turning cylinder and a fixed one (tests/case/couette_annulus.lua,
# wcsph-riemann, Re = 2.5, steady by t = 3: the slowest mode has decayed by e^-12), the fluid in
# rings along the walls (fill { points }) and the dummy layers in rings behind them (circle {
# dummies = "fitted" }). Measured (nf = 10, double): u_θ RMS 2.8% of ω R1 (largest 6.0%), the
# radial speed 0.15%; at nf = 20 1.4% (first order) and 0.05%. The Cartesian lattice for both
# (fitted = 0): 3.2% and 2.1% at nf = 10, 2.1% and 1.3% at nf = 20, its largest error 11% and 15%
# (the walls cut the lattice at every angle). Bounds at about 1.4 times the fitted run's.
clsph_run_test(run_couette_annulus ${CASE_DIR}/couette_annulus.lua
               BOUNDS "u_err_rms<0.04" "u_err_max<0.085" "u_r_rms<0.003")
# Walls that turn (wall { omega, centre }) under the USAW schemes: the vertex particles and
# segments stand rotated by ω t about the centre (kernels/usaw/motion.cl). A square box turning
# with the fluid inside it (tests/case/turning_box.lua: solid-body rotation, no gravity, 1 rad):
# isph-usaw keeps u within 0.62% of ω × r RMS (1.1% at most), the pressure within 1.3% RMS of
# ρ ω² r²/2, the fluid inside the box, the torque on it 0.2% of ρ ω² a³ × its perimeter (double
# and float alike); with the geometry standing still (the velocity only) the corners plough
# through the fluid and the run stops at 0.3 s (a particle 0.52 dr behind a wall).
clsph_run_test(run_turning_box ${CASE_DIR}/turning_box.lua
               BOUNDS "u_err_rms<0.012" "u_err_max<0.02" "p_err_rms<0.025" "outside<0.5"
               "crossed<0.5" "torque>-0.005" "torque<0.005")
# wcsph-usaw from rest density (c0 = 10 ω a √2), to 3 rad: its acoustic start leaves u within
# 5.2% and p within 7.3% RMS (the wall guard on: without it the corner particles, where the
# centripetal pressure peaks, crept out through the turning walls and the run stopped at 0.97 s).
clsph_run_test(run_turning_box_weak ${CASE_DIR}/turning_box.lua SETS weak=1 t_end=3
               BOUNDS "u_err_rms<0.08" "p_err_rms<0.12" "outside<0.5" "crossed<0.5")
# Three particles ahead of a turning paddle's face above the water (tests/case/turning_splash.lua):
# given p̃ = 0 (free_surface.cl, ISPH_SPLASH) they meet the paddle through the wall guard, in 8
# solver iterations at most; as a pressure block of their own the solve ran to its limit at the
# first step (residual 1e42) and they went 0.7 dr through the paddle.
clsph_run_test(run_turning_splash ${CASE_DIR}/turning_splash.lua
               BOUNDS "crossed<0.5" "escaped<0.5" "solver.iterations_max<50")
# The water wheel (cases/water_wheel.lua, Leroy et al. sec 4.4) at dr = 0.05 m (2106 particles, its
# arms 1.6 dr thick) to t = 2 s (t+ = 6.6), both schemes. Measured (double / float; the flow is
# chaotic and the two part within the first second): isph-usaw (density_relaxation 0.01) no
# crossing, the water's area within 0.52% / 0.54% of its start, the deep water's number density
# 0.990 / 0.988, the torque over t = 1-2 s −1405 / −1358 N m/m, the wheel's work 1.53 / 1.38 times
# the fluid's energy gain (the rest dissipated); wcsph-usaw (c0 = 29.7 m/s, samples every 0.05 s)
# area within 0.24% / 0.29%, density 1.003, torque −662 / −670 N m/m, work 1.27 / 1.18 times the
# gain. With the paper's projection (relax = 0) the deep water spread to 0.957 and the area grew
# 2.1% by t = 2 s; before wcsph-usaw's wall vertices took their pressure from their own fluid
# sector (density.cl) its torque was −219 N m/m and the wheel's work 0.42 of the fluid's gain.
clsph_run_test(run_water_wheel ${CMAKE_SOURCE_DIR}/cases/water_wheel.lua
               SETS dr=0.05 t_end=2 every=0.5
               BOUNDS "crossed_wall<0.5" "fluid_particles>2105.5" "fluid_particles<2106.5"
               "water_area_worst<0.015" "water_spray_worst<0.015" "deep_density>0.97" "deep_density<1.02"
               "torque_mean<-600" "torque_mean>-2500" "work_over_gain>1" "work_over_gain<2"
               "max_speed_over_tip<3")
# wcsph-usaw's torque carries its pressure's acoustic noise (peaks of ±3e3 N m/m from one sample to
# the next; the paper too found its force far noisier than isph-usaw's), which the samples alias:
# the work over the gain read 0.86 in float with the samples every 0.1 s, and the mean torque over
# one second −176 to −1301 N m/m between builds; bounds from the energy balance that the old
# vertex pressure failed (0.42), the torque's sign, and the volume.
clsph_run_test(run_water_wheel_weak ${CMAKE_SOURCE_DIR}/cases/water_wheel.lua
               SETS dr=0.05 t_end=2 every=0.25 wcsph=1
               BOUNDS "crossed_wall<0.5" "fluid_particles>2105.5" "fluid_particles<2106.5"
               "water_area_worst<0.015" "water_spray_worst<0.015" "deep_density>0.98" "deep_density<1.02"
               "torque_mean<0" "work_over_gain>0.6" "work_over_gain<2" "max_speed_over_tip<3")
# The wheel's solver tolerance: 0 is the solver's default, a negative one is refused by name
clsph_cli_test(case_water_wheel_bad_rtol ARGS info ${CMAKE_SOURCE_DIR}/cases/water_wheel.lua
               --set rtol=-1e-6 RC 2 REGEX "rtol must be 0 \\(the solver's default\\) or positive")
# The fish-pass (cases/fish_pass.lua, Leroy et al. sec 5.2) at n = 8 (the slot in spacings: 4247
# fluid particles) from rest to t = 1 s, k-ε on, both schemes, against OpenFOAM's start-up from rest
# on the same pool (tests/data/openfoam_fish_pass_flow.csv; its 20-s profiles are the validation
# run's, tests/validation/run_fish_pass.sh). Measured (double): isph-usaw (its singular pressure
# equation mean-free, the wall guard on) no crossing, the flow rate across P2 at 1 s 0.5% under
# OpenFOAM's (whose own mesh halving moves it 3%), 4.3% RMS off its history over the second, the
# x momentum within 2.5% of the drive's impulse less the walls' recorded one, at most 13 solver
# iterations; wcsph-usaw (c0 = 40 m/s, the paper's background pressure 5e4 Pa) no crossing, the flow
# rate 12.8% under OpenFOAM's, its momentum 17.7% short of the balance: the background pressure, 6
# times the jet's dynamic pressure, acts on the first rows through the gradient of a constant, which
# is not zero next to a wall, and not on the walls' recorded force (the paper: "high values of the
# latter lead to inaccurate results"). Without the weighted mean isph-usaw's reinforced solves
# stopped converging within 0.1 s (the pressure's level grew to 6e5 Pa), and without the guard
# its jet took particles 0.36 dr behind the baffles' corners. In float the flow rate at 1 s
# depends on the order of the solver's sums by some per cent (its tolerance is 1e-5): −1.1% and
# −4.2% under OpenFOAM's with the stored rows' reductions strided and in contiguous runs
# (blas1.cl; double +1.43% either way, 2026-12-05), hence ±6%.
clsph_run_test(run_fish_pass ${CMAKE_SOURCE_DIR}/cases/fish_pass.lua
               SETS n=8 t_end=1 every=0.5
               BOUNDS "crossed_wall<0.5" "flow_rate_dev_now>-0.06" "flow_rate_dev_now<0.06"
               "flow_rate_history_rms<0.08" "momentum_residual>-0.05" "momentum_residual<0.02"
               "solver.iterations_max<30")
clsph_run_test(run_fish_pass_weak ${CMAKE_SOURCE_DIR}/cases/fish_pass.lua
               SETS n=8 t_end=1 every=0.5 weak=1
               BOUNDS "crossed_wall<0.5" "flow_rate_dev_now>-0.25" "flow_rate_dev_now<0.05"
               "flow_rate_history_rms<0.12" "momentum_residual>-0.25" "momentum_residual<0.02")
clsph_cli_test(fish_pass_odd_n ARGS info ${CMAKE_SOURCE_DIR}/cases/fish_pass.lua --set n=9 RC 2
               REGEX "fish_pass: n \\(the slot width in particle spacings\\) must be an even number from 8 to 60, not 9")
# Turning walls that cannot turn (tests/case/bad_turning.lua)
set(bad_turning ${CASE_DIR}/bad_turning.lua)
clsph_cli_test(turning_valid ARGS info ${bad_turning} --set what=0 RC 0
               REGEX "particles: 480 \\(fluid 320, wall vertices 160")
clsph_cli_test(turning_hits_wall ARGS info ${bad_turning} --set what=1 RC 2
               REGEX "bad_turning.lua:15: the wall turns about \\(0, 0.75\\) through a disc of radius 0.707107 m that comes within 0.0428932 m of the wall of line 12")
clsph_cli_test(turning_leaves_domain ARGS info ${bad_turning} --set what=2 RC 2
               REGEX "bad_turning.lua:15: the wall turns about \\(0, 1.5\\) through a disc of radius 0.707107 m that leaves the domain \\[0, 2\\] along y")
clsph_cli_test(turning_wider_than_period ARGS info ${bad_turning} --set what=3 RC 2
               REGEX "bad_turning.lua:15: the wall turns .* wider than the period 4 m of axis x less dr: it would meet its own periodic image")
clsph_cli_test(period_cuts_wall ARGS info ${bad_turning} --set what=4 RC 2
               REGEX "bad_turning.lua:12: the wall spans 5 m along the periodic axis x, more than the period 4 m: the period cuts it")
clsph_cli_test(turning_dummy_not_circle ARGS info ${bad_turning} --set what=5 RC 2
               REGEX "bad_turning.lua:15: the wall turns \\(omega = 1\\) but is not a circle about its centre .* a turning geometry needs a USAW scheme")
set(bad_fitted ${CASE_DIR}/bad_fitted.lua)
clsph_cli_test(fitted_valid ARGS info ${bad_fitted} --set what=0 RC 0
               REGEX "particles: 416 \\(fluid 200, wall vertices 0, dummy 216")
clsph_cli_test(fill_points_not_list ARGS info ${bad_fitted} --set what=1 RC 2
               REGEX "fill 'fill 1': points must be a list of particle positions")
clsph_cli_test(fill_points_not_point ARGS info ${bad_fitted} --set what=2 RC 2
               REGEX "fill 'fill 1': points\\[7\\] must be a point \\{x, y\\} of finite numbers")
clsph_cli_test(fill_points_outside ARGS info ${bad_fitted} --set what=3 RC 2
               REGEX "points\\[3\\] \\(2.5, 0.5\\) is outside the domain")
clsph_cli_test(fill_points_twice ARGS info ${bad_fitted} --set what=4 RC 2
               REGEX "are 0.01 m apart, less than dr/2: points given twice, or fills that overlap")
clsph_cli_test(fill_points_and_polygon ARGS info ${bad_fitted} --set what=5 RC 2
               REGEX "give points, a polygon or a rectangle, not two of them")
clsph_cli_test(fitted_under_usaw ARGS info ${bad_fitted} --set what=6 RC 2
               REGEX "wall \\{ dummies = \"fitted\" \\} arranges dummy particles, but this scheme's walls are usaw")
clsph_cli_test(fitted_unknown ARGS info ${bad_fitted} --set what=7 RC 2
               REGEX "wall: 'curved' is not a valid dummies")
clsph_cli_test(fitted_turns_back ARGS info ${bad_fitted} --set what=8 RC 2
               REGEX "it turns back on itself at \\(1.5, 0\\); fitted rows need a smooth wall")
clsph_cli_test(fill_points_in_obstacle ARGS info ${bad_fitted} --set what=9 RC 2
               REGEX "points\\[69\\] \\(0.85, 0.35\\) lies in an obstacle")
clsph_cli_test(fill_points_across_period ARGS info ${bad_fitted} --set what=10 RC 2
               REGEX "at \\(1.995, 0.05\\) \\('fill 1'\\) and \\(0.01, 0.05\\) \\('fill 1'\\) are 0.015 m apart")
# The delayed activation (tests/case/ke_delay.lua: uniform k and ε at rest, delay 0.5 s, ν_t =
# 1e-3 meanwhile). Waiting (t = 0.25): k and ν_t exactly as given (measured ratios 1 to 1e-15;
# bounds 1e-6 for float). Then (t = 1) the homogeneous decay from t = 0.5: k within 0.003% of
# exact and ν_t of eq 6 to 1e-15 (bound 0.5%: the linearised sink is first order, Δt ε/k =
# 0.0025); a model that ignored the delay would read 0.83.
clsph_run_test(run_ke_delay_waiting ${CASE_DIR}/ke_delay.lua SETS t_end=0.25
               BOUNDS "k_ratio>0.999999" "k_ratio<1.000001" "nu_t_ratio>0.999999"
               "nu_t_ratio<1.000001" "k_spread<1e-6")
clsph_run_test(run_ke_delay ${CASE_DIR}/ke_delay.lua SETS t_end=1
               BOUNDS "k_ratio>0.995" "k_ratio<1.005" "nu_t_ratio>0.999" "nu_t_ratio<1.001"
               "k_spread<1e-6")
# The k-ε model's diffusion alone (tests/case/ke_diffusion.lua): a cosine mode of k in a fluid at
# rest decays at D_k (2π)² plus the linearised sink (eq 28): measured within 0.3% of the exact
# rate's decay over t = 0.04 (to 0.45); bound 2% (ε's own diffusion, the ⅔ ρ k pressure and the
# lattice's Laplacian are second order). The diffusion at half its strength (a missing factor 2
# of eq 23, fixed) read +48%. 1 s.
clsph_run_test(run_ke_diffusion ${CASE_DIR}/ke_diffusion.lua
               BOUNDS "decay_error>-0.02" "decay_error<0.02")

# A metrics() that asks for what the run does not have fails the run with one message that says
# what is missing, where the script asked (the reason is not logged a second time).
set(bad_metrics ${CASE_DIR}/bad_metrics.lua --quiet --overwrite)
clsph_cli_test(metrics_no_field ARGS run ${bad_metrics} --set what=1
               --out ${CMAKE_CURRENT_BINARY_DIR}/runs/metrics_no_field RC 2
               REGEX "bad_metrics.lua:17: sim.field: no values of 'k' component 1: no field 'k'"
               NOT_REGEX "error: metrics: no field")
clsph_cli_test(metrics_no_component ARGS run ${bad_metrics} --set what=2
               --out ${CMAKE_CURRENT_BINARY_DIR}/runs/metrics_no_component RC 2
               REGEX "bad_metrics.lua:18: sim.field: no values of 'vel' component 3: field 'vel' has 2 components"
               NOT_REGEX "error: metrics:")
clsph_cli_test(metrics_no_force ARGS run ${bad_metrics} --set what=3
               --out ${CMAKE_CURRENT_BINARY_DIR}/runs/metrics_no_force RC 2
               REGEX "bad_metrics.lua:19: sim.force: the case records no force of 'lid' \\(force \\{ \"lid\" \\}\\)"
               NOT_REGEX "error: metrics:")
clsph_cli_test(metrics_no_probe ARGS run ${bad_metrics} --set what=4
               --out ${CMAKE_CURRENT_BINARY_DIR}/runs/metrics_no_probe RC 2
               REGEX "bad_metrics.lua:20: sim.probe: no value of 'p' \\(component 1\\) at probe 'gauge': the case declares no probe 'gauge'"
               NOT_REGEX "error: metrics:")
clsph_cli_test(metrics_sample_no_field ARGS run ${bad_metrics} --set what=5
               --out ${CMAKE_CURRENT_BINARY_DIR}/runs/metrics_sample_no_field RC 2
               REGEX "bad_metrics.lua:21: sim.sample: cannot sample 'epsilon' at \\(0.5, 0.25\\): no field 'epsilon'"
               NOT_REGEX "error: metrics:")
clsph_cli_test(metrics_sample_interpolation ARGS run ${bad_metrics} --set what=6
               --out ${CMAKE_CURRENT_BINARY_DIR}/runs/metrics_sample_interpolation RC 2
               REGEX "bad_metrics.lua:22: sim.sample: interpolation must be \"shepard\" or \"linear\", not \"cubic\""
               NOT_REGEX "error: metrics:")
clsph_cli_test(metrics_profile_interpolation ARGS run ${bad_metrics} --set what=7
               --out ${CMAKE_CURRENT_BINARY_DIR}/runs/metrics_profile_interpolation RC 2
               REGEX "bad_metrics.lua:24: profile_error: 'quadratic' is not a valid interpolation; known: shepard linear"
               NOT_REGEX "error: metrics:")
clsph_cli_test(profile_interpolation ARGS info ${CASE_DIR}/bad_metrics.lua --set what=8 RC 2
               REGEX "bad_metrics.lua:14: profile: 'linaer' is not a valid interpolation; did you mean 'linear'\\?")


# isph-stabilized (solvers/isph_stabilized/): stabilized ISPH of Asai et al. 2012 on dummy walls
# with virtual markers, the modified virtual marker's Neumann wall pressure (S = the seed paper's
# sec 3.3) and the pseudo-Neumann one (sec 3.2). Bad input
# is refused with the case's scheme line and the key: α out of range, options that are not numbers
# or not among the choices, wall_velocity and slip_ratio together, too few dummy layers for the
# markers, a wall too thin for them, markers outside the domain (with the wall's line), and
# sections.
clsph_cli_test(stab_alpha_range ARGS info ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua --set stab=1
               --set alpha=1.5 RC 2
               REGEX "hydrostatic.lua:[0-9]+: isph-stabilized option alpha = 1.5 is out of range: the relaxation coefficient")
set(bad_stab ${CASE_DIR}/bad_stab.lua)
clsph_cli_test(stab_alpha_text ARGS info ${bad_stab} --set what=1 RC 2
               REGEX "bad_stab.lua:20: isph-stabilized option alpha must be a number from 0 to 1, not \"small\"")
clsph_cli_test(stab_bad_wall_pressure ARGS info ${bad_stab} --set what=2 RC 2
               REGEX "bad_stab.lua:20: isph-stabilized option wall_pressure must be one of \"pseudo_neumann\", \"neumann\", not \"dirichlet\"")
clsph_cli_test(stab_slip_twice ARGS info ${bad_stab} --set what=3 RC 2
               REGEX "bad_stab.lua:20: .*give wall_velocity or slip_ratio, not both")
clsph_cli_test(stab_surface_threshold ARGS info ${bad_stab} --set what=4 RC 2
               REGEX "bad_stab.lua:20: isph-stabilized option surface_threshold = 1.2 is out of range")
clsph_cli_test(stab_bad_wall_velocity ARGS info ${bad_stab} --set what=5 RC 2
               REGEX "bad_stab.lua:20: isph-stabilized option wall_velocity must be one of \"no_slip\", \"slip\", not \"sticky\"")
clsph_cli_test(stab_wall_layers ARGS info ${bad_stab} --set what=6 RC 2
               REGEX "bad_stab.lua: isph-stabilized: wall_layers = 1 puts dummies .* wall_layers >= 2")
clsph_cli_test(stab_thin_wall ARGS info ${bad_stab} --set what=7 RC 2
               REGEX "bad_stab.lua:29: wall \\(group 'plate'\\) is too thin for the virtual markers: .* make it at least 0.38 m thick")
clsph_cli_test(stab_marker_outside ARGS info ${bad_stab} --set what=8 RC 2
               REGEX "bad_stab.lua:32: wall \\(group 'lid'\\): the virtual marker of the dummy at .* falls at .*, outside the domain")
# a scene without a gate builds no gate field; the dam break with one does
clsph_cli_test(stab_no_gate_field ARGS info ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua --set stab=1
               RC 0 REGEX "fields: pos .* dirichlet" NOT_REGEX " gate \\(")
clsph_cli_test(stab_gate_field ARGS info ${CMAKE_SOURCE_DIR}/cases/dam_break.lua --set stab=1
               --set gate=1 RC 0 REGEX "fields: pos .* gate \\(4 B\\)")
clsph_cli_test(stab_gate_group ARGS info ${bad_stab} --set what=9 RC 2
               REGEX "bad_stab.lua:20: isph-stabilized option gate = \"door\": no wall has that group \\(groups: walls\\)")
clsph_cli_test(stab_gate_alone ARGS info ${bad_stab} --set what=10 RC 2
               REGEX "bad_stab.lua:20: isph-stabilized option gate_speed needs gate = ")
clsph_cli_test(stab_gate_order ARGS info ${bad_stab} --set what=11 RC 2
               REGEX "bad_stab.lua:20: isph-stabilized option gate_stop = 0.2 s must come after gate_start = 0.5 s")
clsph_cli_test(stab_gate_travel ARGS info ${bad_stab} --set what=12 RC 2
               REGEX "bad_stab.lua:26: isph-stabilized: the gate \\(group 'walls'\\) leaves the domain: after its lift of 10 m")
clsph_cli_test(stab_sections ARGS info ${CASE_DIR}/bad_open_scheme.lua --set usaw=2 RC 2
               REGEX "bad_open_scheme.lua: isph-stabilized has no inflow or outflow sections")
# The paper's tank (S sec 4.1: 0.2 m of water, 0.2 m wide, dr = 0.01 m), from the hydrostatic
# pressure, α = 0.01, 1 s. What S finds (its figs 3 and 5), here in numbers on the particles within
# 3 dr of the floor, against ρ g (H − z), relative to ρ g H, averaged over the 20 samples of the
# last 0.5 s (bottom_*_avg): the modified virtual marker (the default) right, the pseudo-Neumann
# walls low.
# Modified virtual marker (230 steps, 4.9 BiCGStab iterations a step in double, 2.5 in float;
# about 3 s): bottom_error_avg 0.0081 (double) and 0.0076 (float), bottom_bias_avg +0.0075 and
# +0.0068, speed_ratio 0.029 and 0.027 (the fluid jostles at 3-4 cm/s), no particle behind a wall.
# Bounds: 1.5% on the floor (the pseudo-Neumann walls' 6.8% below), speed 1.5 times measured.
# The tank holds 10 s in both precisions, but after about 1.5 s the time step jitters (1.4 to 4.4
# ms) with the fluid's largest acceleration, which the walls' approach term (ppe.cl) kicks, and the
# α ρ0 (1 − s*/σ0)/Δt² term swings the pressure with it: bottom_error_avg over 1 to 2 s is 0.056
# in double and 0.097 in float.
clsph_run_test(run_stab_hydrostatic_neumann ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               SETS stab=1 depth=0.2 width=0.2 dr=0.01 t_end=1
               BOUNDS "bottom_error_avg<0.015" "bottom_bias_avg>-0.015" "bottom_bias_avg<0.015"
                      "speed_ratio<0.045" "crossed_wall<0.5")
# Pseudo-Neumann, 1 s (230 steps, 5.1 BiCGStab iterations a step in double, 2.2 in float). The
# walls' values are the fluid's Shepard mean at their markers plus ρ g 2d, lagged one step: the
# mean at a marker half a spacing from the floor reads the fluid above it, so the floor carries
# less than the water's weight and the fluid over it settles slightly compressed.
# bottom_bias_avg −0.0545 (double and float), bottom_error_avg 0.068 (both), speed_ratio 0.0248 and
# 0.0275, no particle behind a wall. Bounds: the sign and at least 3.5% (the paper's finding), no
# lower than −0.09 (1.5 times the measured bias; a wall mapping without its ρ a·(x_w − x_m) term
# reads −0.5), error and speed 1.5 times measured. Over 10 s: −0.067 to −0.068, steady.
# Both conditions clustered in the top row (at 0.52 s and 1.17 s) before the pressure gradient took
# Thomas & Couchman's kernel derivative for close pairs (isph_stabilized/project.cl).
clsph_run_test(run_stab_hydrostatic_pseudo ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               SETS stab=1 depth=0.2 width=0.2 dr=0.01 t_end=1 neumann=0
               BOUNDS "bottom_bias_avg<-0.035" "bottom_bias_avg>-0.09" "bottom_error_avg<0.1"
                      "speed_ratio<0.05" "crossed_wall<0.5")
# The same with α = 0, the divergence-free projection alone: nothing pulls the density back, and
# the fluid over the floor stays more compressed: bottom_bias_avg −0.0843 (double), −0.0839
# (float), speed_ratio 0.0285 and 0.0337. The bound on the bias separates it from the α = 0.01 run
# above (−0.0545): the relaxation term is what lifts the pressure there.
clsph_run_test(run_stab_alpha0 ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               SETS stab=1 depth=0.2 width=0.2 dr=0.01 t_end=1 alpha=0 neumann=0
               BOUNDS "bottom_bias_avg<-0.07" "bottom_bias_avg>-0.15" "speed_ratio<0.05"
                      "crossed_wall<0.5")
# The modified virtual marker's system three ways, 0.1 s (30 steps, before the jostle makes the two
# precisions part): the stored BiCGStab gives bottom_bias 0.00832 (double) and 0.00825 (float);
# UMFPACK on the assembled rows (`coefficients`) 0.00832 and 0.00832; the BiCGStab recomputing the
# operator at every application (`apply`) 0.00832 and 0.00825; with 5 dummy layers instead of 3
# 0.00832 and 0.00825 (the deeper dummies, which no fluid particle sees, are Dirichlet rows: as
# unknowns their marker rows reached beyond the multigrid's stencil, whose lumping left them a
# zero diagonal, and that tank blew up at its first step). Bounds ±6% around 0.0083: a rows/apply
# mismatch or a deep dummy that counts moves it more.
foreach(v direct=1 recompute=1 layers=5)
  string(REGEX REPLACE "=.*" "" tag ${v})
  clsph_run_test(run_stab_hydrostatic_${tag} ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
                 SETS stab=1 depth=0.2 width=0.2 dr=0.01 t_end=0.1 ${v}
                 BOUNDS "bottom_bias>0.0078" "bottom_bias<0.0088" "crossed_wall<0.5")
endforeach()
# The tank at rest (cases/hydrostatic.lua as shipped: 1 m of water, dr = H/20), 2 s (211 steps):
# largest speed 0.0340 √(gH) in double, 0.0334 in float (0.11 m/s), bottom_error_avg 0.0086 and
# 0.0083, no particle behind a wall. Bounds 1.5 times the speed, and 1.5% on the floor.
clsph_run_test(run_stab_hydrostatic_rest ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               SETS stab=1 dr=0.05 t_end=2
               BOUNDS "speed_ratio<0.051" "bottom_error_avg<0.015" "crossed_wall<0.5")
# Shaped floors (cases/hydrostatic_shapes.lua, S sec 4.1 fig 4 in 2-D) at the paper's dr = 0.005
# m, 1 s, errors against ρ g (H − y) relative to ρ g H, averaged over the last 0.5 s. The lattice
# cut by an arc leaves holes between the fluid and the dummies; with surface_detection = "scan"
# (the case's default) they stay interior rows (with the density test alone the bump's fluid was
# 34% off, RMS). The semicircular bump (its arc cut into edges of about dr) under the modified
# virtual marker (426 steps in double, 441 in float; 11 s and 8 s, shared cores): RMS over the
# fluid 0.056 (double), 0.053 (float), the fluid within 3 dr of the floor +0.096 and +0.091
# (concave corners +0.125 and +0.125, the arc +0.077 and +0.069), speed 0.050 and 0.051 √(gH), no
# particle behind a wall. High, and it is the walls'
# approach term (ppe.cl): it turns the jostle into pressure (with it counted only within 0.4 dr
# of a wall the floor read −0.004, but the n = 40 dam break blew up after its impact). Bounds:
# 1.5 times the RMS and the speed, the floor's bias under +0.15, no crossing.
clsph_run_test(run_stab_shapes_bump ${CMAKE_SOURCE_DIR}/cases/hydrostatic_shapes.lua
               SETS shape=1
               BOUNDS "fluid_error_avg<0.085" "wall_bias_avg>0" "wall_bias_avg<0.15"
                      "speed_ratio<0.09" "crossed_wall<0.5")
# The same with the pseudo-Neumann walls (367 steps): low, as S finds: the floor −0.055 (both
# precisions), concave corners −0.064, the arc −0.049, RMS 0.030, no particle behind a wall (with
# the arc in edges of dr/2, particles behind it at 6 steps, never 0.5 dr deep). Bounds: the paper's sign by at least
# 3.5%, 1.5 times the measured bias below, 1.5 times the RMS.
clsph_run_test(run_stab_shapes_bump_pseudo ${CMAKE_SOURCE_DIR}/cases/hydrostatic_shapes.lua
               SETS shape=1 neumann=0
               BOUNDS "wall_bias_avg<-0.035" "wall_bias_avg>-0.081" "fluid_error_avg<0.045")
# The pyramid (a convex 90° apex, 45° flanks on the lattice's diagonals) beside the pit (convex
# rim, concave bottom corners), modified virtual marker (330 steps; 10 s, 3 s in float): RMS 0.0047
# and 0.0048, the floor's largest error 0.0099 and 0.0101, its bias +0.0075 and +0.0076 (concave
# +0.0082, convex +0.0073), speed 0.051 and 0.036, no particle behind a wall (the check takes the
# nearest of the dummies' wall points within 2 dr; the nearest dummy's read the pit's fluid as
# behind the floor, and this run stopped at its second step). Bounds: 1.5 times measured.
clsph_run_test(run_stab_shapes_pit ${CMAKE_SOURCE_DIR}/cases/hydrostatic_shapes.lua
               SETS shape=2
               BOUNDS "fluid_error_avg<0.0075" "wall_error_avg<0.016" "speed_ratio<0.077"
                      "crossed_wall<0.5")
# Pseudo-Neumann on the pyramid and pit: the floor −0.050 (both), concave −0.057, convex −0.046,
# RMS 0.025 and 0.024, no crossing. Bounds as the bump's.
clsph_run_test(run_stab_shapes_pit_pseudo ${CMAKE_SOURCE_DIR}/cases/hydrostatic_shapes.lua
               SETS shape=2 neumann=0
               BOUNDS "wall_bias_avg<-0.035" "wall_bias_avg>-0.075" "fluid_error_avg<0.037"
                      "crossed_wall<0.5")
# pressure_form = "dynamic": the pressure equation solved for P = p − ρ0 g·x (project.cl), so that
# the hydrostatic part is exact and never meets the free surface's truncated supports. The paper's
# tank, 1 s (230 steps, 2.3 BiCGStab iterations a step in double, 1.0 in float): bottom_error_avg
# 2.1e-4 and 2.6e-4, bias +2.1e-4 and +1.9e-4, speed 3.2e-4 and 3.9e-4 √(gH) (the total form:
# 0.0075 and 0.045); at δr = 0.005 over 2 s 2.9e-4, speed 0.0015 (the total form: 0.94 from a deep
# particle read as free surface at 1.4 s). Bounds: 3 times measured, an order of magnitude under
# the total form's.
clsph_run_test(run_stab_hydrostatic_dynamic ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               SETS stab=1 depth=0.2 width=0.2 dr=0.01 t_end=1 dyn=1
               BOUNDS "bottom_error_avg<0.001" "bottom_bias_avg>-0.001" "speed_ratio<0.0015"
                      "crossed_wall<0.5")
# The shaped floors with it, 1 s (330 steps): the bump's RMS 5.9e-4 (float 5.9e-4), floor bias
# +5.8e-4 (+5.5e-4), concave corners +5.8e-4, speed 0.0036 (0.0040); the pyramid and pit's RMS
# 1.4e-4 (1.1e-4), speed 4.9e-4 (0.0012); no crossing (the total form: the bump +7.4% at its floor,
# the pit 0.0047 RMS). Bounds: 3 times measured.
clsph_run_test(run_stab_shapes_bump_dynamic ${CMAKE_SOURCE_DIR}/cases/hydrostatic_shapes.lua
               SETS shape=1 dyn=1
               BOUNDS "fluid_error_avg<0.0018" "wall_error_avg<0.0026" "speed_ratio<0.012"
                      "crossed_wall<0.5")
clsph_run_test(run_stab_shapes_pit_dynamic ${CMAKE_SOURCE_DIR}/cases/hydrostatic_shapes.lua
               SETS shape=2 dyn=1
               BOUNDS "fluid_error_avg<0.0005" "wall_error_avg<0.0006" "speed_ratio<0.0036"
                      "crossed_wall<0.5")
# With the pseudo-Neumann walls the dynamic form is refused (the tank ran off under it).
clsph_cli_test(stab_dynamic_pseudo ARGS info ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua --set stab=1
               --set dyn=1 --set neumann=0 RC 2
               REGEX "hydrostatic.lua:[0-9]+: isph-stabilized option pressure_form = \"dynamic\" needs wall_pressure = \"neumann\"")
clsph_cli_test(stab_dynamic_periodic ARGS info ${bad_stab} --set what=14 RC 2
               REGEX "bad_stab.lua:20: isph-stabilized option pressure_form = \"dynamic\" cannot run with gravity or a body force along the periodic x axis")
# the cases' dyn parameter is isph-stabilized's: with another scheme it is refused, not ignored
clsph_cli_test(case_dyn_without_stab ARGS info ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               --set dyn=1 RC 2 REGEX "hydrostatic: dyn = 1 needs stab = 1")
clsph_cli_test(case_dyn_without_stab_dam_break ARGS info ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               --set dyn=1 --set riemann=1 RC 2 REGEX "dam_break: dyn = 1 needs stab = 1")
clsph_cli_test(case_dyn_without_stab_shapes ARGS info ${CMAKE_SOURCE_DIR}/cases/hydrostatic_shapes.lua
               --set dyn=1 --set stab=0 RC 2 REGEX "hydrostatic_shapes: dyn = 1 needs stab = 1")
clsph_cli_test(stab_bad_shifting ARGS info ${bad_stab} --set what=15 RC 2
               REGEX "bad_stab.lua:20: isph-stabilized option shifting = 3 is out of range: the particle shifting coefficient C must be from 0 to 2")
clsph_cli_test(stab_bad_approach ARGS info ${bad_stab} --set what=16 RC 2
               REGEX "bad_stab.lua:20: isph-stabilized option wall_approach must be one of \"particles\", \"impact\", not \"x\"")
clsph_cli_test(case_shift_without_stab ARGS info ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               --set shift=0.5 RC 2 REGEX "dam_break: shift needs stab = 1")
clsph_cli_test(case_shift_negative ARGS info ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               --set stab=1 --set shift=-1 RC 2
               REGEX "hydrostatic: shift must be 0 \\(off\\) or a shifting coefficient C > 0, not -1")
clsph_cli_test(stab_bad_pressure_form ARGS info ${bad_stab} --set what=13 RC 2
               REGEX "bad_stab.lua:[0-9]+: isph-stabilized option pressure_form must be one of \"total\", \"dynamic\", not \"split\"")
# The Lobovsky dam break (cases/dam_break.lua), n = 20, to t = 0.42 s (253 steps, 9.1 BiCGStab
# iterations a step in double, 5.6 in float; about 10 s): the front at 0.672 of Ritter's mean speed
# (both precisions), nothing on the floor faster than 0.934 of Ritter's front, the volume kept, no
# particle behind a wall. Bounds: Ritter's ideal above, 0.6 below (10% under the measured), and
# the wall check. The time step follows the fluid's acceleration and the walls push back an
# approaching fluid (isph_stabilized.c stab_max_dt, ppe.cl): without them the impact at n = 40 put
# particles through the floor next to the downstream wall within 0.03 s.
clsph_run_test(run_dam_break_stab ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS stab=1 n=20 t_end=0.42 every=0.002
               BOUNDS "floor_speed_max<1" "front_over_ritter>0.6" "front_over_ritter<1"
                      "volume_ratio>0.999" "crossed_wall<0.5")
# The same with pressure_form = "dynamic", to t = 0.40 s (234 and 235 steps, 8.5 iterations a step
# in double, 4.8 in float): the front at 0.601 and 0.602 of Ritter's mean speed, the floor's
# fastest 0.878 and 0.872 of his front, no crossing. Same bounds. It stops short of the others'
# 0.42 s: in float, with the multigrid's level 1 summed from A P (other rounding), surface
# particles pair at 0.408 s (the clustering check), the dynamic form's known failure (README).
clsph_run_test(run_dam_break_stab_dynamic ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS stab=1 n=20 t_end=0.40 every=0.002 dyn=1
               BOUNDS "floor_speed_max<1" "front_over_ritter>0.58" "front_over_ritter<1"
                      "volume_ratio>0.999" "crossed_wall<0.5")
# n = 40 to t = 0.72 s, sensor 1 against the experiment (1019 steps, 10.7 BiCGStab iterations a
# step in double, 1041 and 6.4 in float; about 80 s and 63 s on shared cores): the impact 0.54%
# and 0.50% before the experiment's; the peak 2.70 and 3.65 times its (one sample); the mean over
# the 0.1 after the impact 0.39 and −0.09 of the experiment's (the ISPH impact is a sharp peak and a trough,
# where the weakly-compressible scheme rings; its test holds 0.75); the plateau over t* 3-4 1.22
# and 1.08 (1.06 and 1.16, then 1.20 and 1.18, before the last rounding changes: the flow after
# the impact is chaotic);
# no particle behind a wall. The same run to t = 1.1 s clusters at 1.04 s
# (tests/validation/RESULTS_isph_stabilized.md). Bounds: the impact time
# within 2.5% of the measured, the peak as the riemann test's, the plateau within 30%. In float
# this run once ran Δt down to a pressure of −9e9 Pa at t = 0.71 s (the acceleration bound chasing
# the α/Δt² term), which the bound's floor stopped. The mean after the impact is noise: with the
# solve's row sums split in four (other rounding) it is −0.09 in float (0.39 in double), and the
# time step scaled by 0.99 and 1.01 gives 0.10 and 1.13 in float, 0.31 and 0.86 in double (the
# build before: 0.17 to 0.30 in float); at 0.98 both builds' float runs stop before 0.72 s (a
# particle escaped; particles clustered at 0.705 s). Its bounds only catch a lasting tension
# (below −0.3) or an impulse far above the experiment's.
clsph_run_test(run_dam_break_sensor_stab ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS stab=1 n=40 t_end=0.72
               BOUNDS "impact_time_error>-0.03" "impact_time_error<0.02" "peak_ratio>0.5"
                      "peak_ratio<11" "impact_mean_ratio>-0.3" "impact_mean_ratio<1.33"
                      "plateau_ratio>0.8" "plateau_ratio<1.3" "crossed_wall<0.5")
# With the gate (gate = 1: 0.5 m tall, lifted 0.4 m at 4.53 m/s from t = 0, S sec 4.2), n = 20 to
# t = 0.42 s (299 steps, 9.0 BiCGStab iterations a step in double, 5.5 in float): the gate stops
# exactly at its lift (the host integrates it over each step), it holds the water back (the front
# at t* = 1 is 0.803 H past L against 0.834 without it; 0.621 of Ritter's mean speed against 0.672),
# nothing on the floor faster than 0.895 of Ritter's front, no particle behind a wall. Bounds: the
# lift to 1e-4 m (float positions), the front at t* = 1 under the gateless 0.834 less a third of
# the difference, and the gateless test's others.
clsph_run_test(run_dam_break_stab_gate ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS stab=1 gate=1 n=20 t_end=0.42 every=0.002
               BOUNDS "gate_lift>0.3999" "gate_lift<0.4001" "front_x_star_t1<0.824"
                      "front_x_star_t1>0.7" "floor_speed_max<1" "volume_ratio>0.999"
                      "crossed_wall<0.5")
# Particle shifting (shifting = C, off by default: the paper's scheme has none; shift.cl), C = 0.5:
# the same gateless n = 20 run (245 steps): the front at 0.663 of Ritter's mean speed in both
# precisions, the floor's fastest 0.938 and 0.939 of his front, no crossing; the gateless test's
# bounds. Measured at n = 40 to t = 1.1 s (t* = 6.3, the slow test below): without shifting the
# fluid clusters at t = 1.04 s; with it the run goes through.
clsph_run_test(run_dam_break_stab_shift ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS stab=1 n=20 t_end=0.42 every=0.002 shift=0.5
               BOUNDS "floor_speed_max<1" "front_over_ritter>0.6" "front_over_ritter<1"
                      "volume_ratio>0.999" "crossed_wall<0.5")
# The paper's tank with it, 1 s: bottom_error_avg 0.0089 (float 0.0093), bias +0.0063 (+0.0068),
# speed 0.034 (0.048) of √(gH) (without: 0.0081, +0.0075, 0.029): the shift leaves the tank as it
# was; the neumann tank's bounds but the speed's, 0.06: in float the jostle follows the pressure
# solve's rounding (0.038 before the multigrid's level 1 was summed from A P, 0.048 with it and
# with UMFPACK's exact solve).
clsph_run_test(run_stab_hydrostatic_shift ${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               SETS stab=1 depth=0.2 width=0.2 dr=0.01 t_end=1 shift=0.5
               BOUNDS "bottom_error_avg<0.015" "bottom_bias_avg>-0.015" "bottom_bias_avg<0.015"
                      "speed_ratio<0.06" "crossed_wall<0.5")
# n = 40 to t* = 6.3 with C = 0.5 (double, 1518 steps, 10.7 BiCGStab iterations a step, 72 s
# alone): impact 0.5% early, sensor 1's peak 1.94 times the experiment's, plateau 1.22, no
# particle behind a wall (the shift is never toward a wall within dr: without that guard, 89
# steps of shallow crossings).
# Slow: the run is chaotic after the impact (C = 1 sent spray over the tank's 1 m top at 0.63 s).
clsph_run_test(run_dam_break_stab_shift_n40 ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS stab=1 n=40 t_end=1.1 shift=0.5 LABELS slow
               BOUNDS "time_star>6.28" "impact_time_error>-0.02" "impact_time_error<0.02"
                      "crossed_wall<0.5" "volume_ratio>0.999")
# A run stopped while the gate lifts resumes bit for bit: the gate's last velocity travels in the
# checkpoint (the scheme's host state), its dummies' positions and velocities among the fields.
clsph_add_test(restart_stab_gate LABELS case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/restart_stab_gate
               "-DSETS=stab=1|gate=1|n=10|t_end=0.1|checkpoint=0.05" -P ${CASE_DIR}/restart.cmake)
# n = 40 with the gate to t = 0.72 s (1135 steps in double, 1125 in float; 167 s and 98 s on the 2
# shared cores): the impact at t* = 2.529 and 2.534, 3.5% and 3.7% after the experiment's (whose
# time origin is the gate's release; without the gate the impact is 0.5% early), the peak 2.6 and
# 4.9 times the experiment's, the mean over 0.1 after it 0.66 and 0.67 of it, the plateau 1.24 and
# 1.22. Slow (the CI budget); bounds: the impact within 2.5% of the measured, the others as above.
clsph_run_test(run_dam_break_sensor_stab_gate ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS stab=1 gate=1 n=40 t_end=0.72
               BOUNDS "impact_time_error>0.01" "impact_time_error<0.06" "peak_ratio>0.5"
                      "peak_ratio<11" "impact_mean_ratio>0.15" "impact_mean_ratio<1.33"
                      "plateau_ratio>0.8" "plateau_ratio<1.5" "gate_lift>0.3999"
                      "crossed_wall<0.5" LABELS slow)

# ---- 3-D scenes (issue 23): a domain with z, box fills in box containers, isph-stabilized ----
set(bad_3d ${CASE_DIR}/bad_3d.lua)
# The tank of bad_3d.lua: 1 m box, dr = 0.1: 10³ fluid particles below z = 0.5, and the dummies of
# the lattice outside the box within 3 layers (16³ − 10³ = 3096, the edges and corners in full).
clsph_cli_test(three_d_info ARGS info ${bad_3d} RC 0
               REGEX "particles: 3596 \\(fluid 500, wall vertices 0, dummy 3096,"
               REGEX2 "dimensions: 3")
clsph_cli_test(three_d_usaw ARGS info ${bad_3d} --set what=1 RC 2
               REGEX "bad_3d.lua:21: scheme isph-usaw runs 2-D scenes only \\(its semi-analytical walls are 2-D")
clsph_cli_test(three_d_wcsph_usaw ARGS info ${bad_3d} --set what=2 RC 2
               REGEX "bad_3d.lua:21: scheme wcsph-usaw runs 2-D scenes only \\(its semi-analytical walls are 2-D")
clsph_cli_test(three_d_polyline ARGS info ${bad_3d} --set what=3 RC 2
               REGEX "bad_3d.lua:28: wall \\(group 'walls'\\) is a 2-D polyline")
clsph_cli_test(three_d_probe ARGS info ${bad_3d} --set what=4 RC 2
               REGEX "bad_3d.lua:29: probe: its point .* must be a point \\{x, y, z\\} in a 3-D scene")
clsph_cli_test(three_d_disc ARGS info ${bad_3d} --set what=12 RC 2
               REGEX "bad_3d.lua:30: probe 'sensor': a disc is its centre, radius = R and normal")
# an obstacle across the tank 2 dr thick: its two faces' markers need 3.8 dr (its floor and side
# faces lie on the tank's and face no fluid)
clsph_cli_test(three_d_thin ARGS info ${bad_3d} --set what=13 RC 2
               REGEX "bad_3d.lua:32: wall \\(group 'plate'\\) is too thin for the virtual markers: behind \\(0.4, 0.05, 0.05\\)")
clsph_cli_test(three_d_vector_first ARGS info ${bad_3d} --set what=5 RC 2
               REGEX "bad_3d.lua:12: fluid: gravity has 3 components: a 3-D scene declares its domain")
clsph_cli_test(three_d_fill_past ARGS info ${bad_3d} --set what=6 RC 2
               REGEX "bad_3d.lua:34: fluid region 'water' extends past the walls: the particle at \\(0.05, 1.05, 0.05\\)")
clsph_cli_test(three_d_domain ARGS info ${bad_3d} --set what=7 RC 2
               REGEX "bad_3d.lua:14: domain: give the box as .* not 5 numbers")
clsph_cli_test(three_d_empty_fill ARGS info ${bad_3d} --set what=8 RC 2
               REGEX "bad_3d.lua:36: fill 'water': the box is empty along z")
clsph_cli_test(three_d_rectangle ARGS info ${bad_3d} --set what=9 RC 2
               REGEX "bad_3d.lua:38: fill 'water': a 3-D scene fills a box")
clsph_cli_test(three_d_tank_past ARGS info ${bad_3d} --set what=10 RC 2
               REGEX "bad_3d.lua:24: box_wall \\(group 'tank'\\) reaches past the domain along z")
clsph_cli_test(three_d_velocity ARGS info ${bad_3d} --set what=11 RC 2
               REGEX "bad_3d.lua:40: fill 'water': velocity must be \\{u, v, w\\}")
clsph_cli_test(three_d_force ARGS info ${bad_3d} --set what=14 RC 2
               REGEX "bad_3d.lua: force \\{ \"tank\" \\}: wall forces are 2-D only for now")
clsph_cli_test(three_d_rot_implicit ARGS info ${bad_3d} --set what=15 RC 2
               REGEX "bad_3d.lua:21: isph-rotational option viscous = \"implicit\" is 2-D only for now")
clsph_cli_test(three_d_domain_nan ARGS info ${bad_3d} --set what=16 RC 2
               REGEX "bad_3d.lua:16: domain: z1 must be finite")
# Frames of a 3-D run: lit spheres seen by a camera (render/render.c; pixel checks in
# tests/render/test_render.c): the default camera, the command line's, one inside an obstacle
# (refused: it would see nothing), vorticity (2-D only)
clsph_cli_test(three_d_frames ARGS run ${bad_3d} --frames --no-movie --field p --overwrite
               --out ${CMAKE_CURRENT_BINARY_DIR}/runs/three_d_frames
               RC 0 REGEX "frames: .*three_d_frames/frames/p_000000.png .. 000001.png \\(2\\)")
clsph_cli_test(three_d_frames_camera ARGS run ${bad_3d} --frames --no-movie --overwrite
               --camera 0.5,-2,1.5,0.5,0.5,0.25 --fov 40
               --out ${CMAKE_CURRENT_BINARY_DIR}/runs/three_d_frames_camera
               RC 0 REGEX "frames: .*three_d_frames_camera/frames/speed_000000.png .. 000001.png")
clsph_cli_test(three_d_camera_in_wall ARGS run ${bad_3d} --set what=24 --frames
               --camera 0.5,0.5,0.1,0,0,0 --out ${CMAKE_CURRENT_BINARY_DIR}/runs/three_d_cam_wall
               --overwrite RC 2
               REGEX "bad_3d.lua:54: the camera's eye \\(0.5, 0.5, 0.1\\) is inside the wall of group 'block'")
clsph_cli_test(three_d_camera_syntax ARGS run ${bad_3d} --frames --camera 1,2,3
               RC 2 REGEX "--camera: '1,2,3' gives 3 numbers: give 6 \\(eye, look-at\\) or 9")
clsph_cli_test(three_d_camera_blind ARGS run ${bad_3d} --frames --camera 1,1,1,1,1,1
               RC 2 REGEX "--camera: the camera looks at its own eye")
clsph_cli_test(three_d_frames_vorticity ARGS run ${bad_3d} --frames --field vorticity
               --out ${CMAKE_CURRENT_BINARY_DIR}/runs/three_d_vort --overwrite
               RC 2 REGEX "--field vorticity is 2-D")
# The tank in 3-D (cases/hydrostatic3d.lua: 0.2 m of water in a 0.2 m box, dr = H/10, gravity
# along −z, from ρ g (H − z)), 1 s (164 steps). Total pressure (the paper's form): the largest
# error deeper than 3 dr 0.053 (double) and 0.085 (float), RMS 0.015 and 0.029, the floor's
# bottom_error_avg 0.0245 and 0.0276, speed 0.082 and 0.079 √(gH), no particle behind a wall
# (4 s at H/10: RMS 0.023, largest 0.09; 2 s at H/20: RMS 0.0059, largest 0.046). Bounds 1.5
# times the float's.
clsph_run_test(run_stab3d_hydrostatic ${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua SETS t_end=1
               BOUNDS "pressure_error<0.13" "pressure_rms<0.044" "bottom_error_avg<0.042"
                      "speed_ratio<0.12" "crossed_wall<0.5")
# pressure_form = "dynamic" (the hydrostatic part exact): largest error 0.0016 (double) and 0.0025
# (float), RMS 0.0010 and 0.0012, the floor 4.2e-4 and 5.2e-4, speed 1.0e-4 and 1.4e-4 √(gH), 3.2
# and 1.0 BiCGStab iterations a step (2 s at H/20: 0.0033, RMS 0.0014). Bounds: the issue's 1% on
# the pressure below 3 δr, 3 times measured on the floor and the speed.
clsph_run_test(run_stab3d_hydrostatic_dynamic ${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua
               SETS t_end=1 dyn=1
               BOUNDS "pressure_error<0.01" "bottom_error_avg<0.0016" "speed_ratio<5e-4"
                      "crossed_wall<0.5")
# A 3-D run resumes bit for bit from its checkpoint (real4 positions, the 3 components of the
# scheme's host state).
clsph_add_test(restart_stab3d LABELS case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/restart_stab3d
               "-DSETS=t_end=0.1|checkpoint=0.05" -P ${CASE_DIR}/restart.cmake)
# clsph render of a 3-D run: without --slice it names the file and the option; with a slice
# through the tank's middle (y = 0.55 m: the lattice layer there) it draws a frame per snapshot,
# with the tank's four faces that the plane cuts as walls (two triangles each: 8 segments);
# a plane off every particle is refused
clsph_cli_test(three_d_render FRESH_DIR ${CMAKE_CURRENT_BINARY_DIR}/runs/three_d_render RC 0
               FIRST_ARGS run ${bad_3d} --quiet --out ${CMAKE_CURRENT_BINARY_DIR}/runs/three_d_render
               ARGS render ${CMAKE_CURRENT_BINARY_DIR}/runs/three_d_render --no-movie --field p
               REGEX "frames: .*three_d_render/frames/p_000000.png .. 000001.png \\(2\\)")
clsph_cli_test(three_d_render_slice FRESH_DIR ${CMAKE_CURRENT_BINARY_DIR}/runs/three_d_slice RC 0
               FIRST_ARGS run ${bad_3d} --quiet --out ${CMAKE_CURRENT_BINARY_DIR}/runs/three_d_slice
               ARGS render ${CMAKE_CURRENT_BINARY_DIR}/runs/three_d_slice --slice y=0.55 --no-movie
                    --field kind
               REGEX "frames: .*three_d_slice/frames/kind_000000.png .. 000001.png \\(2\\)"
               REGEX2 "--slice y=0.55 cuts the walls' faces in 8 segments")
clsph_cli_test(three_d_render_off FRESH_DIR ${CMAKE_CURRENT_BINARY_DIR}/runs/three_d_off RC 2
               FIRST_ARGS run ${bad_3d} --quiet --out ${CMAKE_CURRENT_BINARY_DIR}/runs/three_d_off
               ARGS render ${CMAKE_CURRENT_BINARY_DIR}/runs/three_d_off --slice z=5 --no-movie
               REGEX "--slice z=5: no particle of .*snap_000000.h5 lies within half a spacing of the plane")
clsph_cli_test(three_d_slice_syntax ARGS render /tmp --slice w=1 RC 2
               REGEX "--slice: 'w=1' is not AXIS=VALUE with AXIS x, y or z")
clsph_cli_test(three_d_slice_nan ARGS render /tmp --slice y=nan RC 2
               REGEX "--slice: 'y=nan': the plane's position 'nan' is not a number")
clsph_cli_test(three_d_slice_run ARGS run ${bad_3d} --slice y=0.5 RC 2
               REGEX "--slice belongs to `clsph render OUTDIR`")
# An obstacle: the tank twice as wide (0.4 m) with a block 6 dr wide and tall on the middle of its
# floor (box_wall { ..., fluid = "outside" }: its top and sides face the water, its bottom lies on
# the floor), pressure_form = "dynamic", 1 s: largest error 0.0017 (double and float), the floor
# and the block's top 4.6e-4 and 5.5e-4, speed 1.2e-4 and 1.3e-4 √(gH), no particle behind a wall
# or in the block. (The total form moves the water at 0.09 √(gH) and 81 of its 164 steps put a
# particle up to 0.42 dr behind a wall: not bounded here.) Bounds as the tank's.
clsph_run_test(run_stab3d_block_dynamic ${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua
               SETS t_end=1 dyn=1 block=1 width=0.4
               BOUNDS "pressure_error<0.01" "bottom_error_avg<0.0017" "speed_ratio<5e-4"
                      "crossed_wall<0.5")
# The dam break in 3-D (cases/dam_break.lua dim=3: the column 0.15 m wide in the tank, the lid at
# 0.6 m; n = 20, 48,368 particles), to t* = 0.57 (38 steps): the front at 0.699 m in double and
# float, its mean speed 0.290 of Ritter's (the 2-D run, n = 20: 0.689 m, 0.261), the fastest on the
# floor 0.585 of Ritter's front (2-D 0.557), no particle lost or behind a wall. Bounds ±0.05 on
# the front's speed around the 3-D and 2-D runs.
clsph_run_test(run_dam_break_stab3d ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS stab=1 dim=3 n=20 top=0.6 t_end=0.1
               BOUNDS "front_over_ritter>0.21" "front_over_ritter<0.34" "floor_speed_max<1"
                      "volume_ratio>0.999" "crossed_wall<0.5")
# Spheres and cylinders (sphere_wall, cylinder_wall, fill { sphere = ... }, fill { cylinder = ... }):
# the round tank (cases/hydrostatic3d.lua round = 1: a vertical cylinder 0.2 m across, the water a
# cylinder fill, dr = H/10) holds π 5² 10 ≈ 785 lattice points, 800 of them, and the dummies of its
# rounded shell; a sphere 0.1 m across at mid-depth in the 0.4 m tank and a pillar 0.16 m across
# from the floor to the lid (its caps on the tank's faces, facing no water) take the lattice points
# inside them from the tank's 4000: 56 (the sphere's volume is 65 dr³) and 52 a layer (π 4² = 50).
clsph_cli_test(three_d_round_tank ARGS info ${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua --set round=1
               RC 0 REGEX "particles: 3776 \\(fluid 800, wall vertices 0, dummy 2976,")
clsph_cli_test(three_d_sphere ARGS info ${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua --set sphere=1
               --set width=0.4 RC 0 REGEX "particles: 12196 \\(fluid 3944, wall vertices 0, dummy 8252,")
clsph_cli_test(three_d_pillar ARGS info ${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua --set pillar=1
               --set width=0.4 RC 0 REGEX "particles: 12396 \\(fluid 3480, wall vertices 0, dummy 8916,")
clsph_cli_test(three_d_sphere_radius ARGS info ${bad_3d} --set what=17 RC 2
               REGEX "bad_3d.lua:48: sphere_wall: the radius R must be positive")
clsph_cli_test(three_d_cylinder_axis ARGS info ${bad_3d} --set what=18 RC 2
               REGEX "bad_3d.lua:49: cylinder_wall: the cylinder's axis has no length")
clsph_cli_test(three_d_fill_two ARGS info ${bad_3d} --set what=19 RC 2
               REGEX "bad_3d.lua:50: fill 'ball': a box's numbers and a sphere: give one solid")
clsph_cli_test(three_d_sphere_past ARGS info ${bad_3d} --set what=20 RC 2
               REGEX "bad_3d.lua:51: sphere_wall \\(group 'ball'\\) reaches past the domain along z: \\[0.6, 1.2\\]")
clsph_cli_test(three_d_cylinder_thin ARGS info ${bad_3d} --set what=21 RC 2
               REGEX "bad_3d.lua:52: wall \\(group 'pole'\\) is too thin for the virtual markers")
clsph_cli_test(three_d_sphere_2d ARGS info ${bad_3d} --set what=22 RC 2
               REGEX "bad_3d.lua:12: sphere_wall is 3-D: declare the domain")
# The round tank at rest with isph-stabilized (pressure_form = "dynamic", 1 s, 164 steps): largest
# error deeper than 3 dr 0.0016 (double and float), the floor 4.2e-4, speed 1.0e-4 and 1.3e-4
# √(gH), no particle behind the curved wall or out of the tank: as the box tank's; the same bounds.
clsph_run_test(run_stab3d_round_tank ${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua
               SETS t_end=1 dyn=1 round=1
               BOUNDS "pressure_error<0.01" "bottom_error_avg<0.0016" "speed_ratio<5e-4"
                      "crossed_wall<0.5")
# The sphere (0.1 m across, its centre at mid-depth, in the 0.4 m tank) and the pillar (0.16 m
# across, floor to lid) as obstacles, the same run: largest error 0.0017 and 0.0017 (double), 0.0018
# and 0.0017 (float), the floor 4.5e-4 and 4.4e-4 (5.6e-4 and 4.9e-4), speed 1.4e-4 and 1.0e-4
# (1.4e-4, 1.8e-4) √(gH), no particle behind a wall nor inside the solid: the box tank's figures
# and bounds. (With the dr/2 shell around the sphere left empty, as around a box obstacle, the
# water next to it ran into it at 0.5 m/s: geometry3.c.)
clsph_run_test(run_stab3d_sphere ${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua
               SETS t_end=1 dyn=1 sphere=1 width=0.4
               BOUNDS "pressure_error<0.01" "bottom_error_avg<0.0017" "speed_ratio<5e-4"
                      "crossed_wall<0.5")
clsph_run_test(run_stab3d_pillar ${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua
               SETS t_end=1 dyn=1 pillar=1 width=0.4
               BOUNDS "pressure_error<0.01" "bottom_error_avg<0.0017" "speed_ratio<5e-4"
                      "crossed_wall<0.5")
# The sphere with wcsph-riemann (c0 = 10 √(2 g H)), 0.5 s (156 steps): pressure RMS 0.037 and
# speed 0.19 √(gH) in double and float with the surface rows' pair push of 3-D (surface_transport
# = "pairs"; without it 0.026 and 0.145), as the box tank's jostle; no particle inside the sphere
# (at 1 s the deepest is 0.02 dr past its face in double, 0.011 in float: wcsph-riemann checks no
# crossing itself, its dummies extrapolate the state pair by pair). Bounds: 1.5 times measured, and
# nothing a quarter spacing inside.
clsph_run_test(run_riemann3d_sphere ${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua
               SETS t_end=0.5 riemann=1 sphere=1 width=0.4
               BOUNDS "pressure_rms<0.056" "speed_ratio<0.28" "inside_depth<0.25")
# STL walls (stl_wall: ADMesh reads the file, host/scene/mesh.c checks and places it). The tank of
# tests/case/bad_stl.lua is the unit cube of cases/stl/cube.stl, the block 0.4 m across on its floor
# the same cube scaled and placed (its bottom facets lie on the floor: they face no water), dr =
# 0.05: 20 x 20 x 10 lattice points of water less the block's 8 x 8 x 8, 3488; the tank's dummies
# lie within 3 dr of it in the Euclidean distance (a box_wall's mitred layers hold 320 more). Its
# 11 steps to t = 0.1 s put no particle behind a wall.
set(bad_stl ${CASE_DIR}/bad_stl.lua)
clsph_cli_test(stl_tank_info ARGS info ${bad_stl} RC 0
               REGEX "particles: 13236 \\(fluid 3488, wall vertices 0, dummy 9748,")
clsph_cli_test(stl_tank_run RC 0
               ARGS run ${bad_stl} --out ${CMAKE_CURRENT_BINARY_DIR}/runs/stl_tank --overwrite
               REGEX "done: t = 0.1 s in 11 steps")
clsph_cli_test(stl_open ARGS info ${bad_stl} --set what=1 RC 2
               REGEX "bad_stl.lua:15: stl_wall: .*stl/open.stl is not closed: 3 of its 11 facets have an edge that no other facet shares")
clsph_cli_test(stl_inverted ARGS info ${bad_stl} --set what=2 RC 2
               REGEX "bad_stl.lua:15: stl_wall: .*stl/inverted.stl: its normals point inward")
clsph_cli_test(stl_flipped ARGS info ${bad_stl} --set what=3 RC 2
               REGEX "bad_stl.lua:15: stl_wall: .*stl/flipped.stl: its facets are not consistently oriented: 1 of 12")
clsph_cli_test(stl_junk ARGS info ${bad_stl} --set what=4 RC 2
               REGEX "bad_stl.lua:15: stl_wall: .*stl/junk.stl is not an STL file that holds facets")
clsph_cli_test(stl_missing ARGS info ${bad_stl} --set what=5 RC 2
               REGEX "bad_stl.lua:15: stl_wall: cannot open .*stl/none.stl: No such file")
clsph_cli_test(stl_2d ARGS info ${bad_stl} --set what=6 RC 2
               REGEX "bad_stl.lua:7: stl_wall is 3-D: declare the domain")
clsph_cli_test(stl_scale ARGS info ${bad_stl} --set what=7 RC 2
               REGEX "bad_stl.lua:16: stl_wall: scale must be positive")
clsph_cli_test(stl_no_file ARGS info ${bad_stl} --set what=8 RC 2
               REGEX "bad_stl.lua:17: stl_wall: give the file as its first entry")
clsph_cli_test(stl_nan ARGS info ${bad_stl} --set what=10 RC 2
               REGEX "bad_stl.lua:15: stl_wall: .*stl/nan.stl is not closed: 3 of its 12 facets")
clsph_cli_test(stl_past ARGS info ${bad_stl} --set what=9 RC 2
               REGEX "bad_stl.lua:18: stl_wall \\(group 'walls'\\) reaches past the domain along x: \\[0.5, 1.5\\]")
# The sphere of cases/hydrostatic3d.lua as a triangulated surface (stl = 1: cases/stl/sphere.stl,
# 1280 facets, scaled to 0.05 m): the same 3944 fluid and 8252 dummy particles as sphere_wall's,
# and at rest (pressure_form = "dynamic", 1 s) the same figures: largest error 0.0017, the floor
# 4.5e-4, speed 1.4e-4 √(gH); bounds as the sphere's.
clsph_run_test(run_stab3d_stl_sphere ${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua
               SETS t_end=1 dyn=1 sphere=1 stl=1 width=0.4
               BOUNDS "pressure_error<0.01" "bottom_error_avg<0.0017" "speed_ratio<5e-4"
                      "crossed_wall<0.5")
# wcsph-riemann in 3-D: the tank of cases/hydrostatic3d.lua (dr = H/10, 1 s, 308 steps, c0 =
# 10 √(2 g H)): the largest error deeper than 3 dr 0.145 (double) and 0.158 (float), RMS 0.036
# and 0.034, the floor's bottom_error_avg 0.031 and 0.034, the surface rows jostling at 0.092 and
# 0.10 √(gH) with 3-D's pair push in the surface rows (surface_transport = "pairs"; without it
# 0.1225, RMS 0.054, floor 0.036, speed 0.16) (the largest errors are the shallowest rows', under
# the surface that takes no tension, acoustic.cl); no particle behind a wall. (H/20 without the
# push: largest 0.125, RMS 0.020, speed 0.11; the 2-D tank at H/10 and the same 0.2 m clusters at
# t = 0.84 s.) Bounds 1.5 times the larger.
clsph_run_test(run_riemann3d_hydrostatic ${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua
               SETS riemann=1 t_end=1
               BOUNDS "pressure_error<0.24" "pressure_rms<0.054" "bottom_error_avg<0.051"
                      "speed_ratio<0.152" "crossed_wall<0.5")
# its checkpoint: a 3-D wcsph-riemann run resumes bit for bit (ρ, dρ/dt, the real4 vectors)
clsph_add_test(restart_riemann3d LABELS case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CMAKE_SOURCE_DIR}/cases/hydrostatic3d.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/restart_riemann3d
               "-DSETS=t_end=0.1|checkpoint=0.05|riemann=1" -P ${CASE_DIR}/restart.cmake)
# a 2-D one with a recorded wall group (cases/square_cylinder.lua, H/20, to t = 1, from t = 0.5):
# the walls' record of the step (force.cl) is a particle field, so that the resumed forces.csv is
# the uninterrupted run's, row for row
clsph_add_test(restart_riemann_forces LABELS case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CMAKE_SOURCE_DIR}/cases/square_cylinder.lua
               -DOUT=${CMAKE_CURRENT_BINARY_DIR}/runs/restart_riemann_forces
               "-DSETS=riemann=1|n=20|re=20|t_end=1|length=16|xc=4|checkpoint=0.5|average_from=0.5"
               -P ${CASE_DIR}/restart.cmake)
# The 3-D dam break with wcsph-riemann (n = 20, 48,368 particles, c0 = 10 · 2 √(gH)) to t* = 0.57
# (50 steps, 332 acoustic sub-steps): the front at 0.687 m in double and float, 0.253 of Ritter's
# speed (0.248 without 3-D's pair push in the surface rows; isph-stabilized 0.290, the 2-D
# wcsph-riemann run 0.25 at n = 20); bounds as isph-stabilized's.
clsph_run_test(run_dam_break_riemann3d ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS riemann=1 dim=3 n=20 top=0.6 t_end=0.1
               BOUNDS "front_over_ritter>0.21" "front_over_ritter<0.34" "floor_speed_max<1"
                      "volume_ratio>0.999" "crossed_wall<0.5")
# The lid-driven cavity in 3-D (cases/cavity.lua dim=3 riemann=1: the box 9 δr deep along z,
# periodic there, its lid the face y = 1 sliding at {U, 0, 0}, Re = 100), n = 20, to t = 5 (310
# steps, 26 s): the rows' mean u at x = 1/2 (every z) against Ghia's 0.035 U RMS in double, where
# the 2-D run reads 0.031 (0.032 in float); the spanwise velocity 0.0013 U RMS (0.02 U at most).
# In float the spanwise noise grows from t = 1.5 (0.11 U at most at t = 4, RMS 0.0043 U at t = 5)
# and the 3-D flow leaves the 2-D one: its rows read 0.010 U, its kinetic energy 2% over the
# double run's. (At n = 30 to t = 10, double: 0.0099 U by the particles' own metric against the 2-D
# run's 0.013, w 0.0033 U RMS; 183 s.) The centreline profiles in the mid-depth plane by linear
# interpolation (profile_error with z): u 0.034 U RMS and v 0.023 U in double, 0.011 and 0.011 in
# float, where the 2-D run reads 0.032 and 0.040 (0.029 and 0.051 in float). Bounds: 0.045 (the
# 2-D run's error and a half) on the rows, 0.05 and 0.06 on the profiles (the same), spanwise
# 0.01 U RMS, no particle behind a wall.
clsph_run_test(run_cavity_riemann3d ${CMAKE_SOURCE_DIR}/cases/cavity.lua
               SETS dim=3 riemann=1 n=20 t_end=5
               BOUNDS "u_rms_rows<0.045" "u_rms_linear<0.05" "v_rms_linear<0.06" "w_rms<0.01"
                      "wall_crossing_steps<0.5")
# Interpolation at points in 3-D (tests/case/sample3d.lua: a tank at rest, dr = 0.1): the linear
# interpolation (first-order moving least squares, a 4x4 system in probe.cl) returns the particles'
# own positions at a point between them and along a profile line in the plane z = 0.25 to
# round-off (1.7e-16 m in double, 1.6e-7 m in float; bound 1e-5 m = 1e-4 dr); the pressure at
# mid-depth by both interpolations within 3 Pa of ρ g (H − z) = 2452.5 Pa after 1 ms (bound 0.5%).
# A point of two coordinates and a profile without z are refused in a 3-D scene.
# The profile line recorded in 3-D (profile { from = {x, y, z}, to = ... }) carries z and its
# 8 points' pressures within 3 Pa of the same.
clsph_run_test(run_sample3d ${CASE_DIR}/sample3d.lua
               BOUNDS "max_err<1e-5" "profile_max<1e-5" "p_shepard_err<12" "p_linear_err<12"
                      "line_p_err<12" "line_points>7.5" "line_points<8.5")
clsph_cli_test(sample3d_two_coordinates ARGS run ${CASE_DIR}/sample3d.lua --set what=1 --quiet
               --overwrite --out ${CMAKE_CURRENT_BINARY_DIR}/runs/sample3d_two_coordinates RC 2
               REGEX "sample3d.lua:25: sim.sample: cannot sample 'p' at \\(0.5, 0.25\\): a point of this 3-D scene has 3 coordinates, not 2")
clsph_cli_test(sample3d_profile_out ARGS info ${CASE_DIR}/sample3d.lua --set what=3 RC 2
               REGEX "sample3d.lua:21: profile 'out' from \\(0.5, 0.5, 0.5\\) to \\(0.5, 0.5, 1.5\\) leaves the domain \\{0, 0, 0, 1, 1, 1\\}")
clsph_cli_test(sample3d_profile_2d ARGS info ${CASE_DIR}/sample3d.lua --set what=4 RC 2
               REGEX "sample3d.lua:22: profile: from must be a vector \\{x, y, z\\}")
foreach(bad "5|32: sim.sample: the point's coordinate 1 is -?nan, not a finite number"
            "6|33: sim.sample: the point must be \\{x, y\\} or \\{x, y, z\\}, not 4 numbers"
            "7|34: sim.sample: the point's coordinate 2 is not a number"
            "8|36: profile_error: the line's z = -?nan is not a finite number")
  string(REPLACE "|" ";" parts "${bad}")
  list(GET parts 0 what)
  list(GET parts 1 message)
  clsph_cli_test(sample3d_bad_${what} ARGS run ${CASE_DIR}/sample3d.lua --set what=${what} --quiet
                 --overwrite --out ${CMAKE_CURRENT_BINARY_DIR}/runs/sample3d_bad_${what} RC 2
                 REGEX "sample3d.lua:${message}")
endforeach()
clsph_cli_test(sample3d_profile_no_z ARGS run ${CASE_DIR}/sample3d.lua --set what=2 --quiet
               --overwrite --out ${CMAKE_CURRENT_BINARY_DIR}/runs/sample3d_profile_no_z RC 2
               REGEX "sample3d.lua:27: profile_error: cannot sample 'pos' at the points of .*sample3d_line.csv: a point of this 3-D scene has 3 coordinates, not 2 \\(give z")
# box_wall's lid in 3-D: it slides along its face and belongs to a container
clsph_cli_test(three_d_lid_across ARGS info ${CMAKE_SOURCE_DIR}/tests/case/bad_3d.lua --set what=23 RC 2
               REGEX "bad_3d.lua:53: box_wall: lid_velocity \\{0.0, 1.0, 0.0\\} crosses the lid face y1: its y component must be 0")
# The gate with wcsph-riemann (solvers/gate, shared with isph-stabilized): the Lobovsky column
# behind a plate lifted 0.4 m at 4.53 m/s; to t = 0.1 s (t* = 0.57, the lift done at 0.088 s) the
# gate is up, the water released (the front 0.254 of Ritter's speed since t = 0 in 2-D, n = 20,
# double and float; 0.253 in 3-D, n = 20, as without the gate), no particle lost or behind a
# wall. Bounds: the lift to 0.1 mm, the front within ±0.05 of measured.
clsph_run_test(run_dam_break_riemann_gate ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS riemann=1 gate=1 n=20 t_end=0.1
               BOUNDS "gate_lift>0.3999" "front_over_ritter>0.18" "front_over_ritter<0.28"
                      "volume_ratio>0.999" "crossed_wall<0.5")
clsph_run_test(run_dam_break_riemann3d_gate ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS riemann=1 gate=1 dim=3 n=20 t_end=0.1
               BOUNDS "gate_lift>0.3999" "front_over_ritter>0.18" "front_over_ritter<0.29"
                      "volume_ratio>0.999" "crossed_wall<0.5")
# Sensor 1 with the gate, wcsph-riemann, 2-D, n = 40 to t = 0.72 s (t* = 4.1): the impact at
# t* = 2.766 and 2.776 (double, float), 13.2% and 13.6% after the experiment's (whose time origin is
# the gate's release: isph-stabilized's gate run is 3.5% late at this resolution, 4% more than
# without its gate; wcsph-riemann without the gate 8.5%), the mean over 0.1 after it 1.08 and 1.11
# of the experiment's, the plateau 1.12 and 1.13, the peak 6.9 and 3.1 times (one particle of the
# tongue), no particle behind a wall. With the no-slip mirror on the gate's dummies the run was 15%
# late and clustered at t = 0.66 s (acoustic.cl, wcr_wall_mirror). Bounds: the impact ±0.025 around
# the two, the rest as the run without the gate.
clsph_run_test(run_dam_break_sensor_riemann_gate ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               SETS riemann=1 gate=1 n=40 t_end=0.72
               BOUNDS "impact_time_error>0.11" "impact_time_error<0.16" "peak_ratio>0.5"
                      "peak_ratio<11" "impact_mean_ratio>0.75" "impact_mean_ratio<1.33"
                      "plateau_ratio>0.8" "plateau_ratio<1.35" "gate_lift>0.3999"
                      "volume_ratio>0.999" "crossed_wall<0.5")
clsph_cli_test(riemann_gate_travel ARGS info ${CMAKE_SOURCE_DIR}/cases/dam_break.lua --set riemann=1
               --set gate=1 --set top=0.6 RC 2
               REGEX "dam_break.lua:[0-9]+: wcsph-riemann: the gate \\(group 'gate'\\) leaves the domain: after its lift of 0.4 m")
# The surface rows' regularisation (surface_transport) needs the transport velocity it completes
# and a free surface; the H = 600 mm column (cases/dam_break.lua H=0.6): the gate lifts 0.7 m
# (H + 0.1) at 4.53 m/s, 0.1545 s, under the lid at 1.6 m (2 H + 0.4); a column of 1.5 m refused.
clsph_cli_test(riemann_surface_without_tvf ARGS info ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               --set riemann=1 --set tvf=0 --set surf=2 RC 2
               REGEX "wcsph-riemann option surface_transport = \"pairs\" needs the transport velocity")
clsph_cli_test(dam_break_h600 ARGS info ${CMAKE_SOURCE_DIR}/cases/dam_break.lua --set H=0.6
               --set dim=3 --set riemann=1 --set gate=1 RC 0
               REGEX "option gate_stop = 0.154525" REGEX2 "particles: 27440 \\(fluid 2000,")
clsph_cli_test(dam_break_gate_low ARGS info ${CMAKE_SOURCE_DIR}/cases/dam_break.lua --set riemann=1
               --set gate=1 --set gate_height=0.2 RC 2
               REGEX "dam_break.lua:[0-9]+: dam_break: gate_height = 0.2 m does not hold the column back \\(H = 0.3 m\\)")
clsph_cli_test(dam_break_approach_value ARGS info ${CMAKE_SOURCE_DIR}/cases/dam_break.lua
               --set stab=1 --set approach=0.5 RC 2
               REGEX "dam_break.lua:[0-9]+: dam_break: approach must be 0, 1 or 2, not 0.5")
clsph_cli_test(dam_break_h_range ARGS info ${CMAKE_SOURCE_DIR}/cases/dam_break.lua --set H=1.5 RC 2
               REGEX "dam_break.lua:[0-9]+: dam_break: H \\(the column's height, m\\) must be in \\(0, 1\\), not 1.5")
# Poiseuille flow in 3-D (cases/poiseuille3d.lua: plates at z = 0 and H, periodic along x and y,
# Re = 1, the pseudo-Neumann walls), dr = H/10, to t = 1 (556 steps, steady): u within 2.17% of
# the series solution RMS and 2.75% at worst (of U0) in double and float, the cross-flow 7.3e-4
# U0, no particle behind a plate. Bounds 1.5 times measured.
clsph_run_test(run_stab3d_poiseuille ${CMAKE_SOURCE_DIR}/cases/poiseuille3d.lua SETS t_end=1
               BOUNDS "u_rms_error<0.033" "u_max_error<0.042" "cross_speed<0.0011"
                      "crossed_wall<0.5")
# The same with isph-rotational (rot=1: its dummies, shifting 0.04, Gaussian at h = 1.2 dr): u
# within 3.81% RMS and 3.93% at worst in double and float, the cross-flow 3e-5 to 7e-5 U0; the
# 2-D case at the same dr (cases/poiseuille_periodic.lua, u_rms_t1 and u_max_t1) reads 3.83% and
# 3.90% (the odd extension of its dummies): 3-D reproduces it within 1%. Bounds: 5% on both (the
# 2-D test's), the cross-flow 1e-3.
clsph_run_test(run_rot3d_poiseuille ${CMAKE_SOURCE_DIR}/cases/poiseuille3d.lua SETS t_end=1 rot=1
               BOUNDS "u_rms_error>0.03" "u_rms_error<0.05" "u_max_error<0.05"
                      "cross_speed<0.001" "crossed_wall<0.5")
