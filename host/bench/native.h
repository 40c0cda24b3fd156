/* native.h: the common operators (kernels/common/operators.cl) as plain C loops compiled with
 * OpenMP, the machine's own reference for `clsph bench neighbours`: the same arithmetic on the
 * same sorted particles, visiting the same rows of cells as the device's neighbour loop. 2-D,
 * Wendland C2, no periodic axes. */
#ifndef CLSPH_BENCH_NATIVE_H
#define CLSPH_BENCH_NATIVE_H

#include <stddef.h>

#include "kern.h"
#include "ops.h"

struct native_set {
  const real *pos;      /* 2 per particle, sorted by cell */
  const real *vol;      /* 1 per particle */
  const real *L;        /* correction matrices, 4 per particle (xx, xy, yy, unused); NULL: none */
  const cl_uint *start; /* cell table: cell c holds start[c] .. start[c + 1] − 1 */
  size_t n;
  int nc[2];       /* cells per axis */
  double cell_inv; /* 1 / cell side */
  int sub;         /* cells searched on each side */
  double h, alpha; /* smoothing length; Wendland's normalisation divided by h² */
};

/** @brief out = op(in) over every particle, as operators.cl computes it (with the correction
 *  matrices s->L when it is not NULL). in: 2 reals a particle for OP_DIV, 1 otherwise, unused by
 *  OP_CORRECTION and OP_SHEPARD; out: 4 reals a particle for OP_CORRECTION, 2 for the gradients,
 *  1 otherwise. Returns the wall time in seconds; *pairs: the pairs within the support (i itself
 *  included). */
double native_op(enum op_kind op, const struct native_set *s, const real *in, real *out,
                 long *pairs);

/** @brief Reals per particle of op's output. */
int native_out_width(enum op_kind op);

#endif /* CLSPH_BENCH_NATIVE_H */
