/* project.cl (isph-usaw): the projection (eq 32),
 *   ũ_a = u*_a − (δt/ρ) G+_a{p̃},
 *   G+_a{p̃} = (1/γ_a) Σ_b V_b (p̃_a + p̃_b) ∇w_ab − (1/γ_a) Σ_s (p̃_a + p̃_s) ∇γ_as     (5)
 * or, with -D ISPH_GRAD_SYM=1 (the default, see isph_usaw.c), the symmetric gradient (eq 8) of
 * P = p̃ + ρgz as in the pressure equation (eqs 41-42): ∇p̃ = ∇P + ρ g, so
 *   ũ_a = u*_a − δt g − (δt/ρ) G−_a{P},
 * which keeps a fluid at rest (P constant) exactly at rest; a dry segment (both vertices free)
 * borders air and takes the particle's own P;
 * for fluid particles; vertex particles keep their wall's velocity. With -D ISPH_GRAD_SYM=1 the
 * symmetric gradient G−{p̃} (eq 8) replaces G+: exact for a constant pressure, where G+ carries
 * 2 p̃_a (Σ_b V_b ∇w_ab − ∇γ_a), the lattice's quadrature error times twice the pressure.
 *
 * Gradient correction (-D ISPH_GRAD_CORR=1, the default: where a free-surface particle is within
 * the support; 2: everywhere; 0: never). Where air truncates the kernel, G−{P} of the gravity
 * part ρgz of P falls short by the missing fraction of the kernel: the top of a falling column
 * falls at about g/2 while the fluid below it falls at g, the column stretches under its surface
 * and the pressure equation answers with negative pressures. The correction (Bonet & Lok 1999,
 * in the form of Oger et al. 2007) makes G− exact for linear fields:
 *   G^c_a{P} = L_a G−_a{P},  L_a = (G−_a{r})^{-1},
 * G−{r} being the same sums, fluid and segment terms, applied to the coordinates (a segment's
 * value is its midpoint's, as for every linear field); a fluid at rest stays at rest (L 0 = 0).
 * Where det G−{r} < 0.1 γ² (a particle nearly alone) the uncorrected gradient is kept. */
#ifndef ISPH_GRAD_SYM
#define ISPH_GRAD_SYM 0
#endif
#ifndef ISPH_VERTEX_ABOVE
#define ISPH_VERTEX_ABOVE R(1.5)
#endif
#ifndef ISPH_WALL_PUSH_ONLY
#define ISPH_WALL_PUSH_ONLY 1
#endif
#ifndef ISPH_GRAD_CORR
#define ISPH_GRAD_CORR 1
#endif
__kernel void isph_project(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *ustar,
                           __global const real *P, __global const real *pt, const real rho,
                           const real dt, const realv gravity, __global const uint *free_surface,
                           __global const real *divr, const uint free_flow,
                           const uint stop_at_walls, __global realv *vel, __global realv *acc,
                           __global realv *acc_p)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ISPH_FLUID) return;
  const realv x = pos[i];
#if ISPH_GRAD_SYM
  __global const real *p = P; /* G−{P}, gravity cancelled analytically */
#else
  __global const real *p = pt; /* G+{p̃}, eq 32 as written */
