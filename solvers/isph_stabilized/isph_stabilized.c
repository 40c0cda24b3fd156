/* isph_stabilized.c: stabilized incompressible SPH (Asai, Aly, Sonoda & Sakai 2012, J. Appl.
 * Math. 2012:139583, "A12") on dummy walls with virtual markers (Asai et al. 2013; the seed paper
 * S = shared/papers/stabilized_isph_virtual_marker.txt, whose equations partly did not survive
 * extraction). Laminar. One time step:
 *   1. the dummies' velocity from their markers x_m = x_w + 2 d n (S eqs 11-13; no-slip, slip or
 *      a slip ratio β_s), and their u* = u_w + Δt a (walls.cl)
 *   2. u* = u + Δt (ν L{u} + a), explicit (predict.cl)
 *   3. s* = Σ V W at the intermediate positions x* = x + Δt u*, against σ0, the same sum on the
 *      lattice (common/lattice.cl); a free surface where s* / σ0 < β_fs, its pressure that of
 *      half a spacing inside the surface (predict.cl); the source
 *      (ρ0/Δt) ∇·u* + α ρ0 (1 − s* / σ0)/Δt² (A12's stabilized PPE, S eq 8; predict.cl)
 *   4. the dummies' rows (ppe.cl): the modified virtual marker (S sec 3.3, the default), whose
 *      dummies are unknowns tied to the fluid at their on-wall marker by the non-homogeneous
 *      Neumann condition p_w = Σ W̃(x_v − x_k) [p_k + ρ0 a·(x_w − x_k)]; or the pseudo-Neumann
 *      mapping p_w = Σ W̃(x_m − x_j) p_j + ρ0 a·(x_w − x_m) of the last pressure (S sec 3.2),
 *      Dirichlet rows (walls.cl)
 *   5. the Morris Laplacian over fluid and dummies (ppe.cl; not symmetric with the modified
 *      virtual marker) solved by the device BiCGStab, the last pressure as the initial guess
 *   6. pseudo-Neumann: the dummies' pressure mapped again from the new one (S eq 22); then
 *      u^{n+1} = u* − (Δt/ρ0) Σ V (p_i + p_j) ∇W (A12's symmetric gradient) and
 *      x^{n+1} = x + Δt u^{n+1} (project.cl)
 * CHOICES (the paper gives none of these; see the kernels' comments): cubic spline (S sec 2.2)
 * with h = 1.2 dr; σ0 from the device lattice sum, never 1; the dummies' u* carries Δt a; the
 * free surface's pressure that of half a spacing in; the walls' pressure held at ≥ 0 where their
 * wall point is at the free surface; Thomas & Couchman's kernel derivative in the pressure
 * gradient for pairs closer than 2h/3; the time step 0.25 h/U, 0.125 h²/ν and 0.125 √(h/|a|)
 * (see stab_max_dt).
 * Options: alpha (α, 0 to 1, default 0.01: S "around 1% or less"), wall_pressure ("neumann",
 * S sec 3.3, the default, or "pseudo_neumann", S sec 3.2), wall_velocity ("no_slip" or "slip")
 * or slip_ratio (β_s from 0 to 1, S eq 13), surface_threshold (β_fs, 0.8 to 0.995, default
 * 0.97 in 2-D, 0.9 in 3-D), surface_detection ("density", the default, or "scan": Marrone et al.
 * 2010's scan region must be empty too, for walls that cut the lattice; predict.cl), pressure_form
 * ("total", the paper's symmetric gradient of the pressure, the default, or "dynamic": the pressure
 * equation solved for p − ρ0 a·x, the hydrostatic part exact; project.cl, with the modified virtual
 * marker only), wall_approach ("particles", the 2-D default, or "impact", the 3-D one: which
 * approaches to a wall the modified virtual marker counts; ppe.cl), shifting (C, 0 off:
 * particle shifting after the motion, not the paper's; shift.cl), wall_layers (checked against the
 * support the markers need) and the pressure solver's. The gate (options gate, a wall group,
 * gate_speed, gate_start, gate_stop): that group's dummies lift against gravity from gate_start to
 * gate_stop (gate_step), and the modified virtual marker carries their acceleration, f = g − a_W
 * (the pseudo-Neumann mapping keeps g). Left out: A12's eddy viscosity, inflow and outflow sections
 * (refused), rotating walls (refused), wall forces. A closed box under the modified virtual marker
 * has no Dirichlet row: its pressure is fixed up to a constant only (the solve reinforces the
 * diagonal), and a negative level attracts particles in the symmetric gradient. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../scheme.h"
#include "clsph_config.h"
#include "gate.h"
#include "geometry.h"
#include "log.h"
#include "poisson_op.h"
#include "psolve.h"
#include "sim.h"

struct stab {
  struct sim *sim;     /* the simulation of the current step (the operator's callbacks) */
  struct psolve_op op; /* the pressure equation over fluid and dummies (ppe.cl) */
  struct psolve ps;
  struct psolve_options popt;
  cl_uint mode;   /* the walls' pressure: STAB_PSEUDO or STAB_NEUMANN of ppe.cl */
  double d0;      /* the Laplacian's diagonal on the lattice: the scale of the non-fluid rows */
  double alpha;   /* α of the density-invariance term (A12) */
  double beta_fs; /* free surface where s* / σ0 < β_fs */
  cl_uint fs_min; /* or where fewer than this many particles lie within the support at x* */
  cl_uint scan;   /* 1: and where the scan region is empty (surface_detection = "scan") */
  int dynamic;    /* pressure_form = "dynamic": the pressure equation's unknown is p − ρ0 a·x */
  double c_shift; /* particle shifting's C (shift.cl; 0: off, the paper's) */
  double beta_s;  /* slip ratio: 0 no-slip, 1 free slip (S eq 13) */
  double sigma0;  /* Σ dr² W over the full lattice support, in the build's precision */
  double umax;    /* largest fluid speed at the last max_dt, m/s */
  int dim;        /* the scene's dimension */
  /* the gate: the dummies of the walls of group `gate` lift along −g/|g| at gate_speed from
   * gate_start to gate_stop (Lobovsky et al.'s set-up, S sec 4.2; solvers/gate) */
  struct gate gate;
  struct realv_arg a_gate; /* its acceleration over this step */
  int f_p, f_fs, f_rhostar, f_dist, f_normal, f_uwall, f_ustar, f_div, f_rhs, f_dir, f_acc,
      f_pshift;
  cl_kernel k_lattice, k_wall_vel, k_wall_p, k_predict, k_source, k_project, k_move, k_diag0,
      k_shift, k_count, k_coeffs, k_apply, k_diag, k_neumann, k_pshift, k_papply;
  cl_mem d_sums; /* the lattice sums (2 reals) */
};

static const char *const sources[] = {POISSON_SOURCES,
                                      GATE_SOURCES,
                                      "common/marker.cl",
                                      "common/lattice.cl",
                                      "isph_stabilized/walls.cl",
                                      "isph_stabilized/ppe.cl",
                                      "isph_stabilized/predict.cl",
                                      "isph_stabilized/project.cl",
                                      "isph_stabilized/shift.cl",
                                      NULL};
