-- Bad walls and sample points: `which` = 1 a closed wall drawn as a figure eight (its third
-- segment crosses its first), 2 an open polyline that doubles back onto itself, 3 a probe outside
-- the domain, 4 a profile that leaves it.
param { which = 1 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme "ballistic"
box_wall { 0, 0, 1, 1 }
if which == 1 then
  wall { {0.2, 0.2}, {0.8, 0.8}, {0.8, 0.2}, {0.2, 0.8}, closed = true, fluid = "outside" }
elseif which == 2 then
  wall { {0.1, 0.5}, {0.9, 0.5}, {0.5, 0.5}, fluid = "left" }
end
fill { 0.1, 0.1, 0.9, 0.9 }
if which == 3 then probe { "outside", {1.5, 0.5} } end
if which == 4 then profile { "long", from = {0.5, 0}, to = {0.5, 2} } end
run { t_end = 1 }
