/* shift.cl (isph-usaw): particle shifting (eqs 35-38). Fluid particles farther than h q_max/2
 * from every free-surface particle move by
 *   δr_a = −C h² G_a{1},   G_a{1} = (1/γ_a) Σ_b V_b ∇w_ab − (1/γ_a) Σ_s ∇γ_as      (36-37)
 * (the segment term keeps them off the walls; C = 0.7 for the Wendland kernel), and their
 * velocity follows to first order (eq 38):
 *   u_a += G−_a{ũ}·δr_a = −(1/γ_a) Σ_b V_b u_ab (∇w_ab·δr_a) + (1/γ_a) Σ_s u_as (∇γ_as·δr_a),
 * u_s from wall_vel: the walls' velocity, or under the k-ε model the vertices' own velocity
 * (eq 24), the one the model's gradients take. With the walls' velocity the wall term reads the
 * log-law jump from 0 to u(δr/2) as a gradient u/(δr/2), 6 times the log law's gradient at the
 * first row of the e+ = 640 channel, and the correction grew a lattice mode along the wall
 * (row-1 u varying with a period of 4 δr) that threw particles out at t = 12 s. */
#ifndef ISPH_SHIFT_MAX
#define ISPH_SHIFT_MAX R(0.1)
#endif
#ifndef ISPH_SHIFT_VCORR /* eq 38 (option shift_velocity, isph_usaw.c) */
#define ISPH_SHIFT_VCORR 1
#endif
/* collisions: usaw/common.cl */
__kernel void isph_shift(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *vel,
                         __global const realv *wall_vel, __global const realv *grad_gam,
                         __global const uint *free_surface, const real c_shift, const uint guard,
                         const real dr0, __global const uint *id, __global realv *shift,
                         __global realv *vel_out)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i], u = vel[i];
  shift[i] = (realv)(R(0.0));
  vel_out[i] = u;
  if (kind[i] != ISPH_FLUID) return;
  const real near2 = R(0.25) * g.sm.support2; /* (h q_max / 2)² */
  const real cd = USAW_COLLIDE * dr0;         /* collision distance */
  realv gc = (realv)(R(0.0));
  realv cx = (realv)(R(0.0)), cu = (realv)(R(0.0)); /* collisions: move and velocity change */
  int near_surface = 0;
  struct neigh_iter it;
  /* in lanes (grid.cl) */
  struct lanesv gc4 = lanes_zero_v();
  maskw near4 = (maskw)(0);
  NEIGH_FOR_LANES(it, g, cell_start, x, b)
  {
    const struct lanesv r = lanes_rel(x, lanes_load_v(pos, b), it.shift);
    const realw r2 = lanes_dot(r, r);
    const uintw kj = lanes_load_u(kind, b);
    const maskw part =
        neigh_live(&it, b) & (r2 < g.sm.support2) & LANES_MASK(kj <= (uintw)(ISPH_VERTEX));
    /* near the free surface (i itself too): no shift */
    near4 |= part & (r2 < near2) & LANES_MASK(lanes_load_u(free_surface, b) != (uintw)(0u));
    const maskw take = part & neigh_other(b, i);
    lanes_acc_v(&gc4, lanes_keep(lanes_load(vol, b) * smoothing_fl(g.sm, sqrt(r2)), take), r);
    if (!guard || !any(take & LANES_MASK(kj == (uintw)(ISPH_FLUID)) & (r2 < cd * cd))) continue;
    for (uint k = 0; k < (uint)NEIGH_W; ++k) { /* rare: the collisions one pair at a time */
      const uint j = b + k;
      if (j < it.j || j >= it.end || j == i || kind[j] != ISPH_FLUID) continue;
      const realv rv = x - (pos[j] + it.shift);
      const real len = length(rv);
      if (len >= cd) continue;
      const realv e = usaw_pair_dir(rv, len, dr0, id[i], id[j]);
      const real vn = dot(u - vel[j], e);
      if (vn < R(0.0)) cu -= R(0.5) * (R(1.0) + USAW_RESTITUTION) * vn * e;
      cx += R(0.5) * (cd - len) * e;
    }
  }
  gc = lanes_total_v(gc4);
  near_surface = any(near4);
  const real lcx = length(cx);
  if (lcx > R(0.5) * cd) cx *= R(0.5) * cd / lcx;
  if (near_surface) {
    if (guard) { /* collisions only */
      const realv m = usaw_wall_guard(x, cx, R(1.0), g.sm.support / R(16.0), g_seg, seg_start,
                                      seg_a, seg_b, seg_n, seg_v1, seg_v2, inv, vel, 0);
      shift[i] = m;
      vel_out[i] = u + cu;
    }
    return;
  }
  gc -= grad_gam[i]; /* Σ_s ∇γ_as at these positions (usaw_gamma ran after the move) */
  const real h = R(1.0) / g.sm.inv_h;
  realv dr = -c_shift * h * h * gc / gam[i];
  /* at most ISPH_SHIFT_MAX h per step: in a sparse region next to a wall (a jet running up a
   * slope) |G{1}| reaches 1/h and eq 35 moved a particle by 0.7 h in one step, through the wall */
  const real ldr = length(dr), lmax = ISPH_SHIFT_MAX * h;
  if (ldr > lmax) dr *= lmax / ldr;
  dr += cx;
  /* in scenes with a free surface, no shift within h q_max/16 of a wall (project.cl): next to
   * the wedge case's apex, where the fluid leaves the corner, the shift carried particles that
   * slid up the slope around the corner and 0.1-0.2 δr into it */
  if (guard)
    dr = usaw_wall_guard(x, dr, R(1.0), g.sm.support / R(16.0), g_seg, seg_start, seg_a, seg_b,
                         seg_n, seg_v1, seg_v2, inv, vel, 0);
  shift[i] = dr;
