-- A channel periodic in x over a wavy floor, driven along x by a body force (gravity along x, no
-- free surface): the segment cache (usaw/gamma.cl) against the walk of the segment grid
-- (segment_cache = 0) must give the same bits (tests/case.cmake: seg_cache_*). The floor's
-- segments are sloped where they cross the periodic seam, so that a wrong image in a cached slot
-- moves a wall distance or a segment's midpoint, not only along the wall.
param { wcsph = 0, segment_cache = 8, t_end = 0.3 }
local L, H, dr = 0.2, 0.1, 0.005
domain { 0, 0, L, H, periodic = "x" }
particles { dr = dr }
if wcsph == 1 then
  scheme { "wcsph-usaw", sound_speed = 2, segment_cache = segment_cache }
else
  scheme { "isph-usaw", segment_cache = segment_cache }
end
fluid { density = 1000, viscosity = 1e-3, gravity = {1, 0} }
local floor = {}
for k = 40, 0, -1 do -- right to left, the fluid above (on the right of the direction of travel)
  local x = L * k / 40
  floor[#floor + 1] = {x, 0.02 + 0.01 * math.sin(2 * math.pi * x / L + 0.5)}
end
floor.fluid = "right"
wall(floor)
wall { {0, H}, {L, H}, fluid = "right" }
-- the channel: under the ceiling, dr/2 above the floor (no lattice point closer than dr/4)
local region = { {0, H}, {L, H} }
for k = 1, #floor do region[#region + 1] = {floor[k][1], floor[k][2] + dr / 2} end
fill { polygon = region }
run { t_end = t_end, output_every = t_end, checkpoint_every = t_end }
