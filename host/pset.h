/* pset.h: a particle set on the device, one buffer per field (structure of arrays). Reordering by
 * the grid's permutation is applied to every field, so no field can be forgotten. Buffers change
 * when the set is reordered: look a field up with pset_mem() each time, never keep the cl_mem. */
#ifndef CLSPH_PSET_H
#define CLSPH_PSET_H

#include "grid.h"

#define PSET_MAX_FIELDS 32

struct pfield {
  char name[32]; /* e.g. "pos", "vel", "p" */
  size_t elem;   /* bytes per particle, a multiple of 4 */
  cl_mem d;      /* device buffer, cap * elem bytes */
};

struct pset {
  size_t n, cap; /* particles, and the buffers' capacity */
  int nfields;
  struct pfield f[PSET_MAX_FIELDS];
  cl_mem scratch[PSET_MAX_FIELDS]; /* one spare buffer per distinct element size */
  size_t scratch_elem[PSET_MAX_FIELDS];
  int nscratch;
};

/** @brief Empty set of n particles with room for cap. */
void pset_init(struct pset *ps, size_t n, size_t cap);
/** @brief Add a field of `elem` bytes per particle, initialised from `init` (n elements) or
 *  zero. @param index receives the field's index for pset_mem(). */
enum clsph_status pset_add(struct pset *ps, const struct dev *dev, const char *name, size_t elem,
                           const void *init, int *index);
/** @brief Current buffer of a field. */
cl_mem pset_mem(const struct pset *ps, int index);
/** @brief Reorder every field by the grid's permutation (after grid_sort). */
enum clsph_status pset_reorder(struct pset *ps, struct grid *g, const struct dev *dev);
/** @brief Release every buffer. */
void pset_destroy(struct pset *ps);

#endif /* CLSPH_PSET_H */
