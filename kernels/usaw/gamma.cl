/* gamma.cl: wall renormalisation of the unified semi-analytical walls (Leroy et al. 2014),
 * computed analytically for the 2-D Wendland C2 kernel (eqs 55-62, clean transcription in
 * shared/notes/usaw_gamma.md), and its gradient per segment (eq 6).
 *
 *   γ_a = 1 − Σ_s γ̃_as                                                            (56)
 *   γ̃_as = sign(d)/(4π) [sign(y2) ψ(q_a0, ζ2) − sign(y1) ψ(q_a0, ζ1)]              (60)
 *   ζ_i = min(½ √(q̃_a0² + y_i²/h²), 1),  q̃_a0 = min(q_a0, 2)                        (59)
 *   ψ(q, ζ) = q √(ζ² − q²/4) P(q, ζ) − (5q²/8 + 21)(q⁵/16) arccosh(2ζ/q)
 *             + 2 arctan √(4ζ²/q² − 1)                                              (61)
 *   ∇γ_as = n_s ∫_s w(r_a − r') dl'                                                 (6)
 * For segment s from v1 to v2 with unit normal n_s into the fluid: r_0 is the foot of the
 * perpendicular from r_a, d = n_s·(r_a − r_0), q_a0 = |d|/h, y_i = (v_i − r_0)·t_s. On the line
 * of a segment (q_a0 → 0) γ̃_as = (sign y2 − sign y1)/4 (eq 62): ½ on the segment, 0 beyond it.
 * At a vertex particle itself that rule would count both adjacent segments as reach-planes, so a
 * vertex takes its own γ_v = θ_v/2π (Table 2), θ_v the fluid angle the geometry computed.
 * Segments live in their own cell grid (struct grid g_seg, binned by midpoint, cells of at least
 * (support + reach the longest segment) / GRID_SUB).
 *
 * Only the ends that change γ are evaluated. Along a straight wall the segments' terms telescope:
 * at a joint where two segments continue each other on one line (same normal, the vertex the end
 * of one and the start of the other), the first segment's + sign(y) ψ(q_a0, ζ) and the second's
 * − sign(y) ψ(q_a0, ζ) are the same number, so both take ζ = 1 there (the value at the edge of
 * the support, where every segment outside it sits) and only the segment that holds the foot of
 * the perpendicular and the wall's true ends (corners, free ends) are evaluated. The gradient's
 * integral (eq 6) is written the same way, as the difference of its antiderivative at the two
 * ends (usaw_line_w, usaw_grad_gamma_line), so a particle beside a straight wall costs one ψ and
 * one antiderivative, not two ψ and 8 kernel values per segment in its support. joint[s]: bit 0
 * at a, bit 1 at b (walls.c). */
real usaw_sign(real x)
{
  return x > R(0.0) ? R(1.0) : (x < R(0.0) ? R(-1.0) : R(0.0));
}

/* eq 61 */
real usaw_psi(real q, real z)
{
  const real q2 = q * q;
  const real s = sqrt(fmax(z * z - R(0.25) * q2, R(0.0)));
  const real c = R(5.0) / R(8.0) * q2 + R(21.0);
  const real p = ((((R(-4.0) / R(3.0) * z + R(7.0)) * z - (R(5.0) / R(12.0) * q2 + R(14.0))) * z +
                   R(7.0) / R(3.0) * (q2 + R(5.0))) *
                      z -
                  R(0.25) * c * q2) *
                     z +
                 R(7.0) / R(6.0) * q2 * q2 + R(35.0) / R(6.0) * q2 - R(7.0);
  const real q5 = q2 * q2 * q;
  return q * s * p - c * q5 / R(16.0) * acosh(fmax(R(2.0) * z / q, R(1.0))) +
         R(2.0) * atan(sqrt(fmax(R(4.0) * z * z / q2 - R(1.0), R(0.0))));
}

