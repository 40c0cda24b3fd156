/* test_geometry.c: the geometry generator on scenes built by hand (no Lua, no OpenCL device):
 * fluid fill, USAW vertex particles and segments (angles, normals, lengths, merged corners, free
 * ends, periodic wrap), dummy layers (counts, distances, normals), wall motion, inflow/outflow
 * layers and profiles, and every input error.
 *
 * Tolerances. Lattice coordinates lo + (k + 1/2) dr and the quantities derived from them carry a
 * few rounding errors of numbers of order 1, so 1e-14 (about 50 ulp of 1) bounds them; angles
 * from atan2 of unit vectors carry a few ulp of π, below 1e-14 too. Sums over n terms get n ulp. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "geometry.h"
#include "tcheck.h"

static const double pi = 3.14159265358979323846;
static const double tol = 1e-14;
static const double dr = 0.1;

/* ---- scene builders ------------------------------------------------------------------------ */

static double box_pts[] = {0, 0, 1, 0, 1, 1, 0, 1};                      /* counter-clockwise */
static double obstacle_pts[] = {0.4, 0.4, 0.4, 0.6, 0.6, 0.6, 0.6, 0.4}; /* clockwise */
static double wedge_pts[] = {0.3, 0.7, 0.7, 0.7, 0.5, 0.3};              /* clockwise, tip down */
static double tank_pts[] = {0, 1, 0, 0, 1, 0, 1, 1};                     /* open, fluid inside */
static double lid_pts[] = {1, 1, 0, 1};                                  /* open, fluid below */

static void scene_init(struct scene *s)
{
  memset(s, 0, sizeof *s);
  snprintf(s->case_path, sizeof s->case_path, "%s", "test.lua");
  snprintf(s->name, sizeof s->name, "%s", "test");
  s->dim = 2;
  s->hi[0] = s->hi[1] = 1.0;
  s->dr = dr;
}

static struct scene_region region(const char *name, double *pts, int npts, int line)
{
  struct scene_region r;
  memset(&r, 0, sizeof r);
  snprintf(r.name, sizeof r.name, "%s", name);
  r.pts = pts;
  r.npts = npts;
  r.line = line;
  return r;
}

static struct scene_wall wall(double *pts, int npts, int closed, int line)
{
  struct scene_wall w;
  memset(&w, 0, sizeof w);
  snprintf(w.group, sizeof w.group, "%s", "walls");
  w.pts = pts;
  w.npts = npts;
  w.closed = closed;
  w.motion = SCENE_FIXED;
  w.line = line;
  return w;
}

static struct scene_section section(enum scene_section_kind kind, const char *name, double ax,
                                    double ay, double bx, double by, int line)
{
  struct scene_section c;
  memset(&c, 0, sizeof c);
  c.kind = kind;
  snprintf(c.name, sizeof c.name, "%s", name);
  c.a[0] = ax;
  c.a[1] = ay;
  c.b[0] = bx;
  c.b[1] = by;
  c.profile = SCENE_UNIFORM;
  c.line = line;
  return c;
}

/* ---- helpers ------------------------------------------------------------------------------- */

static size_t count_kind(const struct geom *g, int kind)
{
  size_t n = 0;
  for (size_t i = 0; i < g->n; ++i) n += g->kind[i] == kind;
  return n;
}

/* Index of the particle of `kind` at (x, y), or g->n. */
static size_t find(const struct geom *g, int kind, double x, double y)
{
  for (size_t i = 0; i < g->n; ++i)
    if (g->kind[i] == kind && fabs(g->x[2 * i] - x) < 1e-12 && fabs(g->x[2 * i + 1] - y) < 1e-12)
      return i;
  return g->n;
}

static int on_lattice(double x, double lo)
{
  double f = (x - lo) / dr - 0.5;
  return fabs(f - round(f)) < 1e-9;
}

/* Distance from p to segment a-b. */
static double seg_dist(const double p[2], const double a[2], const double b[2])
{
  double t[2] = {b[0] - a[0], b[1] - a[1]};
  double s = ((p[0] - a[0]) * t[0] + (p[1] - a[1]) * t[1]) / (t[0] * t[0] + t[1] * t[1]);
  s = fmin(1.0, fmax(0.0, s));
  return hypot(p[0] - a[0] - s * t[0], p[1] - a[1] - s * t[1]);
}

static double polygon_dist(const double p[2], const double *pts, int npts)
{
  double d = INFINITY;
  for (int i = 0; i < npts; ++i) d = fmin(d, seg_dist(p, pts + 2 * i, pts + 2 * ((i + 1) % npts)));
  return d;
}

