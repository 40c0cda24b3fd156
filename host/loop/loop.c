/* loop.c: the time loop of a run.
 *
 * Each step: sort the particles by cell (every field reordered), ask the scheme for its largest
 * stable step, shorten it so that equal steps land exactly on the next output or checkpoint time
 * (k = ⌈remaining/bound⌉ steps of remaining/k: no short step before each output, which would
 * upset the flow-rate control), update the flow-rate control, step, and read the error flags.
 * Outputs in the output folder (host/output/):
 *   snap_NNNNNN.h5 + snapshots.xdmf    particle fields at the output cadence (ParaView)
 *   checkpoint_NNNNNN.h5               at the checkpoint cadence and at the end (--restart)
 *   probes.csv, profile_<name>.csv     interpolated fields at the output cadence
 *   forces.csv                         wall-group forces at the output cadence
 *   series.csv                         what the case's sample(sim) returns, at the same cadence
 *   frames/FIELD_NNNNNN.png, FIELD.mp4 with --frames: a frame with each snapshot, drawn from a
 *                                      host copy of the device state, and the movie at the end
 *   summary.json                       what ran, its cost (with --profile, the device time per
 *                                      kernel), its status and the case's metrics */
#include "loop.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "scheme.h"
#include "checkpoint.h"
#include "interrupt.h"
#include "kern.h"
#include "progress.h"
#include "series.h"
#include "snapshot.h"
#include "str.h"
#include "summary.h"

/* The next multiple of `every` after time t (a function of t alone, so a restart agrees). */
static double next_mark(double t, double every)
{
  if (!(every > 0.0)) return HUGE_VAL;
  double k = floor(t / every + 1e-9);
  double m = (k + 1.0) * every;
  return m > t ? m : m + every;
}

/* The cadences of the outputs, checked before anything is written: more than
 * run { max_snapshots } snapshots and checkpoints fill a disk unasked (run { output_every =
 * 1e-12 } once wrote thousands a minute). An interval below the time step is not refused: the
 * loop then cuts the steps to land on each output, which a short run (--set t_end) may want. */
static enum clsph_status check_cadence(const struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  const double every[2] = {s->output_every, s->checkpoint_every};
  double count = 0.0;
  for (int k = 0; k < 2; ++k)
    if (every[k] > 0.0) count += floor((s->t_end - sim->time) / every[k] + 1e-9);
  size_t bytes = 0;
  for (int k = 0; k < sim->ps.nfields; ++k)
    if (sim->ps.f[k].output) bytes += sim->ps.f[k].elem;
  CLSPH_CHECK(count <= s->max_snapshots, CLSPH_E_INPUT,
              "%s:%d: run: output_every and checkpoint_every ask for %.0f snapshots and "
              "checkpoints up to t_end = %g s (about %.3g GiB), more than run { max_snapshots = "
              "%.0f } allows: give longer intervals, or a larger max_snapshots knowingly",
              s->case_path, s->run_line, count, s->t_end,
              count * (double)bytes * (double)sim->ps.n / 1073741824.0, s->max_snapshots);
done:
  return st;
}

/* Before the first step: what the outputs need is there (the wall groups of forces, the field
 * of frames), a restart has its state back, the cadences are sane, the folder is this run's and
 * ready (what a run continued in place wrote after its checkpoint is gone), the snapshot index
 * and the series go on from the checkpoint's, and a fresh run writes its initial snapshot. */
