/* grid.cl: cell-linked list on the device, and the neighbour loop every operator uses.
 *
 * Cells have a side of at least support / GRID_SUB, so the neighbours of a particle lie within
 * GRID_SUB cells of its own along each axis. Building the list is a stable counting sort:
 *   grid_bin          cell of each particle, and its rank in the cell (atomic counter)
 *   grid_scan_*       exclusive prefix sum of the counts: start[c] .. start[c+1] is cell c
 *                     (grid_scan_group: in one launch, for few cells)
 *   grid_scatter      perm[new] = old
 *   grid_order_cells  sorts each cell's slice of perm by old index, so the result does not
 *                     depend on the order the atomics ran in (bit-for-bit reproducible runs), and
 *                     can write the inverse index of the particles' original ids
 *   grid_gather       applies perm to up to 8 fields at once (dst[new] = src[perm[new]])
 * Periodic axes (-D PERIODIC_X/Y/Z=1) wrap cells and shift the image: r_ij = r_i − (r_j + shift).
 * An open side (-D GRID_OPEN = bits: 1 << a the upper side of axis a, 16 << a the lower; the side
 * gravity points away from, host/sim/domain.c) clamps a particle beyond it into the last layer of
 * cells without reporting it: a splash may rise above the grid and fall back (the distances stay
 * true, so it has neighbours only where it really does).
 * A particle of kind CLSPH_KIND_OUT (a fluid particle that left the domain, kernels/common/
 * domain.cl) is binned to the extra cell ncells, after every real one: the sort moves it to the
 * end of the particle arrays, where the host drops it (host/sim/checks.c).
 * A periodic axis needs at least 2 GRID_SUB + 1 cells (the host checks), and positions on it must
 * lie in [lo, lo + len) (the time integration wraps them). */

struct grid {
  real4 lo;         /* lower corner of the cell grid; .w unused */
  real4 inv_cell;   /* 1 / cell side per axis; .w unused */
  real4 len;        /* grid length per axis (the period of a periodic axis); .w unused */
  struct smooth sm; /* the smoothing function's constants (smoothing.h): they ride with the grid */
  int4 n;           /* cells per axis (1 on unused axes); .w = total number of cells */
};

#ifndef GRID_OPEN
#define GRID_OPEN 0
#endif
#ifndef PERIODIC_X
#define PERIODIC_X 0
#endif
#ifndef PERIODIC_Y
#define PERIODIC_Y 0
#endif
#ifndef PERIODIC_Z
#define PERIODIC_Z 0
#endif

#if DIM == 2
#define REALV_X(v) (v).x
#define REALV_Y(v) (v).y
#define REALV_Z(v) R(0.0)
#else
#define REALV_X(v) (v).x
#define REALV_Y(v) (v).y
#define REALV_Z(v) (v).z
#endif

/* Cell coordinate along one axis: wrapped when periodic, clamped otherwise (and reported, but on
 * an open side: open bit 1 the upper, 2 the lower). */
int grid_axis(real x, real lo, real inv_cell, int n, int periodic, int open, int *escaped)
{
  const real u = (x - lo) * inv_cell;
  int c;
  if (isnan(u)) { /* a non-finite position (whose kernel has raised CLSPH_FLAG_NAN): a cell in
                   * the grid, as (int) NaN is none (a sort may run before the flags are read) */
    *escaped = 1;
    return 0;
  }
  if (periodic) {
    c = (int)floor(u);
    c %= n;
    if (c < 0) c += n;
  } else if (u < R(0.0)) {
    if (!(open & 2)) *escaped = 1;
    c = 0;
  } else if (u >= (real)n) {
    if (!(open & 1)) *escaped = 1;
    c = n - 1;
  } else {
    c = min((int)u, n - 1);
  }
  return c;
}

