/* mg.c: set-up and V-cycle of the aggregation multigrid preconditioner (see mg.h, mg.cl). */
#include "mg.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clsph_config.h"
#include "log.h"

/* Jacobi damping: 2/3 is the classic choice for the 5-point Laplacian; on the particle
 * Laplacian (about 50 neighbours) 0.7 gave the fewest BiCGStab iterations of 0.5-0.9. */
#define MG_OMEGA 0.7

enum clsph_status mg_create(const struct dev *dev, cl_program prog, size_t cap, struct mg *out)
{
  enum clsph_status st = CLSPH_OK;
  struct mg mg;
  memset(&mg, 0, sizeof mg);
  mg.dev = dev;
  mg.omega = MG_OMEGA;
  mg.cap = cap > 0 ? cap : 1;
  struct {
    cl_kernel *k;
    const char *name;
  } ks[] = {{&mg.k_aggregate, "mg_aggregate"},
            {&mg.k_galerkin_csr, "mg_galerkin_csr"},
            {&mg.k_galerkin, "mg_galerkin"},
            {&mg.k_weights, "mg_weights"},
            {&mg.k_damp, "mg_damp"},
            {&mg.k_scale, "blas1_scale"},
            {&mg.k_residual_csr, "mg_residual_csr"},
            {&mg.k_jacobi_csr, "mg_jacobi_csr"},
            {&mg.k_residual, "mg_residual"},
            {&mg.k_jacobi, "mg_jacobi"},
            {&mg.k_restrict_csr, "mg_restrict_csr"},
            {&mg.k_restrict, "mg_restrict"},
            {&mg.k_prolong_csr, "mg_prolong_csr"},
            {&mg.k_prolong, "mg_prolong"},
            {&mg.k_dense, "mg_dense"}};
  for (size_t i = 0; i < sizeof ks / sizeof *ks; ++i)
    CLSPH_TRY(prog_kernel(prog, ks[i].name, ks[i].k));
  CLSPH_TRY(kern_buffer(dev, mg.cap * sizeof(cl_uint), NULL, &mg.d_agg, "multigrid aggregates"));
  cl_mem *vs[] = {&mg.d_dw, &mg.d_res, &mg.d_t};
  for (size_t i = 0; i < sizeof vs / sizeof *vs; ++i)
    CLSPH_TRY(kern_buffer(dev, mg.cap * sizeof(real), NULL, vs[i], "multigrid vector"));
  *out = mg;
  memset(&mg, 0, sizeof mg);
done:
  mg_destroy(&mg);
  return st;
}

static void release_levels(struct mg *mg)
{
  for (int l = 1; l <= mg->nlevels; ++l) {
    struct mg_level *v = &mg->lv[l];
    cl_mem *ms[] = {&v->S, &v->dw, &v->b, &v->x, &v->t};
    for (size_t i = 0; i < sizeof ms / sizeof *ms; ++i) kern_release(ms[i]);
  }
  kern_release(&mg->d_M);
  free(mg->h_S);
  free(mg->h_A);
  free(mg->h_M);
  mg->h_S = NULL;
  mg->h_A = NULL;
  mg->h_M = NULL;
  mg->nlevels = 0;
  mg->grid = NULL;
}

/* The levels of a grid: its cells, then halved along every axis of more than one cell until at
 * most MG_COARSEST cells are left. */
