/* direct.c: the reference solve with UMFPACK (SuiteSparse): the operator's stored coefficients
 * are assembled on the host in double (columns sorted) and factorised. UMFPACK takes compressed
 * columns; our rows are the columns of Aᵀ, so we solve Aᵀᵀ x = b (UMFPACK_At). A singular
 * system is solved as the solver would see it: reinforced, or made mean-free. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <umfpack.h>

#include "clsph_config.h"
#include "psolve.h"

/* Σ w v / Σ w of v (real, or double where vr is NULL) */
static double weighted_mean(const double *w, const real *vr, const double *vd, size_t n)
{
  double s = 0.0, sw = 0.0;
  for (size_t i = 0; i < n; ++i) {
    s += w[i] * (vr != NULL ? (double)vr[i] : vd[i]);
    sw += w[i];
  }
  return sw != 0.0 ? s / sw : 0.0;
}

enum clsph_status psolve_direct(struct psolve *ps, const struct psolve_op *op, cl_mem b, cl_mem x,
                                struct psolve_result *res)
{
  enum clsph_status st = CLSPH_OK;
  const size_t n = op->n;
  size_t *row = NULL;
  int *col = NULL, *ap = NULL;
  double *val = NULL, *hb = NULL, *hx = NULL, *hw = NULL;
  real *buf = NULL;
  void *symbolic = NULL, *numeric = NULL;
  double control[UMFPACK_CONTROL], info[UMFPACK_INFO];

  CLSPH_CHECK(n < 2147483647u, CLSPH_E_INPUT, "direct solve: too many unknowns");
  CLSPH_TRY(psolve_assemble(ps, op, &row, &col, &val));
  CLSPH_CHECK(row[n] < 2147483647u, CLSPH_E_INPUT, "direct solve: too many entries");
  ap = malloc((n + 1) * sizeof *ap);
  hb = malloc(n * sizeof *hb);
  hx = malloc(n * sizeof *hx);
  buf = malloc(n * sizeof *buf);
  CLSPH_CHECK(ap && hb && hx && buf, CLSPH_E_NOMEM, "direct solve: out of memory");
  for (size_t i = 0; i <= n; ++i) ap[i] = (int)row[i];
  /* mean-free: the weights of the mean, the operator's left null vector or ones (psolve.c) */
  if (PSOLVE_MEAN_FREE(ps->opt.singular)) {
    hw = malloc(n * sizeof *hw);
    CLSPH_CHECK(hw != NULL, CLSPH_E_NOMEM, "direct solve: out of memory");
    if (op->weight != NULL) {
      CLSPH_TRY(kern_read(ps->dev, op->weight, n * sizeof *buf, buf));
      for (size_t i = 0; i < n; ++i) hw[i] = (double)buf[i];
    } else {
      for (size_t i = 0; i < n; ++i) hw[i] = 1.0;
    }
  }
  CLSPH_TRY(kern_read(ps->dev, b, n * sizeof *buf, buf));
  const double mean = hw != NULL ? weighted_mean(hw, buf, NULL, n) : 0.0;
  for (size_t i = 0; i < n; ++i) hb[i] = (double)buf[i] - mean;

  umfpack_di_defaults(control);
  int s = umfpack_di_symbolic((int)n, (int)n, ap, col, val, &symbolic, control, info);
  CLSPH_CHECK(s == UMFPACK_OK, CLSPH_E_INPUT, "UMFPACK symbolic analysis failed (status %d)", s);
  s = umfpack_di_numeric(ap, col, val, symbolic, &numeric, control, info);
  CLSPH_CHECK(s == UMFPACK_OK || s == UMFPACK_WARNING_singular_matrix, CLSPH_E_INPUT,
              "UMFPACK factorisation failed (status %d)", s);
  CLSPH_CHECK(s == UMFPACK_OK, CLSPH_E_BLOWUP,
              "UMFPACK: the pressure matrix is singular; use solver_singular = \"reinforce\"");
  s = umfpack_di_solve(UMFPACK_At, ap, col, val, hx, hb, numeric, control, info);
  CLSPH_CHECK(s == UMFPACK_OK, CLSPH_E_BLOWUP, "UMFPACK solve failed (status %d)", s);
  if (hw != NULL) {
    const double m = weighted_mean(hw, NULL, hx, n);
    for (size_t i = 0; i < n; ++i) hx[i] -= m;
  }
  /* residual of the assembled system, in double */
  double rr = 0.0, bb = 0.0;
  for (size_t i = 0; i < n; ++i) {
    double ax = 0.0;
    for (size_t k = row[i]; k < row[i + 1]; ++k) ax += val[k] * hx[col[k]];
    rr += (ax - hb[i]) * (ax - hb[i]);
    bb += hb[i] * hb[i];
  }
  for (size_t i = 0; i < n; ++i) buf[i] = (real)hx[i];
  CLSPH_TRY(kern_write(ps->dev, x, n * sizeof *buf, buf));
  res->reason = PSOLVE_CONVERGED_RTOL;
  res->its = 1;
  res->rnorm = bb > 0.0 ? sqrt(rr / bb) : 0.0;
done:
  if (numeric != NULL) umfpack_di_free_numeric(&numeric);
  if (symbolic != NULL) umfpack_di_free_symbolic(&symbolic);
  free(buf);
  free(hw);
  free(hx);
  free(hb);
  free(ap);
  free(val);
  free(col);
  free(row);
  return st;
}
