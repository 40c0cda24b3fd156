/* native.c: the common operators as plain OpenMP loops (native.h). One generic row function,
 * inlined into one loop per operator with the operator a constant, so that each loop carries only
 * its own arithmetic, as each device kernel does. */
#include "native.h"

#include <math.h>
#include <omp.h>

#include "clsph_config.h"

#define NATIVE_INLINE static inline __attribute__((always_inline))

int native_out_width(enum op_kind op)
{
  switch (op) {
  case OP_CORRECTION:
    return 4;
  case OP_GRAD_SYM:
  case OP_GRAD_ANTISYM:
    return 2;
  default:
    return 1;
  }
}

/* L v for a symmetric 2 × 2 matrix stored (xx, xy, yy, unused); the identity when L is NULL */
NATIVE_INLINE void mat_apply(const real *L, real vx, real vy, real *ox, real *oy)
{
  if (L == NULL) {
    *ox = vx;
    *oy = vy;
    return;
  }
  *ox = L[0] * vx + L[1] * vy;
  *oy = L[1] * vx + L[2] * vy;
}

/* one particle's sum, the operator's arithmetic as in operators.cl (Wendland C2 as in
 * kernels/common/smoothing.h) */
NATIVE_INLINE long native_row(const enum op_kind op, const int kgc, const struct native_set *s,
                              const real *in, size_t i, real *out)
{
  const real *pos = s->pos, *vol = s->vol;
  const real support2 = (real)(4.0 * s->h * s->h), inv_h = (real)(1.0 / s->h);
  const real alpha = (real)s->alpha, ci = (real)s->cell_inv;
  const real ih2 = inv_h * inv_h, eta2 = (real)(1e-4 * s->h * s->h);
  const real *Li = kgc ? s->L + 4 * i : NULL;
  const real xi = pos[2 * i], yi = pos[2 * i + 1];
  const real ai = op == OP_DIV || op == OP_SHEPARD || op == OP_CORRECTION ? 0 : in[i];
  const real uxi = op == OP_DIV ? in[2 * i] : 0, uyi = op == OP_DIV ? in[2 * i + 1] : 0;
  const int cx = (int)(xi * ci), cy = (int)(yi * ci), sub = s->sub;
  const int x0 = cx - sub < 0 ? 0 : cx - sub, x1 = cx + sub >= s->nc[0] ? s->nc[0] - 1 : cx + sub;
  real a0 = 0, a1 = 0, a2 = 0;
  long count = 0;
  for (int y = cy - sub; y <= cy + sub; ++y) {
    if (y < 0 || y >= s->nc[1]) continue;
    const cl_uint end = s->start[y * s->nc[0] + x1 + 1];
    for (cl_uint j = s->start[y * s->nc[0] + x0]; j < end; ++j) {
      const real rx = xi - pos[2 * j], ry = yi - pos[2 * j + 1];
      const real r2 = rx * rx + ry * ry;
      if (r2 >= support2) continue;
      ++count;
      const real q = real_sqrt(r2) * inv_h;
      real t = 1 - (real)0.5 * q;
      t = t > 0 ? t : 0;
      if (op == OP_SHEPARD || op == OP_INTERP) {
        const real t2 = t * t, w = alpha * t2 * t2 * (1 + 2 * q);
        a0 += vol[j] * (op == OP_INTERP ? in[j] : 1) * w;
        continue;
      }
      if (j == i) continue;
      const real f = -5 * alpha * t * t * t * ih2;
      real gx, gy; /* ∇_i W_ij, corrected where the operator corrects it */
      switch (op) {
      case OP_CORRECTION: {
        const real vf = vol[j] * f;
        a0 += -vf * rx * rx;
        a1 += -vf * rx * ry;
        a2 += -vf * ry * ry;
        break;
      }
      case OP_GRAD_SYM:
        mat_apply(Li, f * rx, f * ry, &gx, &gy);
        a0 += vol[j] * (in[j] - ai) * gx;
        a1 += vol[j] * (in[j] - ai) * gy;
        break;
      case OP_GRAD_ANTISYM:
        if (kgc) { /* Σ V (A_i L_j + A_j L_i) ∇W */
          real lx, ly;
          mat_apply(s->L + 4 * j, f * rx, f * ry, &lx, &ly);
          mat_apply(Li, f * rx, f * ry, &gx, &gy);
          a0 += vol[j] * (ai * lx + in[j] * gx);
          a1 += vol[j] * (ai * ly + in[j] * gy);
        } else {
          a0 += vol[j] * (ai + in[j]) * f * rx;
          a1 += vol[j] * (ai + in[j]) * f * ry;
        }
        break;
      case OP_DIV:
        mat_apply(Li, f * rx, f * ry, &gx, &gy);
        a0 += vol[j] * ((in[2 * j] - uxi) * gx + (in[2 * j + 1] - uyi) * gy);
        break;
      case OP_LAP:
        mat_apply(Li, f * rx, f * ry, &gx, &gy);
        a0 += 2 * vol[j] * (ai - in[j]) * (rx * gx + ry * gy) / (r2 + eta2);
        break;
      default:
        break;
      }
    }
  }
  switch (op) {
  case OP_CORRECTION: { /* the inverse, or I where it is nearly singular (operators.cl) */
    const real det = a0 * a2 - a1 * a1;
    if (!(det > (real)1e-2)) {
      out[4 * i] = 1;
      out[4 * i + 1] = 0;
      out[4 * i + 2] = 1;
    } else {
      const real inv = 1 / det;
      out[4 * i] = a2 * inv;
      out[4 * i + 1] = -a1 * inv;
      out[4 * i + 2] = a0 * inv;
    }
    out[4 * i + 3] = 0;
    break;
  }
  case OP_GRAD_SYM:
  case OP_GRAD_ANTISYM:
    out[2 * i] = a0;
    out[2 * i + 1] = a1;
    break;
  default:
    out[i] = a0;
    break;
  }
  return count;
}

