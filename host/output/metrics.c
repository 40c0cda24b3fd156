/* metrics.c: what a case script's metrics(sim) function can ask of a run (struct case_sim_api):
 * statistics and values of fields, interpolation at points, and the recorded wall forces. */
#include "metrics.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "kern.h"

/* A refused input: the reason goes to the api's `why`, which the script's error (case.c) quotes,
 * so that it is said once, where the script asked */
#define METRIC_REFUSE(cond, ...)                                                                   \
  do {                                                                                             \
    if (!(cond)) {                                                                                 \
      struct case_sim_api *api_ = ctx;                                                             \
      snprintf(api_->why, sizeof api_->why, __VA_ARGS__);                                          \
      st = CLSPH_E_INPUT;                                                                          \
      goto done;                                                                                   \
    }                                                                                              \
  } while (0)

/* The run behind a callback's ctx (the api itself: metrics_api), its `why` cleared */
static struct sim *begin(void *ctx)
{
  struct case_sim_api *api = ctx;
  api->why[0] = '\0';
  return api->run;
}

/* Statistics of a field over the particles of a kind (−1: all) in a box (NULL: everywhere). */
static enum clsph_status metric_stats(void *ctx, const char *field, int comp, int kind,
                                      const double *region, double *mn, double *mx, double *mean,
                                      size_t *count)
{
  enum clsph_status st = CLSPH_OK;
  struct sim *sim = begin(ctx);
  real *v = NULL, *x = NULL;
  cl_uint *k = NULL;
  int idx = pset_find(&sim->ps, field);
  METRIC_REFUSE(idx >= 0, "no field '%s'", field);
  const struct pfield *f = &sim->ps.f[idx];
  METRIC_REFUSE(comp >= 0 && comp < f->nout, "field '%s' has %d components", field, f->nout);
  size_t n = sim->ps.n;
  METRIC_REFUSE(region == NULL || sim->scene->dim == 2,
                "a region { x0, y0, x1, y1 } is 2-D: give none in a 3-D scene");
  v = malloc(n * f->elem + 1);
  k = malloc(n * sizeof *k + 1);
  x = region != NULL ? malloc(2 * n * sizeof *x + 1) : NULL;
  CLSPH_CHECK(v != NULL && k != NULL && (region == NULL || x != NULL), CLSPH_E_NOMEM,
              "out of memory");
  CLSPH_TRY(kern_read(sim->dev, f->d, n * f->elem, v));
  CLSPH_TRY(kern_read(sim->dev, pset_mem(&sim->ps, sim->f_kind), n * sizeof *k, k));
  if (region != NULL)
    CLSPH_TRY(kern_read(sim->dev, pset_mem(&sim->ps, sim->f_pos), 2 * n * sizeof *x, x));
  double a = HUGE_VAL, b = -HUGE_VAL, s = 0.0;
  size_t c = 0;
  for (size_t i = 0; i < n; ++i) {
    if (kind >= 0 && k[i] != (cl_uint)kind) continue;
    if (region != NULL && !((double)x[2 * i] >= region[0] && (double)x[2 * i] <= region[2] &&
                            (double)x[2 * i + 1] >= region[1] && (double)x[2 * i + 1] <= region[3]))
      continue;
    double y;
    if (f->type == PF_REAL)
      y = (double)v[i * (size_t)f->ncomp + (size_t)comp];
    else
      y = (double)((const cl_uint *)(const void *)v)[i * (size_t)f->ncomp + (size_t)comp];
    a = fmin(a, y);
    b = fmax(b, y);
    s += y;
    ++c;
  }
  *mn = a;
  *mx = b;
  *mean = c > 0 ? s / (double)c : 0.0;
  *count = c;
done:
  free(x);
  free(k);
  free(v);
  return st;
}

/* What sample() recorded under `name`: rows of (t, value). */
static enum clsph_status metric_series(void *ctx, const char *name, size_t *n, double **rows)
{
  enum clsph_status st = CLSPH_OK;
  const struct sim *sim = begin(ctx);
  const struct sim_samples *h = &sim->samples;
  int col = -1;
  *n = 0;
  *rows = NULL;
  for (int c = 0; c < h->ncols; ++c)
    if (strcmp(h->names[c], name) == 0) col = c;
  METRIC_REFUSE(col >= 0, "sample() records no value '%s'", name);
  double *out = malloc(2 * (h->nrows + 1) * sizeof *out);
  CLSPH_CHECK(out != NULL, CLSPH_E_NOMEM, "out of memory");
  const size_t cols = 1 + (size_t)h->ncols;
  for (size_t r = 0; r < h->nrows; ++r) {
    out[2 * r] = h->rows[r * cols];
    out[2 * r + 1] = h->rows[r * cols + 1 + (size_t)col];
  }
  *n = h->nrows;
  *rows = out;
done:
  return st;
}

