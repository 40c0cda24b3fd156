-- Infinite array of cylinders in a channel (Leroy et al. 2014 sec 4.2, Figure 10): a cylinder of
-- radius Rc = 0.02 m at mid-height of a channel between walls at z = 0 and 2H Rc = 0.08 m,
-- periodic in x with period Lc = L Rc (L = 6). A very viscous flow (µ = 0.1 Pa s, ρ = 1000,
-- Re = ρ Rc ⟨v⟩/µ = 0.024) driven by a body force that the flow-rate control (eqs 67-68) sets
-- each step so that the mean velocity in a slice of width δr at x = Lc (the periodic boundary,
-- away from the cylinder) is ⟨v⟩ = 1.2e-4 m/s. The drag per unit length on the cylinder,
-- F_D = Σ_s (−p_s n_s + µ [∇u_s + ∇u_sᵀ]) · e_x S_s (eqs 69-70), averaged over the last quarter
-- of the run, gives C_D = F_D/(µ⟨v⟩) against 106.77 (Liu et al., tests/data/
-- liu1998_cylinder_array_cd.csv). n is the number of particles across the channel (the paper's
-- 120; even, so that Lc is a whole number of spacings). The viscous time (H Rc)²/ν is 16 s; the
-- paper runs 80 s. --set wcsph=1 runs the WCSPH baseline. segment_cache: the scheme option (slots
-- a particle, 0 none: the same bits; -1, the default, the scheme's own).
param { n = 120, t_end = 80, wcsph = 0, outputs = 80, segment_cache = -1 }

local Rc, L, H = 0.02, 6, 2
local Lc, height = L * Rc, 2 * H * Rc
local mu, rho, U = 0.1, 1000, 1.2e-4
local cd_ref = 106.77 -- Liu et al., tests/data/liu1998_cylinder_array_cd.csv
local dr = height / n

domain { 0, 0, Lc, height, periodic = "x" }
particles { dr = dr }
local cache = segment_cache >= 0 and segment_cache or nil
if wcsph == 1 then
  -- The time step of this very viscous flow is the viscous bound 0.125 h²/ν for both schemes
  -- (the paper: "the time-step is the same with WCSPH and ISPH"), which the CFL bound
  -- 0.2 h/c0 matches at c0 = 1.6 ν/h (h = 2 dr); 10 times the largest speed would be 1000
  -- times slower and let the density vary by far more than the flow's pressure differences
  -- (about 0.02 Pa, against ρ c0² = 0.4 Pa at n = 20 and 14 Pa at n = 120).
  scheme { "wcsph-usaw", sound_speed = 1.6 * (mu / rho) / (2 * dr), segment_cache = cache }
else
  scheme { "isph-usaw", segment_cache = cache }
end
fluid { density = rho, viscosity = mu / rho,
        -- the slice of width δr ending at x = Lc holds the last lattice column in its middle
        -- (centred on Lc, its edges would run through two columns)
        flow_rate_control = { velocity = U, slice = { Lc - dr, Lc } } }
wall { {Lc, 0}, {0, 0}, fluid = "right", group = "floor" }
wall { {0, height}, {Lc, height}, fluid = "right", group = "ceiling" }
circle { centre = {Lc / 2, height / 2}, radius = Rc, fluid = "outside", group = "cylinder" }
fill { 0, 0, Lc, height, name = "channel" }
profile { "gap", from = {Lc / 2, 0}, to = {Lc / 2, height / 2 - Rc}, points = 21 }
force { "cylinder", "floor", "ceiling" }
run { t_end = t_end, output_every = t_end / outputs, checkpoint_every = t_end / 2 }

function metrics(sim)
  local f = sim.force("cylinder", 0.75 * t_end)
  local cd = f.x / (mu * U)
  return { cd = cd, cd_error = math.abs(cd - cd_ref) / cd_ref,
           cd_pressure = f.pressure_x / (mu * U), cd_viscous = f.viscous_x / (mu * U),
           cd_last = sim.force("cylinder").x / (mu * U), force_samples = f.samples }
end
