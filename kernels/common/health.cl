/* health.cl: what the time loop's health checks need (host/sim/checks.c, sim_check_step), reduced
 * on the device over the fluid particles (kind 0): the kinetic energy  Σ_i V_i |v_i|²   (times ρ0/2
 * on the host) and the volume Σ_i V_i, the spacing         d_i = min_j |r_ij|, j ≠ i a fluid
 * particle within the support (the support when there is none): the smallest d_i, and the number of
 *                       particles with d_i < `close` (clustered particles).
 * Fluid-fluid distances only: next to a wall the distance to a wall vertex depends on how the
 * lattice meets the wall, not on the flow. Work-group g writes its five results to
 * partial[5 g + 0..4]: energy, volume, clustered count, fluid count, smallest d_i. A non-finite
 * velocity makes the energy non-finite, which the host reports as such. */
__kernel void health_sums(const uint n, const struct grid g, __global const uint *cell_start,
                          __global const realv *pos, __global const realv *vel,
                          __global const real *vol, __global const uint *kind, const real close,
                          __global real *partial)
{
  __local real s[REDUCE_WG];
  const uint l = get_local_id(0), grp = get_group_id(0);
  real e = R(0.0), v = R(0.0), c = R(0.0), m = R(0.0), dmin = g.sm.support;
  for (uint i = get_global_id(0); i < n; i += get_global_size(0)) {
    if (kind[i] != 0u) continue;
    const realv x = pos[i];
    e += vol[i] * dot(vel[i], vel[i]);
    v += vol[i];
    m += R(1.0);
    realw d2 = (realw)(g.sm.support2);
    struct neigh_iter it;
    NEIGH_FOR_LANES(it, g, cell_start, x, b)
    { /* in lanes (grid.cl) */
      const struct lanesv r = lanes_rel(x, lanes_load_v(pos, b), it.shift);
      const maskw take =
          neigh_live(&it, b) & neigh_other(b, i) & LANES_MASK(lanes_load_u(kind, b) == (uintw)(0u));
      d2 = select(d2, fmin(d2, lanes_dot(r, r)), take);
    }
    const real d = sqrt(lanes_min(d2));
    dmin = fmin(dmin, d);
    c += d < close ? R(1.0) : R(0.0);
  }
  s[l] = e;
  reduce_local_sum(s);
  if (l == 0) partial[5 * grp] = s[0];
  s[l] = v;
  reduce_local_sum(s);
  if (l == 0) partial[5 * grp + 1] = s[0];
  s[l] = c;
  reduce_local_sum(s);
  if (l == 0) partial[5 * grp + 2] = s[0];
  s[l] = m;
  reduce_local_sum(s);
  if (l == 0) partial[5 * grp + 3] = s[0];
  s[l] = -dmin; /* the smallest as the largest of the negatives */
  reduce_local_max(s);
  if (l == 0) partial[5 * grp + 4] = -s[0];
}
