/* demo.c: the default scene until the flow solvers exist: a shuffled particle lattice on the unit
 * square, its device neighbour search and reordering, and every common operator applied to
 * f = sin(2πx) cos(2πy) and u = (x², xy), compared with the exact derivatives in the interior. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli.h"
#include "clsph_config.h"
#include "lattice.h"
#include "ops.h"
#include "pset.h"
#include "smoothing.h"

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

struct demo_err {
  double grad, grad_antisym, div, lap; /* largest interior errors, relative to the field's scale */
};

static enum clsph_status demo_measure(const struct dev *dev, const struct grid_spec *spec,
                                      const struct smoothing *sm, int kgc,
                                      const struct lattice *lat, struct demo_err *err,
                                      double *search_s)
{
  enum clsph_status st = CLSPH_OK;
  const double pi = 3.14159265358979323846;
  cl_program prog = NULL;
  struct ops ops = {0};
  struct grid g = {0};
  struct pset ps;
  cl_mem d_flags = NULL, d_L = NULL, d_grad = NULL, d_div = NULL, d_lap = NULL, d_ga = NULL;
  real *f = NULL, *u = NULL, *vol = NULL, *pos = NULL, *grad = NULL, *ga = NULL, *div = NULL,
       *lap = NULL;
  size_t n = lat->n;
  int i_pos, i_vol, i_f, i_u;
  const cl_uint zero = 0;

  pset_init(&ps, n, n);
  f = malloc(n * sizeof *f);
  u = malloc(2 * n * sizeof *u);
  vol = malloc(n * sizeof *vol);
  pos = malloc(2 * n * sizeof *pos);
  grad = malloc(2 * n * sizeof *grad);
  ga = malloc(2 * n * sizeof *ga);
  div = malloc(n * sizeof *div);
  lap = malloc(n * sizeof *lap);
  CLSPH_CHECK(f && u && vol && pos && grad && ga && div && lap, CLSPH_E_NOMEM,
              "demo: out of memory");
  for (size_t i = 0; i < n; ++i) {
    double x = lattice_x(lat, i, 0), y = lattice_x(lat, i, 1);
    f[i] = (real)(sin(2 * pi * x) * cos(2 * pi * y));
    u[2 * i] = (real)(x * x);
    u[2 * i + 1] = (real)(x * y);
    vol[i] = (real)(lat->dr * lat->dr);
  }
  CLSPH_TRY(ops_build(dev, spec, sm, kgc, &prog));
  CLSPH_TRY(ops_create(prog, kgc, &ops));
  CLSPH_TRY(grid_create(dev, prog, spec, n, &g));
  CLSPH_TRY(kern_buffer(dev, sizeof(cl_uint), &zero, &d_flags, "flags"));
  CLSPH_TRY(pset_add(&ps, dev, "pos", 2 * sizeof(real), lat->pos, &i_pos));
  CLSPH_TRY(pset_add(&ps, dev, "vol", sizeof(real), vol, &i_vol));
  CLSPH_TRY(pset_add(&ps, dev, "f", sizeof(real), f, &i_f));
  CLSPH_TRY(pset_add(&ps, dev, "u", 2 * sizeof(real), u, &i_u));
  CLSPH_TRY(kern_buffer(dev, n * 4 * sizeof(real), NULL, &d_L, "L"));
  CLSPH_TRY(kern_buffer(dev, n * 2 * sizeof(real), NULL, &d_grad, "grad"));
  CLSPH_TRY(kern_buffer(dev, n * 2 * sizeof(real), NULL, &d_ga, "grad antisym"));
  CLSPH_TRY(kern_buffer(dev, n * sizeof(real), NULL, &d_div, "div"));
  CLSPH_TRY(kern_buffer(dev, n * sizeof(real), NULL, &d_lap, "lap"));

  double t0 = now();
  CLSPH_TRY(grid_sort(&g, dev, n, pset_mem(&ps, i_pos), NULL, d_flags));
  CLSPH_TRY(pset_reorder(&ps, &g, dev));
  CLSPH_TRY(kern_finish(dev));
  *search_s = now() - t0;

  cl_mem P = pset_mem(&ps, i_pos), V = pset_mem(&ps, i_vol);
  CLSPH_TRY(ops_apply(&ops, OP_CORRECTION, dev, &g, n, P, V, NULL, NULL, d_L, NULL));
  CLSPH_TRY(ops_apply(&ops, OP_GRAD_SYM, dev, &g, n, P, V, d_L, pset_mem(&ps, i_f), d_grad, NULL));
  CLSPH_TRY(
      ops_apply(&ops, OP_GRAD_ANTISYM, dev, &g, n, P, V, d_L, pset_mem(&ps, i_f), d_ga, NULL));
  CLSPH_TRY(ops_apply(&ops, OP_DIV, dev, &g, n, P, V, d_L, pset_mem(&ps, i_u), d_div, NULL));
  CLSPH_TRY(ops_apply(&ops, OP_LAP, dev, &g, n, P, V, d_L, pset_mem(&ps, i_f), d_lap, NULL));
  CLSPH_TRY(kern_read(dev, P, 2 * n * sizeof(real), pos));
  CLSPH_TRY(kern_read(dev, d_grad, 2 * n * sizeof(real), grad));
  CLSPH_TRY(kern_read(dev, d_ga, 2 * n * sizeof(real), ga));
  CLSPH_TRY(kern_read(dev, d_div, n * sizeof(real), div));
  CLSPH_TRY(kern_read(dev, d_lap, n * sizeof(real), lap));

  /* errors over particles farther than one support radius from the edges */
  memset(err, 0, sizeof *err);
  double k = 2 * pi;
  for (size_t i = 0; i < n; ++i) {
    double x = (double)pos[2 * i], y = (double)pos[2 * i + 1];
    if (x < sm->support || y < sm->support || x > 1 - sm->support || y > 1 - sm->support) continue;
    double gx = k * cos(k * x) * cos(k * y), gy = -k * sin(k * x) * sin(k * y);
    double l = -2 * k * k * sin(k * x) * cos(k * y);
    double d = 2 * x + x; /* ∇·(x², xy) = 2x + x */
    double g0 = (double)grad[2 * i], g1 = (double)grad[2 * i + 1];
    double a0 = (double)ga[2 * i], a1 = (double)ga[2 * i + 1];
    err->grad = fmax(err->grad, hypot(g0 - gx, g1 - gy) / k);
    err->grad_antisym = fmax(err->grad_antisym, hypot(a0 - gx, a1 - gy) / k);
    err->div = fmax(err->div, fabs((double)div[i] - d) / 3.0);
    err->lap = fmax(err->lap, fabs((double)lap[i] - l) / (2 * k * k));
  }
done:
  kern_release(&d_lap);
  kern_release(&d_div);
  kern_release(&d_ga);
  kern_release(&d_grad);
  kern_release(&d_L);
  kern_release(&d_flags);
  pset_destroy(&ps);
  grid_destroy(&g);
  ops_destroy(&ops);
  if (prog != NULL) clReleaseProgram(prog);
  free(lap);
  free(div);
  free(ga);
  free(grad);
  free(pos);
  free(vol);
  free(u);
  free(f);
  return st;
}

