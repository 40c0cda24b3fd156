/* isph_usaw.c: incompressible SPH with unified semi-analytical walls (Leroy et al. 2014),
 * laminar. One time step (sec 3.2, eqs 30-38):
 *   1. r* = r^n + δt/2 u^n                                      (30, move.cl)
 *   2. γ_a analytically (eqs 55-62) for the particles near a wall (usaw/gamma.cl)
 *   3. u* = u^n + δt [(1/ρ) L{µ, u} + g + f]                    (31 with 15, usaw/viscous.cl)
 *   4. free surface: D{r} ≤ 1.5 unless about to hit a wall (eq 39, free_surface.cl)
 *   5. Morris Σ 2V F (P_a − P_b) = γ (ρ/δt) D{u*} + 2 Σ_s (∇P)_s·∇γ_as, P = p̃ + ρgz   (44, ppe.cl)
 *      solved on the device by BiCGStab (solvers/pressure), P = ρgz on free-surface rows;
 *      a flow with no free surface is singular: the diagonal is reinforced (sec 3.3);
 *      with gravity, p̃ ≥ 0 within h q_max/2 of the free surface (no tension, ppe.cl)
 *   6. ũ = u* − (δt/ρ) G+{p̃}                                     (32, project.cl)
 *      (default: ũ = u* − δt g − (δt/ρ) G−{P}, corrected to first order near the free surface)
 *   7. r̃ = r* + δt/2 ũ                                           (34)
 *   8. shifting δr = −C h² G{1} away from the free surface, u += G−{ũ}·δr   (35-38, shift.cl)
 * Time step (48-49): min(0.1 h/u_ref, 0.125 h²/ν, 0.25 √(h/|a|)) (C_CFL halved, see max_dt).
 * Under the k-ε model (turbulence { model = "k-epsilon" }, solvers/usaw/turbulence.h) step 3 takes
 * μ_E = μ + μ_T and the wall law (eq 22), k and ε advance after it at r* with u^n (eqs 18-19),
 * the unknown is P = p̃ + ρgz with p̃ = p + ⅔ ρ k (eq 12), and the viscous bound takes ν + ν_t.
 * The shift (step 8) moves k and ε with the particles without the first-order correction that it
 * gives the velocity. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../scheme.h"
#include "clsph_config.h"
#include "poisson_op.h"
#include "sim.h"
#include "turbulence.h"
#include "walls.h"

struct isph {
  struct usaw_walls walls;
  struct usaw_turb turb; /* the k-ε model, when the scene declares it */
  struct poisson_op po;
  struct psolve ps;
  struct psolve_options popt;
  int f_p, f_P, f_ustar, f_visc, f_gam, f_ggam, f_free, f_theta, f_shift, f_vnew, f_rhs, f_divr,
      f_acc, f_normal, f_acc_p, f_P_last;
  cl_kernel k_half, k_predict, k_free, k_rhs, k_pressure, k_no_tension, k_project, k_shift, k_apply,
      k_strain;
  cl_mem d_strain;  /* rate of strain at the wall vertices, 3 reals each (wall_force.cl) */
  cl_mem d_guess;   /* the pressure solve's initial guess, kept for a second try (solve) */
  cl_mem d_count;   /* the free-surface rows of the step (free_surface.cl; zeroed by move.cl) */
  long resolves;    /* solves tried again with a reinforced diagonal */
  double c_shift;   /* shifting coefficient (0: off) */
  double fs_offset; /* distance of the free surface beyond its particles, in dr */
  double relax;     /* density_relaxation α (0: off, the paper's; ppe.cl) */
  cl_uint guard;    /* the wall guard (project.cl, shift.cl): wall_guard, by default with gravity */
  double u_wall;    /* largest wall speed, m/s */
  double d_min;     /* smallest wall distance of the viscous wall term, m (usaw/viscous.cl) */
  int guess_linear; /* pressure_guess = "linear": the solve starts from P extrapolated in time */
  /* carried from step to step, and over a restart (isph_persist): the largest particle
   * acceleration of the last step, m/s² (the next step's length), and whether the last step had a
   * free surface (1, 0; −1: not known yet), the guess for this one's pressure equation */
  double carry[2];
  cl_uint nfree; /* the free-surface rows' count (queued read) */
};
#define ISPH_ACC  0
#define ISPH_FREE 1

static const char *const sources[] = {POISSON_SOURCES,
                                      "usaw/gamma.cl",
                                      "usaw/common.cl",
                                      "usaw/motion.cl",
                                      "usaw/wall_force.cl",
                                      "isph_usaw/move.cl",
                                      "common/kepsilon.cl",
                                      "usaw/turbulence.cl",
                                      "usaw/viscous.cl",
                                      "isph_usaw/ppe.cl",
                                      "isph_usaw/free_surface.cl",
                                      "isph_usaw/project.cl",
                                      "isph_usaw/shift.cl",
                                      NULL};
static const char *const options[] = {"shifting",
                                      "pressure_gradient",
                                      "free_surface_offset",
                                      "gradient_correction",
                                      "shift_velocity",
                                      "density_relaxation",
                                      "pressure_guess",
                                      USAW_WALL_OPTION_NAMES,
                                      PSOLVE_OPTION_NAMES,
                                      NULL};

/* The segment cache's default (kernels/usaw/gamma.cl): none. γ is evaluated twice a step, and each
 * filling serves two sweeps or one: the wedge dam break to 0.6 s took 1.02 of the time with 8
 * slots (farm-bench, medians of 3 pairs). */
