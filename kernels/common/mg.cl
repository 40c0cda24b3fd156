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
#define MG_NONE      0xffffffffu
#define MG_COARSE_WG 64 /* work-items of mg_coarsest at most (MG_COARSE_WG in mg.h) */

/* The preconditioner's stored coefficients (the fine rows' copy, A P, the coarse stencils) are
 * float in both builds: the cycle's sweeps are bound by memory, and a preconditioner has only to
 * be close to the inverse (its vectors stay in real). MG_REAL_SIZE in mg.h. */
typedef float mreal;

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
  const int yz = (int)id / n.x, z = yz / n.y; /* two divisions, not four */
  return (int4)((int)id - yz * n.x, yz - z * n.y, z, 0);
}

uint mg_id(const int4 n, const int4 c)
{
  return (uint)(c.x + n.x * (c.y + n.y * c.z));
}

/* Offset d = b − a of two cells of an axis of n (|d| < n), wrapped into (−n/2, n/2] on a
 * periodic one. */
int mg_wrap_offset(int d, const int n, const int periodic)
{
  if (!periodic) return d;
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

BLAS1_ROW_DOT(mg_row_dot, mreal) /* the fine rows' float copy (mg_down_csr) */
#define MG_COMMA ,

/* Σ_o S[r0 + o] x[xo + idx[i0 + o]] over the W entries of a stencil row whose idx is a cell
 * (MG_NONE: none), in four partial sums (blas1_row_dot) */
real mg_stencil_dot_at(__global const mreal *S, const size_t r0, __global const uint *idx,
                       const size_t i0, const int W, __global const real *x, const uint xo)
{
  real s0 = R(0.0), s1 = R(0.0), s2 = R(0.0), s3 = R(0.0);
  int o = 0;
  for (; o + 4 <= W; o += 4) {
    const uint J0 = idx[i0 + o], J1 = idx[i0 + o + 1], J2 = idx[i0 + o + 2], J3 = idx[i0 + o + 3];
    if (J0 != MG_NONE) s0 += S[r0 + o] * x[xo + J0];
    if (J1 != MG_NONE) s1 += S[r0 + o + 1] * x[xo + J1];
    if (J2 != MG_NONE) s2 += S[r0 + o + 2] * x[xo + J2];
    if (J3 != MG_NONE) s3 += S[r0 + o + 3] * x[xo + J3];
  }
  for (; o < W; ++o) {
    const uint J = idx[i0 + o];
    if (J != MG_NONE) s0 += S[r0 + o] * x[xo + J];
  }
  return (s0 + s1) + (s2 + s3);
}

/* The same where the row's stencil and its cells lie at the same offset r0 */
real mg_stencil_dot(__global const mreal *S, __global const uint *idx, const size_t r0, const int W,
                    __global const real *x, const uint xo)
{
  return mg_stencil_dot_at(S, r0, idx, r0, W, x, xo);
}

/* ---- set-up, once per solve ---- */

/* The levels' stencils, damped inverse diagonals and vectors lie one after the other in one buffer
 * each (mg.c): a level is its cell counts, radius and offsets into them. The coarse block
 * (mg_block) reads the levels it handles from info[], MG_INFO ints a level. */
#define MG_INFO 8 /* nx, ny, nz, cells, R, S offset, vector offset, unused */

/* agg[i]: the cell of unknown i, or MG_NONE for a row without off-diagonal entries; cell[i]: the
 * cell of unknown i. */
__kernel void mg_aggregate(const uint ncells, __global const uint *start, __global const uint *row,
                           __global const real *val, __global uint *agg, __global uint *cell)
{
  const uint c = get_global_id(0);
  if (c >= ncells) return;
  for (uint i = start[c]; i < start[c + 1]; ++i) {
    int coupled = 0;
    for (uint k = row[i] + 1; k < row[i + 1]; ++k) coupled |= val[k] != R(0.0);
    agg[i] = coupled ? c : MG_NONE;
    cell[i] = c;
  }
}

/* AP = (A + ε diag A) P, fine rows against level-1 cells: row i holds MG_W1 slots, the one of
 * offset o (from i's own cell) at AP[i MG_W1 + o], 0 where no cell couples or the offset leaves
 * the grid; the cell of a slot is level 1's stencil cell of the same offset (nb, mg.c). A
 * coupling beyond the stencil (a particle that moved after the binning) goes to i's own cell: the
 * way up then applies a slightly different (still fixed) preconditioner. */
__kernel void mg_ap_csr(const uint n, const int4 nc, __global const uint *row,
                        __global const uint *col, __global const real *val,
                        __global const uint *agg, __global const uint *cell, const real eps,
                        __global mreal *AP, __global mreal *valm, const real omega,
                        __global const real *dinv, __global real *dw)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  dw[i] = omega * dinv[i]; /* the fine level's damped inverse diagonal */
  const int centre = MG_W1 / 2;
  real acc[MG_W1];
  for (int o = 0; o < MG_W1; ++o) acc[o] = R(0.0);
  const int4 a = mg_coords(nc, cell[i]);
  for (uint k = row[i]; k < row[i + 1]; ++k) valm[k] = (mreal)val[k]; /* mg_down_csr's rows */
  if (agg[i] != MG_NONE) acc[centre] += eps * val[row[i]];
  /* the columns come cell by cell (the neighbour loop's order): a run of one cell's entries is
   * summed first, and placed once */
  uint run_cell = MG_NONE;
  real run = R(0.0);
  for (uint k = row[i]; k <= row[i + 1]; ++k) {
    const uint J = k < row[i + 1] ? agg[col[k]] : MG_NONE;
    if (J == run_cell) {
      run += J != MG_NONE ? val[k] : R(0.0);
      continue;
    }
    if (run_cell != MG_NONE) {
      const int o = mg_offset(nc, a, mg_coords(nc, run_cell), MG_R1);
      acc[o < 0 ? centre : o] += run;
    }
    run_cell = J;
    run = J != MG_NONE ? val[k] : R(0.0);
  }
  for (int o = 0; o < MG_W1; ++o) {
    int4 b;
    const int in = acc[o] != R(0.0) && mg_neighbour(nc, a, o, MG_R1, &b);
    AP[(size_t)i * MG_W1 + o] = in ? (mreal)acc[o] : 0.0f;
  }
}

