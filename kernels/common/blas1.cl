/* blas1.cl: vector operations and dot products of the Krylov solvers (solvers/pressure/).
 * Dot products run on a fixed number of work-groups of BLAS1_WG items, each item summing a
 * strided slice, so a reduction returns a few dozen partial sums (the host adds them in double)
 * and the summation order, hence the result, is the same on every run. */
#ifndef BLAS1_WG
#define BLAS1_WG 64
#endif

/* Tree sum of a work-group's local values; the first item writes it. */
void blas1_group_sum(__local real *s, __global real *partial, uint slot)
{
  const uint l = get_local_id(0);
  for (uint w = BLAS1_WG / 2; w > 0; w >>= 1) {
    barrier(CLK_LOCAL_MEM_FENCE);
    if (l < w) s[l] += s[l + w];
  }
  if (l == 0) partial[slot] = s[0];
}

/* partial[g] = Σ x_i y_i over group g's slice */
__kernel void blas1_dot(const uint n, __global const real *x, __global const real *y,
                        __global real *partial)
{
  __local real s[BLAS1_WG];
  real acc = R(0.0);
  for (uint i = get_global_id(0); i < n; i += get_global_size(0)) acc += x[i] * y[i];
  s[get_local_id(0)] = acc;
  blas1_group_sum(s, partial, get_group_id(0));
}

/* Two dot products in one pass: partial[2g] = Σ a_i b_i, partial[2g + 1] = Σ c_i d_i */
__kernel void blas1_dot2(const uint n, __global const real *a, __global const real *b,
                         __global const real *c, __global const real *d, __global real *partial)
{
  __local real s[BLAS1_WG], t[BLAS1_WG];
  real acc = R(0.0), acc2 = R(0.0);
  for (uint i = get_global_id(0); i < n; i += get_global_size(0)) {
    acc += a[i] * b[i];
    acc2 += c[i] * d[i];
  }
  s[get_local_id(0)] = acc;
  t[get_local_id(0)] = acc2;
  blas1_group_sum(s, partial, 2 * get_group_id(0));
  blas1_group_sum(t, partial, 2 * get_group_id(0) + 1);
}

/* Σ x_i (for the mean of a singular system's solution) */
__kernel void blas1_sum(const uint n, __global const real *x, __global real *partial)
{
  __local real s[BLAS1_WG];
  real acc = R(0.0);
  for (uint i = get_global_id(0); i < n; i += get_global_size(0)) acc += x[i];
  s[get_local_id(0)] = acc;
  blas1_group_sum(s, partial, get_group_id(0));
}

/* y <- y + a x */
__kernel void blas1_axpy(const uint n, const real a, __global const real *x, __global real *y)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  y[i] += a * x[i];
}

/* w <- x + a y */
__kernel void blas1_waxpy(const uint n, __global real *w, __global const real *x, const real a,
                          __global const real *y)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  w[i] = x[i] + a * y[i];
}

/* x <- x + a p + b s */
__kernel void blas1_axpbypz(const uint n, __global real *x, const real a, __global const real *p,
                            const real b, __global const real *s)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  x[i] += a * p[i] + b * s[i];
}

/* p <- r + beta (p − omega v)  (BiCGStab search direction) */
__kernel void blas1_bicgstab_p(const uint n, __global real *p, __global const real *r,
                               const real beta, const real omega, __global const real *v)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  p[i] = r[i] + beta * (p[i] - omega * v[i]);
}

/* y <- d ∘ x (Jacobi preconditioner, d = 1 / diag) */
__kernel void blas1_scale(const uint n, __global real *y, __global const real *d,
                          __global const real *x)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  y[i] = d[i] * x[i];
}

/* z <- z + d ∘ (r − q)  (one Jacobi sweep of z toward A z = r, with q = A z) */
__kernel void blas1_jacobi_sweep(const uint n, __global real *z, __global const real *d,
                                 __global const real *r, __global const real *q)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  z[i] += d[i] * (r[i] - q[i]);
}

/* y <- y + e (d ∘ x)  (diagonal reinforcement of a singular system, Leroy et al. 2014 sec 3.3) */
__kernel void blas1_add_diag(const uint n, __global real *y, const real e, __global const real *d,
                             __global const real *x)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  y[i] += e * d[i] * x[i];
}

/* x <- x − c */
__kernel void blas1_shift(const uint n, __global real *x, const real c)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  x[i] -= c;
}

/* d <- 1 / d, and flag a zero or non-finite diagonal */
__kernel void blas1_invert(const uint n, __global real *d, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  real v = d[i];
  if (!(fabs(v) > R(0.0)) || !isfinite(v)) {
    flags_raise(flags, CLSPH_FLAG_NAN);
    v = R(1.0);
  }
  d[i] = R(1.0) / v;
}
