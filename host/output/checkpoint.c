/* checkpoint.c: checkpoints of a run (every field, bit for bit, with the host state of the
 * flow-rate control and the scheme), and a restart from one. */
#include "checkpoint.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scheme.h"
#include "snapshot.h"
/* The checkpoint's blob: the flow-rate control's state (when on), then the scheme's host doubles
 * (scheme_ops.persist). */
static enum clsph_status state_blob(struct sim *sim, unsigned char *blob, size_t cap, size_t *bytes)
{
  enum clsph_status st = CLSPH_OK;
  size_t n = 0;
  if (sim->scene->flow.on) {
    memcpy(blob, &sim->flow, sizeof sim->flow);
    n = sizeof sim->flow;
  }
  int count = 0;
  const double *v = sim->scheme->persist != NULL ? sim->scheme->persist(sim->state, &count) : NULL;
  CLSPH_CHECK(n + (size_t)count * sizeof(double) <= cap, CLSPH_E_UNSUPPORTED,
              "%s carries %d doubles of state, more than a checkpoint holds", sim->scheme->name,
              count);
  if (count > 0) memcpy(blob + n, v, (size_t)count * sizeof(double));
  *bytes = n + (size_t)count * sizeof(double);
done:
  return st;
}

/* Restores what state_blob saved; a checkpoint without the scheme's state (written before
 * schemes kept any) restarts with a warning: the run goes on, not bit for bit. */
static enum clsph_status restore_blob(struct sim *sim, const char *path, const unsigned char *blob,
                                      size_t bytes)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  const size_t flow = s->flow.on ? sizeof sim->flow : 0;
  CLSPH_CHECK(bytes >= flow, CLSPH_E_INPUT,
              "%s: the checkpoint has no flow-rate control state (%zu bytes of %zu), which %s "
              "needs",
              path, bytes, flow, s->case_path);
  if (flow > 0) memcpy(&sim->flow, blob, flow);
  int count = 0;
  double *v = sim->scheme->persist != NULL ? sim->scheme->persist(sim->state, &count) : NULL;
  const size_t want = (size_t)count * sizeof(double);
  if (bytes - flow == want) {
    if (count > 0) memcpy(v, blob + flow, want);
  } else if (bytes == flow) {
    log_warn("%s: the checkpoint carries no %s state (written by an older clsph): the run "
             "continues, but not bit for bit",
             path, sim->scheme->name);
  } else {
    CLSPH_CHECK(0, CLSPH_E_INPUT,
                "%s: the checkpoint carries %zu bytes of scheme state, %s keeps %zu", path,
                bytes - flow, sim->scheme->name, want);
  }
done:
  return st;
}

/* The figures of the whole run that summary.json reports (solver iterations, acoustic
 * sub-steps and pair interactions, wall crossings, the health checks' worst values, the fluid
 * dropped on leaving the domain, the
 * wall-clock time so far): a checkpoint carries them, so that the summary of a restarted run
 * describes the whole run. The wall-clock time stays last (checkpoint_write sets it). */
enum { NSTATS = 20 };
struct run_stats {
  const char *names[NSTATS];
  double values[NSTATS];
  long *l[NSTATS]; /* the field of struct sim each names (a long or a double) */
  double *d[NSTATS];
};

static void stats_of(struct sim *sim, struct run_stats *r)
{
  int k = 0;
  memset(r, 0, sizeof *r);
#define STAT_L(field) r->names[k] = #field, r->l[k++] = &sim->field
#define STAT_D(field) r->names[k] = #field, r->d[k++] = &sim->field
  STAT_L(solver_its_sum);
  STAT_L(solver_its_max);
  STAT_L(solver_steps);
  STAT_L(aux_its_sum);
  STAT_L(substeps_sum);
  STAT_D(pairs_sum);
  STAT_L(open_waiting_max);
  STAT_L(wall_steps);
  STAT_L(wall_most);
  STAT_L(wall_first_step);
  STAT_D(wall_first_time);
  STAT_D(wall_depth_max);
  STAT_L(health_checks);
  STAT_D(energy_ratio_max);
  STAT_D(spacing_min);
  STAT_D(cluster_max);
  STAT_L(escaped);
  STAT_L(escaped_first_step);
  STAT_D(escaped_first_time);
  STAT_D(wall_before); /* the wall-clock seconds of the run up to the checkpoint */
#undef STAT_L
#undef STAT_D
  for (int i = 0; i < NSTATS; ++i) r->values[i] = r->l[i] != NULL ? (double)*r->l[i] : *r->d[i];
}

