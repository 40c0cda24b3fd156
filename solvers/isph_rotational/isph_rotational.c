/* isph_rotational.c: projection ISPH with the rotational pressure correction and BDF2 time
 * stepping (Hosseini & Feng 2011, J. Comput. Phys. 230:7473), and its homogeneous projection
 * (option projection = "homogeneous"), on dummy-particle walls. One time step (sec 3.2):
 *   1. L_i, the Oger correction over all neighbours (eq 25, common/operators.cl)
 *   2. dummy velocities extrapolated from the fluid, mirrors for Neumann (sec 3.3.1, walls.cl)
 *   3. ũ explicitly: a0 ũ = a1 u^k − a2 u^{k−1} + δt (ν∇²u^k − ∇p^k/ρ + g)  (eq 9; 5 without
 *      ∇p^k), BDF2 coefficients for variable steps (predict.cl)
 *   4. ∇²φ = (a0 ρ/δt) ∇·ũ, ũ = u_wall on the dummies (eqs 13, 27, sec 3.3.3), Neumann by
 *      propagation to the dummies (ppe.cl), BiCGStab (solvers/pressure); no Dirichlet row, so
 *      the system is reinforced (the paper pins one value instead, sec 3.2)
 *   5. u^{k+1} = ũ − δt/(a0 ρ) ∇φ; p^{k+1} = p^k + φ − µ∇·ũ (eqs 10-11); homogeneous: p = φ
 *   6. r += δt u^{k+1} (+ XSPH), then Xu shifting (sec 3.4, shift.cl)
 * Entry and exit sections (sec 3.3.2-3.3.3) are not implemented yet: scenes with inflow or
 * outflow sections are refused. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../scheme.h"
#include "clsph_config.h"
#include "force.h"
#include "geometry.h"
#include "ops.h"
#include "psolve.h"
#include "sim.h"

struct rot {
  struct ops ops;
  struct psolve ps;
  struct psolve_options popt;
  struct psolve_op op;
  struct sim *sim; /* for the operator callbacks, set at each step */
  struct rot_force force; /* sample points of the force groups (force.c) */
  int rotational;  /* 1: rotational (eqs 9-11), 0: homogeneous (eqs 5-8) */
  double c_shift;  /* Xu et al.'s C (0: off) */
  double xsph;     /* XSPH ε (0: off) */
  double dt_prev;  /* the last step, s (0 before the first: BDF1) */
  double umax;     /* largest fluid speed at the last max_dt, m/s */
  int f_p, f_phi, f_uprev, f_ustar, f_div, f_rhs, f_L, f_mirror, f_dist, f_normal, f_uwall, f_shift,
      f_vnew, f_posn;
  cl_kernel k_dummy, k_prop, k_predict, k_source, k_apply, k_coeffs, k_diag, k_count, k_project,
      k_move, k_shift, k_apply_shift;
};

static const char *const sources[] = {"common/blas1.cl",
                                      "common/csr.cl",
                                      "common/mg.cl",
                                      "common/poisson.cl",
                                      "isph_rotational/walls.cl",
                                      "isph_rotational/force.cl",
                                      "isph_rotational/predict.cl",
                                      "isph_rotational/ppe.cl",
                                      "isph_rotational/project.cl",
                                      "isph_rotational/shift.cl",
                                      NULL};
static const char *const options[] = {"projection", "shifting", "xsph", PSOLVE_OPTION_NAMES, NULL};

static const struct scene_option *option(const struct scene *s, const char *key)
{
  for (int i = 0; i < s->noptions; ++i)
    if (strcmp(s->options[i].key, key) == 0) return &s->options[i];
  return NULL;
}

static enum clsph_status rot_define(const struct sim *sim, struct prog_opts *o)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene_option *op = option(sim->scene, "projection");
  int rotational = 1;
  if (op != NULL) {
    CLSPH_CHECK(!op->is_number &&
                    (!strcmp(op->text, "rotational") || !strcmp(op->text, "homogeneous")),
                CLSPH_E_INPUT,
                "%s: projection must be \"rotational\" (eqs 9-11) or "
                "\"homogeneous\" (eqs 5-8)",
                sim->scene->case_path);
    rotational = strcmp(op->text, "rotational") == 0;
  }
  CLSPH_TRY(ops_define(1, o)); /* Oger correction in every operator (eqs 25-29) */
  CLSPH_TRY(prog_opts_define_int(o, "ROT_ROTATIONAL", rotational));