/* Where a joint end e lies along the wall from the foot of x (the sign is all the joint's terms
 * use): from the chain's shared normal (walls.c gives every segment of a chain the same one) and
 * the shared end, so that both segments of the joint compute the same number, also when the foot
 * falls on the joint. */
real usaw_joint_y(realv e, realv x, realv t, realv n)
{
#pragma OPENCL FP_CONTRACT OFF
  realv tn = (realv)(n.y, -n.x);
  if (dot(t, tn) < R(0.0)) tn = -tn;
  const realv r = e - x;
  return r.x * tn.x + r.y * tn.y;
}

/* γ̃_as of the segment a→b (normal n into the fluid) seen from x (eqs 58-60, 62); an end that is a
 * collinear joint (bits of joint) takes ζ = 1, its term cancelling the next segment's. */
real usaw_gamma_seg(const struct smooth sm, realv x, realv a, realv b, realv n, uint joint)
{
  const real inv_h = sm.inv_h;
  realv t = b - a;
  const real len = length(t);
  t /= len;
  const real d = dot(x - a, n);
  const real q0 = fabs(d) * inv_h;
  if (q0 >= R(2.0)) return R(0.0);
  real ya = -dot(x - a, t), yb = ya + len; /* ends along t from the foot r_0 */
  if (joint & 1u) ya = usaw_joint_y(a, x, t, n);
  if (joint & 2u) yb = usaw_joint_y(b, x, t, n);
  if (q0 < R(1e-9)) return R(0.25) * (usaw_sign(yb) - usaw_sign(ya)); /* eq 62 */
  const real za =
      (joint & 1u) ? R(1.0) : fmin(R(0.5) * sqrt(q0 * q0 + ya * ya * inv_h * inv_h), R(1.0));
  const real zb =
      (joint & 2u) ? R(1.0) : fmin(R(0.5) * sqrt(q0 * q0 + yb * yb * inv_h * inv_h), R(1.0));
  const real sa = usaw_sign(ya), sb = usaw_sign(yb);
  /* Both ends at the edge of the support (ζ = 1) on one side of the foot: the segment lies
   * outside it and its two terms cancel exactly; most segments the cell loop visits are such.
   * Equal ζ on both sides (the segment spans the support): one ψ. Both give the same bits. */
  if (za == zb) {
    if (sa == sb) return R(0.0);
    return usaw_sign(d) / (R(4.0) * R(3.14159265358979323846)) * ((sb - sa) * usaw_psi(q0, zb));
  }
  return usaw_sign(d) / (R(4.0) * R(3.14159265358979323846)) *
         (sb * usaw_psi(q0, zb) - sa * usaw_psi(q0, za));
}

/* ∇γ_as = n ∫ w over the part of the segment inside the support (eq 6), eight-point
 * Gauss-Legendre. */
