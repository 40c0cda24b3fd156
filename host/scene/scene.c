/* scene.c: ownership of the scene description. */
#include "scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void scene_free(struct scene *s)
{
  for (int i = 0; i < s->nregions; ++i) free(s->regions[i].pts);
  for (int i = 0; i < s->nwalls; ++i) {
    free(s->walls[i].pts);
    if (s->walls[i].mesh != NULL) mesh_free(s->walls[i].mesh);
    free(s->walls[i].mesh);
    free(s->walls[i].stl);
  }
  free(s->regions);
  free(s->walls);
  for (int i = 0; i < s->nsections; ++i) free(s->sections[i].prof);
  free(s->sections);
  free(s->probes);
  free(s->profiles);
  free(s->forces);
  free(s->params);
  free(s->options);
  memset(s, 0, sizeof *s);
}

double scene_section_value(const struct scene_section *c, int what, double s)
{
  if (c->nprof < 2 || c->prof == NULL) return NAN;
  const double len = hypot(c->b[0] - c->a[0], c->b[1] - c->a[1]);
  double f = len > 0.0 ? s / len * (double)(c->nprof - 1) : 0.0;
  f = fmin(fmax(f, 0.0), (double)(c->nprof - 1));
  const int i = (int)fmin(floor(f), (double)(c->nprof - 2));
  const double w = f - (double)i;
  return (1.0 - w) * c->prof[3 * i + what] + w * c->prof[3 * (i + 1) + what];
}