/* Level 1: S = Pᵀ (A + ε diag A) P = Pᵀ AP, one cell per work-item: the sum of the AP rows of its
 * aggregated unknowns (whose slots are offsets from this cell). */
__kernel void mg_galerkin_ap(const uint ncells, __global const uint *start,
                             __global const uint *agg, __global const mreal *AP, __global mreal *S)
{
  const uint c = get_global_id(0);
  if (c >= ncells) return;
  real acc[MG_W1];
  for (int o = 0; o < MG_W1; ++o) acc[o] = R(0.0);
  for (uint i = start[c]; i < start[c + 1]; ++i) {
    if (agg[i] == MG_NONE) continue;
    for (int o = 0; o < MG_W1; ++o) acc[o] += AP[(size_t)i * MG_W1 + o];
  }
  for (int o = 0; o < MG_W1; ++o) S[(size_t)c * MG_W1 + o] = (mreal)acc[o];
}

/* Level l + 1 (stencil at S + sc) from level l (radius Rf, stencil at S + sf): the 2 x 2 (x 2)
 * children of each coarse cell. */
void mg_galerkin_cell(const int4 nf, const int Rf, const uint sf, const int4 nc, const uint sc,
                      __global mreal *S, const uint K)
{
  const int wf = 2 * Rf + 1;
  const int Wf = DIM == 2 ? wf * wf : wf * wf * wf;
  const int centre = MG_WC / 2;
  __global const mreal *Sf = S + sf;
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
  for (int o = 0; o < MG_WC; ++o) S[sc + (size_t)K * MG_WC + o] = (mreal)acc[o];
}

__kernel void mg_galerkin(const int4 nf, const int Rf, const uint sf, const int4 nc, const uint sc,
                          __global mreal *S)
{
  const uint K = get_global_id(0);
  if (K < (uint)nc.w) mg_galerkin_cell(nf, Rf, sf, nc, sc, S, K);
}

/* dw = ω / diag (0 on an empty cell), a level's stencil at S + so, its vectors at dw + vo (cells
 * nc, level l). live bit 0: the row has a nonzero entry (the cycle skips the others: the cells of
 * a free-surface flow's air, most of a tall domain); bit 1: the cell is one the block passes over
 * (MG_MEMBER: live, or the parent of a member of the finer level, whose cells nf (nf.w = 0 on
 * level 1) and bits lie at fo), listed at list + vo and counted in nlist[l] in no set order (each
 * cell's work is its own). The others' b, t and x are zeroed here, and a cycle over the lists
 * leaves them zero: what the cycle over every cell computes for them, or what nothing reads
 * (a non-member's x on the way up, which only a zero coefficient or no parent reaches). */