realv usaw_grad_gamma_seg(const struct smooth sm, realv x, realv a, realv b, realv n)
{
  const real gx[8] = {R(-0.9602898564975363), R(-0.7966664774136267), R(-0.5255324099163290),
                      R(-0.1834346424956498), R(0.1834346424956498),  R(0.5255324099163290),
                      R(0.7966664774136267),  R(0.9602898564975363)};
  const real gw[8] = {R(0.1012285362903763), R(0.2223810344533745), R(0.3137066661225691),
                      R(0.3626837833783620), R(0.3626837833783620), R(0.3137066661225691),
                      R(0.2223810344533745), R(0.1012285362903763)};
  realv t = b - a;
  const real len = length(t);
  t /= len;
  const real d = dot(x - a, n);
  const real reach2 = sm.support2 - d * d;
  if (reach2 <= R(0.0)) return (realv)(R(0.0));
  const real reach = sqrt(reach2), yfoot = dot(x - a, t); /* foot at a + yfoot t */
  const real lo = fmax(R(0.0), yfoot - reach), hi = fmin(len, yfoot + reach);
  if (hi <= lo) return (realv)(R(0.0));
#if NEIGH_W == 8 /* the eight points as one vector (smoothing_wl) */
  const realw xg = (realw)(gx[0], gx[1], gx[2], gx[3], gx[4], gx[5], gx[6], gx[7]);
  const realw wg = (realw)(gw[0], gw[1], gw[2], gw[3], gw[4], gw[5], gw[6], gw[7]);
  const realw dy = R(0.5) * (lo + hi) + R(0.5) * (hi - lo) * xg - yfoot;
  const realw sv = wg * smoothing_wl(sm, sqrt(d * d + dy * dy));
#else /* as two vectors of four */
  const realw x0 = (realw)(gx[0], gx[1], gx[2], gx[3]), x1 = (realw)(gx[4], gx[5], gx[6], gx[7]);
  const realw w0 = (realw)(gw[0], gw[1], gw[2], gw[3]), w1 = (realw)(gw[4], gw[5], gw[6], gw[7]);
  const realw dy0 = R(0.5) * (lo + hi) + R(0.5) * (hi - lo) * x0 - yfoot;
  const realw dy1 = R(0.5) * (lo + hi) + R(0.5) * (hi - lo) * x1 - yfoot;
  const realw sv = w0 * smoothing_wl(sm, sqrt(d * d + dy0 * dy0)) +
                   w1 * smoothing_wl(sm, sqrt(d * d + dy1 * dy1));
#endif
  const real s = lanes_sum(sv);
  return R(0.5) * (hi - lo) * s * n;
}

/* The segment cache (-D USAW_SEG_CACHE=K, K > 0; the scheme option segment_cache). The sweeps of
 * a USAW step (the prediction, the pressure force, the continuity equation, the pressure
 * equation's right-hand side, the projection, the shift) each walk the segment grid around every
 * particle and weight each segment's ∇γ_as (the quadrature above) by its own value: on the wedge
 * dam break (wcsph-usaw, float) the walk and the quadrature were a quarter of wcsph_continuity's
 * time. The sweeps run at the positions usaw_gamma last saw (it runs after every sort and every
 * move that precedes them), so usaw_gamma, which walks the same cells, keeps for each particle
 * the first K segments of non-zero ∇γ_as in the walk's order, each as its index with its periodic
 * image in the top bits, with the same quadrature's ∇γ_as, and their count (K + 1: more than K,
 * and the sweeps walk the grid themselves, as they do with no cache). Either way a sweep sees the
 * same segments in the same order with the same numbers: the same bits. A particle with no wall
 * in its support reads one count. On the wedge (wcsph-usaw, to 0.3 s) usaw_gamma takes 150-200
 * µs a step more and the three sweeps 190-330 µs less in double, 140-340 µs in float (filled by
 * a kernel of its own the cache cost 190-240 µs a step, by the prediction's walk 90-110 µs more
 * in the prediction in float). */
#ifndef USAW_SEG_CACHE
#define USAW_SEG_CACHE 0
#endif
#define USAW_SEG_INDEX 0x0fffffffu /* the segment's index; bits 28-29: x image, 30-31: y */
#if USAW_SEG_CACHE
#define USAW_CACHE_ARGS , __global uint *seg_cnt, __global uint *seg_list, __global realv *seg_gg
#define USAW_CACHE_PASS , seg_cnt, seg_list, seg_gg
#else
#define USAW_CACHE_ARGS
#define USAW_CACHE_PASS
#endif

/* The image of a range (neigh_iter's shift: 0 or ± the period on each axis) as two bits an axis. */
uint usaw_image_code(realv shift)
{
  const uint cx = shift.x > R(0.0) ? 1u : (shift.x < R(0.0) ? 2u : 0u);
  const uint cy = shift.y > R(0.0) ? 1u : (shift.y < R(0.0) ? 2u : 0u);
  return (cx << 28) | (cy << 30);
}

