/* turbulence.cl (wcsph-riemann): the k-ε RANS model and its particle-based wall model (Wang, Sun
 * & Hu sec 2.1-2.3.2, 2.5 and 4), once per advection step, before the viscous sums
 * (advection.cl) that take the eddy viscosity. Compiled only for a scene that declares
 * turbulence { model = "k-epsilon" } (WCR_TURB = 1): a laminar scene has none of these kernels.
 *
 * Layers (sec 4.2, fig 4): a fluid particle whose distance to the wall d (wall_dist, config.cl)
 * is below R = 2h − dr is in P_ext, below dr in P. The wall model puts every P_ext particle at
 * the model's distance y_p (eq 10; dr/2 unless the case offsets its walls, sec 4.4).
 *
 * wcr_turb_wall, for each P_ext particle (eqs 35-37, 10-14):
 *   n_p = Σ_b W_ib n_b / Σ_b W_ib over the dummy neighbours b (normals into the fluid),
 *   v_t = (v_i − v_w) − ((v_i − v_w)·n_p) n_p, v_w the dummies' kernel-weighted velocity (a
 *   sliding wall), U_p = |v_t|, t_p = v_t/(U_p + ε) (eqs 35-36);
 *   u_s = C_μ^¼ k^½, y+ = y_p u_s/ν (eq 10), u+ = ln(E y+)/κ or y+ below 11.225 (eq 11);
 *   τ_w/ρ = U_p u_s/u+ (eq 12), and the wall function's ∂U/∂n at y_p: τ_w/(ρ u_s κ y_p) in the
 *   log layer, τ_w/(ρ ν) in the linear one (eq 13).
 * Stored: frame = (t_p, n_p) and wall = (τ_w/ρ, ∂U/∂n); zero outside P_ext.
 * With wall_shear = "distance" (WCR_SHEAR_DIST) τ_w reads the log law at i's own distance from
 * the wall (its height over the nearest dummy's layer, less dr/2, plus the boundary offset
 * y_p − dr/2; at least y_p/2) in place of y_p (∂U/∂n and the rest stay at y_p), and eq 39's
 * force is divided by its lattice sum (wcr_wall_shear_sum). Both are quadrature errors of
 * eq 39 on a flat wall: the second row of a lattice (d = 1.5 dr < R) also carries the wall's
 * shear, with 7% of the first row's weight Σ_b V_b ∂W/∂n at h = 1.3 dr, and at y_p it reads
 * the log law from its own, higher, velocity (+19% at 20 rows across the channel); and the two
 * rows' weights sum to 0.974 of τ_w, not 1 (Wendland C2, h = 1.3 dr), at every resolution
 * (cases/channel_ke.lua; RESULTS_rans.md). With wall_shear = "first_row" (WCR_SHEAR_ROW1) only
 * the first row (P, d < dr) takes the wall's stress: with the second row's 7% share of it taken
 * straight to the wall, the first row's upper face carried that much less of it, the velocity
 * step to the second row shrank with it, and the first row, whose log law sets u_τ, ran fast.
 * Each first-row particle takes τ_w over its share of the wall, s_i dr^(DIM−1) (advection.cl,
 * force.cl): every dummy b of the first layer (depth < dr) hands its area V_b/dr to the first
 * row's particles j in proportion to V_j W_jb, so that s_i = Σ_b V_b W_ib / D_b with D_b = Σ_j
 * V_j W_jb (wcr_row1_density), 1 on the lattice, and the shares cover the wall whatever the row
 * holds: eq 39's own sums follow the particles, and a first row short of particles (N_f = 80:
 * 37-40 of 42 per wall) carried 4-8% less of the wall's stress. No particle then takes the
 * dummies' no-slip drag: beyond R a disordered second row's particles (R ≤ d < 2h − dr/2) still
 * reach the dummies, and with ν_t their drag added 1-3% to the wall's stress (N_f = 40).
 * E = 9.793 with the switch at 11.225 (the pair the paper's eq 11 quotes; its "E = 0.9" is a
 * misprint), κ = 0.41.
 *
 * wcr_turb_transport, for each fluid particle (eqs 22-24, 28-30, 40):
 *   ∇v_i = Σ_j v_ij ⊗ (B_i^in ∇W_ij) V_j over the fluid neighbours (eq 22 with the inner
 *   correction B^in of eq 40: B of eq 20 over the fluid neighbours only); for i in P_ext and
 *   j in P, v_ij is w_s ∇v_p,j r_ij + (1 − w_s) v_ij with ∇v_p,j r_ij = (∂U/∂n)_j t_j (n_j·r_ij)
 *   (eq 40: the wall function's gradient of j; eq 38 writes ∇v_p as (∂U/∂n) t⊗t, which gives
 *   eq 13's G under τ:∇v but no velocity difference across the layer: the gradient is t ⊗ n);
 *   G = ν_t (2 S:S − ⅔ (∇·v)²) (eq 9 with the deviatoric Reynolds stress, ≥ 0), and in P the
 *   wall model's G = τ_w ∂U/∂n (eq 13);
 *   diffusion of φ = k, ε (eqs 23-24), over the fluid neighbours only (no flux into the wall:
 *   sec 4.3, third type): 2 Σ_j D̃_ij (φ_i − φ_j) F_ij V_j / λ, D = ν + ν_t/σ, D̃ the pair's
 *   mean (wcr_pair_mean, config.cl: harmonic; turbulent_diffusion below), F = W'/r, λ the lattice's
 * Laplacian sum (as the viscous term's, advection.cl); the linearised update (eq 30 and its ε form,
 * eqs 28-29): k' = (k + Δt (G + D_k)) / (1 + Δt ε/k),  ε' = (ε + Δt (C1 ε/k G + D_ε)) / (1 + Δt C2
 * ε/k), and in P, ε' = C_μ^¾ k'^{3/2}/(κ y_p) (eq 14). A numerator that diffusion makes negative is
 *   clipped to a millionth of the old value and counted (clips[0] for k, clips[1] for ε).
 * C_μ 0.09, C1 1.44, C2 1.92, σ_k 1, σ_ε 1.3. It stores ∇v (grad: ∂u/∂x, ∂u/∂y, ∂v/∂x, ∂v/∂y),
 * which the acoustic sub-steps' reconstructed dissipation reads (acoustic.cl, WCR_MOM_DISS = 2).
 *
 * velocity_gradient = "log" (WCR_GRAD_LOG, an option; the paper's is "kernel"): next to a wall
 * the pair's separation along the wall's normal n, n·r_ij = y_i − y_j (y the distance from the
 * physical wall: the boundary offset's log-law origin), is replaced in B^in's moment sum by the log
 * law's coordinate, y_i ln(y_i/y_j), so that the corrected gradient is exact for u = a ln y + b,
 * where the sums over the rows of a lattice read a log profile's ∂u/∂y high (the support, cut by
 * the wall, reaches the first row's much lower speed): laid on the 1-D solver's profile the
 * second to fourth rows' production comes 41%, 25% and 11% over the model's at 20 rows across
 * the channel, 1.25 times it over the half channel (1.08 at 40); in the log coordinate 1.006
 * (1.007: tests/validation/channel_ke_gradient_bias.py --log-rows 4). Eq 40's compensation, the
 * wall function's gradient on the pairs with the first row, is then left out (the log coordinate
 * is what it approximates). wcr_log_frame gives each particle with a dummy within its support the
 * wall's normal (kernel-weighted, as eq 35's) and its y from the nearest dummy's height (less
 * dr/2, plus the offset y_p − dr/2); one with none takes them from its nearest fluid neighbour
 * that has them (y_i = y_j + n·r_ij): the second to fourth rows of a lattice.
 *
 * turbulent_diffusion = "log_mirror" (WCR_KE_DIFF, an option; the paper's is "harmonic"): next to
 * a wall the diffusion sums carry less than the 1-D solver's fluxes between the same rows, for
 * two reasons: across the first two rows ν_t grows nearly in proportion to the distance (by 1.59
 * and 1.99 times from the first row to the second at 40 and 20 rows across the channel, in the 1-D
 * solver on those rows), where the harmonic mean of D stands 3.0% and 6.6% under the two points'
 * exact conductance for a D linear in the distance, the logarithmic mean; and the support cut by
 * the wall drops the pairs across it, those of the first row with the second at two spacings'
 * reach (7% of the first face's conductance at h = 1.3 dr). From the N_f = 40 channel's snapshots
 * (tests/validation/channel_ke_diffusion.py) the first row's exchange with the rows above came 11%
 * under the 1-D solver's fluxes on the rows' mean k and ε, the second row's ε intake 23% under:
 * the second row's ε stood 2.6% low, its ν_t 3.6% high, and the first row ran 1.3% fast under the
 * wall model's friction (u_τ +1.3% of the 1-D solver's at 40 rows with velocity_gradient = "log").
 * With "log_mirror" each pair takes the logarithmic mean of D (wcr_diff_mean), and a pair of P_ext
 * particles with wall frames adds the pair of i with j's mirror image behind the boundary (the
 * normal separation d_i + d_j along i's normal, r_ij's tangential part): the even extension that
 * keeps sec 4.3's zero flux through the wall (symmetric in i and j on a flat wall, so that the
 * sums still only move k and ε between particles); the first row's exchange then meets the 1-D
 * solver's flux on the run's rows (1.00 of it; started from the 1-D solver's own solution 0.932
 * and 0.945 of it at 20 and 40 rows, the harmonic sums 0.835 and 0.880: k_row1_diffusion of
 * cases/channel_ke.lua, the rest the profile's curvature across the pairs at two spacings). The
 * viscous sums keep the paper's harmonic µ̃_ij (the logarithmic mean there moved u_τ from the
 * drive by +0.2% at 40 rows and +0.8% at 20, single runs).
 *
 * wcr_turb_update: k, ε take the new values and ν_t = C_μ k²/ε (eq 6), or ν_t = nu_fixed while
 * the model waits (sec 5.2's delayed activation: k and ε then stay as they are). */
