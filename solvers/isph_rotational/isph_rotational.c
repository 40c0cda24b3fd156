/* isph_rotational.c: projection ISPH with the rotational pressure correction and BDF2 time
 * stepping (Hosseini & Feng 2011, J. Comput. Phys. 230:7473), and its homogeneous projection
 * (option projection = "homogeneous"), on dummy-particle walls. One time step (sec 3.2):
 *   1. L_i, the Oger correction over all neighbours (eq 25, common/operators.cl)
 *   2. dummy velocities extrapolated from the fluid, mirrors for Neumann (sec 3.3.1, walls.cl);
 *      the entry and exit layers' velocities (solvers/open), mirrors and coefficients (open.cl)
 *   3. ũ explicitly: a0 ũ = a1 u^k − a2 u^{k−1} + δt (ν∇²u^k − ∇p^k/ρ + g)  (eq 9; 5 without
 *      ∇p^k), BDF2 coefficients for variable steps (predict.cl); or, with viscous = "implicit",
 *      with ν∇²ũ: one linear solve per component (viscous.cl), no viscous bound on δt
 *   4. ∇²φ = (a0 ρ/δt) ∇·ũ, ũ = u_wall on the dummies (eqs 13, 27, sec 3.3.3), Neumann by
 *      propagation to the dummies (ppe.cl), BiCGStab (solvers/pressure); no Dirichlet row, so
 *      the system is reinforced (the paper pins one value instead, sec 3.2), unless an exit's
 *      φ = 0 (eq 19) makes it regular
 *   5. u^{k+1} = ũ − δt/(a0 ρ) ∇φ; p^{k+1} = p^k + φ − µ∇·ũ (eqs 10-11); homogeneous: p = φ
 *   6. r += δt u^{k+1} (+ XSPH), then Xu shifting (sec 3.4, shift.cl); then the recycling at
 *      the entry and exit sections (solvers/open)
 * Entry and exit sections (sec 3.3.2-3.3.3, eqs 16-20): the sections, the layers' velocity and
 * the recycling are solvers/open (kernels/common/open.cl, built with -D OPEN_SECTIONS=1 only for
 * scenes that have them, which need an inflow and an outflow together); what is this scheme's is
 * kernels/isph_rotational/open.cl. Entry layers carry the prescribed profile and move with it,
 * ũ = u_in, φ Neumann, the rotational p by eq 15; exit layers copy the velocity and ũ of the exit
 * layer (n·∇u = 0) or take a prescribed profile (outflow { profile = "parabolic" }, the paper's
 * choice above Re = 10), φ = 0 (and p = 0) at the exit by odd reflection. At the end of each step
 * fluid that left through an exit becomes an exit layer particle, and an entry particle that
 * reached the fluid becomes fluid while an exit particle beyond the last layer takes its place at
 * the back of its row: the particle count never changes, and nothing leaves the device. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../scheme.h"
#include "clsph_config.h"
#include "force.h"
#include "geometry.h"
#include "open.h"
#include "ops.h"
#include "psolve.h"
#include "sim.h"

struct rot {
  struct ops ops;
  struct psolve ps;
  struct psolve_options popt;
  struct psolve_op op;
  struct sim *sim;        /* for the operator callbacks, set at each step */
  struct rot_force force; /* sample points of the force groups (force.c) */
  int rotational;         /* 1: rotational (eqs 9-11), 0: homogeneous (eqs 5-8) */
  double c_shift;         /* Xu et al.'s C (0: off) */
  double xsph;            /* XSPH ε (0: off) */
  double dt_prev;         /* the last step, s (0 before the first: BDF1) */
  double umax;            /* largest fluid speed at the last max_dt, m/s */
  int implicit;           /* viscous = "implicit": ν∇²ũ in the prediction (viscous.cl) */
  double kappa;           /* its δt ν / a0 this step */
  struct psolve vs;       /* its solver (Jacobi BiCGStab, operator recomputed) */
  struct psolve_op vop;
  int f_vx, f_vy, f_bx, f_by; /* its unknowns and right-hand sides, per component */
  cl_kernel k_visc_count, k_visc_coeffs, k_visc_split, k_visc_gather;
  int f_p, f_phi, f_uprev, f_ustar, f_div, f_rhs, f_L, f_mirror, f_coef, f_dist, f_normal, f_uwall,
      f_shift, f_vnew, f_posn;
  cl_kernel k_dummy, k_prop, k_predict, k_source, k_apply, k_coeffs, k_diag, k_count, k_project,
      k_move, k_shift, k_apply_shift;
  /* entry and exit sections (solvers/open and open.cl; none: open.nsec = 0) */
  struct open_sections open;
  cl_kernel k_mirrors, k_dummies, k_dummy_p, k_ustar, k_open_p; /* open.cl */
};

