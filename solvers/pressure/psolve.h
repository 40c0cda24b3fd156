/* psolve.h: the pressure solve, on the device. A scheme supplies its operator (struct psolve_op);
 * the solver is a matrix-free preconditioned BiCGStab (van der Vorst 1992) whose operator is a
 * kernel launch over neighbours, either recomputing the kernel terms at every application or
 * applying coefficients stored once per step in a CSR layout; dot products are device reductions
 * whose scalars stay on the device, and one small state vector comes back per batch of
 * iterations. UMFPACK (SuiteSparse) on the same
 * operator, assembled on the host, is the reference and the "direct" solver of small scenes. */
#ifndef CLSPH_PSOLVE_H
#define CLSPH_PSOLVE_H

#include "grid.h"
#include "kern.h"
#include "mg.h"
#include "prog.h"

/** The operator of a linear system A x = b over the particles, supplied by a scheme. */
struct psolve_op {
  void *ctx;
  size_t n; /* unknowns */
  /** The left null vector w of a singular operator (wᵀ A = 0), or NULL for the ones: PSOLVE_MEAN
   *  makes the right-hand side consistent (Σ w b = 0) and the solution's w-weighted mean zero. */
  cl_mem weight;
  /** y = A x, recomputing the kernel terms. */
  enum clsph_status (*apply)(void *ctx, cl_mem x, cl_mem y);
  /** d = diag(A). */
  enum clsph_status (*diagonal)(void *ctx, cl_mem d);
  /** count[i] = entries of row i (the diagonal first, then the neighbours; csr.cl). */
  enum clsph_status (*row_counts)(void *ctx, cl_mem count);
  /** Write the entries of every row at row[i] .. row[i+1] − 1 (column, value). */
  enum clsph_status (*coefficients)(void *ctx, cl_mem row, cl_mem col, cl_mem val);
  /** The grid whose cell order the unknowns follow (unknown i is the i-th particle it sorted),
   *  or NULL: the multigrid preconditioner aggregates its cells. */
  const struct grid *grid;
};

enum psolve_method { PSOLVE_BICGSTAB = 0, PSOLVE_DIRECT };
enum psolve_apply { PSOLVE_STORED = 0, PSOLVE_RECOMPUTE };
enum psolve_precond { PSOLVE_JACOBI = 0, PSOLVE_NONE, PSOLVE_JACOBI_SWEEPS, PSOLVE_MULTIGRID };
enum psolve_singular {
  PSOLVE_REGULAR = 0, /* the system has a unique solution (Dirichlet rows somewhere) */
  PSOLVE_REINFORCE,   /* A + ε diag(A): Leroy et al. 2014 sec 3.3, "a slight reinforcement" */
  PSOLVE_MEAN,        /* consistent singular system: mean-free right-hand side and solution */
  PSOLVE_PROJECT      /* both: the right-hand side made consistent (mean-free), A + ε diag A
                       * solved, the solution mean-free (robust in float, where BiCGStab on the
                       * singular operator itself can diverge) */
};
/** The options' system is solved with A + ε diag A. */
#define PSOLVE_REINFORCED(s) ((s) == PSOLVE_REINFORCE || (s) == PSOLVE_PROJECT)
/** The options' right-hand side and solution are made mean-free. */
#define PSOLVE_MEAN_FREE(s) ((s) == PSOLVE_MEAN || (s) == PSOLVE_PROJECT)

/** Options (defaults from psolve_defaults()). */
struct psolve_options {
  enum psolve_method method;
  enum psolve_apply apply;
  enum psolve_precond precond;
  int sweeps; /* Jacobi sweeps per application of PSOLVE_JACOBI_SWEEPS */
  enum psolve_singular singular;
  double reinforce;    /* ε of PSOLVE_REINFORCE */
  double rtol;         /* stop when ||b − A x|| <= rtol ||b|| */
  double atol;         /* or when ||b − A x|| <= atol */
  int max_it;          /* iterations per solve */
  int max_failures;    /* consecutive non-converged solves before the run stops */
  const char *name;    /* what the messages call the solve: "pressure" (default), "viscous" */
  double row_estimate; /* nonzeros per row expected of the stored operator (its memory is
                        * announced at create, kern_reserve); 0: 50, 2-D at h = 2 dr */
  int group_max;       /* systems of at most this many unknowns are solved in one work-group and
                        * one launch (krylov_group.cl; stored operator, the multigrid's levels all
                        * in its block, or Jacobi); 0: never */
  int fuse; /* with the multigrid: 1, the Krylov kernels that make p and s make the cycle's fine
             * level down too (mg.cl's mg_begin_down, mg_s_down: 9 launches an iteration instead of
             * 11, each fused row sum reading 3 or 4 vectors a neighbour instead of 1); 0: not;
             * PSOLVE_FUSE_AUTO (the default): 1 on a GPU, 0 elsewhere (psolve_create) */
};

