/* smoothing.h: the smoothing function W(r) and F(r) = (1/r) dW/dr, so that
 * ∇_i W_ij = F(|r_ij|) r_ij with r_ij = r_i − r_j.
 * The build fixes only the function (SMOOTHING_WENDLAND_C2 | SMOOTHING_CUBIC_SPLINE |
 * SMOOTHING_GAUSSIAN); the smoothing length arrives at run time in struct smooth, which
 * host/sim/smoothing.c fills in double and struct grid (grid.cl) carries to every neighbour
 * kernel, so one program build serves every resolution.
 * Wendland C2: W = α/h^d (1 − q/2)^4 (1 + 2q), q ≤ 2 (Leroy et al. 2014 eq 1; α_2D = 7/4π).
 * Cubic spline: W = α/h^d [1 − 3q²/2 + 3q³/4] for q < 1, α/h^d (2 − q)³/4 for 1 ≤ q < 2
 *   (Monaghan 1992; α_2D = 10/7π).
 * Truncated Gaussian: W = (e^{−s²} − e^{−9}) / (π h² (1 − 10 e^{−9})) in 2-D, s ≤ 3
 *   (Hosseini & Feng 2011 eq 23). */
#define SMOOTHING_WENDLAND_C2  1
#define SMOOTHING_CUBIC_SPLINE 2
#define SMOOTHING_GAUSSIAN     3

/* Four reals, so that the layout is the same on the host (struct smooth_dev, smoothing.h there)
 * in either precision. */
struct smooth {
  real inv_h;    /* 1/h */
  real alpha;    /* normalisation divided by h^DIM */
  real support;  /* radius of the support (2h, 2h, 3h) */
  real support2; /* support² */
};

/* Regularisation of 1/r² in Laplacians, η² = 1e-4 h². Morris et al. (1997) used 0.01 h², which
 * biases the nearest neighbours (r = h/2 at h = 2δr) by 4%; Leroy et al. (eq 10) and Hosseini &
 * Feng (eq 29) use none. 1e-4 h² keeps coincident particles finite at a 0.04% bias. */
real smooth_eta2(const struct smooth sm)
{
  return R(1e-4) / (sm.inv_h * sm.inv_h);
}

/* Both functions cut at r >= sm.support exactly (not at a rounded q), like the neighbour loops. */
real smoothing_w(const struct smooth sm, real r)
{
  if (r >= sm.support) return R(0.0);
  real q = r * sm.inv_h;
#if SMOOTHING == SMOOTHING_WENDLAND_C2
  real t = fmax(R(1.0) - R(0.5) * q, R(0.0));
  real t2 = t * t;
  return sm.alpha * t2 * t2 * (R(1.0) + R(2.0) * q);
#elif SMOOTHING == SMOOTHING_CUBIC_SPLINE
  if (q < R(1.0)) return sm.alpha * (R(1.0) - R(1.5) * q * q + R(0.75) * q * q * q);
  real t = fmax(R(2.0) - q, R(0.0));
  return sm.alpha * R(0.25) * t * t * t;
#elif SMOOTHING == SMOOTHING_GAUSSIAN
  return sm.alpha * fmax(exp(-q * q) - R(1.2340980408667956e-4), R(0.0));
#else
#error "unknown SMOOTHING"
#endif
}

real smoothing_f(const struct smooth sm, real r)
{
  if (r >= sm.support) return R(0.0);
  real q = r * sm.inv_h;
  const real ih2 = sm.inv_h * sm.inv_h;
#if SMOOTHING == SMOOTHING_WENDLAND_C2
  /* dW/dq = −5 α q (1 − q/2)³ */
  real t = fmax(R(1.0) - R(0.5) * q, R(0.0));
  return R(-5.0) * sm.alpha * t * t * t * ih2;
#elif SMOOTHING == SMOOTHING_CUBIC_SPLINE
  if (q < R(1.0)) return sm.alpha * (R(-3.0) + R(2.25) * q) * ih2;
  real t = fmax(R(2.0) - q, R(0.0));
  return R(-0.75) * sm.alpha * t * t / q * ih2;
#elif SMOOTHING == SMOOTHING_GAUSSIAN
  return R(-2.0) * sm.alpha * exp(-q * q) * ih2;
#endif
}

/* The same functions of NEIGH_W distances at once (the neighbour loops in lanes, grid.cl); lane
 * by lane equal to smoothing_w and smoothing_f (test smoothing). */
realw smoothing_wl(const struct smooth sm, const realw r)
{
  const realw q = r * sm.inv_h;
#if SMOOTHING == SMOOTHING_WENDLAND_C2
  const realw t = fmax(R(1.0) - R(0.5) * q, R(0.0)), t2 = t * t;
  const realw w = sm.alpha * t2 * t2 * (R(1.0) + R(2.0) * q);
#elif SMOOTHING == SMOOTHING_CUBIC_SPLINE
  const realw t = fmax(R(2.0) - q, R(0.0));
  const realw w = select(sm.alpha * R(0.25) * t * t * t,
                         sm.alpha * (R(1.0) - R(1.5) * q * q + R(0.75) * q * q * q), q < R(1.0));
#elif SMOOTHING == SMOOTHING_GAUSSIAN
  const realw w = sm.alpha * fmax(exp(-q * q) - R(1.2340980408667956e-4), R(0.0));
#endif
  return select((realw)(R(0.0)), w, r < sm.support);
}

realw smoothing_fl(const struct smooth sm, const realw r)
{
  const realw q = r * sm.inv_h;
  const real ih2 = sm.inv_h * sm.inv_h;
#if SMOOTHING == SMOOTHING_WENDLAND_C2
  const realw t = fmax(R(1.0) - R(0.5) * q, R(0.0));
  const realw f = R(-5.0) * sm.alpha * t * t * t * ih2;
#elif SMOOTHING == SMOOTHING_CUBIC_SPLINE
  const realw t = fmax(R(2.0) - q, R(0.0));
  /* q = 0 (the particle itself) is in the first branch: the division by it is not selected */
  const realw f = select(R(-0.75) * sm.alpha * t * t / q * ih2,
                         sm.alpha * (R(-3.0) + R(2.25) * q) * ih2, q < R(1.0));
#elif SMOOTHING == SMOOTHING_GAUSSIAN
  const realw f = R(-2.0) * sm.alpha * exp(-q * q) * ih2;
#endif
  return select((realw)(R(0.0)), f, r < sm.support);
}
