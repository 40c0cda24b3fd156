/* grid.c: host side of the device cell-linked list (the stages are described in grid.cl). */
#include "grid.h"

#include <math.h>
#include <string.h>

#define GRID_SCAN_BLOCK 64 /* same value as in grid.cl */

enum clsph_status grid_define(const struct grid_spec *spec, struct prog_opts *o)
{
  enum clsph_status st = CLSPH_OK;
  static const char *const names[] = {"PERIODIC_X", "PERIODIC_Y", "PERIODIC_Z"};
  CLSPH_TRY(prog_opts_define_int(o, "DIM", spec->dim));
  CLSPH_TRY(prog_opts_define_int(o, "GRID_SUB", spec->sub > 0 ? spec->sub : GRID_SUB_DEFAULT));
  int open = 0;
  for (int a = 0; a < spec->dim; ++a) {
    if (spec->periodic[a]) CLSPH_TRY(prog_opts_define_int(o, names[a], 1));
    if (!spec->periodic[a])
      open |= (spec->open_hi[a] ? 1 << a : 0) | (spec->open_lo[a] ? 16 << a : 0);
  }
  if (open) CLSPH_TRY(prog_opts_define_int(o, "GRID_OPEN", open));
done:
  return st;
}

static enum clsph_status size_cells(const struct grid_spec *spec, struct grid *g)
{
  enum clsph_status st = CLSPH_OK;
  static const char axis[] = "xyz";
  double total = 1.0;
  const int sub = spec->sub > 0 ? spec->sub : GRID_SUB_DEFAULT;
  CLSPH_CHECK(spec->dim == 2 || spec->dim == 3, CLSPH_E_INPUT,
              "grid: dimension must be 2 or 3, not %d", spec->dim);
  CLSPH_CHECK(spec->support > 0.0 && isfinite(spec->support), CLSPH_E_INPUT,
              "grid: the support radius must be positive, not %g", spec->support);
  CLSPH_CHECK(sub <= 4, CLSPH_E_INPUT, "grid: %d cells per support radius is too many (1 to 4)",
              sub);
  const double side_min = spec->support / sub;
  double lo[4] = {0}, inv[4] = {0}, len[4] = {0};
  cl_int n[4] = {1, 1, 1, 1};
  for (int a = 0; a < spec->dim; ++a) {
    double ext = spec->hi[a] - spec->lo[a];
    CLSPH_CHECK(ext > 0.0 && isfinite(ext), CLSPH_E_INPUT,
                "grid: the domain along %c is empty (lo %g, hi %g)", axis[a], spec->lo[a],
                spec->hi[a]);
    double cells = spec->periodic[a] ? floor(ext / side_min) : ceil(ext / side_min);
    if (cells < 1.0) cells = 1.0;
    /* every neighbour cell of a periodic axis must be a different cell: 2 sub + 1 of them */
    CLSPH_CHECK(!spec->periodic[a] || cells >= 2 * sub + 1, CLSPH_E_INPUT,
                "grid: periodic axis %c is %g long, which is less than %g support radii (%g); "
                "enlarge the domain or make the axis non-periodic",
                axis[a], ext, (2.0 * sub + 1.0) / sub, (2.0 * sub + 1.0) * side_min);
    CLSPH_CHECK(cells < 1e9, CLSPH_E_INPUT, "grid: too many cells along %c (%g)", axis[a], cells);
    double side = spec->periodic[a] ? ext / cells : side_min;
    lo[a] = spec->lo[a];
    inv[a] = 1.0 / side;
    len[a] = cells * side;
    n[a] = (cl_int)cells;
    total *= cells;
  }
  CLSPH_CHECK(total < 4e9 / 8, CLSPH_E_INPUT,
              "grid: %.3g cells is too many; the domain is too large for the support radius",
              total);
  memset(&g->geom, 0, sizeof g->geom);
  for (int a = 0; a < 4; ++a) {
    g->geom.lo.s[a] = (real)lo[a];
    g->geom.inv_cell.s[a] = (real)inv[a];
    g->geom.len.s[a] = (real)len[a];
    g->geom.n.s[a] = n[a];
  }
  g->geom.n.s[3] = (cl_int)total;
  CLSPH_CHECK(spec->sm.h > 0.0 && spec->sm.support <= spec->support, CLSPH_E_INPUT,
              "grid: the smoothing function (h = %g, support %g) is missing or reaches past the "
              "search radius %g",
              spec->sm.h, spec->sm.support, spec->support);
  g->geom.sm = smoothing_dev(&spec->sm);
  for (int a = 0; a < 3; ++a) g->n[a] = n[a];
  g->ncells = (size_t)total;
done:
  return st;
}