/* Positions and one component of a field of the particles of one kind (−1: all). */
static enum clsph_status metric_particles(void *ctx, const char *field, int comp, int kind,
                                          size_t *count, double **xy, double **values)
{
  enum clsph_status st = CLSPH_OK;
  struct sim *sim = begin(ctx);
  real *v = NULL, *x = NULL;
  cl_uint *k = NULL;
  double *oxy = NULL, *ov = NULL;
  int idx = pset_find(&sim->ps, field);
  METRIC_REFUSE(idx >= 0, "no field '%s'", field);
  const struct pfield *f = &sim->ps.f[idx];
  METRIC_REFUSE(comp >= 0 && comp < f->nout, "field '%s' has %d components", field, f->nout);
  const size_t n = sim->ps.n, stride = (size_t)sim->ps.f[sim->f_pos].ncomp; /* 2, or 4 in 3-D */
  const size_t dim = (size_t)sim->scene->dim;
  v = malloc(n * f->elem);
  x = malloc(stride * n * sizeof *x);
  k = malloc(n * sizeof *k);
  oxy = calloc(3 * n + 1, sizeof *oxy);
  ov = malloc(n * sizeof *ov + 1);
  CLSPH_CHECK(v != NULL && x != NULL && k != NULL && oxy != NULL && ov != NULL, CLSPH_E_NOMEM,
              "out of memory");
  CLSPH_TRY(kern_read(sim->dev, f->d, n * f->elem, v));
  CLSPH_TRY(kern_read(sim->dev, pset_mem(&sim->ps, sim->f_pos), stride * n * sizeof *x, x));
  CLSPH_TRY(kern_read(sim->dev, pset_mem(&sim->ps, sim->f_kind), n * sizeof *k, k));
  size_t c = 0;
  for (size_t i = 0; i < n; ++i) {
    if (kind >= 0 && k[i] != (cl_uint)kind) continue;
    const size_t at = i * (size_t)f->ncomp + (size_t)comp;
    for (size_t a = 0; a < dim; ++a) oxy[3 * c + a] = (double)x[stride * i + a];
    ov[c] = f->type == PF_REAL ? (double)v[at] : (double)((const cl_uint *)(const void *)v)[at];
    ++c;
  }
  *count = c;
  *xy = oxy;
  *values = ov;
  oxy = ov = NULL;
done:
  free(ov);
  free(oxy);
  free(k);
  free(x);
  free(v);
  return st;
}

static enum clsph_status metric_probe(void *ctx, const char *name, const char *field, int comp,
                                      double *value)
{
  enum clsph_status st = CLSPH_OK;
  struct sim *sim = begin(ctx);
  const struct scene *s = sim->scene;
  const struct scene_probe *pr = NULL;
  for (int k = 0; k < s->nprobes; ++k)
    if (strcmp(s->probes[k].name, name) == 0) pr = &s->probes[k];
  METRIC_REFUSE(pr != NULL, "the case declares no probe '%s'", name);
  int idx = pset_find(&sim->ps, field);
  METRIC_REFUSE(idx >= 0, "no field '%s'", field);
  const struct pfield *f = &sim->ps.f[idx];
  METRIC_REFUSE(f->type == PF_REAL && f->ncomp <= 4, "field '%s' cannot be interpolated", field);
  METRIC_REFUSE(comp >= 0 && comp < f->nout, "field '%s' has %d components", field, f->nout);
  /* every probe of the case at once, kept for the next one asked in this state */
  struct sim_probe_cache *c = &sim->probe_cache;
  if (c->v == NULL || c->field != idx || c->step != sim->step || c->sorts != sim->sorts ||
      c->time != sim->time) {
    free(c->v);
    c->v = malloc((size_t)s->nprobes * (size_t)f->ncomp * sizeof *c->v);
    CLSPH_CHECK(c->v != NULL, CLSPH_E_NOMEM, "out of memory");
    st = sim_sample_probes(sim, idx, s->nprobes, s->probes, c->v);
    if (st != CLSPH_OK) {
      free(c->v);
      c->v = NULL;
      goto done;
    }
    c->field = idx;
    c->step = sim->step;
    c->sorts = sim->sorts;
    c->time = sim->time;
  }
  *value = c->v[(size_t)(pr - s->probes) * (size_t)f->ncomp + (size_t)comp];
done:
  return st;
}

