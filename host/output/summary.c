/* summary.c: summary.json, what ran, its cost, its status and the case's metrics. */
#include "summary.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scheme.h"
#include "clsph_config.h"
#include "geometry.h"
#include "interrupt.h"
#include "kern.h"
#include "log.h"
#include "metrics.h"
/* "profile": the run's device time per kernel, slowest first (--profile). */
static enum clsph_status summary_profile(cJSON *root, struct kern_profile *p, double wall)
{
  enum clsph_status st = CLSPH_OK;
  struct kern_profile_entry *e = NULL;
  size_t n = 0;
  double device = 0.0;
  CLSPH_TRY(kern_profile_entries(p, &e, &n, &device));
  cJSON *prof = cJSON_AddObjectToObject(root, "profile");
  int ok = prof != NULL && cJSON_AddNumberToObject(prof, "device_seconds", device) != NULL &&
           cJSON_AddNumberToObject(prof, "wall_seconds", wall) != NULL;
  cJSON *kernels = ok ? cJSON_AddArrayToObject(prof, "kernels") : NULL;
  ok = kernels != NULL;
  for (size_t i = 0; i < n && ok; ++i) {
    cJSON *k = cJSON_CreateObject();
    ok = k != NULL && cJSON_AddItemToArray(kernels, k) &&
         cJSON_AddStringToObject(k, "name", e[i].name) != NULL &&
         cJSON_AddNumberToObject(k, "launches", (double)e[i].launches) != NULL &&
         cJSON_AddNumberToObject(k, "seconds", e[i].seconds) != NULL;
  }
  CLSPH_CHECK(ok, CLSPH_E_NOMEM, "out of memory writing the profile");
done:
  free(e);
  return st;
}

/* The wall layer's y+ under a wall law that reports it per particle (the USAW schemes' k-ε:
 * fields u_star and y_plus, Leroy et al. eq 23): the fluid particles within δr of a wall
 * (distance y+ ν/u*), their smallest and mean y+ at the end of the run. The wall law holds on
 * the log law, y+ >= 11.06; with the wall layer in the viscous sublayer the model has no buffer
 * layer (the channel at e+ = 640 and 40 rows, y+ = 8: u+ 10-14% under the reference), so a mean
 * under it is warned of, unless the scalable wall law holds y+ at 11.06 there. Nothing where the
 * fields are absent. */
static enum clsph_status wall_layer_y_plus(struct sim *sim, cJSON *tb)
{
  enum clsph_status st = CLSPH_OK;
  const int fy = pset_find(&sim->ps, "y_plus"), fu = pset_find(&sim->ps, "u_star");
  const size_t n = sim->ps.n;
  real *yp = NULL, *us = NULL;
  cl_uint *kind = NULL;
  if (fy < 0 || fu < 0 || n == 0 || !(sim->scene->nu > 0.0)) goto done;
  yp = malloc(n * sizeof *yp);
  us = malloc(n * sizeof *us);
  kind = malloc(n * sizeof *kind);
  CLSPH_CHECK(yp != NULL && us != NULL && kind != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(kern_read(sim->dev, sim->ps.f[fy].d, n * sizeof *yp, yp));
  CLSPH_TRY(kern_read(sim->dev, sim->ps.f[fu].d, n * sizeof *us, us));
  CLSPH_TRY(kern_read(sim->dev, pset_mem(&sim->ps, sim->f_kind), n * sizeof *kind, kind));
  double lo = HUGE_VAL, sum = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < n; ++i) {
    if (kind[i] != KIND_FLUID || !(us[i] > 0) || !(yp[i] > 0)) continue;
    if ((double)yp[i] * sim->scene->nu / (double)us[i] >= sim->scene->dr) continue;
    lo = fmin(lo, (double)yp[i]);
    sum += (double)yp[i];
    ++count;
  }
  if (count == 0) goto done;
  cJSON_AddNumberToObject(tb, "wall_layer_particles", (double)count);
  cJSON_AddNumberToObject(tb, "wall_layer_y_plus_min", lo);
  cJSON_AddNumberToObject(tb, "wall_layer_y_plus_mean", sum / (double)count);
  if (sum / (double)count < 11.06 && sim->scene->turb.wall_law != 1)
    log_warn("turbulence: the particles within dr of the walls stand at y+ = %.3g on average "
             "(the smallest %.3g), in the viscous sublayer: the wall law (eq 23) is a log law "
             "from y+ = 11.06 on and the k-epsilon model has no buffer layer, so the velocity "
             "above runs low; coarsen the particles next to the walls to y+ 30-100, or take "
             "turbulence { wall_law = \"scalable\" } (y+ held at 11.06)",
             sum / (double)count, lo);
done:
  free(yp);
  free(us);
  free(kind);
  return st;
}

