/* ops.h: dispatch of the common SPH operators of kernels/common/operators.cl. */
#ifndef CLSPH_OPS_H
#define CLSPH_OPS_H

#include "grid.h"

/** Kernel sources of a program with the common operators, in order. */
#define OPS_SOURCES GRID_SOURCES, "common/operators.cl"

enum op_kind {
  OP_CORRECTION,   /* L_i, the kernel-gradient correction matrix */
  OP_SHEPARD,      /* Σ V_j W_ij */
  OP_INTERP,       /* Σ V_j A_j W_ij */
  OP_GRAD_SYM,     /* Σ V_j (A_j − A_i) ∇W_ij */
  OP_GRAD_ANTISYM, /* Σ V_j (A_i + A_j) ∇W_ij */
  OP_DIV,          /* Σ V_j (u_j − u_i)·∇W_ij */
  OP_LAP,          /* Morris Laplacian */
  OP_COUNT
};

struct ops {
  cl_kernel k[OP_COUNT];
  int kgc; /* the program was built with -D KGC=1 */
};

/** @brief Name of an operator kernel ("op_lap", ...). */
const char *ops_name(enum op_kind op);
/** @brief Add the operator switches (KGC) to the build options. */
enum clsph_status ops_define(int kgc, struct prog_opts *o);
struct smoothing;
/** @brief Build a program with the grid and the common operators for this grid, smoothing
 *  function and correction switch. */
enum clsph_status ops_build(const struct dev *dev, const struct grid_spec *spec,
                            const struct smoothing *sm, int kgc, cl_program *out);
/** @brief Create the operator kernels from a program built with OPS_SOURCES and ops_define. */
enum clsph_status ops_create(cl_program prog, int kgc, struct ops *out);
/** @brief out = op(in) over n particles sorted by g.
 *  @param d_L  correction matrices (used when kgc; may be NULL otherwise)
 *  @param d_in input field (NULL for OP_CORRECTION and OP_SHEPARD) */
enum clsph_status ops_apply(const struct ops *ops, enum op_kind op, const struct dev *dev,
                            const struct grid *g, size_t n, cl_mem d_pos, cl_mem d_vol, cl_mem d_L,
                            cl_mem d_in, cl_mem d_out, struct kern_timer *timer);
/** @brief Release the kernels. */
void ops_destroy(struct ops *ops);

#endif /* CLSPH_OPS_H */
