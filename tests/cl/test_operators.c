/* test_operators.c: the common SPH operators on lattices, against exact derivatives and the
 * errors theory predicts.
 *   - With the kernel-gradient correction the gradient and divergence of linear fields are exact
 *     to round-off at every particle, edges and corners included, on a regular and on a jittered
 *     lattice (Oger et al. 2007; Hosseini & Feng eq 25).
 *   - Without it, on a regular lattice: the sum-form gradient of a constant vanishes in the
 *     interior; at a free edge the normal gradient of a linear field is exactly half its interior
 *     value (the columns beyond the edge are missing and the lattice is mirror-symmetric); on the
 *     jittered lattice the gradient is visibly wrong (so the corrected check is not vacuous).
 *   - The Morris Laplacian of x² + y² is 4 in the interior within the lattice quadrature error,
 *     and of a linear field is 0.
 *   - Σ_i V_i (sum-form gradient)_i = 0 for any field (pairwise antisymmetry: momentum
 *     conservation), with and without the correction (Wang et al. eq 19 form).
 *   - On a fully periodic lattice the Shepard sum Σ V W is the same at every particle.
 *   - In 3-D (jittered), the corrected gradient and divergence of linear fields are exact. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clsph_config.h"
#include "lattice.h"
#include "ops.h"
#include "pset.h"
#include "rng.h"
#include "smoothing.h"
#include "tcheck.h"

#define SIDE 40 /* particles per side of the unit square */

/* Results of every operator for one lattice and one correction switch, in sorted order. */
struct run {
  size_t n;
  real *pos, *shep, *grad_lin, *grad_const, *grad_rand_as, *div_lin, *lap_quad, *lap_lin, *vol;
};

static void run_free(struct run *r)
{
  free(r->pos);
  free(r->shep);
  free(r->grad_lin);
  free(r->grad_const);
  free(r->grad_rand_as);
  free(r->div_lin);
  free(r->lap_quad);
  free(r->lap_lin);
  free(r->vol);
  memset(r, 0, sizeof *r);
}

/* linear f = 1 + 2x − 3y + z/2; u = (2x + y, x − 3y, 2z), ∇·u = −1 (2-D), 1 (3-D);
 * quadratic |x|², ∇² = 2 DIM */
static double f_lin(double x, double y, double z)
{
  return 1.0 + 2.0 * x - 3.0 * y + 0.5 * z;
}

static double coord(const struct lattice *lat, size_t i, int a)
{
  return a < lat->dim ? lattice_x(lat, i, a) : 0.0;
}

