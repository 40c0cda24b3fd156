-- Plane Couette flow between a fixed floor and a ceiling sliding at U, periodic in x: the steady
-- wall shear stress is µ U / H, so the fluid drags the floor with F_x = +µ U L / H per unit
-- length (and the ceiling with −µ U L / H), all of it viscous: the check of the sign and size of
-- the viscous wall force (Leroy et al. 2014 eqs 69-70). t_end = 1 is 1 viscous time H²/ν: the
-- start-up transient has decayed to e^(−π²) ≈ 5e-5 of U.
param { n = 10, t_end = 1, wcsph = 0 }

local L, H, U, nu, rho = 1.5, 1, 1, 1, 1
domain { 0, 0, L, H, periodic = "x" }
particles { dr = H / n }
if wcsph == 1 then scheme "wcsph-usaw" else scheme "isph-usaw" end
fluid { density = rho, viscosity = nu }
wall { {L, 0}, {0, 0}, fluid = "right", group = "floor" }
wall { {0, H}, {L, H}, fluid = "right", group = "ceiling", velocity = {U, 0} }
fill { 0, 0, L, H }
force { "floor", "ceiling" }
run { t_end = t_end, output_every = t_end / 4 }

function metrics(sim)
  local exact = rho * nu * U * L / H
  local floor, ceiling = sim.force("floor"), sim.force("ceiling")
  return { floor_error = math.abs(floor.x - exact) / exact,
           ceiling_error = math.abs(ceiling.x + exact) / exact,
           floor_pressure_x = math.abs(floor.pressure_x) / exact }
end