static enum clsph_status start(struct sim *sim, const struct loop_options *opt, struct run_out *o)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  CLSPH_CHECK(s->nforces == 0 || sim->scheme->wall_force != NULL, CLSPH_E_INPUT,
              "%s: force { ... } asks for wall forces, which scheme '%s' does not compute",
              s->case_path, sim->scheme->name);
  for (int g = 0; g < s->nforces; ++g) {
    int found = 0;
    for (int w = 0; w < s->nwalls; ++w) found |= strcmp(s->walls[w].group, s->forces[g]) == 0;
    CLSPH_CHECK(found, CLSPH_E_INPUT, "%s: force: no wall group '%s'", s->case_path, s->forces[g]);
  }
  if (opt->frames != NULL && s->dim == 3) { /* the camera sees the fluid, from outside the walls */
    CLSPH_CHECK(strcmp(opt->frames->render.field, "vorticity") != 0, CLSPH_E_INPUT,
                "%s: --field vorticity is 2-D (ω = ∂v/∂x − ∂u/∂y); this scene is 3-D",
                s->case_path);
    const struct render_camera *c = &opt->frames->render.camera;
    int wall = -1;
    if (opt->frames->render.camera_set) CLSPH_TRY(geometry3_solid_at(s, c->eye, &wall));
    CLSPH_CHECK(wall < 0, CLSPH_E_INPUT,
                "%s:%d: the camera's eye (%g, %g, %g) is inside the wall of group '%s': it would "
                "see nothing; move it (render { camera } or --camera)",
                s->case_path, wall >= 0 ? s->walls[wall].line : 0, c->eye[0], c->eye[1], c->eye[2],
                wall >= 0 ? s->walls[wall].group : "");
  }
  if (opt->frames != NULL) { /* the field of frames exists, before anything is written */
    const char *names[PSET_MAX_FIELDS];
    int ncomp[PSET_MAX_FIELDS];
    struct field_spec f;
    const int n = snapshot_frame_fields(sim, names, ncomp);
    CLSPH_TRY(field_find(opt->frames->render.field, n, names, ncomp, &f));
  }
  /* a refused checkpoint, cadence or folder leaves the folder as it was (no summary.json) */
  if (opt->restart != NULL) CLSPH_TRY(checkpoint_restore(sim, opt->restart, o));
  CLSPH_TRY(check_cadence(sim));
  int here = 0; /* continuing a run in its own folder */
  CLSPH_TRY(out_claim_dir(opt->out_dir, opt->restart, opt->overwrite, &here));
  CLSPH_TRY(out_prepare_dir(opt->out_dir));
  o->dir = str_printf("%s", opt->out_dir);
  CLSPH_CHECK(o->dir != NULL, CLSPH_E_NOMEM, "out of memory");
  if (opt->frames != NULL) CLSPH_TRY(snapshot_open_frames(sim, opt->frames, opt->out_dir, o));
  if (here) CLSPH_TRY(out_drop_after(opt->out_dir, o->nsnap, sim->step));
  if (opt->restart != NULL) CLSPH_TRY(snapshot_resume_index(o, opt->restart));
  CLSPH_TRY(series_open(sim, o, opt->restart));
  if (opt->restart == NULL) CLSPH_TRY(snapshot_write(sim, o));
done:
  return st;
}

/* The length of the next step: the scheme's bound times cfl (or the fixed step, which must stay
 * within it), shortened so that equal steps land exactly on the next output, checkpoint or end.
 * `target` receives that time and `lands` whether this step reaches it. */
static enum clsph_status step_length(struct sim *sim, double *dt_out, double *target, int *lands)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  const double t_end = s->t_end;
  double dt = HUGE_VAL;
  if (sim->scheme->max_dt != NULL) CLSPH_TRY(sim->scheme->max_dt(sim, sim->state, &dt));
  dt *= s->cfl;
  if (s->dt > 0.0) { /* a fixed time step must stay within the scheme's bounds */
    if (s->dt > dt * (1.0 + 1e-9)) {
      snprintf(sim->status, sizeof sim->status,
               "the fixed time step %g s exceeds the stability bound %g s of %s (cfl %g) at "
               "step %ld, t = %.9g s",
               s->dt, dt, sim->scheme->name, s->cfl, sim->step, sim->time);
      log_error("%s: %s; use a smaller run { dt } or a larger cfl knowingly", s->case_path,
                sim->status);
      snprintf(sim->failure, sizeof sim->failure, "dt_bound");
      st = sim->step == 0 ? CLSPH_E_INPUT : CLSPH_E_BLOWUP;
      goto done;
    }
    dt = s->dt;
  }
  if (!(dt > 0.0) || (isfinite(dt) && dt < 1e-12 * fmax(t_end, 1.0))) {
    snprintf(sim->status, sizeof sim->status,
             "blow-up: the time step collapsed to %g s at step %ld, t = %.9g s; no setting "
             "controls this check (a step below 1e-12 of the run): look in the last snapshot for "
             "a particle that moves much faster than the flow",
             dt, sim->step, sim->time);
    st = sim_fail(sim, "dt_collapse");
    goto done;
  }
  *target = fmin(t_end, fmin(next_mark(sim->time, s->output_every),
                             next_mark(sim->time, s->checkpoint_every)));
  double left = *target - sim->time, k = ceil(left / dt * (1.0 - 1e-9));
  *lands = sim->time + dt >= *target * (1.0 - 1e-12) || !(k > 1.0);
  *dt_out = *lands ? left : left / k;
