/* turbulence.cl (USAW schemes): the k-ε model with the unified semi-analytical wall conditions
 * (Leroy et al. 2014 sec 2, eqs 14 and 18-29; Ferrand et al. 2013), shared by isph-usaw and
 * wcsph-usaw. Compiled only for a scene that declares turbulence { model = "k-epsilon" }
 * (USAW_TURB = 1); the constants and the semi-implicit update are common/kepsilon.cl's.
 *
 * The momentum equation (eq 13) takes μ_E = μ + μ_T in its viscous term (usaw/viscous.cl,
 * usaw_predict): the fluid sum of eq 22 with the pair's (ν_E,a + ν_E,b), as the sums of eqs 25 and
 * 27 take theirs, and the wall term −(2/γ_a) Σ_s u*²_as t_as |∇γ_as| (eq 22), u*_as the friction
 * velocity of the log law at the particle's distance from the segment (eq 23, usaw_friction). The
 * pressure the schemes solve for is then p̃ = p + ⅔ ρ k (eq 12): the field "p" is p̃.
 *
 * Wall vertices (eq 24): their velocity in the volume sums is not the wall's; it evolves by the
 * viscous term alone, u_v += δt L_v{μ_E, u}, its normal part removed (u_vertex; the wall's own
 * velocity stays in vel, for the wall term's u^R, the pressure's wall condition and the guards).
 * Here a vertex has no volume of its own (isph_usaw.c), so that its values enter the fluid's sums
 * only through the segments (a segment's value is the mean of its two vertices'): u_vertex in
 * G−{u} of the production, and nothing in the Laplacians of k and ε. The vertices' k (eq 26) and ε
 * (eqs 28-29) are kept for the outputs and for G−{k}, G−{ε}.
 *
 * usaw_turb_transport, for each fluid particle a (eqs 18-21, 25, 27):
 *   G−_a{u} = −(1/γ_a) Σ_b V_b u_ab ⊗ ∇w_ab + (1/γ_a) Σ_s u_as ⊗ ∇γ_as (eq 8; u_s from u_vertex),
 *   S = √(2 S:S), S = ½ (G + Gᵀ) (eq 21), P = min(√C_μ k S, ν_t S²) (eq 20);
 *   D_k = (1/γ_a) Σ_b V_b (2ν + (ν_t,a + ν_t,b)/σ_k) k_ab F_ab   (eq 25: no flux through walls),
 *   D_ε = (1/γ_a) Σ_b V_b (2ν + (ν_t,a + ν_t,b)/σ_ε) ε_ab F_ab
 *         + (4 C_μ/(σ_ε γ_a)) Σ_s k_a² |∇γ_as| / δr_as          (eq 27, δr_as as in eq 17),
 *   F_ab = r_ab·∇w_ab / r_ab² (the sign of the sums as in the viscous term: a diffusion);
 *   k and ε advance by eqs 18-19 (ke_advance_k, ke_advance_eps).
 * The wall layer: a fluid particle less than δr from its nearest segment, with y+ = u* δr_as / ν
 *   on the log law (≥ 11.063), takes the wall function's two halves, as Code_Saturne's (the
 *   paper's model, its Theory Guide part IV-B) and OpenFOAM's wall cells do: the production
 *   τ_w ∂u/∂n = u*³/(κ δr_as) of the wall law it already feels in its momentum (eqs 22-23), and
 *   ε = C_μ^¾ k^{3/2}/(κ δr_as). With eqs 20-21 and 27 there, G−{u} of the log profile at δr/2,
 *   a kernel sum over four rows, read about half the log law's gradient, the first row's k fell
 *   to 0.64 and ε to 0.35 of the 1-D reference's (e+ = 640, 20 rows), its ν_t, carried into the
 *   rows above by the pair sums, took the shear out of the first two rows, and u+ fell 4% below
 *   the reference all the way to the centre. Eq 27's wall term stays for the rows above. The
 *   vertices carry no volume here, so the Dirichlet values of eqs 26 and 28-29, which the
 *   paper's vertex particles bring into the volume sums, reach no sum: the wall layer's
 *   condition stands for them.
 * usaw_turb_update: k, ε take the new values, ν_t = C_μ k²/ε (eq 14); each vertex v takes
 *   k_v = Σ_{b∈F} V_b k_b w_vb / Σ_{b∈F} V_b w_vb                                    (26)
 *   ε_v = (ε_s1 + ε_s2)/2,  ε_s = Σ_{b∈F} V_b (ε_b + 4 C_μ^¾ k_b^{3/2}/(κ δr_bs)) w_sb / α_s
 *   (eqs 28-29; α_s = Σ_{b∈F} V_b w_sb, w_sb at the segment's midpoint) and ν_t from them. */