static const char *const options[] = {"alpha",
                                      "wall_pressure",
                                      "wall_velocity",
                                      "slip_ratio",
                                      "surface_threshold",
                                      "surface_detection",
                                      "pressure_form",
                                      "shifting",
                                      "wall_layers",
                                      "gate",
                                      "gate_speed",
                                      "gate_start",
                                      "gate_stop",
                                      "wall_approach",
                                      PSOLVE_OPTION_NAMES,
                                      NULL};

static const struct scene_option *option(const struct scene *s, const char *key)
{
  for (int i = 0; i < s->noptions; ++i)
    if (strcmp(s->options[i].key, key) == 0) return &s->options[i];
  return NULL;
}

/* a text option among `names` (NULL-terminated): its index, or `fallback` when not given */
static enum clsph_status option_choice(const struct scene *s, const char *key,
                                       const char *const *names, int fallback, int *out)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene_option *o = option(s, key);
  *out = fallback;
  if (o == NULL) goto done;
  char list[160] = "", given[SCENE_NAME + 32];
  size_t used = 0;
  for (int k = 0; names[k] != NULL; ++k) {
    if (!o->is_number && strcmp(o->text, names[k]) == 0) {
      *out = k;
      goto done;
    }
    used += (size_t)snprintf(list + used, used < sizeof list ? sizeof list - used : 0, "%s\"%s\"",
                             k ? ", " : "", names[k]);
  }
  if (o->is_number)
    snprintf(given, sizeof given, "%g", o->number);
  else
    snprintf(given, sizeof given, "\"%s\"", o->text);
  CLSPH_CHECK(0, CLSPH_E_INPUT, "%s:%d: isph-stabilized option %s must be one of %s, not %s",
              s->case_path, s->scheme_line, key, list, given);
done:
  return st;
}

/* a number option from lo to hi: `what` names the quantity, `hint` (may be "") follows the
 * range in the message */
static enum clsph_status option_number(const struct scene *s, const char *key, double lo, double hi,
                                       const char *what, const char *hint, double *v)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene_option *o = option(s, key);
  if (o == NULL) goto done;
  CLSPH_CHECK(o->is_number, CLSPH_E_INPUT,
              "%s:%d: isph-stabilized option %s must be a number from %g to %g, not \"%s\"",
              s->case_path, s->scheme_line, key, lo, hi, o->text);
  CLSPH_CHECK(o->number >= lo && o->number <= hi, CLSPH_E_INPUT,
              "%s:%d: isph-stabilized option %s = %g is out of range: %s must be from %g to %g%s",
              s->case_path, s->scheme_line, key, o->number, what, lo, hi, hint);
  *v = o->number;
done:
  return st;
}

static enum clsph_status read_options(const struct sim *sim, struct stab *b)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *sc = sim->scene;
  b->alpha = 0.01; /* S sec 2.3: "around 1% or less"; DESIGN.md */
  CLSPH_TRY(
      option_number(sc, "alpha", 0.0, 1.0,
                    "the relaxation coefficient α of the density-invariance term (Asai et al. "
                    "2012)",
                    " (about 0.01 or less in the paper)", &b->alpha));
  /* the order of ppe.cl's STAB_PSEUDO and STAB_NEUMANN */
  static const char *const wallp_names[] = {"pseudo_neumann", "neumann", NULL};
  int wallp = 1;
  CLSPH_TRY(option_choice(sc, "wall_pressure", wallp_names, 1, &wallp));
  b->mode = (cl_uint)wallp;
  static const char *const wallv_names[] = {"no_slip", "slip", NULL};
  int slip = 0;
  CLSPH_TRY(option_choice(sc, "wall_velocity", wallv_names, 0, &slip));
  b->beta_s = slip;
  CLSPH_CHECK(option(sc, "wall_velocity") == NULL || option(sc, "slip_ratio") == NULL,
              CLSPH_E_INPUT,
              "%s:%d: isph-stabilized options wall_velocity and slip_ratio both set the walls' "
              "velocity condition: give wall_velocity or slip_ratio, not both",
              sc->case_path, sc->scheme_line);
  CLSPH_TRY(option_number(sc, "slip_ratio", 0.0, 1.0,
                          "the slip ratio β_s of the walls (Asai et al. 2013, S eq 13)",
                          " (0 no-slip, 1 free slip)", &b->beta_s));
  /* 2-D: the top row of a lattice reads 0.78 at h = 1.2 dr, the second 0.997. 3-D, measured
   * (cases/hydrostatic3d.lua): the top row 0.79-0.81, but the jostle of the fluid below opens
   * gaps that read 0.963 (dr = H/20: four particles 0.1 dr off the lattice at t = 0.25 s), which
   * 0.97 takes for free surface (p = 0 in the water, 88% off); at H/10 over 2 s the pressure RMS
   * is 0.063 with 0.97 and particles cross the walls at 18 steps, 0.0234 over 4 s with 0.9 */
  b->beta_fs = sc->dim == 3 ? 0.9 : 0.97;
  CLSPH_TRY(option_number(sc, "surface_threshold", 0.8, 0.995, "the free-surface threshold β_fs",
                          " (free surface where ρ* / ρ0 < β_fs)", &b->beta_fs));
  /* Spray: a clump of a few particles pressed together reads a full density (four at 0.35 dr,
   * the n = 80 dam break's run-up jet at t = 0.63 s: s* / σ0 0.97-1.005) and took interior rows
   * with no surface row nearby, a system the solve could not meet (its residual rose to 1e107 in
   * 1000 iterations and the step threw the fluid out). A particle with fewer neighbours within
   * the support than a quarter of a full lattice support's (2-D, h = 1.2 dr: 5 of 20; a flat
   * surface has 12, a right-angled corner of it 7) is free surface whatever its density. */
  {
    const double reach = sim->sm.support / sc->dr;
    const int m = (int)ceil(reach);
    long full = 0;
    for (int i = -m; i <= m; ++i)
      for (int j = -m; j <= m; ++j)
        for (int k = sc->dim == 3 ? -m : 0; k <= (sc->dim == 3 ? m : 0); ++k)
          if ((i || j || k) && (double)(i * i + j * j + k * k) < reach * reach) ++full;
    b->fs_min = (cl_uint)(full / 4);
  }
  static const char *const detect_names[] = {"density", "scan", NULL};
  int scan = 0;
  CLSPH_TRY(option_choice(sc, "surface_detection", detect_names, 0, &scan));
  b->scan = (cl_uint)scan;
  b->c_shift = 0.0;
  CLSPH_TRY(option_number(sc, "shifting", 0.0, 2.0, "the particle shifting coefficient C",
                          " (0 off, the paper's; δr = −C h² Σ V ∇W)", &b->c_shift));
  static const char *const form_names[] = {"total", "dynamic", NULL};
  CLSPH_TRY(option_choice(sc, "pressure_form", form_names, 0, &b->dynamic));
  /* measured: the pseudo-Neumann walls' Dirichlet pressure, mapped from the last step's, does not
   * carry the shift's exactness, and the paper's tank (δr = 0.01 m) ran off under it (floor 36% off
   * at 2 s, particles behind the floor from 0.3 s) */
  CLSPH_CHECK(!b->dynamic || b->mode == 1, CLSPH_E_INPUT,
              "%s:%d: isph-stabilized option pressure_form = \"dynamic\" needs wall_pressure = "
              "\"neumann\" (the modified virtual marker): the pseudo-Neumann walls' pressure is "
              "mapped from the last step's and does not hold the hydrostatic part exactly",
              sc->case_path, sc->scheme_line);
  /* P = p − ρ0 a·x jumps by ρ0 a·L across a periodic axis along which a pushes */
  for (int a = 0; a < sc->dim && b->dynamic; ++a)
    CLSPH_CHECK(!sc->periodic[a] || sc->gravity[a] + sc->body_force[a] == 0.0, CLSPH_E_INPUT,
                "%s:%d: isph-stabilized option pressure_form = \"dynamic\" cannot run with gravity "
                "or a body force along the periodic %c axis (%g m/s²): its unknown p − ρ0 a·x "
                "would jump across the period",
                sc->case_path, sc->scheme_line, "xyz"[a], sc -> gravity[a] + sc -> body_force[a]);
  CLSPH_TRY(gate_read(sc, "isph-stabilized", &b->gate)); /* the gate (solvers/gate) */
  /* the dummies fill layers dr behind the wall; the fluid's first row, dr/2 in front of it, sees
   * support − dr/2 behind it */
  const struct scene_option *lo = option(sc, "wall_layers");
  const int layers = lo != NULL ? (int)lo->number : 3; /* sim.c checked it is 1 to 8 */
  const double need = sim->sm.support - 0.5 * sc->dr;
  CLSPH_CHECK(
      sc->nwalls == 0 || layers * sc->dr >= need * (1.0 - 1e-9), CLSPH_E_INPUT,
      "%s: isph-stabilized: wall_layers = %d puts dummies %.3g m deep, less than the %.3g m "
      "(the kernel support less half a spacing) that the virtual markers of the fluid "
      "next to a wall need: wall_layers >= %d",
      sc->case_path, layers, layers * sc->dr, need, (int)ceil(need / sc->dr - 1e-9));
