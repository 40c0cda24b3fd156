/* density.cl (wcsph-usaw): the weakly-compressible baseline of Leroy et al. 2014 on the same
 * walls. Density by the continuity equation with the USAW divergence (eq 9) and a Ferrari
 * et al. (2009) density diffusion,
 *   dρ_a/dt = (ρ_a/γ_a) [Σ_b V_b u_ab·∇w_ab − Σ_s u_as·∇γ_as]
 *             + (c0/γ_a) Σ_b V_b (ρ_a − ρ_b − ρ0 g·r_ab/c0²) r_ab·∇w_ab / r_ab,
 * (ρ0 g·r_ab/c0² is the hydrostatic density difference ρ_H,a − ρ_H,b, which must not be diffused:
 * diffusing it drains the density of the particles along the bottom, as in Fourtakas et al.
 * 2019; with the opposite sign it was diffused twice over, and the hydrostatic tank sank through
 * its bottom wall at 0.05 m/s), the linear
 * equation of state p = c0² (ρ − ρ0) + p_bg, and the wall vertices' pressure as the
 * Shepard mean of the fluid's, carried hydrostatically to the wall (Ferrand et al. 2013):
 *   p_v = Σ_b V_b (p_b + ρ_b g·(r_v − r_b)) w_vb / Σ_b V_b w_vb,
 * over the fluid in the vertex's own fluid sector (the angle θ_v = 2π γ_v about its normal n_v):
 * next to a wall thinner than the support, the fluid on the far side would enter the mean. On
 * the water wheel's arms (cases/water_wheel.lua, 0.08 m thick, 1.6 δr at δr = 0.05 m) it carried
 * the pressure of an arm's lee onto its front: the torque came out 0.16 of isph-usaw's, and the
 * wheel's work was half the energy the fluid gained.
 * dρ/dt is taken from the new velocities u^{n+1} at r^n (the step's order: wcsph_usaw.c), so that
 * ρ^{n+1} = ρ^n + δt dρ/dt is symplectic Euler with the velocity, as the positions are. */
__kernel void wcsph_continuity(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *vel,
                               __global const real *rho, const real c0, const realv gravity,
                               const real rho0_c2, __global real *drho)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  drho[i] = R(0.0);
  if (kind[i] != ISPH_FLUID) return;
  const realv x = pos[i], u = vel[i];
  const real ra = rho[i];
  realw div4 = (realw)(R(0.0)), diff4 = (realw)(R(0.0));
  struct neigh_iter it;
  /* the fluid in lanes (grid.cl); i itself adds nothing (r = 0, u_ab = 0) */
  NEIGH_FOR_LANES(it, g, cell_start, x, b)
  {
    const struct lanesv r = lanes_rel(x, lanes_load_v(pos, b), it.shift);
    const realw rr = sqrt(lanes_dot(r, r));
    const maskw fluid = LANES_MASK(lanes_load_u(kind, b) == (uintw)(ISPH_FLUID));
    const realw vf =
        lanes_keep(lanes_load(vol, b) * smoothing_fl(g.sm, rr), neigh_live(&it, b) & fluid);
    div4 += vf * lanes_dot(lanes_sub_from(u, lanes_load_v(vel, b)), r);
    /* the hydrostatic part of the density difference is not diffused: ρ_H,a − ρ_H,b = ρ0 g·r/c0²
     * (g·r_ab = |g| (z_b − z_a)) */
    diff4 +=
        vf * (ra - lanes_load(rho, b) - rho0_c2 * lanes_dot1(r, gravity)) * rr; /* r·∇w/r = F r */
  }
  real div = lanes_sum(div4), diff = lanes_sum(diff4);
  struct usaw_segs si; /* the segments of non-zero ∇γ_as (gamma.cl) */
  uint s;
  realv sh, gg;
  USAW_SEGS_FOR(si, x, i, s, sh, gg)
  {
    const realv us = R(0.5) * (vel[inv[seg_v1[s]]] + vel[inv[seg_v2[s]]]);
    div -= dot(u - us, gg);
  }
  drho[i] = (ra * div + c0 * diff) / gam[i];
}

__kernel void wcsph_vertex_pressure(USAW_PART_ARGS, __global const real *rho, const realv gravity,
                                    __global const realv *normal, __global real *p)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ISPH_VERTEX) return;
  const realv x = pos[i], nv = normal[i];
  const real cos_half = cos(ISPH_PI * gam[i]); /* cos(θ_v/2), γ_v = θ_v/2π */
  realw s4 = (realw)(R(0.0)), ws4 = s4;
  struct neigh_iter it;
  NEIGH_FOR_LANES(it, g, cell_start, x, b)
  { /* in lanes (grid.cl) */
    const struct lanesv r = lanes_rel(x, lanes_load_v(pos, b), it.shift);
    const realw rr = sqrt(lanes_dot(r, r));
    /* r_b − r_v within θ_v/2 of n_v (a little slack: the fluid next to the wall, along it) */
    const maskw take = neigh_live(&it, b) &
                       LANES_MASK(lanes_load_u(kind, b) == (uintw)(ISPH_FLUID)) &
                       (-lanes_dot1(r, nv) >= (cos_half - R(1e-3)) * rr);
    const realw w = lanes_keep(lanes_load(vol, b) * smoothing_wl(g.sm, rr), take);
    s4 += w * (lanes_load(p, b) + lanes_load(rho, b) * lanes_dot1(r, gravity)); /* r = r_v − r_b */
    ws4 += w;
  }
  const real s = lanes_sum(s4), ws = lanes_sum(ws4);
  p[i] = ws > R(0.0) ? s / ws : R(0.0);
}
