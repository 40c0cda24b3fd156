/* none.c: the scheme that does nothing: particles stay where the geometry put them. It runs the
 * whole pipeline (geometry, device state, outputs) without any physics. */
#include <math.h>

#include "../scheme.h"
#include "sim.h"

static enum clsph_status none_step(struct sim *sim, void *state, double dt)
{
  (void)sim;
  (void)state;
  (void)dt;
  return CLSPH_OK;
}

static enum clsph_status none_max_dt(struct sim *sim, void *state, double *dt)
{
  (void)sim;
  (void)state;
  *dt = HUGE_VAL; /* the outputs and the end time set the steps */
  return CLSPH_OK;
}

static const char *const none_sources[] = {NULL};
static const char *const none_options[] = {"walls", NULL};

const struct scheme_ops scheme_none = {
    .name = "none",
    .summary = "no physics: the particles stay put (pipeline checks)",
    .sources = none_sources,
    .wall_model = "usaw",
    .smoothing = "wendland",
    .h_over_dr = 2.0,
    .options = none_options,
    .step = none_step,
    .max_dt = none_max_dt,
};
