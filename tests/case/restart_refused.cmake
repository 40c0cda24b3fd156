# A checkpoint of one case is refused by another case, and a file that is no checkpoint is
# refused, each with its reason and a non-zero exit.
#   cmake -DCLSPH=exe -DCASE_A=file -DCASE_B=file -DOUT=dir -DNOT_CHECKPOINT=file -P ...
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${CLSPH} run ${CASE_A} --set t_end=0.05 --set dr=0.05 --out ${OUT}/a
                        --quiet RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the run of ${CASE_A} failed (${rc})")
endif()
file(GLOB cps ${OUT}/a/checkpoint_*.h5)
list(GET cps 0 cp)
get_filename_component(a_name ${CASE_A} NAME_WE)
get_filename_component(b_name ${CASE_B} NAME_WE)
foreach(pair "${cp}|written by case '${a_name}', not '${b_name}'"
             "${NOT_CHECKPOINT}|is not a clsph checkpoint")
  string(REPLACE "|" ";" pair "${pair}")
  list(GET pair 0 file)
  list(GET pair 1 want)
  execute_process(COMMAND ${CLSPH} run ${CASE_B} --restart ${file} --out ${OUT}/b --quiet
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  message("${out}")
  if(NOT rc EQUAL 2 OR NOT out MATCHES "${want}") # 2: refused input (a crash is not)
    message(FATAL_ERROR "--restart ${file}: expected a refusal saying '${want}'")
  endif()
endforeach()
message("restart refusals: ok")