static const char *const sources[] = {OPEN_SOURCES,
                                      PSOLVE_SOURCES,
                                      "common/poisson.cl",
                                      "common/marker.cl",
                                      "isph_rotational/walls.cl",
                                      "isph_rotational/force.cl",
                                      "isph_rotational/open.cl",
                                      "isph_rotational/predict.cl",
                                      "isph_rotational/viscous.cl",
                                      "isph_rotational/ppe.cl",
                                      "isph_rotational/project.cl",
                                      "isph_rotational/shift.cl",
                                      NULL};
static const char *const options[] = {"projection", "shifting",          "xsph", "wall_velocity",
                                      "viscous",    PSOLVE_OPTION_NAMES, NULL};

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
  int image = 0; /* the dummies' velocity from the particle at their image (walls.cl) */
  if ((op = option(sim->scene, "wall_velocity")) != NULL) {
    CLSPH_CHECK(!op->is_number && (!strcmp(op->text, "shepard") || !strcmp(op->text, "image")),
                CLSPH_E_INPUT,
                "%s: wall_velocity must be \"shepard\" (the fluid's Shepard interpolation at "
                "a dummy's image, the default) or \"image\" (the particle at its image)",
                sim->scene->case_path);
    image = strcmp(op->text, "image") == 0;
  }
  if ((op = option(sim->scene, "viscous")) != NULL)
    CLSPH_CHECK(!op->is_number && (!strcmp(op->text, "explicit") || !strcmp(op->text, "implicit")),
                CLSPH_E_INPUT,
                "%s: viscous must be \"explicit\" (the paper's prediction, sec 3.2, step bound "
                "0.125 h²/ν) or \"implicit\" (ν∇²ũ solved for, no viscous step bound)",
                sim->scene->case_path);
  CLSPH_TRY(ops_define(1, o)); /* Oger correction in every operator (eqs 25-29) */
  CLSPH_TRY(prog_opts_define_int(o, "ROT_WALL_IMAGE", image));
  CLSPH_TRY(prog_opts_define_int(o, "ROT_ROTATIONAL", rotational));
  CLSPH_TRY(open_define(sim, o)); /* the sections (solvers/open) */
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
  cl_mem mirror = pset_mem(&r->sim->ps, r->f_mirror), coef = pset_mem(&r->sim->ps, r->f_coef);
  CLSPH_TRY(op_prefix(r->sim, r, r->k_apply, &n));
  CLSPH_TRY(kern_set_at(r->k_apply, 7, KARG(mirror)));
  CLSPH_TRY(kern_set_at(r->k_apply, 8, KARG(coef)));
  CLSPH_TRY(kern_set_at(r->k_apply, 9, KARG(x)));
  CLSPH_TRY(kern_set_at(r->k_apply, 10, KARG(y)));
  CLSPH_TRY(kern_launch(r->sim->dev, r->k_apply, n, NULL));
done:
  return st;
}

