# Frames, PNG files and movies (render/), label `render`. test_render draws a small known scene
# and checks it pixel by pixel; test_movie makes an MP4 and checks it with ffprobe (skipped
# without ffmpeg); the scripts compare the frames of a run with those of its snapshots and check
# the messages of bad input. Files go under ${CMAKE_CURRENT_BINARY_DIR}/render-test.
set(RENDER_DIR ${CMAKE_CURRENT_SOURCE_DIR}/render)
set(RENDER_OUT ${CMAKE_CURRENT_BINARY_DIR}/render-test)
file(MAKE_DIRECTORY ${RENDER_OUT})

clsph_test_exe(test_render render/test_render.c)
clsph_add_test(render COMMAND test_render ${RENDER_OUT} LABELS render)
clsph_test_exe(test_movie render/test_movie.c)
clsph_add_test(render_movie COMMAND test_movie ${RENDER_OUT} LABELS render)

clsph_add_test(render_run_and_snapshots LABELS render case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CMAKE_SOURCE_DIR}/cases/hydrostatic.lua
               -DCHOICE=${RENDER_DIR}/render_choice.lua
               -DCHOICE3=${RENDER_DIR}/render_camera3d.lua -DOUT=${RENDER_OUT}/runs
               -P ${RENDER_DIR}/run_and_render.cmake)

clsph_add_test(render_turbulence_fields LABELS render case COMMAND ${CMAKE_COMMAND}
               -DCLSPH=$<TARGET_FILE:clsph> -DCASE=${CMAKE_CURRENT_SOURCE_DIR}/case/inflow_ke.lua
               -DOUT=${RENDER_OUT}/turbulence -P ${RENDER_DIR}/turbulence_fields.cmake)

# The walls the snapshots record where they stand: the dam break's gate lifted 0.4 m in a 3-D run
# (/walls3: the tank's and the gate's faces, counter-clockwise seen from the fluid) and in a 2-D
# run (its polyline); walls_moved.py reads them with h5dump.
if(Python3_Interpreter_FOUND)
  foreach(dim 2 3)
    if(dim EQUAL 3)
      set(sets --set dim=3 --set n=12 --set t_end=0.12)
    else()
      set(sets --set n=20 --set t_end=0.1)
    endif()
    clsph_cli_test(render_walls_moved_${dim}d FRESH_DIR ${RENDER_OUT}/gate${dim} RC 0
                   FIRST_ARGS run ${CMAKE_SOURCE_DIR}/cases/dam_break.lua --set riemann=1
                   --set gate=1 ${sets} --quiet --out ${RENDER_OUT}/gate${dim}
                   ARGS render ${RENDER_OUT}/gate${dim} --no-movie --size 320x240
                   REGEX "frames: .*gate${dim}/frames/speed_000000.png")
    clsph_add_test(render_walls_moved_${dim}d_check LABELS render COMMAND ${Python3_EXECUTABLE}
                   ${RENDER_DIR}/walls_moved.py ${dim} ${RENDER_OUT}/gate${dim})
    set_tests_properties(render_walls_moved_${dim}d PROPERTIES FIXTURES_SETUP gate_run_${dim}d)
    set_tests_properties(render_walls_moved_${dim}d_check PROPERTIES
                         FIXTURES_REQUIRED gate_run_${dim}d)
    set_property(TEST render_walls_moved_${dim}d APPEND PROPERTY LABELS render)
  endforeach()
endif()

# Bad input: exit status 2 and a message that says what is wrong.
function(clsph_render_cli_test name)
  clsph_cli_test(${name} ${ARGN})
  set_property(TEST ${name} APPEND PROPERTY LABELS render)
endfunction()
clsph_render_cli_test(render_missing_folder ARGS render ${RENDER_OUT}/no-such-run RC 2
                      REGEX "render: the output folder .*no-such-run does not exist")
clsph_render_cli_test(render_no_snapshots ARGS render ${CMAKE_CURRENT_SOURCE_DIR}/data RC 2
                      REGEX "render: no snapshots \\(snap_NNNNNN.h5\\) in .*data; it is not the output folder of a run")
clsph_render_cli_test(render_needs_folder ARGS render RC 2
                      REGEX "render: name the output folder of a run")
clsph_render_cli_test(render_bad_range ARGS render out --range 5,1 RC 2
                      REGEX "--range: '5,1': the low end 5 must be below the high end 1")
clsph_render_cli_test(render_range_not_numbers ARGS render out --range low,high RC 2
                      REGEX "--range: 'low,high' is not LO,HI \\(two numbers, e.g. 0,1000\\) or auto")
clsph_render_cli_test(render_bad_size ARGS render out --size 8x8 RC 2
                      REGEX "--size: 8x8: each side must be from 16 to 8192 pixels")
clsph_render_cli_test(render_bad_colormap ARGS render out --colormap jet RC 2
                      REGEX "unknown colour map 'jet'; maps: auto, viridis, coolwarm, kind")
clsph_render_cli_test(render_field_without_frames ARGS run ${CMAKE_SOURCE_DIR}/cases/cavity.lua
                      --field p RC 2 REGEX "--field is an option of frames: use it with `clsph run CASE --frames`")
clsph_render_cli_test(render_run_unknown_field RC 2
                      ARGS run ${CMAKE_SOURCE_DIR}/cases/free_fall.lua --frames --field temperature
                           --quiet --out ${RENDER_OUT}/unknown_field
                      REGEX "unknown field 'temperature'; fields: speed, vorticity, vel_x, vel_y, ")
clsph_render_cli_test(render_case_bad_range ARGS info ${RENDER_DIR}/bad_render_range.lua RC 2
                      REGEX "bad_render_range.lua:7: render: range .*: the low end must be below the high end")
# The font: a --font that is not there, and a fontconfig that knows no DejaVu Sans (an empty font
# folder), each refused with the Debian package to install.
clsph_render_cli_test(render_font_missing RC 1
                      ARGS bench render --bench-sizes 100 --font ${RENDER_OUT}/no-such-font.ttf
                           --out ${RENDER_OUT}/bench
                      REGEX "cannot open the font .*no-such-font.ttf \\(--font\\)"
                      REGEX2 "apt-get install fonts-dejavu-core")
file(MAKE_DIRECTORY ${RENDER_OUT}/no-fonts)
file(WRITE ${RENDER_OUT}/no-fonts/fonts.conf
     "<?xml version=\"1.0\"?>\n<fontconfig><dir>${RENDER_OUT}/no-fonts</dir>"
     "<cachedir>${RENDER_OUT}/no-fonts/cache</cachedir></fontconfig>\n")
clsph_render_cli_test(render_no_dejavu RC 1 ENV FONTCONFIG_FILE=${RENDER_OUT}/no-fonts/fonts.conf
                      ARGS bench render --bench-sizes 100 --out ${RENDER_OUT}/bench
                      REGEX "the font DejaVu Sans is not installed .*apt-get install fonts-dejavu-core")