/* The fluid: on the lattice, in rows of increasing y then x, each point once, at rest. */
static void check_fluid_order(const struct geom *g, const char *what)
{
  int ok = 1;
  for (size_t i = 0; i < g->nfluid; ++i) {
    ok &= g->kind[i] == KIND_FLUID && g->group[i] == -1 && g->v[2 * i] == 0.0 &&
          g->v[2 * i + 1] == 0.0 && on_lattice(g->x[2 * i], 0.0) &&
          on_lattice(g->x[2 * i + 1], 0.0);
    if (i > 0) {
      double y0 = g->x[2 * i - 1], y1 = g->x[2 * i + 1];
      ok &= y1 > y0 + 0.5 * dr || (fabs(y1 - y0) < 1e-12 && g->x[2 * i] > g->x[2 * i - 2]);
    }
  }
  TC_CHECK(ok, "%s: fluid on the lattice, at rest, sorted by y then x, no duplicate", what);
}

/* USAW consistency: every vertex particle ends at most one arriving and one leaving segment
 * (exactly one of each unless it is a free end), segment lengths match the vertex positions
 * (modulo the period on a periodic x axis of length `period_x`, 0 if none), normals are the left
 * normals. */
static void check_segments(const struct geom *g, const char *what, size_t free_ends,
                           double period_x)
{
  size_t nv = 0, ends = 0;
  int ok = 1;
  for (size_t i = g->nfluid; i < g->n; ++i) {
    int in = 0, out = 0;
    if (g->kind[i] != KIND_VERTEX) continue;
    ++nv;
    for (size_t k = 0; k < g->nseg; ++k) {
      out += g->seg_v[2 * k] == i;
      in += g->seg_v[2 * k + 1] == i;
    }
    ok &= in <= 1 && out <= 1 && in + out >= 1;
    ends += in + out == 1;
    ok &= fabs(hypot(g->normal[2 * i], g->normal[2 * i + 1]) - 1.0) < tol;
  }
  TC_CHECK(ok && ends == free_ends,
           "%s: %zu vertices, each with one segment in and one out (%zu free ends, want %zu), "
           "unit normals",
           what, nv, ends, free_ends);
  ok = 1;
  for (size_t k = 0; k < g->nseg; ++k) {
    const double *a = g->x + 2 * g->seg_v[2 * k], *b = g->x + 2 * g->seg_v[2 * k + 1];
    double d[2] = {b[0] - a[0], b[1] - a[1]};
    if (period_x > 0.0) d[0] -= period_x * round(d[0] / period_x);
    double len = hypot(d[0], d[1]);
    ok &= fabs(len - g->seg_len[k]) < tol;
    ok &= fabs(g->seg_normal[2 * k] + d[1] / len) < tol &&
          fabs(g->seg_normal[2 * k + 1] - d[0] / len) < tol;
  }
  TC_CHECK(ok, "%s: segment lengths and left normals match the vertex positions", what);
}

/* ---- scenes --------------------------------------------------------------------------------- */