#endif
  const real pa = p[i];
  realv grad = (realv)(R(0.0));
  realv mx = (realv)(R(0.0)), my = (realv)(R(0.0)); /* G−{x}, G−{y}: the columns of G−{r} */
  int near_air = ISPH_GRAD_CORR == 2 || free_surface[i];
  uint wet = 0; /* fluid neighbours */
  struct neigh_iter it;
  /* in lanes (grid.cl) */
  struct lanesv grad4 = lanes_zero_v(), mx4 = grad4, my4 = grad4;
  maskw air4 = (maskw)(0);
  NEIGH_FOR_LANES(it, g, cell_start, x, b)
  {
    const struct lanesv r = lanes_rel(x, lanes_load_v(pos, b), it.shift);
    const realw r2 = lanes_dot(r, r);
    const uintw kj = lanes_load_u(kind, b);
    const maskw take = neigh_live(&it, b) & neigh_other(b, i) & (r2 < g.sm.support2) &
                       LANES_MASK(kj <= (uintw)(ISPH_VERTEX));
    const maskw fluid = take & LANES_MASK(kj == (uintw)(ISPH_FLUID));
    wet += lanes_count(fluid);
    const realw vf = lanes_keep(lanes_load(vol, b) * smoothing_fl(g.sm, sqrt(r2)), take);
#if ISPH_GRAD_SYM
    lanes_acc_v(&grad4, -(pa - lanes_load(p, b)) * vf, r);
    lanes_acc_v(&mx4, -r.x * vf, r);
    lanes_acc_v(&my4, -r.y * vf, r);
    air4 |= fluid & LANES_MASK(lanes_load_u(free_surface, b) != (uintw)(0u));
#else
    lanes_acc_v(&grad4, (pa + lanes_load(p, b)) * vf, r);
#endif
  }
  grad = lanes_total_v(grad4);
  mx = lanes_total_v(mx4);
  my = lanes_total_v(my4);
  near_air |= any(air4);
  struct usaw_segs si; /* the segments of non-zero ∇γ_as (gamma.cl) */
  uint s;
  realv sh, gs;
  USAW_SEGS_FOR(si, x, i, s, sh, gs)
  {
    const realv a = seg_a[s] + sh, b = seg_b[s] + sh;
    const uint v1 = inv[seg_v1[s]], v2 = inv[seg_v2[s]];
    /* a segment above the free surface borders air: its P says nothing about the fluid's, so
     * it takes the particle's own value. It is above the water line when both its vertices are
     * dry, or when one of them is (D{r} ≤ 1: the fluid fills at most the lower half of its
     * support; a submerged vertex of a straight wall has D{r} = 2, one on the water line 1):
     * there the vertex rows extrapolate P into the air, harmless at rest (P constant) but ever
     * more negative as a surface falls along a wall (−3e3 Pa within 0.05 s in the wedge case's
     * collapsing column), and the segment term then sucked the contact line through the wall */
    const int above = (free_surface[v1] && free_surface[v2]) || divr[v1] <= ISPH_VERTEX_ABOVE ||
                      divr[v2] <= ISPH_VERTEX_ABOVE;
    real ps = ISPH_GRAD_SYM && above ? pa : R(0.5) * (p[v1] + p[v2]);
#if ISPH_GRAD_SYM && ISPH_WALL_PUSH_ONLY
    /* where the fluid has a free surface a wall does not hold it in tension: it only pushes
     * (P_s ≥ P_a); the extrapolated wall pressure under a falling surface pulled the particles of
     * a contact line through the wall (the wedge case: first crossing at t = 0.34 s instead of
     * 0.20 s at δr = 0.01 m); a fluid at rest is unchanged (P_s = P_a) */
    if (free_flow) ps = fmax(ps, pa);
#endif
#if ISPH_GRAD_SYM
    grad += (pa - ps) * gs;
    if (!above) { /* a segment above the water line adds nothing to G−{P} */
      const realv rs = x - R(0.5) * (a + b);
      mx += rs.x * gs;
      my += rs.y * gs;
    }
#else
    grad -= (pa + ps) * gs;
#endif
  }
#if ISPH_GRAD_SYM
  /* G−{A} = M ∇A with M = [mx my] (before the division by γ): ∇P = M^{-1} G−{P} */
  const real det = mx.x * my.y - my.x * mx.y, gm = gam[i];
  /* ∇p̃ = ∇P + ρ g, so the gravity of u* cancels exactly: ũ = u* − δt g − (δt/ρ) G−{P} */
  realv g_part = gravity;
  if (ISPH_GRAD_CORR != 0 && near_air && det > R(0.1) * gm * gm)
    grad = (realv)(my.y * grad.x - my.x * grad.y, mx.x * grad.y - mx.y * grad.x) / det * gm;
  else if (near_air) /* too few neighbours to correct: the gradient of p̃ itself, G−{p̃} =
                      * G−{P} + ρ G−{g·r} = G−{P} + ρ M g; a particle alone in the air (M = 0)
                      * falls freely, where the cancellation above held it up against gravity
                      * (spray flying in straight lines out of the wedge case's pool) */
    g_part = (mx * gravity.x + my * gravity.y) / gm;
  realv u_new = ustar[i] - dt * g_part - dt / rho * grad / gam[i];
#else
  realv u_new = ustar[i] - dt / rho * grad / gam[i];
#endif
  /* A free-surface particle is a Dirichlet row (p̃ given), so the projection cannot hold it off
   * a wall: eq 39 takes the rows of particles that hit a wall fast out of the free surface, but
   * not a film creeping down a wall (the column's meniscus on the wedge case's left wall went
   * through it at t = 0.50 s, 0.52 δr deep) nor spray with no fluid neighbour at all (the jet
   * over the apex, single file, through the right wall). Such a particle that would come within
   * h q_max/8 of a wall in this step loses its velocity into the wall (an inelastic impact;
   * our departure from the paper). A particle whose pressure is solved gets the same treatment
   * within h q_max/16: the fluid sliding up the wedge's slope at 0.3-0.4 δr from it crept
   * through the apex, where the flow separates and the pressure is negative (−6e3 Pa), and a jet
   * meeting the right wall went 0.16 δr deep (usaw_wall_guard, usaw/common.cl; the shift has the
   * same guard, shift.cl). Only in scenes with gravity (stop_at_walls), where a free surface is
   * physics: in a confined flow a particle taken for free surface is a symptom, and a wall crossing
   * there must show (the cavity's stability map). */
  /* the pressure's acceleration, where the next prediction takes its wall term (viscous.cl) */
  acc_p[i] = (u_new - ustar[i]) / dt;
  if (stop_at_walls)
    u_new = usaw_wall_guard(x, u_new, dt,
                            g.sm.support / (free_surface[i] || wet == 0u ? R(8.0) : R(16.0)), g_seg,
                            seg_start, seg_a, seg_b, seg_n, seg_v1, seg_v2, inv, vel, 1);
  acc[i] = (u_new - vel[i]) / dt; /* the particle's acceleration, for the force bound (49) */
  vel[i] = u_new;
}
