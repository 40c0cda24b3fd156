-- isph-stabilized with an option it refuses: what = 1, alpha = "small" (a number from 0 to 1);
-- 2, wall_pressure = "dirichlet" (pseudo_neumann or neumann); 3, wall_velocity and slip_ratio
-- together; 4, surface_threshold = 1.2 (0.8 to 0.995); 5, wall_velocity = "sticky" (no_slip or
-- slip); 6, wall_layers = 1 (the markers of the fluid next to a wall need 2 at h = 1.2 dr); 7, a
-- plate 0.15 m thick in the water (the markers need 0.38 m); 8, a wall near the top whose fluid
-- side faces the domain's edge (its markers fall above it); 9, a gate naming no wall group; 10,
-- gate_speed alone; 11, gate_stop before gate_start; 12, a gate lifted out; 13, pressure_form
-- "split"; 14, pressure_form "dynamic" with a body force along a periodic axis; 15, shifting 3; 16 wall_approach "x".
param { what = 1 }
local opts = ({ { alpha = "small" }, { wall_pressure = "dirichlet" },
                { wall_velocity = "slip", slip_ratio = 0.5 }, { surface_threshold = 1.2 },
                { wall_velocity = "sticky" }, { wall_layers = 1 }, {}, {},
                { gate = "door", gate_speed = 1, gate_stop = 0.1 }, { gate_speed = 1 },
                { gate = "walls", gate_speed = 1, gate_start = 0.5, gate_stop = 0.2 },
                { gate = "walls", gate_speed = 10, gate_stop = 1 }, { pressure_form = "split" },
                { pressure_form = "dynamic" }, { shifting = 3 }, { wall_approach = "x" } })[what]
domain { 0, 0, 1, 1.5, periodic = what == 14 and "x" or nil }
particles { dr = 0.1 }
opts[1] = "isph-stabilized"
scheme(opts)
fluid { density = 1000, viscosity = 1e-6, gravity = {0, -9.81},
        body_force = {what == 14 and 1 or 0, 0} }
if what == 14 then
  wall { {1, 0}, {0, 0}, fluid = "right" } -- the floor of a channel periodic in x
else
  wall { {0, 1.5}, {0, 0}, {1, 0}, {1, 1.5}, fluid = "left" }
end
if what == 7 then
  wall { {0.4, 0.3}, {0.6, 0.3}, {0.6, 0.45}, {0.4, 0.45}, closed = true, fluid = "outside",
         group = "plate" }
elseif what == 8 then
  wall { {0, 1.45}, {1, 1.45}, fluid = "left", group = "lid" }
end
fill { 0, 0, 1, 1 }
run { t_end = 1 }
