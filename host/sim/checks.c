/* checks.c: the blow-up checks of the time loop: the error flags the kernels raise (every step)
 * and the health checks (kinetic energy, particle clustering; every checks.every steps and the
 * last), reduced on the device (kernels/common/health.cl). The thresholds and the runs behind them
 * are in host/scene/scene.c. Every stop message names the run { checks = { ... } } setting that
 * sets its limit, or, for the checks no setting controls (non-finite values, a particle out of the
 * cell grid, neighbour overflow), what to look at. Fluid that leaves the domain is dropped and
 * counted, up to checks.escaped of it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "kern.h"
#include "sim.h"

enum clsph_status sim_fail(struct sim *sim, const char *failure)
{
  snprintf(sim->failure, sizeof sim->failure, "%s", failure);
  log_error("%s", sim->status);
  return CLSPH_E_BLOWUP;
}

/* What to look at after a non-finite value, which no setting controls. */
static const char *const nan_hint =
    "no setting controls this check: look at the progress lines before it (pressure solves that "
    "did not converge) and blowup.h5 (the state that failed); a time step at the scheme's bound "
    "may be too long "
    "for the scene (run { cfl = 0.5 })";

/* Fluid that left the domain at this step (`out` particles, kind CLSPH_KIND_OUT, domain.cl):
 * counted, and dropped (sorted past the others, which then number fewer), or the run stops when
 * more than checks.escaped of the fluid has left. */
static enum clsph_status drop_escaped(struct sim *sim, cl_uint out)
{
  enum clsph_status st = CLSPH_OK;
  const double limit = sim->scene->checks.escaped;
  const double fluid = (double)sim->geom.nfluid;
  if (sim->escaped_first_step < 0) {
    sim->escaped_first_step = sim->step;
    sim->escaped_first_time = sim->time;
  }
  sim->escaped += (long)out;
  const double share = fluid > 0.0 ? (double)sim->escaped / fluid : 1.0;
  if (share > limit) {
    /* half the fluid in one step is no splash: the state exploded (isph-stabilized's n = 80
     * dam break lost 99% at once after a pressure solve ran to its limit) or nothing holds it */
    char burst[192] = "";
    if ((double)out > 0.5 * fluid)
      snprintf(burst, sizeof burst,
               " %u of them in this step: the fluid thrown out at once (a pressure solve that "
               "failed, in the progress lines before it, or no wall where it went);",
               out);
    snprintf(sim->status, sizeof sim->status,
             "blow-up: %ld fluid particle(s), %.3g%% of the fluid, left the domain by step %ld, "
             "t = %.9g s (the first at step %ld), more than run { checks = { escaped = %g } } "
             "lets go;%s look in blowup.h5 (the state that failed: kind 6 marks the particles "
             "leaving at this step) for fluid thrown over a wall or out through a gap (fluid "
             "particles must stay within dr of the domain { } box, but on the side gravity "
             "points away from)",
             sim->escaped, 100.0 * share, sim->step, sim->time, sim->escaped_first_step, limit,
             burst);
    return sim_fail(sim, "escaped");
  }
  if (sim->escaped == (long)out || sim->escaped <= 10)
    log_warn("%u fluid particle(s) left the domain at step %ld, t = %.9g s: dropped from the run "
             "(%ld so far, %.3g%% of the fluid; run { checks = { escaped = %g } } stops the run "
             "beyond that fraction)",
             out, sim->step, sim->time, sim->escaped, 100.0 * share, limit);
  else
    log_debug("%u fluid particle(s) left the domain at step %ld, t = %.9g s: dropped (%ld so far)",
              out, sim->step, sim->time, sim->escaped);
  CLSPH_TRY(sim_sort(sim)); /* grid.cl bins them last */
  CLSPH_ASSERT(sim->ps.n >= out);
  sim->ps.n -= out;
  sim->grid.sorted = sim->ps.n;
done:
  return st;
}

static enum clsph_status health_launch(struct sim *sim, real *part, size_t *groups);
static enum clsph_status health_judge(struct sim *sim, const real *part, size_t groups);

