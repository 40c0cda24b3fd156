-- Lid-driven cavity (Leroy et al. 2014 sec 4.1): a unit square box whose lid slides at U = 1,
-- Re = U L / ν. Centreline profiles u(y) at x = 1/2 and v(x) at y = 1/2 against Ghia, Ghia &
-- Shin 1982 (tests/data), RMS and largest deviation in units of U. The paper's resolutions:
-- 120² (Re 100), 200² (Re 400), 240² (Re 1000). --set wcsph=1 runs the WCSPH baseline. The
-- profiles along y = 1/2 and along the diagonal also carry the pressure (isph-usaw against
-- wcsph-usaw at Re 400: tests/validation/cavity_pressure.py). cfl multiplies the schemes'
-- time-step bounds; shift is isph-usaw's shifting coefficient (0 turns shifting off);
-- checkpoint > 0 writes a checkpoint every that many seconds of flow (long runs: --restart).
param { re = 100, n = 120, t_end = 30, cfl = 1, wcsph = 0, riemann = 0, ard = 0, tvf = 2, dens = 0, c0 = 10, alpha = 0.2,
        shift = 0.7, checkpoint = 0 }

local U = 1
domain { 0, 0, 1, 1 }
particles { dr = 1 / n }
if riemann == 1 then -- Riemann WCSPH with the limited transport velocity (c0 = 10 U)
  scheme { "wcsph-riemann", sound_speed = c0 * U, ard = ard, transport_coefficient = alpha,
           transport_velocity = ({"off", "full", "limited"})[tvf + 1],
           density = dens == 1 and "continuity" or nil }
elseif wcsph == 1 then -- the paper's baseline: c0 = 10 U and a background pressure
  scheme { "wcsph-usaw", sound_speed = 10 * U, background_pressure = 0.05 * 100 * U * U }
else
  scheme { "isph-usaw", shifting = shift }
end
fluid { density = 1, viscosity = U / re }
box_wall { 0, 0, 1, 1, lid_velocity = {U, 0} }
fill { 0, 0, 1, 1, name = "fluid" }
profile { "u_centreline", from = {0.5, 0}, to = {0.5, 1}, points = 101 }
profile { "v_centreline", from = {0, 0.5}, to = {1, 0.5}, points = 101 }
profile { "diagonal", from = {0, 0}, to = {1, 1}, points = 101 }  -- pressure along the diagonal
force { "lid" }
run { t_end = t_end, output_every = t_end / 10, cfl = cfl,
      checkpoint_every = checkpoint > 0 and checkpoint or nil }

function metrics(sim)
  local column = "Re" .. math.floor(re + 0.5)
  if column ~= "Re100" and column ~= "Re400" and column ~= "Re1000" then -- Ghia's other Re: not
    return { wall_crossing_steps = sim.wall_crossing_steps }             -- in tests/data
  end
  local u_rms, u_max = sim.profile_error { field = "vel", component = 1, x = 0.5,
    csv = "tests/data/ghia1982_u_centreline.csv", coordinate = "y", value = "u_" .. column }
  local v_rms, v_max = sim.profile_error { field = "vel", component = 2, y = 0.5,
    csv = "tests/data/ghia1982_v_centreline.csv", coordinate = "x", value = "v_" .. column }
  -- the same by first-order moving least squares, exact for a linear field: next to the walls,
  -- where Shepard's support is cut and the profile curves, Shepard's average lags by h ∂u/∂n
  -- (with isph-usaw's h = 2 δr at 30², 0.16 U next to the lid)
  local ul_rms, ul_max = sim.profile_error { field = "vel", component = 1, x = 0.5,
    csv = "tests/data/ghia1982_u_centreline.csv", coordinate = "y", value = "u_" .. column,
    interpolation = "linear" }
  local vl_rms, vl_max = sim.profile_error { field = "vel", component = 2, y = 0.5,
    csv = "tests/data/ghia1982_v_centreline.csv", coordinate = "x", value = "v_" .. column,
    interpolation = "linear" }
  return { u_rms_vs_ghia = u_rms, u_max_vs_ghia = u_max, v_rms_vs_ghia = v_rms,
           v_max_vs_ghia = v_max, u_rms_linear = ul_rms, u_max_linear = ul_max,
           v_rms_linear = vl_rms, v_max_linear = vl_max,
           wall_crossing_steps = sim.wall_crossing_steps }
end
