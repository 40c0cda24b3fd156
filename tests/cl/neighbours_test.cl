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

/* The same lists from the loop in lanes (NEIGH_FOR_LANES): the live lanes within the support. */
__kernel void test_neigh_lanes(const uint n, const struct grid g, __global const uint *cell_start,
                               __global const realv *pos, const uint maxn, __global uint *count,
                               __global uint *list)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  uint c = 0;
  struct neigh_iter it;
  NEIGH_FOR_LANES(it, g, cell_start, x, b)
  {
    const struct lanesv r = lanes_rel(x, lanes_load_v(pos, b), it.shift);
    int lane[NEIGH_W];
    LANES_VSTORE_I(LANES_INT(neigh_live(&it, b) & (lanes_dot(r, r) < g.sm.support2)), 0, lane);
    for (uint k = 0; k < (uint)NEIGH_W; ++k) {
      if (!lane[k]) continue;
      if (c < maxn) list[i * maxn + c] = b + k;
      ++c;
    }
  }
  count[i] = c;
}
