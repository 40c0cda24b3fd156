/* viscous.cl (USAW schemes): the velocity prediction without pressure (eq 31),
 *   u*_a = u^n_a + δt [ (1/ρ) L_a{µ, u} + g + f ],
 * with the laminar USAW viscous term (eq 15)
 *   (1/ρ) L_a{µ, u} = (2ν/γ_a) Σ_b V_b u_ab r_ab·∇w_ab / r_ab²
 *                      − (2ν/γ_a) Σ_s (u^R_as · t_as / δr_as) t_as |∇γ_as|,
 * u^R_as = u_a − u_s the velocity relative to the segment, t_as its unit tangential direction
 * (eq 16), δr_as = max(r_as·n_s, d_min) (eq 17 with d_min = δr). The segment term stands for the
 * kernel sum cut off by the wall: for a linear shear u = y ∂u/∂n it cancels the fluid sum,
 * 2 ∇u·∇γ_a, only where δr_as is the particle's own distance. With the paper's d_min = δr the
 * first row (δr/2 off the wall) feels half its wall shear and slips: steady Couette flow at 30
 * rows, Re 1, moves the first row 0.0138 U ahead of the exact profile and lowers the core's
 * shear by 2%; with d_min = δr/2 (isph-usaw's default; scheme option wall_distance_floor) the
 * slip is 0.0008 U. For fluid particles the wall term is taken implicitly (at u*, a 2 x 2 solve
 * per particle): its rate 2ν|∇γ_as|/(γ_a δr_as) reaches about 1.6 ν/δr² in the first row with
 * d_min = δr/2, which with the viscous bound δt ≤ 0.125 h²/ν on top of the fluid sum's own made
 * the explicit step unstable (the cylinder array, Stokes flow, blew up at its 50th step). Vertex
 * particles keep the paper's explicit form: their u* is not a velocity they take but the wall
 * condition's input (eq 43), and taken implicitly it let the lid of the 100² and 120² cavities at
 * Re 100 drive particles through the side walls at the corners within 0.07 s (both hold to t = 1
 * with the vertices explicit). visc gets (u* − u^n)/δt − g
 * − f, the viscous acceleration, which the wall condition needs. It runs for vertex particles too:
 * their u* enters the wall condition of the pressure equation through the segments (eq 43). */
#if USAW_TURB
/* Under the k-ε model (usaw/turbulence.cl): ν_t, the vertices' own velocity u_vertex (eq 24; read
 * and advanced here), ∇γ (the vertices' normal), and the outputs u* (u_star: the friction velocity
 * from the nearest segment, eq 23) and y+ = δr_as u* / ν (y_plus). */
#define USAW_PREDICT_TURB_ARGS                                                                     \
  , __global const real *nu_t, __global realv *u_vertex, __global const realv *ggam,               \
      __global real *u_fric, __global real *yplus
#else
#define USAW_PREDICT_TURB_ARGS
#endif
/* The wall term's sums over the segments (below): M = Σ_s c_s P_s and b = Σ_s c_s P_s u_s,
 * P_s = I − n_s n_sᵀ. */
struct usaw_wall_m {
  real m11, m12, m22;
  realv b;
};

void usaw_wall_m_add(struct usaw_wall_m *w, const real c, const realv nn, const realv us)
{
  w->m11 += c * (R(1.0) - nn.x * nn.x);
  w->m12 -= c * nn.x * nn.y;
  w->m22 += c * (R(1.0) - nn.y * nn.y);
  w->b += c * (us - dot(us, nn) * nn);
}

/* M u */
realv usaw_wall_mu(const struct usaw_wall_m *w, const realv u)
{
  realv mu;
  mu.x = w->m11 * u.x + w->m12 * u.y;
  mu.y = w->m12 * u.x + w->m22 * u.y;
  return mu;
}

/* δr_as = max(r_as·n_s, d_min) (eq 17), r_as from the segment's middle */
real usaw_seg_drs(const realv x, const realv a, const realv e, const realv nn, const real d_min)
{
  return fmax(dot(x - R(0.5) * (a + e), nn), d_min);
}

/* u* from the sums: lapg = the fluid's viscous term (ν lap/γ), ti = δt for a fluid particle (the
 * wall term implicit, below) and 0 for a vertex, acc = its acc_p of the last step. */
realv usaw_predict_solve(const struct usaw_wall_m *w, const realv u, const realv lapg,
                         const realv accel, const real dt, const real ti, const realv acc)
{
  const real te = dt - ti;
  const realv q = ti * acc;
  const realv mu = usaw_wall_mu(w, u);
  const realv rhs = u + dt * (lapg + w->b + accel) - te * mu + q;
  const real a11 = R(1.0) + ti * w->m11, a12 = ti * w->m12, a22 = R(1.0) + ti * w->m22;
  const real det = a11 * a22 - a12 * a12;
  realv us;
  us.x = (a22 * rhs.x - a12 * rhs.y) / det - q.x;
  us.y = (a11 * rhs.y - a12 * rhs.x) / det - q.y;
  return us;
}

__kernel void usaw_predict(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *vel, const real dt,
                           const real nu, const real d_min, const realv accel,
                           __global realv *ustar, __global realv *visc,
                           __global const realv *acc_p USAW_PREDICT_TURB_ARGS)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] > ISPH_VERTEX) return;
  const realv x = pos[i];
