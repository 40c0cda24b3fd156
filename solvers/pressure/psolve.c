/* psolve.c: preconditioned BiCGStab on the device (van der Vorst 1992, right preconditioning),
 * with the operator applied matrix-free or from coefficients stored once per solve. The loop
 * reads like the algorithm; each line is one device operation (krylov.cl).
 *
 *   r = b − A x,  r0 = r,  ρ = α = ω = 1,  v = p = 0
 *   repeat:  ρ' = (r0, r);          β = (ρ'/ρ)(α/ω)
 *            p = r + β (p − ω v);   p̂ = M⁻¹ p;   v = A p̂;   α = ρ' / (r0, v)
 *            s = r − α v            (stop if ||s|| small: x += α p̂)
 *            ŝ = M⁻¹ s;   t = A ŝ;   ω = (t, s) / (t, t)
 *            x += α p̂ + ω ŝ;   r = s − ω t   (stop if ||r|| small)
 * A vanishing ρ' or ω (breakdown) restarts from the current residual.
 *
 * The scalars never come to the host: the kernels that need them add up the dot products'
 * partial sums themselves, and a small state vector on the device says when and why the solve
 * ended. The host enqueues a batch of iterations (as many as the last solve needed, and two
 * more), reads the state once, and enqueues more only when the batch fell short; the iterations
 * past the end return at once. A system of at most solver_group_max unknowns is solved whole by
 * one work-group in one launch (krylov_group.cl: the same iteration, tests and state). */
#include "psolve.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "clsph_config.h"

#define PSOLVE_WG         64 /* BLAS1_WG in blas1.cl */
#define PSOLVE_SCAN_BLOCK 64 /* GRID_SCAN_BLOCK in grid.cl */

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void psolve_defaults(struct psolve_options *o)
{
  memset(o, 0, sizeof *o);
  o->method = PSOLVE_BICGSTAB;
  o->apply = PSOLVE_STORED;
  o->precond = PSOLVE_MULTIGRID;
  o->sweeps = 2;
  o->singular = PSOLVE_REGULAR;
  o->reinforce = CLSPH_DOUBLE ? 1e-6 : 1e-4; /* float: 1e-6 is below its resolution */
  o->rtol = CLSPH_DOUBLE ? 1e-8 : 1e-5;
  o->atol = 0.0;
  o->max_it = 1000;
  o->max_failures = 10;
  o->name = "pressure";
  o->group_max = PSOLVE_GROUP_MAX;
  o->fuse = PSOLVE_FUSE_AUTO;
}

static int pick(const char *text, const char *const *names)
{
  for (int i = 0; names[i] != NULL; ++i)
    if (text != NULL && strcmp(text, names[i]) == 0) return i;
  return -1;
}

enum clsph_status psolve_set(struct psolve_options *o, const char *key, const char *text,
                             double number)
{
  enum clsph_status st = CLSPH_OK;
  static const char *const methods[] = {"bicgstab", "direct", NULL};
  static const char *const applies[] = {"stored", "recompute", NULL};
  static const char *const preconds[] = {"jacobi", "none", "jacobi_sweeps", "multigrid", NULL};
  static const char *const singulars[] = {"regular", "reinforce", "mean", "project", NULL};
  static const char *const fuses[] = {"separate", "fused", "auto", NULL};
  int k;
  if (strcmp(key, "solver") == 0) {
    CLSPH_CHECK((k = pick(text, methods)) >= 0, CLSPH_E_INPUT,
                "solver must be \"bicgstab\" or \"direct\"");
    o->method = (enum psolve_method)k;
  } else if (strcmp(key, "apply") == 0) {
    CLSPH_CHECK((k = pick(text, applies)) >= 0, CLSPH_E_INPUT,
                "solver_apply must be \"stored\" or \"recompute\"");
    o->apply = (enum psolve_apply)k;
  } else if (strcmp(key, "precond") == 0) {
    CLSPH_CHECK((k = pick(text, preconds)) >= 0, CLSPH_E_INPUT,
                "solver_precond must be \"jacobi\", \"none\", \"jacobi_sweeps\" or \"multigrid\"");
    o->precond = (enum psolve_precond)k;
  } else if (strcmp(key, "singular") == 0) {
    CLSPH_CHECK((k = pick(text, singulars)) >= 0, CLSPH_E_INPUT,
                "solver_singular must be \"regular\", \"reinforce\", \"mean\" or \"project\"");
    o->singular = (enum psolve_singular)k;
  } else if (strcmp(key, "sweeps") == 0) {
    CLSPH_CHECK(number >= 1 && number <= 16, CLSPH_E_INPUT, "solver_sweeps must be 1 to 16");
    o->sweeps = (int)number;
  } else if (strcmp(key, "reinforce") == 0) {
    CLSPH_CHECK(number > 0 && number < 1, CLSPH_E_INPUT, "solver_reinforce must be in (0, 1)");
    o->reinforce = number;
  } else if (strcmp(key, "rtol") == 0) {
    CLSPH_CHECK(number > 0 && number < 1, CLSPH_E_INPUT, "solver_rtol must be in (0, 1)");
    /* the residual's own rounding is about ε ‖b‖: below a few ε the solve stalls to solver_max_it
     * (or stops on a recursive residual that the true one does not follow) */
    CLSPH_CHECK(number >= 4.0 * REAL_EPS, CLSPH_E_INPUT,
                "solver_rtol = %g is below what a %s build can reach (4 ε = %.2g)", number,
                CLSPH_DOUBLE ? "double" : "float", 4.0 * REAL_EPS);
    o->rtol = number;
  } else if (strcmp(key, "atol") == 0) {
    CLSPH_CHECK(number >= 0, CLSPH_E_INPUT, "solver_atol must not be negative");
    o->atol = number;
  } else if (strcmp(key, "max_it") == 0) {
    CLSPH_CHECK(number >= 1 && number <= 1e6, CLSPH_E_INPUT, "solver_max_it must be 1 to 1e6");
    o->max_it = (int)number;
  } else if (strcmp(key, "group_max") == 0) {
    CLSPH_CHECK(number >= 0 && number <= 1e7 && number == floor(number), CLSPH_E_INPUT,
                "solver_group_max must be a whole number of unknowns from 0 (never) to 1e7");
    o->group_max = (int)number;
  } else if (strcmp(key, "fuse") == 0) {
    CLSPH_CHECK((k = pick(text, fuses)) >= 0, CLSPH_E_INPUT,
                "solver_fuse must be \"separate\", \"fused\" or \"auto\"");
    o->fuse = k;
  } else {
    CLSPH_CHECK(0, CLSPH_E_INPUT, "unknown solver option '%s'", key);
  }
done:
  return st;
}

