-- A channel with an entry and an exit given to a scheme without sections: usaw = 1 isph-usaw,
-- 2 isph-stabilized; usaw = 0 gives isph-rotational an entry without an exit.
param { usaw = 1 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme(({ [0] = "isph-rotational", "isph-usaw", "isph-stabilized" })[usaw])
fluid { density = 1, viscosity = 1 }
wall { {1, 0}, {0, 0}, fluid = "right" }
wall { {0, 1}, {1, 1}, fluid = "right" }
fill { 0, 0, 1, 1 }
inflow { {0, 1}, {0, 0}, velocity = 1, profile = "parabolic" }
if usaw ~= 0 then outflow { {1, 0}, {1, 1} } else wall { {1, 1}, {1, 0}, fluid = "right" } end
run { t_end = 1 }
