/* series.c: the CSV series of a run: probes.csv, profile_<name>.csv, forces.csv (with the force
 * history the metrics read) and flow_control.csv; on a restart each goes on from the rows the
 * restarted run wrote up to the checkpoint's time. */
#include "series.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "metrics.h"
#include "scheme.h"
#include "str.h"
/* Real fields that probes and profiles record (not position or volume). */
static int sampled(const struct pfield *f)
{
  return f->type == PF_REAL && f->output && strcmp(f->name, "pos") != 0 &&
         strcmp(f->name, "vol") != 0 && f->ncomp <= 4;
}

static void csv_field_header(FILE *f, const struct pset *ps, const char *prefix)
{
  for (int k = 0; k < ps->nfields; ++k) {
    const struct pfield *p = &ps->f[k];
    if (!sampled(p)) continue;
    for (int c = 0; c < p->nout; ++c) {
      if (p->nout == 1)
        fprintf(f, ",%s%s", prefix, p->name);
      else
        fprintf(f, ",%s%s_%c", prefix, p->name, "xyzw"[c]);
    }
  }
}

/* A series of the run being restarted (a CSV whose rows lead with their time): its header line
 * and its rows up to the checkpoint's time, read before this run's files are opened (they may be
 * the same files). */
struct kept_series {
  char *header, *rows;
  size_t bytes;
};

/* The rows of `name`, in the folder of the checkpoint `restart`, with time <= t (before: time < t,
 * for a series whose rows are written as a step begins). A missing file keeps nothing. */
static enum clsph_status series_keep(const char *restart, const char *name, double t, int before,
                                     struct kept_series *k)
{
  enum clsph_status st = CLSPH_OK;
  const char *slash = strrchr(restart, '/');
  const int dir = slash == NULL ? 0 : (int)(slash - restart);
  char *path = slash == NULL ? str_printf("%s", name) : str_printf("%.*s/%s", dir, restart, name);
  char *line = NULL;
  size_t cap = 0, room = 0;
  FILE *f = NULL;
  memset(k, 0, sizeof *k);
  CLSPH_CHECK(path != NULL, CLSPH_E_NOMEM, "out of memory");
  f = fopen(path, "r");
  if (f == NULL) goto done;
  ssize_t len;
  while ((len = getline(&line, &cap, f)) > 0) {
    if (k->header == NULL) {
      k->header = strdup(line);
      CLSPH_CHECK(k->header != NULL, CLSPH_E_NOMEM, "out of memory");
      continue;
    }
    char *end = NULL;
    const double row_t = strtod(line, &end);
    if (end == line || row_t > t || (before && row_t == t) || line[len - 1] != '\n')
      continue; /* later, or cut short */
    if (k->bytes + (size_t)len + 1 > room) {
      room = 2 * (k->bytes + (size_t)len + 1);
      char *r = realloc(k->rows, room);
      CLSPH_CHECK(r != NULL, CLSPH_E_NOMEM, "out of memory");
      k->rows = r;
    }
    memcpy(k->rows + k->bytes, line, (size_t)len + 1);
    k->bytes += (size_t)len;
  }
done:
  if (f != NULL) fclose(f);
  free(line);
  free(path);
  return st;
}

/* Append the kept rows to the series just opened at `path` (its header written), when the
 * headers agree; otherwise the series starts afresh, with a warning. */
static enum clsph_status series_resume(FILE *f, const char *path, struct kept_series *k)
{
  enum clsph_status st = CLSPH_OK;
  char *line = NULL;
  size_t cap = 0;
  if (k->header == NULL) goto done;
  CLSPH_CHECK(fflush(f) == 0, CLSPH_E_IO, "cannot write %s: %s", path, strerror(errno));
  FILE *r = fopen(path, "r");
  CLSPH_CHECK(r != NULL, CLSPH_E_IO, "cannot read %s: %s", path, strerror(errno));
  const int same = getline(&line, &cap, r) > 0 && strcmp(line, k->header) == 0;
  fclose(r);
  if (!same) {
    log_warn("%s: the restarted run recorded other columns; the series starts afresh", path);
    k->bytes = 0;
    goto done;
  }
  if (k->bytes > 0)
    CLSPH_CHECK(fwrite(k->rows, 1, k->bytes, f) == k->bytes, CLSPH_E_IO, "cannot write %s: %s",
                path, strerror(errno));
done:
  free(line);
  return st;
}

static void kept_free(struct kept_series *k)
{
  free(k->header);
  free(k->rows);
}