/* The failure class of a run the time loop stopped in a finite state, whose metrics() still tell
 * how far it went (a sensor's history up to a clustering, a front before a wall crossing); NULL
 * for a run that reached its end, an input or I/O error, a stop by metrics() or sample(), an
 * interrupt, a refusal at step 0, and a non-finite state (a NaN position has no cell to
 * search). */
static const char *stopped_state(const struct sim *sim)
{
  static const char *const finite[] = {"escaped",    "neighbours", "wall_crossing",
                                       "clustering", "energy",     "dt_collapse",
                                       "dt_bound",   "solver",     "flow_control"};
  if (strcmp(sim->status, "ok") == 0 || sim->step == 0) return NULL; /* step 0: refused input */
  for (size_t i = 0; i < sizeof finite / sizeof *finite; ++i)
    if (strcmp(sim->failure, finite[i]) == 0) return finite[i];
  return NULL;
}

enum clsph_status summary_write(struct sim *sim, const struct run_out *o, double wall,
                                struct case_script *script)
{
  enum clsph_status st = CLSPH_OK;
  char *path = NULL;
  char *text = NULL;
  FILE *f = NULL;
  cJSON *root = cJSON_CreateObject();
  CLSPH_CHECK(root != NULL, CLSPH_E_NOMEM, "out of memory");
  cJSON_AddStringToObject(root, "case", sim->scene->name);
  cJSON_AddStringToObject(root, "case_path", sim->scene->case_path);
  cJSON_AddStringToObject(root, "scheme", sim->scheme->name);
  cJSON_AddStringToObject(root, "precision", CLSPH_PRECISION_NAME);
  cJSON_AddStringToObject(root, "device", sim->dev->name);
  cJSON_AddStringToObject(root, "clsph_version", CLSPH_VERSION);
  cJSON_AddNumberToObject(root, "particles", (double)sim->ps.n);
  cJSON_AddNumberToObject(root, "fluid_particles", (double)sim->geom.nfluid);
  cJSON_AddNumberToObject(root, "steps", (double)sim->step);
  cJSON_AddNumberToObject(root, "sim_time", sim->time);
  /* wall time and rate of this run: a restarted one counts from its checkpoint */
  if (sim->step0 > 0) {
    cJSON_AddNumberToObject(root, "restarted_at_step", (double)sim->step0);
    cJSON_AddNumberToObject(root, "wall_seconds_whole_run", sim->wall_before + wall);
  }
  cJSON_AddNumberToObject(root, "wall_seconds", wall);
  /* of which the outputs and the set-up before the first step (the case's sample() included),
   * and the steps themselves: what the solver costs, apart from what a run chose to write */
  cJSON_AddNumberToObject(root, "output_seconds", sim->out_wall);
  cJSON_AddNumberToObject(root, "step_seconds", wall - sim->out_wall);
  cJSON_AddNumberToObject(root, "particle_steps_per_second",
                          wall > 0.0 ? (double)sim->ps.n * (double)(sim->step - sim->step0) / wall
                                     : 0.0);
  /* what a scheme with acoustic sub-steps or counted pair interactions reports, over the whole
   * run (a restart's checkpoint carries the sums before it) */
  if (sim->substeps_sum > 0) cJSON_AddNumberToObject(root, "substeps", (double)sim->substeps_sum);
  if (sim->pairs_sum > 0.0) cJSON_AddNumberToObject(root, "pair_interactions", sim->pairs_sum);
  if (sim->scene->turb.on) { /* a clipped k or ε is counted, never silent */
    cJSON *tb = cJSON_AddObjectToObject(root, "turbulence");
    cJSON_AddStringToObject(tb, "model", sim->scene->turb.model);
    const double kc = sim->turb_clip_counts ? (double)sim->turb_clip_counts[0] : 0.0,
                 ec = sim->turb_clip_counts ? (double)sim->turb_clip_counts[1] : 0.0;
    cJSON_AddNumberToObject(tb, "k_clipped", kc);
    cJSON_AddNumberToObject(tb, "epsilon_clipped", ec);
    if (kc + ec > 0.0)
      log_warn("turbulence: %.0f negative k and %.0f negative epsilon values were clipped to a "
               "millionth of their previous value (summary.json: turbulence)",
               kc, ec);
    /* best effort: a summary is written also after a failure that left the device unreadable */
    if (wall_layer_y_plus(sim, tb) != CLSPH_OK)
      log_warn("turbulence: the wall layer's y+ could not be read back (summary.json without it)");
  }
  cJSON_AddStringToObject(root, "status", sim->status);
  cJSON_AddStringToObject(root, "failure", sim->failure);
  cJSON_AddNumberToObject(root, "snapshots", o->nsnap);
  cJSON *params = cJSON_AddObjectToObject(root, "parameters");
  for (int i = 0; i < sim->scene->nparams; ++i)
    cJSON_AddNumberToObject(params, sim->scene->params[i].name, sim->scene->params[i].value);
  if (sim->solver_steps > 0) {
    cJSON *sv = cJSON_AddObjectToObject(root, "solver");
    cJSON_AddNumberToObject(sv, "iterations_mean",
                            (double)sim->solver_its_sum / (double)sim->solver_steps);
    cJSON_AddNumberToObject(sv, "iterations_max", (double)sim->solver_its_max);
    if (sim->aux_its_sum > 0) /* both components of the implicit viscous prediction */
      cJSON_AddNumberToObject(sv, "viscous_iterations_mean",
                              (double)sim->aux_its_sum / (double)sim->solver_steps);
  }
  if (o->force_stats != NULL) { /* over the rows of forces.csv (a restart's included) */
    cJSON *fo = cJSON_AddObjectToObject(root, "forces");
    CLSPH_CHECK(fo != NULL, CLSPH_E_NOMEM, "out of memory");
    for (int g = 0; g < sim->scene->nforces; ++g) {
      const struct force_stat *fs = &o->force_stats[g];
      cJSON *e = cJSON_AddObjectToObject(fo, sim->scene->forces[g]);
      CLSPH_CHECK(e != NULL, CLSPH_E_NOMEM, "out of memory");
      cJSON_AddNumberToObject(e, "peak", fs->peak);
      cJSON_AddNumberToObject(e, "peak_time", fs->peak_time);
      cJSON_AddNumberToObject(e, "peak_fx", fs->peak_f[0]);
      cJSON_AddNumberToObject(e, "peak_fy", fs->peak_f[1]);
      cJSON_AddNumberToObject(e, "last_fx", fs->last[0]);
      cJSON_AddNumberToObject(e, "last_fy", fs->last[1]);
    }
  }
  if (sim->open_waiting_max >= 0) /* entry particles that waited for a recycled one */
    cJSON_AddNumberToObject(root, "entry_waiting_max", (double)sim->open_waiting_max);
  cJSON *wc = cJSON_AddObjectToObject(root, "wall_crossings");
  CLSPH_CHECK(wc != NULL, CLSPH_E_NOMEM, "out of memory");
  cJSON_AddNumberToObject(wc, "steps", (double)sim->wall_steps);
  cJSON_AddNumberToObject(wc, "most_at_one_step", (double)sim->wall_most);
  cJSON_AddNumberToObject(wc, "first_step", (double)sim->wall_first_step);
  if (sim->wall_first_step >= 0) cJSON_AddNumberToObject(wc, "first_time", sim->wall_first_time);
  cJSON_AddNumberToObject(wc, "deepest_dr", sim->wall_depth_max);
  cJSON *ex = cJSON_AddObjectToObject(root, "escaped"); /* fluid dropped from the run */
  CLSPH_CHECK(ex != NULL, CLSPH_E_NOMEM, "out of memory");
  cJSON_AddNumberToObject(ex, "particles", (double)sim->escaped);
  cJSON_AddNumberToObject(
      ex, "fraction", sim->geom.nfluid > 0 ? (double)sim->escaped / (double)sim->geom.nfluid : 0.0);
  cJSON_AddNumberToObject(ex, "first_step", (double)sim->escaped_first_step);
  if (sim->escaped_first_step >= 0)
    cJSON_AddNumberToObject(ex, "first_time", sim->escaped_first_time);
  if (sim->health_checks > 0) { /* the health checks' worst values over the run */
    cJSON *h = cJSON_AddObjectToObject(root, "health");
    CLSPH_CHECK(h != NULL, CLSPH_E_NOMEM, "out of memory");
    cJSON_AddNumberToObject(h, "checks", (double)sim->health_checks);
    cJSON_AddNumberToObject(h, "velocity_scale", sim->u_ref);
    cJSON_AddNumberToObject(h, "kinetic_energy_ratio_max", sim->energy_ratio_max);
    cJSON_AddNumberToObject(h, "nearest_spacing_min_dr", sim->spacing_min);
    cJSON_AddNumberToObject(h, "clustered_fraction_max", sim->cluster_max);
    cJSON_AddNumberToObject(h, "cluster_distance_dr",
                            sim->scene->checks.cluster_h * sim->sm.h / sim->scene->dr);
  }
  if (sim->dev->profile != NULL) CLSPH_TRY(summary_profile(root, sim->dev->profile, wall));
  cJSON *metrics = cJSON_AddObjectToObject(root, "metrics");
  CLSPH_CHECK(params != NULL && metrics != NULL, CLSPH_E_NOMEM, "out of memory");
  const char *stopped = stopped_state(sim);
  if (script != NULL && stopped != NULL) { /* the metrics of the state the run stopped in */
    struct case_sim_api api;
    metrics_api(sim, o->dir, &api);
    api.stopped = stopped;
    if (case_metrics(script, &api, metrics) != CLSPH_OK) /* its message above; status stays */
      log_warn("metrics() of the state the run stopped in (%s) failed: summary.json has none",
               stopped);
    else
      cJSON_AddTrueToObject(root, "metrics_at_stop");
  } else if (script != NULL && strcmp(sim->status, "ok") == 0) {
    struct case_sim_api api;
    metrics_api(sim, o->dir, &api);
    enum clsph_status ms = case_metrics(script, &api, metrics);
    if (ms != CLSPH_OK && interrupt_signal() != 0) { /* Ctrl-C while metrics() ran */
      snprintf(sim->status, sizeof sim->status, "interrupted (%s) while metrics() ran",
               interrupt_name(interrupt_signal()));
      snprintf(sim->failure, sizeof sim->failure, "interrupted");
    } else if (ms != CLSPH_OK) {
      snprintf(sim->status, sizeof sim->status, "metrics failed");
      snprintf(sim->failure, sizeof sim->failure, "metrics");
    }
    cJSON_ReplaceItemInObject(root, "status", cJSON_CreateString(sim->status));
    cJSON_ReplaceItemInObject(root, "failure", cJSON_CreateString(sim->failure));
  }
  text = cJSON_Print(root);
  CLSPH_CHECK(text != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(out_path(o, "summary.json", &path));
  f = fopen(path, "w");
  CLSPH_CHECK(f != NULL, CLSPH_E_IO, "cannot write %s: %s", path, strerror(errno));
  CLSPH_CHECK(fputs(text, f) >= 0 && fputc('\n', f) != EOF, CLSPH_E_IO, "cannot write %s", path);
done:
  if (f != NULL && fclose(f) != 0 && st == CLSPH_OK) {
    log_error("cannot write %s", path);
    st = CLSPH_E_IO;
  }
  free(text);
  free(path);
  cJSON_Delete(root);
  return st;
}
