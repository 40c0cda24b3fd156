/* test_unit.c: host-only checks (no OpenCL device needed): status names, build options that
 * carry reals exactly, smoothing constants and input checks, grid input checks, the seeded
 * random generator and lattices, the spectral peak of a sampled signal. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grid.h"
#include "psolve.h"
#include "lattice.h"
#include "rng.h"
#include "smoothing.h"
#include "spectrum.h"
#include "tcheck.h"

static void check_status(void)
{
  for (int a = CLSPH_OK; a <= CLSPH_E_BLOWUP; ++a) {
    TC_CHECK(strncmp(clsph_status_str((enum clsph_status)a), "CLSPH_", 6) == 0, "status %d named",
             a);
    for (int b = CLSPH_OK; b < a; ++b)
      TC_CHECK(strcmp(clsph_status_str((enum clsph_status)a),
                      clsph_status_str((enum clsph_status)b)) != 0,
               "status names %d and %d differ", a, b);
  }
  TC_CHECK(strcmp(clsph_status_str((enum clsph_status)999), "CLSPH_E_UNKNOWN") == 0,
           "unknown status named");
}

static void check_options(void)
{
  struct prog_opts o = {0};
  const double v = 0.1 + 1.0 / 3.0;
  TC_CHECK(prog_opts_define_real(&o, "X", v) == CLSPH_OK, "define a real");
  TC_CHECK(prog_opts_define_int(&o, "N", -7) == CLSPH_OK, "define an integer");
  TC_CHECK(prog_opts_define(&o, "FLAG", NULL) == CLSPH_OK, "define a flag");
  const char *p = strstr(o.text, "-D X=R(");
  TC_CHECK(p != NULL, "real option text: %s", o.text);
  if (p != NULL) TC_CHECK(strtod(p + 7, NULL) == v, "the real survives the option text exactly");
  TC_CHECK(strstr(o.text, "-D N=-7") != NULL && strstr(o.text, "-D FLAG") != NULL,
           "integer and flag options: %s", o.text);
  prog_opts_free(&o);
}

static void check_smoothing(void)
{
  const double pi = 3.14159265358979323846;
  struct smoothing s;
  enum smoothing_kind k;
  TC_CHECK(smoothing_make(SMOOTHING_WENDLAND_C2, 2, 0.5, &s) == CLSPH_OK, "wendland 2-D");
  TC_NEAR(s.alpha, 7.0 / (4.0 * pi) / 0.25, 1e-15, "Wendland α_2D/h² (Leroy eq 1)");
  TC_NEAR(s.support, 1.0, 0.0, "Wendland support 2h");
  TC_CHECK(smoothing_make(SMOOTHING_GAUSSIAN, 2, 1.0, &s) == CLSPH_OK, "gaussian 2-D");
  TC_NEAR(s.alpha, 1.0 / (pi * (1.0 - 10.0 * exp(-9.0))), 1e-15, "Gaussian α_2D (Hosseini eq 23)");
  TC_NEAR(s.support, 3.0, 0.0, "Gaussian support 3h");
  TC_CHECK(smoothing_make(SMOOTHING_CUBIC_SPLINE, 4, 1.0, &s) == CLSPH_E_INPUT,
           "dimension 4 refused");
  TC_CHECK(smoothing_make(SMOOTHING_CUBIC_SPLINE, 2, 0.0, &s) == CLSPH_E_INPUT, "h = 0 refused");
  TC_CHECK(smoothing_make(SMOOTHING_CUBIC_SPLINE, 2, NAN, &s) == CLSPH_E_INPUT, "h = NaN refused");
  TC_CHECK(smoothing_kind_from_name("gaussian", &k) == CLSPH_OK && k == SMOOTHING_GAUSSIAN,
           "name gaussian");
  TC_CHECK(smoothing_kind_from_name("quintic", &k) == CLSPH_E_INPUT, "unknown name refused");
}

static void check_grid_input(void)
{
  struct grid g;
  struct dev dev;
  memset(&dev, 0, sizeof dev);
  /* every one of these is refused before any device call, so no device is needed */
  struct grid_spec narrow = {.dim = 2, .hi = {0.249, 1, 0}, .support = 0.1, .periodic = {1, 0}};
  TC_CHECK(grid_create(&dev, NULL, &narrow, 10, &g) == CLSPH_E_INPUT,
           "a periodic axis shorter than 2.5 support radii is refused");
  struct grid_spec empty = {.dim = 2, .lo = {1, 0, 0}, .hi = {1, 1, 0}, .support = 0.1};
  TC_CHECK(grid_create(&dev, NULL, &empty, 10, &g) == CLSPH_E_INPUT, "an empty domain is refused");
  struct grid_spec zero = {.dim = 2, .hi = {1, 1, 0}, .support = 0.0};
  TC_CHECK(grid_create(&dev, NULL, &zero, 10, &g) == CLSPH_E_INPUT, "a zero cell side is refused");
  struct grid_spec huge = {.dim = 3, .hi = {1, 1, 1}, .support = 1e-4};
  TC_CHECK(grid_create(&dev, NULL, &huge, 10, &g) == CLSPH_E_INPUT, "1e12 cells are refused");
  struct grid_spec d4 = {.dim = 4, .hi = {1, 1, 1}, .support = 0.1};
  TC_CHECK(grid_create(&dev, NULL, &d4, 10, &g) == CLSPH_E_INPUT, "dimension 4 is refused");
}