static enum clsph_status size_levels(struct mg *mg, const struct grid *g)
{
  enum clsph_status st = CLSPH_OK;
  const int dim = g->spec.dim, sub = g->spec.sub > 0 ? g->spec.sub : GRID_SUB_DEFAULT;
  release_levels(mg);
  int n[3] = {g->n[0], g->n[1], dim == 3 ? g->n[2] : 1};
  for (int l = 1;; ++l) {
    CLSPH_CHECK(l <= MG_MAX_LEVELS, CLSPH_E_INPUT, "multigrid: more than %d levels", MG_MAX_LEVELS);
    struct mg_level *v = &mg->lv[l];
    const size_t cells = (size_t)n[0] * (size_t)n[1] * (size_t)n[2];
    v->R = l == 1 ? sub : 1;
    const int w = 2 * v->R + 1;
    v->W = dim == 2 ? w * w : w * w * w;
    for (int a = 0; a < 3; ++a) v->n.s[a] = n[a];
    v->n.s[3] = (cl_int)cells;
    mg->nlevels = l;
    CLSPH_TRY(kern_buffer(mg->dev, cells * (size_t)v->W * sizeof(real), NULL, &v->S,
                          "multigrid stencil"));
    cl_mem *vs[] = {&v->dw, &v->b, &v->x, &v->t};
    for (size_t i = 0; i < sizeof vs / sizeof *vs; ++i)
      CLSPH_TRY(kern_buffer(mg->dev, cells * sizeof(real), NULL, vs[i], "multigrid vector"));
    if (cells <= MG_COARSEST || (n[0] == 1 && n[1] == 1 && n[2] == 1)) break;
    for (int a = 0; a < 3; ++a) n[a] = (n[a] + 1) / 2;
  }
  const struct mg_level *c = &mg->lv[mg->nlevels];
  mg->m = (size_t)c->n.s[3];
  CLSPH_TRY(kern_buffer(mg->dev, mg->m * mg->m * sizeof(real), NULL, &mg->d_M,
                        "multigrid coarsest inverse"));
  mg->h_S = malloc(mg->m * (size_t)c->W * sizeof *mg->h_S);
  mg->h_A = malloc(mg->m * mg->m * sizeof *mg->h_A);
  mg->h_M = malloc(mg->m * mg->m * sizeof *mg->h_M);
  CLSPH_CHECK(mg->h_S && mg->h_A && mg->h_M, CLSPH_E_NOMEM, "out of memory");
  mg->grid = g;
done:
  return st;
}

/* Gauss-Jordan inversion with partial pivoting of the m x m matrix a (destroyed) into inv;
 * 0 when a pivot vanishes relative to the largest entry: below 1e-12 in double builds and 1e-5
 * in float builds, whose coefficients carry rounding errors near 1e-7 (an inverse through such a
 * pivot amplifies the singular mode by 1e7 and the float solve diverged). */
static int invert(double *a, double *inv, size_t m)
{
  double big = 0.0;
  for (size_t k = 0; k < m * m; ++k) big = fmax(big, fabs(a[k]));
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) inv[i * m + j] = i == j ? 1.0 : 0.0;
  for (size_t c = 0; c < m; ++c) {
    size_t p = c;
    for (size_t i = c + 1; i < m; ++i)
      if (fabs(a[i * m + c]) > fabs(a[p * m + c])) p = i;
    if (!(fabs(a[p * m + c]) > (CLSPH_DOUBLE ? 1e-12 : 1e-5) * big)) return 0;
    if (p != c) {
      for (size_t j = 0; j < m; ++j) {
        double t = a[c * m + j];
        a[c * m + j] = a[p * m + j];
        a[p * m + j] = t;
        t = inv[c * m + j];
        inv[c * m + j] = inv[p * m + j];
        inv[p * m + j] = t;
      }
    }
    const double d = 1.0 / a[c * m + c];
    for (size_t j = 0; j < m; ++j) {
      a[c * m + j] *= d;
      inv[c * m + j] *= d;
    }
    for (size_t i = 0; i < m; ++i) {
      const double f = a[i * m + c];
      if (i == c || f == 0.0) continue;
      for (size_t j = 0; j < m; ++j) {
        a[i * m + j] -= f * a[c * m + j];
        inv[i * m + j] -= f * inv[c * m + j];
      }
    }
  }
  return 1;
}

/* The coarsest level's dense inverse. An empty cell is an identity row. A singular operator
 * (pure Neumann, solved mean-free) gets a diagonal reinforcement of 1e-6 (then 1e-3): the
 * preconditioner only has to be close to the inverse on the rest of the space. One that stays
 * singular (a zero diagonal: rows that only copy a neighbour's value) gets Jacobi there. */
