/* wcsph_usaw.c: the weakly-compressible baseline of Leroy et al. 2014 (their WCSPH-USAW): the
 * same unified semi-analytical walls and operators as isph-usaw, with density by continuity
 * (and Ferrari density diffusion), a linear equation of state with a background pressure, and
 * an explicit time step (kernels/wcsph_usaw/). One step at r^n:
 *   γ; wall-vertex pressure; u* = u^n + δt (a_visc + g + f);
 *   u^{n+1} = u* − δt/ρ G+{p}, or with pressure_form = "dynamic" u* − δt/ρ G+{P} − δt (ρ0/ρ) g,
 *   P = p − ρ0 g·r less its value at rest (update.cl);
 *   dρ/dt from u^{n+1} (symplectic Euler for ρ as for r: wcsph_step);
 *   r, ρ, V = m/ρ, p.
 * Options: sound_speed c0 (m/s; default 10 U, U the scene's velocity scale: solvers/sound/sound.c),
 * background_pressure p_bg (Pa, default 0; the paper uses one for the cavity), density_diffusion
 * (factor of the Ferrari term, 1), pressure_form ("total": G+ of p, the paper's; "dynamic": G+ of
 * the pressure less its hydrostatic part, which holds a tank at rest but glues a moving free
 * surface, update.cl), momentum ("fused": u* and the pressure force in one sweep of the
 * neighbours, the default but under the k-ε model; "separate": two, the same bits; update.cl).
 * Time step (48-49) with u_ref = c0: min(0.2 h/c0, 0.125 h²/ν, 0.25 √(h/|a|)).
 * Under the k-ε model (turbulence { model = "k-epsilon" }, solvers/usaw/turbulence.h) the
 * prediction takes μ_E = μ + μ_T and the wall law (eq 22), k and ε advance after it (eqs 18-19),
 * the equation of state's p plays p̃ = p + ⅔ ρ k (eq 12), and the viscous bound takes ν + ν_t. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../scheme.h"
#include "clsph_config.h"
#include "sim.h"
#include "sound.h"
#include "turbulence.h"
#include "walls.h"

struct wcsph {
  struct usaw_walls walls;
  struct usaw_turb turb; /* the k-ε model, when the scene declares it */
  int f_rho, f_drho, f_p, f_gam, f_ggam, f_theta, f_ustar, f_visc, f_vnormal, f_acc_p, f_close;
  cl_kernel k_cont, k_vertex, k_predict, k_velocity, k_advance, k_strain;
  cl_kernel k_momentum, k_finish; /* without the k-ε model: prediction and pressure in one sweep */
  cl_mem d_strain; /* rate of strain at the wall vertices, 3 reals each (wall_force.cl) */
  double c0, p_bg, mass;
  double d_min;     /* smallest wall distance of the viscous wall term, m (usaw/viscous.cl) */
  double p_ref;     /* −ρ0 g·r_top: P = p − ρ0 g·r − p_ref is p_bg in a fluid at rest */
  int dynamic;      /* 1: G+ of P (pressure_form = "dynamic"), 0: G+ of p (the paper's) */
  double diffusion; /* factor of the Ferrari density diffusion (1: as published, 0: off) */
  cl_uint guard;    /* the wall guard (update.cl): wall_guard, by default with gravity or turning */
  int fused;        /* momentum = "fused": u* and the pressure force in one sweep (update.cl) */
};

static const char *const sources[] = {"usaw/gamma.cl",        "usaw/common.cl",
                                      "usaw/motion.cl",       "usaw/wall_force.cl",
                                      "common/kepsilon.cl",   "usaw/turbulence.cl",
                                      "usaw/viscous.cl",      "wcsph_usaw/density.cl",
                                      "wcsph_usaw/update.cl", NULL};
static const char *const options[] = {"sound_speed",
                                      "background_pressure",
                                      "density_diffusion",
                                      "pressure_form",
                                      "momentum",
                                      USAW_WALL_OPTION_NAMES,
                                      NULL};

