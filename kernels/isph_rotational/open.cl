/* open.cl (isph-rotational): entry and exit sections (Hosseini & Feng 2011 sec 3.3.2-3.3.3 and
 * eqs 16-20), built only for scenes with sections (-D ROT_OPEN=1).
 *
 * A section k is the segment a + s t, 0 <= s <= len; its unit normal n = (−t_y, t_x) points into
 * the fluid, h = (x − a)·n is the signed distance from it. Its layer particles (kind ROT_INFLOW or
 * ROT_OUTFLOW, section[i] = k) lie at −depth <= h < 0, depth = layers δr. Table `sec`, ROT_SEC
 * reals per section: a.x, a.y, t.x, t.y, len, depth, U, kind (1 inflow, 2 outflow), profile
 * (0 natural, 1 uniform, 2 parabolic), unused. Profiles, s along the section:
 * U (uniform) or 4 U s/len (1 − s/len) (parabolic, U the peak; eq 30 with y measured from a wall).
 *
 * Entry (sec 3.3.2): the layers carry the prescribed velocity u_in(s) n and move with it (they
 * are "replicas of the first line of fluid particles", rows at the lattice spacing); ũ = u_in in
 * ∇·ũ; φ (p in the homogeneous scheme) homogeneous Neumann: a layer particle takes the value of
 * the fluid particle nearest to (s, h = δr/2), its row's first fluid particle. The rotational
 * scheme's p^k (in ∇p^k of eq 9) satisfies the non-homogeneous Neumann condition (eq 15), not
 * n·∇p = 0; the paper does not say what the layers carry, so they carry eq 15 itself:
 *   p_i = p_m + (h_i − h_m) n·(ρ g + µ∇²u_m),   m the row's first fluid particle (p_near),
 * µ∇²u_m by eq 28 from u^{k+1}: a copy would impose n·∇p^k = 0 and bring back the entry
 * boundary layer the rotational scheme removes (a two-point extrapolation from the fluid's p
 * amplified the pressure noise of the corners by the layers' depth).
 * When a layer particle reaches h >= 0 it becomes a fluid particle and its row gets a new
 * particle depth behind it: a particle recycled from an exit (below), so that the count of
 * particles never changes. Until an exit has one to give, it stays a layer particle (a few
 * steps at most in a steady flow: what enters leaves; the furthest in are served first).
 * Exit (sec 3.3.3): a fluid particle that crosses the section (h < 0) becomes an exit layer
 * particle. The natural condition n·∇u = 0 (eq 17 with equilibrated pressures): its velocity and
 * ũ are those of its "progenitor in the exit layer", the fluid particle nearest to (s, δr/2);
 * with a prescribed exit profile (outflow { profile = "parabolic" }, the paper's choice above
 * Re = 10, sec 4.3.3) they are −u(s) n instead. Dirichlet φ = 0 (eq 19; p = 0 in the homogeneous
 * scheme), and p = 0 for the rotational scheme's p^k (eq 17: p = 2µ ∂u_n/∂n = 0): the value is
 * extrapolated linearly through 0 at the section from the fluid particle m nearest to the
 * particle's reflection x − 2h n (h_m >= δr/2): a_i = (h_i / h_m) a_m, an odd reflection; these
 * are rows of the pressure operator that name m with coefficient h_i/h_m (ppe.cl). The
 * rotational scheme's p^k on the exit layers is reflected the same way (p = 0 at the exit, sec
 * 3.3.3): a linear extrapolation from the fluid instead leaves the level of p free, and the
 * accumulated −µ∇·ũ of eq 20 (the projection is approximate: ∇·u is not exactly 0) then drifts
 * it without bound (by 20 times the entry-exit drop over t = 1 at δr = 0.05 H).
 * A particle beyond the last layer (h < −depth) stops and waits to be recycled into an entry. */
#ifndef ROT_OPEN
#define ROT_OPEN 0
#endif

#if ROT_OPEN
#define ROT_NO_SECTION 0xffffffffu
#define ROT_SEC        10

struct rot_section {
  realv a, t, n;   /* origin, unit tangent, unit normal into the fluid */
  real len, depth; /* length and depth of the layers, m */
  real speed;      /* U, m/s (prescribed profiles) */
  uint kind;       /* 1 inflow, 2 outflow */
  uint profile;    /* 0 natural (exit), 1 uniform, 2 parabolic */
};