#define ISPH_SEG_CACHE 0

/* -D switches: the pressure-gradient form of the projection. */
static enum clsph_status isph_define(const struct sim *sim, struct prog_opts *o)
{
  enum clsph_status st = CLSPH_OK;
  /* Default: the symmetric gradient of P (eq 8). The antisymmetric form of eq 32 conserves
   * momentum but carries 2 p̃_a (Σ_b V_b ∇w_ab − ∇γ_a)/γ_a, the lattice's quadrature error of
   * ∇γ times twice the pressure: near a wall under 1 m of water that is O(g), and the
   * hydrostatic tank blows up within 0.2 s at δr = 0.05 m. The symmetric form of P keeps it at
   * rest (largest speed 5e-4 m/s after 5 s). */
  int sym = 1, corr = 1;
  /* The first-order velocity correction of the shift (eq 38): on in confined flows, off by
   * default where gravity makes a free surface. There, in the wedge case at δr = 0.02 m, a
   * particle of the film left on the right wall, overrun by the returning jet, was shifted
   * towards the wall by the compressed fluid behind it while G−{u}·δr, its wall term large at
   * 0.5 δr from the wall, doubled its velocity away from the wall every step or two (0.8 to
   * 13.6 m/s within 0.008 s) until it was thrown out of the pool; without the correction the run
   * reaches 2 s. */
  int vcorr = hypot(sim->scene->gravity[0], sim->scene->gravity[1]) == 0.0;
  static const char *const corr_names[] = {"none", "free_surface", "everywhere"};
  for (int i = 0; i < sim->scene->noptions; ++i) {
    const struct scene_option *op = &sim->scene->options[i];
    if (strcmp(op->key, "shift_velocity") == 0) {
      CLSPH_CHECK(!op->is_number && (!strcmp(op->text, "on") || !strcmp(op->text, "off")),
                  CLSPH_E_INPUT,
                  "%s: shift_velocity must be \"on\" (the velocity follows the shift to first "
                  "order, eq 38) or \"off\"",
                  sim->scene->case_path);
      vcorr = strcmp(op->text, "on") == 0;
      continue;
    }
    if (strcmp(op->key, "gradient_correction") == 0) {
      corr = -1;
      for (int k = 0; k < 3 && !op->is_number; ++k)
        if (strcmp(op->text, corr_names[k]) == 0) corr = k;
      CLSPH_CHECK(corr >= 0, CLSPH_E_INPUT,
                  "%s: gradient_correction must be \"free_surface\" (the default: where air "
                  "truncates the kernel), \"everywhere\" or \"none\"",
                  sim->scene->case_path);
      continue;
    }
    if (strcmp(op->key, "pressure_gradient") != 0) continue;
    CLSPH_CHECK(!op->is_number &&
                    (!strcmp(op->text, "antisymmetric") || !strcmp(op->text, "symmetric")),
                CLSPH_E_INPUT,
                "%s: pressure_gradient must be \"antisymmetric\" (eq 5) or \"symmetric\" (eq 8)",
                sim->scene->case_path);
    sym = strcmp(op->text, "symmetric") == 0;
  }
  CLSPH_TRY(prog_opts_define_int(o, "ISPH_GRAD_SYM", sym));
  /* the first-order correction of G−{P} where air truncates the kernel (project.cl) */
  CLSPH_TRY(prog_opts_define_int(o, "ISPH_GRAD_CORR", corr));
  CLSPH_TRY(prog_opts_define_int(o, "ISPH_SHIFT_VCORR", vcorr));
  CLSPH_TRY(usaw_turb_define(sim, o));
  CLSPH_TRY(usaw_seg_cache_define(sim->scene, ISPH_SEG_CACHE, o));
done:
  return st;
}

/* The particle and segment arguments every stage starts with; returns the next index. */
static enum clsph_status prefix(struct sim *sim, struct isph *is, cl_kernel k, cl_uint *next)
{
  return usaw_kernel_prefix(sim, &is->walls, pset_mem(&sim->ps, is->f_gam), k, next);
}

static enum clsph_status arg(cl_kernel k, cl_uint *i, size_t size, const void *v)
{
  enum clsph_status st = CLSPH_OK;
  struct karg a = {size, v};
  CLSPH_TRY(kern_set_at(k, (*i)++, a));
done:
  return st;
}

