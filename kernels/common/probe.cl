/* probe.cl: SPH interpolation of a field at arbitrary points (probes, profiles, metrics),
 * normalised by the kernel sum (Shepard), over fluid and wall-vertex particles:
 *   A(x) = Σ_j V_j A_j W(x − x_j) / Σ_j V_j W(x − x_j).
 * A point with no particle within the support gets NaN.
 * On a wall face (a pressure sensor: a face probe, the mean over points on the face, host
 * sim_sample_probes) the sum runs over the fluid on one side only (dummy particles carry no state
 * of their own: kind > 1 is left out; USAW vertex particles on the wall take part). A(x) is then
 * the kernel-weighted mean of the fluid within the support, whose centre lies about a spacing off
 * the wall: for the pressure, the wall's pressure to second order in that offset where the normal
 * pressure gradient vanishes at the wall, as on a fixed vertical wall (∂p/∂n = ρ (g − a)·n with
 * a·n = 0 there and g·n = 0); on a floor it misses ρ g·n times the offset (hydrostatic). Near a
 * corner the centre also sits off the point along the face, by up to about h.
 * order = 1 (profiles and metrics that ask for interpolation = "linear") fits A(x) + ∇A·(x_j − x)
 * to the same particles by weighted least squares (moving least squares of first order), which
 * is exact for a linear field: Shepard's average is not next to a wall, where the support is cut
 * and its centre sits up to h off the point (an error h ∂A/∂n: 0.16 U in u next to the lid of
 * the 30² cavity with isph-usaw's h = 2 δr). Where the particles do not span every direction
 * (the determinant of the weights' covariance, det M / (Σw)^(DIM+1), below 1e-4 in h units) it
 * falls back to Shepard. */

#if DIM == 3
/* The first row of the inverse of the symmetric 4×4 moment matrix m (row-major; d = (x_j − x)/h):
 * M q = e₁ by Gaussian elimination with partial pivoting; 0 where M is singular to the tolerance
 * above (then q is not written). */
int probe_mls_row3(real m[16], real q[4], const real wsum)
{
  real b[4] = {R(1.0), R(0.0), R(0.0), R(0.0)};
  real det = R(1.0);
  for (int c = 0; c < 4; ++c) {
    int piv = c;
    for (int r = c + 1; r < 4; ++r)
      if (fabs(m[4 * r + c]) > fabs(m[4 * piv + c])) piv = r;
    if (piv != c) {
      for (int k = 0; k < 4; ++k) {
        const real t = m[4 * c + k];
        m[4 * c + k] = m[4 * piv + k];
        m[4 * piv + k] = t;
      }
      const real t = b[c];
      b[c] = b[piv];
      b[piv] = t;
      det = -det;
    }
    const real d = m[4 * c + c];
    det *= d;
    if (d == R(0.0)) return 0;
    for (int r = c + 1; r < 4; ++r) {
      const real f = m[4 * r + c] / d;
      for (int k = c; k < 4; ++k) m[4 * r + k] -= f * m[4 * c + k];
      b[r] -= f * b[c];
    }
  }
  if (!(fabs(det) > R(1e-4) * wsum * wsum * wsum * wsum)) return 0;
  for (int r = 3; r >= 0; --r) {
    real v = b[r];
    for (int k = r + 1; k < 4; ++k) v -= m[4 * r + k] * q[k];
    q[r] = v / m[4 * r + r];
  }
  return 1;
}
#endif
__kernel void probe_sample(const uint np, __global const realv *at, const struct grid g,
                           __global const uint *cell_start, __global const realv *pos,
                           __global const real *vol, __global const uint *kind,
                           __global const real *field, const uint ncomp, const uint order,
                           __global real *out)
{
  const uint p = get_global_id(0);
  if (p >= np) return;
  const realv x = at[p];
  real s[4] = {R(0.0), R(0.0), R(0.0), R(0.0)};
  real wsum = R(0.0);
#if DIM == 2
  /* first order: Σ w d, Σ w d dᵀ (d = (x_j − x)/h) and Σ w A_c d */
  real mx = R(0.0), my = R(0.0), mxx = R(0.0), mxy = R(0.0), myy = R(0.0);
  real sx[4] = {R(0.0), R(0.0), R(0.0), R(0.0)}, sy[4] = {R(0.0), R(0.0), R(0.0), R(0.0)};
#else
  /* first order: M = Σ w [1, d][1, d]ᵀ (row-major) and Σ w A_c d */
  real mm[16];
  for (int k = 0; k < 16; ++k) mm[k] = R(0.0);
  real sd[4][3];
  for (int c = 0; c < 4; ++c) sd[c][0] = sd[c][1] = sd[c][2] = R(0.0);
#endif
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    if (kind[j] > 1u) continue; /* fluid and USAW vertex particles carry the fields */
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2) continue;
    real w = vol[j] * smoothing_w(g.sm, sqrt(r2));
    wsum += w;
    for (uint c = 0; c < ncomp && c < 4u; ++c) s[c] += w * field[j * ncomp + c];
#if DIM == 2
    if (order == 1u) {
      const realv d = -r * g.sm.inv_h;
      mx += w * d.x;
      my += w * d.y;
      mxx += w * d.x * d.x;
      mxy += w * d.x * d.y;
      myy += w * d.y * d.y;
      for (uint c = 0; c < ncomp && c < 4u; ++c) {
        sx[c] += w * d.x * field[j * ncomp + c];
        sy[c] += w * d.y * field[j * ncomp + c];
      }
    }
#else
    if (order == 1u) {
      const realv d = -r * g.sm.inv_h;
      const real e[4] = {R(1.0), d.x, d.y, d.z};
      for (int a = 0; a < 4; ++a)
        for (int b = a; b < 4; ++b) mm[4 * a + b] += w * e[a] * e[b];
      for (uint c = 0; c < ncomp && c < 4u; ++c)
        for (int a = 0; a < 3; ++a) sd[c][a] += w * e[a + 1] * field[j * ncomp + c];
    }
#endif
  }
#if DIM == 2
  /* the first row of the inverse of M = [[Σw, Σw dᵀ], [Σw d, Σw d dᵀ]] by cofactors (M is
   * symmetric); det M / (Σw)³ = var_x var_y − cov² of the weights */
  const real c0 = mxx * myy - mxy * mxy, c1 = my * mxy - mx * myy, c2 = mx * mxy - mxx * my;
  const real det = wsum * c0 + mx * c1 + my * c2;
  if (order == 1u && wsum > R(0.0) && det > R(1e-4) * wsum * wsum * wsum) {
    for (uint c = 0; c < ncomp && c < 4u; ++c)
      out[p * ncomp + c] = (c0 * s[c] + c1 * sx[c] + c2 * sy[c]) / det;
    return;
  }
#else
  if (order == 1u && wsum > R(0.0)) {
    for (int a = 1; a < 4; ++a)
      for (int b = 0; b < a; ++b) mm[4 * a + b] = mm[4 * b + a];
    real q[4];
    if (probe_mls_row3(mm, q, wsum)) {
      for (uint c = 0; c < ncomp && c < 4u; ++c)
        out[p * ncomp + c] = q[0] * s[c] + q[1] * sd[c][0] + q[2] * sd[c][1] + q[3] * sd[c][2];
      return;
    }
  }
#endif
  for (uint c = 0; c < ncomp && c < 4u; ++c) out[p * ncomp + c] = wsum > R(0.0) ? s[c] / wsum : NAN;
}
