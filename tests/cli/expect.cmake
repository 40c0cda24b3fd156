# Runs a command and checks its exit status and output; used by the command-line tests.
#   cmake -DCMD="prog|arg|..." -DRC=0|nonzero|N -DREGEX="..." [-DREGEX2="..."] [-DENV="K=V|..."]
#         [-DNOT_REGEX="..."] (the output must not match it: a message said twice, say)
#         [-DBREAK_KERNELS=DIR -DKERNELS=SRC] [-DFRESH_DIR=DIR [-DFIRST_CMD="prog|arg|..."]]
#         -P expect.cmake
# FRESH_DIR runs the command twice from an empty DIR (FIRST_CMD the first time, when given) and
# checks the second run.
# BREAK_KERNELS copies the kernel sources SRC to DIR and appends a line that is not OpenCL C to
# common/grid.cl; the expected compiler message names that file and line (@LINE@ in REGEX).
string(REPLACE "|" ";" CMD "${CMD}")
string(REPLACE "|" ";" ENV "${ENV}")
if(FIRST_CMD)
  string(REPLACE "|" ";" FIRST_CMD "${FIRST_CMD}")
else()
  set(FIRST_CMD ${CMD})
endif()
if(BREAK_KERNELS)
  file(REMOVE_RECURSE ${BREAK_KERNELS})
  file(COPY ${KERNELS}/ DESTINATION ${BREAK_KERNELS})
  file(READ ${BREAK_KERNELS}/common/grid.cl text)
  string(REGEX MATCHALL "\n" newlines "${text}")
  list(LENGTH newlines count)
  math(EXPR line "${count} + 1")
  file(APPEND ${BREAK_KERNELS}/common/grid.cl "this is not OpenCL C;\n")
  string(REPLACE "@LINE@" "${line}" REGEX "${REGEX}")
endif()
if(FRESH_DIR) # run twice from an empty folder; the second run's output is checked
  file(REMOVE_RECURSE ${FRESH_DIR})
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${ENV} ${FIRST_CMD}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE first ERROR_VARIABLE first)
  message("first run:\n${first}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env ${ENV} ${CMD}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(FRESH_DIR)
  set(out "second run:\n${out}")
endif()
message("${out}")
message("exit status: ${rc}")
if(RC STREQUAL "nonzero")
  if(rc EQUAL 0)
    message(FATAL_ERROR "expected a non-zero exit status")
  endif()
elseif(NOT rc EQUAL RC)
  message(FATAL_ERROR "expected exit status ${RC}, got ${rc}")
endif()
foreach(re IN ITEMS "${REGEX}" "${REGEX2}")
  if(re AND NOT out MATCHES "${re}")
    message(FATAL_ERROR "output does not match '${re}'")
  endif()
endforeach()
if(NOT_REGEX AND out MATCHES "${NOT_REGEX}")
  message(FATAL_ERROR "output matches '${NOT_REGEX}'")
endif()