#if USAW_TURB
  const int vertex = kind[i] == ISPH_VERTEX;
  const realv u = vertex ? u_vertex[i] : vel[i];
  const real nti = nu_t[i], lap_scale = R(1.0); /* lap carries ν_E,a + ν_E,b (eq 22) */
  real near = INFINITY, near_u = R(0.0);        /* the nearest segment's δr_as and u* */
#else
  const realv u = vel[i];
  /* lap carries 2 (eq 15) */
  const real lap_scale = nu;
#endif
  realv lap = (realv)(R(0.0));
  struct neigh_iter it;
  struct lanesv lap4 = lanes_zero_v();
  /* in lanes (grid.cl), i itself left out (a vertex's u is not vel[i] under the model) */
  NEIGH_FOR_LANES(it, g, cell_start, x, b)
  {
    const struct lanesv r = lanes_rel(x, lanes_load_v(pos, b), it.shift);
    const maskw take = neigh_live(&it, b) &
                       LANES_MASK(lanes_load_u(kind, b) <= (uintw)(ISPH_VERTEX)) &
                       neigh_other(b, i);
#if USAW_TURB
    const realw nu_ab = R(2.0) * nu + nti + lanes_load(nu_t, b);
#else
    const realw nu_ab = (realw)(R(2.0));
#endif
    /* r·∇w / r² = F */
    const realw wf =
        lanes_keep(nu_ab * lanes_load(vol, b) * smoothing_fl(g.sm, sqrt(lanes_dot(r, r))), take);
    lanes_acc_v(&lap4, wf, lanes_sub_from(u, lanes_load_v(vel, b)));
  }
  lap = lanes_total_v(lap4);
  /* the wall term −Σ_s c_s P_s (u − u_s), c_s = 2ν|∇γ_as|/(γ_a δr_as), P_s = I − n_s n_sᵀ,
   * taken at u*: M = Σ_s c_s P_s, b = Σ_s c_s P_s u_s */
  struct usaw_wall_m wm = {R(0.0), R(0.0), R(0.0), (realv)(R(0.0))};
#if !USAW_TURB
  const real cg = R(2.0) * nu / gam[i];
#endif
  struct usaw_segs si; /* the segments of non-zero ∇γ_as (gamma.cl) */
  uint s;
  realv sh, gg;
  USAW_SEGS_FOR(si, x, i, s, sh, gg)
  {
    const realv a = seg_a[s] + sh, e = seg_b[s] + sh, nn = seg_n[s];
    const real ggn = length(gg);
    if (ggn == R(0.0)) continue;
    const realv us = R(0.5) * (vel[inv[seg_v1[s]]] + vel[inv[seg_v2[s]]]);
    const real drs = usaw_seg_drs(x, a, e, nn, d_min);
#if USAW_TURB /* eq 22: u*²_as along t_as, the rate 2 u*²/u_t of the tangential slip (eq 23) */
    const real rate = usaw_wall_rate(u - us, nn, drs, nu);
    const real c = rate * ggn / gam[i];
    if (drs < near) {
      near = drs;
      near_u = sqrt(R(0.5) * rate * length((u - us) - dot(u - us, nn) * nn));
    }
#else
    const real c = cg * ggn / drs;
#endif
    usaw_wall_m_add(&wm, c, nn, us);
  }
  /* fluid: the wall term at v = u* + δt q, q = acc_p the pressure's acceleration of the last step
   * (the projection's (ũ − u*)/δt, or wcsph-usaw's pressure force), v the best guess of the new
   * velocity: (I + δt M) v = u + δt (ν lap/γ + b + g + f + q), a 2 x 2 solve (det ≥ 1 as M ≥ 0),
   * u* = v − δt q. Taken at u* itself, the wall dragged on the body force that the pressure
   * balances: in a tank at rest u* = g δt, so the first row by a side wall lagged the rest by
   * g δt² c each step (c the wall term's rate), a sliding the projection cannot take back
   * (normal to the wall it is divergence-free); it grew to 0.025 √(gH) in 5 s at δr = 0.02 m with
   * d_min = δr/2. With q a steady state is exact for the pressure's part as for the body force's
   * (ν lap/γ + b − M u + g + f + q = 0).
   * Vertices: the paper's explicit u* = u + δt (ν lap/γ − M u + b + g + f) */
  const real ti = kind[i] == ISPH_FLUID ? dt : R(0.0);
  const realv us = usaw_predict_solve(&wm, u, lap_scale * lap / gam[i], accel, dt, ti, acc_p[i]);
#if USAW_TURB
  if (vertex) { /* eq 24: the viscous term alone moves it, along the wall (∇γ_v is its normal) */
    const realv gv = ggam[i];
    const real gl = length(gv);
    /* L_v{μ_E, u}/ρ at the vertex's own velocity */
    const realv av = lap / gam[i] + wm.b - usaw_wall_mu(&wm, u);
    realv uv = u + dt * av;
    if (gl > R(0.0)) uv -= dot(uv, gv / gl) * (gv / gl);
    u_vertex[i] = uv;
    /* the wall condition's input (eq 43) as without the model: the wall's velocity plus δt times
     * the viscous and the body accelerations */
    ustar[i] = vel[i] + dt * (av + accel);
    visc[i] = av;
    return;
  } else {
    u_fric[i] = near_u;
    yplus[i] = isinf(near) ? R(0.0) : near * near_u / nu;
  }
#endif
  ustar[i] = us;
  visc[i] = (us - u) / dt - accel;
}