enum clsph_status psolve_create(const struct dev *dev, cl_program prog, size_t n,
                                const struct psolve_options *opt, struct psolve *out)
{
  enum clsph_status st = CLSPH_OK;
  struct psolve ps;
  memset(&ps, 0, sizeof ps);
  ps.dev = dev;
  ps.opt = *opt;
  /* "auto": fused on a GPU, where a launch costs more against the sweeps; separate elsewhere (on
   * PoCL the fused sweeps took longer than the launches they save: README) */
  if (ps.opt.fuse == PSOLVE_FUSE_AUTO) ps.opt.fuse = (dev->type & CL_DEVICE_TYPE_GPU) != 0;
  ps.cap = n > 0 ? n : 1;
  size_t groups = (ps.cap + PSOLVE_WG - 1) / PSOLVE_WG;
  ps.ngroups = groups < 64 ? (int)groups : 64;
  struct {
    cl_kernel *k;
    const char *name;
  } ks[] = {{&ps.k_dot, "kr_dot"},
            {&ps.k_dot_ts, "kr_dot_ts"},
            {&ps.k_residual, "kr_residual"},
            {&ps.k_shift, "kr_shift"},
            {&ps.k_start, "kr_start"},
            {&ps.k_begin, "kr_begin"},
            {&ps.k_s, "kr_s"},
            {&ps.k_end, "kr_end_iteration"},
            {&ps.k_restart, "kr_restart"},
            {&ps.k_total, "kr_total"},
            {&ps.k_wtotal, "kr_wtotal"},
            {&ps.k_wshift, "kr_wshift"},
            {&ps.k_spmv, "kr_spmv"},
            {&ps.k_spmv_dot, "kr_spmv_dot"},
            {&ps.k_group, "kr_solve_group"},
            {&ps.k_scale, "kr_scale"},
            {&ps.k_sweep, "kr_sweep"},
            {&ps.k_axpy, "blas1_axpy"},
            {&ps.k_add_diag, "blas1_add_diag"},
            {&ps.k_invert, "blas1_invert"},
            {&ps.k_csr_diag_inv, "csr_diag_inverse"},
            {&ps.k_residual_csr, "kr_residual_csr"},
            {&ps.k_guard, "csr_guard"}};
  for (size_t i = 0; i < sizeof ks / sizeof *ks; ++i)
    CLSPH_TRY(prog_kernel(prog, ks[i].name, ks[i].k));
  CLSPH_TRY(grid_scan_create(prog, &ps.scan));
  /* the one-group solve's work-group: as many items as the kernel allows, at most
   * PSOLVE_GROUP_WG (its local partial sums hold that many) */
  size_t wg = 0;
  CLSPH_CL_TRY(clGetKernelWorkGroupInfo(ps.k_group, dev->id, CL_KERNEL_WORK_GROUP_SIZE, sizeof wg,
                                        &wg, NULL));
  ps.group_wg = wg < PSOLVE_GROUP_WG ? (wg > 0 ? wg : 1) : PSOLVE_GROUP_WG;
  /* on a CPU a work-group runs on one thread, its items as a loop that each phase of the solve
   * goes through: 32 items (1.8-2.0 ms a solve on the 30² cavity, PoCL) against 256 (3.0 ms) */
  if (dev->type == CL_DEVICE_TYPE_CPU && ps.group_wg > PSOLVE_GROUP_WG_CPU)
    ps.group_wg = PSOLVE_GROUP_WG_CPU;
  cl_mem *vs[] = {&ps.d_r,  &ps.d_r0, &ps.d_p,    &ps.d_v,    &ps.d_s, &ps.d_t, &ps.d_ph,
                  &ps.d_sh, &ps.d_q,  &ps.d_dinv, &ps.d_diag, &ps.d_b, &ps.d_x0};
  for (size_t i = 0; i < sizeof vs / sizeof *vs; ++i)
    CLSPH_TRY(kern_buffer(dev, ps.cap * sizeof(real), NULL, vs[i], "solver vector"));
  CLSPH_TRY(kern_buffer(dev, PSOLVE_SETS * 64 * sizeof(real), NULL, &ps.d_partial,
                        "solver partial sums"));
  /* the state is in double where the device has it (kreal in krylov.cl); zero: ended at
   * iteration 0, so that the first solve's start runs */
  const double state0[PSOLVE_STATE] = {0};
  ps.state_double = CLSPH_DOUBLE || dev->fp64;
  CLSPH_TRY(kern_buffer(dev, sizeof state0, state0, &ps.d_state, "solver state"));
  ps.last_its = 8;
  const cl_uint zeros[2] = {0, 0}; /* a zero diagonal (blas1_invert), store()'s overflow */
  CLSPH_TRY(kern_buffer(dev, sizeof zeros, zeros, &ps.d_flags, "solver flags"));
  CLSPH_TRY(kern_buffer(dev, (ps.cap + 1) * sizeof(cl_uint), NULL, &ps.d_row, "csr rows"));
  CLSPH_TRY(kern_buffer(dev, (ps.cap + 1) * sizeof(cl_uint), NULL, &ps.d_count, "csr counts"));
  CLSPH_TRY(kern_buffer(dev, ((ps.cap + 1) / PSOLVE_SCAN_BLOCK + 2) * sizeof(cl_uint), NULL,
                        &ps.d_block, "csr scan blocks"));
  if (opt->precond == PSOLVE_MULTIGRID) CLSPH_TRY(mg_create(dev, prog, ps.cap, &ps.mg));
  if (opt->precond == PSOLVE_MULTIGRID && ps.opt.fuse) {
    CLSPH_TRY(prog_kernel(prog, "mg_begin_down", &ps.k_begin_down));
    CLSPH_TRY(prog_kernel(prog, "mg_s_down", &ps.k_s_down));
    CLSPH_TRY(kern_buffer(dev, ps.cap * sizeof(real), NULL, &ps.d_p2, "solver vector"));
  }
  /* what the first solve allocates: the stored operator (a quarter more than its nonzeros,
   * store()) and the multigrid's levels: the coarse stencils (about 3 floats a particle) and the
   * fine rows of A P against the level-1 cells (a value and a cell for each of (2 GRID_SUB + 1)^d
   * cells: about half a row of the operator) */
  const double rows = opt->row_estimate > 0.0 ? opt->row_estimate : 50.0;
  if (opt->apply == PSOLVE_STORED)
    ps.reserved += 1.25 * (double)ps.cap * rows * (double)(sizeof(cl_uint) + sizeof(real));
  if (opt->precond == PSOLVE_MULTIGRID) /* and the stored values' float copy */
    ps.reserved += (double)ps.cap *
                   (3.0 * MG_REAL_SIZE + 0.5 * rows * (double)(sizeof(cl_uint) + MG_REAL_SIZE) +
                    1.25 * rows * MG_REAL_SIZE);
  kern_reserve(ps.reserved);
  *out = ps;
  memset(&ps, 0, sizeof ps);
done:
  psolve_destroy(&ps);
  return st;
}

/* ---- device operations ---- */

/* State slots and reasons (krylov.cl) */
#define KR_DONE          0
#define KR_REASON        1
#define KR_RNORM         2
#define KR_DIAG          6
#define KR_RESTART_RHO   10
#define KR_RESTART_OMEGA 11
#define KR_CAPACITY      12
#define KR_RESTARTS      16 /* a one-group solve's restarts (krylov_group.cl) */
#define KR_INIT          17 /* the initial guess's relative residual */
#define KR_RHO_SET       2  /* partial sums of (r0, r) */
#define KR_BB_SET        0  /* partial sums of (b, b) */
#define KR_R0V_SET       3  /* (r0, v) */
#define KR_TS_SET        5  /* (t, s) */
#define KR_TT_SET        6  /* (t, t) */
#define KR_NO_SET        0xffffffffu