static void test_box(void)
{
  struct scene s;
  struct scene_region regs[] = {region("fill 1", box_pts, 4, 3)};
  struct scene_wall walls[] = {wall(box_pts, 4, 1, 2)};
  struct geom g;
  scene_init(&s);
  s.regions = regs;
  s.nregions = 1;
  s.walls = walls;
  s.nwalls = 1;

  /* fluid only */
  TC_CHECK(geometry_build(&s, "none", 0, NULL, &g) == CLSPH_OK, "box, no wall particles");
  TC_CHECK(g.n == 100 && g.nfluid == 100 && g.nseg == 0, "box: 10 x 10 fluid, got %zu of %zu",
           g.nfluid, g.n);
  check_fluid_order(&g, "box");
  TC_NEAR(g.x[0], 0.05, tol, "first particle half a spacing from the wall (x)");
  TC_NEAR(g.x[1], 0.05, tol, "first particle half a spacing from the wall (y)");
  TC_NEAR(g.x[2 * 99], 0.95, tol, "last particle half a spacing from the wall (x)");
  geometry_free(&g);
  TC_CHECK(g.x == NULL && g.n == 0, "geometry_free zeroes");
  geometry_free(&g); /* safe on a zeroed struct */

  /* two regions that overlap on x in [0.4, 0.6]: its 2 x 10 points are added once */
  double left[] = {0, 0, 0.6, 0, 0.6, 1, 0, 1}, right[] = {0.4, 0, 1, 0, 1, 1, 0.4, 1};
  struct scene_region two[] = {region("fill 1", left, 4, 3), region("fill 2", right, 4, 4)};
  s.regions = two;
  s.nregions = 2;
  TC_CHECK(geometry_build(&s, "none", 0, NULL, &g) == CLSPH_OK, "overlapping regions");
  TC_CHECK(g.nfluid == 100, "overlapping regions: 60 + 60 − 20 = 100 fluid particles, got %zu",
           g.nfluid);
  check_fluid_order(&g, "overlapping regions");
  geometry_free(&g);
  s.regions = regs;
  s.nregions = 1;

  /* USAW: 4 edges of 1 m cut into 10 segments: 40 vertices, 40 segments */
  TC_CHECK(geometry_build(&s, "usaw", 0, NULL, &g) == CLSPH_OK, "box, usaw");
  TC_CHECK(g.nfluid == 100 && g.n == 140 && g.nseg == 40, "box usaw: %zu vertices, %zu segments",
           g.n - g.nfluid, g.nseg);
  check_segments(&g, "box usaw", 0, 0.0);
  double sum_len = 0.0, turn = 0.0;
  int ok_len = 1, ok_theta = 1, ok_normal = 1, ok_misc = 1, corners = 0;
  for (size_t k = 0; k < g.nseg; ++k) {
    ok_len &= fabs(g.seg_len[k] - dr) < tol && g.seg_wall[k] == 0;
    sum_len += g.seg_len[k];
  }
  for (size_t i = g.nfluid; i < g.n; ++i) {
    double x = g.x[2 * i], y = g.x[2 * i + 1];
    double n[2] = {0, 0}; /* inward normals of the sides the vertex lies on */
    int sides = 0;
    if (fabs(y) < 1e-12) n[1] += 1.0, ++sides;
    if (fabs(y - 1.0) < 1e-12) n[1] -= 1.0, ++sides;
    if (fabs(x) < 1e-12) n[0] += 1.0, ++sides;
    if (fabs(x - 1.0) < 1e-12) n[0] -= 1.0, ++sides;
    double nn = hypot(n[0], n[1]);
    corners += sides == 2;
    ok_theta &= fabs(g.theta[i] - (sides == 2 ? 0.5 * pi : pi)) < tol;
    ok_normal &= sides >= 1 && fabs(g.normal[2 * i] - n[0] / nn) < tol &&
                 fabs(g.normal[2 * i + 1] - n[1] / nn) < tol;
    ok_misc &= g.kind[i] == KIND_VERTEX && g.group[i] == 0 && g.v[2 * i] == 0.0 &&
               g.v[2 * i + 1] == 0.0 && g.dist[i] == 0.0;
    turn += pi - g.theta[i];
  }
  TC_CHECK(ok_len, "box usaw: every segment is dr = 0.1 long, on wall 0");
  TC_NEAR(sum_len, 4.0, 40 * 4.0 * 2.3e-16,
          "box usaw: segment lengths sum to the perimeter "
          "(40 terms, one ulp of 4 each)");
  TC_CHECK(corners == 4, "box usaw: 4 corners, got %d", corners);
  TC_CHECK(ok_theta, "box usaw: θ = π/2 at the corners and π elsewhere");
  TC_CHECK(ok_normal, "box usaw: vertex normals point into the box (diagonal at corners)");
  TC_CHECK(ok_misc, "box usaw: vertex kind, group 0, at rest");
  TC_NEAR(turn, 2.0 * pi, 40 * tol, "box usaw: Σ(π − θ) = 2π around a container");
  geometry_free(&g);

  /* dummy, 3 layers: the 16 x 16 lattice points of [−0.3, 1.3]² less the 10 x 10 fluid */
  TC_CHECK(geometry_build(&s, "dummy", 3, NULL, &g) == CLSPH_OK, "box, dummy");
  TC_CHECK(g.nfluid == 100 && g.n - g.nfluid == 156 && count_kind(&g, KIND_DUMMY) == 156,
           "box dummy: 156 dummies, got %zu", g.n - g.nfluid);
  int ok_dist = 1, ok_dir = 1, ok_lat = 1, beyond = 0;
  double dmin = INFINITY, dmax = 0.0;
  for (size_t i = g.nfluid; i < g.n; ++i) {
    double x = g.x[2 * i], y = g.x[2 * i + 1];
    double q[2] = {fmin(1.0, fmax(0.0, x)), fmin(1.0, fmax(0.0, y))}; /* nearest wall point */
    double d = hypot(q[0] - x, q[1] - y);
    ok_dist &= fabs(g.dist[i] - d) < tol && fmax(fabs(q[0] - x), fabs(q[1] - y)) < 3 * dr + tol;
    ok_dir &= fabs(g.normal[2 * i] - (q[0] - x) / d) < tol &&
              fabs(g.normal[2 * i + 1] - (q[1] - y) / d) < tol;
    ok_lat &= on_lattice(x, 0.0) && on_lattice(y, 0.0) && g.group[i] == 0 && g.v[2 * i] == 0.0;
    dmin = fmin(dmin, g.dist[i]);
    dmax = fmax(dmax, g.dist[i]);
    beyond += g.dist[i] > 3 * dr + tol;
  }
  TC_CHECK(ok_dist, "box dummy: dist = distance to the box, within 3 lattice layers");
  TC_CHECK(ok_dir, "box dummy: unit normals toward the nearest wall point (into the fluid)");
  TC_CHECK(ok_lat, "box dummy: on the lattice, group 0, at rest");
  TC_CHECK(dmin > 0.0 && dmax <= 3.0 * sqrt(2.0) * dr + tol,
           "box dummy: dist in (0, 3√2 dr]: [%g, %g]", dmin, dmax);
  TC_CHECK(beyond == 4,
           "box dummy: only the 4 outermost corner points are farther than 3 dr "
           "(3√2 dr = 0.42 at (−0.25, −0.25)), got %d",
           beyond);
  geometry_free(&g);
}