static int run_ops(const struct dev *dev, const struct lattice *lat, const struct grid_spec *spec,
                   const struct smoothing *sm, int kgc, struct run *out)
{
  enum clsph_status st = CLSPH_OK;
  const size_t n = lat->n, vs = lat->stride, ms = lat->dim == 2 ? 4 : 8;
  cl_program prog = NULL;
  struct ops ops;
  struct grid g;
  struct pset ps;
  struct rng rg;
  cl_mem d_flags = NULL, d_L = NULL, d_s = NULL, d_v = NULL;
  int i_pos, i_vol, i_lin, i_one, i_quad, i_rand, i_u;
  real *a = calloc(4 * n, sizeof *a);
  const cl_uint zero = 0;

  memset(&ops, 0, sizeof ops);
  memset(&g, 0, sizeof g);
  memset(out, 0, sizeof *out);
  pset_init(&ps, n, n);
  out->n = n;
  out->pos = calloc(vs * n, sizeof(real));
  out->vol = calloc(n, sizeof(real));
  out->shep = calloc(n, sizeof(real));
  out->grad_lin = calloc(vs * n, sizeof(real));
  out->grad_const = calloc(vs * n, sizeof(real));
  out->grad_rand_as = calloc(vs * n, sizeof(real));
  out->div_lin = calloc(n, sizeof(real));
  out->lap_quad = calloc(n, sizeof(real));
  out->lap_lin = calloc(n, sizeof(real));
  CLSPH_CHECK(a != NULL && out->lap_lin != NULL, CLSPH_E_NOMEM, "out of memory");

  CLSPH_TRY(ops_build(dev, spec, sm, kgc, &prog));
  CLSPH_TRY(ops_create(prog, kgc, &ops));
  CLSPH_TRY(grid_create(dev, prog, spec, n, &g));
  CLSPH_TRY(kern_buffer(dev, sizeof zero, &zero, &d_flags, "flags"));
  CLSPH_TRY(kern_buffer(dev, ms * n * sizeof(real), NULL, &d_L, "L"));
  CLSPH_TRY(kern_buffer(dev, n * sizeof(real), NULL, &d_s, "scalar out"));
  CLSPH_TRY(kern_buffer(dev, vs * n * sizeof(real), NULL, &d_v, "vector out"));
  CLSPH_TRY(pset_add(&ps, dev, "pos", vs * sizeof(real), lat->pos, &i_pos));
  /* fields from the stored (rounded) positions, so that linear fields are linear to round-off */
  for (size_t i = 0; i < n; ++i) a[i] = (real)pow(lat->dr, lat->dim);
  CLSPH_TRY(pset_add(&ps, dev, "vol", sizeof(real), a, &i_vol));
  for (size_t i = 0; i < n; ++i)
    a[i] = (real)f_lin(coord(lat, i, 0), coord(lat, i, 1), coord(lat, i, 2));
  CLSPH_TRY(pset_add(&ps, dev, "lin", sizeof(real), a, &i_lin));
  for (size_t i = 0; i < n; ++i) a[i] = (real)1.5;
  CLSPH_TRY(pset_add(&ps, dev, "one", sizeof(real), a, &i_one));
  for (size_t i = 0; i < n; ++i) {
    double x = coord(lat, i, 0), y = coord(lat, i, 1), z = coord(lat, i, 2);
    a[i] = (real)(x * x + y * y + z * z);
  }
  CLSPH_TRY(pset_add(&ps, dev, "quad", sizeof(real), a, &i_quad));
  rng_seed(&rg, 99);
  for (size_t i = 0; i < n; ++i) a[i] = (real)(rng_uniform(&rg) - 0.5);
  CLSPH_TRY(pset_add(&ps, dev, "rand", sizeof(real), a, &i_rand));
  for (size_t i = 0; i < n; ++i) {
    double x = coord(lat, i, 0), y = coord(lat, i, 1), z = coord(lat, i, 2);
    a[vs * i] = (real)(2.0 * x + y);
    a[vs * i + 1] = (real)(x - 3.0 * y);
    if (vs == 4) a[vs * i + 2] = (real)(2.0 * z);
  }
  CLSPH_TRY(pset_add(&ps, dev, "u", vs * sizeof(real), a, &i_u));

  CLSPH_TRY(grid_sort(&g, dev, n, pset_mem(&ps, i_pos), NULL, d_flags));
  CLSPH_TRY(pset_reorder(&ps, &g, dev));
  cl_mem P = pset_mem(&ps, i_pos), V = pset_mem(&ps, i_vol);
  const size_t s1 = n * sizeof(real), s2 = vs * n * sizeof(real);
  CLSPH_TRY(kern_read(dev, P, s2, out->pos));
  CLSPH_TRY(kern_read(dev, V, s1, out->vol));
  CLSPH_TRY(ops_apply(&ops, OP_CORRECTION, dev, &g, n, P, V, NULL, NULL, d_L, NULL));
  CLSPH_TRY(ops_apply(&ops, OP_SHEPARD, dev, &g, n, P, V, d_L, NULL, d_s, NULL));
  CLSPH_TRY(kern_read(dev, d_s, s1, out->shep));
  CLSPH_TRY(ops_apply(&ops, OP_GRAD_SYM, dev, &g, n, P, V, d_L, pset_mem(&ps, i_lin), d_v, NULL));
  CLSPH_TRY(kern_read(dev, d_v, s2, out->grad_lin));
  CLSPH_TRY(
      ops_apply(&ops, OP_GRAD_ANTISYM, dev, &g, n, P, V, d_L, pset_mem(&ps, i_one), d_v, NULL));
  CLSPH_TRY(kern_read(dev, d_v, s2, out->grad_const));
  CLSPH_TRY(
      ops_apply(&ops, OP_GRAD_ANTISYM, dev, &g, n, P, V, d_L, pset_mem(&ps, i_rand), d_v, NULL));
  CLSPH_TRY(kern_read(dev, d_v, s2, out->grad_rand_as));
  CLSPH_TRY(ops_apply(&ops, OP_DIV, dev, &g, n, P, V, d_L, pset_mem(&ps, i_u), d_s, NULL));
  CLSPH_TRY(kern_read(dev, d_s, s1, out->div_lin));
  CLSPH_TRY(ops_apply(&ops, OP_LAP, dev, &g, n, P, V, d_L, pset_mem(&ps, i_quad), d_s, NULL));
  CLSPH_TRY(kern_read(dev, d_s, s1, out->lap_quad));
  CLSPH_TRY(ops_apply(&ops, OP_LAP, dev, &g, n, P, V, d_L, pset_mem(&ps, i_lin), d_s, NULL));
  CLSPH_TRY(kern_read(dev, d_s, s1, out->lap_lin));
done:
  kern_release(&d_v);
  kern_release(&d_s);
  kern_release(&d_L);
  kern_release(&d_flags);
  pset_destroy(&ps);
  grid_destroy(&g);
  ops_destroy(&ops);
  if (prog != NULL) clReleaseProgram(prog);
  free(a);
  return st == CLSPH_OK;
}

