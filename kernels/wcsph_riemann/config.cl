/* config.cl (wcsph-riemann): the particle configuration of an advection step (Wang, Sun & Hu,
 * sec 2.5, after Zhang, Rezavand & Hu 2020): the neighbour list the acoustic sub-steps reuse, the
 * kernel gradient correction matrix B (eq 20) and the density re-initialisation.
 *
 * Conventions: r_ij = x_i − x_j (the nearest periodic image), ∇_i W_ij = F(r) r_ij with
 * F = W'(r)/r < 0 (common/smoothing.h), V_j = m_j/ρ_j for fluid and open-boundary layer particles
 * and dr² for dummy wall particles. Kinds: WCR_FLUID moves; WCR_DUMMY is a fixed wall particle
 * whose state each fluid particle extrapolates for itself (acoustic.cl); WCR_INFLOW and
 * WCR_OUTFLOW are the entry and exit layers, whose state the open-boundary module sets; WCR_PARKED
 * particles wait behind an exit for an entry (common/open.cl), in no list.
 *
 * The list: the neighbours j != i within r_list = support + skin at the start of the advection
 * step, at most WCR_MAXN each (CLSPH_FLAG_NEIGH_OVERFLOW beyond), row i at nlist[i WCR_MAXN ...].
 * The pairs are fixed for the advection step, as in the dual-criteria scheme, but each sum
 * recomputes r_ij from the current positions (F = 0 beyond the support), and the skin (twice
 * the farthest a particle moves in the step, the host's) holds every pair that comes within the
 * support during the step. Without it the pairs that closed in during a step went unseen until
 * its end: the coarse Lobovsky dam break (cases/dam_break.lua, n = 20) clustered where its surge
 * hit the far wall (t = 0.385 s; pairs 0.075 dr apart).
 *
 * B_i = (−Σ_j r_ij ⊗ ∇W_ij V_j)^−1 (eq 20) over every neighbour. Where the support is truncated
 * (a free surface, a lone particle) the matrix A = −Σ r_ij ⊗ ∇W_ij V_j becomes singular; the
 * paper does not say what it does there, and we blend the inverse with the identity as its code
 * (SPHinXsys) does: B = w A^−1 + (1 − w) I, w = det A / (det A + max(WCR_B_DET − det A, 0)), so
 * that B = A^−1 where det A >= WCR_B_DET (0.3; det A = 1 in a full support, about 0.5 on a flat
 * free surface) and B → I as det A → 0.
 *
 * Density (Zhang et al. 2020 sec 3.2): ρ_sum = ρ0 Σ_j W_ij / Σ_j W⁰_ij, W⁰ on the initial lattice
 * (its sum, with V = dr², is sigma0 = Σ W⁰ dr², computed on the host); the density is re-set at
 * each advection step to ρ_sum (flows without a free surface, reinit = 1) or to max(ρ, ρ_sum)
 * (free-surface flows, reinit = 2, where the truncated sum would pull the surface in); reinit = 0
 * keeps the continuity equation's density. */
#define WCR_FLUID   0u
#define WCR_DUMMY   2u
#define WCR_INFLOW  3u
#define WCR_OUTFLOW 4u
#define WCR_PARKED  5u /* KIND_PARKED: waits behind an exit, out of every sum */
#ifndef WCR_MAXN
#define WCR_MAXN 64
#endif
#define WCR_B_DET R(0.3)
#ifndef WCR_ETA
#define WCR_ETA R(3.0) /* η of the dissipation limiter (eq 18) */
#endif
#ifndef WCR_CONT_RIEMANN
#define WCR_CONT_RIEMANN 1
#endif
#ifndef WCR_ARD
#define WCR_ARD 0
#endif
#ifndef WCR_WALL_CONT_NORMAL
#define WCR_WALL_CONT_NORMAL 0
#endif
#ifndef WCR_TURB
#define WCR_TURB 0 /* the k-ε model (turbulence.cl) */
#endif
#ifndef WCR_WALL_FULL
#define WCR_WALL_FULL 0
#endif
#ifndef WCR_MOM_DISS
#define WCR_MOM_DISS 1 /* eq 19's dissipative term between fluid pairs (acoustic.cl) */
#endif
#ifndef WCR_GATE
#define WCR_GATE 0 /* a lifted wall group (solvers/gate): its dummies' mirror (acoustic.cl) */
#endif
#ifndef WCR_TVF_SURFACE
#define WCR_TVF_SURFACE 0 /* the surface rows' correction: 1 tangential, 2 near pairs */
#endif
/* the area of a lattice cell's face, dr^(DIM−1) */
#if DIM == 2
#define WCR_FACE(dr) (dr)
#else
#define WCR_FACE(dr) ((dr) * (dr))
#endif
#ifndef WCR_SHEAR_ROW1
#define WCR_SHEAR_ROW1 0 /* wall_shear = "first_row": τ_w on the first row (advection.cl) */
#endif
#ifndef WCR_WALL_PNORMAL
#define WCR_WALL_PNORMAL 0 /* the dummies' pressure force along their wall normal (acoustic.cl) */
#endif
#ifndef WCR_REC
#define WCR_REC 0 /* wall groups whose force the sub-steps record (force.cl), 0: none */
#endif
#define WCR_PAIR_KAPPA R(0.25) /* the near pairs' push (advection.cl) */
/* below this normalised kernel sum a particle is spray: no correction (advection.cl) */
#define WCR_SURF_SIGMA_MIN R(0.3)

