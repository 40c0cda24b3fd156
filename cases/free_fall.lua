-- A block of water falling freely in a tall box (scheme "ballistic": gravity only, no pressure).
-- The exact drop is g t^2 / 2; semi-implicit Euler drops g t (t + dt) / 2, so the metric
-- drop_error (relative) is of order dt / t: a check of the time loop, not of SPH.
param { dr = 0.02, t_end = 0.2, height = 2.0 }

domain { 0, 0, 1, height }
particles { dr = dr }
scheme "ballistic"
fluid { density = 1000, gravity = {0, -9.81} }
box_wall { 0, 0, 1, height }
fill { 0.2, height - 0.6, 0.8, height - 0.2, name = "block" }
probe { "centre", {0.5, height - 0.4} }
profile { "axis", from = {0.5, 0}, to = {0.5, height}, points = 51 }
run { t_end = t_end, output_every = t_end / 4, checkpoint_every = t_end / 2 }

-- with each snapshot, a row of series.csv: the drop so far, and the highest particle below
-- y = height − 0.4 (nil, written -1, while none is there)
function sample(sim)
  return { drop = height - 0.4 - sim.mean("pos", 2),
           top_below = sim.max("pos", 2, {0, 0, 1, height - 0.4}) or -1 }
end

function metrics(sim)
  local y0 = height - 0.4                    -- initial mean height of the block
  local drop = y0 - sim.mean("pos", 2)
  local exact = 0.5 * 9.81 * sim.time ^ 2
  local speed = -sim.mean("vel", 2)          -- exactly g t for semi-implicit Euler
  local s = sim.series("drop")
  return { drop = drop, drop_error = math.abs(drop - exact) / exact,
           speed_error = math.abs(speed - 9.81 * sim.time) / (9.81 * sim.time),
           samples = #s.time, sample_last_error = math.abs(s.value[#s.value] - drop),
           top_below = sim.max("pos", 2, {0, 0, 1, y0}) }
end
