/* move.cl (isph-usaw): the two half moves of the time step (eqs 30 and 34),
 *   r* = r^n + δt/2 u^n,   r̃^{n+1} = r* + δt/2 ũ^{n+1},
 * for fluid particles only (vertex particles move with their wall, wall.cl). A non-finite
 * position raises CLSPH_FLAG_NAN; periodic axes wrap. Item 0 zeroes the count of free-surface rows
 * that isph_free_surface makes next (the host has queued the read of the last one before). */
__kernel void isph_half_move(const uint n, const real half_dt, const struct grid g,
                             __global realv *pos, __global const realv *vel,
                             __global const uint *kind, __global uint *flags, __global uint *count)
{
  const uint i = get_global_id(0);
  if (i == 0u) count[0] = 0u; /* the free-surface rows' count (free_surface.cl) */
  if (i >= n || kind[i] != ISPH_FLUID) return;
  realv x = pos[i] + half_dt * vel[i];
#if PERIODIC_X
  x.x = isph_wrap(x.x, g.lo.x, g.len.x);
#endif
#if PERIODIC_Y
  x.y = isph_wrap(x.y, g.lo.y, g.len.y);
#endif
  if (!all(isfinite(x))) flags_raise(flags, CLSPH_FLAG_NAN);
  pos[i] = x;
}
