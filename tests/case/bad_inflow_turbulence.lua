-- An entry's turbulence, and wcsph-riemann's momentum dissipation, in ways the loader must refuse
-- (what = ...): 1 inflow { k, epsilon } without turbulence { }, 2 k without epsilon, 3 k and
-- epsilon whose length scale exceeds the entry's width, 4 a negative epsilon, 5 the reconstructed
-- dissipation in a laminar scene, 6 momentum_dissipation = "off" with ARD
param { what = 1 }
domain { 0, 0, 2, 1 }
particles { dr = 0.1 }
local opts = {"wcsph-riemann"}
if what == 5 then opts.momentum_dissipation = "reconstructed" end
if what == 6 then opts.ard, opts.momentum_dissipation = 1, "off" end
scheme(opts)
fluid { density = 1, viscosity = 1e-5 }
if what ~= 1 and what ~= 5 then turbulence { model = "k-epsilon", k = 0.01, epsilon = 0.0025 } end
wall { {2.3, 0}, {-0.3, 0}, fluid = "right" }
wall { {-0.3, 1}, {2.3, 1}, fluid = "right" }
fill { 0, 0, 2, 1 }
local k, eps = 0.01, 0.0025
if what == 2 then eps = nil end
if what == 3 then eps = 1e-6 end
if what == 4 then eps = -1 end
if what >= 5 then k, eps = nil, nil end
inflow { {0, 1}, {0, 0}, velocity = 1, k = k, epsilon = eps, name = "entry" }
outflow { {2, 0}, {2, 1}, name = "exit" }
run { t_end = 1 }
