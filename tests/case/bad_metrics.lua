-- A metrics() that asks the run for what it does not have: the script's error says what is
-- missing, once (tests/case.cmake, metrics_*). what = 1: a field the run does not carry;
-- 2: a component the field does not have; 3: the force of a group the case does not record;
-- 4: a probe the case does not declare; 5: a field sampled at a point; 6: an interpolation
-- sim.sample does not know; 7: one that profile_error does not know; 8: a profile line with a
-- misspelt one (refused when the case loads).
param { what = 1 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme { "wcsph-riemann", sound_speed = 10 }
fluid { density = 1, viscosity = 0.01 }
wall { {0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, fluid = "left", group = "box" }
fill { 0, 0, 1, 0.5 }
if what == 8 then profile { "mid", from = {0.5, 0}, to = {0.5, 1}, interpolation = "linaer" } end
run { t_end = 0.001 }
function metrics(sim)
  if what == 1 then sim.field("k") end
  if what == 2 then sim.field("vel", 3) end
  if what == 3 then sim.force("lid") end
  if what == 4 then sim.probe("gauge", "p") end
  if what == 5 then sim.sample("epsilon", 0.5, 0.25) end
  if what == 6 then sim.sample("vel", 0.5, 0.25, 1, "cubic") end
  if what == 7 then
    sim.profile_error { field = "vel", x = 0.5, csv = "tests/data/ghia1982_u_centreline.csv",
                        coordinate = "y", value = "u_Re100", interpolation = "quadratic" }
  end
  return { done = 1 }
end
