/* integrate.cl (ballistic): fluid particles move under gravity and the body force alone,
 *   dv/dt = g + f,  dx/dt = v  (semi-implicit Euler: v first, then x),
 * with no pressure, viscosity or walls: a scheme that exercises the time loop, periodic wrapping
 * and the blow-up checks. Positions on periodic axes are wrapped into [lo, lo + len). */
real ballistic_wrap(real x, real lo, real len)
{
  real t = x - lo;
  t -= len * floor(t / len);
  if (t >= len) t -= len; /* round-off of the line above */
  return lo + t;
}

__kernel void ballistic_step(const uint n, const real dt, const realv accel, const struct grid g,
                             __global realv *pos, __global realv *vel, __global const uint *kind,
                             __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != 0u) return;
  realv v = vel[i] + dt * accel;
  realv x = pos[i] + dt * v;
#if PERIODIC_X
  x.x = ballistic_wrap(x.x, g.lo.x, g.len.x);
#endif
#if PERIODIC_Y
  x.y = ballistic_wrap(x.y, g.lo.y, g.len.y);
#endif
  if (!all(isfinite(x)) || !all(isfinite(v))) flags_raise(flags, CLSPH_FLAG_NAN);
  vel[i] = v;
  pos[i] = x;
}
