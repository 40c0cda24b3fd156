/* krylov.cl: the BiCGStab iteration with its scalars on the device (solvers/pressure/psolve.c).
 *
 * The host enqueues a batch of iterations without waiting and reads back one small state vector
 * when the batch is done. Every dot product leaves BLAS1 partial sums (blas1.cl: a fixed number
 * of work-groups, so the sum's order, hence its value, is the same on every run) in one of the
 * sets of `part`; the kernel that needs the scalar adds that set up again, in the same order, in
 * the first item of each work-group. α, β, ω and ρ live in two slots of the state (iteration k
 * writes slot k mod 2 and reads slot (k − 1) mod 2), and every kernel of iteration k returns at
 * once when the state says the solve ended before k, so that the iterations enqueued past the
 * end cost a launch each and nothing else.
 *
 * State (KR_*): the iteration at which the solve ended (KR_BIG while it runs), why (KR_REASON:
 * the psolve_reason codes, or KR_RESTART_RHO / KR_RESTART_OMEGA for the host to restart), the
 * last relative residual, the absolute stopping tolerance, ||b||, ||r0|| of the shadow residual
 * (−1: take ||r|| at the next iteration's start), a flag raised by the diagonal's inversion, and
 * atol. */
/* The state and the scalars are kept in double wherever the device has it, also in float builds:
 * the old host loop did its scalar arithmetic in double, and in float the singular test system
 * (test_psolve, mean fixed, multigrid) took 37 iterations with float scalars against 11. */
#ifdef cl_khr_fp64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef double kreal;
#define KR(x) x
#else
typedef float kreal;
#define KR(x) x##f
#endif

#define KR_DONE    0
#define KR_REASON  1
#define KR_RNORM   2
#define KR_STOP    3
#define KR_BNORM   4
#define KR_R0NORM  5
#define KR_DIAG    6
#define KR_INIT    17 /* ||b − A x0|| / ||b||: a failed solve that ends above it keeps x0 */
#define KR_ATOL    7
#define KR_SLOT(k) (8 + 4 * ((k)&1)) /* ρ, α, ω of iteration k */
#define KR_BIG     KR(1e30)

#define KR_RESTART_RHO   10
#define KR_RESTART_OMEGA 11
#define KR_CAPACITY      12 /* the stored operator outgrew its buffers (csr_guard) */

/* Partial-sum sets (BLAS1_GROUPS partial sums each) */
#define KR_BB  0 /* (b, b) */
#define KR_RR  1 /* (r, r) */
#define KR_RHO 2 /* (r0, r) */
#define KR_R0V 3 /* (r0, v) */
#define KR_SS  4 /* (s, s) */
#define KR_TS  5 /* (t, s) */
#define KR_TT  6 /* (t, t) */
#define KR_SUM 7 /* Σ x */

#ifndef BLAS1_GROUPS
#define BLAS1_GROUPS 64
#endif

/* The sum of a set's partial sums, compensated (Kahan): in float the plain sum of 64 partials
 * loses about 64 ulps, and the singular system's mean, taken from such a sum, left it
 * inconsistent by that much (33 iterations and 8.5e-5 off UMFPACK instead of 4 and 1e-6). */
kreal kr_sum(__global const real *part, const uint set, const uint ngroups)
{
  kreal s = KR(0.0), c = KR(0.0);
  for (uint g = 0; g < ngroups; ++g) {
    const kreal y = (kreal)part[set * BLAS1_GROUPS + g] - c;
    const kreal t = s + y;
    c = (t - s) - y;
    s = t;
  }
  return s;
}

/* 1 when the solve ended before iteration k (every item of a work-group agrees) */
int kr_over(__global const kreal *st, const uint k)
{
  return st[KR_DONE] < (kreal)k;
}

/* End the solve at iteration k (first item of group 0 only) */
void kr_end(__global kreal *st, const uint k, const int reason, const kreal rnorm)
{
  st[KR_DONE] = (kreal)k;
  st[KR_REASON] = (kreal)reason;
  st[KR_RNORM] = rnorm;
}