static void test_obstacle(void)
{
  struct scene s;
  struct scene_region regs[] = {region("fill 1", box_pts, 4, 5)};
  struct scene_wall walls[] = {wall(box_pts, 4, 1, 2), wall(obstacle_pts, 4, 1, 3)};
  struct geom g;
  scene_init(&s);
  s.regions = regs;
  s.nregions = 1;
  s.walls = walls;
  s.nwalls = 2;
  walls[1].motion = SCENE_ROTATING;
  walls[1].omega = 2.0;
  walls[1].centre[0] = walls[1].centre[1] = 0.5;

  /* the fill is cut around the obstacle: its 4 inner lattice points go (the next ones, dr/2
   * from it, stay) */
  TC_CHECK(geometry_build(&s, "none", 0, NULL, &g) == CLSPH_OK, "obstacle, no wall particles");
  TC_CHECK(g.nfluid == 96, "obstacle: 100 − 4 fluid particles, got %zu", g.nfluid);
  int ok = 1;
  for (size_t i = 0; i < g.nfluid; ++i)
    ok &= polygon_dist(g.x + 2 * i, obstacle_pts, 4) >= 0.5 * dr - 1e-9 &&
          !(g.x[2 * i] > 0.4 && g.x[2 * i] < 0.6 && g.x[2 * i + 1] > 0.4 && g.x[2 * i + 1] < 0.6);
  TC_CHECK(ok, "obstacle: no fluid inside it or closer than dr/2");
  check_fluid_order(&g, "obstacle");
  geometry_free(&g);

  /* USAW: the obstacle's 4 edges of 0.2 m make 8 more vertices */
  TC_CHECK(geometry_build(&s, "usaw", 0, NULL, &g) == CLSPH_OK, "obstacle, usaw");
  TC_CHECK(g.n - g.nfluid == 48 && g.nseg == 48, "obstacle usaw: 40 + 8 vertices, got %zu",
           g.n - g.nfluid);
  check_segments(&g, "obstacle usaw", 0, 0.0);
  double turn = 0.0;
  int ok_theta = 1, ok_v = 1;
  for (size_t i = g.nfluid; i < g.n; ++i) {
    double x = g.x[2 * i], y = g.x[2 * i + 1];
    if (g.group[i] != 1) {
      ok_v &= g.v[2 * i] == 0.0 && g.v[2 * i + 1] == 0.0;
      continue;
    }
    int corner = fabs(fabs(x - 0.5) - 0.1) < 1e-12 && fabs(fabs(y - 0.5) - 0.1) < 1e-12;
    ok_theta &= fabs(g.theta[i] - (corner ? 1.5 * pi : pi)) < tol;
    if (corner) /* the normal points away from the obstacle, along the diagonal */
      ok_theta &= fabs(g.normal[2 * i] - (x - 0.5) / hypot(x - 0.5, y - 0.5)) < tol &&
                  fabs(g.normal[2 * i + 1] - (y - 0.5) / hypot(x - 0.5, y - 0.5)) < tol;
    /* rigid rotation: ω ez × (x − c) */
    ok_v &=
        fabs(g.v[2 * i] + 2.0 * (y - 0.5)) < tol && fabs(g.v[2 * i + 1] - 2.0 * (x - 0.5)) < tol;
    turn += pi - g.theta[i];
  }
  TC_CHECK(ok_theta, "obstacle usaw: θ = 3π/2 and outward diagonal normals at its corners, π "
                     "elsewhere");
  TC_NEAR(turn, -2.0 * pi, 8 * tol, "obstacle usaw: Σ(π − θ) = −2π around an obstacle");
  TC_CHECK(ok_v, "rotating obstacle: vertex velocity ω × (x − c); the box is at rest");
  geometry_free(&g);

  /* dummy: 156 around the box and the obstacle's 4 inner lattice points */
  TC_CHECK(geometry_build(&s, "dummy", 3, NULL, &g) == CLSPH_OK, "obstacle, dummy");
  TC_CHECK(g.n - g.nfluid == 160, "obstacle dummy: 156 + 4, got %zu", g.n - g.nfluid);
  int inner = 0;
  ok = 1;
  for (size_t i = g.nfluid; i < g.n; ++i) {
    if (g.group[i] != 1) continue;
    double x = g.x[2 * i], y = g.x[2 * i + 1];
    ++inner;
    ok &=
        fabs(g.dist[i] - 0.05) < tol && fabs(hypot(g.normal[2 * i], g.normal[2 * i + 1]) - 1) < tol;
    ok &= g.normal[2 * i] * (x - 0.5) + g.normal[2 * i + 1] * (y - 0.5) > 0.0;
    ok &= fabs(g.v[2 * i] + 2.0 * (y - 0.5)) < tol && fabs(g.v[2 * i + 1] - 2.0 * (x - 0.5)) < tol;
  }
  TC_CHECK(inner == 4 && ok, "obstacle dummy: 4 inside it, dist dr/2, normals out of it, "
                             "rotating with it");
  geometry_free(&g);
}

