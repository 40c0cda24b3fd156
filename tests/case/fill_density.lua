-- fill { density } for wcsph-usaw: the fluid starts with ρ = ρ0 (1 + 0.01 x) and the pressure its
-- equation of state gives, p = c0² (ρ − ρ0) (no background pressure); sample() at t = 0 reads
-- both back (largest errors, relative to ρ0 and to c0² ρ0 / 100).
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme { "wcsph-usaw", sound_speed = 10 }
fluid { density = 1000, viscosity = 1e-3 }
box_wall { 0, 0, 1, 1 }
fill { 0.1, 0.1, 0.9, 0.9, density = function(x, y) return 1000 * (1 + 0.01 * x) end }
run { t_end = 0.001 }
function sample(sim)
  local rho, p = sim.field("rho"), sim.field("p")
  local erho, ep = 0, 0
  for i = 1, #rho.value do
    local want = 1000 * (1 + 0.01 * rho.x[i])
    erho = math.max(erho, math.abs(rho.value[i] - want) / 1000)
    ep = math.max(ep, math.abs(p.value[i] - 100 * (want - 1000)) / 1000)
  end
  return { rho_error = erho, p_error = ep }
end
function metrics(sim)
  return { rho_error = sim.series("rho_error").value[1], p_error = sim.series("p_error").value[1] }
end
