/* smoothing_test.cl: evaluates the smoothing function for tests/cl/test_smoothing.c. */
__kernel void test_smoothing_eval(const struct smooth sm, const uint n, __global const real *r,
                                  __global real *w, __global real *dwdr)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  w[i] = smoothing_w(sm, r[i]);
  dwdr[i] = smoothing_f(sm, r[i]) * r[i];
}

/* The same four radii at a time (smoothing_w4, smoothing_f4), and one at a time beside them. */
__kernel void test_smoothing_eval4(const struct smooth sm, const uint n4, __global const real *r,
                                   __global real *w4, __global real *f4, __global real *w1,
                                   __global real *f1)
{
  const uint i = get_global_id(0);
  if (i >= n4) return;
  const real4 q = vload4(i, r);
  vstore4(smoothing_w4(sm, q), i, w4);
  vstore4(smoothing_f4(sm, q), i, f4);
  for (uint k = 4 * i; k < 4 * i + 4; ++k) {
    w1[k] = smoothing_w(sm, r[k]);
    f1[k] = smoothing_f(sm, r[k]);
  }
}
