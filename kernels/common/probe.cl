/* probe.cl: SPH interpolation of a field at arbitrary points (probes, profiles, metrics),
 * normalised by the kernel sum (Shepard), over fluid and wall-vertex particles:
 *   A(x) = Σ_j V_j A_j W(x − x_j) / Σ_j V_j W(x − x_j).
 * A point with no particle within the support gets NaN. */
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
    if (r2 >= SMOOTH_SUPPORT2) continue;
    real w = vol[j] * smoothing_w(sqrt(r2));
    wsum += w;
    for (uint c = 0; c < ncomp && c < 4u; ++c) s[c] += w * field[j * ncomp + c];
  }
  for (uint c = 0; c < ncomp && c < 4u; ++c) out[p * ncomp + c] = wsum > R(0.0) ? s[c] / wsum : NAN;
}