done:
  return st;
}

/* After a step: the time, the step count and the solver's iterations. */
static void advance(struct sim *sim, double dt, double target, int lands)
{
  sim->time = lands ? target : sim->time + dt;
  sim->dt = dt;
  ++sim->step;
  sim->substeps_sum += sim->substeps;
  sim->pairs_sum += sim->pairs;
  if (sim->step == sim->step0 + 1) /* the solvers have made their buffers */
    log_debug("device memory after the first step: %.1f MiB in buffers (estimated before the "
              "run: %.1f MiB)",
              (double)kern_allocated() / 1048576.0, sim->mem_estimate / 1048576.0);
  if (sim->solver_its > 0) {
    sim->solver_its_sum += sim->solver_its;
    sim->solver_steps += 1;
    if (sim->solver_its > sim->solver_its_max) sim->solver_its_max = sim->solver_its;
    sim->aux_its_sum += sim->aux_its;
  }
}

/* Is time t on the cadence `every` (a multiple of it)? */
static int on_cadence(double t, double every)
{
  return every > 0.0 && fabs(remainder(t, every)) < 1e-9 * every;
}

/* The blow-up checks of a step (checks.c). */
static enum clsph_status blowup_checks(struct sim *sim, int at_end)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  const int health = s->checks.every > 0 && (sim->step % s->checks.every == 0 || at_end);
  CLSPH_TRY(sim_check_step(sim, health));
done:
  return st;
}

/* After a step: the blow-up checks, then the outputs that fall due. A blow-up leaves the state
 * that failed the check in blowup.h5 beside the last good snapshot (where the particle left, which
 * pair clustered): the snapshot before it may be many steps earlier. */
static enum clsph_status check_and_write(struct sim *sim, struct run_out *o, double dt, int lands)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  const int at_end = sim->time >= s->t_end;
  st = blowup_checks(sim, at_end);
  if (st == CLSPH_E_BLOWUP) {
    if (snapshot_write_blowup(sim, o) == CLSPH_OK)
      log_info("the state at the blow-up (step %ld, t = %.9g s): %s/blowup.h5", sim->step,
               sim->time, o->dir);
    goto done;
  }
  CLSPH_TRY(st);
  /* time series at their own cadence: the first step at or past each multiple of sample_every */
  const int sample =
      s->sample_every > 0.0 && floor(sim->time / s->sample_every * (1.0 + 1e-12)) >
                                   floor((sim->time - dt) / s->sample_every * (1.0 + 1e-12));
  const int snap = lands && (at_end || on_cadence(sim->time, s->output_every));
  const int check = lands && (at_end || on_cadence(sim->time, s->checkpoint_every));
  if (!sample && !snap && !check) goto done;
  /* the outputs' own time (summary.json output_seconds), the step's kernels finished first */
  CLSPH_TRY(kern_finish(sim->dev));
  const double t0 = progress_now();
  if (sample) CLSPH_TRY(series_write(sim, o, SERIES_TIME));
  if (snap) CLSPH_TRY(snapshot_write(sim, o));
  if (check) CLSPH_TRY(checkpoint_write(sim, o));
  sim->out_wall += progress_now() - t0;
done:
  return st;
}

/* SIGINT or SIGTERM: the step is over; a checkpoint of the state reached (unless this step wrote
 * one) and the status, so that the summary says so and --restart resumes. During the set-up,
 * before the folder is claimed, nothing is written. */
static enum clsph_status interrupted(struct sim *sim, struct run_out *o, int sig)
{
  enum clsph_status st = CLSPH_OK;
  if (o->dir == NULL) { /* during the set-up: nothing is written */
    snprintf(sim->status, sizeof sim->status, "interrupted (%s) before the first step",
             interrupt_name(sig));
    snprintf(sim->failure, sizeof sim->failure, "interrupted");
    log_info("%s", sim->status);
    st = CLSPH_E_INTERRUPTED;
    goto done;
  }
  if (o->checkpoint_step != sim->step) CLSPH_TRY(checkpoint_write(sim, o));
  snprintf(sim->status, sizeof sim->status, "interrupted (%s) at step %ld, t = %.9g s",
           interrupt_name(sig), sim->step, sim->time);
  snprintf(sim->failure, sizeof sim->failure, "interrupted");
  log_info("%s; to resume: clsph run %s --restart %s/checkpoint_%06ld.h5 (and the same --set)",
           sim->status, sim->scene->case_path, o->dir, sim->step);
  st = CLSPH_E_INTERRUPTED;
done:
  return st;
}