/* Round-off scale of a gradient of a field of magnitude fmax: ε fmax / h per particle sum. The
 * factor 50 covers the ~45 terms of the sum and the conditioning of the 2x2 correction. */
static double grad_tol(double fmax, double h)
{
  return 100.0 * REAL_EPS * fmax / h;
}

static void check_regular(const struct dev *dev, enum smoothing_kind kind)
{
  const char *name = smoothing_name(kind);
  const double dr = 1.0 / SIDE;
  const double c[2] = {2.0, -3.0};
  struct lattice lat = {0};
  struct smoothing sm;
  struct run r[2];
  const int cells[3] = {SIDE, SIDE, 1};
  const double lo[3] = {0, 0, 0};
  memset(r, 0, sizeof r);
  double h = kind == SMOOTHING_GAUSSIAN ? 1.2 * dr : 2.0 * dr; /* the papers' choices */
  if (lattice_make(2, cells, dr, lo, 0.0, 1, 5, &lat) || smoothing_make(kind, 2, h, &sm)) {
    TC_CHECK(0, "%s: set-up", name);
    goto done;
  }
  struct grid_spec spec = {.dim = 2, .hi = {1, 1, 0}, .support = sm.support, .sm = sm};
  for (int k = 0; k < 2; ++k)
    if (!run_ops(dev, &lat, &spec, &sm, k, &r[k])) {
      TC_CHECK(0, "%s: operators run (kgc %d)", name, k);
      goto done;
    }
  const size_t n = lat.n;
  const double tol = grad_tol(6.0, h);
  double e_corr = 0, e_div = 0, e_const = 0, e_half = 0, e_lap = 0, e_laplin = 0, e_lapc = 0;
  double mid = 0.0, shep = 0.0;
  int n_mid = 0;
  /* interior value of the uncorrected normal gradient (all interior particles agree) */
  for (size_t i = 0; i < n; ++i) {
    double x = (double)r[0].pos[2 * i], y = (double)r[0].pos[2 * i + 1];
    int inner = x > sm.support && x < 1 - sm.support && y > sm.support && y < 1 - sm.support;
    if (inner) {
      mid += (double)r[0].grad_lin[2 * i];
      shep = fmax(shep, fabs((double)r[0].shep[i] - 1.0));
      ++n_mid;
    }
  }
  mid /= n_mid;
  for (size_t i = 0; i < n; ++i) {
    double x = (double)r[0].pos[2 * i], y = (double)r[0].pos[2 * i + 1];
    int inner = x > sm.support && x < 1 - sm.support && y > sm.support && y < 1 - sm.support;
    int left_edge = x < 0.5 * dr + 1e-6 && y > sm.support && y < 1 - sm.support;
    e_corr = fmax(e_corr, hypot((double)r[1].grad_lin[2 * i] - c[0],
                                (double)r[1].grad_lin[2 * i + 1] - c[1]));
    e_div = fmax(e_div, fabs((double)r[1].div_lin[i] + 1.0));
    if (inner) {
      e_const =
          fmax(e_const, hypot((double)r[0].grad_const[2 * i], (double)r[0].grad_const[2 * i + 1]));
      e_lap = fmax(e_lap, fabs((double)r[0].lap_quad[i] - 4.0) / 4.0);
      e_lapc = fmax(e_lapc, fabs((double)r[1].lap_quad[i] - 4.0) / 4.0);
      e_laplin = fmax(e_laplin, fabs((double)r[0].lap_lin[i]));
    }
    if (left_edge) e_half = fmax(e_half, fabs((double)r[0].grad_lin[2 * i] - 0.5 * mid));
  }
  TC_NEAR(e_corr, 0.0, tol, "%s: corrected gradient of a linear field at every particle", name);
  TC_NEAR(e_div, 0.0, tol, "%s: corrected divergence of a linear field at every particle", name);
  TC_NEAR(e_const, 0.0, grad_tol(1.5, h), "%s: sum-form gradient of a constant, interior", name);
  TC_NEAR(e_half, 0.0, tol, "%s: uncorrected normal gradient at a free edge = half the interior",
          name);
  TC_NEAR(mid, 2.0, 2e-2, "%s: uncorrected interior gradient (lattice quadrature error)", name);
  /* the lattice sums differ from the integrals by the kernel's quadrature error on the lattice:
   * below 1% for these kernels at these h (Wendland and cubic 2δr, Gaussian 1.2δr) */
  TC_NEAR(e_lap, 0.0, 1e-2, "%s: Morris Laplacian of x² + y², interior, relative", name);
  TC_NEAR(e_lapc, 0.0, 1e-2, "%s: corrected Laplacian of x² + y², interior, relative", name);
  TC_NEAR(e_laplin, 0.0, 2.0 * grad_tol(6.0, h) / h, "%s: Laplacian of a linear field, interior",
          name);
  TC_NEAR(shep, 0.0, 1e-2, "%s: Shepard sum Σ V W = 1 in the interior", name);
  printf("%-13s corrected grad %.1e, div %.1e | plain: const %.1e, edge-half %.1e, interior grad "
         "%.6f (exact 2), lap %.1e (corr %.1e), lap(lin) %.1e, Shepard-1 %.1e\n",
         name, e_corr, e_div, e_const, e_half, mid, e_lap, e_lapc, e_laplin, shep);
done:
  run_free(&r[0]);
  run_free(&r[1]);
  lattice_free(&lat);
}