/* Both sums of one pass: the first set in s, the second in t (local, BLAS1_WG each) */
void kr_group_sum2(__local real *s, __local real *t, __global real *part, const uint set_s,
                   const uint set_t)
{
  const uint l = get_local_id(0), g = get_group_id(0);
  for (uint w = BLAS1_WG / 2; w > 0; w >>= 1) {
    barrier(CLK_LOCAL_MEM_FENCE);
    if (l < w) {
      s[l] += s[l + w];
      t[l] += t[l + w];
    }
  }
  if (l == 0) {
    part[set_s * BLAS1_GROUPS + g] = s[0];
    part[set_t * BLAS1_GROUPS + g] = t[0];
  }
}

/* partial set `set` of (x, y) */
__kernel void kr_dot(const uint n, const uint k, __global const kreal *st, __global const real *x,
                     __global const real *y, const uint set, __global real *part)
{
  __local real s[BLAS1_WG];
  if (kr_over(st, k)) return;
  real acc = R(0.0);
  BLAS1_FOR(i, n) acc += x[i] * y[i];
  s[get_local_id(0)] = acc;
  blas1_group_sum(s, part + set * BLAS1_GROUPS, get_group_id(0));
}

/* sets KR_TS, KR_TT: (t, s) and (t, t) */
__kernel void kr_dot_ts(const uint n, const uint k, __global const kreal *st,
                        __global const real *t, __global const real *s, __global real *part)
{
  __local real a[BLAS1_WG], b[BLAS1_WG];
  if (kr_over(st, k)) return;
  real acc = R(0.0), acc2 = R(0.0);
  BLAS1_FOR(i, n)
  {
    acc += t[i] * s[i];
    acc2 += t[i] * t[i];
  }
  a[get_local_id(0)] = acc;
  b[get_local_id(0)] = acc2;
  kr_group_sum2(a, b, part, KR_TS, KR_TT);
}

/* r = b − q, with (r, r) into sets KR_RR and KR_RHO (r0 will be r) */
__kernel void kr_residual(const uint n, __global const real *b, __global const real *q,
                          __global real *r, __global real *part)
{
  __local real s[BLAS1_WG], t[BLAS1_WG];
  real acc = R(0.0);
  BLAS1_FOR(i, n)
  {
    const real v = b[i] - q[i];
    r[i] = v;
    acc += v * v;
  }
  s[get_local_id(0)] = acc;
  t[get_local_id(0)] = acc;
  kr_group_sum2(s, t, part, KR_RR, KR_RHO);
}

/* kr_dot (b, b), kr_spmv and kr_residual in one pass over the stored rows (csr.cl layout,
 * diagonal first): r = b − (A + ε diag A) x, with (b, b) into set KR_BB and (r, r) into KR_RR and
 * KR_RHO, the sums theirs to the bit */
__kernel void kr_residual_csr(const uint n, __global const real *b, __global const uint *row,
                              __global const uint *col, __global const real *val, const real eps,
                              __global const real *x, __global real *r, __global real *part)
{
  __local real s[BLAS1_WG], t[BLAS1_WG];
  real bb = R(0.0), rr = R(0.0);
  BLAS1_FOR_ROWS(i, n)
  {
    const real bi = b[i];
    const real q = blas1_row_dot(eps * val[row[i]] * x[i], row[i], row[i + 1], col, val, x);
    const real v = bi - q;
    r[i] = v;
    bb += bi * bi;
    rr += v * v;
  }
  s[get_local_id(0)] = bb;
  t[get_local_id(0)] = rr;
  kr_group_sum2(s, t, part, KR_BB, KR_RR);
  if (get_local_id(0) == 0) part[KR_RHO * BLAS1_GROUPS + get_group_id(0)] = t[0];
}

/* dst = src − mean, the mean from set KR_SUM (a consistent singular system's b and x) */
__kernel void kr_shift(const uint n, __global const real *part, const uint ngroups,
                       __global const real *src, __global real *dst)
{
  __local real c;
  if (get_local_id(0) == 0) c = (real)(kr_sum(part, KR_SUM, ngroups) / (kreal)n);
  barrier(CLK_LOCAL_MEM_FENCE);
  BLAS1_FOR(i, n) dst[i] = src[i] - c;
}

