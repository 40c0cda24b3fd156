/* lattice.c: lattice particle sets. */
#include "lattice.h"

#include <stdlib.h>
#include <string.h>

#include "clsph_config.h"
#include "rng.h"

enum clsph_status lattice_make(int dim, const int cells[3], double dr, const double lo[3],
                               double jitter, int shuffle, uint64_t seed, struct lattice *out)
{
  enum clsph_status st = CLSPH_OK;
  struct rng r;
  real *pos = NULL;
  CLSPH_CHECK(dim == 2 || dim == 3, CLSPH_E_INPUT, "lattice: dimension %d is not 2 or 3", dim);
  CLSPH_CHECK(dr > 0.0, CLSPH_E_INPUT, "lattice: spacing must be positive, not %g", dr);
  size_t n = 1;
  for (int a = 0; a < dim; ++a) {
    CLSPH_CHECK(cells[a] > 0, CLSPH_E_INPUT, "lattice: %d particles along axis %d", cells[a], a);
    n *= (size_t)cells[a];
  }
  size_t stride = dim == 2 ? 2 : 4;
  pos = calloc(n * stride, sizeof *pos);
  CLSPH_CHECK(pos != NULL, CLSPH_E_NOMEM, "lattice: out of memory for %zu particles", n);
  rng_seed(&r, seed);
  for (size_t i = 0; i < n; ++i) {
    size_t rest = i;
    for (int a = 0; a < dim; ++a) {
      size_t k = rest % (size_t)cells[a];
      rest /= (size_t)cells[a];
      double x = lo[a] + ((double)k + 0.5) * dr;
      if (jitter > 0.0) x += jitter * dr * (rng_uniform(&r) - 0.5);
      pos[i * stride + (size_t)a] = (real)x;
    }
  }
  if (shuffle) { /* Fisher-Yates */
    for (size_t i = n - 1; i > 0; --i) {
      size_t j = (size_t)rng_below(&r, i + 1);
      for (size_t a = 0; a < stride; ++a) {
        real t = pos[i * stride + a];
        pos[i * stride + a] = pos[j * stride + a];
        pos[j * stride + a] = t;
      }
    }
  }
  memset(out, 0, sizeof *out);
  out->dim = dim;
  out->n = n;
  out->stride = stride;
  out->dr = dr;
  for (int a = 0; a < 3; ++a) {
    out->lo[a] = a < dim ? lo[a] : 0.0;
    out->hi[a] = a < dim ? lo[a] + cells[a] * dr : 0.0;
  }
  out->pos = pos;
  pos = NULL;
done:
  free(pos);
  return st;
}

double lattice_x(const struct lattice *l, size_t i, int a)
{
  return (double)((const real *)l->pos)[i * l->stride + (size_t)a];
}

void lattice_free(struct lattice *l)
{
  free(l->pos);
  l->pos = NULL;
}