static void check_jittered(const struct dev *dev)
{
  const double dr = 1.0 / SIDE;
  struct lattice lat = {0};
  struct smoothing sm;
  struct run r[2];
  const int cells[3] = {SIDE, SIDE, 1};
  const double lo[3] = {0, 0, 0};
  memset(r, 0, sizeof r);
  if (lattice_make(2, cells, dr, lo, 0.4, 1, 11, &lat) ||
      smoothing_make(SMOOTHING_WENDLAND_C2, 2, 2.0 * dr, &sm)) {
    TC_CHECK(0, "jittered: set-up");
    goto done;
  }
  struct grid_spec spec = {
      .dim = 2, .lo = {-dr, -dr, 0}, .hi = {1 + dr, 1 + dr, 0}, .support = sm.support, .sm = sm};
  for (int k = 0; k < 2; ++k)
    if (!run_ops(dev, &lat, &spec, &sm, k, &r[k])) {
      TC_CHECK(0, "jittered: operators run (kgc %d)", k);
      goto done;
    }
  double e[2] = {0, 0}, mom[2][2] = {{0, 0}, {0, 0}}, scale[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    for (size_t i = 0; i < lat.n; ++i) {
      e[k] = fmax(
          e[k], hypot((double)r[k].grad_lin[2 * i] - 2.0, (double)r[k].grad_lin[2 * i + 1] + 3.0));
      double v = (double)r[k].vol[i];
      mom[k][0] += v * (double)r[k].grad_rand_as[2 * i];
      mom[k][1] += v * (double)r[k].grad_rand_as[2 * i + 1];
      scale[k] += v * hypot((double)r[k].grad_rand_as[2 * i], (double)r[k].grad_rand_as[2 * i + 1]);
    }
  }
  TC_NEAR(e[1], 0.0, grad_tol(6.0, sm.h), "jittered: corrected gradient of a linear field");
  TC_CHECK(e[0] > 0.05, "jittered: the uncorrected gradient is visibly wrong (%.3f)", e[0]);
  /* Σ_i V_i G_i sums n·45 terms that cancel in pairs: round-off ε·Σ|terms| */
  for (int k = 0; k < 2; ++k)
    TC_NEAR(hypot(mom[k][0], mom[k][1]), 0.0, 100.0 * REAL_EPS * scale[k],
            "jittered: Σ V (sum-form gradient) = 0 for a random field (kgc %d)", k);
  printf("jittered 0.4dr: corrected grad %.1e, plain grad %.3f, momentum %.1e / %.1e (plain), "
         "%.1e / %.1e (corrected)\n",
         e[1], e[0], hypot(mom[0][0], mom[0][1]), scale[0], hypot(mom[1][0], mom[1][1]), scale[1]);
done:
  run_free(&r[0]);
  run_free(&r[1]);
  lattice_free(&lat);
}

