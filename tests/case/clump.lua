-- Spray pressed into a clump (isph-stabilized's spray rule, solvers/isph_stabilized): five
-- particles in the air above a tank of water at rest, one with four others 0.55 dr from it (the
-- closest that fills allow: less than dr/2 reads as points given twice), falling. Their kernel
-- sums read more than a full density (s*/σ0 1.1 to 1.4, over the 2-D free-surface threshold 0.97),
-- but each has at most 4 neighbours, fewer than a quarter of a full lattice support's (5 of 20 at
-- h = 1.2 dr): Dirichlet rows. As interior rows the clump would be a block of the pressure
-- equation with no given value, singular (the n = 80 dam break's solve diverged to a residual of
-- 1e107 on such a clump at t = 0.63 s). After `steps` steps: clump_surface, the clump's
-- particles that are free surface (5: all); clump_rho_min, the least s*/σ0 among them (over
-- 0.97: the density test alone would have left them interior).
param { steps = 3 }
local H, W, g, rho = 0.1, 0.2, 9.81, 1000
local dr = 0.01
domain { 0, 0, W, 0.3 }
particles { dr = dr }
scheme "isph-stabilized"
fluid { density = rho, viscosity = 1e-6, gravity = {0, -g} }
wall { {0, 0.3}, {0, 0}, {W, 0}, {W, 0.3}, fluid = "left" }
fill { 0, 0, W, H, name = "water", pressure = function(x, y) return rho * g * (H - y) end }
local cx, cy, s = 0.1, 0.2, 0.55 * dr
fill { name = "clump", points = { {cx, cy}, {cx - s, cy}, {cx + s, cy}, {cx, cy - s},
                                  {cx, cy + s} } }
run { dt = 1e-4, t_end = steps * 1e-4, output_every = steps * 1e-4 }

function metrics(sim)
  local y = sim.field("pos", 2).value
  local fs = sim.field("free_surface").value
  local rs = sim.field("rho_star").value
  local n, rmin = 0, math.huge
  for i = 1, #y do
    if y[i] > 0.15 then
      if fs[i] > 0.5 then n = n + 1 end
      rmin = math.min(rmin, rs[i])
    end
  end
  return { clump_surface = n, clump_rho_min = rmin }
end
