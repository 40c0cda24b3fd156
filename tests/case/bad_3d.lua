-- A 3-D scene and what it refuses: what = 0, a valid tank (isph-stabilized); 1, isph-usaw (its
-- semi-analytical walls are 2-D); 2, wcsph-usaw (the same walls); 3, a polyline wall; 4, a
-- probe at a 2-D point; 5, gravity {x, y, z} before the domain; 6, a fill past the tank's walls; 7,
-- a domain of five numbers; 8, an empty fill box; 9, a 2-D rectangle fill; 10, a tank past the
-- domain; 11, a velocity of two components; 12, a disc probe without its normal; 13, an obstacle
-- 2 dr thick in the water (the markers need 3.8 dr); 14, a wall force; 15, isph-rotational's
-- implicit viscous prediction; 16, a domain whose z1 is not a number.
param { what = 0 }
local scheme_name = ({ [1] = "isph-usaw", [2] = "wcsph-usaw", [15] = "isph-rotational",
                       [24] = "wcsph-riemann" })[what]
                    or "isph-stabilized"
if what == 5 then fluid { gravity = {0, 0, -9.81} } elseif what == 22 then sphere_wall { 0.5, 0.5, 0.5, 0.1 } end
if what == 7 then
  domain { 0, 0, 0, 1, 1 }
elseif what == 16 then
  domain { 0, 0, 0, 1, 1, 0 / 0 }
else
  domain { 0, 0, 0, 1, 1, 1 }
end
particles { dr = 0.1 }
scheme { scheme_name, viscous = what == 15 and "implicit" or nil }
if what ~= 5 then fluid { density = 1000, viscosity = 1e-6, gravity = {0, 0, -9.81} } end
if what == 10 then
  box_wall { 0, 0, 0, 1, 1, 1.2, group = "tank" }
else
  box_wall { 0, 0, 0, 1, 1, 1, group = "tank" }
end
if what == 3 then wall { {0, 0.5}, {1, 0.5} } end
if what == 4 then probe { "bottom", {0.5, 0.1} } end
if what == 12 then probe { "sensor", {1, 0.5, 0.1}, radius = 0.01 } end
if what == 14 then force { "tank" } end
if what == 13 then box_wall { 0.4, 0, 0, 0.6, 1, 0.3, fluid = "outside", group = "plate" } end
if what == 6 then
  fill { 0, 0, 0, 1, 1.5, 0.5, name = "water" }
elseif what == 8 then
  fill { 0, 0, 0.5, 1, 1, 0.5, name = "water" }
elseif what == 9 then
  fill { 0, 0, 1, 0.5, name = "water" }
elseif what == 11 then
  fill { 0, 0, 0, 1, 1, 0.5, name = "water", velocity = {1, 0} }
else
  fill { 0, 0, 0, 1, 1, 0.5, name = "water" }
end
-- the curved solids: 17, a sphere of radius 0; 18, a cylinder whose ends are one point; 19, a box
-- and a sphere in one fill; 20, a sphere past the top; 21, a cylinder 2 dr across (the markers
-- need 3.8 dr); 22 (line 11), a sphere before the 3-D domain; 23, a lid sliding across its face;
-- 24, a block in the water (wcsph-riemann), for a camera inside it
if what == 17 then sphere_wall { 0.5, 0.5, 0.25, 0, fluid = "outside", group = "ball" } end
if what == 18 then cylinder_wall { 0.5, 0.5, 0, 0.5, 0.5, 0, 0.2, fluid = "outside" } end
if what == 19 then fill { 0, 0, 0, 1, 1, 0.5, sphere = {0.5, 0.5, 0.5, 0.2}, name = "ball" } end
if what == 20 then sphere_wall { 0.5, 0.5, 0.9, 0.3, fluid = "outside", group = "ball" } end
if what == 21 then cylinder_wall { 0.5, 0.5, 0, 0.5, 0.5, 1, 0.1, fluid = "outside", group = "pole" } end
if what == 23 then box_wall { 0.2, 0.2, 0.2, 0.8, 0.8, 0.8, lid_velocity = {0, 1, 0}, lid_face = "y1" } end
if what == 24 then box_wall { 0.3, 0, 0, 0.7, 1, 0.3, fluid = "outside", group = "block" } end
run { t_end = 0.1 }
