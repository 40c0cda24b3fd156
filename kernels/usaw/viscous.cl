/* viscous.cl (USAW schemes): the velocity prediction without pressure (eq 31),
 *   u*_a = u^n_a + δt [ (1/ρ) L_a{µ, u} + g + f ],
 * with the laminar USAW viscous term (eq 15)
 *   (1/ρ) L_a{µ, u} = (2ν/γ_a) Σ_b V_b u_ab r_ab·∇w_ab / r_ab²
 *                      − (2ν/γ_a) Σ_s (u^R_as · t_as / δr_as) t_as |∇γ_as|,
 * u^R_as = u_a − u_s the velocity relative to the segment, t_as its unit tangential direction
 * (eq 16), δr_as = max(r_as·n_s, δr) (eq 17). It runs for vertex particles too: their u* enters
 * the wall condition of the pressure equation through the segments (eq 43). acc gets
 * (u* − u^n)/δt − g − f, the viscous acceleration, which the wall condition needs. */
__kernel void usaw_predict(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *vel, const real dt,
                           const real nu, const real dr, const realv accel, __global realv *ustar,
                           __global realv *visc)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] > ISPH_VERTEX) return;
  const realv x = pos[i], u = vel[i];
  realv lap = (realv)(R(0.0));
  struct neigh_iter it;
  neigh_begin(&it, &g, x);
  uint j;
  while (neigh_next(&it, &g, cell_start, &j)) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i || kind[j] > ISPH_VERTEX) continue;
    lap += R(2.0) * vol[j] * smoothing_f(g.sm, sqrt(r2)) * (u - vel[j]); /* r·∇w / r² = F */
  }
  neigh_begin(&it, &g_seg, x);
  uint s;
  while (neigh_next(&it, &g_seg, seg_start, &s)) {
    const realv a = seg_a[s] + it.shift, b = seg_b[s] + it.shift, nn = seg_n[s];
    const realv gg = usaw_grad_gamma_seg(g.sm, x, a, b, nn);
    const real ggn = length(gg);
    if (ggn == R(0.0)) continue;
    const realv us = R(0.5) * (vel[inv[seg_v1[s]]] + vel[inv[seg_v2[s]]]);
    realv ur = u - us;
    realv ut = ur - dot(ur, nn) * nn; /* (u^R · t) t */
    const real drs = fmax(dot(x - R(0.5) * (a + b), nn), dr);
    lap -= R(2.0) * ut / drs * ggn;
  }
  const realv a_visc = nu * lap / gam[i];
  visc[i] = a_visc;
  ustar[i] = kind[i] == ISPH_FLUID ? u + dt * (a_visc + accel) : u + dt * (a_visc + accel);
}