int4 grid_coords(const struct grid *g, realv x, int *escaped)
{
  int4 c = (int4)(0, 0, 0, 0);
  c.x = grid_axis(REALV_X(x), g->lo.x, g->inv_cell.x, g->n.x, PERIODIC_X,
                  (GRID_OPEN & 1) | ((GRID_OPEN >> 3) & 2), escaped);
  c.y = grid_axis(REALV_Y(x), g->lo.y, g->inv_cell.y, g->n.y, PERIODIC_Y,
                  ((GRID_OPEN >> 1) & 1) | ((GRID_OPEN >> 4) & 2), escaped);
#if DIM == 3
  c.z = grid_axis(REALV_Z(x), g->lo.z, g->inv_cell.z, g->n.z, PERIODIC_Z,
                  ((GRID_OPEN >> 2) & 1) | ((GRID_OPEN >> 5) & 2), escaped);
#endif
  return c;
}

int grid_cell_id(const struct grid *g, int4 c)
{
  return c.x + g->n.x * (c.y + g->n.y * c.z);
}

/* One neighbour cell coordinate: wraps a periodic axis (shift = image offset of the neighbour),
 * returns 0 when the cell is outside a non-periodic axis. */
int grid_wrap_axis(int *c, int n, int periodic, real len, real *shift)
{
  *shift = R(0.0);
  if (*c >= 0 && *c < n) return 1;
  if (!periodic) return 0;
  if (*c < 0) {
    *c += n;
    *shift = -len;
  } else {
    *c -= n;
    *shift = len;
  }
  return 1;
}

/* ---- the neighbour loop ----
 *   struct neigh_iter it;
 *   NEIGH_FOR(it, g, cell_start, x_i, j) {
 *     realv r_ij = x_i - (pos[j] + it.shift);
 *     ...
 *   }
 * It visits every particle j (i itself included) in the cells within GRID_SUB cells of i's cell
 * (cells have a side of at least support / GRID_SUB); callers test the distance against
 * the support radius. Particles are sorted by cell and cells are numbered x fastest, so the
 * 2 GRID_SUB + 1 cells of a row along x are one contiguous range of particles: the loop runs over
 * rows (strips), not cells. A row that wraps around a periodic x boundary is two ranges with
 * different image shifts. NEIGH_FOR is two nested loops, the inner one a plain counted loop over
 * a range (neigh_range finds the next non-empty one), which the compiler turns into the same code
 * as a native loop; `continue` goes to the next j, and `break` would leave only the range (use
 * neigh_next for a loop that stops early: while (neigh_next(&it, &g, cell_start, &j))). */
#ifndef GRID_SUB
#define GRID_SUB 2
#endif
#define GRID_SPAN (2 * GRID_SUB + 1)
#if DIM == 2
#define NEIGH_ROWS GRID_SPAN
#else
#define NEIGH_ROWS (GRID_SPAN * GRID_SPAN)
#endif

struct neigh_iter {
  int4 home;   /* cell of particle i */
  int row;     /* row being visited, 0 .. NEIGH_ROWS − 1 */
  uint j, end; /* next particle and end of the current range */
  realv shift; /* periodic image offset of the current range */
  uint wrap_j; /* second range of a wrapping row: start, end (wrap_j == wrap_end: none) */
  uint wrap_end;
  realv wrap_shift; /* and its shift */
};

/* A position moved back into [lo, lo + len) along the periodic axes (the time integration's wrap,
 * which the neighbour loop needs); unchanged along the others. */
real grid_wrap_coord(real x, real lo, real len)
{
  real t = x - lo;
  t -= len * floor(t / len);
  if (t >= len) t -= len; /* round-off of the line above */
  return lo + t;
}

realv grid_wrap(const struct grid *g, realv x)
{
#if PERIODIC_X
  x.x = grid_wrap_coord(x.x, g->lo.x, g->len.x);
#endif
#if PERIODIC_Y
  x.y = grid_wrap_coord(x.y, g->lo.y, g->len.y);
#endif
#if PERIODIC_Z && DIM == 3
  x.z = grid_wrap_coord(x.z, g->lo.z, g->len.z);
#endif
  return x;
}

