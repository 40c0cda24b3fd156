/* walls.c: USAW wall segments on the device (see walls.h). */
#include "walls.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clsph_config.h"
#include "geometry.h"
#include "scene.h"
#include "sim.h"

enum clsph_status usaw_wall_distance_floor(const struct scene *sc, double spacings, double *d_min)
{
  enum clsph_status st = CLSPH_OK;
  double f = spacings;
  for (int i = 0; i < sc->noptions; ++i) {
    const struct scene_option *o = &sc->options[i];
    if (strcmp(o->key, "wall_distance_floor") != 0) continue;
    CLSPH_CHECK(o->is_number, CLSPH_E_INPUT,
                "%s: wall_distance_floor must be a number of spacings, not \"%s\"", sc->case_path,
                o->text);
    CLSPH_CHECK(o->number > 0.0 && o->number <= 1.0, CLSPH_E_INPUT,
                "%s: wall_distance_floor must be in (0, 1] spacings (the smallest wall distance of "
                "the viscous wall term; 1 is the paper's eq 17), not %g",
                sc->case_path, o->number);
    f = o->number;
  }
  *d_min = f * sc->dr;
done:
  return st;
}

enum clsph_status usaw_walls_create(const struct dev *dev, cl_program prog,
                                    const struct usaw_segments *segs, const struct grid_spec *box,
                                    struct usaw_walls *out)
{
  enum clsph_status st = CLSPH_OK;
  struct usaw_walls w;
  real *buf = NULL;
  cl_uint *ids = NULL;
  const cl_uint zero = 0;
  const size_t n = segs->n, vs = (size_t)(box->dim == 2 ? 2 : 4);
  memset(&w, 0, sizeof w);
  CLSPH_CHECK(box->dim == 2, CLSPH_E_UNSUPPORTED, "USAW walls are 2-D");
  buf = calloc(4 * vs * (n > 0 ? n : 1), sizeof *buf);
  CLSPH_CHECK(buf != NULL, CLSPH_E_NOMEM, "out of memory for %zu segments", n);
  double lmax = 0.0;
  for (size_t s = 0; s < n; ++s)
    lmax =
        fmax(lmax, hypot(segs->b[2 * s] - segs->a[2 * s], segs->b[2 * s + 1] - segs->a[2 * s + 1]));
  /* the segments' grid: a segment within the support of a particle has its midpoint within
   * support + length/2 of it */
  struct grid_spec gs = *box;
  gs.support = box->support + 0.5 * lmax;
  CLSPH_TRY(grid_create(dev, prog, &gs, n > 0 ? n : 1, &w.g));
  real *mid = buf, *a = buf + vs * n, *b = buf + 2 * vs * n, *nn = buf + 3 * vs * n;
  for (size_t s = 0; s < n; ++s) {
    for (size_t c = 0; c < 2; ++c) {
      a[vs * s + c] = (real)segs->a[2 * s + c];
      b[vs * s + c] = (real)segs->b[2 * s + c];
      nn[vs * s + c] = (real)segs->normal[2 * s + c];
      mid[vs * s + c] = (real)(0.5 * (segs->a[2 * s + c] + segs->b[2 * s + c]));
    }
  }
  pset_init(&w.ps, n, n > 0 ? n : 1);
  CLSPH_TRY(pset_add(&w.ps, dev, "mid", vs * sizeof(real), mid, &w.f_mid));
  CLSPH_TRY(pset_add(&w.ps, dev, "a", vs * sizeof(real), a, &w.f_a));
  CLSPH_TRY(pset_add(&w.ps, dev, "b", vs * sizeof(real), b, &w.f_b));
  CLSPH_TRY(pset_add(&w.ps, dev, "n", vs * sizeof(real), nn, &w.f_n));
  ids = calloc(2 * (n > 0 ? n : 1), sizeof *ids);
  CLSPH_CHECK(ids != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t s = 0; segs->v != NULL && s < n; ++s) {
    ids[s] = (cl_uint)segs->v[2 * s];
    ids[n + s] = (cl_uint)segs->v[2 * s + 1];
  }
  CLSPH_TRY(pset_add(&w.ps, dev, "v1", sizeof(cl_uint), ids, &w.f_v1));
  CLSPH_TRY(pset_add(&w.ps, dev, "v2", sizeof(cl_uint), ids + n, &w.f_v2));
  for (size_t s = 0; s < n; ++s) ids[s] = (cl_uint)s; /* the order given, kept through the sort */
  CLSPH_TRY(pset_add(&w.ps, dev, "index", sizeof(cl_uint), ids, &w.f_index));
  /* the bits, a counter and the deepest crossing (as the sim's flags: usaw_walls_gamma may be
   * given this buffer) */
  const cl_uint zeros[3] = {0, 0, 0};
  CLSPH_TRY(kern_buffer(dev, sizeof zeros, zeros, &w.d_flags, "segment flags"));
  CLSPH_TRY(prog_kernel(prog, "usaw_gamma", &w.k_gamma));
  if (n > 0) {
    CLSPH_TRY(grid_sort(&w.g, dev, n, pset_mem(&w.ps, w.f_mid), w.d_flags));
    CLSPH_TRY(pset_reorder(&w.ps, &w.g, dev));
  } else {
    CLSPH_TRY(kern_fill(dev, w.g.d_start, &zero, sizeof zero, (w.g.ncells + 1) * sizeof zero));
  }
  *out = w;
  memset(&w, 0, sizeof w);
done:
  usaw_walls_destroy(&w);
  free(ids);
  free(buf);
  return st;
}

