/* csr.cl: operators stored per step as compressed sparse rows (the "stored" way of applying a
 * pressure operator): row i holds its diagonal first, then one entry per neighbour within the
 * support in the order of the neighbour loop (grid.cl), so a scheme's coefficient kernel and
 * csr_count agree on the layout. Row starts come from the exclusive scan of grid.cl. */

/* count[i] = 1 (diagonal) + neighbours j ≠ i within the support */
__kernel void csr_count(const uint n, const struct grid g, __global const uint *cell_start,
                        __global const realv *pos, __global uint *count)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  uint c = 1;
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    if (dot(r, r) < g.sm.support2 && j != i) ++c;
  }
  count[i] = c;
}

/* The same rows NEIGH_W neighbours at a time (NEIGH_FOR_LANES, grid.cl), for a coefficient kernel
 * that runs the same loop and the same test (csr_lanes_in; poisson_coeffs): a pair at the edge of
 * the support, where the two ways of summing r² may round apart, is in both or in neither. */
maskw csr_lanes_in(const struct neigh_iter *it, const uint b, const uint i, const realw r2,
                   const real support2)
{
  return neigh_live(it, b) & neigh_other(b, i) & (r2 < support2);
}

__kernel void csr_count_lanes(const uint n, const struct grid g, __global const uint *cell_start,
                              __global const realv *pos, __global uint *count)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  uint c = 0;
  struct neigh_iter it;
  NEIGH_FOR_LANES(it, g, cell_start, x, b)
  {
    const struct lanesv r = lanes_rel(x, lanes_load_v(pos, b), it.shift);
    c += lanes_count(csr_lanes_in(&it, b, i, lanes_dot(r, r), g.sm.support2));
  }
  count[i] = 1u + c;
}

/* After the scan, in one work-group: when the nonzeros row[n] pass the capacity of the stored
 * operator, every row is emptied (so that the coefficient kernels, which write from row[i], stay
 * in bounds, and nothing reads what they wrote) and flags[1] gets their number for the host,
 * which grows the buffers and builds the operator again; else flags[1] = 0. */
__kernel void csr_guard(const uint n, const uint cap, __global uint *row, __global uint *flags)
{
  const uint total = row[n];
  barrier(CLK_GLOBAL_MEM_FENCE);
  if (get_local_id(0) == 0) flags[1] = total > cap ? total : 0u;
  if (total <= cap) return;
  for (uint i = get_local_id(0); i <= n; i += get_local_size(0)) row[i] = 0u;
}

/* d = diag A and dinv = 1 / (d + ε d) (the reinforcement's (1 + ε), blas1_axpy's sum) in one
 * launch, a zero or non-finite one flagged and taken as 1 (blas1_invert) */
__kernel void csr_diag_inverse(const uint n, __global const uint *row, __global const real *val,
                               const real eps, __global real *d, __global real *dinv,
                               __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const real a = val[row[i]];
  d[i] = a;
  real v = a;
  v += eps * a;
  if (!(fabs(v) > R(0.0)) || !isfinite(v)) {
    flags_raise(flags, CLSPH_FLAG_NAN);
    v = R(1.0);
  }
  dinv[i] = R(1.0) / v;
}
