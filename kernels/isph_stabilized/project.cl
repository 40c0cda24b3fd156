/* project.cl (isph-stabilized): the pressure correction and the motion (Asai et al. 2012).
 *   u^{n+1}_i = u*_i − (Δt/ρ0) Σ_j V_j (p_i + p_j) ∇_iW_ij    over fluid and dummies
 *   (A12's symmetric gradient ρ_i Σ_j m_j (p_i/ρ_i² + p_j/ρ_j²) ∇_iW_ij at ρ = ρ0; with the dummies
 *   filling the support next to a wall it holds a tank at rest)
 *   x^{n+1}_i = x_i + Δt u^{n+1}_i  (CHOICE: symplectic Euler, the new velocity moves the
 *   particle), wrapped on periodic axes.
 * CHOICE, measured: the gradient's kernel derivative is Thomas & Couchman's (1992) for pairs closer
 * than 2h/3, |∇W| held at its value there: the cubic spline's own derivative falls to 0 as r → 0,
 * so two particles that come closer than 2h/3 (0.8 dr at h = 1.2 dr) repel less the closer they
 * get. The free-surface particles, whose pressure is prescribed, cannot answer with a higher one,
 * and they paired: the paper's tank (cases/hydrostatic.lua stab=1 depth=0.2 width=0.2 dr=0.01)
 * clustered in its top row at t = 0.52 s with the modified virtual marker and at 1.17 s with the
 * pseudo-Neumann walls, whatever α (0 to 0.1), the time step (cfl 0.5) or β_fs (0.9 to 0.97);
 * with it both hold 10 s. The lattice's pairs (r ≥ dr > 2h/3) see the spline unchanged. */
/* pressure_form = "dynamic" (STAB_DYNAMIC): the pressure equation solved for P = p − ρ0 a·x (the
 * ρgz form of Leroy et al. 2014, eqs 41-42; the dummies' and free-surface rows carry the shift), so
 * that the hydrostatic part is exact, ρ0 a, and never meets a truncated support:
 *   ∇p_i = ρ0 a + Σ_j V_j [(P_j − P_i) + 2 e_i] ∇_iW_ij
 *          + Σ_{r_ij < 2h/3} V_j 2 max(0, p_i, p_j) (∇_iW_ij^TC − ∇_iW_ij),
 * e_i = P_i − min_j P_j over its support (0 on a free-surface row). CHOICE, measured: the
 * difference form alone holds a tank at rest exactly but leaves pairs of particles nothing to
 * part them (the symmetric form's 2 p_i Σ V ∇W does), and the n = 40 dam break clustered along
 * its floor at t = 0.17 s; 2 e_i Σ V ∇W (≥ 0, 0 in a uniform P) parts a particle from its denser
 * side where its pressure stands above its neighbours', and the short-range term (Thomas &
 * Couchman's derivative less the spline's, 0 at the lattice spacing, dr > 2h/3) parts pairs that
 * close in, the free surface's too. With e_i measured from the mean instead of the minimum (it
 * pulls as often as it pushes) the dam break failed at 0.19 s; with e_i on the free-surface rows
 * too the tank's surface lifted off within 0.4 s. */
__kernel void stab_project(OP_ARGS, __global const uint *kind, __global const realv *ustar,
                           __global const real *p, const real coef, const real dt, const realv body,
                           __global realv *vel, __global realv *accel,
                           __global const uint *free_surface, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != STAB_FLUID) return;
  const realv x = pos[i];
  const real p_i = p[i];
  const real rc = R(2.0) / (R(3.0) * g.sm.inv_h);
  struct neigh_iter it;
  uint j;
#if STAB_DYNAMIC
  const realv rho_a = body * (dt / coef); /* ρ0 a (coef = Δt/ρ0) */
  /* e_i = P_i − min P over the support: P_j − P_i = p_j − p_i + ρ0 a·r_ij */
  real e = R(0.0);
  if (free_surface[i] == 0u) {
    NEIGH_FOR(it, g, cell_start, x, j) {
      realv r = x - (pos[j] + it.shift);
      if (dot(r, r) >= g.sm.support2) continue;
      e = fmax(e, -(p[j] - p_i + dot(rho_a, r)));
    }
  }
  realv gp = rho_a;
