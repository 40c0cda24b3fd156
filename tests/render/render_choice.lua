-- A still tank whose frames the case chooses: the vertical velocity, in a fixed range, with the
-- diverging map (tests/render/run_and_render.cmake).
param { dr = 0.1, t_end = 0.02 }
domain { 0, 0, 1, 1.5 }
particles { dr = dr }
scheme "isph-usaw"
fluid { density = 1000, viscosity = 1e-6, gravity = {0, -9.81} }
wall { {0, 1.5}, {0, 0}, {1, 0}, {1, 1.5}, fluid = "left" }
fill { 0, 0, 1, 1 }
run { t_end = t_end, output_every = t_end / 2 }
render { field = "vel_y", range = {-0.05, 0.05}, colormap = "coolwarm" }