void neigh_begin(struct neigh_iter *it, const struct grid *g, realv x)
{
  int escaped = 0;
  it->home = grid_coords(g, x, &escaped);
  it->row = -1;
  it->j = it->end = 0;
  it->wrap_j = it->wrap_end = 0;
  it->shift = it->wrap_shift = (realv)(R(0.0));
}

int neigh_range(struct neigh_iter *it, const struct grid *g, __global const uint *cell_start)
{
  it->j = it->end; /* the current range is done */
  do {
    if (it->wrap_j < it->wrap_end) { /* the other half of a wrapping row */
      it->j = it->wrap_j;
      it->end = it->wrap_end;
      it->shift = it->wrap_shift;
      it->wrap_j = it->wrap_end;
      continue;
    }
    if (++it->row >= NEIGH_ROWS) return 0;
    int cy = it->home.y + it->row % GRID_SPAN - GRID_SUB;
    int cz = 0;
    real sy, sz = R(0.0);
    if (!grid_wrap_axis(&cy, g->n.y, PERIODIC_Y, g->len.y, &sy)) continue;
#if DIM == 3
    cz = it->home.z + it->row / GRID_SPAN - GRID_SUB;
    if (!grid_wrap_axis(&cz, g->n.z, PERIODIC_Z, g->len.z, &sz)) continue;
#endif
    const int base = g->n.x * (cy + g->n.y * cz); /* cell id of x = 0 in this row */
    int x0 = it->home.x - GRID_SUB, x1 = it->home.x + GRID_SUB;
#if DIM == 2
    it->shift = (realv)(R(0.0), sy);
#else
    it->shift = (realv)(R(0.0), sy, sz, R(0.0));
#endif
#if PERIODIC_X
    if (x0 < 0 || x1 >= g->n.x) { /* wraps: [0, x1 mod n] and [x0 mod n, n − 1] */
      const real sx = x0 < 0 ? -g->len.x : g->len.x;
      const int lo = x0 < 0 ? x0 + g->n.x : 0, hi = x0 < 0 ? g->n.x - 1 : x1 - g->n.x;
      it->wrap_j = cell_start[base + lo];
      it->wrap_end = cell_start[base + hi + 1];
      it->wrap_shift = it->shift;
      if (x0 < 0) { /* the wrapped cells are images at the far end */
        it->wrap_shift.x = sx;
        x0 = 0;
      } else {
        it->wrap_shift.x = sx;
        x1 = g->n.x - 1;
      }
    }
#else
    x0 = max(x0, 0);
    x1 = min(x1, g->n.x - 1);
#endif
    it->j = cell_start[base + x0];
    it->end = cell_start[base + x1 + 1];
  } while (it->j >= it->end);
  return 1;
}

int neigh_next(struct neigh_iter *it, const struct grid *g, __global const uint *cell_start,
               uint *j)
{
  if (it->j >= it->end && !neigh_range(it, g, cell_start)) return 0;
  *j = it->j++;
  return 1;
}

#define NEIGH_FOR(IT, G, CS, X, J)                                                                 \
  for (neigh_begin(&(IT), &(G), (X)); neigh_range(&(IT), &(G), (CS));)                             \
    for (uint J = (IT).j; J < (IT).end; ++J)

/* ---- candidates in lanes ----
 * NEIGH_FOR_LANES(it, g, cell_start, x, b) { ... } visits the ranges of NEIGH_FOR NEIGH_W
 * particles at a time (4 or 8 in double, 8 in float: real.h), b .. b + NEIGH_W − 1, as one vector
 * of lanes (realw: SIMD on a CPU, where the one-at-a-time loop's branch on the distance is taken at
 * random for about half the candidates). The lanes that belong to the range and were not visited
 * before are neigh_live(&it, b); the last pass of a range starts at its end − NEIGH_W, so that
 * every load is one vector load of particles that exist (a particle set holds at least NEIGH_W:
 * PSET_MIN_CAP). A dead lane reads some other particle: its weight must be selected away
 * (lanes_keep), and what the weight multiplies must be finite for every particle. Sums in lanes
 * are added at the end in a fixed order (lanes_sum), not that of NEIGH_FOR. */