#if WCR_TURB
/* the model's constants and its update: common/kepsilon.cl */
#define KE_E    R(9.793)
#define KE_YLAM R(11.225)

__kernel void wcr_turb_wall(const uint n, const struct grid g, __global const realv *pos,
                            __global const realv *vel, __global const uint *kind,
                            __global const real *wall_dist, __global const realv *wall_normal,
                            __global const uint *nlist, __global const uint *ncount,
                            __global const real *k, const real y_p, const real nu, const real r_ext,
                            const real shift, __global real4 *frame, __global real2 *wall,
                            __global real *yplus)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  frame[i] = (real4)(R(0.0));
  wall[i] = (real2)(R(0.0));
  yplus[i] = R(0.0);
  const real d = wall_dist[i];
  if (kind[i] != WCR_FLUID || d < R(0.0) || d >= r_ext) return;
  const realv x = pos[i];
  realv nsum = (realv)(R(0.0)), vw = (realv)(R(0.0));
  real wsum = R(0.0);
#if WCR_SHEAR_DIST
  real rmin = INFINITY, dn = R(0.0); /* the nearest dummy: i's height over its layer */
#endif
  const uint c = ncount[i];
  __global const uint *row = nlist + (size_t)i * WCR_MAXN;
  for (uint m = 0; m < c; ++m) {
    const uint j = row[m];
    if (kind[j] != WCR_DUMMY) continue;
    const realv r = wcr_sep(x, pos[j], &g);
    const real w = smoothing_w(g.sm, sqrt(dot(r, r)));
    nsum += w * wall_normal[j];
    vw += w * vel[j];
    wsum += w;
#if WCR_SHEAR_DIST
    const real r2 = dot(r, r);
    if (r2 < rmin) {
      rmin = r2;
      dn = dot(r, wall_normal[j]);
    }
#endif
  }
  if (!(wsum > R(0.0)) || !(dot(nsum, nsum) > R(0.0))) return;
  const realv np = nsum * rsqrt(dot(nsum, nsum)); /* eq 35's n_p, made a unit vector */
  const realv v = vel[i] - vw / wsum;
  const realv vt = v - dot(v, np) * np;
  const real up = sqrt(dot(vt, vt));
  const realv tp = vt / (up + R(1e-12));                         /* eq 36 */
  const real us = sqrt(sqrt(KE_CMU)) * sqrt(fmax(k[i], R(0.0))); /* C_μ^¼ k^½ */
  const real yp = y_p * us / nu;                                 /* eq 10 */
  const int lam = yp < KE_YLAM;
  const real uplus = lam ? yp : log(KE_E * yp) / KE_KAPPA;    /* eq 11 */
  const real tau = uplus > R(0.0) ? up * us / uplus : R(0.0); /* eq 12, over ρ */
  const real dudn = lam ? tau / nu : tau / (us * KE_KAPPA * y_p);