static enum clsph_status isph_create(struct sim *sim, void **state)
{
  enum clsph_status st = CLSPH_OK;
  struct isph *is = calloc(1, sizeof *is);
  const struct geom *geo = &sim->geom;
  real *theta = NULL;
  CLSPH_CHECK(is != NULL, CLSPH_E_NOMEM, "isph-usaw: out of memory");
  is->carry[ISPH_FREE] = -1.0; /* the first step counts the free surface before its solve */
  CLSPH_CHECK(sim->sm.kind == SMOOTHING_WENDLAND_C2, CLSPH_E_INPUT,
              "%s: isph-usaw computes γ analytically for the Wendland C2 kernel only",
              sim->scene->case_path);
  is->c_shift = 0.7; /* Leroy et al. 2014 sec 3.2, for the Wendland kernel */
  /* The paper imposes p̃ = 0 on the free-surface particles. A particle stands for the cell of
   * side δr around it, so the fluid ends δr/2 beyond the last particles; we impose p̃ = 0 there
   * (along the outward normal, free_surface.cl), the reading that reproduces the hydrostatic
   * pressure: within 0.03% of ρg(H − z) (tank, δr = 0.02 m, 5 s) against 8.9% at 3δr with p̃ = 0
   * on the particles. free_surface_offset = 0 gives that literal reading. */
  is->fs_offset = 0.5;
  /* The pressure solve starts from the last two steps' P extrapolated linearly in time
   * (in isph_free_surface's launch, free_surface.cl) rather than from the last step's: BiCGStab
   * stops at solver_rtol ||b||, so a closer start saves iterations. 40² cavity, Re 100, to t = 5
   * s: 7.02 → 6.49 iterations a step; 120², Re 1000, to 1.5 s: 10.57 → 10.37; the wedge dam break
   * to 0.5 s 10.33 → 10.12. */
  is->guess_linear = 1;
  for (int i = 0; i < sim->scene->noptions; ++i) {
    const struct scene_option *o = &sim->scene->options[i];
    if (strcmp(o->key, "shifting") == 0) {
      CLSPH_CHECK(o->is_number && o->number >= 0.0 && o->number <= 2.0, CLSPH_E_INPUT,
                  "%s: shifting must be a coefficient from 0 (off) to 2", sim->scene->case_path);
      is->c_shift = o->number;
    }
    if (strcmp(o->key, "density_relaxation") == 0) {
      CLSPH_CHECK(o->is_number, CLSPH_E_INPUT,
                  "%s: density_relaxation must be a number (a coefficient from 0, off, to 1), "
                  "not \"%s\"",
                  sim->scene->case_path, o->text);
      CLSPH_CHECK(o->number >= 0.0 && o->number <= 1.0, CLSPH_E_INPUT,
                  "%s: density_relaxation must be a coefficient from 0 (off, the paper's "
                  "divergence-free projection) to 1, not %g",
                  sim->scene->case_path, o->number);
      is->relax = o->number;
    }
    if (strcmp(o->key, "pressure_guess") == 0) {
      CLSPH_CHECK(!o->is_number && (!strcmp(o->text, "linear") || !strcmp(o->text, "last")),
                  CLSPH_E_INPUT,
                  "%s: pressure_guess must be \"linear\" (the pressure solve starts from the "
                  "last two steps' pressures extrapolated in time) or \"last\" (from the last "
                  "step's)",
                  sim->scene->case_path);
      is->guess_linear = strcmp(o->text, "linear") == 0;
    }
    if (strcmp(o->key, "free_surface_offset") == 0) {
      CLSPH_CHECK(o->is_number && o->number >= 0.0 && o->number <= 1.0, CLSPH_E_INPUT,
                  "%s: free_surface_offset must be 0 to 1 (spacings)", sim->scene->case_path);
      is->fs_offset = o->number;
    }
  }
  CLSPH_TRY(sim_psolve_options(sim, &is->popt));
  CLSPH_TRY(usaw_wall_guard_option(
      sim->scene, hypot(sim->scene->gravity[0], sim->scene->gravity[1]) > 0.0, &is->guard));
  /* the viscous wall term at the first row's own distance, δr/2, not the paper's δr (eq 17):
   * kernels/usaw/viscous.cl */
  CLSPH_TRY(usaw_wall_distance_floor(sim->scene, 0.5, &is->d_min));
  /* vertex angles the analytic γ handles: a fluid sector of 5° to 355° */
  theta = calloc(geo->n, sizeof *theta);
  CLSPH_CHECK(theta != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t i = 0; i < geo->n; ++i) {
    if (geo->kind[i] != KIND_VERTEX) continue;
    double t = geo->theta[i], deg = t * 180.0 / 3.14159265358979323846;
    CLSPH_CHECK(
        deg >= 5.0 && deg <= 355.0, CLSPH_E_INPUT,
        "%s: the wall vertex at (%g, %g) has a fluid angle of %.1f°, outside the 5° to 355° "
        "the analytic γ handles",
        sim->scene->case_path, geo->x[2 * i], geo->x[2 * i + 1], deg);
    theta[i] = (real)t;
    is->u_wall = fmax(is->u_wall, hypot(geo->v[2 * i], geo->v[2 * i + 1]));
  }
  for (size_t i = 0; i < geo->n; ++i)
    CLSPH_CHECK(geo->kind[i] <= KIND_VERTEX, CLSPH_E_INPUT,
                "%s: isph-usaw has no inflow or outflow sections", sim->scene->case_path);
  /* fields */
  struct pset *ps = &sim->ps;
  const size_t rv = 2 * sizeof(real);
  CLSPH_TRY(pset_add(ps, sim->dev, "p", sizeof(real), NULL, &is->f_p));
  CLSPH_TRY(pset_add(ps, sim->dev, "gamma", sizeof(real), NULL, &is->f_gam));
  CLSPH_TRY(pset_add(ps, sim->dev, "free_surface", sizeof(cl_uint), NULL, &is->f_free));
  CLSPH_TRY(pset_add(ps, sim->dev, "div_r", sizeof(real), NULL, &is->f_divr));
  pset_describe(ps, is->f_free, PF_UINT, 1, 1);
  const struct {
    const char *name;
    size_t elem;
    int *f;
  } hidden[] = {{"P", sizeof(real), &is->f_P},
                {"ustar", rv, &is->f_ustar},
                {"visc", rv, &is->f_visc},
                {"grad_gamma", rv, &is->f_ggam},
                {"shift", rv, &is->f_shift},
                {"vel_new", rv, &is->f_vnew},
                {"acc", rv, &is->f_acc},
                {"rhs", sizeof(real), &is->f_rhs},
                {"normal", rv, &is->f_normal},
                {"acc_p", rv, &is->f_acc_p},
                {"P_last", sizeof(real), &is->f_P_last}};
  for (size_t k = 0; k < sizeof hidden / sizeof *hidden; ++k) {
    CLSPH_TRY(pset_add(ps, sim->dev, hidden[k].name, hidden[k].elem, NULL, hidden[k].f));
    pset_describe(ps, *hidden[k].f, PF_REAL, 0, 0);
  }
  /* made again after each sort before they are read, so the sorts leave them (pset_temporary):
   * u* and the viscous term (prediction, read by the free surface, the right-hand side and the
   * projection), ∇γ (gamma_now after each sort), the shift and its velocity, the free surface's
   * normal and the right-hand side. On the 40² cavity the reordering then takes 2 launches a
   * sort instead of 3, the same bits. */
  const int temps[] = {is->f_ustar, is->f_visc,   is->f_ggam, is->f_shift,
                       is->f_vnew,  is->f_normal, is->f_rhs};
  for (size_t k = 0; k < sizeof temps / sizeof *temps; ++k) pset_temporary(ps, temps[k]);
  CLSPH_TRY(pset_add(ps, sim->dev, "theta", sizeof(real), theta, &is->f_theta));
  if (geo->has_p0) { /* fill { pressure }: p, and P = p − ρ g·x (eq 42), the solver's guess */
    real *pp = calloc(2 * geo->n + 1, sizeof *pp);
    CLSPH_CHECK(pp != NULL, CLSPH_E_NOMEM, "out of memory");
    for (size_t i = 0; i < geo->nfluid; ++i) {
      if (!isfinite(geo->p0[i])) continue;
      pp[i] = (real)geo->p0[i];
      pp[geo->n + i] =
          (real)(geo->p0[i] - sim->scene->rho0 * (sim->scene->gravity[0] * geo->x[2 * i] +
                                                  sim->scene->gravity[1] * geo->x[2 * i + 1]));
    }
    enum clsph_status ws = kern_write(sim->dev, pset_mem(ps, is->f_p), geo->n * sizeof *pp, pp);
    if (ws == CLSPH_OK)
      ws = kern_write(sim->dev, pset_mem(ps, is->f_P), geo->n * sizeof *pp, pp + geo->n);
    free(pp);
    CLSPH_TRY(ws);
  }
  /* Volumes: the fluid lattice (first row δr/2 from the wall) tiles the fluid domain, so the
   * wall vertices carry no volume of their own in the sums over b ∈ P (they would count the
   * strip along the wall twice); their values enter through the segments (eq 5-10). */
  for (size_t k = 0; k < geo->n; ++k)
    theta[k] = geo->kind[k] == KIND_VERTEX ? (real)0 : (real)(sim->scene->dr * sim->scene->dr);
  CLSPH_TRY(kern_write(sim->dev, pset_mem(ps, sim->f_vol), geo->n * sizeof(real), theta));
  pset_describe(ps, is->f_theta, PF_REAL, 0, 0);
  /* segments, kernels, solver */
  CLSPH_TRY(usaw_walls_from_geom(sim->dev, sim->prog, geo, sim->scene, &sim->gspec, &is->walls));
  CLSPH_TRY(usaw_walls_cache(&is->walls, sim->scene, ISPH_SEG_CACHE));
  struct {
    cl_kernel *k;
    const char *name;
  } ks[] = {{&is->k_half, "isph_half_move"},    {&is->k_predict, "usaw_predict"},
            {&is->k_free, "isph_free_surface"}, {&is->k_rhs, "isph_ppe_rhs"},
            {&is->k_pressure, "isph_pressure"}, {&is->k_no_tension, "isph_no_tension"},
            {&is->k_project, "isph_project"},   {&is->k_shift, "isph_shift"},
            {&is->k_apply, "isph_apply_shift"}, {&is->k_strain, "usaw_vertex_strain"}};
  for (size_t k = 0; k < sizeof ks / sizeof *ks; ++k)
    CLSPH_TRY(prog_kernel(sim->prog, ks[k].name, ks[k].k));
  CLSPH_TRY(kern_buffer(sim->dev, 3 * ps->cap * sizeof(real), NULL, &is->d_strain, "strain"));
  CLSPH_TRY(kern_buffer(sim->dev, ps->cap * sizeof(real), NULL, &is->d_guess, "pressure guess"));
  CLSPH_TRY(kern_buffer(sim->dev, sizeof(cl_uint), NULL, &is->d_count, "free-surface count"));
  CLSPH_TRY(usaw_turb_create(sim, &is->turb));
  CLSPH_TRY(poisson_op_create(sim->dev, sim->prog, &is->po));
  CLSPH_TRY(psolve_create(sim->dev, sim->prog, ps->cap, &is->popt, &is->ps));
  *state = is;
  is = NULL;
done:
  free(theta);
  if (is != NULL) {
    usaw_turb_destroy(&is->turb);
    usaw_walls_destroy(&is->walls);
    free(is);
  }
  return st;
}

