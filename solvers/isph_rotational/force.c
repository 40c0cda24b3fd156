/* force.c: sample points on dummy-particle walls and the force integral (see force.h). */
#include "force.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clsph_config.h"

/* Wall velocity of a scene wall at x (fixed, sliding or rotating). */
static void wall_velocity(const struct scene_wall *w, const double x[2], double u[2])
{
  u[0] = u[1] = 0.0;
  if (w->motion == SCENE_SLIDING) {
    u[0] = w->velocity[0];
    u[1] = w->velocity[1];
  } else if (w->motion == SCENE_ROTATING) {
    u[0] = -w->omega * (x[1] - w->centre[1]);
    u[1] = w->omega * (x[0] - w->centre[0]);
  }
}

/* The points of one group: each wall segment a->b cut into ceil(|b − a| / dr) equal pieces, a
 * point at the middle of each, the normal on the left of a->b (the fluid's side). Two passes:
 * count (xs == NULL), then fill. */
static size_t place(const struct scene *sc, const char *group, real *xs, real *uw,
                    struct rot_samples *s)
{
  size_t k = 0;
  for (int w = 0; w < sc->nwalls; ++w) {
    const struct scene_wall *wall = &sc->walls[w];
    if (strcmp(wall->group, group) != 0) continue;
    const int nseg = wall->closed ? wall->npts : wall->npts - 1;
    for (int e = 0; e < nseg; ++e) {
      const double *a = wall->pts + 2 * e, *b = wall->pts + 2 * ((e + 1) % wall->npts);
      const double len = hypot(b[0] - a[0], b[1] - a[1]);
      if (!(len > 0.0)) continue;
      const int m = (int)ceil(len / sc->dr - 1e-9);
      for (int i = 0; i < m; ++i, ++k) {
        if (xs == NULL) continue;
        const double f = (i + 0.5) / m, x[2] = {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])};
        double u[2];
        wall_velocity(wall, x, u);
        s->x[2 * k] = x[0];
        s->x[2 * k + 1] = x[1];
        xs[2 * k] = (real)x[0];
        xs[2 * k + 1] = (real)x[1];
        uw[2 * k] = (real)u[0];
        uw[2 * k + 1] = (real)u[1];
        s->nrm[2 * k] = -(b[1] - a[1]) / len;
        s->nrm[2 * k + 1] = (b[0] - a[0]) / len;
        s->len[k] = len / m;
      }
    }
  }
  return k;
}

enum clsph_status rot_force_create(const struct dev *dev, cl_program prog, const struct scene *sc,
                                   struct rot_force *out)
{
  enum clsph_status st = CLSPH_OK;
  struct rot_force rf;
  real *xs = NULL, *uw = NULL;
  memset(&rf, 0, sizeof rf);
  CLSPH_TRY(prog_kernel(prog, "rot_surface_sample", &rf.k));
  if (sc->nforces > 0) {
    rf.g = calloc((size_t)sc->nforces, sizeof *rf.g);
    CLSPH_CHECK(rf.g != NULL, CLSPH_E_NOMEM, "out of memory");
  }
  for (int f = 0; f < sc->nforces; ++f) {
    struct rot_samples *s = &rf.g[f];
    rf.ngroups = f + 1;
    snprintf(s->group, sizeof s->group, "%s", sc->forces[f]);
    s->n = place(sc, s->group, NULL, NULL, s);
    CLSPH_CHECK(s->n > 0, CLSPH_E_INPUT, "%s: force group '%s' has no wall", sc->case_path,
                s->group);
    s->nrm = malloc(2 * s->n * sizeof *s->nrm);
    s->len = malloc(s->n * sizeof *s->len);
    s->x = malloc(2 * s->n * sizeof *s->x);
    scene_group_centre(sc, s->group, s->centre);
    s->h_out = malloc(5 * s->n * sizeof *s->h_out);
    xs = malloc(2 * s->n * sizeof *xs);
    uw = malloc(2 * s->n * sizeof *uw);
    CLSPH_CHECK(s->nrm && s->len && s->x && s->h_out && xs && uw, CLSPH_E_NOMEM, "out of memory");
    place(sc, s->group, xs, uw, s);
    CLSPH_TRY(kern_buffer(dev, 2 * s->n * sizeof *xs, xs, &s->d_x, "force sample points"));
    CLSPH_TRY(kern_buffer(dev, 2 * s->n * sizeof *uw, uw, &s->d_uw, "force sample velocities"));
    CLSPH_TRY(kern_buffer(dev, 5 * s->n * sizeof(real), NULL, &s->d_out, "force samples"));
    free(xs);
    free(uw);
    xs = uw = NULL;
  }
  *out = rf;
  memset(&rf, 0, sizeof rf);
done:
  free(xs);
  free(uw);
  rot_force_destroy(&rf);
  return st;
}

