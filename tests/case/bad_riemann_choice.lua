-- wcsph-riemann with a transport-velocity choice it does not know.
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme { "wcsph-riemann", sound_speed = 10, transport_velocity = "strong" }
fluid { density = 1, viscosity = 0.01 }
box_wall { 0, 0, 1, 1, lid_velocity = {1, 0} }
fill { 0, 0, 1, 1 }
run { t_end = 1 }
