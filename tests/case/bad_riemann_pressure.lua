-- wcsph-riemann with a background pressure beyond any water's (1e300 Pa).
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme { "wcsph-riemann", sound_speed = 10, background_pressure = 1e300 }
fluid { density = 1, viscosity = 0.01 }
box_wall { 0, 0, 1, 1, lid_velocity = {1, 0} }
fill { 0, 0, 1, 1 }
run { t_end = 1 }
