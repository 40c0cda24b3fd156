/* gate.c: a lifted wall group (see gate.h). */
#include "gate.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "kern.h"
#include "prog.h"

static const struct scene_option *option(const struct scene *s, const char *key)
{
  for (int i = 0; i < s->noptions; ++i)
    if (strcmp(s->options[i].key, key) == 0) return &s->options[i];
  return NULL;
}

/* a number option from lo to hi (absent: v unchanged) */
static enum clsph_status number(const struct scene *s, const char *scheme, const char *key,
                                double lo, double hi, const char *what, double *v)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene_option *o = option(s, key);
  if (o == NULL) goto done;
  CLSPH_CHECK(o->is_number, CLSPH_E_INPUT,
              "%s:%d: %s option %s must be a number from %g to %g, not \"%s\"", s->case_path,
              s->scheme_line, scheme, key, lo, hi, o->text);
  CLSPH_CHECK(o->number >= lo && o->number <= hi, CLSPH_E_INPUT,
              "%s:%d: %s option %s = %g is out of range: %s must be from %g to %g", s->case_path,
              s->scheme_line, scheme, key, o->number, what, lo, hi);
  *v = o->number;
done:
  return st;
}

enum clsph_status gate_read(const struct scene *sc, const char *scheme, struct gate *g)
{
  enum clsph_status st = CLSPH_OK;
  memset(g, 0, sizeof *g);
  g->f_gate = -1;
  const struct scene_option *go = option(sc, "gate");
  static const char *const keys[] = {"gate_speed", "gate_start", "gate_stop"};
  for (int k = 0; k < 3; ++k)
    CLSPH_CHECK(go != NULL || option(sc, keys[k]) == NULL, CLSPH_E_INPUT,
                "%s:%d: %s option %s needs gate = \"<wall group>\", the walls that lift",
                sc->case_path, sc->scheme_line, scheme, keys[k]);
  if (go == NULL) goto done;
  char groups[256] = "";
  size_t used = 0;
  int found = 0;
  for (int w = 0; w < sc->nwalls; ++w) {
    if (!go->is_number && strcmp(sc->walls[w].group, go->text) == 0) found = 1;
    if (strstr(groups, sc->walls[w].group) == NULL)
      used += (size_t)snprintf(groups + used, used < sizeof groups ? sizeof groups - used : 0,
                               "%s%s", used ? ", " : "", sc->walls[w].group);
  }
  CLSPH_CHECK(found, CLSPH_E_INPUT,
              "%s:%d: %s option gate = %s%s%s: no wall has that group (groups: %s)", sc->case_path,
              sc->scheme_line, scheme, go->is_number ? "" : "\"",
              go->is_number ? "a number" : go->text, go->is_number ? "" : "\"", groups);
  g->on = 1;
  snprintf(g->group, sizeof g->group, "%s", go->text);
  CLSPH_CHECK(option(sc, "gate_speed") != NULL && option(sc, "gate_stop") != NULL, CLSPH_E_INPUT,
              "%s:%d: %s option gate needs gate_speed (m/s) and gate_stop (s, when the lift ends; "
              "gate_start, when it begins, is 0 unless given)",
              sc->case_path, sc->scheme_line, scheme);
  CLSPH_TRY(
      number(sc, scheme, "gate_speed", 1e-9, 1e3, "the gate's lifting speed (m/s)", &g->speed));
  CLSPH_TRY(number(sc, scheme, "gate_start", 0.0, 1e9, "the time the gate starts (s)", &g->start));
  CLSPH_TRY(number(sc, scheme, "gate_stop", 0.0, 1e9, "the time the gate stops (s)", &g->stop));
  CLSPH_CHECK(g->stop > g->start, CLSPH_E_INPUT,
              "%s:%d: %s option gate_stop = %g s must come after gate_start = %g s", sc->case_path,
              sc->scheme_line, scheme, g->stop, g->start);
  const double *gr = sc->gravity;
  const double gn = hypot(hypot(gr[0], gr[1]), gr[2]);
  for (int a = 0; a < 3; ++a) /* against gravity, +y without it */
    g->dir[a] = gn > 0.0 ? -gr[a] / gn : a == 1;
done:
  return st;
}

