-- The USAW schemes' wall_guard takes "auto", "on" or "off" (tests/case.cmake: wall_guard_*):
-- what = 1 another word, 2 a number; weak = 1 asks wcsph-usaw instead of isph-usaw
param { what = 1, weak = 0 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
local v = ({[1] = "always", [2] = 1})[what]
scheme { weak == 1 and "wcsph-usaw" or "isph-usaw", wall_guard = v, sound_speed = weak == 1 and 10 or nil }
fluid { density = 1, viscosity = 0.01 }
wall { {0, 1}, {0, 0}, {1, 0}, {1, 1}, {0, 1}, fluid = "left" }
fill { 0, 0, 1, 1 }
run { t_end = 0.1 }