static enum clsph_status ppe_diagonal(void *ctx, cl_mem d)
{
  enum clsph_status st = CLSPH_OK;
  struct rot *r = ctx;
  cl_uint n;
  cl_mem mirror = pset_mem(&r->sim->ps, r->f_mirror), coef = pset_mem(&r->sim->ps, r->f_coef);
  CLSPH_TRY(op_prefix(r->sim, r, r->k_diag, &n));
  CLSPH_TRY(kern_set_at(r->k_diag, 7, KARG(mirror)));
  CLSPH_TRY(kern_set_at(r->k_diag, 8, KARG(coef)));
  CLSPH_TRY(kern_set_at(r->k_diag, 9, KARG(d)));
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
  cl_mem mirror = pset_mem(&r->sim->ps, r->f_mirror), coef = pset_mem(&r->sim->ps, r->f_coef);
  CLSPH_TRY(op_prefix(r->sim, r, r->k_coeffs, &n));
  CLSPH_TRY(kern_set_at(r->k_coeffs, 7, KARG(mirror)));
  CLSPH_TRY(kern_set_at(r->k_coeffs, 8, KARG(coef)));
  CLSPH_TRY(kern_set_at(r->k_coeffs, 9, KARG(row)));
  CLSPH_TRY(kern_set_at(r->k_coeffs, 10, KARG(col)));
  CLSPH_TRY(kern_set_at(r->k_coeffs, 11, KARG(val)));
  CLSPH_TRY(kern_launch(r->sim->dev, r->k_coeffs, n, NULL));
done:
  return st;
}

/* ---- the implicit prediction's operator (viscous.cl), one component at a time ---- */

/* the velocity progenitors of the exit layers, or any buffer where there are none (unread) */
static cl_mem visc_src(struct rot *r)
{
  return pset_mem(&r->sim->ps, r->open.nsec > 0 ? r->open.f_src : r->sim->f_kind);
}

static enum clsph_status visc_counts(void *ctx, cl_mem count)
{
  enum clsph_status st = CLSPH_OK;
  struct rot *r = ctx;
  struct sim *sim = r->sim;
  struct pset *ps = &sim->ps;
  cl_uint n = (cl_uint)ps->n;
  cl_mem pos = pset_mem(ps, sim->f_pos), kind = pset_mem(ps, sim->f_kind);
  cl_mem dist = pset_mem(ps, r->f_dist), normal = pset_mem(ps, r->f_normal), src = visc_src(r);
  CLSPH_TRY(KERN_SET(r->k_visc_count, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start),
                     KARG(pos), KARG(kind), KARG(dist), KARG(normal), KARG(src), KARG(count)));
  CLSPH_TRY(kern_launch(sim->dev, r->k_visc_count, n, NULL));
done:
  return st;
}

static enum clsph_status visc_coefficients(void *ctx, cl_mem row, cl_mem col, cl_mem val)
{
  enum clsph_status st = CLSPH_OK;
  struct rot *r = ctx;
  struct pset *ps = &r->sim->ps;
  cl_uint n;
  const real kappa = (real)r->kappa;
  cl_mem dist = pset_mem(ps, r->f_dist), normal = pset_mem(ps, r->f_normal), src = visc_src(r);
  CLSPH_TRY(op_prefix(r->sim, r, r->k_visc_coeffs, &n));
  cl_uint k = 7;
  const struct karg a[] = {KARG(dist), KARG(normal), KARG(src), KARG(kappa),
                           KARG(row),  KARG(col),    KARG(val)};
  for (size_t q = 0; q < sizeof a / sizeof *a; ++q)
    CLSPH_TRY(kern_set_at(r->k_visc_coeffs, k++, a[q]));
  CLSPH_TRY(kern_launch(r->sim->dev, r->k_visc_coeffs, n, NULL));
done:
  return st;
}