struct rot_section rot_section_load(__global const real *sec, uint k)
{
  __global const real *s = sec + k * ROT_SEC;
  struct rot_section r;
  r.a = (realv)(s[0], s[1]);
  r.t = (realv)(s[2], s[3]);
  r.n = (realv)(-s[3], s[2]);
  r.len = s[4];
  r.depth = s[5];
  r.speed = s[6];
  r.kind = (uint)s[7];
  r.profile = (uint)s[8];
  return r;
}

/* normal speed of the prescribed profile at distance `along` from a */
real rot_profile(const struct rot_section *s, real along)
{
  if (s->profile == 1u) return s->speed;
  const real f = clamp(along / s->len, R(0.0), R(1.0));
  return R(4.0) * s->speed * f * (R(1.0) - f);
}

/* the fluid particle nearest to `at` with h >= hmin from section s, or `none` */
uint rot_nearest_fluid(const struct grid *g, __global const uint *cell_start,
                       __global const realv *pos, __global const uint *kind, realv at,
                       const struct rot_section *s, real hmin, uint none)
{
  real best = INFINITY;
  uint m = none;
  struct neigh_iter it;
  neigh_begin(&it, g, at);
  uint j;
  while (neigh_next(&it, g, cell_start, &j)) {
    if (kind[j] != ROT_FLUID) continue;
    const realv xj = pos[j] + it.shift;
    const realv r = at - xj;
    const real r2 = dot(r, r);
    if (r2 >= SMOOTH_SUPPORT2 || r2 >= best || dot(xj - s->a, s->n) < hmin) continue;
    best = r2;
    m = j;
  }
  return m;
}

/* Each step before the prediction, for the layer particles: velocity (u^k and u^{k−1} alike:
 * the layers have no history), ũ on the layers (wall_vel: read by rot_predict), the pressure
 * mirror and its coefficient (ppe.cl, rot_propagate), the velocity progenitor (src) and the second
 * point of the entry's pressure extrapolation (mirror2). */
__kernel void rot_open_images(const uint n, const struct grid g, __global const uint *cell_start,
                              __global const realv *pos, __global const uint *kind,
                              __global const uint *section, __global const real *sec, const real dr,
                              __global realv *vel, __global realv *vel_prev,
                              __global realv *wall_vel, __global uint *mirror, __global real *coef,
                              __global uint *src, __global uint *p_near, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const uint ki = kind[i];
  if (ki != ROT_INFLOW && ki != ROT_OUTFLOW) return;
  const struct rot_section s = rot_section_load(sec, section[i]);
  const realv x = pos[i];
  const real along = dot(x - s.a, s.t), h = dot(x - s.a, s.n);
  const realv foot = s.a + along * s.t; /* x's projection onto the section */
  /* the row's first fluid particle along the normal */
  const uint m1 =
      rot_nearest_fluid(&g, cell_start, pos, kind, foot + R(0.5) * dr * s.n, &s, -INFINITY, i);
  p_near[i] = m1;
  realv u;
  if (ki == ROT_INFLOW) {
    /* prescribed u_in (sec 3.3.2); φ copied from the row's first fluid particle (Neumann) */
    u = wall_vel[i];
    mirror[i] = m1;
    coef[i] = R(1.0);
    src[i] = i;
  } else {
    /* the exit (sec 3.3.3): n·∇u = 0 from the progenitor, or the prescribed profile */
    uint m = i;
    if (h < -s.depth) {
      u = (realv)(R(0.0)); /* beyond the last layer: waits for recycling */
    } else if (s.profile == 0u) {
      m = m1;
      u = vel[m];
    } else {
      u = -rot_profile(&s, along) * s.n;
    }
    src[i] = m;
    wall_vel[i] = u;
    /* φ = 0 (p = 0 in the homogeneous scheme) at the section: odd reflection (eq 19) */
    const real hmin = R(0.5) * dr;
    const uint r = rot_nearest_fluid(&g, cell_start, pos, kind, x - R(2.0) * h * s.n, &s, hmin, i);
    mirror[i] = r;
    coef[i] = r != i ? h / fmax(dot(pos[r] - s.a, s.n), hmin) : R(0.0);
  }
  if (!all(isfinite(u))) flags_raise(flags, CLSPH_FLAG_NAN);
  vel[i] = u;
  vel_prev[i] = u;
}