done:
  return st;
}

/* The operator arguments every neighbour kernel starts with (OP_ARGS); returns the next index. */
static enum clsph_status op_prefix(struct sim *sim, cl_kernel k, cl_uint *n)
{
  *n = (cl_uint)sim->ps.n;
  cl_mem pos = pset_mem(&sim->ps, sim->f_pos), vol = pset_mem(&sim->ps, sim->f_vol);
  cl_mem none = NULL; /* L: no kernel-gradient correction */
  return KERN_SET(k, KARG(*n), KARG(sim->grid.geom), KARG(sim->grid.d_start), KARG(pos), KARG(vol),
                  KARG(none));
}

/* the remaining arguments of a kernel, from index `first` */
static enum clsph_status set_from(cl_kernel k, cl_uint first, size_t count, const struct karg *a)
{
  enum clsph_status st = CLSPH_OK;
  for (size_t q = 0; q < count; ++q) CLSPH_TRY(kern_set_at(k, first + (cl_uint)q, a[q]));
done:
  return st;
}

static struct realv_arg body_accel(const struct sim *sim)
{
  const struct scene *sc = sim->scene;
  double a[3];
  for (int k = 0; k < 3; ++k) a[k] = sc->gravity[k] + sim->body_force[k];
  return dev_realv(sc->dim, a);
}

/* p of the dummies by the pseudo-Neumann mapping (walls.cl); into rhs too when write_rhs */
static enum clsph_status wall_pressure(struct sim *sim, struct stab *b, cl_uint write_rhs)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  const real rho = (real)sim->scene->rho0, d0 = (real)b->d0;
  const struct realv_arg accel = body_accel(sim);
  cl_mem pos = pset_mem(ps, sim->f_pos), vol = pset_mem(ps, sim->f_vol);
  cl_mem kind = pset_mem(ps, sim->f_kind), dist = pset_mem(ps, b->f_dist);
  cl_mem normal = pset_mem(ps, b->f_normal), p = pset_mem(ps, b->f_p);
  cl_mem rhs = pset_mem(ps, b->f_rhs);
  CLSPH_TRY(KERN_SET(b->k_wall_p, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start), KARG(pos),
                     KARG(vol), KARG(kind), KARG(dist), KARG(normal), KARG(rho), KARGV(accel),
                     KARG(write_rhs), KARG(d0), KARG(p), KARG(rhs), KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, b->k_wall_p, n, NULL));
done:
  return st;
}

/* The pressure operator (ppe.cl): psolve_op's callbacks, ctx the struct stab of the step. */
struct ppe_args {
  cl_mem kind, dist, normal, dir;
  real d0;
};

static struct ppe_args ppe_args(const struct stab *b)
{
  const struct pset *ps = &b->sim->ps;
  return (struct ppe_args){pset_mem(ps, b->sim->f_kind), pset_mem(ps, b->f_dist),
                           pset_mem(ps, b->f_normal), pset_mem(ps, b->f_dir), (real)b->d0};
}

static enum clsph_status ppe_count(void *ctx, cl_mem count)
{
  enum clsph_status st = CLSPH_OK;
  struct stab *b = ctx;
  struct ppe_args q = ppe_args(b);
  cl_uint n;
  CLSPH_TRY(op_prefix(b->sim, b->k_count, &n));
  const struct karg a[] = {KARG(q.kind), KARG(q.dist), KARG(q.normal), KARG(q.dir), KARG(count)};
  CLSPH_TRY(set_from(b->k_count, 6, sizeof a / sizeof *a, a));
  CLSPH_TRY(kern_launch(b->sim->dev, b->k_count, n, NULL));
done:
  return st;
}

static enum clsph_status ppe_coefficients(void *ctx, cl_mem row, cl_mem col, cl_mem val)
{
  enum clsph_status st = CLSPH_OK;
  struct stab *b = ctx;
  struct ppe_args q = ppe_args(b);
  cl_uint n;
  CLSPH_TRY(op_prefix(b->sim, b->k_coeffs, &n));
  const struct karg a[] = {KARG(q.kind), KARG(q.dist), KARG(q.normal), KARG(q.dir),
                           KARG(q.d0),   KARG(row),    KARG(col),      KARG(val)};
  CLSPH_TRY(set_from(b->k_coeffs, 6, sizeof a / sizeof *a, a));
  CLSPH_TRY(kern_launch(b->sim->dev, b->k_coeffs, n, NULL));
done:
  return st;
}

