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

double scene_param(const struct scene *s, const char *name, double fallback)
{
  for (int i = 0; i < s->nparams; ++i)
    if (strcmp(s->params[i].name, name) == 0) return s->params[i].value;
  return fallback;
}