enum clsph_status checkpoint_write(struct sim *sim, struct run_out *o)
{
  enum clsph_status st = CLSPH_OK;
  char name[64], *path = NULL;
  struct io_meta m;
  struct run_stats rs;
  snapshot_meta(sim, &m);
  m.digest = sim->digest;
  stats_of(sim, &rs);
  rs.values[NSTATS - 1] = sim->wall_before + sim->wall; /* up to now */
  m.nstats = NSTATS;
  m.stat_names = rs.names;
  m.stats = rs.values;
  snprintf(name, sizeof name, "checkpoint_%06ld.h5", sim->step);
  CLSPH_TRY(out_path(o, name, &path));
  /* the flow-rate control's state and the scheme's host state travel in the blob, so a restart
   * continues bit for bit */
  unsigned char blob[sizeof sim->flow + 64 * sizeof(double)];
  size_t bytes = 0;
  CLSPH_TRY(state_blob(sim, blob, sizeof blob, &bytes));
  CLSPH_TRY(io_checkpoint_write(path, sim->dev, &sim->ps, &m, bytes > 0 ? blob : NULL, bytes));
  o->checkpoint_step = sim->step;
  log_debug("checkpoint %s at t = %g s", path, sim->time);
done:
  free(path);
  return st;
}

enum clsph_status checkpoint_restore(struct sim *sim, const char *path, struct run_out *o)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  struct io_meta expect, got;
  struct run_stats rs;
  void *blob = NULL;
  size_t blob_bytes = 0;
  snapshot_meta(sim, &expect);
  expect.digest = sim->digest;
  memset(&got, 0, sizeof got);
  stats_of(sim, &rs);
  expect.nstats = NSTATS;
  expect.stat_names = rs.names;
  expect.stats = rs.values;
  for (int k = 0; k < NSTATS; ++k) rs.values[k] = NAN; /* NaN: not in the checkpoint */
  CLSPH_TRY(io_checkpoint_read(path, sim->dev, &sim->ps, &expect, &got, &blob, &blob_bytes));
  CLSPH_TRY(restore_blob(sim, path, blob, blob_bytes));
  if (got.stats_read == 0) {
    log_warn("%s carries none of the %d figures of the run before it (written by an older "
             "clsph): summary.json's solver, wall-crossing and health figures start from the "
             "checkpoint",
             path, NSTATS);
  } else {
    /* each figure the checkpoint has; one an older clsph did not write starts from here */
    char missing[512] = ""; /* room for every name: NSTATS names of under 24 characters */
    for (int k = 0; k < NSTATS; ++k) {
      if (isnan(rs.values[k])) {
        const size_t len = strlen(missing);
        snprintf(missing + len, sizeof missing - len, "%s%s", len > 0 ? ", " : "", rs.names[k]);
        continue;
      }
      if (rs.l[k] != NULL) *rs.l[k] = (long)rs.values[k];
      if (rs.d[k] != NULL) *rs.d[k] = rs.values[k];
    }
    if (got.stats_read < NSTATS)
      log_warn("%s carries %d of the %d figures of the run before it (written by an older clsph): "
               "summary.json counts %s from the checkpoint",
               path, got.stats_read, NSTATS, missing);
  }
  sim->body_force[0] = s->flow.on ? sim->flow.force : s->body_force[0];
  sim->time = got.time;
  sim->step = got.step;
  sim->step0 = got.step;
  sim->dt = got.dt;
  o->nsnap = s->output_every > 0.0 ? (int)floor(sim->time / s->output_every + 1e-9) + 1 : 1;
  log_info("restarting from %s at t = %.9g s, step %ld", path, sim->time, sim->step);
done:
  free(blob);
  return st;
}