static enum clsph_status prefix(struct sim *sim, struct wcsph *ws, cl_kernel k, int with_segments,
                                cl_uint *next)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  struct usaw_walls *w = &ws->walls;
  cl_uint n = (cl_uint)ps->n;
  cl_mem pos = pset_mem(ps, sim->f_pos), vol = pset_mem(ps, sim->f_vol);
  cl_mem kind = pset_mem(ps, sim->f_kind), gam = pset_mem(ps, ws->f_gam);
  if (with_segments) {
    CLSPH_TRY(usaw_kernel_prefix(sim, w, gam, k, next));
    goto done;
  }
  CLSPH_TRY(KERN_SET(k, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start), KARG(pos),
                     KARG(vol), KARG(kind), KARG(gam)));
  *next = 7;
done:
  return st;
}

#define ARG(k, i, x) CLSPH_TRY(kern_set_at((k), (i)++, KARG(x)))

/* The segment cache's default (kernels/usaw/gamma.cl): 8 slots, a straight wall's 6 segments in
 * the first row's support and two more. Its three sweeps a step at the positions of γ: the wedge
 * dam break (2 s) took 0.957 of the time in double and 1.001 in float (farm-bench, medians of 3
 * pairs). */
#define WCSPH_SEG_CACHE 8

/* -D switches: the k-ε model's (solvers/usaw/turbulence.h), the segment cache's (walls.h), and
 * no ∇γ_a without the model. */
static enum clsph_status wcsph_define(const struct sim *sim, struct prog_opts *o)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(usaw_turb_define(sim, o));
  CLSPH_TRY(usaw_seg_cache_define(sim->scene, WCSPH_SEG_CACHE, o));
  /* ∇γ_a (usaw/gamma.cl) only for the k-ε model's vertices (usaw/viscous.cl) */
  if (!sim->scene->turb.on) CLSPH_TRY(prog_opts_define_int(o, "USAW_GRAD_GAMMA", 0));
done:
  return st;
}

