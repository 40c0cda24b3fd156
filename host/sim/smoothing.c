/* smoothing.c: normalisation constants of the smoothing functions (closed forms, in double).
 *   Wendland C2   α = 3/4, 7/(4π), 21/(16π)           in 1, 2, 3 dimensions
 *   cubic spline  α = 2/3, 10/(7π), 1/π
 *   Gaussian      α = 1/(√π erf 3 − 6e⁻⁹), 1/(π(1 − 10e⁻⁹)), 1/(π^{3/2} erf 3 − 42π e⁻⁹),
 *                 the integrals of e^{−s²} − e^{−9} over the ball s ≤ 3 (2-D: Hosseini eq 23). */
#include "smoothing.h"

#include <math.h>
#include <string.h>

static const struct {
  const char *name;
  enum smoothing_kind kind;
} kinds[] = {
    {"wendland", SMOOTHING_WENDLAND_C2},
    {"cubic_spline", SMOOTHING_CUBIC_SPLINE},
    {"gaussian", SMOOTHING_GAUSSIAN},
};

enum clsph_status smoothing_kind_from_name(const char *name, enum smoothing_kind *out)
{
  enum clsph_status st = CLSPH_OK;
  for (size_t i = 0; i < sizeof kinds / sizeof *kinds; ++i) {
    if (strcmp(name, kinds[i].name) == 0) {
      *out = kinds[i].kind;
      goto done;
    }
  }
  CLSPH_CHECK(0, CLSPH_E_INPUT,
              "unknown smoothing function '%s'; known: wendland, cubic_spline, gaussian", name);
done:
  return st;
}

const char *smoothing_name(enum smoothing_kind kind)
{
  for (size_t i = 0; i < sizeof kinds / sizeof *kinds; ++i)
    if (kinds[i].kind == kind) return kinds[i].name;
  return "?";
}

double smoothing_qmax(enum smoothing_kind kind)
{
  return kind == SMOOTHING_GAUSSIAN ? 3.0 : 2.0;
}

enum clsph_status smoothing_make(enum smoothing_kind kind, int dim, double h, struct smoothing *out)
{
  enum clsph_status st = CLSPH_OK;
  const double pi = 3.14159265358979323846;
  const double e9 = exp(-9.0);
  double a = 0.0;
  CLSPH_CHECK(dim >= 1 && dim <= 3, CLSPH_E_INPUT, "dimension must be 1, 2 or 3, not %d", dim);
  CLSPH_CHECK(h > 0.0 && isfinite(h), CLSPH_E_INPUT, "smoothing length must be positive, not %g",
              h);
  switch (kind) {
  case SMOOTHING_WENDLAND_C2:
    a = dim == 1 ? 0.75 : dim == 2 ? 7.0 / (4.0 * pi) : 21.0 / (16.0 * pi);
    break;
  case SMOOTHING_CUBIC_SPLINE:
    a = dim == 1 ? 2.0 / 3.0 : dim == 2 ? 10.0 / (7.0 * pi) : 1.0 / pi;
    break;
  case SMOOTHING_GAUSSIAN:
    a = dim == 1   ? 1.0 / (sqrt(pi) * erf(3.0) - 6.0 * e9)
        : dim == 2 ? 1.0 / (pi * (1.0 - 10.0 * e9))
                   : 1.0 / (pow(pi, 1.5) * erf(3.0) - 42.0 * pi * e9);
    break;
  default:
    CLSPH_CHECK(0, CLSPH_E_INPUT, "unknown smoothing function %d", (int)kind);
  }
  out->kind = kind;
  out->dim = dim;
  out->h = h;
  out->alpha = a / pow(h, dim);
  out->support = smoothing_qmax(kind) * h;
done:
  return st;
}

struct smooth_dev smoothing_dev(const struct smoothing *s)
{
  struct smooth_dev d = {.inv_h = (real)(1.0 / s->h),
                         .alpha = (real)s->alpha,
                         .support = (real)s->support,
                         .support2 = (real)(s->support * s->support)};
  return d;
}

enum clsph_status smoothing_define(const struct smoothing *s, struct prog_opts *o)
{
  return prog_opts_define_int(o, "SMOOTHING", (long)s->kind);
}
