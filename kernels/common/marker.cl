/* marker.cl: the Shepard interpolation of the fluid at a virtual marker (an image point of a dummy
 * wall particle inside the fluid), shared by the dummy-wall schemes.
 *   W̃(x − x_j) = V_j W(x − x_j) / Σ_k V_k W(x − x_k), j and k over the non-dummy particles
 * (Asai et al. 2013 / stabilized_isph_virtual_marker.txt eq 10; Morris et al. 1997's extrapolation
 * as isph-rotational uses it). The dummies themselves never enter the sums: a marker reads the
 * fluid (and, in isph-rotational, the entry and exit layers). A marker with no such particle
 * within the support is "dry" (wsum = 0): the caller decides what a dry marker means. */
#define MARKER_DUMMY 2u /* KIND_DUMMY of host/scene/geometry.h */
#define MARKER_VEL   1  /* marker_shepard's `what`: sum the velocity */
#define MARKER_P     2  /* and/or the pressure */

struct marker_sums {
  real wsum;    /* Σ_j V_j W(x − x_j): 0 for a dry marker */
  realv u;      /* Σ_j V_j W u_j (what & MARKER_VEL), else 0 */
  real p;       /* Σ_j V_j W p_j (what & MARKER_P), else 0 */
  uint nearest; /* the particle nearest to x, or `self` when none is within the support */
};

/* The sums at x over the non-dummy neighbours of x; vel and p are read only as `what` asks. */
struct marker_sums marker_shepard(const struct grid *g, __global const uint *cell_start,
                                  __global const realv *pos, __global const real *vol,
                                  __global const uint *kind, realv x, uint self, int what,
                                  __global const realv *vel, __global const real *p)
{
  struct marker_sums m;
  m.wsum = R(0.0);
  m.u = (realv)(R(0.0));
  m.p = R(0.0);
  m.nearest = self;
  real best = INFINITY;
  struct neigh_iter it;
  NEIGH_FOR(it, *g, cell_start, x, j) {
    if (kind[j] == MARKER_DUMMY) continue;
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g->sm.support2) continue;
    real w = vol[j] * smoothing_w(g->sm, sqrt(r2));
    m.wsum += w;
    if (what & MARKER_VEL) m.u += w * vel[j];
    if (what & MARKER_P) m.p += w * p[j];
    if (r2 < best) {
      best = r2;
      m.nearest = j;
    }
  }
  return m;
}
