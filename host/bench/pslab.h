/* pslab.h: one rank's part of the manufactured pressure problem (pproblem.h) split into slabs of
 * rows (y), the split of README's "Beyond one device": each rank builds the particles of the rows
 * it owns and of the rows its rows reach (pproblem_reach_rows) on each side, computes their
 * operator rows on its device, and keeps the owned rows in dsolve's numbering (owned, then the
 * halo from the rank below, then from the rank above, each neighbour's in the order of the global
 * index, which is the order it sends them in). Every rank computes every other rank's rows from
 * (rows, ranks) alone, so no rank asks another what it holds. */
#ifndef CLSPH_PSLAB_H
#define CLSPH_PSLAB_H

#include "dsolve.h"
#include "pproblem.h"

struct pslab {
  struct pproblem pp; /* the owned rows and the halo rows, sorted by its grid */
  int rank, nranks;
  int row_lo, row_hi; /* owned rows */
  int reach;          /* halo rows each side */
  int nbr[DSOLVE_MAX_NBRS];
  struct dsolve_layout layout; /* points into the arrays below */
  size_t *row;                 /* owned rows, dsolve numbering */
  int *col;
  double *val;
  size_t nsend[DSOLVE_MAX_NBRS], nrecv[DSOLVE_MAX_NBRS];
  cl_uint *send;
  cl_uint *gid;    /* global index of each unknown, dsolve numbering */
  cl_mem d_b, d_x; /* right-hand side and solution, dsolve numbering */
  /* PSOLVE_MULTIGRID: the rank's own multigrid as the split solve's preconditioner (the local
   * problem's operator with the halo's rows made Dirichlet rows, its levels aggregating the rank's
   * cells only) */
  struct psolve ps;
  int multigrid;
  cl_kernel k_to_local, k_back;
  cl_mem d_map;    /* local (grid-sorted) index → dsolve index */
  cl_mem d_own_at; /* owned dsolve index → local index */
  cl_mem d_rl, d_zl;
  struct dsolve_precond pc;
};

/** @brief The rows [lo, hi) rank `rank` of `nranks` owns of `rows`, and a clear error when a slab
 *  would be thinner than `reach` rows (its halo would need more than its two neighbours). */
enum clsph_status pslab_rows(int rows, int nranks, int rank, int reach, int *lo, int *hi);
/** @brief Build rank `rank`'s part of the regular problem `spec` (spec's rows are set here), with
 *  the preconditioner `precond` (PSOLVE_JACOBI or PSOLVE_MULTIGRID). */
enum clsph_status pslab_create(const struct dev *dev, const struct pproblem_spec *spec, int rank,
                               int nranks, enum psolve_precond precond, struct pslab *out);
/** @brief The preconditioner dsolve_create takes: NULL for Jacobi (dsolve's own). */
const struct dsolve_precond *pslab_precond(const struct pslab *s);
/** @brief The owned values of x (dsolve numbering) to the host, in double. */
enum clsph_status pslab_read_owned(struct pslab *s, cl_mem x, double *out);
/** @brief Release. */
void pslab_destroy(struct pslab *s);

#endif /* CLSPH_PSLAB_H */
