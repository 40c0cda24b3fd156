/* open.cl (common): entry and exit sections, the part that does not depend on the scheme
 * (Hosseini & Feng 2011 sec 3.3.2-3.3.3), for solvers/open; built only for scenes with sections
 * (-D OPEN_SECTIONS=1, set by open_define): without them this file compiles to nothing.
 *
 * A section k is the segment a + s t, 0 <= s <= len; its unit normal n = (−t_y, t_x) points into
 * the fluid, h = (x − a)·n is the signed distance from it. Its layer particles (kind OPEN_INFLOW
 * or OPEN_OUTFLOW, section[i] = k) lie at −depth <= h < 0, depth = layers δr. Table `sec`,
 * OPEN_SEC reals per section: a.x, a.y, t.x, t.y, len, depth, U, kind (1 inflow, 2 outflow),
 * profile (0 natural, 1 uniform, 2 parabolic), ramp T, park (an exit's: 0, or the distance behind
 * the section, beyond its last layer, where its particles wait for an entry). Profiles, s along the
 * section: U (uniform) or 4 U s/len (1 − s/len) (parabolic, U the peak; eq 30 with y measured from
 * a wall), times ½(1 − cos(π t/T)) while t < T (a prescribed velocity that rises smoothly: a
 * weakly-compressible fluid set going at once takes a pressure pulse ρ c0 U, a density change of
 * U/c0, that runs up and down the channel; T = 0: at once, the paper's start).
 *
 * Per particle (fields of solvers/open): section[i] (OPEN_NO_SECTION off the layers); near[i],
 * the layer particle's "row's first fluid particle", the fluid particle nearest to (s, h = δr/2);
 * src[i], its velocity progenitor (itself where the velocity is prescribed); u_layer[i], the
 * layers' velocity (the scheme's boundary-velocity field: it holds the geometry's velocities).
 *
 * Entry (sec 3.3.2): the layers carry the prescribed velocity u_in(s) n and move with it (they
 * are "replicas of the first line of fluid particles", rows at the lattice spacing); u_layer
 * holds u_in from the geometry and travels with the recycling. When a layer particle reaches
 * h >= 0 it becomes a fluid particle and its row gets a new particle depth behind it: a particle
 * recycled from an exit (below), so that the count of particles never changes. Until an exit has
 * one to give, it stays a layer particle (a few steps at most in a steady flow: what enters
 * leaves; the furthest in are served first). A weakly-compressible fluid takes in more than it
 * gives out while a pressure wave compresses it (at most U/c0 of its mass): the exits then hold a
 * park of particles (geometry.c, struct geom_park; kind OPEN_PARKED, at rest on a line park
 * behind the section, out of every sum) that feeds the entries meanwhile and fills again as the
 * fluid relaxes; without it, entry particles that wait run on into the fluid as
 * pistons and compress it further (square cylinder, Re = 20, H/80: the entry's density rose to
 * 1.07 ρ0 with 234 particles waiting, and the run blew up).
 * Exit (sec 3.3.3): a fluid particle that crosses the section (h < 0) becomes an exit layer
 * particle. The natural condition n·∇u = 0 (eq 17 with equilibrated pressures): its velocity is
 * that of its "progenitor in the exit layer", the fluid particle nearest to (s, δr/2); with a
 * prescribed exit profile (outflow { profile = "parabolic" }, the paper's choice above Re = 10,
 * sec 4.3.3) it is −u(s) n instead. Where the fluid flows back into the exit (u·n > 0 at its
 * progenitor) the layers take only the tangential part, as a finite-volume inletOutlet condition
 * turns a zero-gradient exit into a wall for backflow: the layers that copied a backflow ran on
 * upstream into the fluid, pushed it back, and copied the faster backflow they made (the square
 * cylinder's exit corner by the floor, cases/square_cylinder.lua with wcsph-riemann, Re = 20,
 * H/80: layer particles 18 δr into the fluid at −16 U0 by t = 3.3). A particle beyond the last
 * layer (h < −depth) stops and
 * waits to be recycled into an entry.
 * The pressure (or density) the layers carry is the scheme's: open_layer_scalar gives the usual
 * weakly-compressible choice (a copy of the row's first fluid particle at an entry, a fixed value
 * at an exit); isph-rotational's φ and p are in kernels/isph_rotational/open.cl. */