done:
  return st;
}

/* The operator arguments every neighbour kernel starts with (OP_ARGS); returns the next index. */
static enum clsph_status op_prefix(struct sim *sim, struct rot *r, cl_kernel k, cl_uint *n)
{
  *n = (cl_uint)sim->ps.n;
  cl_mem pos = pset_mem(&sim->ps, sim->f_pos), vol = pset_mem(&sim->ps, sim->f_vol);
  cl_mem L = pset_mem(&sim->ps, r->f_L), kind = pset_mem(&sim->ps, sim->f_kind);
  return KERN_SET(k, KARG(*n), KARG(sim->grid.geom), KARG(sim->grid.d_start), KARG(pos), KARG(vol),
                  KARG(L), KARG(kind));
}

/* ---- the pressure operator (ppe.cl) for solvers/pressure ---- */

static enum clsph_status ppe_apply(void *ctx, cl_mem x, cl_mem y)
{
  enum clsph_status st = CLSPH_OK;
  struct rot *r = ctx;
  cl_uint n;
  cl_mem mirror = pset_mem(&r->sim->ps, r->f_mirror);
  CLSPH_TRY(op_prefix(r->sim, r, r->k_apply, &n));
  CLSPH_TRY(kern_set_at(r->k_apply, 7, KARG(mirror)));
  CLSPH_TRY(kern_set_at(r->k_apply, 8, KARG(x)));
  CLSPH_TRY(kern_set_at(r->k_apply, 9, KARG(y)));
  CLSPH_TRY(kern_launch(r->sim->dev, r->k_apply, n, NULL));
done:
  return st;
}

static enum clsph_status ppe_diagonal(void *ctx, cl_mem d)
{
  enum clsph_status st = CLSPH_OK;
  struct rot *r = ctx;
  cl_uint n;
  cl_mem mirror = pset_mem(&r->sim->ps, r->f_mirror);
  CLSPH_TRY(op_prefix(r->sim, r, r->k_diag, &n));
  CLSPH_TRY(kern_set_at(r->k_diag, 7, KARG(mirror)));
  CLSPH_TRY(kern_set_at(r->k_diag, 8, KARG(d)));
  CLSPH_TRY(kern_launch(r->sim->dev, r->k_diag, n, NULL));
done:
  return st;
}

static enum clsph_status ppe_counts(void *ctx, cl_mem count)
{
  enum clsph_status st = CLSPH_OK;
  struct rot *r = ctx;
  struct sim *sim = r->sim;
  cl_uint n = (cl_uint)sim->ps.n;
  cl_mem pos = pset_mem(&sim->ps, sim->f_pos);
  CLSPH_TRY(KERN_SET(r->k_count, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start), KARG(pos),
                     KARG(count)));
  CLSPH_TRY(kern_launch(sim->dev, r->k_count, n, NULL));
done:
  return st;
}

static enum clsph_status ppe_coefficients(void *ctx, cl_mem row, cl_mem col, cl_mem val)
{
  enum clsph_status st = CLSPH_OK;
  struct rot *r = ctx;
  cl_uint n;
  cl_mem mirror = pset_mem(&r->sim->ps, r->f_mirror);
  CLSPH_TRY(op_prefix(r->sim, r, r->k_coeffs, &n));
  CLSPH_TRY(kern_set_at(r->k_coeffs, 7, KARG(mirror)));
  CLSPH_TRY(kern_set_at(r->k_coeffs, 8, KARG(row)));
  CLSPH_TRY(kern_set_at(r->k_coeffs, 9, KARG(col)));
  CLSPH_TRY(kern_set_at(r->k_coeffs, 10, KARG(val)));
  CLSPH_TRY(kern_launch(r->sim->dev, r->k_coeffs, n, NULL));
done:
  return st;
}

