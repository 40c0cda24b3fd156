/* shift.cl (isph-stabilized): particle shifting, option `shifting = C` (0, off, by default: the
 * paper's scheme has none). After the motion, a fluid particle farther than h from every
 * free-surface particle, and not one itself, moves by
 *   δr_i = −C h² Σ_j V_j ∇_iW_ij      over fluid and dummies (Leroy et al. 2014 eqs 35-37 with
 * the dummies in place of the segments' term: they fill the support at a wall and push off it),
 * |δr_i| at most dr/10, none of it toward a wall whose point (a dummy's x_d + d n_d) lies within
 * dr, and no correction of the velocity. Near the free surface the truncated
 * support would push the particles out of the water; there the pressure's free-surface row holds
 * the spacing. */
#define STAB_SHIFT_MAX R(0.1)

__kernel void stab_particle_shift(const uint n, const struct grid g,
                                  __global const uint *cell_start, __global const uint *kind,
                                  __global const realv *pos, __global const real *vol,
                                  __global const uint *free_surface, __global const real *dist,
                                  __global const realv *normal, const real c_h2, const real dr,
                                  __global realv *shift)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  shift[i] = (realv)(R(0.0));
  if (kind[i] != STAB_FLUID || free_surface[i]) return;
  const realv x = pos[i];
  const real near2 = R(0.25) * g.sm.support2; /* h² for the cubic spline's support 2h */
  realv gc = (realv)(R(0.0)), wn = (realv)(R(0.0));
  real wbest = dr * dr; /* a wall point within dr: the nearest one's normal */
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    if (j == i) continue;
    const realv r = x - (pos[j] + it.shift);
    const real r2 = dot(r, r);
    if (r2 >= g.sm.support2) continue;
    if (kind[j] == STAB_FLUID && free_surface[j] && r2 < near2) return;
    gc += vol[j] * smoothing_f(g.sm, sqrt(r2)) * r;
    if (kind[j] != STAB_FLUID) {
      const realv q = x - (pos[j] + it.shift + dist[j] * normal[j]);
      const real q2 = dot(q, q);
      if (q2 < wbest) {
        wbest = q2;
        wn = normal[j];
      }
    }
  }
  realv d = -c_h2 * gc;
  const real dn = dot(d, wn);
  if (dn < R(0.0)) d -= dn * wn; /* never toward the nearest wall within dr */
  const real len = sqrt(dot(d, d)), cap = STAB_SHIFT_MAX * dr;
  if (len > cap) d *= cap / len;
  shift[i] = d;
}

__kernel void stab_apply_shift(const uint n, const struct grid g, __global const uint *kind,
                               __global const realv *shift, __global realv *pos)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != STAB_FLUID) return;
  pos[i] = grid_wrap(&g, pos[i] + shift[i]);
}
