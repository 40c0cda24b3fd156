-- Dam break in a tank (the 2-D set-up of Lobovsky et al. 2014, H = 300 mm; the geometry of
-- ../shared/refdata/lobovsky2014_geometry.md): a water column L = 600 mm long and H = 300 mm
-- high at the upstream end of a tank 1610 mm long collapses at t = 0 (no gate). n particles
-- across the depth (dr = H/n). The surge front runs along the floor; Ritter's ideal (inviscid,
-- frictionless) front speed 2 √(gH) = 3.43 m/s bounds it, and the front reaches the downstream
-- wall at about t √(g/H) = 2.4 (sensor 1's impact in the experiment, t* = 2.44).
-- Metrics at the end: the front (the largest x of the fluid on the floor, within 2 dr of it) and
-- the largest fluid speed, both over √(gH); the fluid's volume against the column's.
-- --set wcsph=1 runs the weakly-compressible baseline (c0 = 10 · 2 √(gH)).
param { n = 20, t_end = 0.4, wcsph = 0 }

local g, H, L, tank, top = 9.81, 0.3, 0.6, 1.61, 1.0
local dr = H / n

domain { 0, 0, tank, top }
particles { dr = dr }
if wcsph == 1 then
  scheme { "wcsph-usaw", sound_speed = 20 * math.sqrt(g * H) }
else
  scheme "isph-usaw"
end
fluid { density = 997, viscosity = 8.9e-7, gravity = {0, -g} }
wall { {0, top}, {0, 0}, {tank, 0}, {tank, top}, fluid = "left", group = "tank" }
fill { 0, 0, L, H, name = "water" }
probe { "sensor_1", {tank - dr, 0.003} }
run { t_end = t_end, output_every = 0.05 }

function metrics(sim)
  local f = sim.field("pos", 1)
  local y = sim.field("pos", 2)
  local front = 0
  for i = 1, #f.value do
    if y.value[i] < 2 * dr then front = math.max(front, f.value[i]) end
  end
  local speed = 0
  for c = 1, 2 do
    speed = math.max(speed, math.abs(sim.min("vel", c)), math.abs(sim.max("vel", c)))
  end
  local U = math.sqrt(g * H)
  return { front = front, front_over_H = (front - L) / H, max_speed_over_sqrt_gH = speed / U,
           volume_ratio = #f.value * dr * dr / (L * H),
           time_star = sim.time * math.sqrt(g / H) }
end
