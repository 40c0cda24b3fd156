/* acoustic.cl (wcsph-riemann): the acoustic sub-steps of the dual-criteria time stepping (Wang,
 * Sun & Hu sec 2.5; Zhang, Rezavand & Hu 2020): the pressure relaxation and the continuity
 * equation with the linearised Riemann solver between each pair (eqs 15-19, Zhang, Hu & Adams
 * 2017), over the neighbour list of the advection step (config.cl).
 *
 * A sub-step of length δt is position Verlet (kick-drift-kick in ρ and r):
 *   ρ += ½δt dρ/dt, r += ½δt v, p = p(ρ)          (wcr_drift)
 *   dv/dt = a_prior + a^p (eq 19)                 (wcr_momentum, into acc)
 *   dρ/dt from v^{n+1} = v + δt dv/dt (eq 15)     (wcr_continuity, into drho)
 *   v += δt dv/dt, r += ½δt v, ρ += ½δt dρ/dt     (wcr_drift)
 * and the drift that ends a sub-step and the one that starts the next are one launch.
 * Equation of state (eq 3): p = c0² (ρ − ρ0), the gauge pressure every output shows. A background
 * pressure p_bg (scheme option background_pressure, default 0) enters the pressure force only,
 * as p + p_bg: in the particle sums a uniform pressure P leaves P R_i (R_i = Σ_j (B_i + B_j)
 * ∇W_ij V_j, advection.cl), which pushes particles out of crowded spots where P > 0 and draws
 * them in where P < 0 (the tensile instability). A p_bg that keeps P > 0 stabilises, at the
 * price of force noise where p_bg is large against the flow's pressures: the characteristic
 * exit's start-up pull (solvers/wcsph_riemann, open_exits) let a square cylinder's exit corner
 * flow back until it threw a particle out, and p_bg = ρ0 c0 U cured it, but doubled the
 * Poiseuille channel's exit pressure error (c0 = 30 U0: 0.19 against 0.07 of the drop); the
 * delayed exit target cures it without.
 *
 * Riemann problem between i (left) and j (right) along e = (x_j − x_i)/r_ij: the jump
 * U_ij = (v_i − v_j)·e = −v_ij·r_ij/r_ij (> 0 when the pair closes up),
 *   p* = p̄_ij + ½ ρ0 β_ij U_ij,  β_ij = min(η max(U_ij, 0), c0), η = 3           (eq 18)
 *   v* = v̄_ij + (p_i − p_j)/(2 ρ0 c0) e                                          (eq 16)
 * Eq 18 prints ½ β ρ0 c0 U with β = min(η max(U, 0), c0), a speed: a pressure times a speed.
 * We read it as Zhang, Hu & Adams (2017) define the low-dissipation limiter, ½ ρ0 β U, which is
 * the acoustic solver's ½ ρ0 c0 U where the pair closes faster than c0/η and fades linearly
 * below (no dissipation where the pair opens up).
 * Momentum with the reverse kernel gradient correction on the mean pressure (eq 19):
 *   a^p_i = −(1/ρ_i) Σ_j V_j [(p_i B_j + p_j B_i) + ρ0 β_ij U_ij I] ∇W_ij,
 * continuity (eq 15, with v* above):
 *   dρ_i/dt = 2 ρ_i Σ_j V_j (v_i − v*)·∇W_ij = ρ_i Σ_j V_j F [v_ij·r_ij + r Δp_ij/(ρ0 c0)],
 * with the jump Δp_ij = p_i − p_j − ρ0 g·r_ij less its hydrostatic part (our departure: the
 * paper's flows have no gravity). In a fluid at rest under gravity p_i − p_j = ρ0 g·r_ij; the
 * sum of the jumps cancels in a full support but not on a free surface, whose particles see
 * only the higher pressures below them: dρ/dt ~ ρ g/c0 there, which held the surface of a tank
 * at rest at +150 Pa and lifted it by 2 dr in 2 s (cases/hydrostatic.lua, dr = H/20). Without
 * the Riemann term at all (continuity = "plain") the same tank clustered at 0.15 s.
 * The fluid pairs' dissipative term (WCR_MOM_DISS, scheme option momentum_dissipation; the
 * walls' pairs keep theirs, the continuity equation its pressure-jump term): 1, eq 19 as printed;
 * 0, none; 2, the default under the k-ε model without ARD: U_ij of the jump left after the
 * linear reconstruction, v_ij − ½ (∇v_i + ∇v_j) r_ij, ∇v the model's (turbulence.cl), so that a
 * resolved shear takes none and the particles' noise still does. In a sheared lattice the
 * diagonal pairs close up at U ~ |∂u/∂y| dr/√2, and ρ0 β U with β = 3U is a viscosity of order
 * ½ β h that rivals ν_t near a wall: the fully developed channel (cases/channel_ke.lua, nf = 20,
 * u_τ fixed, t = 1000) ran its bulk 4.2% under OpenFOAM's with the same model and wall function
 * (the second row's k 30% low); 0.65% under with the reconstruction, 0.1% without the term (as
 * SPHinXsys's turbulent channels run: their second half-step, which carries the term, takes no
 * Riemann solver there). At U_b = 1 (flow-rate control) u_τ came 4.4% over OpenFOAM's with eq 19,
 * 1.4% with the reconstruction.
 * With ARD on (-D WCR_ARD=1; sec 3.1, eqs 31-32) the Riemann dissipation leaves eq 19 and acts as
 * a viscosity µ_R = ½ ρ0 β_ij h between the pair, the larger of it and the physical one, µ_c =
 * max(µ_R, µ̃) (eq 32): the physical part is in the advection step's a_prior, so the sub-step
 * adds (2/ρ_i) Σ_j max(µ_R − µ̃, 0) V_j F v_ij (eq 31 form), with the sub-step's velocities.
 *
 * Walls (the one-sided Riemann problem of Zhang et al. 2017 on dummy particles, Adami et al.
 * 2012): a dummy particle w shows i the state
 *   v_w = 2 u_w − v_i  (no penetration, no slip; u_w the wall's velocity),
 *   p_w = p_i − ρ_i a_i·r_iw  (the pressure a column of fluid under i's acceleration
 *         a_i = a_prior (gravity, body force, viscous) adds from i to w: Adami et al.'s
 *         hydrostatic extrapolation, pair by pair). SPHinXsys keeps only the increase,
 *         max(0, −a_i·r_iw); then the dummies of a side wall above i show p_i and those
 *         below it p_i + ρ g dz, a net lift along the wall that set a tank at rest turning
 *         (0.2 m/s up the walls, down the middle, cases/hydrostatic.lua, dr = H/20),
 *   B_w = B_i, V_w = dr²,
 * and the pair is then treated as a fluid pair. With wall_dissipation = "full"
 * (-D WCR_WALL_FULL=1) the wall pair takes β = c0 whatever U (the paper's choice for the
 * wall-bounded RANS flows, sec 4.3: "the low-dissipation limiter ... is not employed"). */