#if ISPH_SHIFT_VCORR
  /* first-order velocity correction (eq 38) */
  struct lanesv du4 = lanes_zero_v();
  NEIGH_FOR_LANES(it, g, cell_start, x, b)
  { /* i itself adds nothing (u_ab = 0) */
    const struct lanesv r = lanes_rel(x, lanes_load_v(pos, b), it.shift);
    const maskw take =
        neigh_live(&it, b) & LANES_MASK(lanes_load_u(kind, b) <= (uintw)(ISPH_VERTEX));
    const realw w = lanes_keep(
        lanes_load(vol, b) * smoothing_fl(g.sm, sqrt(lanes_dot(r, r))) * lanes_dot1(r, dr), take);
    lanes_acc_v(&du4, -w, lanes_sub_from(u, lanes_load_v(vel, b)));
  }
  realv du = lanes_total_v(du4);
  struct usaw_segs si; /* the segments of non-zero ∇γ_as (gamma.cl) */
  uint s;
  realv sh, gg;
  USAW_SEGS_FOR(si, x, i, s, sh, gg)
  {
    const realv us = R(0.5) * (wall_vel[inv[seg_v1[s]]] + wall_vel[inv[seg_v2[s]]]);
    du += (u - us) * dot(gg, dr);
  }
  vel_out[i] = u + du / gam[i] + cu;
#else
  vel_out[i] = u + cu;
#endif
}

/* r += δr, u = corrected u (after isph_shift, which reads the unshifted positions) */
__kernel void isph_apply_shift(const uint n, const struct grid g, __global realv *pos,
                               __global const realv *shift, __global realv *vel,
                               __global const realv *vel_new, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  realv x = pos[i] + shift[i];
#if PERIODIC_X
  x.x = isph_wrap(x.x, g.lo.x, g.len.x);
#endif
#if PERIODIC_Y
  x.y = isph_wrap(x.y, g.lo.y, g.len.y);
#endif
  const realv u = vel_new[i];
  if (!all(isfinite(x)) || !all(isfinite(u))) flags_raise(flags, CLSPH_FLAG_NAN);
  pos[i] = x;
  vel[i] = u;
}