enum clsph_status demo_run(const struct cli *cli)
{
  enum clsph_status st = CLSPH_OK;
  struct dev dev = {0};
  struct lattice lat = {0};
  struct smoothing sm;
  struct demo_err e[2];
  double search[2];

  int side = (int)lround(1.0 / cli->demo_dr);
  CLSPH_CHECK(side >= 16 && side <= 4000, CLSPH_E_INPUT,
              "--demo-dr %g: use a spacing from 1/4000 to 1/16 of the unit square", cli->demo_dr);
  double dr = 1.0 / side;
  CLSPH_TRY(dev_open(cli->device, CLSPH_DOUBLE, &dev));
  const int cells[3] = {side, side, 1};
  const double lo[3] = {0, 0, 0};
  CLSPH_TRY(lattice_make(2, cells, dr, lo, 0.2, 1, 2024, &lat));
  CLSPH_TRY(smoothing_make(SMOOTHING_WENDLAND_C2, 2, 2.0 * dr, &sm));
  struct grid_spec spec = {
      .dim = 2, .lo = {0, 0, 0}, .hi = {1, 1, 0}, .support = sm.support, .sm = sm};

  printf("clsph demo: %zu particles on the unit square, spacing %g, jittered by 0.2 dr and "
         "shuffled\n",
         lat.n, dr);
  printf("device %d: %s (%s), precision %s, smoothing wendland, h = 2 dr\n", dev.index, dev.name,
         dev.platform_name, CLSPH_PRECISION_NAME);
  for (int kgc = 0; kgc < 2; ++kgc)
    CLSPH_TRY(demo_measure(&dev, &spec, &sm, kgc, &lat, &e[kgc], &search[kgc]));
  printf("neighbour search + reorder of the shuffled set: %.2f ms\n", 1e3 * search[0]);
  printf("largest interior error of f = sin 2πx cos 2πy, u = (x², xy) (relative to the exact "
         "scale):\n");
  printf("  %-34s %12s %12s\n", "operator", "plain", "corrected");
  printf("  %-34s %12.3e %12.3e\n", "gradient, differences (sym)", e[0].grad, e[1].grad);
  printf("  %-34s %12.3e %12.3e\n", "gradient, sums (antisym)", e[0].grad_antisym,
         e[1].grad_antisym);
  printf("  %-34s %12.3e %12.3e\n", "divergence of u", e[0].div, e[1].div);
  printf("  %-34s %12.3e %12.3e\n", "Laplacian (Morris)", e[0].lap, e[1].lap);
done:
  lattice_free(&lat);
  dev_close(&dev);
  return st;
}
