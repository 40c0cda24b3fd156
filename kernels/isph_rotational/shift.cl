/* shift.cl (isph-rotational): particle shifting of Xu, Stansby & Laurence 2009 (Hosseini & Feng
 * 2011 sec 3.4), for the fluid:
 *   δr_i = C α Σ_j (r̄_i / r_ij)² r_ij / r_ij,   r̄_i = (1/N_i) Σ_j r_ij,   α = U_max δt
 * over all neighbours (the dummies keep the fluid off the walls), and the velocity follows to
 * first order: u_i += (∇u)_i·δr_i, ∇u_i = Σ_j V_j (u_j − u_i) ⊗ ∇_iW_ij (dummies carry their
 * extrapolated velocity). C = 0.04 unless the case says otherwise (Xu et al. take 0.01-0.1). */
__kernel void rot_shift(const uint n, const struct grid g, __global const uint *cell_start,
                        __global const realv *pos, __global const real *vol,
                        __global const uint *kind, __global const realv *vel, const real c_alpha,
                        __global realv *shift, __global realv *vel_out)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i], u_i = vel[i];
  shift[i] = (realv)(R(0.0));
  vel_out[i] = u_i;
  if (kind[i] != ROT_FLUID) return;
  realv rs = (realv)(R(0.0));
  real rbar = R(0.0), cnt = R(0.0);
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    rbar += sqrt(r2);
    cnt += R(1.0);
  }
  if (cnt == R(0.0)) return;
  rbar /= cnt;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    rs += rbar * rbar / r2 * r / sqrt(r2);
  }
  const realv d = c_alpha * rs;
  realv du = (realv)(R(0.0));
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    du += vol[j] * (vel[j] - u_i) * (smoothing_f(g.sm, sqrt(r2)) * dot(r, d));
  }
  shift[i] = d;
  vel_out[i] = u_i + du;
}

/* r += δr, u = the corrected u (after rot_shift, which reads the unshifted positions) */
__kernel void rot_apply_shift(const uint n, const struct grid g, __global const uint *kind,
                              __global realv *pos, __global const realv *shift, __global realv *vel,
                              __global const realv *vel_new, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ROT_FLUID) return;
  realv x = pos[i] + shift[i];
#if PERIODIC_X
  x.x = rot_wrap(x.x, g.lo.x, g.len.x);
#endif
#if PERIODIC_Y
  x.y = rot_wrap(x.y, g.lo.y, g.len.y);
#endif
#if PERIODIC_Z && DIM == 3
  x.z = rot_wrap(x.z, g.lo.z, g.len.z);
#endif
  const realv u = vel_new[i];
  if (!all(isfinite(x)) || !all(isfinite(u))) flags_raise(flags, CLSPH_FLAG_NAN);
  pos[i] = x;
  vel[i] = u;
}