/* A recorded force as forces.csv holds it (9 digits): the metrics then read the same numbers
 * whether the run was restarted or not. */
static double recorded(double v)
{
  char b[32];
  snprintf(b, sizeof b, "%.9g", v);
  return strtod(b, NULL);
}

static enum clsph_status force_row(struct sim *sim, struct run_out *o, const double *row);

/* Refill the force history (and its peak and last values) from the kept rows of forces.csv. */
static enum clsph_status forces_reload(struct sim *sim, struct run_out *o,
                                       const struct kept_series *k)
{
  enum clsph_status st = CLSPH_OK;
  const int ng = sim->scene->nforces;
  const size_t cols = 1 + SIM_FORCE_COLS * (size_t)ng;
  double *row = malloc(cols * sizeof *row);
  CLSPH_CHECK(row != NULL, CLSPH_E_NOMEM, "out of memory");
  for (const char *c = k->rows; c != NULL && c < k->rows + k->bytes;) {
    char *end = NULL;
    row[0] = strtod(c, &end);
    for (int g = 0; g < ng; ++g) {
      double v[7];
      for (int j = 0; j < 7; ++j) v[j] = strtod(end + 1, &end);
      /* pressure x, y, viscous x, y, torque */
      memcpy(row + 1 + SIM_FORCE_COLS * g, v + 2, SIM_FORCE_COLS * sizeof *v);
    }
    CLSPH_TRY(force_row(sim, o, row));
    c = strchr(end, '\n');
    if (c != NULL) ++c;
  }
done:
  free(row);
  return st;
}

/* The case's sample(sim) now, into o->values; a failure is the run's (status, class). */
static enum clsph_status sample_call(struct sim *sim, struct run_out *o,
                                     const struct case_sim_api *api)
{
  enum clsph_status st = case_sample(o->script, api, &o->values);
  if (st != CLSPH_OK) {
    snprintf(sim->status, sizeof sim->status, "sample() failed at step %ld, t = %.9g s", sim->step,
             sim->time);
    snprintf(sim->failure, sizeof sim->failure, "metrics");
  }
  return st;
}

/* One row of the samples' history (sim->samples): time, then the values in column order. */
static enum clsph_status samples_row(struct sim *sim, double t, const double *v)
{
  enum clsph_status st = CLSPH_OK;
  struct sim_samples *h = &sim->samples;
  const size_t cols = 1 + (size_t)h->ncols;
  if (h->nrows == h->cap) {
    const size_t cap = h->cap ? 2 * h->cap : 64;
    double *r = realloc(h->rows, cap * cols * sizeof *r);
    CLSPH_CHECK(r != NULL, CLSPH_E_NOMEM, "out of memory for the sample history");
    h->rows = r;
    h->cap = cap;
  }
  h->rows[h->nrows * cols] = t;
  memcpy(h->rows + h->nrows * cols + 1, v, (size_t)h->ncols * sizeof *v);
  ++h->nrows;
done:
  return st;
}

/* The history starts with the columns of o->values and the kept rows of series.csv (a
 * restart's: the values as the file holds them, 9 digits, like the rows written later). */
static enum clsph_status samples_init(struct sim *sim, struct run_out *o,
                                      const struct kept_series *k)
{
  enum clsph_status st = CLSPH_OK;
  struct sim_samples *h = &sim->samples;
  double *v = NULL;
  free(h->names);
  h->names = malloc((size_t)o->values.n * sizeof *h->names);
  v = malloc((size_t)o->values.n * sizeof *v);
  CLSPH_CHECK(h->names != NULL && v != NULL, CLSPH_E_NOMEM, "out of memory");
  memcpy(h->names, o->values.names, (size_t)o->values.n * sizeof *h->names);
  h->ncols = o->values.n;
  h->nrows = 0;
  for (const char *c = k->rows; c != NULL && c < k->rows + k->bytes;) {
    char *end = NULL;
    const double t = strtod(c, &end);
    for (int j = 0; j < h->ncols; ++j) v[j] = strtod(end + 1, &end);
    CLSPH_TRY(samples_row(sim, t, v));
    c = strchr(end, '\n');
    if (c != NULL) ++c;
  }
done:
  free(v);
  return st;
}

/* Open the CSV series of the run. On a restart (restart: the checkpoint's path), each goes on
 * from the rows the restarted run wrote up to the checkpoint's time, so that it reads as one
 * run. */
