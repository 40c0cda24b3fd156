-- Hydrostatic tank in 3-D: water at rest in a box tank (width x width, depth of water, gravity
-- along −z), with isph-stabilized and its virtual-marker dummy walls (Asai et al. 2012, 2013; the
-- seed paper's 2-D tank of sec 4.1 in a box). The fluid starts from ρ g (H − z), as the 2-D tank
-- (cases/hydrostatic.lua) does.
-- Metrics, on the fluid particles against ρ g (H − z):
--   pressure_error: the largest |p − ρ g (H − z)| / (ρ g (H − z)) over the particles deeper than
--     3 dr below the surface (the issue's "within 1% below 3 δr"), and pressure_rms its RMS;
--   bottom_error, bottom_bias: the largest and the mean error relative to ρ g H of the particles
--     within 3 dr of the floor; *_avg their means over the samples of the run's second half;
--   speed_ratio: the largest speed over √(g H);
--   crossed_wall: steps at which a fluid particle was behind a wall, plus 1 when one is outside
--     the tank's box at the end (and, with round, sphere or pillar, 1 when one is inside a solid);
--   inside_depth: with round, sphere or pillar, how far the deepest fluid particle lies past the
--     curved face into its solid at the end, in dr (0: none; wcsph-riemann has no crossing check
--     of its own).
-- neumann = 0 takes the pseudo-Neumann walls (S sec 3.2), alpha the relaxation coefficient, dyn = 1
-- the pressure form "dynamic" (the pressure equation solved for p − ρ0 g·x), shift = C > 0 the
-- particle shifting, scan = 1 the scan-region free-surface test, beta_fs the free-surface threshold
-- (0: the scheme's, 0.9 in 3-D), checkpoint the seconds between checkpoints (0: at the end only),
-- block = 1 the block on the floor (below). With the block, "the floor" of bottom_* is the tank's
-- floor and the block's top (particles within 3 dr above either), its error relative to ρ g H.
-- Curved walls: round = 1 makes the tank a vertical cylinder `width` across (cylinder_wall, the
-- water a cylinder fill); sphere = 1 holds a sphere depth/2 across at mid-depth (sphere_wall {
-- fluid = "outside" }), pillar = 1 a cylinder 0.4 width across from the floor to the lid (its caps
-- lie on the tank's faces and face no water). stl = 1 makes the sphere of sphere = 1 from a
-- triangulated surface instead (stl_wall: cases/stl/sphere.stl, 1280 facets on the unit sphere,
-- scaled and placed). The floor of bottom_* stays the tank's.
-- riemann = 1 runs wcsph-riemann instead (its dummy walls, c0 = 10 √(2 g H), the density re-set
-- as a free-surface flow's; the other scheme options do not apply to it).
param { dr = 0.02, t_end = 1, depth = 0.2, width = 0.2, neumann = 1, alpha = 0.01, layers = 3,
        cfl = 1, start_p = 1, shift = 0, scan = 0, beta_fs = 0, dyn = 0, checkpoint = 0, block = 0,
        riemann = 0, round = 0, sphere = 0, pillar = 0, stl = 0 }
for k, v in pairs({ neumann = neumann, start_p = start_p, scan = scan, dyn = dyn, block = block,
                    riemann = riemann, round = round, sphere = sphere, pillar = pillar, stl = stl }) do
  if v ~= 0 and v ~= 1 then error(("hydrostatic3d: %s must be 0 or 1, not %g"):format(k, v)) end
end

local g = 9.81
domain { 0, 0, 0, width, width, 1.5 * depth }
particles { dr = dr }
if riemann == 1 then
  scheme { "wcsph-riemann", wall_layers = layers }
else
  scheme { "isph-stabilized", alpha = alpha,
           wall_pressure = neumann == 1 and "neumann" or "pseudo_neumann", wall_layers = layers,
           shifting = shift > 0 and shift or nil,
           surface_detection = scan == 1 and "scan" or "density",
           surface_threshold = beta_fs > 0 and beta_fs or nil,
           pressure_form = dyn == 1 and "dynamic" or "total" }
end
fluid { density = 1000, viscosity = 1e-6, gravity = {0, 0, -g} }
local c = width / 2
if round == 1 then
  cylinder_wall { c, c, 0, c, c, 1.5 * depth, c, group = "tank" }
else
  box_wall { 0, 0, 0, width, width, 1.5 * depth, group = "tank" }
end
if sphere == 1 and stl == 1 then
  stl_wall { "stl/sphere.stl", scale = depth / 4, offset = {c, c, depth / 2}, fluid = "outside",
             group = "ball" }
elseif sphere == 1 then
  sphere_wall { c, c, depth / 2, depth / 4, fluid = "outside", group = "ball" }
end
if pillar == 1 then
  cylinder_wall { c, c, 0, c, c, 1.5 * depth, width / 5, fluid = "outside", group = "pillar" }
end
-- block = 1: a block 6 dr wide and tall on the middle of the floor (an obstacle: its top and
-- sides face the water, its bottom lies on the floor)
local b0, b1 = width / 2 - 3 * dr, width / 2 + 3 * dr
if block == 1 then box_wall { b0, b0, 0, b1, b1, 6 * dr, fluid = "outside", group = "block" } end
local p_start = start_p == 1 and function(x, y, z) return 1000 * g * (depth - z) end or nil
if round == 1 then
  fill { cylinder = { c, c, 0, c, c, depth, c }, name = "water", pressure = p_start }
else
  fill { 0, 0, 0, width, width, depth, name = "water", pressure = p_start }
end
run { t_end = t_end, output_every = t_end / 4, cfl = cfl, sample_every = t_end / 20,
      checkpoint_every = checkpoint }

local function errors(sim)
  local f = sim.field("p", 1, "fluid")
  local worst, sq, n, bworst, bias, nb = 0, 0, 0, 0, 0, 0
  for i = 1, #f.value do
    local z = f.z[i]
    local exact = 1000 * g * (depth - z)
    if z < depth - 3 * dr then
      local e = math.abs(f.value[i] - exact) / exact
      worst, sq, n = math.max(worst, e), sq + e * e, n + 1
    end
    local on_block = block == 1 and f.x[i] > b0 and f.x[i] < b1 and f.y[i] > b0 and f.y[i] < b1
    if z < 3 * dr or (on_block and z < 9 * dr) then
      local e = (f.value[i] - exact) / (1000 * g * depth)
      bworst, bias, nb = math.max(bworst, math.abs(e)), bias + e, nb + 1
    end
  end
  return worst, math.sqrt(sq / math.max(n, 1)), bworst, bias / math.max(nb, 1)
end

function sample(sim)
  local _, _, bworst, bias = errors(sim)
  return { bottom_error = bworst, bottom_bias = bias }
end

function metrics(sim)
  local worst, rms, bworst, bias = errors(sim)
  local speed = 0
  for c = 1, 3 do
    speed = math.max(speed, math.abs(sim.min("vel", c, "fluid")), math.abs(sim.max("vel", c, "fluid")))
  end
  local crossed = sim.wall_crossing_steps
  for a = 1, 3 do
    local top = a == 3 and 1.5 * depth or width
    if sim.min("pos", a, "fluid") < 0 or sim.max("pos", a, "fluid") > top then
      crossed = crossed + 1
    end
  end
  local inside = 0
  if round + sphere + pillar > 0 then -- fluid outside the round tank or in a solid
    local f = sim.field("p", 1, "fluid")
    for i = 1, #f.value do
      local r = math.sqrt((f.x[i] - c) ^ 2 + (f.y[i] - c) ^ 2)
      local rs = math.sqrt(r * r + (f.z[i] - depth / 2) ^ 2)
      if round == 1 then inside = math.max(inside, r - c) end
      if pillar == 1 then inside = math.max(inside, width / 5 - r) end
      if sphere == 1 then inside = math.max(inside, depth / 4 - rs) end
    end
    if inside > 0 then crossed = crossed + 1 end
  end
  if block == 1 then -- a fluid particle inside the block
    local f = sim.field("p", 1, "fluid")
    for i = 1, #f.value do
      if f.x[i] > b0 and f.x[i] < b1 and f.y[i] > b0 and f.y[i] < b1 and f.z[i] < 6 * dr then
        crossed = crossed + 1
        break
      end
    end
  end
  local tb, eb, bb = sim.series("bottom_bias"), sim.series("bottom_error"), {0, 0, 0}
  for k = 1, #tb.time do
    if tb.time[k] >= t_end / 2 then bb = {bb[1] + tb.value[k], bb[2] + eb.value[k], bb[3] + 1} end
  end
  return { pressure_error = worst, pressure_rms = rms, bottom_error = bworst, bottom_bias = bias,
           bottom_bias_avg = bb[1] / math.max(bb[3], 1),
           bottom_error_avg = bb[2] / math.max(bb[3], 1),
           speed_ratio = speed / math.sqrt(g * depth), crossed_wall = crossed,
           inside_depth = inside / dr }
end