/* ũ of the fluid with ν∇²ũ (viscous.cl): from rot_predict's ũ without the viscous term */
static enum clsph_status visc_solve(struct sim *sim, struct rot *r, double dt, double a0)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  cl_mem kind = pset_mem(ps, sim->f_kind), ustar = pset_mem(ps, r->f_ustar);
  cl_mem vx = pset_mem(ps, r->f_vx), vy = pset_mem(ps, r->f_vy);
  cl_mem bx = pset_mem(ps, r->f_bx), by = pset_mem(ps, r->f_by);
  r->kappa = dt * sim->scene->nu / a0;
  r->vop.n = ps->n;
  r->vop.grid = &sim->grid;
  cl_mem src = visc_src(r), vel = pset_mem(ps, sim->f_vel);
  CLSPH_TRY(KERN_SET(r->k_visc_split, KARG(n), KARG(kind), KARG(src), KARG(ustar), KARG(vel),
                     KARG(bx), KARG(by), KARG(vx), KARG(vy)));
  CLSPH_TRY(kern_launch(sim->dev, r->k_visc_split, n, NULL));
  struct psolve_result res;
  CLSPH_TRY(psolve_solve(&r->vs, &r->vop, bx, vx, &res));
  sim->aux_its = res.its;
  CLSPH_TRY(psolve_solve_again(&r->vs, &r->vop, by, vy, &res)); /* the same operator */
  sim->aux_its += res.its;
  CLSPH_TRY(KERN_SET(r->k_visc_gather, KARG(n), KARG(kind), KARG(vx), KARG(vy), KARG(ustar),
                     KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, r->k_visc_gather, n, NULL));
done:
  if (st == CLSPH_E_BLOWUP) sim->failed_solve = "viscous";
  return st;
}

/* BDF2 needs the last step's length (predict.cl): a restart keeps it (vel_prev, p and φ are
 * particle fields and travel in the checkpoint anyway). */
static double *rot_persist(void *state, int *count)
{
  struct rot *r = state;
  *count = 1;
  return &r->dt_prev;
}

static void rot_destroy(void *state);

/* ---- create ---- */

/* The entry and exit sections: the shared part (solvers/open: the section table, their fields,
 * the layers' velocity in wall_vel) and the kernels of open.cl. */
static enum clsph_status rot_open_create(struct sim *sim, struct rot *r)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(open_create(sim, r->f_uwall, &r->open));
  const struct {
    cl_kernel *k;
    const char *name;
  } ks[] = {{&r->k_mirrors, "rot_open_mirrors"},
            {&r->k_dummies, "rot_open_dummies"},
            {&r->k_dummy_p, "rot_open_dummy_p"},
            {&r->k_ustar, "rot_open_ustar"},
            {&r->k_open_p, "rot_open_pressure"}};
  for (size_t k = 0; k < sizeof ks / sizeof *ks; ++k)
    CLSPH_TRY(prog_kernel(sim->prog, ks[k].name, ks[k].k));