static enum clsph_status wcsph_create(struct sim *sim, void **state)
{
  enum clsph_status st = CLSPH_OK;
  struct wcsph *ws = calloc(1, sizeof *ws);
  const struct geom *geo = &sim->geom;
  const struct scene *sc = sim->scene;
  real *buf = NULL;
  CLSPH_CHECK(ws != NULL, CLSPH_E_NOMEM, "wcsph-usaw: out of memory");
  CLSPH_CHECK(sim->sm.kind == SMOOTHING_WENDLAND_C2, CLSPH_E_INPUT,
              "%s: wcsph-usaw computes γ analytically for the Wendland C2 kernel only",
              sc->case_path);
  for (size_t i = 0; i < geo->n; ++i)
    CLSPH_CHECK(geo->kind[i] <= KIND_VERTEX, CLSPH_E_INPUT,
                "%s: wcsph-usaw has no inflow or outflow sections", sc->case_path);
  struct sound_scale vs;
  sound_velocity_scale(sc, geo, &vs);
  ws->c0 = 10.0 * vs.u; /* Leroy et al. 2014 sec 3.4: 10 U */
  int c0_given = 0;
  const char *momentum = "auto";
  ws->diffusion = 1.0;
  for (int i = 0; i < sc->noptions; ++i) {
    const struct scene_option *o = &sc->options[i];
    if (strcmp(o->key, "sound_speed") == 0) {
      CLSPH_CHECK(o->is_number && o->number > 0.0, CLSPH_E_INPUT,
                  "%s: sound_speed must be a positive speed (m/s)", sc->case_path);
      ws->c0 = o->number;
      c0_given = 1;
    } else if (strcmp(o->key, "density_diffusion") == 0) {
      CLSPH_CHECK(o->is_number && o->number >= 0.0 && o->number <= 1.0, CLSPH_E_INPUT,
                  "%s: density_diffusion must be a factor from 0 (off) to 1", sc->case_path);
      ws->diffusion = o->number;
    } else if (strcmp(o->key, "pressure_form") == 0) {
      CLSPH_CHECK(
          !o->is_number && (strcmp(o->text, "total") == 0 || strcmp(o->text, "dynamic") == 0),
          CLSPH_E_INPUT, "%s: pressure_form must be \"total\" or \"dynamic\"", sc->case_path);
      ws->dynamic = strcmp(o->text, "dynamic") == 0;
    } else if (strcmp(o->key, "momentum") == 0) {
      /* "fused" (without the k-ε model, the default) or "separate": the same bits (update.cl) */
#define WCSPH_MOMENTUM_VALUES                                                                      \
  "%s: momentum must be \"fused\" (the prediction and the pressure force in one sweep), "          \
  "\"separate\" or \"auto\" (fused but under the k-epsilon model), "
      CLSPH_CHECK(!o->is_number, CLSPH_E_INPUT, WCSPH_MOMENTUM_VALUES "not the number %g",
                  sc->case_path, o->number);
      CLSPH_CHECK(strcmp(o->text, "fused") == 0 || strcmp(o->text, "separate") == 0 ||
                      strcmp(o->text, "auto") == 0,
                  CLSPH_E_INPUT, WCSPH_MOMENTUM_VALUES "not \"%s\"", sc->case_path, o->text);
#undef WCSPH_MOMENTUM_VALUES
      momentum = o->text;
    } else if (strcmp(o->key, "background_pressure") == 0) {
      CLSPH_CHECK(o->is_number && o->number >= 0.0, CLSPH_E_INPUT,
                  "%s: background_pressure must be a pressure >= 0 (Pa)", sc->case_path);
      ws->p_bg = o->number;
    }
  }
  CLSPH_CHECK(ws->c0 > 0.0, CLSPH_E_INPUT,
              "%s: wcsph-usaw needs a sound speed: nothing drives the flow (no gravity, moving "
              "wall, inflow, flow-rate control nor initial velocity): set the scheme option "
              "sound_speed (m/s)",
              sc->case_path);
  if (c0_given)
    log_info("wcsph-usaw: sound speed c0 = %.4g m/s (scheme option sound_speed; the default 10 U "
             "would be %.4g m/s, U = %.4g m/s from %s)",
             ws->c0, 10.0 * vs.u, vs.u, vs.what);
  else
    log_info("wcsph-usaw: sound speed c0 = %.4g m/s = 10 U, U = %.4g m/s from %s", ws->c0, vs.u,
             vs.what);
  CLSPH_CHECK(!sc->turb.on || strcmp(momentum, "fused") != 0, CLSPH_E_INPUT,
              "%s: momentum = \"fused\" has no form under the k-epsilon model (k and epsilon "
              "advance between the prediction and the pressure force): \"separate\" or \"auto\"",
              sc->case_path);
  ws->fused = !sc->turb.on && strcmp(momentum, "separate") != 0;
  ws->mass = sc->rho0 * sc->dr * sc->dr;
  /* the paper's δr (eq 17) by default: δr/2, which isph-usaw takes, lowers the 20² cavity's u
   * error at Re 100 from 0.131 U to 0.094 U, but the lid, pulling harder, drives more particles
   * into the side walls at its corners (741 steps of 5000 with a crossing, deepest 0.26 δr, to
   * 2349 steps, deepest 0.45 δr: a run stops at 0.5 δr). Under the k-ε model δr/2: the wall law
   * (eq 23) needs the first row's own distance from the wall. */
  CLSPH_TRY(usaw_wall_distance_floor(sc, sc->turb.on ? 0.5 : 1.0, &ws->d_min));
  int turning = 0;
  for (int w = 0; w < sc->nwalls; ++w) turning |= scene_wall_turns(&sc->walls[w]);
  CLSPH_TRY(usaw_wall_guard_option(sc, hypot(sc->gravity[0], sc->gravity[1]) > 0.0 || turning,
                                   &ws->guard));
  /* fields: density, pressure, and the USAW helpers */
  struct pset *ps = &sim->ps;
  const size_t rv = 2 * sizeof(real);
  buf = calloc(2 * geo->n + 1, sizeof *buf);
  CLSPH_CHECK(buf != NULL, CLSPH_E_NOMEM, "out of memory");
  /* hydrostatic start: p = ρ0 |g| (z_top − z) + p_bg, ρ = ρ0 + (p − p_bg)/c0², z along −g and
   * z_top half a spacing above the highest fluid particle */
  double gn = hypot(sc->gravity[0], sc->gravity[1]), up[2] = {0.0, 0.0}, ztop = -HUGE_VAL;
  if (gn > 0.0) {
    up[0] = -sc->gravity[0] / gn;
    up[1] = -sc->gravity[1] / gn;
  }
  for (size_t i = 0; i < geo->nfluid; ++i)
    ztop = fmax(ztop, up[0] * geo->x[2 * i] + up[1] * geo->x[2 * i + 1] + 0.5 * sc->dr);
  ws->p_ref = gn > 0.0 && geo->nfluid > 0 ? sc->rho0 * gn * ztop : 0.0;
  for (size_t i = 0; i < geo->n; ++i) {
    double z = up[0] * geo->x[2 * i] + up[1] * geo->x[2 * i + 1];
    double ph = geo->kind[i] == KIND_FLUID && gn > 0.0 ? sc->rho0 * gn * (ztop - z) : 0.0;
    /* fill { density } or fill { pressure } (the pressure without p_bg) instead, through the
     * equation of state p = c0² (ρ − ρ0) + p_bg */
    if (i < geo->nfluid && isfinite(geo->rho0[i]))
      ph = ws->c0 * ws->c0 * (geo->rho0[i] - sc->rho0);
    else if (i < geo->nfluid && isfinite(geo->p0[i]))
      ph = geo->p0[i];
    buf[i] = (real)(sc->rho0 + ph / (ws->c0 * ws->c0));
    buf[geo->n + i] = (real)(ws->p_bg + ph);
  }
  CLSPH_TRY(pset_add(ps, sim->dev, "rho", sizeof(real), buf, &ws->f_rho));
  CLSPH_TRY(pset_add(ps, sim->dev, "p", sizeof(real), buf + geo->n, &ws->f_p));
  CLSPH_TRY(pset_add(ps, sim->dev, "gamma", sizeof(real), NULL, &ws->f_gam));
  for (size_t i = 0; i < geo->n; ++i)
    buf[i] = geo->kind[i] == KIND_VERTEX ? (real)geo->theta[i] : 0;
  CLSPH_TRY(pset_add(ps, sim->dev, "theta", sizeof(real), buf, &ws->f_theta));
  pset_describe(ps, ws->f_theta, PF_REAL, 0, 0);
  /* the vertices' normals, for their pressure (density.cl; turned with turning walls) */
  for (size_t i = 0; i < 2 * geo->n; ++i)
    buf[i] = geo->kind[i / 2] == KIND_VERTEX ? (real)geo->normal[i] : 0;
  CLSPH_TRY(pset_add(ps, sim->dev, "wall_normal", rv, buf, &ws->f_vnormal));
  pset_describe(ps, ws->f_vnormal, PF_REAL, 0, 0);
  const struct {
    const char *name;
    size_t elem;
    int *f;
  } hidden[] = {{"drho", sizeof(real), &ws->f_drho},
                {"grad_gamma", rv, &ws->f_ggam},
                {"ustar", rv, &ws->f_ustar},
                {"visc", rv, &ws->f_visc}};
  for (size_t k = 0; k < sizeof hidden / sizeof *hidden; ++k) {
    CLSPH_TRY(pset_add(ps, sim->dev, hidden[k].name, hidden[k].elem, NULL, hidden[k].f));
    pset_describe(ps, *hidden[k].f, PF_REAL, 0, 0);
    pset_temporary(ps, *hidden[k].f); /* each made in the step after its sort, then read */
  }
  /* the pressure's acceleration of the last step, where the prediction takes its wall term
   * (usaw/viscous.cl): kept across the sorts */
  CLSPH_TRY(pset_add(ps, sim->dev, "acc_p", rv, NULL, &ws->f_acc_p));
  pset_describe(ps, ws->f_acc_p, PF_REAL, 0, 0);
  /* volumes: m/ρ0 for the fluid, none for the wall vertices (as in isph-usaw) */
  for (size_t k = 0; k < geo->n; ++k)
    buf[k] = geo->kind[k] == KIND_VERTEX ? (real)0 : (real)(sc->dr * sc->dr);
  CLSPH_TRY(kern_write(sim->dev, pset_mem(ps, sim->f_vol), geo->n * sizeof(real), buf));
  /* segments */
  CLSPH_TRY(usaw_walls_from_geom(sim->dev, sim->prog, geo, sc, &sim->gspec, &ws->walls));
  CLSPH_TRY(usaw_walls_cache(&ws->walls, sc, WCSPH_SEG_CACHE));
  ws->walls.f_vnormal = ws->f_vnormal;
  CLSPH_TRY(prog_kernel(sim->prog, "wcsph_continuity", &ws->k_cont));
  CLSPH_TRY(prog_kernel(sim->prog, "wcsph_vertex_pressure", &ws->k_vertex));
  CLSPH_TRY(prog_kernel(sim->prog, "usaw_predict", &ws->k_predict));
  CLSPH_TRY(prog_kernel(sim->prog, "wcsph_velocity", &ws->k_velocity));
  CLSPH_TRY(prog_kernel(sim->prog, "wcsph_advance", &ws->k_advance));
  CLSPH_TRY(prog_kernel(sim->prog, "usaw_vertex_strain", &ws->k_strain));
  CLSPH_TRY(kern_buffer(sim->dev, 3 * ps->cap * sizeof(real), NULL, &ws->d_strain, "strain"));
  CLSPH_TRY(usaw_turb_create(sim, &ws->turb));
  if (ws->fused) { /* wcsph_momentum marks the particles that collide (update.cl) */
    CLSPH_TRY(pset_add(ps, sim->dev, "close", sizeof(cl_uint), NULL, &ws->f_close));
    pset_describe(ps, ws->f_close, PF_UINT, 0, 0);
    pset_temporary(ps, ws->f_close);
    CLSPH_TRY(prog_kernel(sim->prog, "wcsph_momentum", &ws->k_momentum));
    CLSPH_TRY(prog_kernel(sim->prog, "wcsph_finish", &ws->k_finish));
  }
  *state = ws;
  ws = NULL;
done:
  free(buf);
  if (ws != NULL) {
    usaw_turb_destroy(&ws->turb);
    usaw_walls_destroy(&ws->walls);
    free(ws);
  }
  return st;
}

