/* pproblem.c: the manufactured pressure problem (see pproblem.h). */
#include "pproblem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clsph_config.h"
#include "dsolve.h"
#include "rng.h"

static const double pi = 3.14159265358979323846;
#define PP_H     2.0 /* smoothing length, spacings (Wendland C2: support 2h) */
#define PP_GHOST 4   /* Dirichlet rows below y = 0 and above y = 1 (regular problems) */

static double exact(const struct pproblem_spec *s, double x, double y)
{
  return s->singular ? exp(sin(2 * pi * x)) * cos(2 * pi * y) : cos(2 * pi * x) * exp(y);
}

static double laplacian(const struct pproblem_spec *s, double x, double y)
{
  double c = cos(2 * pi * x), k2 = 4 * pi * pi;
  return s->singular ? k2 * exact(s, x, y) * (c * c - sin(2 * pi * x) - 1.0)
                     : (1 - k2) * exact(s, x, y);
}

enum clsph_status pproblem_create(const struct dev *dev, const struct pproblem_spec *spec,
                                  struct pproblem *out)
{
  enum clsph_status st = CLSPH_OK;
  static const char *const sources[] = {OPS_SOURCES, POISSON_SOURCES, DSOLVE_SOURCES, NULL};
  struct pproblem pp;
  struct prog_opts o = {0};
  struct rng r;
  real *pos = NULL, *vol = NULL, *b = NULL;
  cl_uint *dir = NULL, *gid = NULL;
  const cl_uint zero = 0;
  memset(&pp, 0, sizeof pp);
  pp.dev = dev;
  pp.spec = *spec;
  CLSPH_CHECK(spec->side >= 8, CLSPH_E_INPUT, "pproblem: at least 8 particles per side");
  pp.dr = 1.0 / spec->side;
  const int ghost = spec->singular ? 0 : PP_GHOST, rows = pproblem_rows(spec);
  const int slab = spec->row_hi > 0, lo = slab ? spec->row_lo : 0, hi = slab ? spec->row_hi : rows;
  CLSPH_CHECK(!slab || (!spec->singular && 0 <= lo && lo < hi && hi <= rows), CLSPH_E_INPUT,
              "pproblem: rows [%d, %d) are no slab of the %d rows of a regular problem", lo, hi,
              rows);
  pp.rows = rows;
  pp.n = (size_t)spec->side * (size_t)(hi - lo);
  CLSPH_TRY(smoothing_make(SMOOTHING_WENDLAND_C2, 2, PP_H * pp.dr, &pp.sm));
  /* a slab's grid spans its rows and a spacing more each side (the jitter moves a particle by
   * half a spacing at most) */
  struct grid_spec gs = {.dim = 2,
                         .lo = {0, slab ? (lo - ghost - 1) * pp.dr : -ghost * pp.dr},
                         .hi = {1, slab && hi < rows
                                       ? (hi - ghost + 1) * pp.dr
                                       : 1 + ghost * pp.dr + (spec->singular ? 0.0 : spec->air)},
                         .support = pp.sm.support,
                         .sm = pp.sm,
                         .periodic = {1, spec->singular}};
  CLSPH_TRY(grid_define(&gs, &o));
  CLSPH_TRY(smoothing_define(&pp.sm, &o));
  CLSPH_TRY(ops_define(spec->kgc, &o));
  CLSPH_TRY(prog_build(dev, sources, &o, &pp.prog));
  CLSPH_TRY(ops_create(pp.prog, spec->kgc, &pp.ops));
  CLSPH_TRY(grid_create(dev, pp.prog, &gs, pp.n, &pp.g));
  CLSPH_TRY(poisson_op_create(dev, pp.prog, &pp.po));

