/* pset.h: a particle set on the device, one buffer per field (structure of arrays). Reordering by
 * the grid's permutation is applied to every field, so no field can be forgotten. Buffers change
 * when the set is reordered: look a field up with pset_mem() each time, never keep the cl_mem. */
#ifndef CLSPH_PSET_H
#define CLSPH_PSET_H

#include "grid.h"

#define PSET_MAX_FIELDS 32
/** Spare buffers per element size: the reordering gathers up to this many fields of one size in a
 *  launch (grid_gather takes GRID_GATHER_FIELDS of any sizes). */
#define PSET_SPARES_PER_SIZE 4

/** Element type of a field, for output. */
enum pfield_type { PF_REAL = 0, PF_UINT, PF_INT };

struct pfield {
  char name[32];         /* e.g. "pos", "vel", "p" */
  size_t elem;           /* bytes per particle, a multiple of 4 */
  enum pfield_type type; /* element type */
  int ncomp;             /* components stored per particle (elem / size of the type) */
  int nout;              /* components that carry data (3-D positions: 3 of 4), <= ncomp */
  int output;            /* written to snapshots (all fields go into checkpoints) */
  int temp;              /* a value within a step only (pset_temporary): not reordered */
  cl_mem d;              /* device buffer, cap * elem bytes */
};

struct pset {
  size_t n, cap; /* particles, and the buffers' capacity */
  int nfields;
  struct pfield f[PSET_MAX_FIELDS];
  cl_mem scratch[PSET_MAX_FIELDS]; /* spare buffers: PSET_SPARES_PER_SIZE at most per size */
  size_t scratch_elem[PSET_MAX_FIELDS];
  int nscratch;
};

/* The least capacity of a set: NEIGH_FOR_LANES (kernels/common/grid.cl) loads NEIGH_W particles
 * at a time (4 in double, 8 in float). */
#define PSET_MIN_CAP 8

/** @brief Empty set of n particles with room for cap. */
void pset_init(struct pset *ps, size_t n, size_t cap);
/** @brief Add a field of `elem` bytes per particle, initialised from `init` (n elements) or
 *  zero; typed as `ncomp` reals (output: all of them, but 3 of the 4 of a 3-D vector).
 *  @param index receives the field's index for pset_mem(). */
enum clsph_status pset_add(struct pset *ps, const struct dev *dev, const char *name, size_t elem,
                           const void *init, int *index);
/** @brief Set a field's element type and the components that carry data (after pset_add). */
void pset_describe(struct pset *ps, int index, enum pfield_type type, int nout, int output);
/** @brief Mark a field (not an output) as a scheme's value within a step, which the scheme makes
 *  again after every sort before it reads it: the reordering leaves it (its values then belong to
 *  no particle), and pset_find does not know it. */
void pset_temporary(struct pset *ps, int index);
/** @brief Index of the field called `name` (not a temporary), or −1. */
int pset_find(const struct pset *ps, const char *name);
/** @brief Current buffer of a field. */
cl_mem pset_mem(const struct pset *ps, int index);
/** @brief Reorder every field but the temporaries by the grid's permutation (after grid_sort), as
 *  few launches as the spare buffers allow. */
enum clsph_status pset_reorder(struct pset *ps, struct grid *g, const struct dev *dev);
/** @brief Release every buffer. */
void pset_destroy(struct pset *ps);

#endif /* CLSPH_PSET_H */