static enum clsph_status launch(struct psolve *ps, cl_kernel k, cl_uint n)
{
  return kern_launch(ps->dev, k, n, NULL);
}

/* a kernel over the reductions' fixed work-groups (grid-stride loops) */
static enum clsph_status launch_groups(struct psolve *ps, cl_kernel k)
{
  return kern_launch_wg(ps->dev, k, (size_t)ps->ngroups * PSOLVE_WG, PSOLVE_WG, NULL);
}

/* The iteration's state (krylov.cl), in double or in float as the device keeps it */
static enum clsph_status read_state(struct psolve *ps, double *out)
{
  enum clsph_status st = CLSPH_OK;
  if (ps->state_double) {
    CLSPH_TRY(kern_read(ps->dev, ps->d_state, PSOLVE_STATE * sizeof(double), out));
  } else {
    float f[PSOLVE_STATE];
    CLSPH_TRY(kern_read(ps->dev, ps->d_state, sizeof f, f));
    for (int i = 0; i < PSOLVE_STATE; ++i) out[i] = (double)f[i];
  }
done:
  return st;
}

/* partial sums of (x, y) into set `set`, in iteration k */
static enum clsph_status dot(struct psolve *ps, cl_uint n, cl_uint k, cl_mem x, cl_mem y,
                             cl_uint set)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(KERN_SET(ps->k_dot, KARG(n), KARG(k), KARG(ps->d_state), KARG(x), KARG(y), KARG(set),
                     KARG(ps->d_partial)));
  CLSPH_TRY(launch_groups(ps, ps->k_dot));
done:
  return st;
}

static enum clsph_status copy(struct psolve *ps, cl_mem dst, cl_mem src, cl_uint n)
{
  return kern_copy(ps->dev, dst, src, n * sizeof(real));
}

/* dst = src − mean(src) (PSOLVE_MEAN, PSOLVE_PROJECT), on the device: the mean weighted by the
 * operator's left null vector where it gives one (then Σ w b = 0 makes the system consistent), else
 * the plain one */
static enum clsph_status remove_mean(struct psolve *ps, const struct psolve_op *op, cl_uint n,
                                     cl_mem src, cl_mem dst)
{
  enum clsph_status st = CLSPH_OK;
  const cl_uint ng = (cl_uint)ps->ngroups;
  if (op->weight != NULL) {
    CLSPH_TRY(KERN_SET(ps->k_wtotal, KARG(n), KARG(op->weight), KARG(src), KARG(ps->d_partial)));
    CLSPH_TRY(launch_groups(ps, ps->k_wtotal));
    CLSPH_TRY(KERN_SET(ps->k_wshift, KARG(n), KARG(ps->d_partial), KARG(ng), KARG(src), KARG(dst)));
    CLSPH_TRY(launch_groups(ps, ps->k_wshift));
    goto done;
  }
  CLSPH_TRY(KERN_SET(ps->k_total, KARG(n), KARG(src), KARG(ps->d_partial)));
  CLSPH_TRY(launch_groups(ps, ps->k_total));
  CLSPH_TRY(KERN_SET(ps->k_shift, KARG(n), KARG(ps->d_partial), KARG(ng), KARG(src), KARG(dst)));
  CLSPH_TRY(launch_groups(ps, ps->k_shift));
done:
  return st;
}

/* ---- the operator ---- */

/* The stored operator's buffers hold nnz nonzeros, a quarter more when they grow: particles move.
 */
static enum clsph_status grow(struct psolve *ps, size_t nnz)
{
  enum clsph_status st = CLSPH_OK;
  if (nnz <= ps->nnz_cap) goto done;
  kern_release(&ps->d_col);
  kern_release(&ps->d_val);
  kern_release(&ps->d_valm);
  ps->nnz_cap = nnz + nnz / 4 + 16;
  CLSPH_TRY(kern_buffer(ps->dev, ps->nnz_cap * sizeof(cl_uint), NULL, &ps->d_col, "csr columns"));
  CLSPH_TRY(kern_buffer(ps->dev, ps->nnz_cap * sizeof(real), NULL, &ps->d_val, "csr values"));
  if (ps->opt.precond == PSOLVE_MULTIGRID)
    CLSPH_TRY(kern_buffer(ps->dev, ps->nnz_cap * MG_REAL_SIZE, NULL, &ps->d_valm,
                          "multigrid csr values"));
done:
  return st;
}

/* Build the stored layout: counts, row starts (exclusive scan of the counts), coefficients.
 * Unguarded, the host reads the nonzeros and the buffers grow to them. `guarded` (the multigrid
 * solve's set-up, once the buffers exist) waits for nothing: csr_guard empties every row when the
 * nonzeros pass the capacity, so that the coefficients stay in bounds, and leaves their number in
 * d_flags[1], which stops the solve at its start (kr_start) and comes to the host with the solve's
 * first wait; solve() then grows the buffers and builds and solves again. */
static enum clsph_status store(struct psolve *ps, const struct psolve_op *op, int guarded)
{
  enum clsph_status st = CLSPH_OK;
  const cl_uint zero = 0;
  cl_uint items = (cl_uint)op->n + 1;
  cl_uint nnz = 0;
  CLSPH_TRY(kern_fill(ps->dev, ps->d_count, &zero, sizeof zero, items * sizeof(cl_uint)));
  CLSPH_TRY(op->row_counts(op->ctx, ps->d_count));
  CLSPH_TRY(grid_scan_run(&ps->scan, ps->dev, items, ps->d_count, ps->d_block, ps->d_row, NULL));
  if (!guarded || ps->nnz_cap == 0) { /* the count, waited for; the buffers grow to it */
    CLSPH_TRY(kern_read_at(ps->dev, ps->d_row, op->n * sizeof(cl_uint), sizeof nnz, &nnz));
    CLSPH_TRY(grow(ps, nnz));
  }
  /* d_flags[1]: 0 when the rows fit, else their count (then they are emptied) */
  const cl_uint n = (cl_uint)op->n, cap = (cl_uint)ps->nnz_cap;
  CLSPH_TRY(KERN_SET(ps->k_guard, KARG(n), KARG(cap), KARG(ps->d_row), KARG(ps->d_flags)));
  CLSPH_TRY(kern_launch_wg(ps->dev, ps->k_guard, PSOLVE_WG, PSOLVE_WG, NULL));
  if (guarded)
    CLSPH_TRY(
        kern_read_nb(ps->dev, ps->d_flags, sizeof(cl_uint), sizeof(cl_uint), &ps->h_overflow));
  CLSPH_TRY(op->coefficients(op->ctx, ps->d_row, ps->d_col, ps->d_val));
done:
  return st;
}

