/* poisson_op.h: the Morris Laplacian (kernels/common/poisson.cl), with or without the
 * kernel-gradient correction and with Dirichlet rows, as a pressure-solver operator. The
 * isph-rotational scheme solves its pressure equation with it; the solver tests and benchmark
 * use it as their manufactured problem. */
#ifndef CLSPH_POISSON_OP_H
#define CLSPH_POISSON_OP_H

#include "grid.h"
#include "psolve.h"

/** Kernel sources of a program with the solver and this operator (after OPS_SOURCES). */
#define POISSON_SOURCES PSOLVE_SOURCES, "common/poisson.cl"

struct poisson_op {
  const struct dev *dev;
  const struct grid *g; /* particles sorted by this grid */
  size_t n;
  cl_mem pos, vol, L, dirichlet; /* L: correction matrices (KGC builds) or NULL */
  cl_kernel k_apply, k_coeffs, k_diag, k_count;
  struct psolve_op op; /* what psolve_solve takes */
};

/** @brief Kernels from a program built with OPS_SOURCES and POISSON_SOURCES. */
enum clsph_status poisson_op_create(const struct dev *dev, cl_program prog, struct poisson_op *out);
/** @brief Point the operator at the current particles (after every sort). */
void poisson_op_bind(struct poisson_op *po, const struct grid *g, size_t n, cl_mem pos, cl_mem vol,
                     cl_mem L, cl_mem dirichlet);
/** @brief Release the kernels. */
void poisson_op_destroy(struct poisson_op *po);

#endif /* CLSPH_POISSON_OP_H */
