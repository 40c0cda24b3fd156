/* dsolve.cl: the vector operations of the pressure solve split across ranks
 * (solvers/pressure/dsolve.c). A rank's unknowns are its owned rows [0, nown) followed by the halo
 * [nown, n), the owned rows of its neighbours that its rows reach; the products and the dot
 * products run over the owned rows only, and the halo of a vector is written from the neighbours
 * (ds_gather packs what they need of it) before a product reads it. Dot products leave per-group
 * partial sums (blas1.cl: a fixed number of work-groups, so the order, hence the value, is the
 * same on every run) that the host adds up and sums over the ranks. */

/* y = A x over the owned rows (stored rows; columns index owned and halo entries) */
__kernel void ds_spmv(const uint nown, __global const uint *row, __global const uint *col,
                      __global const real *val, __global const real *x, __global real *y)
{
  const uint i = get_global_id(0);
  if (i >= nown) return;
  y[i] = blas1_row_dot(R(0.0), row[i], row[i + 1], col, val, x);
}

/* r = b − A x over the owned rows */
__kernel void ds_residual(const uint nown, __global const uint *row, __global const uint *col,
                          __global const real *val, __global const real *x, __global const real *b,
                          __global real *r)
{
  const uint i = get_global_id(0);
  if (i >= nown) return;
  r[i] = b[i] - blas1_row_dot(R(0.0), row[i], row[i + 1], col, val, x);
}

/* Partial sums of (a, b) and (c, d) over the owned rows: partial[2 g] and partial[2 g + 1] of
 * work-group g, each item summing a strided slice. */
__kernel void ds_dot2(const uint nown, __global const real *a, __global const real *b,
                      __global const real *c, __global const real *d, __global real *partial,
                      __local real *s)
{
  const uint l = get_local_id(0), g = get_group_id(0);
  const uint stride = get_global_size(0);
  real ab = R(0.0), cd = R(0.0);
  for (uint i = get_global_id(0); i < nown; i += stride) {
    ab += a[i] * b[i];
    cd += c[i] * d[i];
  }
  s[l] = ab;
  blas1_group_sum(s, partial, 2 * g);
  barrier(CLK_LOCAL_MEM_FENCE);
  s[l] = cd;
  blas1_group_sum(s, partial, 2 * g + 1);
}

/* p = r + β (p − ω v), ph = D⁻¹ p (Jacobi) */
__kernel void ds_p(const uint nown, const real beta, const real omega, __global const real *r,
                   __global const real *v, __global const real *dinv, __global real *p,
                   __global real *ph)
{
  const uint i = get_global_id(0);
  if (i >= nown) return;
  const real q = r[i] + beta * (p[i] - omega * v[i]);
  p[i] = q;
  ph[i] = dinv[i] * q;
}

/* s = r − α v, sh = D⁻¹ s */
__kernel void ds_s(const uint nown, const real alpha, __global const real *r,
                   __global const real *v, __global const real *dinv, __global real *s,
                   __global real *sh)
{
  const uint i = get_global_id(0);
  if (i >= nown) return;
  const real q = r[i] - alpha * v[i];
  s[i] = q;
  sh[i] = dinv[i] * q;
}

/* x += α ph + ω sh, r = s − ω t */
__kernel void ds_x(const uint nown, const real alpha, const real omega, __global const real *ph,
                   __global const real *sh, __global const real *s, __global const real *t,
                   __global real *x, __global real *r)
{
  const uint i = get_global_id(0);
  if (i >= nown) return;
  x[i] += alpha * ph[i] + omega * sh[i];
  r[i] = s[i] - omega * t[i];
}

/* buf[k] = x[idx[k]]: the owned values a neighbour's halo holds, packed for the exchange */
__kernel void ds_gather(const uint m, __global const uint *idx, __global const real *x,
                        __global real *buf)
{
  const uint k = get_global_id(0);
  if (k >= m) return;
  buf[k] = x[idx[k]];
}

