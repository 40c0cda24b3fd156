-- Output cadences that are refused before anything is written, more snapshots than
-- run { max_snapshots } (10000): every = 1e-12 s to t_end = 1 s (1e12 snapshots), or every =
-- 0.05 s to t_end = 1000 s (20000).
param { every = 1e-12, t_end = 1 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme "ballistic"
fluid { gravity = {0, -9.81} }
box_wall { 0, 0, 1, 1 }
fill { 0.2, 0.2, 0.8, 0.8 }
run { t_end = t_end, output_every = every }
