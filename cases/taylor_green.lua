-- Taylor-Green vortex (Taylor & Green 1937): the decaying array of vortices in a doubly periodic
-- square of side L, an exact solution of the Navier-Stokes equations with no walls,
--   u = −U cos(kx) sin(ky) e^{−2νk²t},  v = U sin(kx) cos(ky) e^{−2νk²t},  k = 2π/L,
--   p = −ρ U²/4 (cos 2kx + cos 2ky) e^{−4νk²t},
-- Re = U L / ν. The fluid starts on the lattice with the exact velocity. The vortex centres sit at
-- x, y = L/4, 3L/4 and the saddle points at x, y = 0, L/2, where the flow presses the particles
-- together along one axis as the exact solution says (isph-usaw at n = 32: nearest pairs at
-- 0.41 dr, t = 0.2, which its shifting then spreads again; a healthy run, not a clustering one).
-- Metrics at the end: the velocity error against the exact solution at the particles' positions,
-- RMS (vel_rms) and largest (vel_max) over the particles, in units of the exact amplitude
-- U e^{−2νk²t}; the kinetic energy against the exact one at the same positions, minus 1
-- (energy_error: a scheme's numerical dissipation shows here).
-- The fluid also starts with the exact pressure (fill { pressure }; --set start_p=0 starts it from
-- the scheme's own, p = 0): sample() records, with each snapshot, p_rms, the RMS of the pressure
-- error over ρ U² (both mean-free: an incompressible pressure is known to a constant), and the
-- metric p_rms_start is its value at t = 0.
-- --set wcsph=1 runs wcsph-usaw (c0 = 10 U, background pressure ρ U² so that the pressure stays
-- positive), --set rotational=1 isph-rotational.
param { n = 32, re = 100, t_end = 1, wcsph = 0, rotational = 0, start_p = 1 }

local L, U, rho = 1, 1, 1
local nu, k = U * L / re, 2 * math.pi / L

domain { 0, 0, L, L, periodic = "xy" }
particles { dr = L / n }
if wcsph == 1 then
  scheme { "wcsph-usaw", sound_speed = 10 * U, background_pressure = rho * U * U }
elseif rotational == 1 then
  scheme "isph-rotational"
else
  scheme "isph-usaw"
end
fluid { density = rho, viscosity = nu }
local function p_exact(x, y, t)
  return -rho * U * U / 4 * (math.cos(2 * k * x) + math.cos(2 * k * y)) * math.exp(-4 * nu * k * k * t)
end
fill { 0, 0, L, L, velocity = function(x, y)
  return -U * math.cos(k * x) * math.sin(k * y), U * math.sin(k * x) * math.cos(k * y)
end, pressure = start_p == 1 and function(x, y) return p_exact(x, y, 0) end or nil }
run { t_end = t_end, output_every = t_end / 4 }

function sample(sim)
  local p = sim.field("p")
  local n, mean, mean_exact = #p.value, 0, 0
  for i = 1, n do
    mean, mean_exact = mean + p.value[i] / n, mean_exact + p_exact(p.x[i], p.y[i], sim.time) / n
  end
  local e2 = 0
  for i = 1, n do
    e2 = e2 + (p.value[i] - mean - p_exact(p.x[i], p.y[i], sim.time) + mean_exact) ^ 2
  end
  return { p_rms = math.sqrt(e2 / n) / (rho * U * U) }
end

function metrics(sim)
  local u, v = sim.field("vel", 1), sim.field("vel", 2)
  local amp = U * math.exp(-2 * nu * k * k * sim.time)
  local e2, emax, ke, ke_exact = 0, 0, 0, 0
  for i = 1, #u.value do
    local x, y = u.x[i], u.y[i]
    local ue = -amp * math.cos(k * x) * math.sin(k * y)
    local ve = amp * math.sin(k * x) * math.cos(k * y)
    local d2 = (u.value[i] - ue) ^ 2 + (v.value[i] - ve) ^ 2
    e2, emax = e2 + d2, math.max(emax, d2)
    ke, ke_exact = ke + u.value[i] ^ 2 + v.value[i] ^ 2, ke_exact + ue * ue + ve * ve
  end
  return { vel_rms = math.sqrt(e2 / #u.value) / amp, vel_max = math.sqrt(emax) / amp,
           energy_error = ke / ke_exact - 1, p_rms_start = sim.series("p_rms").value[1],
           p_rms = sample(sim).p_rms }
end
