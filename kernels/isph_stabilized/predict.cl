/* predict.cl (isph-stabilized): the explicit viscous prediction and the source of the stabilized
 * pressure equation (Asai, Aly, Sonoda & Sakai 2012, J. Appl. Math. 2012:139583, "A12"; seed
 * paper S = stabilized_isph_virtual_marker.txt sec 2.3, eq 8).
 *
 * Conventions: r_ij = x_i − x_j, ∇_iW_ij = F(r_ij) r_ij (smoothing.h), V_j = dr², ρ = ρ0.
 *   prediction (A12 projection, viscous term explicit):
 *     u*_i = u_i + Δt (ν L{u}_i + a),  L{u}_i = Σ_j 2 V_j F_ij r_ij²/(r_ij² + η²) (u_i − u_j)
 *     (Morris et al. 1997; common/poisson.cl's pair term), over fluid and dummies (walls.cl
 *     gives the dummies their velocity), a = g + body force.
 *   intermediate density (A12; S sec 2.3 "the density updated on the intermediate positions"):
 *     x*_i = x_i + Δt u*_i (fluid), x*_w = x_w + Δt u_W (dummies move with their wall),
 *     s*_i = Σ_j V_j W(|x*_i − x*_j|) over fluid and dummies, i itself included,
 *     ρ*_i/ρ0 = s*_i/σ0, σ0 the same sum over the full lattice (common/lattice.cl). CHOICE: the
 *     reference is the discrete lattice sum, not 1: otherwise a lattice at rest carries the source
 *     αρ0(1 − σ0)/Δt², which grows as Δt shrinks.
 *     The pairs are those of the neighbour grid at x^n: its cells cover the support plus the skin
 *     (support_skin), more than two moves of a step bounded by 0.25 h/U each apart.
 *   free surface (A12, MPS practice; S: β ≈ 0.97): a Dirichlet row where s*_i / σ0 < β_fs, and
 *     where fewer than fs_min particles lie within the support at x* (spray pressed into a clump
 *     reads a full density: isph_stabilized.c says why). The
 *     dummies count in s*, so fluid next to a wall keeps a full support. With the option
 *     surface_detection = "scan" the row must also have an empty scan region (Marrone et al.
 *     2010, stab_scan_empty): a lattice cut by a curved or slanted wall leaves holes between the
 *     fluid and the dummies, the particles around a hole read s* / σ0 from 0.83 to 0.96, and as
 *     Dirichlet rows deep in the water they held p = 0 there (cases/hydrostatic_shapes.lua:
 *     28% of ρ g H off over the fluid); the region beyond a hole holds particles, the air's
 *     does not. Its value: CHOICE, the
 *     pressure half a spacing inside the surface, p_i = −ρ0 a·n dr/2 (≥ 0; n = −Σ V ∇W / |…|, the
 *     outward normal), not A12's p = 0 on the particle itself (the reading isph-usaw makes too,
 *     its free_surface_offset): with the symmetric gradient of project.cl a top particle at
 *     p = 0 feels only half of the weight of its half support (Σ V F Δy² over the rows below is
 *     0.50 at h = 1.2 dr), sinks into the row below at g/2, and the paper's tank clustered within
 *     0.3 s; at 0.54 ρ g dr it is in equilibrium, and ρ g dr/2 is the fluid's own surface.
 *   source (A12 stabilized PPE, S eq 8):
 *     ∇²p_i = (ρ0/Δt) D_i + α ρ0 (1 − s*_i/σ0)/Δt²,  D_i = Σ_j V_j (u*_j − u*_i)·∇_iW_ij at x^n,
 *     the Laplacian that of common/poisson.cl. α = 0: the divergence-free projection alone;
 *     α > 0 pulls the density back to ρ0 (S: "around 1% or less").
 * The dummies' rows (ppe.cl) get their right-hand side from walls.cl (pseudo-Neumann) or ppe.cl
 * (the modified virtual marker) after this kernel. */

/* u* of the fluid */
__kernel void stab_predict(OP_ARGS, __global const uint *kind, __global const realv *vel,
                           const real nu, const real dt, const realv accel, __global realv *ustar,
                           __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != STAB_FLUID) return;
  const realv x = pos[i], u_i = vel[i];
  const realm L_i = mat_identity();
  realv lap = (realv)(R(0.0));
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    lap += poisson_pair(g.sm, L_i, vol[j], r, r2) * (u_i - vel[j]);
  }
  const realv u = u_i + dt * (nu * lap + accel);
  if (!all(isfinite(u))) flags_raise(flags, CLSPH_FLAG_NAN);
  ustar[i] = u;
}

/* x* of particle j: the fluid's with its u*, a dummy's with its wall */
realv stab_xstar(uint j, __global const realv *pos, __global const uint *kind,
                 __global const realv *ustar, __global const realv *wall_vel, real dt)
{
  return pos[j] + dt * (kind[j] == STAB_FLUID ? ustar[j] : wall_vel[j]);
}

/* |n⊥·r|: r's distance from the line along the unit n (in 3-D, from the axis of the scan's cone) */
real stab_across(realv nrm, realv r)
{
#if DIM == 3
  return length(cross(nrm, r));
#else
  return fabs(nrm.x * r.y - nrm.y * r.x);
#endif
}

