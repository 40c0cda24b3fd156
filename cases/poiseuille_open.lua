-- Fully developed Poiseuille flow between an entry and an exit (Hosseini & Feng 2011 sec 4.2,
-- fig 4): a channel of width H and length L = H between no-slip walls at y = 0 and H, parabolic
-- entry profile u_in = 4 U0 y (H − y) / H² (eq 30), natural exit (n·∇u = 0, φ = 0 or p = 0),
-- Re = U0 H / ν = 1. Units H = U0 = ρ = 1, so ν = 1 and time is in H/U0; the fluid starts at
-- rest and is steady (to 1e-4) by t ≈ 1. The paper's resolution: L0 = dr = 0.025 H. The dummies
-- take the velocity of the particle at their image (wall_image = 1; 0: the scheme's default
-- Shepard sum there, whose one-sided bias steepens the pressure next to the walls, most at the
-- entry's corners, and more as dr shrinks: kernels/isph_rotational/walls.cl).
-- Exact: u = u_in(y), v = 0, p = G (L − x) with G = 8 µ U0 / H² (p = 0 at the exit).
-- Metrics over the fluid particles at t_end: p_err_max, the largest |p − p_exact − c| relative to
-- the entry-exit drop G L, c the mean of p − p_exact within 1.5 dr of the centre (the paper zeroes
-- its error there: 0.3% homogeneous, 0.04% rotational); p_err_exit_max the same without c (the
-- error against p = 0 at the exit); p_fit_max the largest deviation from the least-squares line
-- a + b x (the entry and exit boundary layers alone) and dpdx_err = −b/G − 1 (the bulk gradient,
-- which the walls set); u_err_max, u_err_rms: |u − u_in(y)| / U0; v_max: |v| / U0. Measured at
-- dr = 0.025 (double): p_err_max 0.013 homogeneous, 0.126 rotational (a checkerboard of p next to
-- the walls before the exit; the bulk within 0.4%), u_err_max 0.003 both (tests/case.cmake).
-- implicit = 1: the prediction's viscous term implicit (viscous = "implicit"; the paper's is
-- explicit), no viscous bound on the step.
-- riemann = 1: the weakly-compressible wcsph-riemann on dummy walls (c0 = 10 U0 by default; the
-- entry and exit layers carry ρ and p from their rows' first fluid particle at the entry and
-- p = 0 at the exit: the same shared sections, solvers/open). c0 = 0: its default 10 U0, which lets
-- the density vary by 8% over the channel (the drop G L = 8 ρ0 U0², Re = 1): give c0 = 30 or more.
-- The outlet is the paper's fixed p = 0 (characteristic = 1: the scheme's default non-reflecting
-- exit, whose mean holds p = 0 only on average: at c0 = 30, p_err_exit_max 0.12 and 0.23 at
-- dr = 0.1 and 0.05 against 0.066 and 0.16 with p = 0; a channel this short does not ring).
param { dr = 0.025, t_end = 1, homogeneous = 0, exit_parabolic = 0, shift = 0.04, wall_image = 1,
        checkpoint = 0, implicit = 0, riemann = 0, c0 = 0,
        characteristic = 0, wallp = 0 }
if wallp ~= 0 and wallp ~= 1 then
  error(("poiseuille_open: wallp must be 0 (the mirror) or 1 (the gradient), not %g"):format(wallp))
end

local H, L, U0, nu = 1, 1, 1, 1
domain { 0, 0, L, H }
particles { dr = dr }
if riemann == 1 then
  scheme { "wcsph-riemann", sound_speed = c0 > 0 and c0 or nil,
           outlet = characteristic == 1 and "characteristic" or "fixed",
           wall_pressure = wallp == 1 and "gradient" or "mirror" }
else
  scheme { "isph-rotational", projection = homogeneous == 1 and "homogeneous" or "rotational",
           shifting = shift, wall_velocity = wall_image == 1 and "image" or "shepard",
           viscous = implicit == 1 and "implicit" or "explicit" }
end
fluid { density = 1, viscosity = nu }
local e = 3 * dr -- the walls run on through the 3 entry and exit layers (their dummies see them)
wall { {L + e, 0}, {-e, 0}, fluid = "right", group = "floor" }
wall { {-e, H}, {L + e, H}, fluid = "right", group = "ceiling" }
fill { 0, 0, L, H }
inflow { {0, H}, {0, 0}, velocity = U0, profile = "parabolic", name = "entry" }
outflow { {L, 0}, {L, H}, name = "exit", profile = exit_parabolic == 1 and "parabolic" or "natural",
          velocity = exit_parabolic == 1 and U0 or nil } -- parabolic: the paper's choice above Re 10
run { t_end = t_end, output_every = t_end / 10,
      checkpoint_every = checkpoint > 0 and checkpoint or nil } -- s between checkpoints

function metrics(sim)
  local G = 8 * nu * U0 / H ^ 2
  local p, u, v = sim.field("p"), sim.field("vel", 1), sim.field("vel", 2)
  local c, nc = 0, 0
  for k = 1, #p.x do
    if math.abs(p.x[k] - L / 2) < 1.5 * dr and math.abs(p.y[k] - H / 2) < 1.5 * dr then
      c, nc = c + p.value[k] - G * (L - p.x[k]), nc + 1
    end
  end
  c = c / nc
  local n, sx, sp, sxx, sxp = #p.x, 0, 0, 0, 0
  for k = 1, n do
    sx, sp = sx + p.x[k], sp + p.value[k]
    sxx, sxp = sxx + p.x[k] ^ 2, sxp + p.x[k] * p.value[k]
  end
  local b = (n * sxp - sx * sp) / (n * sxx - sx * sx)
  local a = (sp - b * sx) / n
  local out = { p_err_max = 0, p_err_exit_max = 0, p_fit_max = 0, u_err_max = 0, v_max = 0,
                dpdx_err = -b / G - 1 }
  local ss = 0
  for k = 1, n do
    local x, y = p.x[k], p.y[k]
    local e = p.value[k] - G * (L - x)
    out.p_err_max = math.max(out.p_err_max, math.abs(e - c) / (G * L))
    out.p_err_exit_max = math.max(out.p_err_exit_max, math.abs(e) / (G * L))
    out.p_fit_max = math.max(out.p_fit_max, math.abs(p.value[k] - a - b * x) / (G * L))
    local du = math.abs(u.value[k] - 4 * U0 * y * (H - y) / H ^ 2) / U0
    out.u_err_max, ss = math.max(out.u_err_max, du), ss + du * du
    out.v_max = math.max(out.v_max, math.abs(v.value[k]) / U0)
  end
  out.u_err_rms = math.sqrt(ss / n)
  out.fluid = n
  return out
end
