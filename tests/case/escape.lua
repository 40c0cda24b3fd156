-- A block of ballistic particles (they see no walls) moving right at 1 m/s in a closed unit box:
-- its front, at x = 0.475 m, passes the wall at t = 0.525 s and is more than dr beyond the domain
-- at t = 0.575 s (where it lands on dr beyond exactly: in float the step after, 0.6 s), where the
-- run must stop as escaped (the cell grid, which reaches some 11 dr beyond the domain for wall
-- layers, would let it run on to t ≈ 1.1 s).
-- width: the block's length along x (0.05: one column, which leaves in one step).
param { width = 0.2 }
domain { 0, 0, 1, 1 }
particles { dr = 0.05 }
scheme "ballistic"
box_wall { 0, 0, 1, 1 }
fill { 0.5 - width, 0.3, 0.5, 0.5, velocity = {1, 0} }
run { t_end = 2, output_every = 0.5 }
