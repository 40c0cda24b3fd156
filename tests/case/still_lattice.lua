-- The clustering check (tests/case.cmake): fluid particles on a square lattice of spacing dr
-- that nothing moves (scheme "none", h = 2 dr), so that every particle's nearest fluid neighbour
-- is exactly dr = h/2 away. With run { checks = { cluster_h = c } }, c just above 1/2 counts every
-- particle as clustered and stops the run; c just below 1/2 counts none.
param { dr = 0.1, cluster = 0.125, t_end = 1 }

domain { 0, 0, 1, 1 }
particles { dr = dr }
scheme "none"
fluid { density = 1000 }
box_wall { 0, 0, 1, 1 }
fill { 0, 0, 1, 1 }
run { t_end = t_end, output_every = t_end / 2, checks = { cluster_h = cluster } }