/* The one-sum iteration (dsolve.c, DSOLVE_ONE_SUM): BiCGStab on B = A D⁻¹ with the products
 * q = B r and y = B v and every inner product of an iteration in one reduction (after Yang &
 * Brent 2002, "improved BiCGStab"). */

/* p = r + β (p − ω v), v = q + β (v − ω y) (= B p by the recurrence), vh = D⁻¹ v */
__kernel void ds_pv(const uint nown, const real beta, const real omega, __global const real *r,
                    __global const real *q, __global const real *y, __global const real *dinv,
                    __global real *p, __global real *v, __global real *vh)
{
  const uint i = get_global_id(0);
  if (i >= nown) return;
  const real vi = v[i];
  p[i] = r[i] + beta * (p[i] - omega * vi);
  const real w = q[i] + beta * (vi - omega * y[i]);
  v[i] = w;
  vh[i] = dinv[i] * w;
}

/* s = r − α v, t = q − α y, x += D⁻¹ (α p + ω s), r = s − ω t, rh = D⁻¹ r */
__kernel void ds_xr(const uint nown, const real alpha, const real omega, __global const real *dinv,
                    __global const real *p, __global const real *v, __global const real *q,
                    __global const real *y, __global real *x, __global real *r, __global real *rh)
{
  const uint i = get_global_id(0);
  if (i >= nown) return;
  const real s = r[i] - alpha * v[i], t = q[i] - alpha * y[i], d = dinv[i];
  x[i] += d * (alpha * p[i] + omega * s);
  const real rn = s - omega * t;
  r[i] = rn;
  rh[i] = d * rn;
}

/* rh = D⁻¹ r */
__kernel void ds_scale(const uint nown, __global const real *dinv, __global const real *r,
                       __global real *rh)
{
  const uint i = get_global_id(0);
  if (i >= nown) return;
  rh[i] = dinv[i] * r[i];
}

/* The one-sum iteration's DS_NDOTS inner products over the owned rows, partial[DS_NDOTS g + k] of
 * work-group g: (r0, v) (r0, q) (r0, y) (r0, r) (q, r) (q, v) (y, r) (y, v) (q, q) (q, y) (y, y)
 * (r, r). */
#define DS_NDOTS 12
__kernel void ds_dots(const uint nown, __global const real *r0, __global const real *r,
                      __global const real *q, __global const real *v, __global const real *y,
                      __global real *partial, __local real *s)
{
  const uint l = get_local_id(0), g = get_group_id(0);
  const uint stride = get_global_size(0);
  real d[DS_NDOTS];
  for (int k = 0; k < DS_NDOTS; ++k) d[k] = R(0.0);
  for (uint i = get_global_id(0); i < nown; i += stride) {
    const real a = r0[i], ri = r[i], qi = q[i], vi = v[i], yi = y[i];
    d[0] += a * vi;
    d[1] += a * qi;
    d[2] += a * yi;
    d[3] += a * ri;
    d[4] += qi * ri;
    d[5] += qi * vi;
    d[6] += yi * ri;
    d[7] += yi * vi;
    d[8] += qi * qi;
    d[9] += qi * yi;
    d[10] += yi * yi;
    d[11] += ri * ri;
  }
  for (int k = 0; k < DS_NDOTS; ++k) {
    s[l] = d[k];
    blas1_group_sum(s, partial, DS_NDOTS * g + (uint)k);
    barrier(CLK_LOCAL_MEM_FENCE);
  }
}

/* out[i] = in[map[i]] where map[i] < nown (an owned row of the split numbering), else 0: a rank's
 * owned values into its local problem's order, the halo's left at zero (a preconditioner of the
 * owned rows alone, pslab.c) */
__kernel void ds_to_local(const uint n, const uint nown, __global const uint *map,
                          __global const real *in, __global real *out)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const uint m = map[i];
  out[i] = m < nown ? in[m] : R(0.0);
}