static void test_wedge(void)
{
  struct scene s;
  struct scene_region regs[] = {region("fill 1", box_pts, 4, 5)};
  struct scene_wall walls[] = {wall(box_pts, 4, 1, 2), wall(wedge_pts, 3, 1, 3)};
  struct geom g;
  scene_init(&s);
  s.regions = regs;
  s.nregions = 1;
  s.walls = walls;
  s.nwalls = 2;
  TC_CHECK(geometry_build(&s, "usaw", 0, NULL, &g) == CLSPH_OK, "wedge, usaw");
  /* the tip (0.5, 0.3): solid angle 2 atan(0.2/0.4); base corners: atan(0.4/0.2) */
  size_t tip = find(&g, KIND_VERTEX, 0.5, 0.3), left = find(&g, KIND_VERTEX, 0.3, 0.7);
  TC_CHECK(tip < g.n && left < g.n, "wedge: tip and base vertices exist");
  if (tip < g.n && left < g.n) {
    TC_NEAR(g.theta[tip], 2.0 * pi - 2.0 * atan(0.5), tol, "wedge tip θ = 2π − 2 atan(1/2)");
    TC_NEAR(g.normal[2 * tip], 0.0, tol, "wedge tip normal x");
    TC_NEAR(g.normal[2 * tip + 1], -1.0, tol, "wedge tip normal y (down, away from the wedge)");
    TC_NEAR(g.theta[left], 2.0 * pi - atan(2.0), tol, "wedge base corner θ = 2π − atan 2");
  }
  /* 4 + 4 + 4 segments (0.4 and 0.447 m long) */
  TC_CHECK(g.n - g.nfluid == 52 && g.nseg == 52, "wedge: 40 + 12 vertices, got %zu",
           g.n - g.nfluid);
  check_segments(&g, "wedge usaw", 0, 0.0);
  double turn = 0.0;
  for (size_t i = g.nfluid; i < g.n; ++i)
    if (g.group[i] == 1) turn += pi - g.theta[i];
  TC_NEAR(turn, -2.0 * pi, 12 * tol, "wedge: Σ(π − θ) = −2π around an obstacle");
  int ok = 1;
  for (size_t i = 0; i < g.nfluid; ++i)
    ok &= polygon_dist(g.x + 2 * i, wedge_pts, 3) >= 0.5 * dr - 1e-9;
  /* inside the wedge: above both slanted sides and below the base */
  for (size_t i = 0; i < g.nfluid; ++i) {
    double x = g.x[2 * i], y = g.x[2 * i + 1];
    ok &= !(y < 0.7 && y > 0.3 + 2.0 * fabs(x - 0.5));
  }
  TC_CHECK(ok, "wedge: no fluid inside it or closer than dr/2 to it");
  geometry_free(&g);
}

static void expect_input_error(struct scene *s, const char *model, int layers, const char *what);

