/* probe.cl: SPH interpolation of a field at arbitrary points (probes, profiles, metrics),
 * normalised by the kernel sum (Shepard), over fluid and wall-vertex particles:
 *   A(x) = Σ_j V_j A_j W(x − x_j) / Σ_j V_j W(x − x_j).
 * A point with no particle within the support gets NaN.
 * On a wall face (a pressure sensor: a face probe, the mean over points on the face, host
 * sim_sample_probes) the sum runs over the fluid on one side only (dummy particles carry no state
 * of their own: kind > 1 is left out; USAW vertex particles on the wall take part). A(x) is then
 * the kernel-weighted mean of the fluid within the support, whose centre lies about a spacing off
 * the wall: for the pressure, the wall's pressure to second order in that offset where the normal
 * pressure gradient vanishes at the wall, as on a fixed vertical wall (∂p/∂n = ρ (g − a)·n with
 * a·n = 0 there and g·n = 0); on a floor it misses ρ g·n times the offset (hydrostatic). Near a
 * corner the centre also sits off the point along the face, by up to about h. */
__kernel void probe_sample(const uint np, __global const realv *at, const struct grid g,
                           __global const uint *cell_start, __global const realv *pos,
                           __global const real *vol, __global const uint *kind,
                           __global const real *field, const uint ncomp, __global real *out)
{
  const uint p = get_global_id(0);
  if (p >= np) return;
  const realv x = at[p];
  real s[4] = {R(0.0), R(0.0), R(0.0), R(0.0)};
  real wsum = R(0.0);
  struct neigh_iter it;
  neigh_begin(&it, &g, x);
  uint j;
  while (neigh_next(&it, &g, cell_start, &j)) {
    if (kind[j] > 1u) continue; /* fluid and USAW vertex particles carry the fields */
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2) continue;
    real w = vol[j] * smoothing_w(g.sm, sqrt(r2));
    wsum += w;
    for (uint c = 0; c < ncomp && c < 4u; ++c) s[c] += w * field[j * ncomp + c];
  }
  for (uint c = 0; c < ncomp && c < 4u; ++c) out[p * ncomp + c] = wsum > R(0.0) ? s[c] / wsum : NAN;
}
