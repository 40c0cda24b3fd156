-- Lid-driven cavity (Leroy et al. 2014 sec 4.1): a unit square box whose lid slides at U = 1,
-- Re = U L / ν. Centreline profiles u(y) at x = 1/2 and v(x) at y = 1/2 against Ghia, Ghia &
-- Shin 1982 (tests/data), RMS and largest deviation in units of U. The paper's resolutions:
-- 120² (Re 100), 200² (Re 400), 240² (Re 1000). --set wcsph=1 runs the WCSPH baseline. The
-- profiles along y = 1/2 and along the diagonal also carry the pressure (isph-usaw against
-- wcsph-usaw at Re 400: tests/validation/cavity_pressure.py). cfl multiplies the schemes'
-- time-step bounds; shift is isph-usaw's shifting coefficient (0 turns shifting off);
-- checkpoint > 0 writes a checkpoint every that many seconds of flow (long runs: --restart).
-- hdr sets the smoothing length h/δr (0: the scheme's, 2 for the USAW schemes as in the paper);
-- guard = 1 turns the USAW schemes' wall guard on (by default it is on only with gravity);
-- corners = 1 gives the lid's two corner vertices the lid's velocity instead of the side walls'
-- rest; shift_velocity = 0 turns off isph-usaw's first-order velocity correction of the shift
-- (eq 38); floor sets the USAW schemes' wall_distance_floor, the least wall distance of the
-- viscous wall term in spacings (0: the scheme's, δr/2 for isph-usaw) (the study
-- cavity_re100_causes in tests/harness/studies.txt measures each); fuse = 1 sets isph-usaw's
-- solver_fuse = "fused" and fuse = 2 "separate" (the README's pressure solver; 0 leaves its
-- "auto": fused on a GPU, separate elsewhere); guess = 0 sets its pressure_guess = "last"
-- (the solve starts from the last step's pressure instead of the last two extrapolated).
-- dim = 3 (with riemann = 1) runs it in 3-D: the box `span` spacings deep along z, periodic
-- there, its lid the face y = 1 sliding at {U, 0, 0} (box_wall { ..., lid_velocity, lid_face }):
-- a 2-D flow in a 3-D code, which must reproduce the 2-D run. Its metrics are the 2-D run's, the
-- profiles sampled in the mid-depth plane z = span δr/2 (the particles' own metrics over every z),
-- and w_rms, the RMS spanwise velocity over U (0 in the 2-D flow); the profile lines lie in the
-- same plane (the lid's force is 2-D only).
param { re = 100, n = 120, t_end = 30, cfl = 1, wcsph = 0, riemann = 0, ard = 0, tvf = 2, dens = 0, c0 = 10, alpha = 0.2,
        shift = 0.7, checkpoint = 0, hdr = 0, guard = 0, corners = 0, shift_velocity = 1,
        floor = 0, dim = 2, span = 9, fuse = 0, guess = 1 }

local U = 1
for _, sw in ipairs({{"guard", guard}, {"corners", corners}, {"shift_velocity", shift_velocity},
                     {"guess", guess}}) do
  if sw[2] ~= 0 and sw[2] ~= 1 then
    error(("cavity: %s must be 0 or 1, not %g"):format(sw[1], sw[2]))
  end
end
if fuse ~= 0 and fuse ~= 1 and fuse ~= 2 then
  error(("cavity: fuse must be 0, 1 or 2, not %g"):format(fuse))
end
if not (hdr == 0 or (hdr > 0 and hdr <= 10)) then
  error(("cavity: hdr (h/δr) must be 0 (the scheme's) or in (0, 10], not %g"):format(hdr))
end
if not (floor == 0 or (floor > 0 and floor <= 1)) then
  error(("cavity: floor (in δr) must be 0 (the scheme's) or in (0, 1], not %g"):format(floor))
end
local wall_floor = floor > 0 and floor or nil
if dim ~= 2 and dim ~= 3 then error(("cavity: dim must be 2 or 3, not %g"):format(dim)) end
if dim == 3 and riemann ~= 1 then error("cavity: dim = 3 needs riemann = 1 (wcsph-riemann)") end
if dim == 3 then
  domain { 0, 0, 0, 1, 1, span / n, periodic = "z" }
else
  domain { 0, 0, 1, 1 }
end
particles { dr = 1 / n, h_over_dr = hdr > 0 and hdr or nil }
if riemann == 1 then -- Riemann WCSPH with the limited transport velocity (c0 = 10 U)
  scheme { "wcsph-riemann", sound_speed = c0 * U, ard = ard, transport_coefficient = alpha,
           transport_velocity = ({"off", "full", "limited"})[tvf + 1],
           density = dens == 1 and "continuity" or nil }
elseif wcsph == 1 then -- the paper's baseline: c0 = 10 U and a background pressure
  scheme { "wcsph-usaw", sound_speed = 10 * U, background_pressure = 0.05 * 100 * U * U,
           wall_guard = guard == 1 and "on" or nil, wall_distance_floor = wall_floor }
else
  scheme { "isph-usaw", shifting = shift, wall_guard = guard == 1 and "on" or nil,
           shift_velocity = shift_velocity == 0 and "off" or nil,
           wall_distance_floor = wall_floor, solver_fuse = ({"fused", "separate"})[fuse],
           pressure_guess = guess == 0 and "last" or nil }
end
fluid { density = 1, viscosity = U / re }
if dim == 3 then -- the box, its lid the face y = 1 (its edges' dummies at rest, geometry3.c)
  box_wall { 0, 0, 0, 1, 1, span / n, lid_velocity = {U, 0, 0}, lid_face = "y1" }
elseif corners == 1 then -- the lid first: walls that share an end point share its vertex particle,
  -- which takes the velocity of the wall declared first (host/scene/geometry.c)
  wall { {1, 1}, {0, 1}, velocity = {U, 0}, group = "lid" }
  wall { {0, 1}, {0, 0}, {1, 0}, {1, 1} }
else -- box_wall's corners belong to the side walls, at rest
  box_wall { 0, 0, 1, 1, lid_velocity = {U, 0} }
end
if dim == 3 then
  fill { 0, 0, 0, 1, 1, span / n, name = "fluid" }
  local zm = 0.5 * span / n -- the centrelines in the mid-depth plane
  profile { "u_centreline", from = {0.5, 0, zm}, to = {0.5, 1, zm}, points = 101 }
  profile { "v_centreline", from = {0, 0.5, zm}, to = {1, 0.5, zm}, points = 101 }
  profile { "diagonal", from = {0, 0, zm}, to = {1, 1, zm}, points = 101 }
else
  fill { 0, 0, 1, 1, name = "fluid" }
  profile { "u_centreline", from = {0.5, 0}, to = {0.5, 1}, points = 101 }
  profile { "v_centreline", from = {0, 0.5}, to = {1, 0.5}, points = 101 }
  profile { "diagonal", from = {0, 0}, to = {1, 1}, points = 101 } -- pressure along the diagonal
  force { "lid" }
end
run { t_end = t_end, output_every = t_end / 10, cfl = cfl,
      checkpoint_every = checkpoint > 0 and checkpoint or nil }

-- Ghia's centreline u, for the particles' own velocities (below), its rows by increasing y
local ghia_u = reference("tests/data/ghia1982_u_centreline.csv", "y", "u_Re100", "u_Re400",
                         "u_Re1000")
local ghia_rows = {}
for k = 1, #ghia_u.y do ghia_rows[k] = k end
table.sort(ghia_rows, function(a, b) return ghia_u.y[a] < ghia_u.y[b] end)

-- Ghia's u (column "u_ReN") at y by the cubic through the 4 tabulated points nearest (Lagrange)
local function ghia_at(column, y)
  local yy, uu, m = ghia_u.y, ghia_u[column], #ghia_rows
  local near = 1
  for k = 2, m do
    if math.abs(yy[ghia_rows[k]] - y) < math.abs(yy[ghia_rows[near]] - y) then near = k end
  end
  local lo = math.max(1, math.min(m - 3, near - 2))
  local sum = 0
  for a = lo, lo + 3 do
    local w = 1
    for b = lo, lo + 3 do
      if a ~= b then
        w = w * (y - yy[ghia_rows[b]]) / (yy[ghia_rows[a]] - yy[ghia_rows[b]])
      end
    end
    sum = sum + w * uu[ghia_rows[a]]
  end
  return sum
end

-- The particles' own velocities against Ghia's, with no interpolation of ours: the RMS of
-- u − u_Ghia(y) over the fluid particles within δr/2 of x = 1/2, and the mean of u − u_Ghia over
-- those within δr of x = 1/2 and 2 δr of the lid (negative: the flow lags the lid). Ghia's table
-- is read between its points by cubics, which its u column (points at most 0.17 apart, 0.008
-- next to the lid) allows; its v column has no point between x = 0.5 and 0.8047, where v falls
-- from 0.05 to −0.25 U, so v has no such metric.
local function particle_errors(sim, column)
  local dr = 1 / n
  local x, y = sim.field("pos", 1).value, sim.field("pos", 2).value
  local u = sim.field("vel", 1).value
  local su, nu_, sl, nl = 0, 0, 0, 0
  for i = 1, #x do
    if math.abs(x[i] - 0.5) < dr then
      local e = u[i] / U - ghia_at("u_" .. column, y[i])
      if math.abs(x[i] - 0.5) < dr / 2 then su, nu_ = su + e * e, nu_ + 1 end
      if 1 - y[i] < 2 * dr then sl, nl = sl + e, nl + 1 end
    end
  end
  local nan = 0 / 0
  return nu_ > 0 and math.sqrt(su / nu_) or nan, nl > 0 and sl / nl or nan
end

-- The same by rows: the fluid particles within δr of x = 1/2 (the two lattice columns either
-- side of it at even n, every z in 3-D) binned by y in rows δr high; each row's mean u against
-- Ghia's u at the row's mean y, RMS over the rows (the mean of the two columns is u(1/2) to
-- O(δr²); the particles' own metric above counts those within δr/2 of x = 1/2, a set that at even
-- n rounding decides while they sit on the lattice).
local function row_errors(sim, column)
  local dr = 1 / n
  local x, y = sim.field("pos", 1).value, sim.field("pos", 2).value
  local u = sim.field("vel", 1).value
  local su, sy, c = {}, {}, {}
  for i = 1, #x do
    if math.abs(x[i] - 0.5) < dr then
      local k = math.min(n - 1, math.max(0, math.floor(y[i] / dr)))
      su[k], sy[k], c[k] = (su[k] or 0) + u[i], (sy[k] or 0) + y[i], (c[k] or 0) + 1
    end
  end
  local sq, rows = 0, 0
  for k = 0, n - 1 do
    if c[k] then
      local e = su[k] / c[k] / U - ghia_at("u_" .. column, sy[k] / c[k])
      sq, rows = sq + e * e, rows + 1
    end
  end
  return rows > 0 and math.sqrt(sq / rows) or 0 / 0
end

function metrics(sim)
  local column = "Re" .. math.floor(re + 0.5)
  if column ~= "Re100" and column ~= "Re400" and column ~= "Re1000" then -- Ghia's other Re: not
    return { wall_crossing_steps = sim.wall_crossing_steps }             -- in tests/data
  end
  local z = dim == 3 and 0.5 * span / n or nil -- the profiles in 3-D: the box's mid-depth plane
  local u_rms, u_max = sim.profile_error { field = "vel", component = 1, x = 0.5, z = z,
    csv = "tests/data/ghia1982_u_centreline.csv", coordinate = "y", value = "u_" .. column }
  local v_rms, v_max = sim.profile_error { field = "vel", component = 2, y = 0.5, z = z,
    csv = "tests/data/ghia1982_v_centreline.csv", coordinate = "x", value = "v_" .. column }
  -- the same by first-order moving least squares, exact for a linear field: next to the walls,
  -- where Shepard's support is cut and the profile curves, Shepard's average lags by h ∂u/∂n
  -- (with isph-usaw's h = 2 δr at 30², 0.16 U next to the lid)
  local ul_rms, ul_max = sim.profile_error { field = "vel", component = 1, x = 0.5, z = z,
    csv = "tests/data/ghia1982_u_centreline.csv", coordinate = "y", value = "u_" .. column,
    interpolation = "linear" }
  local vl_rms, vl_max = sim.profile_error { field = "vel", component = 2, y = 0.5, z = z,
    csv = "tests/data/ghia1982_v_centreline.csv", coordinate = "x", value = "v_" .. column,
    interpolation = "linear" }
  local up_rms, u_lid = particle_errors(sim, column)
  local m = { u_rms_vs_ghia = u_rms, u_max_vs_ghia = u_max, v_rms_vs_ghia = v_rms,
              v_max_vs_ghia = v_max, u_rms_linear = ul_rms, u_max_linear = ul_max,
              v_rms_linear = vl_rms, v_max_linear = vl_max, u_rms_particles = up_rms,
              u_lid_rows = u_lid, u_rms_rows = row_errors(sim, column),
              wall_crossing_steps = sim.wall_crossing_steps }
  if dim == 3 then -- the spanwise velocity, 0 in the 2-D flow
    local w, sq = sim.field("vel", 3).value, 0
    for i = 1, #w do sq = sq + w[i] * w[i] end
    m.w_rms = math.sqrt(sq / #w) / U
  end
  return m
end