/* The velocity a dummy w shows fluid particle i in the Riemann problems: the no-slip mirror
 * 2 u_w − v_i; a gate's dummy (gate[w] != 0, WCR_GATE) the normal mirror v_i − 2 ((v_i − u_w)·n) n
 * only. A plate lifted at 4.53 m/s through water at rest shows the water next to it a tangential
 * jump of 9 m/s, whose Riemann dissipation dragged the water up with the plate: the Lobovsky dam
 * break with the gate (cases/dam_break.lua, 2-D, n = 40) struck sensor 1 at t* = 2.81, 15% after
 * the experiment (8.5% without the gate); the no-slip of the viscous term (advection.cl) stays. */
realv wcr_wall_mirror(realv vi, realv uw, realv nw, __global const uint *gate, uint w)
{
#if WCR_GATE
  if (gate[w] != 0u) return vi - R(2.0) * dot(vi - uw, nw) * nw;
#else
  (void)nw;
  (void)gate;
  (void)w;
#endif
  return R(2.0) * uw - vi;
}

real wcr_beta(real u, real c0, uint wall)
{
#if WCR_WALL_FULL
  if (wall) return c0;
#else
  (void)wall;
#endif
  return fmin(WCR_ETA * fmax(u, R(0.0)), c0);
}

/* r += dt_x v + shift (shift: once, at the start of an advection step), v += dt_v acc,
 * ρ += dt_rho dρ/dt, then V = m/ρ and p = c0² (ρ − ρ0); fluid only. In free-surface
 * flows (surface > 0) a particle whose kernel sum is short of a full support's (sigma < surface,
 * config.cl: the rows at the surface) takes no tension, p >= 0: pairs of surface particles under
 * a slightly negative pressure (−200 Pa in a tank at rest, dr = H/20) drew together until the
 * clustering check stopped the run (cases/hydrostatic.lua at t = 1.4 s; the Lobovsky dam break,
 * n = 20, at 0.35 s, under the surface of the collapsing column). */
