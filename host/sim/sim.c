/* sim.c: set-up of a simulation from a scene (geometry, program, fields, scheme), the sort by
 * cell that precedes every step, `clsph info`, and release. The reductions over the particles are
 * in reduce.c, the health checks in checks.c, the flow-rate control in flow.c; the time loop that
 * drives a simulation is host/loop/loop.c. */
#include "sim.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scheme.h"
#include "clsph_config.h"
#include "kern.h"
#include "psolve.h"

static const char *const common_sources[] = {OPS_SOURCES, "common/reduce.cl", "common/probe.cl",
                                             "common/health.cl", "common/domain.cl"};

size_t sim_reduce_groups(size_t n)
{
  size_t g = (n + 63) / 64;
  return g < 1 ? 1 : (g > SIM_REDUCE_MAX_GROUPS ? SIM_REDUCE_MAX_GROUPS : g);
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
  const size_t n = g->n, dim = (size_t)g->dim, stride = dim == 3 ? 4 : 2; /* realv */
  real *xv = calloc(2 * stride * n + n, sizeof *xv);
  cl_uint *u = calloc(2 * n, sizeof *u);
  CLSPH_CHECK(xv != NULL && u != NULL, CLSPH_E_NOMEM, "out of memory for %zu particles", n);
  real *v = xv + stride * n, *vol = xv + 2 * stride * n;
  for (size_t i = 0; i < n; ++i) {
    for (size_t a = 0; a < dim; ++a) {
      xv[stride * i + a] = (real)g->x[dim * i + a];
      v[stride * i + a] = (real)g->v[dim * i + a];
    }
    vol[i] = (real)pow(sim->scene->dr, (double)dim);
    u[i] = (cl_uint)g->kind[i];
    u[n + i] = (cl_uint)i;
  }
  pset_init(&sim->ps, n, n);
  CLSPH_TRY(pset_add(&sim->ps, sim->dev, "pos", stride * sizeof(real), xv, &sim->f_pos));
  CLSPH_TRY(pset_add(&sim->ps, sim->dev, "vel", stride * sizeof(real), v, &sim->f_vel));
  CLSPH_TRY(pset_add(&sim->ps, sim->dev, "kind", sizeof(cl_uint), u, &sim->f_kind));
  CLSPH_TRY(pset_add(&sim->ps, sim->dev, "id", sizeof(cl_uint), u + n, &sim->f_id));
  CLSPH_TRY(pset_add(&sim->ps, sim->dev, "vol", sizeof(real), vol, &sim->f_vol));
  if (dim == 3) { /* x, y, z of the real4 */
    pset_describe(&sim->ps, sim->f_pos, PF_REAL, 3, 1);
    pset_describe(&sim->ps, sim->f_vel, PF_REAL, 3, 1);
  }
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
    u2 = fmax(u2, wl->velocity[0] * wl->velocity[0] + wl->velocity[1] * wl->velocity[1] +
                      wl->velocity[2] * wl->velocity[2]);
    for (int k = 0; k < wl->npts && wl->omega != 0.0; ++k) {
      double r = hypot(wl->pts[2 * k] - wl->centre[0], wl->pts[2 * k + 1] - wl->centre[1]);
      u2 = fmax(u2, wl->omega * wl->omega * r * r);
    }
  }
  for (int k = 0; k < s->nsections; ++k)
    u2 = fmax(u2, s->sections[k].velocity * s->sections[k].velocity);
  if (s->flow.on) u2 = fmax(u2, s->flow.velocity * s->flow.velocity);
  const size_t dim = (size_t)g->dim;
  for (size_t i = 0; i < g->nfluid; ++i) {
    double v2 = 0.0;
    for (size_t a = 0; a < dim; ++a) v2 += g->v[dim * i + a] * g->v[dim * i + a];
    u2 = fmax(u2, v2);
  }
  /* (2-D: hypot(., 0) is exact, the figures as they were) */
  const double lz = dim == 3 ? s->hi[2] - s->lo[2] : 0.0;
  const double L = hypot(hypot(s->hi[0] - s->lo[0], s->hi[1] - s->lo[1]), lz);
  const double f = hypot(hypot(s->body_force[0], s->body_force[1]), s->body_force[2]);
  const double acc =
      hypot(hypot(s->gravity[0] + s->body_force[0], s->gravity[1] + s->body_force[1]),
            s->gravity[2] + s->body_force[2]);
  u2 = fmax(u2, 2.0 * acc * L);
  if (s->nu > 0.0) u2 = fmax(u2, (f * L * L / s->nu) * (f * L * L / s->nu));
  return sqrt(u2);
}

