/* ranks.c: clsph-ranks, the pressure solve split across MPI ranks (README, "Beyond one device"),
 * built where Open MPI is installed; `clsph-ranks run` splits a whole run (ranks_run.c). Run under
 * mpiexec:
 *
 *   mpiexec -n 2 clsph-ranks psolve [--side N] [--jitter J] [--kgc 0|1] [--rtol R] [--max-it M]
 *                                   [--reps K] [--device I] [--json FILE] [--no-check]
 *                                   [--one-sum] [--precond jacobi|multigrid]
 *
 * Each rank builds its slab of the manufactured problem (pslab.h: its rows and the rows they
 * reach), stores its rows on its device and solves with dsolve (BiCGStab + Jacobi, halo exchanges
 * and global sums through MPI; --one-sum: one global sum an iteration instead of three;
 * --precond multigrid: each rank's own multigrid V-cycle on its rows instead of Jacobi). Rank 0
 * gathers the solution by global index and, unless
 * --no-check, solves the whole problem alone with the production solver (psolve.c, the same
 * preconditioner, its multigrid over the whole problem, and tolerance) and reports the difference,
 * the iterations of both and the error against the exact solution. It prints the figures and writes
 * them as JSON. Exit codes: 0, 1 failure (a solve that did not converge too), 2 bad command line.
 */
#include <math.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "clsph_config.h"
#include "dev.h"
#include "log.h"
#include "prog.h"
#include "pslab.h"
#include "ranks_run.h"

#if CLSPH_DOUBLE
#define MPI_REAL_T MPI_DOUBLE
#else
#define MPI_REAL_T MPI_FLOAT
#endif

struct mpi_ctx {
  MPI_Comm comm;
  int nbr[DSOLVE_MAX_NBRS];
  int nbrs;
};

static enum clsph_status mpi_sum(void *ctx, double *v, int n)
{
  const struct mpi_ctx *c = ctx;
  const int rc = MPI_Allreduce(MPI_IN_PLACE, v, n, MPI_DOUBLE, MPI_SUM, c->comm);
  if (rc != MPI_SUCCESS) {
    log_error("MPI_Allreduce of %d values failed (%d)", n, rc);
    return CLSPH_E_IO;
  }
  return CLSPH_OK;
}

static enum clsph_status mpi_exchange(void *ctx, const real *send, const size_t *nsend, real *recv,
                                      const size_t *nrecv)
{
  const struct mpi_ctx *c = ctx;
  MPI_Request req[2 * DSOLVE_MAX_NBRS];
  size_t so = 0, ro = 0;
  int nreq = 0, rc = MPI_SUCCESS;
  for (int k = 0; k < c->nbrs && rc == MPI_SUCCESS; ++k) {
    rc = MPI_Irecv(recv + ro, (int)nrecv[k], MPI_REAL_T, c->nbr[k], 7, c->comm, &req[nreq++]);
    if (rc == MPI_SUCCESS)
      rc = MPI_Isend(send + so, (int)nsend[k], MPI_REAL_T, c->nbr[k], 7, c->comm, &req[nreq++]);
    so += nsend[k];
    ro += nrecv[k];
  }
  if (rc == MPI_SUCCESS) rc = MPI_Waitall(nreq, req, MPI_STATUSES_IGNORE);
  if (rc != MPI_SUCCESS) {
    log_error("the halo exchange failed (MPI error %d)", rc);
    return CLSPH_E_IO;
  }
  return CLSPH_OK;
}

struct opts {
  int side, kgc, max_it, reps, device, check, one_sum;
  enum psolve_precond precond;
  double jitter, rtol;
  const char *json;
};

