-- isph-usaw's shift_velocity takes "on" or "off" (tests/case.cmake: case_shift_velocity)
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme { "isph-usaw", shift_velocity = "yes" }
fluid { density = 1, viscosity = 0.01 }
wall { {0, 1}, {0, 0}, {1, 0}, {1, 1}, {0, 1}, fluid = "left" }
fill { 0, 0, 1, 1 }
run { t_end = 0.1 }