#else
  realv gp = (realv)(R(0.0));
#endif
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i) continue;
    const real rr = sqrt(r2);
    const real f =
        rr < rc ? smoothing_f(g.sm, rc) * rc / fmax(rr, R(1e-6) * rc) : smoothing_f(g.sm, rr);
#if STAB_DYNAMIC
    gp += vol[j] * (p[j] - p_i + dot(rho_a, r) + R(2.0) * e) * f * r;
    if (rr < rc)
      gp += vol[j] * R(2.0) * fmax(R(0.0), fmax(p_i, p[j])) * (f - smoothing_f(g.sm, rr)) * r;
#else
    gp += vol[j] * (p_i + p[j]) * f * r;
#endif
  }
  const realv u = ustar[i] - coef * gp; /* coef = Δt/ρ0 */
  if (!all(isfinite(u))) flags_raise(flags, CLSPH_FLAG_NAN);
  vel[i] = u;
  accel[i] = body - coef * gp / dt; /* the body force and the pressure's, for the time step */
}

/* x += Δt u for the fluid (the gate's dummies move in walls.cl), and the wall crossing check: a
 * particle is behind the wall when it is behind the nearest of the dummies' wall points
 * q_d = x_d + d_d n_d, (x − q_d)·n_d < 0, where in front of any wall point within `band` (dr/2)
 * of the nearest puts it in the fluid. Not the nearest dummy's: inside a pit next to its rim (a
 * convex corner of the solid) that is a floor's dummy, and the particle below the floor's line was
 * taken for behind it (cases/hydrostatic_shapes.lua shape = 2 stopped at its second step). The
 * band: next to a convex apex the wall points are sparse (its dummies' nearest points all lie on
 * one flank), and a particle in front of the other flank read as behind the first. Only wall
 * points within 2 dr count (a crossing deeper than that has long stopped the run). A crossing
 * raises CLSPH_FLAG_WALL, counts in flags[1] and keeps the deepest distance behind the wall in
 * flags[2] (usaw/gamma.cl's protocol, which host/sim/checks.c reads). The dummies' positions do not
 * change here, so the loop reads them from the same array the fluid writes. */
__kernel void stab_move(const uint n, const struct grid g, __global const uint *cell_start,
                        __global const uint *kind, __global const realv *vel,
                        __global const real *dist, __global const realv *normal, const real dt,
                        const real band, __global realv *pos, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != STAB_FLUID) return;
  const realv x = grid_wrap(&g, pos[i] + dt * vel[i]);
  if (!all(isfinite(x))) flags_raise(flags, CLSPH_FLAG_NAN);
  pos[i] = x;
  /* the nearest of the dummies' wall points q_d = x_d + d n_d (distance²), the best side there */
  real best = INFINITY, side = INFINITY;
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    if (kind[j] == STAB_FLUID) continue;
    const realv r = x - (pos[j] + it.shift + dist[j] * normal[j]);
    const real r2 = dot(r, r);
    const real s = dot(r, normal[j]);
    if (r2 < best) {
      /* a nearer point: the ones within `band` of it stay candidates */
      side = sqrt(r2) + band < sqrt(best) ? s : fmax(side, s);
      best = r2;
    } else if (sqrt(r2) <= sqrt(best) + band) {
      side = fmax(side, s);
    }
  }
  /* a wall point farther than 2 dr (4 bands) is no wall of this particle: away from the walls the
   * loop still meets the dummies of a convex apex, whose points lie on one flank */
  if (best < R(16.0) * band * band && side < R(0.0)) {
    flags_raise(flags, CLSPH_FLAG_WALL);
    atomic_inc(flags + 1);
    atomic_max(flags + 2, as_uint((float)(-side)));
  }
}
