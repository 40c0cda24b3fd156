-- The k-ε wall model's stress on a first row short of particles (wcsph-riemann, Wang, Sun & Hu
-- sec 4.2): a channel periodic along x, 20 rows across (dr = 0.1, y_p = dr/2: the first row at
-- y_p, no boundary offset), u = 1, k and ε uniform; the floor's first row lacks `holes`
-- neighbouring particles of its 10, the ceiling's is whole; with lift = 1 the floor's last
-- column has one particle at 1.7 dr for its second and third rows, beyond the wall model's
-- P_ext (d < 2h − dr = 1.6 dr) but within the dummies' reach (2h − dr/2). Every first-row
-- particle reads the same τ_w from the log law at y_p (eqs 10-12), so that the wall carries
-- τ_w ρ L whatever its first row holds, where each particle takes τ_w over its share of the
-- wall and no other particle takes the dummies' no-slip drag (wall_shear = "first_row", shear =
-- 2): eq 39's sums follow the particles, and the floor's record fell by the missing particles'
-- share; the lifted particle adds the dummies' no-slip drag.
-- Metrics: floor_over_law and ceiling_over_law, the walls' recorded viscous x force (the mean
-- over the run, which a few steps barely move) over τ_w ρ L, less 1; first_row, the floor's
-- first-row particles at the start.
param { shear = 2, holes = 1, lift = 0, t_end = 0.001 }
local dr, y_p, H, L, nu = 0.1, 0.05, 2.0, 1.0, 1e-4
local k0 = 3.75e-3
local cmu, kappa, E = 0.09, 0.41, 9.793
local eps0 = cmu ^ 0.75 * k0 ^ 1.5 / (kappa * y_p)
if holes ~= math.floor(holes) or holes < 0 or holes > 5 then
  error(("row1_share: holes must be a whole number from 0 to 5, not %g"):format(holes))
end
domain { 0, 0, L, H, periodic = "x" }
particles { dr = dr }
scheme { "wcsph-riemann", sound_speed = 20,
         wall_shear = ({"y_p", "distance", "first_row"})[shear + 1] }
fluid { density = 1, viscosity = nu }
turbulence { model = "k-epsilon", y_p = y_p, k = k0, epsilon = eps0 }
wall { {L, 0}, {0, 0}, fluid = "right", group = "floor" }
wall { {0, H}, {L, H}, fluid = "right", group = "ceiling" }
if shear ~= 0 and shear ~= 1 and shear ~= 2 then
  error(("row1_share: shear must be 0 (y_p), 1 (distance) or 2 (first_row), not %g"):format(shear))
end
if lift ~= 0 and lift ~= 1 then
  error(("row1_share: lift must be 0 or 1, not %g"):format(lift))
end
fill { holes * dr, 0, L, dr, velocity = {1, 0} }
if lift == 1 then -- the floor's last column: one particle at 2 dr for its second and third rows
  fill { 0, dr, L - dr, 3 * dr, velocity = {1, 0} }
  fill { points = { {L - dr / 2, 1.7 * dr} }, velocity = {1, 0} }
  fill { 0, 3 * dr, L, H, velocity = {1, 0} }
else
  fill { 0, dr, L, H, velocity = {1, 0} }
end
force { "floor" }
force { "ceiling" }
run { t_end = t_end, output_every = t_end, dt = 0.001 }

function metrics(sim)
  -- eq 12 at y_p: τ_w/ρ = U_p u_s / u+, u_s = C_μ^¼ k^½, u+ = ln(E y+)/κ, y+ = y_p u_s/ν
  local us = cmu ^ 0.25 * math.sqrt(k0)
  local tau = 1.0 * us / (math.log(E * y_p * us / nu) / kappa)
  local f, c = sim.force("floor", 0), sim.force("ceiling", 0)
  local y, first = sim.field("pos", 2).value, 0
  for i = 1, #y do
    if y[i] < dr then first = first + 1 end
  end
  return { floor_over_law = f.viscous_x / (tau * L) - 1,
           ceiling_over_law = c.viscous_x / (tau * L) - 1, first_row = first }
end
