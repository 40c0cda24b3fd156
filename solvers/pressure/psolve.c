/* psolve.c: preconditioned BiCGStab on the device (van der Vorst 1992, right preconditioning),
 * with the operator applied matrix-free or from coefficients stored once per solve. The loop
 * reads like the algorithm; each line is one device operation.
 *
 *   r = b − A x,  r0 = r,  ρ = α = ω = 1,  v = p = 0
 *   repeat:  ρ' = (r0, r);          β = (ρ'/ρ)(α/ω)
 *            p = r + β (p − ω v);   p̂ = M⁻¹ p;   v = A p̂;   α = ρ' / (r0, v)
 *            s = r − α v            (stop if ||s|| small: x += α p̂)
 *            ŝ = M⁻¹ s;   t = A ŝ;   ω = (t, s) / (t, t)
 *            x += α p̂ + ω ŝ;   r = s − ω t   (stop if ||r|| small)
 * A vanishing ρ' or ω (breakdown) restarts from the current residual. */
#include "psolve.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "clsph_config.h"

#define PSOLVE_WG         64 /* BLAS1_WG in blas1.cl */
#define PSOLVE_SCAN_BLOCK 64 /* GRID_SCAN_BLOCK in grid.cl */

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void psolve_defaults(struct psolve_options *o)
{
  memset(o, 0, sizeof *o);
  o->method = PSOLVE_BICGSTAB;
  o->apply = PSOLVE_STORED;
  o->precond = PSOLVE_MULTIGRID;
  o->sweeps = 2;
  o->singular = PSOLVE_REGULAR;
  o->reinforce = CLSPH_DOUBLE ? 1e-6 : 1e-4; /* float: 1e-6 is below its resolution */
  o->rtol = CLSPH_DOUBLE ? 1e-8 : 1e-5;
  o->atol = 0.0;
  o->max_it = 1000;
  o->max_failures = 10;
  o->name = "pressure";
}

static int pick(const char *text, const char *const *names)
{
  for (int i = 0; names[i] != NULL; ++i)
    if (text != NULL && strcmp(text, names[i]) == 0) return i;
  return -1;
}

enum clsph_status psolve_set(struct psolve_options *o, const char *key, const char *text,
                             double number)
{
  enum clsph_status st = CLSPH_OK;
  static const char *const methods[] = {"bicgstab", "direct", NULL};
  static const char *const applies[] = {"stored", "recompute", NULL};
  static const char *const preconds[] = {"jacobi", "none", "jacobi_sweeps", "multigrid", NULL};
  static const char *const singulars[] = {"regular", "reinforce", "mean", NULL};
  int k;
  if (strcmp(key, "solver") == 0) {
    CLSPH_CHECK((k = pick(text, methods)) >= 0, CLSPH_E_INPUT,
                "solver must be \"bicgstab\" or \"direct\"");
    o->method = (enum psolve_method)k;
  } else if (strcmp(key, "apply") == 0) {
    CLSPH_CHECK((k = pick(text, applies)) >= 0, CLSPH_E_INPUT,
                "solver_apply must be \"stored\" or \"recompute\"");
    o->apply = (enum psolve_apply)k;
  } else if (strcmp(key, "precond") == 0) {
    CLSPH_CHECK((k = pick(text, preconds)) >= 0, CLSPH_E_INPUT,
                "solver_precond must be \"jacobi\", \"none\", \"jacobi_sweeps\" or \"multigrid\"");
    o->precond = (enum psolve_precond)k;
  } else if (strcmp(key, "singular") == 0) {
    CLSPH_CHECK((k = pick(text, singulars)) >= 0, CLSPH_E_INPUT,
                "solver_singular must be \"regular\", \"reinforce\" or \"mean\"");
    o->singular = (enum psolve_singular)k;
  } else if (strcmp(key, "sweeps") == 0) {
    CLSPH_CHECK(number >= 1 && number <= 16, CLSPH_E_INPUT, "solver_sweeps must be 1 to 16");
    o->sweeps = (int)number;
  } else if (strcmp(key, "reinforce") == 0) {
    CLSPH_CHECK(number > 0 && number < 1, CLSPH_E_INPUT, "solver_reinforce must be in (0, 1)");
    o->reinforce = number;
  } else if (strcmp(key, "rtol") == 0) {
    CLSPH_CHECK(number > 0 && number < 1, CLSPH_E_INPUT, "solver_rtol must be in (0, 1)");
    o->rtol = number;
  } else if (strcmp(key, "atol") == 0) {
    CLSPH_CHECK(number >= 0, CLSPH_E_INPUT, "solver_atol must not be negative");
    o->atol = number;
  } else if (strcmp(key, "max_it") == 0) {
    CLSPH_CHECK(number >= 1 && number <= 1e6, CLSPH_E_INPUT, "solver_max_it must be 1 to 1e6");
    o->max_it = (int)number;
  } else {
    CLSPH_CHECK(0, CLSPH_E_INPUT, "unknown solver option '%s'", key);
  }
done:
  return st;
}

