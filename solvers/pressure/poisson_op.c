/* poisson_op.c: argument setting of the Morris-Laplacian operator kernels. */
#include "poisson_op.h"

#include <string.h>

static enum clsph_status prefix(const struct poisson_op *po, cl_kernel k, cl_uint *n)
{
  *n = (cl_uint)po->n;
  return KERN_SET(k, KARG(*n), KARG(po->g->geom), KARG(po->g->d_start), KARG(po->pos),
                  KARG(po->vol), KARG(po->L), KARG(po->dirichlet));
}

static enum clsph_status po_apply(void *ctx, cl_mem x, cl_mem y)
{
  enum clsph_status st = CLSPH_OK;
  struct poisson_op *po = ctx;
  cl_uint n;
  CLSPH_TRY(prefix(po, po->k_apply, &n));
  CLSPH_CL_TRY(clSetKernelArg(po->k_apply, 7, sizeof x, &x));
  CLSPH_CL_TRY(clSetKernelArg(po->k_apply, 8, sizeof y, &y));
  CLSPH_TRY(kern_launch(po->dev, po->k_apply, po->n, NULL));
done:
  return st;
}

static enum clsph_status po_diagonal(void *ctx, cl_mem d)
{
  enum clsph_status st = CLSPH_OK;
  struct poisson_op *po = ctx;
  cl_uint n;
  CLSPH_TRY(prefix(po, po->k_diag, &n));
  CLSPH_CL_TRY(clSetKernelArg(po->k_diag, 7, sizeof d, &d));
  CLSPH_TRY(kern_launch(po->dev, po->k_diag, po->n, NULL));
done:
  return st;
}

static enum clsph_status po_counts(void *ctx, cl_mem count)
{
  enum clsph_status st = CLSPH_OK;
  struct poisson_op *po = ctx;
  cl_uint n = (cl_uint)po->n;
  CLSPH_TRY(KERN_SET(po->k_count, KARG(n), KARG(po->g->geom), KARG(po->g->d_start), KARG(po->pos),
                     KARG(count)));
  CLSPH_TRY(kern_launch(po->dev, po->k_count, po->n, NULL));
done:
  return st;
}

static enum clsph_status po_coefficients(void *ctx, cl_mem row, cl_mem col, cl_mem val)
{
  enum clsph_status st = CLSPH_OK;
  struct poisson_op *po = ctx;
  cl_uint n;
  CLSPH_TRY(prefix(po, po->k_coeffs, &n));
  CLSPH_CL_TRY(clSetKernelArg(po->k_coeffs, 7, sizeof row, &row));
  CLSPH_CL_TRY(clSetKernelArg(po->k_coeffs, 8, sizeof col, &col));
  CLSPH_CL_TRY(clSetKernelArg(po->k_coeffs, 9, sizeof val, &val));
  CLSPH_TRY(kern_launch(po->dev, po->k_coeffs, po->n, NULL));
done:
  return st;
}

enum clsph_status poisson_op_create(const struct dev *dev, cl_program prog, struct poisson_op *out)
{
  enum clsph_status st = CLSPH_OK;
  struct poisson_op po;
  memset(&po, 0, sizeof po);
  po.dev = dev;
  CLSPH_TRY(prog_kernel(prog, "poisson_apply", &po.k_apply));
  CLSPH_TRY(prog_kernel(prog, "poisson_coeffs", &po.k_coeffs));
  CLSPH_TRY(prog_kernel(prog, "poisson_diag", &po.k_diag));
  CLSPH_TRY(prog_kernel(prog, "csr_count_lanes", &po.k_count));
  *out = po;
  memset(&po, 0, sizeof po);
done:
  poisson_op_destroy(&po);
  return st;
}

void poisson_op_bind(struct poisson_op *po, const struct grid *g, size_t n, cl_mem pos, cl_mem vol,
                     cl_mem L, cl_mem dirichlet)
{
  po->g = g;
  po->n = n;
  po->pos = pos;
  po->vol = vol;
  po->L = L;
  po->dirichlet = dirichlet;
  po->op.ctx = po;
  po->op.n = n;
  po->op.apply = po_apply;
  po->op.diagonal = po_diagonal;
  po->op.row_counts = po_counts;
  po->op.coefficients = po_coefficients;
  po->op.grid = g;
  /* V_i A_ij = −2 V_i V_j F_ij is symmetric: the volumes are the left null vector of the
   * Laplacian without Dirichlet rows (not with KGC's L_i) */
  po->op.weight = L == NULL ? vol : NULL;
}

void poisson_op_destroy(struct poisson_op *po)
{
  cl_kernel *ks[] = {&po->k_apply, &po->k_coeffs, &po->k_diag, &po->k_count};
  for (size_t i = 0; i < sizeof ks / sizeof *ks; ++i) {
    if (*ks[i] != NULL) clReleaseKernel(*ks[i]);
    *ks[i] = NULL;
  }
}
