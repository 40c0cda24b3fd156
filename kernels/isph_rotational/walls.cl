/* walls.cl (isph-rotational): dummy wall particles (Hosseini & Feng 2011 sec 3.3.1).
 *
 * Kinds: ROT_FLUID (moves), ROT_DUMMY (fixed, inside the solid), ROT_INFLOW and ROT_OUTFLOW
 * (entry and exit layers, kernels/common/open.cl). A dummy d at distance dist_d
 * from the wall with unit normal n_d into the fluid has its image x_d + 2 dist_d n_d in the fluid.
 *   velocity (Morris et al. 1997 extrapolation; "the negative of the interpolated velocity of
 *   its image", sec 3.3.1): u_d = 2 u_wall − Σ_f V_f u_f W / Σ_f V_f W at the image, fluid only
 *   (option wall_velocity = "shepard", the default); or u_d = 2 u_wall − u_m(d), m(d) the
 *   particle nearest to the image (wall_velocity = "image", -D ROT_WALL_IMAGE=1), which on a
 *   straight wall of the lattice is the particle at the image. The Shepard sum at an image half a
 *   spacing from the wall is one-sided (no fluid behind the wall): in a shear layer it reads
 *   u(δr/2) + ~0.4 δr u', so the dummies drag too hard and ∇²u next to the wall is off by
 *   O(U/(H δr)), which grows as δr shrinks (Poiseuille between an entry and an exit: the
 *   pressure next to the entry's corners; see cases/poiseuille_open.lua);
 *   p and φ (homogeneous Neumann, "propagated along the normal"): a_d = a_m(d), m(d) the fluid
 *   particle nearest to the image.
 * At a box corner the nearest wall point is the corner itself, so the image is the point
 * reflection through the corner: the diagonal dummies take the mean of the fluid around their
 * image, our reading of "averaging between their neighbours" (Lee et al. 2008). */
#ifndef ROT_WALL_IMAGE
#define ROT_WALL_IMAGE 0
#endif
#define ROT_FLUID   0u
#define ROT_DUMMY   2u
#define ROT_INFLOW  3u /* entry layer particle (common/open.cl: OPEN_INFLOW) */
#define ROT_OUTFLOW 4u /* exit layer particle (common/open.cl: OPEN_OUTFLOW) */

real rot_wrap(real x, real lo, real len)
{
  real t = x - lo;
  t -= len * floor(t / len);
  if (t >= len) t -= len; /* round-off of the line above */
  return lo + t;
}

/* vel of the dummies (extrapolated from the fluid and the entry and exit layers) and mirror[d]
 * (the particle nearest to their image, fluid or an entry or exit layer particle: open.cl then
 * resolves the latter to the fluid; the fluid keeps mirror[i] = i); coef = 1 */
__kernel void rot_dummy_velocity(const uint n, const struct grid g, __global const uint *cell_start,
                                 __global const realv *pos, __global const real *vol,
                                 __global const uint *kind, __global const real *dist,
                                 __global const realv *normal, __global const realv *wall_vel,
                                 __global realv *vel, __global uint *mirror, __global real *coef,
                                 __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  coef[i] = R(1.0);
  if (kind[i] != ROT_DUMMY) {
    mirror[i] = i;
    return;
  }
  const realv img = pos[i] + R(2.0) * dist[i] * normal[i];
  /* the Shepard sum of the fluid and the nearest particle at the image (common/marker.cl):
   * fluid, or an entry or exit layer particle (resolved in open.cl) */
  const struct marker_sums s =
      marker_shepard(&g, cell_start, pos, vol, kind, img, i, MARKER_VEL, vel, 0);
  const real wsum = s.wsum;
  const uint m = s.nearest;
  const realv uw = wall_vel[i];
#if ROT_WALL_IMAGE
  const realv u = m != i ? R(2.0) * uw - vel[m] : uw;
#else
  const realv u = wsum > R(0.0) ? R(2.0) * uw - s.u / wsum : uw;
#endif
  if (!all(isfinite(u))) flags_raise(flags, CLSPH_FLAG_NAN);
  vel[i] = u;
  mirror[i] = m;
}

/* a_d = c_d a_m(d) for the dummies (c = 1: Neumann by propagation, sec 3.3.1) and the entry and
 * exit layers (open.cl: c = 1 at an entry, the odd reflection h_d/h_m at an exit) */
__kernel void rot_propagate(const uint n, __global const uint *kind, __global const uint *mirror,
                            __global const real *coef, __global real *a)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] == ROT_FLUID) return;
  a[i] = coef[i] * a[mirror[i]];
}