static enum clsph_status coarsest(struct mg *mg)
{
  enum clsph_status st = CLSPH_OK;
  const struct mg_level *c = &mg->lv[mg->nlevels];
  const size_t m = mg->m;
  const int W = c->W;
  double *dense = NULL, *inv = NULL;
  CLSPH_TRY(kern_read(mg->dev, c->S, m * (size_t)W * sizeof(real), mg->h_S));
  for (size_t k = 0; k < m * (size_t)W; ++k)
    CLSPH_CHECK(isfinite((double)mg->h_S[k]), CLSPH_E_BLOWUP,
                "pressure solve: the operator has a non-finite coefficient (multigrid set-up)");
  dense = malloc(m * m * sizeof *dense);
  inv = malloc(m * m * sizeof *inv);
  CLSPH_CHECK(dense && inv, CLSPH_E_NOMEM, "out of memory");
  for (size_t k = 0; k < m * m; ++k) mg->h_A[k] = 0.0;
  const int w = 2 * c->R + 1;
  const int n[3] = {c->n.s[0], c->n.s[1], c->n.s[2]};
  for (size_t I = 0; I < m; ++I) {
    const int a[3] = {(int)(I % (size_t)n[0]), (int)((I / (size_t)n[0]) % (size_t)n[1]),
                      (int)(I / ((size_t)n[0] * (size_t)n[1]))};
    int empty = 1;
    for (int o = 0; o < W; ++o) {
      const double v = (double)mg->h_S[I * (size_t)W + o];
      if (v == 0.0) continue;
      const int off[3] = {o % w - c->R, (o / w) % w - c->R, W > w * w ? o / (w * w) - c->R : 0};
      int b[3], inside = 1;
      for (int ax = 0; ax < 3; ++ax) {
        b[ax] = a[ax] + off[ax];
        if (b[ax] >= 0 && b[ax] < n[ax]) continue;
        if (!mg->grid->spec.periodic[ax]) inside = 0;
        b[ax] = ((b[ax] % n[ax]) + n[ax]) % n[ax];
      }
      if (!inside) continue;
      mg->h_A[I * m + ((size_t)b[0] + (size_t)n[0] * ((size_t)b[1] + (size_t)n[1] * b[2]))] += v;
      empty = 0;
    }
    if (empty) mg->h_A[I * m + I] = 1.0;
  }
  int ok = 0;
  for (int t = 0; t < 3 && !ok; ++t) {
    const double eps = t == 0 ? 0.0 : t == 1 ? 1e-6 : 1e-3;
    memcpy(dense, mg->h_A, m * m * sizeof *dense);
    for (size_t I = 0; I < m; ++I) dense[I * m + I] *= 1.0 + eps;
    ok = invert(dense, inv, m);
  }
  if (!ok) { /* a singular block (fluid cut off from every Dirichlet row): Jacobi there; the
              * Krylov solve decides whether the system itself can be solved */
    if (!mg->warned_singular)
      log_warn("multigrid: the coarsest operator (%zu cells) is singular; Jacobi on that level", m);
    mg->warned_singular = 1;
    for (size_t i = 0; i < m; ++i)
      for (size_t j = 0; j < m; ++j)
        inv[i * m + j] = i == j && mg->h_A[i * m + i] != 0.0 ? 1.0 / mg->h_A[i * m + i] : 0.0;
  }
  for (size_t k = 0; k < m * m; ++k) mg->h_M[k] = (real)inv[k];
  CLSPH_TRY(kern_write(mg->dev, mg->d_M, m * m * sizeof(real), mg->h_M));
done:
  free(inv);
  free(dense);
  return st;
}