enum clsph_status psolve_create(const struct dev *dev, cl_program prog, size_t n,
                                const struct psolve_options *opt, struct psolve *out)
{
  enum clsph_status st = CLSPH_OK;
  struct psolve ps;
  const cl_uint zero = 0;
  memset(&ps, 0, sizeof ps);
  ps.dev = dev;
  ps.opt = *opt;
  ps.cap = n > 0 ? n : 1;
  size_t groups = (ps.cap + PSOLVE_WG - 1) / PSOLVE_WG;
  ps.ngroups = groups < 64 ? (int)groups : 64;
  struct {
    cl_kernel *k;
    const char *name;
  } ks[] = {{&ps.k_dot, "blas1_dot"},
            {&ps.k_dot2, "blas1_dot2"},
            {&ps.k_sum, "blas1_sum"},
            {&ps.k_axpy, "blas1_axpy"},
            {&ps.k_waxpy, "blas1_waxpy"},
            {&ps.k_axpbypz, "blas1_axpbypz"},
            {&ps.k_p, "blas1_bicgstab_p"},
            {&ps.k_scale, "blas1_scale"},
            {&ps.k_sweep, "blas1_jacobi_sweep"},
            {&ps.k_add_diag, "blas1_add_diag"},
            {&ps.k_shift, "blas1_shift"},
            {&ps.k_invert, "blas1_invert"},
            {&ps.k_spmv, "csr_spmv"},
            {&ps.k_csr_diag, "csr_diag"},
            {&ps.k_scan_blocks, "grid_scan_blocks"},
            {&ps.k_scan_top, "grid_scan_top"},
            {&ps.k_scan_apply, "grid_scan_apply"}};
  for (size_t i = 0; i < sizeof ks / sizeof *ks; ++i)
    CLSPH_TRY(prog_kernel(prog, ks[i].name, ks[i].k));
  cl_mem *vs[] = {&ps.d_r,  &ps.d_r0, &ps.d_p, &ps.d_v,    &ps.d_s,    &ps.d_t,
                  &ps.d_ph, &ps.d_sh, &ps.d_q, &ps.d_dinv, &ps.d_diag, &ps.d_b};
  for (size_t i = 0; i < sizeof vs / sizeof *vs; ++i)
    CLSPH_TRY(kern_buffer(dev, ps.cap * sizeof(real), NULL, vs[i], "solver vector"));
  CLSPH_TRY(kern_buffer(dev, 2 * 64 * sizeof(real), NULL, &ps.d_partial, "solver partial sums"));
  CLSPH_TRY(kern_buffer(dev, sizeof zero, &zero, &ps.d_flags, "solver flags"));
  CLSPH_TRY(kern_buffer(dev, (ps.cap + 1) * sizeof(cl_uint), NULL, &ps.d_row, "csr rows"));
  CLSPH_TRY(kern_buffer(dev, (ps.cap + 1) * sizeof(cl_uint), NULL, &ps.d_count, "csr counts"));
  CLSPH_TRY(kern_buffer(dev, ((ps.cap + 1) / PSOLVE_SCAN_BLOCK + 2) * sizeof(cl_uint), NULL,
                        &ps.d_block, "csr scan blocks"));
  if (opt->precond == PSOLVE_MULTIGRID) CLSPH_TRY(mg_create(dev, prog, ps.cap, &ps.mg));
  /* what the first solve allocates: the stored operator (a quarter more than its nonzeros,
   * store()) and the multigrid's levels: the coarse stencils (about 3 reals a particle) and the
   * fine rows of A P against the level-1 cells (a value and a cell for each of (2 GRID_SUB + 1)^d
   * cells: about half a row of the operator) */
  const double rows = opt->row_estimate > 0.0 ? opt->row_estimate : 50.0;
  if (opt->apply == PSOLVE_STORED)
    ps.reserved += 1.25 * (double)ps.cap * rows * (double)(sizeof(cl_uint) + sizeof(real));
  if (opt->precond == PSOLVE_MULTIGRID)
    ps.reserved += (double)ps.cap *
                   (3.0 * sizeof(real) + 0.5 * rows * (double)(sizeof(cl_uint) + sizeof(real)));
  kern_reserve(ps.reserved);
  ps.h_partial = malloc(2 * 64 * sizeof *ps.h_partial);
  CLSPH_CHECK(ps.h_partial != NULL, CLSPH_E_NOMEM, "out of memory");
  *out = ps;
  memset(&ps, 0, sizeof ps);
done:
  psolve_destroy(&ps);
  return st;
}

