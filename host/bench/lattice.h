/* lattice.h: particles on a square (cubic) lattice, optionally jittered and shuffled; used by the
 * demo, the benchmarks and the tests. */
#ifndef CLSPH_LATTICE_H
#define CLSPH_LATTICE_H

#include <stddef.h>
#include <stdint.h>

#include "status.h"

/** Host particle positions in the device layout (2 reals per particle in 2-D, 4 in 3-D). */
struct lattice {
  int dim;
  size_t n;
  size_t stride;       /* reals per particle: 2 or 4 */
  double dr;           /* spacing, m */
  double lo[3], hi[3]; /* the box the lattice fills */
  void *pos;           /* n * stride reals (real of this build) */
};

/** @brief Fill the box [lo, lo + cells·dr] with cells[a] particles per axis at cell centres.
 *  @param jitter random displacement per axis, as a fraction of dr (0 for a perfect lattice)
 *  @param shuffle randomise the order of the particles
 *  @param seed seed of the generator */
enum clsph_status lattice_make(int dim, const int cells[3], double dr, const double lo[3],
                               double jitter, int shuffle, uint64_t seed, struct lattice *out);
/** @brief Coordinate a of particle i, in double. */
double lattice_x(const struct lattice *l, size_t i, int a);
/** @brief Release the positions. */
void lattice_free(struct lattice *l);

#endif /* CLSPH_LATTICE_H */