/* Without the k-ε model: u* and the pressure force in one sweep (wcsph_momentum), then the
 * collisions, u^{n+1} and the wall guard (wcsph_finish): the bits of usaw_predict, k-ε's place
 * between them empty, and wcsph_velocity (update.cl). */
static enum clsph_status wcsph_momentum(struct sim *sim, struct wcsph *ws, real rdt, real2 accel,
                                        real2 grav, real pref, real rho0_h)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *sc = sim->scene;
  struct pset *ps = &sim->ps;
  cl_uint i;
  const real nu = (real)sc->nu, dr = (real)sc->dr, d_min = (real)ws->d_min;
  cl_mem vel = pset_mem(ps, sim->f_vel), p = pset_mem(ps, ws->f_p);
  cl_mem rho = pset_mem(ps, ws->f_rho), ustar = pset_mem(ps, ws->f_ustar);
  cl_mem acc_p = pset_mem(ps, ws->f_acc_p), close = pset_mem(ps, ws->f_close);
  cl_mem id = pset_mem(ps, sim->f_id);
  CLSPH_TRY(prefix(sim, ws, ws->k_momentum, 1, &i));
  CLSPH_TRY(KERN_SET_AT(ws->k_momentum, i, KARG(vel), KARG(p), KARG(rho), KARG(rdt), KARG(nu),
                        KARG(d_min), KARG(accel), KARG(rho0_h), KARG(grav), KARG(pref),
                        KARG(ws->guard), KARG(dr), KARG(ustar), KARG(acc_p), KARG(close)));
  CLSPH_TRY(kern_launch(sim->dev, ws->k_momentum, ps->n, NULL));
  CLSPH_TRY(prefix(sim, ws, ws->k_finish, 1, &i));
  CLSPH_TRY(KERN_SET_AT(ws->k_finish, i, KARG(ustar), KARG(acc_p), KARG(close), KARG(rdt),
                        KARG(ws->guard), KARG(dr), KARG(id), KARG(vel)));
  CLSPH_TRY(kern_launch(sim->dev, ws->k_finish, ps->n, NULL));