static enum clsph_status ppe_apply(void *ctx, cl_mem x, cl_mem y)
{
  enum clsph_status st = CLSPH_OK;
  struct stab *b = ctx;
  struct ppe_args q = ppe_args(b);
  cl_uint n;
  CLSPH_TRY(op_prefix(b->sim, b->k_apply, &n));
  const struct karg a[] = {KARG(q.kind), KARG(q.dist), KARG(q.normal), KARG(q.dir),
                           KARG(q.d0),   KARG(x),      KARG(y)};
  CLSPH_TRY(set_from(b->k_apply, 6, sizeof a / sizeof *a, a));
  CLSPH_TRY(kern_launch(b->sim->dev, b->k_apply, n, NULL));
done:
  return st;
}

static enum clsph_status ppe_diagonal(void *ctx, cl_mem d)
{
  enum clsph_status st = CLSPH_OK;
  struct stab *b = ctx;
  struct ppe_args q = ppe_args(b);
  cl_uint n;
  CLSPH_TRY(op_prefix(b->sim, b->k_diag, &n));
  const struct karg a[] = {KARG(q.kind), KARG(q.dir), KARG(q.d0), KARG(d)};
  CLSPH_TRY(set_from(b->k_diag, 6, sizeof a / sizeof *a, a));
  CLSPH_TRY(kern_launch(b->sim->dev, b->k_diag, n, NULL));
done:
  return st;
}

/* p += sign ρ0 a·x over every particle (pressure_form = "dynamic", ppe.cl stab_hydro_shift) */
static enum clsph_status hydro_shift(struct sim *sim, struct stab *b, double sign)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  const real rho = (real)sim->scene->rho0, sg = (real)sign;
  const struct realv_arg accel = body_accel(sim);
  cl_mem pos = pset_mem(ps, sim->f_pos), p = pset_mem(ps, b->f_p);
  CLSPH_TRY(KERN_SET(b->k_shift, KARG(n), KARG(pos), KARG(rho), KARGV(accel), KARG(sg), KARG(p)));
  CLSPH_TRY(kern_launch(sim->dev, b->k_shift, n, NULL));
done:
  return st;
}

/* the right-hand side of the dummies' rows under the modified virtual marker (ppe.cl) */
static enum clsph_status wall_neumann(struct sim *sim, struct stab *b, double dt)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  const real rho = (real)sim->scene->rho0, d0 = (real)b->d0, rdt = (real)dt;
  const struct realv_arg force = body_accel(sim); /* f = g − a_W: a_W of the gate in the kernel */
  cl_mem pos = pset_mem(ps, sim->f_pos), vol = pset_mem(ps, sim->f_vol);
  cl_mem kind = pset_mem(ps, sim->f_kind), dist = pset_mem(ps, b->f_dist);
  cl_mem normal = pset_mem(ps, b->f_normal), rhs = pset_mem(ps, b->f_rhs);
  cl_mem dir = pset_mem(ps, b->f_dir), p = pset_mem(ps, b->f_p);
  cl_mem vel = pset_mem(ps, sim->f_vel), uwall = pset_mem(ps, b->f_uwall);
  /* no gate: a NULL buffer (OpenCL 1.2 clSetKernelArg), which ppe.cl reads as "no dummy moves" */
  cl_mem gate = b->gate.on ? pset_mem(ps, b->gate.f_gate) : NULL;
  CLSPH_TRY(KERN_SET(b->k_neumann, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start),
                     KARG(pos), KARG(vol), KARG(kind), KARG(dist), KARG(normal), KARG(rho),
                     KARGV(force), KARG(d0), KARG(p), KARG(vel), KARG(uwall), KARG(rdt), KARG(gate),
                     KARGV(b->a_gate), KARG(dir), KARG(rhs), KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, b->k_neumann, n, NULL));
done:
  return st;
}

/* The dummies binned in cells of side dr from lo: nc[0] x nc[1] x nc[2] of them (nc[2] = 1 in
 * 2-D), first[c] .. first[c + 1] in `order`. */
struct dummy_bins {
  int dim;
  double lo[3], dr;
  long nc[3];
  size_t *order, *first;
};

static long bin_of(const struct dummy_bins *db, const double *x, int a)
{
  return (long)floor((x[a] - db->lo[a]) / db->dr);
}

/* A dummy of wall w within 0.75 dr of y (0.9 dr in 3-D) whose normal does not face away from n
 * (at most 90° from it: behind one face of a solid's convex right-angled corner lie the dummies of
 * the other face, turned by 90°; a plate's far face turns them by 180°)? The radius holds a
 * lattice point wherever y falls: the square lattice's farthest point from its nodes is 0.71 dr
 * away, the cubic's 0.87 dr (a point behind a sphere's or a cylinder's curved face falls
 * anywhere). */
static int dummy_near(const struct geom *geo, const struct dummy_bins *db, const double *y, int w,
                      const double *n)
{
  const int dim = db->dim;
  long c[3] = {0, 0, 0};
  for (int a = 0; a < dim; ++a) c[a] = bin_of(db, y, a);
  for (long kz = dim == 3 ? c[2] - 1 : 0; kz <= (dim == 3 ? c[2] + 1 : 0); ++kz)
    for (long ky = c[1] - 1; ky <= c[1] + 1; ++ky)
      for (long kx = c[0] - 1; kx <= c[0] + 1; ++kx) {
        if (kx < 0 || ky < 0 || kz < 0 || kx >= db->nc[0] || ky >= db->nc[1] || kz >= db->nc[2])
          continue;
        const size_t cell =
            ((size_t)kz * (size_t)db->nc[1] + (size_t)ky) * (size_t)db->nc[0] + (size_t)kx;
        for (size_t k = db->first[cell]; k < db->first[cell + 1]; ++k) {
          const size_t d = db->order[k];
          const double *q = geo->x + (size_t)dim * d, *m = geo->normal + (size_t)dim * d;
          double r2 = 0.0, mn = 0.0;
          for (int a = 0; a < dim; ++a) {
            r2 += (q[a] - y[a]) * (q[a] - y[a]);
            mn += m[a] * n[a];
          }
          const double near = dim == 3 ? 0.81 : 0.5625;
          if (geo->group[d] == w && r2 < near * db->dr * db->dr && mn > -1e-6) return 1;
        }
      }
  return 0;
}

/* a point as "(x, y)" or "(x, y, z)" */
static const char *point_text(char *buf, size_t size, const double *x, int dim)
{
  if (dim == 3)
    snprintf(buf, size, "(%g, %g, %g)", x[0], x[1], x[2]);
  else
    snprintf(buf, size, "(%g, %g)", x[0], x[1]);
  return buf;
}

/* The walls' geometry against what the virtual markers need (host, in double, once):
 *   thickness: behind every dummy of the first row (within dr of its wall) the solid holds
 *     dummies of the same wall, not facing the other way, over the kernel support less half a
 * spacing (the reach of the fluid nearest the wall): a plate thinner than that splits its dummies
 *     between its two faces and the fluid on either side misses part of its support;
 *   markers: every velocity marker x_m = x_d + 2 d n lies inside the domain on each non-periodic
 *     axis (no fluid can be beyond it: the dummy would read a dry marker next to the fluid); the
 *     gate's at both ends of its lift, and its dummies stay inside the neighbour grid. */