#if USAW_TURB
#define USAW_LOG_B   R(5.2)    /* eq 23 */
#define USAW_LOG_LAM R(11.063) /* y+ where u+ = y+ meets u+ = ln(y+)/κ + 5.2 */

/* The friction velocity u* of the log law (eq 23), u_t/u* = ln(d u* / ν)/κ + 5.2, for the
 * tangential speed u_t relative to the wall at the distance d. Below the log law's reach (where
 * the linear law's y+ = √(u_t d/ν) is under 11.063, the two laws' crossing) the viscous sublayer's
 * u_t/u* = d u* / ν, u*² = ν u_t/d: there the wall term of eq 22 is the laminar one of eq 15.
 * With wall_law = "scalable" (as Code_Saturne's scalable wall function) y+ is held at 11.063
 * instead, u* = u_t/11.063, and the wall layer below takes its production and ε at the distance
 * 11.063 ν/u*: the model has no buffer layer, and the channel at e+ = 640 and 40 rows (the wall
 * layer at y+ = 8) ran u+ 10-14% low with the two-layer law, within 1.9% with the scalable one
 * (t = 40 s). */
/* turbulence { production = "standard" } (solvers/usaw/turbulence.c) */
#ifndef USAW_PROD_STANDARD
#define USAW_PROD_STANDARD 0
#endif
#ifndef USAW_SCALABLE /* turbulence { wall_law = "scalable" } (solvers/usaw/turbulence.c) */
#define USAW_SCALABLE 0
#endif
real usaw_friction(const real ut, const real d, const real nu)
{
  const real ulin = sqrt(nu * ut / d);
#if USAW_SCALABLE /* y+ held at 11.063: u* = u_t / u+(11.063) = u_t / 11.063 */
  if (!(ulin * d / nu >= USAW_LOG_LAM)) return ut / USAW_LOG_LAM;
#else
  if (!(ulin * d / nu >= USAW_LOG_LAM)) return ulin;
#endif
  real u = ulin; /* Newton on f(u) = u (ln(d u/ν)/κ + B) − u_t, concave and increasing here */
  for (int it = 0; it < 12; ++it) {
    const real lg = log(d * u / nu) / KE_KAPPA + USAW_LOG_B;
    const real step = (u * lg - ut) / (lg + R(1.0) / KE_KAPPA);
    u = fmax(u - step, R(0.5) * u);
    if (fabs(step) <= R(4.0) * REAL_EPS * u) break;
  }
  return u;
}

/* 2 u*²/u_t, the rate of the wall term of eq 22 per |∇γ_as|/γ_a, for the velocity ur relative to
 * the wall (n the segment's normal) at the distance d: the laminar 2ν/d of eq 15 in the viscous
 * sublayer and where the fluid stands still. */
real usaw_wall_rate(const realv ur, const realv nn, const real d, const real nu)
{
  const realv ut = ur - dot(ur, nn) * nn;
  const real utn = length(ut);
  if (!(utn > R(0.0))) return R(2.0) * nu / d;
  const real us = usaw_friction(utn, d, nu);
  return R(2.0) * us * us / utn;
}