static void check_rng_lattice(void)
{
  struct rng a, b;
  rng_seed(&a, 42);
  rng_seed(&b, 42);
  int same = 1;
  double sum = 0.0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    double x = rng_uniform(&a);
    same &= x == rng_uniform(&b) && x >= 0.0 && x < 1.0;
    sum += x;
  }
  TC_CHECK(same, "same seed, same sequence, in [0, 1)");
  /* mean of n uniforms: σ = 1/sqrt(12 n); 5σ */
  TC_NEAR(sum / n, 0.5, 5.0 / sqrt(12.0 * n), "uniform mean");
  struct lattice l;
  const int cells[3] = {7, 5, 1};
  const double lo[3] = {1, 2, 0};
  TC_CHECK(lattice_make(2, cells, 0.1, lo, 0.0, 1, 1, &l) == CLSPH_OK && l.n == 35,
           "7 x 5 lattice");
  double xmin = 1e9, ymax = -1e9;
  for (size_t i = 0; i < l.n; ++i) {
    xmin = fmin(xmin, lattice_x(&l, i, 0));
    ymax = fmax(ymax, lattice_x(&l, i, 1));
  }
  TC_NEAR(xmin, 1.05, 1e-6, "first column half a spacing from the edge");
  TC_NEAR(ymax, 2.45, 1e-6, "last row half a spacing from the edge");
  lattice_free(&l);
  TC_CHECK(lattice_make(2, cells, -0.1, lo, 0.0, 0, 1, &l) == CLSPH_E_INPUT,
           "negative spacing refused");
}

static void check_solver_options(void)
{
  struct psolve_options o;
  psolve_defaults(&o);
  TC_CHECK(o.method == PSOLVE_BICGSTAB && o.precond == PSOLVE_MULTIGRID && o.max_it > 0,
           "solver defaults: BiCGStab with the multigrid preconditioner");
  TC_CHECK(psolve_set(&o, "precond", "jacobi", 0) == CLSPH_OK && o.precond == PSOLVE_JACOBI,
           "solver_precond = \"jacobi\"");
  TC_CHECK(psolve_set(&o, "precond", "amg", 0) == CLSPH_E_INPUT,
           "an unknown preconditioner is refused");
  TC_CHECK(psolve_set(&o, "solver", "direct", 0) == CLSPH_OK && o.method == PSOLVE_DIRECT,
           "solver = \"direct\" selects UMFPACK");
  TC_CHECK(psolve_set(&o, "rtol", NULL, 1e-6) == CLSPH_OK && o.rtol == 1e-6, "solver_rtol");
  TC_CHECK(psolve_set(&o, "solver", "gmres", 0) == CLSPH_E_INPUT, "an unknown solver is refused");
  TC_CHECK(psolve_set(&o, "rtol", NULL, 2.0) == CLSPH_E_INPUT, "rtol >= 1 is refused");
  TC_CHECK(psolve_set(&o, "max_it", NULL, 0) == CLSPH_E_INPUT, "max_it 0 is refused");
  TC_CHECK(psolve_set(&o, "singular", "mean", 0) == CLSPH_OK && o.singular == PSOLVE_MEAN,
           "solver_singular = \"mean\"");
  TC_CHECK(psolve_set(&o, "singular", "project", 0) == CLSPH_OK && o.singular == PSOLVE_PROJECT,
           "solver_singular = \"project\"");
  TC_CHECK(psolve_set(&o, "singular", "pin", 0) == CLSPH_E_INPUT,
           "an unknown solver_singular is refused");
  TC_CHECK(psolve_set(&o, "colour", "red", 0) == CLSPH_E_INPUT, "an unknown option is refused");
  TC_CHECK(o.group_max == PSOLVE_GROUP_MAX, "solver_group_max defaults to %d", PSOLVE_GROUP_MAX);
  TC_CHECK(psolve_set(&o, "group_max", NULL, 0) == CLSPH_OK && o.group_max == 0,
           "solver_group_max = 0: never one group");
  TC_CHECK(psolve_set(&o, "group_max", NULL, 2000) == CLSPH_OK && o.group_max == 2000,
           "solver_group_max = 2000");
  TC_CHECK(psolve_set(&o, "group_max", NULL, -1) == CLSPH_E_INPUT &&
               psolve_set(&o, "group_max", NULL, 2.5) == CLSPH_E_INPUT &&
               psolve_set(&o, "group_max", NULL, NAN) == CLSPH_E_INPUT &&
               psolve_set(&o, "group_max", NULL, 1e8) == CLSPH_E_INPUT,
           "solver_group_max below 0, fractional, not a number or above 1e7 is refused");
}

