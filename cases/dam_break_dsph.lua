-- Dam break of DualSPHysics 5.4's own 2-D validation case, CaseDambreakVal2D (examples/main/
-- 01_DamBreak), the speed anchor of `clsph bench dambreak`: a tank 4 m long with walls 3 m high
-- (bottom, left and right; open at the top) and a water column 1 m wide and 2 m high against the
-- left wall, released at t = 0 (no gate). dp = 0.01 m gives 100 × 200 = 20,000 fluid particles;
-- c0 = 88.4 m/s, ρ = 1000 kg/m³, ν = 1e-6 m²/s, g = 9.81 m/s²; 0.5 s simulated (DualSPHysics
-- 5.4 takes 15,880 steps and 120 s on 2 cores for it). The geometry and these figures are those
-- the speed issue describes, not read from DualSPHysics's XML.
-- What differs from DualSPHysics's run: our smoothing function and smoothing length (the
-- scheme's choice; wcsph-usaw: Wendland C2 at h = 2 dp), our walls (unified semi-analytical wall segments, not
-- layers of boundary particles) and our time stepping (wcsph-usaw: symplectic Euler at
-- min(0.2 h/c0, 0.125 h²/ν, 0.25 √(h/|a|)); wcsph-riemann: advection steps of several acoustic
-- sub-steps); so the steps and the particle counts with walls differ, the fluid does not.
-- Outputs are off (the loop's first and last snapshots and its final checkpoint only): the case
-- is timed. metrics: front, the largest x of the fluid within 2 dp of the floor at the end (m).
-- --set riemann=0 runs wcsph-usaw with the same sound speed, for comparison.
param { dp = 0.01, t_end = 0.5, riemann = 1 }

local g, tank, top, width, height = 9.81, 4.0, 3.0, 1.0, 2.0

domain { 0, 0, tank, top }
particles { dr = dp }
if riemann == 1 then
  scheme { "wcsph-riemann", sound_speed = 88.4 }
else
  scheme { "wcsph-usaw", sound_speed = 88.4 }
end
fluid { density = 1000, viscosity = 1e-6, gravity = {0, -g} }
wall { {0, top}, {0, 0}, {tank, 0}, {tank, top}, fluid = "left", group = "tank" }
fill { 0, 0, width, height, name = "water" }
run { t_end = t_end }

function metrics(sim)
  return { front = sim.max("pos", 1, {0, 0, tank, 2 * dp}) or 0 }
end
