-- A water column released in a tank (isph-usaw, δr = 0.02 m), its first 0.03 s: the pressure
-- equation's right-hand side made by the free-surface kernel (density_relaxation = 0) or by its
-- own kernel (relax > 0; tests/case.cmake: rhs_fused)
param { relax = 0, t_end = 0.03 }
domain { 0, 0, 1, 0.7 }
particles { dr = 0.02 }
scheme { "isph-usaw", density_relaxation = relax }
fluid { density = 1000, viscosity = 1e-2, gravity = {0, -9.81} }
wall { {0, 0.7}, {0, 0}, {1, 0}, {1, 0.7}, fluid = "left" }
fill { 0, 0, 0.4, 0.4 }
run { t_end = t_end, output_every = t_end }
