-- A layer of particles pushed along a channel periodic in x by a body force (scheme
-- "ballistic"): particles leave through x = L and come back through x = 0. The metric is the
-- mean speed against the exact f t, and how far the particles stayed inside [0, L).
param { dr = 0.025, t_end = 1.0, force = 2.0, length = 1.0 }

domain { 0, 0, length, 0.5, periodic = "x" }
particles { dr = dr }
scheme "ballistic"
fluid { density = 1000, body_force = {force, 0} }
wall { {length, 0}, {0, 0}, fluid = "right", group = "floor" }
wall { {0, 0.5}, {length, 0.5}, fluid = "right", group = "ceiling" }
fill { 0, 0, length, 0.5 }
run { t_end = t_end, output_every = t_end / 2 }

function metrics(sim)
  return { speed_error = math.abs(sim.mean("vel", 1) - force * sim.time) / (force * sim.time),
           x_min = sim.min("pos", 1), x_max = sim.max("pos", 1) }
end
