/* ppe.cl (isph-rotational): the pressure (φ or p) equation as a matrix-free operator for
 * solvers/pressure (Hosseini & Feng 2011 eqs 13 and 29):
 *   fluid row i:  Σ_j 2 V_j (x_i − x_ĵ) r_ij·L_i∇_iW_ij / (r_ij² + η²)
 *                 ĵ = j for a fluid neighbour, ĵ = mirror[j] for a dummy: the dummy takes the
 *                 value of the fluid particle at its image (Neumann by propagation, sec 3.3.1);
 *                 with sections (-D OPEN_SECTIONS=1) the term is (x_i − c_j x_ĵ): an entry layer
 *                 copies (c_j = 1, Neumann), an exit layer reflects oddly (c_j = h_j/h_ĵ < 0:
 *                 Dirichlet x = 0 at the exit, eq 19; open.cl)
 *   dummy row d:  x_d (identity; its right-hand side is 0 and its value is set afterwards by
 *                 rot_propagate)
 * The rows have the layout of csr_count (diagonal first, then the neighbours in loop order); a
 * dummy neighbour's column is its mirror, so a row may name a column twice (the product sums).
 * A neighbour whose mirror is i itself adds (1 − c_j) to the diagonal.
 * The pair term is common/poisson.cl's poisson_pair (the Morris Laplacian, with L_i). */
#if OPEN_SECTIONS
#define ROT_COEF(j) coef[j]
#else
#define ROT_COEF(j) R(1.0)
#endif

__kernel void rot_ppe_apply(OP_ARGS, __global const uint *kind, __global const uint *mirror,
                            __global const real *coef, __global const real *x, __global real *y)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  if (kind[i] != ROT_FLUID) {
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
    s += poisson_pair(g.sm, L_i, vol[j], r, r2) * (x_i - ROT_COEF(j) * x[mirror[j]]);
  }
  y[i] = s;
}

__kernel void rot_ppe_coeffs(OP_ARGS, __global const uint *kind, __global const uint *mirror,
                             __global const real *coef, __global const uint *row,
                             __global uint *col, __global real *val)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const int fixed = kind[i] != ROT_FLUID;
  const realv xi = pos[i];
  const realm L_i = OP_LOAD_L(i);
  uint k = row[i] + 1;
  real diag = R(0.0);
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, xi, j) {
    realv r = xi - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    const uint c = mirror[j];
    const real c_j = ROT_COEF(j);
    real a = fixed ? R(0.0) : poisson_pair(g.sm, L_i, vol[j], r, r2);
    if (c == i) { /* x_i − c_j x_i: on the diagonal */
      diag += a * (R(1.0) - c_j);
      a = R(0.0);
    } else {
      diag += a;
    }
    col[k] = c;
    val[k] = -a * c_j;
    ++k;
  }
  col[row[i]] = i;
  val[row[i]] = fixed ? R(1.0) : diag;
}

__kernel void rot_ppe_diag(OP_ARGS, __global const uint *kind, __global const uint *mirror,
                           __global const real *coef, __global real *d)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  if (kind[i] != ROT_FLUID) {
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
    if (mirror[j] == i) {
#if OPEN_SECTIONS
      s += poisson_pair(g.sm, L_i, vol[j], r, r2) * (R(1.0) - coef[j]);
#endif
      continue;
    }
    s += poisson_pair(g.sm, L_i, vol[j], r, r2);
  }
  d[i] = s;
}