enum clsph_status rot_force_eval(struct rot_force *rf, const struct dev *dev, const struct grid *g,
                                 size_t n, cl_mem pos, cl_mem vol, cl_mem kind, cl_mem vel,
                                 cl_mem p, double mu, const char *group, double pressure[2],
                                 double viscous[2], double *torque)
{
  enum clsph_status st = CLSPH_OK;
  struct rot_samples *s = NULL;
  for (int f = 0; f < rf->ngroups; ++f)
    if (strcmp(rf->g[f].group, group) == 0) s = &rf->g[f];
  CLSPH_CHECK(s != NULL, CLSPH_E_INPUT, "force group '%s' was not declared", group);
  const cl_uint ns = (cl_uint)s->n, nn = (cl_uint)n;
  CLSPH_TRY(KERN_SET(rf->k, KARG(ns), KARG(s->d_x), KARG(s->d_uw), KARG(nn), KARG(g->geom),
                     KARG(g->d_start), KARG(pos), KARG(vol), KARG(kind), KARG(vel), KARG(p),
                     KARG(s->d_out)));
  CLSPH_TRY(kern_launch(dev, rf->k, s->n, NULL));
  CLSPH_TRY(kern_read(dev, s->d_out, 5 * s->n * sizeof(real), s->h_out));
  pressure[0] = pressure[1] = viscous[0] = viscous[1] = *torque = 0.0;
  for (size_t k = 0; k < s->n; ++k) { /* eq 31: f = Σ (−p n + µ (∇u + ∇uᵀ) n) ΔS */
    const real *o = s->h_out + 5 * k;
    const double nx = s->nrm[2 * k], ny = s->nrm[2 * k + 1], L = s->len[k];
    const double exx = 2.0 * (double)o[1], exy = (double)o[2] + (double)o[3],
                 eyy = 2.0 * (double)o[4];
    const double f[2] = {-(double)o[0] * nx * L + mu * (exx * nx + exy * ny) * L,
                         -(double)o[0] * ny * L + mu * (exy * nx + eyy * ny) * L};
    pressure[0] -= (double)o[0] * nx * L;
    pressure[1] -= (double)o[0] * ny * L;
    viscous[0] += mu * (exx * nx + exy * ny) * L;
    viscous[1] += mu * (exy * nx + eyy * ny) * L;
    *torque += (s->x[2 * k] - s->centre[0]) * f[1] - (s->x[2 * k + 1] - s->centre[1]) * f[0];
  }
done:
  return st;
}

void rot_force_destroy(struct rot_force *rf)
{
  for (int f = 0; f < rf->ngroups; ++f) {
    struct rot_samples *s = &rf->g[f];
    kern_release(&s->d_x);
    kern_release(&s->d_uw);
    kern_release(&s->d_out);
    free(s->nrm);
    free(s->len);
    free(s->x);
    free(s->h_out);
  }
  free(rf->g);
  if (rf->k != NULL) clReleaseKernel(rf->k);
  memset(rf, 0, sizeof *rf);
}