static enum clsph_status half_move(struct sim *sim, struct isph *is, double dt)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint n = (cl_uint)sim->ps.n;
  real hdt = (real)(0.5 * dt);
  cl_mem pos = pset_mem(&sim->ps, sim->f_pos), vel = pset_mem(&sim->ps, sim->f_vel);
  cl_mem kind = pset_mem(&sim->ps, sim->f_kind);
  CLSPH_TRY(KERN_SET(is->k_half, KARG(n), KARG(hdt), KARG(sim->grid.geom), KARG(pos), KARG(vel),
                     KARG(kind), KARG(sim->d_flags), KARG(is->d_count)));
  CLSPH_TRY(kern_launch(sim->dev, is->k_half, sim->ps.n, NULL));
done:
  return st;
}

static enum clsph_status gamma_now(struct sim *sim, struct isph *is)
{
  return usaw_walls_gamma(&is->walls, sim->dev, sim->ps.n, pset_mem(&sim->ps, sim->f_pos),
                          pset_mem(&sim->ps, is->f_theta), pset_mem(&sim->ps, is->f_gam),
                          pset_mem(&sim->ps, is->f_ggam), sim->d_flags);
}

/* The pressure solve, and a second try when it fails. Fluid that touches a wall and nothing else
 * (a few particles flung onto a turning arm above the water, cases/water_wheel.lua) is about to
 * hit the wall (free_surface.cl), so it has no Dirichlet row: its block is a pure Neumann problem,
 * singular and, with the arm closing on it, inconsistent. BiCGStab then diverged (a residual of
 * 1e118 after 639 iterations at t = 3.31 s, δr = 0.02 m) and the run stopped. The second try
 * starts again from the same guess with the reinforced diagonal of the confined flows (sec 3.3),
 * which makes such a block regular. */
