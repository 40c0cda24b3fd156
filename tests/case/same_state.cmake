# Two code paths that must compute the same numbers (a fused kernel and the kernels it replaces):
# the same case run with SETS and SETS_A, and with SETS and SETS_B, whose final particle fields are
# compared with h5diff: those named in EXACT bit for bit, those in REL to a relative 1e-9, those in
# ABS to an absolute ABS_TOL (fields with exact zeros, where a relative test reads any rounding as
# a whole difference). The fields compared must have changed from the first snapshot to the last
# (else the test proves nothing), where the snapshots hold them.
#   cmake -DCLSPH=exe -DCASE=file -DOUT=dir -DSETS="a=1" -DSETS_A="b=0" -DSETS_B="b=1"
#         -DEXACT="f|g" -DREL="P" -DABS="h" -DABS_TOL=1e-6 -P same_state.cmake
cmake_policy(SET CMP0054 NEW) # "REL" is a string here, not the variable
find_program(H5DIFF h5diff)
if(NOT H5DIFF)
  message(FATAL_ERROR "h5diff not found: apt-get install hdf5-tools")
endif()
foreach(run A B)
  string(REPLACE "|" ";" sets "${SETS}|${SETS_${run}}")
  set(args "")
  foreach(s IN LISTS sets)
    list(APPEND args --set ${s})
  endforeach()
  file(REMOVE_RECURSE ${OUT}/${run})
  execute_process(COMMAND ${CLSPH} run ${CASE} ${args} --out ${OUT}/${run} --quiet
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "run ${run} (${SETS}|${SETS_${run}}) failed (${rc})")
  endif()
endforeach()
file(GLOB cps RELATIVE ${OUT}/A ${OUT}/A/checkpoint_*.h5)
list(SORT cps)
list(GET cps -1 last)
if(NOT EXISTS ${OUT}/B/${last})
  message(FATAL_ERROR "run B has no ${last}: the runs took different steps")
endif()
file(GLOB snaps RELATIVE ${OUT}/A ${OUT}/A/snap_*.h5)
list(SORT snaps)
list(GET snaps -1 last_snap)
if(last_snap STREQUAL "snap_000000.h5")
  message(FATAL_ERROR "run A wrote one snapshot: nothing to tell a change by")
endif()
foreach(kind EXACT REL ABS)
  string(REPLACE "|" ";" names "${${kind}}")
  set(opt "")
  if(kind STREQUAL "REL")
    set(opt -p 1e-9)
  elseif(kind STREQUAL "ABS")
    set(opt -d ${ABS_TOL})
  endif()
  foreach(f IN LISTS names)
    # the values only: the dataset's checksum attribute differs wherever a bit does
    execute_process(COMMAND ${H5DIFF} ${opt} --exclude-attribute /fields/${f} ${OUT}/A/${last}
                            ${OUT}/B/${last} /fields/${f} /fields/${f} RESULT_VARIABLE rc
                            OUTPUT_VARIABLE out ERROR_VARIABLE out)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${f}: (${SETS_A}) and (${SETS_B}) differ (${opt}): ${out}")
    endif()
    # the first snapshot against the last (snapshots hold /particles/, checkpoints /fields/):
    # h5diff says 1 where they differ, 2 where the snapshots do not hold the field
    execute_process(COMMAND ${H5DIFF} ${OUT}/A/snap_000000.h5 ${OUT}/A/${last_snap}
                            /particles/${f} /particles/${f} RESULT_VARIABLE rc OUTPUT_QUIET
                            ERROR_QUIET)
    if(rc EQUAL 0)
      message(FATAL_ERROR "${f} did not change from the first snapshot: the test proves nothing")
    elseif(rc EQUAL 1)
      message("${f} in ${last}: the same (${opt}), and changed since the first snapshot")
    else()
      message("${f} in ${last}: the same (${opt}); not in the snapshots, its change not checked")
    endif()
  endforeach()
endforeach()
