/* test_dsolve.c: the pressure solve split across ranks (dsolve.h) and the slabs it is tested on
 * (pslab.h), without MPI (the runs of clsph-ranks under mpiexec are the ranks_* tests).
 *   - The slabs' rows: every row of the jittered, corrected problem (40 per side) built by a slab
 *     of 2 or 3 ranks from its own and its halo particles equals the whole problem's row (the
 *     same columns by global index, the values to rounding): the halo reaches far enough (and
 *     no farther than it must: one row less, which a build was tried with, loses columns).
 *   - The exchange lists: what rank r sends its upper neighbour is, in order, the halo that
 *     neighbour reads from below, and back; every unknown is owned once.
 *   - One rank: dsolve (BiCGStab + Jacobi, the host's loop) takes the iterations of psolve's
 *     Jacobi on the whole problem within one, and gives its solution to the solver's tolerance;
 *     the one-sum variant within three, its recomputed residual within the tolerance, one global
 *     sum an iteration; with the rank's own multigrid (pslab.c) psolve's multigrid iterations
 *     within one and its solution.
 *   - Bad input: too many ranks for the rows, a singular problem, a zero tolerance.
 * Float builds solve to 1e-5 and compare at 2e-4 (the Laplacian's condition number, ~160 at 40
 * per side, times the float tolerance); the rows agree to 1e-5 of their largest entry (the
 * kernel sums in float, in another order). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clsph_config.h"
#include "pslab.h"
#include "tcheck.h"

static const double rtol = CLSPH_DOUBLE ? 1e-10 : 1e-5;
static const double agree = CLSPH_DOUBLE ? 1e-9 : 2e-4;
static const double row_tol = CLSPH_DOUBLE ? 1e-11 : 1e-5;

static const struct pproblem_spec spec = {.side = 40, .jitter = 0.3, .kgc = 1, .seed = 7};

/* the whole problem's rows by global index (host CSR, columns as global indices) */
struct whole {
  struct pproblem pp;
  size_t *row;
  int *col;
  double *val;
  cl_uint *gid;
  size_t *at; /* sorted index of each global index */
};

static void whole_free(struct whole *w)
{
  free(w->row);
  free(w->col);
  free(w->val);
  free(w->gid);
  free(w->at);
  pproblem_destroy(&w->pp);
}

static int whole_make(const struct dev *dev, struct whole *w)
{
  struct psolve ps;
  struct psolve_options o;
  memset(w, 0, sizeof *w);
  memset(&ps, 0, sizeof ps);
  psolve_defaults(&o);
  o.precond = PSOLVE_JACOBI;
  int ok = pproblem_create(dev, &spec, &w->pp) == CLSPH_OK &&
           psolve_create(dev, w->pp.prog, w->pp.n, &o, &ps) == CLSPH_OK &&
           psolve_assemble(&ps, &w->pp.po.op, &w->row, &w->col, &w->val) == CLSPH_OK;
  psolve_destroy(&ps);
  if (!ok) return 0;
  w->gid = malloc(w->pp.n * sizeof *w->gid);
  w->at = malloc(w->pp.n * sizeof *w->at);
  if (w->gid == NULL || w->at == NULL ||
      kern_read(dev, pset_mem(&w->pp.ps, w->pp.f_gid), w->pp.n * sizeof *w->gid, w->gid))
    return 0;
  for (size_t i = 0; i < w->pp.n; ++i) w->at[w->gid[i]] = i;
  return 1;
}

struct entry {
  cl_uint gid;
  double val;
};
static int cmp_entry(const void *a, const void *b)
{
  const cl_uint x = ((const struct entry *)a)->gid, y = ((const struct entry *)b)->gid;
  return (x > y) - (x < y);
}

/* the slab's owned rows against the whole problem's: the worst difference over the largest entry
 * of its row, and rows whose columns differ */
