# A long --out (1413 characters: seven folders of 200) is used whole, not cut at a fixed buffer's
# size: the summary, a checkpoint and a frame land in that folder. One beyond the system's limit
# on a path (PATH_MAX, 4096) is refused with the system's reason, before anything runs.
#   cmake -DCLSPH=exe -DCASE=file -DOUT=dir -P long_out.cmake
string(REPEAT "d" 200 seg)
set(dir ${OUT})
foreach(i RANGE 1 7)
  set(dir ${dir}/${seg})
endforeach()
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${CLSPH} run ${CASE} --set dr=0.1 --set t_end=0.05 --out ${dir} --quiet
                        --frames --no-movie
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the run into a long --out failed (${rc})")
endif()
foreach(f summary.json snap_000000.h5 frames/speed_000000.png)
  if(NOT EXISTS ${dir}/${f})
    message(FATAL_ERROR "${f} is not in the long --out folder")
  endif()
endforeach()
file(GLOB cps ${dir}/checkpoint_*.h5)
if(NOT cps)
  message(FATAL_ERROR "no checkpoint in the long --out folder")
endif()
string(REPEAT "${seg}/" 25 toolong)
execute_process(COMMAND ${CLSPH} run ${CASE} --set dr=0.1 --out ${OUT}/${toolong} --quiet
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 1 OR NOT out MATCHES "cannot be created: File name too long")
  message(FATAL_ERROR "a --out beyond PATH_MAX was not refused with its reason")
endif()
file(REMOVE_RECURSE ${OUT})
message("long --out: ok")
