-- wcsph-riemann with a wall pressure it does not know ("linear": mirror or gradient).
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme { "wcsph-riemann", sound_speed = 10, wall_pressure = "linear" }
fluid { density = 1, viscosity = 0.01 }
box_wall { 0, 0, 1, 1, lid_velocity = {1, 0} }
fill { 0, 0, 1, 1 }
run { t_end = 1 }
