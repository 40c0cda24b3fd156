-- wcsph-riemann with a choice it does not know: what = 1, transport_velocity = "strong";
-- what = 2, wall_pressure = "linear" (mirror or gradient).
param { what = 1 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
if what == 1 then
  scheme { "wcsph-riemann", sound_speed = 10, transport_velocity = "strong" }
else
  scheme { "wcsph-riemann", sound_speed = 10, wall_pressure = "linear" }
end
fluid { density = 1, viscosity = 0.01 }
box_wall { 0, 0, 1, 1, lid_velocity = {1, 0} }
fill { 0, 0, 1, 1 }
run { t_end = 1 }
