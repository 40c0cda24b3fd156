/* domain.cl: the fluid stays in the scene's domain (host/sim/domain.c). A fluid particle (kind 0)
 * beyond the box lo .. hi on a non-periodic axis has left the domain: it takes the kind
 * CLSPH_KIND_OUT and is counted in flags[3]; the host sorts it past the others and drops it, or
 * stops the run when too many have left (host/sim/checks.c). The host puts the box a spacing
 * outside the domain (a particle that far out is behind any wall on the domain's edge by more
 * than the wall-crossing check allows) and leaves the side open that gravity points away from (a
 * splash may rise above an open tank and fall back; the cell grid clamps it into its top cells,
 * grid.cl). The cell grid itself reaches several spacings further, for the wall and section
 * layers: its own escape test alone let a jet run 0.75 m out of a unit box. */
/* The box: lo .. hi, the domain's own; margin: how far beyond a closed side a particle may stray
 * (dr); open: the sides gravity points away from (bits as GRID_OPEN, grid.cl), unbounded. A
 * particle above an open side is over the rim of the walls that stand on the domain's edge: one
 * beyond a closed side there has gone over them, and leaves at once, before it falls behind
 * them (where it would read as a wall crossing). */
__kernel void domain_check(const uint n, __global const realv *pos, __global uint *kind,
                           const real4 lo, const real4 hi, const real margin, const uint open,
                           __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != 0u) return;
  const realv x = pos[i];
  int beyond = 0, far = 0, above = 0;
#define DOMAIN_AXIS(C, A, PER)                                                                     \
  if (!(PER)) {                                                                                    \
    if (C > hi.s##A) {                                                                             \
      if (open & (1u << A))                                                                        \
        above = 1;                                                                                 \
      else {                                                                                       \
        beyond = 1;                                                                                \
        far |= C > hi.s##A + margin;                                                               \
      }                                                                                            \
    } else if (C < lo.s##A) {                                                                      \
      if (open & (16u << A))                                                                       \
        above = 1;                                                                                 \
      else {                                                                                       \
        beyond = 1;                                                                                \
        far |= C < lo.s##A - margin;                                                               \
      }                                                                                            \
    }                                                                                              \
  }
  DOMAIN_AXIS(REALV_X(x), 0, PERIODIC_X)
  DOMAIN_AXIS(REALV_Y(x), 1, PERIODIC_Y)
#if DIM == 3
  DOMAIN_AXIS(REALV_Z(x), 2, PERIODIC_Z)
#endif
#undef DOMAIN_AXIS
  if (far || (beyond && above)) {
    kind[i] = CLSPH_KIND_OUT;
    atomic_inc(&flags[3]);
  }
}
