/* ballistic.c: fluid particles under gravity and the body force alone (no pressure, viscosity or
 * walls). It exercises the time loop, periodic wrapping, outputs, restarts and the blow-up checks
 * with a motion whose exact answer is known: x(t) = x0 + v0 t + a t²/2 up to the O(dt) error of
 * semi-implicit Euler. Time step: a particle moves at most a quarter of h per step,
 * dt = 0.25 h / max(|v|max, sqrt(|a| h)). */
#include <math.h>
#include <stdlib.h>

#include "../scheme.h"
#include "kern.h"
#include "sim.h"

struct ballistic {
  cl_kernel k_step;
};

static enum clsph_status ballistic_create(struct sim *sim, void **state)
{
  enum clsph_status st = CLSPH_OK;
  struct ballistic *b = calloc(1, sizeof *b);
  CLSPH_CHECK(b != NULL, CLSPH_E_NOMEM, "ballistic: out of memory");
  CLSPH_TRY(prog_kernel(sim->prog, "ballistic_step", &b->k_step));
  *state = b;
  b = NULL;
done:
  free(b);
  return st;
}

static enum clsph_status ballistic_step(struct sim *sim, void *state, double dt)
{
  enum clsph_status st = CLSPH_OK;
  struct ballistic *b = state;
  const struct scene *s = sim->scene;
  cl_uint n = (cl_uint)sim->ps.n;
  real rdt = (real)dt;
  real2 accel = dev_real2(s->gravity[0] + sim->body_force[0], s->gravity[1] + sim->body_force[1]);
  cl_mem pos = pset_mem(&sim->ps, sim->f_pos), vel = pset_mem(&sim->ps, sim->f_vel);
  cl_mem kind = pset_mem(&sim->ps, sim->f_kind);
  CLSPH_TRY(KERN_SET(b->k_step, KARG(n), KARG(rdt), KARG(accel), KARG(sim->grid.geom), KARG(pos),
                     KARG(vel), KARG(kind), KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, b->k_step, sim->ps.n, NULL));
done:
  return st;
}

static enum clsph_status ballistic_max_dt(struct sim *sim, void *state, double *dt)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  double vmax = 0.0;
  (void)state;
  CLSPH_TRY(sim_max_speed(sim, 0, &vmax));
  double a = hypot(s->gravity[0] + sim->body_force[0], s->gravity[1] + sim->body_force[1]);
  double speed = fmax(vmax, sqrt(a * sim->sm.h));
  *dt = speed > 0.0 ? 0.25 * sim->sm.h / speed : HUGE_VAL;
done:
  return st;
}

static void ballistic_destroy(void *state)
{
  struct ballistic *b = state;
  if (b == NULL) return;
  if (b->k_step != NULL) clReleaseKernel(b->k_step);
  free(b);
}

static const char *const ballistic_sources[] = {"ballistic/integrate.cl", NULL};
static const char *const ballistic_options[] = {"walls", NULL};

const struct scheme_ops scheme_ballistic = {
    .name = "ballistic",
    .summary = "free particles under gravity and body force, no pressure or walls (driver checks)",
    .sources = ballistic_sources,
    .wall_model = "usaw",
    .smoothing = "wendland",
    .h_over_dr = 2.0,
    .options = ballistic_options,
    .create = ballistic_create,
    .step = ballistic_step,
    .max_dt = ballistic_max_dt,
    .destroy = ballistic_destroy,
};