static void compare_rows(const struct pslab *s, const struct whole *w, double *worst, int *bad)
{
  struct entry a[256], b[256];
  *worst = 0.0;
  *bad = 0;
  for (size_t i = 0; i < s->layout.nown; ++i) {
    const size_t j = w->at[s->gid[i]];
    const size_t na = s->row[i + 1] - s->row[i], nb = w->row[j + 1] - w->row[j];
    if (na != nb || na > 256) {
      ++*bad;
      continue;
    }
    double big = 0.0;
    for (size_t k = 0; k < na; ++k) {
      a[k] = (struct entry){s->gid[s->col[s->row[i] + k]], s->val[s->row[i] + k]};
      b[k] = (struct entry){w->gid[w->col[w->row[j] + k]], w->val[w->row[j] + k]};
      big = fmax(big, fabs(b[k].val));
    }
    qsort(a, na, sizeof *a, cmp_entry);
    qsort(b, nb, sizeof *b, cmp_entry);
    for (size_t k = 0; k < na; ++k) {
      if (a[k].gid != b[k].gid) {
        ++*bad;
        break;
      }
      *worst = fmax(*worst, fabs(a[k].val - b[k].val) / big);
    }
  }
}

static void check_split(const struct dev *dev, const struct whole *w, int nranks)
{
  struct pslab s[3];
  memset(s, 0, sizeof s);
  int made = 0;
  for (int r = 0; r < nranks; ++r, ++made)
    if (pslab_create(dev, &spec, r, nranks, PSOLVE_JACOBI, &s[r]) != CLSPH_OK) break;
  TC_CHECK(made == nranks, "%d ranks: every slab builds", nranks);
  if (made < nranks) goto done;
  /* every unknown owned once */
  unsigned char *owned = calloc(w->pp.n, 1);
  size_t total = 0;
  int twice = 0;
  for (int r = 0; r < nranks; ++r)
    for (size_t i = 0; i < s[r].layout.nown; ++i, ++total) twice += owned[s[r].gid[i]]++ > 0;
  free(owned);
  TC_CHECK(total == w->pp.n && twice == 0, "%d ranks own %zu unknowns of %zu, %d twice", nranks,
           total, w->pp.n, twice);
  for (int r = 0; r < nranks; ++r) {
    double worst = 0.0;
    int bad = 0;
    compare_rows(&s[r], w, &worst, &bad);
    TC_CHECK(bad == 0,
             "%d ranks, rank %d: every owned row has the whole problem's columns (%d "
             "differ)",
             nranks, r, bad);
    TC_NEAR(worst, 0.0, row_tol, "%d ranks, rank %d: owned rows = the whole problem's", nranks, r);
    TC_CHECK(s[r].layout.nbrs == (r > 0) + (r + 1 < nranks), "%d ranks, rank %d: %d neighbours",
             nranks, r, s[r].layout.nbrs);
  }
  /* rank r's sends to r + 1 are r + 1's halo from below, in order, and back */
  for (int r = 0; r + 1 < nranks; ++r) {
    const struct pslab *lo = &s[r], *hi = &s[r + 1];
    const int up = lo->layout.nbrs - 1; /* the upper neighbour is the last */
    size_t off = 0;
    for (int k = 0; k < up; ++k) off += lo->nsend[k];
    int same = lo->nsend[up] == hi->nrecv[0];
    for (size_t k = 0; same && k < lo->nsend[up]; ++k)
      same = lo->gid[lo->send[off + k]] == hi->gid[hi->layout.nown + k];
    TC_CHECK(same, "%d ranks: rank %d's %zu sends up = rank %d's halo from below (%zu)", nranks, r,
             lo->nsend[up], r + 1, hi->nrecv[0]);
    same = hi->nsend[0] == lo->nrecv[up];
    size_t below = 0; /* lo's halo from its own lower neighbour comes first */
    for (int k = 0; k < up; ++k) below += lo->nrecv[k];
    for (size_t k = 0; same && k < hi->nsend[0]; ++k)
      same = hi->gid[hi->send[k]] == lo->gid[lo->layout.nown + below + k];
    TC_CHECK(same, "%d ranks: rank %d's %zu sends down = rank %d's halo from above (%zu)", nranks,
             r + 1, hi->nsend[0], r, lo->nrecv[up]);
  }
done:
  for (int r = 0; r < nranks; ++r) pslab_destroy(&s[r]);
}

