/* update.cl (wcsph-usaw): the pressure force with the momentum-conserving USAW gradient (eq 5),
 *   u^{n+1}_a = u*_a − (δt/ρ_a) G+_a{p},  u* = u^n + δt (a_visc + g + f)   (usaw/viscous.cl)
 * then positions, density, volume and pressure (symplectic Euler):
 *   r^{n+1} = r^n + δt u^{n+1},  ρ^{n+1} = ρ^n + δt dρ/dt,  V = m/ρ,  p = c0² (ρ − ρ0) + p_bg. */
__kernel void wcsph_velocity(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *ustar,
                             __global const real *p, __global const real *rho, const real dt,
                             __global realv *vel)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ISPH_FLUID) return;
  const realv x = pos[i];
  const real pa = p[i];
  realv grad = (realv)(R(0.0));
  struct neigh_iter it;
  neigh_begin(&it, &g, x);
  uint j;
  while (neigh_next(&it, &g, cell_start, &j)) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= SMOOTH_SUPPORT2 || j == i || kind[j] > ISPH_VERTEX) continue;
    grad += vol[j] * (pa + p[j]) * smoothing_f(sqrt(r2)) * r;
  }
  neigh_begin(&it, &g_seg, x);
  uint s;
  while (neigh_next(&it, &g_seg, seg_start, &s)) {
    const realv a = seg_a[s] + it.shift, b = seg_b[s] + it.shift;
    const real ps = R(0.5) * (p[inv[seg_v1[s]]] + p[inv[seg_v2[s]]]);
    grad -= (pa + ps) * usaw_grad_gamma_seg(x, a, b, seg_n[s]);
  }
  vel[i] = ustar[i] - dt / rho[i] * grad / gam[i];
}

__kernel void wcsph_advance(const uint n, const struct grid g, const real dt, const real mass,
                            const real rho0, const real c0, const real p_bg,
                            __global const uint *kind, __global realv *pos,
                            __global const realv *vel, __global real *rho,
                            __global const real *drho, __global real *vol, __global real *p,
                            __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ISPH_FLUID) return;
  realv x = pos[i] + dt * vel[i];
#if PERIODIC_X
  x.x = isph_wrap(x.x, g.lo.x, g.len.x);
#endif
#if PERIODIC_Y
  x.y = isph_wrap(x.y, g.lo.y, g.len.y);
#endif
  const real r = rho[i] + dt * drho[i];
  if (!all(isfinite(x)) || !isfinite(r) || !(r > R(0.0))) flags_raise(flags, CLSPH_FLAG_NAN);
  pos[i] = x;
  rho[i] = r;
  vol[i] = mass / r;
  p[i] = c0 * c0 * (r - rho0) + p_bg;
}
