/* advection.cl (wcsph-riemann): what an advection step computes once for its acoustic sub-steps
 * (Wang, Sun & Hu sec 2.5): the viscous acceleration with the body forces, the transport-velocity
 * position correction, and the ARD indicator.
 *
 * Viscous acceleration (eq 21, the pairwise form of Hu & Adams 2006), written with V_j = m_j/ρ_j:
 *   a_i^ν = (2/ρ_i) Σ_j µ̃_ij V_j F(r_ij) (v_i − v_j),   F = W'/r,
 * and evaluated as (2 V_i/m) Σ_j µ̃_ij V_j F (v_i − v_j), V = m/ρ of the last drift on both sides
 * (acoustic.cl): the summation's re-set of ρ at the step's start (config.cl) leaves V to the
 * drift, and 1/ρ_i of the re-set against V_j of the drift made the pairs' forces unequal: a
 * periodic channel (tests/case/wall_momentum.lua) gained 3.8e-4 of its body force's momentum a
 * step from its own viscous pairs. With V_i/m for 1/ρ_i they cancel (and m/ρ_j of the re-set for
 * V_j instead, equally conservative, let the fitted rows of the HCD channel close to 0.55 dr
 * where they stay at 0.71: cases/channel_hcd.lua, fitted = 1, t = 0.3).
 * µ̃_ij the pair's mean of the two viscosities (one viscosity here, µ, unless the k-ε model adds
 * ν_t: wcr_pair_mean, config.cl), divided by lambda, the
 * sum's value for ∇²(x²/2) = 1 on the particles' lattice (config.cl): 0.974 at h = 1.3 dr with
 * the Wendland C2, and 1 only as h/dr → ∞, so that the steady body-force Poiseuille flow ran
 * 2.5% fast on its centreline at every resolution (cases/poiseuille_periodic.lua, dr = H/20 and
 * H/40; 0.2% with the division). No slip on a dummy wall
 * particle w (Morris, Fox & Zhu 1997): its velocity extrapolates the fluid's linearly through the
 * wall's velocity u_w (which moves a sliding or rotating wall) at the wall,
 *   v_i − v_w = β (v_i − u_w),  β = 1 + d_w / max(d_i, dr/2),
 * d_w the dummy's depth behind the wall and d_i = (x_i − x_w)·n_w − d_w the fluid particle's
 * distance from the wall along the dummy's normal n_w. Morris et al. bound β by 1.5 instead, for
 * particles that come close to the wall; on dummies in layers (depths dr/2, 3dr/2, 5dr/2) that
 * cuts the first row's β of 2, 4, 6 to 1.5 and the wall drags too little: the body-force
 * Poiseuille flow (cases/poiseuille_periodic.lua) ran 8.6% fast on its centreline at dr = H/10,
 * 4.3% at H/40. The mirror 2 u_w − v_i of the Riemann
 * sums (acoustic.cl), β = 2, puts the wall half-way between i and w, which is right only for the
 * first row: it dragged the lid-driven cavity's centreline by 2.5% of U at 30² (u RMS against
 * Ghia 0.025 U; 0.0XX with Morris's extrapolation).
 *
 * Transport-velocity correction (sec 2.4 and 3.2, eqs 25-26 and 33-34), once per advection step:
 *   R_i = Σ_j (B_i + B_j) ∇W_ij V_j   (eq 26; B_j = B_i for a dummy particle),
 *   Δr_i = −α h² β R_i,  β = min(m h² |R_i|², 1) (LTVF, eq 33; β = 1: the original TVF, eq 25),
 * α = 0.2, m = 1000. R points from i towards the side where its neighbours crowd (∇_i W_ij
 * points from i to j), so the correction moves i the other way, down the gradient of the number
 * density, as the background pressure of Adami et al.'s transport velocity does: eq 25 prints
 * +α h² R with the residue taken the other way round. In free-surface flows the correction is
 * applied only where the kernel sum is complete (sigma >= bulk, config.cl): at the surface R
 * measures the missing air, and the correction would push the surface out: it is applied only
 * where no neighbour (nor i) has a kernel sum below `bulk` (0.8 of a full support's; 0.5 to 0.6
 * on the surface, 0.9 one row below), so the rows within a support of the surface keep their
 * positions (as SPHinXsys keeps its corrections to the particles away from the surface). With a
 * bound on i's own sum only (0.95) the rows under the surface were pushed up into the air at
 * every step: a tank at rest (cases/hydrostatic.lua, dr = H/20) rose 4% in 2 s.
 *
 * ARD indicator (eq 42): the number of neighbours j for which the Riemann dissipation's viscosity
 * µ_R = ½ ρ0 β_ij h (eq 31) exceeds the physical one, µ_R > µ̃_ij, at the advection step's
 * velocities; β_ij = min(η max(U_ij, 0), c0) as in acoustic.cl. Eq 42 writes ρ β h, twice eq 31's
 * µ_R; we count where eq 32 switches, which is what the indicator is said to show. */

