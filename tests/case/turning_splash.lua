-- A few particles flung onto a turning paddle above the water (the water wheel's arms lift such
-- droplets, cases/water_wheel.lua): three particles in a column just ahead of a paddle's face,
-- which turns into them at up to 2.7 m/s, over a pool with a free surface. They touch the wall and
-- nothing else; about to hit it, a particle of a body of fluid keeps its pressure unknown
-- (isph-usaw, free_surface.cl), and these made a block of the pressure equation with no Dirichlet
-- row: BiCGStab ran to its limit (residual 1e42) at the first step and the particles went 0.7 dr
-- through the paddle at the fourth. Metrics: the steps with a particle behind a wall; the solver's
-- iterations come from summary.json.
param { n = 3, t_end = 0.2 }
domain { -2, 0, 2, 3.2, periodic = "x" }
particles { dr = 0.05 }
scheme { "isph-usaw" }
fluid { density = 1000, viscosity = 1e-2, gravity = {0, -9.81} }
wall { {-2, 0}, {2, 0}, fluid = "left" }
-- a paddle 0.08 m thick hanging from (0, 2) down to 1 m, turning counter-clockwise at 3 rad/s:
-- its lower part sweeps towards +x, into the particles
wall { {-0.04, 1.0}, {0.04, 1.0}, {0.04, 1.9}, {-0.04, 1.9}, closed = true, fluid = "outside",
       omega = 3, centre = {0, 2}, group = "paddle" }
fill { -2, 0, 2, 0.3, name = "pool" }
local pts = {}
for k = 1, n do pts[#pts + 1] = {0.07, 1.05 + 0.05 * k} end
fill { points = pts, name = "droplet" }
run { t_end = t_end, output_every = t_end }

function metrics(sim)
  return { crossed = sim.wall_crossing_steps, escaped = sim.max("pos", 2) > 3.2 and 1 or 0 }
end