/* y = A x (A + ε diag A for a reinforced singular system), stored or recomputed, in iteration k
 * (the stored product returns at once after the end of the solve). */
static enum clsph_status apply(struct psolve *ps, const struct psolve_op *op, cl_mem x, cl_mem y,
                               cl_uint k)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint n = (cl_uint)op->n;
  struct kern_timer *t = &ps->t_apply;
  const real e = (real)(PSOLVE_REINFORCED(ps->opt.singular) ? ps->opt.reinforce : 0.0);
  if (ps->opt.apply == PSOLVE_STORED) {
    CLSPH_TRY(KERN_SET(ps->k_spmv, KARG(n), KARG(k), KARG(ps->d_state), KARG(ps->d_row),
                       KARG(ps->d_col), KARG(ps->d_val), KARG(e), KARG(x), KARG(y)));
    CLSPH_TRY(kern_launch(ps->dev, ps->k_spmv, n, t));
    goto done;
  }
  double t0 = t->on ? now() : 0.0;
  CLSPH_TRY(op->apply(op->ctx, x, y));
  if (t->on) {
    CLSPH_TRY(kern_finish(ps->dev));
    t->seconds += now() - t0;
    t->launches += 1;
  }
  if (PSOLVE_REINFORCED(ps->opt.singular)) { /* y += ε diag(A) x */
    CLSPH_TRY(KERN_SET(ps->k_add_diag, KARG(n), KARG(y), KARG(e), KARG(ps->d_diag), KARG(x)));
    CLSPH_TRY(launch(ps, ps->k_add_diag, n));
  }
done:
  return st;
}

/* ε of the multigrid preconditioner's A + ε diag(A): the reinforcement's, and a mean-free solve's
 * too, whose operator stays singular but whose preconditioner must not be: on the fish-pass
 * (cases/fish_pass.lua) in float the singular coarse levels sent BiCGStab to non-finite values in
 * its first step; 0 for a regular system */
static double reinforcement(const struct psolve *ps)
{
  return ps->opt.singular == PSOLVE_REGULAR ? 0.0 : ps->opt.reinforce;
}

/* z = M⁻¹ r in iteration k: none, multigrid, Jacobi, or Jacobi followed by sweeps toward A z = r
 * (scratch: A z). */
static enum clsph_status precond(struct psolve *ps, const struct psolve_op *op, cl_mem r, cl_mem z,
                                 cl_mem scratch, cl_uint k)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint n = (cl_uint)op->n;
  if (ps->opt.precond == PSOLVE_NONE) {
    CLSPH_TRY(copy(ps, z, r, n));
    goto done;
  }
  if (ps->opt.precond == PSOLVE_MULTIGRID) {
    CLSPH_TRY(mg_apply(&ps->mg, op->n, ps->d_row, ps->d_col, ps->d_valm, reinforcement(ps), r, z,
                       ps->d_state, k));
    goto done;
  }
  CLSPH_TRY(KERN_SET(ps->k_scale, KARG(n), KARG(k), KARG(ps->d_state), KARG(z), KARG(ps->d_dinv),
                     KARG(r)));
  CLSPH_TRY(launch(ps, ps->k_scale, n));
  if (ps->opt.precond == PSOLVE_JACOBI_SWEEPS) {
    for (int s = 0; s < ps->opt.sweeps; ++s) { /* z <- z + D⁻¹ (r − A z) */
      CLSPH_TRY(apply(ps, op, z, scratch, k));
      CLSPH_TRY(KERN_SET(ps->k_sweep, KARG(n), KARG(k), KARG(ps->d_state), KARG(z),
                         KARG(ps->d_dinv), KARG(r), KARG(scratch)));
      CLSPH_TRY(launch(ps, ps->k_sweep, n));
    }
  }
done:
  return st;
}

/* diag(A) into d_diag (for the reinforcement) and the inverse diagonal of the operator solved,
 * A or A + ε diag(A), into d_dinv (Jacobi). */
static enum clsph_status diagonal(struct psolve *ps, const struct psolve_op *op)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint n = (cl_uint)op->n;
  const cl_uint zero = 0;
  const real e = (real)(PSOLVE_REINFORCED(ps->opt.singular) ? ps->opt.reinforce : 0.0);
  CLSPH_TRY(kern_fill(ps->dev, ps->d_flags, &zero, sizeof zero, sizeof zero));
  if (ps->opt.apply == PSOLVE_STORED) { /* one launch (csr.cl) */
    CLSPH_TRY(KERN_SET(ps->k_csr_diag_inv, KARG(n), KARG(ps->d_row), KARG(ps->d_val), KARG(e),
                       KARG(ps->d_diag), KARG(ps->d_dinv), KARG(ps->d_flags)));
    CLSPH_TRY(launch(ps, ps->k_csr_diag_inv, n));
    goto done;
  }
  CLSPH_TRY(op->diagonal(op->ctx, ps->d_diag));
  CLSPH_TRY(copy(ps, ps->d_dinv, ps->d_diag, n));
  if (PSOLVE_REINFORCED(ps->opt.singular)) { /* dinv = (1 + ε) diag(A) */
    CLSPH_TRY(KERN_SET(ps->k_axpy, KARG(n), KARG(e), KARG(ps->d_diag), KARG(ps->d_dinv)));
    CLSPH_TRY(launch(ps, ps->k_axpy, n));
  }
  CLSPH_TRY(KERN_SET(ps->k_invert, KARG(n), KARG(ps->d_dinv), KARG(ps->d_flags)));
  CLSPH_TRY(launch(ps, ps->k_invert, n)); /* the flag reaches the host with the solve's state */
done:
  return st;
}

/* y = A x and the partial sums of (a, y) into set sa and, unless sb is KR_NO_SET, of (y, y) into
 * set sb: in one pass (kr_spmv_dot) with the stored operator, else the product and then the dot
 * products, with the same sums */
static enum clsph_status apply_dot(struct psolve *ps, const struct psolve_op *op, cl_mem x,
                                   cl_mem y, cl_uint k, cl_mem a, cl_uint sa, cl_uint sb)
{
  enum clsph_status st = CLSPH_OK;
  const cl_uint n = (cl_uint)op->n;
  if (ps->opt.apply == PSOLVE_STORED) {
    const real e = (real)(PSOLVE_REINFORCED(ps->opt.singular) ? ps->opt.reinforce : 0.0);
    CLSPH_TRY(KERN_SET(ps->k_spmv_dot, KARG(n), KARG(k), KARG(ps->d_state), KARG(ps->d_row),
                       KARG(ps->d_col), KARG(ps->d_val), KARG(e), KARG(x), KARG(y), KARG(a),
                       KARG(sa), KARG(sb), KARG(ps->d_partial)));
    CLSPH_TRY(kern_launch_wg(ps->dev, ps->k_spmv_dot, (size_t)ps->ngroups * PSOLVE_WG, PSOLVE_WG,
                             &ps->t_apply));
    goto done;
  }
  CLSPH_TRY(apply(ps, op, x, y, k));
  if (sb == KR_NO_SET) {
    CLSPH_TRY(dot(ps, n, k, a, y, sa));
  } else { /* kr_dot_ts's sets: (t, s) and (t, t) */
    CLSPH_TRY(KERN_SET(ps->k_dot_ts, KARG(n), KARG(k), KARG(ps->d_state), KARG(y), KARG(a),
                       KARG(ps->d_partial)));
    CLSPH_TRY(launch_groups(ps, ps->k_dot_ts));
  }
done:
  return st;
}

