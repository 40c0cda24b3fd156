-- A ramp that cannot be: negative (natural = 0) or on a natural exit, which takes the fluid's
-- velocity (natural = 1); and a natural exit given a speed (natural = 2).
param { natural = 0 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme "wcsph-riemann"
fluid { density = 1, viscosity = 1 }
wall { {1.3, 0}, {-0.3, 0}, fluid = "right" }
wall { {-0.3, 1}, {1.3, 1}, fluid = "right" }
fill { 0, 0, 1, 1 }
inflow { {0, 1}, {0, 0}, velocity = 1, profile = "parabolic", ramp = natural == 0 and -1 or 1 }
outflow { {1, 0}, {1, 1}, ramp = natural == 1 and 0.5 or nil, velocity = natural == 2 and 2 or nil }
run { t_end = 1 }