static enum clsph_status metric_sample_many(void *ctx, const char *field, int comp, int order,
                                            int np, int ncoord, const double *pts, double *values)
{
  enum clsph_status st = CLSPH_OK;
  struct sim *sim = begin(ctx);
  double *out = NULL;
  METRIC_REFUSE(ncoord == sim->scene->dim,
                "a point of this %d-D scene has %d coordinates, not %d%s", sim->scene->dim,
                sim->scene->dim, ncoord,
                sim->scene->dim == 3 ? " (give z: sim.sample(field, {x, y, z}), "
                                       "profile_error{ ..., z = })"
                                     : "");
  int idx = pset_find(&sim->ps, field);
  METRIC_REFUSE(idx >= 0, "no field '%s'", field);
  const struct pfield *f = &sim->ps.f[idx];
  METRIC_REFUSE(comp >= 0 && comp < f->nout, "field '%s' has %d components", field, f->nout);
  out = malloc((size_t)np * (size_t)f->ncomp * sizeof *out);
  CLSPH_CHECK(out != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(sim_sample(sim, idx, order, (size_t)np, pts, out));
  for (int k = 0; k < np; ++k) values[k] = out[(size_t)k * (size_t)f->ncomp + (size_t)comp];
done:
  free(out);
  return st;
}

/* The column block of wall group `group` in the recorded force rows (−1: not recorded). */
static int force_group(const struct scene *s, const char *group)
{
  for (int k = 0; k < s->nforces; ++k)
    if (strcmp(s->forces[k], group) == 0) return k;
  return -1;
}

/* The recorded total force of a group at each row with t >= since: rows of (t, x, y, torque). */
static enum clsph_status metric_force_history(void *ctx, const char *group, double since, size_t *n,
                                              double **rows)
{
  enum clsph_status st = CLSPH_OK;
  struct sim *sim = begin(ctx);
  const int g = force_group(sim->scene, group);
  *rows = NULL;
  *n = 0;
  METRIC_REFUSE(g >= 0, "the case records no force of '%s' (force { \"%s\" })", group, group);
  const size_t cols = 1 + SIM_FORCE_COLS * (size_t)sim->scene->nforces, gc = SIM_FORCE_COLS * g;
  double *out = malloc(4 * (sim->nforce_rows + 1) * sizeof *out);
  CLSPH_CHECK(out != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t r = 0; r < sim->nforce_rows; ++r) {
    const double *row = sim->force_rows + r * cols;
    if (row[0] < since * (1.0 - 1e-12)) continue;
    out[4 * *n] = row[0];
    out[4 * *n + 1] = row[1 + gc] + row[3 + gc]; /* pressure + viscous */
    out[4 * *n + 2] = row[2 + gc] + row[4 + gc];
    out[4 * *n + 3] = row[5 + gc]; /* torque */
    ++*n;
  }
  *rows = out;
done:
  return st;
}

/* Mean of the recorded forces of a group over the outputs at t >= since (since < 0: the last). */
static enum clsph_status metric_force(void *ctx, const char *group, double since, double out[7],
                                      int *samples)
{
  enum clsph_status st = CLSPH_OK;
  struct sim *sim = begin(ctx);
  const struct scene *s = sim->scene;
  const int g = force_group(s, group);
  METRIC_REFUSE(g >= 0,
                "the case records no force of '%s' "
                "(force { \"%s\" })",
                group, group);
  METRIC_REFUSE(sim->nforce_rows > 0, "no force recorded yet");
  const size_t cols = 1 + SIM_FORCE_COLS * (size_t)s->nforces;
  double sum[SIM_FORCE_COLS] = {0.0, 0.0, 0.0, 0.0, 0.0};
  int c = 0;
  for (size_t r = 0; r < sim->nforce_rows; ++r) {
    const double *row = sim->force_rows + r * cols;
    if (since < 0.0 ? r + 1 < sim->nforce_rows : row[0] < since * (1.0 - 1e-12)) continue;
    for (int k = 0; k < SIM_FORCE_COLS; ++k) sum[k] += row[1 + SIM_FORCE_COLS * g + k];
    ++c;
  }
  METRIC_REFUSE(c > 0, "no force recorded at t >= %g s", since);
  for (int k = 0; k < SIM_FORCE_COLS; ++k) sum[k] /= c;
  out[0] = sum[0] + sum[2];
  out[1] = sum[1] + sum[3];
  for (int k = 0; k < SIM_FORCE_COLS; ++k) out[2 + k] = sum[k];
  *samples = c;
done:
  return st;
}

void metrics_api(struct sim *sim, const char *dir, struct case_sim_api *api)
{
  memset(api, 0, sizeof *api);
  api->ctx = api;
  api->run = sim;
  api->time = sim->time;
  api->steps = sim->step;
  api->particles = (double)sim->ps.n;
  api->wall_steps = sim->wall_steps;
  api->wall_most = sim->wall_most;
  api->escaped = sim->escaped;
  for (int k = 0; k < 3; ++k) api->body[k] = sim->body_force[k];
  api->stats = metric_stats;
  api->sample_many = metric_sample_many;
  api->probe = metric_probe;
  api->force = metric_force;
  api->force_history = metric_force_history;
  api->dir = dir;
  api->field_values = metric_particles;
  api->series = metric_series;
}
