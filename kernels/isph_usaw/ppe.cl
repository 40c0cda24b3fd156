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
 * (the dam break, where the hydrostatic value pushed the top layer down onto the layer below).
 * With the scheme option density_relaxation = α (our addition; 0, the paper's, by default) a row
 * whose support holds no free-surface particle also takes
 *   + α ρ (γ_a − Σ_b V_b w_ab)/δt²,
 * the relaxed density invariance of Asai et al. 2012 (isph-stabilized's, with the number density
 * Σ_b V_b w_ab/γ_a for ρ* over ρ0): the projection then contracts where the particles have spread
 * (∇·ũ = −α (1 − ρ* over ρ0)/δt), which the divergence-free projection alone lets accumulate. */
/* A free-surface row's value: P_a = −ρ g·r_a + max(0, −ρ (g − a_a)·n_a d) */
real isph_rhs_surface(const real rho, const real surface_offset, const realv gravity,
                      const realv acc, const realv normal, const realv x)
{
  const real pt = fmax(R(0.0), -rho * surface_offset * dot(gravity - acc, normal));
  return -rho * dot(gravity, x) + pt;
}

/* Segment s (vertices v1, v2, ∇γ_as = gg) in an inner row: u*_as·∇γ_as into div (eq 9) and the
 * Neumann term a_visc,s·∇γ_as into wall (eq 43) */
void isph_rhs_seg(const realv us, __global const realv *ustar, __global const realv *visc,
                  const uint v1, const uint v2, const realv gg, real *div, real *wall)
{
  *div += dot(us - R(0.5) * (ustar[v1] + ustar[v2]), gg);
  *wall += dot(R(0.5) * (visc[v1] + visc[v2]), gg);
}

/* With density_relaxation = 0 the free-surface kernel makes this right-hand side in its own loops
 * (isph_free_surface's with_rhs, free_surface.cl): a row needs only its own flag. The relaxation
 * term reads its neighbours' flags, so that it waits for all of them here. */
__kernel void isph_ppe_rhs(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *ustar,
                           __global const realv *visc, __global const uint *free_surface,
                           const real rho, const real dt, const realv gravity,
                           __global const realv *normal, const real surface_offset,
                           __global const realv *acc, const real relax, __global real *rhs)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  if (kind[i] > ISPH_VERTEX) {
    rhs[i] = R(0.0);
    return;
  }
  if (free_surface[i]) { /* p̃ = 0 on the surface, surface_offset outside the particle */
    rhs[i] = isph_rhs_surface(rho, surface_offset, gravity, acc[i], normal[i], x);
    return;
  }
  const realv us = ustar[i];
  real div = R(0.0), wall = R(0.0), dens = vol[i] * smoothing_w(g.sm, R(0.0));
  uint near_surface = 0;
  struct neigh_iter it;
  /* in lanes (grid.cl), div as isph_free_surface sums it (the same bits) */
  realw div4 = (realw)(R(0.0)), dens4 = div4;
  maskw near4 = (maskw)(0);
  NEIGH_FOR_LANES(it, g, cell_start, x, b)
  {
    const struct lanesv r = lanes_rel(x, lanes_load_v(pos, b), it.shift);
    const realw r2 = lanes_dot(r, r), rr = sqrt(r2), vj = lanes_load(vol, b);
    const uintw kj = lanes_load_u(kind, b);
    const maskw take =
        neigh_live(&it, b) & neigh_other(b, i) & LANES_MASK(kj <= (uintw)(ISPH_VERTEX));
    const realw vf = lanes_keep(vj * smoothing_fl(g.sm, rr), take);
    div4 -= vf * lanes_dot(lanes_sub_from(us, lanes_load_v(ustar, b)), r);
    if (relax > R(0.0)) {
      dens4 += lanes_keep(vj * smoothing_wl(g.sm, rr), take);
      near4 |=
          take & (r2 < g.sm.support2) & LANES_MASK(lanes_load_u(free_surface, b) != (uintw)(0u));
    }
  }
  div = lanes_sum(div4);
  dens += lanes_sum(dens4);
  near_surface = any(near4);
  struct usaw_segs si; /* the segments of non-zero ∇γ_as (gamma.cl) */
  uint s;
  realv sh, gg;
  USAW_SEGS_FOR(si, x, i, s, sh, gg)
  isph_rhs_seg(us, ustar, visc, inv[seg_v1[s]], inv[seg_v2[s]], gg, &div, &wall);
  rhs[i] = rho / dt * div + R(2.0) * rho * wall;
  if (relax > R(0.0) && kind[i] == ISPH_FLUID && !near_surface) rhs[i] += relax * (gam[i] - dens);
}

/* p̃ = P + ρ g·r */
__kernel void isph_pressure(const uint n, __global const realv *pos, __global const real *P,
                            const real rho, const realv gravity, __global real *p)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  p[i] = P[i] + rho * dot(gravity, pos[i]);
}

/* No tension next to the air (scenes with gravity; our departure from the paper, whose projection,
 * eq 32, takes the pressure of eq 44 wherever it is not a free-surface row): a fluid particle
 * within h q_max/2 of a free-surface particle (the layer where shifting is off, shift.cl) takes
 *   p̃_a = max(p̃_a, 0),   P_a = p̃_a − ρ g·r_a,
 * as the air it borders holds no tension. Under the thin front of the dam break
 * (cases/dam_break.lua) the particles on the floor are no free-surface rows, D{r} = 1.5 to 1.8
 * (the floor fills the lower half of their kernel, and D{r} counts the wall's part as fluid),
 * though air lies just ahead of them; they took −2.6e3 to −9.4e3 Pa (ρ g H = 2.9e3 Pa) as they drew
 * away from the particles behind, and the one-sided gradient of that pressure, its neighbours all
 * behind or above, threw them forward along the floor at 1.1 to 1.46 × 2 √(gH) (Ritter's front
 * speed; 7 of 9 runs at n = 20, 1.29 at n = 40), ahead of the front (0.75 to 0.85 × 2 √(gH)). With
 * the bound the fluid on the floor stays below 0.92 × 2 √(gH) at n = 20 (0.99 at n = 40: the
 * front's own tip) and the front runs as before. */
__kernel void isph_no_tension(USAW_PART_ARGS, USAW_SEG_ARGS, __global const uint *free_surface,
                              const real rho, const realv gravity, __global real *P,
                              __global real *p)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ISPH_FLUID || free_surface[i] || p[i] >= R(0.0)) return;
  const realv x = pos[i];
  const real near2 = R(0.25) * g.sm.support2; /* (h q_max / 2)² */
  int near_surface = 0;
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    near_surface |= kind[j] == ISPH_FLUID && free_surface[j] && dot(r, r) < near2;
  }
  if (!near_surface) return;
  p[i] = R(0.0);
  P[i] = -rho * dot(gravity, x);
}
