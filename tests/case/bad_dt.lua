-- a fixed time step far above the scheme's bounds
domain { 0, 0, 1, 1.5 }
particles { dr = 0.1 }
scheme "isph-usaw"
fluid { density = 1000, viscosity = 1e-6, gravity = {0, -9.81} }
wall { {0, 1.5}, {0, 0}, {1, 0}, {1, 1.5}, fluid = "left" }
fill { 0, 0, 1, 1 }
run { t_end = 1, dt = 0.5 }
