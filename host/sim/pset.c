/* pset.c: particle fields on the device and their reordering. */
#include "pset.h"

#include <stdio.h>
#include <string.h>

#include "clsph_config.h"

void pset_init(struct pset *ps, size_t n, size_t cap)
{
  memset(ps, 0, sizeof *ps);
  ps->n = n;
  ps->cap = cap < n ? n : cap;
  /* the neighbour loops in lanes load NEIGH_W particles even from a set of fewer (grid.cl) */
  if (ps->cap < PSET_MIN_CAP) ps->cap = PSET_MIN_CAP;
}

enum clsph_status pset_add(struct pset *ps, const struct dev *dev, const char *name, size_t elem,
                           const void *init, int *index)
{
  enum clsph_status st = CLSPH_OK;
  const cl_uint zero = 0;
  CLSPH_CHECK(ps->nfields < PSET_MAX_FIELDS, CLSPH_E_INPUT, "too many particle fields (%d)",
              PSET_MAX_FIELDS);
  CLSPH_CHECK(elem > 0 && elem % 4 == 0, CLSPH_E_INPUT,
              "particle field '%s': %zu bytes per particle is not a multiple of 4", name, elem);
  struct pfield *f = &ps->f[ps->nfields];
  snprintf(f->name, sizeof f->name, "%s", name);
  f->elem = elem;
  f->type = PF_REAL;
  f->ncomp = (int)(elem / sizeof(real));
  f->nout = f->ncomp;
  f->output = 1;
  CLSPH_TRY(kern_buffer(dev, ps->cap * elem, NULL, &f->d, name));
  /* zeros past the particles too: the neighbour loops in lanes read up to NEIGH_W − 1 of them in
   * a set of fewer than NEIGH_W particles (grid.cl), and a dead lane's weight is zero, its terms
   * must be finite */
  CLSPH_TRY(kern_fill(dev, f->d, &zero, sizeof zero, ps->cap * elem));
  if (init != NULL) CLSPH_TRY(kern_write(dev, f->d, ps->n * elem, init));
  /* spare buffers for the reordering: one per field of this size, up to PSET_SPARES_PER_SIZE */
  int have = 0;
  for (int s = 0; s < ps->nscratch; ++s) have += ps->scratch_elem[s] == elem;
  if (have < PSET_SPARES_PER_SIZE) {
    CLSPH_TRY(kern_buffer(dev, ps->cap * elem, NULL, &ps->scratch[ps->nscratch], "reorder spare"));
    /* a field's buffer after a reordering: its tail past the particles zero as well */
    CLSPH_TRY(kern_fill(dev, ps->scratch[ps->nscratch], &zero, sizeof zero, ps->cap * elem));
    ps->scratch_elem[ps->nscratch++] = elem;
  }
  *index = ps->nfields++;
done:
  if (st != CLSPH_OK && ps->nfields < PSET_MAX_FIELDS) kern_release(&ps->f[ps->nfields].d);
  return st;
}

void pset_describe(struct pset *ps, int index, enum pfield_type type, int nout, int output)
{
  struct pfield *f = &ps->f[index];
  f->type = type;
  f->ncomp = (int)(f->elem / (type == PF_REAL ? sizeof(real) : 4));
  f->nout = nout > 0 && nout <= f->ncomp ? nout : f->ncomp;
  f->output = output;
}

void pset_temporary(struct pset *ps, int index)
{
  ps->f[index].temp = 1;
  ps->f[index].output = 0;
}

int pset_find(const struct pset *ps, const char *name)
{
  for (int k = 0; k < ps->nfields; ++k)
    if (!ps->f[k].temp && strcmp(ps->f[k].name, name) == 0) return k;
  return -1;
}

cl_mem pset_mem(const struct pset *ps, int index)
{
  CLSPH_ASSERT(index >= 0 && index < ps->nfields);
  return ps->f[index].d;
}

/* Batches of consecutive fields, each gathered into a spare of its size that no other field of
 * the batch takes, GRID_GATHER_FIELDS to a launch (3 launches for isph-usaw's 19 fields). */
enum clsph_status pset_reorder(struct pset *ps, struct grid *g, const struct dev *dev)
{
  enum clsph_status st = CLSPH_OK;
  int done[PSET_MAX_FIELDS] = {0};
  for (;;) { /* a launch takes every field left whose size still has a spare, up to its slots */
    int field[GRID_GATHER_FIELDS], spare[GRID_GATHER_FIELDS], taken[PSET_MAX_FIELDS] = {0};
    size_t words[GRID_GATHER_FIELDS];
    cl_mem src[GRID_GATHER_FIELDS], dst[GRID_GATHER_FIELDS];
    int count = 0;
    for (int k = 0; k < ps->nfields && count < GRID_GATHER_FIELDS; ++k) {
      const struct pfield *f = &ps->f[k];
      if (done[k] || f->temp) continue;
      int s = 0;
      while (s < ps->nscratch && (ps->scratch_elem[s] != f->elem || taken[s])) ++s;
      if (s == ps->nscratch) continue; /* every spare of this size is taken: a later launch */
      taken[s] = 1;
      done[k] = 1;
      field[count] = k;
      spare[count] = s;
      words[count] = f->elem / 4;
      src[count] = f->d;
      dst[count] = ps->scratch[s];
      ++count;
    }
    if (count == 0) break;
    CLSPH_TRY(grid_gather(g, dev, ps->n, count, words, src, dst));
    for (int c = 0; c < count; ++c) { /* the gathered copy becomes the field; the old its spare */
      struct pfield *f = &ps->f[field[c]];
      cl_mem old = f->d;
      f->d = ps->scratch[spare[c]];
      ps->scratch[spare[c]] = old;
    }
  }
done:
  return st;
}

void pset_destroy(struct pset *ps)
{
  for (int k = 0; k < ps->nfields; ++k) kern_release(&ps->f[k].d);
  for (int s = 0; s < ps->nscratch; ++s) kern_release(&ps->scratch[s]);
  ps->nfields = ps->nscratch = 0;
}
