/* pslab.c: one rank's slab of the manufactured pressure problem (see pslab.h). */
#include "pslab.h"

#include <stdlib.h>
#include <string.h>

#include "clsph_config.h"
#include "log.h"
#include "prog.h"

enum clsph_status pslab_rows(int rows, int nranks, int rank, int reach, int *lo, int *hi)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_CHECK(nranks >= 1 && rank >= 0 && rank < nranks, CLSPH_E_INPUT,
              "rank %d of %d ranks does not exist", rank, nranks);
  const int thinnest = rows / nranks;
  CLSPH_CHECK(nranks == 1 || thinnest >= reach, CLSPH_E_INPUT,
              "%d ranks split the problem's %d rows into slabs of %d rows, thinner than the %d "
              "rows an unknown reaches: a halo would span more than the two neighbouring ranks; "
              "use at most %d rank%s or more particles per side",
              nranks, rows, thinnest, reach, rows / reach > 1 ? rows / reach : 1,
              rows / reach > 1 ? "s" : "");
  *lo = (int)((long)rank * rows / nranks);
  *hi = (int)((long)(rank + 1) * rows / nranks);
done:
  return st;
}

/* ascending global index, for qsort of (global index, position) pairs */
struct keyed {
  cl_uint gid;
  size_t at;
};
static int cmp_keyed(const void *a, const void *b)
{
  const cl_uint x = ((const struct keyed *)a)->gid, y = ((const struct keyed *)b)->gid;
  return (x > y) - (x < y);
}

/* z = M⁻¹ r by the rank's multigrid: r's owned values into the local order (halo zero), one
 * V-cycle, z's owned values back */
static enum clsph_status mg_apply_owned(void *ctx, cl_mem r, cl_mem z)
{
  enum clsph_status st = CLSPH_OK;
  struct pslab *s = ctx;
  const cl_uint n = (cl_uint)s->layout.n, nown = (cl_uint)s->layout.nown;
  CLSPH_TRY(KERN_SET(s->k_to_local, KARG(n), KARG(nown), KARG(s->d_map), KARG(r), KARG(s->d_rl)));
  CLSPH_TRY(kern_launch(s->pp.dev, s->k_to_local, n, NULL));
  CLSPH_TRY(psolve_precond_apply(&s->ps, &s->pp.po.op, s->d_rl, s->d_zl));
  CLSPH_TRY(KERN_SET(s->k_back, KARG(nown), KARG(s->d_own_at), KARG(s->d_zl), KARG(z)));
  CLSPH_TRY(kern_launch(s->pp.dev, s->k_back, nown, NULL));
done:
  return st;
}

const struct dsolve_precond *pslab_precond(const struct pslab *s)
{
  return s->multigrid ? &s->pc : NULL;
}

