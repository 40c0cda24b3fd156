/* common.cl (USAW schemes): the USAW operators of Leroy et al. 2014 over particles b ∈ P (fluid and
 * vertex particles) and segments s, shared by the stages of the scheme.
 *   G+_a{A} = (1/γ_a) Σ_b V_b (A_a + A_b) ∇w_ab − (1/γ_a) Σ_s (A_a + A_s) ∇γ_as      (5)
 *   G−_a{A} = −(1/γ_a) Σ_b V_b A_ab ∇w_ab + (1/γ_a) Σ_s A_as ∇γ_as                  (8)
 *   D_a{A}  = −(1/γ_a) Σ_b V_b A_ab · ∇w_ab + (1/γ_a) Σ_s A_as · ∇γ_as              (9)
 * with A_ab = A_a − A_b, ∇w_ab = ∇_a w(r_a − r_b) = F(r) r_ab. A segment's value is the mean of
 * its two vertex particles' (Ferrand et al. 2013); its vertices are found through inv[] (the
 * current index of each original particle index). Kinds: 0 fluid, 1 vertex. */
#define ISPH_FLUID  0u
#define ISPH_VERTEX 1u
#define ISPH_PI     R(3.14159265358979323846)

/* The arguments every stage passes for the segments, then the segment cache's (gamma.cl). */
#define USAW_SEG_BASE_ARGS                                                                         \
  const struct grid g_seg, __global const uint *seg_start, __global const realv *seg_a,            \
      __global const realv *seg_b, __global const realv *seg_n, __global const uint *seg_v1,       \
      __global const uint *seg_v2, __global const uint *inv
#define USAW_SEG_ARGS USAW_SEG_BASE_ARGS USAW_CACHE_ARGS

/* The particle arguments every stage passes. */
#define USAW_PART_ARGS                                                                             \
  const uint n, const struct grid g, __global const uint *cell_start, __global const realv *pos,   \
      __global const real *vol, __global const uint *kind, __global const real *gam

/* Position on a periodic axis wrapped into [lo, lo + len). */
real isph_wrap(real x, real lo, real len)
{
  real t = x - lo;
  t -= len * floor(t / len);
  if (t >= len) t -= len; /* round-off of the line above */
  return lo + t;
}

/* The wall guard of scenes with a free surface (our departure from the paper; isph_usaw/project.cl
 * and wcsph_usaw/update.cl): a motion m of a fluid particle at x over a time tau (a velocity over
 * δt, or a shift over 1) that would bring it within margin of a wall loses its component into the
 * wall, relative to the wall's velocity when moving_walls (vel, the wall vertices' velocities).
 * Past the end of a segment the direction is the one from its end point: over a convex corner the
 * segment's own normal would brake the flow that leaves the corner along the next segment. */
realv usaw_wall_guard(const realv x, realv m, const real tau, const real margin, USAW_SEG_BASE_ARGS,
                      __global const realv *vel, const int moving_walls)
{
  struct neigh_iter it;
  NEIGH_FOR(it, g_seg, seg_start, x, s) {
    const realv a = seg_a[s] + it.shift, b = seg_b[s] + it.shift, t = b - a;
    const real f = dot(x - a, t) / dot(t, t);
    const realv c = a + clamp(f, R(0.0), R(1.0)) * t;
    const real dist = length(x - c);
    const realv nrm = (f < R(0.0) || f > R(1.0)) && dist > R(0.0) ? (x - c) / dist : seg_n[s];
    /* the wall's velocity at c: linear along a segment for a sliding or a turning wall (the
     * segment's mean would miss a turning wall's ω × (c − mid), and let a particle that rides a
     * rotating arm's corner creep into it by that times δt every step) */
    const realv v1 = moving_walls ? vel[inv[seg_v1[s]]] : (realv)(R(0.0));
    const realv us =
        moving_walls ? v1 + clamp(f, R(0.0), R(1.0)) * (vel[inv[seg_v2[s]]] - v1) : (realv)(R(0.0));
    const real mn = dot(m - us, nrm);
    if (mn < R(0.0) && dist + tau * mn < margin) m -= mn * nrm;
  }
  return m;
}

/* Collisions (scenes with a free surface only; our departure from the paper). Free-surface
 * particles are Dirichlet rows and are not shifted (eq 35 is switched off within h q_max/2 of
 * the surface), so nothing keeps two of them apart: the paper reports "particle clumping ... at
 * the free-surface, which is well visible on the jet" (sec 4.3). In the wedge case at δr = 0.02 m
 * ten particles of the jet ended on one point with one velocity, and the particle next to the
 * clump, its sums weighted by ten times the mass at one place, took −8e4 Pa and was thrown at
 * 24 m/s out of the pool. Here, as in the collision model of MPS (Lee et al. 2011), two fluid
 * particles closer than USAW_COLLIDE δr that approach each other lose their relative normal
 * velocity but a restitution USAW_RESTITUTION (momentum kept: equal masses), and are moved apart
 * to that distance, half each (at most USAW_COLLIDE δr / 2 per step; the wall guard applies;
 * isph_usaw/shift.cl). wcsph-usaw applies the velocity part to u* (wcsph_usaw/update.cl).
 * Particles at the same point part along a direction set by their two ids. */
#ifndef USAW_COLLIDE
#define USAW_COLLIDE R(0.5)
#endif
#ifndef USAW_RESTITUTION
#define USAW_RESTITUTION R(0.2)
#endif
/* the unit vector from particle j to particle i, r_ij / |r_ij|; for coincident particles a
 * direction drawn from the pair's ids, opposite for the two */
realv usaw_pair_dir(const realv r, const real len, const real scale, const uint id_i,
                    const uint id_j)
{
  if (len > R(1e-6) * scale) return r / len;
  const uint lo = min(id_i, id_j), hi = max(id_i, id_j);
  const real ang = (real)((lo * 2654435761u + hi) % 6283u) * R(1e-3);
  const realv d = (realv)(cos(ang), sin(ang));
  return id_i < id_j ? d : -d;
}
