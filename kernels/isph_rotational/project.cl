/* project.cl (isph-rotational): correction and motion (Hosseini & Feng 2011 sec 3.2).
 *   u^{k+1} = ũ − δt/(a0 ρ) ∇φ                                     (eqs 10 and 19; 6 with p)
 *   ∇φ_i = Σ_j V_j (φ_j − φ_i) L_i∇_iW_ij                          (eq 26)
 *   rotational:  p^{k+1} = p^k + φ − µ ∇·ũ                          (eqs 11 and 20)
 *   homogeneous: p^{k+1} = φ (the equation was solved for p, eq 7)
 * u^{k−1} ← u^k for the next BDF2 step. The fluid then moves with r += δt (u + ε_x ΔU),
 * ΔU_i = Σ_j V_j (u_j − u_i) W_ij over the fluid (XSPH, ε_x = 0 unless the case asks for it);
 * entry and exit layer particles move with their own (prescribed or copied) velocity
 * (common/open.cl). */
__kernel void rot_project(OP_ARGS, __global const uint *kind, __global const real *phi,
                          __global const realv *ustar, __global const real *div, const real coef,
                          const real mu, __global realv *vel, __global realv *vel_prev,
                          __global real *p, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ROT_FLUID) return;
  const realv x = pos[i];
  const real f_i = phi[i];
  const realm L_i = OP_LOAD_L(i);
  realv gf = (realv)(R(0.0));
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    gf += vol[j] * (phi[j] - f_i) * op_grad_w(L_i, smoothing_f(g.sm, sqrt(r2)), r);
  }
  const realv u = ustar[i] - coef * gf;
#if ROT_ROTATIONAL
  const real pn = p[i] + f_i - mu * div[i];
#else
  const real pn = f_i;
#endif
  if (!all(isfinite(u)) || !isfinite(pn)) flags_raise(flags, CLSPH_FLAG_NAN);
  vel_prev[i] = vel[i];
  vel[i] = u;
  p[i] = pn;
}

__kernel void rot_move(const uint n, const struct grid g, __global const uint *cell_start,
                       __global const realv *pos, __global const real *vol,
                       __global const uint *kind, __global const realv *vel, const real dt,
                       const real xsph, __global realv *pos_new, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  realv x = pos[i];
  const uint ki = kind[i];
  if (ki == ROT_INFLOW || ki == ROT_OUTFLOW) { /* entry and exit layers: with their velocity */
    x += dt * vel[i];
    if (!all(isfinite(x))) flags_raise(flags, CLSPH_FLAG_NAN);
    pos_new[i] = x;
    return;
  }
  if (ki != ROT_FLUID) {
    pos_new[i] = x;
    return;
  }
  const realv u_i = vel[i];
  realv du = (realv)(R(0.0));
  if (xsph > R(0.0)) {
    struct neigh_iter it;
    NEIGH_FOR(it, g, cell_start, x, j) {
      if (kind[j] != ROT_FLUID) continue;
      realv r = x - (pos[j] + it.shift);
      real r2 = dot(r, r);
      if (r2 >= g.sm.support2 || j == i) continue;
      du += vol[j] * (vel[j] - u_i) * smoothing_w(g.sm, sqrt(r2));
    }
  }
  x += dt * (u_i + xsph * du);
#if PERIODIC_X
  x.x = rot_wrap(x.x, g.lo.x, g.len.x);
#endif
#if PERIODIC_Y
  x.y = rot_wrap(x.y, g.lo.y, g.len.y);
#endif
#if PERIODIC_Z && DIM == 3
  x.z = rot_wrap(x.z, g.lo.z, g.len.z);
#endif
  if (!all(isfinite(x))) flags_raise(flags, CLSPH_FLAG_NAN);
  pos_new[i] = x;
}
