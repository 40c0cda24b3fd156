/* neighbours_test.cl: the neighbour loop of grid.cl writes each particle's neighbours (within the
 * support, itself included) for tests/cl/test_neighbours.c. */
__kernel void test_neigh_list(const uint n, const struct grid g, __global const uint *cell_start,
                              __global const realv *pos, const uint maxn, __global uint *count,
                              __global uint *list)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  uint c = 0;
  struct neigh_iter it;
  neigh_begin(&it, &g, x);
  uint j;
  while (neigh_next(&it, &g, cell_start, &j)) {
    realv r = x - (pos[j] + it.shift);
    if (dot(r, r) >= g.sm.support2) continue;
    if (c < maxn) list[i * maxn + c] = j;
    ++c;
  }
  count[i] = c;
}

/* The same lists from the loop four at a time (NEIGH_FOR4): the live lanes within the support. */
__kernel void test_neigh_list4(const uint n, const struct grid g, __global const uint *cell_start,
                               __global const realv *pos, const uint maxn, __global uint *count,
                               __global uint *list)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  uint c = 0;
  struct neigh_iter it;
  NEIGH_FOR4(it, g, cell_start, x, b)
  {
    const struct lanesv r = lanes_rel(x, lanes_load_v(pos, b), it.shift);
    const int4 in = convert_int4(neigh_live4(&it, b) & (lanes_dot(r, r) < g.sm.support2));
    const int lane[4] = {in.x, in.y, in.z, in.w};
    for (uint k = 0; k < 4u; ++k) {
      if (!lane[k]) continue;
      if (c < maxn) list[i * maxn + c] = b + k;
      ++c;
    }
  }
  count[i] = c;
}
