/* scene.c: ownership of the scene description. */
#include "scene.h"

#include <stdlib.h>
#include <string.h>

void scene_free(struct scene *s)
{
  for (int i = 0; i < s->nregions; ++i) free(s->regions[i].pts);
  for (int i = 0; i < s->nwalls; ++i) free(s->walls[i].pts);
  free(s->regions);
  free(s->walls);
  free(s->sections);
  free(s->probes);
  free(s->profiles);
  free(s->forces);
  free(s->params);
  free(s->options);
  memset(s, 0, sizeof *s);
}

/* The defaults of the health checks, from runs that hold and runs that do not (the cavity's
 * stability sweep, 16² particles, 2 s, Re 100 to 3200, cfl 0.5 to 4, tests/validation/
 * cavity_re_cfl.csv; the coarse cavity and cylinder-array runs of tests/case.cmake):
 *  - every 10 steps: a check costs one neighbour sweep and a sort; measured with --profile on the
 *    cavity at 40², 0.4% of the wall time of wcsph-usaw and 0.03% of isph-usaw (a NaN or a
 *    particle through a wall is caught at every step).
 *  - cluster_spacing 0.5, cluster_fraction 0.02: a run that holds keeps its nearest fluid
 *    neighbours at 0.5 dr or more (smallest seen: isph-usaw 0.51 dr, wcsph-usaw 0.50 dr, both at
 *    cfl 2 at Re 100, at most 0.8% of the fluid below 0.5 dr); isph-usaw without shifting packs
 *    2% to 14% of the fluid closer than that (down to 0.07 dr) before particles go through the
 *    walls.
 *  - energy 4: ½ M U² bounds the kinetic energy of a flow driven by a wall of speed U (its speeds
 *    stay below U) or by gravity (v² <= 2 g L); the largest ratio seen is 1.5, the cylinder
 *    array, where U is the flow-rate control's mean velocity and the fluid squeezes past the
 *    cylinder at twice that (cavity Re 100: 0.045). A blow-up passes 4 within a few checks
 *    (isph-usaw without shifting, Re 100, cfl 0.5: 8.8e5 when it stopped).
 *  - wall_depth 0.5: a particle more than dr/2 behind a wall has the whole of its cell (its
 *    volume dr², centred on it) on the solid side: it has gone through. Shallower crossings are
 *    counted only: wcsph-usaw's cavity has particles up to 0.25 dr behind the walls at the lid's
 *    corners at every time step factor and stays accurate (tests/case.cmake); the runs that go
 *    through reach 0.54 dr to 6.8 dr. */
void scene_checks_default(struct scene_checks *c)
{
  c->every = 10;
  c->cluster_spacing = 0.5;
  c->cluster_fraction = 0.02;
  c->energy = 4.0;
  c->wall_depth = 0.5;
}

double scene_param(const struct scene *s, const char *name, double fallback)
{
  for (int i = 0; i < s->nparams; ++i)
    if (strcmp(s->params[i].name, name) == 0) return s->params[i].value;
  return fallback;
}
