-- Interpolation at points in 3-D (sim.sample with a point {x, y, z}, profile_error with z =):
-- a tank 1 m wide, dr = 0.1, water 0.5 m deep at rest with its hydrostatic pressure, one step.
-- metrics: the first-order moving least squares (interpolation "linear") of the particles'
-- own positions at a point between them, which it must return exactly (x_err, y_err, z_err,
-- m: the largest of the three), the pressure at mid-depth by both interpolations against
-- ρ g (0.5 − 0.25) (p_shepard_err, p_linear_err, Pa) and a profile of x along a line (RMS and
-- largest against a linear table: 0 but for round-off). what = 1: a point of two coordinates
-- (refused: the scene is 3-D); what = 2: profile_error without z (refused the same way). The
-- profile line "column" (y from 0.15 to 0.85 at x = 0.45, z = 0.25, 8 points) is recorded with
-- its z; line_p_err is the largest |p − ρ g (0.5 − z)| along it. what = 3: a profile that
-- leaves the domain; 4: a profile with 2-D ends.
param { what = 0 }
domain { 0, 0, 0, 1, 1, 1 }
particles { dr = 0.1 }
scheme { "wcsph-riemann", sound_speed = 30 }
fluid { density = 1000, viscosity = 1e-6, gravity = {0, 0, -9.81} }
box_wall { 0, 0, 0, 1, 1, 1, group = "tank" }
fill { 0, 0, 0, 1, 1, 0.5, pressure = function(x, y, z) return 1000 * 9.81 * (0.5 - z) end }
profile { "column", from = {0.45, 0.15, 0.25}, to = {0.45, 0.85, 0.25}, points = 8,
          interpolation = "linear" }
if what == 3 then profile { "out", from = {0.5, 0.5, 0.5}, to = {0.5, 0.5, 1.5} } end
if what == 4 then profile { "flat", from = {0.5, 0.5}, to = {0.5, 0.9} } end
run { t_end = 1e-3 }
function metrics(sim)
  if what == 1 then sim.sample("p", 0.5, 0.25) end
  if what == 2 then
    sim.profile_error { field = "pos", x = 0.5, csv = "tests/case/sample3d_line.csv",
                        coordinate = "y", value = "y" }
  end
  -- what = 5: a coordinate that is NaN; 6: four of them; 7: one that is a string; 8: a line in
  -- the plane z = NaN (each refused, named)
  if what == 5 then sim.sample("p", {0 / 0, 0.5, 0.25}) end
  if what == 6 then sim.sample("p", {0.5, 0.5, 0.25, 1}) end
  if what == 7 then sim.sample("p", {0.5, "a", 0.25}) end
  if what == 8 then
    sim.profile_error { field = "p", x = 0.5, z = 0 / 0, csv = "tests/case/sample3d_line.csv",
                        coordinate = "y", value = "y" }
  end
  local at = {0.43, 0.37, 0.21}
  local e = 0
  local m = {}
  for c, name in ipairs({"x_err", "y_err", "z_err"}) do
    m[name] = math.abs(sim.sample("pos", at, c, "linear") - at[c])
    e = math.max(e, m[name])
  end
  m.max_err = e
  local p0 = 1000 * 9.81 * 0.25
  m.p_shepard = sim.sample("p", {0.5, 0.5, 0.25}); m.p_shepard_err = math.abs(m.p_shepard - p0)
  m.p_linear_err = math.abs(sim.sample("p", {0.5, 0.5, 0.25}, 1, "linear") - p0)
  m.profile_rms, m.profile_max = sim.profile_error { field = "pos", component = 2, x = 0.45,
    z = 0.25, csv = "tests/case/sample3d_line.csv", coordinate = "y", value = "y",
    interpolation = "linear" }
  -- the recorded profile line (profile_column.csv, x, y, z and the sampled fields)
  local t, worst = sim.profile("column", sim.time), 0
  for k = 1, #t.p do
    worst = math.max(worst, math.abs(t.p[k] - 1000 * 9.81 * (0.5 - t.z[k])), math.abs(t.x[k] - 0.45))
  end
  m.line_p_err, m.line_points = worst, #t.p
  return m
end