__kernel void wcr_drift(const uint n, const struct grid g, __global const uint *kind,
                        const real dt_v, const real dt_x, const real dt_rho,
                        __global const realv *acc, const uint use_shift,
                        __global const realv *shift, __global const real *sigma, const real surface,
                        const real mass, const real rho0, const real c0, __global realv *pos,
                        __global realv *vel, __global real *rho, __global const real *drho,
                        __global real *vol, __global real *p, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != WCR_FLUID) return;
  realv v = vel[i];
  if (dt_v != R(0.0)) v += dt_v * acc[i];
  realv x = pos[i] + dt_x * v;
  if (use_shift) x += shift[i];
#if PERIODIC_X
  x.x = g.lo.x + (x.x - g.lo.x) - g.len.x * floor((x.x - g.lo.x) / g.len.x);
  if (x.x >= g.lo.x + g.len.x) x.x = g.lo.x; /* round-off of the line above */
#endif
#if PERIODIC_Y
  x.y = g.lo.y + (x.y - g.lo.y) - g.len.y * floor((x.y - g.lo.y) / g.len.y);
  if (x.y >= g.lo.y + g.len.y) x.y = g.lo.y;
#endif
#if PERIODIC_Z && DIM == 3
  x.z = g.lo.z + (x.z - g.lo.z) - g.len.z * floor((x.z - g.lo.z) / g.len.z);
  if (x.z >= g.lo.z + g.len.z) x.z = g.lo.z;
#endif
  const real r = rho[i] + dt_rho * drho[i];
  if (!all(isfinite(x)) || !all(isfinite(v)) || !isfinite(r) || !(r > R(0.0)))
    flags_raise(flags, CLSPH_FLAG_NAN);
  vel[i] = v;
  pos[i] = x;
  rho[i] = r;
  vol[i] = mass / r;
  real pr = c0 * c0 * (r - rho0);
  if (surface > R(0.0) && sigma[i] < surface) pr = fmax(pr, R(0.0));
  p[i] = pr;
}

/* ∇p_i for the wall pressure of wall_pressure = "gradient" (config.cl): the corrected gradient
 * over the fluid neighbours only, B^in Σ_j (p_j − p_i) ∇W_ij V_j with B^in the inverse of
 * −Σ_j F r_ij ⊗ r_ij V_j over the same neighbours (exact for a linear p however truncated the
 * support), p the pressure of the momentum sum (with ⅔ ρ k under the k-ε model); 0 where i has
 * no dummy neighbour (it is not needed there) */
realv wcr_pressure_gradient(realv x, real pi, const struct grid *g, __global const realv *pos,
                            __global const real *vol, __global const uint *kind,
                            __global const real *p, __global const real *rho,
                            __global const real *tk, __global const uint *row, uint c)
{
  uint near = 0; /* a dummy among the neighbours: most particles have none, and stop here */
  for (uint k = 0; k < c && !near; ++k) near = kind[row[k]] == WCR_DUMMY;
  if (!near) return (realv)(R(0.0));
  wcr_mat a = WCR_MAT_ZERO;
  realv s = (realv)(R(0.0));
  for (uint k = 0; k < c; ++k) {
    const uint j = row[k];
    if (kind[j] == WCR_DUMMY) continue;
    const realv r = wcr_sep(x, pos[j], g);
    const real f = smoothing_f(g->sm, sqrt(dot(r, r))) * vol[j];
    real pj = p[j];
#if WCR_TURB
    pj += R(2.0) / R(3.0) * rho[j] * tk[j];
#else
    (void)rho;
    (void)tk;
#endif
    a = wcr_moment(a, f, r);
    s += f * (pj - pi) * r;
  }
  return wcr_apply(wcr_correction(a), s);
}

/* dv/dt = a_prior + a^p (eq 19), and with ARD the Riemann viscosity (eq 31-32); fluid only */
__kernel void
wcr_momentum(const uint n, const struct grid g, __global const realv *pos,
             __global const realv *vel, __global const real *vol, __global const uint *kind,
             __global const real *rho, __global const real *p, __global const uint *nlist,
             __global const uint *ncount, __global const wcr_mat *bmat,
             __global const realv *acc_prior, const real rho0, const real c0, const real p_bg,
             const real mu, const real h, __global realv *acc, __global const real *tk,
             __global const real *nu_t, __global const realv *wall_normal, const realv gravity,
             __global const real4 *grad, __global realv *gradp, __global const uint *gate,
             __global const uint *wall, __global real4 *rec, __global const uint *wgroup,
             const uint nwall, const real rec_w)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != WCR_FLUID) return;
#if WCR_REC
  real4 wp[WCR_REC]; /* the walls' pair sums by group (force.cl): pressure and Riemann, ARD */
  for (uint q = 0; q < WCR_REC; ++q) wp[q] = (real4)(R(0.0));
