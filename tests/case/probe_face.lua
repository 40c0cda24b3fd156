-- Face probes (probe { "name", {x0, y0}, {x1, y1} }): a shear layer u = y carried unchanged by the
-- ballistic scheme (no force; tests/case/fill_velocity.lua), sampled at the end.
--   face_error      a face across the layer (y = 0.1 to 0.4, points from dr: 24) against the
--                   mean of sim.sample at the midpoints of 24 equal parts (the definition)
--   face_exact      the same face against the layer's mean over it, 0.25 (interpolation error)
--   points_error    a face with points = 6 that crosses the layer's surface (y = 0.3 to 0.9)
--                   against the mean of the samples with fluid within the support (its dry
--                   points, NaN, left out)
--   dry             1 when a face above the layer (no fluid within the support) reads NaN
--   point_error     a point probe against sim.sample at its point
param { dr = 0.05, t_end = 0.1 }
domain { 0, -0.5, 1, 1.5, periodic = "x" }
particles { dr = dr }
scheme "ballistic"
fluid { density = 1000 }
wall { {1, -0.2}, {0, -0.2}, fluid = "right" }
wall { {0, 1.2}, {1, 1.2}, fluid = "right" }
fill { 0, 0, 1, 0.5, name = "shear", velocity = function(x, y) return y, 0 end }
probe { "across", {0.5, 0.1}, {0.5, 0.4} }
probe { name = "surface", from = {0.3, 0.3}, to = {0.3, 0.9}, points = 6 }
probe { "above", {0.5, 0.8}, {0.7, 0.9} }
probe { "point", {0.45, 0.27} }
run { t_end = t_end, output_every = t_end }

-- The mean of sim.sample("vel") at the midpoints of n equal parts of a face, of those not NaN.
local function midpoint_mean(sim, a, b, n)
  local sum, wet = 0, 0
  for k = 0, n - 1 do
    local s = (k + 0.5) / n
    local v = sim.sample("vel", a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2]))
    if v == v then sum, wet = sum + v, wet + 1 end
  end
  return sum / wet
end

function metrics(sim)
  local across = sim.probe("across", "vel")
  local surface = sim.probe("surface", "vel")
  local above = sim.probe("above", "vel")
  return { face_error = math.abs(across - midpoint_mean(sim, {0.5, 0.1}, {0.5, 0.4}, 24)),
           face_exact = math.abs(across - 0.25),
           points_error = math.abs(surface - midpoint_mean(sim, {0.3, 0.3}, {0.3, 0.9}, 6)),
           dry = above ~= above and 1 or 0,
           point_error = math.abs(sim.probe("point", "vel") - sim.sample("vel", 0.45, 0.27)) }
end
