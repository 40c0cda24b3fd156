-- The walls' force record against the fluid's momentum (wcsph-riemann: force.cl). A periodic
-- channel under a fixed body force f, started from a jittered parabola (±jitter U in both
-- components), so that the first rows are disordered and the dummies' pressure pairs push along
-- x as well as the viscous ones. The fluid's own pairs cancel (their forces are antisymmetric), so
-- over each step M ΔU = Δt (M f − F_x), F_x the x force that the walls record for that step (floor
-- and ceiling): the record must be what the fluid felt in the step's sub-steps. The series
-- samples every step (sample_every below any step).
-- balance_max: the largest |M ΔU/Δt − M f + F_x| over the steps, over M f;
-- balance_mean: the same without the absolute value, averaged (a bias);
-- wall_share: the steps' mean |F_x| over M f (the record is not trivially small).
-- turb = 1 adds the k-ε model and its wall model (eq 39's shear instead of the no-slip drag);
-- ard = 1 switches ARD on (the walls' Riemann viscosity in the sub-steps).
param { n = 10, t_end = 0.5, turb = 0, ard = 0, seed = 1, jitter = 0.1, cont = 0 }
local dens = cont == 1 and "continuity" or "summation"

if n < 4 or n ~= math.floor(n) then error("wall_momentum: n must be an integer >= 4") end
if math.tointeger(seed) == nil then error("wall_momentum: seed must be an integer") end
local H, L, U = 1, 1, 1
local nu = turb == 1 and 1e-4 or 0.01 -- k-ε: the first row at y+ = 55
local f = 0.08 -- the laminar channel's Poiseuille drive of a centreline speed U
domain { 0, 0, L, H, periodic = "x" }
particles { dr = H / n }
scheme { "wcsph-riemann", sound_speed = 16, ard = ard,
         transport_velocity = "limited", density = dens }
fluid { density = 1, viscosity = nu, body_force = {f, 0} }
if turb == 1 then
  local dr = H / n
  turbulence { model = "k-epsilon", y_p = dr, k = 0.01, epsilon = 0.002 }
end
wall { {L, 0}, {0, 0}, fluid = "right", group = "floor" }
wall { {0, H}, {L, H}, fluid = "right", group = "ceiling" }
math.randomseed(math.tointeger(seed))
local function jit() return jitter * U * (2 * math.random() - 1) end
fill { 0, 0, L, H, velocity = function(x, y) return 6 * U * y * (H - y) / (H * H) + jit(), jit() end }
force { "floor", "ceiling" }
run { t_end = t_end, output_every = t_end, sample_every = 1e-9 }

function sample(sim)
  return { u = sim.mean("vel", 1) - U } -- less U: the CSV keeps 9 digits of the change
end

function metrics(sim)
  local s = sim.series("u")
  local fl, ce = sim.force_history("floor"), sim.force_history("ceiling")
  local m = #sim.field("vel", 1).value * (H / n) ^ 2 -- the fluid's mass (ρ = 1)
  if #s.time ~= #fl.time or #s.time < 3 then
    error(("wall_momentum: %d samples of u against %d of the forces"):format(#s.time, #fl.time))
  end
  local worst, bias, share, steps = 0, 0, 0, 0
  for j = 2, #s.time do
    if math.abs(fl.time[j] - s.time[j]) > 1e-12 then error("wall_momentum: unmatched samples") end
    local dt = s.time[j] - s.time[j - 1]
    local fx = fl.x[j] + ce.x[j]
    local r = (m * (s.value[j] - s.value[j - 1]) / dt - m * f + fx) / (m * f)
    worst, bias, share = math.max(worst, math.abs(r)), bias + r, share + math.abs(fx) / (m * f)
    steps = steps + 1
  end
  return { balance_max = worst, balance_mean = bias / steps, wall_share = share / steps,
           steps_checked = steps }
end
