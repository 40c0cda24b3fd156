-- Fully developed turbulent channel under the k-ε RANS model of wcsph-riemann (Wang, Sun & Hu
-- sec 5.1): half-height δ = 1 (H = 2), periodic in x, driven by the body force u_τ²/δ with
-- u_τ = 0.0543496 and ν = 1e-4: Lee & Moser's Re_τ = 543.5 channel (their δ = 1, U_b = 1,
-- ν = 1e-4), ρ = 1. The wall model sits at y_p = 0.05 from each wall (eq 10; y+ about 25), and
-- nf particle rows fill the channel: with the boundary offset of sec 4.4 the walls move in by
-- y_p − dr/2, dr = (H − 2 y_p)/(nf − 1), so that the first row stays at y_p at every
-- resolution (nf = 20: dr = 0.1, no offset). Start (init = 1): u, k and ε of the 1-D reference at
-- each particle's distance from the wall, as the paper starts its channel from its FDM solution;
-- init = 0: the 1/7 power law of the same mean U_b = 1.0653, k = u_τ²/√C_μ, ε = u_τ³/(κ δ/10).
-- Metrics: u+ = ⟨u⟩/u_τ per particle row (the mean over x, both halves folded) against the 1-D
-- reference (tests/data/channel1d_re_tau543.csv, tests/reference/channel1d with the same u_τ,
-- y_p and ν) at the rows' heights: u_plus_dev_max (the largest |u+ − u+_1D|/u+_1D), u_plus_rms;
-- the bulk velocity against the reference's 1.0653 (bulk_dev), and u_plus_rowN, the rows' u+;
-- tau_w_dev, the walls' viscous force (the wall model's shear, eq 39) over the second half of
-- the run per unit length, over ρ u_τ², less 1 (0 once the walls carry the body force), and
-- wall_pressure_x, the pressure part along x in the same unit (0 on a flat wall).
-- The run is the last instant's (no time average yet).
-- tvf: the transport-velocity correction (0 off, 1 full, 2 limited: the scheme's default);
-- turb = 0 runs the same scene laminar (for the model's cost: `--profile`); ws ≥ 0 sets w_s of
-- eq 40 (the scheme's 0.1 otherwise).
param { nf = 20, t_end = 40, y_p = 0.05, ard = 0, every = 0.5, tvf = 2, turb = 1, init = 1, ws = -1 }

local delta, nu, u_tau, kappa, cmu = 1.0, 1e-4, 0.0543496, 0.41, 0.09
local H = 2 * delta
local dr = (H - 2 * y_p) / (nf - 1)
local off = y_p - dr / 2
local nx = math.max(math.floor(1.0 / dr + 0.5), 8)
local L = nx * dr
domain { 0, off, L, H - off, periodic = "x" }
particles { dr = dr }
scheme { "wcsph-riemann", ard = ard, transport_velocity = ({"off", "full", "limited"})[tvf + 1] }
fluid { density = 1, viscosity = nu, body_force = {u_tau * u_tau / delta, 0} }
if turb == 1 then
  turbulence { model = "k-epsilon", y_p = y_p, k = u_tau * u_tau / math.sqrt(cmu),
               epsilon = u_tau ^ 3 / (kappa * 0.1 * delta), wall_weight = ws >= 0 and ws or nil }
end
wall { {L, off}, {0, off}, fluid = "right", group = "floor" }
wall { {0, H - off}, {L, H - off}, fluid = "right", group = "ceiling" }
local ub = 1.0653
-- the 1-D reference (distance from the wall y, from y_p to δ) and its linear interpolation
local ref = reference("tests/data/channel1d_re_tau543.csv", "y", "u", "u_plus", "k", "epsilon")
local function ref_at(col, d)
  local ys, vs = ref.y, ref[col]
  d = math.max(d, ys[1])
  for j = 2, #ys do
    if ys[j] >= d then
      return vs[j - 1] + (vs[j] - vs[j - 1]) * (d - ys[j - 1]) / (ys[j] - ys[j - 1])
    end
  end
  return vs[#vs]
end
if init == 1 then -- the reference's u, k and ε at the particle's distance from the wall
  local function at(col, y) return ref_at(col, math.min(y, H - y)) end
  fill { off, off, L, H - off, velocity = function(x, y) return at("u", y), 0 end,
         k = function(x, y) return at("k", y) end,
         epsilon = function(x, y) return at("epsilon", y) end }
else -- the 1/7 power law of the same mean, k and ε of turbulence { }
  fill { off, off, L, H - off, velocity = function(x, y)
    local d = math.min(y, H - y) / delta
    return 8 / 7 * ub * math.max(d, 1e-3) ^ (1 / 7), 0
  end }
end
force { "floor" }
force { "ceiling" }
run { t_end = t_end, output_every = every }

function metrics(sim)
  local x, y = sim.field("pos", 1).value, sim.field("pos", 2).value
  local u = sim.field("vel", 1).value
  local rows, half = {}, math.floor(nf / 2)
  for r = 1, half do rows[r] = {sum = 0, n = 0} end
  for i = 1, #u do
    local d = math.min(y[i], H - y[i]) -- distance from the nearer wall
    local r = math.floor((d - off) / dr) + 1
    if r >= 1 and r <= half then rows[r].sum, rows[r].n = rows[r].sum + u[i], rows[r].n + 1 end
  end
  local m = {}
  local bulk, count = 0, 0
  for i = 1, #u do bulk, count = bulk + u[i], count + 1 end
  m.bulk = bulk / count
  local worst, sq = 0, 0
  for r = 1, half do
    local yy = y_p + (r - 1) * dr
    local up = rows[r].sum / math.max(rows[r].n, 1) / u_tau
    local want = ref_at("u_plus", yy)
    local dev = math.abs(up - want) / want
    worst = math.max(worst, dev)
    sq = sq + dev * dev
    m[("u_plus_row%d"):format(r)] = up
  end
  m.u_plus_dev_max = worst
  m.u_plus_rms = math.sqrt(sq / half)
  m.bulk_dev = m.bulk / ub - 1
  -- the walls' friction over the second half of the run: u_τ,wall² = F_x/(2 L ρ) against the
  -- body force's u_τ² (a steady periodic channel's walls carry it all)
  local f, c = sim.force("floor", t_end / 2), sim.force("ceiling", t_end / 2)
  m.tau_w_dev = (f.viscous_x + c.viscous_x) / (2 * L) / (u_tau * u_tau) - 1
  m.wall_pressure_x = (f.pressure_x + c.pressure_x) / (2 * L) / (u_tau * u_tau)
  return m
end
