-- A channel with an entry and an exit given to a scheme without sections (OPEN_SCHEME picks it).
param { usaw = 1 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme(usaw == 1 and "isph-usaw" or "isph-rotational")
fluid { density = 1, viscosity = 1 }
wall { {1, 0}, {0, 0}, fluid = "right" }
wall { {0, 1}, {1, 1}, fluid = "right" }
fill { 0, 0, 1, 1 }
inflow { {0, 1}, {0, 0}, velocity = 1, profile = "parabolic" }
if usaw == 1 then outflow { {1, 0}, {1, 1} } else wall { {1, 1}, {1, 0}, fluid = "right" } end
run { t_end = 1 }