#ifndef OPEN_SECTIONS
#define OPEN_SECTIONS 0
#endif

#if OPEN_SECTIONS
#define OPEN_FLUID      0u /* the kinds of host/scene/geometry.h: KIND_FLUID */
#define OPEN_INFLOW     3u /* KIND_INFLOW, entry layer particle */
#define OPEN_OUTFLOW    4u /* KIND_OUTFLOW, exit layer particle */
#define OPEN_PARKED     5u /* KIND_PARKED, waits in an exit's park */
#define OPEN_NO_SECTION 0xffffffffu
#define OPEN_SEC        11

struct open_section {
  realv a, t, n;   /* origin, unit tangent, unit normal into the fluid */
  real len, depth; /* length and depth of the layers, m */
  real speed;      /* U, m/s (prescribed profiles) */
  uint kind;       /* 1 inflow, 2 outflow */
  uint profile;    /* 0 natural (exit), 1 uniform, 2 parabolic */
  real ramp;       /* T, s: the prescribed speed's rise time (0: none) */
  real park;       /* an exit's park: distance behind the section, m (0: none) */
};

struct open_section open_section_load(__global const real *sec, uint k)
{
  __global const real *s = sec + k * OPEN_SEC;
  struct open_section r;
  r.a = (realv)(s[0], s[1]);
  r.t = (realv)(s[2], s[3]);
  r.n = (realv)(-s[3], s[2]);
  r.len = s[4];
  r.depth = s[5];
  r.speed = s[6];
  r.kind = (uint)s[7];
  r.profile = (uint)s[8];
  r.ramp = s[9];
  r.park = s[10];
  return r;
}

/* normal speed of the prescribed profile at distance `along` from a */
real open_profile(const struct open_section *s, real along)
{
  if (s->profile == 1u) return s->speed;
  const real f = clamp(along / s->len, R(0.0), R(1.0));
  return R(4.0) * s->speed * f * (R(1.0) - f);
}

/* the fluid particle nearest to `at` with h >= hmin from section s, or `none` */
uint open_nearest_fluid(const struct grid *g, __global const uint *cell_start,
                        __global const realv *pos, __global const uint *kind, realv at,
                        const struct open_section *s, real hmin, uint none)
{
  real best = INFINITY;
  uint m = none;
  struct neigh_iter it;
  NEIGH_FOR(it, *g, cell_start, at, j) {
    if (kind[j] != OPEN_FLUID) continue;
    const realv xj = pos[j] + it.shift;
    const realv r = at - xj;
    const real r2 = dot(r, r);
    if (r2 >= g->sm.support2 || r2 >= best || dot(xj - s->a, s->n) < hmin) continue;
    best = r2;
    m = j;
  }
  return m;
}

/* Each step before the scheme's neighbour loops, for the layer particles: near (the row's first
 * fluid particle along the normal, itself if there is none), the velocity and its progenitor src
 * (sec 3.3.2-3.3.3, see the header). vel[i] = u_layer[i] = u: the entry's prescribed velocity,
 * the exit's progenitor's (n·∇u = 0) or prescribed profile, 0 beyond the last exit layer. */
__kernel void open_layer_velocity(const uint n, const struct grid g,
                                  __global const uint *cell_start, __global const realv *pos,
                                  __global const uint *kind, __global const uint *section,
                                  __global const real *sec, const real dr, const real time,
                                  __global realv *vel, __global realv *u_layer, __global uint *src,
                                  __global uint *near, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const uint ki = kind[i];
  if (ki != OPEN_INFLOW && ki != OPEN_OUTFLOW) return; /* (a parked particle is at rest) */
  const struct open_section s = open_section_load(sec, section[i]);
  const realv x = pos[i];
  const real along = dot(x - s.a, s.t), h = dot(x - s.a, s.n);
  const realv foot = s.a + along * s.t; /* x's projection onto the section */
  /* (a particle beyond the last exit layer has no row) */
  const uint m1 = ki == OPEN_OUTFLOW && h < -s.depth
                      ? i
                      : open_nearest_fluid(&g, cell_start, pos, kind, foot + R(0.5) * dr * s.n, &s,
                                           -INFINITY, i);
  near[i] = m1;
  realv u;
  uint m = i;
  /* the ramp's factor, ½(1 − cos(π t/T)) while t < T */
  const real rise = time < s.ramp ? R(0.5) * (R(1.0) - cospi(time / s.ramp)) : R(1.0);
  if (ki == OPEN_INFLOW) {
    u = u_layer[i];        /* prescribed u_in (sec 3.3.2) */
    if (s.ramp > R(0.0)) { /* the geometry's u_in, less the ramp's factor while it rises */
      u = rise * open_profile(&s, along) * s.n;
      u_layer[i] = u;
    }
  } else {
    /* the exit (sec 3.3.3): n·∇u = 0 from the progenitor, or the prescribed profile */
    if (h < -s.depth) {
      u = (realv)(R(0.0)); /* beyond the last layer: waits for recycling */
    } else if (s.profile == 0u) {
      m = m1;
      u = vel[m];
      const real un = dot(u, s.n); /* backflow: the layers do not move into the fluid */
      if (un > R(0.0)) u -= un * s.n;
    } else {
      u = -rise * open_profile(&s, along) * s.n;
    }
    u_layer[i] = u;
  }
  src[i] = m;
  if (!all(isfinite(u))) flags_raise(flags, CLSPH_FLAG_NAN);
  vel[i] = u;
}

