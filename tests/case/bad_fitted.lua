-- Particles where the script puts them (fill { points }) and fitted dummy layers (wall {
-- dummies = "fitted" }) in ways the loader must refuse (what = ...): 1 points that is not a list,
-- 2 a point that is not {x, y}, 3 a point outside the domain, 4 a point given twice, 5 points and
-- a polygon in one fill, 6 fitted dummies under semi-analytical walls, 7 an unknown arrangement,
-- 8 a fitted wall that turns back on itself, 9 a point inside an obstacle, 10 two points dr/2
-- apart only across a periodic axis's wrap; what = 0 is the valid scene they spoil (200 points,
-- the box's dummies fitted)
param { what = 1 }
domain { 0, 0, 2, 1, periodic = what == 10 and "x" or nil }
particles { dr = 0.1 }
if what == 6 then scheme "isph-usaw" else scheme { "wcsph-riemann", sound_speed = 1 } end
fluid { density = 1, viscosity = 0.01 }
local dummies = (what == 7 and "curved") or (what == 9 and "lattice") or "fitted"
if what == 8 then
  wall { {0, 0}, {1.5, 0}, {0, 0.12}, fluid = "left", dummies = dummies }
elseif what == 10 then
  wall { {-0.5, 0}, {2.5, 0}, fluid = "left", dummies = dummies }
  wall { {-0.5, 1}, {2.5, 1}, fluid = "right", dummies = dummies }
else
  wall { {0, 0}, {2, 0}, {2, 1}, {0, 1}, closed = true, dummies = dummies }
end
if what == 9 then circle { centre = {1, 0.5}, radius = 0.2 } end
local pts = {}
for j = 0, 9 do
  for i = 0, 19 do pts[#pts + 1] = {0.05 + 0.1 * i, 0.05 + 0.1 * j} end
end
if what == 1 then pts = 5 end
if what == 2 then pts[7] = {0.3} end
if what == 3 then pts[3] = {2.5, 0.5} end
if what == 4 then pts[#pts + 1] = {0.05 + 0.1 * 4 + 0.01, 0.05 + 0.1 * 2} end
if what == 10 then pts[1], pts[20] = {0.01, 0.05}, {1.995, 0.05} end
local f = {points = pts}
if what == 5 then f.polygon = {{0, 0}, {1, 0}, {1, 1}} end
if what == 8 then f.points = {{0.5, 0.05}} end
fill(f)
run { t_end = 0.1 }
