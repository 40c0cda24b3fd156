/* update.cl (wcsph-usaw): the pressure force with the momentum-conserving USAW gradient (eq 5),
 *   u^{n+1}_a = u*_a − (δt/ρ_a) G+_a{p},  u* = u^n + δt (a_visc + g + f)   (usaw/viscous.cl),
 * or, with pressure_form = "dynamic" (rho0 ≠ 0 here), applied as isph-usaw does (eqs 41-42) to the
 * pressure less its hydrostatic part,
 *   P = p − ρ0 g·(r − r_top),   −∇p/ρ = −∇P/ρ − (ρ0/ρ) g,
 *   u^{n+1}_a = u*_a − (δt/ρ_a) G+_a{P} − δt (ρ0/ρ_a) g,
 * r_top the top of the fluid at the start. G+ of a constant is not zero on a particle lattice next
 * to a wall: Σ_b V_b ∇w_ab − ∇γ_a = ε_a ≠ 0 (2.6% of ∇γ on the first row), and G+{p} carries
 * 2 p_a ε_a: 5 m/s² into the walls of a 1 m tank at δr = 0.05 m. In a fluid at rest P is p_bg
 * and the error goes (tank, δr = 0.02 m, 5 s: pressure within 0.45% against 6%, speeds 3e-3
 * against 3e-2 √(gH)). Where the free surface moves it does harm: P = ρ0 |g| (z − z_top) ≠ 0 on
 * the surface, whose truncated kernel sum then acts like a surface tension (the dam-break column
 * hardly collapses). p_bg stays in P: its 2 p_bg ε_a is the regularising force it is there for.
 * Then positions, density, volume and pressure (symplectic Euler, dρ/dt from u^{n+1}):
 *   r^{n+1} = r^n + δt u^{n+1},  ρ^{n+1} = ρ^n + δt dρ/dt,  V = m/ρ,  p = c0² (ρ − ρ0) + p_bg,
 * and the fluid that left the domain is marked (so the time loop launches no step_end for it). */

/* The collisions of u* (usaw/common.cl) of particle i at x with the fluid particles of the lanes
 * b .. b + NEIGH_W − 1 that the range of it holds, closer than cd, one pair at a time: what they
 * take from u*_i added to *cu. */
void wcsph_collide(const struct neigh_iter *it, const uint b, const uint i, const realv x,
                   const real cd, const real dr0, __global const realv *pos,
                   __global const uint *kind, __global const uint *id, __global const realv *ustar,
                   realv *cu)
{
  for (uint k = 0; k < (uint)NEIGH_W; ++k) {
    const uint j = b + k;
    if (j < it->j || j >= it->end || j == i || kind[j] != ISPH_FLUID) continue;
    const realv rv = x - (pos[j] + it->shift);
    const real rl = length(rv);
    if (rl >= cd) continue;
    const realv e = usaw_pair_dir(rv, rl, dr0, id[i], id[j]);
    const real vn = dot(ustar[i] - ustar[j], e);
    if (vn < R(0.0)) *cu -= R(0.5) * (R(1.0) + USAW_RESTITUTION) * vn * e;
  }
}