/* v_i − v_j for the viscous sum: j's velocity, or a dummy's by Morris's extrapolation (depth d_w,
 * normal n_w, wall velocity u_w = vel[j]) */
realv wcr_visc_jump(uint kj, realv xi, realv xj, realv vi, realv vj, real dw, realv nw, real dr)
{
  if (kj != WCR_DUMMY) return vi - vj;
  const real di = fmax(dot(xi - xj, nw) - dw, R(0.5) * dr);
  return (R(1.0) + dw / di) * (vi - vj);
}

__kernel void
wcr_advection(const uint n, const struct grid g, __global const realv *pos,
              __global const realv *vel, __global const real *vol, __global const uint *kind,
              __global const real *rho, __global const real *wall_dist,
              __global const realv *wall_normal, __global const uint *nlist,
              __global const uint *ncount, __global const wcr_mat *bmat, __global const real *sigma,
              const real dr, const real mu, const real inv_lambda, const realv accel,
              const real tvf_a, const real tvf_m, const real bulk, const real rho0, const real c0,
              const real h, __global realv *acc_prior, __global realv *shift, __global real *ard,
              __global const real *nu_t, __global const real4 *frame, __global const real2 *wallv,
              const real r_ext, const uint wall_model, const real wscale, __global const uint *wall,
              __global real4 *rec, __global const uint *wgroup, const uint nwall, const real mass,
              const real layer, __global const real *row1)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
#if WCR_REC
  /* the record of the walls' force over this step (force.cl): the viscous reactions here, the
   * pressure and Riemann ones of the sub-steps added by wcr_momentum */
  real4 wv[WCR_REC];
  for (uint q = 0; q < WCR_REC; ++q) wv[q] = (real4)(R(0.0));
  if (kind[i] != WCR_FLUID) {
    for (uint q = 0; q < WCR_REC; ++q) rec[(size_t)i * WCR_REC + q] = wv[q];
    return;
  }
#else
  (void)wall;
  (void)rec;
  (void)wgroup;
  (void)nwall;
  if (kind[i] != WCR_FLUID) return;
#endif
  const realv x = pos[i], vi = vel[i];
  const wcr_mat bi = bmat[i];
  realv visc = (realv)(R(0.0)), res = (realv)(R(0.0));
#if WCR_TVF_SURFACE == 1
  realv gsig = (realv)(R(0.0)); /* ∇σ_i = Σ_j (σ_j − σ_i) ∇W_ij V_j over the fluid */
  const real si = sigma[i];
#elif WCR_TVF_SURFACE == 2
  realv near = (realv)(R(0.0)); /* Σ_j (1 − r/dr)² r̂_ij over the fluid closer than dr */
  const real si = sigma[i];
#endif
  real count = R(0.0), smin = sigma[i];
  const uint c = ncount[i];
  __global const uint *row = nlist + (size_t)i * WCR_MAXN;
#if WCR_TURB
  /* µ_eff = ρ0 (ν + ν_t) and its pair mean (eq 21); the wall model replaces the
   * dummies' no-slip drag on a P_ext particle by the wall shear stress (eq 39) */
  const real nu_l = mu / rho0, mui = mu + rho0 * nu_t[i];
  const real di = wall_dist[i];
#if WCR_SHEAR_ROW1
  /* "first_row": no particle that sees a dummy takes its no-slip drag, the P_ext rows and those
   * beyond R = 2h − dr that the dummies still reach (d < 2h − dr/2: off the lattice's rows, a
   * disordered second row's) alike: the wall's stress is the first row's τ_w alone */
  const int modelled = wall_model && di >= R(0.0);
  (void)r_ext;
#else
  const int modelled = wall_model && di >= R(0.0) && di < r_ext;
