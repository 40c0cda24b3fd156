-- Flow past a square cylinder in a channel (Hosseini & Feng 2011 sec 4.3, fig 1): a square of
-- side D centred at height H/2 between no-slip walls H = 8 D apart, a parabolic entry profile of
-- peak U0 at x = 0 and a natural exit at x = length (parabolic above Re = 10, as the paper does),
-- Re = U0 D / ν. Units D = U0 = ρ = 1 (time in D/U0). The paper's convergence study is Re = 1 in
-- a channel 3H = 24 D long with the cylinder in its middle (xc = 12) at L0 = H/40, H/80, H/160
-- (n = 40, 80, 160); its Re sweep (5 to 50) matches Breuer et al. 2000: length 32 D, the cylinder
-- 8 D from the entry. Drag (eqs 31-32): C_D = f_d / (½ ρ U0² D), the wall force of the fluid on the
-- cylinder, averaged over 1 <= t <= t_end (the paper's 1 to 10), against the finite-volume C_D
-- of Breuer et al. 2000 (tests/data/breuer2000_square_cylinder_cd.csv, digitised, ±4-6%; the
-- value at Re = 1, 24.0, was read from the same figure at 25.3 by a second digitisation).
-- Profiles: u and p along the centreline (profile "centreline").
-- Metrics: cd, its pressure and viscous parts, pressure_share = cd_pressure / cd (the paper:
-- about 2/3), cl (zero by symmetry while the wake is steady), cd_dev = cd / cd_ref − 1 and
-- cd_error = |cd_dev|; upstream (how far fluid got upstream of the entry by the end, in dr:
-- 0); where the wake sheds vortices, strouhal = f D / U0 (the frequency of the lift, searched
-- up to 0.5 U0/D: the shedding of bluff bodies lies at 0.1 to 0.3) and cl_amplitude (the
-- amplitude of that oscillation of C_L); cl_spectrum_median (the median amplitude of the lift's
-- spectrum up to 2 U0/D: its noise); cl_ringing_frequency and cl_ringing_amplitude, where the
-- strongest line of that spectrum lies above the shedding band (the weakly-compressible
-- wcsph-riemann's channel rings at about 1.7 U0/D with c0 = 10 U0). In Breuer's geometry
-- (length = 32, xc = 8) at an Re that tests/data/openfoam_square_cylinder.csv holds (20, 100):
-- cd_openfoam and cd_dev_openfoam, strouhal_openfoam and strouhal_dev_openfoam (its finest mesh).
-- cfl multiplies the scheme's time-step bounds (the stability map); the drag is averaged from
-- t = average_from (the paper's 1 at Re = 1; the wake of Re = 20 takes about 12 D/U0 to
-- settle). implicit = 1 solves the prediction's viscous term implicitly (viscous = "implicit", not
-- the paper's explicit one): at Re = 1 the explicit viscous bound is 1/30 of the CFL bound at
-- H/160 (0.125 h²/ν against 0.25 h/U, h = 1.2 L0), so this is what makes H/160 affordable. It
-- suits the rotational projection (C_D within 0.2% of the explicit run's at H/40 and H/80); the
-- homogeneous one's splitting error grows with the step: C_D 9% and 17% higher than its explicit
-- runs' at H/40 and H/80, the pressure's share of it 0.45 and 0.34 instead of 0.63 and 0.51.
-- riemann = 1 runs the weakly-compressible wcsph-riemann instead (dummy walls, the same entry and
-- exit sections; c0 = sound speed in U0, 0: its default 10 U with U the entry's peak speed U0),
-- with the density from the continuity equation alone: re-set by summation (summation = 1, the
-- scheme's default) the pressure is c0² times the particles' disorder, and C_D at Re = 20, H/40
-- was 3.44 at c0 = 10 U0 and 4.70 at 20 U0 (2.79 and 2.84 without; Breuer 2.40).
-- ramp: the entry's (and a prescribed exit's) speed rises over `ramp` D/U0 (inflow { ramp });
-- default 0 for isph-rotational (the paper's impulsive start), 2 with riemann = 1: an impulsive
-- start sends a pressure pulse ρ c0 U0 (10% of ρ0 at c0 = 10 U0) up and down the channel, and at
-- Re = 100, H/40 the entry's layers then piled up at t = 8 (the exits gave back too few
-- particles while the fluid was rarefied).
param { n = 80, re = 1, t_end = 10, length = 24, xc = 12, homogeneous = 0, exit_parabolic = 0,
        xsph = 0, shift = 0.04, outputs = 20, cfl = 1, average_from = 1, developed = 0,
        checkpoint = 0, implicit = 0, riemann = 0, c0 = 0, ramp = -1, summation = 0 }

if summation ~= 0 and summation ~= 1 then
  error(string.format("summation = %s: 1 (density re-set by summation) or 0 (the continuity " ..
                      "equation alone)", tostring(summation)))
end
local D, U0, H = 1, 1, 8
local nu, dr = U0 * D / re, H / n
domain { 0, 0, length, H }
particles { dr = dr }
if riemann == 1 then
  scheme { "wcsph-riemann", sound_speed = c0 > 0 and c0 * U0 or nil,
           density = ({"continuity", "summation"})[summation + 1] }
else
  scheme { "isph-rotational", projection = homogeneous == 1 and "homogeneous" or "rotational",
           shifting = shift, xsph = xsph, wall_velocity = "image",
           viscous = implicit == 1 and "implicit" or "explicit" }
end
fluid { density = 1, viscosity = nu }
local e = 3 * dr -- the channel walls run on through the entry and exit layers
wall { {length + e, 0}, {-e, 0}, fluid = "right", group = "floor" }
wall { {-e, H}, {length + e, H}, fluid = "right", group = "ceiling" }
local x0, x1, y0, y1 = xc - D / 2, xc + D / 2, H / 2 - D / 2, H / 2 + D / 2
wall { {x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, closed = true, fluid = "outside",
       group = "cylinder" }
-- The fluid starts at rest (the first projection turns it into the potential flow of the entry's
-- flux): the channel's profile then develops over H²/ν = 64 Re D/U0 (at Re = 20 the centreline
-- speed 20 D downstream of the cylinder is still 9% short at t = 20). developed = 1 starts it
-- with the entry's Poiseuille profile instead, a harder start at the cylinder's corners (at
-- Re = 100, H/40 it blows up there by t = 4.4).
fill { 0, 0, length, H, velocity = function(_, y)
  return developed == 1 and 4 * U0 * y / H * (1 - y / H) or 0, 0
end }
local rise = ramp >= 0 and ramp or (riemann == 1 and 2 or 0)
inflow { {0, H}, {0, 0}, velocity = U0, profile = "parabolic", name = "entry", ramp = rise * D / U0 }
outflow { {length, 0}, {length, H}, name = "exit",
          profile = exit_parabolic == 1 and "parabolic" or "natural",
          velocity = exit_parabolic == 1 and U0 or nil,
          ramp = exit_parabolic == 1 and rise * D / U0 or nil }
force { "cylinder" }
profile { "centreline", from = {0, H / 2}, to = {length, H / 2}, points = 4 * length + 1 }
run { t_end = t_end, output_every = t_end / outputs, sample_every = 0.05, cfl = cfl,
      checkpoint_every = checkpoint > 0 and checkpoint or nil } -- D/U0 between checkpoints

-- Breuer et al.'s C_D at this Re (Re, C_D from tests/data/breuer2000_square_cylinder_cd.csv),
-- linear in log-log between the tabulated points
local BREUER = { {0.5, 47.4}, {1, 24.0}, {2, 12.34}, {5, 5.67}, {10, 3.49}, {15, 2.76},
                 {20, 2.40}, {25, 2.16}, {30, 1.98}, {35, 1.84}, {40, 1.74}, {45, 1.66},
                 {50, 1.59}, {55, 1.53}, {60, 1.48} }
local function breuer(r)
  for k = 1, #BREUER - 1 do
    local a, b = BREUER[k], BREUER[k + 1]
    if r >= a[1] and r <= b[1] then
      local f = math.log(r / a[1]) / math.log(b[1] / a[1])
      return math.exp(math.log(a[2]) + f * math.log(b[2] / a[2]))
    end
  end
  return nil
end

function metrics(sim)
  local f = sim.force("cylinder", math.min(average_from, t_end / 2))
  local q = 0.5 * U0 * U0 * D
  local out = { cd = f.x / q, cd_pressure = f.pressure_x / q, cd_viscous = f.viscous_x / q,
                cl = f.y / q, force_samples = f.samples }
  out.pressure_share = out.cd_pressure / out.cd
  -- fluid upstream of the entry section (x = 0) at the end, in dr: 0 unless the entry's layers
  -- let fluid through
  out.upstream = math.max(-sim.min("pos", 1), 0) / dr
  -- vortex shedding: the spectrum of the lift over the averaging window (sim.spectrum_peak).
  -- Over a window of at least 20 D/U0, where one frequency stands out (an amplitude at least 4
  -- times the spectrum's median; the noise of the steady wakes at Re 20 and 50, H/80, peaks at
  -- 2.6-3.2 times it, the shedding at Re = 100 at 13.6), strouhal = f D / U0 and cl_amplitude is
  -- the amplitude of that oscillation of C_L; the force noise of SPH (a few per cent of C_D from
  -- sample to sample) spreads over all frequencies.
  local h = sim.force_history("cylinder", math.min(average_from, t_end / 2))
  local span = #h.time > 1 and h.time[#h.time] - h.time[1] or 0
  if #h.time >= 16 and span >= 20 * D / U0 then -- 3 periods at St = 0.15
    local all = sim.spectrum_peak(h.time, h.y, 0, 2 * U0 / D)
    local p = sim.spectrum_peak(h.time, h.y, 0, 0.5 * U0 / D)
    out.cl_spectrum_median = all.median / q
    if p.amplitude > 4 * all.median and p.amplitude > 1e-3 * math.abs(f.x) then
      out.strouhal = p.frequency * D / U0
      out.cl_amplitude = p.amplitude / q
      out.shedding_periods = p.frequency * span
    end
    -- a weakly-compressible channel also rings: the strongest line above the shedding band
    if all.frequency > 0.5 * U0 / D and all.amplitude > 4 * all.median then
      out.cl_ringing_frequency = all.frequency * D / U0
      out.cl_ringing_amplitude = all.amplitude / q
    end
  end
  -- OpenFOAM in this geometry (32 D, the cylinder 8 D from the entry; the finest mesh run at this
  -- Re: tests/data/openfoam_square_cylinder.csv, made by tests/validation/openfoam/square_cylinder)
  if length == 32 and xc == 8 then
    local of = sim.reference("tests/data/openfoam_square_cylinder.csv", "re", "cells", "cd",
                             "strouhal")
    local best
    for k = 1, #of.re do
      if of.re[k] == re and (best == nil or of.cells[k] > of.cells[best]) then best = k end
    end
    if best then
      out.cd_openfoam = of.cd[best]
      out.cd_dev_openfoam = out.cd / of.cd[best] - 1
      if out.strouhal and of.strouhal[best] == of.strouhal[best] then -- (NaN: steady)
        out.strouhal_openfoam = of.strouhal[best]
        out.strouhal_dev_openfoam = out.strouhal / of.strouhal[best] - 1
      end
    end
  end
  local ref = breuer(re)
  if ref then
    out.cd_ref = ref
    out.cd_dev = out.cd / ref - 1
    out.cd_error = math.abs(out.cd_dev)
  end
  return out
end
