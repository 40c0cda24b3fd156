-- Water spilling out of an open tank: a column H = 0.2 m high and 0.1 m long at the left end of
-- a tank 0.3 m long whose walls are 0.22 m high (the domain's top); the surge runs up the right
-- wall and part of it goes over and out of the domain. The fluid that leaves is dropped and
-- counted (summary.json escaped, host/sim/checks.c) and the run goes on, until more than
-- `escaped` of the fluid (run { checks }) has left; checkpoint: s between checkpoints. method:
-- 0 isph-usaw, 1 isph-stabilized, 2 wcsph-riemann; cluster: the clustered fraction that stops the
-- run (checks.cluster_fraction: the dummy-wall schemes' coarse surge pairs particles at 0.1 dr).
param { method = 0, n = 10, t_end = 0.6, escaped = 0.5, checkpoint = 0.45, cluster = 0.005,
        bad_metrics = 0 }
local H, L, tank, top, g = 0.2, 0.1, 0.3, 0.22, 9.81
local dr = L / n
domain { 0, 0, tank, top }
particles { dr = dr }
if method == 1 then
  scheme "isph-stabilized"
elseif method == 2 then
  scheme { "wcsph-riemann", sound_speed = 20 * math.sqrt(g * H) }
else
  scheme "isph-usaw"
end
fluid { density = 1000, viscosity = 1e-6, gravity = {0, -g} }
wall { {0, top}, {0, 0}, {tank, 0}, {tank, top}, fluid = "left", group = "tank" }
fill { 0, 0, L, H, name = "water",
       pressure = method == 1 and function(x, y) return 1000 * g * (H - y) end or nil }
run { t_end = t_end, output_every = 0.1, checkpoint_every = checkpoint,
      checks = { escaped = escaped, cluster_fraction = cluster } }

-- fluid_now: the fluid particles left; lost_vs_escaped: those missing from the column's less
-- the count the run dropped (0: every missing one was counted); outside: fluid left outside the
-- tank's box (0: what went over the wall was dropped); stopped: 1 when the run stopped early (a
-- metrics() of the state it stopped in, sim.stopped its failure class), else 0; bad_metrics = 1:
-- metrics() raises an error
local column = math.floor(L / dr + 0.5) * math.floor(H / dr + 0.5)
function metrics(sim)
  if bad_metrics == 1 then error("metrics() refuses the state") end
  local y = sim.field("pos", 2).value
  local x = sim.field("pos", 1).value
  local inside = 0
  for i = 1, #x do
    if x[i] >= 0 and x[i] <= tank and y[i] >= 0 then inside = inside + 1 end
  end
  return { fluid_now = #x, outside = #x - inside, lost_vs_escaped = column - #x - sim.escaped,
           escaped = sim.escaped, stopped = sim.stopped == "escaped" and 1 or 0 }
end