done:
  return st;
}

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
  if ((o = option(sc, "viscous")) != NULL) r->implicit = strcmp(o->text, "implicit") == 0;
  CLSPH_CHECK(!r->implicit || sc->dim == 2, CLSPH_E_INPUT,
              "%s:%d: isph-rotational option viscous = \"implicit\" is 2-D only for now (its solve "
              "splits the velocity into x and y): this scene is 3-D",
              sc->case_path, sc->scheme_line);
  for (size_t i = 0; i < geo->n; ++i)
    CLSPH_CHECK(geo->kind[i] == KIND_FLUID || geo->kind[i] == KIND_DUMMY ||
                    geo->kind[i] == KIND_INFLOW || geo->kind[i] == KIND_OUTFLOW,
                CLSPH_E_UNSUPPORTED, "%s: isph-rotational has a particle of kind %d", sc->case_path,
                geo->kind[i]);
  CLSPH_TRY(sim_psolve_options(sim, &r->popt));
  /* fields: the wall geometry of the dummies, then the scheme's state */
  struct pset *ps = &sim->ps;
  const size_t dim = (size_t)sc->dim, stride = dim == 3 ? 4 : 2; /* realv */
  const size_t rv = stride * sizeof(real);
  host = calloc(stride * geo->n + 1, sizeof *host);
  CLSPH_CHECK(host != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t i = 0; i < geo->n; ++i) host[i] = (real)geo->dist[i];
  CLSPH_TRY(pset_add(ps, sim->dev, "wall_dist", sizeof(real), host, &r->f_dist));
  /* (the padding of a 3-D real4 stays 0: every length and dot product reads it) */
  memset(host, 0, (stride * geo->n + 1) * sizeof *host);
  for (size_t i = 0; i < geo->n; ++i)
    for (size_t a = 0; a < dim; ++a) host[stride * i + a] = (real)geo->normal[dim * i + a];
  CLSPH_TRY(pset_add(ps, sim->dev, "wall_normal", rv, host, &r->f_normal));
  for (size_t i = 0; i < geo->n; ++i)
    for (size_t a = 0; a < dim; ++a) host[stride * i + a] = (real)geo->v[dim * i + a];
  CLSPH_TRY(pset_add(ps, sim->dev, "wall_vel", rv, host, &r->f_uwall));
  for (size_t i = 0; i < geo->n; ++i) /* fill { pressure }, the p^k of the first prediction */
    host[i] = i < geo->nfluid && isfinite(geo->p0[i]) ? (real)geo->p0[i] : 0;
  CLSPH_TRY(pset_add(ps, sim->dev, "p", sizeof(real), host, &r->f_p));
  CLSPH_TRY(pset_add(ps, sim->dev, "div_ustar", sizeof(real), NULL, &r->f_div));
  const struct {
    const char *name;
    size_t elem;
    int *f;
  } hidden[] = {{"phi", sizeof(real), &r->f_phi},
                {"vel_prev", rv, &r->f_uprev},
                {"ustar", rv, &r->f_ustar},
                {"rhs", sizeof(real), &r->f_rhs},
                {"L", (dim == 3 ? 8 : 4) * sizeof(real), &r->f_L}, /* realm */
                {"shift", rv, &r->f_shift},
                {"vel_new", rv, &r->f_vnew},
                {"pos_new", rv, &r->f_posn}};
  for (size_t k = 0; k < sizeof hidden / sizeof *hidden; ++k) {
    CLSPH_TRY(pset_add(ps, sim->dev, hidden[k].name, hidden[k].elem, NULL, hidden[k].f));
    pset_describe(ps, *hidden[k].f, PF_REAL, 0, 0);
  }
  pset_describe(ps, r->f_dist, PF_REAL, 0, 0);
  pset_describe(ps, r->f_normal, PF_REAL, 0, 0);
  pset_describe(ps, r->f_uwall, PF_REAL, 0, 0);
  CLSPH_TRY(pset_add(ps, sim->dev, "mirror", sizeof(cl_uint), NULL, &r->f_mirror));
  pset_describe(ps, r->f_mirror, PF_UINT, 0, 0);
  CLSPH_TRY(pset_add(ps, sim->dev, "mirror_coef", sizeof(real), NULL, &r->f_coef));
  pset_describe(ps, r->f_coef, PF_REAL, 0, 0);
  if (sc->nsections > 0) CLSPH_TRY(rot_open_create(sim, r));
  if (r->implicit) { /* the implicit prediction: fields, kernels, its solver */
    int *vf[] = {&r->f_vx, &r->f_vy, &r->f_bx, &r->f_by};
    const char *vn[] = {"visc_x", "visc_y", "visc_bx", "visc_by"};
    for (int k = 0; k < 4; ++k) {
      CLSPH_TRY(pset_add(ps, sim->dev, vn[k], sizeof(real), NULL, vf[k]));
      pset_describe(ps, *vf[k], PF_REAL, 0, 0);
    }
    CLSPH_TRY(prog_kernel(sim->prog, "rot_visc_count", &r->k_visc_count));
    CLSPH_TRY(prog_kernel(sim->prog, "rot_visc_coeffs", &r->k_visc_coeffs));
    CLSPH_TRY(prog_kernel(sim->prog, "rot_visc_split", &r->k_visc_split));
    CLSPH_TRY(prog_kernel(sim->prog, "rot_visc_gather", &r->k_visc_gather));
    /* stored coefficients (the dummy rows reach around their image, not their own neighbours:
     * the operator cannot be recomputed from a particle's neighbours alone); tolerances, the
     * iteration limit and the preconditioner are the pressure solver's */
    struct psolve_options vo = r->popt;
    vo.apply = PSOLVE_STORED;
    vo.singular = PSOLVE_REGULAR;
    vo.name = "viscous";
    CLSPH_TRY(psolve_create(sim->dev, sim->prog, ps->cap, &vo, &r->vs));
    r->vop.ctx = r;
    r->vop.row_counts = visc_counts;
    r->vop.coefficients = visc_coefficients;
  }
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
  if (r != NULL) rot_destroy(r);
  return st;
}

