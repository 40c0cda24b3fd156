-- Half converging-diverging (HCD) channel under the k-ε RANS model of wcsph-riemann (Wang, Sun &
-- Hu sec 5.3; the geometry and monitoring lines of SPHinXsys's 2d_turbulent_HCD_channel): H = 2,
-- a flat upper wall at y = H, the lower wall y = 0 with a platform: a 30° ramp from x = 3 to 4.5,
-- the top y = 1.5 tan 30° = 0.866 from 4.5 to 5.5, a ramp down to x = 7; entry at x = 0, exit at
-- x = 12. U_b = 1, ν = U_b H / Re with Re = 40000, ρ = 1; y_p = 0.025 (the paper's, eq 10).
-- Entry: SPHinXsys's, uniform u = 1 (rising over `ramp` s), k = 3/2 (0.05 U_b)² = 3.75e-3 and
-- ε = C_μ^¾ k^{3/2} / (0.07 H) = 2.695e-4, which are also the initial field (the fluid starts at
-- rest); exit: natural (n·∇u = 0, n·∇k = n·∇ε = 0) at the scheme's characteristic pressure.
-- nf particle rows fill the entry's height; with the boundary offset (sec 4.4, fig 7) every wall
-- moves into the fluid by y_p − dr/2, dr = (H − 2 y_p)/(nf − 1), the lower wall's corners by
-- the miter of its offset segments, so that the first row stays at y_p at every resolution
-- (nf = 40: dr = 0.05 = 2 y_p, no offset; nf < 40 would need a negative one and is refused).
-- ard = 1: adaptive Riemann-eddy dissipation (sec 3.1), the paper's choice for this channel;
-- ard = 0 shows what it prevents (figs 24-26). md sets the momentum equation's Riemann
-- dissipation between fluid pairs without ARD (wcsph-riemann's momentum_dissipation): -1 the
-- scheme's default under the model ("reconstructed"), 0 none, the eddy viscosity alone (sec 3.1
-- and fig 2: the scheme without the Riemann dissipation), 1 eq 19's full jump (the Riemann solver
-- SPHinXsys's HCD channel keeps without ARD), 2 "reconstructed" (tests/validation/run_rans_map.sh).
-- Metrics, against OpenFOAM v1912 with the same entry, model and wall functions
-- (tests/data/openfoam_channel_hcd.csv, inlet "uniform"; tests/validation/openfoam/channel_ke):
-- the profiles along x = 5 (mid-platform, platform to upper wall) and x = 9.5 (the exit section,
-- wall to wall), averaged over the outputs of the last `avg` s (the paper averages in time), at
-- OpenFOAM's cell centres: u_rms_platform, u_max_platform, u_rms_exit, u_max_exit, the RMS and
-- largest |u − u_FV| / U_b; k_rms_platform, k_rms_exit, |k − k_FV| over the line's largest k_FV;
-- backflow_exit and backflow_exit_fv, the share of the exit line's points whose time-mean u is
-- negative in the run and in OpenFOAM's (the platform's wake: 0.125, up to y = 0.25 over the
-- wall); u_unsteady_platform, u_unsteady_exit, k_unsteady_platform, k_unsteady_exit, the RMS
-- along the line of u's spread in time over the same outputs (over U_b) and of k's (over its mean
-- along the line): the disturbance that ARD is to prevent (a steady RANS flow has none);
-- ard_mean, the ARD indicator (neighbours whose Riemann viscosity exceeds the eddy one, eq 42),
-- its mean over the fluid averaged over the outputs of the last `avg` s, and ard_now, the mean
-- at the end, with ard = 1.
-- fitted = 1 lays the fluid next to the lower wall in `band` rows parallel to it, at (j + ½) dr
-- from the offset wall (round at the platform's convex corners, trimmed at the concave ones), the
-- lattice above them, and the floor's dummy layers in rows behind it (wall { dummies = "fitted"
-- }), as the paper relaxes its particles to the walls; fitted = 0 takes the Cartesian lattice,
-- which meets the ramps at every distance (from dr/4 on) and leaves the platform's first row
-- 0.009 (not y_p = 0.025) above it at nf = 40. Neither separates behind the platform as
-- OpenFOAM does (ard = 1, nf = 40, t = 30): fitted, the wall row over the platform ran at 1.57
-- U_b (lattice 1.18, OpenFOAM's wall cell 0.69) and the exit line's u RMS was 0.49 off OpenFOAM's
-- (lattice 0.18 at t = 60). OpenFOAM's wall cells slow from 2.0 U_b at the platform's leading
-- corner (x = 4.47) to 0.65 by x = 4.87, and the shear over them makes its k (0.13 U_b², the
-- second cell); the particles keep their speed past the corner. pbg sets the scheme's
-- background_pressure (20 = ρ0 c0 U_b: no separation either, u RMS 0.30 at the exit line).
-- wallp = 1 (the default; 0 is the mirror) extrapolates the walls' pressure along them with the
-- particles' own pressure gradient (wall_pressure = "gradient"): with the mirror the wall-adjacent
-- row feels 0.78 of the adverse gradient past the corners. At nf = 40 (t = 60, the last 20 s) the
-- exit line's u RMS fell from 0.182 to 0.132 (ard = 1) and from 0.137 to 0.085 (ard = 0), k's from
-- 0.181 to 0.126 and 0.135 to 0.081, and with ard = 0 5% of the line flows back (OpenFOAM's 12.5%);
-- at nf = 80 (t = 30, ard = 0) 0.074 (mirror 0.132), k 0.083 (0.137), 7.5% backflow.
-- OpenFOAM's profiles are near their mesh limit: halving its core and streamwise cells
-- (tests/data/openfoam_channel_hcd_fine.csv, the wall cells kept) moves U by 0.01 U_b RMS along
-- both lines (0.05 at most, the platform's wall cell), k by 3% of its largest along x = 9.5 and
-- 18% at the platform's near-wall peak; its backflow spans x = 5.65-10.69 (5.61-10.63).
param { nf = 40, t_end = 60, y_p = 0.025, ard = 1, every = 1, avg = 20, ramp = 2, c0 = 20,
        points = 121, fitted = 0, band = 6, pbg = 0, wallp = 1, grad = 0, diff = 0,
        shear = 0, pforce = 0, md = -1 }
if md ~= -1 and md ~= 0 and md ~= 1 and md ~= 2 then
  error(("channel_hcd: md must be -1 (the scheme's default), 0 (no Riemann dissipation), 1 (eq 19's full jump) or 2 (the reconstructed jump), not %g"):format(md))
end
if md ~= -1 and ard == 1 then
  error(("channel_hcd: md = %g with ard = 1: ARD sets the momentum's dissipation itself (eq 32); take md = -1"):format(md))
end
if wallp ~= 0 and wallp ~= 1 then
  error(("channel_hcd: wallp must be 0 (the mirror) or 1 (the gradient), not %g"):format(wallp))
end
-- grad = 1: the k-ε model's velocity gradient in the log law's coordinate by the walls (wcsph-riemann's
-- velocity_gradient = "log"); diff = 1: k and ε diffused with the log mean and the walls' mirror
-- (turbulent_diffusion = "log_mirror"); 0: the paper's
if grad ~= 0 and grad ~= 1 then
  error(("channel_hcd: grad must be 0 (the kernel sums' velocity gradient) or 1 (in the log law's coordinate by the walls), not %g"):format(grad))
end
if diff ~= 0 and diff ~= 1 then
  error(("channel_hcd: diff must be 0 (the harmonic mean over the fluid neighbours) or 1 (the log mean and the walls' mirror), not %g"):format(diff))
end
-- shear = 2: the wall model's shear on the first row only (wcsph-riemann's wall_shear =
-- "first_row"; 0: at y_p on the first two rows, the paper's; 1: at each particle's distance);
-- pforce = 1: the dummies' pressure force on the fluid along the walls' normal but for the share
-- of the pressure's gradient along them (wall_pressure_force = "normal"; 0: "corrected", eq 19)
if shear ~= 0 and shear ~= 1 and shear ~= 2 then
  error(("channel_hcd: shear must be 0 (the wall's shear from the log law at y_p), 1 (at each particle's distance) or 2 (on the first row only), not %g"):format(shear))
end
if pforce ~= 0 and pforce ~= 1 then
  error(("channel_hcd: pforce must be 0 (the walls' pressure force with the correction matrix) or 1 (along the walls' normal), not %g"):format(pforce))
end

local H, U, Re = 2.0, 1.0, 40000
local nu = U * H / Re
local dr = (H - 2 * y_p) / (nf - 1)
local off = y_p - dr / 2
if off < -1e-12 then
  error(("channel_hcd: nf = %d gives dr/2 = %g above y_p = %g: the boundary offset y_p − dr/2 "
         .. "would be negative; take nf >= %d"):format(nf, dr / 2, y_p,
        math.ceil((H - 2 * y_p) / (2 * y_p) + 1)))
end
off = math.max(off, 0)
if fitted ~= 0 and fitted ~= 1 then
  error(("channel_hcd: fitted must be 0 or 1, not %g"):format(fitted))
end
if fitted == 1 and (band ~= math.floor(band) or band < 2 or band * dr > 0.5) then
  error(("channel_hcd: band = %g: the fitted rows must be a whole number from 2 (the wall "
         .. "model's layers) to %d (0.5 over the floor)"):format(band, math.floor(0.5 / dr)))
end
local rise = 1.5 * math.tan(math.rad(30))
local L, e = 12.0, 3 * dr -- the walls run on through the entry's and the exit's layers

-- the lower wall (left to right, fluid above) moved up by d: each vertex by the miter of its two
-- segments' unit normals n1, n2, d (n1 + n2) / (1 + n1·n2)
local function offset_up(pts, d)
  local normals = {}
  for i = 1, #pts - 1 do
    local tx, ty = pts[i + 1][1] - pts[i][1], pts[i + 1][2] - pts[i][2]
    local len = math.sqrt(tx * tx + ty * ty)
    normals[i] = {-ty / len, tx / len}
  end
  local out = {}
  for i = 1, #pts do
    local n1, n2 = normals[math.max(i - 1, 1)], normals[math.min(i, #pts - 1)]
    local c = 1 + n1[1] * n2[1] + n1[2] * n2[2]
    out[i] = {pts[i][1] + d * (n1[1] + n2[1]) / c, pts[i][2] + d * (n1[2] + n2[2]) / c}
  end
  return out
end
local floor_line = offset_up({{-e, 0}, {3, 0}, {4.5, rise}, {5.5, rise}, {7, 0}, {L + e, 0}}, off)
local top = H - off

-- the domain between the offset walls: the lattice's rows then sit y_p off the real walls
domain { 0, off, L, top }
particles { dr = dr }
scheme { "wcsph-riemann", ard = ard, sound_speed = c0 * U, background_pressure = pbg,
         momentum_dissipation = ({"off", "riemann", "reconstructed"})[md + 1],
         wall_pressure = wallp == 1 and "gradient" or "mirror",
         velocity_gradient = ({"kernel", "log"})[grad + 1],
         turbulent_diffusion = ({"harmonic", "log_mirror"})[diff + 1],
         wall_shear = ({"y_p", "distance", "first_row"})[shear + 1],
         wall_pressure_force = ({"corrected", "normal"})[pforce + 1] }
fluid { density = 1, viscosity = nu }
local k_in = 1.5 * (0.05 * U) ^ 2
local eps_in = 0.09 ^ 0.75 * k_in ^ 1.5 / (0.07 * H)
turbulence { model = "k-epsilon", y_p = y_p, k = k_in, epsilon = eps_in }
local back = {}
for i = #floor_line, 1, -1 do back[#back + 1] = floor_line[i] end
back.fluid, back.group = "right", "floor"
if fitted == 1 then back.dummies = "fitted" end
wall(back)
wall { {-e, top}, {L + e, top}, fluid = "right", group = "ceiling" }
-- the fluid: between the offset walls from x = 0 to L, dr/4 clear of the lower one (the lattice
-- is Cartesian: along the ramps its points come at any distance from the wall)
if fitted == 1 then
  -- the distance of (x, y) from the offset floor (a polyline)
  local function floor_dist(x, y)
    local best = math.huge
    for i = 1, #floor_line - 1 do
      local a, b = floor_line[i], floor_line[i + 1]
      local tx, ty = b[1] - a[1], b[2] - a[2]
      local t = math.max(0, math.min(1, ((x - a[1]) * tx + (y - a[2]) * ty) / (tx * tx + ty * ty)))
      best = math.min(best, math.sqrt((x - a[1] - t * tx) ^ 2 + (y - a[2] - t * ty) ^ 2))
    end
    return best
  end
  -- the points at distance d above the offset floor, by arc length from x = 0: the segments
  -- moved along their normals, meeting at the miter where the floor turns up (concave) and
  -- joined by an arc of radius d about the corner where it turns down (convex)
  local function row_points(d, out)
    local pieces, n = {}, #floor_line
    local nrm = {}
    for i = 1, n - 1 do
      local a, b = floor_line[i], floor_line[i + 1]
      local tx, ty = b[1] - a[1], b[2] - a[2]
      local len = math.sqrt(tx * tx + ty * ty)
      nrm[i] = {-ty / len, tx / len}
    end
    local start = {floor_line[1][1] + d * nrm[1][1], floor_line[1][2] + d * nrm[1][2]}
    for i = 2, n do
      local v = floor_line[i]
      local n1 = nrm[i - 1]
      if i == n then
        pieces[#pieces + 1] = {start, {v[1] + d * n1[1], v[2] + d * n1[2]}}
      else
        local n2 = nrm[i]
        local cross = n1[1] * n2[2] - n1[2] * n2[1]
        if cross < 0 then -- the floor turns down: an arc about v
          pieces[#pieces + 1] = {start, {v[1] + d * n1[1], v[2] + d * n1[2]}}
          pieces[#pieces + 1] = {arc = v, r = d, a0 = math.atan(n1[2], n1[1]),
                                 a1 = math.atan(n2[2], n2[1])}
          start = {v[1] + d * n2[1], v[2] + d * n2[2]}
        else -- turns up: the two moved segments meet at the miter
          local c = 1 + n1[1] * n2[1] + n1[2] * n2[2]
          local m = {v[1] + d * (n1[1] + n2[1]) / c, v[2] + d * (n1[2] + n2[2]) / c}
          pieces[#pieces + 1] = {start, m}
          start = m
        end
      end
    end
    -- walk the pieces in steps of dr from the point above x = 0 (x = dr/2 first, as the lattice)
    local s_next = nil
    local walked = 0
    for _, pc in ipairs(pieces) do
      local len, at
      if pc.arc then
        len = pc.r * math.abs(pc.a1 - pc.a0)
        at = function(u)
          local a = pc.a0 + (pc.a1 - pc.a0) * u
          return pc.arc[1] + pc.r * math.cos(a), pc.arc[2] + pc.r * math.sin(a)
        end
      else
        len = math.sqrt((pc[2][1] - pc[1][1]) ^ 2 + (pc[2][2] - pc[1][2]) ^ 2)
        at = function(u)
          return pc[1][1] + (pc[2][1] - pc[1][1]) * u, pc[1][2] + (pc[2][2] - pc[1][2]) * u
        end
      end
      if s_next == nil and not pc.arc and pc[2][1] > 0 then -- the first piece runs along x
        s_next = walked + (dr / 2 - pc[1][1])
      end
      while s_next ~= nil and s_next <= walked + len do
        local x, y = at((s_next - walked) / len)
        if x > 0 and x < L then out[#out + 1] = {x, y} end
        s_next = s_next + dr
      end
      walked = walked + len
    end
  end
  local function floor_y(x) -- the offset floor's height at x (it is a graph over x)
    for i = 1, #floor_line - 1 do
      local a, b = floor_line[i], floor_line[i + 1]
      if x <= b[1] then return a[2] + (b[2] - a[2]) * (x - a[1]) / (b[1] - a[1]) end
    end
    return floor_line[#floor_line][2]
  end
  local pts = {}
  for j = 0, band - 1 do row_points((j + 0.5) * dr, pts) end
  -- the lattice above the band, 0.8 dr clear of its last row
  local nx, ny = math.floor(L / dr + 0.5), math.floor((top - off) / dr + 0.5)
  for i = 0, nx - 1 do
    for j = 0, ny - 1 do
      local x, y = (i + 0.5) * dr, off + (j + 0.5) * dr
      if y < top and y > floor_y(x) and floor_dist(x, y) >= (band + 0.3) * dr then
        pts[#pts + 1] = {x, y}
      end
    end
  end
  fill { points = pts }
else
  local clear = offset_up({{-e, 0}, {3, 0}, {4.5, rise}, {5.5, rise}, {7, 0}, {L + e, 0}},
                          off + dr / 4)
  local poly = {{0, off}}
  for i = 2, #clear - 1 do poly[#poly + 1] = clear[i] end
  poly[#poly + 1] = {L, off}
  poly[#poly + 1] = {L, top}
  poly[#poly + 1] = {0, top}
  fill { polygon = poly }
end
inflow { {0, top}, {0, off}, velocity = U, ramp = ramp, k = k_in, epsilon = eps_in, name = "entry" }
outflow { {L, off}, {L, top}, name = "exit" }
-- the monitoring lines, from the first row (y_p off the wall) to the last
local plat = rise + y_p -- the platform is flat at x = 5
profile { name = "platform", from = {5, plat}, to = {5, H - y_p}, points = points }
profile { name = "exit", from = {9.5, y_p}, to = {9.5, H - y_p}, points = points }
force { "floor" }
force { "ceiling" }
run { t_end = t_end, output_every = every, sample_every = ard == 1 and every or nil }

-- the ARD indicator's mean over the fluid at each output (series ard), averaged over the last
-- `avg` s as the profiles are: one output's mean moves with the flow's unsteadiness
if ard == 1 then
  function sample(sim)
    return { ard = sim.mean("ard") }
  end
end

local fv = reference("tests/data/openfoam_channel_hcd.csv", "inlet", "line", "y", "U", "k")

function metrics(sim)
  local m = {}
  local outputs = {}
  local t0 = t_end - avg
  local t = t_end
  while t >= t0 - 1e-9 do
    outputs[#outputs + 1] = t
    t = t - every
  end
  for _, line in ipairs({"platform", "exit"}) do
    -- the time mean of u and k along the line, and u's and k's spread in time
    local mu, mk, su2, sk2, ys, seen = {}, {}, {}, {}, nil, {}
    local count = 0
    for _, time in ipairs(outputs) do
      local p = sim.profile(line, time)
      local key = ("%.9g"):format(p.time)
      if not seen[key] then
        seen[key] = true
        count = count + 1
        ys = p.y
        for i = 1, #p.y do
          mu[i] = (mu[i] or 0) + p.vel_x[i]
          mk[i] = (mk[i] or 0) + p.k[i]
          su2[i] = (su2[i] or 0) + p.vel_x[i] ^ 2
          sk2[i] = (sk2[i] or 0) + p.k[i] ^ 2
        end
      end
    end
    local fu, fk, kbar = 0, 0, 0
    for i = 1, #ys do
      mu[i], mk[i] = mu[i] / count, mk[i] / count
      fu = fu + math.max(su2[i] / count - mu[i] ^ 2, 0)
      fk = fk + math.max(sk2[i] / count - mk[i] ^ 2, 0)
      kbar = kbar + mk[i]
    end
    -- a steady RANS flow holds still: the RMS over the line of the spread in time
    m["u_unsteady_" .. line] = math.sqrt(fu / #ys) / U
    m["k_unsteady_" .. line] = math.sqrt(fk / #ys) / (kbar / #ys)
    local function at(vals, y) -- linear along the line
      if y <= ys[1] then return vals[1] end
      for i = 2, #ys do
        if ys[i] >= y then
          return vals[i - 1] + (vals[i] - vals[i - 1]) * (y - ys[i - 1]) / (ys[i] - ys[i - 1])
        end
      end
      return vals[#ys]
    end
    local su, umax, sk, n, kmax = 0, 0, 0, 0, 0
    for i = 1, #fv.y do
      if fv.inlet[i] == "uniform" and fv.line[i] == line then kmax = math.max(kmax, fv.k[i]) end
    end
    for i = 1, #fv.y do
      if fv.inlet[i] == "uniform" and fv.line[i] == line then
        local du = (at(mu, fv.y[i]) - fv.U[i]) / U
        local dk = (at(mk, fv.y[i]) - fv.k[i]) / kmax
        su, sk, n = su + du * du, sk + dk * dk, n + 1
        umax = math.max(umax, math.abs(du))
      end
    end
    m["u_rms_" .. line] = math.sqrt(su / n)
    m["u_max_" .. line] = umax
    m["k_rms_" .. line] = math.sqrt(sk / n)
    if line == "exit" then -- at OpenFOAM's points, in both
      local neg, negfv = 0, 0
      for i = 1, #fv.y do
        if fv.inlet[i] == "uniform" and fv.line[i] == line then
          if at(mu, fv.y[i]) < 0 then neg = neg + 1 end
          if fv.U[i] < 0 then negfv = negfv + 1 end
        end
      end
      m.backflow_exit, m.backflow_exit_fv = neg / n, negfv / n
    end
    m["samples_" .. line] = count
  end
  if ard == 1 then
    local series, sum, n = sim.series("ard"), 0, 0
    for i = 1, #series.time do
      if series.time[i] >= t0 - 1e-9 then sum, n = sum + series.value[i], n + 1 end
    end
    if n > 0 then m.ard_mean = sum / n end
    m.ard_now = sim.mean("ard")
  end
  return m
end