static int parse(int argc, char **argv, struct opts *o, int rank)
{
  *o = (struct opts){.side = 64,
                     .kgc = 1,
                     .max_it = 5000,
                     .reps = 3,
                     .device = -1,
                     .check = 1,
                     .jitter = 0.3,
                     .rtol = CLSPH_DOUBLE ? 1e-10 : 1e-5,
                     .json = NULL};
  if (argc < 2 || strcmp(argv[1], "psolve") != 0) {
    if (rank == 0)
      fprintf(stderr, "usage: mpiexec -n RANKS clsph-ranks psolve [--side N] [--jitter J] "
                      "[--kgc 0|1] [--rtol R] [--max-it M] [--reps K] [--device I] [--json FILE] "
                      "[--no-check] [--one-sum] [--precond jacobi|multigrid]\n"
                      "       mpiexec -n RANKS clsph-ranks run CASE [--set NAME=VALUE ...] "
                      "[--halo SWEEPS] [--cuts X1,X2,...] [--recut STEPS] [--device I] "
                      "[--json FILE] [--out DIR] [--no-check]\n");
    return 0;
  }
  for (int i = 2; i < argc; ++i) {
    const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
    char *end = NULL;
    int ok = 1;
    if (strcmp(a, "--no-check") == 0) {
      o->check = 0;
      continue;
    }
    if (strcmp(a, "--one-sum") == 0) {
      o->one_sum = 1;
      continue;
    }
    if (v == NULL) {
      if (rank == 0) fprintf(stderr, "clsph-ranks: %s needs a value\n", a);
      return 0;
    }
    ++i;
    if (strcmp(a, "--json") == 0) {
      o->json = v;
      continue;
    }
    if (strcmp(a, "--precond") == 0) {
      if (strcmp(v, "jacobi") == 0 || strcmp(v, "multigrid") == 0) {
        o->precond = strcmp(v, "jacobi") == 0 ? PSOLVE_JACOBI : PSOLVE_MULTIGRID;
        continue;
      }
      if (rank == 0)
        fprintf(stderr, "clsph-ranks: --precond %s: the preconditioners are jacobi and multigrid\n",
                v);
      return 0;
    }
    const double x = strtod(v, &end);
    ok = end != v && *end == '\0' && isfinite(x);
    if (ok && strcmp(a, "--side") == 0)
      ok = x >= 8 && x <= 4096 && x == floor(x), o->side = (int)x;
    else if (ok && strcmp(a, "--kgc") == 0)
      ok = x == 0 || x == 1, o->kgc = (int)x;
    else if (ok && strcmp(a, "--max-it") == 0)
      ok = x >= 1 && x <= 1e6 && x == floor(x), o->max_it = (int)x;
    else if (ok && strcmp(a, "--reps") == 0)
      ok = x >= 1 && x <= 100 && x == floor(x), o->reps = (int)x;
    else if (ok && strcmp(a, "--device") == 0)
      ok = x >= 0 && x == floor(x), o->device = (int)x;
    else if (ok && strcmp(a, "--jitter") == 0)
      ok = x >= 0 && x <= 0.5, o->jitter = x;
    else if (ok && strcmp(a, "--rtol") == 0)
      ok = x >= 4.0 * REAL_EPS && x < 1.0, o->rtol = x;
    else if (ok) {
      if (rank == 0) fprintf(stderr, "clsph-ranks: unknown option '%s'\n", a);
      return 0;
    }
    if (!ok) {
      if (rank == 0)
        fprintf(stderr,
                "clsph-ranks: %s %s is not a number in its range (side 8-4096, kgc 0 or 1, "
                "max-it 1-1e6, reps 1-100, jitter 0-0.5, rtol from 4 epsilon (%.2g) to 1)\n",
                a, v, 4.0 * REAL_EPS);
      return 0;
    }
  }
  return 1;
}