static void test_open_tank_and_lid(void)
{
  struct scene s;
  double half[] = {0, 0, 1, 0, 1, 0.5, 0, 0.5};
  struct scene_region regs[] = {region("fill 1", half, 4, 5)};
  struct scene_wall walls[] = {wall(tank_pts, 4, 0, 2), wall(lid_pts, 2, 0, 3)};
  struct geom g;
  scene_init(&s);
  s.regions = regs;
  s.nregions = 1;
  s.walls = walls;
  s.nwalls = 1;

  /* without gravity nothing keeps the fluid in an open tank: refused */
  expect_input_error(&s, "usaw", 0, "open tank without gravity");
  s.gravity[1] = -9.81; /* an open tank holds its water under gravity */

  /* an open tank: 3 edges, 30 segments, 31 vertices; free ends at the top */
  TC_CHECK(geometry_build(&s, "usaw", 0, NULL, &g) == CLSPH_OK, "open tank, usaw");
  TC_CHECK(g.nfluid == 50 && g.n - g.nfluid == 31 && g.nseg == 30,
           "open tank: 50 fluid, 31 vertices, 30 segments, got %zu, %zu, %zu", g.nfluid,
           g.n - g.nfluid, g.nseg);
  check_segments(&g, "open tank", 2, 0.0);
  size_t e0 = find(&g, KIND_VERTEX, 0, 1), e1 = find(&g, KIND_VERTEX, 1, 1);
  size_t c0 = find(&g, KIND_VERTEX, 0, 0);
  TC_CHECK(e0 < g.n && e1 < g.n && c0 < g.n, "open tank: end and corner vertices exist");
  if (e0 < g.n && e1 < g.n && c0 < g.n) {
    TC_NEAR(g.theta[e0], pi, tol, "free end θ = π (chosen: the wall continues straight)");
    TC_NEAR(g.theta[e1], pi, tol, "other free end θ = π");
    TC_CHECK(g.normal[2 * e0] == 1.0 && g.normal[2 * e1] == -1.0,
             "free end normals are their segment's: (1, 0) and (−1, 0)");
    TC_NEAR(g.theta[c0], 0.5 * pi, tol, "tank corner θ = π/2");
  }
  geometry_free(&g);

  /* dummy: 3 columns of 16 beside each side (3 layers below, a 3 x 3 square cap above each free
   * end), 3 rows of 10 under the floor */
  TC_CHECK(geometry_build(&s, "dummy", 3, NULL, &g) == CLSPH_OK, "open tank, dummy");
  TC_CHECK(g.n - g.nfluid == 2 * 48 + 30, "open tank dummy: 126, got %zu", g.n - g.nfluid);
  geometry_free(&g);

  /* a lid that slides, joined to the tank at both ends: a box with 4 true corners */
  walls[1].motion = SCENE_SLIDING;
  walls[1].velocity[0] = 1.0;
  s.nwalls = 2;
  regs[0].pts = box_pts;
  TC_CHECK(geometry_build(&s, "usaw", 0, NULL, &g) == CLSPH_OK, "cavity, usaw");
  TC_CHECK(g.n - g.nfluid == 40 && g.nseg == 40,
           "cavity: the lid ends merge: 31 + 11 − 2 = 40 "
           "vertices, got %zu",
           g.n - g.nfluid);
  check_segments(&g, "cavity", 0, 0.0);
  int ok = 1, lid = 0;
  for (size_t i = g.nfluid; i < g.n; ++i) {
    double x = g.x[2 * i], y = g.x[2 * i + 1];
    int corner =
        (fabs(x) < 1e-12 || fabs(x - 1) < 1e-12) && (fabs(y) < 1e-12 || fabs(y - 1) < 1e-12);
    ok &= fabs(g.theta[i] - (corner ? 0.5 * pi : pi)) < tol;
    if (fabs(y - 1.0) < 1e-12 && !corner) {
      ++lid;
      ok &= g.group[i] == 1 && g.v[2 * i] == 1.0 && g.v[2 * i + 1] == 0.0;
    } else { /* corners belong to the first wall that made them (the tank, at rest) */
      ok &= g.group[i] == 0 && g.v[2 * i] == 0.0 && g.v[2 * i + 1] == 0.0;
    }
  }
  TC_CHECK(ok && lid == 9, "cavity: θ = π/2 at the 4 corners, 9 lid vertices slide at (1, 0)");
  geometry_free(&g);

  TC_CHECK(geometry_build(&s, "dummy", 3, NULL, &g) == CLSPH_OK, "cavity, dummy");
  TC_CHECK(g.n - g.nfluid == 156, "cavity dummy: 156 as for the closed box, got %zu",
           g.n - g.nfluid);
  ok = 1;
  int above = 0;
  for (size_t i = g.nfluid; i < g.n; ++i) {
    double x = g.x[2 * i], y = g.x[2 * i + 1];
    if (y > 1.0 && x > 0.0 && x < 1.0) {
      ++above;
      ok &= g.group[i] == 1 && g.v[2 * i] == 1.0 && g.v[2 * i + 1] == 0.0;
    }
  }
  TC_CHECK(ok && above == 30, "cavity dummy: the 30 above the lid slide with it");
  geometry_free(&g);
}

static void test_periodic_channel(void)
{
  struct scene s;
  double bottom[] = {0, 0, 1, 0}, top[] = {1, 1, 0, 1};
  struct scene_region regs[] = {region("fill 1", box_pts, 4, 5)};
  struct scene_wall walls[] = {wall(bottom, 2, 0, 2), wall(top, 2, 0, 3)};
  struct geom g;
  scene_init(&s);
  s.regions = regs;
  s.nregions = 1;
  s.walls = walls;
  s.nwalls = 2;
  s.periodic[0] = 1;
  /* each wall's ends are one point modulo the period: 10 vertices, 10 segments, all straight */
  TC_CHECK(geometry_build(&s, "usaw", 0, NULL, &g) == CLSPH_OK, "periodic channel, usaw");
  TC_CHECK(g.nfluid == 100 && g.n - g.nfluid == 20 && g.nseg == 20,
           "periodic channel: 20 vertices and segments, got %zu, %zu", g.n - g.nfluid, g.nseg);
  check_segments(&g, "periodic channel", 0, 1.0);
  int ok = 1;
  for (size_t i = g.nfluid; i < g.n; ++i)
    ok &= fabs(g.theta[i] - pi) < tol && g.x[2 * i] >= 0.0 && g.x[2 * i] < 1.0;
  TC_CHECK(ok, "periodic channel: θ = π everywhere, vertices in [0, 1)");
  geometry_free(&g);
  TC_CHECK(geometry_build(&s, "dummy", 3, NULL, &g) == CLSPH_OK, "periodic channel, dummy");
  TC_CHECK(g.n - g.nfluid == 60, "periodic channel: 2 x 3 rows of 10 dummies, got %zu",
           g.n - g.nfluid);
  geometry_free(&g);
}