  /* particles, right-hand side and Dirichlet rows */
  pos = malloc(2 * pp.n * sizeof *pos);
  vol = malloc(pp.n * sizeof *vol);
  b = malloc(pp.n * sizeof *b);
  dir = malloc(pp.n * sizeof *dir);
  gid = malloc(pp.n * sizeof *gid);
  CLSPH_CHECK(pos && vol && b && dir && gid, CLSPH_E_NOMEM, "pproblem: out of memory");
  rng_seed(&r, spec->seed);
  const double scale = spec->scale > 0.0 ? spec->scale : 1.0;
  size_t i = 0;
  for (int k = 0; k < rows; ++k) {
    for (int m = 0; m < spec->side; ++m) {
      double x = (m + 0.5) * pp.dr, y = (k - ghost + 0.5) * pp.dr;
      if (spec->jitter > 0.0) {
        x += spec->jitter * pp.dr * (rng_uniform(&r) - 0.5);
        y += spec->jitter * pp.dr * (rng_uniform(&r) - 0.5);
        x -= floor(x); /* periodic in x (and y when singular) */
        if (spec->singular) y -= floor(y);
      }
      if (k < lo || k >= hi) continue;
      gid[i] = (cl_uint)k * (cl_uint)spec->side + (cl_uint)m;
      pos[2 * i] = (real)x;
      pos[2 * i + 1] = (real)y;
      x = (double)pos[2 * i];
      y = (double)pos[2 * i + 1];
      vol[i] = (real)(scale * pp.dr * pp.dr);
      dir[i] = !spec->singular && (k < ghost || k >= ghost + spec->side);
      b[i] = (real)(dir[i] ? exact(spec, x, y) : scale * laplacian(spec, x, y));
      ++i;
    }
  }
  pset_init(&pp.ps, pp.n, pp.n);
  CLSPH_TRY(pset_add(&pp.ps, dev, "pos", 2 * sizeof(real), pos, &pp.f_pos));
  CLSPH_TRY(pset_add(&pp.ps, dev, "vol", sizeof(real), vol, &pp.f_vol));
  CLSPH_TRY(pset_add(&pp.ps, dev, "dirichlet", sizeof(cl_uint), dir, &pp.f_dir));
  CLSPH_TRY(pset_add(&pp.ps, dev, "b", sizeof(real), b, &pp.f_b));
  CLSPH_TRY(pset_add(&pp.ps, dev, "x", sizeof(real), NULL, &pp.f_x));
  CLSPH_TRY(pset_add(&pp.ps, dev, "gid", sizeof(cl_uint), gid, &pp.f_gid));
  CLSPH_TRY(kern_buffer(dev, sizeof zero, &zero, &pp.d_flags, "flags"));
  CLSPH_TRY(kern_buffer(dev, 4 * pp.n * sizeof(real), NULL, &pp.d_L, "L"));
  CLSPH_TRY(grid_sort(&pp.g, dev, pp.n, pset_mem(&pp.ps, pp.f_pos), NULL, pp.d_flags));
  CLSPH_TRY(pset_reorder(&pp.ps, &pp.g, dev));
  cl_mem P = pset_mem(&pp.ps, pp.f_pos), V = pset_mem(&pp.ps, pp.f_vol);
  if (spec->kgc)
    CLSPH_TRY(ops_apply(&pp.ops, OP_CORRECTION, dev, &pp.g, pp.n, P, V, NULL, NULL, pp.d_L, NULL));
  *out = pp;
  memset(&pp, 0, sizeof pp);
  pproblem_rebind(out); /* after the copy: the operator keeps the address of the grid */
done:
  pproblem_destroy(&pp);
  prog_opts_free(&o);
  free(gid);
  free(dir);
  free(b);
  free(vol);
  free(pos);
  return st;
}

void pproblem_rebind(struct pproblem *pp)
{
  poisson_op_bind(&pp->po, &pp->g, pp->n, pset_mem(&pp->ps, pp->f_pos),
                  pset_mem(&pp->ps, pp->f_vol), pp->spec.kgc ? pp->d_L : NULL,
                  pset_mem(&pp->ps, pp->f_dir));
}

enum clsph_status pproblem_read_n(const struct dev *dev, cl_mem x, size_t n, double *out)
{
  enum clsph_status st = CLSPH_OK;
  real *buf = malloc((n > 0 ? n : 1) * sizeof *buf);
  CLSPH_CHECK(buf != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(kern_read(dev, x, n * sizeof *buf, buf));
  for (size_t i = 0; i < n; ++i) out[i] = (double)buf[i];
done:
  free(buf);
  return st;
}

enum clsph_status pproblem_read(struct pproblem *pp, cl_mem x, double *out)
{
  return pproblem_read_n(pp->dev, x, pp->n, out);
}

enum clsph_status pproblem_error(struct pproblem *pp, cl_mem x, double *err)
{
  enum clsph_status st = CLSPH_OK;
  double *hx = malloc(pp->n * sizeof *hx), *ex = malloc(pp->n * sizeof *ex);
  real *pos = malloc(2 * pp->n * sizeof *pos);
  cl_uint *dir = malloc(pp->n * sizeof *dir);
  CLSPH_CHECK(hx && ex && pos && dir, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(pproblem_read(pp, x, hx));
  CLSPH_TRY(kern_read(pp->dev, pset_mem(&pp->ps, pp->f_pos), 2 * pp->n * sizeof *pos, pos));
  CLSPH_TRY(kern_read(pp->dev, pset_mem(&pp->ps, pp->f_dir), pp->n * sizeof *dir, dir));
  double shift = 0.0, scale = 0.0, e = 0.0;
  size_t m = 0;
  for (size_t i = 0; i < pp->n; ++i) {
    ex[i] = exact(&pp->spec, (double)pos[2 * i], (double)pos[2 * i + 1]);
    scale = fmax(scale, fabs(ex[i]));
    if (!dir[i]) {
      shift += hx[i] - ex[i];
      ++m;
    }
  }
  shift = pp->spec.singular && m > 0 ? shift / (double)m : 0.0;
  for (size_t i = 0; i < pp->n; ++i)
    if (!dir[i]) e = fmax(e, fabs(hx[i] - shift - ex[i]));
  *err = e / scale;
done:
  free(dir);
  free(pos);
  free(ex);
  free(hx);
  return st;
}

void pproblem_destroy(struct pproblem *pp)
{
  kern_release(&pp->d_L);
  kern_release(&pp->d_flags);
  pset_destroy(&pp->ps);
  poisson_op_destroy(&pp->po);
  grid_destroy(&pp->g);
  ops_destroy(&pp->ops);
  if (pp->prog != NULL) clReleaseProgram(pp->prog);
  pp->prog = NULL;
}

int pproblem_reach_rows(const struct pproblem_spec *spec)
{
  /* rows k apart are at least (k − jitter) dr apart, and a pair counts closer than the support
   * (2h): k < 2h/dr + jitter. The correction enters a row through its own L_i only (poisson.cl). */
  return (int)floor(2.0 * PP_H + spec->jitter);
}

int pproblem_rows(const struct pproblem_spec *spec)
{
  return spec->side + (spec->singular ? 0 : 2 * PP_GHOST);
}
