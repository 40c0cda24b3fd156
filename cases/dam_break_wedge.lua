-- Dam break over a wedge (Leroy et al. 2014 sec 4.3, the geometry of Ferrand et al. 2013): a
-- water column of depth H = 1 m collapses in a pool 2 m long and 1 m deep and runs over a
-- triangular wedge on the bottom; δr = 0.01 m, ν = 1e-2 m²/s, 2 s (t+ = t √(g/H) up to 6.3).
-- The output is the pressure force on the left side of the wedge against time (eq 71,
-- forces.csv, group "wedge_left"; tests/validation/wedge_chart.sh charts both schemes), and no
-- fluid particle may cross a wall.
--
-- The papers give the pool (2 m × 1 m) and the depth but not the column's width nor the wedge's
-- size and place; this case fixes them, and they stay fixed:
--   * the column fills 0 ≤ x ≤ 0.6 m, 0 ≤ z ≤ 1 m (6000 fluid particles at δr = 0.01 m, close to
--     the paper's 5881 particles);
--   * the wedge is an isosceles triangle standing on the bottom, base 1.2 m ≤ x ≤ 1.8 m, apex
--     (1.5 m, 0.3 m): both sides at 45°;
--   * the side walls rise to 1.6 m, so that the run-up on the right wall stays in the pool (the
--     flow never reaches 1 m but at the walls).
-- --set wcsph=1 runs the weakly-compressible baseline (c0 = 20 m/s, Ferrari density diffusion).
-- cfl multiplies the scheme's time-step constants; 0 (default) takes the paper's C_CFL = 0.2
-- (cfl = 2) with isph-usaw, whose own 0.1 keeps particles in the lid-driven cavity's corners:
-- here the wall guard of scenes with gravity holds them (no wall crossing, the mean force on the
-- wedge 4% under the run at 0.1, half the steps), and wcsph-usaw's own constants (cfl = 1).
-- relax: isph-usaw's density_relaxation (0, the paper's projection, by default).
-- segment_cache: the scheme option (slots a particle, 0 none: the same bits; -1, the default, the
-- scheme's own). momentum: wcsph-usaw's option, 1 "fused", 2 "separate" (the same bits), 0 its
-- default.
param { dr = 0.01, t_end = 2, nu = 1e-2, wcsph = 0, offset = 0.5, cfl = 0, relax = 0,
        segment_cache = -1, momentum = 0 }

local g, H, L, top = 9.81, 1.0, 2.0, 1.6
local column = 0.6
local base0, base1, apex = 1.2, 1.8, {1.5, 0.3}

domain { 0, 0, L, top }
particles { dr = dr }
local cache = segment_cache >= 0 and segment_cache or nil
if wcsph == 1 then -- the paper's baseline: c0 = 20 m/s and a Ferrari density correction
  local forms = { [1] = "fused", [2] = "separate" }
  scheme { "wcsph-usaw", sound_speed = 20, segment_cache = cache, momentum = forms[momentum] }
else
  scheme { "isph-usaw", free_surface_offset = offset, density_relaxation = relax,
           segment_cache = cache }
end
fluid { density = 1000, viscosity = nu, gravity = {0, -g} }
-- one container, in three pieces so that the wedge's left side is a group of its own; the
-- pieces share their end points, and the fluid is on the left of the direction of travel
wall { {0, top}, {0, 0}, {base0, 0}, fluid = "left", group = "pool" }
wall { {base0, 0}, apex, fluid = "left", group = "wedge_left" }
wall { apex, {base1, 0}, {L, 0}, {L, top}, fluid = "left", group = "pool" }
fill { 0, 0, column, H, name = "water" }
force { "wedge_left" }
probe { "right_wall", {L - 2 * dr, 0.1} }
if cfl == 0 then cfl = wcsph == 1 and 1 or 2 end
run { t_end = t_end, output_every = 0.1, sample_every = 0.005, cfl = cfl }

function metrics(sim)
  -- fluid particles behind a wall: the walls check every step; the box check catches a particle
  -- thrown beyond the reach of every segment
  local crossed = sim.wall_crossing_steps
  if sim.min("pos", 1) < 0 or sim.max("pos", 1) > L or sim.min("pos", 2) < 0 then
    crossed = crossed + 1
  end
  -- the pressure force on the left side, normal to it (it pushes the wedge along (1, −1)/√2),
  -- averaged from the front's arrival (t = 0.25 s) on; at rest the water would stand 0.345 m
  -- deep and push with √2 ρ g (0.345 · 0.3 − 0.3²/2) = 811 N/m
  local f = sim.force("wedge_left", 0.25)
  return { crossed_wall = crossed, max_speed_over_sqrt_gH =
    math.max(-sim.min("vel", 1), sim.max("vel", 1), -sim.min("vel", 2), sim.max("vel", 2)) /
    math.sqrt(g * H), wedge_force_mean = (f.x - f.y) / math.sqrt(2) }
end