/* ---- device reductions and vector operations ---- */

static enum clsph_status reduce(struct psolve *ps, cl_kernel k, int per_group, double *out)
{
  enum clsph_status st = CLSPH_OK;
  real part[128];
  size_t global = (size_t)ps->ngroups * PSOLVE_WG;
  CLSPH_CHECK(per_group <= 2, CLSPH_E_INPUT, "reduce: at most two sums");
  CLSPH_TRY(kern_launch_wg(ps->dev, k, global, PSOLVE_WG, NULL));
  CLSPH_TRY(
      kern_read(ps->dev, ps->d_partial, (size_t)(per_group * ps->ngroups) * sizeof(real), part));
  for (int c = 0; c < per_group; ++c) {
    double s = 0.0;
    for (int g = 0; g < ps->ngroups; ++g) s += (double)part[per_group * g + c];
    out[c] = s;
  }
done:
  return st;
}

static enum clsph_status dot(struct psolve *ps, cl_uint n, cl_mem x, cl_mem y, double *out)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(KERN_SET(ps->k_dot, KARG(n), KARG(x), KARG(y), KARG(ps->d_partial)));
  CLSPH_TRY(reduce(ps, ps->k_dot, 1, out));
done:
  return st;
}

static enum clsph_status dot2(struct psolve *ps, cl_uint n, cl_mem a, cl_mem b, cl_mem c, cl_mem d,
                              double out[2])
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(KERN_SET(ps->k_dot2, KARG(n), KARG(a), KARG(b), KARG(c), KARG(d), KARG(ps->d_partial)));
  CLSPH_TRY(reduce(ps, ps->k_dot2, 2, out));
done:
  return st;
}

static enum clsph_status launch(struct psolve *ps, cl_kernel k, cl_uint n)
{
  return kern_launch(ps->dev, k, n, NULL);
}

/* w = x + a y */
static enum clsph_status waxpy(struct psolve *ps, cl_uint n, cl_mem w, cl_mem x, double a, cl_mem y)
{
  enum clsph_status st = CLSPH_OK;
  real ra = (real)a;
  CLSPH_TRY(KERN_SET(ps->k_waxpy, KARG(n), KARG(w), KARG(x), KARG(ra), KARG(y)));
  CLSPH_TRY(launch(ps, ps->k_waxpy, n));
done:
  return st;
}

static enum clsph_status copy(struct psolve *ps, cl_mem dst, cl_mem src, cl_uint n)
{
  return kern_copy(ps->dev, dst, src, n * sizeof(real));
}

static enum clsph_status zero(struct psolve *ps, cl_mem x, cl_uint n)
{
  const real z = 0;
  return kern_fill(ps->dev, x, &z, sizeof z, n * sizeof(real));
}

/* Subtract the mean of x (PSOLVE_MEAN). */
static enum clsph_status remove_mean(struct psolve *ps, cl_uint n, cl_mem x)
{
  enum clsph_status st = CLSPH_OK;
  double sum = 0.0;
  CLSPH_TRY(KERN_SET(ps->k_sum, KARG(n), KARG(x), KARG(ps->d_partial)));
  CLSPH_TRY(reduce(ps, ps->k_sum, 1, &sum));
  real c = (real)(sum / n);
  CLSPH_TRY(KERN_SET(ps->k_shift, KARG(n), KARG(x), KARG(c)));
  CLSPH_TRY(launch(ps, ps->k_shift, n));
done:
  return st;
}

/* ---- the operator ---- */

