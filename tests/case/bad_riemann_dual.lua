-- wcsph-riemann with CFL numbers that make the advection step shorter than the acoustic one at
-- the scene's velocity scale (U = 1 m/s, c0 = 10 m/s: ratio (0.01/1) (11/1) = 0.11 < 1).
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme { "wcsph-riemann", sound_speed = 10, advection_cfl = 0.01, acoustic_cfl = 1 }
fluid { density = 1, viscosity = 0.01 }
box_wall { 0, 0, 1, 1, lid_velocity = {1, 0} }
fill { 0, 0, 1, 1 }
run { t_end = 1 }