/* r_ij between the nearest images on the periodic axes (the support is shorter than half a
 * period: the grid needs 2 GRID_SUB + 1 cells on a periodic axis) */
realv wcr_sep(realv xi, realv xj, const struct grid *g)
{
  realv r = xi - xj;
#if PERIODIC_X
  r.x -= g->len.x * rint(r.x / g->len.x);
#endif
#if PERIODIC_Y
  r.y -= g->len.y * rint(r.y / g->len.y);
#endif
#if PERIODIC_Z && DIM == 3
  r.z -= g->len.z * rint(r.z / g->len.z);
#endif
  return r;
}

/* The matrices A = −Σ r_ij ⊗ ∇W_ij V_j and B = A^−1 of eq 20, symmetric: in 2-D a real4
 * (xx, xy, yx, yy), in 3-D a real8 (xx, xy, xz, yy, yz, zz, 0, 0) */
#if DIM == 2
typedef real4 wcr_mat;
#define WCR_MAT_ZERO ((real4)(R(0.0)))
#define WCR_MAT_I    ((real4)(R(1.0), R(0.0), R(0.0), R(1.0)))
#else
typedef real8 wcr_mat;
#define WCR_MAT_ZERO ((real8)(R(0.0)))
#define WCR_MAT_I    ((real8)(R(1.0), R(0.0), R(0.0), R(1.0), R(0.0), R(1.0), R(0.0), R(0.0)))
#endif

/* a − f r ⊗ r: one pair's term of A (f = F V_j, ∇W_ij = F r_ij) */
wcr_mat wcr_moment(wcr_mat a, real f, realv r)
{
#if DIM == 2
  a.x -= f * r.x * r.x;
  a.y -= f * r.x * r.y;
  a.w -= f * r.y * r.y;
  a.z = a.y;
#else
  a.s0 -= f * r.x * r.x;
  a.s1 -= f * r.x * r.y;
  a.s2 -= f * r.x * r.z;
  a.s3 -= f * r.y * r.y;
  a.s4 -= f * r.y * r.z;
  a.s5 -= f * r.z * r.z;
#endif
  return a;
}

/* B = w A^−1 + (1 − w) I for the symmetric A */
wcr_mat wcr_correction(wcr_mat a)
{
#if DIM == 2
  const real axx = a.x, axy = a.y, ayy = a.w;
  const real det = axx * ayy - axy * axy;
  if (!(det > R(1e-12))) return WCR_MAT_I;
  const real4 inv = (real4)(ayy, -axy, -axy, axx) / det;
#else
  const real c00 = a.s3 * a.s5 - a.s4 * a.s4, c01 = a.s2 * a.s4 - a.s1 * a.s5;
  const real c02 = a.s1 * a.s4 - a.s2 * a.s3;
  const real det = a.s0 * c00 + a.s1 * c01 + a.s2 * c02;
  if (!(det > R(1e-12))) return WCR_MAT_I;
  const real8 inv = (real8)(c00, c01, c02, a.s0 * a.s5 - a.s2 * a.s2, a.s1 * a.s2 - a.s0 * a.s4,
                            a.s0 * a.s3 - a.s1 * a.s1, R(0.0), R(0.0)) /
                    det;
#endif
  const real lack = fmax(WCR_B_DET - det, R(0.0)), w = det / (det + lack);
  return w * inv + (R(1.0) - w) * WCR_MAT_I;
}

