/* operators.cl: SPH operators over the neighbour loop of grid.cl, shared by every scheme.
 *
 * Conventions: r_ij = r_i − r_j; ∇_i W_ij = F(r_ij) r_ij (smoothing.h); V_j = m_j / ρ_j.
 * Kernel-gradient correction (-D KGC=1): ∇_i W_ij becomes L_i ∇_i W_ij with
 *   L_i = ( Σ_j V_j (r_j − r_i) ⊗ ∇_i W_ij )^{-1}
 * (Oger et al. 2007; Hosseini & Feng 2011 eq 25; Wang et al. eq 20 writes it
 * B_i = (−Σ_j r_ij ⊗ ∇W_ij V_j)^{-1}). Because ∇W_ij ∥ r_ij the matrix is symmetric. Where it is
 * nearly singular (too few neighbours: det < 10^−DIM, the full-support value being 1), L_i = I.
 *
 *   op_correction   L_i
 *   op_shepard      Σ_j V_j W_ij                                   (the density-type sum)
 *   op_interp       Σ_j V_j A_j W_ij
 *   op_grad_sym     Σ_j V_j (A_j − A_i) L_i ∇_i W_ij              (Leroy eq 8 form; Hosseini eq 26)
 *   op_grad_antisym Σ_j V_j (A_i + A_j) ∇_i W_ij                  (Leroy eq 5 form, conservative)
 *                   Σ_j V_j (A_i L_j + A_j L_i) ∇_i W_ij with KGC (Wang et al. eq 19 form)
 *   op_div          Σ_j V_j (u_j − u_i) · L_i ∇_i W_ij            (Hosseini eq 27)
 *   op_lap          Σ_j 2 V_j (A_i − A_j) r_ij·L_i∇_i W_ij / (r_ij² + η²)  (Morris 1997;
 *                                                                  Hosseini eq 29; η: smoothing.h)
 * Every operator kernel takes (n, grid, cell_start, pos, vol, L, ...); L is ignored unless KGC. */

#ifndef KGC
#define KGC 0
#endif

#if DIM == 2
realv mat_apply(realm m, realv v)
{
  return (realv)(m.s0 * v.x + m.s1 * v.y, m.s1 * v.x + m.s2 * v.y);
}

realm mat_identity(void)
{
  return (realm)(R(1.0), R(0.0), R(1.0), R(0.0));
}

/* Accumulates V (r_j − r_i) ⊗ ∇W = −V F r_ij ⊗ r_ij (symmetric). */
realm mat_moment(real vf, realv r)
{
  return (realm)(-vf * r.x * r.x, -vf * r.x * r.y, -vf * r.y * r.y, R(0.0));
}

realm mat_inverse_or_identity(realm m)
{
  real det = m.s0 * m.s2 - m.s1 * m.s1;
  if (!(det > R(1e-2))) return mat_identity();
  real inv = R(1.0) / det;
  return (realm)(m.s2 * inv, -m.s1 * inv, m.s0 * inv, R(0.0));
}
#elif DIM == 3
realv mat_apply(realm m, realv v)
{
  return (realv)(m.s0 * v.x + m.s1 * v.y + m.s2 * v.z, m.s1 * v.x + m.s3 * v.y + m.s4 * v.z,
                 m.s2 * v.x + m.s4 * v.y + m.s5 * v.z, R(0.0));
}

realm mat_identity(void)
{
  return (realm)(R(1.0), R(0.0), R(0.0), R(1.0), R(0.0), R(1.0), R(0.0), R(0.0));
}

realm mat_moment(real vf, realv r)
{
  return -vf *
         (realm)(r.x * r.x, r.x * r.y, r.x * r.z, r.y * r.y, r.y * r.z, r.z * r.z, R(0.0), R(0.0));
}

realm mat_inverse_or_identity(realm m)
{
  real c00 = m.s3 * m.s5 - m.s4 * m.s4, c01 = m.s2 * m.s4 - m.s1 * m.s5;
  real c02 = m.s1 * m.s4 - m.s2 * m.s3;
  real det = m.s0 * c00 + m.s1 * c01 + m.s2 * c02;
  if (!(det > R(1e-3))) return mat_identity();
  real inv = R(1.0) / det;
  return inv * (realm)(c00, c01, c02, m.s0 * m.s5 - m.s2 * m.s2, m.s1 * m.s2 - m.s0 * m.s4,
                       m.s0 * m.s3 - m.s1 * m.s1, R(0.0), R(0.0));
}
#endif

/* ∇_i W_ij, corrected when KGC: L_i F r_ij. */
realv op_grad_w(realm L_i, real f, realv r_ij)
{
#if KGC
  return mat_apply(L_i, f * r_ij);
#else
  return f * r_ij;
#endif
}

#define OP_ARGS                                                                                    \
  const uint n, const struct grid g, __global const uint *cell_start, __global const realv *pos,   \
      __global const real *vol, __global const realm *L

#if KGC
#define OP_LOAD_L(i) L[i]
#else
#define OP_LOAD_L(i) mat_identity()
#endif

__kernel void op_correction(OP_ARGS, __global realm *L_out)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  realm m = (realm)(R(0.0));
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    m += mat_moment(vol[j] * smoothing_f(g.sm, sqrt(r2)), r);
  }
  L_out[i] = mat_inverse_or_identity(m);
}

__kernel void op_shepard(OP_ARGS, __global real *out)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  real s = R(0.0);
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2) continue;
    s += vol[j] * smoothing_w(g.sm, sqrt(r2));
  }
  out[i] = s;
}

__kernel void op_interp(OP_ARGS, __global const real *a, __global real *out)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  real s = R(0.0);
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2) continue;
    s += vol[j] * a[j] * smoothing_w(g.sm, sqrt(r2));
  }
  out[i] = s;
}

__kernel void op_grad_sym(OP_ARGS, __global const real *a, __global realv *out)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  const real a_i = a[i];
  const realm L_i = OP_LOAD_L(i);
  realv s = (realv)(R(0.0));
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    s += vol[j] * (a[j] - a_i) * op_grad_w(L_i, smoothing_f(g.sm, sqrt(r2)), r);
  }
  out[i] = s;
}

__kernel void op_grad_antisym(OP_ARGS, __global const real *a, __global realv *out)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  const real a_i = a[i];
  realv s = (realv)(R(0.0));
#if KGC
  const realm L_i = L[i];
#endif
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    realv gw = smoothing_f(g.sm, sqrt(r2)) * r;
#if KGC
    s += vol[j] * (a_i * mat_apply(L[j], gw) + a[j] * mat_apply(L_i, gw));
#else
    s += vol[j] * (a_i + a[j]) * gw;
#endif
  }
  out[i] = s;
}

__kernel void op_div(OP_ARGS, __global const realv *u, __global real *out)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  const realv u_i = u[i];
  const realm L_i = OP_LOAD_L(i);
  real s = R(0.0);
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    s += vol[j] * dot(u[j] - u_i, op_grad_w(L_i, smoothing_f(g.sm, sqrt(r2)), r));
  }
  out[i] = s;
}

__kernel void op_lap(OP_ARGS, __global const real *a, __global real *out)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  const real a_i = a[i];
  const realm L_i = OP_LOAD_L(i);
  real s = R(0.0);
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    real rgw = dot(r, op_grad_w(L_i, smoothing_f(g.sm, sqrt(r2)), r));
    s += R(2.0) * vol[j] * (a_i - a[j]) * rgw / (r2 + smooth_eta2(g.sm));
  }
  out[i] = s;
}