__kernel void wcsph_velocity(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *ustar,
                             __global const real *p, __global const real *rho, const real dt,
                             const real rho0, const realv gravity, const real p_ref,
                             const uint guard, const real dr0, __global const uint *id,
                             __global realv *vel, __global realv *acc_p)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ISPH_FLUID) return;
  const realv x = pos[i];
  /* P = p − ρ0 g·r − p_ref, p_ref = −ρ0 g·r_top */
  const real pa = p[i] - rho0 * dot(gravity, x) - p_ref;
  realv grad = (realv)(R(0.0));
  realv cu = (realv)(R(0.0)); /* collisions (usaw/common.cl), in scenes with gravity */
  const real cd = USAW_COLLIDE * dr0;
  struct neigh_iter it;
  struct lanesv grad4 = lanes_zero_v();
  /* in lanes (grid.cl); i itself adds nothing to the gradient (r = 0) */
  NEIGH_FOR_LANES(it, g, cell_start, x, b)
  {
    const struct lanesv pj = lanes_load_v(pos, b), r = lanes_rel(x, pj, it.shift);
    const realw r2 = lanes_dot(r, r);
    const uintw kj = lanes_load_u(kind, b);
    const maskw live = neigh_live(&it, b);
    /* P_b = p_b − ρ0 g·r_b − p_ref with r_b = x − r */
    const realw pb = lanes_load(p, b) - rho0 * (dot(gravity, x) - lanes_dot1(r, gravity)) - p_ref;
    const realw wf = lanes_keep(lanes_load(vol, b) * (pa + pb) * smoothing_fl(g.sm, sqrt(r2)),
                                live & LANES_MASK(kj <= (uintw)(ISPH_VERTEX)));
    lanes_acc_v(&grad4, wf, r);
    if (!guard) continue;
    const maskw close =
        live & LANES_MASK(kj == (uintw)(ISPH_FLUID)) & neigh_other(b, i) & (r2 < cd * cd);
    if (!any(close)) continue;
    wcsph_collide(&it, b, i, x, cd, dr0, pos, kind, id, ustar, &cu); /* rare */
  }
  grad = lanes_total_v(grad4);
  struct usaw_segs si; /* the segments of non-zero ∇γ_as (gamma.cl) */
  uint s;
  realv sh, gg;
  USAW_SEGS_FOR(si, x, i, s, sh, gg)
  {
    const realv a = seg_a[s] + sh, b = seg_b[s] + sh;
    const real ps = R(0.5) * (p[inv[seg_v1[s]]] + p[inv[seg_v2[s]]]) -
                    rho0 * dot(gravity, R(0.5) * (a + b)) - p_ref;
    grad -= (pa + ps) * gg;
  }
  /* the pressure's acceleration, where the next prediction takes its wall term (viscous.cl) */
  const realv ap = -(grad / gam[i] + rho0 * gravity) / rho[i];
  acc_p[i] = ap;
  realv u = ustar[i] + cu + dt * ap;
  /* In scenes with gravity, isph-usaw's wall guard (usaw/common.cl; our departure from the
   * paper): a particle that would come within h q_max/16 of a wall loses its velocity into it.
   * At the free surface p ≈ 0 holds nothing off the wall: in the wedge case the meniscus of the
   * falling column crept through the left wall from t = 0.087 s and the run stopped at 0.37 s
   * with particles 0.5 δr behind it. Velocities of the walls are those of their vertices.
   * Collisions of the predicted velocities u* (cu above) ended the clumping that stopped the run
   * next, at 0.67 s (pairs 0.03 δr apart). */
  if (guard)
    u = usaw_wall_guard(x, u, dt, g.sm.support / R(16.0), g_seg, seg_start, seg_a, seg_b, seg_n,
                        seg_v1, seg_v2, inv, vel, 1);
  vel[i] = u;
}

__kernel void wcsph_advance(const uint n, const struct grid g, const real dt, const real mass,
                            const real rho0, const real c0, const real p_bg, const real4 lo,
                            const real4 hi, const real margin, const uint open, __global uint *kind,
                            __global realv *pos, __global const realv *vel, __global real *rho,
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
  if (domain_left(x, lo, hi, margin, open)) { /* step_end's check (domain.cl), here */
    kind[i] = CLSPH_KIND_OUT;
    atomic_inc(&flags[3]);
  }
}

#if !USAW_TURB
/* wcsph_momentum and wcsph_finish: the laminar step's prediction (usaw_predict, usaw/viscous.cl)
 * and pressure force (wcsph_velocity above) in one sweep of the neighbours and one walk of the
 * segments, the same arithmetic as the two kernels (the same bits): the viscous sum reads the
 * neighbours' u^n and the pressure sum their p, which the prediction does not change, and both
 * take the same F(r) of a pair. What needs the neighbours' u* waits for wcsph_finish: the
 * collisions (wcsph_velocity), rare, whose particles wcsph_momentum marks (close), then
 *   u^{n+1} = u* + collisions + δt acc_p,  and the wall guard (the walk of the segment grid: over
 *   the segment cache's lists it took 10-20% longer on the wedge dam break).
 * For fluid particles only: a vertex's u* and viscous acceleration enter nothing in wcsph-usaw
 * without the k-ε model. */
