domain { 0, 0, 1, 1, periodic = "x" }
particles { dr = 0.1 }
scheme { "isph-rotational", viscous = "sometimes" }
fluid { density = 1, viscosity = 1, body_force = {1, 0} }
wall { {1, 0}, {0, 0}, fluid = "right" }
wall { {0, 1}, {1, 1}, fluid = "right" }
fill { 0, 0, 1, 1 }
run { t_end = 1 }
