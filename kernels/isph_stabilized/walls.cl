/* walls.cl (isph-stabilized): dummy wall particles with virtual markers (Asai et al. 2013; seed
 * paper S = stabilized_isph_virtual_marker.txt sec 3).
 *
 * Kinds: STAB_FLUID (moves) and STAB_DUMMY (inside the solid, moving with its wall). A dummy w at
 * distance d_w from the wall, n_w its unit normal into the fluid, has its velocity marker
 * x_m = x_w + 2 d_w n_w inside the fluid (S sec 3.1; at a box corner the point reflection through
 * the corner, the image isph-rotational uses). W̃ is the Shepard weight of the fluid at a marker
 * (S eq 10, common/marker.cl).
 *   velocity (S eqs 11-13): u_m = Σ_j W̃(x_m − x_j) u_j,
 *     u_w = u_W + [β_s M + (1 − β_s) R](u_m − u_W),  M = I − 2 n⊗n (slip), R = −I (no-slip);
 *     a dry marker (no fluid in reach) gives u_w = u_W.
 *   u*_w = u_w + Δt a (a = g + body force). CHOICE: the dummies take the same explicit body force
 *     as the fluid in the divergence of the pressure equation. The pressure below carries the
 *     hydrostatic jump ρ a·(x_w − x_m); a dummy u* without Δt a (u_W, or the mirror of u*) would
 *     add a velocity jump Δt a·n at the wall, a second flux across it that counts gravity twice.
 *     With it a tank at rest has ∇·u* = 0 everywhere.
 *   pressure, pseudo-Neumann (S sec 3.2): p_w = Σ_j W̃(x_m − x_j) p_j + ρ0 a·(x_w − x_m)
 *     ("plus ρ g times the distance"), computed from the fluid's last pressure and imposed as a
 *     Dirichlet value on the dummy rows of the pressure equation; after the solve it is mapped
 *     again from the new pressure (S eq 22) for the projection and the next step. A dry marker
 *     gives p_w = 0 (no fluid near: nothing to hold). CHOICE: p_w ≥ 0, as the free surface's:
 *     above the water the carry ρ0 a·(x_w − x_m) is negative, a tension that pulls the contact
 *     line's particles into the wall. */
#ifndef STAB_DYNAMIC /* isph_stabilized.c stab_define: pressure_form = "dynamic" */
#define STAB_DYNAMIC 0
#endif
#ifndef STAB_APPROACH_IMPACT /* stab_define: wall_approach = "impact" (ppe.cl) */
#define STAB_APPROACH_IMPACT 0
#endif
/* wall_approach = "impact": a neighbour's approach counts when it reaches the wall within this many
 * steps (isph-usaw's ISPH_IMPACT_STEPS, free_surface.cl) */
#ifndef STAB_IMPACT_STEPS
#define STAB_IMPACT_STEPS 10
#endif
#define STAB_FLUID 0u
#define STAB_DUMMY 2u

/* vel and ustar of the dummies (the fluid's are left alone) */
__kernel void stab_wall_velocity(const uint n, const struct grid g, __global const uint *cell_start,
                                 __global const realv *pos, __global const real *vol,
                                 __global const uint *kind, __global const real *dist,
                                 __global const realv *normal, __global const realv *wall_vel,
                                 const real beta_s, const real dt, const realv accel,
                                 __global realv *vel, __global realv *ustar, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != STAB_DUMMY) return;
  const realv nw = normal[i], uW = wall_vel[i];
  const realv xm = pos[i] + R(2.0) * dist[i] * nw;
  const struct marker_sums s =
      marker_shepard(&g, cell_start, pos, vol, kind, xm, i, MARKER_VEL, vel, 0);
  realv u = uW;
  if (s.wsum > R(0.0)) {
    /* [β M + (1 − β) R] Δ = (2β − 1) Δ − 2β n (n·Δ), Δ = u_m − u_W (S eqs 11-13) */
    const realv du = s.u / s.wsum - uW;
    u = uW + (R(2.0) * beta_s - R(1.0)) * du - R(2.0) * beta_s * dot(nw, du) * nw;
  }
  if (!all(isfinite(u))) flags_raise(flags, CLSPH_FLAG_NAN);
  vel[i] = u;
  ustar[i] = u + dt * accel;
}

/* p of the dummies by the pseudo-Neumann mapping; also into rhs (their Dirichlet row d0 p_w = d0
 * p̂_w, ppe.cl) when write_rhs (before the solve) */
__kernel void stab_wall_pressure(const uint n, const struct grid g, __global const uint *cell_start,
                                 __global const realv *pos, __global const real *vol,
                                 __global const uint *kind, __global const real *dist,
                                 __global const realv *normal, const real rho0, const realv accel,
                                 const uint write_rhs, const real d0, __global real *p,
                                 __global real *rhs, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != STAB_DUMMY) return;
  const realv xw = pos[i], xm = xw + R(2.0) * dist[i] * normal[i];
  const struct marker_sums s =
      marker_shepard(&g, cell_start, pos, vol, kind, xm, i, MARKER_P, 0, p);
  const real pw =
      s.wsum > R(0.0) ? fmax(R(0.0), s.p / s.wsum + rho0 * dot(accel, xw - xm)) : R(0.0);
  if (!isfinite(pw)) flags_raise(flags, CLSPH_FLAG_NAN);
  p[i] = pw;
  if (write_rhs) rhs[i] = d0 * (pw - STAB_DYNAMIC * rho0 * dot(accel, xw)); /* P_w (dynamic) */
}
