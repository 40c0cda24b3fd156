/* ops.c: argument setting and launch of the common operators. */
#include "ops.h"

#include <string.h>

#include "smoothing.h"

static const char *const names[OP_COUNT] = {
    [OP_CORRECTION] = "op_correction",
    [OP_SHEPARD] = "op_shepard",
    [OP_INTERP] = "op_interp",
    [OP_GRAD_SYM] = "op_grad_sym",
    [OP_GRAD_ANTISYM] = "op_grad_antisym",
    [OP_DIV] = "op_div",
    [OP_LAP] = "op_lap",
};

const char *ops_name(enum op_kind op)
{
  return (unsigned)op < OP_COUNT ? names[op] : "?";
}

enum clsph_status ops_define(int kgc, struct prog_opts *o)
{
  return prog_opts_define_int(o, "KGC", kgc ? 1 : 0);
}

enum clsph_status ops_build(const struct dev *dev, const struct grid_spec *spec,
                            const struct smoothing *sm, int kgc, cl_program *out)
{
  enum clsph_status st = CLSPH_OK;
  struct prog_opts o = {0};
  static const char *const sources[] = {OPS_SOURCES, NULL};
  CLSPH_CHECK(sm->dim == spec->dim, CLSPH_E_INPUT,
              "smoothing function built for %d dimensions on a %d-D grid", sm->dim, spec->dim);
  CLSPH_TRY(grid_define(spec, &o));
  CLSPH_TRY(smoothing_define(sm, &o));
  CLSPH_TRY(ops_define(kgc, &o));
  CLSPH_TRY(prog_build(dev, sources, &o, out));
done:
  prog_opts_free(&o);
  return st;
}

enum clsph_status ops_create(cl_program prog, int kgc, struct ops *out)
{
  enum clsph_status st = CLSPH_OK;
  struct ops ops;
  memset(&ops, 0, sizeof ops);
  ops.kgc = kgc;
  for (int k = 0; k < OP_COUNT; ++k) CLSPH_TRY(prog_kernel(prog, names[k], &ops.k[k]));
  *out = ops;
  memset(&ops, 0, sizeof ops);
done:
  ops_destroy(&ops);
  return st;
}

enum clsph_status ops_apply(const struct ops *ops, enum op_kind op, const struct dev *dev,
                            const struct grid *g, size_t n, cl_mem d_pos, cl_mem d_vol, cl_mem d_L,
                            cl_mem d_in, cl_mem d_out, struct kern_timer *timer)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_CHECK(!ops->kgc || op == OP_CORRECTION || d_L != NULL, CLSPH_E_INPUT,
              "%s: the corrected operator needs the correction matrices", ops_name(op));
  cl_uint np = (cl_uint)n;
  cl_mem L = ops->kgc ? d_L : NULL;
  cl_kernel k = ops->k[op];
  if (op == OP_CORRECTION || op == OP_SHEPARD)
    CLSPH_TRY(KERN_SET(k, KARG(np), KARG(g->geom), KARG(g->d_start), KARG(d_pos), KARG(d_vol),
                       KARG(L), KARG(d_out)));
  else
    CLSPH_TRY(KERN_SET(k, KARG(np), KARG(g->geom), KARG(g->d_start), KARG(d_pos), KARG(d_vol),
                       KARG(L), KARG(d_in), KARG(d_out)));
  CLSPH_TRY(kern_launch(dev, k, n, timer));
done:
  return st;
}

void ops_destroy(struct ops *ops)
{
  for (int k = 0; k < OP_COUNT; ++k) {
    if (ops->k[k] != NULL) clReleaseKernel(ops->k[k]);
    ops->k[k] = NULL;
  }
}