static enum clsph_status check_walls(const struct sim *sim, const struct stab *b)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *sc = sim->scene;
  const struct geom *geo = &sim->geom;
  const int dim = sc->dim;
  const double dr = sc->dr, tol = 1e-9 * dr;
  struct dummy_bins db = {.dim = dim, .dr = dr, .nc = {1, 1, 1}};
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  char t0[96], t1[96], t2[96];
  size_t nd = 0;
  CLSPH_TRY(gate_check(sim, &b->gate, "isph-stabilized")); /* its dummies stay in the grid */
  for (size_t i = 0; i < geo->n; ++i) {
    if (geo->kind[i] != KIND_DUMMY) continue;
    ++nd;
    const double *x0 = geo->x + (size_t)dim * i, *n = geo->normal + (size_t)dim * i;
    const struct scene_wall *w = &sc->walls[geo->group[i]];
    const int gate = b->gate.on && strcmp(w->group, b->gate.group) == 0;
    const double lift = gate ? b->gate.speed * (b->gate.stop - b->gate.start) : 0.0;
    double x1[3] = {0.0, 0.0, 0.0}, m[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < dim; ++a) x1[a] = x0[a] + lift * b->gate.dir[a];
    for (int a = 0; a < dim; ++a) {
      lo[a] = fmin(lo[a], x0[a]);
      hi[a] = fmax(hi[a], x0[a]);
    }
    for (int e = 0; e < (gate ? 2 : 1); ++e) {
      const double *x = e == 0 ? x0 : x1;
      for (int a = 0; a < dim; ++a) m[a] = x[a] + 2.0 * geo->dist[i] * n[a];
      for (int a = 0; a < dim; ++a)
        CLSPH_CHECK(sc->periodic[a] || (m[a] >= sc->lo[a] - tol && m[a] <= sc->hi[a] + tol),
                    CLSPH_E_INPUT,
                    "%s:%d: wall (group '%s'): the virtual marker of the dummy at %s%s falls at "
                    "%s, outside the domain along %c ([%g, %g]): the wall's fluid side faces the "
                    "domain's edge closer than the %.3g m (twice the dummy's depth) its markers "
                    "reach",
                    sc->case_path, w->line, w->group, point_text(t0, sizeof t0, x, dim),
                    e == 1 ? " after the gate's lift" : "", point_text(t1, sizeof t1, m, dim),
                    "xyz"[a], sc -> lo[a], sc -> hi[a], 2.0 * geo -> dist[i]);
    }
  }
  if (nd == 0) goto done;
  /* bin the dummies in cells of side dr */
  size_t ncell = 1;
  for (int a = 0; a < dim; ++a) {
    db.lo[a] = lo[a];
    db.nc[a] = (long)floor((hi[a] - lo[a]) / dr) + 1;
    ncell *= (size_t)db.nc[a];
  }
  db.order = malloc(nd * sizeof *db.order);
  db.first = calloc(ncell + 1, sizeof *db.first);
  CLSPH_CHECK(db.order != NULL && db.first != NULL, CLSPH_E_NOMEM, "out of memory");
#define CELL(i)                                                                                    \
  (((size_t)(dim == 3 ? bin_of(&db, geo->x + 3 * (i), 2) : 0) * (size_t)db.nc[1] +                 \
    (size_t)bin_of(&db, geo->x + (size_t)dim * (i), 1)) *                                          \
       (size_t)db.nc[0] +                                                                          \
   (size_t)bin_of(&db, geo->x + (size_t)dim * (i), 0))
  for (size_t i = 0; i < geo->n; ++i)
    if (geo->kind[i] == KIND_DUMMY) ++db.first[CELL(i) + 1];
  for (size_t c = 0; c < ncell; ++c) db.first[c + 1] += db.first[c];
  for (size_t i = 0; i < geo->n; ++i) /* first[c] moves to the cell's end; restored below */
    if (geo->kind[i] == KIND_DUMMY) db.order[db.first[CELL(i)]++] = i;
  for (size_t c = ncell; c > 0; --c) db.first[c] = db.first[c - 1];
  db.first[0] = 0;
#undef CELL
  const double reach = sim->sm.support - 0.5 * dr;
  const int steps = (int)ceil(reach / dr - 1e-9);
  for (size_t i = 0; i < geo->n; ++i) {
    if (geo->kind[i] != KIND_DUMMY || geo->dist[i] > dr) continue;
    const double *x = geo->x + (size_t)dim * i, *n = geo->normal + (size_t)dim * i;
    double q[3] = {0.0, 0.0, 0.0}, y[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < dim; ++a) q[a] = x[a] + geo->dist[i] * n[a];
    for (int k = 1; k <= steps; ++k) {
      const double depth = fmin(k * dr, reach) + 0.5 * dr;
      for (int a = 0; a < dim; ++a) y[a] = q[a] - depth * n[a];
      const struct scene_wall *w = &sc->walls[geo->group[i]];
      CLSPH_CHECK(dummy_near(geo, &db, y, geo->group[i], n), CLSPH_E_INPUT,
                  "%s:%d: wall (group '%s') is too thin for the virtual markers: behind %s "
                  "the solid holds no dummy of this side %.3g m deep, and the fluid next to it "
                  "reaches %.3g m behind the wall (the kernel support %.3g m less half a spacing, "
                  "dr = %g): make it at least %.3g m thick",
                  sc->case_path, w->line, w->group, point_text(t2, sizeof t2, q, dim), depth, reach,
                  sim->sm.support, dr, 2.0 * reach);
    }
  }
done:
  free(db.order);
  free(db.first);
  return st;
}

static void stab_destroy(void *state);