/* The dominant frequency of a sampled signal (vortex shedding from a lift history): a sinusoid
 * in noise, sampled at uneven times as a run's force history is, and noise alone. */
static void check_spectrum(void)
{
  const double pi = 3.14159265358979323846, f0 = 0.137, a0 = 0.3;
  enum { N = 1200 };
  static double t[N], y[N], noise[N];
  struct rng r;
  rng_seed(&r, 42);
  double tk = 10.0;
  for (int k = 0; k < N; ++k) {
    t[k] = tk;
    tk += 0.05 * (0.8 + 0.4 * rng_uniform(&r)); /* steps of 0.04 to 0.06 */
    double g = 0.0; /* noise of standard deviation a0 (sum of 12 uniforms − 6) */
    for (int j = 0; j < 12; ++j) g += rng_uniform(&r);
    noise[k] = a0 * (g - 6.0);
    y[k] = 1.5 + a0 * sin(2.0 * pi * f0 * t[k] + 0.4) + noise[k];
  }
  struct spectrum_peak p;
  TC_CHECK(spectrum_peak(N, t, y, 0.0, 0.0, &p) == CLSPH_OK, "spectrum of a sinusoid in noise");
  /* the record spans about 8 periods of 1/f0 = 7.3: the peak's width is 1/T = 0.017, its
   * centre is found to within an eighth of that; white noise of deviation σ = a0 has a spectral
   * amplitude of about 2σ/√N = 0.017 at any frequency, which adds to or takes from the
   * sinusoid's: 2.5 of those */
  TC_NEAR(p.frequency, f0, 2e-3, "dominant frequency of a sinusoid in noise");
  TC_NEAR(p.amplitude, a0, 2.5 * 2.0 * a0 / sqrt((double)N), "its amplitude");
  TC_NEAR(p.mean, 1.5, 0.02, "the time-weighted mean");
  TC_CHECK(p.amplitude > 4.0 * p.median, "the peak stands out of the noise: %g vs median %g",
           p.amplitude, p.median);
  /* noise alone: no frequency stands 4 times above the median (the criterion of the square
   * cylinder's Strouhal number) */
  TC_CHECK(spectrum_peak(N, t, noise, 0.0, 0.0, &p) == CLSPH_OK, "spectrum of noise");
  TC_CHECK(p.amplitude < 4.0 * p.median, "noise has no peak: %g vs median %g", p.amplitude,
           p.median);
  TC_CHECK(p.median > 0.0 && p.amplitude < 0.1, "noise floor %g, peak %g", p.median, p.amplitude);
  /* inputs refused */
  TC_CHECK(spectrum_peak(4, t, y, 0.0, 0.0, &p) == CLSPH_E_INPUT, "4 samples refused");
  const double back[8] = {0, 1, 2, 3, 3, 4, 5, 6};
  TC_CHECK(spectrum_peak(8, back, y, 0.0, 0.0, &p) == CLSPH_E_INPUT, "repeated time refused");
  TC_CHECK(spectrum_peak(N, t, y, 20.0, 0.0, &p) == CLSPH_E_INPUT,
           "a range above the Nyquist frequency refused");
}

int main(void)
{
  log_set_level(LOG_ERROR);
  check_status();
  check_options();
  check_smoothing();
  check_grid_input();
  check_rng_lattice();
  check_solver_options();
  check_spectrum();
  return tc_finish("test_unit");
}