static void test_sections(void)
{
  struct scene s;
  double chan[] = {0, 0, 2, 0, 2, 1, 0, 1}, bottom[] = {0, 0, 2, 0}, top[] = {2, 1, 0, 1};
  struct scene_region regs[] = {region("fill 1", chan, 4, 5)};
  struct scene_wall walls[] = {wall(bottom, 2, 0, 2), wall(top, 2, 0, 3)};
  struct scene_section secs[] = {section(SCENE_INFLOW, "in", 0, 1, 0, 0, 6),
                                 section(SCENE_OUTFLOW, "out", 2, 0, 2, 1, 7)};
  struct geom g;
  scene_init(&s);
  s.hi[0] = 2.0;
  s.regions = regs;
  s.nregions = 1;
  s.walls = walls;
  s.nwalls = 2;
  s.sections = secs;
  s.nsections = 2;
  secs[0].profile = SCENE_PARABOLIC;
  secs[0].velocity = 1.5;
  secs[0].layers = 3;

  TC_CHECK(geometry_build(&s, "usaw", 0, NULL, &g) == CLSPH_OK, "channel, usaw");
  TC_CHECK(g.nfluid == 200 && g.nseg == 40 && count_kind(&g, KIND_VERTEX) == 42,
           "channel: 200 fluid, 2 x 21 vertices, 40 segments");
  TC_CHECK(count_kind(&g, KIND_INFLOW) == 30 && count_kind(&g, KIND_OUTFLOW) == 30,
           "channel: 3 layers of 10 behind each section, got %zu and %zu",
           count_kind(&g, KIND_INFLOW), count_kind(&g, KIND_OUTFLOW));
  check_segments(&g, "channel", 4, 0.0);
  /* order: fluid, vertices, inflow, outflow */
  int ok = 1;
  for (size_t i = 0; i < g.n; ++i) {
    int want = i < 200 ? KIND_FLUID : i < 242 ? KIND_VERTEX : i < 272 ? KIND_INFLOW : KIND_OUTFLOW;
    ok &= g.kind[i] == want;
  }
  TC_CHECK(ok, "channel: fluid, then vertices, then inflow, then outflow");
  /* parabolic profile, peak 1.5 m/s: s = 1 − y along a->b from (0, 1) to (0, 0) */
  int ok_in = 1, ok_out = 1;
  double vmax = 0.0;
  for (size_t i = 0; i < g.n; ++i) {
    double x = g.x[2 * i], y = g.x[2 * i + 1];
    if (g.kind[i] == KIND_INFLOW) {
      ok_in &= (fabs(x + 0.05) < 1e-12 || fabs(x + 0.15) < 1e-12 || fabs(x + 0.25) < 1e-12) &&
               on_lattice(y, 0.0) && y > 0.0 && y < 1.0 && g.group[i] == 0;
      ok_in &= fabs(g.v[2 * i] - 1.5 * 4.0 * y * (1.0 - y)) < tol && g.v[2 * i + 1] == 0.0;
      ok_in &= g.normal[2 * i] == 1.0 && g.normal[2 * i + 1] == 0.0;
      vmax = fmax(vmax, g.v[2 * i]);
    } else if (g.kind[i] == KIND_OUTFLOW) {
      ok_out &= (fabs(x - 2.05) < 1e-12 || fabs(x - 2.15) < 1e-12 || fabs(x - 2.25) < 1e-12) &&
                g.group[i] == 1 && g.v[2 * i] == 0.0 && g.v[2 * i + 1] == 0.0;
      ok_out &= g.normal[2 * i] == -1.0 && g.normal[2 * i + 1] == 0.0;
    }
  }
  TC_CHECK(ok_in, "inflow: x = −0.05, −0.15, −0.25; v = 4 U y (1 − y) ex; normal ex; group 0");
  TC_NEAR(vmax, 1.5 * 4.0 * 0.45 * 0.55, tol,
          "inflow: the largest lattice velocity, at y = "
          "0.45 and 0.55");
  TC_CHECK(ok_out, "outflow: x = 2.05, 2.15, 2.25, at rest, normal −ex, group 1");
  geometry_free(&g);

  /* uniform, 2 layers */
  secs[0].profile = SCENE_UNIFORM;
  secs[0].layers = 2;
  TC_CHECK(geometry_build(&s, "none", 0, NULL, &g) == CLSPH_OK, "channel, uniform inflow");
  TC_CHECK(count_kind(&g, KIND_INFLOW) == 20 && g.n == 250, "2 inflow layers of 10, got %zu",
           count_kind(&g, KIND_INFLOW));
  ok = 1;
  for (size_t i = 0; i < g.n; ++i)
    if (g.kind[i] == KIND_INFLOW) ok &= g.v[2 * i] == 1.5 && g.v[2 * i + 1] == 0.0;
  TC_CHECK(ok, "uniform inflow: v = U n");
  geometry_free(&g);

  /* a prescribed (parabolic) exit profile: along −n, peak 2 m/s; s = y along (2, 0)->(2, 1) */
  secs[1].profile = SCENE_PARABOLIC;
  secs[1].velocity = 2.0;
  TC_CHECK(geometry_build(&s, "none", 0, NULL, &g) == CLSPH_OK, "channel, parabolic exit");
  ok = 1;
  for (size_t i = 0; i < g.n; ++i) {
    double y = g.x[2 * i + 1];
    if (g.kind[i] == KIND_OUTFLOW)
      ok &= fabs(g.v[2 * i] - 2.0 * 4.0 * y * (1.0 - y)) < tol && g.v[2 * i + 1] == 0.0;
  }
  TC_CHECK(ok, "parabolic exit: v = 4 U y (1 − y) ex (out of the fluid, along −n)");
  geometry_free(&g);
}