/* ---- create ---- */

static enum clsph_status rot_create(struct sim *sim, void **state)
{
  enum clsph_status st = CLSPH_OK;
  struct rot *r = calloc(1, sizeof *r);
  const struct geom *geo = &sim->geom;
  const struct scene *sc = sim->scene;
  real *host = NULL;
  CLSPH_CHECK(r != NULL, CLSPH_E_NOMEM, "isph-rotational: out of memory");
  r->rotational = 1;
  r->c_shift = 0.04;
  const struct scene_option *o = option(sc, "projection");
  if (o != NULL) r->rotational = strcmp(o->text, "rotational") == 0;
  if ((o = option(sc, "shifting")) != NULL) {
    CLSPH_CHECK(o->is_number && o->number >= 0.0 && o->number <= 0.2, CLSPH_E_INPUT,
                "%s: shifting must be Xu et al.'s coefficient C, 0 (off) to 0.2", sc->case_path);
    r->c_shift = o->number;
  }
  if ((o = option(sc, "xsph")) != NULL) {
    CLSPH_CHECK(o->is_number && o->number >= 0.0 && o->number <= 0.5, CLSPH_E_INPUT,
                "%s: xsph must be the XSPH coefficient, 0 (off) to 0.5", sc->case_path);
    r->xsph = o->number;
  }
  for (size_t i = 0; i < geo->n; ++i)
    CLSPH_CHECK(geo->kind[i] == KIND_FLUID || geo->kind[i] == KIND_DUMMY, CLSPH_E_UNSUPPORTED,
                "%s: isph-rotational has no entry or exit sections yet (sec 3.3.2-3.3.3)",
                sc->case_path);
  CLSPH_TRY(sim_psolve_options(sim, &r->popt));
  /* fields: the wall geometry of the dummies, then the scheme's state */
  struct pset *ps = &sim->ps;
  const size_t rv = 2 * sizeof(real);
  host = calloc(2 * geo->n, sizeof *host);
  CLSPH_CHECK(host != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t i = 0; i < geo->n; ++i) host[i] = (real)geo->dist[i];
  CLSPH_TRY(pset_add(ps, sim->dev, "wall_dist", sizeof(real), host, &r->f_dist));
  for (size_t i = 0; i < 2 * geo->n; ++i) host[i] = (real)geo->normal[i];
  CLSPH_TRY(pset_add(ps, sim->dev, "wall_normal", rv, host, &r->f_normal));
  for (size_t i = 0; i < 2 * geo->n; ++i) host[i] = (real)geo->v[i];
  CLSPH_TRY(pset_add(ps, sim->dev, "wall_vel", rv, host, &r->f_uwall));
  CLSPH_TRY(pset_add(ps, sim->dev, "p", sizeof(real), NULL, &r->f_p));
  CLSPH_TRY(pset_add(ps, sim->dev, "div_ustar", sizeof(real), NULL, &r->f_div));
  const struct {
    const char *name;
    size_t elem;
    int *f;
  } hidden[] = {{"phi", sizeof(real), &r->f_phi}, {"vel_prev", rv, &r->f_uprev},
                {"ustar", rv, &r->f_ustar},       {"rhs", sizeof(real), &r->f_rhs},
                {"L", 4 * sizeof(real), &r->f_L}, {"shift", rv, &r->f_shift},
                {"vel_new", rv, &r->f_vnew},      {"pos_new", rv, &r->f_posn}};
  for (size_t k = 0; k < sizeof hidden / sizeof *hidden; ++k) {
    CLSPH_TRY(pset_add(ps, sim->dev, hidden[k].name, hidden[k].elem, NULL, hidden[k].f));
    pset_describe(ps, *hidden[k].f, PF_REAL, 0, 0);
  }
  pset_describe(ps, r->f_dist, PF_REAL, 0, 0);
  pset_describe(ps, r->f_normal, PF_REAL, 0, 0);
  pset_describe(ps, r->f_uwall, PF_REAL, 0, 0);
  CLSPH_TRY(pset_add(ps, sim->dev, "mirror", sizeof(cl_uint), NULL, &r->f_mirror));
  pset_describe(ps, r->f_mirror, PF_UINT, 0, 0);
  /* kernels, operators, solver */
  struct {
    cl_kernel *k;
    const char *name;
  } ks[] = {{&r->k_dummy, "rot_dummy_velocity"}, {&r->k_prop, "rot_propagate"},
            {&r->k_predict, "rot_predict"},      {&r->k_source, "rot_source"},
            {&r->k_apply, "rot_ppe_apply"},      {&r->k_coeffs, "rot_ppe_coeffs"},
            {&r->k_diag, "rot_ppe_diag"},        {&r->k_count, "csr_count"},
            {&r->k_project, "rot_project"},      {&r->k_move, "rot_move"},
            {&r->k_shift, "rot_shift"},          {&r->k_apply_shift, "rot_apply_shift"}};
  for (size_t k = 0; k < sizeof ks / sizeof *ks; ++k)
    CLSPH_TRY(prog_kernel(sim->prog, ks[k].name, ks[k].k));
  CLSPH_TRY(ops_create(sim->prog, 1, &r->ops));
  CLSPH_TRY(psolve_create(sim->dev, sim->prog, ps->cap, &r->popt, &r->ps));
  CLSPH_TRY(rot_force_create(sim->dev, sim->prog, sc, &r->force));
  r->op.ctx = r;
  r->op.apply = ppe_apply;
  r->op.diagonal = ppe_diagonal;
  r->op.row_counts = ppe_counts;
  r->op.coefficients = ppe_coefficients;
  *state = r;
  r = NULL;
done:
  free(host);
  if (r != NULL) {
    rot_force_destroy(&r->force);
    psolve_destroy(&r->ps);
    ops_destroy(&r->ops);
    free(r);
  }
  return st;
}