enum clsph_status series_open(struct sim *sim, struct run_out *o, const char *restart)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  char *path = NULL, name[SCENE_NAME + 32], prefix[SCENE_NAME + 2];
  const int np = s->nprofiles;
  /* the kept rows of the profiles, then of the probes, the flow control, the forces and the
   * case's samples */
  struct kept_series *kept = calloc((size_t)np + 4, sizeof *kept);
  CLSPH_CHECK(kept != NULL, CLSPH_E_NOMEM, "out of memory");
  if (restart != NULL) {
    for (int p = 0; p < np; ++p) {
      snprintf(name, sizeof name, "profile_%s.csv", s->profiles[p].name);
      CLSPH_TRY(series_keep(restart, name, sim->time, 0, &kept[p]));
    }
    if (s->nprobes > 0) CLSPH_TRY(series_keep(restart, "probes.csv", sim->time, 0, &kept[np]));
    if (s->flow.on) /* its rows are written as each step begins */
      CLSPH_TRY(series_keep(restart, "flow_control.csv", sim->time, 1, &kept[np + 1]));
    if (s->nforces > 0) CLSPH_TRY(series_keep(restart, "forces.csv", sim->time, 0, &kept[np + 2]));
    if (case_has_sample(o->script))
      CLSPH_TRY(series_keep(restart, "series.csv", sim->time, 0, &kept[np + 3]));
  }
  if (s->nprobes > 0) {
    free(path);
    CLSPH_TRY(out_path(o, "probes.csv", &path));
    o->probes = fopen(path, "w");
    CLSPH_CHECK(o->probes != NULL, CLSPH_E_IO, "cannot write %s: %s", path, strerror(errno));
    fprintf(o->probes, "time");
    for (int p = 0; p < s->nprobes; ++p) {
      snprintf(prefix, sizeof prefix, "%s:", s->probes[p].name);
      csv_field_header(o->probes, &sim->ps, prefix);
    }
    fprintf(o->probes, "\n");
    CLSPH_TRY(series_resume(o->probes, path, &kept[np]));
  }
  if (np > 0) {
    o->profiles = calloc((size_t)np, sizeof *o->profiles);
    CLSPH_CHECK(o->profiles != NULL, CLSPH_E_NOMEM, "out of memory");
  }
  for (int p = 0; p < np; ++p) {
    snprintf(name, sizeof name, "profile_%s.csv", s->profiles[p].name);
    free(path);
    CLSPH_TRY(out_path(o, name, &path));
    o->profiles[p] = fopen(path, "w");
    CLSPH_CHECK(o->profiles[p] != NULL, CLSPH_E_IO, "cannot write %s: %s", path, strerror(errno));
    fprintf(o->profiles[p], sim->scene->dim == 3 ? "time,s,x,y,z" : "time,s,x,y");
    csv_field_header(o->profiles[p], &sim->ps, "");
    fprintf(o->profiles[p], "\n");
    CLSPH_TRY(series_resume(o->profiles[p], path, &kept[p]));
  }
  if (s->flow.on) {
    free(path);
    CLSPH_TRY(out_path(o, "flow_control.csv", &path));
    o->flow = fopen(path, "w");
    CLSPH_CHECK(o->flow != NULL, CLSPH_E_IO, "cannot write %s: %s", path, strerror(errno));
    fprintf(o->flow, "time,dt,body_force_x,slice_velocity,slice_particles\n");
    CLSPH_TRY(series_resume(o->flow, path, &kept[np + 1]));
  }
  if (s->nforces > 0) {
    free(path);
    CLSPH_TRY(out_path(o, "forces.csv", &path));
    o->force_stats = calloc((size_t)s->nforces, sizeof *o->force_stats);
    o->force_scratch = malloc((1 + SIM_FORCE_COLS * (size_t)s->nforces) * sizeof *o->force_scratch);
    CLSPH_CHECK(o->force_stats != NULL && o->force_scratch != NULL, CLSPH_E_NOMEM, "out of memory");
    o->forces = fopen(path, "w");
    CLSPH_CHECK(o->forces != NULL, CLSPH_E_IO, "cannot write %s: %s", path, strerror(errno));
    fprintf(o->forces, "time");
    for (int g = 0; g < s->nforces; ++g) {
      const char *n = s->forces[g];
      fprintf(o->forces,
              ",%s:fx,%s:fy,%s:fx_pressure,%s:fy_pressure,%s:fx_viscous,%s:fy_viscous,%s:torque", n,
              n, n, n, n, n, n);
    }
    fprintf(o->forces, "\n");
    CLSPH_TRY(series_resume(o->forces, path, &kept[np + 2]));
    CLSPH_TRY(forces_reload(sim, o, &kept[np + 2]));
  }
  if (case_has_sample(o->script)) {
    /* a first call names the columns (a fresh run's state at t = 0, a restart's at its
     * checkpoint: a row for it is written with the snapshot, or was kept) */
    struct case_sim_api api;
    metrics_api(sim, o->dir, &api);
    CLSPH_TRY(sample_call(sim, o, &api));
    free(path);
    CLSPH_TRY(out_path(o, "series.csv", &path));
    o->samples = fopen(path, "w");
    CLSPH_CHECK(o->samples != NULL, CLSPH_E_IO, "cannot write %s: %s", path, strerror(errno));
    fprintf(o->samples, "time");
    for (int c = 0; c < o->values.n; ++c) fprintf(o->samples, ",%s", o->values.names[c]);
    fprintf(o->samples, "\n");
    CLSPH_TRY(series_resume(o->samples, path, &kept[np + 3]));
    CLSPH_TRY(samples_init(sim, o, &kept[np + 3]));
  }
