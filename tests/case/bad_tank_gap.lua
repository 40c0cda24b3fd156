-- A tank under gravity whose floor stops short of its right wall: the water leaks out below.
domain { 0, 0, 1, 1.5 }
particles { dr = 0.05 }
scheme "isph-usaw"
fluid { density = 1000, viscosity = 1e-6, gravity = {0, -9.81} }
wall { {0, 1.5}, {0, 0}, {0.8, 0}, fluid = "left" }
wall { {1, 0.2}, {1, 1.5}, fluid = "left" }
fill { 0, 0, 1, 1 }
run { t_end = 1 }
