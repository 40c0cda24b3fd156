/* viscous.cl (isph-rotational): the implicit prediction (option viscous = "implicit").
 *
 * The paper predicts ũ explicitly (sec 3.2: "we have tested implicit and explicit schemes in both
 * steps ... solving for the intermediate velocity explicitly"), which bounds the step by
 * 0.125 h²/ν: at Re = 1 around a square cylinder at L0 = H/160 that is 1/30 of the CFL bound.
 * The implicit option solves eq 9 (eq 5 for the homogeneous scheme) with ν∇²ũ:
 *   a0 ũ − δt ν∇²ũ = a1 u^k − a2 u^{k−1} + δt (−∇p^k/ρ + g)
 * divided by a0, one component at a time, with κ = δt ν / a0:
 *   fluid row i:    x_i − κ Σ_j P_ij (x_i − x_j),  P_ij = 2 V_j r_ij·L_i∇_iW_ij / (r_ij² + η²)
 *                   (eq 28, µ uniform: common/poisson.cl's poisson_pair)
 *   dummy row d:    (x_d + S_d(x)) / 2 = u_wall,d: the wall condition of walls.cl as an equation,
 *                   S_d the Shepard interpolation of the fluid and the layers at the dummy's image
 *                   (or the value of the particle nearest to it, -D ROT_WALL_IMAGE=1), so the
 *                   dummies extrapolate the new velocity, not the old one
 *   entry layer:    x = u_in (prescribed)
 *   exit layer:     x_e − x_src(e) = 0 (n·∇u = 0 from its progenitor, common/open.cl), or
 *                   x = the prescribed profile (src(e) = e)
 * The right-hand side is rot_predict's ũ with ν = 0 (u_wall on the dummies and layers, set there
 * and by open.cl), except 0 on the exit rows that copy. The operator is the same for both
 * components: stored once per step in the layout of csr.cl and solved by solvers/pressure.
 * After the solve the fluid takes x; the dummies keep ũ = u_wall for ∇·ũ (sec 3.3.3) and the
 * exit layers their progenitor's ũ (rot_open_ustar). */
#ifndef OPEN_SECTIONS
#define OPEN_SECTIONS 0
#endif

/* Row counts in the layout of csr.cl (the diagonal first): a fluid row names its neighbours, a
 * dummy row the fluid and layer particles around its image, a copying exit row its progenitor. */
__kernel void rot_visc_count(const uint n, const struct grid g, __global const uint *cell_start,
                             __global const realv *pos, __global const uint *kind,
                             __global const real *dist, __global const realv *normal,
                             __global const uint *src, __global uint *count)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const uint ki = kind[i];
  uint c = 1;
  if (ki == ROT_FLUID || ki == ROT_DUMMY) {
    const int fluid = ki == ROT_FLUID;
    const realv at = fluid ? pos[i] : pos[i] + R(2.0) * dist[i] * normal[i];
    struct neigh_iter it;
    NEIGH_FOR(it, g, cell_start, at, j) {
      if (fluid ? j == i : kind[j] == ROT_DUMMY) continue;
      realv r = at - (pos[j] + it.shift);
      if (dot(r, r) < g.sm.support2) ++c;
    }
  }
#if OPEN_SECTIONS
  else if (ki == ROT_OUTFLOW && src[i] != i) {
    c = 2;
  }
#endif
  count[i] = c;
}

/* The coefficients of the rows counted by rot_visc_count (see the header for the rows) */
__kernel void rot_visc_coeffs(OP_ARGS, __global const uint *kind, __global const real *dist,
                              __global const realv *normal, __global const uint *src,
                              const real kappa, __global const uint *row, __global uint *col,
                              __global real *val)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const uint ki = kind[i], r0 = row[i];
  uint k = r0 + 1;
  col[r0] = i;
  if (ki == ROT_FLUID) {
    const realv xi = pos[i];
    const realm L_i = OP_LOAD_L(i);
    real diag = R(0.0);
    struct neigh_iter it;
    NEIGH_FOR(it, g, cell_start, xi, j) {
      realv r = xi - (pos[j] + it.shift);
      real r2 = dot(r, r);
      if (r2 >= g.sm.support2 || j == i) continue;
      const real a = -kappa * poisson_pair(g.sm, L_i, vol[j], r, r2); /* −κ P_ij, eq 28 */
      diag += a;
      col[k] = j;
      val[k] = -a;
      ++k;
    }
    val[r0] = R(1.0) + diag;
    return;
  }
  if (ki == ROT_DUMMY) { /* (x_d + S_d(x)) / 2 */
    const realv img = pos[i] + R(2.0) * dist[i] * normal[i];
    real wsum = R(0.0), best = INFINITY;
    uint near = 0;
    struct neigh_iter it;
    NEIGH_FOR(it, g, cell_start, img, j) {
      if (kind[j] == ROT_DUMMY) continue;
      realv r = img - (pos[j] + it.shift);
      real r2 = dot(r, r);
      if (r2 >= g.sm.support2) continue;
      const real w = vol[j] * smoothing_w(g.sm, sqrt(r2));
      wsum += w;
      col[k] = j;
      val[k] = w; /* normalised below */
      if (r2 < best) {
        best = r2;
        near = k;
      }
      ++k;
    }
    for (uint q = r0 + 1; q < k; ++q)
#if ROT_WALL_IMAGE
      val[q] = q == near ? R(0.5) : R(0.0);
#else
      val[q] = R(0.5) * val[q] / wsum;
#endif
    val[r0] = k > r0 + 1 ? R(0.5) : R(1.0); /* no fluid at the image: x_d = u_wall */
    return;
  }
  val[r0] = R(1.0);
#if OPEN_SECTIONS
  if (ki == ROT_OUTFLOW && src[i] != i) { /* x_e − x_src */
    col[k] = src[i];
    val[k] = R(-1.0);
  }
#endif
}

/* the right-hand sides and the initial guesses, per component, from rot_predict's ũ (ν = 0) and
 * u^k (the dummies' u^k is their extrapolated velocity: a guess that already holds the wall) */
__kernel void rot_visc_split(const uint n, __global const uint *kind, __global const uint *src,
                             __global const realv *ustar, __global const realv *vel,
                             __global real *bx, __global real *by, __global real *x,
                             __global real *y)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  realv b = ustar[i];
#if OPEN_SECTIONS
  if (kind[i] == ROT_OUTFLOW && src[i] != i) b = (realv)(R(0.0));
#endif
  bx[i] = b.x;
  by[i] = b.y;
  x[i] = vel[i].x;
  y[i] = vel[i].y;
}

/* ũ of the fluid from the solution */
__kernel void rot_visc_gather(const uint n, __global const uint *kind, __global const real *x,
                              __global const real *y, __global realv *ustar, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ROT_FLUID) return;
#if DIM == 2
  const realv u = (realv)(x[i], y[i]);
#else /* (the implicit prediction is 2-D only: isph_rotational.c refuses it in 3-D) */
  const realv u = (realv)(x[i], y[i], R(0.0), R(0.0));
#endif
  if (!all(isfinite(u))) flags_raise(flags, CLSPH_FLAG_NAN);
  ustar[i] = u;
}
