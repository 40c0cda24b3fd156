# `clsph bench dambreak` on a coarse, short dam break: it exits 0, prints every figure as a
# positive number (particles, simulated and wall time, steps, particle-steps/s, the device time
# per kernel, and grid_bin's launches at least one a step), the scheme, the precision of the build and
# DualSPHysics's anchor, and removes its temporary output folder (TMPDIR points into OUT here).
#   cmake -DCLSPH=exe -DOUT=dir -DPRECISION=double|float -DSCHEME=name "-DARGS=a|b|..."
#         -P bench_dambreak.cmake
string(REPLACE "|" ";" ARGS "${ARGS}")
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT}/tmp)
execute_process(COMMAND ${CMAKE_COMMAND} -E env TMPDIR=${OUT}/tmp ${CLSPH} bench dambreak ${ARGS}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "clsph bench dambreak exited with ${rc}")
endif()

# a figure: the first group of `re` in the output, which must be a positive number
function(positive re what)
  if(NOT out MATCHES "${re}")
    message(FATAL_ERROR "no ${what}: the output does not match '${re}'")
  endif()
  set(v ${CMAKE_MATCH_1})
  if(NOT v GREATER 0)
    message(FATAL_ERROR "${what} is ${v}, not a positive number")
  endif()
  message("${what}: ${v}")
  set(value ${v} PARENT_SCOPE)
endfunction()

positive("\n  particles: +([0-9]+) fluid" "fluid particles")
set(fluid ${value})
positive("\n  particles: +[0-9]+ fluid, ([0-9]+) in all" "particles")
if(value LESS fluid)
  message(FATAL_ERROR "${value} particles in all, fewer than the ${fluid} fluid particles")
endif()
positive("\n  simulated time: +([0-9.e+-]+) s" "simulated time")
positive("\n  wall time: +([0-9.e+-]+) s" "wall time")
positive("\n  advection steps: +([0-9]+)" "advection steps")
set(steps ${value})
positive("per advection step: +([0-9.e+-]+)" "fluid particle-steps/s per advection step")
positive("\n  device total +([0-9]+) " "kernel calls")
positive("\n  device total +[0-9]+ +([0-9.e+-]+)" "device time")
positive("\n  grid_bin +([0-9]+) " "grid_bin calls")
if(value LESS steps)
  message(FATAL_ERROR "grid_bin ran ${value} times in ${steps} steps (once a step at least)")
endif()
foreach(re "\n  precision: +${PRECISION}\n" "\n  scheme: +${SCHEME}\n"
           "\n  acoustic sub-steps: +(none|[1-9][0-9]*)" "\n  pair interactions/s: +(not counted|[0-9])"
           "\n  case metrics: +front = [0-9]" "anchor: DualSPHysics 5.4.* 120 s .*15,880 steps.*2.8e6")
  if(NOT out MATCHES "${re}")
    message(FATAL_ERROR "the output does not match '${re}'")
  endif()
endforeach()

# the temporary output folder is gone
file(GLOB left ${OUT}/tmp/*)
if(left)
  message(FATAL_ERROR "the temporary output folder was left behind: ${left}")
endif()
message("bench dambreak: every figure positive; its temporary folder removed")
