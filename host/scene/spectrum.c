/* spectrum.c: the dominant frequency of a sampled signal, by a direct Fourier sum over uneven
 * samples (the force history of a run is sampled where the time steps land). */
#include "spectrum.h"

#include <math.h>
#include <stdlib.h>

#include "log.h"

struct signal {
  size_t n;
  const double *t, *y;
  double *w, mean, span;
};

/* A(f): the amplitude of the signal's component at frequency f over the record. */
static double amplitude(const struct signal *s, double f)
{
  const double pi = 3.14159265358979323846;
  double c = 0.0, q = 0.0;
  for (size_t k = 0; k < s->n; ++k) {
    const double a = 2.0 * pi * f * (s->t[k] - s->t[0]), v = s->w[k] * (s->y[k] - s->mean);
    c += v * cos(a);
    q += v * sin(a);
  }
  return 2.0 * sqrt(c * c + q * q) / s->span;
}

static int by_value(const void *a, const void *b)
{
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

enum clsph_status spectrum_peak(size_t n, const double *t, const double *y, double f_lo,
                                double f_hi, struct spectrum_peak *out)
{
  enum clsph_status st = CLSPH_OK;
  struct signal s = {n, t, y, NULL, 0.0, 0.0};
  double *spec = NULL;
  CLSPH_CHECK(n >= 8, CLSPH_E_INPUT, "spectrum: %zu samples (at least 8 needed)", n);
  for (size_t k = 1; k < n; ++k)
    CLSPH_CHECK(t[k] > t[k - 1] && isfinite(y[k]) && isfinite(y[k - 1]), CLSPH_E_INPUT,
                "spectrum: sample %zu: times must increase and values be finite", k + 1);
  s.span = t[n - 1] - t[0];
  s.w = malloc(n * sizeof *s.w);
  CLSPH_CHECK(s.w != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t k = 0; k < n; ++k) {
    s.w[k] = 0.5 * ((k > 0 ? t[k] - t[k - 1] : 0.0) + (k + 1 < n ? t[k + 1] - t[k] : 0.0));
    s.mean += s.w[k] * y[k] / s.span;
  }
  const double nyquist = 0.5 * (double)(n - 1) / s.span, df = 0.1 / s.span;
  if (f_lo <= 0.0) f_lo = 3.0 / s.span;
  if (f_hi <= 0.0 || f_hi > nyquist) f_hi = nyquist;
  CLSPH_CHECK(f_hi > f_lo, CLSPH_E_INPUT,
              "spectrum: no frequency between %g and %g (the record spans %g, %zu samples)", f_lo,
              f_hi, s.span, n);
  const size_t m = (size_t)floor((f_hi - f_lo) / df) + 1;
  spec = malloc(m * sizeof *spec);
  CLSPH_CHECK(spec != NULL, CLSPH_E_NOMEM, "out of memory");
  double best = -1.0, fbest = f_lo;
  for (size_t j = 0; j < m; ++j) {
    const double f = f_lo + (double)j * df;
    spec[j] = amplitude(&s, f);
    if (spec[j] > best) {
      best = spec[j];
      fbest = f;
    }
  }
  /* refine within a grid step either side: the spectrum's main lobe is 1 / T wide */
  const double g = 0.5 * (sqrt(5.0) - 1.0);
  double lo = fmax(f_lo, fbest - df), hi = fmin(f_hi, fbest + df);
  for (int it = 0; it < 40; ++it) {
    const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
    if (amplitude(&s, a) > amplitude(&s, b))
      hi = b;
    else
      lo = a;
  }
  const double f = 0.5 * (lo + hi), af = amplitude(&s, f);
  if (af > best) {
    best = af;
    fbest = f;
  }
  qsort(spec, m, sizeof *spec, by_value);
  out->frequency = fbest;
  out->amplitude = best;
  out->median = m % 2 ? spec[m / 2] : 0.5 * (spec[m / 2 - 1] + spec[m / 2]);
  out->mean = s.mean;
done:
  free(s.w);
  free(spec);
  return st;
}
