# Frames of a run against frames of its snapshots, and the render command's messages.
#   cmake -DCLSPH=exe -DCASE=hydrostatic.lua -DCHOICE=render_choice.lua
#         -DCHOICE3=render_camera3d.lua -DOUT=dir -P this
# 1. `clsph run --frames` (fixed range) and `clsph render` of its snapshots draw the same frames,
#    byte for byte: the device state a frame was drawn from is the state the snapshot holds.
# 2. A case's render { } choices (field, range, map) serve both commands, and travel in the
#    snapshots.
# 3. Without ffmpeg the frames stay and a warning says how to get the movie; exit status 0. An
#    automatic range spans every snapshot.
# 4. `clsph render --field` of a field the run does not have lists the fields there are.
file(REMOVE_RECURSE ${OUT})

function(clsph_run expect_rc)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${ENV_ARGS} ${CLSPH} ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  message("$ clsph ${ARGN}\n${out}")
  if(NOT rc EQUAL expect_rc)
    message(FATAL_ERROR "clsph exited with ${rc}, expected ${expect_rc}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

function(same_frames a b pattern count)
  file(GLOB fa ${a}/frames/${pattern})
  file(GLOB fb ${b}/frames/${pattern})
  list(LENGTH fa na)
  list(LENGTH fb nb)
  if(NOT na EQUAL count OR NOT nb EQUAL count)
    message(FATAL_ERROR "expected ${count} frames ${pattern} in both, got ${na} and ${nb}")
  endif()
  foreach(f IN LISTS fa)
    get_filename_component(name ${f} NAME)
    file(SHA256 ${f} ha)
    file(SHA256 ${b}/frames/${name} hb)
    if(NOT ha STREQUAL hb)
      message(FATAL_ERROR "${name} differs between ${a} and ${b}")
    endif()
  endforeach()
  message("${count} frames ${pattern}: the same bytes in ${a} and ${b}")
endfunction()

set(small --size 320x240 --no-movie --quiet)
# 1: 11 snapshots (t_end / 10 apart) of a 10 x 10 tank
clsph_run(0 run ${CASE} --set dr=0.1 --set t_end=0.1 --out ${OUT}/run --frames --field p
          --range 0,12000 ${small})
clsph_run(0 render ${OUT}/run --field p --range 0,12000 --out ${OUT}/again ${small})
same_frames(${OUT}/run ${OUT}/again "p_*.png" 11)

# 2: the case says render { field = "vel_y", range = {-0.05, 0.05}, colormap = "coolwarm" }
clsph_run(0 run ${CHOICE} --out ${OUT}/choice --frames ${small})
clsph_run(0 render ${OUT}/choice --out ${OUT}/choice_again ${small})
same_frames(${OUT}/choice ${OUT}/choice_again "vel_y_*.png" 3)

# 3: no ffmpeg
set(ENV_ARGS CLSPH_FFMPEG=${OUT}/no-such-ffmpeg)
clsph_run(0 render ${OUT}/run --field speed --out ${OUT}/noffmpeg --size 320x240)
set(ENV_ARGS "")
if(NOT out MATCHES "no movie: [^ ]*no-such-ffmpeg was not found \\(install it with 'apt-get install ffmpeg'\\); the frames stay")
  message(FATAL_ERROR "no message about the missing ffmpeg")
endif()
if(NOT out MATCHES "colour range of speed over 11 snapshots: 0 \\.\\. [0-9]")
  message(FATAL_ERROR "an automatic range spans the snapshots, from 0 for the speed")
endif()
if(NOT EXISTS ${OUT}/noffmpeg/frames/speed_000010.png OR EXISTS ${OUT}/noffmpeg/speed.mp4)
  message(FATAL_ERROR "without ffmpeg the frames must be there and no movie")
endif()

# 4: an unknown field
clsph_run(2 render ${OUT}/run --field temperature --out ${OUT}/bad ${small})
if(NOT out MATCHES "unknown field 'temperature'; fields: speed, vorticity, vel_x, vel_y, .*p")
  message(FATAL_ERROR "the message does not list the fields")
endif()
# 5: 3-D frames (lit spheres): the case's render { camera } travels in the snapshots, and the
#    default camera (one that sees the domain whole: the snapshots record its 3-D box) is the same
#    in both
foreach(cam 1 0)
  clsph_run(0 run ${CHOICE3} --set cam=${cam} --out ${OUT}/cam${cam} --frames ${small})
  clsph_run(0 render ${OUT}/cam${cam} --out ${OUT}/cam${cam}_again ${small})
  same_frames(${OUT}/cam${cam} ${OUT}/cam${cam}_again "p_*.png" 3)
endforeach()
# a 3-D run's fields: the z components (no vorticity, which is 2-D)
clsph_run(2 render ${OUT}/cam0 --field temperature --out ${OUT}/cam0_bad ${small})
if(NOT out MATCHES "unknown field 'temperature'; fields: speed, vel_x, vel_y, vel_z, .*pos_x, pos_y, pos_z")
  message(FATAL_ERROR "a 3-D run's fields must list the z components and no vorticity")
endif()
clsph_run(0 render ${OUT}/cam0 --field vel_z --out ${OUT}/cam0_w ${small})
if(NOT EXISTS ${OUT}/cam0_w/frames/vel_z_000002.png)
  message(FATAL_ERROR "no frames of vel_z")
endif()
file(SHA256 ${OUT}/cam1/frames/p_000000.png h1)
file(SHA256 ${OUT}/cam0/frames/p_000000.png h0)
if(h1 STREQUAL h0)
  message(FATAL_ERROR "the case's camera and the default one drew the same frame")
endif()
clsph_run(2 info ${CHOICE3} --set bad=1)
if(NOT out MATCHES "render_camera3d.lua:10: render: camera is for 3-D scenes")
  message(FATAL_ERROR "a camera in a 2-D scene: no message")
endif()
clsph_run(2 run ${CHOICE3} --set bad=2 --frames --out ${OUT}/bad2 ${small})
if(NOT out MATCHES "render_camera3d.lua:12: render camera: the camera looks at its own eye")
  message(FATAL_ERROR "a blind camera: no message")
endif()
clsph_run(2 info ${CHOICE3} --set bad=3)
if(NOT out MATCHES "render_camera3d.lua:14: render: camera needs eye = \\{x, y, z\\} and look_at")
  message(FATAL_ERROR "a camera without look_at: no message")
endif()
clsph_run(2 run ${CHOICE3} --set bad=4 --frames --out ${OUT}/bad4 ${small})
if(NOT out MATCHES "render_camera3d.lua:16: render camera: the field of view fov = 500 must be between 1 and 170")
  message(FATAL_ERROR "a field of view of 500 degrees: no message")
endif()
message("run and render agree; the messages are there")
