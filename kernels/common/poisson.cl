/* poisson.cl: the Morris Laplacian as a pressure operator, with and without the kernel-gradient
 * correction (-D KGC=1), and Dirichlet rows:
 *   (A x)_i = Σ_j 2 V_j (x_i − x_j) r_ij·L_i∇_i W_ij / (r_ij² + η²)    (Morris et al. 1997;
 *                                                                       Hosseini & Feng eq 29)
 *   (A x)_i = x_i   for a Dirichlet row (dirichlet[i] != 0: a free-surface, outflow or boundary
 *                    particle whose value the right-hand side prescribes)
 * Three entry points share one pair term: poisson_apply (recomputes the kernel terms at every
 * application), poisson_coeffs (writes them once into the CSR layout of csr.cl, NEIGH_W neighbours
 * at a time: poisson_pair_lanes, with csr_count_lanes's rows) and poisson_diag (the diagonal, for
 * Jacobi). With KGC the matrix is not symmetric. */
real poisson_pair(const struct smooth sm, realm L_i, real vol_j, realv r, real r2)
{
  return R(2.0) * vol_j * dot(r, op_grad_w(L_i, smoothing_f(sm, sqrt(r2)), r)) /
         (r2 + smooth_eta2(sm));
}

/* The same pair term of NEIGH_W neighbours at once (NEIGH_FOR_LANES, grid.cl): r·L_i F r = F rᵀ L_i
 * r.
 */
realw poisson_pair_lanes(const struct smooth sm, realm L_i, realw vol_j, const struct lanesv r,
                         const realw r2)
{
#if KGC && DIM == 2
  const realw q = L_i.s0 * r.x * r.x + R(2.0) * L_i.s1 * r.x * r.y + L_i.s2 * r.y * r.y;
#elif KGC
  const realw q = L_i.s0 * r.x * r.x + L_i.s3 * r.y * r.y + L_i.s5 * r.z * r.z +
                  R(2.0) * (L_i.s1 * r.x * r.y + L_i.s2 * r.x * r.z + L_i.s4 * r.y * r.z);
#else
  const realw q = r2;
#endif
  return R(2.0) * vol_j * smoothing_fl(sm, sqrt(r2)) * q / (r2 + smooth_eta2(sm));
}

__kernel void poisson_apply(OP_ARGS, __global const uint *dirichlet, __global const real *x,
                            __global real *y)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  if (dirichlet[i] != 0u) {
    y[i] = x[i];
    return;
  }
  const realv xi = pos[i];
  const real x_i = x[i];
  const realm L_i = OP_LOAD_L(i);
  real s = R(0.0);
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, xi, j) {
    realv r = xi - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    s += poisson_pair(g.sm, L_i, vol[j], r, r2) * (x_i - x[j]);
  }
  y[i] = s;
}

__kernel void poisson_coeffs(OP_ARGS, __global const uint *dirichlet, __global const uint *row,
                             __global uint *col, __global real *val)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const int fixed = dirichlet[i] != 0u;
  const realv xi = pos[i];
  const realm L_i = OP_LOAD_L(i);
  uint k = row[i] + 1;
  realw diag4 = (realw)(R(0.0));
  struct neigh_iter it;
  /* in lanes (grid.cl), the entries in the order and by the test of csr_count_lanes */
  NEIGH_FOR_LANES(it, g, cell_start, xi, b)
  {
    const struct lanesv r = lanes_rel(xi, lanes_load_v(pos, b), it.shift);
    const realw r2 = lanes_dot(r, r);
    const maskw in = csr_lanes_in(&it, b, i, r2, g.sm.support2);
    if (!any(in)) continue;
    const realw c =
        fixed ? (realw)(R(0.0)) : poisson_pair_lanes(g.sm, L_i, lanes_load(vol, b), r, r2);
    diag4 += lanes_keep(c, in);
    int lane[NEIGH_W];
    real cl[NEIGH_W];
    LANES_VSTORE_I(LANES_INT(in), 0, lane);
    LANES_VSTORE_R(c, 0, cl);
    for (uint q = 0; q < (uint)NEIGH_W; ++q) {
      if (!lane[q]) continue;
      col[k] = b + q;
      val[k] = -cl[q];
      ++k;
    }
  }
  const real diag = lanes_sum(diag4);
  col[row[i]] = i;
  val[row[i]] = fixed ? R(1.0) : diag;
}

__kernel void poisson_diag(OP_ARGS, __global const uint *dirichlet, __global real *d)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  if (dirichlet[i] != 0u) {
    d[i] = R(1.0);
    return;
  }
  const realv xi = pos[i];
  const realm L_i = OP_LOAD_L(i);
  real s = R(0.0);
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, xi, j) {
    realv r = xi - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    s += poisson_pair(g.sm, L_i, vol[j], r, r2);
  }
  d[i] = s;
}