enum clsph_status sim_check_step(struct sim *sim, int health)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint f[4] = {0, 0, 0, 0}; /* flags.h: bits, behind walls, deepest, left the domain */
  float depth = 0.0f;          /* the deepest crossing of the step, m */
  real *part = NULL;           /* the health sums' partials */
  size_t groups = 0;
  /* the domain check, the step-end maxima and the health sums come with the flags: one wait */
  CLSPH_TRY(sim_deferred_enqueue(sim));
  if (health) {
    part = malloc(5 * SIM_REDUCE_MAX_GROUPS * sizeof *part);
    CLSPH_CHECK(part != NULL, CLSPH_E_NOMEM, "out of memory");
    CLSPH_TRY(health_launch(sim, part, &groups));
  }
  CLSPH_TRY(kern_read(sim->dev, sim->d_flags, sizeof f, f));
  sim_deferred_finish(sim);
  cl_uint flags = f[0];
  const cl_uint out = f[3];
  if (flags & 8u) { /* counted; fatal only when deeper than checks.wall_depth dr */
    memcpy(&depth, &f[2], sizeof depth);
    if (sim->wall_steps++ == 0) {
      sim->wall_first_step = sim->step;
      sim->wall_first_time = sim->time;
      log_warn("%u fluid particle(s) behind a wall at step %ld, t = %.9g s (%.3g dr deep)", f[1],
               sim->step, sim->time, (double)depth / sim->scene->dr);
    }
    if ((long)f[1] > sim->wall_most) sim->wall_most = (long)f[1];
    sim->wall_depth_max = fmax(sim->wall_depth_max, (double)depth / sim->scene->dr);
  }
  if ((flags & 8u) || out > 0) {
    const cl_uint zeros[4] = {flags & ~8u, 0, 0, 0};
    CLSPH_TRY(kern_write(sim->dev, sim->d_flags, sizeof zeros, zeros));
    flags &= ~8u;
  }
  if (flags & 1u) {
    snprintf(sim->status, sizeof sim->status,
             "blow-up: a non-finite value (NaN or Inf) at step %ld, t = %.9g s; %s", sim->step,
             sim->time, nan_hint);
    st = sim_fail(sim, "nan");
  } else if (flags & 4u) {
    snprintf(sim->status, sizeof sim->status,
             "blow-up: a particle left the cell grid at step %ld, t = %.9g s; no setting "
             "controls this check: look in blowup.h5 (the state that failed) for a wall "
             "particle moved out of the domain, or fluid thrown out within one step (the grid "
             "reaches several dr beyond the domain { } box, but on the side gravity points "
             "away from)",
             sim->step, sim->time);
    st = sim_fail(sim, "escaped");
  } else if (flags & 2u) {
    snprintf(
        sim->status, sizeof sim->status,
        "blow-up: a particle has more neighbours than its table holds at step %ld, t = %.9g s; "
        "no setting controls this check: particles have piled up; blowup.h5 (the state that "
        "failed) shows "
        "where",
        sim->step, sim->time);
    st = sim_fail(sim, "neighbours");
  } else if (sim->scene->checks.every > 0 &&
             (double)depth > sim->scene->checks.wall_depth * sim->scene->dr) {
    snprintf(sim->status, sizeof sim->status,
             "blow-up: a fluid particle crossed a wall (%.3g dr behind it, %u behind walls) at "
             "step %ld, t = %.9g s (run { checks = { wall_depth = %g } } sets this limit, in dr)",
             (double)depth / sim->scene->dr, f[1], sim->step, sim->time,
             sim->scene->checks.wall_depth);
    st = sim_fail(sim, "wall_crossing");
  } else if (out > 0) {
    st = drop_escaped(sim, out);
  }
  if (st == CLSPH_OK && health) st = health_judge(sim, part, groups);
done:
  free(part);
  return st;
}

