/* lattice.cl: sums of the smoothing function over the full support of a particle on the square
 * lattice of the particle spacing, on the device and in the build's precision: the references
 * that the schemes measure kernel sums against (a particle of the initial lattice reads exactly
 * these), so that a lattice at rest carries no bias from the quadrature error of the sums. */
/* Over the square (cubic in 3-D) lattice of spacing dr around a particle (one work-item), V =
 * dr^DIM:
 *   out[0] = Σ_k W(|x_k|) V, itself included: sigma0, the kernel sum of a full support;
 *   out[1] = −Σ_k F(|x_k|) x_k² V: lambda, what the viscous sum 2 Σ V F (v_i − v_j) makes of
 *            ∇²(x²/2) = 1 (wcsph_riemann/advection.cl divides by it). */
__kernel void lattice_sums(const struct smooth sm, const real dr, __global real *out)
{
  if (get_global_id(0) != 0) return;
  const int m = (int)ceil(sm.support / dr) + 1;
  const int mz = DIM == 3 ? m : 0;
  real s = R(0.0), l = R(0.0);
  for (int c = -mz; c <= mz; ++c)
    for (int a = -m; a <= m; ++a)
      for (int b = -m; b <= m; ++b) {
        const real r = dr * sqrt((real)(a * a + b * b + c * c));
        if (r >= sm.support) continue;
        s += smoothing_w(sm, r);
        if (a != 0 || b != 0 || c != 0) l -= smoothing_f(sm, r) * (real)(a * a) * dr * dr;
      }
  /* (s dr) dr, as the 2-D sums always were: the same rounding, the same runs */
  out[0] = DIM == 3 ? s * dr * dr * dr : s * dr * dr;
  out[1] = DIM == 3 ? l * dr * dr * dr : l * dr * dr;
}