enum clsph_status pslab_create(const struct dev *dev, const struct pproblem_spec *spec, int rank,
                               int nranks, enum psolve_precond precond, struct pslab *out)
{
  enum clsph_status st = CLSPH_OK;
  struct pslab s;
  struct psolve ps;
  struct psolve_options o;
  struct pproblem_spec sp = *spec;
  cl_uint *gid_sorted = NULL;
  size_t *arow = NULL, *inv = NULL, *own_at = NULL;
  int *acol = NULL;
  double *aval = NULL;
  real *b_sorted = NULL, *b_new = NULL;
  struct keyed *halo = NULL;
  memset(&s, 0, sizeof s);
  memset(&ps, 0, sizeof ps);
  CLSPH_CHECK(precond == PSOLVE_JACOBI || precond == PSOLVE_MULTIGRID, CLSPH_E_INPUT,
              "the split solve's preconditioner is Jacobi or the multigrid");
  CLSPH_CHECK(!spec->singular, CLSPH_E_INPUT,
              "the split problem is the regular one (Dirichlet layers): a singular problem's "
              "mean would need one more global sum per product");
  s.rank = rank;
  s.nranks = nranks;
  s.reach = pproblem_reach_rows(spec);
  const int rows = pproblem_rows(spec);
  CLSPH_TRY(pslab_rows(rows, nranks, rank, s.reach, &s.row_lo, &s.row_hi));
  sp.row_lo = s.row_lo - s.reach > 0 ? s.row_lo - s.reach : 0;
  sp.row_hi = s.row_hi + s.reach < rows ? s.row_hi + s.reach : rows;
  CLSPH_TRY(pproblem_create(dev, &sp, &s.pp));
  CLSPH_CHECK(s.pp.rows == rows, CLSPH_E_UNSUPPORTED, "pslab: %d rows, pproblem has %d", rows,
              s.pp.rows);
  const size_t n = s.pp.n, side = (size_t)spec->side;
  gid_sorted = malloc(n * sizeof *gid_sorted);
  inv = malloc(n * sizeof *inv);
  b_sorted = malloc(n * sizeof *b_sorted);
  b_new = malloc(n * sizeof *b_new);
  halo = malloc(n * sizeof *halo);
  s.gid = malloc(n * sizeof *s.gid);
  s.send = malloc(n * sizeof *s.send);
  CLSPH_CHECK(gid_sorted && inv && b_sorted && b_new && halo && s.gid && s.send, CLSPH_E_NOMEM,
              "out of memory");
  CLSPH_TRY(kern_read(dev, pset_mem(&s.pp.ps, s.pp.f_gid), n * sizeof *gid_sorted, gid_sorted));
  CLSPH_TRY(kern_read(dev, pset_mem(&s.pp.ps, s.pp.f_b), n * sizeof *b_sorted, b_sorted));
  /* owned first, in the grid's order (its neighbours stay close in memory); then the halo from
   * below and from above, each by global index */
  size_t nown = 0, nbelow = 0, nhalo = 0;
  for (size_t i = 0; i < n; ++i) {
    const int r = (int)(gid_sorted[i] / side);
    if (r >= s.row_lo && r < s.row_hi) {
      inv[i] = nown;
      s.gid[nown++] = gid_sorted[i];
    } else {
      halo[nhalo].gid = gid_sorted[i];
      halo[nhalo++].at = i;
      nbelow += r < s.row_lo;
    }
  }
  qsort(halo, nhalo, sizeof *halo, cmp_keyed); /* below's rows come first: lower indices */
  for (size_t k = 0; k < nhalo; ++k) {
    inv[halo[k].at] = nown + k;
    s.gid[nown + k] = halo[k].gid;
  }
  int nb = 0;
  if (rank > 0) {
    s.nbr[nb] = rank - 1;
    s.nrecv[nb++] = nbelow;
  }
  if (rank + 1 < nranks) {
    s.nbr[nb] = rank + 1;
    s.nrecv[nb++] = nhalo - nbelow;
  }
  CLSPH_CHECK((rank > 0 || nbelow == 0) && (rank + 1 < nranks || nhalo == nbelow),
              CLSPH_E_UNSUPPORTED, "pslab: halo rows beyond the outer ranks");
  /* what each neighbour's halo holds of the owned rows: rows within reach of its slab */
  size_t nsend = 0;
  for (int k = 0; k < nb; ++k) {
    const int below = s.nbr[k] < rank;
    size_t m = 0;
    for (size_t i = 0; i < nown; ++i) {
      const int r = (int)(s.gid[i] / side);
      if (below ? r < s.row_lo + s.reach : r >= s.row_hi - s.reach) {
        halo[m].gid = s.gid[i];
        halo[m++].at = i;
      }
    }
    qsort(halo, m, sizeof *halo, cmp_keyed);
    for (size_t j = 0; j < m; ++j) s.send[nsend + j] = (cl_uint)halo[j].at;
    s.nsend[k] = m;
    nsend += m;
  }
  /* the operator's rows on this device, the owned ones renumbered */
  psolve_defaults(&o);
  o.precond = PSOLVE_JACOBI;
  o.apply = PSOLVE_STORED;
  CLSPH_TRY(psolve_create(dev, s.pp.prog, n, &o, &ps));
  CLSPH_TRY(psolve_assemble(&ps, &s.pp.po.op, &arow, &acol, &aval));
  own_at = malloc((nown > 0 ? nown : 1) * sizeof *own_at); /* sorted index of each owned row */
  CLSPH_CHECK(own_at != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t i = 0; i < n; ++i)
    if (inv[i] < nown) own_at[inv[i]] = i;
  size_t nnz = 0;
  for (size_t i = 0; i < nown; ++i) nnz += arow[own_at[i] + 1] - arow[own_at[i]];
  s.row = malloc((nown + 1) * sizeof *s.row);
  s.col = malloc((nnz > 0 ? nnz : 1) * sizeof *s.col);
  s.val = malloc((nnz > 0 ? nnz : 1) * sizeof *s.val);
  CLSPH_CHECK(s.row && s.col && s.val, CLSPH_E_NOMEM, "out of memory for %zu entries", nnz);
  nnz = 0;
  for (size_t i = 0; i < nown; ++i) {
    s.row[i] = nnz;
    const size_t j = own_at[i];
    for (size_t k = arow[j]; k < arow[j + 1]; ++k, ++nnz) {
      s.col[nnz] = (int)inv[acol[k]];
      s.val[nnz] = aval[k];
    }
  }
  s.row[nown] = nnz;
  if (precond == PSOLVE_MULTIGRID) { /* the rank's own multigrid, kept for the solve */
    /* its problem: the owned rows, and the halo's rows as Dirichlet rows (the correction zero
     * beyond the owned rows). The halo's own rows, with their neighbourhoods cut at the halo's
     * edge, would leave a middle rank's problem without a Dirichlet row: nearly singular, its
     * multigrid a poor inverse (3 ranks at 48 per side: 51 iterations against the whole
     * problem's 10) */
    cl_uint *dir = malloc(n * sizeof *dir);
    CLSPH_CHECK(dir != NULL, CLSPH_E_NOMEM, "out of memory");
    st = kern_read(dev, pset_mem(&s.pp.ps, s.pp.f_dir), n * sizeof *dir, dir);
    for (size_t i = 0; i < n && st == CLSPH_OK; ++i)
      if (inv[i] >= nown) dir[i] = 1;
    if (st == CLSPH_OK) st = kern_write(dev, pset_mem(&s.pp.ps, s.pp.f_dir), n * sizeof *dir, dir);
    free(dir);
    CLSPH_TRY(st);
    cl_uint *map = malloc(n * sizeof *map), *at = malloc((nown > 0 ? nown : 1) * sizeof *at);
    CLSPH_CHECK(map && at, CLSPH_E_NOMEM, "out of memory");
    for (size_t i = 0; i < n; ++i) map[i] = (cl_uint)inv[i];
    for (size_t j = 0; j < nown; ++j) at[j] = (cl_uint)own_at[j];
    st = kern_buffer(dev, n * sizeof *map, map, &s.d_map, "pslab map");
    if (st == CLSPH_OK)
      st = kern_buffer(dev, (nown > 0 ? nown : 1) * sizeof *at, at, &s.d_own_at, "pslab own");
    free(map);
    free(at);
    CLSPH_TRY(st);
    CLSPH_TRY(kern_buffer(dev, n * sizeof(real), NULL, &s.d_rl, "pslab local r"));
    CLSPH_TRY(kern_buffer(dev, n * sizeof(real), NULL, &s.d_zl, "pslab local z"));
    CLSPH_TRY(prog_kernel(s.pp.prog, "ds_to_local", &s.k_to_local));
    CLSPH_TRY(prog_kernel(s.pp.prog, "ds_gather", &s.k_back));
    psolve_destroy(&ps);
    o.precond = PSOLVE_MULTIGRID;
    CLSPH_TRY(psolve_create(dev, s.pp.prog, n, &o, &ps));
    s.ps = ps; /* set up below, once the slab is where it stays */
    memset(&ps, 0, sizeof ps);
    s.multigrid = 1;
  }
  for (size_t i = 0; i < n; ++i) b_new[inv[i]] = b_sorted[i];
  CLSPH_TRY(kern_buffer(dev, n * sizeof(real), b_new, &s.d_b, "pslab b"));
  for (size_t i = 0; i < n; ++i) b_new[i] = 0;
  CLSPH_TRY(kern_buffer(dev, n * sizeof(real), b_new, &s.d_x, "pslab x"));
  s.layout = (struct dsolve_layout){.nown = nown,
                                    .n = n,
                                    .row = s.row,
                                    .col = s.col,
                                    .val = s.val,
                                    .nbrs = nb,
                                    .nsend = s.nsend,
                                    .send = s.send,
                                    .nrecv = s.nrecv};
  *out = s;
  out->layout.nsend = out->nsend; /* the layout points into the slab's own arrays */
  out->layout.nrecv = out->nrecv;
  out->pc = (struct dsolve_precond){.ctx = out, .apply = mg_apply_owned}; /* points at the slab */
  memset(&s, 0, sizeof s);
  pproblem_rebind(&out->pp); /* the operator keeps the addresses of the grid and of itself */
  if (out->multigrid && (st = psolve_precond_setup(&out->ps, &out->pp.po.op)) != CLSPH_OK)
    pslab_destroy(out);
done:
  psolve_destroy(&ps);
  pslab_destroy(&s);
  free(own_at);
  free(halo);
  free(b_new);
  free(b_sorted);
  free(inv);
  free(gid_sorted);
  free(arow);
  free(acol);
  free(aval);
  return st;
}

enum clsph_status pslab_read_owned(struct pslab *s, cl_mem x, double *out)
{
  return pproblem_read_n(s->pp.dev, x, s->layout.nown, out);
}

void pslab_destroy(struct pslab *s)
{
  psolve_destroy(&s->ps);
  if (s->k_to_local != NULL) clReleaseKernel(s->k_to_local);
  if (s->k_back != NULL) clReleaseKernel(s->k_back);
  s->k_to_local = s->k_back = NULL;
  kern_release(&s->d_map);
  kern_release(&s->d_own_at);
  kern_release(&s->d_rl);
  kern_release(&s->d_zl);
  kern_release(&s->d_b);
  kern_release(&s->d_x);
  free(s->row);
  free(s->col);
  free(s->val);
  free(s->send);
  free(s->gid);
  s->row = NULL;
  s->col = NULL;
  s->val = NULL;
  s->send = NULL;
  s->gid = NULL;
  pproblem_destroy(&s->pp);
}
