-- fill { pressure, density } go to the schemes that take them: `which` = 1 a pressure for the
-- ballistic scheme (it has none), 2 a density for isph-usaw (incompressible: ρ stays ρ0),
-- 3 a pressure function that returns a string, 4 a negative density.
param { which = 1 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme(which == 1 and "ballistic" or (which == 2 and "isph-usaw" or "wcsph-usaw"))
fluid { density = 1000, viscosity = 1e-3 }
box_wall { 0, 0, 1, 1 }
fill { 0.1, 0.1, 0.9, 0.9,
       pressure = (which == 1 and 10) or (which == 3 and function(x, y) return "high" end) or nil,
       density = (which == 2 and 1000) or (which == 4 and -1) or nil }
run { t_end = 1 }