__kernel void usaw_turb_transport(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *vel,
                                  __global const realv *u_vertex, __global const real *k,
                                  __global const real *eps, __global const real *nu_t,
                                  const real dt, const real nu, const real d_min, const real dr0,
                                  __global real *k_new, __global real *eps_new,
                                  __global uint *clips)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const real ki = k[i], ei = eps[i];
  k_new[i] = ki;
  eps_new[i] = ei;
  if (kind[i] != ISPH_FLUID) return;
  const realv x = pos[i], u = vel[i];
  const real nti = nu_t[i];
  realv gx = (realv)(R(0.0)), gy = (realv)(R(0.0)); /* rows of γ G−{u}: ∇u_x, ∇u_y */
  real dk = R(0.0), de = R(0.0);
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    const realv r = x - (pos[j] + it.shift);
    const real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i || kind[j] != ISPH_FLUID) continue;
    const real f = smoothing_f(g.sm, sqrt(r2)) * vol[j];
    const realv du = u - vel[j];
    gx -= du.x * f * r;
    gy -= du.y * f * r;
    const real ntj = nu_t[j];
    dk += (R(2.0) * nu + (nti + ntj) / KE_SK) * (ki - k[j]) * f;
    de += (R(2.0) * nu + (nti + ntj) / KE_SE) * (ei - eps[j]) * f;
  }
  real wall = R(0.0);                                      /* Σ_s |∇γ_as| / δr_as */
  real near = INFINITY, near_ut = R(0.0), near_d = R(0.0); /* the nearest segment */
  NEIGH_FOR(it, g_seg, seg_start, x, s) {
    const realv a = seg_a[s] + it.shift, b = seg_b[s] + it.shift, nn = seg_n[s];
    const realv gg = usaw_grad_gamma_seg(g.sm, x, a, b, nn);
    const real ggn = length(gg);
    if (ggn == R(0.0)) continue;
    const realv du = u - R(0.5) * (u_vertex[inv[seg_v1[s]]] + u_vertex[inv[seg_v2[s]]]);
    gx += du.x * gg;
    gy += du.y * gg;
    const real dist = dot(x - R(0.5) * (a + b), nn), drs = fmax(dist, d_min);
    wall += ggn / drs;
    if (dist < near) { /* the slip relative to the wall itself (its vertices' vel) */
      const realv ur = u - R(0.5) * (vel[inv[seg_v1[s]]] + vel[inv[seg_v2[s]]]);
      near = dist;
      near_d = drs;
      near_ut = length(ur - dot(ur, nn) * nn);
    }
  }
  const real ig = R(1.0) / gam[i];
  gx *= ig;
  gy *= ig;
  const real sxy = R(0.5) * (gx.y + gy.x);
  const real s2 = R(2.0) * (gx.x * gx.x + gy.y * gy.y + R(2.0) * sxy * sxy); /* S² = 2 S:S */
#if USAW_PROD_STANDARD /* turbulence { production = "standard" }: ν_T S², OpenFOAM's kEpsilon */
  real prod = nti * s2;
#else /* the semi-linear production of eq 20 (Guimet & Laurence): at most √C_μ k S */
  real prod = fmin(sqrt(KE_CMU) * ki * sqrt(s2), nti * s2);
#endif
  int layer = 0; /* in the wall layer, on the log law: the wall function's P and ε (see above) */
  if (near < dr0) {
    const real us = usaw_friction(near_ut, near_d, nu);
#if USAW_SCALABLE /* the wall virtually moved back to y+ = 11.063 */
    layer = 1;
    if (us > R(0.0)) near_d = fmax(near_d, USAW_LOG_LAM * nu / us);
#else
    layer = near_d * us / nu >= USAW_LOG_LAM;
#endif
    if (layer) prod = us * us * us / (KE_KAPPA * near_d); /* τ_w ∂u/∂n of eq 23 */
  }
  dk *= ig;
  de = de * ig + R(4.0) * KE_CMU / KE_SE * ki * ki * wall * ig; /* eq 27 */
  const real kn = ke_advance_k(ki, ei, prod, dk, dt, clips);    /* eq 18 */
  k_new[i] = kn;
  if (layer && kn > R(0.0)) /* ε = C_μ^¾ k^{3/2} / (κ δr_as), the log law's */
    eps_new[i] = sqrt(KE_CMU) * sqrt(sqrt(KE_CMU)) * kn * sqrt(kn) / (KE_KAPPA * near_d);
  else
    eps_new[i] = ke_advance_eps(ki, ei, prod, de, dt, clips); /* eq 19 */
}