static int cmp_double(const void *a, const void *b)
{
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* Rank 0: the whole problem solved alone by psolve (Jacobi, the same tolerance); its iterations,
 * its solution by global index, and the error of `xg` (by global index) against the exact one. */
static enum clsph_status reference(const struct dev *dev, const struct pproblem_spec *spec,
                                   enum psolve_precond precond, double rtol, int max_it,
                                   const double *xg, int *its, double *diff, double *err,
                                   double *err_ref)
{
  enum clsph_status st = CLSPH_OK;
  struct pproblem pp;
  struct psolve ps;
  struct psolve_options o;
  struct psolve_result res;
  cl_uint *gid = NULL;
  double *xr = NULL;
  real *xs = NULL;
  const real zero = 0;
  memset(&pp, 0, sizeof pp);
  memset(&ps, 0, sizeof ps);
  CLSPH_TRY(pproblem_create(dev, spec, &pp));
  const size_t n = pp.n;
  gid = malloc(n * sizeof *gid);
  xr = malloc(n * sizeof *xr);
  xs = malloc(n * sizeof *xs);
  CLSPH_CHECK(gid && xr && xs, CLSPH_E_NOMEM, "out of memory");
  psolve_defaults(&o);
  o.precond = precond;
  o.apply = PSOLVE_STORED;
  o.rtol = rtol;
  o.max_it = max_it;
  o.group_max = 0;
  cl_mem x = pset_mem(&pp.ps, pp.f_x);
  CLSPH_TRY(psolve_create(dev, pp.prog, n, &o, &ps));
  CLSPH_TRY(kern_fill(dev, x, &zero, sizeof zero, n * sizeof(real)));
  CLSPH_TRY(psolve_solve(&ps, &pp.po.op, pset_mem(&pp.ps, pp.f_b), x, &res));
  CLSPH_CHECK(res.reason > 0, CLSPH_E_BLOWUP, "the whole problem's solve did not converge");
  *its = res.its;
  CLSPH_TRY(pproblem_error(&pp, x, err_ref));
  CLSPH_TRY(pproblem_read(&pp, x, xr));
  CLSPH_TRY(kern_read(dev, pset_mem(&pp.ps, pp.f_gid), n * sizeof *gid, gid));
  double d = 0.0, m = 0.0;
  for (size_t i = 0; i < n; ++i) {
    d = fmax(d, fabs(xg[gid[i]] - xr[i]));
    m = fmax(m, fabs(xr[i]));
    xs[i] = (real)xg[gid[i]];
  }
  *diff = d / m;
  CLSPH_TRY(kern_write(dev, x, n * sizeof *xs, xs));
  CLSPH_TRY(pproblem_error(&pp, x, err));
done:
  psolve_destroy(&ps);
  pproblem_destroy(&pp);
  free(xs);
  free(xr);
  free(gid);
  return st;
}

int main(int argc, char **argv)
{
  enum clsph_status st = CLSPH_OK;
  int rank = 0, size = 1, converged = 0, its_ref = -1;
  struct opts o;
  struct dev dev;
  struct pslab slab;
  struct dsolve ds;
  struct dsolve_result res;
  struct mpi_ctx mc;
  double *xo = NULL, *xg = NULL, *all_x = NULL, *times = NULL;
  cl_uint *all_gid = NULL;
  int *counts = NULL, *displs = NULL;
  double diff = NAN, err = NAN, err_ref = NAN;
  const real zero = 0;
  memset(&dev, 0, sizeof dev);
  memset(&slab, 0, sizeof slab);
  memset(&ds, 0, sizeof ds);
  memset(&res, 0, sizeof res);
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (argc >= 2 && strcmp(argv[1], "run") == 0) { /* a whole run split (ranks_run.c) */
    const int rc = ranks_run(argc, argv, MPI_COMM_WORLD);
    MPI_Finalize();
    return rc;
  }
  if (!parse(argc, argv, &o, rank)) {
    MPI_Finalize();
    return 2;
  }
  prog_set_cache_dir(NULL);
  struct pproblem_spec spec = {.side = o.side, .jitter = o.jitter, .kgc = o.kgc, .seed = 11};
  CLSPH_TRY(dev_open(o.device, CLSPH_DOUBLE, &dev));
  CLSPH_TRY(pslab_create(&dev, &spec, rank, size, o.precond, &slab));
  mc.comm = MPI_COMM_WORLD;
  mc.nbrs = slab.layout.nbrs;
  for (int k = 0; k < mc.nbrs; ++k) mc.nbr[k] = slab.nbr[k];
  const struct dsolve_comm comm = {.ctx = &mc, .sum = mpi_sum, .exchange = mpi_exchange};
  CLSPH_TRY(dsolve_create(&dev, slab.pp.prog, &slab.layout, &comm, pslab_precond(&slab), &ds));
  times = malloc((size_t)o.reps * sizeof *times);
  CLSPH_CHECK(times != NULL, CLSPH_E_NOMEM, "out of memory");
  for (int r = 0; r < o.reps; ++r) { /* cold solves from x = 0; the slowest rank's time */
    CLSPH_TRY(kern_fill(&dev, slab.d_x, &zero, sizeof zero, slab.layout.n * sizeof(real)));
    CLSPH_TRY(kern_finish(&dev));
    MPI_Barrier(MPI_COMM_WORLD);
    CLSPH_TRY(dsolve_solve(&ds, slab.d_b, slab.d_x, o.rtol, o.max_it,
                           o.one_sum ? DSOLVE_ONE_SUM : DSOLVE_BICGSTAB, &res));
    MPI_Allreduce(MPI_IN_PLACE, &res.stats.seconds, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    times[r] = res.stats.seconds;
  }
  qsort(times, (size_t)o.reps, sizeof *times, cmp_double);
  converged = res.converged;
  /* the solution by global index on rank 0 */
  const int nown = (int)slab.layout.nown;
  xo = malloc((size_t)(nown > 0 ? nown : 1) * sizeof *xo);
  CLSPH_CHECK(xo != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(pslab_read_owned(&slab, slab.d_x, xo));
  const size_t total = (size_t)o.side * (size_t)slab.pp.rows;
  if (rank == 0) {
    counts = malloc((size_t)size * sizeof *counts);
    displs = malloc((size_t)size * sizeof *displs);
    all_x = malloc(total * sizeof *all_x);
    all_gid = malloc(total * sizeof *all_gid);
    xg = malloc(total * sizeof *xg);
    CLSPH_CHECK(counts && displs && all_x && all_gid && xg, CLSPH_E_NOMEM, "out of memory");
  }
  MPI_Gather(&nown, 1, MPI_INT, counts, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (rank == 0) {
    int at = 0;
    for (int r = 0; r < size; ++r) displs[r] = at, at += counts[r];
    CLSPH_CHECK((size_t)at == total, CLSPH_E_UNSUPPORTED,
                "the ranks own %d unknowns of the problem's %zu", at, total);
  }
  MPI_Gatherv(xo, nown, MPI_DOUBLE, all_x, counts, displs, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  MPI_Gatherv(slab.gid, nown, MPI_UNSIGNED, all_gid, counts, displs, MPI_UNSIGNED, 0,
              MPI_COMM_WORLD);
  /* the costs: the slowest rank's time in exchanges and sums, the bytes of all ranks */
  double cost[3] = {res.stats.exchange_comm_seconds, res.stats.sum_comm_seconds,
                    res.stats.bytes_sent};
  MPI_Allreduce(MPI_IN_PLACE, cost, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, cost + 2, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  long halo = (long)(slab.layout.n - slab.layout.nown);
  MPI_Allreduce(MPI_IN_PLACE, &halo, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0) {
    for (size_t k = 0; k < total; ++k) xg[all_gid[k]] = all_x[k];
    if (o.check)
      CLSPH_TRY(
          reference(&dev, &spec, o.precond, o.rtol, o.max_it, xg, &its_ref, &diff, &err, &err_ref));
    const double med = times[o.reps / 2], per = res.its > 0 ? med / res.its : 0.0;
    printf("pressure solve split across %d ranks: %zu unknowns (%d per side, jitter %g, %s), "
           "%s\n",
           size, total, o.side, o.jitter, o.kgc ? "corrected Laplacian" : "Morris Laplacian",
           CLSPH_PRECISION_NAME);
    printf("  %s, %s: iterations %d (whole problem alone, psolve: %d), relative residual %.2e "
           "(recomputed %.2e), %s\n",
           o.one_sum ? "BiCGStab with one global sum an iteration" : "BiCGStab",
           o.precond == PSOLVE_MULTIGRID ? "each rank's multigrid" : "Jacobi", res.its, its_ref,
           res.rnorm, res.rnorm_true, converged ? "converged" : "NOT converged");
    printf("  solve %.4f s (median of %d), %.3f ms an iteration; in MPI (the last solve, the "
           "rank longest in each): halo exchanges %.1f%%, global sums %.1f%%\n",
           med, o.reps, 1e3 * per, 100.0 * cost[0] / res.stats.seconds,
           100.0 * cost[1] / res.stats.seconds);
    printf("  %ld exchanges and %ld sums a solve; %ld halo unknowns over the ranks, %.0f bytes "
           "sent an iteration\n",
           res.stats.exchanges, res.stats.sums, halo, res.its > 0 ? cost[2] / res.its : 0.0);
    if (o.check)
      printf("  against the whole problem: max |x − x_alone| / max |x_alone| = %.2e; error "
             "against the exact solution %.4e (alone %.4e)\n",
             diff, err, err_ref);
    if (o.json != NULL) {
      cJSON *j = cJSON_CreateObject();
      CLSPH_CHECK(j != NULL, CLSPH_E_NOMEM, "out of memory");
      cJSON_AddNumberToObject(j, "ranks", size);
      cJSON_AddNumberToObject(j, "unknowns", (double)total);
      cJSON_AddNumberToObject(j, "side", o.side);
      cJSON_AddStringToObject(j, "precision", CLSPH_PRECISION_NAME);
      cJSON_AddBoolToObject(j, "converged", converged);
      cJSON_AddNumberToObject(j, "iterations", res.its);
      cJSON_AddNumberToObject(j, "iterations_alone", its_ref);
      cJSON_AddNumberToObject(j, "rnorm", res.rnorm);
      cJSON_AddNumberToObject(j, "rnorm_true", res.rnorm_true);
      cJSON_AddStringToObject(j, "variant", o.one_sum ? "one-sum" : "bicgstab");
      cJSON_AddStringToObject(j, "precond", o.precond == PSOLVE_MULTIGRID ? "multigrid" : "jacobi");
      cJSON_AddNumberToObject(j, "restarts", res.restarts);
      cJSON_AddNumberToObject(j, "seconds", med);
      cJSON_AddNumberToObject(j, "exchange_mpi_seconds", cost[0]);
      cJSON_AddNumberToObject(j, "sum_mpi_seconds", cost[1]);
      cJSON_AddNumberToObject(j, "exchanges", (double)res.stats.exchanges);
      cJSON_AddNumberToObject(j, "sums", (double)res.stats.sums);
      cJSON_AddNumberToObject(j, "halo_unknowns", (double)halo);
      cJSON_AddNumberToObject(j, "bytes_per_iteration", res.its > 0 ? cost[2] / res.its : 0.0);
      if (o.check) {
        cJSON_AddNumberToObject(j, "diff_alone", diff);
        cJSON_AddNumberToObject(j, "error", err);
        cJSON_AddNumberToObject(j, "error_alone", err_ref);
      }
      st = ranks_write_json(o.json, j);
      cJSON_Delete(j);
      if (st != CLSPH_OK) goto done;
    }
  }
  CLSPH_CHECK(converged, CLSPH_E_BLOWUP,
              "the split solve did not converge in %d iterations (residual %.2e)", o.max_it,
              res.rnorm);
done:
  dsolve_destroy(&ds);
  pslab_destroy(&slab);
  dev_close(&dev);
  free(times);
  free(xo);
  free(xg);
  free(all_x);
  free(all_gid);
  free(counts);
  free(displs);
  if (st != CLSPH_OK && size > 1) /* a failed rank stops the others, which wait in a collective */
    MPI_Abort(MPI_COMM_WORLD, st == CLSPH_E_INPUT ? 2 : 1);
  MPI_Finalize();
  return st == CLSPH_OK ? 0 : st == CLSPH_E_INPUT ? 2 : 1;
}