#if WCR_SHEAR_DIST
  /* wall_shear = "distance": the shear from the log law at i's own distance from the wall, its
   * height over the nearest dummy's layer (dr/2 behind the boundary) less dr/2, plus the
   * boundary offset y_p − dr/2 (shift = y_p − dr) */
  (void)d;
  const real yi = fmax(dn + shift, R(0.5) * y_p);
  const real ypi = yi * us / nu;
  const real upi = ypi < KE_YLAM ? ypi : log(KE_E * ypi) / KE_KAPPA;
  const real tw = upi > R(0.0) ? up * us / upi : R(0.0);
#else
  (void)shift;
  const real tw = tau;
#endif
  frame[i] = (real4)(tp.x, tp.y, np.x, np.y);
  wall[i] = (real2)(tw, dudn);
  yplus[i] = yp;
}

#if WCR_SHEAR_ROW1
/* wall_shear = "first_row": D_b = Σ_j V_j W_jb over the first row (0 ≤ d_j < dr: the fluid and the
 * open boundaries' layers, which hold their share of the wall where they run along it) for each
 * dummy b of the first layer (depth < dr); 0 for every other particle */
__kernel void wcr_row1_density(const uint n, const struct grid g, __global const uint *cell_start,
                               __global const realv *pos, __global const real *vol,
                               __global const uint *kind, __global const real *wall_dist,
                               const real dr, __global real *row1)
{
  const uint b = get_global_id(0);
  if (b >= n) return;
  real s = R(0.0);
  if (kind[b] == WCR_DUMMY && wall_dist[b] < dr) {
    const realv x = pos[b];
    struct neigh_iter it;
    NEIGH_FOR(it, g, cell_start, x, j) {
      const uint kj = kind[j];
      if (kj != WCR_FLUID && kj != WCR_INFLOW && kj != WCR_OUTFLOW) continue;
      if (!(wall_dist[j] >= R(0.0) && wall_dist[j] < dr)) continue;
      const realv r = x - (pos[j] + it.shift);
      const real r2 = dot(r, r);
      if (r2 < g.sm.support2) s += vol[j] * smoothing_w(g.sm, sqrt(r2));
    }
  }
  row1[b] = s;
}
#endif