uint neigh_lane_base(const struct neigh_iter *it)
{
  return it->end >= (uint)NEIGH_W ? min(it->j, it->end - (uint)NEIGH_W) : 0u;
}

maskw neigh_live(const struct neigh_iter *it, const uint b)
{
  const uintw k = (uintw)(b) + LANES_IOTA;
  return LANES_MASK(k >= (uintw)(it->j) && k < (uintw)(it->end));
}

/* lanes k ≠ i: the particle itself left out */
maskw neigh_other(const uint b, const uint i)
{
  return LANES_MASK((uintw)(b) + LANES_IOTA != (uintw)(i));
}

#define NEIGH_FOR_LANES(IT, G, CS, X, B)                                                           \
  for (neigh_begin(&(IT), &(G), (X)); neigh_range(&(IT), &(G), (CS));)                             \
    for (uint B; (IT).j < (IT).end && ((B) = neigh_lane_base(&(IT)), 1); (IT).j += NEIGH_W)

/* NEIGH_W vectors, one lane each. */
struct lanesv {
  realw x, y;
#if DIM == 3
  realw z;
#endif
};

realw lanes_load(__global const real *a, const uint b)
{
  return LANES_VLOAD(0, a + b);
}

uintw lanes_load_u(__global const uint *a, const uint b)
{
  return LANES_VLOAD(0, a + b);
}

struct lanesv lanes_load_v(__global const realv *a, const uint b)
{
  struct lanesv v;
  __global const real *f = (__global const real *)(a + b);
#if DIM == 2 && NEIGH_W == 4
  const real8 q = vload8(0, f);
  v.x = q.even;
  v.y = q.odd;
#elif DIM == 2
  const real16 q = vload16(0, f);
  v.x = q.even;
  v.y = q.odd;
#elif NEIGH_W == 4
  const real8 q0 = vload8(0, f), q1 = vload8(1, f); /* x y z w of four particles */
  v.x = (realw)(q0.s04, q1.s04);
  v.y = (realw)(q0.s15, q1.s15);
  v.z = (realw)(q0.s26, q1.s26);
#else
  const real16 q0 = vload16(0, f), q1 = vload16(1, f); /* x y z w of eight particles */
  v.x = (realw)(q0.s048c, q1.s048c);
  v.y = (realw)(q0.s159d, q1.s159d);
  v.z = (realw)(q0.s26ae, q1.s26ae);
#endif
  return v;
}

/* x − (p + shift), lane by lane */
struct lanesv lanes_rel(const realv x, const struct lanesv p, const realv shift)
{
  struct lanesv r;
  r.x = x.x - (p.x + shift.x);
  r.y = x.y - (p.y + shift.y);
#if DIM == 3
  r.z = x.z - (p.z + shift.z);
#endif
  return r;
}

/* a − b with a the same vector in every lane */
struct lanesv lanes_sub_from(const realv a, const struct lanesv b)
{
  return lanes_rel(a, b, (realv)(R(0.0)));
}

realw lanes_dot(const struct lanesv a, const struct lanesv b)
{
  realw d = a.x * b.x + a.y * b.y;
#if DIM == 3
  d += a.z * b.z;
#endif
  return d;
}

/* a · v with v the same vector in every lane */
realw lanes_dot1(const struct lanesv a, const realv v)
{
  realw d = a.x * v.x + a.y * v.y;
#if DIM == 3
  d += a.z * v.z;
#endif
  return d;
}

realw lanes_keep(const realw v, const maskw live)
{
  return select((realw)(R(0.0)), v, live);
}