static void check_periodic(const struct dev *dev)
{
  const double dr = 1.0 / SIDE;
  struct lattice lat = {0};
  struct smoothing sm;
  struct run r;
  const int cells[3] = {SIDE, SIDE, 1};
  const double lo[3] = {0, 0, 0};
  memset(&r, 0, sizeof r);
  if (lattice_make(2, cells, dr, lo, 0.0, 1, 3, &lat) ||
      smoothing_make(SMOOTHING_WENDLAND_C2, 2, 2.0 * dr, &sm)) {
    TC_CHECK(0, "periodic: set-up");
    goto done;
  }
  struct grid_spec spec = {
      .dim = 2, .hi = {1, 1, 0}, .support = sm.support, .sm = sm, .periodic = {1, 1}};
  if (!run_ops(dev, &lat, &spec, &sm, 0, &r)) {
    TC_CHECK(0, "periodic: operators run");
    goto done;
  }
  double lo_s = 1e300, hi_s = -1e300;
  for (size_t i = 0; i < lat.n; ++i) {
    lo_s = fmin(lo_s, (double)r.shep[i]);
    hi_s = fmax(hi_s, (double)r.shep[i]);
  }
  TC_NEAR(hi_s - lo_s, 0.0, 50.0 * REAL_EPS, "periodic: Shepard sum equal at every particle");
  printf("periodic: Shepard sum in [%.15f, %.15f]\n", lo_s, hi_s);
done:
  run_free(&r);
  lattice_free(&lat);
}

static void check_3d(const struct dev *dev)
{
  const int side = 14;
  const double dr = 1.0 / side, c[3] = {2.0, -3.0, 0.5};
  struct lattice lat = {0};
  struct smoothing sm;
  struct run r[2];
  const int cells[3] = {side, side, side};
  const double lo[3] = {0, 0, 0};
  memset(r, 0, sizeof r);
  if (lattice_make(3, cells, dr, lo, 0.3, 1, 17, &lat) ||
      smoothing_make(SMOOTHING_WENDLAND_C2, 3, 2.0 * dr, &sm)) {
    TC_CHECK(0, "3-D: set-up");
    goto done;
  }
  struct grid_spec spec = {.dim = 3,
                           .lo = {-dr, -dr, -dr},
                           .hi = {1 + dr, 1 + dr, 1 + dr},
                           .support = sm.support,
                           .sm = sm};
  for (int k = 0; k < 2; ++k)
    if (!run_ops(dev, &lat, &spec, &sm, k, &r[k])) {
      TC_CHECK(0, "3-D: operators run (kgc %d)", k);
      goto done;
    }
  double e_grad = 0, e_div = 0, mom[3] = {0, 0, 0}, scale = 0;
  for (size_t i = 0; i < lat.n; ++i) {
    const real *g = &r[1].grad_lin[4 * i], *a = &r[1].grad_rand_as[4 * i];
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) d2 += ((double)g[k] - c[k]) * ((double)g[k] - c[k]);
    e_grad = fmax(e_grad, sqrt(d2));
    e_div = fmax(e_div, fabs((double)r[1].div_lin[i] - 1.0));
    double v = (double)r[1].vol[i];
    for (int k = 0; k < 3; ++k) mom[k] += v * (double)a[k];
    scale += v * sqrt((double)(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]));
  }
  TC_NEAR(e_grad, 0.0, grad_tol(6.5, sm.h), "3-D jittered: corrected gradient of a linear field");
  TC_NEAR(e_div, 0.0, grad_tol(6.5, sm.h), "3-D jittered: corrected divergence of a linear field");
  TC_NEAR(sqrt(mom[0] * mom[0] + mom[1] * mom[1] + mom[2] * mom[2]), 0.0, 100.0 * REAL_EPS * scale,
          "3-D jittered: Σ V (corrected sum-form gradient) = 0");
  printf("3-D jittered 0.3dr: corrected grad %.1e, div %.1e\n", e_grad, e_div);
done:
  run_free(&r[0]);
  run_free(&r[1]);
  lattice_free(&lat);
}

int main(void)
{
  struct dev dev;
  tc_open_device(&dev);
  check_regular(&dev, SMOOTHING_WENDLAND_C2);
  check_regular(&dev, SMOOTHING_CUBIC_SPLINE);
  check_regular(&dev, SMOOTHING_GAUSSIAN);
  check_jittered(&dev);
  check_periodic(&dev);
  check_3d(&dev);
  dev_close(&dev);
  return tc_finish("test_operators");
}