#if WCR_SHEAR_DIST
/* wall_shear = "distance": what eq 39 makes of a wall shear stress τ_w on a flat wall of the
 * dummy lattice, per unit area over τ_w: 2 dr^(DIM+1)
 * Σ_i Σ_b (−F(r_ib)) (r_ib·n) over the rows i of a column at (m + ½) dr from the boundary within R
 * = 2h − dr (the wall model's P_ext) and the dummy lattice b at −(j + ½) dr (the continuum's value
 * is 1; one work-item). */
__kernel void wcr_wall_shear_sum(const struct smooth sm, const real dr, const real r_ext,
                                 __global real *out)
{
  if (get_global_id(0) != 0) return;
  const int m = (int)ceil(sm.support / dr) + 1;
  const int mz = DIM == 3 ? m : 0;
  real s = R(0.0);
  for (int row = 0; ((real)row + R(0.5)) * dr < r_ext; ++row)
    for (int j = 0; j <= m; ++j)
      for (int c = -mz; c <= mz; ++c)
        for (int a = -m; a <= m; ++a) {
          const real rn = (real)(row + j + 1) * dr;
          const real r = sqrt(rn * rn + (real)(a * a + c * c) * dr * dr);
          if (r >= sm.support) continue;
          s -= smoothing_f(sm, r) * rn;
        }
  out[0] = R(2.0) * s * (DIM == 3 ? dr * dr * dr * dr : dr * dr * dr);
}
#endif