enum clsph_status gate_create(struct sim *sim, struct gate *g)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint *flag = NULL;
  if (!g->on) goto done;
  const struct geom *geo = &sim->geom;
  const struct scene *sc = sim->scene;
  flag = calloc(geo->n + 1, sizeof *flag);
  CLSPH_CHECK(flag != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t i = 0; i < geo->n; ++i)
    flag[i] = geo->kind[i] == KIND_DUMMY && strcmp(sc->walls[geo->group[i]].group, g->group) == 0;
  CLSPH_TRY(pset_add(&sim->ps, sim->dev, "gate", sizeof(cl_uint), flag, &g->f_gate));
  pset_describe(&sim->ps, g->f_gate, PF_UINT, 0, 0);
  CLSPH_TRY(prog_kernel(sim->prog, "gate_move", &g->k_move));
  /* the outputs draw its walls where they stand */
  sim->moved =
      (struct sim_moved){g->group, {g->dir[0], g->dir[1], g->dir[2]}, g->speed, g->start, g->stop};
done:
  free(flag);
  return st;
}

enum clsph_status gate_check(const struct sim *sim, const struct gate *g, const char *scheme)
{
  enum clsph_status st = CLSPH_OK;
  if (!g->on) goto done;
  const struct scene *sc = sim->scene;
  const struct geom *geo = &sim->geom;
  const int dim = sc->dim;
  const double lift = g->speed * (g->stop - g->start);
  for (size_t i = 0; i < geo->n; ++i) {
    if (geo->kind[i] != KIND_DUMMY || strcmp(sc->walls[geo->group[i]].group, g->group) != 0)
      continue;
    const double *x0 = geo->x + (size_t)dim * i;
    double x1[3] = {0.0, 0.0, 0.0};
    int inside = 1;
    for (int a = 0; a < dim; ++a) {
      x1[a] = x0[a] + lift * g->dir[a];
      inside &= sc->periodic[a] || (x1[a] >= sim->gspec.lo[a] && x1[a] < sim->gspec.hi[a]);
    }
    char p0[96], p1[96];
    if (dim == 3) {
      snprintf(p0, sizeof p0, "(%g, %g, %g)", x0[0], x0[1], x0[2]);
      snprintf(p1, sizeof p1, "(%g, %g, %g)", x1[0], x1[1], x1[2]);
    } else {
      snprintf(p0, sizeof p0, "(%g, %g)", x0[0], x0[1]);
      snprintf(p1, sizeof p1, "(%g, %g)", x1[0], x1[1]);
    }
    CLSPH_CHECK(inside, CLSPH_E_INPUT,
                "%s:%d: %s: the gate (group '%s') leaves the domain: after its lift of %g m its "
                "dummy from %s is at %s; lower gate_speed or gate_stop",
                sc->case_path, sc->walls[geo->group[i]].line, scheme, g->group, lift, p0, p1);
  }
done:
  return st;
}

double gate_speed_at(const struct gate *g, double t0, double t1)
{
  return g->on && t1 >= g->start && t0 < g->stop ? g->speed : 0.0;
}

enum clsph_status gate_move(struct sim *sim, struct gate *g, double t, double dt, cl_mem wall_vel,
                            double v[3])
{
  enum clsph_status st = CLSPH_OK;
  const double moving = fmax(0.0, fmin(t + dt, g->stop) - fmax(t, g->start));
  double disp[3];
  int changed = moving > 0.0;
  for (int a = 0; a < 3; ++a) {
    v[a] = g->on && dt > 0.0 ? g->speed * moving / dt * g->dir[a] : 0.0;
    disp[a] = v[a] * dt;
    changed |= v[a] != g->v_prev[a];
  }
  if (g->on && changed) {
    struct pset *ps = &sim->ps;
    const cl_uint n = (cl_uint)ps->n;
    const int dim = sim->scene->dim;
    const struct realv_arg dv = dev_realv(dim, disp), rv = dev_realv(dim, v);
    cl_mem flag = pset_mem(ps, g->f_gate), pos = pset_mem(ps, sim->f_pos);
    CLSPH_TRY(
        KERN_SET(g->k_move, KARG(n), KARG(flag), KARGV(dv), KARGV(rv), KARG(pos), KARG(wall_vel)));
    CLSPH_TRY(kern_launch(sim->dev, g->k_move, n, NULL));
  }
  for (int a = 0; a < 3; ++a) g->v_prev[a] = v[a];
done:
  return st;
}

void gate_destroy(struct gate *g)
{
  if (g->k_move != NULL) clReleaseKernel(g->k_move);
  g->k_move = NULL;
}