done:
  return st;
}

static enum clsph_status wcsph_step(struct sim *sim, void *state, double dt)
{
  enum clsph_status st = CLSPH_OK;
  struct wcsph *ws = state;
  const struct scene *sc = sim->scene;
  struct pset *ps = &sim->ps;
  cl_uint i;
  const real rdt = (real)dt, nu = (real)sc->nu, dr = (real)sc->dr, c0 = (real)ws->c0;
  const real mass = (real)ws->mass, rho0 = (real)sc->rho0, pbg = (real)ws->p_bg;
  const real2 accel =
      dev_real2(sc->gravity[0] + sim->body_force[0], sc->gravity[1] + sim->body_force[1]);
  const real2 grav = dev_real2(sc->gravity[0], sc->gravity[1]);
  cl_mem pos = pset_mem(ps, sim->f_pos), vel = pset_mem(ps, sim->f_vel);
  cl_mem kind = pset_mem(ps, sim->f_kind), vol = pset_mem(ps, sim->f_vol);
  cl_mem rho = pset_mem(ps, ws->f_rho), drho = pset_mem(ps, ws->f_drho), p = pset_mem(ps, ws->f_p);
  cl_mem ustar = pset_mem(ps, ws->f_ustar), visc = pset_mem(ps, ws->f_visc);
  cl_mem acc_p = pset_mem(ps, ws->f_acc_p);
  cl_uint n = (cl_uint)ps->n;
  if (ws->walls.turning && ws->walls.t_now != sim->time) { /* a restart: the walls at t^n */
    CLSPH_TRY(usaw_walls_turn(&ws->walls, sim, sim->time));
    CLSPH_TRY(sim_sort(sim));
    pos = pset_mem(ps, sim->f_pos);
    vel = pset_mem(ps, sim->f_vel);
    kind = pset_mem(ps, sim->f_kind);
    vol = pset_mem(ps, sim->f_vol);
    rho = pset_mem(ps, ws->f_rho);
    drho = pset_mem(ps, ws->f_drho);
    p = pset_mem(ps, ws->f_p);
    ustar = pset_mem(ps, ws->f_ustar);
    visc = pset_mem(ps, ws->f_visc);
    acc_p = pset_mem(ps, ws->f_acc_p);
  }
  CLSPH_TRY(usaw_walls_gamma(&ws->walls, sim->dev, ps->n, pos, pset_mem(ps, ws->f_theta),
                             pset_mem(ps, ws->f_gam), pset_mem(ps, ws->f_ggam), sim->d_flags));
  /* wall-vertex pressure, density rate, prediction, pressure force, advance */
  CLSPH_TRY(prefix(sim, ws, ws->k_vertex, 0, &i));
  ARG(ws->k_vertex, i, rho);
  ARG(ws->k_vertex, i, grav);
  cl_mem vnormal = pset_mem(ps, ws->f_vnormal);
  ARG(ws->k_vertex, i, vnormal);
  ARG(ws->k_vertex, i, p);
  CLSPH_TRY(kern_launch(sim->dev, ws->k_vertex, ps->n, NULL));
  const real d_min = (real)ws->d_min;
  const real pref = ws->dynamic ? (real)ws->p_ref : 0, rho0_h = ws->dynamic ? rho0 : 0;
  cl_mem id = pset_mem(ps, sim->f_id);
  if (ws->fused) {
    CLSPH_TRY(wcsph_momentum(sim, ws, rdt, accel, grav, pref, rho0_h));
    goto continuity;
  }
  CLSPH_TRY(prefix(sim, ws, ws->k_predict, 1, &i));
  ARG(ws->k_predict, i, vel);
  ARG(ws->k_predict, i, rdt);
  ARG(ws->k_predict, i, nu);
  ARG(ws->k_predict, i, d_min);
  ARG(ws->k_predict, i, accel);
  ARG(ws->k_predict, i, ustar);
  ARG(ws->k_predict, i, visc);
  ARG(ws->k_predict, i, acc_p);
  CLSPH_TRY(usaw_turb_predict_args(sim, &ws->turb, pset_mem(ps, ws->f_ggam), ws->k_predict, &i));
  CLSPH_TRY(kern_launch(sim->dev, ws->k_predict, ps->n, NULL));
  /* k and ε (the k-ε model) */
  CLSPH_TRY(usaw_turb_advance(sim, &ws->turb, &ws->walls, pset_mem(ps, ws->f_gam), dt, ws->d_min));
  CLSPH_TRY(prefix(sim, ws, ws->k_velocity, 1, &i));
  ARG(ws->k_velocity, i, ustar);
  ARG(ws->k_velocity, i, p);
  ARG(ws->k_velocity, i, rho);
  ARG(ws->k_velocity, i, rdt);
  ARG(ws->k_velocity, i, rho0_h);
  ARG(ws->k_velocity, i, grav);
  ARG(ws->k_velocity, i, pref);
  /* the wall guard (update.cl) with gravity, and where walls turn: in a square box turning with
   * the fluid in it (tests/case/turning_box.lua, ω = 1 rad/s, no gravity) the particles in the
   * corners, where the centripetal pressure peaks, crept out through the turning walls by
   * 3e-4 δr a step from t = 0.82 s and the run stopped at 0.97 s, 0.5 δr behind them */
  ARG(ws->k_velocity, i, ws->guard);
  ARG(ws->k_velocity, i, dr);
  ARG(ws->k_velocity, i, id);
  ARG(ws->k_velocity, i, vel);
  ARG(ws->k_velocity, i, acc_p);
  CLSPH_TRY(kern_launch(sim->dev, ws->k_velocity, ps->n, NULL));
  /* dρ/dt with u^{n+1} (at r^n), after the velocity: ρ^{n+1} = ρ^n + δt D{u^{n+1}} as
   * r^{n+1} = r^n + δt u^{n+1}, symplectic Euler for the pair (ρ, u) as for (r, u). The paper gives
   * the continuity equation (eq 9, D of eq 13) and the time step (eqs 48-49) but not the order of
   * the updates. With dρ/dt from u^n, as before, (ρ, u) went by forward Euler, under which an
   * undamped oscillation of frequency ω grows by (ω δt)²/2 a step at any δt. The density
   * diffusion damps sound waves in the bulk but not the breathing of a thin layer, uniform across
   * it (p > 0 pushes its free surface out, p < 0 pulls it in, through the kernel sum the air
   * truncates). Under the front of the dam break (cases/dam_break.lua, n = 20, c0 = 34 m/s) the
   * tongue on the floor beyond x = 1 m, 1 to 3 particles thick (γ 0.59 to 0.86, 5 to 25 fluid
   * neighbours, Shepard sum of the fluid 0.35 to 0.97), breathed with a period of 5.8 ms
   * (ω δt = 0.18) and grew 1.5 times a period from t = 0.29 s: its density swung from 0.80 ρ0 to
   * 1.26 ρ0 (p from −2.3e5 to 3.1e5 Pa, ρ0 g H = 2.9e3 Pa), its particles took 1e3 to 1e4 m/s²,
   * were thrown along the floor at up to 2.8 × 2 √(gH) and the front stalled near x = 1.35 m.
   * Halving δt hid it (growth ∝ δt over a given time). Now the density stays within 1% of ρ0
   * (p ≥ −1.1e4 Pa, at the front's tip), the floor's largest speed is that of the front's tip,
   * 0.92 × 2 √(gH) (0.96 at n = 40, against 1.88 before), and the front runs on (its mean speed
   * 0.66 of Ritter's at 0.42 s, 0.58 before). */
continuity:
  CLSPH_TRY(prefix(sim, ws, ws->k_cont, 1, &i));
  ARG(ws->k_cont, i, vel);
  ARG(ws->k_cont, i, rho);
  const real cd = (real)(ws->diffusion * ws->c0), r0c2 = (real)(sc->rho0 / (ws->c0 * ws->c0));
  ARG(ws->k_cont, i, cd);
  ARG(ws->k_cont, i, grav);
  ARG(ws->k_cont, i, r0c2);
  ARG(ws->k_cont, i, drho);
  CLSPH_TRY(kern_launch(sim->dev, ws->k_cont, ps->n, NULL));
  real4 lo, hi; /* the domain check (scheme_ops.checks_domain) */
  real margin;
  cl_uint open;
  sim_domain_box(sim, &lo, &hi, &margin, &open);
  CLSPH_TRY(KERN_SET(ws->k_advance, KARG(n), KARG(sim->grid.geom), KARG(rdt), KARG(mass),
                     KARG(rho0), KARG(c0), KARG(pbg), KARG(lo), KARG(hi), KARG(margin), KARG(open),
                     KARG(kind), KARG(pos), KARG(vel), KARG(rho), KARG(drho), KARG(vol), KARG(p),
                     KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, ws->k_advance, ps->n, NULL));
  /* the turning walls where they stand at t^{n+1}, for the next step's sort */
  CLSPH_TRY(usaw_walls_turn(&ws->walls, sim, sim->time + dt));
done:
  return st;
}

