/* mg.cl: the aggregation multigrid preconditioner of the pressure solve (solvers/pressure/mg.c).
 *
 * The unknowns are particles sorted by the neighbour grid (grid.cl), so a cell's particles are
 * one contiguous range. The aggregates are geometric:
 *   level 1: the neighbour-grid cells (side ≥ support / GRID_SUB: about 4 particles in 2-D),
 *   level l + 1: blocks of 2 x 2 (x 2) cells of level l,
 * with piecewise-constant prolongation P (Vaněk, Mandel & Brezina 1996 without the smoothing of
 * P) and the Galerkin coarse operator A_{l+1} = Pᵀ A_l P. A coarse operator is a stencil over
 * the cells of its level: level 1 couples cells up to GRID_SUB apart (the support), every coarser
 * level up to 1 apart, so row I holds (2R + 1)^DIM values, the one of offset o at S[I W + o].
 * Rows with no off-diagonal entry (Dirichlet rows, inert particles) are their own exact solve
 * and join no aggregate (P has a zero row there). A coupling that a moved particle stretches
 * beyond the stencil is lumped into the diagonal (row sums are kept). Empty cells are zero rows,
 * which the smoother leaves at zero (dinv = 0). Periodic axes wrap at every level. */
#define MG_NONE 0xffffffffu

#ifndef MG_OVER
#define MG_OVER R(1.5)
#endif

/* Stencil radius and width of level 1 and of the coarser levels. */
#define MG_R1 GRID_SUB
#if DIM == 2
#define MG_W1       ((2 * MG_R1 + 1) * (2 * MG_R1 + 1))
#define MG_WC       9
#define MG_CHILDREN 4
#else
#define MG_W1       ((2 * MG_R1 + 1) * (2 * MG_R1 + 1) * (2 * MG_R1 + 1))
#define MG_WC       27
#define MG_CHILDREN 8
#endif

int4 mg_coords(const int4 n, const uint id)
{
  return (int4)((int)id % n.x, ((int)id / n.x) % n.y, (int)id / (n.x * n.y), 0);
}

uint mg_id(const int4 n, const int4 c)
{
  return (uint)(c.x + n.x * (c.y + n.y * c.z));
}

/* Offset d along an axis of n cells, wrapped into (−n/2, n/2] on a periodic one. */
int mg_wrap_offset(int d, const int n, const int periodic)
{
  if (!periodic) return d;
  d %= n;
  if (d < 0) d += n;
  if (2 * d > n) d -= n;
  return d;
}

/* Index of the stencil entry coupling cell a to cell b (radius R), or −1 beyond the stencil. */
int mg_offset(const int4 n, const int4 a, const int4 b, const int R)
{
  const int w = 2 * R + 1;
  const int dx = mg_wrap_offset(b.x - a.x, n.x, PERIODIC_X);
  const int dy = mg_wrap_offset(b.y - a.y, n.y, PERIODIC_Y);
  const int dz = mg_wrap_offset(b.z - a.z, n.z, PERIODIC_Z);
  if (abs(dx) > R || abs(dy) > R || abs(dz) > R) return -1;
#if DIM == 2
  return (dy + R) * w + (dx + R);
#else
  return ((dz + R) * w + (dy + R)) * w + (dx + R);
#endif
}

/* One coordinate of a neighbour cell: wrapped on a periodic axis; −1 outside a non-periodic one. */
int mg_wrap_coord(int c, const int n, const int periodic)
{
  if (c >= 0 && c < n) return c;
  if (!periodic) return -1;
  c %= n;
  return c < 0 ? c + n : c;
}

/* The cell at stencil entry o of cell a (radius R); 0 when it is outside the grid. */
int mg_neighbour(const int4 n, const int4 a, const int o, const int R, int4 *b)
{
  const int w = 2 * R + 1;
#if DIM == 2
  const int4 c = a + (int4)(o % w - R, o / w - R, 0, 0);
#else
  const int4 c = a + (int4)(o % w - R, (o / w) % w - R, o / (w * w) - R, 0);
#endif
  const int x = mg_wrap_coord(c.x, n.x, PERIODIC_X), y = mg_wrap_coord(c.y, n.y, PERIODIC_Y),
            z = mg_wrap_coord(c.z, n.z, PERIODIC_Z);
  if (x < 0 || y < 0 || z < 0) return 0;
  *b = (int4)(x, y, z, 0);
  return 1;
}