#endif
#if WCR_SHEAR_ROW1
  /* wall_shear = "first_row": on the first row (P) only, τ_w over its share of the wall s_i =
   * Σ_b V_b W_ib / D_b over the first dummy layer (turbulence.cl) */
  const int row1i = modelled && di < dr;
  real share = R(0.0);
#if WCR_REC
  real wsh[WCR_REC];
  for (uint q = 0; q < WCR_REC; ++q) wsh[q] = R(0.0);
#endif
  (void)wscale;
#else
  const real w39 = wscale;
  (void)row1;
#endif
  realv swall = (realv)(R(0.0)); /* Σ_b V_b ∇W_ib over the dummies */
#else
  (void)row1;
#endif
  for (uint k = 0; k < c; ++k) {
    const uint j = row[k];
    const realv r = wcr_sep(x, pos[j], &g);
    const real r2 = dot(r, r);
    const uint kj = kind[j];
    const real f = smoothing_f(g.sm, sqrt(r2)) * vol[j];
    if (kj != WCR_DUMMY) smin = fmin(smin, sigma[j]);
#if WCR_TVF_SURFACE == 1
    if (kj != WCR_DUMMY) gsig += (sigma[j] - si) * f * r;
#elif WCR_TVF_SURFACE == 2
    if (kj != WCR_DUMMY && r2 < dr * dr && r2 > R(0.0)) {
      const real rr = sqrt(r2), q = R(1.0) - rr / dr;
      near += (q * q / rr) * r;
    }
#endif
#if WCR_REC
    const uint q = kj == WCR_DUMMY ? wcr_rec_group(j, wall, wgroup, nwall) : 0u;
#endif
#if WCR_TURB
    const real muj = kj == WCR_DUMMY ? mui : mu + rho0 * nu_t[j];
    const real mij = wcr_pair_mean(mui, muj); /* µ̃_ij of eq 21 */
    if (modelled && kj == WCR_DUMMY) {
#if WCR_SHEAR_ROW1
      if (row1i && wall_dist[j] < dr && row1[j] > R(0.0)) {
        const real sb = vol[j] * smoothing_w(g.sm, sqrt(r2)) / row1[j];
        share += sb;
#if WCR_REC
        if (q) wsh[q - 1] += sb; /* the group's part of the share */
#endif
      }
#else
      swall += f * r;
#if WCR_REC
      if (q) wv[q - 1].xy += f * r; /* Σ_b V_b ∇W_ib of the group, for eq 39 below */
#endif
#endif
    } else {
      const realv dv =
          mij * f * wcr_visc_jump(kj, x, x - r, vi, vel[j], wall_dist[j], wall_normal[j], dr);
      visc += dv;
#if WCR_REC
      if (q) wv[q - 1].zw += dv;
#endif
    }
#else
    const real mij = mu;
    const realv dv = f * wcr_visc_jump(kj, x, x - r, vi, vel[j], wall_dist[j], wall_normal[j], dr);
    visc += dv;
#if WCR_REC
    if (q) wv[q - 1].zw += mu * dv;
#endif
#endif
    const wcr_mat bj = kj == WCR_DUMMY ? bi : bmat[j];
    res += f * wcr_apply(bi + bj, r); /* (B_i + B_j) ∇W V */
#if WCR_ARD
    const realv vij = vi - (kj == WCR_DUMMY ? R(2.0) * vel[j] - vi : vel[j]);
    const real u = -dot(vij, r) * rsqrt(fmax(r2, REAL_EPS * g.sm.support2));
    const real beta = fmin(WCR_ETA * fmax(u, R(0.0)), c0);
    if (R(0.5) * rho0 * beta * h > mij) count += R(1.0);
#else
    (void)mij;
#endif
  }
