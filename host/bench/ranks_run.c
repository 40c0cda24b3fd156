/* ranks_run.c: `clsph-ranks run`, a whole run of an explicit scheme split across MPI ranks
 * (README, "Beyond one device"):
 *
 *   mpiexec -n RANKS clsph-ranks run CASE [--set NAME=VALUE ...] [--halo SWEEPS] [--cuts X1,X2,...]
 *                                       [--recut STEPS] [--device I] [--json FILE] [--out DIR]
 *                                       [--no-check]
 *
 * The domain is cut into slabs along x, one per rank (by default at the quantiles of the
 * particles' x at t = 0, so that each rank starts with as many particles). A rank steps the
 * particles of its slab and a halo of the neighbours' particles SWEEPS supports deep: a sum over
 * the neighbours that misses some (the halo's outer edge) spoils the particle's value, and each
 * sweep of the step carries that one support (the neighbour lists' reach) further in, so a halo as
 * deep as the step has sweeps (wcsph-riemann: the lists, the advection, two per acoustic sub-step,
 * and one for the step's motion) leaves every particle of the slab as the whole run would compute
 * it. After each step each rank keeps the particles now in its slab, sends the neighbours those in
 * their halos (every field of the particle set: a particle that crossed a cut migrates so), and
 * takes theirs: one exchange a step, no change to the scheme. The largest speed that sets the time
 * step is reduced over the ranks (sim_comm), so every rank takes the whole run's steps.
 *
 * Set-up builds the whole scene on every rank and then keeps its slab and halo: the work splits,
 * the memory does not yet (a rank's buffers have the whole scene's capacity, so that the fluid
 * may gather anywhere). Rank 0 gathers the particles' final positions and velocities by id and,
 * unless --no-check, runs the whole scene alone to the same time and reports the largest
 * difference; --out DIR writes the final state, gathered, as one snapshot that `clsph render` and
 * ParaView read. No probes, forces or snapshots along the way: the figures go to standard output
 * and --json. Exit codes: 0, 1 failure, 2 bad command line or a scene the split cannot run. */
#include <math.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "case.h"
#include "clsph_config.h"
#include "dev.h"
#include "kern.h"
#include "log.h"
#include "prog.h"
#include "ranks_run.h"
#include "io.h"
#include "out.h"
#include "scheme.h"
#include "sim.h"
#include "snapshot.h"
#include "str.h"

#define RUN_MAX_SETS  64
#define RUN_MAX_RANKS 64

struct run_opts {
  const char *case_path, *json, *out; /* --out: the final state's snapshot folder */
  char *sets[RUN_MAX_SETS];
  int nsets, sweeps, device, check, ncuts, recut;
  double cuts[RUN_MAX_RANKS];
};

/* One rank's part of the split run: its slab [cut[rank], cut[rank + 1]) and the halo. */
struct part {
  MPI_Comm comm;
  int rank, size, dim;
  double cut[RUN_MAX_RANKS + 1]; /* cut[0] = −∞, cut[size] = +∞ */
  double halo;                   /* the halo's depth, m: sweeps × the lists' reach */
  int sweeps;
  size_t cap, rec;    /* particles the buffers hold; bytes of one particle's fields */
  MPI_Datatype rtype; /* one particle's record (rec bytes): MPI counts in particles, not bytes */
  int nf, fidx[PSET_MAX_FIELDS];
  unsigned char *h[PSET_MAX_FIELDS]; /* host copy of each exchanged field, cap elements */
  unsigned char *sbuf[2], *rbuf[2];  /* records to and from the left and right neighbours */
  size_t *own;                       /* indices of the owned particles */
  /* figures: exchanges, bytes sent, seconds in them (transfers to and from the device with
   * the MPI), particles held over the steps (owned + halo) and owned */
  int recut;   /* move the cuts every this many steps (0: never) */
  long recuts; /* times they moved */
  long exchanges;
  double bytes, seconds, held_sum, owned_sum, held_max_sum;
  size_t owned, held;
};

static enum clsph_status mpi_max(void *ctx, double *v)
{
  const struct part *p = ctx;
  const int rc = MPI_Allreduce(MPI_IN_PLACE, v, 1, MPI_DOUBLE, MPI_MAX, p->comm);
  if (rc != MPI_SUCCESS) {
    log_error("MPI_Allreduce of a maximum failed (%d)", rc);
    return CLSPH_E_IO;
  }
  return CLSPH_OK;
}

static void usage(void)
{
  fprintf(stderr, "usage: mpiexec -n RANKS clsph-ranks run CASE [--set NAME=VALUE ...] "
                  "[--halo SWEEPS] [--cuts X1,X2,...] [--recut STEPS] [--device I] [--json FILE] "
                  "[--out DIR] [--no-check]\n");
}

