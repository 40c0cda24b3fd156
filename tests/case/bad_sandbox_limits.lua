-- The case sandbox's limits (host/scene/case.c): `which` picks the script that runs out.
--   1 an endless loop at the top level          4 a metamethod on _G that loops (param sets a
--   2 an endless loop in a fill's velocity         global through it)
--   3 an endless loop in metrics()              5 a 2 GB string            6 a table that grows
param { which = 1 }
if which == 4 then
  setmetatable(_G, { __newindex = function(t, k, v) while true do end end })
end
param { t_end = 0.02 }
domain { 0, 0, 1, 1 }
particles { dr = 0.25 }
scheme "ballistic"
box_wall { 0, 0, 1, 1 }
fill { 0.25, 0.25, 0.75, 0.75,
       velocity = function(x, y)
         while which == 2 do end
         return 0, 0
       end }
run { t_end = t_end }
if which == 1 then
  while true do end
elseif which == 5 then
  local s = string.rep("x", 2e9)
elseif which == 6 then
  local t = {}
  for i = 1, 1e12 do t[i] = i end
end
function metrics(sim)
  while which == 3 do end
  return { done = 1 }
end