/* ---- the solve ---- */

/* With the multigrid fused (opt.fuse) the Krylov kernels that make p and s also make the cycle's
 * fine level down (mg.cl's mg_begin_down, mg_s_down), where kr_begin, kr_s and mg_down_csr twice
 * took 4 launches: 9 launches an iteration with the block from level 1 instead of 11, the same
 * bits. A neighbour's share of the fine residual is then made from its vectors (three or four
 * reads instead of one): on the 2-core CPU the two kernels took 145 and 139 µs a launch on the
 * 60² cavity against 36 + 18 + 2 × 43 µs for the four, and a whole run of the cavity to t = 1 s
 * took 1.03 (60²) and 1.06 (40²) times the separate kernels' time (medians of 5 interleaved
 * pairs), so "separate" is the default; a device whose launches cost more than those reads should
 * gain (not measured: no GPU was at hand). */
static int fused(const struct psolve *ps)
{
  return ps->opt.precond == PSOLVE_MULTIGRID && ps->opt.fuse;
}

/* The buffer that holds p in iteration k: fused, p alternates between d_p (even k: kr_start's zero
 * p is iteration 1's p') and d_p2, as mg_begin_down reads the last p while it writes the new one;
 * else d_p. */
static cl_mem p_of(const struct psolve *ps, int k)
{
  return fused(ps) && (k & 1) ? ps->d_p2 : ps->d_p;
}

/* Enqueue iteration k (krylov.cl): its kernels return at once once the solve has ended. */
static enum clsph_status iteration(struct psolve *ps, const struct psolve_op *op, cl_uint k,
                                   cl_mem x, real tiny)
{
  enum clsph_status st = CLSPH_OK;
  const cl_uint n = (cl_uint)op->n, ng = (cl_uint)ps->ngroups, update = 0;
  const real noise = REAL_EPS; /* (r0, r) below noise ||r0|| ||r||: a breakdown (krylov.cl) */
  /* with the multigrid the kernels that make p and s also make its first sweep dw ∘ p, dw ∘ s
   * (fused, its fine residual too) */
  const cl_uint scale = ps->opt.precond == PSOLVE_MULTIGRID;
  cl_mem dw = scale ? ps->mg.d_dw : ps->d_q, t = scale ? ps->mg.d_t : ps->d_q;
  const cl_mem p = p_of(ps, (int)k);
  if (fused(ps)) {
    const real me = (real)reinforcement(ps);
    const cl_mem pp = p_of(ps, (int)k - 1), res = ps->mg.d_res;
    CLSPH_TRY(KERN_SET(ps->k_begin_down, KARG(n), KARG(k), KARG(ng), KARG(ps->d_state),
                       KARG(ps->d_partial), KARG(pp), KARG(p), KARG(ps->d_r), KARG(ps->d_v),
                       KARG(noise), KARG(dw), KARG(t), KARG(ps->d_row), KARG(ps->d_col),
                       KARG(ps->d_valm), KARG(me), KARG(res)));
    CLSPH_TRY(launch_groups(ps, ps->k_begin_down)); /* ρ', β, p, the cycle's fine level down */
    CLSPH_TRY(mg_apply_coarse(&ps->mg, op->n, ps->d_ph, ps->d_state, k)); /* p̂ <- M⁻¹ p */
  } else {
    CLSPH_TRY(KERN_SET(ps->k_begin, KARG(n), KARG(k), KARG(ng), KARG(update), KARG(ps->d_state),
                       KARG(ps->d_partial), KARG(p), KARG(ps->d_r), KARG(ps->d_v), KARG(noise),
                       KARG(scale), KARG(dw), KARG(t)));
    CLSPH_TRY(launch_groups(ps, ps->k_begin));           /* ρ', β, p */
    CLSPH_TRY(precond(ps, op, p, ps->d_ph, ps->d_q, k)); /* p̂ <- M⁻¹ p */
  }
  CLSPH_TRY(
      apply_dot(ps, op, ps->d_ph, ps->d_v, k, ps->d_r0, KR_R0V_SET, KR_NO_SET)); /* v, (r0, v) */
  if (fused(ps)) {
    const real me = (real)reinforcement(ps);
    const cl_mem res = ps->mg.d_res;
    CLSPH_TRY(KERN_SET(ps->k_s_down, KARG(n), KARG(k), KARG(ng), KARG(ps->d_state),
                       KARG(ps->d_partial), KARG(ps->d_r), KARG(ps->d_v), KARG(ps->d_s), KARG(dw),
                       KARG(t), KARG(ps->d_row), KARG(ps->d_col), KARG(ps->d_valm), KARG(me),
                       KARG(res)));
    CLSPH_TRY(launch_groups(ps, ps->k_s_down)); /* α, s = r − α v, (s, s), the fine level down */
    CLSPH_TRY(mg_apply_coarse(&ps->mg, op->n, ps->d_sh, ps->d_state, k)); /* ŝ <- M⁻¹ s */
  } else {
    CLSPH_TRY(KERN_SET(ps->k_s, KARG(n), KARG(k), KARG(ng), KARG(ps->d_state), KARG(ps->d_partial),
                       KARG(ps->d_r), KARG(ps->d_v), KARG(ps->d_s), KARG(scale), KARG(dw),
                       KARG(t)));
    CLSPH_TRY(launch_groups(ps, ps->k_s));                     /* α, s = r − α v, (s, s) */
    CLSPH_TRY(precond(ps, op, ps->d_s, ps->d_sh, ps->d_q, k)); /* ŝ <- M⁻¹ s */
  }
  CLSPH_TRY(apply_dot(ps, op, ps->d_sh, ps->d_t, k, ps->d_s, KR_TS_SET,
                      KR_TT_SET)); /* t, (t, s), (t, t) */
  CLSPH_TRY(KERN_SET(ps->k_end, KARG(n), KARG(k), KARG(ng), KARG(tiny), KARG(ps->d_state),
                     KARG(ps->d_partial), KARG(x), KARG(ps->d_ph), KARG(ps->d_sh), KARG(ps->d_r),
                     KARG(ps->d_s), KARG(ps->d_t), KARG(ps->d_r0)));
  CLSPH_TRY(launch_groups(ps, ps->k_end)); /* ω, x, r, (r, r), (r0, r) */
done:
  return st;
}

/* The solve in one work-group (krylov_group.cl): a system of at most group_max unknowns with the
 * stored operator and the multigrid (all its levels in the block: mg.c's l0 = 1) or Jacobi. */
static int one_group(const struct psolve *ps, const struct psolve_op *op)
{
  if (op->n > (size_t)ps->opt.group_max || ps->opt.apply != PSOLVE_STORED) return 0;
  if (ps->opt.precond == PSOLVE_MULTIGRID) return ps->mg.l0 == 1;
  return ps->opt.precond == PSOLVE_JACOBI;
}

