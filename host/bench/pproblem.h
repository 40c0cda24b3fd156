/* pproblem.h: a manufactured pressure problem for the solver tests and benchmark: the Morris
 * Laplacian (poisson_op) on a particle lattice of the unit square, with
 *   regular:  periodic in x, Dirichlet rows in 4 layers below y = 0 and above y = 1,
 *             p = cos(2πx) e^y, ∇²p = (1 − 4π²) p;
 *   singular: periodic in x and y (pure Neumann, solution up to a constant),
 *             p = e^{sin 2πx} cos(2πy), ∇²p = 4π² p (cos² 2πx − sin 2πx − 1), whose mean is
 *             zero (a consistent system) and which is no eigenvector of the discrete Laplacian.
 * The lattice can be jittered and the Laplacian corrected (KGC), which makes A non-symmetric. */
#ifndef CLSPH_PPROBLEM_H
#define CLSPH_PPROBLEM_H

#include "ops.h"
#include "poisson_op.h"
#include "pset.h"
#include "smoothing.h"

struct pproblem_spec {
  int side;      /* particles per unit length */
  int singular;  /* periodic in y too */
  double jitter; /* random displacement, fraction of dr */
  int kgc;       /* kernel-gradient correction */
  double scale;  /* the volumes and so the Laplacian's rows, and their right-hand side, times this
                    (0: 1): the same solution on another scale */
  double air;    /* empty grid above the particles (regular problems), unit lengths: the cells a
                    free surface leaves without fluid */
  unsigned long seed;
  /* a slab of the lattice's rows (the Dirichlet layers counted: row 0 is the lowest of the
   * regular problem's ghost rows): rows [row_lo, row_hi) only, their global particle index in the
   * field "gid" (row × side + column); row_hi 0: every row. The jitter is that of the whole
   * lattice, so slabs of one seed put each particle where the whole problem does. */
  int row_lo, row_hi;
};

struct pproblem {
  const struct dev *dev;
  struct pproblem_spec spec;
  cl_program prog;
  struct smoothing sm;
  struct grid g;
  struct ops ops;
  struct pset ps;
  struct poisson_op po;
  int f_pos, f_vol, f_dir, f_b, f_x, f_gid;
  cl_mem d_L, d_flags;
  size_t n;
  double dr;
  int rows; /* of the whole lattice, the Dirichlet layers counted */
};

/** @brief Build the problem: particles sorted, correction computed, operator bound, x = 0. */
enum clsph_status pproblem_create(const struct dev *dev, const struct pproblem_spec *spec,
                                  struct pproblem *out);
/** @brief Largest |x − p_exact| over the unknown (non-Dirichlet) particles, relative to max|p|,
 *  after removing the mean difference when the problem is singular. */
enum clsph_status pproblem_error(struct pproblem *pp, cl_mem x, double *err);
/** @brief Read a solution vector to the host in double (sorted order). */
enum clsph_status pproblem_read(struct pproblem *pp, cl_mem x, double *out);
/** @brief Read the first n reals of a device vector to the host in double. */
enum clsph_status pproblem_read_n(const struct dev *dev, cl_mem x, size_t n, double *out);
/** @brief Release. */
void pproblem_destroy(struct pproblem *pp);
/** @brief Point the operator at the problem where it now lies (after a struct pproblem was copied:
 *  the operator keeps the addresses of the problem's grid and of itself). */
void pproblem_rebind(struct pproblem *pp);
/** @brief The rows of the lattice that one row's unknown reaches through the operator (the
 *  Laplacian's support and the jitter); a slab that owns rows needs this many more on each side
 *  (pslab.h). */
int pproblem_reach_rows(const struct pproblem_spec *spec);
/** @brief The lattice's rows, the Dirichlet layers counted. */
int pproblem_rows(const struct pproblem_spec *spec);

#endif /* CLSPH_PPROBLEM_H */
