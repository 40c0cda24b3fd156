-- Turning walls that cannot turn (host/scene/geometry.c, check_periodic_and_turning), chosen by
-- `what`: 0 a valid wheel; 1 its disc reaches the bottom; 2 its disc leaves the domain's top;
-- 3 its disc is wider than the period; 4 a bottom longer than the period (USAW walls); 5 a
-- turning square under dummy walls (wcsph-riemann), which keep their place.
param { what = 0 }
local L, top = 4, 2
domain { -L / 2, 0, L / 2, top, periodic = "x" }
particles { dr = 0.05 }
scheme { what == 5 and "wcsph-riemann" or "isph-usaw" }
fluid { density = 1000, viscosity = 1e-2, gravity = {0, -9.81} }
local bottom = what == 4 and L / 2 + 0.5 or L / 2
wall { {-bottom, 0}, {bottom, 0}, fluid = "left" }
local yc = ({[1] = 0.75, [2] = 1.5})[what] or 1.0
local a = what == 3 and 1.5 or 0.5
wall { {-a, yc - a}, {a, yc - a}, {a, yc + a}, {-a, yc + a}, closed = true, fluid = "outside",
       omega = 1, centre = {0, yc}, group = "paddle" }
fill { -L / 2, 0, L / 2, 0.2 }
run { t_end = 0.1 }