enum clsph_status grid_create(const struct dev *dev, cl_program prog, const struct grid_spec *spec,
                              size_t cap, struct grid *out)
{
  enum clsph_status st = CLSPH_OK;
  struct grid g;
  memset(&g, 0, sizeof g);
  g.spec = *spec;
  g.cap = cap;
  CLSPH_TRY(size_cells(spec, &g));
  CLSPH_TRY(prog_kernel(prog, "grid_bin", &g.k_bin));
  CLSPH_TRY(grid_scan_create(prog, &g.scan));
  CLSPH_TRY(prog_kernel(prog, "grid_scatter", &g.k_scatter));
  CLSPH_TRY(prog_kernel(prog, "grid_order_cells", &g.k_order));
  CLSPH_TRY(prog_kernel(prog, "grid_gather", &g.k_gather));
  size_t items = g.ncells + 1;
  size_t blocks = (items + GRID_SCAN_BLOCK - 1) / GRID_SCAN_BLOCK;
  CLSPH_TRY(kern_buffer(dev, items * sizeof(cl_uint), NULL, &g.d_count, "grid count"));
  CLSPH_TRY(kern_buffer(dev, items * sizeof(cl_uint), NULL, &g.d_start, "grid start"));
  CLSPH_TRY(kern_buffer(dev, blocks * sizeof(cl_uint), NULL, &g.d_block, "grid block sums"));
  CLSPH_TRY(kern_buffer(dev, cap * sizeof(cl_uint), NULL, &g.d_cell, "grid cell"));
  CLSPH_TRY(kern_buffer(dev, cap * sizeof(cl_uint), NULL, &g.d_rank, "grid rank"));
  CLSPH_TRY(kern_buffer(dev, cap * sizeof(cl_uint), NULL, &g.d_perm, "grid perm"));
  *out = g;
  memset(&g, 0, sizeof g);
done:
  grid_destroy(&g);
  return st;
}

enum clsph_status grid_sort(struct grid *g, const struct dev *dev, size_t n, cl_mem d_pos,
                            cl_mem d_kind, cl_mem d_flags)
{
  return grid_sort_inv(g, dev, n, d_pos, d_kind, d_flags, NULL, NULL);
}

enum clsph_status grid_sort_inv(struct grid *g, const struct dev *dev, size_t n, cl_mem d_pos,
                                cl_mem d_kind, cl_mem d_flags, cl_mem d_id, cl_mem d_inv)
{
  enum clsph_status st = CLSPH_OK;
  const cl_uint zero = 0;
  CLSPH_CHECK(n <= g->cap, CLSPH_E_INPUT, "grid: %zu particles exceed the capacity %zu", n, g->cap);
  cl_uint np = (cl_uint)n;
  cl_uint items = (cl_uint)(g->ncells + 1);
  cl_uint ncells = (cl_uint)g->ncells;
  cl_uint use_kind = d_kind != NULL;
  cl_mem kind = use_kind ? d_kind : d_pos; /* unread without kinds */

  /* bin: cell and rank of each particle */
  CLSPH_TRY(kern_fill(dev, g->d_count, &zero, sizeof zero, items * sizeof(cl_uint)));
  CLSPH_TRY(KERN_SET(g->k_bin, KARG(np), KARG(g->geom), KARG(d_pos), KARG(kind), KARG(use_kind),
                     KARG(g->d_cell), KARG(g->d_rank), KARG(g->d_count), KARG(d_flags)));
  CLSPH_TRY(kern_launch(dev, g->k_bin, n, &g->t_bin));
  /* exclusive scan of the counts into start */
  CLSPH_TRY(grid_scan_run(&g->scan, dev, items, g->d_count, g->d_block, g->d_start, &g->t_scan));
  /* permutation, made independent of the order of the atomics */
  CLSPH_TRY(KERN_SET(g->k_scatter, KARG(np), KARG(g->d_cell), KARG(g->d_rank), KARG(g->d_start),
                     KARG(g->d_perm)));
  CLSPH_TRY(kern_launch(dev, g->k_scatter, n, &g->t_scatter));
  /* each cell's slice (and the extra cell's) by old index, with the inverse of the ids */
  const cl_uint with_inv = d_id != NULL;
  cl_mem id = with_inv ? d_id : g->d_perm, inv = with_inv ? d_inv : g->d_perm; /* unread without */
  CLSPH_TRY(KERN_SET(g->k_order, KARG(ncells), KARG(np), KARG(g->d_start), KARG(g->d_perm),
                     KARG(with_inv), KARG(id), KARG(inv)));
  CLSPH_TRY(kern_launch(dev, g->k_order, g->ncells + 1, &g->t_order));
  g->sorted = n;
done:
  return st;
}