/* A dummy particle's pressure, extrapolated from fluid particle i (r = x_i − x_w, a_prior the
 * acceleration i has from everything but the pressure): p_w = p_i − ρ_i a_prior·r, the steady
 * balance ∇p = ρ a_prior along r. Under the k-ε wall model (WCR_TURB) only the normal part and
 * gravity's tangential part: p_w = p_i − ρ_i [(a_prior·n)(r·n) + g·(r − (r·n) n)]. Along the
 * wall a_prior also holds the viscous force, the wall model's shear and a body force that drives
 * a channel, which no pressure gradient balances; read as one, they made a pressure force along a
 * flat wall: in the periodic channel (cases/channel_ke.lua, 20 rows) the bulk velocity fell to
 * 0.64 of the reference's by t = 1000. With the normal part alone it is 6.7% under it, the walls'
 * pressure force along x is −1.6% of ρ u_τ², the wall model carries u_τ² within 0.5%, and the
 * wall-adjacent row's u, k and ε are within 3% of OpenFOAM's (the same wall function, 20 cells). */
real wcr_wall_pressure(real pi, real ri, realv ai, realv r, realv nw, realv gravity)
{
#if WCR_TURB
  const real rn = dot(r, nw);
  return pi - ri * (dot(ai, nw) * rn + dot(gravity, r - rn * nw));
#else
  (void)nw;
  (void)gravity;
  return pi - ri * dot(ai, r);
#endif
}

/* With wall_pressure = "gradient" (WCR_WALL_PGRAD): the pressure along the wall extrapolated
 * with i's own gradient ∇p_i (wcr_pressure_gradient, acoustic.cl), the normal part as above,
 *   p_w = p_i − ρ_i (a_prior·n)(r·n) − (∇p_i − (∇p_i·n) n)·r,
 * where the mirror keeps p_i along the wall and so leaves a pressure gradient along the wall out
 * of the dummy half of i's support: the first row of a lattice (h = 1.3 dr, Wendland C2) feels
 * 0.78 of it, the second 0.995, so that a boundary layer meets 0.78 of an adverse gradient
 * (gravity's part along the wall is in ∇p_i, and comes in once). */
real wcr_wall_pressure_grad(real pi, real ri, realv ai, realv r, realv nw, realv gp)
{
  const real rn = dot(r, nw);
  const realv gt = gp - dot(gp, nw) * nw;
  return pi - ri * dot(ai, nw) * rn - dot(gt, r);
}

/* The pair's mean of a diffusivity (µ_eff of eq 21, D_k and D_ε of eqs 23-24): the harmonic
 * mean 2ab/(a + b) (Wang, Sun & Hu, after eq 21). The logarithmic mean (a − b)/ln(a/b), exact for
 * a diffusivity linear between the two, moved the channel's steady bulk velocity by 0.4%
 * (cases/channel_ke.lua, 20 rows). */
real wcr_pair_mean(real a, real b)
{
  return R(2.0) * a * b / (a + b);
}

/* the record a dummy particle's pair forces go to: 1 + the index of its wall's group among the
 * scene's force groups (force.cl), 0: not recorded */
uint wcr_rec_group(uint j, __global const uint *wall, __global const uint *wgroup, uint nwall)
{
  const uint k = wall[j];
  return k < nwall ? wgroup[k] : 0u;
}

/* B applied to a vector */
realv wcr_apply(wcr_mat b, realv v)
{
#if DIM == 2
  return (realv)(b.x * v.x + b.y * v.y, b.z * v.x + b.w * v.y);
#else
  return (realv)(b.s0 * v.x + b.s1 * v.y + b.s2 * v.z, b.s1 * v.x + b.s3 * v.y + b.s4 * v.z,
                 b.s2 * v.x + b.s4 * v.y + b.s5 * v.z, R(0.0));
#endif
}

