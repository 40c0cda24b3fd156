/* reduce.cl: reductions. They run on a fixed number of work-groups of REDUCE_WG items (a power
 * of two), each item walking a strided slice, and each work-group writes one partial result: a
 * few dozen values that the host finishes in double (STYLE: partial sums per work-group). */
#ifndef REDUCE_WG
#define REDUCE_WG 64
#endif

/* Tree reduction of the local array to its first element (max). */
void reduce_local_max(__local real *s)
{
  const uint l = get_local_id(0);
  for (uint w = REDUCE_WG / 2; w > 0; w >>= 1) {
    barrier(CLK_LOCAL_MEM_FENCE);
    if (l < w) s[l] = fmax(s[l], s[l + w]);
  }
  barrier(CLK_LOCAL_MEM_FENCE);
}

/* Largest speed |v| over the particles of kind `kind` (all kinds when kind < 0), one partial per
 * work-group from partial[at] on; also raises CLSPH_FLAG_NAN for a non-finite velocity. */
__kernel void reduce_max_speed(const uint n, __global const realv *vel, __global const uint *kind,
                               const int only, __global real *partial, const uint at,
                               __global uint *flags)
{
  __local real s[REDUCE_WG];
  const uint l = get_local_id(0);
  real v = R(0.0);
  for (uint i = get_global_id(0); i < n; i += get_global_size(0)) {
    if (only >= 0 && kind[i] != (uint)only) continue;
    real speed = length(vel[i]);
    if (!isfinite(speed)) flags_raise(flags, CLSPH_FLAG_NAN);
    v = fmax(v, speed);
  }
  s[l] = v;
  reduce_local_max(s);
  if (l == 0) partial[at + get_group_id(0)] = s[0];
}

/* Sum of a work-group's local values (tree). */
void reduce_local_sum(__local real *s)
{
  const uint l = get_local_id(0);
  for (uint w = REDUCE_WG / 2; w > 0; w >>= 1) {
    barrier(CLK_LOCAL_MEM_FENCE);
    if (l < w) s[l] += s[l + w];
  }
  barrier(CLK_LOCAL_MEM_FENCE);
}

/* Number of nonzero entries of a uint field (e.g. free-surface flags). */
__kernel void reduce_count(const uint n, __global const uint *field, __global real *partial)
{
  __local real s[REDUCE_WG];
  const uint l = get_local_id(0);
  real c = R(0.0);
  for (uint i = get_global_id(0); i < n; i += get_global_size(0))
    c += field[i] != 0u ? R(1.0) : R(0.0);
  s[l] = c;
  reduce_local_sum(s);
  if (l == 0) partial[get_group_id(0)] = s[0];
}

/* Sum of the x velocities and count of the fluid particles (kind 0) with x0 <= x < x0 + width,
 * x taken modulo `period` on a periodic x axis (period 0: not periodic); work-group g writes
 * its sum to partial[g] and its count to partial[get_num_groups(0) + g]. */
__kernel void reduce_slice_velocity(const uint n, __global const realv *pos,
                                    __global const realv *vel, __global const uint *kind,
                                    const real x0, const real width, const real period,
                                    __global real *partial)
{
  __local real s[REDUCE_WG];
  const uint l = get_local_id(0);
  real u = R(0.0), c = R(0.0);
  for (uint i = get_global_id(0); i < n; i += get_global_size(0)) {
    if (kind[i] != 0u) continue;
    real d = pos[i].x - x0;
    if (period > R(0.0)) d -= period * floor(d / period);
    if (d >= R(0.0) && d < width) {
      u += vel[i].x;
      c += R(1.0);
    }
  }
  s[l] = u;
  reduce_local_sum(s);
  if (l == 0) partial[get_group_id(0)] = s[0];
  s[l] = c;
  reduce_local_sum(s);
  if (l == 0) partial[get_num_groups(0) + get_group_id(0)] = s[0];
}
