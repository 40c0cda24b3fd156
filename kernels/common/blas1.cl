/* blas1.cl: the work-group sum of the Krylov solvers' reductions and the vector operations that
 * set up a solve (solvers/pressure/); the iteration's own kernels are in krylov.cl. Reductions run
 * on a fixed number of work-groups of BLAS1_WG items, each item summing a strided slice, so the
 * summation order, hence the result, is the same on every run. */
#ifndef BLAS1_WG
#define BLAS1_WG 64
#endif

/* The rows of a reduction's work-item. On a GPU both loops below stride by the launch's size, so
 * that neighbouring items take neighbouring rows (coalesced). On other devices (the host's
 * BLAS1_CONTIGUOUS_ROWS, prog.c; CLSPH_REDUCE_ROWS chooses) PoCL runs a work-group's items one
 * after the other as a loop, vectorised across them where it can: BLAS1_FOR gives each work-group
 * a contiguous chunk of rows, its items strided by the group's size (contiguous vectors, and one
 * stream a group instead of one every launch's size), and BLAS1_FOR_ROWS, for the kernels whose
 * item sums a stored row (kr_spmv_dot, kr_residual_csr), which PoCL does not vectorise, gives each
 * item a contiguous run of rows, read in order. PoCL on 2 cores, the 240² cavity (58560 rows),
 * µs a launch, strided → these: kr_spmv_dot 2739 → 758, kr_residual_csr 3231 → 884,
 * kr_end_iteration 430 → 182, kr_begin 244 → 116; on the 120² about the same either way, but
 * kr_spmv_dot 226 → 177 (with contiguous runs in the vector kernels too they took 3 times as long
 * there). Every item loops as many times as the group's others and skips the rows past its end:
 * with a trip count of its own, 0 past the last row, PoCL 3.1 entered the loop of a work-group's
 * first empty item when the group's others had rows, and ran it 2^32 times (the 80² to 130²
 * cavities). The sums' order is fixed by the launch, so the same on every run. */
#ifndef BLAS1_CONTIGUOUS_ROWS
#define BLAS1_CONTIGUOUS_ROWS 0
#endif
#if BLAS1_CONTIGUOUS_ROWS
/* the work-group's chunk of rows, blas1_chunk(n) of them from group × blas1_chunk(n); each item
 * loops over the chunk rounded up to the group's size */
uint blas1_chunk(const uint n)
{
  const uint groups = (uint)get_num_groups(0);
  return (n + groups - 1u) / groups;
}
uint blas1_chunk_span(const uint n)
{
  const uint l = (uint)get_local_size(0);
  return (blas1_chunk(n) + l - 1u) / l * l;
}
#define BLAS1_FOR(i, n)                                                                            \
  for (uint i##_c = (uint)get_local_id(0), i##_k = blas1_chunk(n), i##_s = blas1_chunk_span(n),    \
            i = (uint)get_group_id(0) * i##_k + i##_c;                                             \
       i##_c < i##_s; i##_c += (uint)get_local_size(0), i += (uint)get_local_size(0))              \
    if (i##_c < i##_k && i < (n))
#else
#define BLAS1_FOR(i, n) for (uint i = get_global_id(0); i < (n); i += get_global_size(0))
#endif
#if BLAS1_CONTIGUOUS_ROWS
uint blas1_run(const uint n)
{
  const uint items = (uint)get_global_size(0);
  return (n + items - 1u) / items;
}
#define BLAS1_FOR_ROWS(i, n)                                                                       \
  for (uint i##_c = 0u, i##_run = blas1_run(n), i = (uint)get_global_id(0) * i##_run;              \
       i##_c < i##_run; ++i##_c, ++i)                                                              \
    if (i < (n))
#else
#define BLAS1_FOR_ROWS(i, n) BLAS1_FOR(i, n)
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

/* s + Σ_{k in [k0, k1)} val[k] x[col[k]]: a stored row times x, in four partial sums (a single sum
 * waits on each multiply-add before the next: the CPU's floating-point latency, not memory, set
 * the speed of the solve's row sweeps). NAME's values are of type VT (mg.cl keeps a float copy). */
#define BLAS1_ROW_DOT(NAME, VT)                                                                    \
  real NAME(real s, uint k, const uint k1, __global const uint *col, __global const VT *val,       \
            __global const real *x)                                                                \
  {                                                                                                \
    real s1 = R(0.0), s2 = R(0.0), s3 = R(0.0);                                                    \
    for (; k + 4 <= k1; k += 4) {                                                                  \
      s += val[k] * x[col[k]];                                                                     \
      s1 += val[k + 1] * x[col[k + 1]];                                                            \
      s2 += val[k + 2] * x[col[k + 2]];                                                            \
      s3 += val[k + 3] * x[col[k + 3]];                                                            \
    }                                                                                              \
    for (; k < k1; ++k) s += val[k] * x[col[k]];                                                   \
    return (s + s1) + (s2 + s3);                                                                   \
  }
BLAS1_ROW_DOT(blas1_row_dot, real)

/* y <- y + a x */
__kernel void blas1_axpy(const uint n, const real a, __global const real *x, __global real *y)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  y[i] += a * x[i];
}

/* y <- y + e (d ∘ x)  (diagonal reinforcement of a singular system, Leroy et al. 2014 sec 3.3) */
__kernel void blas1_add_diag(const uint n, __global real *y, const real e, __global const real *d,
                             __global const real *x)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  y[i] += e * d[i] * x[i];
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