static enum clsph_status wcsph_max_dt(struct sim *sim, void *state, double *dt)
{
  struct wcsph *ws = state;
  const struct scene *s = sim->scene;
  const double h = sim->sm.h;
  double a = hypot(s->gravity[0] + sim->body_force[0], s->gravity[1] + sim->body_force[1]);
  double d = 0.2 * h / ws->c0; /* CFL with u_ref = c0 (49) */
  const double nu = s->nu + (ws->turb.on ? ws->turb.ke.nut_max : 0.0); /* ν + ν_t */
  if (nu > 0.0) d = fmin(d, 0.125 * h * h / nu);                       /* viscous (49) */
  if (a > 0.0) d = fmin(d, 0.25 * sqrt(h / a));                        /* force (49) */
  *dt = d;
  return CLSPH_OK;
}

/* Force of the fluid on the walls of a group, pressure and viscous parts (eqs 69-70, walls.c). */
static enum clsph_status wcsph_wall_force(struct sim *sim, void *state, const char *group,
                                          struct wall_force *f)
{
  enum clsph_status st = CLSPH_OK;
  struct wcsph *ws = state;
  cl_uint i;
  cl_mem vel = pset_mem(&sim->ps, sim->f_vel);
  /* the turning walls where they stand now (a restart's first output), γ at the current
   * positions (none yet before the first step) */
  if (ws->walls.turning && ws->walls.t_now != sim->time) {
    CLSPH_TRY(usaw_walls_turn(&ws->walls, sim, sim->time));
    CLSPH_TRY(sim_sort(sim));
    vel = pset_mem(&sim->ps, sim->f_vel);
  }
  CLSPH_TRY(usaw_walls_gamma(&ws->walls, sim->dev, sim->ps.n, pset_mem(&sim->ps, sim->f_pos),
                             pset_mem(&sim->ps, ws->f_theta), pset_mem(&sim->ps, ws->f_gam),
                             pset_mem(&sim->ps, ws->f_ggam), ws->walls.d_flags));
  CLSPH_TRY(prefix(sim, ws, ws->k_strain, 1, &i));
  ARG(ws->k_strain, i, vel);
  ARG(ws->k_strain, i, ws->d_strain);
  CLSPH_TRY(kern_launch(sim->dev, ws->k_strain, sim->ps.n, NULL));
  const double mu = ws->turb.on ? 0.0 : sim->scene->rho0 * sim->scene->nu;
  CLSPH_TRY(usaw_wall_force(sim->dev, &sim->geom, sim->scene, sim->ps.n,
                            pset_mem(&sim->ps, ws->f_p), ws->d_strain, sim->d_inv, mu, sim->time,
                            group, f));
  if (ws->turb.on) /* the wall law's shear (eq 22) */
    CLSPH_TRY(usaw_turb_wall_force(sim, &ws->turb, &ws->walls, pset_mem(&sim->ps, ws->f_gam),
                                   ws->d_min, group, f->viscous));
done:
  return st;
}