/** psolve_options.fuse: fused on a GPU, separate elsewhere. */
#define PSOLVE_FUSE_AUTO 2

/** Reasons: > 0 converged, < 0 failed. */
enum psolve_reason {
  PSOLVE_CONVERGED_RTOL = 1,
  PSOLVE_CONVERGED_ATOL = 2,
  PSOLVE_DIVERGED_ITS = -1,       /* max_it reached */
  PSOLVE_DIVERGED_BREAKDOWN = -2, /* rho or omega vanished again right after a restart */
  PSOLVE_DIVERGED_NANORINF = -3,  /* a dot product or norm is not finite */
};

struct psolve_result {
  enum psolve_reason reason;
  int its;        /* iterations (operator applications / 2) */
  double rnorm;   /* final ||b − A x|| / ||b|| */
  int kept_guess; /* failed above the initial guess's residual (or not finite): x is the guess */
  double rnorm_failed; /* then the residual the iteration ended at */
  int restarts;        /* breakdown restarts */
  int one_group;       /* solved in one work-group and one launch (solver_group_max) */
  double seconds;      /* wall time of the solve (setup of the stored layout included) */
};

struct psolve {
  const struct dev *dev;
  struct psolve_options opt;
  size_t cap;   /* vector length the buffers hold */
  int failures; /* consecutive non-converged solves */
  cl_kernel k_dot, k_dot_ts, k_residual, k_shift, k_start, k_begin, k_s, k_end, k_restart, k_total,
      k_spmv, k_spmv_dot, k_scale, k_sweep, k_axpy, k_add_diag, k_invert, k_csr_diag_inv,
      k_residual_csr, k_guard, k_wtotal, k_wshift, k_group;
  cl_kernel k_begin_down, k_s_down; /* with the multigrid: kr_begin, kr_s and its fine level down */
  struct grid_scan scan;            /* the stored rows' offsets (grid.h) */
  cl_mem d_r, d_r0, d_p, d_v, d_s, d_t, d_ph, d_sh, d_q, d_dinv, d_diag, d_b, d_partial, d_flags,
      d_x0;
  cl_mem d_p2;    /* with the multigrid, p of every other iteration (mg_begin_down: p_of()) */
  cl_mem d_state; /* the iteration's state (krylov.cl) */
  cl_mem d_row, d_col, d_val, d_count, d_block; /* stored layout */
  cl_mem d_valm;                                /* the multigrid's copy of d_val (mg.h) */
  size_t nnz_cap;
  cl_uint h_overflow; /* the nonzeros of the last guarded store() when they passed nnz_cap, else 0
                       * (queued read: valid once the multigrid's set-up has read its stencils) */
  double reserved;    /* bytes announced for the stored operator and the multigrid levels */
  int ngroups;        /* work-groups of the reductions */
  int last_its;       /* iterations of the last converged solve: the next one's first batch */
  int state_double;   /* the device keeps the state in double (krylov.cl's kreal) */
  size_t group_wg;    /* work-group of the one-group solve (PSOLVE_GROUP_WG items at most) */
  struct kern_timer t_apply; /* device time of operator applications (benchmarks) */
  struct mg mg;              /* the multigrid preconditioner (PSOLVE_MULTIGRID) */
};

/** @brief Default options: BiCGStab, stored coefficients, the multigrid preconditioner, rtol 1e-8
 * (double builds) or 1e-5 (float builds, whose dot products bottom out near 1e-6), 1000 iterations,
 * 10 failures. */