/* ---- step ---- */

static enum clsph_status propagate(struct sim *sim, struct rot *r, int field)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint n = (cl_uint)sim->ps.n;
  cl_mem kind = pset_mem(&sim->ps, sim->f_kind), mirror = pset_mem(&sim->ps, r->f_mirror);
  cl_mem coef = pset_mem(&sim->ps, r->f_coef), a = pset_mem(&sim->ps, field);
  CLSPH_TRY(KERN_SET(r->k_prop, KARG(n), KARG(kind), KARG(mirror), KARG(coef), KARG(a)));
  CLSPH_TRY(kern_launch(sim->dev, r->k_prop, n, NULL));
done:
  return st;
}

/* The entry and exit layers before the prediction: their velocity (solvers/open), then their
 * history, mirrors and coefficients (open.cl). */
static enum clsph_status rot_open_layers(struct sim *sim, struct rot *r)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  const real dr = (real)sim->scene->dr;
  CLSPH_TRY(open_layer_velocity(&r->open, sim));
  cl_mem pos = pset_mem(ps, sim->f_pos), kind = pset_mem(ps, sim->f_kind);
  cl_mem section = pset_mem(ps, r->open.f_section), vel = pset_mem(ps, sim->f_vel);
  cl_mem uprev = pset_mem(ps, r->f_uprev), pnear = pset_mem(ps, r->open.f_near);
  cl_mem mirror = pset_mem(ps, r->f_mirror), coef = pset_mem(ps, r->f_coef);
  CLSPH_TRY(KERN_SET(r->k_mirrors, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start),
                     KARG(pos), KARG(kind), KARG(section), KARG(r->open.d_sec), KARG(dr),
                     KARG(pnear), KARG(vel), KARG(uprev), KARG(mirror), KARG(coef)));
  CLSPH_TRY(kern_launch(sim->dev, r->k_mirrors, n, NULL));
  CLSPH_TRY(KERN_SET(r->k_dummies, KARG(n), KARG(kind), KARG(mirror), KARG(coef), KARG(pnear)));
  CLSPH_TRY(kern_launch(sim->dev, r->k_dummies, n, NULL));
done:
  return st;
}

/* After the motion: the recycling (solvers/open moves position, kind, section, velocity and
 * wall_vel), then the rest of a recycled particle's state from the entry particle it replaces:
 * u^{k−1} (an entry particle's is its wall_vel, rot_open_mirrors), the wall normal (the
 * section's n), p and φ. */