static enum clsph_status stab_create(struct sim *sim, void **state)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *sc = sim->scene;
  const struct geom *geo = &sim->geom;
  struct stab *b = calloc(1, sizeof *b);
  real *host = NULL;
  CLSPH_CHECK(b != NULL, CLSPH_E_NOMEM, "isph-stabilized: out of memory");
  CLSPH_CHECK(sc->nsections == 0, CLSPH_E_INPUT,
              "%s: isph-stabilized has no inflow or outflow sections", sc->case_path);
  for (int w = 0; w < sc->nwalls; ++w)
    CLSPH_CHECK(sc->walls[w].motion != SCENE_ROTATING, CLSPH_E_UNSUPPORTED,
                "%s:%d: isph-stabilized: wall (group '%s') rotates; its dummies do not move with "
                "it (fixed and sliding walls only)",
                sc->case_path, sc->walls[w].line, sc->walls[w].group);
  for (size_t i = 0; i < geo->n; ++i)
    CLSPH_CHECK(geo->kind[i] == KIND_FLUID || geo->kind[i] == KIND_DUMMY, CLSPH_E_UNSUPPORTED,
                "%s: isph-stabilized has a particle of kind %d (fluid and dummy walls only)",
                sc->case_path, geo->kind[i]);
  b->dim = sc->dim;
  const double still[3] = {0.0, 0.0, 0.0};
  b->a_gate = dev_realv(sc->dim, still); /* until a gate moves (gate_step) */
  CLSPH_TRY(read_options(sim, b));
  CLSPH_TRY(check_walls(sim, b));
  CLSPH_TRY(sim_psolve_options(sim, &b->popt));
  /* fields: the wall geometry of the dummies, then the scheme's state */
  struct pset *ps = &sim->ps;
  const size_t dim = (size_t)sc->dim, stride = dim == 3 ? 4 : 2; /* realv */
  const size_t rv = stride * sizeof(real);
  host = calloc(stride * geo->n + 1, sizeof *host);
  CLSPH_CHECK(host != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t i = 0; i < geo->n; ++i) host[i] = (real)geo->dist[i];
  CLSPH_TRY(pset_add(ps, sim->dev, "wall_dist", sizeof(real), host, &b->f_dist));
  /* (the padding of a 3-D real4 stays 0: every length and dot product reads it) */
  memset(host, 0, (stride * geo->n + 1) * sizeof *host);
  for (size_t i = 0; i < geo->n; ++i)
    for (size_t a = 0; a < dim; ++a) host[stride * i + a] = (real)geo->normal[dim * i + a];
  CLSPH_TRY(pset_add(ps, sim->dev, "wall_normal", rv, host, &b->f_normal));
  for (size_t i = 0; i < geo->n; ++i)
    for (size_t a = 0; a < dim; ++a) host[stride * i + a] = (real)geo->v[dim * i + a];
  CLSPH_TRY(pset_add(ps, sim->dev, "wall_vel", rv, host, &b->f_uwall));
  for (size_t i = 0; i < geo->n; ++i) /* fill { pressure }: the first guess and wall mapping */
    host[i] = i < geo->nfluid && isfinite(geo->p0[i]) ? (real)geo->p0[i] : 0;
  CLSPH_TRY(pset_add(ps, sim->dev, "p", sizeof(real), host, &b->f_p));
  CLSPH_TRY(pset_add(ps, sim->dev, "free_surface", sizeof(cl_uint), NULL, &b->f_fs));
  pset_describe(ps, b->f_fs, PF_UINT, 1, 1);
  CLSPH_TRY(pset_add(ps, sim->dev, "rho_star", sizeof(real), NULL, &b->f_rhostar));
  CLSPH_TRY(pset_add(ps, sim->dev, "div_ustar", sizeof(real), NULL, &b->f_div));
  const struct {
    const char *name;
    size_t elem;
    int *f;
  } hidden[] = {
      {"ustar", rv, &b->f_ustar}, {"rhs", sizeof(real), &b->f_rhs}, {"accel", rv, &b->f_acc}};
  for (size_t k = 0; k < sizeof hidden / sizeof *hidden; ++k) {
    CLSPH_TRY(pset_add(ps, sim->dev, hidden[k].name, hidden[k].elem, NULL, hidden[k].f));
    pset_describe(ps, *hidden[k].f, PF_REAL, 0, 0);
  }
  CLSPH_TRY(gate_create(sim, &b->gate)); /* a scene without a gate pays nothing for it */
  if (b->c_shift > 0.0) {
    CLSPH_TRY(pset_add(ps, sim->dev, "shift", rv, NULL, &b->f_pshift));
    pset_describe(ps, b->f_pshift, PF_REAL, (int)dim, 0);
  }
  CLSPH_TRY(pset_add(ps, sim->dev, "dirichlet", sizeof(cl_uint), NULL, &b->f_dir));
  pset_describe(ps, b->f_dir, PF_UINT, 0, 0);
  pset_describe(ps, b->f_dist, PF_REAL, 0, 0);
  pset_describe(ps, b->f_normal, PF_REAL, 0, 0);
  pset_describe(ps, b->f_uwall, PF_REAL, 0, 0);
  /* kernels, operator, solver */
  const struct {
    cl_kernel *k;
    const char *name;
  } ks[] = {{&b->k_lattice, "lattice_sums"},       {&b->k_wall_vel, "stab_wall_velocity"},
            {&b->k_wall_p, "stab_wall_pressure"},  {&b->k_predict, "stab_predict"},
            {&b->k_source, "stab_source"},         {&b->k_project, "stab_project"},
            {&b->k_shift, "stab_hydro_shift"},     {&b->k_move, "stab_move"},
            {&b->k_diag0, "stab_lattice_diag"},    {&b->k_count, "stab_ppe_count"},
            {&b->k_coeffs, "stab_ppe_coeffs"},     {&b->k_apply, "stab_ppe_apply"},
            {&b->k_diag, "stab_ppe_diag"},         {&b->k_neumann, "stab_wall_neumann"},
            {&b->k_pshift, "stab_particle_shift"}, {&b->k_papply, "stab_apply_shift"}};
  for (size_t k = 0; k < sizeof ks / sizeof *ks; ++k)
    CLSPH_TRY(prog_kernel(sim->prog, ks[k].name, ks[k].k));
  CLSPH_TRY(psolve_create(sim->dev, sim->prog, ps->cap, &b->popt, &b->ps));
  /* σ0: the kernel sum of a full support on the lattice, on the device (common/lattice.cl) */
  real sums[2];
  const real dr = (real)sc->dr;
  const struct smooth_dev smd = smoothing_dev(&sim->sm);
  CLSPH_TRY(kern_buffer(sim->dev, sizeof sums, NULL, &b->d_sums, "lattice sums"));
  CLSPH_TRY(KERN_SET(b->k_lattice, KARG(smd), KARG(dr), KARG(b->d_sums)));
  CLSPH_TRY(kern_launch(sim->dev, b->k_lattice, 1, NULL));
  CLSPH_TRY(kern_read(sim->dev, b->d_sums, sizeof sums, sums));
  b->sigma0 = (double)sums[0];
  CLSPH_TRY(KERN_SET(b->k_diag0, KARG(smd), KARG(dr), KARG(b->d_sums)));
  CLSPH_TRY(kern_launch(sim->dev, b->k_diag0, 1, NULL));
  CLSPH_TRY(kern_read(sim->dev, b->d_sums, sizeof sums, sums));
  b->d0 = (double)sums[0]; /* negative: the Morris diagonal of a full support */
  CLSPH_CHECK(b->sigma0 > 0.5 && b->sigma0 < 1.5, CLSPH_E_INPUT,
              "%s: isph-stabilized: the kernel sum of the lattice is %g, not about 1: the "
              "smoothing length (h_over_dr) is too small for the particle spacing",
              sc->case_path, b->sigma0);
  log_debug("isph-stabilized: alpha %g, wall pressure %s, slip ratio %g, free surface below "
            "rho*/rho0 = %g%s or with fewer than %u neighbours, lattice sum %.8g, Laplacian "
            "diagonal %.8g",
            b->alpha, b->mode == 1 ? "modified virtual marker (Neumann)" : "pseudo-Neumann",
            b->beta_s, b->beta_fs, b->scan ? " with an empty scan region" : "", b->fs_min,
            b->sigma0, b->d0);
  b->op = (struct psolve_op){.ctx = b,
                             .apply = ppe_apply,
                             .diagonal = ppe_diagonal,
                             .row_counts = ppe_count,
                             .coefficients = ppe_coefficients};
  *state = b;
  b = NULL;
