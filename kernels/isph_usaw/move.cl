/* move.cl (isph-usaw): the two half moves of the time step (eqs 30 and 34),
 *   r* = r^n + δt/2 u^n,   r̃^{n+1} = r* + δt/2 ũ^{n+1},
 * for fluid particles only (vertex particles move with their wall, wall.cl). A non-finite
 * position raises CLSPH_FLAG_NAN; periodic axes wrap. */
__kernel void isph_half_move(const uint n, const real half_dt, const struct grid g,
                             __global realv *pos, __global const realv *vel,
                             __global const uint *kind, __global uint *flags)
{
  const uint i = get_global_id(0);
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

/* The wall guard of scenes with a free surface (our departure from the paper, see project.cl):
 * a motion m of a fluid particle at x over a time tau (a velocity over δt, or a shift over 1)
 * that would bring it within margin of a wall loses its component into the wall, relative to
 * the wall's velocity when moving_walls (vel, the wall vertices' velocities). Past the end of a
 * segment the direction is the one from its end point: over a convex corner the segment's own
 * normal would brake the flow that leaves the corner along the next segment. */
realv isph_wall_guard(const realv x, realv m, const real tau, const real margin, USAW_SEG_ARGS,
                      __global const realv *vel, const int moving_walls)
{
  struct neigh_iter it;
  neigh_begin(&it, &g_seg, x);
  uint s;
  while (neigh_next(&it, &g_seg, seg_start, &s)) {
    const realv a = seg_a[s] + it.shift, b = seg_b[s] + it.shift, t = b - a;
    const real f = dot(x - a, t) / dot(t, t);
    const realv c = a + clamp(f, R(0.0), R(1.0)) * t;
    const real dist = length(x - c);
    const realv nrm = (f < R(0.0) || f > R(1.0)) && dist > R(0.0) ? (x - c) / dist : seg_n[s];
    const realv us =
        moving_walls ? R(0.5) * (vel[inv[seg_v1[s]]] + vel[inv[seg_v2[s]]]) : (realv)(R(0.0));
    const real mn = dot(m - us, nrm);
    if (mn < R(0.0) && dist + tau * mn < margin) m -= mn * nrm;
  }
  return m;
}
