/* open.cl (isph-rotational): what the scheme's entry and exit sections need besides the shared
 * machinery of kernels/common/open.cl (Hosseini & Feng 2011 sec 3.3.2-3.3.3 and eqs 16-20: the
 * sections, the layers' velocity, the recycling), built only for scenes with sections
 * (-D OPEN_SECTIONS=1): the pressure rows of the layers, the history of their velocity, ũ of the
 * exit layers and the rotational p on the entry layers.
 *
 * Entry (sec 3.3.2): ũ = u_in in ∇·ũ (the layers' wall_vel, which open_layer_velocity keeps);
 * φ (p in the homogeneous scheme) homogeneous Neumann: a layer particle takes the value of the
 * fluid particle nearest to (s, h = δr/2), its row's first fluid particle (p_near, from
 * open_layer_velocity). The rotational scheme's p^k (in ∇p^k of eq 9) satisfies the
 * non-homogeneous Neumann condition (eq 15), not n·∇p = 0; the paper does not say what the layers
 * carry, so they carry eq 15 itself:
 *   p_i = p_m + (h_i − h_m) n·(ρ g + µ∇²u_m),   m the row's first fluid particle (p_near),
 * µ∇²u_m by eq 28 from u^{k+1}: a copy would impose n·∇p^k = 0 and bring back the entry
 * boundary layer the rotational scheme removes (a two-point extrapolation from the fluid's p
 * amplified the pressure noise of the corners by the layers' depth).
 * Exit (sec 3.3.3): the velocity and ũ are those of the progenitor (n·∇u = 0; vel_src, from
 * open_layer_velocity) or the prescribed profile. Dirichlet φ = 0 (eq 19; p = 0 in the
 * homogeneous scheme), and p = 0 for the rotational scheme's p^k (eq 17: p = 2µ ∂u_n/∂n = 0): the
 * value is extrapolated linearly through 0 at the section from the fluid particle m nearest to the
 * particle's reflection x − 2h n (h_m >= δr/2): a_i = (h_i / h_m) a_m, an odd reflection; these
 * are rows of the pressure operator that name m with coefficient h_i/h_m (ppe.cl). The
 * rotational scheme's p^k on the exit layers is reflected the same way (p = 0 at the exit, sec
 * 3.3.3): a linear extrapolation from the fluid instead leaves the level of p free, and the
 * accumulated −µ∇·ũ of eq 20 (the projection is approximate: ∇·u is not exactly 0) then drifts
 * it without bound (by 20 times the entry-exit drop over t = 1 at δr = 0.05 H). */
#if OPEN_SECTIONS
/* Each step after open_layer_velocity, for the layer particles: u^{k−1} = u^k (the layers have
 * no history), and the pressure mirror and its coefficient (ppe.cl, rot_propagate): at an entry
 * the row's first fluid particle (p_near) with 1 (Neumann), at an exit the odd reflection. */
__kernel void rot_open_mirrors(const uint n, const struct grid g, __global const uint *cell_start,
                               __global const realv *pos, __global const uint *kind,
                               __global const uint *section, __global const real *sec,
                               const real dr, __global const uint *p_near,
                               __global const realv *vel, __global realv *vel_prev,
                               __global uint *mirror, __global real *coef)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const uint ki = kind[i];
  if (ki != ROT_INFLOW && ki != ROT_OUTFLOW) return;
  vel_prev[i] = vel[i];
  if (ki == ROT_INFLOW) { /* φ copied from the row's first fluid particle (Neumann) */
    mirror[i] = p_near[i];
    coef[i] = R(1.0);
    return;
  }
  /* φ = 0 (p = 0 in the homogeneous scheme) at the section: odd reflection (eq 19) */
  const struct open_section s = open_section_load(sec, section[i]);
  const realv x = pos[i];
  const real h = dot(x - s.a, s.n), hmin = R(0.5) * dr;
  const uint r = open_nearest_fluid(&g, cell_start, pos, kind, x - R(2.0) * h * s.n, &s, hmin, i);
  mirror[i] = r;
  coef[i] = r != i ? h / fmax(dot(pos[r] - s.a, s.n), hmin) : R(0.0);
}

/* Dummies whose image lies among entry or exit layer particles (walls that run on through the
 * layers) take the layer particle's value: their mirror and coefficient become the layer
 * particle's (p_near keeps the layer particle for rot_open_dummy_p); after rot_open_mirrors. */
__kernel void rot_open_dummies(const uint n, __global const uint *kind, __global uint *mirror,
                               __global real *coef, __global uint *p_near)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ROT_DUMMY) return;
  const uint m = mirror[i];
  p_near[i] = i;
  if (kind[m] != ROT_INFLOW && kind[m] != ROT_OUTFLOW) return;
  p_near[i] = m;
  mirror[i] = mirror[m];
  coef[i] = coef[m];
}

/* p of those dummies: the entry layer particle's (eq 15, after rot_open_pressure) */
__kernel void rot_open_dummy_p(const uint n, __global const uint *kind, __global const uint *p_near,
                               __global real *p)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ROT_DUMMY || p_near[i] == i) return;
  p[i] = p[p_near[i]];
}

/* ũ of the exit layers: that of their progenitor (sec 3.3.3, "we assign the ũ value of the ...
 * exit layer to the image particles"); after rot_predict */
__kernel void rot_open_ustar(const uint n, __global const uint *kind, __global const uint *src,
                             __global realv *ustar)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ROT_OUTFLOW || src[i] == i) return;
  ustar[i] = ustar[src[i]];
}

/* p^{k+1} on the entry layers of the rotational scheme (eq 15, see the header), from u^{k+1};
 * after rot_project and rot_propagate */
__kernel void rot_open_pressure(OP_ARGS, __global const uint *kind, __global const uint *section,
                                __global const real *sec, __global const uint *p_near,
                                __global const realv *vel, const real rho, const real mu,
                                const realv accel, __global real *p)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ROT_INFLOW) return;
  const uint m = p_near[i];
  if (m == i) return;
  const realv xm = pos[m], u_m = vel[m];
  const realm L_m = OP_LOAD_L(m);
  realv lap = (realv)(R(0.0));
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, xm, j) {
    realv r = xm - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == m) continue;
    realv gw = op_grad_w(L_m, smoothing_f(g.sm, sqrt(r2)), r);
    lap += R(2.0) * vol[j] * dot(r, gw) / (r2 + smooth_eta2(g.sm)) * (u_m - vel[j]); /* eq 28 */
  }
  const struct open_section s = open_section_load(sec, section[i]);
  const real dh = dot(pos[i] - xm, s.n);
  p[i] = p[m] + dh * dot(s.n, rho * accel + mu * lap); /* eq 15 */
}
#endif /* OPEN_SECTIONS */
