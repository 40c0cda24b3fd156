-- Walls of every shape in one tank, with no physics (scheme "none"): a container whose floor
-- rises into a wedge, a sliding lid, a turning cylinder and an arc-shaped baffle. Walls that
-- share an end point meet in one corner. `clsph info` shows the particle counts; a run writes the
-- geometry to a snapshot for ParaView.
param { dr = 0.02, t_end = 0.01 }

domain { 0, 0, 2, 1 }
particles { dr = dr }
scheme { "none", walls = "usaw" }
fluid { density = 1000, viscosity = 1e-6 }
wall { {0, 1}, {0, 0}, {0.6, 0}, fluid = "left", group = "tank" }
wall { {0.6, 0}, {0.9, 0.3}, {1.2, 0}, fluid = "left", group = "wedge" }
wall { {1.2, 0}, {2, 0}, {2, 1}, fluid = "left", group = "tank" }
wall { {2, 1}, {0, 1}, fluid = "left", group = "lid", velocity = {1, 0} }
circle { centre = {1.6, 0.6}, radius = 0.1, omega = 2, group = "cylinder" }
arc { centre = {0.3, 0.6}, radius = 0.15, from = 0, to = math.pi, fluid = "outside",
      group = "baffle" }
for k = 0, 1 do
  fill { 0.04 + 0.26 * k, 0.04, 0.26 + 0.26 * k, 0.36, name = "pool " .. (k + 1) }
end
fill { 1.26, 0.04, 1.96, 0.4, name = "pool 3" }
probe { "middle", {1.0, 0.5} }
run { t_end = t_end }