/* ---- set-up, once per solve ---- */

/* agg[i]: the cell of unknown i, or MG_NONE for a row without off-diagonal entries. */
__kernel void mg_aggregate(const uint ncells, __global const uint *start, __global const uint *row,
                           __global const real *val, __global uint *agg)
{
  const uint c = get_global_id(0);
  if (c >= ncells) return;
  for (uint i = start[c]; i < start[c + 1]; ++i) {
    int coupled = 0;
    for (uint k = row[i] + 1; k < row[i + 1]; ++k) coupled |= val[k] != R(0.0);
    agg[i] = coupled ? c : MG_NONE;
  }
}

/* Level 1: S = Pᵀ (A + ε diag A) P from the stored rows (csr.cl), one cell per work-item. */
__kernel void mg_galerkin_csr(const int4 nc, __global const uint *start, __global const uint *row,
                              __global const uint *col, __global const real *val,
                              __global const uint *agg, const real eps, __global real *S)
{
  const uint c = get_global_id(0);
  if (c >= (uint)nc.w) return;
  const int centre = MG_W1 / 2;
  real acc[MG_W1];
  for (int o = 0; o < MG_W1; ++o) acc[o] = R(0.0);
  const int4 a = mg_coords(nc, c);
  for (uint i = start[c]; i < start[c + 1]; ++i) {
    if (agg[i] == MG_NONE) continue;
    acc[centre] += eps * val[row[i]];
    for (uint k = row[i]; k < row[i + 1]; ++k) {
      const uint J = agg[col[k]];
      if (J == MG_NONE) continue;
      const int o = mg_offset(nc, a, mg_coords(nc, J), MG_R1);
      acc[o < 0 ? centre : o] += val[k];
    }
  }
  for (int o = 0; o < MG_W1; ++o) S[(size_t)c * MG_W1 + o] = acc[o];
}

/* Level l + 1 from level l (radius Rf): the 2 x 2 (x 2) children of each coarse cell. */
__kernel void mg_galerkin(const int4 nf, const int Rf, __global const real *Sf, const int4 nc,
                          __global real *Sc)
{
  const uint K = get_global_id(0);
  if (K >= (uint)nc.w) return;
  const int wf = 2 * Rf + 1;
  const int Wf = DIM == 2 ? wf * wf : wf * wf * wf;
  const int centre = MG_WC / 2;
  real acc[MG_WC];
  for (int o = 0; o < MG_WC; ++o) acc[o] = R(0.0);
  const int4 k = mg_coords(nc, K);
  for (int ch = 0; ch < MG_CHILDREN; ++ch) {
    const int4 I = 2 * k + (int4)(ch & 1, (ch >> 1) & 1, (ch >> 2) & 1, 0);
    if (I.x >= nf.x || I.y >= nf.y || I.z >= nf.z) continue;
    const uint id = mg_id(nf, I);
    for (int o = 0; o < Wf; ++o) {
      const real v = Sf[(size_t)id * Wf + o];
      int4 J;
      if (v == R(0.0) || !mg_neighbour(nf, I, o, Rf, &J)) continue;
      const int oc = mg_offset(nc, k, J / 2, 1);
      acc[oc < 0 ? centre : oc] += v;
    }
  }
  for (int o = 0; o < MG_WC; ++o) Sc[(size_t)K * MG_WC + o] = acc[o];
}

/* dw = ω / diag (0 on an empty cell) */
__kernel void mg_weights(const uint n, const int W, __global const real *S, const real omega,
                         __global real *dw)
{
  const uint I = get_global_id(0);
  if (I >= n) return;
  const real d = S[(size_t)I * W + W / 2];
  dw[I] = d != R(0.0) ? omega / d : R(0.0);
}

/* ---- the cycle ---- */

/* y = (A x)_I on a stencil level (radius R) */
real mg_stencil_row(const int4 nl, const int R, __global const real *S, __global const real *x,
                    const uint I)
{
  const int w = 2 * R + 1;
  const int W = DIM == 2 ? w * w : w * w * w;
  const int4 a = mg_coords(nl, I);
  real s = R(0.0);
  for (int o = 0; o < W; ++o) {
    const real v = S[(size_t)I * W + o];
    int4 b;
    if (v != R(0.0) && mg_neighbour(nl, a, o, R, &b)) s += v * x[mg_id(nl, b)];
  }
  return s;
}