static enum clsph_status rot_open_recycle(struct sim *sim, struct rot *r)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(open_recycle(&r->open, sim));
  const int fields[] = {r->f_uprev, r->f_normal, r->f_p, r->f_phi};
  for (size_t k = 0; k < sizeof fields / sizeof *fields; ++k)
    CLSPH_TRY(open_recycle_copy(&r->open, sim, fields[k]));
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
  cl_mem mcoef = pset_mem(ps, r->f_coef);
  /* BDF2 coefficients for steps dt (now) and dt_prev (BDF1 on the first step) */
  const double w = r->dt_prev > 0.0 ? dt / r->dt_prev : 0.0;
  const double b0 = (1.0 + 2.0 * w) / (1.0 + w);
  const real a0 = (real)b0, a1 = (real)(1.0 + w), a2 = (real)(w * w / (1.0 + w));
  const real rdt = (real)dt, rho = (real)sc->rho0;
  const real nu = r->implicit ? (real)0 : (real)sc->nu; /* implicit: ν∇²ũ solved for below */
  double body[3];
  for (int a = 0; a < 3; ++a) body[a] = sc->gravity[a] + sim->body_force[a];
  const struct realv_arg accel = dev_realv(sc->dim, body);

  /* 1. the Oger correction matrices (eq 25) */
  CLSPH_TRY(ops_apply(&r->ops, OP_CORRECTION, sim->dev, &sim->grid, ps->n, pos, vol, NULL, NULL, L,
                      NULL));
  /* 2. dummy velocities and mirrors (sec 3.3.1) */
  CLSPH_TRY(KERN_SET(r->k_dummy, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start), KARG(pos),
                     KARG(vol), KARG(kind), KARG(dist), KARG(normal), KARG(uwall), KARG(vel),
                     KARG(mirror), KARG(mcoef), KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, r->k_dummy, n, NULL));
  /* 2'. entry and exit layers (sec 3.3.2-3.3.3) */
  if (r->open.nsec > 0) CLSPH_TRY(rot_open_layers(sim, r));
  /* 3. prediction (eq 9 or 5) */
  CLSPH_TRY(op_prefix(sim, r, r->k_predict, &np));
  {
    cl_uint i = 7;
    const struct karg a[] = {KARG(vel),    KARG(uprev), KARG(p),           KARG(uwall), KARG(rdt),
                             KARG(a0),     KARG(a1),    KARG(a2),          KARG(nu),    KARG(rho),
                             KARGV(accel), KARG(ustar), KARG(sim->d_flags)};
    for (size_t k = 0; k < sizeof a / sizeof *a; ++k)
      CLSPH_TRY(kern_set_at(r->k_predict, i++, a[k]));
  }
  CLSPH_TRY(kern_launch(sim->dev, r->k_predict, n, NULL));
  if (r->implicit) CLSPH_TRY(visc_solve(sim, r, dt, b0));
  if (r->open.nsec > 0) { /* ũ of the exit layers: that of their progenitor */
    cl_mem src = pset_mem(ps, r->open.f_src);
    CLSPH_TRY(KERN_SET(r->k_ustar, KARG(n), KARG(kind), KARG(src), KARG(ustar)));
    CLSPH_TRY(kern_launch(sim->dev, r->k_ustar, n, NULL));
  }
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
  /* Neumann everywhere: no Dirichlet row, reinforce; an exit's φ = 0 makes it regular */
  r->ps.opt.singular = r->open.noutflow > 0 ? PSOLVE_REGULAR : PSOLVE_REINFORCE;
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
  if (r->open.nsec > 0 && r->rotational) { /* p on the entry layers: eq 15 */
    cl_mem section = pset_mem(ps, r->open.f_section), pnear = pset_mem(ps, r->open.f_near);
    CLSPH_TRY(op_prefix(sim, r, r->k_open_p, &np));
    cl_uint k = 7;
    const struct karg a[] = {KARG(section), KARG(r->open.d_sec), KARG(pnear), KARG(vel), KARG(rho),
                             KARG(mu),      KARGV(accel),        KARG(p)};
    for (size_t q = 0; q < sizeof a / sizeof *a; ++q)
      CLSPH_TRY(kern_set_at(r->k_open_p, k++, a[q]));
    CLSPH_TRY(kern_launch(sim->dev, r->k_open_p, n, NULL));
    CLSPH_TRY(KERN_SET(r->k_dummy_p, KARG(n), KARG(kind), KARG(pnear), KARG(p)));
    CLSPH_TRY(kern_launch(sim->dev, r->k_dummy_p, n, NULL));
  }
  r->dt_prev = dt;
  /* 6. motion (+ XSPH) and shifting */
  cl_mem posn = pset_mem(ps, r->f_posn);
  const real xs = (real)r->xsph;
  CLSPH_TRY(KERN_SET(r->k_move, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start), KARG(pos),
                     KARG(vol), KARG(kind), KARG(vel), KARG(rdt), KARG(xs), KARG(posn),
                     KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, r->k_move, n, NULL));
  CLSPH_TRY(kern_copy(sim->dev, pos, posn, ps->n * (sc->dim == 3 ? 4 : 2) * sizeof(real)));
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
  if (r->open.nsec > 0) CLSPH_TRY(rot_open_recycle(sim, r));
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
  /* the CFL speed: the fluid's, and an entry's or exit's prescribed speed (a fluid at rest
   * behind an entry would otherwise get only the viscous bound: at Re = 100 that is 0.8 h/U0 and
   * the run failed at its third step) */
  double u = fmax(r->umax, open_speed(s));
  double a = hypot(hypot(s->gravity[0] + sim->body_force[0], s->gravity[1] + sim->body_force[1]),
                   s->gravity[2] + sim->body_force[2]); /* (2-D: hypot(., 0) is exact) */
  double d = HUGE_VAL;
  if (u > 0.0) d = fmin(d, 0.25 * h / u);
  if (s->nu > 0.0 && !r->implicit) d = fmin(d, 0.125 * h * h / s->nu);
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
  CLSPH_TRY(rot_force_eval(
      &r->force, sim->dev, &sim->grid, ps->n, pset_mem(ps, sim->f_pos), pset_mem(ps, sim->f_vol),
      pset_mem(ps, sim->f_kind), pset_mem(ps, sim->f_vel), pset_mem(ps, r->f_p),
      sim->scene->rho0 * sim->scene->nu, group, f->pressure, f->viscous, &f->torque));
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
  cl_kernel open[] = {r->k_mirrors, r->k_dummies, r->k_dummy_p, r->k_ustar, r->k_open_p};
  for (size_t k = 0; k < sizeof open / sizeof *open; ++k)
    if (open[k] != NULL) clReleaseKernel(open[k]);
  open_destroy(&r->open);
  cl_kernel visc[] = {r->k_visc_count, r->k_visc_coeffs, r->k_visc_split, r->k_visc_gather};
  for (size_t k = 0; k < sizeof visc / sizeof *visc; ++k)
    if (visc[k] != NULL) clReleaseKernel(visc[k]);
  if (r->implicit) psolve_destroy(&r->vs);
  psolve_destroy(&r->ps);
  ops_destroy(&r->ops);
  free(r);
}

const struct scheme_ops scheme_isph_rotational = {
    .name = "isph-rotational",
    .summary = "ISPH, rotational pressure correction, BDF2, dummy walls (Hosseini & Feng 2011)",
    .sources = sources,
    .wall_model = "dummy",
    .three_d = 1,
    .smoothing = "gaussian",
    .h_over_dr = 1.2,
    .fill_fields = SCHEME_FILL_PRESSURE,
    .options = options,
    .define = rot_define,
    .create = rot_create,
    .step = rot_step,
    .max_dt = rot_max_dt,
    .wall_force = rot_wall_force,
    .persist = rot_persist,
    .destroy = rot_destroy,
};
