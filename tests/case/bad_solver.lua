-- Pressure-solver options a solve cannot meet (tests/case.cmake): `what` picks one.
param { what = 1 }

local bad = {
  { solver_rtol = 1e-20 },  -- below 4 ε in either precision
  { solver_rtol = 0 / 0 },  -- not a number
  { solver_max_it = 0 },    -- no iteration at all
  { solver_rtol = 1 },      -- nothing to solve for
  { solver_group_max = -4 }, -- not a number of unknowns
  { solver_fuse = "yes" },   -- not a way of launching the kernels
}
local opts = { "isph-usaw" }
for k, v in pairs(bad[what]) do opts[k] = v end
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme(opts)
fluid { density = 1, viscosity = 0.01 }
box_wall { 0, 0, 1, 1, lid_velocity = {1, 0} }
fill { 0, 0, 1, 1 }
run { t_end = 1 }
