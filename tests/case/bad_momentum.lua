-- wcsph-usaw's momentum takes "fused", "separate" or "auto" (tests/case.cmake: momentum_*):
-- what = 1 another word, 2 a number, 3 "fused" under the k-epsilon model (which advances k and
-- epsilon between the prediction and the pressure force)
param { what = 1 }
domain { 0, 0, 1.5, 2, periodic = "x" }
particles { dr = 0.1 }
local v = ({[1] = "merged", [2] = 1, [3] = "fused"})[what]
scheme { "wcsph-usaw", sound_speed = 1, momentum = v }
fluid { density = 1, viscosity = 1e-4, body_force = {0.003, 0} }
if what == 3 then
  turbulence { model = "k-epsilon", k = 0.01, epsilon = 0.004 }
end
wall { {0, 0}, {1.5, 0}, fluid = "left" }
wall { {1.5, 2}, {0, 2}, fluid = "left" }
fill { 0, 0, 1.5, 2 }
run { t_end = 0.1 }