enum clsph_status grid_gather(struct grid *g, const struct dev *dev, size_t n, int count,
                              const size_t *words, const cl_mem *src, const cl_mem *dst)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_ASSERT(count > 0 && count <= GRID_GATHER_FIELDS);
  cl_uint np = (cl_uint)n;
  cl_uint8 w;
  memset(&w, 0, sizeof w);
  /* an unused slot copies 0 words; it still needs a valid buffer */
  cl_mem s[GRID_GATHER_FIELDS], d[GRID_GATHER_FIELDS];
  for (int f = 0; f < GRID_GATHER_FIELDS; ++f) {
    w.s[f] = f < count ? (cl_uint)words[f] : 0u;
    s[f] = f < count ? src[f] : g->d_perm;
    d[f] = f < count ? dst[f] : g->d_perm;
  }
  CLSPH_TRY(KERN_SET(g->k_gather, KARG(np), KARG(g->d_perm), KARG(w), KARG(s[0]), KARG(d[0]),
                     KARG(s[1]), KARG(d[1]), KARG(s[2]), KARG(d[2]), KARG(s[3]), KARG(d[3]),
                     KARG(s[4]), KARG(d[4]), KARG(s[5]), KARG(d[5]), KARG(s[6]), KARG(d[6]),
                     KARG(s[7]), KARG(d[7])));
  CLSPH_TRY(kern_launch(dev, g->k_gather, n, &g->t_gather));
done:
  return st;
}

enum clsph_status grid_scan_create(cl_program prog, struct grid_scan *s)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(prog_kernel(prog, "grid_scan_blocks", &s->blocks));
  CLSPH_TRY(prog_kernel(prog, "grid_scan_top", &s->top));
  CLSPH_TRY(prog_kernel(prog, "grid_scan_apply", &s->apply));
  CLSPH_TRY(prog_kernel(prog, "grid_scan_group", &s->group));
done:
  return st;
}

/* Up to GRID_SCAN_GROUP_MAX items one work-group scans them in one launch: on the 2-core CPU a
 * scan of the 40² cavity (its grid's cells and the stored operator's 1,761 rows) took 3.4 µs
 * against 1.9 + 1.4 + 4.2 µs in three launches (profiles one after the other) */
enum clsph_status grid_scan_run(const struct grid_scan *s, const struct dev *dev, cl_uint items,
                                cl_mem count, cl_mem block, cl_mem start, struct kern_timer *t)
{
  enum clsph_status st = CLSPH_OK;
  if (items <= GRID_SCAN_GROUP_MAX) {
    CLSPH_TRY(KERN_SET(s->group, KARG(items), KARG(count), KARG(start)));
    CLSPH_TRY(kern_launch_wg(dev, s->group, GRID_SCAN_GROUP_WG, GRID_SCAN_GROUP_WG, t));
    goto done;
  }
  cl_uint blocks = (items + GRID_SCAN_BLOCK - 1) / GRID_SCAN_BLOCK;
  CLSPH_TRY(KERN_SET(s->blocks, KARG(items), KARG(count), KARG(block)));
  CLSPH_TRY(kern_launch(dev, s->blocks, blocks, t));
  CLSPH_TRY(KERN_SET(s->top, KARG(blocks), KARG(block)));
  CLSPH_TRY(kern_launch_wg(dev, s->top, 1, 1, t));
  CLSPH_TRY(KERN_SET(s->apply, KARG(items), KARG(count), KARG(block), KARG(start)));
  CLSPH_TRY(kern_launch(dev, s->apply, blocks, t));
done:
  return st;
}

void grid_scan_destroy(struct grid_scan *s)
{
  cl_kernel *ks[] = {&s->blocks, &s->top, &s->apply, &s->group};
  for (size_t i = 0; i < sizeof ks / sizeof *ks; ++i) {
    if (*ks[i] != NULL) clReleaseKernel(*ks[i]);
    *ks[i] = NULL;
  }
}

void grid_timing(struct grid *g, int on)
{
  struct kern_timer t = {on, 0.0, 0};
  g->t_bin = g->t_scan = g->t_scatter = g->t_order = g->t_gather = t;
}

void grid_destroy(struct grid *g)
{
  cl_kernel *ks[] = {&g->k_bin, &g->k_scatter, &g->k_order, &g->k_gather};
  for (size_t i = 0; i < sizeof ks / sizeof *ks; ++i) {
    if (*ks[i] != NULL) clReleaseKernel(*ks[i]);
    *ks[i] = NULL;
  }
  grid_scan_destroy(&g->scan);
  kern_release(&g->d_count);
  kern_release(&g->d_start);
  kern_release(&g->d_block);
  kern_release(&g->d_cell);
  kern_release(&g->d_rank);
  kern_release(&g->d_perm);
}
