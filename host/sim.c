/* sim.c: set-up of a simulation from a scene, and the time loop with its outputs.
 *
 * Each step: sort the particles by cell (every field reordered), ask the scheme for its largest
 * stable step, shorten it so that equal steps land exactly on the next output or checkpoint time
 * (k = ⌈remaining/bound⌉ steps of remaining/k: no short step before each output, which would
 * upset the flow-rate control), update the flow-rate control, step, and read the error flags.
 * Outputs in the output folder:
 *   snap_NNNNNN.h5 + snapshots.xdmf    particle fields at the output cadence (ParaView)
 *   checkpoint_NNNNNN.h5               at the checkpoint cadence and at the end (--restart)
 *   probes.csv, profile_<name>.csv     interpolated fields at the output cadence
 *   forces.csv                         wall-group forces at the output cadence
 *   frames/FIELD_NNNNNN.png, FIELD.mp4 with --frames: a frame with each snapshot, drawn from a
 *                                      host copy of the device state, and the movie at the end
 *   summary.json                       what ran, its cost (with --profile, the device time per
 *                                      kernel), its status and the case's metrics */
#include "sim.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "../solvers/scheme.h"
#include "case.h"
#include "clsph_config.h"
#include "frames.h"
#include "kern.h"
#include "psolve.h"

static const char *const common_sources[] = {OPS_SOURCES, "common/reduce.cl", "common/probe.cl",
                                             "common/health.cl"};

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Work-groups of 64 of a reduction over n particles: at most 64, so a few dozen partial results
 * come back to the host per reduction (reduce.cl). */
static size_t reduce_groups(size_t n)
{
  size_t g = (n + 63) / 64;
  return g < 1 ? 1 : (g > 64 ? 64 : g);
}

/* ---- set-up ---- */

static enum clsph_status check_options(const struct scene *s, const struct scheme_ops *sc)
{
  enum clsph_status st = CLSPH_OK;
  for (int i = 0; i < s->noptions; ++i) {
    int known = 0;
    for (int k = 0; sc->options[k] != NULL; ++k)
      known |= !strcmp(sc->options[k], s->options[i].key);
    if (known) continue;
    char list[512];
    size_t used = 0;
    list[0] = '\0';
    for (int k = 0; sc->options[k] != NULL && used < sizeof list; ++k)
      used +=
          (size_t)snprintf(list + used, sizeof list - used, "%s%s", k ? ", " : "", sc->options[k]);
    CLSPH_CHECK(0, CLSPH_E_INPUT, "%s: scheme '%s' has no option '%s' (options: %s)", s->case_path,
                sc->name, s->options[i].key, used ? list : "none");
  }
done:
  return st;
}

static const struct scene_option *find_option(const struct scene *s, const char *key)
{
  for (int i = 0; i < s->noptions; ++i)
    if (strcmp(s->options[i].key, key) == 0) return &s->options[i];
  return NULL;
}

static enum clsph_status build_program(struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  struct prog_opts o = {0};
  const char **sources = NULL;
  size_t nc = sizeof common_sources / sizeof *common_sources, ns = 0;
  while (sim->scheme->sources[ns] != NULL) ++ns;
  sources = calloc(nc + ns + 1, sizeof *sources);
  CLSPH_CHECK(sources != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t i = 0; i < nc; ++i) sources[i] = common_sources[i];
  for (size_t i = 0; i < ns; ++i) sources[nc + i] = sim->scheme->sources[i];
  CLSPH_TRY(grid_define(&sim->gspec, &o));
  CLSPH_TRY(smoothing_define(&sim->sm, &o));
  if (sim->scheme->define != NULL) CLSPH_TRY(sim->scheme->define(sim, &o));
  CLSPH_TRY(prog_build(sim->dev, sources, &o, &sim->prog));
done:
  free(sources);
  prog_opts_free(&o);
  return st;
}

/* The common fields: position, velocity, kind, id, volume. */
static enum clsph_status add_fields(struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  const struct geom *g = &sim->geom;
  const size_t n = g->n, stride = 2;
  real *xv = calloc(2 * stride * n + n, sizeof *xv);
  cl_uint *u = calloc(2 * n, sizeof *u);
  CLSPH_CHECK(xv != NULL && u != NULL, CLSPH_E_NOMEM, "out of memory for %zu particles", n);
  real *v = xv + stride * n, *vol = xv + 2 * stride * n;
  for (size_t i = 0; i < n; ++i) {
    for (size_t a = 0; a < 2; ++a) {
      xv[stride * i + a] = (real)g->x[2 * i + a];
      v[stride * i + a] = (real)g->v[2 * i + a];
    }
    vol[i] = (real)(sim->scene->dr * sim->scene->dr);
    u[i] = (cl_uint)g->kind[i];
    u[n + i] = (cl_uint)i;
  }
  pset_init(&sim->ps, n, n);
  CLSPH_TRY(pset_add(&sim->ps, sim->dev, "pos", stride * sizeof(real), xv, &sim->f_pos));
  CLSPH_TRY(pset_add(&sim->ps, sim->dev, "vel", stride * sizeof(real), v, &sim->f_vel));
  CLSPH_TRY(pset_add(&sim->ps, sim->dev, "kind", sizeof(cl_uint), u, &sim->f_kind));
  CLSPH_TRY(pset_add(&sim->ps, sim->dev, "id", sizeof(cl_uint), u + n, &sim->f_id));
  CLSPH_TRY(pset_add(&sim->ps, sim->dev, "vol", sizeof(real), vol, &sim->f_vol));
  pset_describe(&sim->ps, sim->f_kind, PF_UINT, 1, 1);
  pset_describe(&sim->ps, sim->f_id, PF_UINT, 1, 1);
done:
  free(u);
  free(xv);
  return st;
}

/* The scene's velocity scale U of the energy check (m/s): the largest speed its drives give the
 * fluid. The largest of: the walls' speeds (sliding, or |ω| times the farthest vertex from the
 * centre), the inflow speeds, the flow-rate control's target, the initial fluid speeds, the speed
 * √(2 |g + f| L) of a free fall over the domain's diagonal L, and for a constant body force f
 * held by viscosity its viscous speed |f| L²/ν (a plane Poiseuille peak is |f| H²/(8ν), H <= L).
 * 0 when nothing drives the flow: then the energy check is off. */
static double velocity_scale(const struct scene *s, const struct geom *g)
{
  double u2 = 0.0;
  for (int w = 0; w < s->nwalls; ++w) {
    const struct scene_wall *wl = &s->walls[w];
    u2 = fmax(u2, wl->velocity[0] * wl->velocity[0] + wl->velocity[1] * wl->velocity[1]);
    for (int k = 0; k < wl->npts && wl->omega != 0.0; ++k) {
      double r = hypot(wl->pts[2 * k] - wl->centre[0], wl->pts[2 * k + 1] - wl->centre[1]);
      u2 = fmax(u2, wl->omega * wl->omega * r * r);
    }
  }
  for (int k = 0; k < s->nsections; ++k)
    u2 = fmax(u2, s->sections[k].velocity * s->sections[k].velocity);
  if (s->flow.on) u2 = fmax(u2, s->flow.velocity * s->flow.velocity);
  for (size_t i = 0; i < g->nfluid; ++i)
    u2 = fmax(u2, g->v[2 * i] * g->v[2 * i] + g->v[2 * i + 1] * g->v[2 * i + 1]);
  const double L = hypot(s->hi[0] - s->lo[0], s->hi[1] - s->lo[1]);
  const double f = hypot(s->body_force[0], s->body_force[1]);
  u2 =
      fmax(u2, 2.0 * hypot(s->gravity[0] + s->body_force[0], s->gravity[1] + s->body_force[1]) * L);
  if (s->nu > 0.0) u2 = fmax(u2, (f * L * L / s->nu) * (f * L * L / s->nu));
  return sqrt(u2);
}

enum clsph_status sim_create(const struct dev *dev, const struct scene *scene, struct sim *out)
{
  enum clsph_status st = CLSPH_OK;
  struct sim sim;
  memset(&sim, 0, sizeof sim);
  sim.dev = dev;
  sim.scene = scene;
  snprintf(sim.status, sizeof sim.status, "ok");
  snprintf(sim.failure, sizeof sim.failure, "none");
  sim.spacing_min = HUGE_VAL;

