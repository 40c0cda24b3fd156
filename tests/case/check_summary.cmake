# Checks OUT/summary.json of a finished run: the keys every run writes, status "ok", and the
# metrics bounds given as METRIC_NAME<value, e.g. -DBOUNDS="drop_error<0.1;x_min>-1e-9", and bounds
# on another object of summary.json as BLOCK.NAME<value: the health checks' worst values
# (health.nearest_spacing_min_dr>0.8), the wall crossings (wall_crossings.steps<0.5).
file(READ ${OUT}/summary.json json)
foreach(key case scheme precision device particles steps sim_time wall_seconds
            particle_steps_per_second status metrics)
  string(JSON v ERROR_VARIABLE err GET "${json}" ${key})
  if(err)
    message(FATAL_ERROR "summary.json has no key '${key}'")
  endif()
endforeach()
# the wall time split into the outputs' and the steps': each part in [0, wall_seconds]
string(JSON wall GET "${json}" wall_seconds)
foreach(part output_seconds step_seconds)
  string(JSON v ERROR_VARIABLE err GET "${json}" ${part})
  if(err)
    message(FATAL_ERROR "summary.json has no key '${part}'")
  endif()
  if(v LESS 0 OR v GREATER wall)
    message(FATAL_ERROR "${part} = ${v} is not within [0, wall_seconds = ${wall}]")
  endif()
endforeach()
string(JSON status GET "${json}" status)
if(NOT status STREQUAL "ok")
  message(FATAL_ERROR "status is '${status}'")
endif()
string(JSON failure ERROR_VARIABLE err GET "${json}" failure)
if(err OR NOT failure STREQUAL "none")
  message(FATAL_ERROR "failure is '${failure}', not 'none'")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/bounds.cmake)
message("summary.json: status ok, ${json}")