/* Build the stored layout: counts, row starts (exclusive scan of the counts), coefficients. */
static enum clsph_status store(struct psolve *ps, const struct psolve_op *op)
{
  enum clsph_status st = CLSPH_OK;
  const cl_uint zero = 0;
  cl_uint items = (cl_uint)op->n + 1, blocks = (items + PSOLVE_SCAN_BLOCK - 1) / PSOLVE_SCAN_BLOCK;
  cl_uint nnz = 0;
  CLSPH_TRY(kern_fill(ps->dev, ps->d_count, &zero, sizeof zero, items * sizeof(cl_uint)));
  CLSPH_TRY(op->row_counts(op->ctx, ps->d_count));
  CLSPH_TRY(KERN_SET(ps->k_scan_blocks, KARG(items), KARG(ps->d_count), KARG(ps->d_block)));
  CLSPH_TRY(kern_launch(ps->dev, ps->k_scan_blocks, blocks, NULL));
  CLSPH_TRY(KERN_SET(ps->k_scan_top, KARG(blocks), KARG(ps->d_block)));
  CLSPH_TRY(kern_launch_wg(ps->dev, ps->k_scan_top, 1, 1, NULL));
  CLSPH_TRY(KERN_SET(ps->k_scan_apply, KARG(items), KARG(ps->d_count), KARG(ps->d_block),
                     KARG(ps->d_row)));
  CLSPH_TRY(kern_launch(ps->dev, ps->k_scan_apply, blocks, NULL));
  CLSPH_TRY(kern_read_at(ps->dev, ps->d_row, op->n * sizeof(cl_uint), sizeof nnz, &nnz));
  if (nnz > ps->nnz_cap) { /* grow by a quarter more than needed: particles move */
    kern_release(&ps->d_col);
    kern_release(&ps->d_val);
    ps->nnz_cap = (size_t)nnz + nnz / 4 + 16;
    CLSPH_TRY(kern_buffer(ps->dev, ps->nnz_cap * sizeof(cl_uint), NULL, &ps->d_col, "csr columns"));
    CLSPH_TRY(kern_buffer(ps->dev, ps->nnz_cap * sizeof(real), NULL, &ps->d_val, "csr values"));
  }
  CLSPH_TRY(op->coefficients(op->ctx, ps->d_row, ps->d_col, ps->d_val));
done:
  return st;
}

/* y = A x, stored or recomputed, plus the reinforcement of a singular system. */
static enum clsph_status apply(struct psolve *ps, const struct psolve_op *op, cl_mem x, cl_mem y)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint n = (cl_uint)op->n;
  struct kern_timer *t = &ps->t_apply;
  if (ps->opt.apply == PSOLVE_STORED) {
    CLSPH_TRY(KERN_SET(ps->k_spmv, KARG(n), KARG(ps->d_row), KARG(ps->d_col), KARG(ps->d_val),
                       KARG(x), KARG(y)));
    CLSPH_TRY(kern_launch(ps->dev, ps->k_spmv, n, t));
  } else {
    double t0 = t->on ? now() : 0.0;
    CLSPH_TRY(op->apply(op->ctx, x, y));
    if (t->on) {
      CLSPH_TRY(kern_finish(ps->dev));
      t->seconds += now() - t0;
      t->launches += 1;
    }
  }
  if (ps->opt.singular == PSOLVE_REINFORCE) { /* y += ε diag(A) x */
    real e = (real)ps->opt.reinforce;
    CLSPH_TRY(KERN_SET(ps->k_add_diag, KARG(n), KARG(y), KARG(e), KARG(ps->d_diag), KARG(x)));
    CLSPH_TRY(launch(ps, ps->k_add_diag, n));
  }
done:
  return st;
}

/* ε of A + ε diag(A), 0 without the reinforcement */
static double reinforcement(const struct psolve *ps)
{
  return ps->opt.singular == PSOLVE_REINFORCE ? ps->opt.reinforce : 0.0;
}

/* z = M⁻¹ r: none, multigrid, Jacobi, or Jacobi followed by sweeps toward A z = r (scratch: A z).
 */