enum clsph_status usaw_walls_gamma(struct usaw_walls *w, const struct dev *dev, size_t n,
                                   cl_mem d_pos, cl_mem d_theta, cl_mem d_gamma,
                                   cl_mem d_grad_gamma, cl_mem d_flags)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint np = (cl_uint)n;
  cl_mem a = pset_mem(&w->ps, w->f_a), b = pset_mem(&w->ps, w->f_b), nn = pset_mem(&w->ps, w->f_n);
  CLSPH_TRY(KERN_SET(w->k_gamma, KARG(np), KARG(w->g.geom), KARG(w->g.d_start), KARG(a), KARG(b),
                     KARG(nn), KARG(d_pos), KARG(d_theta), KARG(d_gamma), KARG(d_grad_gamma),
                     KARG(d_flags)));
  CLSPH_TRY(kern_launch(dev, w->k_gamma, n, NULL));
done:
  return st;
}

enum clsph_status usaw_walls_from_geom(const struct dev *dev, cl_program prog,
                                       const struct geom *geo, const struct grid_spec *box,
                                       struct usaw_walls *out)
{
  enum clsph_status st = CLSPH_OK;
  double *ab = calloc(4 * (geo->nseg + 1), sizeof *ab);
  CLSPH_CHECK(ab != NULL, CLSPH_E_NOMEM, "out of memory for %zu segments", geo->nseg);
  /* The ends are the vertex particles' positions. On a periodic axis those are wrapped into
   * [lo, hi), so a segment that crosses the boundary takes the image of its second end nearest
   * the first, and both ends move by a period where needed to put the midpoint (which bins the
   * segment) in [lo, hi); the kernels add the image shift of the midpoint's cell to both ends. */
  for (size_t s = 0; s < geo->nseg; ++s)
    for (size_t c = 0; c < 2; ++c) {
      double xa = geo->x[2 * geo->seg_v[2 * s] + c], xb = geo->x[2 * geo->seg_v[2 * s + 1] + c];
      if (box->periodic[c]) {
        const double len = box->hi[c] - box->lo[c];
        xb -= len * round((xb - xa) / len);
        const double shift = len * floor((0.5 * (xa + xb) - box->lo[c]) / len);
        xa -= shift;
        xb -= shift;
      }
      ab[2 * s + c] = xa;
      ab[2 * geo->nseg + 2 * s + c] = xb;
    }
  struct usaw_segments segs = {geo->nseg, ab, ab + 2 * geo->nseg, geo->seg_normal, geo->seg_v};
  CLSPH_TRY(usaw_walls_create(dev, prog, &segs, box, out));
done:
  free(ab);
  return st;
}

enum clsph_status usaw_wall_force(const struct dev *dev, const struct geom *geo,
                                  const struct scene *sc, size_t n, cl_mem d_p, cl_mem d_strain,
                                  cl_mem d_inv, double mu, const char *group, struct wall_force *f)
{
  enum clsph_status st = CLSPH_OK;
  real *p = malloc(4 * n * sizeof *p);
  cl_uint *inv = malloc(n * sizeof *inv);
  CLSPH_CHECK(p != NULL && inv != NULL, CLSPH_E_NOMEM, "out of memory");
  real *e = p + n; /* strain: xx, xy, yy per particle */
  CLSPH_TRY(kern_read(dev, d_p, n * sizeof *p, p));
  CLSPH_TRY(kern_read(dev, d_strain, 3 * n * sizeof *e, e));
  CLSPH_TRY(kern_read(dev, d_inv, n * sizeof *inv, inv));
  memset(f, 0, sizeof *f);
  for (size_t s = 0; s < geo->nseg; ++s) {
    if (strcmp(sc->walls[geo->seg_wall[s]].group, group) != 0) continue;
    const size_t v1 = inv[geo->seg_v[2 * s]], v2 = inv[geo->seg_v[2 * s + 1]];
    const double nx = geo->seg_normal[2 * s], ny = geo->seg_normal[2 * s + 1],
                 len = geo->seg_len[s];
    const double ps = 0.5 * ((double)p[v1] + (double)p[v2]);
    double es[3];
    for (int c = 0; c < 3; ++c) es[c] = 0.5 * ((double)e[3 * v1 + c] + (double)e[3 * v2 + c]);
    f->pressure[0] -= ps * nx * len;
    f->pressure[1] -= ps * ny * len;
    f->viscous[0] += mu * (es[0] * nx + es[1] * ny) * len;
    f->viscous[1] += mu * (es[1] * nx + es[2] * ny) * len;
  }
done:
  free(inv);
  free(p);
  return st;
}

enum clsph_status usaw_kernel_prefix(struct sim *sim, struct usaw_walls *w, cl_mem gam, cl_kernel k,
                                     cl_uint *next)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  cl_mem pos = pset_mem(ps, sim->f_pos), vol = pset_mem(ps, sim->f_vol);
  cl_mem kind = pset_mem(ps, sim->f_kind);
  cl_mem sa = pset_mem(&w->ps, w->f_a), sb = pset_mem(&w->ps, w->f_b);
  cl_mem sn = pset_mem(&w->ps, w->f_n), v1 = pset_mem(&w->ps, w->f_v1);
  cl_mem v2 = pset_mem(&w->ps, w->f_v2);
  CLSPH_TRY(KERN_SET(k, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start), KARG(pos),
                     KARG(vol), KARG(kind), KARG(gam), KARG(w->g.geom), KARG(w->g.d_start),
                     KARG(sa), KARG(sb), KARG(sn), KARG(v1), KARG(v2), KARG(sim->d_inv)));
  *next = 15;
done:
  return st;
}

void usaw_walls_destroy(struct usaw_walls *w)
{
  if (w->k_gamma != NULL) clReleaseKernel(w->k_gamma);
  w->k_gamma = NULL;
  kern_release(&w->d_flags);
  pset_destroy(&w->ps);
  grid_destroy(&w->g);
}