enum clsph_status mg_setup(struct mg *mg, const struct grid *g, size_t n, cl_mem row, cl_mem col,
                           cl_mem val, double eps, cl_mem dinv)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint total = 0;
  CLSPH_CHECK(n <= mg->cap, CLSPH_E_INPUT, "multigrid: %zu unknowns exceed %zu", n, mg->cap);
  CLSPH_TRY(kern_read_at(mg->dev, g->d_start, g->ncells * sizeof(cl_uint), sizeof total, &total));
  CLSPH_CHECK(total == n, CLSPH_E_INPUT,
              "multigrid: the operator has %zu unknowns but its grid sorts %u particles", n,
              (unsigned)total);
  if (mg->grid != g || mg->lv[1].n.s[3] != (cl_int)g->ncells) CLSPH_TRY(size_levels(mg, g));
  const cl_uint ncells = (cl_uint)g->ncells, nn = (cl_uint)n;
  const real e = (real)eps, omega = (real)mg->omega;
  /* fine level: aggregates, damped inverse diagonal */
  CLSPH_TRY(KERN_SET(mg->k_aggregate, KARG(ncells), KARG(g->d_start), KARG(row), KARG(val),
                     KARG(mg->d_agg)));
  CLSPH_TRY(kern_launch(mg->dev, mg->k_aggregate, ncells, NULL));
  CLSPH_TRY(KERN_SET(mg->k_damp, KARG(nn), KARG(omega), KARG(dinv), KARG(mg->d_dw)));
  CLSPH_TRY(kern_launch(mg->dev, mg->k_damp, n, NULL));
  /* Galerkin operators, level by level */
  struct mg_level *v = &mg->lv[1];
  CLSPH_TRY(KERN_SET(mg->k_galerkin_csr, KARG(v->n), KARG(g->d_start), KARG(row), KARG(col),
                     KARG(val), KARG(mg->d_agg), KARG(e), KARG(v->S)));
  CLSPH_TRY(kern_launch(mg->dev, mg->k_galerkin_csr, ncells, NULL));
  for (int l = 1; l <= mg->nlevels; ++l) {
    v = &mg->lv[l];
    const cl_uint cells = (cl_uint)v->n.s[3];
    const cl_int W = v->W;
    if (l > 1) {
      const struct mg_level *f = &mg->lv[l - 1];
      const cl_int Rf = f->R;
      CLSPH_TRY(KERN_SET(mg->k_galerkin, KARG(f->n), KARG(Rf), KARG(f->S), KARG(v->n), KARG(v->S)));
      CLSPH_TRY(kern_launch(mg->dev, mg->k_galerkin, cells, NULL));
    }
    CLSPH_TRY(KERN_SET(mg->k_weights, KARG(cells), KARG(W), KARG(v->S), KARG(omega), KARG(v->dw)));
    CLSPH_TRY(kern_launch(mg->dev, mg->k_weights, cells, NULL));
  }
  CLSPH_TRY(coarsest(mg));
done:
  return st;
}

/* x = dw ∘ b */
static enum clsph_status scale(struct mg *mg, cl_uint n, cl_mem x, cl_mem dw, cl_mem b)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(KERN_SET(mg->k_scale, KARG(n), KARG(x), KARG(dw), KARG(b)));
  CLSPH_TRY(kern_launch(mg->dev, mg->k_scale, n, NULL));
done:
  return st;
}

/* The V(1,1) cycle: down the levels, one damped-Jacobi sweep from zero and the restricted
 * residual; the coarsest solved; up the levels, the prolonged correction and one sweep. */