__kernel void usaw_turb_update(USAW_PART_ARGS, USAW_SEG_ARGS, __global const uint *id,
                               __global const real *k_new, __global const real *eps_new,
                               const real d_min, __global real *k, __global real *eps,
                               __global real *nu_t, __global realv *nu_t2)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  if (kind[i] == ISPH_FLUID) {
    k[i] = k_new[i];
    eps[i] = eps_new[i];
    nu_t[i] = ke_nu_t(k_new[i], eps_new[i]); /* eq 14 */
    nu_t2[i] = (realv)(nu_t[i], R(0.0));     /* for the host's largest ν_t (the time step) */
    return;
  }
  nu_t2[i] = (realv)(R(0.0));
  if (kind[i] != ISPH_VERTEX) return;
  const realv x = pos[i];
  real wk = R(0.0), sk = R(0.0);
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    const realv r = x - (pos[j] + it.shift);
    const real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || kind[j] != ISPH_FLUID) continue;
    const real w = vol[j] * smoothing_w(g.sm, sqrt(r2));
    wk += w;
    sk += w * k_new[j];
  }
  /* ε_s of the vertex's own segments (eq 29) */
  const real c34 = sqrt(KE_CMU) * sqrt(sqrt(KE_CMU)); /* C_μ^¾ */
  real se = R(0.0);
  int ns = 0;
  NEIGH_FOR(it, g_seg, seg_start, x, s) {
    if (seg_v1[s] != id[i] && seg_v2[s] != id[i]) continue;
    const realv m = R(0.5) * (seg_a[s] + seg_b[s]) + it.shift, nn = seg_n[s];
    real ws = R(0.0), es = R(0.0);
    struct neigh_iter jt;
    NEIGH_FOR(jt, g, cell_start, m, j) {
      const realv xb = pos[j] + jt.shift, r = m - xb;
      const real r2 = dot(r, r);
      if (r2 >= g.sm.support2 || kind[j] != ISPH_FLUID) continue;
      const real w = vol[j] * smoothing_w(g.sm, sqrt(r2));
      const real kb = fmax(k_new[j], R(0.0));
      const real d = fmax(dot(xb - m, nn), d_min);
      ws += w;
      es += w * (eps_new[j] + R(4.0) * c34 * kb * sqrt(kb) / (KE_KAPPA * d));
    }
    if (ws > R(0.0)) {
      se += es / ws;
      ++ns;
    }
  }
  if (wk > R(0.0) && ns > 0) { /* a dry vertex keeps its values */
    k[i] = sk / wk;
    eps[i] = se / (real)ns;
    nu_t[i] = ke_nu_t(k[i], eps[i]);
  }
}

/* The shear of the wall law on the walls of one group (in_group[seg_index[s]] = 1: the geometry's
 * order of the segments), ρ u*² t (eqs 22-23), as its mean over the group, weighted as the wall
 * term weighs it: particle a adds w_as = V_a (2/γ_a) |∇γ_as| and w_as u*²_as t_as (u*²_as t_as =
 * ½ rate u_t, usaw_wall_rate) for each of the group's segments, and the host divides the sums and
 * multiplies by ρ and the group's length. The wall term's own momentum, Σ_a m_a (2/γ_a) Σ_s u*²
 * t |∇γ_as|, is not the wall's force: for a uniform u* its weights add up to 2 ln 2 (∫ (1/γ) dγ
 * from γ = ½ at the wall to 1) times the wall's length, the sum of the fluid pairs' 1/γ_a-weighted
 * viscous forces takes back the rest. Writes (Σ w u*² t_x, Σ w u*² t_y, Σ w, 0) per particle. */
__kernel void usaw_turb_wall_shear(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *vel,
                                   __global const uint *seg_index, __global const uint *in_group,
                                   const real nu, const real d_min, __global real4 *out)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  real4 f = (real4)(R(0.0));
  if (kind[i] == ISPH_FLUID) {
    const realv x = pos[i], u = vel[i];
    struct neigh_iter it;
    NEIGH_FOR(it, g_seg, seg_start, x, s) {
      if (in_group[seg_index[s]] == 0u) continue;
      const realv a = seg_a[s] + it.shift, b = seg_b[s] + it.shift, nn = seg_n[s];
      const real ggn = length(usaw_grad_gamma_seg(g.sm, x, a, b, nn));
      if (ggn == R(0.0)) continue;
      const realv us = R(0.5) * (vel[inv[seg_v1[s]]] + vel[inv[seg_v2[s]]]);
      const real drs = fmax(dot(x - R(0.5) * (a + b), nn), d_min);
      const realv ur = u - us, ut = ur - dot(ur, nn) * nn;
      const real w = vol[i] * R(2.0) * ggn / gam[i];
      const realv tau = R(0.5) * usaw_wall_rate(ur, nn, drs, nu) * ut;
      f += (real4)(w * tau.x, w * tau.y, w, R(0.0));
    }
  }
  out[i] = f;
}
#endif
