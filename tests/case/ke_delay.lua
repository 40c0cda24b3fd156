-- The k-ε model's delayed activation (Wang, Sun & Hu sec 5.2; turbulence { delay = T, nu_t = N }):
-- until t = T the model waits (k and ε stay as they are, ν_t = N), then it runs. A fluid at rest
-- in a box periodic on both axes with uniform k0, ε0 has no production nor diffusion, so after
-- the delay each particle decays as homogeneous turbulence (eqs 7-8 with G = 0):
--   k(t) = k0 (1 + (C2 − 1) ε0 (t − T)/k0)^(−1/(C2−1)) for t > T, k0 before.
-- Metrics at t_end: k_ratio, the mean k against that (1 exactly before the delay), k_spread, the
-- largest |k − mean|/mean; nu_t_ratio, the mean ν_t against N before the delay and against
-- C_μ k²/ε (eq 6, from the decayed k and ε) after it.
param { t_end = 1, delay = 0.5, dr = 0.1 }
local k0, e0, C2, N = 0.01, 0.005, 1.92, 1e-3
domain { 0, 0, 1, 1, periodic = "xy" }
particles { dr = dr }
scheme { "wcsph-riemann", sound_speed = 1 }
fluid { density = 1, viscosity = 1e-6 }
turbulence { model = "k-epsilon", k = k0, epsilon = e0, delay = delay > 0 and delay or nil,
              nu_t = delay > 0 and N or nil }
fill { 0, 0, 1, 1 }
-- (at rest nothing bounds the step: dt = 0.005 keeps the linearised sink's Δt ε/k at 0.0025)
run { t_end = t_end, output_every = t_end, dt = 0.005 }

function metrics(sim)
  local k, e, nut = sim.field("k").value, sim.field("epsilon").value, sim.field("nu_t").value
  local mk, me, mn, spread = 0, 0, 0, 0
  for i = 1, #k do mk, me, mn = mk + k[i], me + e[i], mn + nut[i] end
  mk, me, mn = mk / #k, me / #k, mn / #k
  for i = 1, #k do spread = math.max(spread, math.abs(k[i] - mk) / mk) end
  local s = math.max(0, sim.time - delay)
  local want = k0 * (1 + (C2 - 1) * e0 * s / k0) ^ (-1 / (C2 - 1))
  local nut_want = sim.time < delay and N or 0.09 * mk * mk / me
  return { k_ratio = mk / want, k_spread = spread, nu_t_ratio = mn / nut_want }
end
