/* project.cl (isph-stabilized): the pressure correction and the motion (Asai et al. 2012).
 *   u^{n+1}_i = u*_i − (Δt/ρ0) Σ_j V_j (p_i + p_j) ∇_iW_ij    over fluid and dummies
 *   (A12's symmetric gradient ρ_i Σ_j m_j (p_i/ρ_i² + p_j/ρ_j²) ∇_iW_ij at ρ = ρ0; with the dummies
 *   filling the support next to a wall it holds a tank at rest)
 *   x^{n+1}_i = x_i + Δt u^{n+1}_i  (CHOICE: symplectic Euler, the new velocity moves the
 *   particle), wrapped on periodic axes. */
__kernel void stab_project(OP_ARGS, __global const uint *kind, __global const realv *ustar,
                           __global const real *p, const real coef, __global realv *vel,
                           __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != STAB_FLUID) return;
  const realv x = pos[i];
  const real p_i = p[i];
  realv gp = (realv)(R(0.0));
  struct neigh_iter it;
  neigh_begin(&it, &g, x);
  uint j;
  while (neigh_next(&it, &g, cell_start, &j)) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= SMOOTH_SUPPORT2 || j == i) continue;
    gp += vol[j] * (p_i + p[j]) * smoothing_f(sqrt(r2)) * r;
  }
  const realv u = ustar[i] - coef * gp; /* coef = Δt/ρ0 */
  if (!all(isfinite(u))) flags_raise(flags, CLSPH_FLAG_NAN);
  vel[i] = u;
}

/* x += Δt u for the fluid (the dummies stay: no wall of this scheme translates) */
__kernel void stab_move(const uint n, const struct grid g, __global const uint *kind,
                        __global const realv *vel, const real dt, __global realv *pos,
                        __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != STAB_FLUID) return;
  const realv x = grid_wrap(&g, pos[i] + dt * vel[i]);
  if (!all(isfinite(x))) flags_raise(flags, CLSPH_FLAG_NAN);
  pos[i] = x;
}