static enum clsph_status no_sum(void *ctx, double *v, int n)
{
  (void)ctx;
  (void)v;
  (void)n;
  return CLSPH_OK;
}
static enum clsph_status no_exchange(void *ctx, const real *send, const size_t *nsend, real *recv,
                                     const size_t *nrecv)
{
  (void)ctx;
  (void)send;
  (void)nsend;
  (void)recv;
  (void)nrecv;
  return CLSPH_OK;
}

/* One rank, with Jacobi or its own multigrid: the local problem is the whole one, so dsolve
 * (through pslab's renumbering) takes psolve's iterations with the same preconditioner within one
 * and gives its solution. With Jacobi also: 3 sums an iteration, the one-sum iteration's figures,
 * a zero tolerance refused; with the multigrid: the one-sum iteration refuses it. */
static void check_one_rank(const struct dev *dev, struct whole *w, enum psolve_precond precond)
{
  struct pslab s;
  struct dsolve ds;
  struct dsolve_result res;
  struct psolve ps;
  struct psolve_options o;
  struct psolve_result pres;
  const struct dsolve_comm comm = {.ctx = NULL, .sum = no_sum, .exchange = no_exchange};
  const char *what = precond == PSOLVE_MULTIGRID ? "one rank, multigrid" : "one rank, Jacobi";
  double *xs = NULL, *xw = NULL;
  const real zero = 0;
  memset(&s, 0, sizeof s);
  memset(&ds, 0, sizeof ds);
  memset(&ps, 0, sizeof ps);
  psolve_defaults(&o);
  o.precond = precond;
  o.rtol = rtol;
  o.max_it = 5000;
  o.group_max = 0;
  cl_mem x = pset_mem(&w->pp.ps, w->pp.f_x);
  const int ok =
      pslab_create(dev, &spec, 0, 1, precond, &s) == CLSPH_OK &&
      dsolve_create(dev, s.pp.prog, &s.layout, &comm, pslab_precond(&s), &ds) == CLSPH_OK &&
      dsolve_solve(&ds, s.d_b, s.d_x, rtol, 5000, DSOLVE_BICGSTAB, &res) == CLSPH_OK &&
      psolve_create(dev, w->pp.prog, w->pp.n, &o, &ps) == CLSPH_OK &&
      kern_fill(dev, x, &zero, sizeof zero, w->pp.n * sizeof(real)) == CLSPH_OK &&
      psolve_solve(&ps, &w->pp.po.op, pset_mem(&w->pp.ps, w->pp.f_b), x, &pres) == CLSPH_OK;
  TC_CHECK(ok, "%s: both solves run", what);
  if (!ok) goto done;
  TC_CHECK(res.converged && pres.reason > 0 && abs(res.its - pres.its) <= 1,
           "%s: dsolve's %d iterations = psolve's %d (± 1)", what, res.its, pres.its);
  xs = malloc(s.layout.nown * sizeof *xs);
  xw = malloc(w->pp.n * sizeof *xw);
  if (xs == NULL || xw == NULL || pslab_read_owned(&s, s.d_x, xs) || pproblem_read(&w->pp, x, xw)) {
    TC_CHECK(0, "%s: read the solutions", what);
    goto done;
  }
  double d = 0.0, m = 0.0;
  for (size_t i = 0; i < s.layout.nown; ++i) {
    d = fmax(d, fabs(xs[i] - xw[w->at[s.gid[i]]]));
    m = fmax(m, fabs(xw[w->at[s.gid[i]]]));
  }
  TC_NEAR(d / m, 0.0, agree, "%s: dsolve's solution = psolve's", what);
  if (precond == PSOLVE_MULTIGRID) {
    TC_CHECK(dsolve_solve(&ds, s.d_b, s.d_x, rtol, 10, DSOLVE_ONE_SUM, &res) == CLSPH_E_INPUT,
             "%s: the one-sum iteration refuses a preconditioner but Jacobi", what);
    goto done;
  }
  TC_CHECK(res.stats.exchanges == 0 && res.stats.sums == 3 * res.its + 1,
           "%s: no exchange, 3 sums an iteration and one at the start (%ld, %ld)", what,
           res.stats.exchanges, res.stats.sums);
  /* one global sum an iteration: the same solution, the iterations within 3, the recomputed
   * residual within the tolerance */
  struct dsolve_result r1;
  if (kern_fill(dev, s.d_x, &zero, sizeof zero, s.layout.n * sizeof(real)) ||
      dsolve_solve(&ds, s.d_b, s.d_x, rtol, 5000, DSOLVE_ONE_SUM, &r1) ||
      pslab_read_owned(&s, s.d_x, xs)) {
    TC_CHECK(0, "one rank, one sum: the solve runs");
    goto done;
  }
  TC_CHECK(r1.converged && abs(r1.its - pres.its) <= 3 && r1.rnorm_true <= rtol,
           "one rank, one sum: %d iterations (psolve %d), recomputed residual %.2e", r1.its,
           pres.its, r1.rnorm_true);
  TC_CHECK(r1.stats.sums <= r1.its + 1 + 2 * (1 + r1.restarts),
           "one rank, one sum: %ld global sums for %d iterations", r1.stats.sums, r1.its);
  d = 0.0;
  for (size_t i = 0; i < s.layout.nown; ++i) d = fmax(d, fabs(xs[i] - xw[w->at[s.gid[i]]]));
  TC_NEAR(d / m, 0.0, agree, "one rank, one sum: the solution = psolve's");
  /* a zero tolerance is refused */
  TC_CHECK(dsolve_solve(&ds, s.d_b, s.d_x, 0.0, 10, DSOLVE_BICGSTAB, &res) == CLSPH_E_INPUT,
           "rtol 0 is refused");
done:
  free(xs);
  free(xw);
  psolve_destroy(&ps);
  dsolve_destroy(&ds);
  pslab_destroy(&s);
}