static enum clsph_status solve_group(struct psolve *ps, const struct psolve_op *op, cl_mem x,
                                     real tiny)
{
  enum clsph_status st = CLSPH_OK;
  const cl_uint n = (cl_uint)op->n, max_it = (cl_uint)ps->opt.max_it;
  const real noise = REAL_EPS;
  const real e = (real)(PSOLVE_REINFORCED(ps->opt.singular) ? ps->opt.reinforce : 0.0);
  /* the multigrid's buffers and ε (its cycle: mg_apply), none with Jacobi */
  const struct mg *mg = &ps->mg;
  const cl_int mgo = ps->opt.precond == PSOLVE_MULTIGRID;
  const real me = (real)reinforcement(ps);
  const cl_int L = mgo ? mg->nlevels : 0;
  const cl_uint m = mgo ? (cl_uint)mg->m : 0u;
  const cl_mem none = NULL;
  const cl_mem valm = mgo ? ps->d_valm : none, dw = mgo ? mg->d_dw : none,
               mt = mgo ? mg->d_t : none, mres = mgo ? mg->d_res : none,
               agg = mgo ? mg->d_agg : none, AP = mgo ? mg->d_AP : none,
               info = mgo ? mg->d_info : none, M = mgo ? mg->d_M : none, S = mgo ? mg->d_S : none,
               nb = mgo ? mg->d_nb : none, pnb = mgo ? mg->d_pnb : none,
               par = mgo ? mg->d_par : none, live = mgo ? mg->d_live : none,
               cdw = mgo ? mg->d_cdw : none, cb = mgo ? mg->d_b : none, ct = mgo ? mg->d_t_c : none,
               cx = mgo ? mg->d_x : none, start = mgo ? mg->grid->d_start : none,
               list = mgo ? mg->d_list : none, nlist = mgo ? mg->d_nlist : none;
  CLSPH_TRY(KERN_SET(ps->k_group, KARG(n), KARG(max_it), KARG(noise), KARG(tiny), KARG(mgo),
                     KARG(ps->d_state), KARG(ps->d_row), KARG(ps->d_col), KARG(ps->d_val), KARG(e),
                     KARG(ps->d_dinv), KARG(x), KARG(ps->d_r), KARG(ps->d_r0), KARG(ps->d_p),
                     KARG(ps->d_v), KARG(ps->d_s), KARG(ps->d_t), KARG(ps->d_ph), KARG(ps->d_sh),
                     KARG(me), KARG(valm), KARG(dw), KARG(mt), KARG(mres), KARG(agg), KARG(AP),
                     KARG(L), KARG(info), KARG(m), KARG(M), KARG(S), KARG(nb), KARG(pnb), KARG(par),
                     KARG(live), KARG(cdw), KARG(cb), KARG(ct), KARG(cx), KARG(start), KARG(list),
                     KARG(nlist)));
  CLSPH_TRY(kern_launch_wg(ps->dev, ps->k_group, ps->group_wg, ps->group_wg, NULL));
done:
  return st;
}

static enum clsph_status bicgstab(struct psolve *ps, const struct psolve_op *op, cl_mem b, cl_mem x,
                                  struct psolve_result *res)
{
  enum clsph_status st = CLSPH_OK;
  const cl_uint n = (cl_uint)op->n, ng = (cl_uint)ps->ngroups;
  const real tiny = (real)(1e3 * REAL_EPS * REAL_EPS), rtol = (real)ps->opt.rtol,
             atol = (real)ps->opt.atol;
  double state[PSOLVE_STATE];
  int restarted_at = -1;
  res->its = 0;
  res->restarts = 0;
  /* b (mean-free for a consistent singular system), r = b − A x (x: the initial guess), r0 = r */
  const int mean_free = PSOLVE_MEAN_FREE(ps->opt.singular);
  if (mean_free) CLSPH_TRY(remove_mean(ps, op, n, b, ps->d_b));
  const cl_mem bm = mean_free ? ps->d_b : b;
  if (ps->opt.apply == PSOLVE_STORED) { /* (b, b), A x and r in one pass */
    const real e = (real)(PSOLVE_REINFORCED(ps->opt.singular) ? ps->opt.reinforce : 0.0);
    CLSPH_TRY(KERN_SET(ps->k_residual_csr, KARG(n), KARG(bm), KARG(ps->d_row), KARG(ps->d_col),
                       KARG(ps->d_val), KARG(e), KARG(x), KARG(ps->d_r), KARG(ps->d_partial)));
    CLSPH_TRY(launch_groups(ps, ps->k_residual_csr));
  } else {
    CLSPH_TRY(dot(ps, n, 0, bm, bm, KR_BB_SET));
    CLSPH_TRY(apply(ps, op, x, ps->d_q, 0));
    CLSPH_TRY(KERN_SET(ps->k_residual, KARG(n), KARG(bm), KARG(ps->d_q), KARG(ps->d_r),
                       KARG(ps->d_partial)));
    CLSPH_TRY(launch_groups(ps, ps->k_residual));
  }
  CLSPH_TRY(KERN_SET(ps->k_start, KARG(n), KARG(ng), KARG(rtol), KARG(atol), KARG(ps->d_flags),
                     KARG(ps->d_state), KARG(ps->d_partial), KARG(x), KARG(ps->d_r), KARG(ps->d_r0),
                     KARG(ps->d_p), KARG(ps->d_v), KARG(ps->d_x0)));
  CLSPH_TRY(launch_groups(ps, ps->k_start));
  /* batches: as many iterations as the last solve took, then a quarter of that. Iterations past
   * the end cost their launches (11 with the multigrid), a short batch one more read of the
   * state: the solves of a run take about as many iterations as the last or fewer (the 40²
   * cavity: 7.1 a step, 0.14 extra reads a step against 2 iterations' launches; the 60² cavity
   * to t = 1 s 5% faster than with two more, median of 5 interleaved pairs). */
  const int max_it = ps->opt.max_it;
  const int recompute = ps->opt.apply == PSOLVE_RECOMPUTE; /* its kernels have no early exit */
  int next = 1, batch = ps->last_its;
  const int group = one_group(ps, op);
  res->one_group = group;
  for (;;) {
    const int last = group ? max_it : (next + batch - 1 < max_it ? next + batch - 1 : max_it);
    if (group) {
      CLSPH_TRY(solve_group(ps, op, x, tiny)); /* every iteration, its restarts and the test */
    } else {
      for (int k = next; k <= last; ++k) CLSPH_TRY(iteration(ps, op, (cl_uint)k, x, tiny));
      const cl_uint check = 1, after = (cl_uint)last + 1, noscale = 0;
      CLSPH_TRY(KERN_SET(ps->k_begin, KARG(n), KARG(after), KARG(ng), KARG(check),
                         KARG(ps->d_state), KARG(ps->d_partial), KARG(ps->d_p), KARG(ps->d_r),
                         KARG(ps->d_v), KARG(tiny), KARG(noscale), KARG(ps->d_q), KARG(ps->d_q)));
      CLSPH_TRY(launch_groups(ps, ps->k_begin)); /* the last residual's test */
    }
    CLSPH_TRY(read_state(ps, state));
    if (group) res->restarts += (int)state[KR_RESTARTS];
    if (ps->opt.precond == PSOLVE_MULTIGRID) mg_report(&ps->mg);
    if (ps->h_overflow != 0 || (int)state[KR_REASON] == KR_CAPACITY)
      break; /* solve() grows the operator and solves again (x is as it was) */
    CLSPH_CHECK(state[KR_DIAG] == 0, CLSPH_E_BLOWUP,
                "%s solve: the operator has a zero or non-finite diagonal entry", ps->opt.name);
    const double done_at = (double)state[KR_DONE];
    const int reason = (int)state[KR_REASON];
    res->rnorm = (double)state[KR_RNORM];
    if (done_at > (double)max_it) { /* still running */
      res->its = last;
      if (last >= max_it) {
        res->reason = PSOLVE_DIVERGED_ITS;
        break;
      }
      next = last + 1;
      batch = recompute ? 1 : (ps->last_its / 4 > 2 ? ps->last_its / 4 : 2);
      continue;
    }
    const int k = (int)done_at;
    res->its = k;
    if (reason == KR_RESTART_RHO || reason == KR_RESTART_OMEGA) {
      /* a vanishing ρ' at iteration k + 1 (which then did nothing: the state ends at k) restarts
       * it (twice in a row: give up), a vanishing ω at iteration k the next: either way the next
       * is k + 1, and reads the slot of k */
      const int rho = reason == KR_RESTART_RHO;
      if (rho && restarted_at == k) {
        res->reason = PSOLVE_DIVERGED_BREAKDOWN;
        break;
      }
      if (rho) restarted_at = k + 1;
      ++res->restarts;
      const cl_uint slot = (cl_uint)k;
      next = k + 1;
      const cl_mem pp = p_of(ps, next - 1); /* the p the next iteration starts from */
      CLSPH_TRY(KERN_SET(ps->k_restart, KARG(n), KARG(slot), KARG(ps->d_state), KARG(ps->d_partial),
                         KARG(ps->d_r), KARG(ps->d_r0), KARG(pp), KARG(ps->d_v)));
      CLSPH_TRY(launch_groups(ps, ps->k_restart));
      batch = recompute ? 1 : ps->last_its;
      if (next > max_it) {
        res->reason = PSOLVE_DIVERGED_ITS;
        break;
      }
      continue;
    }
    res->reason = (enum psolve_reason)reason;
    break;
  }
  if (res->reason > 0 && res->its > 0) ps->last_its = res->its;
  /* a solve that failed further from the solution than it started (BiCGStab's residual can grow
   * by orders: 4.9e107 in isph-stabilized's dam break before its spray rule) or with a non-finite
   * value leaves x the initial guess, the last step's pressure: the step goes on from a field
   * that was an answer, the failure still counted */
  if (res->reason <= 0 && ps->h_overflow == 0 && (int)state[KR_REASON] != KR_CAPACITY &&
      !(isfinite(res->rnorm) && res->rnorm <= state[KR_INIT])) {
    CLSPH_TRY(copy(ps, x, ps->d_x0, n));
    res->rnorm_failed = res->rnorm;
    res->rnorm = state[KR_INIT];
    res->kept_guess = 1;
  }
done:
  if (st == CLSPH_OK && PSOLVE_MEAN_FREE(ps->opt.singular)) st = remove_mean(ps, op, n, x, x);
  return st;
}

