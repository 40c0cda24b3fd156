-- isph-usaw's density_relaxation takes a coefficient from 0 to 1 (tests/case.cmake:
-- density_relaxation_*): what = 1 out of range, 2 not a number (NaN is out of range too)
param { what = 1 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
local v = ({[1] = 2, [2] = "strong", [3] = 0 / 0})[what]
scheme { "isph-usaw", density_relaxation = v }
fluid { density = 1, viscosity = 0.01 }
wall { {0, 1}, {0, 0}, {1, 0}, {1, 1}, {0, 1}, fluid = "left" }
fill { 0, 0, 1, 1 }
run { t_end = 0.1 }