/* dst = src − Σ w src / Σ w, the sums of kr_wtotal */
__kernel void kr_wshift(const uint n, __global const real *part, const uint ngroups,
                        __global const real *src, __global real *dst)
{
  __local real c;
  if (get_local_id(0) == 0)
    c = (real)(kr_sum(part, KR_SUM, ngroups) / kr_sum(part, KR_TT, ngroups));
  barrier(CLK_LOCAL_MEM_FENCE);
  BLAS1_FOR(i, n) dst[i] = src[i] - c;
}

/* Start: ||b|| (set KR_BB) and ||r|| (set KR_RR) decide whether there is anything to do; if so,
 * r0 = r, p = v = 0, ρ = α = ω = 1, and x0 = x (the guess a failed solve falls back to). */
__kernel void kr_start(const uint n, const uint ngroups, const real rtol, const real atol,
                       __global const uint *flags, __global kreal *st, __global const real *part,
                       __global real *x, __global const real *r, __global real *r0,
                       __global real *p, __global real *v, __global real *x0)
{
  __local int what; /* 0 iterate, 1 x = 0, 2 nothing */
  const int first = get_global_id(0) == 0;
  if (get_local_id(0) == 0) {
    const kreal bnorm = sqrt(kr_sum(part, KR_BB, ngroups));
    const kreal rn = sqrt(kr_sum(part, KR_RR, ngroups));
    const kreal stop = fmax((kreal)rtol * bnorm, (kreal)atol);
    what = 0;
    if (flags[1] != 0u) { /* csr_guard: the operator did not fit; the host builds it again */
      what = 2;
      if (first) kr_end(st, 0, KR_CAPACITY, KR(0.0));
    } else if (!isfinite(bnorm)) {
      what = 2;
      if (first) kr_end(st, 0, -3, KR(0.0));
    } else if (bnorm == KR(0.0)) { /* A x = 0: x = 0 */
      what = 1;
      if (first) kr_end(st, 0, 2, KR(0.0));
    } else if (rn <= stop) {
      what = 2;
      if (first) kr_end(st, 0, rn <= (kreal)atol ? 2 : 1, rn / bnorm);
    } else if (first) {
      st[KR_DONE] = KR_BIG;
      st[KR_REASON] = KR(0.0);
      st[KR_RNORM] = rn / bnorm;
    }
    if (first) {
      st[KR_ATOL] = atol;
      st[KR_DIAG] = flags[0] != 0u ? KR(1.0) : KR(0.0);
      st[KR_STOP] = stop;
      st[KR_BNORM] = bnorm;
      st[KR_R0NORM] = rn;
      st[KR_INIT] = bnorm > KR(0.0) ? rn / bnorm : KR(0.0);
      st[KR_SLOT(0)] = st[KR_SLOT(0) + 1] = st[KR_SLOT(0) + 2] = KR(1.0);
    }
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  if (what == 2) return;
  BLAS1_FOR(i, n)
  {
    if (what == 1) {
      x[i] = R(0.0);
    } else {
      x0[i] = x[i];
      r0[i] = r[i];
      p[i] = R(0.0);
      v[i] = R(0.0);
    }
  }
}

/* Iteration k begins: the residual of k − 1 (sets KR_RR, KR_RHO) ends the solve if it is small
 * or not finite; else ρ' = (r0, r), β = (ρ'/ρ)(α/ω) and p = r + β (p − ω v), and with `scale`
 * t = dw ∘ p for the multigrid (fused, mg.cl's mg_begin_down, which also makes the cycle's fine
 * residual). check = 1: the test alone (after the last iteration of a batch). ρ' below noise
 * ||r0|| ||r|| (noise: the precision's epsilon) is the dot product's rounding alone: a breakdown,
 * restarted from r. A smaller bound let a hydrostatic tank's second solve go on with ρ' 16 orders
 * under ρ, and the next α (7e15) ruin x while the recursive residual converged. Here and in kr_s
 * the loop is written twice rather than storing t under `if (scale)`: PoCL 5 (LLVM 15) compiled
 * that conditional store to writes past n (valgrind: 8 bytes past p). kr_begin_scalars: the
 * scalars, taken by the first item of each work-group; 1 when iteration k goes on, with β, ω. */
int kr_begin_scalars(__global kreal *st, __global const real *part, const uint k,
                     const uint ngroups, const uint check, const real noise, real *beta,
                     real *omega)
{
  const int first = get_global_id(0) == 0;
  const kreal rr = kr_sum(part, KR_RR, ngroups), rho = kr_sum(part, KR_RHO, ngroups);
  const kreal bnorm = st[KR_BNORM], stop = st[KR_STOP], rn = sqrt(rr);
  if (!isfinite(rr)) {
    if (first) kr_end(st, k - 1, -3, rn / bnorm);
  } else if (rn <= stop) {
    if (first) kr_end(st, k - 1, rn <= st[KR_ATOL] ? 2 : 1, rn / bnorm);
  } else if (check) {
    if (first) st[KR_RNORM] = rn / bnorm;
  } else if (!isfinite(rho)) {
    if (first) kr_end(st, k, -3, rn / bnorm);
  } else if (fabs(rho) <= (kreal)noise * (st[KR_R0NORM] < KR(0.0) ? rn : st[KR_R0NORM]) * rn) {
    /* breakdown: the host restarts. The state ends the solve at k − 1, so that the rest of
     * iteration k does nothing (ended at k, its kernels went on with the α of iteration k − 2's
     * slot and moved x and r by it before the restart) */
    if (first) kr_end(st, k - 1, KR_RESTART_RHO, rn / bnorm);
  } else {
    const uint o = KR_SLOT(k - 1);
    *beta = (real)((rho / st[o]) * (st[o + 1] / st[o + 2]));
    *omega = (real)st[o + 2];
    if (first) {
      st[KR_SLOT(k)] = rho;
      st[KR_RNORM] = rn / bnorm;
      if (st[KR_R0NORM] < KR(0.0)) st[KR_R0NORM] = rn;
    }
    return 1;
  }
  return 0;
}

__kernel void kr_begin(const uint n, const uint k, const uint ngroups, const uint check,
                       __global kreal *st, __global const real *part, __global real *p,
                       __global const real *r, __global const real *v, const real noise,
                       const uint scale, __global const real *dw, __global real *t)
{
  __local real beta, omega; /* for the vectors, rounded as the scalars of a host loop were */
  __local int go;
  if (kr_over(st, k)) return;
  if (get_local_id(0) == 0) {
    real b = R(0.0), w = R(0.0);
    go = kr_begin_scalars(st, part, k, ngroups, check, noise, &b, &w);
    beta = b;
    omega = w;
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  if (!go) return;
  if (scale) { /* and the multigrid's first sweep (mg.cl) */
    BLAS1_FOR(i, n)
    {
      const real w = r[i] + beta * (p[i] - omega * v[i]);
      p[i] = w;
      t[i] = dw[i] * w;
    }
  } else {
    BLAS1_FOR(i, n)
    p[i] = r[i] + beta * (p[i] - omega * v[i]);
  }
}

/* α = ρ' / (r0, v) (set KR_R0V); s = r − α v with (s, s) into set KR_SS, and with `scale`
 * t = dw ∘ s for the multigrid (fused, mg.cl's mg_s_down, which also makes the cycle's fine
 * residual). kr_s_scalars: the scalars, taken by the first item of each work-group; 1 when
 * iteration k goes on, with α. */
int kr_s_scalars(__global kreal *st, __global const real *part, const uint k, const uint ngroups,
                 real *alpha)
{
  const int first = get_global_id(0) == 0;
  const kreal r0v = kr_sum(part, KR_R0V, ngroups);
  if (!isfinite(r0v)) {
    if (first) kr_end(st, k, -3, st[KR_RNORM]);
  } else if (r0v == KR(0.0)) {
    if (first) kr_end(st, k, -2, st[KR_RNORM]);
  } else {
    const kreal a = st[KR_SLOT(k)] / r0v;
    *alpha = (real)a;
    if (first) st[KR_SLOT(k) + 1] = a;
    return 1;
  }
  return 0;
}

__kernel void kr_s(const uint n, const uint k, const uint ngroups, __global kreal *st,
                   __global real *part, __global const real *r, __global const real *v,
                   __global real *s, const uint scale, __global const real *dw, __global real *t)
{
  __local real a[BLAS1_WG];
  __local real alpha;
  __local int go;
  if (kr_over(st, k)) return;
  if (get_local_id(0) == 0) {
    real al = R(0.0);
    go = kr_s_scalars(st, part, k, ngroups, &al);
    alpha = al;
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  if (!go) return;
  real acc = R(0.0);
  if (scale) { /* and the multigrid's first sweep (mg.cl) */
    BLAS1_FOR(i, n)
    {
      const real w = r[i] - alpha * v[i];
      s[i] = w;
      t[i] = dw[i] * w;
      acc += w * w;
    }
  } else {
    BLAS1_FOR(i, n)
    {
      const real w = r[i] - alpha * v[i];
      s[i] = w;
      acc += w * w;
    }
  }
  a[get_local_id(0)] = acc;
  blas1_group_sum(a, part + KR_SS * BLAS1_GROUPS, get_group_id(0));
}

/* The end of iteration k: if ||s|| is small, x += α p̂ and the solve ends; else ω = (t, s)/(t, t),
 * x += α p̂ + ω ŝ, r = s − ω t with (r, r) and (r0, r) into sets KR_RR and KR_RHO; a vanishing
 * ω asks the host for a restart. */
__kernel void kr_end_iteration(const uint n, const uint k, const uint ngroups, const real tiny,
                               __global kreal *st, __global real *part, __global real *x,
                               __global const real *ph, __global const real *sh, __global real *r,
                               __global const real *s, __global const real *t,
                               __global const real *r0)
{
  __local real a[BLAS1_WG], b[BLAS1_WG];
  __local real alpha, omega;
  __local int mode; /* 0 nothing, 1 x += α p̂, 2 the full update */
  if (kr_over(st, k)) return;
  const int first = get_global_id(0) == 0;
  if (get_local_id(0) == 0) {
    const kreal bnorm = st[KR_BNORM], sn = sqrt(kr_sum(part, KR_SS, ngroups));
    alpha = (real)st[KR_SLOT(k) + 1];
    if (sn <= st[KR_STOP]) {
      mode = 1;
      if (first) kr_end(st, k, 1, sn / bnorm);
    } else {
      const kreal ts = kr_sum(part, KR_TS, ngroups), tt = kr_sum(part, KR_TT, ngroups);
      if (!isfinite(ts) || !isfinite(tt)) {
        mode = 0;
        if (first) kr_end(st, k, -3, st[KR_RNORM]);
      } else {
        mode = 2;
        const kreal w = tt > KR(0.0) ? ts / tt : KR(0.0);
        omega = (real)w;
        if (first) {
          st[KR_SLOT(k) + 2] = w;
          if (fabs(w) <= (kreal)tiny) kr_end(st, k, KR_RESTART_OMEGA, st[KR_RNORM]);
        }
      }
    }
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  if (mode == 0) return;
  if (mode == 1) {
    BLAS1_FOR(i, n) x[i] += alpha * ph[i];
    return;
  }
  real acc = R(0.0), acc2 = R(0.0);
  BLAS1_FOR(i, n)
  {
    x[i] += alpha * ph[i] + omega * sh[i];
    const real w = s[i] - omega * t[i];
    r[i] = w;
    acc += w * w;
    acc2 += r0[i] * w;
  }
  a[get_local_id(0)] = acc;
  b[get_local_id(0)] = acc2;
  kr_group_sum2(a, b, part, KR_RR, KR_RHO);
}

/* A restart after a breakdown at iteration k (the host saw it): r0 = r, p = v = 0, the slot that
 * iteration `slot` reads set to ρ = α = ω = 1, (r0, r) = (r, r) into set KR_RHO, ||r0|| taken at
 * the next start, and the solve running again. */
__kernel void kr_restart(const uint n, const uint slot, __global kreal *st, __global real *part,
                         __global const real *r, __global real *r0, __global real *p,
                         __global real *v)
{
  __local real a[BLAS1_WG];
  if (get_global_id(0) == 0) {
    st[KR_SLOT(slot)] = st[KR_SLOT(slot) + 1] = st[KR_SLOT(slot) + 2] = KR(1.0);
    st[KR_R0NORM] = KR(-1.0);
    st[KR_DONE] = KR_BIG;
    st[KR_REASON] = KR(0.0);
  }
  real acc = R(0.0);
  BLAS1_FOR(i, n)
  {
    r0[i] = r[i];
    p[i] = R(0.0);
    v[i] = R(0.0);
    acc += r[i] * r[i];
  }
  a[get_local_id(0)] = acc;
  blas1_group_sum(a, part + KR_RHO * BLAS1_GROUPS, get_group_id(0));
}

/* Σ x into set KR_SUM */
__kernel void kr_total(const uint n, __global const real *x, __global real *part)
{
  __local real s[BLAS1_WG];
  real acc = R(0.0);
  BLAS1_FOR(i, n) acc += x[i];
  s[get_local_id(0)] = acc;
  blas1_group_sum(s, part + KR_SUM * BLAS1_GROUPS, get_group_id(0));
}

/* Σ w x into set KR_SUM and Σ w into set KR_TT (free outside the iterations): the weighted mean
 * of a singular operator whose left null vector is w (PSOLVE_MEAN with psolve_op.weight) */
__kernel void kr_wtotal(const uint n, __global const real *w, __global const real *x,
                        __global real *part)
{
  __local real s[BLAS1_WG];
  __local real t[BLAS1_WG];
  real acc = R(0.0), wacc = R(0.0);
  BLAS1_FOR(i, n)
  {
    acc += w[i] * x[i];
    wacc += w[i];
  }
  s[get_local_id(0)] = acc;
  t[get_local_id(0)] = wacc;
  blas1_group_sum(s, part + KR_SUM * BLAS1_GROUPS, get_group_id(0));
  blas1_group_sum(t, part + KR_TT * BLAS1_GROUPS, get_group_id(0));
}

/* y = (A + ε diag A) x from the stored rows (csr.cl layout, diagonal first), in iteration k */
__kernel void kr_spmv(const uint n, const uint k, __global const kreal *st,
                      __global const uint *row, __global const uint *col, __global const real *val,
                      const real eps, __global const real *x, __global real *y)
{
  if (kr_over(st, k)) return;
  const uint i = get_global_id(0);
  if (i >= n) return;
  const uint end = row[i + 1];
  y[i] = blas1_row_dot(eps * val[row[i]] * x[i], row[i], end, col, val, x);
}

/* kr_spmv and the dot product that follows it in one pass, over the reductions' fixed work-groups:
 * y = (A + ε diag A) x, with the partial sums of (a, y) into set sa and, unless sb is KR_NO_SET,
 * of (y, y) into set sb. An item's rows: BLAS1_FOR_ROWS (blas1.cl), strided on a GPU, the rows
 * kr_dot and kr_dot_ts would give it (the sums theirs to the bit), a contiguous run elsewhere. */
#define KR_NO_SET 0xffffffffu
__kernel void kr_spmv_dot(const uint n, const uint k, __global const kreal *st,
                          __global const uint *row, __global const uint *col,
                          __global const real *val, const real eps, __global const real *x,
                          __global real *y, __global const real *a, const uint sa, const uint sb,
                          __global real *part)
{
  __local real s[BLAS1_WG], q[BLAS1_WG];
  if (kr_over(st, k)) return;
  real acc = R(0.0), acc2 = R(0.0);
  BLAS1_FOR_ROWS(i, n)
  {
    const real yi = blas1_row_dot(eps * val[row[i]] * x[i], row[i], row[i + 1], col, val, x);
    y[i] = yi;
    acc += a[i] * yi;
    acc2 += yi * yi;
  }
  s[get_local_id(0)] = acc;
  q[get_local_id(0)] = acc2;
  if (sb == KR_NO_SET)
    blas1_group_sum(s, part + sa * BLAS1_GROUPS, get_group_id(0));
  else
    kr_group_sum2(s, q, part, sa, sb);
}

/* y = d ∘ x (Jacobi), in iteration k */
__kernel void kr_scale(const uint n, const uint k, __global const kreal *st, __global real *y,
                       __global const real *d, __global const real *x)
{
  if (kr_over(st, k)) return;
  const uint i = get_global_id(0);
  if (i >= n) return;
  y[i] = d[i] * x[i];
}

/* z += d ∘ (r − q) (a Jacobi sweep toward A z = r, q = A z), in iteration k */
__kernel void kr_sweep(const uint n, const uint k, __global const kreal *st, __global real *z,
                       __global const real *d, __global const real *r, __global const real *q)
{
  if (kr_over(st, k)) return;
  const uint i = get_global_id(0);
  if (i >= n) return;
  z[i] += d[i] * (r[i] - q[i]);
}
