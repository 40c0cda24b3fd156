# clsph(RC ARGS...): runs ${CLSPH} ARGS... --quiet, prints the command, its exit status and
# output, fails unless the exit status is RC, and leaves the output in `out` (parent scope).
function(clsph expect_rc)
  execute_process(COMMAND ${CLSPH} ${ARGN} --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE out)
  message("clsph ${ARGN}: ${rc}\n${out}")
  if(NOT rc EQUAL expect_rc)
    message(FATAL_ERROR "exit status ${rc}, expected ${expect_rc}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()
