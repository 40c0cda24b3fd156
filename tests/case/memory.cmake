# A scene that needs more device memory than the run may use (--device-memory) is refused before
# anything runs or is written: the message gives the estimate and its parts, and the output
# folder is not even created. `clsph info` prints the estimate.
#   cmake -DCLSPH=exe -DCASE=cases/cavity.lua -DOUT=dir -P memory.cmake
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${CLSPH} run ${CASE} --set n=60 --device-memory 2 --out ${OUT} --quiet
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 2 OR NOT out MATCHES
   "the scene needs about [0-9]+ MiB of device memory \\(3[0-9]+ particles: [0-9]+ MiB of fields and buffers, [0-9]+ MiB for the pressure solver's stored operator\\), more than the 2 MiB --device-memory allows")
  message(FATAL_ERROR "exit status ${rc}: not the refusal expected")
endif()
if(EXISTS ${OUT})
  message(FATAL_ERROR "the refused run created its output folder")
endif()
execute_process(COMMAND ${CLSPH} info ${CASE} --set n=60 --device-memory 20
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "device memory: about [0-9.]+ MiB .*of which the run may use 20\\)")
  message(FATAL_ERROR "clsph info does not give the estimate")
endif()
message("device memory: ok")
