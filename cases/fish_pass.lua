-- Fish-pass (Leroy et al. 2014 sec 5.2): one periodic pool of a vertical-slot fish-pass seen from
-- above, 2-D, no gravity and no free surface, driven by a body force of 1.885 m/s² along x,
-- ν = 1e-6 m²/s, ρ = 1000 kg/m³, slot b = 0.3 m, the k-ε model with the semi-analytical walls
-- (the wall law at each particle's distance, eq 23). The paper compares u, p, k and ε along
-- three sections P1-P3 and the wall pressure along P4 after 20 s, isph-usaw against wcsph-usaw
-- (background pressure 5e4 Pa) and a finite-volume code.
--
-- The geometry: the paper refers it to its refs [45, 10] (the vertical-slot pool of Violeau et
-- al.'s fish-pass study after the standard designs of Rajaratnam et al. 1986 and Larinier 2002),
-- whose numbers did not survive in our copy; the drawing of fig 18 is lost too. This case takes
-- the standard vertical-slot proportions those designs use and fixes them, in units of b:
--   * pool length (the period) L = 10 b = 3.0 m along x, width B = 8 b = 2.4 m (walls y = 0, B);
--   * the partition at x = 1.0 m: a long baffle from the wall y = 0 to y = 6 b = 1.8 m, b/2 =
--     0.15 m thick (x = 1.0-1.15), and a short baffle (the deflector) from the wall y = B down to
--     y = 7 b = 2.1 m, 1.5 b = 0.45 m long (x = 1.0-1.45); the slot between them is y = 1.8-2.1;
--   * the baffles are rectangles (the designs' noses and deflector angles left out).
-- The fluid then fills 6.795 m²: at dr = b/28 = 0.0107 m that is 5.92e4 particles, the paper's
-- count (58823) within 0.6%, which supports the proportions; `n` is the slot in spacings.
-- Sections (across the pool, wall to wall): P1 at x = 1.6 m (the jet just past the deflector),
-- P2 at x = 2.2 m (mid-pool), P3 at x = 2.8 m (before the next partition); P4 along the wall
-- y = 0 downstream of the long baffle, x = 1.175-2.975 m (the paper's "bottom-left part of the
-- wall"). These are this case's own choice too.
--
-- The reference: OpenFOAM v1912 pimpleFoam on the same geometry, standard k-ε with wall
-- functions, from rest to 20 s (tests/validation/openfoam/fish_pass/run.sh, its profiles in
-- tests/data/openfoam_fish_pass.csv with the command and the mesh sensitivity). Pressure is
-- defined up to a constant in a periodic pool with walls only: both sides subtract their mean
-- over the P1-P3 points. (The pressure the USAW schemes solve for is p + ⅔ρk, eq 12, as
-- OpenFOAM's kinematic p is.)
-- Metrics at t_end (instantaneous, as the paper's "after 20 s"), at the reference's points:
--   u_rms_P1..3: RMS over the section of |u − u_FV| over U_ref (the reference's largest |u| on
--   P1-P3); p_rms_P1..4: RMS of p − p_FV over ½ ρ U_ref²; k_rms_P1..3: RMS of k − k_FV over the
--   section's largest k_FV; eps_log_rms_P1..3: RMS of log10(ε/ε_FV); flow_rate and flow_rate_fv
--   (∫ u_x dy across P2, m²/s) and flow_rate_dev; flow_rate_fv_now and flow_rate_dev_now, the
--   reference's flow rate at the run's own end (tests/data/openfoam_fish_pass_flow.csv: for short
--   runs, the start-up) and the deviation from it; flow_rate_history_rms, the RMS over the run's
--   samples of Q − Q_FV(t) over Q_FV(20 s); momentum_residual (below); u_max (the particles'
--   largest speed), and the wall crossings. sample() records the flow rate across P2, the
--   largest speed and the fluid's mean x velocity over time.
--
-- prod = 1 takes the standard production of k, ν_T S² (OpenFOAM's kEpsilon), instead of the
-- paper's semi-linear one (eq 20, min(√C_μ k S, ν_T S²)), which caps it where the strain is large
-- against ε/k, as in the jet's shear layers: so the model's difference from the reference and the
-- particles' own can be told apart. mean = 0 solves the pressure equation with the reinforced
-- diagonal alone (sec 3.3), guard = 0 leaves the wall guard off (README: both fail here).
-- weak = 1 runs wcsph-usaw: sound speed c0 = 10 U_max (U_max = 4 m/s, above the slot's jet),
-- background pressure 5e4 Pa (the paper's: higher values spoil the results, lower ones leave
-- voids).
param { n = 10, t_end = 20, weak = 0, every = 1, turb = 1, cfl = 1, mean = 1, guard = 1, prod = 0 }
if weak ~= 0 and weak ~= 1 then
  error(("fish_pass: weak must be 0 (isph-usaw) or 1 (wcsph-usaw), not %g"):format(weak))
end
if turb ~= 0 and turb ~= 1 then
  error(("fish_pass: turb must be 1 (the k-ε model) or 0 (laminar, for the cost of a step only), not %g"):format(turb))
end
-- n even puts every wall face on the lattice's cell faces (below); from n = 8 on the kernel's
-- support (4 dr) no longer reaches through the long baffle (b/2 thick) to its far face's segments
if not (n >= 8 and n <= 60 and n % 2 == 0) then
  error(("fish_pass: n (the slot width in particle spacings) must be an even number from 8 to 60, not %g"):format(n))
end

local b = 0.3
local L, B = 10 * b, 8 * b
local xp, tl, ts = 1.0, 0.5 * b, 1.5 * b -- the partition's upstream face, the baffles' lengths
local yl, ys = 6 * b, 7 * b              -- the long baffle's tip, the short baffle's face
local rho, nu, force_x = 1000, 1e-6, 1.885
local dr = b / n
local u_max_est = 4.0

-- the period's window starts 3 b before the partition, so that every wall face lies on the
-- lattice's cell faces (n even: b/2 is a whole number of spacings) and the fluid starts dr/2 off
-- every wall
local x0 = xp - 3 * b
domain { x0, 0, x0 + L, B, periodic = "x" }
particles { dr = dr }
if weak == 0 then
  scheme { "isph-usaw", solver_singular = mean == 1 and "project" or nil, wall_guard = guard == 1 and "on" or "auto" }
else
  scheme { "wcsph-usaw", sound_speed = 10 * u_max_est, background_pressure = 5e4,
           wall_guard = guard == 1 and "on" or "auto" }
end
fluid { density = rho, viscosity = nu, body_force = {force_x, 0} }
-- at rest with a low turbulence: k = 1e-4 m²/s², its length scale 0.1 b
local k0 = 1e-4
local eps0 = 0.09 ^ 0.75 * k0 ^ 1.5 / (0.1 * b)
if turb == 1 then
  turbulence { model = "k-epsilon", k = k0, epsilon = eps0, production = prod == 1 and "standard" or nil }
end
-- the lower wall with the long baffle, left to right (the fluid on the left: above it)
local lower = { {x0, 0}, {xp, 0}, {xp, yl}, {xp + tl, yl}, {xp + tl, 0}, {x0 + L, 0} }
local upper = { {x0 + L, B}, {xp + ts, B}, {xp + ts, ys}, {xp, ys}, {xp, B}, {x0, B} }
wall { lower[1], lower[2], lower[3], lower[4], lower[5], lower[6], fluid = "left", group = "lower" }
-- the upper wall with the short baffle, right to left (the fluid on the left: below it)
wall { upper[1], upper[2], upper[3], upper[4], upper[5], upper[6], fluid = "left", group = "upper" }
local pool = {}
for _, q in ipairs(lower) do pool[#pool + 1] = q end
for _, q in ipairs(upper) do pool[#pool + 1] = q end
fill { polygon = pool, name = "pool" }
force { "lower" }
force { "upper" }
local sections = { P1 = 1.6, P2 = 2.2, P3 = 2.8 }
for _, name in ipairs({"P1", "P2", "P3"}) do
  profile { name, from = {sections[name], 0.025}, to = {sections[name], B - 0.025}, points = 95 }
end
profile { "P4", from = {1.175, 0.25 * dr}, to = {2.975, 0.25 * dr}, points = 37 }
run { t_end = t_end, output_every = every, sample_every = math.min(every, 0.02), cfl = cfl }
render { field = "speed" }

-- ∫ u_x dy across x = 2.2 (P2), by the midpoint rule on points dr apart
local function flow_rate(sim)
  local m = math.max(math.floor(B / dr + 0.5), 8)
  local q = 0
  for j = 0, m - 1 do
    local u = sim.sample("vel", sections.P2, (j + 0.5) * B / m, 1)
    if u == u then q = q + u * B / m end
  end
  return q
end

local function speed_max(sim)
  local u, v = sim.field("vel", 1).value, sim.field("vel", 2).value
  local s = 0
  for i = 1, #u do s = math.max(s, u[i] * u[i] + v[i] * v[i]) end
  return math.sqrt(s)
end

function sample(sim)
  return { flow_rate = flow_rate(sim), u_max = speed_max(sim), bulk = sim.mean("vel", 1) }
end

-- The x momentum over the run: M (U(t) − U(0)) = M f t − ∫ F_x dt, M the fluid's mass (ρ dr² per
-- particle), U its mean x velocity, F_x the walls' force from the fluid (forces.csv, both groups,
-- trapezoid over its samples). Returns the imbalance over M f t: what the walls' recorded force
-- (pressure, viscous and the wall law's shear) misses of what the particles felt.
local function momentum_residual(sim)
  local lo, up = sim.force_history("lower"), sim.force_history("upper")
  local impulse = 0
  for i = 2, #lo.time do
    impulse = impulse + 0.5 * (lo.x[i] + lo.x[i - 1] + up.x[i] + up.x[i - 1]) * (lo.time[i] - lo.time[i - 1])
  end
  local t = lo.time[#lo.time]
  local mass = rho * dr * dr * #sim.field("vel", 1).value
  local gain = mass * sim.mean("vel", 1)
  return (gain - (mass * force_x * t - impulse)) / (mass * force_x * t)
end

function metrics(sim)
  local m = { flow_rate = flow_rate(sim), u_max = speed_max(sim), bulk = sim.mean("vel", 1),
              crossed_wall = sim.wall_crossing_steps, momentum_residual = momentum_residual(sim) }
  local ref = sim.reference("tests/data/openfoam_fish_pass.csv", "line", "x", "y", "U_x", "U_y", "p", "k",
                            "epsilon")
  -- the reference's largest speed on P1-P3, its flow rate across P2 (trapezoid over its points,
  -- with u = 0 on the walls)
  local uref, q_fv, prev_y, prev_u = 0, 0, 0, 0
  local pmean_fv, np = 0, 0
  for i = 1, #ref.line do
    if ref.line[i] ~= "P4" then
      uref = math.max(uref, math.sqrt(ref.U_x[i] ^ 2 + ref.U_y[i] ^ 2))
      pmean_fv, np = pmean_fv + ref.p[i], np + 1
    end
    if ref.line[i] == "P2" then
      q_fv = q_fv + 0.5 * (ref.U_x[i] + prev_u) * (ref.y[i] - prev_y)
      prev_y, prev_u = ref.y[i], ref.U_x[i]
    end
  end
  q_fv = q_fv + 0.5 * prev_u * (B - prev_y)
  pmean_fv = pmean_fv / np
  -- the run's fields at the reference's points; the pressure's level over P1-P3 as the reference's
  local vals, pmean = {}, 0
  for i = 1, #ref.line do
    local x, y = ref.x[i], ref.y[i]
    if ref.line[i] == "P4" then y = 0.25 * dr end
    local v = { ux = sim.sample("vel", x, y, 1), uy = sim.sample("vel", x, y, 2), p = sim.sample("p", x, y) }
    if turb == 1 then v.k, v.eps = sim.sample("k", x, y), sim.sample("epsilon", x, y) end
    vals[i] = v
    if ref.line[i] ~= "P4" then pmean = pmean + v.p / np end
  end
  local q = 0.5 * rho * uref * uref
  for _, name in ipairs({"P1", "P2", "P3", "P4"}) do
    local su, sp, sk, se, c, kmax = 0, 0, 0, 0, 0, 0
    for i = 1, #ref.line do
      if ref.line[i] == name then kmax = math.max(kmax, ref.k[i]) end
    end
    for i = 1, #ref.line do
      local v = vals[i]
      if ref.line[i] == name and v.ux == v.ux and v.p == v.p then
        su = su + (v.ux - ref.U_x[i]) ^ 2 + (v.uy - ref.U_y[i]) ^ 2
        sp = sp + ((v.p - pmean) - (ref.p[i] - pmean_fv)) ^ 2
        if turb == 1 and name ~= "P4" then
          sk = sk + (v.k - ref.k[i]) ^ 2
          se = se + math.log(math.max(v.eps, 1e-30) / ref.epsilon[i], 10) ^ 2
        end
        c = c + 1
      end
    end
    if c > 0 then
      m["p_rms_" .. name] = math.sqrt(sp / c) / q
      if name ~= "P4" then
        m["u_rms_" .. name] = math.sqrt(su / c) / uref
        if turb == 1 then
          m["k_rms_" .. name] = math.sqrt(sk / c) / kmax
          m["eps_log_rms_" .. name] = math.sqrt(se / c)
        end
      end
    end
    m["points_" .. name] = c
  end
  m.u_ref_fv = uref
  m.flow_rate_fv = q_fv
  m.flow_rate_dev = m.flow_rate / q_fv - 1
  -- the flow rate over time against OpenFOAM's (its steps nearest each 0.05 s, linear between)
  local hist = sim.reference("tests/data/openfoam_fish_pass_flow.csv", "time", "flow_rate")
  local function q_fv_at(t)
    for j = 2, #hist.time do
      if hist.time[j] >= t then
        local a = (t - hist.time[j - 1]) / (hist.time[j] - hist.time[j - 1])
        return hist.flow_rate[j - 1] + a * (hist.flow_rate[j] - hist.flow_rate[j - 1])
      end
    end
    return hist.flow_rate[#hist.time]
  end
  local series = sim.series("flow_rate")
  local sq, c = 0, 0
  for j = 1, #series.time do
    if series.time[j] > 0 and series.time[j] <= hist.time[#hist.time] then
      sq, c = sq + (series.value[j] - q_fv_at(series.time[j])) ^ 2, c + 1
    end
  end
  m.flow_rate_fv_now = q_fv_at(sim.time)
  m.flow_rate_dev_now = m.flow_rate / m.flow_rate_fv_now - 1
  m.flow_rate_history_rms = math.sqrt(sq / math.max(c, 1)) / q_fv
  return m
end
