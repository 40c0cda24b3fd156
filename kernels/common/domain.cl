/* domain.cl: the fluid stays in the scene's domain (host/sim/domain.c). A fluid particle (kind 0)
 * that has left the domain takes the kind CLSPH_KIND_OUT and is counted in flags[3]; the host
 * sorts it past the others and drops it, or stops the run when too many have left
 * (host/sim/checks.c). It has left when it is more than `margin` (dr) beyond the box lo .. hi,
 * the domain's own, on a closed side (that far out it is behind any wall on the domain's edge by
 * more than the wall-crossing check allows), or beyond a closed side at all while above an open
 * one: over the rim of the walls that stand on the domain's edge, it leaves at once, before it
 * falls behind them (where it would read as a wall crossing). The sides gravity points away from
 * (`open`, bits as GRID_OPEN in grid.cl) are unbounded: a splash rises above an open tank and
 * falls back, the cell grid clamping it into its top cells. The grid itself reaches several
 * spacings beyond the domain, for the wall and section layers: its own escape test alone let a
 * jet run 0.75 m out of a unit box. */
int domain_left(const realv x, const real4 lo, const real4 hi, const real margin, const uint open)
{
  int beyond = 0, far = 0, above = 0;
#define DOMAIN_AXIS(C, A, PER)                                                                     \
  if (!(PER)) {                                                                                    \
    if (C > hi.s##A) {                                                                             \
      if (open & (1u << A))                                                                        \
        above = 1;                                                                                 \
      else {                                                                                       \
        beyond = 1;                                                                                \
        far |= C > hi.s##A + margin;                                                               \
      }                                                                                            \
    } else if (C < lo.s##A) {                                                                      \
      if (open & (16u << A))                                                                       \
        above = 1;                                                                                 \
      else {                                                                                       \
        beyond = 1;                                                                                \
        far |= C < lo.s##A - margin;                                                               \
      }                                                                                            \
    }                                                                                              \
  }
  DOMAIN_AXIS(REALV_X(x), 0, PERIODIC_X)
  DOMAIN_AXIS(REALV_Y(x), 1, PERIODIC_Y)
#if DIM == 3
  DOMAIN_AXIS(REALV_Z(x), 2, PERIODIC_Z)
#endif
#undef DOMAIN_AXIS
  return far || (beyond && above);
}

/* The step's end in one launch (host/sim/domain.c, sim_step_end): the domain check above over
 * the fluid, then the largest norm of up to `nvec` (0 to 2) vector fields, v0 over the particles
 * of kind kind0 and v1 over kind1 (all kinds when negative), the kinds as the check leaves them:
 * one partial per work-group at partial[at0 + group] and partial[at1 + group] (reduce.cl's
 * layout), a non-finite norm raising CLSPH_FLAG_NAN. */
__kernel void step_end(const uint n, __global const realv *pos, __global uint *kind, const real4 lo,
                       const real4 hi, const real margin, const uint open, const uint nvec,
                       __global const realv *v0, const int kind0, const uint at0,
                       __global const realv *v1, const int kind1, const uint at1,
                       __global real *partial, __global uint *flags)
{
  __local real s[REDUCE_WG];
  const uint l = get_local_id(0);
  real m0 = R(0.0), m1 = R(0.0);
  for (uint i = get_global_id(0); i < n; i += get_global_size(0)) {
    uint k = kind[i];
    if (k == 0u && domain_left(pos[i], lo, hi, margin, open)) {
      kind[i] = k = CLSPH_KIND_OUT;
      atomic_inc(&flags[3]);
    }
    if (nvec > 0u && (kind0 < 0 || k == (uint)kind0)) {
      const real a = length(v0[i]);
      if (!isfinite(a)) flags_raise(flags, CLSPH_FLAG_NAN);
      m0 = fmax(m0, a);
    }
    if (nvec > 1u && (kind1 < 0 || k == (uint)kind1)) {
      const real a = length(v1[i]);
      if (!isfinite(a)) flags_raise(flags, CLSPH_FLAG_NAN);
      m1 = fmax(m1, a);
    }
  }
  if (nvec > 0u) {
    s[l] = m0;
    reduce_local_max(s);
    if (l == 0u) partial[at0 + get_group_id(0)] = s[0];
  }
  if (nvec > 1u) {
    s[l] = m1;
    reduce_local_max(s);
    if (l == 0u) partial[at1 + get_group_id(0)] = s[0];
  }
}