/* ---- step ---- */

static enum clsph_status propagate(struct sim *sim, struct rot *r, int field)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint n = (cl_uint)sim->ps.n;
  cl_mem kind = pset_mem(&sim->ps, sim->f_kind), mirror = pset_mem(&sim->ps, r->f_mirror);
  cl_mem a = pset_mem(&sim->ps, field);
  CLSPH_TRY(KERN_SET(r->k_prop, KARG(n), KARG(kind), KARG(mirror), KARG(a)));
  CLSPH_TRY(kern_launch(sim->dev, r->k_prop, n, NULL));
done:
  return st;
}

static enum clsph_status rot_step(struct sim *sim, void *state, double dt)
{
  enum clsph_status st = CLSPH_OK;
  struct rot *r = state;
  r->sim = sim; /* sim_create moves the sim after create: the operator's context is set here */
  const struct scene *sc = sim->scene;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  cl_uint np;
#define M(f) cl_mem f = pset_mem(ps, r->f_##f)
  M(p);
  M(phi);
  M(uprev);
  M(ustar);
  M(div);
  M(rhs);
  M(L);
  M(mirror);
  M(dist);
  M(normal);
  M(uwall);
#undef M
  cl_mem pos = pset_mem(ps, sim->f_pos), vol = pset_mem(ps, sim->f_vol);
  cl_mem vel = pset_mem(ps, sim->f_vel), kind = pset_mem(ps, sim->f_kind);
  /* BDF2 coefficients for steps dt (now) and dt_prev (BDF1 on the first step) */
  const double w = r->dt_prev > 0.0 ? dt / r->dt_prev : 0.0;
  const double b0 = (1.0 + 2.0 * w) / (1.0 + w);
  const real a0 = (real)b0, a1 = (real)(1.0 + w), a2 = (real)(w * w / (1.0 + w));
  const real rdt = (real)dt, rho = (real)sc->rho0, nu = (real)sc->nu;
  const real2 accel =
      dev_real2(sc->gravity[0] + sim->body_force[0], sc->gravity[1] + sim->body_force[1]);

