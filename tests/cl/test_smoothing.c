/* test_smoothing.c: each smoothing function, evaluated on the device, integrates to 1 in 1, 2
 * and 3 dimensions (Gauss-Legendre quadrature over the radius, panels split where the function is
 * piecewise), its derivative matches a central finite difference, it is zero outside its support
 * and never negative; the forms in lanes (smoothing_wl, smoothing_fl) equal the scalar ones. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "clsph_config.h"
#include "kern.h"
#include "smoothing.h"
#include "tcheck.h"

#define GL_N 20  /* nodes per panel: exact for the polynomial pieces, 1e-15 for the Gaussian */
#define FD_N 400 /* finite-difference sample radii */

/* Gauss-Legendre nodes and weights on [-1, 1] (Newton on the Legendre polynomial). */
static void gauss_legendre(int n, double *x, double *w)
{
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) {
    double z = cos(pi * (i + 0.75) / (n + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = z;
      for (int k = 2; k <= n; ++k) {
        double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1.0);
      double dz = p1 / dp;
      z -= dz;
      if (fabs(dz) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
}

/* Evaluate W and dW/dr at m radii on the device. */
static enum clsph_status eval(const struct dev *dev, cl_kernel k, const struct smoothing *sm,
                              size_t m, const double *r, double *w, double *dwdr)
{
  enum clsph_status st = CLSPH_OK;
  cl_mem d_r = NULL, d_w = NULL, d_d = NULL;
  real *buf = malloc(3 * m * sizeof *buf);
  CLSPH_CHECK(buf != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t i = 0; i < m; ++i) buf[i] = (real)r[i];
  CLSPH_TRY(kern_buffer(dev, m * sizeof(real), buf, &d_r, "r"));
  CLSPH_TRY(kern_buffer(dev, m * sizeof(real), NULL, &d_w, "w"));
  CLSPH_TRY(kern_buffer(dev, m * sizeof(real), NULL, &d_d, "dwdr"));
  cl_uint n = (cl_uint)m;
  const struct smooth_dev smd = smoothing_dev(sm);
  CLSPH_TRY(KERN_SET(k, KARG(smd), KARG(n), KARG(d_r), KARG(d_w), KARG(d_d)));
  CLSPH_TRY(kern_launch(dev, k, m, NULL));
  CLSPH_TRY(kern_read(dev, d_w, m * sizeof(real), buf + m));
  CLSPH_TRY(kern_read(dev, d_d, m * sizeof(real), buf + 2 * m));
  for (size_t i = 0; i < m; ++i) {
    w[i] = (double)buf[m + i];
    dwdr[i] = (double)buf[2 * m + i];
  }
done:
  kern_release(&d_d);
  kern_release(&d_w);
  kern_release(&d_r);
  free(buf);
  return st;
}

/* The largest differences, relative to the largest magnitude, between W and F in lanes and one
 * at a time at m radii (m a multiple of 8). */
static enum clsph_status eval_lanes(const struct dev *dev, cl_kernel k, const struct smoothing *sm,
                                    size_t m, const double *r, double *dw, double *df)
{
  enum clsph_status st = CLSPH_OK;
  cl_mem d[5] = {NULL, NULL, NULL, NULL, NULL};
  real *buf = malloc(5 * m * sizeof *buf);
  CLSPH_CHECK(buf != NULL && m % 8 == 0, CLSPH_E_NOMEM, "out of memory");
  for (size_t i = 0; i < m; ++i) buf[i] = (real)r[i];
  CLSPH_TRY(kern_buffer(dev, m * sizeof(real), buf, &d[0], "r"));
  for (int b = 1; b < 5; ++b) CLSPH_TRY(kern_buffer(dev, m * sizeof(real), NULL, &d[b], "out"));
  int nl = 0;
  CLSPH_TRY(prog_neigh_lanes(dev, &nl)); /* NEIGH_W (real.h) */
  const size_t lanes = (size_t)nl;
  cl_uint nw = (cl_uint)(m / lanes);
  const struct smooth_dev smd = smoothing_dev(sm);
  CLSPH_TRY(
      KERN_SET(k, KARG(smd), KARG(nw), KARG(d[0]), KARG(d[1]), KARG(d[2]), KARG(d[3]), KARG(d[4])));
  CLSPH_TRY(kern_launch(dev, k, m / lanes, NULL));
  for (int b = 1; b < 5; ++b) CLSPH_TRY(kern_read(dev, d[b], m * sizeof(real), buf + b * m));
  double wmax = 0.0, fmax_ = 0.0, ew = 0.0, ef = 0.0;
  for (size_t i = 0; i < m; ++i) {
    wmax = fmax(wmax, fabs((double)buf[3 * m + i]));
    fmax_ = fmax(fmax_, fabs((double)buf[4 * m + i]));
    ew = fmax(ew, fabs((double)buf[m + i] - (double)buf[3 * m + i]));
    ef = fmax(ef, fabs((double)buf[2 * m + i] - (double)buf[4 * m + i]));
  }
  *dw = ew / wmax;
  *df = ef / fmax_;
done:
  for (int b = 0; b < 5; ++b) kern_release(&d[b]);
  free(buf);
  return st;
}

static void check_one(const struct dev *dev, const char *test_src, enum smoothing_kind kind,
                      int dim)
{
  const double pi = 3.14159265358979323846;
  const double h = 0.37; /* any length: the constants scale with it */
  struct smoothing sm;
  struct prog_opts o = {0};
  cl_program prog = NULL;
  cl_kernel k = NULL;
  static const char *const sources[] = {"common/real.h", "common/smoothing.h", NULL};
  const char *name = smoothing_name(kind);
  double gx[GL_N], gw[GL_N];
  int panels = (int)smoothing_qmax(kind);
  size_t m = (size_t)(panels * GL_N);
  double *r = malloc(3 * m * sizeof *r), *w = r + m, *d = r + 2 * m;
  double *fr = malloc(9 * FD_N * sizeof *fr);

  if (smoothing_make(kind, dim, h, &sm) != CLSPH_OK || prog_opts_define_int(&o, "DIM", dim) ||
      smoothing_define(&sm, &o) ||
      prog_build_extra(dev, sources, "tests/cl/smoothing_test.cl", test_src, &o, &prog) ||
      prog_kernel(prog, "test_smoothing_eval", &k)) {
    TC_CHECK(0, "%s %dD: program builds", name, dim);
    goto done;
  }

  /* normalisation: ∫ W dV over the support */
  gauss_legendre(GL_N, gx, gw);
  for (int p = 0; p < panels; ++p)
    for (int i = 0; i < GL_N; ++i) r[p * GL_N + i] = h * (p + 0.5 * (gx[i] + 1.0));
  if (eval(dev, k, &sm, m, r, w, d) != CLSPH_OK) {
    TC_CHECK(0, "%s %dD: evaluation runs", name, dim);
    goto done;
  }
  double integral = 0.0;
  for (int p = 0; p < panels; ++p) {
    for (int i = 0; i < GL_N; ++i) {
      double x = r[p * GL_N + i];
      double shell = dim == 1 ? 2.0 : dim == 2 ? 2.0 * pi * x : 4.0 * pi * x * x;
      integral += 0.5 * h * gw[i] * shell * w[p * GL_N + i];
    }
  }
  /* 1e-6: the quadrature is exact to 1e-14; float evaluation adds ~1e-7 */
  TC_NEAR(integral, 1.0, 1e-6, "%s %dD: integral of W", name, dim);

  /* derivative against a central difference (away from the kinks of the cubic spline at q = 1
   * and the end of the support, where the difference straddles a discontinuous derivative).
   * Tolerance: truncation δ²W'''/6 plus round-off ε W/δ, relative to max |W'|. */
  const double delta = (CLSPH_DOUBLE ? 1e-5 : 2e-3) * h;
  const double tol = CLSPH_DOUBLE ? 1e-7 : 2e-3;
  double *fw = fr + 3 * FD_N, *fd = fr + 6 * FD_N;
  for (int i = 0; i < FD_N; ++i) {
    double x = sm.support * (i + 0.5) / FD_N;
    fr[i] = x;
    fr[FD_N + i] = x + delta;
    fr[2 * FD_N + i] = x - delta;
  }
  if (eval(dev, k, &sm, 3 * FD_N, fr, fw, fd) != CLSPH_OK) {
    TC_CHECK(0, "%s %dD: evaluation runs", name, dim);
    goto done;
  }
  double dmax = 0.0, worst = 0.0, wmin = 0.0;
  for (int i = 0; i < FD_N; ++i) dmax = fmax(dmax, fabs(fd[i]));
  for (int i = 0; i < FD_N; ++i) {
    double q = fr[i] / h;
    wmin = fmin(wmin, fw[i]);
    if (fabs(q - 1.0) < 3 * delta / h || fabs(fr[i] - sm.support) < 3 * delta) continue;
    double fdiff = (fw[FD_N + i] - fw[2 * FD_N + i]) / (2.0 * delta);
    worst = fmax(worst, fabs(fdiff - fd[i]) / dmax);
  }
  TC_NEAR(worst, 0.0, tol, "%s %dD: dW/dr against a central difference (relative to max|dW/dr|)",
          name, dim);
  TC_CHECK(wmin >= 0.0, "%s %dD: W >= 0 (smallest %g)", name, dim, wmin);
  TC_CHECK(fd[0] <= 0.0 && fw[0] > 0.0, "%s %dD: W(0) > 0 and decreasing", name, dim);

  /* compact support: W and its gradient vanish from the support radius on */
  for (int i = 0; i < FD_N; ++i) fr[i] = sm.support * (1.0 + 0.5 * i / FD_N);
  if (eval(dev, k, &sm, FD_N, fr, fw, fd) != CLSPH_OK) {
    TC_CHECK(0, "%s %dD: evaluation runs", name, dim);
    goto done;
  }
  int outside = 0;
  for (int i = 0; i < FD_N; ++i) outside += fw[i] != 0.0 || fd[i] != 0.0;
  TC_CHECK(outside == 0, "%s %dD: W = 0 for r >= %g h (%d nonzero)", name, dim,
           smoothing_qmax(kind), outside);

  /* in lanes (smoothing_wl, smoothing_fl) against one at a time, on radii through the
   * support, the kinks and beyond it: the same formulas, up to the compiler's contractions (a
   * few ε of the largest value) */
  cl_kernel k4 = NULL;
  double lane_w = 0.0, lane_f = 0.0;
  if (prog_kernel(prog, "test_smoothing_eval_lanes", &k4) != CLSPH_OK ||
      eval_lanes(dev, k4, &sm, 3 * FD_N, fr, &lane_w, &lane_f) != CLSPH_OK) {
    TC_CHECK(0, "%s %dD: the lanes run", name, dim);
  } else {
    const double eps = CLSPH_DOUBLE ? 2.2e-16 : 1.2e-7;
    TC_NEAR(lane_w, 0.0, 8 * eps, "%s %dD: smoothing_wl = smoothing_w (relative to max W)", name,
            dim);
    TC_NEAR(lane_f, 0.0, 8 * eps, "%s %dD: smoothing_fl = smoothing_f (relative to max |F|)", name,
            dim);
  }
  if (k4 != NULL) clReleaseKernel(k4);
  printf("%-13s %dD: integral - 1 = %+.2e, derivative error %.2e of max\n", name, dim,
         integral - 1.0, worst);
done:
  if (k != NULL) clReleaseKernel(k);
  if (prog != NULL) clReleaseProgram(prog);
  prog_opts_free(&o);
  free(fr);
  free(r);
}

int main(int argc, char **argv)
{
  struct dev dev;
  if (argc != 2) {
    printf("usage: test_smoothing SMOOTHING_TEST_CL\n");
    return 1;
  }
  tc_open_device(&dev);
  char *src = tc_read_text(argv[1]);
  const enum smoothing_kind kinds[] = {SMOOTHING_WENDLAND_C2, SMOOTHING_CUBIC_SPLINE,
                                       SMOOTHING_GAUSSIAN};
  for (size_t i = 0; i < sizeof kinds / sizeof *kinds; ++i)
    for (int dim = 1; dim <= 3; ++dim) check_one(&dev, src, kinds[i], dim);
  free(src);
  dev_close(&dev);
  return tc_finish("test_smoothing");
}
