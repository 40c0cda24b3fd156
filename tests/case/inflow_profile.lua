-- An entry whose velocity, k and ε are functions of s, the distance from its first end along it
-- (inflow { velocity = function(s) ... }, the developed profile of a channel's entry), under
-- wcsph-riemann's k-ε model: a stream in x, periodic in y (no walls, so that the sheared stream
-- is a steady Euler flow), entering at x = 0 through the section from (0, W) to (0, 0), so that
-- s = W − y:
--   u(s) = U (1 + a sin 2π s/W), k(s) = k0 (1 + ½ sin 2π s/W), ε(s) = ε0 (1 + ½ cos 2π s/W),
-- and turbulence { }'s k and ε far from both (an entry that fell back on them would be off by
-- 3 k0). The fluid starts on the entry's profile. Metrics over the fluid of the first row
-- (0 <= x < dr, what entered within dr/U), against the functions at its s: u_err_rms,
-- u_err_max (over U), k_err_rms, k_err_max (over k0), eps_err_rms (over ε0); flux_ratio, the
-- mean of u_x over the fluid with x in [L/2 − dr, L/2 + dr] against the profile's mean U: what
-- the entry lets in must match its table's mean (the characteristic exit takes the entries' flux
-- from it).
param { dr = 0.05, t_end = 1, a = 0.1 }
local L, W, U, k0, e0 = 2.0, 1.0, 1.0, 0.01, 0.002
local tau = 2 * math.pi / W
local function u_in(s) return U * (1 + a * math.sin(tau * s)) end
local function k_in(s) return k0 * (1 + 0.5 * math.sin(tau * s)) end
local function e_in(s) return e0 * (1 + 0.5 * math.cos(tau * s)) end
domain { 0, 0, L, W, periodic = "y" }
particles { dr = dr }
scheme { "wcsph-riemann", sound_speed = 15 * U }
fluid { density = 1, viscosity = 1e-5 }
turbulence { model = "k-epsilon", k = 4 * k0, epsilon = 4 * e0 }
fill { 0, 0, L, W, velocity = function(x, y) return u_in(W - y), 0 end,
       k = function(x, y) return k_in(W - y) end, epsilon = function(x, y) return e_in(W - y) end }
inflow { {0, W}, {0, 0}, name = "entry", velocity = u_in, k = k_in, epsilon = e_in }
outflow { {L, 0}, {L, W}, name = "exit" }
run { t_end = t_end, output_every = t_end }

function metrics(sim)
  local u, k, e = sim.field("vel", 1), sim.field("k"), sim.field("epsilon")
  local m = {u_err_rms = 0, u_err_max = 0, k_err_rms = 0, k_err_max = 0, eps_err_rms = 0}
  local n, flux, nflux = 0, 0, 0
  for i = 1, #u.x do
    local x, s = u.x[i], W - u.y[i]
    if x >= 0 and x < dr then
      local du = math.abs(u.value[i] - u_in(s)) / U
      local dk = math.abs(k.value[i] - k_in(s)) / k0
      local de = math.abs(e.value[i] - e_in(s)) / e0
      m.u_err_rms, m.k_err_rms, m.eps_err_rms = m.u_err_rms + du * du, m.k_err_rms + dk * dk,
                                                m.eps_err_rms + de * de
      m.u_err_max, m.k_err_max = math.max(m.u_err_max, du), math.max(m.k_err_max, dk)
      n = n + 1
    end
    if math.abs(x - L / 2) <= dr then flux, nflux = flux + u.value[i], nflux + 1 end
  end
  for _, key in ipairs({"u_err_rms", "k_err_rms", "eps_err_rms"}) do
    m[key] = math.sqrt(m[key] / n)
  end
  m.first_row = n
  m.flux_ratio = flux / nflux / U
  return m
end