  CLSPH_TRY(scheme_find(scene->scheme, &sim.scheme));
  CLSPH_TRY(check_options(scene, sim.scheme));
  /* smoothing function and length */
  enum smoothing_kind kind;
  CLSPH_TRY(smoothing_kind_from_name(scene->smoothing[0] ? scene->smoothing : sim.scheme->smoothing,
                                     &kind));
  double hr = scene->h_over_dr > 0.0 ? scene->h_over_dr : sim.scheme->h_over_dr;
  CLSPH_TRY(smoothing_make(kind, 2, hr * scene->dr, &sim.sm));
  /* particles */
  const char *model = sim.scheme->wall_model;
  const struct scene_option *wo = find_option(scene, "walls");
  if (wo != NULL) {
    CLSPH_CHECK(!wo->is_number && (!strcmp(wo->text, "usaw") || !strcmp(wo->text, "dummy") ||
                                   !strcmp(wo->text, "none")),
                CLSPH_E_INPUT, "%s: scheme option walls must be \"usaw\", \"dummy\" or \"none\"",
                scene->case_path);
    model = wo->text;
  }
  const struct scene_option *lo = find_option(scene, "wall_layers");
  int layers = lo != NULL && lo->is_number ? (int)lo->number : 3;
  CLSPH_TRY(geometry_build(scene, model, layers, &sim.geom));
  /* the cell grid: the domain, with room for wall and section layers on non-periodic axes */
  sim.gspec.dim = 2;
  sim.gspec.support = sim.sm.support;
  double margin = (layers + 4) * scene->dr + sim.sm.support;
  for (int a = 0; a < 2; ++a) {
    sim.gspec.periodic[a] = scene->periodic[a];
    sim.gspec.lo[a] = scene->lo[a] - (scene->periodic[a] ? 0.0 : margin);
    sim.gspec.hi[a] = scene->hi[a] + (scene->periodic[a] ? 0.0 : margin);
  }
  for (size_t i = 0; i < sim.geom.n; ++i)
    for (int a = 0; a < 2; ++a)
      CLSPH_CHECK(scene->periodic[a] || (sim.geom.x[2 * i + a] >= sim.gspec.lo[a] &&
                                         sim.geom.x[2 * i + a] < sim.gspec.hi[a]),
                  CLSPH_E_INPUT, "%s: a particle at (%g, %g) lies outside the domain",
                  scene->case_path, sim.geom.x[2 * i], sim.geom.x[2 * i + 1]);
  /* device state */
  CLSPH_TRY(build_program(&sim));
  CLSPH_TRY(add_fields(&sim));
  CLSPH_TRY(grid_create(dev, sim.prog, &sim.gspec, sim.ps.cap, &sim.grid));
  /* the bits, the count of particles behind a wall and the deepest (flags.h) */
  const cl_uint zeros[3] = {0, 0, 0};
  CLSPH_TRY(kern_buffer(dev, sizeof zeros, zeros, &sim.d_flags, "flags"));
  sim.wall_first_step = -1;
  sim.open_waiting = sim.open_waiting_max = -1;
  CLSPH_TRY(prog_kernel(sim.prog, "probe_sample", &sim.k_probe));
  CLSPH_TRY(prog_kernel(sim.prog, "reduce_max_speed", &sim.k_max_speed));
  CLSPH_TRY(prog_kernel(sim.prog, "reduce_count", &sim.k_count));
  CLSPH_TRY(prog_kernel(sim.prog, "grid_invert", &sim.k_invert));
  CLSPH_TRY(prog_kernel(sim.prog, "reduce_slice_velocity", &sim.k_slice));
  CLSPH_TRY(prog_kernel(sim.prog, "health_sums", &sim.k_health));
  CLSPH_TRY(kern_buffer(dev, 5 * reduce_groups(sim.ps.cap) * sizeof(real), NULL, &sim.d_health,
                        "health partials"));
  sim.u_ref = velocity_scale(scene, &sim.geom);
  CLSPH_TRY(kern_buffer(dev, sim.ps.cap * sizeof(cl_uint), NULL, &sim.d_inv, "inverse index"));
  CLSPH_TRY(kern_buffer(dev, 2 * (reduce_groups(sim.ps.cap) + 1) * sizeof(real), NULL,
                        &sim.d_partial, "reduction partials"));
  sim.body_force[0] = scene->body_force[0];
  sim.body_force[1] = scene->body_force[1];
  sim.flow.force = scene->body_force[0];
  if (sim.scheme->create != NULL) CLSPH_TRY(sim.scheme->create(&sim, &sim.state));
  CLSPH_TRY(sim_sort(&sim));
  *out = sim;
  memset(&sim, 0, sizeof sim);
done:
  sim_destroy(&sim);
  return st;
}

enum clsph_status sim_sort(struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(
      grid_sort(&sim->grid, sim->dev, sim->ps.n, pset_mem(&sim->ps, sim->f_pos), sim->d_flags));
  CLSPH_TRY(pset_reorder(&sim->ps, &sim->grid, sim->dev));
  cl_uint n = (cl_uint)sim->ps.n;
  cl_mem id = pset_mem(&sim->ps, sim->f_id);
  CLSPH_TRY(KERN_SET(sim->k_invert, KARG(n), KARG(id), KARG(sim->d_inv)));
  CLSPH_TRY(kern_launch(sim->dev, sim->k_invert, sim->ps.n, NULL));
done:
  return st;
}

enum clsph_status sim_count(struct sim *sim, cl_mem d_field, double *count)
{
  enum clsph_status st = CLSPH_OK;
  real *part = NULL;
  cl_uint n = (cl_uint)sim->ps.n;
  size_t groups = reduce_groups(sim->ps.n);
  part = malloc(groups * sizeof *part);
  CLSPH_CHECK(part != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(KERN_SET(sim->k_count, KARG(n), KARG(d_field), KARG(sim->d_partial)));
  CLSPH_TRY(kern_launch_wg(sim->dev, sim->k_count, groups * 64, 64, NULL));
  CLSPH_TRY(kern_read(sim->dev, sim->d_partial, groups * sizeof *part, part));
  double c = 0.0;
  for (size_t g = 0; g < groups; ++g) c += (double)part[g];
  *count = c;
done:
  free(part);
  return st;
}

enum clsph_status sim_slice_velocity(struct sim *sim, double x0, double x1, double *mean,
                                     double *count)
{
  enum clsph_status st = CLSPH_OK;
  real *part = NULL;
  const struct scene *s = sim->scene;
  cl_uint n = (cl_uint)sim->ps.n;
  size_t groups = reduce_groups(sim->ps.n);
  const real rx0 = (real)x0, width = (real)(x1 - x0);
  const real period = (real)(s->periodic[0] ? s->hi[0] - s->lo[0] : 0.0);
  cl_mem pos = pset_mem(&sim->ps, sim->f_pos), vel = pset_mem(&sim->ps, sim->f_vel);
  cl_mem kind = pset_mem(&sim->ps, sim->f_kind);
  part = malloc(2 * groups * sizeof *part);
  CLSPH_CHECK(part != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(KERN_SET(sim->k_slice, KARG(n), KARG(pos), KARG(vel), KARG(kind), KARG(rx0),
                     KARG(width), KARG(period), KARG(sim->d_partial)));
  CLSPH_TRY(kern_launch_wg(sim->dev, sim->k_slice, groups * 64, 64, NULL));
  CLSPH_TRY(kern_read(sim->dev, sim->d_partial, 2 * groups * sizeof *part, part));
  double u = 0.0, c = 0.0;
  for (size_t g = 0; g < groups; ++g) {
    u += (double)part[g];
    c += (double)part[groups + g];
  }
  *mean = c > 0.0 ? u / c : 0.0;
  *count = c;
done:
  free(part);
  return st;
}

/* A failed check: the reason (already in sim->status) and its class, logged once. */
static enum clsph_status fail(struct sim *sim, const char *failure)
{
  snprintf(sim->failure, sizeof sim->failure, "%s", failure);
  log_error("%s", sim->status);
  return CLSPH_E_BLOWUP;
}

enum clsph_status sim_check_flags(struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint f[3] = {0, 0, 0};
  float depth = 0.0f; /* the deepest crossing of the step, m */
  CLSPH_TRY(kern_read(sim->dev, sim->d_flags, sizeof f, f));
  cl_uint flags = f[0];
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
    const cl_uint zeros[3] = {flags & ~8u, 0, 0};
    CLSPH_TRY(kern_write(sim->dev, sim->d_flags, sizeof zeros, zeros));
    flags &= ~8u;
  }
  if (flags & 1u) {
    snprintf(sim->status, sizeof sim->status,
             "blow-up: a non-finite value (NaN or Inf) at step %ld, t = %.9g s", sim->step,
             sim->time);
    st = fail(sim, "nan");
  } else if (flags & 4u) {
    snprintf(sim->status, sizeof sim->status,
             "blow-up: a particle left the domain at step %ld, t = %.9g s", sim->step, sim->time);
    st = fail(sim, "escaped");
  } else if (flags & 2u) {
    snprintf(sim->status, sizeof sim->status,
             "blow-up: a particle has more neighbours than its table holds at step %ld", sim->step);
    st = fail(sim, "neighbours");
  } else if (sim->scene->checks.every > 0 &&
             (double)depth > sim->scene->checks.wall_depth * sim->scene->dr) {
    snprintf(sim->status, sizeof sim->status,
             "blow-up: a fluid particle crossed a wall (%.3g dr behind it, %u behind walls) at "
             "step %ld, t = %.9g s",
             (double)depth / sim->scene->dr, f[1], sim->step, sim->time);
    st = fail(sim, "wall_crossing");
  }
done:
  return st;
}

enum clsph_status sim_check_health(struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene_checks *c = &sim->scene->checks;
  const double dr = sim->scene->dr;
  real *part = NULL;
  const size_t groups = reduce_groups(sim->ps.n);
  part = malloc(5 * groups * sizeof *part);
  CLSPH_CHECK(part != NULL, CLSPH_E_NOMEM, "out of memory");
  /* the spacing needs a current cell table (sorting is idempotent: the next step sees the same) */
  CLSPH_TRY(sim_sort(sim));
  cl_uint n = (cl_uint)sim->ps.n;
  const real close = (real)(c->cluster_spacing * dr);
  cl_mem pos = pset_mem(&sim->ps, sim->f_pos), vel = pset_mem(&sim->ps, sim->f_vel);
  cl_mem vol = pset_mem(&sim->ps, sim->f_vol), kind = pset_mem(&sim->ps, sim->f_kind);
  CLSPH_TRY(KERN_SET(sim->k_health, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start),
                     KARG(pos), KARG(vel), KARG(vol), KARG(kind), KARG(close),
                     KARG(sim->d_health)));
  CLSPH_TRY(kern_launch_wg(sim->dev, sim->k_health, groups * 64, 64, NULL));
  CLSPH_TRY(kern_read(sim->dev, sim->d_health, 5 * groups * sizeof *part, part));
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
             "blow-up: a non-finite velocity at step %ld, t = %.9g s", sim->step, sim->time);
    st = fail(sim, "nan");
  } else if (frac > c->cluster_fraction) {
    snprintf(sim->status, sizeof sim->status,
             "blow-up: particles cluster: %.3g%% of the fluid has a neighbour closer than %g dr "
             "(closest %.3g dr) at step %ld, t = %.9g s",
             100.0 * frac, c->cluster_spacing, dmin / dr, sim->step, sim->time);
    st = fail(sim, "clustering");
  } else if (c->energy > 0.0 && ratio > c->energy) {
    snprintf(sim->status, sizeof sim->status,
             "blow-up: the kinetic energy grew to %.3g times ½ M U² (U = %.3g m/s, the scene's "
             "velocity scale) at step %ld, t = %.9g s",
             ratio, sim->u_ref, sim->step, sim->time);
    st = fail(sim, "energy");
  }