done:
  for (int k = 0; kept != NULL && k < np + 4; ++k) kept_free(&kept[k]);
  free(kept);
  free(path);
  return st;
}

/* Append one row (time, then pressure x, y and viscous x, y of each group) to the force history
 * and update each group's peak and last force. */
static enum clsph_status force_row(struct sim *sim, struct run_out *o, const double *row)
{
  enum clsph_status st = CLSPH_OK;
  const int ng = sim->scene->nforces;
  const size_t cols = 1 + SIM_FORCE_COLS * (size_t)ng;
  if (sim->nforce_rows == sim->force_rows_cap) {
    size_t cap = sim->force_rows_cap ? 2 * sim->force_rows_cap : 64;
    double *r = realloc(sim->force_rows, cap * cols * sizeof *r);
    CLSPH_CHECK(r != NULL, CLSPH_E_NOMEM, "out of memory for the force history");
    sim->force_rows = r;
    sim->force_rows_cap = cap;
  }
  memcpy(sim->force_rows + sim->nforce_rows * cols, row, cols * sizeof *row);
  ++sim->nforce_rows;
  for (int g = 0; g < ng; ++g) {
    const double *q = row + 1 + SIM_FORCE_COLS * g, ft[2] = {q[0] + q[2], q[1] + q[3]};
    struct force_stat *fs = &o->force_stats[g];
    if (hypot(ft[0], ft[1]) > fs->peak) {
      fs->peak = hypot(ft[0], ft[1]);
      fs->peak_time = row[0];
      memcpy(fs->peak_f, ft, sizeof ft);
    }
    memcpy(fs->last, ft, sizeof ft);
  }
done:
  return st;
}

/* Sample every recorded field at np points (probes NULL) or at the np probes (a point's value, or
 * a face's mean: sim_sample_probes); one row of values per point into rows. */
static enum clsph_status sample_all(struct sim *sim, size_t np, const double *at, int order,
                                    const struct scene_probe *probes, double *rows, int ncols)
{
  enum clsph_status st = CLSPH_OK;
  double *tmp = malloc(4 * np * sizeof *tmp);
  int col = 0;
  CLSPH_CHECK(tmp != NULL, CLSPH_E_NOMEM, "out of memory");
  for (int k = 0; k < sim->ps.nfields; ++k) {
    const struct pfield *p = &sim->ps.f[k];
    if (!sampled(p)) continue;
    if (probes != NULL)
      CLSPH_TRY(sim_sample_probes(sim, k, (int)np, probes, tmp));
    else
      CLSPH_TRY(sim_sample(sim, k, order, np, at, tmp));
    for (size_t i = 0; i < np; ++i)
      for (int c = 0; c < p->nout; ++c)
        rows[i * (size_t)ncols + (size_t)(col + c)] = tmp[i * (size_t)p->ncomp + (size_t)c];
    col += p->nout;
  }
done:
  free(tmp);
  return st;
}

static int sampled_columns(const struct pset *ps)
{
  int n = 0;
  for (int k = 0; k < ps->nfields; ++k)
    if (sampled(&ps->f[k])) n += ps->f[k].nout;
  return n;
}

