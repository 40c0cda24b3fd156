# The k-ε model's fields in frames (tests/case/inflow_ke.lua: an entry's decaying turbulence):
#   cmake -DCLSPH=exe -DCASE=inflow_ke.lua -DOUT=dir -P this
# `clsph run --frames --field k` and `clsph render` of its snapshots draw the same frames byte for
# byte (a fixed range); render draws epsilon, nu_t, y_plus and the ARD indicator (ard) too, and the automatic range
# of k spans what the run carried: from the exit's decayed k (0.005: k0 (1 + 0.92 ε0 L/(U k0))^-1.087
# = 0.00494 at x = 4) to the entry's k0 = 0.01 (up to 0.0101 while the exit held the moving
# fluid back at the start and sent a sound wave up the stream).
file(REMOVE_RECURSE ${OUT})

function(clsph_run)
  execute_process(COMMAND ${CLSPH} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE out)
  message("$ clsph ${ARGN}\n${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "clsph exited with ${rc}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

set(small --size 320x240 --no-movie --quiet)
clsph_run(run ${CASE} --set t_end=2 --set ard=1 --out ${OUT}/run --frames --field k
          --range 0.004,0.011 ${small})
clsph_run(render ${OUT}/run --field k --range 0.004,0.011 --out ${OUT}/again ${small})
clsph_run(render ${OUT}/run --field k --out ${OUT}/auto --size 320x240 --no-movie)
if(NOT out MATCHES "colour range of k over 5 snapshots: 0\\.00(4[5-9]|5[0-5])[0-9]* \\.\\. 0\\.01(0[0-9]*)?\n")
  message(FATAL_ERROR "the automatic range of k does not span the run's k (0.005 .. 0.01)")
endif()
file(GLOB fa ${OUT}/run/frames/k_*.png)
list(LENGTH fa na)
if(NOT na EQUAL 5)
  message(FATAL_ERROR "expected 5 frames of k, got ${na}")
endif()
foreach(f IN LISTS fa)
  get_filename_component(name ${f} NAME)
  file(SHA256 ${f} ha)
  file(SHA256 ${OUT}/again/frames/${name} hb)
  if(NOT ha STREQUAL hb)
    message(FATAL_ERROR "${name} differs between the run's frames and the render of its snapshots")
  endif()
endforeach()
foreach(field epsilon nu_t y_plus ard)
  clsph_run(render ${OUT}/run --field ${field} --out ${OUT}/${field} ${small})
  if(NOT EXISTS ${OUT}/${field}/frames/${field}_000004.png)
    message(FATAL_ERROR "no frames of ${field}")
  endif()
endforeach()
message("k, epsilon, nu_t, y_plus and ard render; run and render agree")