static enum clsph_status precond(struct psolve *ps, const struct psolve_op *op, cl_mem r, cl_mem z,
                                 cl_mem scratch)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint n = (cl_uint)op->n;
  if (ps->opt.precond == PSOLVE_NONE) {
    CLSPH_TRY(copy(ps, z, r, n));
    goto done;
  }
  if (ps->opt.precond == PSOLVE_MULTIGRID) {
    CLSPH_TRY(mg_apply(&ps->mg, op->n, ps->d_row, ps->d_col, ps->d_val, reinforcement(ps), r, z));
    goto done;
  }
  CLSPH_TRY(KERN_SET(ps->k_scale, KARG(n), KARG(z), KARG(ps->d_dinv), KARG(r)));
  CLSPH_TRY(launch(ps, ps->k_scale, n));
  if (ps->opt.precond == PSOLVE_JACOBI_SWEEPS) {
    for (int k = 0; k < ps->opt.sweeps; ++k) { /* z <- z + D⁻¹ (r − A z) */
      CLSPH_TRY(apply(ps, op, z, scratch));
      CLSPH_TRY(KERN_SET(ps->k_sweep, KARG(n), KARG(z), KARG(ps->d_dinv), KARG(r), KARG(scratch)));
      CLSPH_TRY(launch(ps, ps->k_sweep, n));
    }
  }
done:
  return st;
}

/* diag(A) into d_diag (for the reinforcement) and the inverse diagonal of the operator solved,
 * A or A + ε diag(A), into d_dinv (Jacobi). */
static enum clsph_status diagonal(struct psolve *ps, const struct psolve_op *op)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint n = (cl_uint)op->n, flags = 0;
  const cl_uint zero = 0;
  if (ps->opt.apply == PSOLVE_STORED) {
    CLSPH_TRY(
        KERN_SET(ps->k_csr_diag, KARG(n), KARG(ps->d_row), KARG(ps->d_val), KARG(ps->d_diag)));
    CLSPH_TRY(launch(ps, ps->k_csr_diag, n));
  } else {
    CLSPH_TRY(op->diagonal(op->ctx, ps->d_diag));
  }
  CLSPH_TRY(copy(ps, ps->d_dinv, ps->d_diag, n));
  if (ps->opt.singular == PSOLVE_REINFORCE) { /* dinv = (1 + ε) diag(A) */
    real e = (real)ps->opt.reinforce;
    CLSPH_TRY(KERN_SET(ps->k_axpy, KARG(n), KARG(e), KARG(ps->d_diag), KARG(ps->d_dinv)));
    CLSPH_TRY(launch(ps, ps->k_axpy, n));
  }
  CLSPH_TRY(kern_fill(ps->dev, ps->d_flags, &zero, sizeof zero, sizeof zero));
  CLSPH_TRY(KERN_SET(ps->k_invert, KARG(n), KARG(ps->d_dinv), KARG(ps->d_flags)));
  CLSPH_TRY(launch(ps, ps->k_invert, n));
  CLSPH_TRY(kern_read(ps->dev, ps->d_flags, sizeof flags, &flags));
  CLSPH_CHECK(flags == 0, CLSPH_E_BLOWUP,
              "%s solve: the operator has a zero or non-finite diagonal entry", ps->opt.name);
done:
  return st;
}

/* ---- the solve ---- */

static int finite(double v)
{
  return isfinite(v);
}

static enum clsph_status bicgstab(struct psolve *ps, const struct psolve_op *op, cl_mem b, cl_mem x,
                                  struct psolve_result *res)
{
  enum clsph_status st = CLSPH_OK;
  const cl_uint n = (cl_uint)op->n;
  const double tiny = 1e3 * REAL_EPS * REAL_EPS;
  double bb = 0.0, rr = 0.0, d2[2];
  double rho = 1.0, alpha = 1.0, omega = 1.0;
  int restarted_at = -1;

