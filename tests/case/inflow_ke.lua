-- Decaying turbulence carried in from an entry (wcsph-riemann's k-ε model at an inflow { k,
-- epsilon } and a natural exit): a uniform stream u = U in x, periodic in y, no walls, so that
-- nothing produces k and each particle decays as homogeneous turbulence does (Wang, Sun & Hu
-- eqs 7-8 without production, G = 0):
--   dk/dt = −ε, dε/dt = −C2 ε²/k  →  k = k0 (1 + (C2 − 1) ε0 t / k0)^(−1/(C2−1)),
--   ε = ε0 (1 + (C2 − 1) ε0 t / k0)^(−C2/(C2−1)),  t = x / U (the time since the entry).
-- The entry holds k0, ε0; the fluid starts on the exact profile; the exit layers copy their
-- rows' first fluid (n·∇k = n·∇ε = 0). Metrics over the fluid with 0.25 <= x <= L − 0.5:
-- k_err_rms, k_err_max, eps_err_rms, |k − k_exact|/k0 and |ε − ε_exact|/ε0; k_exit_ratio, k of
-- the fluid within 2 dr of the exit against the exact there (the exit must not feed back).
-- ard = 1 adds the ARD indicator field (tests/render/turbulence_fields.cmake draws it).
param { dr = 0.1, t_end = 6, ard = 0 }
local L, W, U, k0, e0, C2 = 4.0, 1.0, 1.0, 0.01, 0.0025, 1.92
domain { 0, 0, L, W, periodic = "y" }
particles { dr = dr }
scheme { "wcsph-riemann", ard = ard }
fluid { density = 1, viscosity = 1e-5 }
turbulence { model = "k-epsilon", k = k0, epsilon = e0 }
local function decay(x)
  return 1 + (C2 - 1) * e0 * (x / U) / k0
end
local function k_exact(x) return k0 * decay(x) ^ (-1 / (C2 - 1)) end
local function e_exact(x) return e0 * decay(x) ^ (-C2 / (C2 - 1)) end
fill { 0, 0, L, W, velocity = {U, 0}, k = function(x, y) return k_exact(x) end,
       epsilon = function(x, y) return e_exact(x) end }
inflow { {0, W}, {0, 0}, velocity = U, k = k0, epsilon = e0, name = "entry" }
outflow { {L, 0}, {L, W}, name = "exit" }
run { t_end = t_end, output_every = t_end / 4 }

function metrics(sim)
  local k, e = sim.field("k"), sim.field("epsilon")
  local m = {k_err_rms = 0, k_err_max = 0, eps_err_rms = 0}
  local n, ex, exn = 0, 0, 0
  for i = 1, #k.x do
    local x = k.x[i]
    if x >= 0.25 and x <= L - 0.5 then
      local dk = math.abs(k.value[i] - k_exact(x)) / k0
      local de = math.abs(e.value[i] - e_exact(x)) / e0
      m.k_err_rms, m.eps_err_rms = m.k_err_rms + dk * dk, m.eps_err_rms + de * de
      m.k_err_max, n = math.max(m.k_err_max, dk), n + 1
    end
    if x >= L - 2 * dr then ex, exn = ex + k.value[i] / k_exact(x), exn + 1 end
  end
  m.k_err_rms, m.eps_err_rms = math.sqrt(m.k_err_rms / n), math.sqrt(m.eps_err_rms / n)
  m.k_exit_ratio = ex / exn
  return m
end