static const char *reason_str(enum psolve_reason r)
{
  switch (r) {
  case PSOLVE_CONVERGED_RTOL:
  case PSOLVE_CONVERGED_ATOL:
    return "converged";
  case PSOLVE_DIVERGED_ITS:
    return "reached the iteration limit";
  case PSOLVE_DIVERGED_BREAKDOWN:
    return "broke down";
  case PSOLVE_DIVERGED_NANORINF:
    return "produced a non-finite value";
  }
  return "?";
}

enum clsph_status psolve_precond_setup(struct psolve *ps, const struct psolve_op *op)
{
  enum clsph_status st = CLSPH_OK;
  const int multigrid = ps->opt.precond == PSOLVE_MULTIGRID;
  CLSPH_CHECK(op->n <= ps->cap, CLSPH_E_INPUT, "%s preconditioner: %zu unknowns exceed %zu",
              ps->opt.name, op->n, ps->cap);
  CLSPH_CHECK(!multigrid || op->grid != NULL, CLSPH_E_INPUT,
              "%s preconditioner: the multigrid needs unknowns sorted by a grid", ps->opt.name);
  CLSPH_TRY(store(ps, op, 0)); /* unguarded: the count is read and the buffers grow to it */
  CLSPH_TRY(diagonal(ps, op));
  if (multigrid)
    CLSPH_TRY(mg_setup(&ps->mg, op->grid, op->n, ps->d_row, ps->d_col, ps->d_val, ps->d_valm,
                       reinforcement(ps), ps->d_dinv));
  /* a state that never ended, so that the cycle's kernels of "iteration 0" run (krylov.cl) */
  double big[PSOLVE_STATE] = {0};
  float bigf[PSOLVE_STATE] = {0};
  big[0] = 1e30;
  bigf[0] = 1e30f;
  if (ps->state_double)
    CLSPH_TRY(kern_write(ps->dev, ps->d_state, sizeof big, big));
  else
    CLSPH_TRY(kern_write(ps->dev, ps->d_state, sizeof bigf, bigf));
done:
  return st;
}

enum clsph_status psolve_precond_apply(struct psolve *ps, const struct psolve_op *op, cl_mem r,
                                       cl_mem z)
{
  enum clsph_status st = CLSPH_OK;
  if (ps->opt.precond == PSOLVE_MULTIGRID) { /* the cycle's first sweep from zero: t = dw ∘ r */
    const cl_uint n = (cl_uint)op->n, k = 0;
    CLSPH_TRY(KERN_SET(ps->k_scale, KARG(n), KARG(k), KARG(ps->d_state), KARG(ps->mg.d_t),
                       KARG(ps->mg.d_dw), KARG(r)));
    CLSPH_TRY(launch(ps, ps->k_scale, n));
  }
  CLSPH_TRY(precond(ps, op, r, z, ps->d_t, 0));
done:
  return st;
}

