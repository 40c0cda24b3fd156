-- A lid-driven cavity whose lid was forgotten: with no gravity nothing keeps the fluid in.
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme "isph-usaw"
fluid { density = 1, viscosity = 0.01 }
wall { {0, 1}, {0, 0}, {1, 0}, {1, 1}, fluid = "left" }
fill { 0, 0, 1, 1 }
run { t_end = 1 }
