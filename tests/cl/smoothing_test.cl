/* smoothing_test.cl: evaluates the smoothing function for tests/cl/test_smoothing.c. */
__kernel void test_smoothing_eval(const struct smooth sm, const uint n, __global const real *r,
                                  __global real *w, __global real *dwdr)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  w[i] = smoothing_w(sm, r[i]);
  dwdr[i] = smoothing_f(sm, r[i]) * r[i];
}
