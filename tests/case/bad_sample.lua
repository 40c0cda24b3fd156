-- sample(sim) that cannot make series.csv: `which` = 1 a column named 'time', 2 other names at a
-- later call than at the first, 3 a value that is not a number.
param { which = 1 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme "ballistic"
box_wall { 0, 0, 1, 1 }
fill { 0.2, 0.2, 0.8, 0.8 }
run { t_end = 0.5, output_every = 0.1 }
local calls = 0
function sample(sim)
  calls = calls + 1
  if which == 1 then return { time = sim.time } end
  if which == 2 and calls > 2 then return { a = 1, b = 2 } end
  if which == 3 then return { a = "one" } end
  return { a = 1 }
end
