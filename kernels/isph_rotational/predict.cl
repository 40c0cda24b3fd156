/* predict.cl (isph-rotational): the explicit prediction of the intermediate velocity and the
 * source of the pressure equation (Hosseini & Feng 2011 sec 3.2).
 *
 * BDF2 with steps δt (now) and δt' (before), ω = δt/δt': a0 = (1+2ω)/(1+ω), a1 = 1+ω,
 * a2 = ω²/(1+ω) (3/2, 2, 1/2 at constant δt; the first step is BDF1: 1, 1, 0).
 *   rotational (eq 9, viscous term explicit as in sec 3.2):
 *     a0 ũ = a1 u^k − a2 u^{k−1} + δt (ν∇²u^k − ∇p^k/ρ + g)
 *   homogeneous (eq 5): the same without ∇p^k (ROT_ROTATIONAL = 0).
 *   ν∇²u_i = Σ_j 2ν V_j (u_i − u_j) r_ij·L_i∇_iW_ij / (r_ij² + η²)        (eq 28, µ uniform)
 *   ∇p_i   = Σ_j V_j (p_j − p_i) L_i∇_iW_ij                               (eq 26)
 * Dummies carry the extrapolated velocity (walls.cl) in the viscous term and ũ = u_wall
 * (= 0 on a wall at rest) in the divergence (sec 3.3.3):
 *   D_i = Σ_j V_j (ũ_j − ũ_i)·L_i∇_iW_ij                                   (eq 27)
 *   rhs_i = a0 ρ/δt D_i                                    (eqs 7 and 13: 3ρ/(2δt) ∇·ũ)
 * with rhs = 0 on the dummy rows (ppe.cl). */
#ifndef ROT_ROTATIONAL
#define ROT_ROTATIONAL 1
#endif

__kernel void rot_predict(OP_ARGS, __global const uint *kind, __global const realv *vel,
                          __global const realv *vel_prev, __global const real *p,
                          __global const realv *wall_vel, const real dt, const real a0,
                          const real a1, const real a2, const real nu, const real rho,
                          const realv accel, __global realv *ustar, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  if (kind[i] != ROT_FLUID) {
    ustar[i] = wall_vel[i];
    return;
  }
  const realv x = pos[i], u_i = vel[i];
  const real p_i = p[i];
  const realm L_i = OP_LOAD_L(i);
  realv lap = (realv)(R(0.0)), gp = (realv)(R(0.0));
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    realv gw = op_grad_w(L_i, smoothing_f(g.sm, sqrt(r2)), r);
    lap += R(2.0) * vol[j] * dot(r, gw) / (r2 + smooth_eta2(g.sm)) * (u_i - vel[j]);
#if ROT_ROTATIONAL
    gp += vol[j] * (p[j] - p_i) * gw;
#endif
  }
  realv u = (a1 * u_i - a2 * vel_prev[i] + dt * (nu * lap - gp / rho + accel)) / a0;
  if (!all(isfinite(u))) flags_raise(flags, CLSPH_FLAG_NAN);
  ustar[i] = u;
}

__kernel void rot_source(OP_ARGS, __global const uint *kind, __global const realv *ustar,
                         const real scale, __global real *div, __global real *rhs)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  if (kind[i] != ROT_FLUID) {
    div[i] = R(0.0);
    rhs[i] = R(0.0);
    return;
  }
  const realv x = pos[i], u_i = ustar[i];
  const realm L_i = OP_LOAD_L(i);
  real s = R(0.0);
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    s += vol[j] * dot(ustar[j] - u_i, op_grad_w(L_i, smoothing_f(g.sm, sqrt(r2)), r));
  }
  div[i] = s;
  rhs[i] = scale * s;
}