static enum clsph_status solve(struct sim *sim, struct isph *is, cl_mem rhs, cl_mem P,
                               struct psolve_result *res)
{
  enum clsph_status st = CLSPH_OK;
  const size_t bytes = sim->ps.n * sizeof(real);
  CLSPH_TRY(kern_copy(sim->dev, is->d_guess, P, bytes));
  CLSPH_TRY(psolve_solve(&is->ps, &is->po.op, rhs, P, res));
  if (res->reason > 0 || is->ps.opt.singular == PSOLVE_REINFORCE) goto done;
  const int its = res->its;
  const enum psolve_singular singular = is->ps.opt.singular;
  ++is->resolves;
  log_warn("isph-usaw: step %ld: the pressure solve failed; again with a reinforced diagonal",
           sim->step);
  CLSPH_TRY(kern_copy(sim->dev, P, is->d_guess, bytes));
  is->ps.opt.singular = PSOLVE_REINFORCE;
  st = psolve_solve(&is->ps, &is->po.op, rhs, P, res);
  is->ps.opt.singular = singular;
  CLSPH_TRY(st);
  res->its += its;
done:
  return st;
}

/* How the pressure equation is solved: with a free surface (Dirichlet rows) as solver_singular
 * says, but never mean-free (the rows break the weighted mean's null vector); without one
 * (singular) with the reinforced diagonal of sec 3.3, or mean-free (solver_singular = "mean" or
 * "project"). */
static enum psolve_singular singular_mode(const struct isph *is, int free_surface)
{
  const enum psolve_singular s = is->popt.singular;
  if (free_surface) return PSOLVE_MEAN_FREE(s) ? PSOLVE_REGULAR : s;
  return PSOLVE_MEAN_FREE(s) ? s : PSOLVE_REINFORCE;
}

static enum clsph_status isph_step(struct sim *sim, void *state, double dt)
{
  enum clsph_status st = CLSPH_OK;
  struct isph *is = state;
  const struct scene *sc = sim->scene;
  struct pset *ps = &sim->ps;
  cl_uint i;
  const real rdt = (real)dt, rho = (real)sc->rho0, nu = (real)sc->nu, dr = (real)sc->dr;
  const real c = (real)is->c_shift;
  const real2 accel =
      dev_real2(sc->gravity[0] + sim->body_force[0], sc->gravity[1] + sim->body_force[1]);
  const real2 grav = dev_real2(sc->gravity[0], sc->gravity[1]);