  /* b (mean-free for a consistent singular system) and its norm */
  CLSPH_TRY(copy(ps, ps->d_b, b, n));
  if (ps->opt.singular == PSOLVE_MEAN) CLSPH_TRY(remove_mean(ps, n, ps->d_b));
  CLSPH_TRY(dot(ps, n, ps->d_b, ps->d_b, &bb));
  const double bnorm = sqrt(bb);
  res->its = 0;
  res->restarts = 0;
  if (!finite(bnorm)) {
    res->reason = PSOLVE_DIVERGED_NANORINF;
    goto done;
  }
  if (bnorm == 0.0) { /* A x = 0: x = 0 */
    CLSPH_TRY(zero(ps, x, n));
    res->rnorm = 0.0;
    res->reason = PSOLVE_CONVERGED_ATOL;
    goto done;
  }
  const double stop = fmax(ps->opt.rtol * bnorm, ps->opt.atol);
  /* r = b − A x (x: the initial guess); r0 = r */
  CLSPH_TRY(apply(ps, op, x, ps->d_q));
  CLSPH_TRY(waxpy(ps, n, ps->d_r, ps->d_b, -1.0, ps->d_q));
  CLSPH_TRY(dot(ps, n, ps->d_r, ps->d_r, &rr));
  res->rnorm = sqrt(rr) / bnorm;
  if (sqrt(rr) <= stop) {
    res->reason = sqrt(rr) <= ps->opt.atol ? PSOLVE_CONVERGED_ATOL : PSOLVE_CONVERGED_RTOL;
    goto done;
  }
  CLSPH_TRY(copy(ps, ps->d_r0, ps->d_r, n));
  CLSPH_TRY(zero(ps, ps->d_p, n));
  CLSPH_TRY(zero(ps, ps->d_v, n));
  double r0norm = sqrt(rr);
  res->reason = PSOLVE_DIVERGED_ITS;
  for (int it = 1; it <= ps->opt.max_it; ++it) {
    res->its = it;
    double rho_new = 0.0;
    CLSPH_TRY(dot(ps, n, ps->d_r0, ps->d_r, &rho_new)); /* ρ' = (r0, r) */
    if (!finite(rho_new)) {
      res->reason = PSOLVE_DIVERGED_NANORINF;
      goto done;
    }
    if (fabs(rho_new) <= tiny * r0norm * sqrt(rr)) { /* breakdown: restart with r0 = r */
      if (restarted_at == it - 1) {
        res->reason = PSOLVE_DIVERGED_BREAKDOWN;
        goto done;
      }
      restarted_at = it;
      ++res->restarts;
      CLSPH_TRY(copy(ps, ps->d_r0, ps->d_r, n));
      CLSPH_TRY(zero(ps, ps->d_p, n));
      CLSPH_TRY(zero(ps, ps->d_v, n));
      r0norm = sqrt(rr);
      rho = alpha = omega = 1.0;
      rho_new = rr;
    }
    double beta = (rho_new / rho) * (alpha / omega);
    real rb = (real)beta, ro = (real)omega; /* p <- r + β (p − ω v) */
    CLSPH_TRY(KERN_SET(ps->k_p, KARG(n), KARG(ps->d_p), KARG(ps->d_r), KARG(rb), KARG(ro),
                       KARG(ps->d_v)));
    CLSPH_TRY(launch(ps, ps->k_p, n));
    CLSPH_TRY(precond(ps, op, ps->d_p, ps->d_ph, ps->d_q)); /* p̂ <- M⁻¹ p */
    CLSPH_TRY(apply(ps, op, ps->d_ph, ps->d_v));            /* v <- A p̂ */
    double r0v = 0.0;
    CLSPH_TRY(dot(ps, n, ps->d_r0, ps->d_v, &r0v));
    if (!finite(r0v) || r0v == 0.0) {
      res->reason = finite(r0v) ? PSOLVE_DIVERGED_BREAKDOWN : PSOLVE_DIVERGED_NANORINF;
      goto done;
    }
    alpha = rho_new / r0v;                                      /* α <- ρ' / (r0, v) */
    CLSPH_TRY(waxpy(ps, n, ps->d_s, ps->d_r, -alpha, ps->d_v)); /* s <- r − α v */
    double ss = 0.0;
    CLSPH_TRY(dot(ps, n, ps->d_s, ps->d_s, &ss));
    if (sqrt(ss) <= stop) { /* x <- x + α p̂ */
      real ra = (real)alpha;
      CLSPH_TRY(KERN_SET(ps->k_axpy, KARG(n), KARG(ra), KARG(ps->d_ph), KARG(x)));
      CLSPH_TRY(launch(ps, ps->k_axpy, n));
      res->rnorm = sqrt(ss) / bnorm;
      res->reason = PSOLVE_CONVERGED_RTOL;
      goto done;
    }
    CLSPH_TRY(precond(ps, op, ps->d_s, ps->d_sh, ps->d_q)); /* ŝ <- M⁻¹ s */
    CLSPH_TRY(apply(ps, op, ps->d_sh, ps->d_t));            /* t <- A ŝ */
    CLSPH_TRY(dot2(ps, n, ps->d_t, ps->d_s, ps->d_t, ps->d_t, d2));
    if (!finite(d2[0]) || !finite(d2[1])) {
      res->reason = PSOLVE_DIVERGED_NANORINF;
      goto done;
    }
    omega = d2[1] > 0.0 ? d2[0] / d2[1] : 0.0; /* ω <- (t, s) / (t, t) */
    real ra = (real)alpha, rw = (real)omega;   /* x <- x + α p̂ + ω ŝ */
    CLSPH_TRY(KERN_SET(ps->k_axpbypz, KARG(n), KARG(x), KARG(ra), KARG(ps->d_ph), KARG(rw),
                       KARG(ps->d_sh)));
    CLSPH_TRY(launch(ps, ps->k_axpbypz, n));
    CLSPH_TRY(waxpy(ps, n, ps->d_r, ps->d_s, -omega, ps->d_t)); /* r <- s − ω t */
    CLSPH_TRY(dot(ps, n, ps->d_r, ps->d_r, &rr));
    res->rnorm = sqrt(rr) / bnorm;
    if (!finite(rr)) {
      res->reason = PSOLVE_DIVERGED_NANORINF;
      goto done;
    }
    if (sqrt(rr) <= stop) {
      res->reason = sqrt(rr) <= ps->opt.atol ? PSOLVE_CONVERGED_ATOL : PSOLVE_CONVERGED_RTOL;
      goto done;
    }
    if (fabs(omega) <= tiny) { /* ω breakdown: the next iteration restarts */
      rho = alpha = omega = 1.0;
      CLSPH_TRY(copy(ps, ps->d_r0, ps->d_r, n));
      CLSPH_TRY(zero(ps, ps->d_p, n));
      CLSPH_TRY(zero(ps, ps->d_v, n));
      r0norm = sqrt(rr);
      ++res->restarts;
      continue;
    }
    rho = rho_new;
  }
done:
  if (st == CLSPH_OK && ps->opt.singular == PSOLVE_MEAN) st = remove_mean(ps, n, x);
  return st;
}

