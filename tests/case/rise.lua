-- A splash above the cell grid falls back: a block of ballistic particles (they see no walls)
-- thrown straight up at 6 m/s from the floor of an open unit tank rises to y = 0.25 + 6²/(2 g)
-- ≈ 2.1 m, far above the domain's top (1 m) and the cell grid's (its margin is a few tenths of
-- a metre), and comes back down. The side gravity points away from is open: the grid clamps the
-- block into its top cells (grid.cl) and the run goes on; before, the grid's edge stopped it as
-- "escaped". At t = 2 v/g the block is back where it started: rise_error is its mean height's
-- distance from the start, over the peak height (semi-implicit Euler: of order g dt t / peak).
local v, g = 6, 9.81
param { dr = 0.05 }
domain { 0, 0, 1, 1 }
particles { dr = dr }
scheme "ballistic"
fluid { density = 1000, gravity = {0, -g} }
wall { {0, 1}, {0, 0}, {1, 0}, {1, 1}, fluid = "left" }
fill { 0.3, 0.1, 0.7, 0.4, velocity = {0, v} }
run { t_end = 2 * v / g, output_every = v / g }

function metrics(sim)
  local peak = v * v / (2 * g)
  return { rise_error = math.abs(sim.mean("pos", 2) - 0.25) / peak,
           top = sim.max("pos", 2), escaped = sim.escaped }
end