/* The shift back from its code: the same numbers the walk added (grid_wrap_axis). */
realv usaw_image_shift(const struct grid *g, uint code)
{
  const uint cx = (code >> 28) & 3u, cy = code >> 30;
  realv sh = (realv)(R(0.0));
  sh.x = cx == 1u ? g->len.x : (cx == 2u ? -g->len.x : R(0.0));
  sh.y = cy == 1u ? g->len.y : (cy == 2u ? -g->len.y : R(0.0));
  return sh;
}

/* The segments of non-zero ∇γ_as around particle i at x, in the walk's order, as ranges like
 * NEIGH_FOR's (the cache's slots are one range): s its index, shift its image's offset, gg its
 * ∇γ_as. */
struct usaw_segs {
  struct neigh_iter it;
  uint j, end;       /* the current range */
  uint k, cnt, base; /* the cache: its range given (1), count, first slot */
  int walk;          /* 1: walk the grid */
};

void usaw_segs_begin(struct usaw_segs *si, const struct grid *g_seg, realv x,
                     uint i USAW_CACHE_ARGS)
{
  si->j = si->end = 0;
  si->k = 0;
#if USAW_SEG_CACHE
  si->cnt = seg_cnt[i];
  si->base = i * (uint)USAW_SEG_CACHE;
  si->walk = si->cnt > (uint)USAW_SEG_CACHE;
#else
  (void)i;
  si->walk = 1;
#endif
  if (si->walk) neigh_begin(&si->it, g_seg, x);
}

/* The next range: the cache's slots once, or the walk's next cell range. */
int usaw_segs_range(struct usaw_segs *si, const struct grid *g_seg,
                    __global const uint *seg_start USAW_CACHE_ARGS)
{
  if (!si->walk) {
    if (si->k > 0 || si->cnt == 0) return 0;
    si->k = 1;
    si->j = 0;
    si->end = si->cnt;
    return 1;
  }
  if (!neigh_range(&si->it, g_seg, seg_start)) return 0;
  si->j = si->it.j;
  si->end = si->it.end;
  return 1;
}

/* Entry j of the current range: 0 for a segment of zero ∇γ_as (the walk skips it). */
int usaw_segs_at(struct usaw_segs *si, const struct grid *g_seg, __global const realv *seg_a,
                 __global const realv *seg_b, __global const realv *seg_n, realv x,
                 uint j USAW_CACHE_ARGS, uint *s, realv *shift, realv *gg)
{
#if USAW_SEG_CACHE
  if (!si->walk) {
    const uint code = seg_list[si->base + j];
    *gg = seg_gg[si->base + j];
    *s = code & USAW_SEG_INDEX;
    *shift = usaw_image_shift(g_seg, code);
    return 1;
  }
#endif
  const realv q =
      usaw_grad_gamma_seg(g_seg->sm, x, seg_a[j] + si->it.shift, seg_b[j] + si->it.shift, seg_n[j]);
  if (q.x == R(0.0) && q.y == R(0.0)) return 0;
  *s = j;
  *shift = si->it.shift;
  *gg = q;
  return 1;
}

/* for (each segment s of non-zero ∇γ_as gg around particle i at x, image offset sh): in a kernel
 * with USAW_SEG_ARGS, two nested loops as NEIGH_FOR (a continue goes to the next segment). */
#define USAW_SEGS_FOR(SI, X, I, S, SH, GG)                                                         \
  for (usaw_segs_begin(&(SI), &g_seg, (X), (I)USAW_CACHE_PASS);                                    \
       usaw_segs_range(&(SI), &g_seg, seg_start USAW_CACHE_PASS);)                                 \
    for (uint j_ = (SI).j; j_ < (SI).end; ++j_)                                                    \
      if (usaw_segs_at(&(SI), &g_seg, seg_a, seg_b, seg_n, (X), j_ USAW_CACHE_PASS, &(S), &(SH),   \
                       &(GG)))