/* The device memory the run needs, before anything runs or is written: the buffers made so far
 * (the particle fields, the grid, the scheme's) and what the scheme announced for its first step
 * (the pressure solver's stored operator). A device lazily backs a buffer, so a scene too large
 * otherwise failed only at its first step, after writing its initial snapshot. */
static enum clsph_status check_memory(struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  const double mib = 1024.0 * 1024.0;
  const double made = (double)kern_allocated(), later = (double)kern_reserved();
  sim->mem_estimate = made + later;
  CLSPH_CHECK(made + later <= (double)sim->dev->mem_limit, CLSPH_E_INPUT,
              "%s: the scene needs about %.0f MiB of device memory (%zu particles: %.0f MiB of "
              "fields and buffers, %.0f MiB for the pressure solver's stored operator), more than "
              "the %.0f MiB %s of %s: a coarser dr, solver_apply = \"recompute\" (no stored "
              "operator), or another device (clsph devices)",
              sim->scene->case_path, (made + later) / mib, sim->ps.cap, made / mib, later / mib,
              (double)sim->dev->mem_limit / mib,
              sim->dev->mem_limit < sim->dev->global_mem ? "--device-memory allows" : "of memory",
              sim->dev->name);
done:
  return st;
}

/* Before the particles are made: the fluid regions' area over dr² (their overlaps counted twice,
 * the domain's area at most) times the fields every particle has (position, velocity, volume,
 * kind and id) must fit in the device memory the run may use. A scene far too large is refused
 * here, before minutes of geometry and gigabytes of host memory. */