int main(void)
{
  struct dev dev;
  struct whole w;
  tc_open_device(&dev);
  if (!whole_make(&dev, &w)) {
    TC_CHECK(0, "the whole problem builds");
  } else {
    check_split(&dev, &w, 2);
    check_split(&dev, &w, 3);
    check_one_rank(&dev, &w, PSOLVE_JACOBI);
    check_one_rank(&dev, &w, PSOLVE_MULTIGRID);
  }
  whole_free(&w);
  /* bad input: 48 rows of 10 reached at 5 ranks; a singular problem */
  int lo = 0, hi = 0;
  TC_CHECK(pslab_rows(48, 5, 0, 10, &lo, &hi) == CLSPH_E_INPUT,
           "5 slabs of 9 rows with a reach of 10 are refused");
  const enum clsph_status rs = pslab_rows(48, 4, 3, 10, &lo, &hi);
  TC_CHECK(rs == CLSPH_OK && lo == 36 && hi == 48, "4 ranks: the last owns rows [36, 48) (%d, %d)",
           lo, hi);
  struct pproblem_spec sing = spec;
  struct pslab s;
  memset(&s, 0, sizeof s);
  sing.singular = 1;
  TC_CHECK(pslab_create(&dev, &sing, 0, 2, PSOLVE_JACOBI, &s) == CLSPH_E_INPUT,
           "a singular problem is refused");
  pslab_destroy(&s);
  dev_close(&dev);
  return tc_finish("dsolve");
}
