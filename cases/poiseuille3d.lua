-- Body-force Poiseuille flow between two plates in 3-D, start-up from rest: the channel H high,
-- periodic along x and y (the box_wall's x and y faces lie on the periodic boundaries, so its
-- dummies are the floor's and the ceiling's only), no-slip plates at z = 0 and H, Re = U0 H / ν = 1
-- with U0 = g H² / (8ν) the steady centreline velocity; units H = U0 = 1 (ν = 1, g = 8), as the
-- 2-D case (cases/poiseuille_periodic.lua, Hosseini & Feng 2011 sec 4.1), with isph-stabilized
-- (Asai et al. 2012; its no-slip virtual markers, S eqs 11-13) unless rot = 1. Reference: the
-- series solution of Morris, Fox & Zhu 1997 (shared/refdata/analytic.md sec 1)
--   u(z,t) = g/(2ν) z (H − z) − Σ_n 4 g H² / (ν π³ (2n+1)³) sin((2n+1)πz/H) e^{−(2n+1)²π²νt/H²}.
-- The walls are pseudo-Neumann (S sec 3.2): their Dirichlet rows fix the pressure. Under the
-- modified virtual marker (the default) a channel with no free surface has no Dirichlet row, the
-- pressure is fixed up to a constant only, and the symmetric gradient of that constant is not zero
-- next to the walls: measured, the level ran to 8.9e18 Pa and the fluid left at the 4th step.
-- rot = 1 runs isph-rotational instead (Hosseini & Feng 2011, its dummies and shifting C = shift,
-- the 2-D case's): the same flow as cases/poiseuille_periodic.lua in 3-D.
-- Metrics at the end, over the fluid particles at their own heights: u_rms_error and u_max_error
-- (|u − u_exact| / U0), cross_speed (the largest |v|, |w| over U0: the flow is along x only), and
-- crossed_wall.
param { dr = 0.1, t_end = 1, side = 1, rot = 0, shift = 0.04 }

local H, nu, g = 1, 1, 8
domain { 0, 0, 0, side, side, H, periodic = "xy" }
particles { dr = dr }
if rot == 1 then
  scheme { "isph-rotational", shifting = shift }
else
  scheme { "isph-stabilized", wall_pressure = "pseudo_neumann" }
end
fluid { density = 1, viscosity = nu, body_force = {g, 0, 0} }
box_wall { 0, 0, 0, side, side, H, group = "plates" }
fill { 0, 0, 0, side, side, H }
run { t_end = t_end, output_every = t_end / 4 }

local function exact(z, t)
  local u = g / (2 * nu) * z * (H - z)
  for n = 0, 200 do
    local k = 2 * n + 1
    u = u - 4 * g * H * H / (nu * math.pi ^ 3 * k ^ 3) * math.sin(k * math.pi * z / H) *
          math.exp(-k * k * math.pi * math.pi * nu * t / (H * H))
  end
  return u
end

function metrics(sim)
  local U0 = g * H * H / (8 * nu)
  local u = sim.field("vel", 1, "fluid")
  local sq, worst = 0, 0
  for i = 1, #u.value do
    local e = math.abs(u.value[i] - exact(u.z[i], sim.time)) / U0
    sq, worst = sq + e * e, math.max(worst, e)
  end
  local cross = 0
  for c = 2, 3 do
    cross = math.max(cross, math.abs(sim.min("vel", c)), math.abs(sim.max("vel", c)))
  end
  local crossed = sim.wall_crossing_steps
  if sim.min("pos", 3) < 0 or sim.max("pos", 3) > H then crossed = crossed + 1 end
  return { u_rms_error = math.sqrt(sq / #u.value), u_max_error = worst, cross_speed = cross / U0,
           crossed_wall = crossed }
end
