# Runs a case that must stop as a blow-up of one class: exit status RC (default 1), summary.json
# written with
# "failure" = FAILURE and a status matching REGEX (the health checks of host/sim/checks.c), and a
# message matching MESSAGE (default: REGEX; a failure reported where it happened, such as the
# pressure solver's, is worded there). The failures of the time loop's checks leave the state
# that failed them in blowup.h5.
#   cmake -DCLSPH=exe -DCASE=file -DOUT=dir -DSETS="a=1|b=2" -DFAILURE=energy -DREGEX=...
#         [-DARGS="--opt|value"] [-DRC=2] [-DBOUNDS="name<v|name>v"] [-DNO_METRICS=1] -P ...
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
# The metrics of the state the run stopped in (summary.c, stopped_state): BOUNDS on them where
# given; none where the state is not finite or the run never stepped.
string(JSON at_stop ERROR_VARIABLE err GET "${json}" metrics_at_stop)
if(BOUNDS)
  string(REPLACE "|" ";" BOUNDS "${BOUNDS}")
  if(err OR NOT at_stop)
    message(FATAL_ERROR "summary.json has no metrics_at_stop: metrics() did not run on the stop")
  endif()
  include(${CMAKE_CURRENT_LIST_DIR}/bounds.cmake)
elseif(NOT err AND failure MATCHES "^(nan|error|metrics|interrupted)$")
  message(FATAL_ERROR "metrics of a '${failure}' stop: its state is not one to measure")
endif()
if(NO_METRICS) # metrics() failed on the stop: none written, no metrics_at_stop
  string(JSON nmetrics LENGTH "${json}" metrics)
  if(NOT err OR NOT nmetrics EQUAL 0)
    message(FATAL_ERROR "summary.json has metrics (${nmetrics}, metrics_at_stop '${at_stop}')")
  endif()
endif()
if(NOT MESSAGE)
  set(MESSAGE "${REGEX}")
endif()
if(NOT out MATCHES "${MESSAGE}")
  message(FATAL_ERROR "the message does not match '${MESSAGE}'")
endif()
message("failure '${failure}', status '${status}'")