void psolve_defaults(struct psolve_options *o);
/** @brief Set an option by name (`solver = "direct"`, `solver_rtol = 1e-6`, ...): key is one of
 *  solver, apply, precond, sweeps, singular, reinforce, rtol, atol, max_it. */
enum clsph_status psolve_set(struct psolve_options *o, const char *key, const char *text,
                             double number);
/** Scheme options that reach the solver (a scheme lists them among its options): `solver` is
 *  psolve_set's "solver", `solver_X` its "X". */
#define PSOLVE_OPTION_NAMES                                                                        \
  "solver", "solver_apply", "solver_precond", "solver_sweeps", "solver_singular",                  \
      "solver_reinforce", "solver_rtol", "solver_atol", "solver_max_it", "solver_group_max",       \
      "solver_fuse"

/** @brief Kernels (from a program built with PSOLVE_SOURCES) and work vectors for n unknowns. */
enum clsph_status psolve_create(const struct dev *dev, cl_program prog, size_t n,
                                const struct psolve_options *opt, struct psolve *out);
/** @brief Solve A x = b; x holds the initial guess (the previous step's solution) and gets the
 *  solution. A solve that does not converge is a warning with its residual; max_failures of them
 *  in a row stop the run (CLSPH_E_BLOWUP). */
enum clsph_status psolve_solve(struct psolve *ps, const struct psolve_op *op, cl_mem b, cl_mem x,
                               struct psolve_result *res);
/** @brief Solve A x = b for another b with the operator of the last psolve_solve (its stored
 *  coefficients, diagonal and multigrid levels are reused: the particles have not moved). */
enum clsph_status psolve_solve_again(struct psolve *ps, const struct psolve_op *op, cl_mem b,
                                     cl_mem x, struct psolve_result *res);
/** @brief Assemble the operator on the host (CSR, columns sorted, in double) from the stored
 *  layout; the arrays are malloc'd. Used by the direct solver and the tests. */
enum clsph_status psolve_assemble(struct psolve *ps, const struct psolve_op *op, size_t **row,
                                  int **col, double **val);
/** @brief Solve with UMFPACK on the host (the reference). */
enum clsph_status psolve_direct(struct psolve *ps, const struct psolve_op *op, cl_mem b, cl_mem x,
                                struct psolve_result *res);
/** @brief Set up the preconditioner of the options for op without solving (the stored operator,
 *  its diagonal, the multigrid's levels): psolve_precond_apply then applies it, e.g. to the rows a
 *  rank owns of a system split across ranks (dsolve.h). */
enum clsph_status psolve_precond_setup(struct psolve *ps, const struct psolve_op *op);
/** @brief z = M⁻¹ r with the preconditioner of the last psolve_precond_setup (one V-cycle of the
 *  multigrid; D⁻¹ r for Jacobi). */
enum clsph_status psolve_precond_apply(struct psolve *ps, const struct psolve_op *op, cl_mem r,
                                       cl_mem z);
/** @brief Release. */
void psolve_destroy(struct psolve *ps);

/** Kernel sources the solver needs after the neighbour sources (GRID_SOURCES). */
#define PSOLVE_SOURCES                                                                             \
  "common/blas1.cl", "common/krylov.cl", "common/csr.cl", "common/mg.cl", "common/krylov_group.cl"
#define PSOLVE_SETS         8   /* partial-sum sets of the dot products (krylov.cl) */
#define PSOLVE_STATE        18  /* reals of the iteration's state (krylov.cl, krylov_group.cl) */
#define PSOLVE_GROUP_WG     256 /* items of the one-group solve at most (KR_GROUP_WG) */
#define PSOLVE_GROUP_WG_CPU 32  /* and on a CPU device */
/* solver_group_max's default: the unknowns up to which one work-group solves at least as fast as
 * the iteration's launches. On a CPU (PoCL, 2 cores: the cavity at 30², 1020 unknowns, 6% less
 * wall time a run; at 45², 2205, 5% more; at 60², 3840, 10% more) the group runs on one core; on a
 * GPU on one compute unit, where the launches cost more and the break-even lies higher (not
 * measured: no GPU was at hand) */
#define PSOLVE_GROUP_MAX 1500

#endif /* CLSPH_PSOLVE_H */
