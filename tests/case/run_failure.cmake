# Runs a case that must stop as a blow-up of one class: exit status RC (default 1), summary.json
# written with
# "failure" = FAILURE and a status matching REGEX (the health checks of host/sim/checks.c), and a
# message matching MESSAGE (default: REGEX; a failure reported where it happened, such as the
# pressure solver's, is worded there). The failures of the time loop's checks leave the state
# that failed them in blowup.h5.
#   cmake -DCLSPH=exe -DCASE=file -DOUT=dir -DSETS="a=1|b=2" -DFAILURE=energy -DREGEX=...
#         [-DARGS="--opt|value"] [-DRC=2] -P ...
string(REPLACE "|" ";" SETS "${SETS}")
set(args "")
foreach(s IN LISTS SETS)
  list(APPEND args --set ${s})
endforeach()
string(REPLACE "|" ";" ARGS "${ARGS}")
if(NOT RC)
  set(RC 1)
endif()
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${CLSPH} run ${CASE} ${args} ${ARGS} --out ${OUT} --quiet
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(NOT rc EQUAL RC)
  message(FATAL_ERROR "clsph run exited with ${rc}, not ${RC}")
endif()
if(NOT EXISTS ${OUT}/summary.json)
  message(FATAL_ERROR "the run stopped without writing summary.json")
endif()
file(READ ${OUT}/summary.json json)
string(JSON failure ERROR_VARIABLE err GET "${json}" failure)
string(JSON status GET "${json}" status)
if(err OR NOT failure STREQUAL "${FAILURE}")
  message(FATAL_ERROR "summary.json failure is '${failure}', not '${FAILURE}' (status '${status}')")
endif()
if(NOT status MATCHES "${REGEX}")
  message(FATAL_ERROR "summary.json status '${status}' does not match '${REGEX}'")
endif()
if(failure MATCHES "^(nan|escaped|neighbours|wall_crossing|clustering|energy)$" AND
   NOT EXISTS ${OUT}/blowup.h5)
  message(FATAL_ERROR "the run stopped ('${failure}') without leaving its state in blowup.h5")
endif()
if(NOT MESSAGE)
  set(MESSAGE "${REGEX}")
endif()
if(NOT out MATCHES "${MESSAGE}")
  message(FATAL_ERROR "the message does not match '${MESSAGE}'")
endif()
message("failure '${failure}', status '${status}'")