#define MG_LIVE   1
#define MG_MEMBER 2
void mg_weights_cell(const int W, const uint so, __global const mreal *S, const real omega,
                     const uint vo, __global real *dw, __global uchar *live, const int l,
                     const int4 nc, const int4 nf, const uint fo, __global uint *list,
                     __global uint *nlist, __global real *b, __global real *t, __global real *x,
                     const uint I)
{
  const size_t r0 = so + (size_t)I * W;
  const real d = S[r0 + W / 2];
  dw[vo + I] = d != R(0.0) ? omega / d : R(0.0);
  uchar any = 0;
  for (int o = 0; o < W; ++o) any |= S[r0 + o] != R(0.0);
  uchar member = any;
  if (nf.w > 0) {
    const int4 k = mg_coords(nc, I);
    for (int ch = 0; ch < MG_CHILDREN; ++ch) {
      const int4 C = 2 * k + (int4)(ch & 1, (ch >> 1) & 1, (ch >> 2) & 1, 0);
      if (C.x < nf.x && C.y < nf.y && C.z < nf.z && (live[fo + mg_id(nf, C)] & MG_MEMBER))
        member = 1;
    }
  }
  live[vo + I] = (any ? MG_LIVE : 0) | (member ? MG_MEMBER : 0);
  if (member) {
    list[vo + atomic_inc(nlist + l)] = I;
  } else {
    b[vo + I] = R(0.0);
    t[vo + I] = R(0.0);
    x[vo + I] = R(0.0);
  }
}

__kernel void mg_weights(const uint n, const int W, const uint so, __global const mreal *S,
                         const real omega, const uint vo, __global real *dw, __global uchar *live,
                         const int l, const int4 nc, const int4 nf, const uint fo,
                         __global uint *list, __global uint *nlist, __global real *b,
                         __global real *t, __global real *x)
{
  const uint I = get_global_id(0);
  if (I < n) mg_weights_cell(W, so, S, omega, vo, dw, live, l, nc, nf, fo, list, nlist, b, t, x, I);
}

/* The levels from lb on that fit the block (at most MG_BLOCK cells each), set up in one work-group
 * and one launch: each level's Galerkin stencils (mg_galerkin, but level 1's: mg_galerkin_ap) and
 * then its weights and members (mg_weights), which read the finer level's members, in turn */
__kernel void mg_setup_block(const int lb, const int L, __global const int *info, __global mreal *S,
                             const real omega, __global real *dw, __global uchar *live,
                             __global uint *list, __global uint *nlist, __global real *b,
                             __global real *t, __global real *x)
{
  const uint lid = get_local_id(0), ls = get_local_size(0);
  for (int l = lb; l <= L; ++l) {
    __global const int *v = info + MG_INFO * l;
    const int4 nc = (int4)(v[0], v[1], v[2], v[3]);
    const int W = v[4];
    const uint so = (uint)v[5], vo = (uint)v[6];
    int4 nf = (int4)(0);
    uint fo = 0u;
    if (l > 1) {
      __global const int *f = info + MG_INFO * (l - 1);
      nf = (int4)(f[0], f[1], f[2], f[3]);
      fo = (uint)f[6];
      const int Rf = l - 1 == 1 ? MG_R1 : 1;
      for (uint K = lid; K < (uint)nc.w; K += ls)
        mg_galerkin_cell(nf, Rf, (uint)f[5], nc, so, S, K);
      barrier(CLK_GLOBAL_MEM_FENCE);
    }
    for (uint I = lid; I < (uint)nc.w; I += ls)
      mg_weights_cell(W, so, S, omega, vo, dw, live, l, nc, nf, fo, list, nlist, b, t, x, I);
    barrier(CLK_GLOBAL_MEM_FENCE);
  }
}

/* ---- the cycle ----
 * A V(1,1) cycle from zero: down each level, one damped-Jacobi sweep from zero (t = dw b) and
 * the restricted residual Pᵀ (b − A t); the coarsest solved; up each level, u = t + P x_coarse
 * (over-corrected by MG_OVER) and one sweep u + dw (b − A u), written as
 *   u + dw (res − MG_OVER (A P) x_coarse),   res = b − A t kept from the way down,
 * so that the way up reads the coarse solution, not a prolonged vector. A stencil level's res is
 * its x until the way up overwrites it; the fine level keeps AP (mg_ap_csr). The stencils'
 * neighbours (nb), their parents (pnb) and each cell's parent (par) are tables made with the
 * levels (mg.c). The kernel that makes a level's b makes its t. Launches: the fine res
 * (mg_down_csr, the fine t = dw ∘ r coming with r; in the solve the kernel that makes r makes
 * both: mg_begin_down, mg_s_down below), for the levels above MG_BLOCK cells the restriction and
 * one launch a level each way, the small levels in one work-group (mg_block), the fine level up. */

