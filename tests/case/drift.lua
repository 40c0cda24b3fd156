-- Ballistic particles drifting for ever in a doubly periodic box (the interrupt tests: a run that
-- does not end by itself, whose state changes every step). `slow` = 1 adds a metrics() that
-- loops until the sandbox's budget ends it (about 2 s).
param { t_end = 1e6, every = 100, slow = 0 }
domain { 0, 0, 1, 1, periodic = "xy" }
particles { dr = 0.1 }
scheme "ballistic"
fill { 0.2, 0.2, 0.8, 0.8, velocity = {0.3, 0.2} }
run { t_end = t_end, output_every = every }
function metrics(sim)
  while slow == 1 do end
  return { x_mean = sim.mean("pos", 1) }
end