static int parse(int argc, char **argv, struct run_opts *o, int rank)
{
  *o = (struct run_opts){.sweeps = 18, .device = -1, .check = 1, .recut = 20};
  for (int i = 2; i < argc; ++i) {
    const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
    if (strcmp(a, "--no-check") == 0) {
      o->check = 0;
      continue;
    }
    if (a[0] != '-') {
      if (o->case_path != NULL) {
        if (rank == 0) fprintf(stderr, "clsph-ranks run: one case file, not '%s' too\n", a);
        return 0;
      }
      o->case_path = a;
      continue;
    }
    if (v == NULL) {
      if (rank == 0) fprintf(stderr, "clsph-ranks run: %s needs a value\n", a);
      return 0;
    }
    ++i;
    char *end = NULL;
    if (strcmp(a, "--set") == 0) {
      if (o->nsets == RUN_MAX_SETS || strchr(v, '=') == NULL) {
        if (rank == 0)
          fprintf(stderr, "clsph-ranks run: --set %s: NAME=VALUE, at most %d of them\n", v,
                  RUN_MAX_SETS);
        return 0;
      }
      o->sets[o->nsets++] = (char *)v;
    } else if (strcmp(a, "--json") == 0) {
      o->json = v;
    } else if (strcmp(a, "--out") == 0) {
      o->out = v;
    } else if (strcmp(a, "--halo") == 0 || strcmp(a, "--device") == 0 ||
               strcmp(a, "--recut") == 0) {
      const double x = strtod(v, &end);
      const int halo = a[2] == 'h', dev = a[2] == 'd';
      if (end == v || *end != '\0' || !(x >= (halo ? 1 : 0)) || !(x <= (dev ? 1000 : 1e6)) ||
          x != floor(x)) {
        if (rank == 0)
          fprintf(stderr, "clsph-ranks run: %s %s: %s\n", a, v,
                  halo  ? "a whole number of sweeps from 1 to 1000"
                  : dev ? "a device index"
                        : "a whole number of steps (0: the cuts stay)");
        return 0;
      }
      *(halo ? &o->sweeps : dev ? &o->device : &o->recut) = (int)x;
    } else if (strcmp(a, "--cuts") == 0) {
      const char *s = v;
      o->ncuts = 0;
      for (;;) {
        const double x = strtod(s, &end);
        if (end == s || !isfinite(x) || o->ncuts == RUN_MAX_RANKS - 1 ||
            (o->ncuts > 0 && !(x > o->cuts[o->ncuts - 1])) || (*end != ',' && *end != '\0')) {
          if (rank == 0)
            fprintf(stderr,
                    "clsph-ranks run: --cuts %s: increasing x positions (m), one fewer "
                    "than the ranks, separated by commas\n",
                    v);
          return 0;
        }
        o->cuts[o->ncuts++] = x;
        if (*end == '\0') break;
        s = end + 1;
      }
    } else {
      if (rank == 0) fprintf(stderr, "clsph-ranks run: unknown option '%s'\n", a);
      return 0;
    }
  }
  if (o->case_path == NULL) {
    if (rank == 0) usage();
    return 0;
  }
  return 1;
}

/* What the split cannot run yet, named. */
static enum clsph_status check_scene(const struct scene *s, const struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_CHECK(strcmp(sim->scheme->name, "wcsph-riemann") == 0, CLSPH_E_INPUT,
              "%s: clsph-ranks run splits wcsph-riemann's runs (explicit: its steps sum over "
              "neighbours only); scheme %s %s",
              s->case_path, sim->scheme->name,
              strncmp(sim->scheme->name, "isph", 4) == 0
                  ? "solves for the pressure over the whole fluid (the solve across ranks is "
                    "clsph-ranks psolve)"
                  : "keeps wall segments that the split does not carry");
  CLSPH_CHECK(!s->periodic[0], CLSPH_E_INPUT,
              "%s: the domain is periodic in x, along which clsph-ranks run cuts it into slabs",
              s->case_path);
  CLSPH_CHECK(s->nsections == 0, CLSPH_E_INPUT,
              "%s: inflow and outflow sections are not split across ranks yet (their layers are "
              "lists of particle indices)",
              s->case_path);
  CLSPH_CHECK(!s->flow.on, CLSPH_E_INPUT,
              "%s: the flow-rate control sums over the whole fluid: not split across ranks yet",
              s->case_path);
  CLSPH_CHECK(!s->turb.on, CLSPH_E_INPUT,
              "%s: the k-ε model is not split across ranks yet (its wall model adds sweeps and a "
              "global sum)",
              s->case_path);
  for (int i = 0; i < s->noptions; ++i)
    CLSPH_CHECK(strcmp(s->options[i].key, "wall_pressure") != 0 || s->options[i].is_number ||
                    strcmp(s->options[i].text, "gradient") != 0,
                CLSPH_E_INPUT,
                "%s: wall_pressure = \"gradient\" keeps a per-particle buffer across steps "
                "outside the particle set: not split across ranks yet",
                s->case_path);
done:
  return st;
}