/* A scalar of the layers (a weakly-compressible scheme's density or pressure), after
 * open_layer_velocity: an entry layer particle takes the value of its row's first fluid particle
 * (the zeroth-order extrapolation from the fluid: n·∇a = 0); an exit layer particle takes its
 * section's exit_value (copy_exit = 0: e.g. p = 0, ρ = ρ0 at a natural exit) or, copy_exit = 1,
 * its row's first fluid particle's too; copy_exit = 2: the exit copies, the entry keeps its own
 * (a prescribed entry value: k and ε of the k-ε model). A particle without fluid in its row keeps
 * its value. */
__kernel void open_layer_scalar(const uint n, __global const uint *kind, __global const uint *near,
                                __global const uint *section, const uint copy_exit,
                                __global const real *exit_value, __global real *a)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const uint ki = kind[i];
  if (ki == OPEN_OUTFLOW && copy_exit == 0u) {
    a[i] = exit_value[section[i]];
  } else if ((ki == OPEN_INFLOW && copy_exit != 2u) || ki == OPEN_OUTFLOW) {
    const uint m = near[i];
    if (m != i) a[i] = a[m];
  }
}

/* The fluid's flow through section k: over the fluid particles of its first row (0 <= h < δr,
 * 0 <= s <= len), the sum of the normal speed through it (in at an entry, u·n; out at an exit,
 * −u·n) and their count, into partial[g] and partial[G + g] for work-group g of G. */
__kernel void open_exit_sums(const uint n, __global const realv *pos, __global const realv *vel,
                             __global const uint *kind, __global const real *sec, const uint k,
                             const real dr, __global real *partial)
{
  __local real s[REDUCE_WG];
  const uint l = get_local_id(0), grp = get_group_id(0), groups = get_num_groups(0);
  const struct open_section c = open_section_load(sec, k);
  real u = R(0.0), m = R(0.0);
  for (uint i = get_global_id(0); i < n; i += get_global_size(0)) {
    if (kind[i] != OPEN_FLUID) continue;
    const realv d = pos[i] - c.a;
    const real along = dot(d, c.t), h = dot(d, c.n);
    if (h < R(0.0) || h >= dr || along < R(0.0) || along > c.len) continue;
    u += c.kind == 1u ? dot(vel[i], c.n) : -dot(vel[i], c.n);
    m += R(1.0);
  }
  s[l] = u;
  reduce_local_sum(s);
  if (l == 0) partial[grp] = s[0];
  s[l] = m;
  reduce_local_sum(s);
  if (l == 0) partial[groups + grp] = s[0];
}

/* The layers move with their own (prescribed or copied) velocity: x += δt u. */
__kernel void open_move(const uint n, __global const uint *kind, __global const realv *vel,
                        const real dt, __global realv *pos, __global uint *flags)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const uint ki = kind[i];
  if (ki != OPEN_INFLOW && ki != OPEN_OUTFLOW) return;
  const realv x = pos[i] + dt * vel[i];
  if (!all(isfinite(x))) flags_raise(flags, CLSPH_FLAG_NAN);
  pos[i] = x;
}

/* After the motion: fluid that crossed an exit becomes an exit layer particle; role 1 for entry
 * layer particles that reached the fluid (h >= 0), 2 for exit particles beyond the last layer and
 * for parked ones. */