/* ∫_0^s P(√(a² + t²)) dt, with P(q) = (1 − q/2)⁴ (1 + 2q) = 1 − 5q²/2 + 5q³/2 − 15q⁴/16 + q⁵/8
 * the Wendland C2 polynomial (w = α P(r/h)), for √(a² + s²) ≤ 2: the even powers of r are
 * polynomials in t, the odd ones
 *   ∫ r³ dt = t (2t² + 5a²) r / 8 + 3a⁴/8 asinh(t/a),
 *   ∫ r⁵ dt = t (8t⁴ + 26a²t² + 33a⁴) r / 48 + 5a⁶/16 asinh(t/a)     (r = √(a² + t²)). */
real usaw_line_w(real a, real s)
{
  const real a2 = a * a, a4 = a2 * a2, s2 = s * s, r = sqrt(a2 + s2);
  const real as = a > R(0.0) ? asinh(s / a) : R(0.0); /* its factors a⁴, a⁶ vanish at a = 0 */
  const real i2 = (a2 + s2 / R(3.0)) * s;
  const real i4 = (a4 + (R(2.0) / R(3.0) * a2 + s2 / R(5.0)) * s2) * s;
  const real i3 = s * (R(2.0) * s2 + R(5.0) * a2) * r / R(8.0) + R(3.0) / R(8.0) * a4 * as;
  const real i5 = s * ((R(8.0) * s2 + R(26.0) * a2) * s2 + R(33.0) * a4) * r / R(48.0) +
                  R(5.0) / R(16.0) * a4 * a2 * as;
  return s - R(2.5) * i2 + R(2.5) * i3 - R(15.0) / R(16.0) * i4 + R(0.125) * i5;
}

/* The same ∇γ_as from the antiderivative along the segment's line (usaw_line_w): t = (y − y_foot)/h
 * clipped to the support's chord ±√(4 − q_a0²); an end that is a collinear joint sits at the
 * chord's end on its side (the same cancellation as ψ in usaw_gamma_seg). The sum Σ_s ∇γ_as of
 * usaw_gamma takes it: one evaluation at the foot's segment and one per true end, where the
 * quadrature above costs 8 kernel values on every segment in the support. The antiderivative is
 * exact; the quadrature is off by up to 2.4e-6 α h where a segment straddles the foot of a point
 * within 0.01 h of its line (w's r³ and r⁵ terms are not smooth there), 5e-8 α h at 0.1 h and
 * 9e-9 α h at the first row's 0.25 h (the integral over a whole chord is up to 1.33 α h). The
 * kernels that weight each segment's ∇γ_as by its own pressure or velocity keep the quadrature,
 * which is cheaper per segment than two asinh. */
realv usaw_grad_gamma_line(const struct smooth sm, realv x, realv a, realv b, realv n, uint joint)
{
  const real inv_h = sm.inv_h;
  realv t = b - a;
  const real len = length(t);
  t /= len;
  const real q0 = fabs(dot(x - a, n)) * inv_h;
  if (q0 >= R(2.0)) return (realv)(R(0.0));
  const real chord = sqrt(R(4.0) - q0 * q0);
  const real ta = -dot(x - a, t) * inv_h, tb = ta + len * inv_h; /* ends from the foot, in h */
  const real ca =
      (joint & 1u) ? usaw_sign(usaw_joint_y(a, x, t, n)) * chord : clamp(ta, -chord, chord);
  const real cb =
      (joint & 2u) ? usaw_sign(usaw_joint_y(b, x, t, n)) * chord : clamp(tb, -chord, chord);
  if (ca == cb) return (realv)(R(0.0)); /* outside the support, or both ends cancelled */
  return sm.alpha / inv_h * (usaw_line_w(q0, cb) - usaw_line_w(q0, ca)) * n;
}

