/* smoothing_test.cl: evaluates the smoothing function for tests/cl/test_smoothing.c. */
__kernel void test_smoothing_eval(const struct smooth sm, const uint n, __global const real *r,
                                  __global real *w, __global real *dwdr)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  w[i] = smoothing_w(sm, r[i]);
  dwdr[i] = smoothing_f(sm, r[i]) * r[i];
}

/* The same NEIGH_W radii at a time (smoothing_wl, smoothing_fl), and one at a time beside them. */
__kernel void test_smoothing_eval_lanes(const struct smooth sm, const uint nw,
                                        __global const real *r, __global real *wl,
                                        __global real *fl, __global real *w1, __global real *f1)
{
  const uint i = get_global_id(0);
  if (i >= nw) return;
  const realw q = LANES_VLOAD(i, r);
  LANES_VSTORE_R(smoothing_wl(sm, q), i, wl);
  LANES_VSTORE_R(smoothing_fl(sm, q), i, fl);
  for (uint k = NEIGH_W * i; k < NEIGH_W * (i + 1); ++k) {
    w1[k] = smoothing_w(sm, r[k]);
    f1[k] = smoothing_f(sm, r[k]);
  }
}