static void wcsph_destroy(void *state)
{
  struct wcsph *ws = state;
  if (ws == NULL) return;
  cl_kernel *ks[] = {&ws->k_cont,    &ws->k_vertex, &ws->k_predict,  &ws->k_velocity,
                     &ws->k_advance, &ws->k_strain, &ws->k_momentum, &ws->k_finish};
  for (size_t k = 0; k < sizeof ks / sizeof *ks; ++k)
    if (*ks[k] != NULL) clReleaseKernel(*ks[k]);
  kern_release(&ws->d_strain);
  usaw_turb_destroy(&ws->turb);
  usaw_walls_destroy(&ws->walls);
  free(ws);
}

const struct scheme_ops scheme_wcsph_usaw = {
    .name = "wcsph-usaw",
    .summary =
        "weakly-compressible SPH, unified semi-analytical walls (Leroy et al. 2014 baseline)",
    .sources = sources,
    .wall_model = "usaw",
    .smoothing = "wendland",
    .h_over_dr = 2.0,
    .fill_fields = SCHEME_FILL_PRESSURE | SCHEME_FILL_DENSITY,
    .checks_domain = 1, /* wcsph_advance (update.cl) */
    .turbulence = usaw_turbulence_models,
    .options = options,
    .define = wcsph_define,
    .create = wcsph_create,
    .step = wcsph_step,
    .max_dt = wcsph_max_dt,
    .wall_force = wcsph_wall_force,
    .destroy = wcsph_destroy,
};