static int cmp_double(const void *a, const void *b)
{
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* The cuts: given, or at the quantiles of the particles' x at t = 0 (the whole geometry). */
static enum clsph_status make_cuts(struct part *p, const struct run_opts *o, const struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  double *xs = NULL;
  const struct geom *g = &sim->geom;
  p->cut[0] = -HUGE_VAL;
  p->cut[p->size] = HUGE_VAL;
  if (o->ncuts > 0) {
    CLSPH_CHECK(o->ncuts == p->size - 1, CLSPH_E_INPUT,
                "clsph-ranks run: --cuts gives %d positions for %d ranks (one fewer than the "
                "ranks)",
                o->ncuts, p->size);
    for (int r = 1; r < p->size; ++r) p->cut[r] = o->cuts[r - 1];
  } else {
    xs = malloc((g->n + 1) * sizeof *xs);
    CLSPH_CHECK(xs != NULL, CLSPH_E_NOMEM, "out of memory");
    for (size_t i = 0; i < g->n; ++i) xs[i] = g->x[(size_t)g->dim * i];
    qsort(xs, g->n, sizeof *xs, cmp_double);
    for (int r = 1; r < p->size; ++r) p->cut[r] = xs[(g->n * (size_t)r) / (size_t)p->size];
  }
  /* a halo reaches into the neighbouring slab only: the inner slabs are at least as wide */
  for (int r = 1; r + 1 < p->size; ++r)
    CLSPH_CHECK(p->cut[r + 1] - p->cut[r] >= p->halo, CLSPH_E_INPUT,
                "%s: slab %d of %d spans x = %g to %g m, thinner than the halo (%g m: %d sweeps "
                "of the lists' reach %g m): fewer ranks, other --cuts or a smaller --halo",
                sim->scene->case_path, r, p->size, p->cut[r], p->cut[r + 1], p->halo, p->sweeps,
                sim->gspec.support);
done:
  free(xs);
  return st;
}

static int owner(const struct part *p, double x)
{
  int r = 0;
  while (r + 1 < p->size && x >= p->cut[r + 1]) ++r;
  return r;
}

static enum clsph_status part_create(struct part *p, const struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  const struct pset *ps = &sim->ps;
  p->cap = ps->cap;
  for (int k = 0; k < ps->nfields; ++k) {
    if (ps->f[k].temp) continue; /* made again within each step */
    p->fidx[p->nf] = k;
    p->h[p->nf] = malloc(p->cap * ps->f[k].elem);
    CLSPH_CHECK(p->h[p->nf] != NULL, CLSPH_E_NOMEM, "out of memory");
    p->rec += ps->f[k].elem;
    ++p->nf;
  }
  CLSPH_CHECK(ps->f[sim->f_pos].elem == (p->dim == 3 ? 4 : 2) * sizeof(real), CLSPH_E_UNSUPPORTED,
              "positions of an unexpected size");
  for (int s = 0; s < 2; ++s) {
    p->sbuf[s] = malloc(p->cap * p->rec);
    p->rbuf[s] = malloc(p->cap * p->rec);
    CLSPH_CHECK(p->sbuf[s] != NULL && p->rbuf[s] != NULL, CLSPH_E_NOMEM, "out of memory");
  }
  CLSPH_CHECK(MPI_Type_contiguous((int)p->rec, MPI_BYTE, &p->rtype) == MPI_SUCCESS &&
                  MPI_Type_commit(&p->rtype) == MPI_SUCCESS,
              CLSPH_E_IO, "cannot make the MPI type of a particle's record");
  p->own = malloc(p->cap * sizeof *p->own);
  CLSPH_CHECK(p->own != NULL, CLSPH_E_NOMEM, "out of memory");
done:
  return st;
}

static void part_destroy(struct part *p)
{
  if (p->rtype != MPI_DATATYPE_NULL && p->rtype != 0) MPI_Type_free(&p->rtype);
  for (int k = 0; k < p->nf; ++k) free(p->h[k]);
  for (int s = 0; s < 2; ++s) {
    free(p->sbuf[s]);
    free(p->rbuf[s]);
  }
  free(p->own);
}

/* Pack particle i's fields into one record. */
static void pack(const struct part *p, const struct pset *ps, size_t i, unsigned char *rec)
{
  for (int k = 0; k < p->nf; ++k) {
    const size_t e = ps->f[p->fidx[k]].elem;
    memcpy(rec, p->h[k] + i * e, e);
    rec += e;
  }
}

static void unpack(const struct part *p, const struct pset *ps, const unsigned char *rec, size_t i)
{
  for (int k = 0; k < p->nf; ++k) {
    const size_t e = ps->f[p->fidx[k]].elem;
    memcpy(p->h[k] + i * e, rec, e);
    rec += e;
  }
}

/* Move the cuts to the quantiles of the particles the ranks own now, so that the load follows
 * the fluid: each cut by at most `reach` (a rank's particles that far past its slab are as the
 * whole run computes them: the halo's depth less the sweeps the last step took) and only where
 * every inner slab stays as wide as the halo. Every rank computes the same cuts. */
static enum clsph_status recut(struct part *p, const real *x, size_t n, size_t stride, double reach)
{
  enum clsph_status st = CLSPH_OK;
  double *mine = malloc((n + 1) * sizeof *mine), *all = NULL;
  int *counts = malloc((size_t)p->size * sizeof *counts);
  int *displs = malloc((size_t)p->size * sizeof *displs);
  CLSPH_CHECK(mine != NULL && counts != NULL && displs != NULL, CLSPH_E_NOMEM, "out of memory");
  int m = 0;
  for (size_t i = 0; i < n; ++i)
    if (owner(p, (double)x[stride * i]) == p->rank) mine[m++] = (double)x[stride * i];
  CLSPH_CHECK(MPI_Allgather(&m, 1, MPI_INT, counts, 1, MPI_INT, p->comm) == MPI_SUCCESS, CLSPH_E_IO,
              "the gather of the particle counts failed");
  size_t total = 0;
  for (int r = 0; r < p->size; ++r) displs[r] = (int)total, total += (size_t)counts[r];
  all = malloc((total + 1) * sizeof *all);
  CLSPH_CHECK(all != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_CHECK(MPI_Allgatherv(mine, m, MPI_DOUBLE, all, counts, displs, MPI_DOUBLE, p->comm) ==
                  MPI_SUCCESS,
              CLSPH_E_IO, "the gather of the particles' x failed");
  qsort(all, total, sizeof *all, cmp_double);
  double cut[RUN_MAX_RANKS + 1];
  memcpy(cut, p->cut, sizeof cut);
  for (int r = 1; r < p->size; ++r)
    cut[r] = fmin(fmax(all[(total * (size_t)r) / (size_t)p->size], p->cut[r] - reach),
                  p->cut[r] + reach);
  int ok = 1;
  for (int r = 1; r + 1 < p->size; ++r) ok &= cut[r + 1] - cut[r] >= p->halo;
  if (ok) {
    memcpy(p->cut, cut, sizeof cut);
    ++p->recuts;
  }
done:
  free(mine);
  free(all);
  free(counts);
  free(displs);
  return st;
}

/* The exchange after a step (or, `first`, the selection at t = 0, when every rank holds every
 * particle): keep the particles of the slab, send each neighbour those of its halo (and those
 * that crossed into its slab), take the neighbours' in. */
static enum clsph_status exchange(struct part *p, struct sim *sim, int first, double reach)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const double t0 = MPI_Wtime();
  const size_t n = ps->n, stride = p->dim == 3 ? 4 : 2;
  for (int k = 0; k < p->nf; ++k)
    CLSPH_TRY(kern_read(sim->dev, pset_mem(ps, p->fidx[k]), n * ps->f[p->fidx[k]].elem, p->h[k]));
  int posk = -1;
  for (int k = 0; k < p->nf; ++k)
    if (p->fidx[k] == sim->f_pos) posk = k;
  CLSPH_CHECK(posk >= 0, CLSPH_E_UNSUPPORTED, "no position field");
  const real *x = (const real *)p->h[posk];
  if (!first && p->recut > 0 && sim->step % p->recut == 0 && reach > 0.0)
    CLSPH_TRY(recut(p, x, n, stride, reach));
  const double lo = p->cut[p->rank], hi = p->cut[p->rank + 1];
  const int nbr[2] = {p->rank - 1, p->rank + 1};
  size_t nown = 0, nsend[2] = {0, 0}, nrecv[2] = {0, 0};
  for (size_t i = 0; i < n; ++i) {
    const double xi = (double)x[stride * i];
    if (first) { /* every rank has every particle: keep the slab and its halo */
      if (xi >= lo - p->halo && xi < hi + p->halo) p->own[nown++] = i;
      continue;
    }
    if (owner(p, xi) != p->rank) continue; /* a neighbour's: it sends its own copy */
    p->own[nown++] = i;
    for (int s = 0; s < 2; ++s) {
      if (nbr[s] < 0 || nbr[s] >= p->size) continue;
      if (xi >= p->cut[nbr[s]] - p->halo && xi < p->cut[nbr[s] + 1] + p->halo)
        pack(p, ps, i, p->sbuf[s] + p->rec * nsend[s]++);
    }
  }
  if (!first) { /* the counts, then the records */
    MPI_Request req[4];
    int nreq = 0, rc = MPI_SUCCESS;
    unsigned long cs[2] = {nsend[0], nsend[1]}, cr[2] = {0, 0};
    for (int s = 0; s < 2 && rc == MPI_SUCCESS; ++s) {
      if (nbr[s] < 0 || nbr[s] >= p->size) continue;
      rc = MPI_Irecv(&cr[s], 1, MPI_UNSIGNED_LONG, nbr[s], 11, p->comm, &req[nreq++]);
      if (rc == MPI_SUCCESS)
        rc = MPI_Isend(&cs[s], 1, MPI_UNSIGNED_LONG, nbr[s], 11, p->comm, &req[nreq++]);
    }
    if (rc == MPI_SUCCESS) rc = MPI_Waitall(nreq, req, MPI_STATUSES_IGNORE);
    CLSPH_CHECK(rc == MPI_SUCCESS, CLSPH_E_IO, "the exchange of particle counts failed (%d)", rc);
    nrecv[0] = cr[0];
    nrecv[1] = cr[1];
    CLSPH_CHECK(nown + nrecv[0] + nrecv[1] <= p->cap, CLSPH_E_UNSUPPORTED,
                "rank %d: %zu particles and %zu from its neighbours outgrow its %zu", p->rank, nown,
                nrecv[0] + nrecv[1], p->cap);
    nreq = 0;
    for (int s = 0; s < 2 && rc == MPI_SUCCESS; ++s) {
      if (nbr[s] < 0 || nbr[s] >= p->size) continue;
      rc = MPI_Irecv(p->rbuf[s], (int)nrecv[s], p->rtype, nbr[s], 12, p->comm, &req[nreq++]);
      if (rc == MPI_SUCCESS)
        rc = MPI_Isend(p->sbuf[s], (int)nsend[s], p->rtype, nbr[s], 12, p->comm, &req[nreq++]);
      p->bytes += (double)(nsend[s] * p->rec);
    }
    if (rc == MPI_SUCCESS) rc = MPI_Waitall(nreq, req, MPI_STATUSES_IGNORE);
    CLSPH_CHECK(rc == MPI_SUCCESS, CLSPH_E_IO, "the exchange of particles failed (%d)", rc);
  }
  /* the kept particles in their order, then the left neighbour's, then the right one's */
  size_t m = 0;
  for (size_t j = 0; j < nown; ++j, ++m)
    if (p->own[j] != m)
      for (int k = 0; k < p->nf; ++k) {
        const size_t e = ps->f[p->fidx[k]].elem;
        memcpy(p->h[k] + m * e, p->h[k] + p->own[j] * e, e);
      }
  p->owned = 0;
  for (size_t i = 0; i < nown; ++i) p->owned += owner(p, (double)x[stride * i]) == p->rank;
  for (int s = 0; s < 2; ++s)
    for (size_t j = 0; j < nrecv[s]; ++j) unpack(p, ps, p->rbuf[s] + p->rec * j, m++);
  for (int k = 0; k < p->nf; ++k)
    CLSPH_TRY(kern_write(sim->dev, pset_mem(ps, p->fidx[k]), m * ps->f[p->fidx[k]].elem, p->h[k]));
  ps->n = m;
  p->held = m;
  sim->speed_ready = 0; /* the step's largest speed took in the halo's spoilt edge */
  if (!first) {
    ++p->exchanges;
    p->seconds += MPI_Wtime() - t0;
  }
done:
  return st;
}

/* Step to the scene's end time (the loop's step_length without outputs): the split run with
 * `p`, the whole scene alone without. */
static enum clsph_status run_to_end(struct sim *sim, struct part *p)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  while (sim->time < s->t_end * (1.0 - 1e-12)) {
    if (!sim->scheme->sorts_first) CLSPH_TRY(sim_sort(sim));
    double dt = HUGE_VAL;
    CLSPH_TRY(sim->scheme->max_dt(sim, sim->state, &dt));
    dt = s->dt > 0.0 ? s->dt : dt * s->cfl;
    CLSPH_CHECK(dt > 1e-12 * fmax(s->t_end, 1.0), CLSPH_E_BLOWUP,
                "the time step collapsed to %g s at step %ld, t = %.9g s", dt, sim->step,
                sim->time);
    const int lands = sim->time + dt >= s->t_end * (1.0 - 1e-12);
    if (lands) dt = s->t_end - sim->time;
    CLSPH_TRY(sim->scheme->step(sim, sim->state, dt));
    sim->time = lands ? s->t_end : sim->time + dt;
    sim->dt = dt;
    ++sim->step;
    sim->substeps_sum += sim->substeps;
    CLSPH_TRY(sim_check_step(sim, 0));
    if (p == NULL) continue;
    if (p->size == 1) { /* no halo */
      p->held_sum += (double)sim->ps.n;
      p->held_max_sum += (double)sim->ps.n;
      continue;
    }
    /* wcsph-riemann's sweeps this step: the lists, the advection, two per acoustic sub-step,
     * and one for the particles' motion (the same on every rank: the time step is global) */
    const long need = 3 + 2 * sim->substeps;
    CLSPH_CHECK(need <= p->sweeps, CLSPH_E_INPUT,
                "%s: step %ld took %ld acoustic sub-steps: %ld sweeps reach through the halo of "
                "%d (--halo %ld or more)",
                s->case_path, sim->step, sim->substeps, need, p->sweeps, need);
    CLSPH_TRY(exchange(p, sim, 0, (double)(p->sweeps - need) * sim->gspec.support));
    p->held_sum += (double)p->held;
    p->owned_sum += (double)p->owned;
    double most = (double)p->held; /* the busiest rank's particles */
    CLSPH_CHECK(MPI_Allreduce(MPI_IN_PLACE, &most, 1, MPI_DOUBLE, MPI_MAX, p->comm) == MPI_SUCCESS,
                CLSPH_E_IO, "MPI_Allreduce of the particles held failed");
    p->held_max_sum += most;
  }
done:
  return st;
}

