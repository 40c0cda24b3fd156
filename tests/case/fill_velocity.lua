-- Initial velocities of the fluid (fill { velocity = ... }), carried unchanged by the ballistic
-- scheme (no force): a shear u = y given as a function, and a region at a constant {0.5, −0.25}.
-- The metrics are the largest deviations from what each particle was given.
param { dr = 0.05, t_end = 0.2 }
domain { 0, -0.5, 1, 1.5, periodic = "x" }
particles { dr = dr }
scheme "ballistic"
fluid { density = 1000 }
wall { {1, -0.2}, {0, -0.2}, fluid = "right" } -- clear of the block as it sinks
wall { {0, 1.2}, {1, 1.2}, fluid = "right" }
fill { 0, 0, 1, 0.5, name = "shear", velocity = function(x, y) return y, 0 end }
fill { 0, 0.6, 1, 1, name = "block", velocity = {0.5, -0.25} }
run { t_end = t_end, output_every = t_end }

function metrics(sim)
  local f, g = sim.field("vel", 1), sim.field("vel", 2)
  local shear, block, n = 0, 0, 0
  for k = 1, #f.value do
    if f.y[k] < 0.55 then -- the shear layer (it moves along x only)
      shear = math.max(shear, math.abs(f.value[k] - f.y[k]), math.abs(g.value[k]))
      n = n + 1
    else
      block = math.max(block, math.abs(f.value[k] - 0.5), math.abs(g.value[k] + 0.25))
    end
  end
  return { shear_error = shear, block_error = block, shear_particles = n }
end
