-- Ballistic particles in a box with fixed output cadences (the tests of output folders: reuse,
-- --overwrite, restarts in place, interrupts).
param { every = 0.05, t_end = 0.4, check = 0.2, dr = 0.1 }
domain { 0, 0, 1, 1 }
particles { dr = dr }
scheme "ballistic"
fluid { gravity = {0, -1} }
box_wall { 0, 0, 1, 1 }
fill { 0.2, 0.5, 0.8, 0.9 }
run { t_end = t_end, output_every = every, checkpoint_every = check }