/* set_up = 0: the stored layout, diagonal and multigrid levels of the last solve serve again */
static enum clsph_status solve(struct psolve *ps, const struct psolve_op *op, cl_mem b, cl_mem x,
                               struct psolve_result *res, int set_up)
{
  enum clsph_status st = CLSPH_OK;
  double t0 = now();
  memset(res, 0, sizeof *res);
  CLSPH_CHECK(op->n <= ps->cap, CLSPH_E_INPUT, "%s solve: %zu unknowns exceed %zu", ps->opt.name,
              op->n, ps->cap);
  if (ps->opt.method == PSOLVE_DIRECT) {
    CLSPH_TRY(psolve_direct(ps, op, b, x, res));
    goto done;
  }
  const int multigrid = ps->opt.precond == PSOLVE_MULTIGRID;
  CLSPH_CHECK(!multigrid || op->grid != NULL, CLSPH_E_INPUT,
              "%s solve: solver_precond = \"multigrid\" needs unknowns that are particles "
              "sorted by a grid, which this operator does not have",
              ps->opt.name);
  for (int pass = 0;; ++pass) {
    if (set_up) {
      ps->h_overflow = 0;
      if (ps->opt.apply == PSOLVE_STORED || multigrid) CLSPH_TRY(store(ps, op, multigrid && !pass));
      CLSPH_TRY(diagonal(ps, op));
      if (multigrid)
        CLSPH_TRY(mg_setup(&ps->mg, op->grid, op->n, ps->d_row, ps->d_col, ps->d_val, ps->d_valm,
                           reinforcement(ps), ps->d_dinv));
    }
    CLSPH_TRY(bicgstab(ps, op, b, x, res));
    if (ps->h_overflow == 0) break; /* the rows fitted (the solve's first wait brought the count) */
    log_debug("%s solve: %u nonzeros pass the stored operator's %zu: growing, solving again",
              ps->opt.name, (unsigned)ps->h_overflow, ps->nnz_cap);
    CLSPH_TRY(grow(ps, ps->h_overflow));
    set_up = 1;
  }
  log_debug("%s solve: %s, %d iterations, residual %.3g", ps->opt.name, reason_str(res->reason),
            res->its, res->rnorm);
  if (res->reason > 0) {
    ps->failures = 0;
  } else {
    ++ps->failures;
    if (res->kept_guess)
      log_warn("%s solve %s after %d iterations (residual %.3g, tolerance %.3g): kept its "
               "initial guess (residual %.3g)",
               ps->opt.name, reason_str(res->reason), res->its, res->rnorm_failed, ps->opt.rtol,
               res->rnorm);
    else
      log_warn("%s solve %s after %d iterations (residual %.3g, tolerance %.3g)", ps->opt.name,
               reason_str(res->reason), res->its, res->rnorm, ps->opt.rtol);
    CLSPH_CHECK(ps->failures < ps->opt.max_failures, CLSPH_E_BLOWUP,
                "the %s solve failed %d times in a row (last residual %.3g): stopping; the "
                "scheme options solver_rtol, solver_max_it and solver_precond set what a solve "
                "must reach and how",
                ps->opt.name, ps->failures, res->rnorm);
  }
done:
  res->seconds = now() - t0;
  return st;
}

enum clsph_status psolve_solve(struct psolve *ps, const struct psolve_op *op, cl_mem b, cl_mem x,
                               struct psolve_result *res)
{
  return solve(ps, op, b, x, res, 1);
}

enum clsph_status psolve_solve_again(struct psolve *ps, const struct psolve_op *op, cl_mem b,
                                     cl_mem x, struct psolve_result *res)
{
  return solve(ps, op, b, x, res, 0);
}

enum clsph_status psolve_assemble(struct psolve *ps, const struct psolve_op *op, size_t **row,
                                  int **col, double **val)
{
  enum clsph_status st = CLSPH_OK;
  const size_t n = op->n;
  cl_uint *r = NULL, *c = NULL;
  real *v = NULL;
  size_t *rows = NULL;
  int *cols = NULL;
  double *vals = NULL;
  CLSPH_TRY(store(ps, op, 0));
  r = malloc((n + 1) * sizeof *r);
  CLSPH_CHECK(r != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(kern_read(ps->dev, ps->d_row, (n + 1) * sizeof *r, r));
  size_t nnz = r[n];
  c = malloc(nnz * sizeof *c);
  v = malloc(nnz * sizeof *v);
  rows = malloc((n + 1) * sizeof *rows);
  cols = malloc(nnz * sizeof *cols);
  vals = malloc(nnz * sizeof *vals);
  CLSPH_CHECK(c && v && rows && cols && vals, CLSPH_E_NOMEM, "out of memory for %zu entries", nnz);
  CLSPH_TRY(kern_read(ps->dev, ps->d_col, nnz * sizeof *c, c));
  CLSPH_TRY(kern_read(ps->dev, ps->d_val, nnz * sizeof *v, v));
  for (size_t i = 0; i <= n; ++i) rows[i] = r[i];
  for (size_t i = 0; i < n; ++i) { /* copy with the columns of each row sorted (insertion) */
    for (size_t k = r[i]; k < r[i + 1]; ++k) {
      int cc = (int)c[k];
      double vv = (double)v[k];
      if (cc == (int)i && PSOLVE_REINFORCED(ps->opt.singular)) vv *= 1.0 + ps->opt.reinforce;
      size_t m = k;
      while (m > r[i] && cols[m - 1] > cc) {
        cols[m] = cols[m - 1];
        vals[m] = vals[m - 1];
        --m;
      }
      cols[m] = cc;
      vals[m] = vv;
    }
  }
  *row = rows;
  *col = cols;
  *val = vals;
  rows = NULL;
  cols = NULL;
  vals = NULL;
done:
  free(vals);
  free(cols);
  free(rows);
  free(v);
  free(c);
  free(r);
  return st;
}

void psolve_destroy(struct psolve *ps)
{
  cl_kernel *ks[] = {
      &ps->k_dot,      &ps->k_dot_ts,   &ps->k_residual,     &ps->k_shift,        &ps->k_start,
      &ps->k_begin,    &ps->k_s,        &ps->k_end,          &ps->k_restart,      &ps->k_total,
      &ps->k_spmv,     &ps->k_spmv_dot, &ps->k_scale,        &ps->k_sweep,        &ps->k_axpy,
      &ps->k_add_diag, &ps->k_invert,   &ps->k_csr_diag_inv, &ps->k_residual_csr, &ps->k_wtotal,
      &ps->k_wshift,   &ps->k_guard,    &ps->k_group,        &ps->k_begin_down,   &ps->k_s_down};
  for (size_t i = 0; i < sizeof ks / sizeof *ks; ++i) {
    if (*ks[i] != NULL) clReleaseKernel(*ks[i]);
    *ks[i] = NULL;
  }
  grid_scan_destroy(&ps->scan);
  kern_release(&ps->d_state);
  cl_mem *ms[] = {&ps->d_r,       &ps->d_r0,    &ps->d_p,   &ps->d_v,    &ps->d_s,    &ps->d_t,
                  &ps->d_ph,      &ps->d_sh,    &ps->d_q,   &ps->d_dinv, &ps->d_diag, &ps->d_b,
                  &ps->d_partial, &ps->d_flags, &ps->d_row, &ps->d_col,  &ps->d_val,  &ps->d_count,
                  &ps->d_block,   &ps->d_valm,  &ps->d_x0,  &ps->d_p2};
  for (size_t i = 0; i < sizeof ms / sizeof *ms; ++i) kern_release(ms[i]);
  mg_destroy(&ps->mg);
  kern_reserve(-ps->reserved);
  ps->reserved = 0.0;
}