  /* 1. half move, neighbours and γ at r* (turning walls where they stand at t + δt/2) */
  CLSPH_TRY(half_move(sim, is, dt));
  CLSPH_TRY(usaw_walls_turn(&is->walls, sim, sim->time + 0.5 * dt));
  CLSPH_TRY(sim_sort(sim));
  CLSPH_TRY(gamma_now(sim, is));
  cl_mem vel = pset_mem(ps, sim->f_vel), ustar = pset_mem(ps, is->f_ustar);
  cl_mem visc = pset_mem(ps, is->f_visc), fs = pset_mem(ps, is->f_free);
  cl_mem rhs = pset_mem(ps, is->f_rhs), P = pset_mem(ps, is->f_P), p = pset_mem(ps, is->f_p);
  cl_mem pos = pset_mem(ps, sim->f_pos);
  /* 2. prediction */
  CLSPH_TRY(prefix(sim, is, is->k_predict, &i));
  CLSPH_TRY(arg(is->k_predict, &i, sizeof vel, &vel));
  CLSPH_TRY(arg(is->k_predict, &i, sizeof rdt, &rdt));
  CLSPH_TRY(arg(is->k_predict, &i, sizeof nu, &nu));
  const real d_min = (real)is->d_min;
  CLSPH_TRY(arg(is->k_predict, &i, sizeof d_min, &d_min));
  CLSPH_TRY(arg(is->k_predict, &i, sizeof accel, &accel));
  CLSPH_TRY(arg(is->k_predict, &i, sizeof ustar, &ustar));
  CLSPH_TRY(arg(is->k_predict, &i, sizeof visc, &visc));
  cl_mem acc_p = pset_mem(ps, is->f_acc_p); /* the pressure's acceleration of the last step */
  CLSPH_TRY(arg(is->k_predict, &i, sizeof acc_p, &acc_p));
  CLSPH_TRY(usaw_turb_predict_args(sim, &is->turb, pset_mem(ps, is->f_ggam), is->k_predict, &i));
  CLSPH_TRY(kern_launch(sim->dev, is->k_predict, ps->n, NULL));
  /* k and ε (the k-ε model) */
  CLSPH_TRY(usaw_turb_advance(sim, &is->turb, &is->walls, pset_mem(ps, is->f_gam), dt, is->d_min));
  /* 3. free surface */
  cl_mem divr = pset_mem(ps, is->f_divr);
  CLSPH_TRY(prefix(sim, is, is->k_free, &i));
  CLSPH_TRY(arg(is->k_free, &i, sizeof vel, &vel));
  CLSPH_TRY(arg(is->k_free, &i, sizeof rdt, &rdt));
  CLSPH_TRY(arg(is->k_free, &i, sizeof fs, &fs));
  CLSPH_TRY(arg(is->k_free, &i, sizeof divr, &divr));
  cl_mem nrm = pset_mem(ps, is->f_normal);
  CLSPH_TRY(arg(is->k_free, &i, sizeof nrm, &nrm));
  /* the right-hand side (step 4) in the same sweep, where a row needs only its own flag */
  const cl_uint with_rhs = !(is->relax > 0.0);
  const real off = (real)(is->fs_offset * sc->dr);
  cl_mem acc_last = pset_mem(ps, is->f_acc); /* the accelerations of the last step */
  CLSPH_TRY(arg(is->k_free, &i, sizeof with_rhs, &with_rhs));
  CLSPH_TRY(arg(is->k_free, &i, sizeof ustar, &ustar));
  CLSPH_TRY(arg(is->k_free, &i, sizeof visc, &visc));
  CLSPH_TRY(arg(is->k_free, &i, sizeof rho, &rho));
  CLSPH_TRY(arg(is->k_free, &i, sizeof grav, &grav));
  CLSPH_TRY(arg(is->k_free, &i, sizeof off, &off));
  CLSPH_TRY(arg(is->k_free, &i, sizeof acc_last, &acc_last));
  CLSPH_TRY(arg(is->k_free, &i, sizeof rhs, &rhs));
  /* the solve's initial guess (free_surface.cl): none before the first step */
  const cl_uint guess_now = (cl_uint)is->guess_linear;
  const real theta = (real)(sim->dt > 0.0 ? dt / sim->dt : 0.0);
  cl_mem Pl = pset_mem(ps, is->f_P_last);
  CLSPH_TRY(arg(is->k_free, &i, sizeof guess_now, &guess_now));
  CLSPH_TRY(arg(is->k_free, &i, sizeof theta, &theta));
  CLSPH_TRY(arg(is->k_free, &i, sizeof P, &P));
  CLSPH_TRY(arg(is->k_free, &i, sizeof Pl, &Pl));
  CLSPH_TRY(arg(is->k_free, &i, sizeof is->d_count, &is->d_count));
  CLSPH_TRY(kern_launch(sim->dev, is->k_free, ps->n, NULL));
  /* A free surface makes the pressure equation regular; without one it is singular (reinforced).
   * The count comes with the solve's first wait: the last step's answer is the guess, and a wrong
   * one (a surface appeared or closed) solves again with the right form. */
  double nfree = 0.0;
  const int known = is->carry[ISPH_FREE] >= 0.0;
  if (known)
    CLSPH_TRY(kern_read_nb(sim->dev, is->d_count, 0, sizeof is->nfree, &is->nfree));
  else {
    CLSPH_TRY(kern_read(sim->dev, is->d_count, sizeof is->nfree, &is->nfree));
    nfree = (double)is->nfree;
  }
  const int guess = known ? is->carry[ISPH_FREE] > 0.0 : nfree > 0.0;
  /* 4. pressure equation: P = p̃ + ρgz, previous P as the initial guess; the right-hand side
   * here where the relaxation reads the neighbours' flags */
  if (!with_rhs) {
    CLSPH_TRY(prefix(sim, is, is->k_rhs, &i));
    CLSPH_TRY(arg(is->k_rhs, &i, sizeof ustar, &ustar));
    CLSPH_TRY(arg(is->k_rhs, &i, sizeof visc, &visc));
    CLSPH_TRY(arg(is->k_rhs, &i, sizeof fs, &fs));
    CLSPH_TRY(arg(is->k_rhs, &i, sizeof rho, &rho));
    CLSPH_TRY(arg(is->k_rhs, &i, sizeof rdt, &rdt));
    CLSPH_TRY(arg(is->k_rhs, &i, sizeof grav, &grav));
    CLSPH_TRY(arg(is->k_rhs, &i, sizeof nrm, &nrm));
    CLSPH_TRY(arg(is->k_rhs, &i, sizeof off, &off));
    CLSPH_TRY(arg(is->k_rhs, &i, sizeof acc_last, &acc_last));
    const real relax = (real)(is->relax * sc->rho0 / (dt * dt)); /* α ρ/δt² */
    CLSPH_TRY(arg(is->k_rhs, &i, sizeof relax, &relax));
    CLSPH_TRY(arg(is->k_rhs, &i, sizeof rhs, &rhs));
    CLSPH_TRY(kern_launch(sim->dev, is->k_rhs, ps->n, NULL));
  }
  is->ps.opt.singular = singular_mode(is, guess);
  cl_uint n = (cl_uint)ps->n;
  poisson_op_bind(&is->po, &sim->grid, ps->n, pos, pset_mem(ps, sim->f_vol), NULL, fs);
  struct psolve_result res;
  CLSPH_TRY(solve(sim, is, rhs, P, &res));
  if (known) { /* the solve has waited: the partial counts are here */
    nfree = (double)is->nfree;
    if ((nfree > 0.0) != guess) {
      log_debug("isph-usaw: step %ld: the free surface %s; the pressure equation again, %s",
                sim->step, guess ? "is gone" : "is back", guess ? "reinforced" : "regular");
      is->ps.opt.singular = singular_mode(is, nfree > 0.0);
      const int its = res.its; /* the step reports both solves' iterations */
      CLSPH_TRY(solve(sim, is, rhs, P, &res));
      res.its += its;
    }
  }
  is->carry[ISPH_FREE] = nfree > 0.0 ? 1.0 : 0.0;
  sim->solver_its = res.its;
  sim->solver_res = res.rnorm;
  CLSPH_TRY(KERN_SET(is->k_pressure, KARG(n), KARG(pos), KARG(P), KARG(rho), KARG(grav), KARG(p)));
  CLSPH_TRY(kern_launch(sim->dev, is->k_pressure, ps->n, NULL));
  /* no tension next to the air (scenes with gravity, where a free surface is physics; ppe.cl) */
  const cl_uint stop_at_walls = hypot(sc->gravity[0], sc->gravity[1]) > 0.0;
  if (stop_at_walls && nfree > 0.0) {
    CLSPH_TRY(prefix(sim, is, is->k_no_tension, &i));
    CLSPH_TRY(arg(is->k_no_tension, &i, sizeof fs, &fs));
    CLSPH_TRY(arg(is->k_no_tension, &i, sizeof rho, &rho));
    CLSPH_TRY(arg(is->k_no_tension, &i, sizeof grav, &grav));
    CLSPH_TRY(arg(is->k_no_tension, &i, sizeof P, &P));
    CLSPH_TRY(arg(is->k_no_tension, &i, sizeof p, &p));
    CLSPH_TRY(kern_launch(sim->dev, is->k_no_tension, ps->n, NULL));
  }
  /* 5. projection, second half move */
  CLSPH_TRY(prefix(sim, is, is->k_project, &i));
  CLSPH_TRY(arg(is->k_project, &i, sizeof ustar, &ustar));
  CLSPH_TRY(arg(is->k_project, &i, sizeof P, &P));
  CLSPH_TRY(arg(is->k_project, &i, sizeof p, &p));
  CLSPH_TRY(arg(is->k_project, &i, sizeof rho, &rho));
  CLSPH_TRY(arg(is->k_project, &i, sizeof rdt, &rdt));
  CLSPH_TRY(arg(is->k_project, &i, sizeof grav, &grav));
  CLSPH_TRY(arg(is->k_project, &i, sizeof fs, &fs));
  CLSPH_TRY(arg(is->k_project, &i, sizeof divr, &divr));
  const cl_uint free_flow = nfree > 0.0;
  CLSPH_TRY(arg(is->k_project, &i, sizeof free_flow, &free_flow));
  CLSPH_TRY(arg(is->k_project, &i, sizeof is->guard, &is->guard));
  CLSPH_TRY(arg(is->k_project, &i, sizeof vel, &vel));
  cl_mem acc = pset_mem(ps, is->f_acc); /* the accelerations, kept for the next free surface */
  CLSPH_TRY(arg(is->k_project, &i, sizeof acc, &acc));
  CLSPH_TRY(arg(is->k_project, &i, sizeof acc_p, &acc_p));
  CLSPH_TRY(kern_launch(sim->dev, is->k_project, ps->n, NULL));
  /* largest |u̇_a| of the fluid (49), for the next step's length: read at the step's end */
  CLSPH_TRY(sim_max_field_deferred(sim, is->f_acc, 0, &is->carry[ISPH_ACC]));
  CLSPH_TRY(half_move(sim, is, dt));
  CLSPH_TRY(usaw_walls_turn(&is->walls, sim, sim->time + dt));
  /* 6. shifting at r̃ */
  if (is->c_shift > 0.0) {
    CLSPH_TRY(sim_sort(sim));
    CLSPH_TRY(gamma_now(sim, is));
    vel = pset_mem(ps, sim->f_vel);
    fs = pset_mem(ps, is->f_free);
    pos = pset_mem(ps, sim->f_pos);
    cl_mem shift = pset_mem(ps, is->f_shift), vnew = pset_mem(ps, is->f_vnew);
    CLSPH_TRY(prefix(sim, is, is->k_shift, &i));
    CLSPH_TRY(arg(is->k_shift, &i, sizeof vel, &vel));
    cl_mem wall_vel = is->turb.on ? pset_mem(ps, is->turb.f_uvert) : vel;
    CLSPH_TRY(arg(is->k_shift, &i, sizeof wall_vel, &wall_vel));
    cl_mem ggam = pset_mem(ps, is->f_ggam);
    CLSPH_TRY(arg(is->k_shift, &i, sizeof ggam, &ggam));
    CLSPH_TRY(arg(is->k_shift, &i, sizeof fs, &fs));
    CLSPH_TRY(arg(is->k_shift, &i, sizeof c, &c));
    CLSPH_TRY(arg(is->k_shift, &i, sizeof is->guard, &is->guard));
    CLSPH_TRY(arg(is->k_shift, &i, sizeof dr, &dr));
    cl_mem id = pset_mem(ps, sim->f_id);
    CLSPH_TRY(arg(is->k_shift, &i, sizeof id, &id));
    CLSPH_TRY(arg(is->k_shift, &i, sizeof shift, &shift));
    CLSPH_TRY(arg(is->k_shift, &i, sizeof vnew, &vnew));
    CLSPH_TRY(kern_launch(sim->dev, is->k_shift, ps->n, NULL));
    CLSPH_TRY(KERN_SET(is->k_apply, KARG(n), KARG(sim->grid.geom), KARG(pos), KARG(shift),
                       KARG(vel), KARG(vnew), KARG(sim->d_flags)));
    CLSPH_TRY(kern_launch(sim->dev, is->k_apply, ps->n, NULL));
  }
done:
  return st;
}

