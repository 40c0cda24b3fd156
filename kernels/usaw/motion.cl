/* motion.cl (USAW schemes): walls that turn, wall { omega, centre } (the water wheel of Leroy et
 * al. 2014 sec 4.4). A turning wall is a rigid body: at time t its points stand rotated by
 * θ = ω t about the centre c, r(t) = c + R(θ) (r(0) − c), and move at u = ω e_z × (r − c), the
 * velocity its vertex particles carry into the sums (the wall's own velocity, as a sliding lid's).
 * The rotation is applied to the positions at t = 0, not stepped, so the wheel keeps its shape
 * and its radius over any number of steps. rot holds, per scene wall, c_x, c_y, ω; the time t
 * comes as an argument, so that turning the walls takes no transfer (in float, θ = ω t at t =
 * 30 s is within 3e-6 rad). */

/* cos θ, sin θ of wall w at time t */
real2 usaw_turn_angle(__global const real *rot, const int w, const real t)
{
  const real th = rot[3 * w + 2] * t;
  return (real2)(cos(th), sin(th));
}

/* the vector v turned by the angle cs (cos θ, sin θ) */
realv usaw_rotate(const real2 cs, const realv v)
{
  return (realv)(cs.x * v.x - cs.y * v.y, cs.y * v.x + cs.x * v.y);
}

/* r(0) of wall w turned by the angle cs about its centre */
realv usaw_turned(__global const real *rot, const int w, const real2 cs, const realv x0)
{
  const realv c = (realv)(rot[3 * w], rot[3 * w + 1]);
  return c + usaw_rotate(cs, x0 - c);
}

/* x wrapped into the domain on its periodic axes */
realv usaw_wrap_point(const struct grid g, realv x)
{
#if PERIODIC_X
  x.x = isph_wrap(x.x, g.lo.x, g.len.x);
#endif
#if PERIODIC_Y
  x.y = isph_wrap(x.y, g.lo.y, g.len.y);
#endif
  return x;
}

/* The vertex particles of turning walls: position and velocity now, and their normal (into the
 * fluid) when has_normal; periodic axes wrap. x0: per original particle, its position and its
 * normal at t = 0. */
__kernel void usaw_turn_vertices(const uint n, const struct grid g, __global const uint *id,
                                 __global const int *turn, __global const realv *x0,
                                 __global const real *rot, const real t, __global realv *pos,
                                 __global realv *vel, const uint has_normal, __global realv *normal)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const uint o = id[i];
  const int w = turn[o];
  if (w < 0) return;
  const real2 cs = usaw_turn_angle(rot, w, t);
  const realv x = usaw_turned(rot, w, cs, x0[2 * o]);
  const realv d = x - (realv)(rot[3 * w], rot[3 * w + 1]);
  vel[i] = rot[3 * w + 2] * (realv)(-d.y, d.x);
  if (has_normal) normal[i] = usaw_rotate(cs, x0[2 * o + 1]);
  pos[i] = usaw_wrap_point(g, x);
}

/* The segments of turning walls (index: each segment's place in the geometry's order): ends,
 * normal and midpoint now; on a periodic axis the midpoint (which bins the segment) is wrapped
 * into the domain and both ends move with it, as usaw_walls_from_geom places them at t = 0. */
__kernel void usaw_turn_segments(const uint ns, const struct grid g, __global const uint *index,
                                 __global const int *turn, __global const realv *seg0,
                                 __global const real *rot, const real t, __global realv *a,
                                 __global realv *b, __global realv *nrm, __global realv *mid)
{
  const uint s = get_global_id(0);
  if (s >= ns) return;
  const uint o = index[s];
  const int w = turn[o];
  if (w < 0) return;
  const real2 cs = usaw_turn_angle(rot, w, t);
  const realv A = usaw_turned(rot, w, cs, seg0[3 * o]);
  const realv B = usaw_turned(rot, w, cs, seg0[3 * o + 1]);
  const realv M = R(0.5) * (A + B), Mw = usaw_wrap_point(g, M);
  a[s] = A + (Mw - M);
  b[s] = B + (Mw - M);
  nrm[s] = usaw_rotate(cs, seg0[3 * o + 2]);
  mid[s] = Mw;
}