#else
  (void)wall;
  (void)rec;
  (void)wgroup;
  (void)nwall;
  (void)rec_w;
#endif
  const realv x = pos[i], vi = vel[i], ai = acc_prior[i];
#if WCR_MOM_DISS == 2
  const real4 gi = grad[i];
#else
  (void)grad;
#endif
#if WCR_TURB
  /* the effective pressure p + ⅔ ρ k and viscosity ν + ν_t (Wang, Sun & Hu eq 5) */
  const real pi = p[i] + p_bg + R(2.0) / R(3.0) * rho[i] * tk[i], ri = rho[i];
  const real mui = mu + rho0 * nu_t[i];
#else
  (void)tk;
  (void)nu_t;
  const real pi = p[i] + p_bg, ri = rho[i];
#endif
  const wcr_mat bi = bmat[i];
  realv sum = (realv)(R(0.0)); /* Σ V_j [(p_i B_j + p_j B_i) ∇W + ρ0 β U ∇W], p with p_bg */
#if WCR_ARD
  realv visc = (realv)(R(0.0));
#endif
  const uint c = ncount[i];
  __global const uint *row = nlist + (size_t)i * WCR_MAXN;
#if WCR_WALL_PGRAD
  const realv gpi = wcr_pressure_gradient(x, pi - p_bg, &g, pos, vol, kind, p, rho, tk, row, c);
  gradp[i] = gpi; /* for the walls' force (force.cl) */
#else
  (void)gradp;
#endif
  for (uint k = 0; k < c; ++k) {
    const uint j = row[k];
    const realv r = wcr_sep(x, pos[j], &g);
    const real r2 = dot(r, r), rr = sqrt(r2);
    const real f = smoothing_f(g.sm, rr) * vol[j];
    const uint kj = kind[j], isw = kj == WCR_DUMMY;
    realv vj;
    real pj;
    wcr_mat bj;
    if (isw) {
#if WCR_TURB
      /* the wall model carries the wall's shear (eq 39): the Riemann problem sees the normal
       * mirror only, no tangential jump (else its dissipation is a laminar no-slip drag) */
      const realv nw = wall_normal[j];
      vj = vi - R(2.0) * dot(vi - vel[j], nw) * nw;
#else
      vj = wcr_wall_mirror(vi, vel[j], wall_normal[j], gate, j);
#endif
#if WCR_WALL_PGRAD
      pj = wcr_wall_pressure_grad(pi, ri, ai, r, wall_normal[j], gpi);
#else
      pj = wcr_wall_pressure(pi, ri, ai, r, wall_normal[j], gravity);
#endif
      bj = bi;
    } else {
      vj = vel[j];
      pj = p[j] + p_bg;
#if WCR_TURB
      pj += R(2.0) / R(3.0) * rho[j] * tk[j];
#endif
      bj = bmat[j];
    }
    const realv vij = vi - vj;
    real u = rr > R(0.0) ? -dot(vij, r) / rr : R(0.0);
#if WCR_MOM_DISS == 2
    if (!isw) { /* the jump left after the linear reconstruction, ½ (∇v_i + ∇v_j) r_ij */
      const real4 gm = kj == WCR_FLUID ? R(0.5) * (gi + grad[j]) : gi;
      const realv rec = vij - (realv)(gm.x * r.x + gm.y * r.y, gm.z * r.x + gm.w * r.y);
      u = rr > R(0.0) ? -dot(rec, r) / rr : R(0.0);
    }
#endif
    const real beta = wcr_beta(u, c0, isw);
#if WCR_TURB && WCR_WALL_PNORMAL
#if WCR_WALL_PGRAD
    const realv tp = isw ? wcr_wall_push(f, pi + pj, bi, r, wall_normal[j], gpi)
#else
    const realv tp = isw ? wcr_wall_push(f, pi + pj, bi, r, wall_normal[j], ri * gravity)
#endif
                         : f * (pi * wcr_apply(bj, r) + pj * wcr_apply(bi, r));
#else
    const realv tp = f * (pi * wcr_apply(bj, r) + pj * wcr_apply(bi, r));
#endif
    sum += tp;
#if WCR_ARD
#if WCR_TURB
    const real muj = isw ? mui : mu + rho0 * nu_t[j];
    const real mij = wcr_pair_mean(mui, muj); /* eq 32 against µ̃_ij */
#else
    const real mij = mu;
#endif
    const realv dv = fmax(R(0.5) * rho0 * beta * h - mij, R(0.0)) * f * vij;
    visc += dv;
#else
    realv td = (realv)(R(0.0));
    if (WCR_MOM_DISS != 0 || isw) {
      td = f * (rho0 * beta * u) * r;
      sum += td;
    }
#endif
#if WCR_REC
    const uint q = isw ? wcr_rec_group(j, wall, wgroup, nwall) : 0u;
    if (q) {
#if WCR_ARD
      wp[q - 1].xy += tp;
      wp[q - 1].zw += dv;
#else
      wp[q - 1].xy += tp + td;
#endif
    }
#endif
  }
  realv a = ai - sum / ri;
