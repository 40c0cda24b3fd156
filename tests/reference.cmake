# References the project computes itself (tests/reference/): the 1-D fully developed k-ε channel
# of Wang, Sun & Hu sec 5.1 (eq 41), a library for the tests, a command for the profiles, and its
# own test (steady residual, grid convergence, the log law, the two drives, bad input).
add_library(clsph_channel1d STATIC reference/channel1d.c)
target_include_directories(clsph_channel1d PUBLIC reference)
target_compile_options(clsph_channel1d PRIVATE ${CLSPH_WARNINGS})
target_link_libraries(clsph_channel1d PUBLIC m)

add_executable(channel1d reference/channel1d_main.c)
target_link_libraries(channel1d PRIVATE clsph_channel1d)
target_compile_options(channel1d PRIVATE ${CLSPH_WARNINGS})

clsph_test_exe(test_channel1d reference/test_channel1d.c)
target_link_libraries(test_channel1d PRIVATE clsph_channel1d)
clsph_add_test(channel1d COMMAND test_channel1d ${CMAKE_SOURCE_DIR}/tests/data LABELS unit)

# the command: Lee & Moser's Re_τ = 543.5 channel at 400 cells (u_τ 0.05146, test_channel1d)
function(channel1d_cli_test name)
  cmake_parse_arguments(T "" "RC;REGEX;REGEX2" "ARGS" ${ARGN})
  string(REPLACE ";" "|" args "${T_ARGS}")
  clsph_add_test(${name} LABELS cli COMMAND ${CMAKE_COMMAND} "-DCMD=$<TARGET_FILE:channel1d>|${args}"
                 -DRC=${T_RC} "-DREGEX=${T_REGEX}" "-DREGEX2=${T_REGEX2}" "-DENV="
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect.cmake)
endfunction()
channel1d_cli_test(channel1d_cli ARGS --cells 400 RC 0 REGEX "u_tau = 0\\.05145[0-9]"
                   REGEX2 "y,y_over_delta,y_plus,u,u_plus,k,k_plus,epsilon,nu_t")
channel1d_cli_test(channel1d_cli_bad_number ARGS --nu fast RC 2 REGEX "--nu: 'fast' is not a number")
channel1d_cli_test(channel1d_cli_bad_option ARGS --re 40000 RC 2 REGEX "unknown option --re")
# --rows: fewer than 8 rows, or a bulk over the rows without them, is refused
channel1d_cli_test(channel1d_cli_few_rows ARGS --rows 5 RC 1 REGEX "channel1d: rows must be 8 or more")
channel1d_cli_test(channel1d_cli_bulk_without_rows ARGS --bulk-over-rows RC 1
                   REGEX "channel1d: a bulk over the rows needs rows")
channel1d_cli_test(channel1d_cli_offset_without_bulk ARGS --rows 40 --offset-momentum RC 1
                   REGEX "channel1d: the offset wall's momentum balance needs the bulk over the rows")
channel1d_cli_test(channel1d_cli_two_schemes ARGS --fv --backward RC 1
                   REGEX "channel1d: one scheme: the finite volume's \\(--fv\\) or the backward differences \\(--backward\\)")
channel1d_cli_test(channel1d_cli_fv ARGS --rows 20 --bulk-over-rows --log-b 5.5667 --fv RC 0
                   REGEX "rows = 20 \\(spacing 0.1\\), bulk over the rows: u_tau = 0\\.05252[0-9]")
channel1d_cli_test(channel1d_cli_rows_nan ARGS --rows nan RC 2
                   REGEX "--rows must be a whole number from 1 to 1e7, not nan")
channel1d_cli_test(channel1d_cli_cells_fraction ARGS --cells 20.5 RC 2
                   REGEX "--cells must be a whole number from 1 to 1e7, not 20.5")

# The kernel sums' ∂u/∂y on the 1-D solution laid on a run's rows (RESULTS_rans.md: what puts the
# channel's u_τ over the 1-D solver's), tests/validation/channel_ke_gradient_bias.py: at N_f = 40
# the production of rows 2 on is 8.5% over the model's and the third row's gradient 6.3% over the
# exact one (deterministic: the Wendland sums on a lattice of the stored profile).
if(Python3_Interpreter_FOUND)
  clsph_add_test(channel_ke_gradient_bias LABELS unit COMMAND ${CMAKE_COMMAND}
                 "-DCMD=${Python3_EXECUTABLE}|${CMAKE_SOURCE_DIR}/tests/validation/channel_ke_gradient_bias.py|${CMAKE_SOURCE_DIR}/tests/data|40"
                 -DRC=0 "-DREGEX=# N_f = 40: production over rows 2 on 1\\.084[0-9] of the model's"
                 "-DREGEX2=40,3,0\\.1474,1\\.06[23][0-9],1\\.129[0-9]" "-DENV="
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect.cmake)
endif()

# results.py's reading of the HCD channel's floor (RESULTS_rans_map.md's and
# RESULTS_rans_options.md's last section): the foot and tangent of points over each piece of the
# floor exactly, and OpenFOAM's stored wall cells (tests/data/openfoam_channel_hcd.csv, line
# "floor") binned as the runs' first row is: their zero crossings, 5.70 and 10.66, each within a
# bin (0.25) of the cells' own backflow range in the file's header (5.61 to 10.63).
if(Python3_Interpreter_FOUND)
  clsph_add_test(hcd_floor_reading LABELS unit COMMAND ${CMAKE_COMMAND}
                 "-DCMD=${Python3_EXECUTABLE}|${CMAKE_SOURCE_DIR}/tests/validation/hcd_floor_check.py"
                 -DRC=0 "-DREGEX=separation 5\\.70, reattachment 10\\.66. the cells' backflow 5\\.61 to 10\\.63"
                 "-DREGEX2=48 bins" "-DENV=" -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect.cmake)
  # the same on the mesh twice as fine in the core and along the floor: 5.70 and 10.69
  clsph_add_test(hcd_floor_reading_fine LABELS unit COMMAND ${CMAKE_COMMAND}
                 "-DCMD=${Python3_EXECUTABLE}|${CMAKE_SOURCE_DIR}/tests/validation/hcd_floor_check.py|${CMAKE_SOURCE_DIR}/tests/data/openfoam_channel_hcd_fine.csv"
                 -DRC=0 "-DREGEX=separation 5\\.70, reattachment 10\\.69. the cells' backflow 5\\.65 to 10\\.69"
                 "-DREGEX2=48 bins" "-DENV=" -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect.cmake)
endif()
