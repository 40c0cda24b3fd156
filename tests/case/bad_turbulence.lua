-- A channel that declares turbulence in ways the loader must refuse (what = ...):
--   1 a scheme without a turbulence model, 2 y_p in the viscous sublayer, 3 k without epsilon,
--   4 k and epsilon whose length scale exceeds the domain, 5 nu_t without a delay, 6 k < 0,
--   7 fill { k, epsilon } without turbulence { }, 8 fill { epsilon } < 0, 9 an unknown model,
--   10 k not a number, 11 a reference table that does not exist; isph-usaw with the keys of
--   wcsph-riemann's wall model: 12 y_p, 13 wall_weight, 14 delay; 15 wcsph-usaw with y_p;
--   16 a misspelt wall_law, 17 wall_law in wcsph-riemann, 18 an unknown production, 19 production
--   in wcsph-riemann
param { what = 1 }
local usaw = what >= 12 and what ~= 17 and what ~= 19
local L = usaw and 1.5 or 1 -- the segments' grid needs a longer period
domain { 0, 0, L, 2, periodic = "x" }
particles { dr = 0.1 }
if what == 15 then
  scheme { "wcsph-usaw", sound_speed = 1 }
elseif what == 17 or what == 19 then
  scheme { "wcsph-riemann", sound_speed = 1 }
else
  scheme(what == 1 and "isph-rotational" or (usaw and "isph-usaw") or "wcsph-riemann")
end
fluid { density = 1, viscosity = 1e-4, body_force = {0.003, 0} }
local k, eps = 0.01, 0.004
if what == 2 then
  turbulence { model = "k-epsilon", k = k, epsilon = eps, y_p = 0.01 }
elseif what == 3 then
  turbulence { model = "k-epsilon", k = k }
elseif what == 4 then
  turbulence { model = "k-epsilon", k = k, epsilon = 1e-7 }
elseif what == 5 then
  turbulence { model = "k-epsilon", k = k, epsilon = eps, nu_t = 1e-3 }
elseif what == 6 then
  turbulence { model = "k-epsilon", k = -k, epsilon = eps }
elseif what == 7 then
  -- no turbulence { }
elseif what == 9 then
  turbulence { model = "k-omega", k = k, epsilon = eps }
elseif what == 10 then
  turbulence { model = "k-epsilon", k = "big", epsilon = eps }
elseif what == 11 then
  local r = reference("tests/data/no_such_table.csv", "y")
elseif what == 12 or what == 15 then
  turbulence { model = "k-epsilon", k = k, epsilon = eps, y_p = 0.1 }
elseif what == 13 then
  turbulence { model = "k-epsilon", k = k, epsilon = eps, wall_weight = 0.2 }
elseif what == 16 then
  turbulence { model = "k-epsilon", k = k, epsilon = eps, wall_law = "scaleable" }
elseif what == 17 then
  turbulence { model = "k-epsilon", k = k, epsilon = eps, wall_law = "scalable" }
elseif what == 18 then
  turbulence { model = "k-epsilon", k = k, epsilon = eps, production = "linear" }
elseif what == 19 then
  turbulence { model = "k-epsilon", k = k, epsilon = eps, production = "standard" }
elseif what == 14 then
  turbulence { model = "k-epsilon", k = k, epsilon = eps, delay = 1, nu_t = 1e-3 }
else
  turbulence { model = "k-epsilon", k = k, epsilon = eps }
end
wall { {L, 0}, {0, 0}, fluid = "right" }
wall { {0, 2}, {L, 2}, fluid = "right" }
fill { 0, 0, L, 2, k = what >= 7 and function(x, y) return 0.01 end or nil,
       epsilon = what == 8 and -1 or nil }
run { t_end = 1 }