/* The end of a run, however it ended: the status and failure class worded, summary.json (with
 * the metrics of a run that ended well), the movie of the frames there are. */
static enum clsph_status finish(struct sim *sim, const struct loop_options *opt,
                                struct case_script *script, struct run_out *o, enum clsph_status st)
{
  if (st == CLSPH_E_BLOWUP && strcmp(sim->status, "ok") == 0) {
    /* the only blow-up the time loop does not word itself: the pressure solver's (psolve.c) */
    snprintf(sim->status, sizeof sim->status,
             "blow-up: the %s solve failed at step %ld, t = %.9g s (scheme options solver_rtol, "
             "solver_max_it, solver_precond)",
             sim->failed_solve != NULL ? sim->failed_solve : "pressure", sim->step + 1, sim->time);
    snprintf(sim->failure, sizeof sim->failure, "solver");
  }
  if (st != CLSPH_OK && strcmp(sim->status, "ok") == 0)
    snprintf(sim->status, sizeof sim->status, "failed: %s", clsph_status_str(st));
  if (st != CLSPH_OK && strcmp(sim->failure, "none") == 0)
    snprintf(sim->failure, sizeof sim->failure, "error");
  if (o->dir != NULL) {
    enum clsph_status ws = summary_write(sim, o, sim->wall, script);
    if (st == CLSPH_OK) st = ws;
    if (st == CLSPH_OK && strcmp(sim->status, "ok") != 0) /* metrics() failed or was stopped */
      st = strcmp(sim->failure, "interrupted") == 0 ? CLSPH_E_INTERRUPTED : CLSPH_E_INPUT;
  }
  if (o->frames != NULL) { /* the movie of what there is, also of a run that stopped */
    enum clsph_status fs = frames_finish(o->frames, opt->quiet);
    if (st == CLSPH_OK) st = fs;
  }
  out_close(sim->scene, o);
  return st;
}

enum clsph_status loop_run(struct sim *sim, const struct loop_options *opt,
                           struct case_script *script)
{
  enum clsph_status st = CLSPH_OK;
  struct run_out o;
  struct progress pr = {.tty = isatty(2), .quiet = opt->quiet};
  memset(&o, 0, sizeof o);
  const double wall0 = progress_now();
  kern_profile_start(sim->dev->profile);

  o.checkpoint_step = -1;
  o.script = script;
  if (interrupt_signal() != 0) CLSPH_TRY(interrupted(sim, &o, interrupt_signal()));
  CLSPH_TRY(start(sim, opt, &o));
  pr.start = progress_now();
  sim->out_wall = pr.start - wall0;
  while (sim->time < sim->scene->t_end && interrupt_signal() == 0) {
    double dt = 0.0, target = 0.0;
    int lands = 0;
    if (!sim->scheme->sorts_first) CLSPH_TRY(sim_sort(sim));
    CLSPH_TRY(step_length(sim, &dt, &target, &lands));
    if (sim->scene->flow.on) CLSPH_TRY(sim_flow_control(sim, dt, o.flow));
    CLSPH_TRY(sim->scheme->step(sim, sim->state, dt));
    advance(sim, dt, target, lands);
    sim->wall = progress_now() - wall0; /* checkpoints record it */
    CLSPH_TRY(check_and_write(sim, &o, dt, lands));
    progress_show(sim, &pr, 0);
  }
  progress_show(sim, &pr, 1);
  if (interrupt_signal() != 0) CLSPH_TRY(interrupted(sim, &o, interrupt_signal()));
done:;
  /* the profiled window ends with its commands run, and leaves out the metrics' kernels */
  const enum clsph_status pst = kern_profile_stop(sim->dev->profile);
  if (st == CLSPH_OK) st = pst;
  sim->wall = progress_now() - wall0;
  return finish(sim, opt, script, &o, st);
}