enum clsph_status series_write(struct sim *sim, struct run_out *o, int what)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  const int nc = sampled_columns(&sim->ps);
  double *at = NULL, *rows = NULL;
  /* the probes and the velocity gradient at the walls sum over neighbours: the cell table must be
   * current (sorting is idempotent, so the next step's sort and a restart see the same order) */
  if ((s->nprobes > 0 || s->nforces > 0) && (what & SERIES_TIME)) CLSPH_TRY(sim_sort(sim));
  if (s->nprobes > 0 && (what & SERIES_TIME)) {
    rows = malloc((size_t)s->nprobes * (size_t)(nc + 1) * sizeof *rows);
    CLSPH_CHECK(rows != NULL, CLSPH_E_NOMEM, "out of memory");
    CLSPH_TRY(sample_all(sim, (size_t)sim->scene->nprobes, NULL, 0, sim->scene->probes, rows, nc));
    fprintf(o->probes, "%.17g", sim->time);
    for (int i = 0; i < s->nprobes * nc; ++i) fprintf(o->probes, ",%.9g", rows[i]);
    fprintf(o->probes, "\n");
    fflush(o->probes);
    free(rows);
    rows = NULL;
  }
  for (int p = 0; p < s->nprofiles && (what & SERIES_PROFILES); ++p) {
    const struct scene_profile_line *pl = &s->profiles[p];
    const size_t np = (size_t)pl->npts, dim = (size_t)s->dim;
    at = malloc(dim * np * sizeof *at);
    rows = malloc(np * (size_t)(nc + 1) * sizeof *rows);
    CLSPH_CHECK(at != NULL && rows != NULL, CLSPH_E_NOMEM, "out of memory");
    double len2 = 0.0;
    for (size_t a = 0; a < dim; ++a) len2 += (pl->b[a] - pl->a[a]) * (pl->b[a] - pl->a[a]);
    for (size_t i = 0; i < np; ++i) {
      double t = (double)i / (double)(np - 1);
      for (size_t a = 0; a < dim; ++a) at[dim * i + a] = pl->a[a] + t * (pl->b[a] - pl->a[a]);
    }
    CLSPH_TRY(sample_all(sim, np, at, pl->order, NULL, rows, nc));
    const double len = sqrt(len2);
    for (size_t i = 0; i < np; ++i) {
      fprintf(o->profiles[p], "%.17g,%.9g", sim->time, len * (double)i / (double)(np - 1));
      for (size_t a = 0; a < dim; ++a) fprintf(o->profiles[p], ",%.9g", at[dim * i + a]);
      for (int c = 0; c < nc; ++c)
        fprintf(o->profiles[p], ",%.9g", rows[i * (size_t)nc + (size_t)c]);
      fprintf(o->profiles[p], "\n");
    }
    fflush(o->profiles[p]);
    free(at);
    free(rows);
    at = rows = NULL;
  }
  if (s->nforces > 0 && (what & SERIES_TIME)) {
    double *row = o->force_scratch;
    row[0] = sim->time;
    fprintf(o->forces, "%.17g", sim->time);
    for (int g = 0; g < s->nforces; ++g) {
      struct wall_force f;
      CLSPH_TRY(sim->scheme->wall_force(sim, sim->state, s->forces[g], &f));
      double *q = row + 1 + SIM_FORCE_COLS * g;
      q[0] = recorded(f.pressure[0]);
      q[1] = recorded(f.pressure[1]);
      q[2] = recorded(f.viscous[0]);
      q[3] = recorded(f.viscous[1]);
      q[4] = recorded(f.torque);
      fprintf(o->forces, ",%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g", q[0] + q[2], q[1] + q[3], q[0],
              q[1], q[2], q[3], q[4]);
    }
    fprintf(o->forces, "\n");
    fflush(o->forces);
    CLSPH_TRY(force_row(sim, o, row));
  }
  if (o->samples != NULL && (what & SERIES_TIME)) {
    struct case_sim_api api;
    metrics_api(sim, o->dir, &api);
    CLSPH_TRY(sample_call(sim, o, &api));
    fprintf(o->samples, "%.17g", sim->time);
    for (int c = 0; c < o->values.n; ++c) {
      o->values.values[c] = recorded(o->values.values[c]);
      fprintf(o->samples, ",%.9g", o->values.values[c]);
    }
    fprintf(o->samples, "\n");
    fflush(o->samples);
    CLSPH_TRY(samples_row(sim, sim->time, o->values.values));
  }
  if (o->flow != NULL) fflush(o->flow);
done:
  free(at);
  free(rows);
  return st;
}
