/* kepsilon.cl: what the schemes' k-ε models share (the standard model, Launder & Spalding 1974):
 * the constants and the semi-implicit update of k and ε with the sinks linearised (Leroy et al.
 * 2014 eqs 18-19; Wang, Sun & Hu eqs 28-30), and the eddy viscosity. The wall treatments differ
 * and stay with each scheme: wcsph_riemann/turbulence.cl (the particle-based wall model of Wang,
 * Sun & Hu sec 4), usaw/turbulence.cl (the semi-analytical walls of Leroy et al. eqs 22-29).
 * Compiled only where a scene declares turbulence { model = "k-epsilon" } (KE_ON = 1). */
#if KE_ON
#define KE_CMU   R(0.09) /* Leroy et al. Table 1; Wang, Sun & Hu eq 6 */
#define KE_C1    R(1.44)
#define KE_C2    R(1.92)
#define KE_SK    R(1.0)
#define KE_SE    R(1.3)
#define KE_KAPPA R(0.41)

/* k^{n+1} = (k + δt (P + D_k)) / (1 + δt ε/k) (Leroy eq 18, Wang eq 30): the sink −ε k^{n+1}/k^n
 * implicit. A numerator that diffusion makes negative is clipped to a millionth of k and counted
 * (clips[0]). */
real ke_advance_k(const real k, const real eps, const real prod, const real diff, const real dt,
                  __global uint *clips)
{
  const real rate = eps / fmax(k, R(1e-30));
  real kn = k + dt * (prod + diff);
  if (!(kn > R(0.0))) {
    kn = R(1e-6) * k;
    atomic_inc(&clips[0]);
  }
  return kn / (R(1.0) + dt * rate);
}

/* ε^{n+1} = (ε + δt (C1 (ε/k) P + D_ε)) / (1 + δt C2 ε/k) (Leroy eq 19, Wang eqs 28-29), clipped
 * as k (clips[1]). */
real ke_advance_eps(const real k, const real eps, const real prod, const real diff, const real dt,
                    __global uint *clips)
{
  const real rate = eps / fmax(k, R(1e-30));
  real en = eps + dt * (KE_C1 * rate * prod + diff);
  if (!(en > R(0.0))) {
    en = R(1e-6) * eps;
    atomic_inc(&clips[1]);
  }
  return en / (R(1.0) + dt * KE_C2 * rate);
}

/* ν_t = C_μ k²/ε (Leroy eq 14, Wang eq 6) */
real ke_nu_t(const real k, const real eps)
{
  return KE_CMU * k * k / eps;
}
#endif
