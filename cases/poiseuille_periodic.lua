-- Body-force Poiseuille flow in a periodic channel, start-up from rest (Hosseini & Feng 2011
-- sec 4.1, fig 3): width H, length 2H, periodic in x, no-slip walls at y = 0 and H, Re =
-- U0 H / ν = 1 with U0 = g H² / (8ν) the steady centreline velocity. Units H = U0 = 1, so ν = 1,
-- g = 8 and time is in H/U0. The paper's resolutions: dr = 0.1 (360 particles) and 0.05.
-- Reference: the series solution of Morris, Fox & Zhu 1997 (J. Comput. Phys. 136:214, sec 4),
--   u(y,t) = g/(2ν) y (H − y) − Σ_n 4 g H² / (ν π³ (2n+1)³) sin((2n+1)πy/H) e^{−(2n+1)²π²νt/H²}
-- (shared/refdata/analytic.md sec 1). The paper does not print its four times; we take 0.02,
-- 0.05, 0.1 and 1 (steady within 5e-5). Metrics: RMS and largest |u − u_exact| / U0 over the
-- particle rows, at each time; the profile is interpolated at the row heights (1/2 + k) dr and
-- the exact solution goes through the same interpolation (the rows stay at their heights in
-- this unidirectional flow; the Gaussian's row weights are e^{−(Δy/h)²}), so the metric is the
-- particles' error, not the interpolation's (Shepard on a parabola alone is −2 U0 (h/H)²).
-- wall_drag_error: at t = 1 the walls' shear (Hosseini & Feng eqs 31-32) carries the body force,
-- floor and ceiling g H L / 2 each along x; the relative error of their sum, and their x
-- pressure force (zero on a flat wall) relative to it.
-- implicit = 1 solves the prediction's viscous term implicitly (option viscous = "implicit"; the
-- paper's is explicit), which lifts the viscous bound on the step.
-- riemann = 1 runs wcsph-riemann (Wendland C2, h = 1.3 dr, c0 = 10 U0, the limited transport
-- velocity): the exact rows then go through the Wendland interpolation (rows weighted by the
-- sum of W over a row's particles, which are dr apart).
param { dr = 0.1, t_end = 1, homogeneous = 0, shift = 0.04, implicit = 0, riemann = 0,
        tvf = 2 }

local H, nu, g = 1, 1, 8
domain { 0, 0, 2 * H, H, periodic = "x" }
particles { dr = dr }
if riemann == 1 then
  scheme { "wcsph-riemann", sound_speed = 10, transport_velocity = ({"off", "full", "limited"})[tvf + 1] }
else
  scheme { "isph-rotational", projection = homogeneous == 1 and "homogeneous" or "rotational",
           shifting = shift, viscous = implicit == 1 and "implicit" or "explicit" }
end
fluid { density = 1, viscosity = nu, body_force = {g, 0} }
wall { {2 * H, 0}, {0, 0}, fluid = "right", group = "floor" }
wall { {0, H}, {2 * H, H}, fluid = "right", group = "ceiling" }
fill { 0, 0, 2 * H, H }
local rows = math.floor(H / dr + 0.5)
profile { "u", from = {H, dr / 2}, to = {H, H - dr / 2}, points = rows }
force { "floor" }
force { "ceiling" }
run { t_end = t_end, output_every = 0.01 }

local function exact(y, t)
  local u = g / (2 * nu) * y * (H - y)
  for n = 0, 200 do
    local k = 2 * n + 1
    u = u - 4 * g * H * H / (nu * math.pi ^ 3 * k ^ 3) * math.sin(k * math.pi * y / H) *
          math.exp(-k * k * math.pi * math.pi * nu * t / (H * H))
  end
  return u
end

function metrics(sim)
  local h, U0 = (riemann == 1 and 1.3 or 1.2) * dr, g * H * H / (8 * nu)
  local function row_weight(dy) -- the interpolation's weight of a row at dy from the point
    if riemann ~= 1 then return math.exp(-(dy / h) ^ 2) - math.exp(-9) end
    local w = 0
    for k = -3, 3 do -- Wendland C2 (1 − q/2)^4 (1 + 2q), q <= 2, over the row's particles
      local q = math.sqrt((k * dr) ^ 2 + dy * dy) / h
      if q < 2 then w = w + (1 - q / 2) ^ 4 * (1 + 2 * q) end
    end
    return w
  end
  local out = {}
  for _, t in ipairs { 0.02, 0.05, 0.1, 1 } do
    if t <= t_end + 1e-9 then
      local p = sim.profile("u", t)
      local ss, mx = 0, 0
      for k, y in ipairs(p.y) do
        local ws, us = 0, 0 -- the exact rows through the profile's interpolation
        for m = 0, rows - 1 do
          local yr = (m + 0.5) * dr
          if math.abs(yr - y) < 3 * h then
            local w = row_weight(yr - y)
            ws, us = ws + w, us + w * exact(yr, p.time)
          end
        end
        local d = math.abs(p.vel_x[k] - us / ws) / U0
        ss, mx = ss + d * d, math.max(mx, d)
      end
      local tag = string.format("%g", t):gsub("%.", "p")
      out["u_rms_t" .. tag] = math.sqrt(ss / #p.y)
      out["u_max_t" .. tag] = mx
    end
  end
  out.u_centre = sim.sample("vel", H, H / 2)
  if t_end >= 1 - 1e-9 then
    local f, c, total = sim.force("floor", 0.9), sim.force("ceiling", 0.9), g * H * 2 * H
    out.wall_drag_error = math.abs(f.x + c.x - total) / total
    out.wall_pressure_x = math.abs(f.pressure_x + c.pressure_x) / total
  end
  return out
end
