-- A square box turning about its centre, full of fluid turning with it (solid-body rotation
-- u = ω e_z × r, p = ρ ω² r²/2 + c), no gravity: the exact steady state of a rotating container,
-- which a geometry that did not turn (walls that only carry the velocity ω × r, their corners
-- standing still) would break at once, the corners ploughing through the fluid. The walls turn
-- (wall { omega, centre }; kernels/usaw/motion.cl): after t_end (1 rad at ω = 1) the fluid must
-- still turn rigidly, stay inside the turned box, and carry the parabolic pressure.
-- Metrics: u_err_rms, u_err_max (|u − ω × r| over ω a, a the half side), p_err_rms (over
-- ρ ω² a², the mean removed), outside (fluid particles outside the turned box), crossed (steps
-- with a particle behind a wall), torque and force on the box (both 0 for the exact state).
param { dr = 0.05, t_end = 1, weak = 0 }
local a, omega, nu, rho = 0.5, 1.0, 0.1, 1.0
domain { -0.75, -0.75, 0.75, 0.75 }
particles { dr = dr }
if weak == 1 then
  scheme { "wcsph-usaw", sound_speed = 10 * omega * a * math.sqrt(2) }
else
  scheme { "isph-usaw" }
end
fluid { density = rho, viscosity = nu }
wall { {-a, -a}, {a, -a}, {a, a}, {-a, a}, closed = true, fluid = "inside", omega = omega,
       centre = {0, 0}, group = "box" }
fill { -a, -a, a, a, velocity = function(x, y) return -omega * y, omega * x end }
force { "box" }
run { t_end = t_end, output_every = t_end }

function metrics(sim)
  local x, y = sim.field("pos", 1), sim.field("pos", 2)
  local u, v = sim.field("vel", 1).value, sim.field("vel", 2).value
  local p = sim.field("p").value
  local n = #x.value
  local th = omega * sim.time
  local c, s = math.cos(-th), math.sin(-th)
  local m = {u_err_rms = 0, u_err_max = 0, p_err_rms = 0, outside = 0}
  local pm, em = 0, 0
  for i = 1, n do
    local px, py = x.value[i], y.value[i]
    local du = math.sqrt((u[i] + omega * py) ^ 2 + (v[i] - omega * px) ^ 2) / (omega * a)
    m.u_err_rms, m.u_err_max = m.u_err_rms + du * du, math.max(m.u_err_max, du)
    local bx, by = c * px - s * py, s * px + c * py -- in the box's frame
    if math.abs(bx) > a or math.abs(by) > a then m.outside = m.outside + 1 end
    pm = pm + p[i]
    em = em + rho * omega ^ 2 * (px * px + py * py) / 2
  end
  pm, em = pm / n, em / n
  for i = 1, n do
    local px, py = x.value[i], y.value[i]
    local e = (p[i] - pm) - (rho * omega ^ 2 * (px * px + py * py) / 2 - em)
    m.p_err_rms = m.p_err_rms + (e / (rho * omega ^ 2 * a * a)) ^ 2
  end
  m.u_err_rms, m.p_err_rms = math.sqrt(m.u_err_rms / n), math.sqrt(m.p_err_rms / n)
  m.crossed = sim.wall_crossing_steps
  local f = sim.force("box")
  m.torque = f.torque -- of a fluid in rigid rotation on its box: 0 (no shear, pressure central)
  m.force = math.sqrt(f.x ^ 2 + f.y ^ 2)
  return m
end