#if WCR_GRAD_LOG
/* velocity_gradient = "log": the wall's normal n and i's distance y from the physical wall, from
 * the dummies within its support; (0, 0, 0, 0) where none is */
__kernel void wcr_log_frame(const uint n, const struct grid g, __global const realv *pos,
                            __global const uint *kind, __global const realv *wall_normal,
                            __global const uint *nlist, __global const uint *ncount,
                            const real shift, const real y_min, __global real4 *logf)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  logf[i] = (real4)(R(0.0));
  if (kind[i] != WCR_FLUID) return;
  const realv x = pos[i];
  realv ns = (realv)(R(0.0));
  real rmin = INFINITY, dn = R(0.0);
  const uint c = ncount[i];
  __global const uint *row = nlist + (size_t)i * WCR_MAXN;
  for (uint m = 0; m < c; ++m) {
    const uint j = row[m];
    if (kind[j] != WCR_DUMMY) continue;
    const realv r = wcr_sep(x, pos[j], &g);
    const real r2 = dot(r, r);
    if (r2 >= g.sm.support2) continue;
    ns += smoothing_w(g.sm, sqrt(r2)) * wall_normal[j];
    if (r2 < rmin) {
      rmin = r2;
      dn = dot(r, wall_normal[j]);
    }
  }
  if (!(dot(ns, ns) > R(0.0))) return;
  const realv nw = ns * rsqrt(dot(ns, ns));
  logf[i] = (real4)(nw.x, nw.y, fmax(dn + shift, y_min), R(1.0));
}

/* r_ij with its part along n replaced by the log law's coordinate y_i ln(y_i/y_j), y_j = y_i −
 * n·r_ij (at least y_min) */
realv wcr_log_sep(realv r, realv nw, real yi, real y_min)
{
  const real rn = dot(r, nw);
  const real yj = fmax(yi - rn, y_min);
  return r + (yi * log(yi / yj) - rn) * nw;
}
#endif

/* D̃_ij of eqs 23-24: the harmonic mean (wcr_pair_mean), or with turbulent_diffusion =
 * "log_mirror" the logarithmic mean (a − b)/ln(a/b) = m x/atanh x, m = (a + b)/2, x = (a − b)/(a +
 * b): the two points' exact conductance for a D linear in the distance, as ν_t = κ u_τ y is in the
 * log layer. Where |x| < 0.05 (most pairs away from the walls) its series m (1 − x²/3 − 4x⁴/45),
 * within 1e-9 of it, spares the atanh */
real wcr_diff_mean(real a, real b)
{
#if WCR_KE_DIFF
  const real m = R(0.5) * (a + b), x = (a - b) / (a + b), x2 = x * x;
  return x2 < R(0.0025) ? m * (R(1.0) - x2 * (R(1.0) / R(3.0) + x2 * (R(4.0) / R(45.0))))
                        : m * x / atanh(x);
#else
  return wcr_pair_mean(a, b);
#endif
}