/* The defaults of the health checks, from runs that hold and runs that do not (the cavity's
 * stability sweep, 16² particles, 2 s, Re 100 to 3200, cfl 0.5 to 4, tests/validation/
 * cavity_re_cfl.csv; the coarse runs of tests/case.cmake; the Taylor-Green vortex and the dam
 * breaks):
 *  - every 10 steps: a check costs one neighbour sweep and a sort; measured with --profile on the
 *    cavity at 40², 0.4% of the wall time of wcsph-usaw and 0.03% of isph-usaw (a NaN or a
 *    particle through a wall is caught at every step).
 *  - cluster_h 0.125, cluster_fraction 0.005: a fluid particle is clustered when its nearest
 *    fluid neighbour is closer than h/8 (0.25 dr at the h = 2 dr of isph-usaw and wcsph-usaw,
 *    0.15 dr at isph-rotational's 1.2 dr), and the run stops when more than 0.5% of the fluid is.
 *    Nearest fluid spacing (dr) and largest clustered fraction, measured at every check:
 *    healthy runs
 *      isph-usaw   Taylor-Green (cases/taylor_green.lua, Re 100) n = 16, 32, 64: 0.42, 0.41,
 *                  0.26, none clustered; n = 128 to t = 0.5: 0.23, 0.10% (16 of 16384 at the
 *                  saddle points, t = 0.2); Re 1000, n = 32: 0.41. Dam break (cases/
 *                  dam_break.lua) n = 20 to t = 0.78 s: 0.34, n = 40: 0.36; wedge (cases/
 *                  dam_break_wedge.lua) δr = 0.04 to 0.01 m: 0.31 to 0.35, none clustered. Pairs
 *                  pressed by impacts sit at its collision distance, 0.5 dr = h/4, which the old
 *                  limit (0.5 dr) counted: it stopped the n = 32 vortex at t = 0.13 s and the
 *                  n = 20 dam break at t = 0.354 s.
 *      wcsph-usaw  Taylor-Green n = 32: 0.34 (0.29 without background pressure), none clustered;
 *                  dam break n = 20: 0.42; wedge δr = 0.04, 0.03: 0.39, 0.38; δr = 0.02: one
 *                  pair at 0.12 dr for five checks, 0.13%; δr = 0.01: pairs in the splash
 *                  collapse (down to 1e-7 dr) while the run stays accurate (wedge force within
 *                  3% of isph-usaw), at most 9 of 6000 particles, 0.15%.
 *      isph-rotational  Taylor-Green n = 16, 32: 0.56; the square cylinder maps (tests/
 *                  validation/square_cylinder_*.csv) at most 0.094% closer than 0.5 dr, so
 *                  below 0.5% closer than 0.15 dr.
 *      the coarse runs of tests/case.cmake: 0.46 dr or more.
 *    failing runs: the cavity map without shifting clumps particles until one goes through a wall;
 *      the check stops each first (step, time, nearest spacing, clustered fraction; the wall
 *      crossing that stops the same run without it): Re 100, cfl 0.5: 120, 0.75 s, 0.25 dr,
 *      0.78% (crossing at step 134); Re 400, cfl 0.5: 240, 1.5 s, 0.20 dr, 0.78% (445, 2.78 s);
 *      Re 400, cfl 1: 100, 1.25 s, 0.16 dr, 1.6% (181, 2.26 s); Re 1000, cfl 1: 160, 2 s,
 *      0.24 dr, 0.78% (277, 3.46 s); Re 1000, cfl 2: 70, 1.75 s, 0.06 dr, 1.6% (78); wcsph-usaw
 *      Re 100, cfl 4: 150, 1.5 s, 0.18 dr, 0.78% (152). Left to them, the clumps deepen to
 *      0.03-0.09 dr and 2-5% of the fluid. At 32² (Re 400, cfl 1) the wall crossing comes first
 *      (step 83; 0.39% clustered at step 80). isph-usaw without shifting on the Taylor-Green
 *      vortex stops at t = 0.26 s (4.7% clustered, 0.18 dr); left to run, 7.8% of its fluid
 *      sits at 0.04-0.08 dr and its velocity error is twice the shifted run's (5.7% against
 *      2.8% RMS at t = 0.5 s), though it does not blow up.
 *    Neither the trend of the nearest spacing nor the pressure residual separates the two sets:
 *    the spacing falls over tens of checks in healthy vortices too (wcsph-usaw without background
 *    pressure: 0.92 to 0.29 dr over 24 checks, then back to 0.49), and the failing runs' solves
 *    converge to 1e-9 up to the crossing. The check counts with the same kernel as before (one
 * neighbour sweep).
 *  - energy 4: ½ M U² bounds the kinetic energy of a flow driven by a wall of speed U (its speeds
 *    stay below U) or by gravity (v² <= 2 g L); the largest ratio seen is 1.5, the cylinder
 *    array, where U is the flow-rate control's mean velocity and the fluid squeezes past the
 *    cylinder at twice that (cavity Re 100: 0.045). A blow-up passes 4 within a few checks
 *    (isph-usaw without shifting, Re 100, cfl 0.5: 8.8e5 when it stopped).
 *  - wall_depth 0.5: a particle more than dr/2 behind a wall has the whole of its cell (its
 *    volume dr², centred on it) on the solid side: it has gone through. Shallower crossings are
 *    counted only: wcsph-usaw's cavity has particles up to 0.25 dr behind the walls at the lid's
 *    corners at every time step factor and stays accurate (tests/case.cmake); the runs that go
 *    through reach 0.54 dr to 6.8 dr.
 *  - escaped 0.01: a fluid particle more than dr beyond the domain's box (but on the side gravity
 *    points away from) has left the tank over or through its walls; it is dropped from the run
 *    and counted (summary.json escaped), as established SPH codes exclude the particles that
 *    leave their domain, and the run stops when more than 1% of the fluid has gone (a leaking
 *    wall, a jet aimed out of the domain: the whole fluid leaves within a few steps of the
 *    first). tests/case/spill.lua loses 2 of 200 (isph-usaw) and 3 (isph-stabilized) over its
 *    0.22 m walls; Lobovsky's dam break (cases/dam_break.lua, t = 1.1 s) throws single particles
 *    of the run-up jet above the tank's 1 m walls, which stopped isph-usaw at n = 80 and
 *    isph-stabilized at n = 40 and 80 between 0.69 and 0.77 s while the cell grid's top bounded
 *    them (it no longer does: grid.cl), with the flow near the sensors intact. */
