-- The clustering check (tests/case.cmake): fluid particles on a square lattice of spacing dr
-- that nothing moves (scheme "none"), so that every particle's nearest fluid neighbour is
-- exactly dr away. With run { checks = { cluster_spacing = s } }, s just above 1 counts every
-- particle as clustered and stops the run; s just below 1 counts none.
param { dr = 0.1, spacing = 0.5, t_end = 1 }

domain { 0, 0, 1, 1 }
particles { dr = dr }
scheme "none"
fluid { density = 1000 }
box_wall { 0, 0, 1, 1 }
fill { 0, 0, 1, 1 }
run { t_end = t_end, output_every = t_end / 2, checks = { cluster_spacing = spacing } }