__kernel void wcsph_momentum(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *vel,
                             __global const real *p, __global const real *rho, const real dt,
                             const real nu, const real d_min, const realv accel, const real rho0,
                             const realv gravity, const real p_ref, const uint guard,
                             const real dr0, __global realv *ustar, __global realv *acc_p,
                             __global uint *close)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ISPH_FLUID) return;
  const realv x = pos[i], u = vel[i];
  const real pa = p[i] - rho0 * dot(gravity, x) - p_ref; /* as wcsph_velocity */
  const real cd = USAW_COLLIDE * dr0;
  int near = 0;
  struct neigh_iter it;
  struct lanesv lap4 = lanes_zero_v(), grad4 = lanes_zero_v();
  NEIGH_FOR_LANES(it, g, cell_start, x, b)
  {
    const struct lanesv r = lanes_rel(x, lanes_load_v(pos, b), it.shift);
    const realw r2 = lanes_dot(r, r);
    const uintw kj = lanes_load_u(kind, b);
    const maskw live = neigh_live(&it, b), part = live & LANES_MASK(kj <= (uintw)(ISPH_VERTEX));
    const realw vb = lanes_load(vol, b), f = smoothing_fl(g.sm, sqrt(r2));
    /* viscous: 2 V_b F u_ab (usaw_predict), i left out */
    const realw wv = lanes_keep((realw)(R(2.0)) * vb * f, part & neigh_other(b, i));
    lanes_acc_v(&lap4, wv, lanes_sub_from(u, lanes_load_v(vel, b)));
    /* pressure: V_b (P_a + P_b) F r_ab (wcsph_velocity) */
    const realw pb = lanes_load(p, b) - rho0 * (dot(gravity, x) - lanes_dot1(r, gravity)) - p_ref;
    lanes_acc_v(&grad4, lanes_keep(vb * (pa + pb) * f, part), r);
    if (guard)
      near |=
          any(live & LANES_MASK(kj == (uintw)(ISPH_FLUID)) & neigh_other(b, i) & (r2 < cd * cd));
  }
  const realv lap = lanes_total_v(lap4);
  realv grad = lanes_total_v(grad4);
  struct usaw_wall_m wm = {R(0.0), R(0.0), R(0.0), (realv)(R(0.0))};
  const real cg = R(2.0) * nu / gam[i];
  struct usaw_segs si; /* the segments of non-zero ∇γ_as (gamma.cl) */
  uint s;
  realv sh, gg;
  USAW_SEGS_FOR(si, x, i, s, sh, gg)
  {
    const realv a = seg_a[s] + sh, e = seg_b[s] + sh, nn = seg_n[s];
    const uint v1 = inv[seg_v1[s]], v2 = inv[seg_v2[s]];
    const real ps = R(0.5) * (p[v1] + p[v2]) - rho0 * dot(gravity, R(0.5) * (a + e)) - p_ref;
    grad -= (pa + ps) * gg;
    const real ggn = length(gg);
    if (ggn == R(0.0)) continue;
    const realv us = R(0.5) * (vel[v1] + vel[v2]);
    usaw_wall_m_add(&wm, cg * ggn / usaw_seg_drs(x, a, e, nn, d_min), nn, us);
  }
  ustar[i] = usaw_predict_solve(&wm, u, nu * lap / gam[i], accel, dt, dt, acc_p[i]);
  acc_p[i] = -(grad / gam[i] + rho0 * gravity) / rho[i];
  close[i] = (uint)near;
}

__kernel void wcsph_finish(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *ustar,
                           __global const realv *acc_p, __global const uint *close, const real dt,
                           const uint guard, const real dr0, __global const uint *id,
                           __global realv *vel)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ISPH_FLUID) return;
  realv cu = (realv)(R(0.0));
  const realv x = pos[i];
  if (close[i]) { /* the collisions of wcsph_velocity, in the same order */
    const real cd = USAW_COLLIDE * dr0;
    struct neigh_iter it;
    NEIGH_FOR_LANES(it, g, cell_start, x, b)
    {
      const struct lanesv r = lanes_rel(x, lanes_load_v(pos, b), it.shift);
      const maskw near = neigh_live(&it, b) &
                         LANES_MASK(lanes_load_u(kind, b) == (uintw)(ISPH_FLUID)) &
                         neigh_other(b, i) & (lanes_dot(r, r) < cd * cd);
      if (!any(near)) continue;
      wcsph_collide(&it, b, i, x, cd, dr0, pos, kind, id, ustar, &cu);
    }
  }
  realv u = ustar[i] + cu + dt * acc_p[i];
  if (guard)
    u = usaw_wall_guard(x, u, dt, g.sm.support / R(16.0), g_seg, seg_start, seg_a, seg_b, seg_n,
                        seg_v1, seg_v2, inv, vel, 1);
  vel[i] = u;
}
#endif
