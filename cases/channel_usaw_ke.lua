-- Fully developed turbulent channel under the k-ε model with the semi-analytical walls (Leroy et
-- al. 2014 sec 5.1): half-height e = 1, periodic in x, driven by the body force f = 1 m/s², so
-- that the walls' friction velocity is u* = √(f e) = 1 m/s; ν = 1/re_tau (the paper's e+ = 640:
-- ν = 1.5625e-3; re_tau = 543.5 is Lee & Moser's DNS), ρ = 1. n particle rows per half-height
-- (the paper's spacing 0.05 m is n = 20), the first δr/2 from the wall; the wall law applies at
-- each particle's own distance from the wall (eq 23), so the resolution sets nothing else.
-- Start (init = 1): u, k and ε of the 1-D reference at each particle's distance from the wall
-- (below, tests/data/channel1d_leroy*.csv); init = 0: at rest with k = u*²/√C_μ, ε = u*³/(κ e/10).
-- weak = 0: isph-usaw, 1: wcsph-usaw (sound speed 10 times the reference's centreline speed, a
-- background pressure of 5% of ρ c0²).
-- scalable = 1 takes the scalable wall law (y+ held at 11.06: the wall layer in the viscous
-- sublayer, n > 28 at e+ = 640, then stands for one on the log law).
-- turb = 0 leaves the model out (the same particles, laminar): for the cost of a step only.
-- control = 1 drives the channel by flow-rate control (eqs 67-68) instead, holding the particles'
-- mean velocity at the reference's mean over the same rows: the walls' friction velocity is then
-- the result (u_tau_wall against the reference's 1).
--
-- The reference: the standard k-ε model with the wall law of eq 23, u/u* = ln(y u*/ν)/κ + 5.2
-- (κ = 0.41, scaled by u* itself: channel1d --wall-law u_tau), solved across the half channel by
-- tests/reference/channel1d (3200 cells, the wall function at y = 0.025, the first row of the
-- paper's spacing, y+ = 16 at e+ = 640; above it the profile is the model's): the model's own
-- answer, so that what differs is the particles' discretisation.
-- Against it, per particle row (the mean over x, both halves folded), from the rows above y+ = 30
-- (the issue's goal: u+ within 2% there) and for the first rows apart:
--   u_plus_dev_max, u_plus_rms: the largest and the RMS |u+ − u+_1D|/u+_1D above y+ = 30,
--   u_plus_row1: the first row's u+, and u_plus_dev_row1 against the reference (where the first
--   row lies at or above the reference's first node, n <= 20),
--   k_plus_rms, eps_plus_rms: RMS of (k − k_1D)/k_1D and (ε − ε_1D)/ε_1D above y+ = 30,
--   u_tau_wall: the friction velocity the walls' force gives (√(F_x/(2 L ρ)) over the second half
--   of the run: 1 once they carry the body force), u_tau_dev = u_tau_wall − 1,
--   bulk and bulk_dev (the particles' mean velocity against the reference's mean over the rows).
-- With re_tau = 543.5 also the DNS (Lee & Moser 2015, tests/data/channel_dns_LM550.csv):
--   u_plus_dns_dev_max above y+ = 30 (the model's error and the particles' together), and
--   k_plus_dns_rms (the k-ε model is not made to reproduce k near the wall: from y+ = 30 on).
param { n = 20, t_end = 100, weak = 0, re_tau = 640, init = 1, every = 5, cfl = 2, control = 0, turb = 1,
        scalable = 0 }
if scalable ~= 0 and scalable ~= 1 then
  error(("channel_usaw_ke: scalable must be 0 (the two-layer wall law of eq 23) or 1 (the scalable one), not %g"):format(scalable))
end
if turb ~= 0 and turb ~= 1 then
  error(("channel_usaw_ke: turb must be 1 (the k-ε model) or 0 (none: the same particles laminar, for the cost of a step only), not %g"):format(turb))
end
if not (n >= 4 and n <= 400 and n == math.floor(n)) then
  error(("channel_usaw_ke: n must be a whole number of particle rows per half height from 4 to 400, not %g"):format(n))
end
if control ~= 0 and control ~= 1 then
  error(("channel_usaw_ke: control must be 0 (the body force f = u*²/e) or 1 (flow-rate control, eqs 67-68, at the reference's mean over the rows), not %g"):format(control))
end
if weak ~= 0 and weak ~= 1 then
  error(("channel_usaw_ke: weak must be 0 (isph-usaw) or 1 (wcsph-usaw), not %g"):format(weak))
end
if re_tau ~= 640 and re_tau ~= 543.5 then
  error(("channel_usaw_ke: re_tau must be 640 (the paper's) or 543.5 (Lee & Moser's DNS), not %g"):format(re_tau))
end

local e, ustar, kappa, cmu = 1.0, 1.0, 0.41, 0.09
local nu = ustar * e / re_tau
local dr = e / n
local nx = 12 -- the periodic length must exceed 2.5 times the segments' grid support
local L = nx * dr
local ref_file = re_tau == 640 and "tests/data/channel1d_leroy640.csv" or "tests/data/channel1d_leroy543.csv"
local ref = reference(ref_file, "y", "u", "u_plus", "k", "epsilon")
local u_centre = ref.u[#ref.u]
domain { 0, 0, L, 2 * e, periodic = "x" }
particles { dr = dr }
if weak == 0 then
  scheme { "isph-usaw" }
else
  -- a background pressure of 5% of ρ c0² keeps the rows along the walls: without it the first
  -- two rows (n = 10) swapped particles and clustered by t = 3 s; with 45% they did by t = 8 s
  scheme { "wcsph-usaw", sound_speed = 10 * u_centre, background_pressure = 0.05 * (10 * u_centre) ^ 2 }
end
-- the reference's mean velocity over the particle rows (what flow-rate control holds)
local function interp0(ys, vs, y)
  if y <= ys[1] then return vs[1] end
  for j = 2, #ys do
    if ys[j] >= y then return vs[j - 1] + (vs[j] - vs[j - 1]) * (y - ys[j - 1]) / (ys[j] - ys[j - 1]) end
  end
  return vs[#ys]
end
local u_rows = 0
for r = 1, n do u_rows = u_rows + interp0(ref.y, ref.u, (r - 0.5) * dr) / n end
if control == 1 then
  fluid { density = 1, viscosity = nu, flow_rate_control = { velocity = u_rows, slice = { 0, L * (1 - 1e-9) } } }
else
  fluid { density = 1, viscosity = nu, body_force = {ustar * ustar / e, 0} }
end
if turb == 1 then
  turbulence { model = "k-epsilon", k = ustar * ustar / math.sqrt(cmu), epsilon = ustar ^ 3 / (kappa * 0.1 * e),
               wall_law = scalable == 1 and "scalable" or nil }
end
wall { {L, 0}, {0, 0}, fluid = "right", group = "floor" }
wall { {0, 2 * e}, {L, 2 * e}, fluid = "right", group = "ceiling" }

-- a column of the reference against the distance from the wall, linear (flat beyond the ends)
local interp = interp0
local function ref_at(col, y) return interp(ref.y, ref[col], math.min(y, 2 * e - y)) end
if init == 1 then
  fill { 0, 0, L, 2 * e, velocity = function(x, y) return ref_at("u", y), 0 end,
         k = turb == 1 and function(x, y) return ref_at("k", y) end or nil,
         epsilon = turb == 1 and function(x, y) return ref_at("epsilon", y) end or nil }
else
  fill { 0, 0, L, 2 * e }
end
force { "floor" }
force { "ceiling" }
run { t_end = t_end, output_every = every, sample_every = math.min(every, 1), cfl = cfl }

local dns = nil
if re_tau == 543.5 then dns = reference("tests/data/channel_dns_LM550.csv", "y_over_delta", "y_plus", "U_plus", "k_plus") end

function metrics(sim)
  local y = sim.field("pos", 2).value
  local u = sim.field("vel", 1).value
  local k, eps = {}, {}
  if turb == 1 then
    k, eps = sim.field("k").value, sim.field("epsilon").value
  else -- laminar (the cost comparison): no k or ε
    for i = 1, #u do k[i], eps[i] = 0, 0 end
  end
  local rows = {}
  for r = 1, n do rows[r] = {u = 0, k = 0, e = 0, c = 0} end
  local usum, count = 0, 0
  for i = 1, #u do
    local d = math.min(y[i], 2 * e - y[i]) -- from the nearer wall
    local r = math.floor(d / dr) + 1
    if r >= 1 and r <= n then
      local w = rows[r]
      w.u, w.k, w.e, w.c = w.u + u[i], w.k + k[i], w.e + eps[i], w.c + 1
    end
    usum, count = usum + u[i], count + 1
  end
  local m = {}
  local su, sk, se, nr, umax, dmax, skd, nkd = 0, 0, 0, 0, 0, 0, 0, 0
  for r = 1, n do
    local w = rows[r]
    if w.c > 0 then
      local d = (r - 0.5) * dr
      local up, kp, ep = w.u / w.c / ustar, w.k / w.c / ustar ^ 2, w.e / w.c * e / ustar ^ 3
      local uref, kref, eref = ref_at("u", d) / ustar, ref_at("k", d) / ustar ^ 2, ref_at("epsilon", d) * e / ustar ^ 3
      if r <= 3 then
        m["u_plus_row" .. r] = up
        m["k_plus_row" .. r] = kp
      end
      -- only where the reference has a value: below its first node (y = 0.025, n > 20) it is
      -- its wall function's, not a solution of the model
      if r == 1 and d >= ref.y[1] then m.u_plus_dev_row1 = up / uref - 1 end
      if d * ustar / nu >= 30 then
        local du = up / uref - 1
        su, sk, se, nr = su + du * du, sk + (kp / kref - 1) ^ 2, se + (ep / eref - 1) ^ 2, nr + 1
        umax = math.max(umax, math.abs(du))
        if dns then
          local yp = d * ustar / nu
          local ud = interp(dns.y_plus, dns.U_plus, yp)
          dmax = math.max(dmax, math.abs(up / ud - 1))
          skd, nkd = skd + (kp / interp(dns.y_plus, dns.k_plus, yp) - 1) ^ 2, nkd + 1
        end
      end
    end
  end
  m.u_plus_dev_max = umax
  m.u_plus_rms = math.sqrt(su / math.max(nr, 1))
  m.k_plus_rms = math.sqrt(sk / math.max(nr, 1))
  m.eps_plus_rms = math.sqrt(se / math.max(nr, 1))
  m.rows_log = nr
  if dns then
    m.u_plus_dns_dev_max = dmax
    m.k_plus_dns_rms = math.sqrt(skd / math.max(nkd, 1))
  end
  -- the particles' mean velocity against the reference's mean over the same rows
  m.bulk = usum / count
  m.bulk_dev = m.bulk / u_rows - 1
  local f, c = sim.force("floor", t_end / 2), sim.force("ceiling", t_end / 2)
  m.u_tau_wall = math.sqrt(math.max((f.viscous_x + c.viscous_x) / (2 * L), 0))
  m.u_tau_dev = m.u_tau_wall / ustar - 1
  return m
end
