-- An entry's turbulence, and wcsph-riemann's momentum dissipation, in ways the loader must refuse
-- (what = ...): 1 inflow { k, epsilon } without turbulence { }, 2 k without epsilon, 3 k and
-- epsilon whose length scale exceeds the entry's width, 4 a negative epsilon, 5 the reconstructed
-- dissipation in a laminar scene, 6 momentum_dissipation = "off" with ARD; an entry given as
-- functions of s: 7 a velocity function that returns a string, 8 a k function negative at the far
-- end, 9 profile = with a velocity function, 10 ramp = with one, 11 a velocity function whose mean
-- flows out, 12 k and epsilon functions inconsistent near s = 1 (only there), 13 a k function
-- without epsilon, 14 a velocity function that returns NaN; 15 wall_shear = "distance" in a laminar
-- scene, 16 a wall_shear the scheme does not know; 17 velocity_gradient = "log" in a laminar scene,
-- 18 a velocity_gradient the scheme does not know; 19 turbulent_diffusion = "log_mirror" in a laminar
-- scene, 20 a turbulent_diffusion the scheme does not know; 21 offset_layer = "body_force" in a
-- laminar scene, 22 an offset_layer the scheme does not know, 23 offset_layer = "body_force" with
-- y_p under half the spacing (no layer below the first row), 24 wall_pressure_force = "normal" in a
-- laminar scene, 25 a wall_pressure_force the scheme does not know
param { what = 1 }
domain { 0, 0, 2, 1 }
particles { dr = 0.1 }
local opts = {"wcsph-riemann"}
if what == 5 then opts.momentum_dissipation = "reconstructed" end
if what == 6 then opts.ard, opts.momentum_dissipation = 1, "off" end
if what == 15 then opts.wall_shear = "distance" end
if what == 16 then opts.wall_shear = "wall" end
if what == 17 then opts.velocity_gradient = "log" end
if what == 18 then opts.velocity_gradient = "logarithmic" end
if what == 19 then opts.turbulent_diffusion = "log_mirror" end
if what == 20 then opts.turbulent_diffusion = "mirror" end
if what == 21 or what == 23 then opts.offset_layer = "body_force" end
if what == 22 then opts.offset_layer = "layer" end
if what == 24 then opts.wall_pressure_force = "normal" end
if what == 25 then opts.wall_pressure_force = "tangential" end
scheme(opts)
fluid { density = 1, viscosity = 1e-5 }
if what ~= 1 and what ~= 5 and what ~= 15 and what ~= 17 and what ~= 19 and what ~= 21 and what ~= 24 then
  turbulence { model = "k-epsilon", k = 0.01, epsilon = 0.0025, y_p = what == 23 and 0.02 or nil }
end
wall { {2.3, 0}, {-0.3, 0}, fluid = "right" }
wall { {-0.3, 1}, {2.3, 1}, fluid = "right" }
fill { 0, 0, 2, 1 }
local k, eps = 0.01, 0.0025
if what == 2 then eps = nil end
if what == 3 then eps = 1e-6 end
if what == 4 then eps = -1 end
if what == 5 or what == 6 or what == 15 or what == 17 or what == 19 or what == 21 or what == 24 then
  k, eps = nil, nil
end
local entry = {{0, 1}, {0, 0}, velocity = 1, k = k, epsilon = eps, name = "entry"}
if what == 7 then entry.velocity = function(s) return "fast" end end
if what == 8 then entry.k = function(s) return 0.01 - 0.02 * s end end
if what == 9 then entry.velocity, entry.profile = function(s) return 1 end, "parabolic" end
if what == 10 then entry.velocity, entry.ramp = function(s) return 1 end, 0.5 end
if what == 11 then entry.velocity = function(s) return 0.2 - s end end
if what == 12 then entry.epsilon = function(s) return s < 0.9 and 0.0025 or 1e-6 end end
if what == 13 then entry.k, entry.epsilon = function(s) return 0.01 end, nil end
if what == 14 then entry.velocity = function(s) return 0 / 0 end end
inflow(entry)
outflow { {2, 0}, {2, 1}, name = "exit" }
run { t_end = 1 }
