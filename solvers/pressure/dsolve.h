/* dsolve.h: the pressure solve split across ranks (README, "Beyond one device"): BiCGStab with the
 * Jacobi preconditioner (van der Vorst 1992, right-preconditioned as psolve.c), each rank holding
 * the rows of the particles it owns and a halo of its neighbours' unknowns that those rows reach.
 * Per iteration: two halo exchanges (the preconditioned vectors before each product) and three
 * global sums (σ = (r0, v); (t, s) with (t, t); (r, r) with (r0, r)). How values travel between
 * ranks is the caller's (struct dsolve_comm): MPI in clsph-ranks, nothing for one rank; the solver
 * itself depends on no MPI. Jacobi is the same on every split, so a split solve takes the
 * iterations of the whole one within the rounding of its sums' order. */
#ifndef CLSPH_DSOLVE_H
#define CLSPH_DSOLVE_H

#include "kern.h"

/** How the ranks talk (one rank: sum does nothing, there are no neighbours). */
struct dsolve_comm {
  void *ctx;
  /** Sum n doubles over the ranks, in place. */
  enum clsph_status (*sum)(void *ctx, double *v, int n);
  /** Send nsend[k] reals from send (neighbour after neighbour) to neighbour k and receive
   *  nrecv[k] from it into recv (in the same order). */
  enum clsph_status (*exchange)(void *ctx, const real *send, const size_t *nsend, real *recv,
                                const size_t *nrecv);
};

/** A preconditioner of the owned rows other than Jacobi (NULL apply: Jacobi): z = M⁻¹ r, both in
 *  the layout's numbering, reading r's owned values and writing z's (pslab.c: one V-cycle of the
 *  multigrid of the rank's own rows, its halo's rows Dirichlet rows). */
struct dsolve_precond {
  void *ctx;
  enum clsph_status (*apply)(void *ctx, cl_mem r, cl_mem z);
};

/** DSOLVE_MAX_NBRS neighbours at most (slabs: the one below and the one above). */
#define DSOLVE_MAX_NBRS 2

/** A rank's part of the system, in its own numbering: owned rows [0, nown), halo [nown, n), the
 *  halo grouped by neighbour in the order the neighbour sends it. */
struct dsolve_layout {
  size_t nown, n;
  const size_t *row; /* nown + 1 row starts */
  const int *col;    /* columns in [0, n) */
  const double *val;
  int nbrs;            /* neighbours */
  const size_t *nsend; /* owned values each neighbour's halo holds */
  const cl_uint *send; /* their rows, neighbour after neighbour (sum of nsend) */
  const size_t *nrecv; /* halo values from each neighbour, stored from nown on in that order */
};

/** What a solve cost, besides its iterations. */
struct dsolve_stats {
  double seconds;               /* the solve, s */
  double exchange_seconds;      /* in halo exchanges (pack, read, send and receive, write), s: the
                                 * device's work queued before the read is waited for here too */
  double sum_seconds;           /* in global sums (partials read, added, summed over the ranks), s:
                                 * likewise */
  double exchange_comm_seconds; /* of exchange_seconds, in comm.exchange (sending, receiving and
                                 * waiting for the neighbours), s */
  double sum_comm_seconds;      /* of sum_seconds, in comm.sum, s */
  long exchanges, sums;         /* how many */
  double bytes_sent;            /* halo values sent by this rank, bytes */
};

/** The iteration. DSOLVE_ONE_SUM: BiCGStab on A D⁻¹ rearranged so that every inner product of an
 *  iteration comes from one reduction (after Yang & Brent 2002, "improved BiCGStab"): the products
 *  q = B r and y = B v, v = B p by recurrence, and the scalars from 12 inner products, one global
 *  sum an iteration instead of three; the residual's norm in that sum is the one the iteration
 *  started with, so convergence is seen one iteration late (its two products spent for nothing). */
enum dsolve_variant { DSOLVE_BICGSTAB = 0, DSOLVE_ONE_SUM };

struct dsolve_result {
  int converged;
  int its;
  double rnorm;      /* ||r|| / ||b|| of the iteration's residual, over every rank */
  double rnorm_true; /* ||b − A x|| / ||b|| recomputed at the end (DSOLVE_ONE_SUM, whose v is a
                      * recurrence; the other: rnorm) */
  int restarts;      /* breakdown restarts */
  struct dsolve_stats stats;
};

struct dsolve {
  const struct dev *dev;
  struct dsolve_comm comm;
  struct dsolve_precond pc;
  size_t nown, n, nsend_total, nrecv_total;
  int nbrs;
  size_t nsend[DSOLVE_MAX_NBRS], nrecv[DSOLVE_MAX_NBRS];
  size_t groups;
  cl_kernel k_spmv, k_residual, k_dot2, k_p, k_s, k_x, k_gather, k_pv, k_xr, k_scale, k_dots;
  cl_mem d_row, d_col, d_val, d_dinv, d_send_idx, d_sendbuf;
  cl_mem d_r, d_r0, d_p, d_v, d_s, d_t, d_ph, d_sh, d_partial;
  real *h_send, *h_recv, *h_partial;
};

/** @brief Kernels (program with DSOLVE_SOURCES after PSOLVE_SOURCES) and the stored rows; pc NULL
 *  or with a NULL apply: Jacobi (DSOLVE_ONE_SUM takes Jacobi only). */
enum clsph_status dsolve_create(const struct dev *dev, cl_program prog,
                                const struct dsolve_layout *l, const struct dsolve_comm *comm,
                                const struct dsolve_precond *pc, struct dsolve *out);
/** @brief Solve A x = b to ||b − A x|| <= rtol ||b|| (b and x: n reals in the layout's numbering,
 *  x the initial guess; b's halo is not read, x's is overwritten). Collective: every rank calls
 *  it. A solve that reaches max_it is reported (converged 0), not an error. */
enum clsph_status dsolve_solve(struct dsolve *ds, cl_mem b, cl_mem x, double rtol, int max_it,
                               enum dsolve_variant variant, struct dsolve_result *res);
/** @brief Release. */
void dsolve_destroy(struct dsolve *ds);

#define DSOLVE_SOURCES "common/dsolve.cl"

#endif /* CLSPH_DSOLVE_H */