done:
  free(part);
  return st;
}

enum clsph_status sim_max_speed(struct sim *sim, int kind, double *vmax)
{
  return sim_max_norm(sim, pset_mem(&sim->ps, sim->f_vel), kind, vmax);
}

enum clsph_status sim_max_norm(struct sim *sim, cl_mem d_vec, int kind, double *vmax)
{
  enum clsph_status st = CLSPH_OK;
  real *part = NULL;
  cl_uint n = (cl_uint)sim->ps.n;
  cl_int only = kind;
  size_t groups = reduce_groups(sim->ps.n);
  cl_mem vel = d_vec, kd = pset_mem(&sim->ps, sim->f_kind);
  part = malloc(groups * sizeof *part);
  CLSPH_CHECK(part != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(KERN_SET(sim->k_max_speed, KARG(n), KARG(vel), KARG(kd), KARG(only),
                     KARG(sim->d_partial), KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch_wg(sim->dev, sim->k_max_speed, groups * 64, 64, NULL));
  CLSPH_TRY(kern_read(sim->dev, sim->d_partial, groups * sizeof *part, part));
  double m = 0.0;
  for (size_t g = 0; g < groups; ++g) m = fmax(m, (double)part[g]);
  *vmax = m;
done:
  free(part);
  return st;
}

enum clsph_status sim_sample(struct sim *sim, int field, size_t np, const double *at, double *out)
{
  enum clsph_status st = CLSPH_OK;
  const struct pfield *f = &sim->ps.f[field];
  real *buf = NULL;
  cl_mem d_at = NULL, d_out = NULL;
  cl_uint ncomp = (cl_uint)f->ncomp, npts = (cl_uint)np;
  CLSPH_CHECK(f->type == PF_REAL && f->ncomp <= 4, CLSPH_E_INPUT,
              "field '%s' cannot be interpolated", f->name);
  buf = calloc(np * (2 + ncomp), sizeof *buf);
  CLSPH_CHECK(buf != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t p = 0; p < 2 * np; ++p) buf[p] = (real)at[p];
  CLSPH_TRY(kern_buffer(sim->dev, 2 * np * sizeof(real), buf, &d_at, "sample points"));
  CLSPH_TRY(kern_buffer(sim->dev, ncomp * np * sizeof(real), NULL, &d_out, "samples"));
  cl_mem pos = pset_mem(&sim->ps, sim->f_pos), vol = pset_mem(&sim->ps, sim->f_vol);
  cl_mem kind = pset_mem(&sim->ps, sim->f_kind);
  CLSPH_TRY(KERN_SET(sim->k_probe, KARG(npts), KARG(d_at), KARG(sim->grid.geom),
                     KARG(sim->grid.d_start), KARG(pos), KARG(vol), KARG(kind), KARG(f->d),
                     KARG(ncomp), KARG(d_out)));
  CLSPH_TRY(kern_launch(sim->dev, sim->k_probe, np, NULL));
  CLSPH_TRY(kern_read(sim->dev, d_out, ncomp * np * sizeof(real), buf + 2 * np));
  for (size_t k = 0; k < ncomp * np; ++k) out[k] = (double)buf[2 * np + k];
done:
  kern_release(&d_out);
  kern_release(&d_at);
  free(buf);
  return st;
}

/* ---- info ---- */

enum clsph_status sim_info(struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  size_t count[5] = {0, 0, 0, 0, 0};
  for (size_t i = 0; i < sim->geom.n; ++i)
    if (sim->geom.kind[i] >= 0 && sim->geom.kind[i] < 5) ++count[sim->geom.kind[i]];
  size_t per = 0;
  for (int k = 0; k < sim->ps.nfields; ++k) per += sim->ps.f[k].elem;
  size_t spare = 0;
  for (int k = 0; k < sim->ps.nscratch; ++k) spare += sim->ps.scratch_elem[k];
  size_t grid_bytes = 2 * (sim->grid.ncells + 1) * sizeof(cl_uint) + 3 * sim->ps.cap * 4;
  double dt = HUGE_VAL;
  if (sim->scheme->max_dt != NULL) CLSPH_TRY(sim->scheme->max_dt(sim, sim->state, &dt));
  dt *= s->cfl;
  printf("case %s (%s)\n", s->name, s->case_path);
  printf("scheme %s: %s\n", sim->scheme->name, sim->scheme->summary);
  printf("particles: %zu (fluid %zu, wall vertices %zu, dummy %zu, inflow %zu, outflow %zu), "
         "%zu wall segments\n",
         sim->geom.n, count[0], count[1], count[2], count[3], count[4], sim->geom.nseg);
  printf("spacing dr = %g m, smoothing %s, h = %g m (%g dr), support %g m\n", s->dr,
         smoothing_name(sim->sm.kind), sim->sm.h, sim->sm.h / s->dr, sim->sm.support);
  printf("active: walls %s, periodic %s%s%s, gravity %s, body force %s, probes %d, profiles %d, "
         "forces %d\n",
         sim->geom.nseg ? "usaw"
         : count[2]     ? "dummy"
                        : "none",
         s->periodic[0] || s->periodic[1] ? "" : "none", s->periodic[0] ? "x" : "",
         s->periodic[1] ? "y" : "", s->gravity[0] || s->gravity[1] ? "on" : "off",
         s->flow.on                             ? "flow-rate control"
         : s->body_force[0] || s->body_force[1] ? "on"
                                                : "off",
         s->nprobes, s->nprofiles, s->nforces);
  for (int i = 0; i < s->noptions; ++i) {
    if (s->options[i].is_number)
      printf("option %s = %g\n", s->options[i].key, s->options[i].number);
    else
      printf("option %s = %s\n", s->options[i].key, s->options[i].text);
  }
  printf("fields:");
  for (int k = 0; k < sim->ps.nfields; ++k)
    printf(" %s (%zu B)", sim->ps.f[k].name, sim->ps.f[k].elem);
  printf("\nmemory: %zu B per particle (+ %zu B reorder spare), %.1f MiB in all with the grid of "
         "%zu cells\n",
         per, spare, (double)((per + spare) * sim->ps.cap + grid_bytes) / (1024.0 * 1024.0),
         sim->grid.ncells);
  if (isfinite(dt))
    printf("time step %.6g s (cfl %g): about %.0f steps to t_end = %g s\n", dt, s->cfl,
           ceil(s->t_end / dt), s->t_end);
  else
    printf("time step: set by the outputs (the scheme has no stability bound); t_end = %g s\n",
           s->t_end);
done:
  return st;
}

/* ---- outputs ---- */

struct run_out {
  char dir[1024];
  struct io_series series;
  FILE *probes, *forces, *flow;
  FILE **profiles;
  int nsnap;
  /* per force group, over the samples written: the largest |F| (time, fx, fy) and the last F */
  struct force_stat {
    double peak, peak_time, peak_f[2], last[2];
  } * force_stats;
  double *force_scratch; /* one row of the force history */
  /* frames (--frames): the renderer, the walls as it reads them, the region shown, and a host
   * copy of the arrays a frame reads (pos, vol, kind and the field's) */
  struct frames *frames;
  struct render_wall *walls;
  double view[4];
  double *frame_arrays[4];
  struct render_array frame_in[4];
  int nframe_arrays;
};

static enum clsph_status path_in(const struct run_out *o, const char *name, char *buf, size_t size)
{
  enum clsph_status st = CLSPH_OK;
  int w = snprintf(buf, size, "%s/%s", o->dir, name);
  CLSPH_CHECK(w > 0 && (size_t)w < size, CLSPH_E_INPUT, "output path too long: %s/%s", o->dir,
              name);
done:
  return st;
}

/* Create the folder (and its parents) and prove it can be written, before anything runs. */
static enum clsph_status prepare_dir(const char *dir)
{
  enum clsph_status st = CLSPH_OK;
  char path[1100];
  CLSPH_CHECK(strlen(dir) > 0 && strlen(dir) < 1024, CLSPH_E_INPUT, "--out: bad folder name");
  snprintf(path, sizeof path, "%s", dir);
  for (char *p = path + 1; *p != '\0'; ++p) {
    if (*p != '/') continue;
    *p = '\0';
    mkdir(path, 0755);
    *p = '/';
  }
  if (mkdir(path, 0755) != 0 && errno != EEXIST) {
    log_error("output folder %s cannot be created: %s", dir, strerror(errno));
    st = CLSPH_E_IO;
    goto done;
  }
  snprintf(path, sizeof path, "%s/.clsph-write-test", dir);
  FILE *f = fopen(path, "w");
  if (f == NULL) {
    log_error("output folder %s cannot be written: %s", dir, strerror(errno));
    st = CLSPH_E_IO;
    goto done;
  }
  fclose(f);
  remove(path);
done:
  return st;
}

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
  char path[1200];
  const char *slash = strrchr(restart, '/');
  const int dir = slash == NULL ? 0 : (int)(slash - restart);
  int w = slash == NULL ? snprintf(path, sizeof path, "%s", name)
                        : snprintf(path, sizeof path, "%.*s/%s", dir, restart, name);
  char *line = NULL;
  size_t cap = 0, room = 0;
  FILE *f = NULL;
  memset(k, 0, sizeof *k);
  CLSPH_CHECK(w > 0 && (size_t)w < sizeof path, CLSPH_E_INPUT, "path too long: %s", restart);
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
  const size_t cols = 1 + 4 * (size_t)ng;
  double *row = malloc(cols * sizeof *row);
  CLSPH_CHECK(row != NULL, CLSPH_E_NOMEM, "out of memory");
  for (const char *c = k->rows; c != NULL && c < k->rows + k->bytes;) {
    char *end = NULL;
    row[0] = strtod(c, &end);
    for (int g = 0; g < ng; ++g) {
      double v[6];
      for (int j = 0; j < 6; ++j) v[j] = strtod(end + 1, &end);
      memcpy(row + 1 + 4 * g, v + 2, 4 * sizeof *v); /* pressure x, y, viscous x, y */
    }
    CLSPH_TRY(force_row(sim, o, row));
    c = strchr(end, '\n');
    if (c != NULL) ++c;
  }
done:
  free(row);
  return st;
}

/* Open the CSV series of the run. On a restart (restart: the checkpoint's path), each goes on
 * from the rows the restarted run wrote up to the checkpoint's time, so that it reads as one
 * run. */
static enum clsph_status open_series(struct sim *sim, struct run_out *o, const char *restart)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  char path[1200], name[SCENE_NAME + 32], prefix[SCENE_NAME + 2];
  const int np = s->nprofiles;
  /* the kept rows of the profiles, then of the probes, the flow control and the forces */
  struct kept_series *kept = calloc((size_t)np + 3, sizeof *kept);
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
  }
  if (s->nprobes > 0) {
    CLSPH_TRY(path_in(o, "probes.csv", path, sizeof path));
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
    CLSPH_TRY(path_in(o, name, path, sizeof path));
    o->profiles[p] = fopen(path, "w");
    CLSPH_CHECK(o->profiles[p] != NULL, CLSPH_E_IO, "cannot write %s: %s", path, strerror(errno));
    fprintf(o->profiles[p], "time,s,x,y");
    csv_field_header(o->profiles[p], &sim->ps, "");
    fprintf(o->profiles[p], "\n");
    CLSPH_TRY(series_resume(o->profiles[p], path, &kept[p]));
  }
  if (s->flow.on) {
    CLSPH_TRY(path_in(o, "flow_control.csv", path, sizeof path));
    o->flow = fopen(path, "w");
    CLSPH_CHECK(o->flow != NULL, CLSPH_E_IO, "cannot write %s: %s", path, strerror(errno));
    fprintf(o->flow, "time,dt,body_force_x,slice_velocity,slice_particles\n");
    CLSPH_TRY(series_resume(o->flow, path, &kept[np + 1]));
  }
  if (s->nforces > 0) {
    CLSPH_TRY(path_in(o, "forces.csv", path, sizeof path));
    o->force_stats = calloc((size_t)s->nforces, sizeof *o->force_stats);
    o->force_scratch = malloc((1 + 4 * (size_t)s->nforces) * sizeof *o->force_scratch);
    CLSPH_CHECK(o->force_stats != NULL && o->force_scratch != NULL, CLSPH_E_NOMEM, "out of memory");
    o->forces = fopen(path, "w");
    CLSPH_CHECK(o->forces != NULL, CLSPH_E_IO, "cannot write %s: %s", path, strerror(errno));
    fprintf(o->forces, "time");
    for (int g = 0; g < s->nforces; ++g) {
      const char *n = s->forces[g];
      fprintf(o->forces, ",%s:fx,%s:fy,%s:fx_pressure,%s:fy_pressure,%s:fx_viscous,%s:fy_viscous",
              n, n, n, n, n, n);
    }
    fprintf(o->forces, "\n");
    CLSPH_TRY(series_resume(o->forces, path, &kept[np + 2]));
    CLSPH_TRY(forces_reload(sim, o, &kept[np + 2]));
  }