__kernel void open_classify(const uint n, __global const realv *pos, __global uint *kind,
                            __global uint *section, __global const real *sec, const uint nsec,
                            const real tol, __global uint *role)
{
  const uint i = get_global_id(0);
  if (i >= n) return;
  const uint ki = kind[i];
  const realv x = pos[i];
  uint r = 0u;
  if (ki == OPEN_FLUID) {
    for (uint k = 0; k < nsec; ++k) {
      const struct open_section s = open_section_load(sec, k);
      const real along = dot(x - s.a, s.t), h = dot(x - s.a, s.n);
      if (s.kind == 2u && h < R(0.0) && along >= -tol && along <= s.len + tol) {
        kind[i] = OPEN_OUTFLOW;
        section[i] = k;
        break;
      }
    }
  } else if (ki == OPEN_INFLOW || ki == OPEN_OUTFLOW) {
    const struct open_section s = open_section_load(sec, section[i]);
    const real h = dot(x - s.a, s.n);
    if (ki == OPEN_INFLOW && h >= R(0.0)) r = 1u;
    if (ki == OPEN_OUTFLOW && h < -s.depth) r = 2u;
  } else if (ki == OPEN_PARKED) {
    r = 2u;
  }
  role[i] = r;
}

/* Recycling, one work item (the same run gives the same particles): each entry particle i of
 * role 1 becomes fluid and an exit particle j of role 2 takes its place at the back of its row,
 * depth behind it, with the row's prescribed velocity (vel[j] = u_layer[j] = u_layer[i]); exit
 * particles left over wait at rest in their exit's park (if it has one); the
 * scheme's own fields follow with open_copy_real(v) (j takes i's values). When the exits have
 * fewer to give than the entries ask for (the fluid's volume fluctuates by a few particles), the
 * entry particles furthest into the fluid go first. Served in index order (the sort's, by cell),
 * the same rows would wait every time: their layers run on into the fluid, the gap they leave
 * behind fills with fluid, and that fluid is then upstream of the entry with nothing to bring it
 * back.
 * list: the exit particles (j) from 0, the entry particles (i) from count[4]; pair q is
 * (list[q], list[count[4] + q]), q < count[3].
 * count[0] += pairs made; count[1] = entry particles left waiting; count[2] = exit particles
 * left waiting; count[3] = pairs made now; count[4] = where the entry particles start in list. */
__kernel void open_recycle(const uint n, __global const uint *role, __global uint *list,
                           __global const real *sec, __global realv *pos, __global uint *kind,
                           __global uint *section, __global realv *vel, __global realv *u_layer,
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
        const struct open_section s = open_section_load(sec, section[want[b]]);
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
    const struct open_section s = open_section_load(sec, k);
    pos[j] = pos[i] - s.depth * s.n;
    kind[j] = OPEN_INFLOW;
    section[j] = k;
    vel[j] = u_layer[i];
    u_layer[j] = u_layer[i];
    kind[i] = OPEN_FLUID;
    section[i] = OPEN_NO_SECTION;
  }
  for (uint q = used; q < ng; ++q) { /* exit particles left waiting go to their park */
    const uint j = list[q];
    const struct open_section s = open_section_load(sec, section[j]);
    if (s.park <= R(0.0) || kind[j] == OPEN_PARKED) continue;
    pos[j] = s.a + dot(pos[j] - s.a, s.t) * s.t - s.park * s.n;
    kind[j] = OPEN_PARKED;
    vel[j] = (realv)(R(0.0));
    u_layer[j] = (realv)(R(0.0));
  }
  count[0] += used;
  count[1] = nw - used;
  count[2] = ng - used;
  count[3] = used;
  count[4] = ng;
}

/* a[j] = a[i] for the pairs of the last open_recycle (j the recycled exit particle, i the entry
 * particle it replaces), for a field of reals or of vectors */
__kernel void open_copy_real(const uint used, const uint off, __global const uint *list,
                             __global real *a)
{
  const uint q = get_global_id(0);
  if (q >= used) return;
  a[list[q]] = a[list[off + q]];
}

__kernel void open_copy_realv(const uint used, const uint off, __global const uint *list,
                              __global realv *a)
{
  const uint q = get_global_id(0);
  if (q >= used) return;
  a[list[q]] = a[list[off + q]];
}
#endif /* OPEN_SECTIONS */
