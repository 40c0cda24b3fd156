-- wcsph-usaw's default sound speed c0 = 10 U (solvers/wcsph_usaw/wcsph_usaw.c): water 0.4 m deep
-- at rest in a tank whose side walls rise to `top` gets U = √(2 g D) from its depth D = 0.4 m,
-- whatever the walls' height (c0 = 28.01 m/s); set going at u m/s faster than that, it gets
-- U = u. The scheme prints c0 and where it came from when it is created.
param { top = 1, u = 0, t_end = 0.001 }
domain { 0, 0, 1, top }
particles { dr = 0.05 }
scheme "wcsph-usaw"
fluid { density = 1000, viscosity = 1e-6, gravity = {0, -9.81} }
wall { {0, top}, {0, 0}, {1, 0}, {1, top}, fluid = "left" }
if u ~= 0 then
  fill { 0, 0, 1, 0.4, velocity = {u, 0} }
else
  fill { 0, 0, 1, 0.4 }
end
run { t_end = t_end }
