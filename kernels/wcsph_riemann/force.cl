/* force.cl (wcsph-riemann): the force of the fluid on a group of dummy-particle walls, the sum of
 * the reactions of the pair forces the walls exert on the fluid, so that what the fluid loses the
 * walls gain:
 *   pressure: Σ_i V_i Σ_w V_w [(p_i B_w + p_w B_i) + ρ0 β U I] ∇W_iw   (eq 19 with the wall state;
 *             p + p_bg as the momentum sum has it, acoustic.cl)
 *   viscous:  −Σ_i V_i Σ_w 2 µ V_w F (v_i − v_w)  (eq 21 with Morris's wall velocity,
 *             advection.cl; with ARD the Riemann viscosity's excess max(µ_R − µ, 0) with the
 *             mirror velocity, eqs 31-32)
 * over the fluid particles i and the dummy particles w of the group (mask[wall[w]] != 0).
 * A step records them where the fluid feels them (-D WCR_REC = the scene's force groups): the
 * advection step writes each fluid particle's viscous reactions per group (wcr_advection) and
 * each acoustic sub-step adds its pressure and Riemann ones over their number (wcr_momentum), so
 * that the record is the step's mean force and M ΔU = Δt (M f − F) holds to round-off
 * (tests/case/wall_momentum.lua). This kernel evaluates the same pairs once on the present state:
 * the output before the first step only. Used after every step, it missed
 * what the sub-steps did between: in the k-ε channel (cases/channel_ke.lua, N_f = 20, a fixed
 * body force, TVF off) the sub-steps' wall pairs pushed a disordered first row forward by 49% of
 * the body force while the end of the step read a drag of 12%. Each fluid particle writes its
 * share (pressure x, y, viscous x, y); the host sums them in double. */
__kernel void wcr_wall_force(
    const uint n, const struct grid g, __global const realv *pos, __global const realv *vel,
    __global const real *vol, __global const uint *kind, __global const real *rho,
    __global const real *wall_dist, __global const realv *wall_normal, __global const real *p,
    __global const uint *nlist, __global const uint *ncount, __global const wcr_mat *bmat,
    __global const realv *acc_prior, __global const uint *wall, __global const uint *mask,
    const uint nmask, const real dr, const real rho0, const real c0, const real p_bg, const real mu,
    const real inv_lambda, const real h, __global real4 *out, __global const real *tk,
    __global const real *nu_t, __global const real4 *frame, __global const real2 *wallv,
    const real r_ext, const uint wall_model, const realv gravity, __global const realv *gradp,
    const real wscale, __global const real *row1)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
#if !WCR_WALL_PGRAD
  (void)gradp;
#endif
  real4 o = (real4)(R(0.0));
  if (kind[i] != WCR_FLUID) {
    out[i] = o;
    return;
  }
  const realv x = pos[i], vi = vel[i], ai = acc_prior[i];
#if WCR_TURB
  /* the k-ε model: p + ⅔ ρ k, µ + ρ0 ν_t, the normal mirror, and on a P_ext particle the wall
   * model's shear (eq 39) instead of the no-slip drag, as acoustic.cl and advection.cl have them */
  const real pi = p[i] + R(2.0) / R(3.0) * rho[i] * tk[i], ri = rho[i], vol_i = vol[i];
  const real mui = mu + rho0 * nu_t[i], di = wall_dist[i];
#if WCR_SHEAR_ROW1
  /* "first_row": no particle that sees a dummy takes its no-slip drag, the P_ext rows and those
   * beyond R = 2h − dr that the dummies still reach (d < 2h − dr/2: off the lattice's rows, a
   * disordered second row's) alike: the wall's stress is the first row's τ_w alone */
  const int modelled = wall_model && di >= R(0.0);
  (void)r_ext;
#else
  const int modelled = wall_model && di >= R(0.0) && di < r_ext;