/* The health sums (health.cl), their read queued into part (5 SIM_REDUCE_MAX_GROUPS reals) for
 * the flags' blocking read to complete. The kernel skips all but the fluid, so the particles the
 * step-end domain check has just marked as gone (sorted last here) are left out, as they are
 * dropped. */
static enum clsph_status health_launch(struct sim *sim, real *part, size_t *groups)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene_checks *c = &sim->scene->checks;
  *groups = sim_reduce_groups(sim->ps.n);
  /* the spacing needs a current cell table (sorting is idempotent: the next step sees the same) */
  CLSPH_TRY(sim_sort(sim));
  cl_uint n = (cl_uint)sim->ps.n;
  const real close = (real)(c->cluster_h * sim->sm.h); /* the clustering distance, m */
  cl_mem pos = pset_mem(&sim->ps, sim->f_pos), vel = pset_mem(&sim->ps, sim->f_vel);
  cl_mem vol = pset_mem(&sim->ps, sim->f_vol), kind = pset_mem(&sim->ps, sim->f_kind);
  CLSPH_TRY(KERN_SET(sim->k_health, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start),
                     KARG(pos), KARG(vel), KARG(vol), KARG(kind), KARG(close),
                     KARG(sim->d_health)));
  CLSPH_TRY(kern_launch_wg(sim->dev, sim->k_health, *groups * 64, 64, NULL));
  CLSPH_TRY(kern_read_nb(sim->dev, sim->d_health, 0, 5 * *groups * sizeof *part, part));
done:
  return st;
}

/* The health checks on the sums health_launch has read. */
static enum clsph_status health_judge(struct sim *sim, const real *part, size_t groups)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene_checks *c = &sim->scene->checks;
  const double dr = sim->scene->dr;
  const double limit = c->cluster_h * sim->sm.h; /* the clustering distance, m */
  double e = 0.0, v = 0.0, clustered = 0.0, count = 0.0, dmin = HUGE_VAL;
  for (size_t g = 0; g < groups; ++g) {
    e += (double)part[5 * g];
    v += (double)part[5 * g + 1];
    clustered += (double)part[5 * g + 2];
    count += (double)part[5 * g + 3];
    dmin = fmin(dmin, (double)part[5 * g + 4]);
  }
  if (!(count > 0.0)) goto done; /* no fluid */
  ++sim->health_checks;
  const double ratio = sim->u_ref > 0.0 ? e / (v * sim->u_ref * sim->u_ref) : 0.0;
  const double frac = clustered / count;
  sim->energy_ratio_max = fmax(sim->energy_ratio_max, ratio);
  sim->cluster_max = fmax(sim->cluster_max, frac);
  sim->spacing_min = fmin(sim->spacing_min, dmin / dr);
  if (!isfinite(e)) {
    snprintf(sim->status, sizeof sim->status,
             "blow-up: a non-finite velocity at step %ld, t = %.9g s; %s", sim->step, sim->time,
             nan_hint);
    st = sim_fail(sim, "nan");
  } else if (frac > c->cluster_fraction) {
    snprintf(sim->status, sizeof sim->status,
             "blow-up: particles cluster: %.3g%% of the fluid has a fluid neighbour closer than "
             "%g h = %.3g dr (closest %.3g dr) at step %ld, t = %.9g s (run { checks = { "
             "cluster_h = %g, cluster_fraction = %g } } sets these limits)",
             100.0 * frac, c->cluster_h, limit / dr, dmin / dr, sim->step, sim->time, c->cluster_h,
             c->cluster_fraction);
    st = sim_fail(sim, "clustering");
  } else if (c->energy > 0.0 && ratio > c->energy) {
    snprintf(sim->status, sizeof sim->status,
             "blow-up: the kinetic energy grew to %.3g times ½ M U² (U = %.3g m/s, the scene's "
             "velocity scale) at step %ld, t = %.9g s (run { checks = { energy = %g } } sets this "
             "limit)",
             ratio, sim->u_ref, sim->step, sim->time, c->energy);
    st = sim_fail(sim, "energy");
  }
done:
  return st;
}
