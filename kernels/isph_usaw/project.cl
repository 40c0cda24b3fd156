/* project.cl (isph-usaw): the projection (eq 32),
 *   ũ_a = u*_a − (δt/ρ) G+_a{p̃},
 *   G+_a{p̃} = (1/γ_a) Σ_b V_b (p̃_a + p̃_b) ∇w_ab − (1/γ_a) Σ_s (p̃_a + p̃_s) ∇γ_as     (5)
 * or, with -D ISPH_GRAD_SYM=1 (the default, see isph_usaw.c), the symmetric gradient (eq 8) of
 * P = p̃ + ρgz as in the pressure equation (eqs 41-42): ∇p̃ = ∇P + ρ g, so
 *   ũ_a = u*_a − δt g − (δt/ρ) G−_a{P},
 * which keeps a fluid at rest (P constant) exactly at rest; a dry segment (both vertices free)
 * borders air and takes the particle's own P;
 * for fluid particles; vertex particles keep their wall's velocity. With -D ISPH_GRAD_SYM=1 the
 * symmetric gradient G−{p̃} (eq 8) replaces G+: exact for a constant pressure, where G+ carries
 * 2 p̃_a (Σ_b V_b ∇w_ab − ∇γ_a), the lattice's quadrature error times twice the pressure. */
#ifndef ISPH_GRAD_SYM
#define ISPH_GRAD_SYM 0
#endif
__kernel void isph_project(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *ustar,
                           __global const real *P, __global const real *pt, const real rho,
                           const real dt, const realv gravity, __global const uint *free_surface,
                           __global realv *vel, __global realv *acc)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ISPH_FLUID) return;
  const realv x = pos[i];
#if ISPH_GRAD_SYM
  __global const real *p = P; /* G−{P}, gravity cancelled analytically */
#else
  __global const real *p = pt; /* G+{p̃}, eq 32 as written */
#endif
  const real pa = p[i];
  realv grad = (realv)(R(0.0));
  struct neigh_iter it;
  neigh_begin(&it, &g, x);
  uint j;
  while (neigh_next(&it, &g, cell_start, &j)) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= SMOOTH_SUPPORT2 || j == i || kind[j] > ISPH_VERTEX) continue;
#if ISPH_GRAD_SYM
    grad -= vol[j] * (pa - p[j]) * smoothing_f(sqrt(r2)) * r;
#else
    grad += vol[j] * (pa + p[j]) * smoothing_f(sqrt(r2)) * r;
#endif
  }
  neigh_begin(&it, &g_seg, x);
  uint s;
  while (neigh_next(&it, &g_seg, seg_start, &s)) {
    const realv a = seg_a[s] + it.shift, b = seg_b[s] + it.shift;
    const uint v1 = inv[seg_v1[s]], v2 = inv[seg_v2[s]];
    /* a segment above the free surface (both vertices free) borders air: its P = ρgz says
     * nothing about the fluid's, so it takes the particle's own value */
    const real ps =
        ISPH_GRAD_SYM && free_surface[v1] && free_surface[v2] ? pa : R(0.5) * (p[v1] + p[v2]);
#if ISPH_GRAD_SYM
    grad += (pa - ps) * usaw_grad_gamma_seg(x, a, b, seg_n[s]);
#else
    grad -= (pa + ps) * usaw_grad_gamma_seg(x, a, b, seg_n[s]);
#endif
  }
#if ISPH_GRAD_SYM
  /* ∇p̃ = ∇P + ρ g, so the gravity of u* cancels exactly: ũ = u* − δt g − (δt/ρ) G−{P} */
  const realv u_new = ustar[i] - dt * gravity - dt / rho * grad / gam[i];
#else
  const realv u_new = ustar[i] - dt / rho * grad / gam[i];
#endif
  acc[i] = (u_new - vel[i]) / dt; /* the particle's acceleration, for the force bound (49) */
  vel[i] = u_new;
}
