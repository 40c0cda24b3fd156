domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme "isph-rotational"
wall { {1.3, 0}, {-0.3, 0}, fluid = "right" }
wall { {-0.3, 1}, {1.3, 1}, fluid = "right" }
fill { 0, 0, 1, 1 }
inflow { {0, 1}, {0, 0}, velocity = 1, profile = "parabolic" }
outflow { {1, 0}, {1, 1}, profile = "parabolic", name = "exit" }
run { t_end = 1 }
