-- STL walls and what they refuse: what = 0, a cube tank from an STL surface (cases/stl/cube.stl
-- scaled to 1 m) with a cube obstacle 0.4 m across on its floor; 1, a surface with a facet missing
-- (not closed); 2, every facet reversed (normals inward); 3, one facet reversed; 4, a text file;
-- 5, a file that is not there; 6, stl_wall in a 2-D scene; 7, scale 0; 8, no file; 9, a surface
-- past the domain; 10, a vertex NaN.
param { what = 0 }
if what == 6 then stl_wall { "stl/open.stl" } end
domain { -0.2, -0.2, -0.2, 1.2, 1.2, 1.2 }
particles { dr = 0.05 }
scheme { "isph-stabilized" }
fluid { density = 1000, viscosity = 1e-6, gravity = {0, 0, -9.81} }
local files = { "stl/open.stl", "stl/inverted.stl", "stl/flipped.stl", "stl/junk.stl",
                "stl/none.stl", [10] = "stl/nan.stl" }
stl_wall { "../../cases/stl/cube.stl", group = "tank" }
if files[what] then stl_wall { files[what], scale = 0.2, offset = {0.4, 0.4, 0}, fluid = "outside" } end
if what == 7 then stl_wall { "../../cases/stl/cube.stl", scale = 0, fluid = "outside" } end
if what == 8 then stl_wall { scale = 0.2, fluid = "outside" } end
if what == 9 then stl_wall { "../../cases/stl/cube.stl", offset = {0.5, 0.5, 0.7}, fluid = "outside" } end
if what == 0 then
  stl_wall { "../../cases/stl/cube.stl", scale = 0.4, offset = {0.3, 0.3, 0}, fluid = "outside",
             group = "block" }
end
fill { 0, 0, 0, 1, 1, 0.5, name = "water" }
run { t_end = 0.1 }