/* Fine level down: res = r − (A + ε diag A) t */
__kernel void mg_down_csr(const uint n, __global const uint *row, __global const uint *col,
                          __global const mreal *val, const real eps, __global const real *t,
                          __global const real *r, __global real *res, const uint kit,
                          __global const kreal *st)
{
  if (kr_over(st, kit)) return;
  const uint i = get_global_id(0);
  if (i >= n) return;
  res[i] = r[i] - mg_row_dot(eps * val[row[i]] * t[i], row[i], row[i + 1], col, val, t);
}

/* The Krylov vector updates with the fine level down, in one launch each (psolve.c): the kernel
 * that makes the cycle's input w also makes t = dw ∘ w and res = w − (A + ε diag A) t, a
 * neighbour's t made from its own vectors as its item makes it (the same expression, so the same
 * value), where kr_begin or kr_s and then mg_down_csr were two launches. A row's sum reads three or
 * four vectors a neighbour instead of one. MG_ROW_DOT_AT(NAME, ARGS, T): Σ val[k] T(col[k]) over a
 * stored row in four partial sums, as blas1_row_dot. */
#define MG_ROW_DOT_AT(NAME, ARGS, T)                                                               \
  real NAME(real s, uint k, const uint k1, __global const uint *col, __global const mreal *val,    \
            __global const real *dw, ARGS)                                                         \
  {                                                                                                \
    real s1 = R(0.0), s2 = R(0.0), s3 = R(0.0);                                                    \
    for (; k + 4 <= k1; k += 4) {                                                                  \
      s += val[k] * T(col[k]);                                                                     \
      s1 += val[k + 1] * T(col[k + 1]);                                                            \
      s2 += val[k + 2] * T(col[k + 2]);                                                            \
      s3 += val[k + 3] * T(col[k + 3]);                                                            \
    }                                                                                              \
    for (; k < k1; ++k) s += val[k] * T(col[k]);                                                   \
    return (s + s1) + (s2 + s3);                                                                   \
  }
/* p = r + β (p' − ω v) and s = r − α v, times dw (kr_begin, kr_s) */
#define MG_T_P(j) (dw[j] * (r[j] + beta * (pp[j] - omega * v[j])))
#define MG_T_S(j) (dw[j] * (r[j] - alpha * v[j]))
MG_ROW_DOT_AT(mg_row_dot_p,
              __global const real *r MG_COMMA __global const real *pp MG_COMMA
                  __global const real *v MG_COMMA const real beta MG_COMMA const real omega,
              MG_T_P)
MG_ROW_DOT_AT(mg_row_dot_s,
              __global const real *r MG_COMMA __global const real *v MG_COMMA const real alpha,
              MG_T_S)

/* kr_begin and mg_down_csr: p = r + β (p' − ω v) into p (p' the last iteration's p, in the
 * other buffer: a neighbour's item reads it while this one writes), t = dw ∘ p, res = p − A t */