#if WCR_TURB
  realv a = accel + R(2.0) * inv_lambda * (vol[i] / mass) * visc;
  if (modelled) {
    const real4 fr = frame[i];
    const realv t = (realv)(fr.x, fr.y), nw = (realv)(fr.z, fr.w);
#if WCR_SHEAR_ROW1
    /* "first_row": ρ0 τ_w A_i along −t on the particle, A_i = s_i dr^(DIM−1) its share of the
     * wall's area (on the lattice eq 39's τ_w dr^(DIM−1) per particle) */
    const real area = share * WCR_FACE(dr);
    a -= (rho0 * wallv[i].x * area / mass) * t;
    const real lshare = rho0 * area * dr / mass; /* the layer's mass under A_i over m_i */
    (void)swall;
#else
    /* eq 39: −(2/ρ) Σ_b τ_w V_b ∇W_ib, τ_w = −ρ (τ_w/ρ)(t⊗n + n⊗t) on the fluid */
    a += R(2.0) * w39 * wallv[i].x * (dot(nw, swall) * t + dot(t, swall) * nw);
    const real lshare = R(1.0);
#endif
#if WCR_OFFSET_LAYER
    /* offset_layer = "body_force": the layer between the wall and the offset boundary (sec 4.4)
     * under the first row (P, d < dr), of (y_p − dr/2)/dr = layer times the particle's mass (and
     * its share of the wall with "first_row"), passes its body force along the wall to the
     * particle: the wall's τ_w holds the layer and the fluid above it */
    if (di < dr) a += layer * lshare * (accel - dot(accel, nw) * nw);
#else
    (void)lshare;
#endif
  }
  acc_prior[i] = a;
#if !WCR_OFFSET_LAYER
  (void)layer;
#endif
  (void)nu_l;
#if WCR_REC
  /* the walls take the reactions: −m_i of the acceleration each group's pairs give i */
  for (uint q = 0; q < WCR_REC; ++q) {
    realv fw = -R(2.0) * inv_lambda * vol[i] * wv[q].zw;
    if (modelled) {
      const real4 fr = frame[i];
      const realv t = (realv)(fr.x, fr.y), nw = (realv)(fr.z, fr.w);
#if WCR_SHEAR_ROW1
      fw += (rho0 * wallv[i].x * wsh[q] * WCR_FACE(dr)) * t;
      (void)nw;
#else
      const realv s = wv[q].xy;
      fw -= R(2.0) * mass * w39 * wallv[i].x * (dot(nw, s) * t + dot(t, s) * nw);
#endif
    }
    rec[(size_t)i * WCR_REC + q] = (real4)(R(0.0), R(0.0), fw.x, fw.y);
  }
#endif
#else
  (void)nu_t;
  (void)frame;
  (void)wallv;
  (void)wscale;
  (void)r_ext;
  (void)wall_model;
  (void)layer;
  acc_prior[i] = accel + R(2.0) * mu * inv_lambda * (vol[i] / mass) * visc;
#if WCR_REC
  for (uint q = 0; q < WCR_REC; ++q) {
    const realv fw = -R(2.0) * inv_lambda * vol[i] * wv[q].zw;
    rec[(size_t)i * WCR_REC + q] = (real4)(R(0.0), R(0.0), fw.x, fw.y);
  }
#endif
#endif
  realv d = (realv)(R(0.0));
  if (tvf_a > R(0.0) && smin >= bulk) {
    const real lim = tvf_m > R(0.0) ? fmin(tvf_m * dot(res, res), R(1.0)) : R(1.0);
    d = -tvf_a * lim * res;
  }
#if WCR_TVF_SURFACE == 1
  else if (tvf_a > R(0.0) && si >= WCR_SURF_SIGMA_MIN) {
    /* the surface rows: the correction along the surface only, its normal n = −∇σ/|∇σ|
     * from the kernel sum's gradient in difference form, which a pair drawn together leaves
     * alone (σ_i ≈ σ_j); where |∇σ| h < 0.1 the surface has no direction (a thin sheet's middle) */
    const real g2 = dot(gsig, gsig);
    if (g2 * h * h >= R(0.01)) {
      const realv rt = res - (dot(res, gsig) / g2) * gsig;
      const real lim = tvf_m > R(0.0) ? fmin(tvf_m * dot(rt, rt), R(1.0)) : R(1.0);
      d = -tvf_a * lim * rt;
    }
  }
#elif WCR_TVF_SURFACE == 2
  else if (tvf_a > R(0.0) && si >= WCR_SURF_SIGMA_MIN) {
    /* the surface rows: pairs closer than the lattice spacing pushed apart, each by
     * κ dr (1 − r/dr)² per advection step (κ = WCR_PAIR_KAPPA), which a surface at its spacing
     * or stretched (a tongue's tip) does not feel */
    d = WCR_PAIR_KAPPA * dr * near;
  }
#endif
  shift[i] = d;
#if WCR_ARD
  ard[i] = count;
#else
  (void)ard;
  (void)count;
#endif
}
