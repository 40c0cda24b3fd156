-- Hydrostatic tanks with shaped floors (the stabilized ISPH paper, sec 4.1 and its fig 4, here in
-- 2-D): water 0.2 m deep at rest in a tank 0.2 m wide, with dr = 0.005 m (the paper's second
-- resolution). The paper's objects are a semi-hemisphere, a pyramid and a rectangular pit; their
-- sizes are not given, so these are ours:
--   shape = 1: a semicircular bump of radius 0.05 m in the middle of the floor (convex on top,
--              concave where it meets the floor: the fluid there has a 90° corner);
--   shape = 2: a pyramid (45° flanks, base 0.08 m, height 0.04 m: its apex is a convex 90° corner
--              of the solid) and, beside it, a rectangular pit 0.04 m wide and 0.03 m deep
--              (concave at its bottom corners, convex at its rim).
-- The floor is one wall polyline with the tank's sides. The fluid is the lattice above it, less
-- the points closer than dr/2 to the floor (as obstacles are carved out of a fill): next to a
-- slope or an arc the first row therefore stands between dr/2 and about dr off the wall.
-- stab = 1 (default) runs isph-stabilized (neumann = 1: the modified virtual marker's Neumann wall
-- pressure, 0: pseudo-Neumann; alpha, cfl as in hydrostatic.lua); stab = 0 runs isph-usaw on the
-- same floor. dyn = 1 gives isph-stabilized pressure_form = "dynamic" (its pressure equation solved
-- for p − ρ0 g·x). Every run starts from ρ g (H − y).
-- Metrics, all relative to ρ g H and against ρ g (H − y), over the samples (40 a run) of the run's
-- second half and at the end:
--   fluid_error: the RMS over the fluid deeper than 3 dr below the surface (the whole fluid);
--   wall_error / wall_bias: the largest and the mean error over the fluid within 3 dr of the floor;
--   concave_bias / convex_bias: the mean error over the fluid within 3 dr of the concave corners
--   (the tank's two, the bump's feet, the pyramid's feet, the pit's bottom corners) and of the
--   convex ones (the bump's arc away from its feet, the pyramid's apex, the pit's rim);
--   bottom_centre: the mean pressure of the fluid within 1.5 dr of x = W/2 and 3 dr of the floor
--   there against ρ g (H − y) (the paper's measuring point, the middle of the bottom);
--   speed_ratio: the largest speed over √(g H); crossed_wall: steps with a particle behind a wall.
param { dr = 0.005, t_end = 1, shape = 1, clear = 0.3, stab = 1, neumann = 1, alpha = 0.01, cfl = 1,
        scan = 1, dyn = 0 }
for k, v in pairs({ stab = stab, neumann = neumann, scan = scan, dyn = dyn }) do
  if v ~= 0 and v ~= 1 then error(("hydrostatic_shapes: %s must be 0 or 1, not %g"):format(k, v)) end
end
if dyn == 1 and stab ~= 1 then
  error("hydrostatic_shapes: dyn = 1 needs stab = 1 (isph-stabilized's pressure_form)")
end
if shape ~= 1 and shape ~= 2 then
  error(("hydrostatic_shapes: shape must be 1 (the semicircular bump) or 2 (the pyramid and the " ..
         "pit), not %g"):format(shape))
end

local g, rho, depth, width = 9.81, 1000, 0.2, 0.2
local pit_depth = 0.03
-- the floor y = 0 and the pit's bottom sit on lattice lines (the lattice starts at the domain's
-- lower edge, y = −pit_depth)
local rows = pit_depth / dr
if math.abs(rows - math.floor(rows + 0.5)) > 1e-9 then
  error(("hydrostatic_shapes: dr = %g must divide the pit's depth %g m"):format(dr, pit_depth))
end

-- the floor, left to right (the fluid above it, on its left), and the corner points
local floor, concave, convex = {}, { {0, 0}, {width, 0} }, {}
local function add(x, y) floor[#floor + 1] = {x, y} end
if shape == 1 then
  local c, r = width / 2, 0.05
  local n = math.ceil(math.pi * r / dr) -- edges of about dr (USAW wants its vertices dr apart)
  add(0, 0)
  for k = 0, n do
    local a = math.pi * (1 - k / n)
    add(c + r * math.cos(a), r * math.sin(a))
    -- the arc's points between 30° and 150° are its convex part
    if a > math.pi / 6 and a < 5 * math.pi / 6 then convex[#convex + 1] = floor[#floor] end
  end
  concave[#concave + 1] = {c - r, 0}
  concave[#concave + 1] = {c + r, 0}
  add(width, 0)
else
  -- the pyramid's feet off the lattice lines x = (k + 1/2) dr, so that no lattice point lies on
  -- its flanks
  local x0, b, pit0, pw = 0.0225, 0.08, 0.1325, 0.04
  add(0, 0); add(x0, 0); add(x0 + b / 2, b / 2); add(x0 + b, 0)
  add(pit0, 0); add(pit0, -pit_depth); add(pit0 + pw, -pit_depth); add(pit0 + pw, 0)
  add(width, 0)
  concave[#concave + 1] = {x0, 0}
  concave[#concave + 1] = {x0 + b, 0}
  concave[#concave + 1] = {pit0, -pit_depth}
  concave[#concave + 1] = {pit0 + pw, -pit_depth}
  convex[#convex + 1] = {x0 + b / 2, b / 2}
  convex[#convex + 1] = {pit0, 0}
  convex[#convex + 1] = {pit0 + pw, 0}
end

-- the distance from (x, y) to the floor polyline
local function floor_distance(x, y)
  local best = math.huge
  for k = 1, #floor - 1 do
    local ax, ay, bx, by = floor[k][1], floor[k][2], floor[k + 1][1], floor[k + 1][2]
    local tx, ty = bx - ax, by - ay
    local t = math.max(0, math.min(1, ((x - ax) * tx + (y - ay) * ty) / (tx * tx + ty * ty)))
    best = math.min(best, math.sqrt((x - ax - t * tx) ^ 2 + (y - ay - t * ty) ^ 2))
  end
  return best
end
-- the floor's height under x (each shape is a graph over x; the pit's walls are vertical)
local function floor_height(x)
  if shape == 1 then
    local d = x - width / 2
    return math.abs(d) < 0.05 and math.sqrt(0.05 ^ 2 - d * d) or 0
  end
  for k = 1, #floor - 1 do
    local ax, ay, bx, by = floor[k][1], floor[k][2], floor[k + 1][1], floor[k + 1][2]
    if bx > ax and x >= ax and x < bx then return ay + (by - ay) * (x - ax) / (bx - ax) end
  end
  return 0
end

local function near_any(points, x, y, reach)
  for _, q in ipairs(points) do
    if (x - q[1]) ^ 2 + (y - q[2]) ^ 2 < reach * reach then return true end
  end
  return false
end

domain { 0, -pit_depth, width, 1.5 * depth }
particles { dr = dr }
if stab == 1 then
  scheme { "isph-stabilized", alpha = alpha,
           wall_pressure = neumann == 1 and "neumann" or "pseudo_neumann",
           surface_detection = scan == 1 and "scan" or "density",
           pressure_form = dyn == 1 and "dynamic" or "total" }
else
  scheme { "isph-usaw" }
end
fluid { density = rho, viscosity = 1e-6, gravity = {0, -g} }
local wall_pts = { {0, 1.5 * depth} }
for _, q in ipairs(floor) do wall_pts[#wall_pts + 1] = q end
wall_pts[#wall_pts + 1] = {width, 1.5 * depth}
wall_pts.fluid, wall_pts.group = "left", "tank"
wall(wall_pts)

-- the lattice points above the floor and below the surface, at least dr/2 from the floor
local water = {}
for j = 0, math.floor((depth + pit_depth) / dr) - 1 do
  local y = -pit_depth + (j + 0.5) * dr
  for i = 0, math.floor(width / dr) - 1 do
    local x = (i + 0.5) * dr
    if y > floor_height(x) and floor_distance(x, y) > (clear - 1e-6) * dr then
      water[#water + 1] = {x, y}
    end
  end
end
fill { points = water, name = "water",
       pressure = function(x, y) return rho * g * (depth - y) end }
run { t_end = t_end, output_every = t_end / 10, cfl = cfl, sample_every = t_end / 40 }

-- the errors of the fluid particles now, relative to ρ g H
local function errors(sim)
  local f = sim.field("p")
  local s = { fluid = 0, nf = 0, wall = 0, wall_sum = 0, nw = 0, cc = 0, ncc = 0, cv = 0, ncv = 0,
              centre = 0, nc = 0 }
  for i = 1, #f.value do
    local x, y = f.x[i], f.y[i]
    local e = (f.value[i] - rho * g * (depth - y)) / (rho * g * depth)
    if y < depth - 3 * dr then s.fluid, s.nf = s.fluid + e * e, s.nf + 1 end
    if floor_distance(x, y) < 3 * dr then
      s.wall, s.wall_sum, s.nw = math.max(s.wall, math.abs(e)), s.wall_sum + e, s.nw + 1
      if math.abs(x - width / 2) < 1.5 * dr then s.centre, s.nc = s.centre + e, s.nc + 1 end
    end
    if near_any(concave, x, y, 3 * dr) then s.cc, s.ncc = s.cc + e, s.ncc + 1 end
    if near_any(convex, x, y, 3 * dr) then s.cv, s.ncv = s.cv + e, s.ncv + 1 end
  end
  local function mean(a, n) return a / math.max(n, 1) end
  return { fluid_error = math.sqrt(mean(s.fluid, s.nf)), wall_error = s.wall,
           wall_bias = mean(s.wall_sum, s.nw), concave_bias = mean(s.cc, s.ncc),
           convex_bias = mean(s.cv, s.ncv), bottom_centre = mean(s.centre, s.nc) }
end

function sample(sim) return errors(sim) end

function metrics(sim)
  local m = errors(sim)
  -- the same errors averaged over the samples of the run's second half
  for _, k in ipairs({ "fluid_error", "wall_error", "wall_bias", "concave_bias", "convex_bias",
                       "bottom_centre" }) do
    local s, sum, n = sim.series(k), 0, 0
    for i = 1, #s.time do
      if s.time[i] >= t_end / 2 then sum, n = sum + s.value[i], n + 1 end
    end
    m[k .. "_avg"] = sum / math.max(n, 1)
  end
  local speed = 0
  for c = 1, 2 do
    speed = math.max(speed, math.abs(sim.min("vel", c)), math.abs(sim.max("vel", c)))
  end
  m.speed_ratio = speed / math.sqrt(g * depth)
  -- steps at which a fluid particle was found behind a wall (checked every step by the walls), and
  -- a particle below the floor now
  local crossed = sim.wall_crossing_steps
  local f = sim.field("p")
  for i = 1, #f.value do
    if f.x[i] < 0 or f.x[i] > width or f.y[i] < floor_height(f.x[i]) then
      crossed = crossed + 1
      break
    end
  end
  m.crossed_wall = crossed
  return m
end
