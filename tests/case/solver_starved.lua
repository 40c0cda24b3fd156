-- The pressure solver's failure class (tests/case.cmake): a coarse lid-driven cavity whose
-- pressure solve may take one BiCGStab iteration to a tolerance it cannot reach in one, so every
-- solve fails and the tenth in a row stops the run (psolve.c), classified "solver".
param { n = 10, t_end = 1 }

domain { 0, 0, 1, 1 }
particles { dr = 1 / n }
scheme { "isph-usaw", solver_max_it = 1, solver_rtol = 1e-6 }
fluid { density = 1, viscosity = 0.01 }
box_wall { 0, 0, 1, 1, lid_velocity = {1, 0} }
fill { 0, 0, 1, 1 }
run { t_end = t_end, output_every = t_end }