__kernel void wcr_turb_transport(
    const uint n, const struct grid g, __global const realv *pos, __global const realv *vel,
    __global const real *vol, __global const uint *kind, __global const real *wall_dist,
    __global const uint *nlist, __global const uint *ncount, __global const real *k,
    __global const real *eps, __global const real *nu_t, __global const real4 *frame,
    __global const real2 *wall, const real dt, const real nu, const real inv_lambda, const real y_p,
    const real r_ext, const real r_p, const real w_s, __global real *k_new, __global real *eps_new,
    __global uint *clips, __global real4 *grad, __global const real4 *logf)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const real ki = k[i], ei = eps[i];
  k_new[i] = ki;
  eps_new[i] = ei;
  grad[i] = (real4)(R(0.0));
  if (kind[i] != WCR_FLUID) return;
  const realv x = pos[i], vi = vel[i];
  const real di = wall_dist[i], nti = nu_t[i];
  const int in_ext = di >= R(0.0) && di < r_ext;
  const real4 fi = frame[i];
  const int in_p = di >= R(0.0) && di < r_p && (fi.z != R(0.0) || fi.w != R(0.0));
  const uint c = ncount[i];
  __global const uint *row = nlist + (size_t)i * WCR_MAXN;
#if WCR_GRAD_LOG
  /* the wall's frame: i's own, or its nearest fluid neighbour's carried over to i */
  real4 lf = logf[i];
  if (lf.w == R(0.0)) {
    real best = INFINITY;
    for (uint m = 0; m < c; ++m) {
      const uint j = row[m];
      if (kind[j] != WCR_FLUID || logf[j].w == R(0.0)) continue;
      const realv r = wcr_sep(x, pos[j], &g);
      const real r2 = dot(r, r);
      if (r2 >= g.sm.support2 || r2 >= best) continue;
      best = r2;
      const real4 q = logf[j];
      lf = (real4)(q.x, q.y, q.z + dot((realv)(q.x, q.y), r), R(1.0));
    }
  }
  int logmap = lf.w != R(0.0) && lf.z > R(0.0);
  const realv nl = (realv)(lf.x, lf.y);
  const real yl = lf.z, ymin = R(0.5) * y_p;
  real4 am = (real4)(R(0.0)); /* Σ −F V r ⊗ s, s the mapped separation: (xx, xy, yx, yy) */
#else
  (void)logf;
  const int logmap = 0;
#endif
  /* B^in: eq 20 over the fluid (and layer) neighbours */
  wcr_mat a = WCR_MAT_ZERO;
  for (uint m = 0; m < c; ++m) {
    const uint j = row[m];
    if (kind[j] == WCR_DUMMY) continue;
    const realv r = wcr_sep(x, pos[j], &g);
    const real f = smoothing_f(g.sm, sqrt(dot(r, r))) * vol[j];
    a = wcr_moment(a, f, r);
#if WCR_GRAD_LOG
    if (logmap) {
      const realv sm = wcr_log_sep(r, nl, yl, ymin);
      am -= f * (real4)(r.x * sm.x, r.x * sm.y, r.y * sm.x, r.y * sm.y);
    }
#endif
  }
  wcr_mat b = wcr_correction(a);
#if WCR_GRAD_LOG
  if (logmap) { /* B = (Σ −F V r ⊗ s)^−1, so that Σ v_ij ⊗ B ∇W_ij V_j is exact for v_ij = G s_ij */
    const real det = am.x * am.w - am.y * am.z;
    if (det > WCR_B_DET)
      b = (real4)(am.w, -am.y, -am.z, am.x) / det;
    else
      logmap = 0; /* too few neighbours to map: eqs 22 and 40 */
  }
