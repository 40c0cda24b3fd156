# Kernel launches and blocking reads of a time step (issue 22: at most 100 launches and 2 blocking
# reads in a step whose pressure solve converges within its batch of iterations).
#   cmake -DCLSPH=exe -DCASE=file -DOUT=dir -DSETS="a=1|b=2" -DSHORT=t1 -DLONG=t2
#         -DMAX_LAUNCHES=L -DMAX_READS_K=R -P step_budget.cmake   (R: reads a step, in thousandths)
# Two --profile runs to t = SHORT and t = LONG with the same number of outputs (the case writes
# ten), so that their difference over the steps the long run adds is that of the steps alone,
# without the outputs' reads: launches (every row of the profile but the transfers) and blocking
# reads ("(read)") a step. A step reads at least twice (its flags and the solve's state), so fewer
# than 2 means the counting is wrong; more than MAX_READS_K/1000, a wait added to the step.
string(REPLACE "|" ";" SETS "${SETS}")
set(args "")
foreach(s IN LISTS SETS)
  list(APPEND args --set ${s})
endforeach()

function(counts t_end out_steps out_launches out_reads)
  set(dir ${OUT}/t${t_end})
  file(REMOVE_RECURSE ${dir})
  execute_process(COMMAND ${CLSPH} run ${CASE} ${args} --set t_end=${t_end} --profile --quiet
                          --out ${dir}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "clsph run to t = ${t_end} exited with ${rc}:\n${out}\n${err}")
  endif()
  file(READ ${dir}/summary.json json)
  string(JSON steps GET "${json}" steps)
  string(JSON n LENGTH "${json}" profile kernels)
  math(EXPR last "${n} - 1")
  set(launches 0)
  set(reads 0)
  foreach(i RANGE ${last})
    string(JSON name GET "${json}" profile kernels ${i} name)
    string(JSON l GET "${json}" profile kernels ${i} launches)
    if(name STREQUAL "(read)")
      set(reads ${l})
    elseif(NOT name MATCHES "^\\(")
      math(EXPR launches "${launches} + ${l}")
    endif()
  endforeach()
  set(${out_steps} ${steps} PARENT_SCOPE)
  set(${out_launches} ${launches} PARENT_SCOPE)
  set(${out_reads} ${reads} PARENT_SCOPE)
endfunction()

counts(${SHORT} s1 l1 r1)
counts(${LONG} s2 l2 r2)
math(EXPR ds "${s2} - ${s1}")
if(NOT ds GREATER 0)
  message(FATAL_ERROR "the run to t = ${LONG} has ${s2} steps, the one to ${SHORT} ${s1}")
endif()
math(EXPR dl "${l2} - ${l1}")
math(EXPR dr "${r2} - ${r1}")
# per step, in thousandths (cmake's integers)
math(EXPR launches_k "${dl} * 1000 / ${ds}")
math(EXPR reads_k "${dr} * 1000 / ${ds}")
math(EXPR max_launches_k "${MAX_LAUNCHES} * 1000")
message("${ds} steps (${s1} to ${s2}): ${dl} launches, ${dr} blocking reads: "
        "${launches_k}/1000 and ${reads_k}/1000 a step (at most ${MAX_LAUNCHES} and ${MAX_READS_K}/1000)")
if(reads_k LESS 2000)
  message(FATAL_ERROR "${reads_k}/1000 blocking reads a step: a step reads its flags and the "
                      "solve's state at least once each")
endif()
if(launches_k GREATER max_launches_k)
  message(FATAL_ERROR "${launches_k}/1000 kernel launches a step, more than ${MAX_LAUNCHES}")
endif()
if(reads_k GREATER MAX_READS_K)
  message(FATAL_ERROR "${reads_k}/1000 blocking reads a step, more than ${MAX_READS_K}/1000")
endif()
