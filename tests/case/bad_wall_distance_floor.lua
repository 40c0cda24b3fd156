-- The USAW schemes' wall_distance_floor is a number of spacings in (0, 1] (tests/case.cmake:
-- case_wall_distance_floor_*): what = 0 gives 0, 1 gives 1.5, 2 text, 4 NaN, each to
-- isph-usaw, 3 gives 0 to wcsph-usaw.
param { what = 0 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
local v = ({0, 1.5, "half", 0, 0 / 0})[what + 1]
scheme { what == 3 and "wcsph-usaw" or "isph-usaw", wall_distance_floor = v }
fluid { density = 1, viscosity = 0.01 }
box_wall { 0, 0, 1, 1, lid_velocity = {1, 0} }
fill { 0, 0, 1, 1 }
run { t_end = 0.1 }