#if WCR_ARD
  a += R(2.0) / ri * visc;
#endif
  acc[i] = a;
#if WCR_REC
  /* the walls take the reactions, −m_i (= −ρ_i V_i) of what each group's pairs give i, as the
   * mean over the step's sub-steps (rec_w = 1/their number; the viscous part: wcr_advection) */
  const real vi_w = rec_w * vol[i];
  for (uint q = 0; q < WCR_REC; ++q) {
    const size_t at = (size_t)i * WCR_REC + q;
    rec[at] +=
        (real4)(vi_w * wp[q].x, vi_w * wp[q].y, -R(2.0) * vi_w * wp[q].z, -R(2.0) * vi_w * wp[q].w);
  }
#endif
}

/* dρ/dt (eq 15) from v^{n+1} = v + δt dv/dt of both particles; fluid only (0 elsewhere). The
 * entry and exit layers (solvers/open) are neighbours with their own v, ρ and p.
 * A dummy particle's velocity is the no-slip mirror 2 u_w − v_i, whose tangential jump cancels
 * along a straight wall but not where walls meet: at the lid's ends of the lid-driven cavity
 * (cases/cavity.lua) it is a density source of order ρ U/h. With the density re-set by summation
 * at each advection step (density = "summation") it does not add up; with the continuity
 * equation alone (density = "continuity", -D WCR_WALL_CONT_NORMAL=1) it did, and the 30² cavity
 * threw a particle out at its 13th step: there the dummy shows the free-slip mirror
 * v_i − 2 ((v_i − u_w)·n_w) n_w instead, no penetration through the wall along its normal n_w
 * and no tangential jump (the viscous sum keeps no slip, advection.cl). The 30² cavity at
 * Re = 100 then runs (u RMS against Ghia 0.025 U at t = 10, 0.015 with summation). Under
 * summation the free-slip mirror moved the 50² cavity's u RMS from 0.0048 to 0.0078 U, and it is
 * not used there. */
__kernel void wcr_continuity(const uint n, const struct grid g, __global const realv *pos,
                             __global const realv *vel, __global const realv *acc, const real dt,
                             __global const real *vol, __global const uint *kind,
                             __global const real *rho, __global const real *p,
                             __global const uint *nlist, __global const uint *ncount,
                             __global const realv *acc_prior, __global const realv *wall_normal,
                             const real rho0, const real c0, const realv gravity,
                             __global real *drho, __global const uint *gate)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  if (kind[i] != WCR_FLUID) { /* a layer particle that becomes fluid starts from dρ/dt = 0 */
    drho[i] = R(0.0);
    return;
  }
  const realv x = pos[i], vi = vel[i] + dt * acc[i], ai = acc_prior[i];
  const real pi = p[i], ri = rho[i], inv_z = R(1.0) / (rho0 * c0);
  real s = R(0.0);
  const uint c = ncount[i];
  __global const uint *row = nlist + (size_t)i * WCR_MAXN;
  for (uint k = 0; k < c; ++k) {
    const uint j = row[k];
    const realv r = wcr_sep(x, pos[j], &g);
    const real rr = sqrt(dot(r, r));
    const real f = smoothing_f(g.sm, rr) * vol[j];
    const uint kj = kind[j];
    realv vj;
    real pj;
    if (kj == WCR_DUMMY) {
#if WCR_WALL_CONT_NORMAL
      const realv nw = wall_normal[j];
      vj = vi - R(2.0) * dot(vi - vel[j], nw) * nw;
#else
      vj = wcr_wall_mirror(vi, vel[j], wall_normal[j], gate, j);
#endif
      pj = wcr_wall_pressure(pi, ri, ai, r, wall_normal[j], gravity);
    } else {
      vj = kj == WCR_FLUID ? vel[j] + dt * acc[j] : vel[j];
      pj = p[j];
    }
#if WCR_CONT_RIEMANN
    s += f * (dot(vi - vj, r) + rr * (pi - pj - rho0 * dot(gravity, r)) * inv_z);
#else
    s += f * dot(vi - vj, r);
    (void)pj;
    (void)inv_z;
    (void)gravity;
#endif
  }
  drho[i] = ri * s;
}