done:
  free(host);
  stab_destroy(b); /* on failure: what was made so far */
  return st;
}

/* The gate over [t, t + Δt] (solvers/gate: its dummies moved, their wall velocity), and its
 * acceleration since the last step (the a_W of f = g − a_W in the walls' Neumann condition). */
static enum clsph_status gate_step(struct sim *sim, struct stab *b, double dt)
{
  enum clsph_status st = CLSPH_OK;
  double prev[3], v[3], acc[3];
  memcpy(prev, b->gate.v_prev, sizeof prev);
  CLSPH_TRY(gate_move(sim, &b->gate, sim->time, dt, pset_mem(&sim->ps, b->f_uwall), v));
  for (int a = 0; a < 3; ++a) acc[a] = (v[a] - prev[a]) / dt;
  b->a_gate = dev_realv(sim->scene->dim, acc);
done:
  return st;
}

static enum clsph_status stab_step(struct sim *sim, void *state, double dt)
{
  enum clsph_status st = CLSPH_OK;
  struct stab *b = state;
  const struct scene *sc = sim->scene;
  struct pset *ps = &sim->ps;
  cl_uint n;
  b->sim = sim;
#define M(f) cl_mem f = pset_mem(ps, b->f_##f)
  M(p);
  M(fs);
  M(rhostar);
  M(dist);
  M(normal);
  M(uwall);
  M(ustar);
  M(div);
  M(rhs);
  M(dir);
  M(acc);
#undef M
  cl_mem pos = pset_mem(ps, sim->f_pos), vol = pset_mem(ps, sim->f_vol);
  cl_mem vel = pset_mem(ps, sim->f_vel), kind = pset_mem(ps, sim->f_kind);
  const real rdt = (real)dt, rho = (real)sc->rho0, nu = (real)sc->nu;
  const real beta_s = (real)b->beta_s, beta_fs = (real)b->beta_fs, alpha = (real)b->alpha;
  const real inv_sigma0 = (real)(1.0 / b->sigma0);
  const struct realv_arg accel = body_accel(sim);
  const real fs_offset = (real)(0.5 * sc->dr), d0 = (real)b->d0;
  const int neumann = b->mode == 1;

  /* 0. the gate (its dummies move before anything reads them) */
  if (b->gate.on) CLSPH_TRY(gate_step(sim, b, dt));
  /* 1. the dummies' velocity and u* from their markers (S eqs 11-13) */
  n = (cl_uint)ps->n;
  n = (cl_uint)ps->n;
  CLSPH_TRY(KERN_SET(b->k_wall_vel, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start),
                     KARG(pos), KARG(vol), KARG(kind), KARG(dist), KARG(normal), KARG(uwall),
                     KARG(beta_s), KARG(rdt), KARGV(accel), KARG(vel), KARG(ustar),
                     KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, b->k_wall_vel, n, NULL));
  /* 2. the prediction */
  CLSPH_TRY(op_prefix(sim, b->k_predict, &n));
  {
    const struct karg a[] = {KARG(kind),   KARG(vel),   KARG(nu),          KARG(rdt),
                             KARGV(accel), KARG(ustar), KARG(sim->d_flags)};
    CLSPH_TRY(set_from(b->k_predict, 6, sizeof a / sizeof *a, a));
  }
  CLSPH_TRY(kern_launch(sim->dev, b->k_predict, n, NULL));
  /* 3. s* at x*, the free surface and the source (A12, S eq 8) */
  CLSPH_TRY(op_prefix(sim, b->k_source, &n));
  {
    const struct karg a[] = {KARG(kind),       KARG(ustar),   KARG(uwall),       KARG(rdt),
                             KARG(inv_sigma0), KARG(beta_fs), KARG(b->fs_min),   KARG(b->scan),
                             KARG(alpha),      KARG(rho),     KARGV(accel),      KARG(fs_offset),
                             KARG(d0),         KARG(rhostar), KARG(fs),          KARG(dir),
                             KARG(div),        KARG(rhs),     KARG(sim->d_flags)};
    CLSPH_TRY(set_from(b->k_source, 6, sizeof a / sizeof *a, a));
  }
  CLSPH_TRY(kern_launch(sim->dev, b->k_source, n, NULL));
  /* 4. the dummies' rows: pseudo-Neumann, Dirichlet values mapped from the last pressure (S sec
   *    3.2); the modified virtual marker, the hydrostatic carry of its fluid (S sec 3.3) */
  if (neumann)
    CLSPH_TRY(wall_neumann(sim, b, dt));
  else
    CLSPH_TRY(wall_pressure(sim, b, 1));
  /* 5. the pressure equation; without any Dirichlet row (the modified virtual marker in a closed
   *    box, or no wall and no free surface) it is singular and the diagonal is reinforced */
  double nfixed = 0.0;
  CLSPH_TRY(sim_count(sim, dir, &nfixed));
  b->ps.opt.singular = nfixed > 0.0 ? b->popt.singular : PSOLVE_REINFORCE;
  b->op.n = ps->n;
  b->op.grid = &sim->grid;
  struct psolve_result res;
  /* pressure_form = "dynamic": the solve's unknown is P = p − ρ0 a·x (its guess too) */
  if (b->dynamic) CLSPH_TRY(hydro_shift(sim, b, -1.0));
  CLSPH_TRY(psolve_solve(&b->ps, &b->op, rhs, p, &res));
  if (b->dynamic) CLSPH_TRY(hydro_shift(sim, b, 1.0));
  sim->solver_its = res.its;
  sim->solver_res = res.rnorm;
  /* 6. pseudo-Neumann: the dummies' pressure mapped from the new one (S eq 22; the modified
   *    virtual marker solved for it); the projection and the motion */
  if (!neumann) CLSPH_TRY(wall_pressure(sim, b, 0));

  const real coef = (real)(dt / sc->rho0), band = (real)(0.5 * sc->dr);
  CLSPH_TRY(op_prefix(sim, b->k_project, &n));
  {
    const struct karg a[] = {KARG(kind),   KARG(ustar), KARG(p),   KARG(coef), KARG(rdt),
                             KARGV(accel), KARG(vel),   KARG(acc), KARG(fs),   KARG(sim->d_flags)};
    CLSPH_TRY(set_from(b->k_project, 6, sizeof a / sizeof *a, a));
  }
  CLSPH_TRY(kern_launch(sim->dev, b->k_project, n, NULL));
  CLSPH_TRY(KERN_SET(b->k_move, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start), KARG(kind),
                     KARG(vel), KARG(dist), KARG(normal), KARG(rdt), KARG(band), KARG(pos),
                     KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, b->k_move, n, NULL));
  if (b->c_shift > 0.0) { /* shifting (shift.cl): the offsets first, then the moves */
    const real h = (real)sim->sm.h, c_h2 = (real)b->c_shift * h * h, dr = (real)sc->dr;
    cl_mem shift = pset_mem(ps, b->f_pshift);
    CLSPH_TRY(KERN_SET(b->k_pshift, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start),
                       KARG(kind), KARG(pos), KARG(vol), KARG(fs), KARG(dist), KARG(normal),
                       KARG(c_h2), KARG(dr), KARG(shift)));
    CLSPH_TRY(kern_launch(sim->dev, b->k_pshift, n, NULL));
    CLSPH_TRY(
        KERN_SET(b->k_papply, KARG(n), KARG(sim->grid.geom), KARG(kind), KARG(shift), KARG(pos)));
    CLSPH_TRY(kern_launch(sim->dev, b->k_papply, n, NULL));
  }
