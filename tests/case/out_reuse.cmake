# Output folders hold one run: a folder with another run's outputs is refused and left as it was;
# --overwrite clears it first (the files then are those of a fresh run); a run continued from a
# checkpoint in its own folder drops what came after the checkpoint (snapshots, checkpoints,
# frames), so the folder reads as one run; --overwrite is refused when it would delete the
# checkpoint, and a restart into a folder of other outputs is refused.
#   cmake -DCLSPH=exe -DCASE=tests/case/outputs.lua -DOUT=dir -P out_reuse.cmake
file(REMOVE_RECURSE ${OUT})
include(${CMAKE_CURRENT_LIST_DIR}/clsph.cmake)
function(listing dir var)
  file(GLOB_RECURSE files RELATIVE ${dir} ${dir}/*.h5 ${dir}/frames/*.png)
  list(SORT files)
  set(${var} "${files}" PARENT_SCOPE)
endfunction()
# a run, then another into the same folder: refused, nothing touched
clsph(0 run ${CASE} --set dr=0.05 --out ${OUT}/a --frames --no-movie)
listing(${OUT}/a before)
clsph(2 run ${CASE} --set t_end=0.1 --out ${OUT}/a)
if(NOT out MATCHES "holds the outputs of another run .*--overwrite clears them")
  message(FATAL_ERROR "the refusal does not say what to do")
endif()
listing(${OUT}/a after)
if(NOT before STREQUAL after)
  message(FATAL_ERROR "a refused run changed the folder: ${before} -> ${after}")
endif()
# --overwrite: the folder then holds what a fresh run of the second case holds
clsph(0 run ${CASE} --set t_end=0.1 --out ${OUT}/a --overwrite)
clsph(0 run ${CASE} --set t_end=0.1 --out ${OUT}/fresh)
listing(${OUT}/a over)
listing(${OUT}/fresh fresh)
if(NOT over STREQUAL fresh OR EXISTS ${OUT}/a/frames)
  message(FATAL_ERROR "--overwrite left other files: ${over} against a fresh run's ${fresh}")
endif()
# a restart in place from t = 0.2 to 0.3: what the longer run wrote after 0.2 goes
clsph(0 run ${CASE} --out ${OUT}/b --frames --no-movie)
file(GLOB cps RELATIVE ${OUT}/b ${OUT}/b/checkpoint_*.h5)
list(SORT cps)
list(GET cps 0 mid)
clsph(0 run ${CASE} --set t_end=0.3 --restart ${OUT}/b/${mid} --out ${OUT}/b --frames --no-movie)
clsph(0 run ${CASE} --set t_end=0.3 --out ${OUT}/c --frames --no-movie)
listing(${OUT}/b resumed)
listing(${OUT}/c whole)
if(NOT resumed STREQUAL whole)
  message(FATAL_ERROR "the folder continued in place holds ${resumed}, the run to 0.3 ${whole}")
endif()
# --overwrite would delete the checkpoint; a restart into another run's folder is refused
clsph(2 run ${CASE} --restart ${OUT}/b/${mid} --out ${OUT}/b --overwrite)
if(NOT out MATCHES "--overwrite would delete .*${mid}")
  message(FATAL_ERROR "no reason given")
endif()
clsph(2 run ${CASE} --restart ${OUT}/b/${mid} --out ${OUT}/fresh)
message("output folders: ok")
