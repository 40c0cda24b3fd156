/* ppe.cl (isph-usaw): right-hand side of the pressure Poisson equation (eq 44) with the ρgz form
 * (eqs 41-42): the unknown is P = p̃ + ρ g z = p̃ − ρ g·r. Each row is multiplied by γ_a, so the
 * left-hand side is the plain Morris sum Σ_b 2 V_b F_ab (P_a − P_b) (kernels/common/poisson.cl):
 *   rhs_a = γ_a (ρ/δt) D_a{u*} + 2 Σ_s (∇P)_s · ∇γ_as,
 *   γ_a D_a{u*} = −Σ_b V_b u*_ab·∇w_ab + Σ_s u*_as·∇γ_as                      (9)
 * and the exact non-homogeneous Neumann condition at the walls (eq 43): projecting the momentum
 * equation on the wall normal, (∇p̃)_s = ρ (u*_s − u_wall)/δt, so
 *   (∇P)_s·n_s = ρ [(u*_s − u_wall)/δt − g]·n_s = ρ a_visc,s·n_s,
 * a_visc,s the viscous acceleration of the segment (mean of its vertices'), since a vertex moves
 * with its wall (u*_v = u_wall + δt (a_visc,v + g)). At rest it vanishes: hydrostatics is exact.
 * Free-surface rows are Dirichlet: p̃ = 0 at the surface, which lies surface_offset d (default
 * δr/2, see isph_usaw.c) outside the particle along the outward normal n. Between the two the
 * pressure gradient is the one the momentum equation gives the surface, ∇p̃ = ρ (g − a), a the
 * particle's acceleration of the last step, so
 *   p̃_a = max(0, −ρ (g − a_a)·n d),   P_a = −ρ g·r_a + p̃_a:
 * ρ |g| d under a surface at rest (the hydrostatic tank), 0 on the top of a column in free fall
 * (the dam break, where the hydrostatic value pushed the top layer down onto the layer below). */
__kernel void isph_ppe_rhs(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *ustar,
                           __global const realv *visc, __global const uint *free_surface,
                           const real rho, const real dt, const realv gravity,
                           __global const realv *normal, const real surface_offset,
                           __global const realv *acc, __global real *rhs)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  if (kind[i] > ISPH_VERTEX) {
    rhs[i] = R(0.0);
    return;
  }
  if (free_surface[i]) { /* p̃ = 0 on the surface, surface_offset outside the particle */
    const real pt = fmax(R(0.0), -rho * surface_offset * dot(gravity - acc[i], normal[i]));
    rhs[i] = -rho * dot(gravity, x) + pt;
    return;
  }
  const realv us = ustar[i];
  real div = R(0.0), wall = R(0.0);
  struct neigh_iter it;
  neigh_begin(&it, &g, x);
  uint j;
  while (neigh_next(&it, &g, cell_start, &j)) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= SMOOTH_SUPPORT2 || j == i || kind[j] > ISPH_VERTEX) continue;
    div -= vol[j] * smoothing_f(sqrt(r2)) * dot(us - ustar[j], r);
  }
  neigh_begin(&it, &g_seg, x);
  uint s;
  while (neigh_next(&it, &g_seg, seg_start, &s)) {
    const realv a = seg_a[s] + it.shift, b = seg_b[s] + it.shift;
    const realv gg = usaw_grad_gamma_seg(x, a, b, seg_n[s]);
    const uint v1 = inv[seg_v1[s]], v2 = inv[seg_v2[s]];
    div += dot(us - R(0.5) * (ustar[v1] + ustar[v2]), gg);
    wall += dot(R(0.5) * (visc[v1] + visc[v2]), gg);
  }
  rhs[i] = rho / dt * div + R(2.0) * rho * wall;
}

/* p̃ = P + ρ g·r */
__kernel void isph_pressure(const uint n, __global const realv *pos, __global const real *P,
                            const real rho, const realv gravity, __global real *p)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  p[i] = P[i] + rho * dot(gravity, pos[i]);
}