__kernel void mg_begin_down(const uint n, const uint k, const uint ngroups, __global kreal *st,
                            __global const real *part, __global const real *pp, __global real *p,
                            __global const real *r, __global const real *v, const real noise,
                            __global const real *dw, __global real *t, __global const uint *row,
                            __global const uint *col, __global const mreal *val, const real eps,
                            __global real *res)
{
  __local real lbeta, lomega;
  __local int go;
  if (kr_over(st, k)) return;
  if (get_local_id(0) == 0) {
    real b = R(0.0), w = R(0.0);
    go = kr_begin_scalars(st, part, k, ngroups, 0u, noise, &b, &w);
    lbeta = b;
    lomega = w;
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  if (!go) return;
  const real beta = lbeta, omega = lomega;
  BLAS1_FOR_ROWS(i, n)
  {
    const real w = r[i] + beta * (pp[i] - omega * v[i]);
    const real ti = dw[i] * w;
    p[i] = w;
    t[i] = ti;
    res[i] = w - mg_row_dot_p(eps * val[row[i]] * ti, row[i], row[i + 1], col, val, dw, r, pp, v,
                              beta, omega);
  }
}

/* kr_s and mg_down_csr: s = r − α v, (s, s) into set KR_SS, t = dw ∘ s, res = s − A t */
__kernel void mg_s_down(const uint n, const uint k, const uint ngroups, __global kreal *st,
                        __global real *part, __global const real *r, __global const real *v,
                        __global real *s, __global const real *dw, __global real *t,
                        __global const uint *row, __global const uint *col,
                        __global const mreal *val, const real eps, __global real *res)
{
  __local real a[BLAS1_WG];
  __local real lalpha;
  __local int go;
  if (kr_over(st, k)) return;
  if (get_local_id(0) == 0) {
    real al = R(0.0);
    go = kr_s_scalars(st, part, k, ngroups, &al);
    lalpha = al;
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  if (!go) return;
  const real alpha = lalpha;
  real acc = R(0.0);
  /* (s, s) over kr_s's rows (the same sum), the rows' sums over the stored rows' (blas1.cl) */
  BLAS1_FOR(i, n)
  {
    const real w = r[i] - alpha * v[i];
    acc += w * w;
  }
  BLAS1_FOR_ROWS(i, n)
  {
    const real w = r[i] - alpha * v[i];
    const real ti = dw[i] * w;
    s[i] = w;
    t[i] = ti;
    res[i] =
        w - mg_row_dot_s(eps * val[row[i]] * ti, row[i], row[i + 1], col, val, dw, r, v, alpha);
  }
  a[get_local_id(0)] = acc;
  blas1_group_sum(a, part + KR_SS * BLAS1_GROUPS, get_group_id(0));
}

/* Level-1 b and t of cell c: Σ res over its aggregated unknowns, times dw */
void mg_restrict_cell(__global const uint *start, __global const uint *agg,
                      __global const real *res, __global const real *cdw, __global real *b,
                      __global real *t, const uint c)
{
  real s = R(0.0);
  for (uint i = start[c]; i < start[c + 1]; ++i)
    if (agg[i] != MG_NONE) s += res[i];
  b[c] = s;
  t[c] = cdw[c] * s;
}

__kernel void mg_restrict_csr(const uint ncells, __global const uint *start,
                              __global const uint *agg, __global const real *res,
                              __global const real *cdw, __global real *b, __global real *t,
                              const uint kit, __global const kreal *st)
{
  if (kr_over(st, kit)) return;
  const uint c = get_global_id(0);
  if (c >= ncells) return;
  mg_restrict_cell(start, agg, res, cdw, b, t, c);
}

/* Fine level up: z = t + MG_OVER x1(agg) + dw (res − MG_OVER AP x1), row i. The cells of AP's
 * slots are those of level 1's stencil row of the row's cell (nb from offset 0; a row outside
 * the aggregates has no coupling): one table a cell, which the cell's rows share, rather than one
 * a row. */
real mg_up_row(__global const uint *agg, __global const mreal *AP, __global const uint *nb,
               __global const real *dw, __global const real *t, __global const real *res,
               __global const real *x1, const uint i)
{
  const uint g = agg[i];
  const real s =
      g != MG_NONE ? mg_stencil_dot_at(AP, (size_t)i * MG_W1, nb, (size_t)g * MG_W1, MG_W1, x1, 0u)
                   : R(0.0);
  const real u = t[i] + (g != MG_NONE ? MG_OVER * x1[g] : R(0.0));
  return u + dw[i] * (res[i] - MG_OVER * s);
}

__kernel void mg_up_csr(const uint n, __global const uint *agg, __global const mreal *AP,
                        __global const uint *nb, __global const real *dw, __global const real *t,
                        __global const real *res, __global const real *x1, __global real *z,
                        const uint kit, __global const kreal *st)
{
  if (kr_over(st, kit)) return;
  const uint i = get_global_id(0);
  if (i >= n) return;
  z[i] = mg_up_row(agg, AP, nb, dw, t, res, x1, i);
}

/* Coarse cell K (cells nc, vectors at co): its b (the sum of its children's res, which go to x
 * of level l at fo) and t. Level l: cells nf, W entries a row, stencil and tables at sf. */
void mg_down_cell(const int4 nf, const int W, const uint sf, const uint fo, const int4 nc,
                  const uint co, __global const mreal *S, __global const uint *nb,
                  __global const uchar *live, __global const real *dw, __global real *b,
                  __global real *t, __global real *x, const uint K)
{
  const int4 k = mg_coords(nc, K);
  real sum = R(0.0);
  for (int ch = 0; ch < MG_CHILDREN; ++ch) {
    const int4 I = 2 * k + (int4)(ch & 1, (ch >> 1) & 1, (ch >> 2) & 1, 0);
    if (I.x >= nf.x || I.y >= nf.y || I.z >= nf.z) continue;
    const uint id = mg_id(nf, I);
    const size_t r0 = sf + (size_t)id * W;
    const real res =
        b[fo + id] - ((live[fo + id] & MG_LIVE) ? mg_stencil_dot(S, nb, r0, W, t, fo) : R(0.0));
    x[fo + id] = res;
    sum += res;
  }
  b[co + K] = sum;
  t[co + K] = dw[co + K] * sum;
}

/* Cell I of level l (W entries a row, stencil and tables at so, vectors at vo; the coarser
 * level's at co) on the way up: x = t + MG_OVER x_c(par) + dw (res − MG_OVER Σ S x_c(pnb)),
 * res being x from the way down; a row whose dw is 0 (no diagonal: empty) skips the sum it would
 * multiply by 0 */
void mg_up_cell(const int W, const uint so, const uint vo, const uint co, __global const mreal *S,
                __global const uint *pnb, __global const uint *par, __global const real *dw,
                __global const real *t, __global real *x, const uint I)
{
  const size_t r0 = so + (size_t)I * W;
  const uint J = vo + I;
  const real d = dw[J];
  const real s = d != R(0.0) ? mg_stencil_dot(S, pnb, r0, W, x, co) : R(0.0);
  x[J] = t[J] + MG_OVER * x[co + par[J]] + d * (x[J] - MG_OVER * s);
}

/* One stencil level down, one coarse cell per work-item */
__kernel void mg_down(const int4 nf, const int W, const uint sf, const uint fo, const int4 nc,
                      const uint co, __global const mreal *S, __global const uint *nb,
                      __global const uchar *live, __global const real *dw, __global real *b,
                      __global real *t, __global real *x, const uint kit, __global const kreal *st)
{
  if (kr_over(st, kit)) return;
  const uint K = get_global_id(0);
  if (K >= (uint)nc.w) return;
  mg_down_cell(nf, W, sf, fo, nc, co, S, nb, live, dw, b, t, x, K);
}

/* One stencil level up, one cell per work-item */
__kernel void mg_up(const uint cells, const int W, const uint so, const uint vo, const uint co,
                    __global const mreal *S, __global const uint *pnb, __global const uint *par,
                    __global const real *dw, __global const real *t, __global real *x,
                    const uint kit, __global const kreal *st)
{
  if (kr_over(st, kit)) return;
  const uint I = get_global_id(0);
  if (I >= cells) return;
  mg_up_cell(W, so, vo, co, S, pnb, par, dw, t, x, I);
}

int4 mg_info_n(__global const int *info, const int l)
{
  return (int4)(info[MG_INFO * l], info[MG_INFO * l + 1], info[MG_INFO * l + 2],
                info[MG_INFO * l + 3]);
}

/* One step of the block, over the work-group's items (mg_block and the one-group solve of
 * krylov_group.cl, which put a barrier after each): level 1's b and t from the fine residual
 * (restrict), level l down to l + 1, the coarsest level L
 * by its dense inverse M (m x m, row-major), level l up. info: per level nx, ny, nz, cells, W,
 * stencil offset, vector offset. Each passes over its level's members only (list, nlist:
 * mg_weights): in the wedge dam break 1,600 of level 1's 14,500 cells. */
void mg_block_restrict(__global const int *info, __global const uint *list,
                       __global const uint *nlist, __global const uint *start,
                       __global const uint *agg, __global const real *res, __global const real *dw,
                       __global real *b, __global real *t)
{
  const uint lid = get_local_id(0), ls = get_local_size(0);
  const uint cnt = nlist[1], vo = (uint)info[MG_INFO + 6];
  for (uint k = lid; k < cnt; k += ls) mg_restrict_cell(start, agg, res, dw, b, t, list[vo + k]);
}

void mg_block_down(__global const int *info, const int l, __global const uint *list,
                   __global const uint *nlist, __global const mreal *S, __global const uint *nb,
                   __global const uchar *live, __global const real *dw, __global real *b,
                   __global real *t, __global real *x)
{
  const uint lid = get_local_id(0), ls = get_local_size(0);
  const int4 nf = mg_info_n(info, l), nc = mg_info_n(info, l + 1);
  const int W = info[MG_INFO * l + 4];
  const uint sf = (uint)info[MG_INFO * l + 5], fo = (uint)info[MG_INFO * l + 6];
  const uint co = (uint)info[MG_INFO * (l + 1) + 6], cnt = nlist[l + 1];
  for (uint k = lid; k < cnt; k += ls)
    mg_down_cell(nf, W, sf, fo, nc, co, S, nb, live, dw, b, t, x, list[co + k]);
}

void mg_block_coarsest(__global const int *info, const int L, const uint m, __global const real *M,
                       __global const real *b, __global real *x)
{
  const uint lid = get_local_id(0), ls = get_local_size(0);
  const uint cL = (uint)info[MG_INFO * L + 6];
  for (uint i = lid; i < m; i += ls) {
    real s = R(0.0);
    for (uint j = 0; j < m; ++j) s += M[(size_t)i * m + j] * b[cL + j];
    x[cL + i] = s;
  }
}

void mg_block_up(__global const int *info, const int l, __global const uint *list,
                 __global const uint *nlist, __global const mreal *S, __global const uint *pnb,
                 __global const uint *par, __global const real *dw, __global const real *t,
                 __global real *x)
{
  const uint lid = get_local_id(0), ls = get_local_size(0);
  const int W = info[MG_INFO * l + 4];
  const uint so = (uint)info[MG_INFO * l + 5], vo = (uint)info[MG_INFO * l + 6];
  const uint co = (uint)info[MG_INFO * (l + 1) + 6], cnt = nlist[l];
  for (uint k = lid; k < cnt; k += ls)
    mg_up_cell(W, so, vo, co, S, pnb, par, dw, t, x, list[vo + k]);
}

/* Levels l0 .. L in one work-group: (l0 = 1) level 1's b and t restricted from the fine res;
 * down to L; the coarsest; up to l0. Global memory between the steps is ordered by the
 * work-group's barriers. */
__kernel void mg_block(const int l0, const int L, __global const int *info, const uint m,
                       __global const real *M, __global const mreal *S, __global const uint *nb,
                       __global const uint *pnb, __global const uint *par,
                       __global const uchar *live, __global const real *dw, __global real *b,
                       __global real *t, __global real *x, __global const uint *start,
                       __global const uint *agg, __global const real *res,
                       __global const uint *list, __global const uint *nlist, const uint kit,
                       __global const kreal *st)
{
  if (kr_over(st, kit)) return;
  if (l0 == 1) {
    mg_block_restrict(info, list, nlist, start, agg, res, dw, b, t);
    barrier(CLK_GLOBAL_MEM_FENCE);
  }
  for (int l = l0; l < L; ++l) {
    mg_block_down(info, l, list, nlist, S, nb, live, dw, b, t, x);
    barrier(CLK_GLOBAL_MEM_FENCE);
  }
  mg_block_coarsest(info, L, m, M, b, x);
  barrier(CLK_GLOBAL_MEM_FENCE);
  for (int l = L - 1; l >= l0; --l) {
    mg_block_up(info, l, list, nlist, S, pnb, par, dw, t, x);
    barrier(CLK_GLOBAL_MEM_FENCE);
  }
}

/* The coarsest level's dense inverse M = A⁻¹ (m ≤ MG_COARSEST cells), in one work-group, in
 * kreal (double where the device has it; krylov.cl): A from the level's stencils (an empty cell
 * is an identity row scaled to the operator's largest entry, so that it neither sets nor fails
 * the test below; periodic axes wrap), then Gauss-Jordan with partial pivoting, a pivot under
 * 1e-5 of the largest entry counting as singular: the stencils are float in both builds, so an
 * exactly singular operator shows pivots of its float rounding (about 1e-7), which a double-only
 * bound (1e-12) had taken for regular and inverted, amplifying its null space. A singular
 * operator (pure Neumann, solved mean-free) is tried again with its diagonal scaled by 1 + 1e-6,
 * then by 1 + 1e-3: the preconditioner only has to be close to the inverse on the rest of the
 * space. One that stays singular (a zero diagonal: rows that only copy a neighbour's value) gets
 * Jacobi, and flag = 1 for the host's warning. work holds a, b and inv (m² each); at most
 * MG_COARSE_WG work-items. */
__kernel void mg_coarsest(const int4 nc, const int R, const int W, const uint so, const uint m,
                          __global const mreal *S, __global kreal *work, __global real *M,
                          __global uint *flag)
{
#pragma OPENCL FP_CONTRACT OFF /* no fused multiply-adds: the same sums as the host's old loop */
  __global kreal *a = work, *b = work + m * m, *inv = work + 2 * m * m;
  __local kreal big_l[MG_COARSE_WG];
  __local uint piv;
  __local int ok;
  const uint lid = get_local_id(0), L = get_local_size(0);
  const int w = 2 * R + 1;
  kreal big = KR(0.0);
  for (uint I = lid; I < m; I += L) {
    for (uint j = 0; j < m; ++j) a[I * m + j] = KR(0.0);
    const int4 c = mg_coords(nc, I);
    for (int o = 0; o < W; ++o) {
      const kreal v = (kreal)S[so + I * (uint)W + (uint)o];
      if (v == KR(0.0)) continue;
      int4 d = (int4)(o % w - R, (o / w) % w - R, W > w * w ? o / (w * w) - R : 0, 0);
      int4 t = c + d;
      int inside = 1;
      if (t.x < 0 || t.x >= nc.x) {
        if (!PERIODIC_X) inside = 0;
        t.x = ((t.x % nc.x) + nc.x) % nc.x;
      }
      if (t.y < 0 || t.y >= nc.y) {
        if (!PERIODIC_Y) inside = 0;
        t.y = ((t.y % nc.y) + nc.y) % nc.y;
      }
      if (t.z < 0 || t.z >= nc.z) {
        if (!PERIODIC_Z) inside = 0;
        t.z = ((t.z % nc.z) + nc.z) % nc.z;
      }
      if (!inside) continue;
      a[I * m + mg_id(nc, t)] += v;
    }
    for (uint j = 0; j < m; ++j) big = fmax(big, fabs(a[I * m + j]));
  }
  big_l[lid] = big;
  barrier(CLK_LOCAL_MEM_FENCE | CLK_GLOBAL_MEM_FENCE);
  big = KR(0.0);
  for (uint k = 0; k < L; ++k) big = fmax(big, big_l[k]);
  if (!(big > KR(0.0))) big = KR(1.0); /* no fluid at all: identity rows */
  for (uint I = lid; I < m; I += L) {  /* empty cells: identity rows on the operator's scale */
    int empty = 1;
    for (uint j = 0; j < m && empty; ++j) empty = a[I * m + j] == KR(0.0);
    if (empty) a[I * m + I] = big;
  }
  barrier(CLK_GLOBAL_MEM_FENCE);
  const kreal tol = KR(1e-5) * big;
  for (int attempt = 0; attempt < 3; ++attempt) {
    const kreal eps = attempt == 0 ? KR(0.0) : (attempt == 1 ? KR(1e-6) : KR(1e-3));
    for (uint I = lid; I < m; I += L)
      for (uint j = 0; j < m; ++j) {
        b[I * m + j] = a[I * m + j] * (I == j ? KR(1.0) + eps : KR(1.0));
        inv[I * m + j] = I == j ? KR(1.0) : KR(0.0);
      }
    if (lid == 0) ok = 1;
    barrier(CLK_LOCAL_MEM_FENCE | CLK_GLOBAL_MEM_FENCE);
    for (uint c = 0; c < m; ++c) {
      if (lid == 0) {
        uint p = c;
        for (uint i = c + 1; i < m; ++i)
          if (fabs(b[i * m + c]) > fabs(b[p * m + c])) p = i;
        piv = p;
        if (!(fabs(b[p * m + c]) > tol)) ok = 0;
      }
      barrier(CLK_LOCAL_MEM_FENCE | CLK_GLOBAL_MEM_FENCE);
      if (!ok) break;
      const uint p = piv;
      if (p != c)
        for (uint j = lid; j < m; j += L) {
          kreal t = b[c * m + j];
          b[c * m + j] = b[p * m + j];
          b[p * m + j] = t;
          t = inv[c * m + j];
          inv[c * m + j] = inv[p * m + j];
          inv[p * m + j] = t;
        }
      barrier(CLK_GLOBAL_MEM_FENCE);
      const kreal d = KR(1.0) / b[c * m + c];
      barrier(CLK_GLOBAL_MEM_FENCE);
      for (uint j = lid; j < m; j += L) {
        b[c * m + j] *= d;
        inv[c * m + j] *= d;
      }
      barrier(CLK_GLOBAL_MEM_FENCE);
      for (uint i = lid; i < m; i += L) {
        const kreal f = b[i * m + c];
        if (i == c || f == KR(0.0)) continue;
        for (uint j = 0; j < m; ++j) {
          b[i * m + j] -= f * b[c * m + j];
          inv[i * m + j] -= f * inv[c * m + j];
        }
      }
      barrier(CLK_GLOBAL_MEM_FENCE);
    }
    if (ok) break;
    barrier(CLK_LOCAL_MEM_FENCE); /* every item has read ok before the next attempt resets it */
  }
  for (uint I = lid; I < m; I += L)
    for (uint j = 0; j < m; ++j)
      M[I * m + j] =
          ok ? (real)inv[I * m + j]
             : (I == j && a[I * m + I] != KR(0.0) ? (real)(KR(1.0) / a[I * m + I]) : R(0.0));
  if (lid == 0) flag[0] = ok ? 0u : 1u;
}