/* ((A + ε diag A) x)_i from the stored rows */
real mg_csr_row(__global const uint *row, __global const uint *col, __global const real *val,
                const real eps, __global const real *x, const uint i)
{
  real s = eps * val[row[i]] * x[i];
  for (uint k = row[i]; k < row[i + 1]; ++k) s += val[k] * x[col[k]];
  return s;
}

/* r = b − A x, fine level */
__kernel void mg_residual_csr(const uint n, __global const uint *row, __global const uint *col,
                              __global const real *val, const real eps, __global const real *b,
                              __global const real *x, __global real *r)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  r[i] = b[i] - mg_csr_row(row, col, val, eps, x, i);
}

/* y = x + dw (b − A x): a damped Jacobi sweep, fine level */
__kernel void mg_jacobi_csr(const uint n, __global const uint *row, __global const uint *col,
                            __global const real *val, const real eps, __global const real *dw,
                            __global const real *b, __global const real *x, __global real *y)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  y[i] = x[i] + dw[i] * (b[i] - mg_csr_row(row, col, val, eps, x, i));
}

/* r = b − A x, stencil level */
__kernel void mg_residual(const int4 nl, const int R, __global const real *S,
                          __global const real *b, __global const real *x, __global real *r)
{
  const uint I = get_global_id(0);
  if (I >= (uint)nl.w) return;
  r[I] = b[I] - mg_stencil_row(nl, R, S, x, I);
}

/* y = x + dw (b − A x), stencil level */
__kernel void mg_jacobi(const int4 nl, const int R, __global const real *S, __global const real *dw,
                        __global const real *b, __global const real *x, __global real *y)
{
  const uint I = get_global_id(0);
  if (I >= (uint)nl.w) return;
  y[I] = x[I] + dw[I] * (b[I] - mg_stencil_row(nl, R, S, x, I));
}

/* Level 1 right-hand side: rc = Pᵀ r (the sum over each cell's aggregated unknowns) */
__kernel void mg_restrict_csr(const uint ncells, __global const uint *start,
                              __global const uint *agg, __global const real *r, __global real *rc)
{
  const uint c = get_global_id(0);
  if (c >= ncells) return;
  real s = R(0.0);
  for (uint i = start[c]; i < start[c + 1]; ++i)
    if (agg[i] != MG_NONE) s += r[i];
  rc[c] = s;
}

/* Level l + 1 right-hand side: the sum over the children */
__kernel void mg_restrict(const int4 nf, __global const real *r, const int4 nc, __global real *rc)
{
  const uint K = get_global_id(0);
  if (K >= (uint)nc.w) return;
  const int4 k = mg_coords(nc, K);
  real s = R(0.0);
  for (int ch = 0; ch < MG_CHILDREN; ++ch) {
    const int4 I = 2 * k + (int4)(ch & 1, (ch >> 1) & 1, (ch >> 2) & 1, 0);
    if (I.x < nf.x && I.y < nf.y && I.z < nf.z) s += r[mg_id(nf, I)];
  }
  rc[K] = s;
}

/* x += P xc, fine level */
__kernel void mg_prolong_csr(const uint n, __global const uint *agg, __global const real *xc,
                             __global real *x)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  if (agg[i] != MG_NONE) x[i] += MG_OVER * xc[agg[i]];
}

/* x += P xc, stencil level */
__kernel void mg_prolong(const int4 nf, __global real *x, const int4 nc, __global const real *xc)
{
  const uint I = get_global_id(0);
  if (I >= (uint)nf.w) return;
  x[I] += MG_OVER * xc[mg_id(nc, mg_coords(nf, I) / 2)];
}

/* y = M r on the coarsest level, M its inverse (dense, row-major, set up on the host) */
__kernel void mg_dense(const uint m, __global const real *M, __global const real *r,
                       __global real *y)
{
  const uint i = get_global_id(0);
  if (i >= m) return;
  real s = R(0.0);
  for (uint j = 0; j < m; ++j) s += M[(size_t)i * m + j] * r[j];
  y[i] = s;
}

/* dw = ω dinv */
__kernel void mg_damp(const uint n, const real omega, __global const real *dinv, __global real *dw)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  dw[i] = omega * dinv[i];
}