done:
  for (int k = 0; kept != NULL && k < np + 3; ++k) kept_free(&kept[k]);
  free(kept);
  return st;
}

/* Append one row (time, then pressure x, y and viscous x, y of each group) to the force history
 * and update each group's peak and last force. */
static enum clsph_status force_row(struct sim *sim, struct run_out *o, const double *row)
{
  enum clsph_status st = CLSPH_OK;
  const int ng = sim->scene->nforces;
  const size_t cols = 1 + 4 * (size_t)ng;
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
    const double *q = row + 1 + 4 * g, ft[2] = {q[0] + q[2], q[1] + q[3]};
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

/* Sample every recorded field at np points; one row of values per point into rows. */
static enum clsph_status sample_all(struct sim *sim, size_t np, const double *at, double *rows,
                                    int ncols)
{
  enum clsph_status st = CLSPH_OK;
  double *tmp = malloc(4 * np * sizeof *tmp);
  int col = 0;
  CLSPH_CHECK(tmp != NULL, CLSPH_E_NOMEM, "out of memory");
  for (int k = 0; k < sim->ps.nfields; ++k) {
    const struct pfield *p = &sim->ps.f[k];
    if (!sampled(p)) continue;
    CLSPH_TRY(sim_sample(sim, k, np, at, tmp));
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

/* What write_series writes: the time series (probes.csv, forces.csv), the profiles, or both. */
enum { SERIES_TIME = 1, SERIES_PROFILES = 2 };

static enum clsph_status write_series(struct sim *sim, struct run_out *o, int what)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  const int nc = sampled_columns(&sim->ps);
  double *at = NULL, *rows = NULL;
  if (s->nprobes > 0 && (what & SERIES_TIME)) {
    at = malloc(2 * (size_t)s->nprobes * sizeof *at);
    rows = malloc((size_t)s->nprobes * (size_t)(nc + 1) * sizeof *rows);
    CLSPH_CHECK(at != NULL && rows != NULL, CLSPH_E_NOMEM, "out of memory");
    for (int p = 0; p < s->nprobes; ++p) {
      at[2 * p] = s->probes[p].x[0];
      at[2 * p + 1] = s->probes[p].x[1];
    }
    CLSPH_TRY(sample_all(sim, (size_t)s->nprobes, at, rows, nc));
    fprintf(o->probes, "%.17g", sim->time);
    for (int i = 0; i < s->nprobes * nc; ++i) fprintf(o->probes, ",%.9g", rows[i]);
    fprintf(o->probes, "\n");
    fflush(o->probes);
    free(at);
    free(rows);
    at = rows = NULL;
  }
  for (int p = 0; p < s->nprofiles && (what & SERIES_PROFILES); ++p) {
    const struct scene_profile_line *pl = &s->profiles[p];
    size_t np = (size_t)pl->npts;
    at = malloc(2 * np * sizeof *at);
    rows = malloc(np * (size_t)(nc + 1) * sizeof *rows);
    CLSPH_CHECK(at != NULL && rows != NULL, CLSPH_E_NOMEM, "out of memory");
    for (size_t i = 0; i < np; ++i) {
      double t = (double)i / (double)(np - 1);
      at[2 * i] = pl->a[0] + t * (pl->b[0] - pl->a[0]);
      at[2 * i + 1] = pl->a[1] + t * (pl->b[1] - pl->a[1]);
    }
    CLSPH_TRY(sample_all(sim, np, at, rows, nc));
    double len = hypot(pl->b[0] - pl->a[0], pl->b[1] - pl->a[1]);
    for (size_t i = 0; i < np; ++i) {
      fprintf(o->profiles[p], "%.17g,%.9g,%.9g,%.9g", sim->time, len * (double)i / (double)(np - 1),
              at[2 * i], at[2 * i + 1]);
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
    /* the velocity gradient at the walls sums over neighbours: the cell table must be current
     * (sorting is idempotent, so the next step's sort and a restart see the same order) */
    CLSPH_TRY(sim_sort(sim));
    double *row = o->force_scratch;
    row[0] = sim->time;
    fprintf(o->forces, "%.17g", sim->time);
    for (int g = 0; g < s->nforces; ++g) {
      struct wall_force f;
      CLSPH_TRY(sim->scheme->wall_force(sim, sim->state, s->forces[g], &f));
      double *q = row + 1 + 4 * g;
      q[0] = recorded(f.pressure[0]);
      q[1] = recorded(f.pressure[1]);
      q[2] = recorded(f.viscous[0]);
      q[3] = recorded(f.viscous[1]);
      fprintf(o->forces, ",%.9g,%.9g,%.9g,%.9g,%.9g,%.9g", q[0] + q[2], q[1] + q[3], q[0], q[1],
              q[2], q[3]);
    }
    fprintf(o->forces, "\n");
    fflush(o->forces);
    CLSPH_TRY(force_row(sim, o, row));
  }
  if (o->flow != NULL) fflush(o->flow);
done:
  free(at);
  free(rows);
  return st;
}

/* The fields a frame can show: the output fields, by name and components. */
static int frame_fields(const struct sim *sim, const char **names, int *ncomp)
{
  int n = 0;
  for (int k = 0; k < sim->ps.nfields; ++k) {
    if (!sim->ps.f[k].output) continue;
    names[n] = sim->ps.f[k].name;
    ncomp[n++] = sim->ps.f[k].nout;
  }
  return n;
}

/* Frames: resolve the field against the run's output fields, open the renderer, and list the
 * arrays a frame reads from the device. */
static enum clsph_status open_frames(struct sim *sim, const struct sim_options *opt,
                                     struct run_out *o)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  const char *names[PSET_MAX_FIELDS];
  int ncomp[PSET_MAX_FIELDS];
  const int n = frame_fields(sim, names, ncomp);
  CLSPH_TRY(frames_open(opt->frames, opt->out_dir, n, names, ncomp, &o->frames));
  const char *want[4] = {"pos", "vol", "kind", frames_field(o->frames)->array};
  for (int k = 0; k < 4; ++k) {
    int dup = 0;
    for (int j = 0; j < k; ++j) dup |= strcmp(want[j], want[k]) == 0;
    if (dup) continue;
    const int f = pset_find(&sim->ps, want[k]);
    CLSPH_CHECK(f >= 0, CLSPH_E_INPUT, "frames: the run has no field '%s'", want[k]);
    o->frame_in[o->nframe_arrays].name = sim->ps.f[f].name;
    o->frame_in[o->nframe_arrays].ncomp = sim->ps.f[f].nout;
    o->frame_arrays[o->nframe_arrays] =
        malloc(sim->ps.cap * (size_t)sim->ps.f[f].nout * sizeof(double));
    CLSPH_CHECK(o->frame_arrays[o->nframe_arrays] != NULL, CLSPH_E_NOMEM,
                "out of memory for the frames");
    o->frame_in[o->nframe_arrays].v = o->frame_arrays[o->nframe_arrays];
    ++o->nframe_arrays;
  }
  if (s->nwalls > 0) {
    o->walls = calloc((size_t)s->nwalls, sizeof *o->walls);
    CLSPH_CHECK(o->walls != NULL, CLSPH_E_NOMEM, "out of memory");
    for (int w = 0; w < s->nwalls; ++w)
      o->walls[w] = (struct render_wall){s->walls[w].npts, s->walls[w].pts, s->walls[w].closed};
  }
  const double domain[4] = {s->lo[0], s->lo[1], s->hi[0], s->hi[1]};
  frames_view(domain, s->nwalls, o->walls, o->view);
done:
  return st;
}

/* A frame of the device state now: the arrays it reads, copied to the host as doubles. */
static enum clsph_status write_frame(struct sim *sim, struct run_out *o)
{
  enum clsph_status st = CLSPH_OK;
  unsigned char *h = NULL;
  const size_t n = sim->ps.n;
  for (int a = 0; a < o->nframe_arrays; ++a) {
    const struct pfield *f = &sim->ps.f[pset_find(&sim->ps, o->frame_in[a].name)];
    h = malloc(n > 0 ? n * f->elem : 1);
    CLSPH_CHECK(h != NULL, CLSPH_E_NOMEM, "out of memory for a frame");
    if (n > 0) CLSPH_TRY(kern_read(sim->dev, f->d, n * f->elem, h));
    double *v = o->frame_arrays[a];
    const size_t nc = (size_t)f->ncomp, nout = (size_t)f->nout;
    for (size_t i = 0; i < n; ++i) {
      for (size_t c = 0; c < nout; ++c) {
        const size_t k = i * nc + c;
        v[i * nout + c] = f->type == PF_REAL   ? (double)((const real *)(const void *)h)[k]
                          : f->type == PF_UINT ? (double)((const cl_uint *)(const void *)h)[k]
                                               : (double)((const cl_int *)(const void *)h)[k];
      }
    }
    free(h);
    h = NULL;
  }
  struct render_input in;
  memset(&in, 0, sizeof in);
  in.n = n;
  in.narrays = o->nframe_arrays;
  in.arrays = o->frame_in;
  in.nwalls = sim->scene->nwalls;
  in.walls = o->walls;
  memcpy(in.view, o->view, sizeof in.view);
  in.time = sim->time;
  in.case_name = sim->scene->name;
  in.scheme = sim->scheme->name;
  CLSPH_TRY(frames_write(o->frames, &in, o->nsnap));
done:
  free(h);
  return st;
}

static void meta_of(const struct sim *sim, struct io_meta *m)
{
  memset(m, 0, sizeof *m);
  m->case_name = sim->scene->name;
  m->case_path = sim->scene->case_path;
  m->scheme = sim->scheme->name;
  m->precision = CLSPH_PRECISION_NAME;
  m->version = CLSPH_VERSION;
  m->time = sim->time;
  m->step = sim->step;
  m->dt = sim->dt;
  m->dim = 2;
  m->params = sim->scene->params;
  m->nparams = sim->scene->nparams;
  m->has_domain = 1;
  m->domain[0] = sim->scene->lo[0];
  m->domain[1] = sim->scene->lo[1];
  m->domain[2] = sim->scene->hi[0];
  m->domain[3] = sim->scene->hi[1];
  m->walls = sim->scene->walls;
  m->nwalls = sim->scene->nwalls;
  m->render = &sim->scene->render;
}

static enum clsph_status write_snapshot(struct sim *sim, struct run_out *o)
{
  enum clsph_status st = CLSPH_OK;
  char name[64], path[1200];
  struct io_meta m;
  meta_of(sim, &m);
  snprintf(name, sizeof name, "snap_%06d.h5", o->nsnap);
  CLSPH_TRY(path_in(o, name, path, sizeof path));
  CLSPH_TRY(io_snapshot_write(path, sim->dev, &sim->ps, &m));
  CLSPH_TRY(io_series_add(&o->series, name, sim->time, sim->ps.n));
  CLSPH_TRY(path_in(o, "snapshots.xdmf", path, sizeof path));
  CLSPH_TRY(io_xdmf_write(path, &o->series, &sim->ps, 2));
  if (o->frames != NULL) CLSPH_TRY(write_frame(sim, o));
  /* with run { sample_every }, the time series keep their own cadence (see sim_run) */
  CLSPH_TRY(write_series(sim, o,
                         sim->scene->sample_every > 0.0 && sim->time > 0.0
                             ? SERIES_PROFILES
                             : SERIES_TIME | SERIES_PROFILES));
  ++o->nsnap;
done:
  return st;
}

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

static enum clsph_status write_checkpoint(struct sim *sim, struct run_out *o)
{
  enum clsph_status st = CLSPH_OK;
  char name[64], path[1200];
  struct io_meta m;
  meta_of(sim, &m);
  snprintf(name, sizeof name, "checkpoint_%06ld.h5", sim->step);
  CLSPH_TRY(path_in(o, name, path, sizeof path));
  /* the flow-rate control's state and the scheme's host state travel in the blob, so a restart
   * continues bit for bit */
  unsigned char blob[sizeof sim->flow + 64 * sizeof(double)];
  size_t bytes = 0;
  CLSPH_TRY(state_blob(sim, blob, sizeof blob, &bytes));
  CLSPH_TRY(io_checkpoint_write(path, sim->dev, &sim->ps, &m, bytes > 0 ? blob : NULL, bytes));
  log_debug("checkpoint %s at t = %g s", path, sim->time);
done:
  return st;
}

static void close_out(const struct scene *s, struct run_out *o)
{
  if (o->probes != NULL) fclose(o->probes);
  if (o->forces != NULL) fclose(o->forces);
  if (o->flow != NULL) fclose(o->flow);
  for (int p = 0; o->profiles != NULL && p < s->nprofiles; ++p)
    if (o->profiles[p] != NULL) fclose(o->profiles[p]);
  free(o->profiles);
  free(o->force_stats);
  free(o->force_scratch);
  io_series_free(&o->series);
  frames_close(o->frames);
  free(o->walls);
  for (int a = 0; a < o->nframe_arrays; ++a) free(o->frame_arrays[a]);
}

/* ---- progress ---- */

struct progress {
  int tty, quiet;
  double start, last;
};

static void progress_show(const struct sim *sim, struct progress *pr, int final)
{
  double t = now();
  if (pr->quiet || (!final && t - pr->last < (pr->tty ? 0.2 : 5.0))) return;
  pr->last = t;
  double frac = sim->scene->t_end > 0.0 ? sim->time / sim->scene->t_end : 1.0;
  double el = t - pr->start, rate = el > 0.0 ? (double)sim->step / el : 0.0;
  double eta = frac > 0.0 ? el * (1.0 - frac) / frac : 0.0;
  char solver[96] = "";
  if (sim->solver_steps > 0)
    snprintf(solver, sizeof solver, "  solver %ld its (res %.1e)", sim->solver_its,
             sim->solver_res);
  if (sim->aux_its_sum > 0)
    snprintf(solver + strlen(solver), sizeof solver - strlen(solver), ", viscous %ld its",
             sim->aux_its);
  if (pr->tty) {
    char bar[21];
    int fill = (int)(20.0 * fmin(frac, 1.0));
    for (int i = 0; i < 20; ++i) bar[i] = i < fill ? '=' : ' ';
    bar[20] = '\0';
    fprintf(stderr, "\r[%s] t %.4g/%.4g s  step %ld  %.1f steps/s%s  ETA %.0f s   ", bar, sim->time,
            sim->scene->t_end, sim->step, rate, solver, eta);
    if (final) fputc('\n', stderr);
  } else {
    fprintf(stderr, "t %.6g/%.6g s (%.0f%%)  step %ld  %.1f steps/s%s  ETA %.0f s\n", sim->time,
            sim->scene->t_end, 100.0 * frac, sim->step, rate, solver, eta);
  }
}

/* ---- metrics ---- */

struct metric_ctx {
  struct sim *sim;
};

static enum clsph_status metric_stats(void *ctx, const char *field, int comp, int kind, double *mn,
                                      double *mx, double *mean)
{
  enum clsph_status st = CLSPH_OK;
  struct sim *sim = ((struct metric_ctx *)ctx)->sim;
  real *v = NULL;
  cl_uint *k = NULL;
  int idx = pset_find(&sim->ps, field);
  CLSPH_CHECK(idx >= 0, CLSPH_E_INPUT, "metrics: no field '%s'", field);
  const struct pfield *f = &sim->ps.f[idx];
  CLSPH_CHECK(comp >= 0 && comp < f->nout, CLSPH_E_INPUT, "metrics: field '%s' has %d components",
              field, f->nout);
  size_t n = sim->ps.n;
  v = malloc(n * f->elem);
  k = malloc(n * sizeof *k);
  CLSPH_CHECK(v != NULL && k != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(kern_read(sim->dev, f->d, n * f->elem, v));
  CLSPH_TRY(kern_read(sim->dev, pset_mem(&sim->ps, sim->f_kind), n * sizeof *k, k));
  double a = HUGE_VAL, b = -HUGE_VAL, s = 0.0;
  size_t c = 0;
  for (size_t i = 0; i < n; ++i) {
    if (kind >= 0 && k[i] != (cl_uint)kind) continue;
    double x;
    if (f->type == PF_REAL)
      x = (double)v[i * (size_t)f->ncomp + (size_t)comp];
    else
      x = (double)((const cl_uint *)(const void *)v)[i * (size_t)f->ncomp + (size_t)comp];
    a = fmin(a, x);
    b = fmax(b, x);
    s += x;
    ++c;
  }
  CLSPH_CHECK(c > 0, CLSPH_E_INPUT, "metrics: no particle of that kind");
  *mn = a;
  *mx = b;
  *mean = s / (double)c;
done:
  free(k);
  free(v);
  return st;
}

/* Positions and one component of a field of the particles of one kind (−1: all). */
static enum clsph_status metric_particles(void *ctx, const char *field, int comp, int kind,
                                          size_t *count, double **xy, double **values)
{
  enum clsph_status st = CLSPH_OK;
  struct sim *sim = ((struct metric_ctx *)ctx)->sim;
  real *v = NULL, *x = NULL;
  cl_uint *k = NULL;
  double *oxy = NULL, *ov = NULL;
  int idx = pset_find(&sim->ps, field);
  CLSPH_CHECK(idx >= 0, CLSPH_E_INPUT, "metrics: no field '%s'", field);
  const struct pfield *f = &sim->ps.f[idx];
  CLSPH_CHECK(comp >= 0 && comp < f->nout, CLSPH_E_INPUT, "metrics: field '%s' has %d components",
              field, f->nout);
  const size_t n = sim->ps.n;
  v = malloc(n * f->elem);
  x = malloc(2 * n * sizeof *x);
  k = malloc(n * sizeof *k);
  oxy = malloc(2 * n * sizeof *oxy + 1);
  ov = malloc(n * sizeof *ov + 1);
  CLSPH_CHECK(v != NULL && x != NULL && k != NULL && oxy != NULL && ov != NULL, CLSPH_E_NOMEM,
              "out of memory");
  CLSPH_TRY(kern_read(sim->dev, f->d, n * f->elem, v));
  CLSPH_TRY(kern_read(sim->dev, pset_mem(&sim->ps, sim->f_pos), 2 * n * sizeof *x, x));
  CLSPH_TRY(kern_read(sim->dev, pset_mem(&sim->ps, sim->f_kind), n * sizeof *k, k));
  size_t c = 0;
  for (size_t i = 0; i < n; ++i) {
    if (kind >= 0 && k[i] != (cl_uint)kind) continue;
    const size_t at = i * (size_t)f->ncomp + (size_t)comp;
    oxy[2 * c] = (double)x[2 * i];
    oxy[2 * c + 1] = (double)x[2 * i + 1];
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

static enum clsph_status metric_sample(void *ctx, const char *field, int comp, double x, double y,
                                       double *value)
{
  enum clsph_status st = CLSPH_OK;
  struct sim *sim = ((struct metric_ctx *)ctx)->sim;
  double at[2] = {x, y}, out[4];
  int idx = pset_find(&sim->ps, field);
  CLSPH_CHECK(idx >= 0, CLSPH_E_INPUT, "metrics: no field '%s'", field);
  CLSPH_CHECK(comp >= 0 && comp < sim->ps.f[idx].nout, CLSPH_E_INPUT,
              "metrics: field '%s' has %d components", field, sim->ps.f[idx].nout);
  CLSPH_TRY(sim_sample(sim, idx, 1, at, out));
  *value = out[comp];
done:
  return st;
}

static enum clsph_status metric_sample_many(void *ctx, const char *field, int comp, int np,
                                            const double *xy, double *values)
{
  enum clsph_status st = CLSPH_OK;
  struct sim *sim = ((struct metric_ctx *)ctx)->sim;
  double *out = NULL;
  int idx = pset_find(&sim->ps, field);
  CLSPH_CHECK(idx >= 0, CLSPH_E_INPUT, "metrics: no field '%s'", field);
  const struct pfield *f = &sim->ps.f[idx];
  CLSPH_CHECK(comp >= 0 && comp < f->nout, CLSPH_E_INPUT, "metrics: field '%s' has %d components",
              field, f->nout);
  out = malloc((size_t)np * (size_t)f->ncomp * sizeof *out);
  CLSPH_CHECK(out != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(sim_sample(sim, idx, (size_t)np, xy, out));
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

/* The recorded total force of a group at each row with t >= since: rows of (t, x, y). */
static enum clsph_status metric_force_history(void *ctx, const char *group, double since, size_t *n,
                                              double **rows)
{
  enum clsph_status st = CLSPH_OK;
  struct sim *sim = ((struct metric_ctx *)ctx)->sim;
  const int g = force_group(sim->scene, group);
  *rows = NULL;
  *n = 0;
  CLSPH_CHECK(g >= 0, CLSPH_E_INPUT,
              "metrics: sim.force_history: the case records no force of '%s' (force { \"%s\" })",
              group, group);
  const size_t cols = 1 + 4 * (size_t)sim->scene->nforces;
  double *out = malloc(3 * (sim->nforce_rows + 1) * sizeof *out);
  CLSPH_CHECK(out != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t r = 0; r < sim->nforce_rows; ++r) {
    const double *row = sim->force_rows + r * cols;
    if (row[0] < since * (1.0 - 1e-12)) continue;
    out[3 * *n] = row[0];
    out[3 * *n + 1] = row[1 + 4 * g] + row[3 + 4 * g]; /* pressure + viscous */
    out[3 * *n + 2] = row[2 + 4 * g] + row[4 + 4 * g];
    ++*n;
  }
  *rows = out;
done:
  return st;
}

/* Mean of the recorded forces of a group over the outputs at t >= since (since < 0: the last). */
static enum clsph_status metric_force(void *ctx, const char *group, double since, double out[6],
                                      int *samples)
{
  enum clsph_status st = CLSPH_OK;
  struct sim *sim = ((struct metric_ctx *)ctx)->sim;
  const struct scene *s = sim->scene;
  const int g = force_group(s, group);
  CLSPH_CHECK(g >= 0, CLSPH_E_INPUT,
              "metrics: sim.force: the case records no force of '%s' "
              "(force { \"%s\" })",
              group, group);
  CLSPH_CHECK(sim->nforce_rows > 0, CLSPH_E_INPUT, "metrics: sim.force: no force recorded yet");
  const size_t cols = 1 + 4 * (size_t)s->nforces;
  double sum[4] = {0.0, 0.0, 0.0, 0.0};
  int c = 0;
  for (size_t r = 0; r < sim->nforce_rows; ++r) {
    const double *row = sim->force_rows + r * cols;
    if (since < 0.0 ? r + 1 < sim->nforce_rows : row[0] < since * (1.0 - 1e-12)) continue;
    for (int k = 0; k < 4; ++k) sum[k] += row[1 + 4 * g + k];
    ++c;
  }
  CLSPH_CHECK(c > 0, CLSPH_E_INPUT, "metrics: sim.force: no force recorded at t >= %g s", since);
  for (int k = 0; k < 4; ++k) sum[k] /= c;
  out[0] = sum[0] + sum[2];
  out[1] = sum[1] + sum[3];
  for (int k = 0; k < 4; ++k) out[2 + k] = sum[k];
  *samples = c;
done:
  return st;
}

/* ---- summary ---- */

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

static enum clsph_status write_summary(struct sim *sim, const struct run_out *o, double wall,
                                       struct case_script *script)
{
  enum clsph_status st = CLSPH_OK;
  char path[1200];
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
  if (sim->step0 > 0) cJSON_AddNumberToObject(root, "restarted_at_step", (double)sim->step0);
  cJSON_AddNumberToObject(root, "wall_seconds", wall);
  cJSON_AddNumberToObject(root, "particle_steps_per_second",
                          wall > 0.0 ? (double)sim->ps.n * (double)(sim->step - sim->step0) / wall
                                     : 0.0);
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
  if (sim->health_checks > 0) { /* the health checks' worst values over the run */
    cJSON *h = cJSON_AddObjectToObject(root, "health");
    CLSPH_CHECK(h != NULL, CLSPH_E_NOMEM, "out of memory");
    cJSON_AddNumberToObject(h, "checks", (double)sim->health_checks);
    cJSON_AddNumberToObject(h, "velocity_scale", sim->u_ref);
    cJSON_AddNumberToObject(h, "kinetic_energy_ratio_max", sim->energy_ratio_max);
    cJSON_AddNumberToObject(h, "nearest_spacing_min_dr", sim->spacing_min);
    cJSON_AddNumberToObject(h, "clustered_fraction_max", sim->cluster_max);
  }
  if (sim->dev->profile != NULL) CLSPH_TRY(summary_profile(root, sim->dev->profile, wall));
  cJSON *metrics = cJSON_AddObjectToObject(root, "metrics");
  CLSPH_CHECK(params != NULL && metrics != NULL, CLSPH_E_NOMEM, "out of memory");
  if (script != NULL && strcmp(sim->status, "ok") == 0) {
    struct metric_ctx ctx = {sim};
    struct case_sim_api api = {.ctx = &ctx,
                               .time = sim->time,
                               .steps = sim->step,
                               .particles = (double)sim->ps.n,
                               .wall_steps = sim->wall_steps,
                               .wall_most = sim->wall_most,
                               .stats = metric_stats,
                               .sample_many = metric_sample_many,
                               .sample = metric_sample,
                               .force = metric_force,
                               .force_history = metric_force_history,
                               .dir = o->dir,
                               .field_values = metric_particles};
    enum clsph_status ms = case_metrics(script, &api, metrics);
    if (ms != CLSPH_OK) {
      snprintf(sim->status, sizeof sim->status, "metrics failed");
      snprintf(sim->failure, sizeof sim->failure, "metrics");
    }
    cJSON_ReplaceItemInObject(root, "status", cJSON_CreateString(sim->status));
    cJSON_ReplaceItemInObject(root, "failure", cJSON_CreateString(sim->failure));
  }
  text = cJSON_Print(root);
  CLSPH_CHECK(text != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(path_in(o, "summary.json", path, sizeof path));
  f = fopen(path, "w");
  CLSPH_CHECK(f != NULL, CLSPH_E_IO, "cannot write %s: %s", path, strerror(errno));
  CLSPH_CHECK(fputs(text, f) >= 0 && fputc('\n', f) != EOF, CLSPH_E_IO, "cannot write %s", path);
done:
  if (f != NULL && fclose(f) != 0 && st == CLSPH_OK) {
    log_error("cannot write %s", path);
    st = CLSPH_E_IO;
  }
  free(text);
  cJSON_Delete(root);
  return st;
}

/* ---- the time loop ---- */

/* Flow-rate control, before a step of length δt (Leroy et al. 2014 eq 67, from Morris, Fox &
 * Zhu 1997):
 *   F^n = F^{n−1} + (⟨v⟩ − 2ṽ^{n−1} + ṽ^{n−2})/δt,
 * ṽ (eq 68) the mean x velocity of the fluid particles in the slice; before the first step
 * ṽ^{n−2} = ṽ^{n−1}. The controller needs steps of (nearly) constant length: a short step cut
 * to land on an output time made it unstable (cylinder array, n = 20: steps of 0.08 s with one
 * of 0.01 s every 0.25 s gave a period-4 oscillation of F growing 25% a cycle), which is why
 * the time loop lands on outputs in equal steps. One line per step goes to flow_control.csv. */
static enum clsph_status flow_control(struct sim *sim, double dt, FILE *log)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene_flow_control *c = &sim->scene->flow;
  struct sim_flow *f = &sim->flow;
  double v = 0.0, count = 0.0;
  CLSPH_TRY(sim_slice_velocity(sim, c->slice[0], c->slice[1], &v, &count));
  if (!(count > 0.0)) {
    snprintf(sim->status, sizeof sim->status,
             "flow-rate control: no fluid particle in the slice [%g, %g) at step %ld, t = %.9g s",
             c->slice[0], c->slice[1], sim->step, sim->time);
    log_error("%s:%d: %s", sim->scene->case_path, c->line, sim->status);
    snprintf(sim->failure, sizeof sim->failure, "flow_control");
    st = sim->step == 0 ? CLSPH_E_INPUT : CLSPH_E_BLOWUP;
    goto done;
  }
  if (f->primed == 0.0) f->v1 = v; /* ṽ^{n−2} = ṽ^{n−1} at the first step */
  f->v2 = f->v1;
  f->v1 = v;
  f->force += (c->velocity - 2.0 * f->v1 + f->v2) / dt;
  f->primed = 1.0;
  sim->body_force[0] = f->force;
  if (log != NULL)
    fprintf(log, "%.17g,%.9g,%.9g,%.9g,%.0f\n", sim->time, dt, f->force, f->v1, count);
done:
  return st;
}

/* The next multiple of `every` after time t (a function of t alone, so a restart agrees). */
static double next_mark(double t, double every)
{
  if (!(every > 0.0)) return HUGE_VAL;
  double k = floor(t / every + 1e-9);
  double m = (k + 1.0) * every;
  return m > t ? m : m + every;
}

enum clsph_status sim_run(struct sim *sim, const struct sim_options *opt,
                          struct case_script *script)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  struct run_out o;
  struct progress pr;
  memset(&o, 0, sizeof o);
  memset(&pr, 0, sizeof pr);
  enum clsph_status pst = CLSPH_OK;
  double start = now();
  kern_profile_start(sim->dev->profile);

  CLSPH_CHECK(s->nforces == 0 || sim->scheme->wall_force != NULL, CLSPH_E_INPUT,
              "%s: force { ... } asks for wall forces, which scheme '%s' does not compute",
              s->case_path, sim->scheme->name);
  for (int g = 0; g < s->nforces; ++g) {
    int found = 0;
    for (int w = 0; w < s->nwalls; ++w) found |= strcmp(s->walls[w].group, s->forces[g]) == 0;
    CLSPH_CHECK(found, CLSPH_E_INPUT, "%s: force: no wall group '%s'", s->case_path, s->forces[g]);
  }
  if (opt->frames != NULL) { /* the field of frames exists, before anything is written */
    const char *names[PSET_MAX_FIELDS];
    int ncomp[PSET_MAX_FIELDS];
    struct field_spec f;
    const int n = frame_fields(sim, names, ncomp);
    CLSPH_TRY(field_find(opt->frames->render.field, n, names, ncomp, &f));
  }
  CLSPH_TRY(prepare_dir(opt->out_dir));
  snprintf(o.dir, sizeof o.dir, "%s", opt->out_dir);
  if (opt->frames != NULL) CLSPH_TRY(open_frames(sim, opt, &o));
  if (opt->restart != NULL) {
    struct io_meta expect, got;
    meta_of(sim, &expect);
    memset(&got, 0, sizeof got);
    void *blob = NULL;
    size_t blob_bytes = 0;
    CLSPH_TRY(
        io_checkpoint_read(opt->restart, sim->dev, &sim->ps, &expect, &got, &blob, &blob_bytes));
    st = restore_blob(sim, opt->restart, blob, blob_bytes);
    free(blob);
    if (st != CLSPH_OK) goto done;
    sim->body_force[0] = s->flow.on ? sim->flow.force : s->body_force[0];
    sim->time = got.time;
    sim->step = got.step;
    sim->step0 = got.step;
    sim->dt = got.dt;
    o.nsnap = s->output_every > 0.0 ? (int)floor(sim->time / s->output_every + 1e-9) + 1 : 1;
    log_info("restarting from %s at t = %.9g s, step %ld", opt->restart, sim->time, sim->step);
  }
  CLSPH_TRY(open_series(sim, &o, opt->restart));
  pr.tty = isatty(2);
  pr.quiet = opt->quiet;
  pr.start = now();
  if (opt->restart == NULL) CLSPH_TRY(write_snapshot(sim, &o));

  const double t_end = s->t_end;
  while (sim->time < t_end) {
    CLSPH_TRY(sim_sort(sim));
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
               "blow-up: the time step collapsed to %g s at step %ld, t = %.9g s", dt, sim->step,
               sim->time);
      st = fail(sim, "dt_collapse");
      goto done;
    }
    /* land exactly on the next output, checkpoint or end, in equal steps */
    double target = fmin(t_end, fmin(next_mark(sim->time, s->output_every),
                                     next_mark(sim->time, s->checkpoint_every)));
    double left = target - sim->time, k = ceil(left / dt * (1.0 - 1e-9));
    int lands = sim->time + dt >= target * (1.0 - 1e-12) || !(k > 1.0);
    dt = lands ? left : left / k;
    if (s->flow.on) CLSPH_TRY(flow_control(sim, dt, o.flow));
    CLSPH_TRY(sim->scheme->step(sim, sim->state, dt));
    sim->time = lands ? target : sim->time + dt;
    sim->dt = dt;
    ++sim->step;
    if (sim->solver_its > 0) {
      sim->solver_its_sum += sim->solver_its;
      sim->solver_steps += 1;
      if (sim->solver_its > sim->solver_its_max) sim->solver_its_max = sim->solver_its;
      sim->aux_its_sum += sim->aux_its;
    }
    CLSPH_TRY(sim_check_flags(sim));
    int at_end = sim->time >= t_end;
    if (s->checks.every > 0 && (sim->step % s->checks.every == 0 || at_end))
      CLSPH_TRY(sim_check_health(sim));
    /* time series at their own cadence: the first step at or past each multiple of sample_every */
    if (s->sample_every > 0.0 && floor(sim->time / s->sample_every * (1.0 + 1e-12)) >
                                     floor((sim->time - dt) / s->sample_every * (1.0 + 1e-12)))
      CLSPH_TRY(write_series(sim, &o, SERIES_TIME));
    if (lands && (at_end || (s->output_every > 0.0 &&
                             fabs(remainder(sim->time, s->output_every)) < 1e-9 * s->output_every)))
      CLSPH_TRY(write_snapshot(sim, &o));
    if (lands &&
        (at_end || (s->checkpoint_every > 0.0 &&
                    fabs(remainder(sim->time, s->checkpoint_every)) < 1e-9 * s->checkpoint_every)))
      CLSPH_TRY(write_checkpoint(sim, &o));
    progress_show(sim, &pr, 0);
  }
  progress_show(sim, &pr, 1);
done:
  /* the profiled window ends with its commands run, and leaves out the metrics' kernels */
  pst = kern_profile_stop(sim->dev->profile);
  if (st == CLSPH_OK) st = pst;
  sim->wall = now() - start;
  if (st == CLSPH_E_BLOWUP && strcmp(sim->status, "ok") == 0) {
    /* the only blow-up the time loop does not word itself: the pressure solver's (psolve.c) */
    snprintf(sim->status, sizeof sim->status,
             "blow-up: the %s solve failed at step %ld, t = %.9g s",
             sim->failed_solve != NULL ? sim->failed_solve : "pressure", sim->step + 1, sim->time);
    snprintf(sim->failure, sizeof sim->failure, "solver");
  }
  if (st != CLSPH_OK && strcmp(sim->status, "ok") == 0)
    snprintf(sim->status, sizeof sim->status, "failed: %s", clsph_status_str(st));
  if (st != CLSPH_OK && strcmp(sim->failure, "none") == 0)
    snprintf(sim->failure, sizeof sim->failure, "error");
  if (o.dir[0] != '\0') {
    enum clsph_status ws = write_summary(sim, &o, sim->wall, script);
    if (st == CLSPH_OK) st = ws;
    if (st == CLSPH_OK && strcmp(sim->status, "ok") != 0) st = CLSPH_E_INPUT;
  }
  if (o.frames != NULL) { /* the movie of what there is, also of a run that stopped */
    enum clsph_status fs = frames_finish(o.frames, opt->quiet);
    if (st == CLSPH_OK) st = fs;
  }
  close_out(s, &o);
  return st;
}

enum clsph_status sim_psolve_options(const struct sim *sim, struct psolve_options *o)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  psolve_defaults(o);
  for (int i = 0; i < s->noptions; ++i) {
    const struct scene_option *opt = &s->options[i];
    const char *key = NULL;
    if (strcmp(opt->key, "solver") == 0)
      key = "solver";
    else if (strncmp(opt->key, "solver_", 7) == 0)
      key = opt->key + 7;
    if (key == NULL) continue;
    enum clsph_status os = psolve_set(o, key, opt->is_number ? NULL : opt->text,
                                      opt->is_number ? opt->number : (double)NAN);
    CLSPH_CHECK(os == CLSPH_OK, os, "%s: in scheme option %s", s->case_path, opt->key);
  }
done:
  return st;
}

void sim_destroy(struct sim *sim)
{
  if (sim->scheme != NULL && sim->scheme->destroy != NULL) sim->scheme->destroy(sim->state);
  sim->state = NULL;
  if (sim->k_probe != NULL) clReleaseKernel(sim->k_probe);
  if (sim->k_max_speed != NULL) clReleaseKernel(sim->k_max_speed);
  if (sim->k_count != NULL) clReleaseKernel(sim->k_count);
  if (sim->k_invert != NULL) clReleaseKernel(sim->k_invert);
  if (sim->k_slice != NULL) clReleaseKernel(sim->k_slice);
  if (sim->k_health != NULL) clReleaseKernel(sim->k_health);
  sim->k_probe = sim->k_max_speed = sim->k_count = sim->k_invert = sim->k_slice = NULL;
  sim->k_health = NULL;
  kern_release(&sim->d_health);
  kern_release(&sim->d_inv);
  kern_release(&sim->d_partial);
  kern_release(&sim->d_flags);
  grid_destroy(&sim->grid);
  pset_destroy(&sim->ps);
  if (sim->prog != NULL) clReleaseProgram(sim->prog);
  sim->prog = NULL;
  geometry_free(&sim->geom);
  free(sim->force_rows);
  sim->force_rows = NULL;
  sim->nforce_rows = sim->force_rows_cap = 0;
}
