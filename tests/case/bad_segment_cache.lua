-- The USAW schemes' segment_cache is a whole number of slots from 0 to 64 (tests/case.cmake:
-- case_segment_cache_*): what = 0 gives 2.5, 1 gives -1, 2 text, 4 NaN, each to isph-usaw, 3 gives
-- 65 to wcsph-usaw.
param { what = 0 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
local v = ({2.5, -1, "many", 65, 0 / 0})[what + 1]
scheme { what == 3 and "wcsph-usaw" or "isph-usaw", segment_cache = v }
fluid { density = 1, viscosity = 0.01 }
box_wall { 0, 0, 1, 1, lid_velocity = {1, 0} }
fill { 0, 0, 1, 1 }
run { t_end = 0.1 }