#endif
  const real4 fr = frame[i];
  const realv tt = (realv)(fr.x, fr.y), nn = (realv)(fr.z, fr.w);
#if WCR_SHEAR_ROW1
  /* wall_shear = "first_row": τ_w over the first row's shares of the wall (advection.cl) */
  const real tau = di < dr ? wallv[i].x : R(0.0);
  real share = R(0.0);
  (void)wscale;
#else
  const real tau = wscale * wallv[i].x; /* eq 39's (wcr_wall_shear_sum) */
  (void)row1;
#endif
#else
  (void)tk;
  (void)nu_t;
  (void)frame;
  (void)wallv;
  (void)wscale;
  (void)row1;
  (void)r_ext;
  (void)wall_model;
  const real pi = p[i], ri = rho[i], vol_i = vol[i];
  const real mui = mu;
#endif
  const wcr_mat bi = bmat[i];
  realv fp = (realv)(R(0.0)), fv = (realv)(R(0.0));
  const uint c = ncount[i];
  __global const uint *row = nlist + (size_t)i * WCR_MAXN;
  for (uint k = 0; k < c; ++k) {
    const uint j = row[k];
    const uint kj = kind[j];
    if (kj != WCR_DUMMY || wall[j] >= nmask || mask[wall[j]] == 0u) continue;
    const realv r = wcr_sep(x, pos[j], &g);
    const real rr = sqrt(dot(r, r));
    const real f = smoothing_f(g.sm, rr) * vol[j];
#if WCR_TURB
    const realv nw = wall_normal[j];
    const realv vij = R(2.0) * dot(vi - vel[j], nw) * nw;
#else
    const realv vij = R(2.0) * (vi - vel[j]);
#endif
#if WCR_WALL_PGRAD
    const real pj = wcr_wall_pressure_grad(pi, ri, ai, r, wall_normal[j], gradp[i]);
#else
    const real pj = wcr_wall_pressure(pi, ri, ai, r, wall_normal[j], gravity);
#endif
    const real u = rr > R(0.0) ? -dot(vij, r) / rr : R(0.0);
    const real beta = wcr_beta(u, c0, 1u);
#if WCR_TURB && WCR_WALL_PNORMAL /* wall_pressure_force = "normal" (config.cl) */
#if WCR_WALL_PGRAD
    fp += wcr_wall_push(f, pi + pj + R(2.0) * p_bg, bi, r, wall_normal[j], gradp[i]);
#else
    fp += wcr_wall_push(f, pi + pj + R(2.0) * p_bg, bi, r, wall_normal[j], ri * gravity);
#endif
#else
    fp += f * (pi + pj + R(2.0) * p_bg) * wcr_apply(bi, r);
#endif
#if WCR_ARD
    fv -= R(2.0) * fmax(R(0.5) * rho0 * beta * h - mui, R(0.0)) * f * vij;
#else
    fp += f * (rho0 * beta * u) * r;
#endif
#if WCR_TURB
    if (modelled) { /* the reaction of eq 39's pair term */
#if WCR_SHEAR_ROW1
      if (tau != R(0.0) && wall_dist[j] < dr && row1[j] > R(0.0))
        share += vol[j] * smoothing_w(g.sm, rr) / row1[j];
#else
      const realv s = f * r;
      fv -= R(2.0) * ri * tau * (dot(nn, s) * tt + dot(tt, s) * nn);
#endif
      continue;
    }
#endif
    fv -= R(2.0) * mui * inv_lambda * f *
          wcr_visc_jump(kj, x, x - r, vi, vel[j], wall_dist[j], wall_normal[j], dr);
  }
#if WCR_TURB && WCR_SHEAR_ROW1
  fv += (rho0 * tau * share * WCR_FACE(dr) / vol_i) * tt; /* ρ0 τ_w A_i on the wall, along t */
#endif
  o = (real4)(vol_i * fp.x, vol_i * fp.y, vol_i * fv.x, vol_i * fv.y);
  out[i] = o;
}