/* id, position and velocity (dim each) of the particles `p` owns (all with p NULL), as doubles */
static enum clsph_status read_state(struct sim *sim, const struct part *p, double **out, int *count)
{
  enum clsph_status st = CLSPH_OK;
  const size_t n = sim->ps.n, dim = (size_t)sim->scene->dim, stride = dim == 3 ? 4 : 2;
  const size_t rec = 1 + 2 * dim;
  real *x = malloc((2 * stride * n + 1) * sizeof *x);
  cl_uint *id = malloc((n + 1) * sizeof *id);
  double *o = malloc((rec * n + 1) * sizeof *o);
  CLSPH_CHECK(x != NULL && id != NULL && o != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(kern_read(sim->dev, pset_mem(&sim->ps, sim->f_pos), stride * n * sizeof *x, x));
  CLSPH_TRY(
      kern_read(sim->dev, pset_mem(&sim->ps, sim->f_vel), stride * n * sizeof *x, x + stride * n));
  CLSPH_TRY(kern_read(sim->dev, pset_mem(&sim->ps, sim->f_id), n * sizeof *id, id));
  size_t m = 0;
  for (size_t i = 0; i < n; ++i) {
    if (p != NULL && owner(p, (double)x[stride * i]) != p->rank) continue;
    double *r = o + rec * m++;
    r[0] = (double)id[i];
    for (size_t a = 0; a < dim; ++a) {
      r[1 + a] = (double)x[stride * i + a];
      r[1 + dim + a] = (double)x[stride * (n + i) + a];
    }
  }
  *out = o;
  o = NULL;
  *count = (int)m;
done:
  free(x);
  free(id);
  free(o);
  return st;
}

/* The final state in one snapshot (out/snap_000000.h5 and snapshots.xdmf, as `clsph run` writes
 * them, so that `clsph render` and ParaView read it): every rank's owned particles, every field,
 * gathered into rank 0's buffers, which have the whole scene's capacity. */
static enum clsph_status write_snapshot(struct part *p, struct sim *sim, const char *dir)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const size_t n = ps->n, stride = p->dim == 3 ? 4 : 2;
  unsigned char *all = NULL;
  int *counts = NULL, *displs = NULL;
  char *path = NULL;
  struct io_series series;
  memset(&series, 0, sizeof series);
  int posk = -1;
  for (int k = 0; k < p->nf; ++k) {
    CLSPH_TRY(kern_read(sim->dev, pset_mem(ps, p->fidx[k]), n * ps->f[p->fidx[k]].elem, p->h[k]));
    if (p->fidx[k] == sim->f_pos) posk = k;
  }
  CLSPH_CHECK(posk >= 0, CLSPH_E_UNSUPPORTED, "no position field");
  const real *x = (const real *)p->h[posk];
  size_t m = 0;
  for (size_t i = 0; i < n; ++i)
    if (owner(p, (double)x[stride * i]) == p->rank) pack(p, ps, i, p->sbuf[0] + p->rec * m++);
  const int recs = (int)m;
  if (p->rank == 0) {
    counts = malloc((size_t)p->size * sizeof *counts);
    displs = malloc((size_t)p->size * sizeof *displs);
    CLSPH_CHECK(counts != NULL && displs != NULL, CLSPH_E_NOMEM, "out of memory");
  }
  CLSPH_CHECK(MPI_Gather(&recs, 1, MPI_INT, counts, 1, MPI_INT, 0, p->comm) == MPI_SUCCESS,
              CLSPH_E_IO, "the gather of the snapshot's counts failed");
  size_t total = 0;
  if (p->rank == 0) {
    for (int r = 0; r < p->size; ++r) displs[r] = (int)total, total += (size_t)counts[r];
    all = malloc(total * p->rec + 1);
    CLSPH_CHECK(all != NULL, CLSPH_E_NOMEM, "out of memory");
  }
  CLSPH_CHECK(MPI_Gatherv(p->sbuf[0], recs, p->rtype, all, counts, displs, p->rtype, 0, p->comm) ==
                  MPI_SUCCESS,
              CLSPH_E_IO, "the gather of the snapshot's particles failed");
  if (p->rank != 0) goto done;
  CLSPH_CHECK(total <= p->cap, CLSPH_E_UNSUPPORTED, "%zu particles gathered, room for %zu", total,
              p->cap);
  for (size_t i = 0; i < total; ++i) unpack(p, ps, all + p->rec * i, i);
  for (int k = 0; k < p->nf; ++k)
    CLSPH_TRY(
        kern_write(sim->dev, pset_mem(ps, p->fidx[k]), total * ps->f[p->fidx[k]].elem, p->h[k]));
  ps->n = total;
  struct io_meta meta;
  snapshot_meta(sim, &meta);
  path = str_printf("%s/snap_000000.h5", dir);
  CLSPH_CHECK(path != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(io_snapshot_write(path, sim->dev, ps, &meta));
  free(path);
  path = str_printf("%s/snapshots.xdmf", dir);
  CLSPH_CHECK(path != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(io_series_add(&series, "snap_000000.h5", sim->time, total));
  CLSPH_TRY(io_xdmf_write(path, &series, ps, p->dim));
done:
  io_series_free(&series);
  free(path);
  free(all);
  free(counts);
  free(displs);
  return st;
}

enum clsph_status ranks_write_json(const char *path, struct cJSON *j)
{
  enum clsph_status st = CLSPH_OK;
  char *text = cJSON_Print(j);
  FILE *f = text != NULL ? fopen(path, "w") : NULL;
  if (f != NULL) {
    fputs(text, f);
    fputc('\n', f);
  }
  const int wrote = f != NULL && fclose(f) == 0;
  free(text);
  CLSPH_CHECK(wrote, CLSPH_E_IO, "cannot write %s", path);
done:
  return st;
}

/* The case, the device, the whole scene, the cuts, this rank's buffers. */
static enum clsph_status set_up(const struct run_opts *o, struct part *p, struct dev *dev,
                                struct scene *scene, struct case_script **script, struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  struct case_limits lim;
  case_limits_default(&lim);
  if (o->out != NULL && p->rank == 0) { /* a folder that holds no other run's outputs */
    int here = 0;
    CLSPH_TRY(out_claim_dir(o->out, NULL, 0, &here));
    CLSPH_TRY(out_prepare_dir(o->out));
  }
  CLSPH_TRY(case_load(o->case_path, o->nsets, o->sets, &lim, scene, script));
  CLSPH_TRY(dev_open(o->device, CLSPH_DOUBLE, dev));
  CLSPH_TRY(sim_create(dev, scene, sim));
  CLSPH_TRY(check_scene(scene, sim));
  p->dim = scene->dim;
  p->sweeps = o->sweeps;
  p->recut = o->recut;
  p->halo = o->sweeps * sim->gspec.support;
  CLSPH_TRY(make_cuts(p, o, sim));
  CLSPH_TRY(part_create(p, sim));
done:
  return st;
}

int ranks_run(int argc, char **argv, MPI_Comm comm)
{
  enum clsph_status st = CLSPH_OK;
  struct run_opts o;
  struct part p;
  struct dev dev;
  struct scene scene;
  struct sim sim, ref;
  struct case_script *script = NULL;
  double *mine = NULL, *all = NULL, *alone = NULL;
  int *counts = NULL, *displs = NULL;
  long *where = NULL;
  memset(&p, 0, sizeof p);
  memset(&dev, 0, sizeof dev);
  memset(&scene, 0, sizeof scene);
  memset(&sim, 0, sizeof sim);
  memset(&ref, 0, sizeof ref);
  MPI_Comm_rank(comm, &p.rank);
  MPI_Comm_size(comm, &p.size);
  p.comm = comm;
  if (!parse(argc, argv, &o, p.rank)) return 2;
  if (p.size > RUN_MAX_RANKS) {
    if (p.rank == 0) fprintf(stderr, "clsph-ranks run: at most %d ranks\n", RUN_MAX_RANKS);
    return 2;
  }
  prog_set_cache_dir(NULL);
  if (p.rank > 0) log_set_level(LOG_WARN); /* rank 0 says what the scheme reports */
  st = set_up(&o, &p, &dev, &scene, &script, &sim);
  int failed = st != CLSPH_OK, every = 0;
  MPI_Allreduce(&failed, &every, 1, MPI_INT, MPI_LAND, comm);
  if (every) { /* the same refusal on every rank: no need to abort the others */
    p.size = 1;
    goto done;
  }
  if (st != CLSPH_OK) goto done;
  const struct sim_comm sc = {.ctx = &p, .max = mpi_max};
  sim.comm = &sc;
  const size_t total = sim.ps.n;
  CLSPH_TRY(exchange(&p, &sim, 1, 0.0));
  MPI_Barrier(comm);
  const double w0 = MPI_Wtime();
  CLSPH_TRY(run_to_end(&sim, &p));
  double wall = MPI_Wtime() - w0;
  /* the figures: the slowest rank's times, the sums of the particles held and sent */
  double fig[4] = {wall, p.seconds, p.held_sum, p.bytes};
  MPI_Allreduce(MPI_IN_PLACE, fig, 2, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(MPI_IN_PLACE, fig + 2, 2, MPI_DOUBLE, MPI_SUM, comm);
  wall = fig[0];
  if (o.out != NULL) CLSPH_TRY(write_snapshot(&p, &sim, o.out));
  /* the final state by id on rank 0 */
  int nmine = 0;
  CLSPH_TRY(read_state(&sim, &p, &mine, &nmine));
  const size_t dim = (size_t)scene.dim, rec = 1 + 2 * dim;
  if (p.rank == 0) {
    counts = malloc((size_t)p.size * sizeof *counts);
    displs = malloc((size_t)p.size * sizeof *displs);
    CLSPH_CHECK(counts != NULL && displs != NULL, CLSPH_E_NOMEM, "out of memory");
  }
  const int nrec = nmine * (int)rec;
  MPI_Gather(&nrec, 1, MPI_INT, counts, 1, MPI_INT, 0, comm);
  size_t gathered = 0;
  if (p.rank == 0) {
    int at = 0;
    for (int r = 0; r < p.size; ++r) displs[r] = at, at += counts[r];
    gathered = (size_t)at / rec;
    all = malloc(((size_t)at + 1) * sizeof *all);
    CLSPH_CHECK(all != NULL, CLSPH_E_NOMEM, "out of memory");
  }
  MPI_Gatherv(mine, nrec, MPI_DOUBLE, all, counts, displs, MPI_DOUBLE, 0, comm);
  if (p.rank == 0) {
    /* every particle owned once */
    where = malloc((total + 1) * sizeof *where);
    CLSPH_CHECK(where != NULL, CLSPH_E_NOMEM, "out of memory");
    for (size_t i = 0; i < total; ++i) where[i] = -1;
    for (size_t k = 0; k < gathered; ++k) {
      const double id = all[rec * k];
      CLSPH_CHECK(id >= 0 && id < (double)total && where[(size_t)id] < 0, CLSPH_E_UNSUPPORTED,
                  "particle %.0f is owned twice or has no place among the %zu", id, total);
      where[(size_t)id] = (long)k;
    }
    const double steps = (double)sim.step;
    const double balance = fig[2] > 0.0 ? p.held_max_sum * p.size / fig[2] : 1.0;
    printf("clsph-ranks run: %s split across %d ranks along x (%s), %s, %zu particles\n",
           scene.case_path, p.size, o.ncuts > 0 ? "cuts given" : "cuts at the particles' quantiles",
           CLSPH_PRECISION_NAME, total);
    printf("  cuts at the end:");
    for (int r = 1; r < p.size; ++r) printf(" %.6g", p.cut[r]);
    printf(" m (moved %ld times: --recut %d); halo %d sweeps = %.4g m\n", p.recuts, p.recut,
           p.sweeps, p.halo);
    printf("  to t = %g s: %ld steps (%.2f acoustic sub-steps a step), %.3f s, %.3g "
           "particle-steps/s; the ranks held %.3f times the particles (halos)\n",
           scene.t_end, sim.step, steps > 0 ? (double)sim.substeps_sum / steps : 0.0, wall,
           wall > 0.0 ? (double)total * steps / wall : 0.0,
           steps > 0 ? fig[2] / steps / (double)total : 0.0);
    printf("  load: the busiest rank held %.3f times the ranks' mean, on average over the steps\n",
           balance);
    printf("  exchanges: one a step, %.0f bytes sent a step over the ranks, %.1f%% of the wall "
           "time (the slowest rank's, with its transfers to and from the device)\n",
           steps > 0 ? fig[3] / steps : 0.0, wall > 0.0 ? 100.0 * fig[1] / wall : 0.0);
    printf("  owned at the end: %zu of %zu particles\n", gathered, total);
  }
  /* the whole scene alone on rank 0 */
  double dx = NAN, dv = NAN, vmax = 0.0, wall_alone = NAN;
  long steps_alone = -1;
  int nalone = 0;
  if (p.rank == 0 && o.check) {
    CLSPH_TRY(sim_create(&dev, &scene, &ref));
    const double a0 = MPI_Wtime();
    CLSPH_TRY(run_to_end(&ref, NULL));
    wall_alone = MPI_Wtime() - a0;
    steps_alone = ref.step;
    CLSPH_TRY(read_state(&ref, NULL, &alone, &nalone));
    dx = dv = 0.0;
    size_t missing = 0;
    for (int k = 0; k < nalone; ++k) {
      const double *r = alone + rec * (size_t)k;
      const long at = where[(size_t)r[0]];
      if (at < 0) {
        ++missing;
        continue;
      }
      const double *s = all + rec * (size_t)at;
      double ex = 0.0, ev = 0.0, v2 = 0.0;
      for (size_t a = 0; a < dim; ++a) {
        ex += (s[1 + a] - r[1 + a]) * (s[1 + a] - r[1 + a]);
        ev += (s[1 + dim + a] - r[1 + dim + a]) * (s[1 + dim + a] - r[1 + dim + a]);
        v2 += r[1 + dim + a] * r[1 + dim + a];
      }
      dx = fmax(dx, sqrt(ex));
      dv = fmax(dv, sqrt(ev));
      vmax = fmax(vmax, sqrt(v2));
    }
    dx /= scene.dr;
    if (vmax > 0.0) dv /= vmax;
    printf("  the whole scene alone: %ld steps, %.3f s; largest |x − x_alone| = %.3g dr, "
           "|v − v_alone| = %.3g of the largest speed (%.4g m/s); particles not owned by a "
           "rank: %zu of %d\n",
           steps_alone, wall_alone, dx, dv, vmax, missing, nalone);
    CLSPH_CHECK(missing == 0 && (size_t)nalone == gathered && steps_alone == sim.step,
                CLSPH_E_BLOWUP,
                "the split run does not hold the whole run's particles (%zu missing, %zu owned "
                "against %d) or steps (%ld against %ld)",
                missing, gathered, nalone, sim.step, steps_alone);
  }
  if (p.rank == 0 && o.json != NULL) {
    cJSON *j = cJSON_CreateObject();
    CLSPH_CHECK(j != NULL, CLSPH_E_NOMEM, "out of memory");
    cJSON_AddStringToObject(j, "case", scene.case_path);
    cJSON_AddNumberToObject(j, "ranks", p.size);
    cJSON_AddStringToObject(j, "precision", CLSPH_PRECISION_NAME);
    cJSON_AddNumberToObject(j, "particles", (double)total);
    cJSON_AddNumberToObject(j, "owned", (double)gathered);
    cJSON_AddNumberToObject(j, "steps", (double)sim.step);
    cJSON_AddNumberToObject(j, "substeps", (double)sim.substeps_sum);
    cJSON_AddNumberToObject(j, "halo_sweeps", p.sweeps);
    cJSON_AddNumberToObject(j, "halo_m", p.halo);
    cJSON_AddNumberToObject(j, "seconds", wall);
    cJSON_AddNumberToObject(j, "exchange_seconds", fig[1]);
    cJSON_AddNumberToObject(j, "held_ratio",
                            sim.step > 0 ? fig[2] / (double)sim.step / (double)total : 0.0);
    cJSON_AddNumberToObject(j, "recuts", (double)p.recuts);
    cJSON_AddNumberToObject(j, "balance", fig[2] > 0.0 ? p.held_max_sum * p.size / fig[2] : 1.0);
    cJSON *cuts = cJSON_AddArrayToObject(j, "cuts");
    for (int r = 1; r < p.size && cuts != NULL; ++r)
      cJSON_AddItemToArray(cuts, cJSON_CreateNumber(p.cut[r]));
    cJSON_AddNumberToObject(j, "bytes_per_step", sim.step > 0 ? fig[3] / (double)sim.step : 0.0);
    if (o.check) {
      cJSON_AddNumberToObject(j, "steps_alone", (double)steps_alone);
      cJSON_AddNumberToObject(j, "seconds_alone", wall_alone);
      cJSON_AddNumberToObject(j, "dx_dr", dx);
      cJSON_AddNumberToObject(j, "dv_rel", dv);
    }
    st = ranks_write_json(o.json, j);
    cJSON_Delete(j);
    if (st != CLSPH_OK) goto done;
  }
done:
  sim.comm = NULL;
  sim_destroy(&ref);
  sim_destroy(&sim);
  part_destroy(&p);
  case_close(script);
  scene_free(&scene);
  dev_close(&dev);
  free(mine);
  free(all);
  free(alone);
  free(counts);
  free(displs);
  free(where);
  if (st != CLSPH_OK && p.size > 1) /* a failed rank stops the others, which wait in a collective */
    MPI_Abort(comm, st == CLSPH_E_INPUT ? 2 : 1);
  return st == CLSPH_OK ? 0 : st == CLSPH_E_INPUT ? 2 : 1;
}