  /* 1. the Oger correction matrices (eq 25) */
  CLSPH_TRY(ops_apply(&r->ops, OP_CORRECTION, sim->dev, &sim->grid, ps->n, pos, vol, NULL, NULL, L,
                      NULL));
  /* 2. dummy velocities and mirrors (sec 3.3.1) */
  CLSPH_TRY(KERN_SET(r->k_dummy, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start), KARG(pos),
                     KARG(vol), KARG(kind), KARG(dist), KARG(normal), KARG(uwall), KARG(vel),
                     KARG(mirror), KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, r->k_dummy, n, NULL));
  /* 3. prediction (eq 9 or 5) */
  CLSPH_TRY(op_prefix(sim, r, r->k_predict, &np));
  {
    cl_uint i = 7;
    const struct karg a[] = {KARG(vel),   KARG(uprev), KARG(p),           KARG(uwall), KARG(rdt),
                             KARG(a0),    KARG(a1),    KARG(a2),          KARG(nu),    KARG(rho),
                             KARG(accel), KARG(ustar), KARG(sim->d_flags)};
    for (size_t k = 0; k < sizeof a / sizeof *a; ++k)
      CLSPH_TRY(kern_set_at(r->k_predict, i++, a[k]));
  }
  CLSPH_TRY(kern_launch(sim->dev, r->k_predict, n, NULL));
  /* 4. source and pressure equation (eqs 13 or 7) */
  const real scale = (real)(b0 * sc->rho0 / dt);
  CLSPH_TRY(op_prefix(sim, r, r->k_source, &np));
  CLSPH_TRY(kern_set_at(r->k_source, 7, KARG(ustar)));
  CLSPH_TRY(kern_set_at(r->k_source, 8, KARG(scale)));
  CLSPH_TRY(kern_set_at(r->k_source, 9, KARG(div)));
  CLSPH_TRY(kern_set_at(r->k_source, 10, KARG(rhs)));
  CLSPH_TRY(kern_launch(sim->dev, r->k_source, n, NULL));
  r->op.n = ps->n;
  r->op.grid = &sim->grid;
  r->ps.opt.singular = PSOLVE_REINFORCE; /* Neumann everywhere: no Dirichlet row */
  struct psolve_result res;
  cl_mem x = r->rotational ? phi : p; /* the previous solution is the initial guess */
  CLSPH_TRY(psolve_solve(&r->ps, &r->op, rhs, x, &res));
  sim->solver_its = res.its;
  sim->solver_res = res.rnorm;
  if (!r->rotational) CLSPH_TRY(kern_copy(sim->dev, phi, p, ps->n * sizeof(real)));
  CLSPH_TRY(propagate(sim, r, r->f_phi));
  /* 5. correction (eqs 10-11 or 6) */
  const real coef = (real)(dt / (b0 * sc->rho0)), mu = (real)(sc->rho0 * sc->nu);
  CLSPH_TRY(op_prefix(sim, r, r->k_project, &np));
  {
    cl_uint i = 7;
    const struct karg a[] = {KARG(phi), KARG(ustar), KARG(div), KARG(coef),        KARG(mu),
                             KARG(vel), KARG(uprev), KARG(p),   KARG(sim->d_flags)};
    for (size_t k = 0; k < sizeof a / sizeof *a; ++k)
      CLSPH_TRY(kern_set_at(r->k_project, i++, a[k]));
  }
  CLSPH_TRY(kern_launch(sim->dev, r->k_project, n, NULL));
  CLSPH_TRY(propagate(sim, r, r->f_p));
  r->dt_prev = dt;
  /* 6. motion (+ XSPH) and shifting */
  cl_mem posn = pset_mem(ps, r->f_posn);
  const real xs = (real)r->xsph;
  CLSPH_TRY(KERN_SET(r->k_move, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start), KARG(pos),
                     KARG(vol), KARG(kind), KARG(vel), KARG(rdt), KARG(xs), KARG(posn),
                     KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, r->k_move, n, NULL));
  CLSPH_TRY(kern_copy(sim->dev, pos, posn, ps->n * 2 * sizeof(real)));
  if (r->c_shift > 0.0) {
    CLSPH_TRY(sim_sort(sim));
    pos = pset_mem(ps, sim->f_pos);
    vol = pset_mem(ps, sim->f_vol);
    vel = pset_mem(ps, sim->f_vel);
    kind = pset_mem(ps, sim->f_kind);
    cl_mem shift = pset_mem(ps, r->f_shift), vnew = pset_mem(ps, r->f_vnew);
    const real ca = (real)(r->c_shift * r->umax * dt); /* C α, α = U_max δt */
    CLSPH_TRY(KERN_SET(r->k_shift, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start),
                       KARG(pos), KARG(vol), KARG(kind), KARG(vel), KARG(ca), KARG(shift),
                       KARG(vnew)));
    CLSPH_TRY(kern_launch(sim->dev, r->k_shift, n, NULL));
    CLSPH_TRY(KERN_SET(r->k_apply_shift, KARG(n), KARG(sim->grid.geom), KARG(kind), KARG(pos),
                       KARG(shift), KARG(vel), KARG(vnew), KARG(sim->d_flags)));
    CLSPH_TRY(kern_launch(sim->dev, r->k_apply_shift, n, NULL));
  }