#if WCR_TURB && WCR_WALL_PNORMAL
/* wall_pressure_force = "normal": a dummy particle's pressure pair f (p_i + p_w) B_i r_iw (eq 19)
 * along its wall's normal n_w, but for the share of p_w that i's pressure gradient along the
 * wall gives it (wcr_wall_pressure_grad), which keeps its direction: that share is how the first
 * row feels the whole of a gradient along the wall. A wall at one pressure pushes along its
 * normal; the pair sum of a uniform pressure, Σ_w f B_i r_iw, has a part along the wall wherever
 * the first row is not a lattice over the dummies' (its positions over their columns, B_i's
 * off-diagonal part in a sheared row): in the k-ε channel (cases/channel_ke.lua, N_f = 40) a
 * push of 1% of τ_w on the fluid over 300-600 δ/U_b, by which the drive that holds its flow rate
 * stood under the walls' friction.
 * Projecting the whole pair instead loses the gradient's share too (0.22 of it on a lattice's
 * first row). gp: i's ∇p (wall_pressure = "gradient"), or ρ_i g (the mirror's share of
 * gravity along the wall: wcr_wall_pressure). */
realv wcr_wall_push(real f, real psum, wcr_mat bi, realv r, realv nw, realv gp)
{
  const realv br = wcr_apply(bi, r);
  const real dp = -dot(gp - dot(gp, nw) * nw, r);
  return f * ((psum - dp) * dot(br, nw) * nw + dp * br);
}
#endif

/* The configuration of the fluid and layer particles: list, B, ρ, the normalised kernel sum
 * sigma = Σ_j W_ij dr² / sigma0 (1 in a full support; advection.cl tells the free surface by it)
 * and the distance to the nearest dummy particle less dr/2 (about the distance to the wall; for
 * the wall-adjacent layers of a wall model; −1: no dummy particle within the support). */
__kernel void wcr_config(const uint n, const struct grid g, __global const uint *cell_start,
                         __global const realv *pos, __global const real *vol,
                         __global const uint *kind, const real rlist2, const real dr,
                         const real sigma0, const real rho0, const uint reinit,
                         __global uint *nlist, __global uint *ncount, __global wcr_mat *bmat,
                         __global real *sigma, __global real *rho, __global real *wall_dist,
                         __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  if (kind[i] == WCR_DUMMY || kind[i] == WCR_PARKED) {
    ncount[i] = 0u;
    return;
  }
  const realv x = pos[i];
  wcr_mat a = WCR_MAT_ZERO;
  real s = smoothing_w(g.sm, R(0.0)), dmin = INFINITY;
  uint c = 0u;
  __global uint *row = nlist + (size_t)i * WCR_MAXN;
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    const realv r = x - (pos[j] + it.shift);
    const real r2 = dot(r, r);
    if (r2 >= rlist2 || j == i || kind[j] == WCR_PARKED) continue;
    if (c < WCR_MAXN) row[c] = j;
    ++c;
    if (r2 >= g.sm.support2) continue;
    const real rr = sqrt(r2), vj = vol[j], f = smoothing_f(g.sm, rr) * vj;
    a = wcr_moment(a, f, r); /* −Σ r ⊗ ∇W V (eq 20) */
    s += smoothing_w(g.sm, rr);
    if (kind[j] == WCR_DUMMY) dmin = fmin(dmin, rr);
  }
  if (c > WCR_MAXN) {
    flags_raise(flags, CLSPH_FLAG_NEIGH_OVERFLOW);
    c = WCR_MAXN;
  }
  ncount[i] = c;
  bmat[i] = wcr_correction(a);
#if DIM == 2
  const real sn = s * dr * dr / sigma0;
#else
  const real sn = s * dr * dr * dr / sigma0;
#endif
  sigma[i] = sn;
  wall_dist[i] = isfinite(dmin) ? fmax(dmin - R(0.5) * dr, R(0.0)) : R(-1.0);
  if (kind[i] != WCR_FLUID) return;
  const real rs = rho0 * sn;
  if (reinit == 1u)
    rho[i] = rs;
  else if (reinit == 2u)
    rho[i] = fmax(rho[i], rs);
}

/* Σ of the fluid particles' list lengths (pairs per sum over the fluid), per work-group */
__kernel void wcr_count_pairs(const uint n, __global const uint *kind, __global const uint *ncount,
                              __global real *partial)
{
  __local real s[REDUCE_WG];
  const uint l = get_local_id(0);
  real c = R(0.0);
  for (uint i = get_global_id(0); i < n; i += get_global_size(0))
    c += kind[i] == WCR_FLUID ? (real)ncount[i] : R(0.0);
  s[l] = c;
  reduce_local_sum(s);
  if (l == 0) partial[get_group_id(0)] = s[0];
}
