/* flags.h: error bits that kernels atomic_or into d_flags[0]; the host reads them once per step.
 * d_flags[1] counts the fluid particles found behind a wall in the step and d_flags[2] holds the
 * deepest of them (m, the bits of a float); d_flags[3] counts the fluid particles that left the
 * domain (kernels/common/domain.cl); host/sim/checks.c reads them. */
#define CLSPH_FLAG_NAN            1u /* a non-finite value was produced */
#define CLSPH_FLAG_NEIGH_OVERFLOW 2u /* a per-particle neighbour table was too small */
#define CLSPH_FLAG_ESCAPED        4u /* a particle left the (non-periodic) grid */
#define CLSPH_FLAG_WALL           8u /* a fluid particle is behind a wall segment */

/* The kind a fluid particle takes when it leaves the domain (KIND_OUT of host/scene/geometry.h):
 * the next sort moves it past the last particle and the run drops it. */
#define CLSPH_KIND_OUT 6u

void flags_raise(__global uint *flags, uint bit)
{
  atomic_or(flags, bit);
}