/* one function per operator and correction switch, the operator a constant in its loop (OpenMP
 * outlines the loop before inlining, so the constant must be there already) */
// clang-format off
#define NATIVE_SWEEP_FN(NAME, OP, KGC)                                                             \
  static long NAME(const struct native_set *s, const real *in, real *out)                          \
  {                                                                                                \
    long count = 0;                                                                                \
    _Pragma("omp parallel for schedule(static) reduction(+ : count)")                              \
    for (size_t i = 0; i < s->n; ++i) count += native_row(OP, KGC, s, in, i, out);                 \
    return count;                                                                                  \
  }
// clang-format on
NATIVE_SWEEP_FN(sweep_correction, OP_CORRECTION, 0)
NATIVE_SWEEP_FN(sweep_shepard, OP_SHEPARD, 0)
NATIVE_SWEEP_FN(sweep_interp, OP_INTERP, 0)
NATIVE_SWEEP_FN(sweep_grad_sym, OP_GRAD_SYM, 0)
NATIVE_SWEEP_FN(sweep_grad_sym_kgc, OP_GRAD_SYM, 1)
NATIVE_SWEEP_FN(sweep_grad_antisym, OP_GRAD_ANTISYM, 0)
NATIVE_SWEEP_FN(sweep_grad_antisym_kgc, OP_GRAD_ANTISYM, 1)
NATIVE_SWEEP_FN(sweep_div, OP_DIV, 0)
NATIVE_SWEEP_FN(sweep_div_kgc, OP_DIV, 1)
NATIVE_SWEEP_FN(sweep_lap, OP_LAP, 0)
NATIVE_SWEEP_FN(sweep_lap_kgc, OP_LAP, 1)

/* the loop of each operator, without and with the correction (those with no gradient inside
 * ignore it) */
typedef long (*native_sweep)(const struct native_set *, const real *, real *);
static const native_sweep sweeps[OP_COUNT][2] = {
    [OP_CORRECTION] = {sweep_correction, sweep_correction},
    [OP_SHEPARD] = {sweep_shepard, sweep_shepard},
    [OP_INTERP] = {sweep_interp, sweep_interp},
    [OP_GRAD_SYM] = {sweep_grad_sym, sweep_grad_sym_kgc},
    [OP_GRAD_ANTISYM] = {sweep_grad_antisym, sweep_grad_antisym_kgc},
    [OP_DIV] = {sweep_div, sweep_div_kgc},
    [OP_LAP] = {sweep_lap, sweep_lap_kgc},
};

double native_op(enum op_kind op, const struct native_set *s, const real *in, real *out,
                 long *pairs)
{
  const double t0 = omp_get_wtime();
  *pairs = op >= 0 && op < OP_COUNT ? sweeps[op][s->L != NULL](s, in, out) : 0;
  return omp_get_wtime() - t0;
}
