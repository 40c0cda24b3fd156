-- Plane Couette flow between a fixed floor and a ceiling sliding at U, periodic in x: the steady
-- wall shear stress is µ U / H, so the fluid drags the floor with F_x = +µ U L / H per unit
-- length (and the ceiling with −µ U L / H), all of it viscous: the check of the sign and size of
-- the viscous wall force (Leroy et al. 2014 eqs 69-70). t_end = 1 is 1 viscous time H²/ν: the
-- start-up transient has decayed to e^(−π²) ≈ 5e-5 of U. The particles' velocities against the
-- exact u = U y / H: u_err_max, the largest |u − U y/H| / U over the fluid; slip, the first rows'
-- mean (u − U y/H)/U next to the floor less that next to the ceiling, halved (the slip of the
-- viscous wall term, usaw/viscous.cl; 0 exactly). floor sets the scheme option
-- wall_distance_floor (0: the scheme's default). interp_shepard and interp_linear: the largest
-- |u − U y/H| / U of the velocity sampled (sim.sample) at 40 heights across the channel, by
-- Shepard's average and by first-order moving least squares: within h of a wall Shepard's
-- support is cut and it returns the mean of the particles above (or below) the point; the
-- linear fit is exact for this linear profile, so it reads the particles' own error.
param { n = 10, t_end = 1, wcsph = 0, floor = 0 }

local L, H, U, nu, rho = 1.5, 1, 1, 1, 1
domain { 0, 0, L, H, periodic = "x" }
particles { dr = H / n }
local wdf = floor > 0 and floor or nil
if wcsph == 1 then scheme { "wcsph-usaw", wall_distance_floor = wdf }
else scheme { "isph-usaw", wall_distance_floor = wdf } end
fluid { density = rho, viscosity = nu }
wall { {L, 0}, {0, 0}, fluid = "right", group = "floor" }
wall { {0, H}, {L, H}, fluid = "right", group = "ceiling", velocity = {U, 0} }
fill { 0, 0, L, H }
force { "floor", "ceiling" }
run { t_end = t_end, output_every = t_end / 4 }

function metrics(sim)
  local exact = rho * nu * U * L / H
  local floor, ceiling = sim.force("floor"), sim.force("ceiling")
  local y, u = sim.field("pos", 2).value, sim.field("vel", 1).value
  local dr, err, lo, nlo, hi, nhi = H / n, 0, 0, 0, 0, 0
  for i = 1, #u do
    local d = (u[i] - U * y[i] / H) / U
    err = math.max(err, math.abs(d))
    if y[i] < dr then lo, nlo = lo + d, nlo + 1 end
    if y[i] > H - dr then hi, nhi = hi + d, nhi + 1 end
  end
  local shep, lin = 0, 0
  for k = 0, 39 do
    local yk = (k + 0.5) * H / 40
    shep = math.max(shep, math.abs(sim.sample("vel", L / 2, yk, 1) - U * yk / H) / U)
    lin = math.max(lin, math.abs(sim.sample("vel", L / 2, yk, 1, "linear") - U * yk / H) / U)
  end
  return { interp_shepard = shep, interp_linear = lin, floor_error = math.abs(floor.x - exact) / exact,
           ceiling_error = math.abs(ceiling.x + exact) / exact,
           floor_pressure_x = math.abs(floor.pressure_x) / exact,
           u_err_max = err, slip = 0.5 * (lo / nlo - hi / nhi) }
end
