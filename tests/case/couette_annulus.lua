-- Circular Couette flow (wcsph-riemann): fluid between a cylinder of radius R1 turning at ω and a
-- fixed one of radius R2, from rest to the steady laminar flow (Re = ω R1 (R2 − R1)/ν = 2.5)
--   u_θ(r) = A r + B/r,  A = −ω R1²/(R2² − R1²),  B = ω R1² R2²/(R2² − R1²),
-- a test of walls that curve across the lattice. fitted = 1: the fluid in rings along the walls
-- (fill { points }) and the walls' dummy layers in rings behind them (circle { dummies =
-- "fitted" }); fitted = 0: the Cartesian lattice for both. Metrics over the fluid at t_end:
-- u_err_rms, u_err_max, |u_θ − u_exact| over ω R1; u_r_rms, the radial speed over ω R1 (0
-- exactly).
param { nf = 10, t_end = 3, fitted = 1 }
local R1, R2, omega, nu = 0.5, 1.0, 1.0, 0.1
local dr = (R2 - R1) / nf
domain { -R2 - 4 * dr, -R2 - 4 * dr, R2 + 4 * dr, R2 + 4 * dr }
particles { dr = dr }
scheme { "wcsph-riemann", sound_speed = 10 * omega * R1 }
fluid { density = 1, viscosity = nu }
local dummies = fitted == 1 and "fitted" or "lattice"
circle { centre = {0, 0}, radius = R1, fluid = "outside", omega = omega, group = "inner",
         dummies = dummies }
circle { centre = {0, 0}, radius = R2, fluid = "inside", group = "outer", dummies = dummies }
if fitted == 1 then
  local pts = {}
  for j = 0, nf - 1 do
    local r = R1 + (j + 0.5) * dr
    local n = math.floor(2 * math.pi * r / dr + 0.5)
    for i = 0, n - 1 do
      local a = 2 * math.pi * (i + 0.5 * (j % 2)) / n
      pts[#pts + 1] = {r * math.cos(a), r * math.sin(a)}
    end
  end
  fill { points = pts }
else
  local ring = {}
  for i = 0, 63 do
    local a = 2 * math.pi * i / 64
    ring[#ring + 1] = {(R2 - dr / 4) * math.cos(a), (R2 - dr / 4) * math.sin(a)}
  end
  fill { polygon = ring } -- the inner cylinder carves itself out
end
run { t_end = t_end, output_every = t_end / 3 }

local A = -omega * R1 ^ 2 / (R2 ^ 2 - R1 ^ 2)
local B = omega * R1 ^ 2 * R2 ^ 2 / (R2 ^ 2 - R1 ^ 2)
function metrics(sim)
  local x, y = sim.field("pos", 1), sim.field("pos", 2)
  local u, v = sim.field("vel", 1), sim.field("vel", 2)
  local m = {u_err_rms = 0, u_err_max = 0, u_r_rms = 0}
  local n = #x.value
  for i = 1, n do
    local px, py = x.value[i], y.value[i]
    local r = math.sqrt(px * px + py * py)
    local ut = (-py * u.value[i] + px * v.value[i]) / r
    local ur = (px * u.value[i] + py * v.value[i]) / r
    local du = math.abs(ut - (A * r + B / r)) / (omega * R1)
    m.u_err_rms, m.u_err_max = m.u_err_rms + du * du, math.max(m.u_err_max, du)
    m.u_r_rms = m.u_r_rms + (ur / (omega * R1)) ^ 2
  end
  m.u_err_rms, m.u_r_rms = math.sqrt(m.u_err_rms / n), math.sqrt(m.u_r_rms / n)
  return m
end
