/* free_surface.cl (isph-usaw): free-surface particles get the Dirichlet condition p̃ = 0.
 * A particle is at the free surface when the divergence of the position (eq 9 applied to r)
 *   D_a{r} = −(1/γ_a) Σ_b V_b r_ab·∇w_ab + (1/γ_a) Σ_s r_as·∇γ_as ≤ 1.5   (2-D, sec 3.2)
 * except when it is about to hit a wall (eq 39):
 *   |r_av| + δt (u_a · r_av)/|r_av| < h q_max / 8,
 * so that jets hitting a wall keep their pressure and do not cross it (the vertex it hits has
 * fluid around it, so it is no Dirichlet row either; see below). Two departures, both found on the
 * collapsing water column of the wedge case (cases/dam_break_wedge.lua):
 *  - the distance is taken to the wall itself (the nearest point of each segment), not to its
 *    vertices: a particle sliding along a wall closes on the vertices ahead of it at its full
 *    speed while it never approaches the wall, and the tip of a front running along the bottom
 *    lost its free surface at every vertex it passed (pressure spikes of ±3e4 Pa);
 *  - the particle must close on the wall within ISPH_IMPACT_STEPS steps at its present speed:
 *    a particle creeping towards a wall at the free surface (the meniscus of a falling column,
 *    0.1 m/s) kept its pressure unknown, the pressure went negative and pulled it through.
 * normal gets the outward unit normal of the surface (for free_surface_offset). With with_rhs the
 * same loops make the pressure equation's right-hand side (isph_ppe_rhs, ppe.cl, in the same
 * order: the same bits), which a row takes from its own flag alone unless density_relaxation is
 * on: one sweep over the neighbours and the segments' quadrature a step less (the wedge: about
 * 2.7 of 45 ms a step). The same launch counts the free-surface rows into count[0] (which the
 * host reads with the pressure solve's first wait) and, with guess, makes the solve's initial
 * guess: two launches a step less. */
#ifndef ISPH_IMPACT_STEPS
#define ISPH_IMPACT_STEPS 10
#endif
/* A particle is wet (its pressure row is solved, not given) when the fluid fills at least this
 * fraction of its kernel: Σ_b V_b w_ab ≥ ISPH_WET γ_a over the fluid neighbours b. A vertex with
 * one fluid particle at the edge of its support (w ≈ 0) had a row coupled to the fluid by almost
 * nothing and to its neighbouring vertices fully: the chain of such rows along a wall under a jet
 * took pressures of ±1e6 to 1e9 Pa (the wedge case, t ≈ 0.5 s), and the segments passed them on
 * to the fluid (a kick to 14-29 m/s). One particle within about 1.5 δr of a wall vertex wets it (h
 * = 2 δr). */
#ifndef ISPH_WET
#define ISPH_WET R(0.1)
#endif
/* A fluid particle about to hit a wall keeps its pressure unknown only when it is part of a body of
 * fluid, Σ_b V_b w_ab ≥ ISPH_SPLASH γ_a (a jet two particles thick, about 0.3; a flat free surface
 * 0.36; a particle inside 0.86): a few particles flung onto a turning arm above the water
 * (cases/water_wheel.lua), which touch the wall and nothing else, otherwise made a block of the
 * pressure equation with no Dirichlet row, singular and, with the arm closing on them,
 * inconsistent: BiCGStab diverged (a residual of 1e118 at t = 3.31 s, δr = 0.02 m) and the run
 * stopped. Given p̃ = 0 they meet the wall through the projection's wall guard (project.cl). */
#ifndef ISPH_SPLASH
#define ISPH_SPLASH R(0.25)
#endif
/* Eq 39 with the departures above: a point at distance dist from the wall (or vertex) that
 * closes on it by `closing` in one step. */
int isph_impact(const struct smooth sm, real dist, real closing)
{
  return dist - closing < sm.support / R(8.0) && closing * ISPH_IMPACT_STEPS > dist;
}