static const char *reason_str(enum psolve_reason r)
{
  switch (r) {
  case PSOLVE_CONVERGED_RTOL:
  case PSOLVE_CONVERGED_ATOL:
    return "converged";
  case PSOLVE_DIVERGED_ITS:
    return "reached the iteration limit";
  case PSOLVE_DIVERGED_BREAKDOWN:
    return "broke down";
  case PSOLVE_DIVERGED_NANORINF:
    return "produced a non-finite value";
  }
  return "?";
}

/* set_up = 0: the stored layout, diagonal and multigrid levels of the last solve serve again */
static enum clsph_status solve(struct psolve *ps, const struct psolve_op *op, cl_mem b, cl_mem x,
                               struct psolve_result *res, int set_up)
{
  enum clsph_status st = CLSPH_OK;
  double t0 = now();
  memset(res, 0, sizeof *res);
  CLSPH_CHECK(op->n <= ps->cap, CLSPH_E_INPUT, "%s solve: %zu unknowns exceed %zu", ps->opt.name,
              op->n, ps->cap);
  if (ps->opt.method == PSOLVE_DIRECT) {
    CLSPH_TRY(psolve_direct(ps, op, b, x, res));
    goto done;
  }
  const int multigrid = ps->opt.precond == PSOLVE_MULTIGRID;
  CLSPH_CHECK(!multigrid || op->grid != NULL, CLSPH_E_INPUT,
              "%s solve: solver_precond = \"multigrid\" needs unknowns that are particles "
              "sorted by a grid, which this operator does not have",
              ps->opt.name);
  if (set_up) {
    if (ps->opt.apply == PSOLVE_STORED || multigrid) CLSPH_TRY(store(ps, op));
    CLSPH_TRY(diagonal(ps, op));
    if (multigrid)
      CLSPH_TRY(mg_setup(&ps->mg, op->grid, op->n, ps->d_row, ps->d_col, ps->d_val,
                         reinforcement(ps), ps->d_dinv));
  }
  CLSPH_TRY(bicgstab(ps, op, b, x, res));
  if (res->reason > 0) {
    ps->failures = 0;
  } else {
    ++ps->failures;
    log_warn("%s solve %s after %d iterations (residual %.3g, tolerance %.3g)", ps->opt.name,
             reason_str(res->reason), res->its, res->rnorm, ps->opt.rtol);
    CLSPH_CHECK(ps->failures < ps->opt.max_failures, CLSPH_E_BLOWUP,
                "the %s solve failed %d times in a row (last residual %.3g): stopping; the "
                "scheme options solver_rtol, solver_max_it and solver_precond set what a solve "
                "must reach and how",
                ps->opt.name, ps->failures, res->rnorm);
  }
done:
  res->seconds = now() - t0;
  return st;
}