/* What one step hands the next (carry): a restart keeps it, so that it goes on bit for bit. */
static double *isph_persist(void *state, int *count)
{
  struct isph *is = state;
  *count = 2;
  return is->carry;
}

static enum clsph_status isph_max_dt(struct sim *sim, void *state, double *dt)
{
  enum clsph_status st = CLSPH_OK;
  struct isph *is = state;
  const struct scene *s = sim->scene;
  const double h = sim->sm.h;
  double vmax = 0.0;
  CLSPH_TRY(sim_max_speed(sim, 0, &vmax));
  double uref = fmax(vmax, is->u_wall);
  double a = fmax(hypot(s->gravity[0] + sim->body_force[0], s->gravity[1] + sim->body_force[1]),
                  is->carry[ISPH_ACC]);
  double d = HUGE_VAL;
  /* CFL (49): the paper's C_CFL = 0.2 lets particles cross the side wall of the lid-driven
   * cavity (Re 100, 20 and 30 particles per side, within 5 s); 0.1 keeps them in. The paper's
   * value is run { cfl = 2 }. */
  if (uref > 0.0) d = fmin(d, 0.1 * h / uref);
  const double nu = s->nu + (is->turb.on ? is->turb.ke.nut_max : 0.0); /* ν + ν_t */
  if (nu > 0.0) d = fmin(d, 0.125 * h * h / nu);                       /* viscous (49) */
  if (a > 0.0) d = fmin(d, 0.25 * sqrt(h / a));                        /* force (49) */
  *dt = d;
done:
  return st;
}