/* the lanes' sum: (s0 + s1) + (s2 + s3), the halves added first in float */
real lanes_sum(const realw s)
{
#if NEIGH_W == 8
  const real4 t = s.lo + s.hi;
#else
  const real4 t = s;
#endif
  return (t.x + t.y) + (t.z + t.w);
}

/* the smallest lane */
real lanes_min(const realw s)
{
#if NEIGH_W == 8
  const real4 t = fmin(s.lo, s.hi);
#else
  const real4 t = s;
#endif
  return fmin(fmin(t.x, t.y), fmin(t.z, t.w));
}

/* the lanes set in m */
uint lanes_count(const maskw m)
{
  const intw c = -LANES_INT(m);
#if NEIGH_W == 8
  const int4 t = c.lo + c.hi;
#else
  const int4 t = c;
#endif
  return (uint)((t.x + t.y) + (t.z + t.w));
}

struct lanesv lanes_zero_v(void)
{
  struct lanesv z;
  z.x = z.y = (realw)(R(0.0));
#if DIM == 3
  z.z = z.x;
#endif
  return z;
}

/* acc += w a, lane by lane (a vector sum kept in lanes: lanes_total_v at the end) */
void lanes_acc_v(struct lanesv *acc, const realw w, const struct lanesv a)
{
  acc->x += w * a.x;
  acc->y += w * a.y;
#if DIM == 3
  acc->z += w * a.z;
#endif
}

realv lanes_total_v(const struct lanesv acc)
{
  realv s = (realv)(R(0.0));
  s.x = lanes_sum(acc.x);
  s.y = lanes_sum(acc.y);
#if DIM == 3
  s.z = lanes_sum(acc.z);
#endif
  return s;
}

/* ---- building the list ---- */

/* kind: the particles' kinds where use_kind (the fluid's grid), else unread */
__kernel void grid_bin(const uint n, const struct grid g, __global const realv *pos,
                       __global const uint *kind, const uint use_kind, __global uint *cell,
                       __global uint *rank, __global uint *count, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  int escaped = 0;
  int id = grid_cell_id(&g, grid_coords(&g, pos[i], &escaped));
  if (use_kind && kind[i] == CLSPH_KIND_OUT) {
    id = g.n.w; /* the extra cell: sorted last, then dropped */
    escaped = 0;
  }
  if (escaped) flags_raise(flags, CLSPH_FLAG_ESCAPED);
  cell[i] = (uint)id;
  rank[i] = atomic_inc(&count[id]);
}

/* Exclusive scan in three launches: block sums, a scan of the block sums, block rescans. */
#define GRID_SCAN_BLOCK 64

__kernel void grid_scan_blocks(const uint n, __global const uint *count, __global uint *block_sum)
{
  const uint b = get_global_id(0);
  const uint first = b * GRID_SCAN_BLOCK;
  if (first >= n) return;
  const uint last = min(n, first + GRID_SCAN_BLOCK);
  uint s = 0;
  for (uint k = first; k < last; ++k) s += count[k];
  block_sum[b] = s;
}

__kernel void grid_scan_top(const uint nblocks, __global uint *block_sum)
{
  if (get_global_id(0) != 0) return;
  uint s = 0;
  for (uint b = 0; b < nblocks; ++b) {
    uint v = block_sum[b];
    block_sum[b] = s;
    s += v;
  }
}

__kernel void grid_scan_apply(const uint n, __global const uint *count,
                              __global const uint *block_sum, __global uint *start)
{
  const uint b = get_global_id(0);
  const uint first = b * GRID_SCAN_BLOCK;
  if (first >= n) return;
  const uint last = min(n, first + GRID_SCAN_BLOCK);
  uint s = block_sum[b];
  for (uint k = first; k < last; ++k) {
    start[k] = s;
    s += count[k];
  }
}

/* The same scan in one launch, for at most GRID_SCAN_GROUP_MAX items (grid.h): one work-group of
 * GRID_SCAN_WG items, each summing a contiguous slice, its first item scanning the slices' sums,
 * each then writing its slice (where grid_scan_blocks, _top and _apply take three launches) */