done:
  return st;
}

/* Time step: CFL 0.25 h/U, viscous 0.125 h²/ν (S gives none and A12's was not recovered;
 * isph-rotational's bounds, Cummins & Rudman 1999), and the body force 0.125 √(h/|a|), half of
 * theirs. CHOICE, measured: with 0.25 √(h/|a|) the paper's tank (cases/hydrostatic.lua, stab=1
 * depth=0.2 width=0.2 dr=0.01) lets a particle through the floor at t = 0.23 s in double and in
 * float, with half of it (and 0.4 or 0.6 of it) the tank holds past 1 s. The relaxation term
 * α ρ0 (1 − s* / σ0)/Δt² that holds the fluid off the pseudo-Neumann walls stiffens as Δt shrinks.
 * |a| is the larger of the body force and the fluid's largest acceleration in the last step (the
 * pressure's included; Monaghan's force criterion): at an impact the pressure accelerates the
 * fluid by hundreds of g within a step, and a step sized on the speed alone carried particles a
 * spacing through the floor (cases/dam_break.lua stab=1 n=40); the walls' approach term
 * (ppe.cl), without it, pumped the paper's tank until it clustered at t = 2.4 s.
 * The CFL bound keeps each move within 0.25 h, which the neighbour grid's skin (support_skin)
 * covers for x*. */
static enum clsph_status stab_max_dt(struct sim *sim, void *state, double *dt)
{
  enum clsph_status st = CLSPH_OK;
  struct stab *b = state;
  const struct scene *s = sim->scene;
  const double h = sim->sm.h;
  CLSPH_TRY(sim_max_speed(sim, 0, &b->umax));
  double u = b->umax;
  for (int w = 0; w < s->nwalls; ++w) /* a sliding wall drives the fluid */
    u = fmax(
        u, hypot(hypot(s->walls[w].velocity[0], s->walls[w].velocity[1]), s->walls[w].velocity[2]));
  u = fmax(u, gate_speed_at(&b->gate, sim->time, sim->time)); /* the gate's moves */
  const double a =
      hypot(hypot(s->gravity[0] + sim->body_force[0], s->gravity[1] + sim->body_force[1]),
            s->gravity[2] + sim->body_force[2]); /* (2-D: hypot(., 0) is exact) */
  double am = 0.0;                               /* the last step's largest acceleration */
  if (sim->step > 0) CLSPH_TRY(sim_max_norm(sim, pset_mem(&sim->ps, b->f_acc), KIND_FLUID, &am));
  double d = HUGE_VAL;
  if (u > 0.0) d = fmin(d, 0.25 * h / u);
  if (s->nu > 0.0) d = fmin(d, 0.125 * h * h / s->nu);
  if (a > 0.0) d = fmin(d, 0.125 * sqrt(h / a));
  /* not under a quarter of the other bounds: the relaxation term's acceleration grows as 1/Δt²,
   * and the bound on it alone ran Δt down step after step until the pressure reached −9e9 Pa (the
   * n = 40 dam break in float at t = 0.71 s) */
  if (am > 0.0) d = fmax(0.25 * d, fmin(d, 0.125 * sqrt(h / am)));
  *dt = d;
done:
  return st;
}

static double *stab_persist(void *state, int *count)
{
  struct stab *b = state;
  *count = b->dim; /* the gate's velocity: 2-D checkpoints keep their 2 values */
  return b->gate.v_prev;
}

static void stab_destroy(void *state)
{
  struct stab *b = state;
  if (b == NULL) return;
  cl_kernel ks[] = {b->k_move,    b->k_project,  b->k_source,  b->k_predict,
                    b->k_wall_p,  b->k_wall_vel, b->k_lattice, b->k_diag0,
                    b->k_count,   b->k_coeffs,   b->k_apply,   b->k_diag,
                    b->k_neumann, b->k_shift,    b->k_pshift,  b->k_papply};
  for (size_t k = 0; k < sizeof ks / sizeof *ks; ++k)
    if (ks[k] != NULL) clReleaseKernel(ks[k]);
  kern_release(&b->d_sums);
  psolve_destroy(&b->ps);
  gate_destroy(&b->gate);
  free(b);
}

/* -D switches: the pressure form (pressure_form = "dynamic": STAB_DYNAMIC 1) and the walls'
 * approach term (wall_approach = "impact": STAB_APPROACH_IMPACT 1, the default in 3-D; ppe.cl) */
static enum clsph_status stab_define(const struct sim *sim, struct prog_opts *o)
{
  static const char *const form_names[] = {"total", "dynamic", NULL};
  static const char *const approach_names[] = {"particles", "impact", NULL};
  int dynamic = 0, impact = 0;
  enum clsph_status st = option_choice(sim->scene, "pressure_form", form_names, 0, &dynamic);
  if (st == CLSPH_OK)
    st = option_choice(sim->scene, "wall_approach", approach_names, sim->scene->dim == 3, &impact);
  if (st == CLSPH_OK) st = prog_opts_define_int(o, "STAB_DYNAMIC", dynamic);
  if (st == CLSPH_OK) st = prog_opts_define_int(o, "STAB_APPROACH_IMPACT", impact);
  return st;
}

const struct scheme_ops scheme_isph_stabilized = {
    .define = stab_define,
    .name = "isph-stabilized",
    .summary = "stabilized ISPH (density-invariance relaxation), virtual-marker dummy walls "
               "(Asai et al. 2012, 2013)",
    .sources = sources,
    .wall_model = "dummy",
    .three_d = 1,
    .smoothing = "cubic_spline",
    .h_over_dr = 1.2,
    .support_skin = 0.25,
    .fill_fields = SCHEME_FILL_PRESSURE,
    .options = options,
    .create = stab_create,
    .step = stab_step,
    .max_dt = stab_max_dt,
    .persist = stab_persist,
    .destroy = stab_destroy,
};