#endif
  /* ∇v (eqs 22, 40) and the diffusion sums (eqs 23-24) */
  real gxx = R(0.0), gxy = R(0.0), gyx = R(0.0), gyy = R(0.0), dk = R(0.0), de = R(0.0);
  const real dki = nu + nti / KE_SK, dei = nu + nti / KE_SE;
  for (uint m = 0; m < c; ++m) {
    const uint j = row[m];
    const uint kj = kind[j];
    if (kj == WCR_DUMMY) continue;
    const realv r = wcr_sep(x, pos[j], &g);
    const real f = smoothing_f(g.sm, sqrt(dot(r, r))) * vol[j];
    realv vij = vi - vel[j];
    const real dj = wall_dist[j];
    const real4 fr = frame[j];
    if (!logmap && in_ext && kj == WCR_FLUID && dj >= R(0.0) && dj < r_p &&
        (fr.z != R(0.0) || fr.w != R(0.0))) {
      const realv tj = (realv)(fr.x, fr.y), nj = (realv)(fr.z, fr.w);
      vij = w_s * wall[j].y * dot(nj, r) * tj + (R(1.0) - w_s) * vij;
    }
    const realv gw = f * wcr_apply(b, r); /* B^in ∇W_ij V_j */
    gxx += vij.x * gw.x;
    gxy += vij.x * gw.y;
    gyx += vij.y * gw.x;
    gyy += vij.y * gw.y;
    const real ntj = nu_t[j];
    const real dkj = nu + ntj / KE_SK, dej = nu + ntj / KE_SE;
    const real mk = wcr_diff_mean(dki, dkj), me = wcr_diff_mean(dei, dej);
    real fd = f;
#if WCR_KE_DIFF
    /* the wall's mirror: the pair of i with j's image behind the boundary, at the separation
     * d_i + d_j (wall_dist: the heights over the boundary) along i's wall normal (both in P_ext,
     * with a wall frame) */
    if (in_ext && kj == WCR_FLUID && dj >= R(0.0) && dj < r_ext &&
        (fi.z != R(0.0) || fi.w != R(0.0)) && (fr.z != R(0.0) || fr.w != R(0.0))) {
      const realv ni = (realv)(fi.z, fi.w);
      const realv rt = r - dot(r, ni) * ni;
      const real sn = di + dj;
      const real r2m = dot(rt, rt) + sn * sn;
      if (r2m < g.sm.support2) fd += smoothing_f(g.sm, sqrt(r2m)) * vol[j];
    }
#endif
    dk += R(2.0) * mk * (ki - k[j]) * fd;
    de += R(2.0) * me * (ei - eps[j]) * fd;
  }
  /* ∇_i W_ij = F r_ij with r_ij = x_i − x_j, so Σ v_ij ⊗ ∇W V is −∇v: flip */
  gxx = -gxx;
  gxy = -gxy;
  gyx = -gyx;
  gyy = -gyy;
  grad[i] = (real4)(gxx, gxy, gyx, gyy); /* for the momentum dissipation (acoustic.cl) */
  dk *= inv_lambda;
  de *= inv_lambda;
  real prod;
  if (in_p) {
    prod = wall[i].x * wall[i].y; /* eq 13 */
  } else {
    const real sxy = R(0.5) * (gxy + gyx), div = gxx + gyy;
    prod =
        nti * (R(2.0) * (gxx * gxx + gyy * gyy + R(2.0) * sxy * sxy) - div * div * R(2.0) / R(3.0));
    prod = fmax(prod, R(0.0));
  }
  const real kn = ke_advance_k(ki, ei, prod, dk, dt, clips); /* eq 30 */
  const real en =
      in_p ? sqrt(KE_CMU) * sqrt(sqrt(KE_CMU)) * kn * sqrt(kn) / (KE_KAPPA * y_p) /* 14 */
           : ke_advance_eps(ki, ei, prod, de, dt, clips);                         /* eqs 29-30 */
  k_new[i] = kn;
  eps_new[i] = en;
}

__kernel void wcr_turb_update(const uint n, __global const uint *kind, __global const real *k_new,
                              __global const real *eps_new, const uint active, const real nu_fixed,
                              __global real *k, __global real *eps, __global real *nu_t,
                              __global realv *nu_t2)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  real nt = nu_t[i];
  if (kind[i] == WCR_FLUID) {
    if (active) {
      k[i] = k_new[i];
      eps[i] = eps_new[i];
      nt = ke_nu_t(k_new[i], eps_new[i]); /* eq 6 */
    } else {
      nt = nu_fixed;
    }
    nu_t[i] = nt;
  }
  nu_t2[i] = (realv)(nt, R(0.0)); /* for the host's largest ν_t (the time step, eq 27) */
}
#endif
