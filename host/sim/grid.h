/* grid.h: the device cell-linked list (kernels/common/grid.cl): binning, counting sort by cell,
 * cell start table and the permutation that reorders every particle field. */
#ifndef CLSPH_GRID_H
#define CLSPH_GRID_H

#include <stddef.h>

#include "kern.h"
#include "prog.h"
#include "smoothing.h"

/** What the user asks for: a box, the support radius, periodic axes. */
struct grid_spec {
  int dim;         /* 2 or 3 */
  double lo[3];    /* lower corner, m */
  double hi[3];    /* upper corner, m (the period of a periodic axis is hi − lo) */
  double support;  /* support radius of the smoothing function, m */
  int periodic[3]; /* 1 for a periodic axis */
  int open_lo[3];  /* 1 for a side open to splashes (clamped, not reported; grid.cl) */
  int open_hi[3];
  int sub;             /* cells per support radius (0: GRID_SUB_DEFAULT) */
  struct smoothing sm; /* the function the neighbour kernels evaluate (its support may be less than
                          the search radius above, which can carry a skin) */
};

/** Cells per support radius: 2 visits 5 x 5 cells of side ≥ support/2 (about 100 candidates per
 *  particle in 2-D at h = 2δr) instead of 3 x 3 of side ≥ support (144); see grid.cl. */
#define GRID_SUB_DEFAULT 2

/** Device view of the grid, passed by value to every neighbour kernel (struct grid in grid.cl). */
struct grid_dev {
  real4 lo;             /* lower corner */
  real4 inv_cell;       /* 1 / cell side per axis */
  real4 len;            /* grid length per axis */
  struct smooth_dev sm; /* the smoothing function's constants */
  cl_int4 n;            /* cells per axis; .s[3] = total cells */
};
/* The kernels' struct grid lays out the same: sm (4 reals) sits on a real4 boundary. */
_Static_assert(offsetof(struct grid_dev, sm) == 3 * sizeof(real4) &&
                   offsetof(struct grid_dev, n) == 4 * sizeof(real4),
               "struct grid_dev must match struct grid in kernels/common/grid.cl");

/** Kernel sources every neighbour program starts with, in order. */
#define GRID_SOURCES "common/real.h", "common/flags.h", "common/smoothing.h", "common/grid.cl"

/** Items up to which grid_scan runs in one work-group and one launch (grid_scan_group in grid.cl)
 *  rather than three launches. */
#define GRID_SCAN_GROUP_MAX 16384
#define GRID_SCAN_GROUP_WG  64 /* GRID_SCAN_WG in grid.cl */

/** The kernels of the exclusive prefix sum (grid.cl): blocks, top and apply, or one group. */
struct grid_scan {
  cl_kernel blocks, top, apply, group;
};

struct grid {
  struct grid_spec spec;
  struct grid_dev geom;
  int n[3];      /* cells per axis */
  size_t ncells; /* total cells */
  size_t sorted; /* particles the last grid_sort binned (the start table's total) */
  size_t cap;    /* particles the per-particle buffers hold */
  cl_kernel k_bin, k_scatter, k_order, k_gather;
  struct grid_scan scan;
  cl_mem d_count; /* ncells + 1 counts (the last: particles that left, grid.cl) */
  cl_mem d_block; /* block sums of the scan */
  cl_mem d_start; /* ncells + 1: cell c holds sorted particles start[c] .. start[c+1] − 1 */
  cl_mem d_cell;  /* cell of each particle (unsorted order) */
  cl_mem d_rank;  /* rank of each particle in its cell (unsorted order) */
  cl_mem d_perm;  /* perm[new] = old */
  struct kern_timer t_bin, t_scan, t_scatter, t_order, t_gather; /* device time per stage */
};

/** @brief Add the -D switches of the grid (DIM, PERIODIC_X/Y/Z) to the build options. */
enum clsph_status grid_define(const struct grid_spec *spec, struct prog_opts *o);
/** @brief Check the spec, size the cells, create the kernels from `prog` (built with
 *  GRID_SOURCES and grid_define) and the buffers for `cap` particles. */
enum clsph_status grid_create(const struct dev *dev, cl_program prog, const struct grid_spec *spec,
                              size_t cap, struct grid *out);
/** @brief Bin the n particles at d_pos, sort them by cell: fills d_start and d_perm. Particles
 *  outside a non-periodic axis are clamped into the edge cell and raise CLSPH_FLAG_ESCAPED (but
 *  on an open side). With d_kind (may be NULL), particles of kind CLSPH_KIND_OUT sort after all
 *  the others (the extra cell ncells). */
enum clsph_status grid_sort(struct grid *g, const struct dev *dev, size_t n, cl_mem d_pos,
                            cl_mem d_kind, cl_mem d_flags);
/** @brief grid_sort, and with d_id (the particles' original indices before the reorder) in the
 *  same launch as the cells' ordering d_inv[id] = the index each particle takes in the reorder
 *  (the inverse of the reordered id field); d_id NULL: grid_sort alone. */
enum clsph_status grid_sort_inv(struct grid *g, const struct dev *dev, size_t n, cl_mem d_pos,
                                cl_mem d_kind, cl_mem d_flags, cl_mem d_id, cl_mem d_inv);
/** Fields one grid_gather launch reorders. */
#define GRID_GATHER_FIELDS 8
/** @brief dst[f][k] = src[f][perm[k]] for `count` <= GRID_GATHER_FIELDS fields, field f of
 *  words[f] 32-bit words per particle, in one launch. */
enum clsph_status grid_gather(struct grid *g, const struct dev *dev, size_t n, int count,
                              const size_t *words, const cl_mem *src, const cl_mem *dst);
/** @brief Create the scan's kernels from a program built with GRID_SOURCES. */
enum clsph_status grid_scan_create(cl_program prog, struct grid_scan *s);
/** @brief start = the exclusive prefix sum of the `items` counts (block: (items + 63) / 64 + 1
 *  words of scratch): one launch up to GRID_SCAN_GROUP_MAX items, else three. t may be NULL. */
enum clsph_status grid_scan_run(const struct grid_scan *s, const struct dev *dev, cl_uint items,
                                cl_mem count, cl_mem block, cl_mem start, struct kern_timer *t);
/** @brief Release the scan's kernels (safe on a zeroed struct). */
void grid_scan_destroy(struct grid_scan *s);
/** @brief Switch per-stage device timing on or off (and reset it). */
void grid_timing(struct grid *g, int on);
/** @brief Release kernels and buffers. Safe on a zeroed struct. */
void grid_destroy(struct grid *g);

#endif /* CLSPH_GRID_H */