#define GRID_SCAN_WG 64
__kernel void grid_scan_group(const uint n, __global const uint *count, __global uint *start)
{
  __local uint part[GRID_SCAN_WG];
  const uint l = get_local_id(0), per = (n + GRID_SCAN_WG - 1) / GRID_SCAN_WG;
  const uint first = min(n, l * per), last = min(n, first + per);
  uint s = 0;
  for (uint k = first; k < last; ++k) s += count[k];
  part[l] = s;
  barrier(CLK_LOCAL_MEM_FENCE);
  if (l == 0) {
    uint a = 0;
    for (uint w = 0; w < GRID_SCAN_WG; ++w) {
      const uint v = part[w];
      part[w] = a;
      a += v;
    }
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  s = part[l];
  for (uint k = first; k < last; ++k) {
    start[k] = s;
    s += count[k];
  }
}

__kernel void grid_scatter(const uint n, __global const uint *cell, __global const uint *rank,
                           __global const uint *start, __global uint *perm)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  perm[start[cell[i]] + rank[i]] = i;
}

__kernel void grid_order_cells(const uint ncells, const uint n, __global const uint *start,
                               __global uint *perm, const uint with_inv, __global const uint *id,
                               __global uint *inv)
{
  const uint c = get_global_id(0);
  if (c > ncells) return;
  /* the extra cell ncells holds the particles that left (CLSPH_KIND_OUT) up to n */
  const uint first = start[c], last = c < ncells ? start[c + 1] : n;
  for (uint a = first + 1; a < last; ++a) { /* insertion sort: cells hold a few particles */
    uint v = perm[a];
    uint b = a;
    while (b > first && perm[b - 1] > v) {
      perm[b] = perm[b - 1];
      --b;
    }
    perm[b] = v;
  }
  if (with_inv) /* inv[id[k]] = k of the reordered ids, read from the ids before the reorder */
    for (uint a = first; a < last; ++a) inv[id[perm[a]]] = a;
}

/* Reorder up to GRID_GATHER_FIELDS fields in one launch, field f of words.sf 32-bit words per
 * particle: df[i] = sf[perm[i]]; a slot with 0 words is unused. */
/* The common widths (a real, a realv in float or double) as one vector copy: the loop over a
 * width known only at run time copied a word at a time (on the wedge dam break, PoCL: 67 µs a
 * launch). */
#define GRID_GATHER_ONE(w, s, d)                                                                   \
  if ((w) == 4u)                                                                                   \
    vstore4(vload4(k, s), i, d);                                                                   \
  else if ((w) == 2u)                                                                              \
    vstore2(vload2(k, s), i, d);                                                                   \
  else if ((w) == 1u)                                                                              \
    (d)[i] = (s)[k];                                                                               \
  else                                                                                             \
    for (uint c = 0; c < (w); ++c) (d)[i * (w) + c] = (s)[k * (w) + c]

__kernel void grid_gather(const uint n, __global const uint *perm, const uint8 words,
                          __global const uint *s0, __global uint *d0, __global const uint *s1,
                          __global uint *d1, __global const uint *s2, __global uint *d2,
                          __global const uint *s3, __global uint *d3, __global const uint *s4,
                          __global uint *d4, __global const uint *s5, __global uint *d5,
                          __global const uint *s6, __global uint *d6, __global const uint *s7,
                          __global uint *d7)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const uint k = perm[i];
  GRID_GATHER_ONE(words.s0, s0, d0);
  GRID_GATHER_ONE(words.s1, s1, d1);
  GRID_GATHER_ONE(words.s2, s2, d2);
  GRID_GATHER_ONE(words.s3, s3, d3);
  GRID_GATHER_ONE(words.s4, s4, d4);
  GRID_GATHER_ONE(words.s5, s5, d5);
  GRID_GATHER_ONE(words.s6, s6, d6);
  GRID_GATHER_ONE(words.s7, s7, d7);
}