enum clsph_status psolve_solve(struct psolve *ps, const struct psolve_op *op, cl_mem b, cl_mem x,
                               struct psolve_result *res)
{
  return solve(ps, op, b, x, res, 1);
}

enum clsph_status psolve_solve_again(struct psolve *ps, const struct psolve_op *op, cl_mem b,
                                     cl_mem x, struct psolve_result *res)
{
  return solve(ps, op, b, x, res, 0);
}

enum clsph_status psolve_assemble(struct psolve *ps, const struct psolve_op *op, size_t **row,
                                  int **col, double **val)
{
  enum clsph_status st = CLSPH_OK;
  const size_t n = op->n;
  cl_uint *r = NULL, *c = NULL;
  real *v = NULL;
  size_t *rows = NULL;
  int *cols = NULL;
  double *vals = NULL;
  CLSPH_TRY(store(ps, op));
  r = malloc((n + 1) * sizeof *r);
  CLSPH_CHECK(r != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(kern_read(ps->dev, ps->d_row, (n + 1) * sizeof *r, r));
  size_t nnz = r[n];
  c = malloc(nnz * sizeof *c);
  v = malloc(nnz * sizeof *v);
  rows = malloc((n + 1) * sizeof *rows);
  cols = malloc(nnz * sizeof *cols);
  vals = malloc(nnz * sizeof *vals);
  CLSPH_CHECK(c && v && rows && cols && vals, CLSPH_E_NOMEM, "out of memory for %zu entries", nnz);
  CLSPH_TRY(kern_read(ps->dev, ps->d_col, nnz * sizeof *c, c));
  CLSPH_TRY(kern_read(ps->dev, ps->d_val, nnz * sizeof *v, v));
  for (size_t i = 0; i <= n; ++i) rows[i] = r[i];
  for (size_t i = 0; i < n; ++i) { /* copy with the columns of each row sorted (insertion) */
    for (size_t k = r[i]; k < r[i + 1]; ++k) {
      int cc = (int)c[k];
      double vv = (double)v[k];
      if (cc == (int)i && ps->opt.singular == PSOLVE_REINFORCE) vv *= 1.0 + ps->opt.reinforce;
      size_t m = k;
      while (m > r[i] && cols[m - 1] > cc) {
        cols[m] = cols[m - 1];
        vals[m] = vals[m - 1];
        --m;
      }
      cols[m] = cc;
      vals[m] = vv;
    }
  }
  *row = rows;
  *col = cols;
  *val = vals;
  rows = NULL;
  cols = NULL;
  vals = NULL;
done:
  free(vals);
  free(cols);
  free(rows);
  free(v);
  free(c);
  free(r);
  return st;
}

void psolve_destroy(struct psolve *ps)
{
  cl_kernel *ks[] = {&ps->k_dot,       &ps->k_dot2,     &ps->k_sum,         &ps->k_axpy,
                     &ps->k_waxpy,     &ps->k_axpbypz,  &ps->k_p,           &ps->k_scale,
                     &ps->k_sweep,     &ps->k_add_diag, &ps->k_shift,       &ps->k_invert,
                     &ps->k_spmv,      &ps->k_csr_diag, &ps->k_scan_blocks, &ps->k_scan_top,
                     &ps->k_scan_apply};
  for (size_t i = 0; i < sizeof ks / sizeof *ks; ++i) {
    if (*ks[i] != NULL) clReleaseKernel(*ks[i]);
    *ks[i] = NULL;
  }
  cl_mem *ms[] = {&ps->d_r,    &ps->d_r0,  &ps->d_p,       &ps->d_v,     &ps->d_s,
                  &ps->d_t,    &ps->d_ph,  &ps->d_sh,      &ps->d_q,     &ps->d_dinv,
                  &ps->d_diag, &ps->d_b,   &ps->d_partial, &ps->d_flags, &ps->d_row,
                  &ps->d_col,  &ps->d_val, &ps->d_count,   &ps->d_block};
  for (size_t i = 0; i < sizeof ms / sizeof *ms; ++i) kern_release(ms[i]);
  mg_destroy(&ps->mg);
  free(ps->h_partial);
  ps->h_partial = NULL;
  kern_reserve(-ps->reserved);
  ps->reserved = 0.0;
}