enum clsph_status mg_apply(struct mg *mg, size_t n, cl_mem row, cl_mem col, cl_mem val, double eps,
                           cl_mem r, cl_mem z)
{
  enum clsph_status st = CLSPH_OK;
  const cl_uint nn = (cl_uint)n, ncells = (cl_uint)mg->grid->ncells;
  const real e = (real)eps;
  const int L = mg->nlevels;
  /* fine level down */
  CLSPH_TRY(scale(mg, nn, mg->d_t, mg->d_dw, r));
  CLSPH_TRY(KERN_SET(mg->k_residual_csr, KARG(nn), KARG(row), KARG(col), KARG(val), KARG(e),
                     KARG(r), KARG(mg->d_t), KARG(mg->d_res)));
  CLSPH_TRY(kern_launch(mg->dev, mg->k_residual_csr, n, NULL));
  CLSPH_TRY(KERN_SET(mg->k_restrict_csr, KARG(ncells), KARG(mg->grid->d_start), KARG(mg->d_agg),
                     KARG(mg->d_res), KARG(mg->lv[1].b)));
  CLSPH_TRY(kern_launch(mg->dev, mg->k_restrict_csr, ncells, NULL));
  /* coarse levels down */
  for (int l = 1; l < L; ++l) {
    struct mg_level *v = &mg->lv[l], *c = &mg->lv[l + 1];
    const cl_uint cells = (cl_uint)v->n.s[3];
    const cl_int R = v->R;
    CLSPH_TRY(scale(mg, cells, v->t, v->dw, v->b));
    CLSPH_TRY(KERN_SET(mg->k_residual, KARG(v->n), KARG(R), KARG(v->S), KARG(v->b), KARG(v->t),
                       KARG(v->x)));
    CLSPH_TRY(kern_launch(mg->dev, mg->k_residual, cells, NULL));
    CLSPH_TRY(KERN_SET(mg->k_restrict, KARG(v->n), KARG(v->x), KARG(c->n), KARG(c->b)));
    CLSPH_TRY(kern_launch(mg->dev, mg->k_restrict, (size_t)c->n.s[3], NULL));
  }
  /* coarsest */
  {
    const struct mg_level *c = &mg->lv[L];
    const cl_uint m = (cl_uint)mg->m;
    CLSPH_TRY(KERN_SET(mg->k_dense, KARG(m), KARG(mg->d_M), KARG(c->b), KARG(c->x)));
    CLSPH_TRY(kern_launch(mg->dev, mg->k_dense, m, NULL));
  }
  /* coarse levels up: t += P x_{l+1}, then x_l = t + dw (b − A t) */
  for (int l = L - 1; l >= 1; --l) {
    struct mg_level *v = &mg->lv[l], *c = &mg->lv[l + 1];
    const cl_uint cells = (cl_uint)v->n.s[3];
    const cl_int R = v->R;
    CLSPH_TRY(KERN_SET(mg->k_prolong, KARG(v->n), KARG(v->t), KARG(c->n), KARG(c->x)));
    CLSPH_TRY(kern_launch(mg->dev, mg->k_prolong, cells, NULL));
    CLSPH_TRY(KERN_SET(mg->k_jacobi, KARG(v->n), KARG(R), KARG(v->S), KARG(v->dw), KARG(v->b),
                       KARG(v->t), KARG(v->x)));
    CLSPH_TRY(kern_launch(mg->dev, mg->k_jacobi, cells, NULL));
  }
  /* fine level up */
  CLSPH_TRY(
      KERN_SET(mg->k_prolong_csr, KARG(nn), KARG(mg->d_agg), KARG(mg->lv[1].x), KARG(mg->d_t)));
  CLSPH_TRY(kern_launch(mg->dev, mg->k_prolong_csr, n, NULL));
  CLSPH_TRY(KERN_SET(mg->k_jacobi_csr, KARG(nn), KARG(row), KARG(col), KARG(val), KARG(e),
                     KARG(mg->d_dw), KARG(r), KARG(mg->d_t), KARG(z)));
  CLSPH_TRY(kern_launch(mg->dev, mg->k_jacobi_csr, n, NULL));
done:
  return st;
}

void mg_destroy(struct mg *mg)
{
  release_levels(mg);
  cl_kernel *ks[] = {
      &mg->k_aggregate,    &mg->k_galerkin_csr, &mg->k_galerkin,    &mg->k_weights,  &mg->k_damp,
      &mg->k_scale,        &mg->k_residual_csr, &mg->k_jacobi_csr,  &mg->k_residual, &mg->k_jacobi,
      &mg->k_restrict_csr, &mg->k_restrict,     &mg->k_prolong_csr, &mg->k_prolong,  &mg->k_dense};
  for (size_t i = 0; i < sizeof ks / sizeof *ks; ++i) {
    if (*ks[i] != NULL) clReleaseKernel(*ks[i]);
    *ks[i] = NULL;
  }
  cl_mem *ms[] = {&mg->d_agg, &mg->d_dw, &mg->d_res, &mg->d_t};
  for (size_t i = 0; i < sizeof ms / sizeof *ms; ++i) kern_release(ms[i]);
}
