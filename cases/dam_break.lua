-- Dam break in a tank (the 2-D set-up of Lobovsky et al. 2014, H = 300 mm; the geometry of
-- ../shared/refdata/lobovsky2014_geometry.md): a water column L = 600 mm long and H = 300 mm
-- high at the upstream end of a tank 1610 mm long collapses at t = 0 (no gate). n particles
-- across the depth (dr = H/n). The surge front runs along the floor; Ritter's ideal (inviscid,
-- frictionless) front speed 2 √(gH) = 3.43 m/s bounds it, and the front reaches the downstream
-- wall at about t √(g/H) = 2.4 (sensor 1's impact in the experiment, t* = 2.44).
-- sample(sim), every `every` seconds (series.csv), records (the fluid "on the floor" is the fluid
-- within 2 dr of it):
--   front                   the largest x of the fluid on the floor
--   front_over_ritter       (front − L)/(2 √(gH) t): the front's mean speed since the release over
--                           Ritter's (its x is L + 2 √(gH) t)
--   bulk_front              the largest x of the fluid on the floor that has at least 4 other fluid
--                           particles within 4 dr (the kernel's support at h = 2 dr): the body of
--                           the surge, without the single particles ahead of it
--   lead_ahead_dr           (front − bulk_front)/dr: how far single particles run ahead
--   floor_speed             the largest speed along the floor (x) of the fluid on the floor over
--                           2 √(gH): nothing on the floor outruns Ritter's front (a particle thrown
--                           along the floor by a bad pressure does, for 0.002 to 0.17 s)
-- and the metrics at the end: those of the last sample, floor_speed_max and lead_ahead_max (the
-- largest over the samples), max_speed_over_sqrt_gH (the largest fluid speed over √(gH) now),
-- volume_ratio (the fluid's volume against the column's), time_star = t √(g/H).
-- --set wcsph=1 runs the weakly-compressible baseline (c0 = 10 · 2 √(gH)); --set riemann=1 runs
-- wcsph-riemann with the same sound speed.
param { n = 20, t_end = 0.4, wcsph = 0, riemann = 0, every = 0.01, cfl = 1,
        tvf = 2, ard = 0 }

local g, H, L, tank, top = 9.81, 0.3, 0.6, 1.61, 1.0
local dr = H / n
local U = 2 * math.sqrt(g * H) -- Ritter's front speed

domain { 0, 0, tank, top }
particles { dr = dr }
if riemann == 1 then
  scheme { "wcsph-riemann", sound_speed = 10 * U, ard = ard,
           transport_velocity = ({"off", "full", "limited"})[tvf + 1] }
elseif wcsph == 1 then
  scheme { "wcsph-usaw", sound_speed = 10 * U }
else
  scheme "isph-usaw"
end
fluid { density = 997, viscosity = 8.9e-7, gravity = {0, -g} }
wall { {0, top}, {0, 0}, {tank, 0}, {tank, top}, fluid = "left", group = "tank" }
fill { 0, 0, L, H, name = "water" }
probe { "sensor_1", {tank - dr, 0.003} }
run { t_end = t_end, output_every = 0.05, sample_every = every, cfl = cfl }

function sample(sim)
  local x, y = sim.field("pos", 1), sim.field("pos", 2)
  local u = sim.field("vel", 1)
  local px, py = x.value, y.value
  -- the fluid on the floor, furthest first
  local floor = {}
  for i = 1, #px do
    if py[i] < 2 * dr then floor[#floor + 1] = i end
  end
  table.sort(floor, function(a, b) return px[a] > px[b] end)
  local front = #floor > 0 and px[floor[1]] or 0
  local speed = 0 -- along the floor
  for _, i in ipairs(floor) do speed = math.max(speed, u.value[i]) end
  -- the body's front: the furthest floor particle with company within the kernel's support
  local bulk, reach2 = 0, (4 * dr) ^ 2
  for _, i in ipairs(floor) do
    local company = 0
    for j = 1, #px do
      if j ~= i and (px[j] - px[i]) ^ 2 + (py[j] - py[i]) ^ 2 < reach2 then company = company + 1 end
    end
    if company >= 4 then
      bulk = px[i]
      break
    end
  end
  return { front = front, front_over_ritter = sim.time > 0 and (front - L) / (U * sim.time) or 0,
           bulk_front = bulk, lead_ahead_dr = (front - bulk) / dr, floor_speed = speed / U }
end

function metrics(sim)
  local m = sample(sim)
  local function largest(name)
    local v = 0
    for _, s in ipairs(sim.series(name).value) do v = math.max(v, s) end
    return v
  end
  m.floor_speed_max = largest("floor_speed")
  m.lead_ahead_max = largest("lead_ahead_dr")
  local top_speed = 0
  for c = 1, 2 do
    top_speed = math.max(top_speed, math.abs(sim.min("vel", c)), math.abs(sim.max("vel", c)))
  end
  m.max_speed_over_sqrt_gH = top_speed / math.sqrt(g * H)
  m.volume_ratio = #sim.field("pos", 1).value * dr * dr / (L * H)
  m.time_star = sim.time * math.sqrt(g / H)
  return m
end