__kernel void isph_free_surface(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *vel,
                                const real dt, __global uint *free_surface, __global real *divr,
                                __global realv *normal, const uint with_rhs,
                                __global const realv *ustar, __global const realv *visc,
                                const real rho, const realv gravity, const real surface_offset,
                                __global const realv *acc, __global real *rhs, const uint guess,
                                const real theta, __global real *P, __global real *P_last,
                                __global uint *count)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  if (guess) { /* the pressure solve's initial guess, P extrapolated linearly in time from the last
                * two steps' solutions: P + θ (P − P_last), θ = δt_n / δt_(n−1) (0 at a run's
                * first step); P_last <- P */
    const real last = P[i];
    P[i] = last + theta * (last - P_last[i]);
    P_last[i] = last;
  }
  if (kind[i] > ISPH_VERTEX) {
    free_surface[i] = 0u;
    if (with_rhs) rhs[i] = R(0.0);
    return;
  }
  const realv x = pos[i], u = vel[i], us = ustar[i];
  real div = R(0.0), wall = R(0.0); /* the right-hand side's sums (with_rhs) */
  real d = R(0.0);
  int hitting = 0;
  real wet = R(0.0);          /* Σ_b V_b w_ab over the fluid neighbours */
  realv gf = (realv)(R(0.0)); /* Σ_b V_b ∇w_ab: into the fluid (and the walls) */
  realv gw = (realv)(R(0.0)); /* ∇γ_a = Σ_s ∇γ_as: away from the walls */
  struct neigh_iter it;
  /* in lanes (grid.cl) */
  realw d4 = (realw)(R(0.0)), wet4 = d4, div4 = d4;
  struct lanesv gf4 = lanes_zero_v();
  NEIGH_FOR_LANES(it, g, cell_start, x, b)
  {
    const struct lanesv r = lanes_rel(x, lanes_load_v(pos, b), it.shift);
    const realw r2 = lanes_dot(r, r), rr = sqrt(r2), vj = lanes_load(vol, b);
    const uintw kj = lanes_load_u(kind, b);
    const maskw take =
        neigh_live(&it, b) & neigh_other(b, i) & LANES_MASK(kj <= (uintw)(ISPH_VERTEX));
    const realw vf = lanes_keep(vj * smoothing_fl(g.sm, rr), take);
    d4 -= vf * r2; /* r_ab·∇w_ab = F r² */
    wet4 += lanes_keep(vj * smoothing_wl(g.sm, rr), take & LANES_MASK(kj == (uintw)(ISPH_FLUID)));
    lanes_acc_v(&gf4, vf, r);
    if (with_rhs) div4 -= vf * lanes_dot(lanes_sub_from(us, lanes_load_v(ustar, b)), r);
  }
  d = lanes_sum(d4);
  wet = lanes_sum(wet4);
  gf = lanes_total_v(gf4);
  div = lanes_sum(div4);
  NEIGH_FOR(it, g_seg, seg_start, x, s) {
    const realv a = seg_a[s] + it.shift, b = seg_b[s] + it.shift;
    const realv gg = usaw_grad_gamma_seg(g.sm, x, a, b, seg_n[s]);
    d += dot(x - R(0.5) * (a + b), gg);
    gw += gg;
    if (with_rhs) isph_rhs_seg(us, ustar, visc, inv[seg_v1[s]], inv[seg_v2[s]], gg, &div, &wall);
    if (kind[i] == ISPH_FLUID) { /* eq 39 against the nearest point of the segment */
      const realv t = b - a;
      const realv c = a + clamp(dot(x - a, t) / dot(t, t), R(0.0), R(1.0)) * t;
      const realv us = R(0.5) * (vel[inv[seg_v1[s]]] + vel[inv[seg_v2[s]]]); /* wall velocity */
      const real dist = length(x - c);
      if (dist > R(0.0) && isph_impact(g.sm, dist, -dt * dot(u - us, x - c) / dist)) hitting = 1;
    }
  }
  d /= gam[i];
  divr[i] = d;
  /* outward normal of the free surface: the concentration gradient of the fluid alone, less its
   * component across a nearby wall (where the surface meets the wall, the missing neighbours
   * behind the wall are not missing fluid) */
  realv nf = -gf;
  const real lw = length(gw);
  if (lw > R(0.0)) nf -= dot(nf, gw / lw) * (gw / lw);
  const real lf = length(nf);
  const realv nrm = lf > R(0.0) ? nf / lf : (realv)(R(0.0));
  normal[i] = nrm;
  /* A wall vertex is a Dirichlet row only when it is dry (ISPH_WET): one
   * next to the free surface would impose p̃ = 0 below the fluid's top row and pull the fluid
   * into the wall; with fluid around, its row of eq 44 extrapolates the pressure to the wall
   * (P constant at rest; above the water line see project.cl). */
  const int dry = wet < ISPH_WET * gam[i], splash = wet < ISPH_SPLASH * gam[i];
  const uint fs = kind[i] == ISPH_VERTEX ? dry : d <= R(1.5) && (!hitting || splash);
  free_surface[i] = fs;
  if (fs) atomic_inc(count); /* zeroed by the step's first half move (move.cl) */
  if (with_rhs)
    rhs[i] = fs ? isph_rhs_surface(rho, surface_offset, gravity, acc[i], nrm, x)
                : rho / dt * div + R(2.0) * rho * wall;
}