/* γ_a and ∇γ_a = Σ_s ∇γ_as (eq 7) of every particle, from the segments near it; 1 and 0 away
 * from the walls; θ_v/2π at a vertex particle (theta > 0).
 * The same loop checks that no fluid particle has crossed a wall: a particle is on the solid side
 * when it is behind the nearest segment, (r_a − c)·n_s < 0 with c its closest point on s. Where
 * several segments share the nearest point (a corner), the particle is in the fluid when it is in
 * front of any of them; a closest point at the free end of an open wall decides nothing. A
 * crossing raises CLSPH_FLAG_WALL, counts in flags[1], and keeps the deepest distance behind the
 * wall (m) in flags[2] as the bits of a float (non-negative floats order as their bits do).
 * A scheme that reads no ∇γ_a (-D USAW_GRAD_GAMMA=0: wcsph-usaw without the k-ε model, whose
 * sweeps take each segment's ∇γ_as) gets zeros: on the wedge dam break the sum was a quarter of
 * this kernel's time. */
#ifndef USAW_GRAD_GAMMA
#define USAW_GRAD_GAMMA 1
#endif
__kernel void usaw_gamma(const uint n, const struct grid g_seg, __global const uint *seg_start,
                         __global const realv *seg_a, __global const realv *seg_b,
                         __global const realv *seg_n, __global const uint *seg_joint,
                         __global const realv *pos, __global const real *theta,
                         __global real *gamma, __global realv *grad_gamma, __global uint *flags
#if USAW_SEG_CACHE
                         ,
                         __global uint *seg_cnt, __global uint *seg_list, __global realv *seg_gg
#endif
)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const realv x = pos[i];
  real g = R(1.0);
  realv gg = (realv)(R(0.0));
  real dmin = INFINITY, side = -INFINITY; /* nearest distance², best signed distance there */
  int decided = 0;
  uint cached = 0; /* segments of non-zero ∇γ_as seen (the cache) */
  struct neigh_iter it;
  NEIGH_FOR(it, g_seg, seg_start, x, s) {
    const realv a = seg_a[s] + it.shift, b = seg_b[s] + it.shift, nn = seg_n[s];
    const uint joint = seg_joint[s];
    g -= usaw_gamma_seg(g_seg.sm, x, a, b, nn, joint);
#if USAW_GRAD_GAMMA
    gg += usaw_grad_gamma_line(g_seg.sm, x, a, b, nn, joint);
#endif
#if USAW_SEG_CACHE /* the sweeps' ∇γ_as (above) */
    const realv q = usaw_grad_gamma_seg(g_seg.sm, x, a, b, nn);
    if (q.x != R(0.0) || q.y != R(0.0)) {
      if (cached < (uint)USAW_SEG_CACHE) {
        seg_list[i * (uint)USAW_SEG_CACHE + cached] = s | usaw_image_code(it.shift);
        seg_gg[i * (uint)USAW_SEG_CACHE + cached] = q;
      }
      cached = min(cached + 1u, (uint)USAW_SEG_CACHE + 1u); /* K + 1: the slots ran out */
    }
#endif
    const realv t = b - a;
    const real u = clamp(dot(x - a, t) / dot(t, t), R(0.0), R(1.0));
    const realv c = u <= R(0.0) ? a : (u >= R(1.0) ? b : a + u * t); /* corners bit-exact */
    const real d2 = dot(x - c, x - c), sd = dot(x - c, nn);
    const real tie = R(1e-6) * dot(t, t);
    const int interior = u > R(0.0) && u < R(1.0);
    if (d2 < dmin - tie) { /* a strictly nearer segment */
      dmin = d2;
      side = sd;
      decided = interior;
    } else if (d2 <= dmin + tie) { /* a corner shared with the nearest one */
      side = fmax(side, sd);
      decided = 1;
    }
  }
  const int vertex = theta[i] > R(0.0);
  gamma[i] = vertex ? theta[i] / (R(2.0) * R(3.14159265358979323846)) : g;
  grad_gamma[i] = gg;
#if USAW_SEG_CACHE
  seg_cnt[i] = cached;
#else
  (void)cached;
#endif
  if (!vertex && decided && side < R(0.0)) {
    flags_raise(flags, CLSPH_FLAG_WALL);
    atomic_inc(flags + 1);
    atomic_max(flags + 2, as_uint((float)(-side)));
  }
}
