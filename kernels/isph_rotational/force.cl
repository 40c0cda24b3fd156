/* force.cl (isph-rotational): the force of the fluid on dummy-particle walls (Hosseini & Feng
 * 2011 eqs 31-32), f = ∮ (−p n + µ (∇u + ∇uᵀ) n) dS over the wall line, n into the fluid. The
 * host puts sample points along the line (at most δr apart); at each point x_s this kernel
 * evaluates, from the particles within the support,
 *   p(x_s) = Σ_b V_b p_b W_sb / Σ_b V_b W_sb over fluid and dummies (the dummies carry the
 *            wall's pressure, propagated along the normal: walls.cl),
 *   ∇u(x_s) from the weighted least-squares quadratic through the wall value u_w (no slip) and
 *            the fluid particles: u_b − u_w ≈ ∇u·d_b + ½ d_bᵀ H d_b, d_b = x_b − x_s, weights W_sb.
 * The paper takes the pressure of the surface particles and the velocity gradient from fluid,
 * wall and dummy particles with the dummies' velocity extrapolated through the wall. Our dummies
 * carry the odd reflection of the fluid's velocity (Morris et al.), which is a linear
 * extrapolation only of a linear profile: a linear fit through them gave the Poiseuille wall
 * shear 15% low at δr = 0.1 H. The quadratic fit over the fluid side is exact for the parabola.
 * No particle lies on the wall in our layout (fluid rows δr/2 from it, dummies δr/2 inside), so
 * both values are interpolated to it. out[5k..5k+4] = p, ∂u_x/∂x, ∂u_x/∂y, ∂u_y/∂x, ∂u_y/∂y. */
__kernel void rot_surface_sample(const uint ns, __global const realv *xs, __global const realv *uw,
                                 const uint n, const struct grid g, __global const uint *cell_start,
                                 __global const realv *pos, __global const real *vol,
                                 __global const uint *kind, __global const realv *vel,
                                 __global const real *p, __global real *out)
{
  const uint k = get_global_id(0);
  if (k >= ns) return;
  const realv x = xs[k], u_w = uw[k];
  const real inv_h = g.sm.inv_h;
  real sw = R(0.0), sp = R(0.0);
  real M[5][7]; /* normal equations of the fit, with the two right-hand sides (u_x, u_y) */
  for (int a = 0; a < 5; ++a)
    for (int b = 0; b < 7; ++b) M[a][b] = R(0.0);
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    if (kind[j] != ROT_FLUID && kind[j] != ROT_DUMMY) continue;
    const realv d = pos[j] + it.shift - x;
    const real r2 = dot(d, d);
    if (r2 >= g.sm.support2) continue;
    const real w = vol[j] * smoothing_w(g.sm, sqrt(r2));
    sw += w;
    sp += w * p[j];
    if (kind[j] != ROT_FLUID) continue;
    const realv e = d * inv_h; /* scaled: the matrix stays well conditioned */
    const real phi[5] = {e.x, e.y, e.x * e.x, e.x * e.y, e.y * e.y};
    const realv du = vel[j] - u_w;
    for (int a = 0; a < 5; ++a) {
      for (int b = 0; b < 5; ++b) M[a][b] += w * phi[a] * phi[b];
      M[a][5] += w * phi[a] * du.x;
      M[a][6] += w * phi[a] * du.y;
    }
  }
  /* Gaussian elimination with partial pivoting; a singular fit (too few fluid neighbours)
   * gives no gradient */
  int ok = 1;
  for (int c = 0; c < 5 && ok; ++c) {
    int piv = c;
    for (int a = c + 1; a < 5; ++a)
      if (fabs(M[a][c]) > fabs(M[piv][c])) piv = a;
    if (!(fabs(M[piv][c]) > R(1e-9) * (fabs(M[0][0]) + fabs(M[1][1])))) {
      ok = 0;
      break;
    }
    for (int b = 0; b < 7; ++b) {
      const real t = M[c][b];
      M[c][b] = M[piv][b];
      M[piv][b] = t;
    }
    for (int a = c + 1; a < 5; ++a) {
      const real f = M[a][c] / M[c][c];
      for (int b = c; b < 7; ++b) M[a][b] -= f * M[c][b];
    }
  }
  real gx[2] = {R(0.0), R(0.0)}, gy[2] = {R(0.0), R(0.0)}; /* ∇u_x, ∇u_y */
  if (ok) {
    real cx[5], cy[5];
    for (int a = 4; a >= 0; --a) {
      real sx = M[a][5], sy = M[a][6];
      for (int b = a + 1; b < 5; ++b) {
        sx -= M[a][b] * cx[b];
        sy -= M[a][b] * cy[b];
      }
      cx[a] = sx / M[a][a];
      cy[a] = sy / M[a][a];
    }
    gx[0] = cx[0] * inv_h;
    gx[1] = cx[1] * inv_h;
    gy[0] = cy[0] * inv_h;
    gy[1] = cy[1] * inv_h;
  }
  out[5 * k] = sw > R(0.0) ? sp / sw : R(0.0);
  out[5 * k + 1] = gx[0];
  out[5 * k + 2] = gx[1];
  out[5 * k + 3] = gy[0];
  out[5 * k + 4] = gy[1];
}
