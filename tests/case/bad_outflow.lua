domain { 0, 0, 3, 1 }
particles { dr = 0.1 }
scheme "none"
wall { {0, 1}, {0, 0}, {3, 0}, fluid = "left" }
wall { {3, 1}, {0, 1}, fluid = "left" }
fill { 0, 0, 1, 1 }
outflow { {3, 0}, {3, 1}, name = "exit" }
run { t_end = 1 }
