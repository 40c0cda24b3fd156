# A checkpoint restarts only the scene it was written by: another value of a parameter (t_end
# aside) is refused naming it, and so is the same case file with its geometry changed (the scene
# digest); a longer t_end is accepted. A checkpoint whose data was changed on disk (one byte of a
# field, or of its time) fails its checksum.
#   cmake -DCLSPH=exe -DCASE=cases/periodic_drift.lua -DOUT=dir -DPYTHON=python3 -P ...
file(REMOVE_RECURSE ${OUT})
include(${CMAKE_CURRENT_LIST_DIR}/clsph.cmake)
clsph(0 run ${CASE} --set dr=0.05 --set t_end=0.1 --out ${OUT}/a)
file(GLOB cps ${OUT}/a/checkpoint_*.h5)
list(GET cps 0 cp)
clsph(2 run ${CASE} --set dr=0.04 --set t_end=0.1 --restart ${cp} --out ${OUT}/b)
if(NOT out MATCHES "comes from another scene: its run had dr = 0.05, this run dr = 0.04")
  message(FATAL_ERROR "the refusal does not name the parameter")
endif()
# the same case file (the same name and parameters) with a taller channel
get_filename_component(name ${CASE} NAME)
file(READ ${CASE} text)
string(REPLACE "domain { 0, 0, length, 0.5" "domain { 0, 0, length, 0.6" text "${text}")
string(REPLACE "{0, 0.5}, {length, 0.5}" "{0, 0.6}, {length, 0.6}" text "${text}")
file(WRITE ${OUT}/changed/${name} "${text}")
clsph(2 run ${OUT}/changed/${name} --set dr=0.05 --set t_end=0.1 --restart ${cp} --out ${OUT}/c)
if(NOT out MATCHES "the parameters agree, but the particles, walls, domain, fluid or scheme")
  message(FATAL_ERROR "a changed geometry was not refused")
endif()
clsph(0 run ${CASE} --set dr=0.05 --set t_end=0.2 --restart ${cp} --out ${OUT}/d)
# damage on disk: a byte of the positions, then a byte of the time
foreach(what pos time)
  file(COPY ${cp} DESTINATION ${OUT}/${what})
  get_filename_component(cpname ${cp} NAME)
  execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/flip_byte.py ${OUT}/${what}/${cpname}
                          ${what} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "flip_byte.py failed")
  endif()
  clsph(2 run ${CASE} --set dr=0.05 --set t_end=0.1 --restart ${OUT}/${what}/${cpname}
        --out ${OUT}/e_${what})
  if(what STREQUAL "pos" AND NOT out MATCHES "is damaged: field 'pos' fails its checksum")
    message(FATAL_ERROR "a changed position was not caught")
  elseif(what STREQUAL "time" AND NOT out MATCHES "is damaged: its time, step, dt or particle")
    message(FATAL_ERROR "a changed time was not caught")
  endif()
endforeach()
message("restart refusals of another scene and of damaged checkpoints: ok")
