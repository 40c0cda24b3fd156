-- A fill whose velocity function returns nothing usable is refused with the region and the point.
param { which = 1 }
domain { 0, -0.5, 1, 1.5, periodic = "x" }
particles { dr = 0.1 }
scheme "ballistic"
fluid { density = 1000 }
wall { {1, -0.2}, {0, -0.2}, fluid = "right" }
wall { {0, 1.2}, {1, 1.2}, fluid = "right" }
if which == 1 then
  fill { 0, 0, 1, 1, name = "layer", velocity = function(x, y) return y end }
else
  fill { 0, 0, 1, 1, name = "layer", velocity = {1} }
end
run { t_end = 0.1 }