static enum clsph_status check_fluid_count(const struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  double area = 0.0;
  for (int r = 0; r < s->nregions; ++r) {
    const struct scene_region *g = &s->regions[r];
    double a = 0.0;
    for (int i = 0; i < g->npts; ++i) {
      const int j = (i + 1) % g->npts;
      a += g->pts[2 * i] * g->pts[2 * j + 1] - g->pts[2 * j] * g->pts[2 * i + 1];
    }
    area += 0.5 * fabs(a);
  }
  double domain = 1.0;
  for (int a = 0; a < s->dim; ++a) domain *= s->hi[a] - s->lo[a];
  for (int r = 0; r < s->nregions && s->dim == 3; ++r) { /* 3-D: boxes, spheres, cylinders */
    const double *bx = s->regions[r].box3, *sh = s->regions[r].shape3, pi = 3.141592653589793;
    if (s->regions[r].shape == SCENE_SPHERE) {
      area += 4.0 / 3.0 * pi * sh[3] * sh[3] * sh[3];
    } else if (s->regions[r].shape == SCENE_CYLINDER) {
      const double len =
          sqrt((sh[3] - sh[0]) * (sh[3] - sh[0]) + (sh[4] - sh[1]) * (sh[4] - sh[1]) +
               (sh[5] - sh[2]) * (sh[5] - sh[2]));
      area += pi * sh[6] * sh[6] * len;
    } else {
      area += (bx[3] - bx[0]) * (bx[4] - bx[1]) * (bx[5] - bx[2]);
    }
  }
  area = fmin(area, domain);
  const double n = area / pow(s->dr, s->dim),
               bytes = n * ((s->dim == 3 ? 9.0 : 5.0) * sizeof(real) + 8.0);
  CLSPH_CHECK(bytes <= (double)sim->dev->mem_limit, CLSPH_E_INPUT,
              "%s: the fluid regions hold about %.3g particles at dr = %g: their positions and "
              "velocities alone need %.0f MiB of device memory, more than the %.0f MiB the run "
              "may use on %s: a coarser dr, or another device (clsph devices)",
              s->case_path, n, s->dr, bytes / 1048576.0, (double)sim->dev->mem_limit / 1048576.0,
              sim->dev->name);
done:
  return st;
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

  char where[sizeof scene->case_path + 16];
  snprintf(where, sizeof where, "%s:%d", scene->case_path, scene->scheme_line);
  CLSPH_TRY(scheme_find(scene->scheme, where, &sim.scheme));
  CLSPH_TRY(check_options(scene, sim.scheme));
  CLSPH_CHECK(scene->dim == 2 || sim.scheme->three_d, CLSPH_E_INPUT,
              "%s: scheme %s runs 2-D scenes only%s; this scene is 3-D (its domain gives z): "
              "isph-stabilized, isph-rotational and wcsph-riemann run it",
              where, sim.scheme->name,
              strcmp(sim.scheme->wall_model, "usaw") == 0
                  ? " (its semi-analytical walls are 2-D: segments and vertex particles)"
                  : "");
  if (scene->turb.on) { /* a model the scheme has */
    int has = 0;
    for (const char *const *m = sim.scheme->turbulence; m != NULL && *m != NULL; ++m)
      has |= strcmp(*m, scene->turb.model) == 0;
    CLSPH_CHECK(has, CLSPH_E_INPUT,
                "%s:%d: turbulence: model = \"%s\": scheme %s has no turbulence model (the k-ε "
                "RANS model is wcsph-riemann's, isph-usaw's and wcsph-usaw's)",
                scene->case_path, scene->turb.line, scene->turb.model, sim.scheme->name);
    /* wcsph-riemann's wall model at y_p (Wang, Sun & Hu eq 10, from the declared k): its
     * step-wise wall function (eq 11) is a log law only above y+ = 11.225, and the paper keeps
     * y+ in 30-100. The USAW schemes' wall law (Leroy et al. eq 23) takes each particle's own
     * distance and turns linear in the sublayer: no such bound there. */
    if (strcmp(sim.scheme->wall_model, "usaw") != 0) {
      const struct scene_turbulence *t = &scene->turb;
      const double y_p = t->y_p > 0.0 ? t->y_p : 0.5 * scene->dr;
      const double yplus = y_p * pow(0.09, 0.25) * sqrt(t->k) / scene->nu;
      CLSPH_CHECK(yplus >= 11.225, CLSPH_E_INPUT,
                  "%s:%d: turbulence: y_p = %g m puts the first particles in the viscous "
                  "sublayer: y+ = y_p C_mu^1/4 k^1/2 / nu = %.3g with k = %g (Wang, Sun & Hu eq "
                  "10) is below 11.225, where the wall function is no log law; raise y_p (the "
                  "particles' first row, dr/2 = %g m unless given) to y+ 30-100",
                  scene->case_path, t->line, y_p, yplus, t->k, 0.5 * scene->dr);
    }
  }
  /* smoothing function and length */
  enum smoothing_kind kind;
  CLSPH_TRY(smoothing_kind_from_name(scene->smoothing[0] ? scene->smoothing : sim.scheme->smoothing,
                                     &kind));
  double hr = scene->h_over_dr > 0.0 ? scene->h_over_dr : sim.scheme->h_over_dr;
  CLSPH_TRY(smoothing_make(kind, scene->dim, hr * scene->dr, &sim.sm));
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
  CLSPH_CHECK(lo == NULL || (lo->is_number && lo->number >= 1.0 && lo->number <= 8.0 &&
                             lo->number == floor(lo->number)),
              CLSPH_E_INPUT,
              "%s: scheme option wall_layers must be a whole number of dummy layers from 1 to 8",
              scene->case_path);
  int layers = lo != NULL ? (int)lo->number : 3;
  CLSPH_TRY(check_fluid_count(&sim));
  /* a weakly-compressible scheme's park behind the exits: beyond the support of the last layer
   * and of the dummies of a wall that runs on through it */
  sim.park.fraction = sim.scheme->open_reserve;
  sim.park.behind = sim.sm.support + 0.5 * scene->dr;
  CLSPH_TRY(geometry_build(scene, model, layers, &sim.park, &sim.geom));
  sim.digest = geometry_digest(scene, &sim.geom);
  CLSPH_CHECK(!sim.geom.has_p0 || (sim.scheme->fill_fields & SCHEME_FILL_PRESSURE), CLSPH_E_INPUT,
              "%s:%d: fill { pressure }: scheme '%s' takes no initial pressure (it has none, or "
              "solves for it from the start)",
              scene->case_path, sim.geom.has_p0, sim.scheme->name);
  CLSPH_CHECK(!sim.geom.has_k0 || scene->turb.on, CLSPH_E_INPUT,
              "%s:%d: fill { k, epsilon }: the case declares no turbulence { model = ... } for "
              "them",
              scene->case_path, sim.geom.has_k0);
  CLSPH_CHECK(!sim.geom.has_rho0 || (sim.scheme->fill_fields & SCHEME_FILL_DENSITY), CLSPH_E_INPUT,
              "%s:%d: fill { density }: scheme '%s' takes no initial density (an incompressible "
              "scheme holds it at the fluid's density: give the weakly-compressible schemes one)",
              scene->case_path, sim.geom.has_rho0, sim.scheme->name);
  /* the cell grid: the domain, with room for wall and section layers on non-periodic axes */
  const int dim = scene->dim;
  sim.gspec.dim = dim;
  sim.gspec.sm = sim.sm;
  sim.gspec.support = sim.sm.support * (1.0 + sim.scheme->support_skin * fmax(scene->cfl, 1.0));
  double margin = (layers + 4) * scene->dr + sim.sm.support;
  sim_open_sides(scene, sim.gspec.open_lo, sim.gspec.open_hi); /* splashes clamp, grid.cl */
  for (int a = 0; a < dim; ++a) {
    sim.gspec.periodic[a] = scene->periodic[a];
    sim.gspec.lo[a] = scene->lo[a] - (scene->periodic[a] ? 0.0 : margin);
    sim.gspec.hi[a] = scene->hi[a] + (scene->periodic[a] ? 0.0 : margin);
  }
  /* and the particles parked behind the exits, with a cell to spare */
  for (size_t i = 0; i < sim.geom.n && sim.park.fraction > 0.0; ++i)
    for (int a = 0; a < dim; ++a)
      if (!scene->periodic[a] && sim.geom.kind[i] == KIND_PARKED) {
        sim.gspec.lo[a] = fmin(sim.gspec.lo[a], sim.geom.x[dim * i + a] - sim.gspec.support);
        sim.gspec.hi[a] = fmax(sim.gspec.hi[a], sim.geom.x[dim * i + a] + sim.gspec.support);
      }
  for (size_t i = 0; i < sim.geom.n; ++i)
    for (int a = 0; a < dim; ++a)
      CLSPH_CHECK(scene->periodic[a] || (sim.geom.x[dim * i + a] >= sim.gspec.lo[a] &&
                                         sim.geom.x[dim * i + a] < sim.gspec.hi[a]),
                  CLSPH_E_INPUT, "%s: a particle at (%g, %g%s) lies outside the domain",
                  scene->case_path, sim.geom.x[dim * i], sim.geom.x[dim * i + 1],
                  dim == 3 ? ", z beyond" : "");
  /* device state */
  CLSPH_TRY(build_program(&sim));
  CLSPH_TRY(add_fields(&sim));
  CLSPH_TRY(grid_create(dev, sim.prog, &sim.gspec, sim.ps.cap, &sim.grid));
  /* the bits, the count of particles behind a wall and the deepest, the fluid that left
   * (flags.h) */
  const cl_uint zeros[4] = {0, 0, 0, 0};
  CLSPH_TRY(kern_buffer(dev, sizeof zeros, zeros, &sim.d_flags, "flags"));
  sim.wall_first_step = -1;
  sim.escaped_first_step = -1;
  sim.open_waiting = sim.open_waiting_max = -1;
  CLSPH_TRY(prog_kernel(sim.prog, "probe_sample", &sim.k_probe));
  CLSPH_TRY(prog_kernel(sim.prog, "reduce_max_speed", &sim.k_max_speed));
  CLSPH_TRY(prog_kernel(sim.prog, "reduce_count", &sim.k_count));
  CLSPH_TRY(prog_kernel(sim.prog, "step_end", &sim.k_step_end));
  CLSPH_TRY(prog_kernel(sim.prog, "reduce_slice_velocity", &sim.k_slice));
  CLSPH_TRY(prog_kernel(sim.prog, "health_sums", &sim.k_health));
  CLSPH_TRY(kern_buffer(dev, 5 * sim_reduce_groups(sim.ps.cap) * sizeof(real), NULL, &sim.d_health,
                        "health partials"));
  sim.u_ref = velocity_scale(scene, &sim.geom);
  CLSPH_TRY(kern_buffer(dev, sim.ps.cap * sizeof(cl_uint), NULL, &sim.d_inv, "inverse index"));
  CLSPH_TRY(kern_buffer(dev, 2 * (sim_reduce_groups(sim.ps.cap) + 1) * sizeof(real), NULL,
                        &sim.d_partial, "reduction partials"));
  CLSPH_TRY(kern_buffer(dev, SIM_DEFERRED * SIM_REDUCE_MAX_GROUPS * sizeof(real), NULL,
                        &sim.d_deferred, "step-end partials"));
  sim.h_deferred = malloc(SIM_DEFERRED * SIM_REDUCE_MAX_GROUPS * sizeof *sim.h_deferred);
  CLSPH_CHECK(sim.h_deferred != NULL, CLSPH_E_NOMEM, "out of memory");
  sim.speed_kind = SIM_KIND_UNSET;
  for (int a = 0; a < 3; ++a) sim.body_force[a] = scene->body_force[a];
  sim.flow.force = scene->body_force[0];
  if (sim.scheme->create != NULL) CLSPH_TRY(sim.scheme->create(&sim, &sim.state));
  CLSPH_TRY(check_memory(&sim));
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
  /* the inverse index with the cells' ordering, from the ids before the reorder */
  CLSPH_TRY(grid_sort_inv(&sim->grid, sim->dev, sim->ps.n, pset_mem(&sim->ps, sim->f_pos),
                          pset_mem(&sim->ps, sim->f_kind), sim->d_flags,
                          pset_mem(&sim->ps, sim->f_id), sim->d_inv));
  CLSPH_TRY(pset_reorder(&sim->ps, &sim->grid, sim->dev));
  ++sim->sorts;
done:
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
  printf("scene digest %08lx (checkpoints record it: a restart must start from the same scene)\n",
         sim->digest);
  printf("spacing dr = %g m, smoothing %s, h = %g m (%g dr), support %g m\n", s->dr,
         smoothing_name(sim->sm.kind), sim->sm.h, sim->sm.h / s->dr, sim->sm.support);
  printf("dimensions: %d\n", s->dim);
  printf("active: walls %s, periodic %s%s%s%s, gravity %s, body force %s, probes %d, profiles %d, "
         "forces %d\n",
         sim->geom.nseg ? "usaw"
         : count[2]     ? "dummy"
                        : "none",
         s->periodic[0] || s->periodic[1] || s->periodic[2] ? "" : "none",
         s->periodic[0] ? "x" : "", s->periodic[1] ? "y" : "", s->periodic[2] ? "z" : "",
         s->gravity[0] || s->gravity[1] || s->gravity[2] ? "on" : "off",
         s->flow.on                                                 ? "flow-rate control"
         : s->body_force[0] || s->body_force[1] || s->body_force[2] ? "on"
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
  printf("device memory: about %.1f MiB with the scheme's buffers and its first step's (the "
         "device: %.0f MiB, of which the run may use %.0f)\n",
         sim->mem_estimate / (1024.0 * 1024.0), (double)sim->dev->global_mem / (1024.0 * 1024.0),
         (double)sim->dev->mem_limit / (1024.0 * 1024.0));
  if (s->dt > 0.0) dt = s->dt;
  if (isfinite(dt))
    printf("time step %.6g s (cfl %g): about %.0f steps to t_end = %g s\n", dt, s->cfl,
           ceil(s->t_end / dt), s->t_end);
  else
    printf("time step: set by the outputs (the scheme has no stability bound); t_end = %g s\n",
           s->t_end);
  printf("outputs: %.0f snapshots (output_every %g s), %.0f checkpoints (checkpoint_every %g s; "
         "0: at the end only)\n",
         s->output_every > 0.0 ? floor(s->t_end / s->output_every + 1e-9) + 1.0 : 1.0,
         s->output_every,
         s->checkpoint_every > 0.0 ? floor(s->t_end / s->checkpoint_every + 1e-9) : 1.0,
         s->checkpoint_every);
done:
  return st;
}

enum clsph_status sim_psolve_options(const struct sim *sim, struct psolve_options *o)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  psolve_defaults(o);
  /* the neighbours within the support: the nonzeros of a row of the operator */
  const double q = sim->sm.support / s->dr;
  o->row_estimate =
      (s->dim == 3 ? 4.0 / 3.0 * 3.14159265358979 * q * q * q : 3.14159265358979 * q * q) + 1.0;
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
  if (sim->k_step_end != NULL) clReleaseKernel(sim->k_step_end);
  if (sim->k_slice != NULL) clReleaseKernel(sim->k_slice);
  if (sim->k_health != NULL) clReleaseKernel(sim->k_health);
  sim->k_probe = sim->k_max_speed = sim->k_count = sim->k_slice = NULL;
  free(sim->probe_cache.v);
  sim->probe_cache.v = NULL;
  sim->k_step_end = NULL;
  sim->k_health = NULL;
  kern_release(&sim->d_health);
  kern_release(&sim->d_inv);
  kern_release(&sim->d_partial);
  kern_release(&sim->d_deferred);
  free(sim->h_deferred);
  sim->h_deferred = NULL;
  kern_release(&sim->d_flags);
  grid_destroy(&sim->grid);
  pset_destroy(&sim->ps);
  if (sim->prog != NULL) clReleaseProgram(sim->prog);
  sim->prog = NULL;
  geometry_free(&sim->geom);
  free(sim->force_rows);
  sim->force_rows = NULL;
  free(sim->samples.names);
  free(sim->samples.rows);
  memset(&sim->samples, 0, sizeof sim->samples);
  sim->nforce_rows = sim->force_rows_cap = 0;
}

void sim_moved_offset(const struct sim *sim, double t, double d[3])
{
  const struct sim_moved *m = &sim->moved;
  const double run = m->group != NULL ? fmax(0.0, fmin(t, m->stop) - m->start) : 0.0;
  for (int a = 0; a < 3; ++a) d[a] = m->speed * run * m->dir[a];
}