/* Dummies whose image lies among entry or exit layer particles (walls that run on through the
 * layers) take the layer particle's value: their mirror and coefficient become the layer
 * particle's (p_near keeps the layer particle for rot_open_dummy_p); after rot_open_images. */
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
  neigh_begin(&it, &g, xm);
  uint j;
  while (neigh_next(&it, &g, cell_start, &j)) {
    realv r = xm - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= SMOOTH_SUPPORT2 || j == m) continue;
    realv gw = op_grad_w(L_m, smoothing_f(sqrt(r2)), r);
    lap += R(2.0) * vol[j] * dot(r, gw) / (r2 + SMOOTH_ETA2) * (u_m - vel[j]); /* eq 28 */
  }
  const struct rot_section s = rot_section_load(sec, section[i]);
  const real dh = dot(pos[i] - xm, s.n);
  p[i] = p[m] + dh * dot(s.n, rho * accel + mu * lap); /* eq 15 */
}

/* After the motion: fluid that crossed an exit becomes an exit layer particle; role 1 for entry
 * layer particles that reached the fluid (h >= 0), 2 for exit particles beyond the last layer. */
__kernel void rot_open_classify(const uint n, __global const realv *pos, __global uint *kind,
                                __global uint *section, __global const real *sec, const uint nsec,
                                const real tol, __global uint *role)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const uint ki = kind[i];
  const realv x = pos[i];
  uint r = 0u;
  if (ki == ROT_FLUID) {
    for (uint k = 0; k < nsec; ++k) {
      const struct rot_section s = rot_section_load(sec, k);
      const real along = dot(x - s.a, s.t), h = dot(x - s.a, s.n);
      if (s.kind == 2u && h < R(0.0) && along >= -tol && along <= s.len + tol) {
        kind[i] = ROT_OUTFLOW;
        section[i] = k;
        break;
      }
    }
  } else if (ki == ROT_INFLOW || ki == ROT_OUTFLOW) {
    const struct rot_section s = rot_section_load(sec, section[i]);
    const real h = dot(x - s.a, s.n);
    if (ki == ROT_INFLOW && h >= R(0.0)) r = 1u;
    if (ki == ROT_OUTFLOW && h < -s.depth) r = 2u;
  }
  role[i] = r;
}

/* Recycling, one work item (the same run gives the same particles): each entry particle of role
 * 1 becomes fluid and an exit particle of role 2 takes its place at the back of its row, depth
 * behind it, with the row's prescribed velocity. When the exits have fewer to give than the
 * entries ask for (the fluid's volume fluctuates by a few particles), the entry particles furthest
 * into the fluid go first. Served in index order (the sort's, by cell), the same rows would wait
 * every time: their layers run on into the fluid, the gap they leave behind fills with fluid, and
 * that fluid is then upstream of the entry with nothing to bring it back.
 * count[0] += pairs made; count[1] = entry particles left waiting; count[2] = exit particles
 * left waiting. */
__kernel void rot_open_recycle(const uint n, __global const uint *role, __global uint *list,
                               __global const real *sec, __global realv *pos, __global uint *kind,
                               __global uint *section, __global realv *vel,
                               __global realv *vel_prev, __global realv *wall_vel,
                               __global realv *wall_normal, __global real *p, __global real *phi,
                               __global uint *count)
{
  if (get_global_id(0) != 0) return;
  uint ng = 0, nw = 0;
  for (uint i = 0; i < n; ++i)
    if (role[i] == 2u) list[ng++] = i;
  __global uint *want = list + ng; /* the roles are exclusive: ng + nw <= n */
  for (uint i = 0; i < n; ++i)
    if (role[i] == 1u) want[nw++] = i;
  const uint used = min(ng, nw);
  if (nw > ng) /* partial selection sort: the `used` furthest in (largest h) to the front */
    for (uint a = 0; a < used; ++a) {
      uint best = a;
      real hbest = -INFINITY;
      for (uint b = a; b < nw; ++b) {
        const struct rot_section s = rot_section_load(sec, section[want[b]]);
        const real h = dot(pos[want[b]] - s.a, s.n);
        if (h > hbest) {
          hbest = h;
          best = b;
        }
      }
      const uint t = want[a];
      want[a] = want[best];
      want[best] = t;
    }
  for (uint q = 0; q < used; ++q) {
    const uint i = want[q], j = list[q], k = section[i];
    const struct rot_section s = rot_section_load(sec, k);
    pos[j] = pos[i] - s.depth * s.n;
    kind[j] = ROT_INFLOW;
    section[j] = k;
    vel[j] = wall_vel[i];
    vel_prev[j] = wall_vel[i];
    wall_vel[j] = wall_vel[i];
    wall_normal[j] = s.n;
    p[j] = p[i];
    phi[j] = phi[i];
    kind[i] = ROT_FLUID;
    section[i] = ROT_NO_SECTION;
  }
  count[0] += used;
  count[1] = nw - used;
  count[2] = ng - used;
}
#endif /* ROT_OPEN */