/* Is the scan region of fluid i at x*_i empty (Marrone et al. 2010, CMAME 199:2734 sec 3.2)?
 * n = −∇s* / |∇s*| (the outward normal of the kernel sum at x*), T = x*_i + h n; a neighbour j
 * (fluid or dummy, at x*_j) fills it when |x_ji| ≥ √2 h and |x_j − T| < h, or |x_ji| < √2 h and
 * |n⊥·x_ji| + |n·(x_j − T)| < h, with x_ji = x*_j − x*_i. A particle with no gradient (alone, or
 * thinned evenly) has an empty region. */
uint stab_scan_empty(uint i, realv xs, realv gss, const struct grid *gg,
                     __global const uint *cell_start, __global const realv *pos,
                     __global const uint *kind, __global const realv *ustar,
                     __global const realv *wall_vel, real dt)
{
  const real gl = length(gss);
  if (!(gl > R(0.0))) return 1u;
  const realv nrm = -gss / gl;
  const real h = R(1.0) / gg->sm.inv_h;
  const realv t = xs + h * nrm;
  struct neigh_iter it;
  NEIGH_FOR(it, *gg, cell_start, pos[i], j) {
    if (j == i) continue;
    const realv xj = stab_xstar(j, pos, kind, ustar, wall_vel, dt) + it.shift;
    const realv rj = xj - xs, rt = xj - t;
    const real r2 = dot(rj, rj);
    if (r2 >= gg->sm.support2) continue;
    if (r2 >= R(2.0) * h * h) {
      if (dot(rt, rt) < h * h) return 0u;
    } else if (stab_across(nrm, rj) + fabs(dot(nrm, rt)) < h) {
      return 0u;
    }
  }
  return 1u;
}

/* s* / σ0, the free surface, the Dirichlet mask, D and the right-hand side (a free-surface row
 * d0 p_i = d0 p_s, ppe.cl; the dummies' rows come from walls.cl and ppe.cl) */
__kernel void stab_source(OP_ARGS, __global const uint *kind, __global const realv *ustar,
                          __global const realv *wall_vel, const real dt, const real inv_sigma0,
                          const real beta_fs, const uint fs_min, const uint scan, const real alpha,
                          const real rho0, const realv accel, const real fs_offset, const real d0,
                          __global real *rho_star, __global uint *free_surface,
                          __global uint *dirichlet, __global real *div, __global real *rhs,
                          __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  if (kind[i] != STAB_FLUID) {
    rho_star[i] = R(1.0);
    free_surface[i] = 0u;
    dirichlet[i] = 1u;
    div[i] = R(0.0);
    rhs[i] = R(0.0);
    return;
  }
  const realv x = pos[i], u_i = ustar[i], xs = x + dt * u_i;
  real s = R(0.0), d = R(0.0);
  uint near = 0u;              /* the other particles within the support at x* */
  realv gs = (realv)(R(0.0));  /* Σ V ∇W: −gs points out of the fluid */
  realv gss = (realv)(R(0.0)); /* the same at x*, for the scan */
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv rs = xs - (stab_xstar(j, pos, kind, ustar, wall_vel, dt) + it.shift);
    const real rsl = sqrt(dot(rs, rs));
    s += vol[j] * smoothing_w(g.sm, rsl); /* j == i included: W(0) */
    if (j != i && rsl < g.sm.support) {
      gss += vol[j] * smoothing_f(g.sm, rsl) * rs;
      ++near;
    }
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    const realv gw = smoothing_f(g.sm, sqrt(r2)) * r;
    d += vol[j] * dot(ustar[j] - u_i, gw);
    gs += vol[j] * gw;
  }
  const real ratio = s * inv_sigma0;
  const uint fs =
      near < fs_min ||
      (ratio < beta_fs &&
       (scan == 0u || stab_scan_empty(i, xs, gss, &g, cell_start, pos, kind, ustar, wall_vel, dt)));
  /* a free-surface particle: the pressure fs_offset inside the surface, −ρ0 a·n fs_offset along
   * its outward normal n (≥ 0) */
  const real gn = length(gs);
  real pfs = gn > R(0.0) ? fmax(R(0.0), rho0 * fs_offset * dot(accel, gs) / gn) : R(0.0);
#if STAB_DYNAMIC
  /* a surface facing up (within 60° of −a): the whole ρ0 |a| fs_offset, whatever the tilt of its
   * normal, which the dummies above the water bend at a wall: under a level surface P = p − ρ0 a·x
   * is then the same on every surface row, and a tank at rest stays at rest to the solver's
   * tolerance. The dummies' rows and the free-surface rows carry the shift too (ppe.cl). */
  if (gn > R(0.0) && dot(accel, gs) / gn > R(0.5) * length(accel))
    pfs = rho0 * fs_offset * length(accel);
  pfs -= rho0 * dot(accel, x);
#endif
  const real b = fs ? d0 * pfs : rho0 / dt * d + alpha * rho0 * (R(1.0) - ratio) / (dt * dt);
  if (!isfinite(b)) flags_raise(flags, CLSPH_FLAG_NAN);
  rho_star[i] = ratio;
  free_surface[i] = fs;
  dirichlet[i] = fs;
  div[i] = d;
  rhs[i] = b;
}