done:
  return st;
}

/* Time step: CFL 0.25 h/U, viscous 0.125 h²/ν, body force 0.25 √(h/|g|) (the paper gives no
 * bound; these are the usual ISPH ones, Cummins & Rudman 1999). */
static enum clsph_status rot_max_dt(struct sim *sim, void *state, double *dt)
{
  enum clsph_status st = CLSPH_OK;
  struct rot *r = state;
  const struct scene *s = sim->scene;
  const double h = sim->sm.h;
  CLSPH_TRY(sim_max_speed(sim, 0, &r->umax));
  double a = hypot(s->gravity[0] + sim->body_force[0], s->gravity[1] + sim->body_force[1]);
  double d = HUGE_VAL;
  if (r->umax > 0.0) d = fmin(d, 0.25 * h / r->umax);
  if (s->nu > 0.0) d = fmin(d, 0.125 * h * h / s->nu);
  if (a > 0.0) d = fmin(d, 0.25 * sqrt(h / a));
  *dt = d;
done:
  return st;
}

/* Force of the fluid on the dummy walls of a group (eqs 31-32, force.c), at the current
 * positions (sorted first: the particles moved since the step's sort). */
static enum clsph_status rot_wall_force(struct sim *sim, void *state, const char *group,
                                        struct wall_force *f)
{
  enum clsph_status st = CLSPH_OK;
  struct rot *r = state;
  struct pset *ps = &sim->ps;
  CLSPH_TRY(sim_sort(sim));
  CLSPH_TRY(rot_force_eval(&r->force, sim->dev, &sim->grid, ps->n, pset_mem(ps, sim->f_pos),
                           pset_mem(ps, sim->f_vol), pset_mem(ps, sim->f_kind),
                           pset_mem(ps, sim->f_vel), pset_mem(ps, r->f_p),
                           sim->scene->rho0 * sim->scene->nu, group, f->pressure, f->viscous));
done:
  return st;
}

static void rot_destroy(void *state)
{
  struct rot *r = state;
  if (r == NULL) return;
  cl_kernel *ks[] = {&r->k_dummy,   &r->k_prop,   &r->k_predict, &r->k_source,
                     &r->k_apply,   &r->k_coeffs, &r->k_diag,    &r->k_count,
                     &r->k_project, &r->k_move,   &r->k_shift,   &r->k_apply_shift};
  for (size_t k = 0; k < sizeof ks / sizeof *ks; ++k)
    if (*ks[k] != NULL) clReleaseKernel(*ks[k]);
  rot_force_destroy(&r->force);
  psolve_destroy(&r->ps);
  ops_destroy(&r->ops);
  free(r);
}

const struct scheme_ops scheme_isph_rotational = {
    .name = "isph-rotational",
    .summary = "ISPH, rotational pressure correction, BDF2, dummy walls (Hosseini & Feng 2011)",
    .sources = sources,
    .wall_model = "dummy",
    .smoothing = "gaussian",
    .h_over_dr = 1.2,
    .options = options,
    .define = rot_define,
    .create = rot_create,
    .step = rot_step,
    .max_dt = rot_max_dt,
    .wall_force = rot_wall_force,
    .destroy = rot_destroy,
};