void scene_checks_default(struct scene_checks *c)
{
  c->every = 10;
  c->cluster_h = 0.125;
  c->cluster_fraction = 0.005;
  c->energy = 4.0;
  c->wall_depth = 0.5;
  c->escaped = 0.01;
}

double scene_param(const struct scene *s, const char *name, double fallback)
{
  for (int i = 0; i < s->nparams; ++i)
    if (strcmp(s->params[i].name, name) == 0) return s->params[i].value;
  return fallback;
}

int scene_wall_turns(const struct scene_wall *w)
{
  return w->motion == SCENE_ROTATING && w->omega != 0.0;
}

void scene_wall_turn(const struct scene_wall *w, double t, const double x[2], int vector,
                     double out[2])
{
  if (!scene_wall_turns(w)) {
    out[0] = x[0];
    out[1] = x[1];
    return;
  }
  const double th = fmod(w->omega * t, 2.0 * 3.14159265358979323846);
  const double c = cos(th), s = sin(th);
  const double o[2] = {vector ? 0.0 : w->centre[0], vector ? 0.0 : w->centre[1]};
  const double d[2] = {x[0] - o[0], x[1] - o[1]};
  out[0] = o[0] + c * d[0] - s * d[1];
  out[1] = o[1] + s * d[0] + c * d[1];
}

void scene_group_centre(const struct scene *s, const char *group, double c[2])
{
  c[0] = c[1] = 0.0;
  for (int w = 0; w < s->nwalls; ++w)
    if (scene_wall_turns(&s->walls[w]) && strcmp(s->walls[w].group, group) == 0) {
      c[0] = s->walls[w].centre[0];
      c[1] = s->walls[w].centre[1];
      return;
    }
}

/* a unit vector normal to the unit n, and n × that: the plane of a disc */
static void disc_axes(const double *n, double e1[3], double e2[3])
{
  const double t[3] = {fabs(n[0]) < 0.9 ? 1.0 : 0.0, fabs(n[0]) < 0.9 ? 0.0 : 1.0, 0.0};
  const double d = t[0] * n[0] + t[1] * n[1] + t[2] * n[2];
  double l = 0.0;
  for (int a = 0; a < 3; ++a) {
    e1[a] = t[a] - d * n[a];
    l += e1[a] * e1[a];
  }
  for (int a = 0; a < 3; ++a) e1[a] /= sqrt(l);
  e2[0] = n[1] * e1[2] - n[2] * e1[1];
  e2[1] = n[2] * e1[0] - n[0] * e1[2];
  e2[2] = n[0] * e1[1] - n[1] * e1[0];
}

int scene_probe_points(const struct scene_probe *p, int dim, double dr, double *out)
{
  if (p->face != 2) {
    for (int k = 0; k < p->npts && out != NULL; ++k) {
      const double s = p->face ? (k + 0.5) / p->npts : 0.0;
      for (int a = 0; a < dim; ++a) out[dim * k + a] = p->x[a] + s * (p->b[a] - p->x[a]);
    }
    return p->npts;
  }
  /* the disc: a square lattice in its plane (an odd count across, so the centre is a point) */
  const double step = fmin(0.25 * dr, 0.5 * p->radius);
  const int half = (int)fmin(50.0, floor(p->radius / step + 1e-9));
  double e1[3], e2[3];
  disc_axes(p->normal, e1, e2);
  int count = 0;
  for (int j = -half; j <= half; ++j)
    for (int i = -half; i <= half; ++i) {
      const double u = i * step, v = j * step;
      if (u * u + v * v > p->radius * p->radius * (1.0 + 1e-12)) continue;
      if (out != NULL)
        for (int a = 0; a < 3; ++a) out[3 * count + a] = p->x[a] + u * e1[a] + v * e2[a];
      ++count;
    }
  return count;
}
