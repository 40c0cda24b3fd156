# Runs CASE twice, with SETS_A and with SETS_B ('|'-separated name=value), and checks that run A
# took at most RATIO times the pressure-solver iterations a step of run B (solver.iterations_mean
# of summary.json). OUT: a folder for the two runs.

# a non-negative decimal number in thousandths (cmake's math() has integers only)
function(to_milli value result)
  if(NOT value MATCHES "^([0-9]+)(\\.([0-9]*))?$")
    message(FATAL_ERROR "'${value}' is not a non-negative decimal number")
  endif()
  set(whole "${CMAKE_MATCH_1}")
  set(frac "${CMAKE_MATCH_3}000")
  string(SUBSTRING "${frac}" 0 3 frac)
  string(REGEX REPLACE "^0+([0-9])" "\\1" frac "${frac}")
  math(EXPR m "${whole} * 1000 + ${frac}")
  set(${result} ${m} PARENT_SCOPE)
endfunction()

foreach(run A B)
  set(args run ${CASE} --out ${OUT}/${run} --overwrite --quiet)
  string(REPLACE "|" ";" sets "${SETS_${run}}")
  foreach(s IN LISTS sets)
    list(APPEND args --set ${s})
  endforeach()
  execute_process(COMMAND ${CLSPH} ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "run ${run} (${SETS_${run}}) failed (rc ${rc}):\n${out}")
  endif()
  file(READ ${OUT}/${run}/summary.json json)
  string(JSON its_${run} GET "${json}" solver iterations_mean)
  to_milli(${its_${run}} m_${run})
endforeach()
to_milli(${RATIO} ratio)
math(EXPR bound "${m_B} * ${ratio} / 1000")
message("iterations a step: A (${SETS_A}) ${its_A}, B (${SETS_B}) ${its_B}; A at most ${RATIO} B")
if(m_A GREATER bound)
  message(FATAL_ERROR "run A took ${its_A} iterations a step, more than ${RATIO} times the ${its_B} "
                      "of run B")
endif()
