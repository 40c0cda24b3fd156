-- isph-usaw's pressure_guess is "linear" or "last" (tests/case.cmake: case_pressure_guess*):
-- what = 1 an unknown name, 2 a number
param { what = 1 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme { "isph-usaw", pressure_guess = ({[1] = "quadratic", [2] = 1})[what] }
fluid { density = 1, viscosity = 0.01 }
wall { {0, 1}, {0, 0}, {1, 0}, {1, 1}, {0, 1}, fluid = "left" }
fill { 0, 0, 1, 1 }
run { t_end = 0.1 }