/* ---- errors ------------------------------------------------------------------------------- */

static void expect_input_error(struct scene *s, const char *model, int layers, const char *what)
{
  struct geom g;
  enum clsph_status st = geometry_build(s, model, layers, NULL, &g);
  TC_CHECK(st == CLSPH_E_INPUT && g.n == 0 && g.x == NULL, "%s: CLSPH_E_INPUT, got %s", what,
           clsph_status_str(st));
  geometry_free(&g);
}

static void test_errors(void)
{
  struct scene s;
  double tiny[] = {0.51, 0.51, 0.54, 0.51, 0.54, 0.54, 0.51, 0.54};
  double wide[] = {0, 0, 1.2, 0, 1.2, 0.5, 0, 0.5};
  double one[] = {0.5, 0.5};
  double a[] = {0, 0, 1, 0}, b[] = {0, 0, 0, 1}, far[] = {0.5, 0.5, 0.8, 0.5, 0.8, 0.8, 0.5, 0.8};
  double chan[] = {0, 0, 2, 0, 2, 1, 0, 1};
  struct scene_region regs[1];
  struct scene_wall walls[2];
  struct scene_section secs[1];

  /* an empty region: no lattice point in [0.51, 0.54]² */
  scene_init(&s);
  regs[0] = region("fill 2", tiny, 4, 7);
  s.regions = regs;
  s.nregions = 1;
  expect_input_error(&s, "none", 0, "empty region");

  /* fluid past the right side of a closed box, and past an open tank's side */
  scene_init(&s);
  regs[0] = region("fill 1", wide, 4, 7);
  walls[0] = wall(box_pts, 4, 1, 3);
  s.regions = regs;
  s.nregions = 1;
  s.walls = walls;
  s.nwalls = 1;
  expect_input_error(&s, "usaw", 0, "fluid outside a closed container");
  walls[0] = wall(tank_pts, 4, 0, 3);
  expect_input_error(&s, "usaw", 0, "fluid behind an open wall");

  /* fluid closer than dr/4 to a wall: the lattice shifted so a column sits at x = 0.02 */
  regs[0] = region("fill 1", box_pts, 4, 7);
  walls[0] = wall(box_pts, 4, 1, 3);
  s.lo[0] = -0.03;
  expect_input_error(&s, "usaw", 0, "fluid 0.02 m (< dr/4) from a wall");
  s.lo[0] = 0.0;

  /* bad input: one-point wall, dr <= 0 or NaN, unknown model, no dummy layer */
  walls[0] = wall(one, 1, 0, 3);
  expect_input_error(&s, "usaw", 0, "a wall with 1 point");
  walls[0] = wall(box_pts, 4, 1, 3);
  s.dr = 0.0;
  expect_input_error(&s, "usaw", 0, "dr = 0");
  s.dr = -0.1;
  expect_input_error(&s, "usaw", 0, "dr < 0");
  s.dr = NAN;
  expect_input_error(&s, "usaw", 0, "dr = NaN");
  s.dr = dr;
  expect_input_error(&s, "mirror", 0, "unknown wall model");
  expect_input_error(&s, "dummy", 0, "dummy walls with 0 layers");
  {
    struct geom g;
    TC_CHECK(geometry_build(&s, "usaw", 0, NULL, &g) == CLSPH_OK, "the same scene, fixed, builds");
    geometry_free(&g);
  }

  /* two walls leaving the same point: opposite orientations (fluid kept far from both) */
  scene_init(&s);
  regs[0] = region("fill 1", far, 4, 7);
  walls[0] = wall(a, 2, 0, 3);
  walls[1] = wall(b, 2, 0, 4);
  s.regions = regs;
  s.nregions = 1;
  s.walls = walls;
  s.nwalls = 2;
  expect_input_error(&s, "usaw", 0, "walls joined with opposite orientations");

  /* an outflow with no fluid next to it, and fluid inside an inflow's layers */
  scene_init(&s);
  s.hi[0] = 2.0;
  regs[0] = region("fill 1", box_pts, 4, 7); /* fluid up to x = 1 only */
  secs[0] = section(SCENE_OUTFLOW, "out", 2, 0, 2, 1, 9);
  s.regions = regs;
  s.nregions = 1;
  s.sections = secs;
  s.nsections = 1;
  expect_input_error(&s, "none", 0, "outflow with no fluid next to it");
  regs[0] = region("fill 1", chan, 4, 7);
  secs[0] = section(SCENE_INFLOW, "in", 0.5, 1, 0.5, 0, 9); /* fluid on both sides */
  expect_input_error(&s, "none", 0, "fluid inside an inflow's layers");
}

int main(void)
{
  log_set_level(LOG_ERROR);
  test_box();
  test_obstacle();
  test_wedge();
  test_open_tank_and_lid();
  test_periodic_channel();
  test_sections();
  test_errors();
  return tc_finish("test_geometry");
}