/* Force of the fluid on the walls of a group, pressure and viscous parts (eqs 69-70, walls.c). */
static enum clsph_status isph_wall_force(struct sim *sim, void *state, const char *group,
                                         struct wall_force *f)
{
  enum clsph_status st = CLSPH_OK;
  struct isph *is = state;
  cl_uint i;
  /* the turning walls where they stand now (a restart's first output), γ at the current
   * positions (none yet before the first step) */
  if (is->walls.turning) {
    CLSPH_TRY(usaw_walls_turn(&is->walls, sim, sim->time));
    CLSPH_TRY(sim_sort(sim));
  }
  cl_mem vel = pset_mem(&sim->ps, sim->f_vel);
  CLSPH_TRY(gamma_now(sim, is));
  CLSPH_TRY(prefix(sim, is, is->k_strain, &i));
  CLSPH_TRY(arg(is->k_strain, &i, sizeof vel, &vel));
  CLSPH_TRY(arg(is->k_strain, &i, sizeof is->d_strain, &is->d_strain));
  CLSPH_TRY(kern_launch(sim->dev, is->k_strain, sim->ps.n, NULL));
  /* under the k-ε model the viscous part is the wall law's mean shear (below), whose moment
   * the torque leaves out */
  const double mu = is->turb.on ? 0.0 : sim->scene->rho0 * sim->scene->nu;
  CLSPH_TRY(usaw_wall_force(sim->dev, &sim->geom, sim->scene, sim->ps.n,
                            pset_mem(&sim->ps, is->f_p), is->d_strain, sim->d_inv, mu, sim->time,
                            group, f));
  if (is->turb.on) /* the wall law's shear (eq 22) */
    CLSPH_TRY(usaw_turb_wall_force(sim, &is->turb, &is->walls, pset_mem(&sim->ps, is->f_gam),
                                   is->d_min, group, f->viscous));
done:
  return st;
}

static void isph_destroy(void *state)
{
  struct isph *is = state;
  if (is == NULL) return;
  cl_kernel *ks[] = {&is->k_half,       &is->k_predict, &is->k_free,  &is->k_rhs,   &is->k_pressure,
                     &is->k_no_tension, &is->k_project, &is->k_shift, &is->k_apply, &is->k_strain};
  for (size_t k = 0; k < sizeof ks / sizeof *ks; ++k)
    if (*ks[k] != NULL) clReleaseKernel(*ks[k]);
  kern_release(&is->d_strain);
  kern_release(&is->d_guess);
  kern_release(&is->d_count);
  usaw_turb_destroy(&is->turb);
  psolve_destroy(&is->ps);
  poisson_op_destroy(&is->po);
  usaw_walls_destroy(&is->walls);
  free(is);
}

const struct scheme_ops scheme_isph_usaw = {
    .name = "isph-usaw",
    .summary = "incompressible SPH, unified semi-analytical walls (Leroy et al. 2014)",
    .sources = sources,
    .wall_model = "usaw",
    .smoothing = "wendland",
    .h_over_dr = 2.0,
    .fill_fields = SCHEME_FILL_PRESSURE,
    .turbulence = usaw_turbulence_models,
    .sorts_first = 1, /* the half move to r* comes first (step 1) */
    .options = options,
    .define = isph_define,
    .create = isph_create,
    .step = isph_step,
    .max_dt = isph_max_dt,
    .persist = isph_persist,
    .wall_force = isph_wall_force,
    .destroy = isph_destroy,
};
