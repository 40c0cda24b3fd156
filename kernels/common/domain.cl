/* domain.cl: the fluid stays in the scene's domain (host/sim/domain.c). A fluid particle (kind 0)
 * beyond the box lo .. hi on a non-periodic axis raises CLSPH_FLAG_ESCAPED; the host puts the box
 * a spacing outside the domain (a particle that far out is behind any wall on the domain's edge
 * by more than the wall-crossing check allows) and leaves the side open that gravity points away
 * from (a splash may rise above an open tank; the cell grid still bounds it). The cell grid
 * itself reaches several spacings further, for the wall and section layers: its own escape
 * test alone let a jet run 0.75 m out of a unit box. */
__kernel void domain_check(const uint n, __global const realv *pos, __global const uint *kind,
                           const real4 lo, const real4 hi, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != 0u) return;
  const realv x = pos[i];
  int out = 0;
  if (!PERIODIC_X) out |= REALV_X(x) < lo.x || REALV_X(x) > hi.x;
  if (!PERIODIC_Y) out |= REALV_Y(x) < lo.y || REALV_Y(x) > hi.y;
#if DIM == 3
  if (!PERIODIC_Z) out |= REALV_Z(x) < lo.z || REALV_Z(x) > hi.z;
#endif
  if (out) flags_raise(flags, CLSPH_FLAG_ESCAPED);
}
