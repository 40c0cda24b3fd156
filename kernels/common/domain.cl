/* domain.cl: the fluid stays in the scene's domain (host/sim/domain.c). A fluid particle (kind 0)
 * that has left the domain takes the kind CLSPH_KIND_OUT and is counted in flags[3]; the host
 * sorts it past the others and drops it, or stops the run when too many have left
 * (host/sim/checks.c). It has left when it is more than `margin` (dr) beyond the box lo .. hi,
 * the domain's own, on a closed side (that far out it is behind any wall on the domain's edge by
 * more than the wall-crossing check allows), or beyond a closed side at all while above an open
 * one: over the rim of the walls that stand on the domain's edge, it leaves at once, before it
 * falls behind them (where it would read as a wall crossing). The sides gravity points away from
 * (`open`, bits as GRID_OPEN in grid.cl) are unbounded: a splash rises above an open tank and
 * falls back, the cell grid clamping it into its top cells. The grid itself reaches several
 * spacings beyond the domain, for the wall and section layers: its own escape test alone let a
 * jet run 0.75 m out of a unit box. */
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
