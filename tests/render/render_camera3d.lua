-- A 3-D tank whose frames the case chooses (tests/render/run_and_render.cmake): the pressure in a
-- fixed range, seen by the case's camera (cam = 1) or the default one (cam = 0).
-- bad = 1: a camera in a 2-D scene; 2: a camera that looks at its own eye; 3: no look_at; 4: a
-- field of view of 500 degrees.
param { cam = 1, bad = 0 }
if bad ~= 1 then domain { 0, 0, 0, 1, 1, 1 } else domain { 0, 0, 1, 1 } end
particles { dr = 0.1 }
scheme "isph-stabilized"
if bad == 1 then
  render { camera = { eye = {0.5, -2}, look_at = {0.5, 0.5} } }
elseif bad == 2 then
  render { camera = { eye = {1, 1, 1}, look_at = {1, 1, 1} } }
elseif bad == 3 then
  render { camera = { eye = {1, 1, 1} } }
elseif bad == 4 then
  render { camera = { eye = {0.5, -2, 1}, look_at = {0.5, 0.5, 0.5}, fov = 500 } }
end
fluid { density = 1000, viscosity = 1e-6, gravity = {0, 0, -9.81} }
box_wall { 0, 0, 0, 1, 1, 1 }
fill { 0, 0, 0, 1, 1, 0.5 }
run { t_end = 0.02, output_every = 0.01 }
if bad == 0 then
  render { field = "p", range = {0, 5000},
           camera = cam == 1 and { eye = {0.5, -1.5, 1.2}, look_at = {0.5, 0.5, 0.25}, fov = 40 }
                    or nil }
end
