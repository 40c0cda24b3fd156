/* geometry.c: turns a scene (host/scene/scene.h) into particles and wall elements; 2-D, in double.
 *
 * Lattice. Fluid, dummy and inflow/outflow particles sit on x = lo + (k + 1/2) dr, k an integer
 * per axis, aligned to scene->lo. On a periodic axis only the points in [lo, hi) are kept.
 *
 * Orientation. A wall is a polyline with the fluid on its LEFT: the unit normal into the fluid of
 * an edge a->b is n = (−t_y, t_x), t = (b − a)/|b − a|. A closed wall that turns
 * counter-clockwise (signed area > 0) is a container and holds fluid inside; one that turns
 * clockwise is an obstacle and holds fluid outside. Inside/outside is the even-odd crossing test
 * with the half-open rule (an edge counts when exactly one of its ends lies strictly above the
 * point), so a point on an edge shared by two polygons belongs to exactly one of them.
 *
 * Fluid. The lattice points inside at least one region, once each, less those inside an obstacle
 * or closer than dr/2 to one (obstacles are cut out of the fill, so a channel can be filled around
 * a cylinder). A region left with no particle is an error. So is a fluid particle closer than dr/4
 * to a wall, outside every container (when the scene has one), or on the solid side of an open
 * wall within the reach of the wall particles (2 dr, or the dummy layers).
 *
 * USAW (Leroy et al. 2014, sec 2.2, fig 1 and eqs 63-64). Each wall edge is cut into
 * m = max(1, round(|b − a|/dr)) equal segments whose ends are vertex particles, shared by adjacent
 * segments (and by the closing segment of a closed wall). The angle θ_v of a vertex is the angle
 * of the fluid sector at it, so that γ_v = θ_v/2π (eq 64): with t_in the direction of the segment
 * that arrives at v and t_out that of the segment that leaves it, θ_v is the counter-clockwise
 * angle from t_out to −t_in, in (0, 2π]: π on a straight wall, π/2 in a box corner, 3π/2 at a
 * corner of an obstacle. The vertex normal is the bisector of that sector, which is the normalised
 * sum of the two segment normals wherever that sum is not zero. The free end of an open polyline
 * has one segment: we give it θ = π and that segment's normal, as if the wall went on straight
 * (the reading under which a wall cut by an inflow/outflow section or a periodic boundary is
 * right). End points of walls closer than 1e-9 dr (modulo the period on a periodic axis, where
 * vertex positions are wrapped into [lo, hi)) share one vertex particle, so corners between walls
 * get their true angle; two walls meeting with opposite orientations, or three segments at one
 * vertex, are errors.
 *
 * Dummy. The lattice points on the solid side of their nearest wall and within `layers` lattice
 * layers of it: at most layers·dr from it, except where the nearest wall point q is a corner or a
 * free end, where the distance is measured to the lines of the edges there (a mitre: a box corner
 * gets its full layers·dr × layers·dr square, a free end a square cap) but never less than
 * |x − q|/√2. dist = |x − q|, normal = (q − x)/|q − x| (into the fluid), velocity = the rigid
 * motion of that wall at the particle.
 *
 * Sections. `layers` lattice layers on the side opposite to the normal (0 < −h ≤ layers·dr, h the
 * signed distance along the normal), spanning a->b. Inflow velocity: U n (uniform) or
 * 4 U s (1 − s) n (parabolic, U the peak, s ∈ [0, 1] along a->b); outflow particles start at rest
 * (a natural exit) or with their prescribed profile, along −n. With a park (struct geom_park), each
 * exit gets its share of the parked particles after its layers: at rest, on the line
 * h = −(layers·dr + behind), evenly along a->b.
 *
 * Order of the particles: fluid (rows of increasing y, increasing x within a row), then wall
 * particles (USAW: walls in scene order, vertices along each polyline; dummy: rows), then the
 * particles of each section in scene order (rows).
 */
#include "geometry.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

static const double geom_pi = 3.14159265358979323846;
static const double max_lattice = 1e9;   /* lattice points one scan may visit */
static const double max_cells = 4e6;     /* cells of the wall index */
static const double merge_tol = 1e-9;    /* in dr: points this close are one point */
static const double layer_tol = 1e-6;    /* in dr: slack on layer thicknesses */
static const int default_sec_layers = 3; /* inflow/outflow layers unless the case says */

enum wall_model { MODEL_NONE, MODEL_USAW, MODEL_DUMMY };

/** One particle while the arrays are built. */
struct particle {
  double x[2], v[2], normal[2]; /* m, m/s, unit */
  double p0, rho0;              /* initial pressure and density (NAN: the scheme's), Pa, kg/m^3 */
  double k0, eps0;              /* initial k and ε (NAN: turbulence { }'s), m²/s², m²/s³ */
  double theta, dist;           /* rad, m */
  int kind, group;              /* group: the region index while fluid is checked, then −1 */
};

/** One USAW segment while the arrays are built. */
struct segment {
  size_t v[2];       /* vertex particles at its ends */
  double t[2], n[2]; /* unit tangent (from v[0] to v[1]) and unit normal into the fluid */
  double len;        /* m */
  int wall;
};

/** A wall edge, as given by the case (not cut into segments). */
struct edge {
  double a[2], b[2], t[2], n[2]; /* ends (m), unit tangent, unit normal into the fluid */
  double len;                    /* m */
  int wall;
  int free_a, free_b; /* a (b) is the free end of an open wall */
};

/** Uniform grid of cells listing the edges near each cell. */
struct wall_index {
  struct edge *edges;
  size_t nedges;
  double reach; /* a query finds every edge within this distance, and only those, m */
  double lo[2]; /* corner of the grid, m */
  double cs;    /* cell side, m */
  long nx, ny;
  size_t *start; /* nx·ny + 1 offsets into items */
  size_t *items; /* edge indices, cell after cell */
};

/** The nearest wall point to a query point. */
struct nearest {
  int found;      /* some edge within the reach */
  double d;       /* distance to q, m */
  double q[2];    /* nearest wall point, m */
  int wall;       /* its wall (that of the first nearest edge) */
  double nsum[2]; /* sum of the unit normals of the edges that reach q (pseudo-normal) */
  double mitre;   /* largest distance to the lines of the edges that reach q (or past a free end) */
  int free_end;   /* q is the free end of an open wall that no other edge reaches */
};

struct build {
  const struct scene *s;
  double dr;
  enum wall_model model;
  double *area; /* per wall: signed area of a closed wall (> 0: counter-clockwise), 0 if open */
  struct wall_index ix;
  struct particle *p;
  size_t np, pcap;
  struct segment *seg;
  size_t nseg, segcap;
  size_t nfluid;
  const struct geom_park *park; /* parked particles behind the exits (NULL: none) */
};

/* ---- small helpers ---------------------------------------------------------------------- */

static double dot2(const double a[2], const double b[2])
{
  return a[0] * b[0] + a[1] * b[1];
}

/* Grow `buf` (items of `size` bytes) to at least `need` items; the new pointer goes to *out. */
static enum clsph_status reserve(void *buf, size_t size, size_t need, size_t *cap, void **out)
{
  enum clsph_status st = CLSPH_OK;
  void *q = buf;
  if (need > *cap) {
    size_t c = *cap > 0 ? *cap : 256;
    while (c < need) c *= 2;
    q = realloc(buf, c * size);
    CLSPH_CHECK(q != NULL, CLSPH_E_NOMEM, "geometry: out of memory for %zu items", c);
    *cap = c;
  }
  *out = q;
done:
  return st;
}

static enum clsph_status push_particle(struct build *b, const struct particle *p)
{
  enum clsph_status st = CLSPH_OK;
  void *q = NULL;
  CLSPH_TRY(reserve(b->p, sizeof *b->p, b->np + 1, &b->pcap, &q));
  b->p = q;
  b->p[b->np++] = *p;
done:
  return st;
}

static enum clsph_status push_segment(struct build *b, const struct segment *sg)
{
  enum clsph_status st = CLSPH_OK;
  void *q = NULL;
  CLSPH_TRY(reserve(b->seg, sizeof *b->seg, b->nseg + 1, &b->segcap, &q));
  b->seg = q;
  b->seg[b->nseg++] = *sg;
done:
  return st;
}

/* Lattice coordinate k along axis a. */
static double lat(const struct scene *s, int a, long k)
{
  return s->lo[a] + ((double)k + 0.5) * s->dr;
}

/* Lattice indices k0..k1 whose points cover the box [bb[0], bb[1]] x [bb[2], bb[3]] (one more
 * each side; on a periodic axis, only the points in [lo, hi)). */
static enum clsph_status lat_box(const struct scene *s, const double bb[4], long k0[2], long k1[2])
{
  enum clsph_status st = CLSPH_OK;
  double count = 1.0;
  for (int a = 0; a < 2; ++a) {
    double f0 = (bb[2 * a] - s->lo[a]) / s->dr - 0.5, f1 = (bb[2 * a + 1] - s->lo[a]) / s->dr - 0.5;
    CLSPH_CHECK(fabs(f0) < max_lattice && fabs(f1) < max_lattice, CLSPH_E_INPUT,
                "%s: dr = %g is too small for the extent [%g, %g] of axis %c", s->case_path, s->dr,
                bb[2 * a], bb[2 * a + 1], "xy"[a]);
    k0[a] = (long)floor(f0);
    k1[a] = (long)ceil(f1);
    if (s->periodic[a]) {
      long nper = (long)ceil((s->hi[a] - s->lo[a]) / s->dr - 0.5);
      if (k0[a] < 0) k0[a] = 0;
      if (k1[a] > nper - 1) k1[a] = nper - 1;
    }
    count *= k1[a] >= k0[a] ? (double)(k1[a] - k0[a] + 1) : 0.0;
  }
  CLSPH_CHECK(count <= max_lattice, CLSPH_E_INPUT,
              "%s: dr = %g gives %.3g lattice points over [%g, %g] x [%g, %g] (at most %.0g)",
              s->case_path, s->dr, count, bb[0], bb[1], bb[2], bb[3], max_lattice);
done:
  return st;
}

/* Velocity of the rigid motion of wall w at x. */
static void wall_velocity(const struct scene_wall *w, const double x[2], double v[2])
{
  v[0] = v[1] = 0.0;
  if (w->motion == SCENE_SLIDING) {
    v[0] = w->velocity[0];
    v[1] = w->velocity[1];
  } else if (w->motion == SCENE_ROTATING) { /* omega ez × (x − c) */
    v[0] = -w->omega * (x[1] - w->centre[1]);
    v[1] = w->omega * (x[0] - w->centre[0]);
  }
}

/* Signed area of a polygon (> 0 when counter-clockwise), m^2. */
static double polygon_area(const double *pts, int npts)
{
  double a = 0.0;
  for (int i = 0, j = npts - 1; i < npts; j = i++)
    a += pts[2 * j] * pts[2 * i + 1] - pts[2 * i] * pts[2 * j + 1];
  return 0.5 * a;
}

/* x where edge i-j crosses the horizontal line y (the caller checks that it does). */
static double cross_x(const double *pts, int i, int j, double y)
{
  return pts[2 * i] +
         (y - pts[2 * i + 1]) * (pts[2 * j] - pts[2 * i]) / (pts[2 * j + 1] - pts[2 * i + 1]);
}

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* The sorted x of every crossing of a polygon with the line y (half-open rule); returns how
 * many. */
static int row_crossings(const double *pts, int npts, double y, double *xs)
{
  int n = 0;
  for (int i = 0, j = npts - 1; i < npts; j = i++)
    if ((pts[2 * i + 1] > y) != (pts[2 * j + 1] > y)) xs[n++] = cross_x(pts, i, j, y);
  qsort(xs, (size_t)n, sizeof *xs, cmp_double);
  return n;
}

/* Even-odd test on one row: an odd number of crossings lies strictly right of x. */
static int row_inside(const double *xs, int n, double x)
{
  int lo = 0, hi = n; /* first crossing > x */
  while (lo < hi) {
    int mid = (lo + hi) / 2;
    if (xs[mid] > x)
      hi = mid;
    else
      lo = mid + 1;
  }
  return (n - lo) & 1;
}

/* Even-odd test of one point (same rule and arithmetic as row_inside). */
static int point_inside(const double *pts, int npts, const double p[2])
{
  int in = 0;
  for (int i = 0, j = npts - 1; i < npts; j = i++)
    if ((pts[2 * i + 1] > p[1]) != (pts[2 * j + 1] > p[1]) && p[0] < cross_x(pts, i, j, p[1]))
      in = !in;
  return in;
}

/* Difference b − a along axis ax, the shortest modulo the period on a periodic axis. */
static double gap(const struct scene *s, int ax, double a, double b)
{
  double d = b - a;
  if (s->periodic[ax]) {
    double len = s->hi[ax] - s->lo[ax];
    d -= len * round(d / len);
  }
  return d;
}

static int same_point(const struct scene *s, const double a[2], const double b[2])
{
  return hypot(gap(s, 0, a[0], b[0]), gap(s, 1, a[1], b[1])) <= merge_tol * s->dr;
}

/* ---- validation --------------------------------------------------------------------------- */

static int finite_pts(const double *pts, int npts)
{
  for (int i = 0; i < 2 * npts; ++i)
    if (!isfinite(pts[i])) return 0;
  return 1;
}

/* Distance from c to the segment a-b, or to its nearest periodic image on periodic axes. */
static double seg_distance(const struct scene *s, const double c[2], const double *a,
                           const double *b)
{
  const double t[2] = {b[0] - a[0], b[1] - a[1]}, tt = t[0] * t[0] + t[1] * t[1];
  double best = HUGE_VAL;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j) {
      if ((i != 0 && !s->periodic[0]) || (j != 0 && !s->periodic[1])) continue;
      double d[2] = {a[0] - c[0], a[1] - c[1]}; /* a − c, of the image (i, j) of the midpoint's
                                                 * image nearest c */
      const double m[2] = {gap(s, 0, c[0], a[0] + 0.5 * t[0]), gap(s, 1, c[1], a[1] + 0.5 * t[1])};
      d[0] = m[0] - 0.5 * t[0] + i * (s->hi[0] - s->lo[0]);
      d[1] = m[1] - 0.5 * t[1] + j * (s->hi[1] - s->lo[1]);
      double u = tt > 0.0 ? -(d[0] * t[0] + d[1] * t[1]) / tt : 0.0;
      u = u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
      best = fmin(best, hypot(d[0] + u * t[0], d[1] + u * t[1]));
    }
  return best;
}

/* Walls on periodic axes and walls that turn: under the USAW walls a wall longer than the period
 * overlaps its own image (the period cuts it: its segments and their images would count twice in
 * γ; dummy walls only mark the lattice points behind them, so there it may run on); a turning wall
 * sweeps the disc of its farthest point about its centre, which must stay inside the domain on a
 * bounded axis, clear of its own periodic image, and at least dr (room for a particle) from every
 * wall that does not turn with it; under dummy walls the geometry does not turn (the particles keep
 * their lattice), so a turning wall must be a circle about its centre there. */
static enum clsph_status check_periodic_and_turning(const struct scene *s, enum wall_model model)
{
  enum clsph_status st = CLSPH_OK;
  const char *path = s->case_path;
  const double dr = s->dr;
  for (int w = 0; w < s->nwalls; ++w) {
    const struct scene_wall *wl = &s->walls[w];
    for (int a = 0; a < 2 && model == MODEL_USAW; ++a) {
      if (!s->periodic[a]) continue;
      const double len = s->hi[a] - s->lo[a];
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for (int k = 0; k < wl->npts; ++k) {
        lo = fmin(lo, wl->pts[2 * k + a]);
        hi = fmax(hi, wl->pts[2 * k + a]);
      }
      CLSPH_CHECK(hi - lo <= len + merge_tol * dr, CLSPH_E_INPUT,
                  "%s:%d: the wall spans %g m along the periodic axis %c, more than the period "
                  "%g m: the period cuts it and its images overlap (end it within one period)",
                  path, wl->line, hi - lo, "xy"[a], len);
    }
    if (!scene_wall_turns(wl)) continue;
    const double *c = wl->centre;
    double rmax = 0.0, rmin = HUGE_VAL, emax = 0.0; /* farthest and nearest vertex, longest edge */
    const int nedge = wl->closed ? wl->npts : wl->npts - 1;
    for (int k = 0; k < wl->npts; ++k) {
      const double r = hypot(wl->pts[2 * k] - c[0], wl->pts[2 * k + 1] - c[1]);
      rmax = fmax(rmax, r);
      rmin = fmin(rmin, r);
    }
    for (int e = 0; e < nedge; ++e) {
      const double *p = wl->pts + 2 * e, *q = wl->pts + 2 * ((e + 1) % wl->npts);
      emax = fmax(emax, hypot(q[0] - p[0], q[1] - p[1]));
    }
    /* a circle { } or an arc { } about its centre: its vertices on one circle, about dr apart */
    CLSPH_CHECK(model != MODEL_DUMMY || (rmax - rmin <= 1e-6 * rmax && emax <= 2.0 * dr),
                CLSPH_E_INPUT,
                "%s:%d: the wall turns (omega = %g) but is not a circle about its centre (%g, %g) "
                "(its points lie %g to %g m from it, %g m apart at most): dummy-particle walls "
                "keep their place and only carry the velocity; a turning geometry needs a USAW "
                "scheme (isph-usaw, wcsph-usaw)",
                path, wl->line, wl->omega, c[0], c[1], rmin, rmax, emax);
    for (int a = 0; a < 2; ++a) {
      if (s->periodic[a]) {
        const double len = s->hi[a] - s->lo[a];
        CLSPH_CHECK(2.0 * rmax + dr <= len, CLSPH_E_INPUT,
                    "%s:%d: the wall turns about (%g, %g) through a disc of radius %g m, wider "
                    "than the period %g m of axis %c less dr: it would meet its own periodic "
                    "image (lengthen the period or move the centre)",
                    path, wl->line, c[0], c[1], rmax, len, "xy"[a]);
      } else {
        CLSPH_CHECK(c[a] - rmax >= s->lo[a] && c[a] + rmax <= s->hi[a], CLSPH_E_INPUT,
                    "%s:%d: the wall turns about (%g, %g) through a disc of radius %g m that "
                    "leaves the domain [%g, %g] along %c (check centre and the wall's points)",
                    path, wl->line, c[0], c[1], rmax, s->lo[a], s->hi[a], "xy"[a]);
      }
    }
    for (int v = 0; v < s->nwalls; ++v) {
      const struct scene_wall *o = &s->walls[v];
      if (v == w || (scene_wall_turns(o) && o->omega == wl->omega && o->centre[0] == c[0] &&
                     o->centre[1] == c[1]))
        continue; /* the same rigid body */
      const int ne = o->closed ? o->npts : o->npts - 1;
      for (int e = 0; e < ne; ++e) {
        const double *pa = o->pts + 2 * e, *pb = o->pts + 2 * ((e + 1) % o->npts);
        const double d = seg_distance(s, c, pa, pb);
        CLSPH_CHECK(d >= rmax + dr, CLSPH_E_INPUT,
                    "%s:%d: the wall turns about (%g, %g) through a disc of radius %g m that "
                    "comes within %g m of the wall of line %d (at %g m from the centre, the "
                    "edge from (%g, %g) to (%g, %g)): as it turns it would cut through it; move "
                    "the centre (centre = {x, y}) or shorten the wall so that dr = %g m stays "
                    "between them",
                    path, wl->line, c[0], c[1], rmax, fmax(0.0, d - rmax), o->line, d, pa[0], pa[1],
                    pb[0], pb[1], dr);
      }
    }
  }
done:
  return st;
}

static enum clsph_status check_scene(const struct scene *s, const char *model, int layers,
                                     enum wall_model *out)
{
  enum clsph_status st = CLSPH_OK;
  const char *path = s->case_path;
  const double dr = s->dr;
  CLSPH_CHECK(isfinite(dr) && dr > 0.0, CLSPH_E_INPUT,
              "%s: the particle spacing dr must be positive and finite, not %g", path, dr);
  if (strcmp(model, "usaw") == 0)
    *out = MODEL_USAW;
  else if (strcmp(model, "dummy") == 0)
    *out = MODEL_DUMMY;
  else if (strcmp(model, "none") == 0)
    *out = MODEL_NONE;
  else
    CLSPH_CHECK(0, CLSPH_E_INPUT, "%s: unknown wall model '%s' (known: usaw, dummy, none)", path,
                model);
  CLSPH_CHECK(*out != MODEL_DUMMY || layers >= 1, CLSPH_E_INPUT,
              "%s: dummy walls need at least one layer, not %d", path, layers);
  for (int a = 0; a < 2; ++a) {
    if (!s->periodic[a]) continue;
    double len = s->hi[a] - s->lo[a];
    CLSPH_CHECK(isfinite(len) && len > 0.0, CLSPH_E_INPUT,
                "%s: periodic axis %c has an empty period [%g, %g]", path, "xy"[a], s -> lo[a],
                s -> hi[a]);
    if (fabs(len / dr - round(len / dr)) > layer_tol)
      log_warn("%s: the period %g of axis %c is not a multiple of dr = %g: the lattice does not "
               "wrap evenly",
               path, len, "xy"[a], dr);
  }
  for (int r = 0; r < s->nregions; ++r) {
    const struct scene_region *g = &s->regions[r];
    CLSPH_CHECK(g->npts >= (g->given ? 1 : 3), CLSPH_E_INPUT,
                "%s:%d: fluid region '%s' needs at least %s, not %d", path, g->line, g->name,
                g->given ? "1 point" : "3 vertices", g->npts);
    CLSPH_CHECK(finite_pts(g->pts, g->npts), CLSPH_E_INPUT,
                "%s:%d: fluid region '%s' has a coordinate that is not finite", path, g->line,
                g->name);
  }
  for (int w = 0; w < s->nwalls; ++w) {
    const struct scene_wall *wl = &s->walls[w];
    CLSPH_CHECK(wl->npts >= (wl->closed ? 3 : 2), CLSPH_E_INPUT,
                "%s:%d: %s wall needs at least %d points, not %d", path, wl->line,
                wl->closed ? "a closed" : "a", wl->closed ? 3 : 2, wl->npts);
    CLSPH_CHECK(finite_pts(wl->pts, wl->npts), CLSPH_E_INPUT,
                "%s:%d: wall has a coordinate that is not finite", path, wl->line);
    int ne = wl->closed ? wl->npts : wl->npts - 1;
    for (int e = 0; e < ne; ++e) {
      const double *a = wl->pts + 2 * e, *b = wl->pts + 2 * ((e + 1) % wl->npts);
      CLSPH_CHECK(hypot(b[0] - a[0], b[1] - a[1]) > merge_tol * dr, CLSPH_E_INPUT,
                  "%s:%d: wall has a zero-length edge at (%g, %g)", path, wl->line, a[0], a[1]);
    }
    CLSPH_CHECK(!wl->closed || fabs(polygon_area(wl->pts, wl->npts)) > merge_tol * dr * dr,
                CLSPH_E_INPUT, "%s:%d: closed wall encloses no area", path, wl->line);
    CLSPH_CHECK(!wl->fitted || *out == MODEL_DUMMY, CLSPH_E_INPUT,
                "%s:%d: wall { dummies = \"fitted\" } arranges dummy particles, but this scheme's "
                "walls are %s: drop it",
                path, wl->line, model);
    CLSPH_CHECK(
        wl->motion == SCENE_FIXED || wl->motion == SCENE_SLIDING || wl->motion == SCENE_ROTATING,
        CLSPH_E_INPUT, "%s:%d: wall has an unknown motion %d", path, wl->line, (int)wl->motion);
    CLSPH_CHECK(isfinite(wl->velocity[0]) && isfinite(wl->velocity[1]) && isfinite(wl->omega) &&
                    isfinite(wl->centre[0]) && isfinite(wl->centre[1]),
                CLSPH_E_INPUT, "%s:%d: wall motion is not finite", path, wl->line);
  }
  for (int k = 0; k < s->nsections; ++k) {
    const struct scene_section *sc = &s->sections[k];
    CLSPH_CHECK(sc->kind == SCENE_INFLOW || sc->kind == SCENE_OUTFLOW, CLSPH_E_INPUT,
                "%s:%d: section '%s' is neither an inflow nor an outflow", path, sc->line,
                sc->name);
    CLSPH_CHECK(sc->profile == 0 || sc->profile == SCENE_UNIFORM ||
                    sc->profile == SCENE_PARABOLIC ||
                    (sc->profile == SCENE_TABLE && sc->kind == SCENE_INFLOW),
                CLSPH_E_INPUT, "%s:%d: section '%s' has an unknown profile %d", path, sc->line,
                sc->name, (int)sc->profile);
    CLSPH_CHECK(isfinite(sc->a[0]) && isfinite(sc->a[1]) && isfinite(sc->b[0]) &&
                    isfinite(sc->b[1]) && isfinite(sc->velocity),
                CLSPH_E_INPUT, "%s:%d: section '%s' has a value that is not finite", path, sc->line,
                sc->name);
    CLSPH_CHECK(hypot(sc->b[0] - sc->a[0], sc->b[1] - sc->a[1]) > merge_tol * dr, CLSPH_E_INPUT,
                "%s:%d: section '%s' has zero width", path, sc->line, sc->name);
    CLSPH_CHECK(sc->layers >= 0, CLSPH_E_INPUT, "%s:%d: section '%s' has %d layers", path, sc->line,
                sc->name, sc->layers);
  }
  CLSPH_TRY(check_periodic_and_turning(s, *out));
done:
  return st;
}

/* ---- wall index ------------------------------------------------------------------------- */

/* Distance from p to edge e; q the nearest point; *at = −1 (q = a), +1 (q = b) or 0. */
static double edge_nearest(const struct edge *e, const double p[2], double q[2], int *at)
{
  double s = (p[0] - e->a[0]) * e->t[0] + (p[1] - e->a[1]) * e->t[1];
  if (s <= 0.0) {
    q[0] = e->a[0];
    q[1] = e->a[1];
    *at = -1;
  } else if (s >= e->len) {
    q[0] = e->b[0];
    q[1] = e->b[1];
    *at = 1;
  } else {
    q[0] = e->a[0] + s * e->t[0];
    q[1] = e->a[1] + s * e->t[1];
    *at = 0;
  }
  return hypot(p[0] - q[0], p[1] - q[1]);
}

static void index_free(struct wall_index *ix)
{
  free(ix->edges);
  free(ix->start);
  free(ix->items);
  memset(ix, 0, sizeof *ix);
}

/* Cell range [i0, i1] covering [x0, x1] along axis a. */
static void index_span(const struct wall_index *ix, int a, double x0, double x1, long *i0, long *i1)
{
  long n = a == 0 ? ix->nx : ix->ny;
  *i0 = (long)floor((x0 - ix->lo[a]) / ix->cs);
  *i1 = (long)floor((x1 - ix->lo[a]) / ix->cs);
  if (*i0 < 0) *i0 = 0;
  if (*i1 > n - 1) *i1 = n - 1;
}

static enum clsph_status index_build(const struct scene *s, double reach, struct wall_index *ix)
{
  enum clsph_status st = CLSPH_OK;
  size_t *fill = NULL;
  double bb[4] = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
  memset(ix, 0, sizeof *ix);
  ix->reach = reach;
  /* the edges of every wall */
  for (int w = 0; w < s->nwalls; ++w)
    ix->nedges += (size_t)(s->walls[w].closed ? s->walls[w].npts : s->walls[w].npts - 1);
  if (ix->nedges == 0) goto done;
  ix->edges = calloc(ix->nedges, sizeof *ix->edges);
  CLSPH_CHECK(ix->edges != NULL, CLSPH_E_NOMEM, "geometry: out of memory for %zu wall edges",
              ix->nedges);
  size_t k = 0;
  for (int w = 0; w < s->nwalls; ++w) {
    const struct scene_wall *wl = &s->walls[w];
    int ne = wl->closed ? wl->npts : wl->npts - 1;
    for (int i = 0; i < ne; ++i, ++k) {
      struct edge *e = &ix->edges[k];
      const double *a = wl->pts + 2 * i, *b = wl->pts + 2 * ((i + 1) % wl->npts);
      memcpy(e->a, a, sizeof e->a);
      memcpy(e->b, b, sizeof e->b);
      e->len = hypot(b[0] - a[0], b[1] - a[1]);
      e->t[0] = (b[0] - a[0]) / e->len;
      e->t[1] = (b[1] - a[1]) / e->len;
      e->n[0] = -e->t[1];
      e->n[1] = e->t[0];
      e->wall = w;
      e->free_a = !wl->closed && i == 0;
      e->free_b = !wl->closed && i == ne - 1;
      for (int a2 = 0; a2 < 2; ++a2) {
        bb[2 * a2] = fmin(bb[2 * a2], fmin(a[a2], b[a2]));
        bb[2 * a2 + 1] = fmax(bb[2 * a2 + 1], fmax(a[a2], b[a2]));
      }
    }
  }
  /* the grid: cells of side >= reach, at most max_cells of them */
  double wx = bb[1] - bb[0] + 2.0 * reach, wy = bb[3] - bb[2] + 2.0 * reach;
  ix->cs = fmax(reach, sqrt(wx * wy / max_cells));
  while ((wx / ix->cs + 1.0) * (wy / ix->cs + 1.0) > max_cells) ix->cs *= 1.5; /* thin extents */
  ix->lo[0] = bb[0] - reach;
  ix->lo[1] = bb[2] - reach;
  ix->nx = (long)(wx / ix->cs) + 1;
  ix->ny = (long)(wy / ix->cs) + 1;
  size_t ncell = (size_t)ix->nx * (size_t)ix->ny;
  ix->start = calloc(ncell + 1, sizeof *ix->start);
  fill = calloc(ncell + 1, sizeof *fill);
  CLSPH_CHECK(ix->start != NULL && fill != NULL, CLSPH_E_NOMEM,
              "geometry: out of memory for %zu wall index cells", ncell);
  /* two passes: count, then fill; a cell lists an edge when a point of the cell can be within
   * the reach of it (distance from the centre <= reach + half the diagonal, rounded up to cs) */
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t e = 0; e < ix->nedges; ++e) {
      const struct edge *ed = &ix->edges[e];
      long i0, i1, j0, j1;
      index_span(ix, 0, fmin(ed->a[0], ed->b[0]) - reach, fmax(ed->a[0], ed->b[0]) + reach, &i0,
                 &i1);
      index_span(ix, 1, fmin(ed->a[1], ed->b[1]) - reach, fmax(ed->a[1], ed->b[1]) + reach, &j0,
                 &j1);
      for (long j = j0; j <= j1; ++j) {
        for (long i = i0; i <= i1; ++i) {
          double c[2] = {ix->lo[0] + ((double)i + 0.5) * ix->cs,
                         ix->lo[1] + ((double)j + 0.5) * ix->cs};
          double q[2];
          int at;
          if (edge_nearest(ed, c, q, &at) > reach + ix->cs) continue;
          size_t cell = (size_t)j * (size_t)ix->nx + (size_t)i;
          if (pass == 0)
            ++ix->start[cell + 1];
          else
            ix->items[fill[cell]++] = e;
        }
      }
    }
    if (pass == 0) {
      for (size_t c = 0; c < ncell; ++c) ix->start[c + 1] += ix->start[c];
      memcpy(fill, ix->start, (ncell + 1) * sizeof *fill);
      ix->items = malloc((ix->start[ncell] > 0 ? ix->start[ncell] : 1) * sizeof *ix->items);
      CLSPH_CHECK(ix->items != NULL, CLSPH_E_NOMEM,
                  "geometry: out of memory for the wall index (%zu entries)", ix->start[ncell]);
    }
  }
done:
  free(fill);
  if (st != CLSPH_OK) index_free(ix);
  return st;
}

/* The edges listed by the cell of p (none when p is off the grid); returns how many. */
static size_t index_cell(const struct wall_index *ix, const double p[2], const size_t **items)
{
  if (ix->nx == 0) return 0;
  double fx = (p[0] - ix->lo[0]) / ix->cs, fy = (p[1] - ix->lo[1]) / ix->cs;
  if (!(fx >= 0.0 && fy >= 0.0 && fx < (double)ix->nx && fy < (double)ix->ny)) return 0;
  size_t c = (size_t)(long)fy * (size_t)ix->nx + (size_t)(long)fx;
  *items = ix->items + ix->start[c];
  return ix->start[c + 1] - ix->start[c];
}

/* Nearest wall point q to p within the reach, over wall `wall` only (or every wall if < 0).
 * Every edge (of any wall) whose own nearest point to p is q reaches q: together they make the
 * pseudo-normal, the mitre and the free-end test, so walls that share an end make one corner. */
static void index_nearest(const struct wall_index *ix, const double p[2], int wall, double dr,
                          struct nearest *r)
{
  const size_t *items = NULL;
  const size_t n = index_cell(ix, p, &items);
  memset(r, 0, sizeof *r);
  r->wall = -1;
  r->d = HUGE_VAL;
  for (size_t k = 0; k < n; ++k) {
    const struct edge *e = &ix->edges[items[k]];
    double q[2];
    int at;
    if (wall >= 0 && e->wall != wall) continue;
    double d = edge_nearest(e, p, q, &at);
    if (d <= ix->reach && d < r->d) {
      r->found = 1;
      r->d = d;
      r->q[0] = q[0];
      r->q[1] = q[1];
      r->wall = e->wall;
    }
  }
  if (!r->found) return;
  int reaching = 0, free_hits = 0;
  for (size_t k = 0; k < n; ++k) {
    const struct edge *e = &ix->edges[items[k]];
    double q[2];
    int at;
    double d = edge_nearest(e, p, q, &at);
    if (hypot(q[0] - r->q[0], q[1] - r->q[1]) > merge_tol * dr) continue;
    ++reaching;
    r->nsum[0] += e->n[0];
    r->nsum[1] += e->n[1];
    if (at != 0) { /* q is an end of e: distance to its line (and beyond a free end) */
      double pq[2] = {p[0] - q[0], p[1] - q[1]};
      r->mitre = fmax(r->mitre, fabs(dot2(pq, e->n)));
      if ((at < 0 && e->free_a) || (at > 0 && e->free_b)) {
        r->mitre = fmax(r->mitre, fabs(dot2(pq, e->t)));
        ++free_hits;
      }
    } else {
      r->mitre = fmax(r->mitre, d);
    }
  }
  r->free_end = reaching == 1 && free_hits == 1;
}

/* Is p (not on the wall) on the solid side of wall w, whose nearest point r was found? */
static int solid_side(const struct build *b, int w, const double p[2], const struct nearest *r)
{
  const struct scene_wall *wl = &b->s->walls[w];
  if (wl->closed) return point_inside(wl->pts, wl->npts, p) == (b->area[w] < 0.0);
  double pq[2] = {p[0] - r->q[0], p[1] - r->q[1]};
  return dot2(pq, r->nsum) < 0.0;
}

/* Is p closer than `clearance` (<= the reach) to an obstacle, a clockwise closed wall? */
static int near_obstacle(const struct build *b, const double p[2], double clearance)
{
  const size_t *items = NULL;
  const size_t n = index_cell(&b->ix, p, &items);
  for (size_t k = 0; k < n; ++k) {
    const struct edge *e = &b->ix.edges[items[k]];
    double q[2];
    int at;
    if (b->area[e->wall] < 0.0 && edge_nearest(e, p, q, &at) < clearance) return 1;
  }
  return 0;
}

/* ---- fluid -------------------------------------------------------------------------------- */

/* The initial pressure and density of a fluid particle at x in region g (index r): the fill's
 * constants or functions (case.c), checked finite (and the density positive). */
static enum clsph_status fill_scalars(const struct scene *s, const struct scene_region *g, int r,
                                      const double x[2], struct particle *p)
{
  enum clsph_status st = CLSPH_OK;
  const int mode[4] = {g->pressure, g->density, g->k, g->epsilon};
  const double value[4] = {g->p0, g->rho0, g->k0, g->eps0};
  static const char *const what[4] = {"pressure", "density", "k", "epsilon"};
  double v[4] = {NAN, NAN, NAN, NAN};
  for (int k = 0; k < 4; ++k) {
    if (mode[k] == 0) continue;
    v[k] = value[k];
    if (mode[k] == 2) {
      CLSPH_CHECK(s->velocity_fn.scalar != NULL, CLSPH_E_INPUT,
                  "%s:%d: fluid region '%s': its %s function is gone (the case script was closed)",
                  s->case_path, g->line, g->name, what[k]);
      CLSPH_CHECK(s->velocity_fn.scalar(s->velocity_fn.ctx, r, k, x, &v[k]) == CLSPH_OK,
                  CLSPH_E_INPUT, "%s:%d: fluid region '%s': its %s at (%g, %g) failed",
                  s->case_path, g->line, g->name, what[k], x[0], x[1]);
    }
    CLSPH_CHECK(isfinite(v[k]) && (k == 0 || v[k] > 0.0), CLSPH_E_INPUT,
                "%s:%d: fluid region '%s': its initial %s at (%g, %g) is %g: it must be %s",
                s->case_path, g->line, g->name, what[k], x[0], x[1], v[k],
                k == 0 ? "finite" : "positive");
  }
  p->p0 = v[0];
  p->rho0 = v[1];
  p->k0 = v[2];
  p->eps0 = v[3];
done:
  return st;
}

/* A fluid particle of region r at xy: its initial scalars and velocity from the fill. */
static enum clsph_status push_fluid(struct build *b, int r, const double xy[2])
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = b->s;
  const struct scene_region *g = &s->regions[r];
  struct particle p = {.x = {xy[0], xy[1]},
                       .kind = KIND_FLUID,
                       .group = r,
                       .p0 = NAN,
                       .rho0 = NAN,
                       .k0 = NAN,
                       .eps0 = NAN};
  CLSPH_TRY(fill_scalars(s, g, r, xy, &p));
  if (g->velocity == 1) memcpy(p.v, g->u0, sizeof p.v);
  if (g->velocity == 2) {
    CLSPH_CHECK(s->velocity_fn.eval != NULL, CLSPH_E_INPUT,
                "%s:%d: fluid region '%s': its velocity function is gone (the case script was "
                "closed)",
                s->case_path, g->line, g->name);
    CLSPH_CHECK(s->velocity_fn.eval(s->velocity_fn.ctx, r, xy, p.v) == CLSPH_OK, CLSPH_E_INPUT,
                "%s:%d: fluid region '%s': its velocity at (%g, %g) failed", s->case_path, g->line,
                g->name, xy[0], xy[1]);
  }
  CLSPH_TRY(push_particle(b, &p));
done:
  return st;
}

static enum clsph_status fill_fluid(struct build *b)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = b->s;
  const int nr = s->nregions, nw = s->nwalls;
  double *xs = NULL;
  size_t *off = NULL, *count = NULL;
  int *cnt = NULL;
  if (nr == 0) goto done;
  /* scratch: the crossings of every region and closed wall with the current row */
  off = malloc((size_t)(nr + nw) * sizeof *off);
  cnt = calloc((size_t)(nr + nw), sizeof *cnt);
  count = calloc((size_t)nr, sizeof *count);
  CLSPH_CHECK(off != NULL && cnt != NULL && count != NULL, CLSPH_E_NOMEM,
              "geometry: out of memory");
  size_t total = 0;
  double bb[4] = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
  for (int r = 0; r < nr; ++r) {
    off[r] = total;
    total += (size_t)s->regions[r].npts;
    for (int i = 0; i < s->regions[r].npts && !s->regions[r].given; ++i) {
      for (int a = 0; a < 2; ++a) {
        bb[2 * a] = fmin(bb[2 * a], s->regions[r].pts[2 * i + a]);
        bb[2 * a + 1] = fmax(bb[2 * a + 1], s->regions[r].pts[2 * i + a]);
      }
    }
  }
  for (int w = 0; w < nw; ++w) {
    off[nr + w] = total;
    total += (size_t)s->walls[w].npts;
  }
  xs = malloc(total * sizeof *xs);
  CLSPH_CHECK(xs != NULL, CLSPH_E_NOMEM, "geometry: out of memory");
  long k0[2] = {0, 0}, k1[2] = {-1, -1}; /* (no lattice when every region is given) */
  if (bb[0] <= bb[1]) CLSPH_TRY(lat_box(s, bb, k0, k1));
  for (long j = k0[1]; j <= k1[1]; ++j) {
    const double y = lat(s, 1, j);
    int any = 0;
    for (int r = 0; r < nr; ++r) {
      cnt[r] = s->regions[r].given
                   ? 0
                   : row_crossings(s->regions[r].pts, s->regions[r].npts, y, xs + off[r]);
      any |= cnt[r] > 0;
    }
    if (!any) continue;
    for (int w = 0; w < nw; ++w)
      if (s->walls[w].closed)
        cnt[nr + w] = row_crossings(s->walls[w].pts, s->walls[w].npts, y, xs + off[nr + w]);
    for (long i = k0[0]; i <= k1[0]; ++i) {
      const double x = lat(s, 0, i);
      const double xy[2] = {x, y};
      int first = -1;
      for (int r = 0; r < nr && first < 0; ++r)
        if (row_inside(xs + off[r], cnt[r], x)) first = r;
      if (first < 0) continue;
      /* obstacles are cut out, with a clearance of dr/2 */
      int carved = 0;
      for (int w = 0; w < nw && !carved; ++w)
        if (b->area[w] < 0.0) carved = row_inside(xs + off[nr + w], cnt[nr + w], x);
      if (carved || near_obstacle(b, xy, (0.5 - layer_tol) * s->dr)) continue;
      for (int r = first; r < nr; ++r) count[r] += (size_t)row_inside(xs + off[r], cnt[r], x);
      /* containers: the particle is inside one, if there is one */
      const struct scene_region *g = &s->regions[first];
      int container = -1, contained = 0;
      for (int w = 0; w < nw; ++w) {
        if (b->area[w] <= 0.0) continue;
        if (container < 0) container = w;
        contained |= row_inside(xs + off[nr + w], cnt[nr + w], x);
      }
      CLSPH_CHECK(container < 0 || contained, CLSPH_E_INPUT,
                  "%s:%d: fluid region '%s' extends past the wall of line %d: the particle at "
                  "(%g, %g) is outside it (a counter-clockwise closed wall holds its fluid inside)",
                  s->case_path, g->line, g->name, s->walls[container].line, x, y);
      CLSPH_TRY(push_fluid(b, first, xy));
    }
  }
  /* regions given as points: their particles where the script puts them */
  for (int r = 0; r < nr; ++r) {
    const struct scene_region *g = &s->regions[r];
    for (int i = 0; i < g->npts && g->given; ++i) {
      const double *xy = &g->pts[2 * i];
      for (int a = 0; a < 2; ++a)
        CLSPH_CHECK(xy[a] >= s->lo[a] && xy[a] <= s->hi[a], CLSPH_E_INPUT,
                    "%s:%d: fluid region '%s': points[%d] (%g, %g) is outside the domain "
                    "[%g, %g] x [%g, %g]",
                    s->case_path, g->line, g->name, i + 1, xy[0], xy[1], s->lo[0], s->hi[0],
                    s->lo[1], s->hi[1]);
      int inside = near_obstacle(b, xy, (0.5 - layer_tol) * s->dr), container = -1, held = 0;
      for (int w = 0; w < nw; ++w) {
        const struct scene_wall *wl = &s->walls[w];
        if (b->area[w] < 0.0) inside |= point_inside(wl->pts, wl->npts, xy);
        if (b->area[w] > 0.0) {
          if (container < 0) container = w;
          held |= point_inside(wl->pts, wl->npts, xy);
        }
      }
      CLSPH_CHECK(!inside, CLSPH_E_INPUT,
                  "%s:%d: fluid region '%s': points[%d] (%g, %g) lies in an obstacle or within "
                  "dr/2 of it",
                  s->case_path, g->line, g->name, i + 1, xy[0], xy[1]);
      CLSPH_CHECK(container < 0 || held, CLSPH_E_INPUT,
                  "%s:%d: fluid region '%s': points[%d] (%g, %g) is outside the closed wall of "
                  "line %d (a counter-clockwise closed wall holds its fluid inside)",
                  s->case_path, g->line, g->name, i + 1, xy[0], xy[1], s->walls[container].line);
      CLSPH_TRY(push_fluid(b, r, xy));
    }
    count[r] += g->given ? (size_t)g->npts : 0;
  }
  for (int r = 0; r < nr; ++r)
    CLSPH_CHECK(count[r] > 0, CLSPH_E_INPUT,
                "%s:%d: fluid region '%s' contains no particle at dr = %g", s->case_path,
                s->regions[r].line, s->regions[r].name, s->dr);
done:
  free(xs);
  free(count);
  free(cnt);
  free(off);
  return st;
}

/* Points given by the script (fill { points }) keep dr/2 from every other fluid particle: two
 * particles closer than that are a duplicate or an overlap of two fills (the lattice's own points
 * are dr apart). Cells of dr/2 sorted by key; a pair that close lies in neighbouring cells. */
struct cell_key {
  long cx, cy;
  size_t i;
};

static int cell_key_cmp(const void *pa, const void *pb)
{
  const struct cell_key *a = pa, *b = pb;
  if (a->cy != b->cy) return a->cy < b->cy ? -1 : 1;
  if (a->cx != b->cx) return a->cx < b->cx ? -1 : 1;
  return (a->i > b->i) - (a->i < b->i);
}

static enum clsph_status check_given_spacing(struct build *b)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = b->s;
  struct cell_key *keys = NULL;
  int given = 0;
  for (int r = 0; r < s->nregions; ++r) given |= s->regions[r].given;
  if (!given || b->np < 2) goto done;
  const double c = 0.5 * b->dr;
  /* a periodic axis wraps its cells (a whole number of them, each at least c) and distances */
  double cell[2] = {c, c};
  long ncell[2] = {0, 0};
  for (int a = 0; a < 2; ++a) {
    if (!s->periodic[a]) continue;
    ncell[a] = (long)fmax(1.0, floor((s->hi[a] - s->lo[a]) / c));
    cell[a] = (s->hi[a] - s->lo[a]) / (double)ncell[a];
  }
  keys = malloc(b->np * sizeof *keys);
  CLSPH_CHECK(keys != NULL, CLSPH_E_NOMEM, "geometry: out of memory");
  for (size_t i = 0; i < b->np; ++i) {
    long ix[2];
    for (int a = 0; a < 2; ++a) {
      ix[a] = (long)floor((b->p[i].x[a] - s->lo[a]) / cell[a]);
      if (s->periodic[a]) ix[a] = (ix[a] % ncell[a] + ncell[a]) % ncell[a];
    }
    keys[i] = (struct cell_key){ix[0], ix[1], i};
  }
  qsort(keys, b->np, sizeof *keys, cell_key_cmp);
  for (size_t k = 0; k < b->np; ++k) {
    const struct particle *p = &b->p[keys[k].i];
    for (long dy = 0; dy <= 1; ++dy) {
      for (long dx = -1; dx <= 1; ++dx) {
        if (dy == 0 && dx < 0) continue; /* each pair of cells once */
        struct cell_key want = {keys[k].cx + dx, keys[k].cy + dy, 0};
        if (s->periodic[0]) want.cx = (want.cx % ncell[0] + ncell[0]) % ncell[0];
        if (s->periodic[1]) want.cy = (want.cy % ncell[1] + ncell[1]) % ncell[1];
        size_t lo = 0, hi = b->np; /* the first key >= want */
        while (lo < hi) {
          size_t mid = lo + (hi - lo) / 2;
          if (cell_key_cmp(&keys[mid], &want) < 0)
            lo = mid + 1;
          else
            hi = mid;
        }
        for (size_t m = lo; m < b->np && keys[m].cx == want.cx && keys[m].cy == want.cy; ++m) {
          if (m == k || (dx == 0 && dy == 0 && m < k)) continue;
          const struct particle *q = &b->p[keys[m].i];
          double e[2];
          for (int a = 0; a < 2; ++a) e[a] = gap(s, a, p->x[a], q->x[a]);
          const double d = hypot(e[0], e[1]);
          const struct scene_region *gp = &s->regions[p->group], *gq = &s->regions[q->group];
          CLSPH_CHECK(d >= c, CLSPH_E_INPUT,
                      "%s:%d: fluid particles at (%g, %g) ('%s') and (%g, %g) ('%s') are %g m "
                      "apart, less than dr/2: points given twice, or fills that overlap",
                      s->case_path, gp->given ? gp->line : gq->line, p->x[0], p->x[1], gp->name,
                      q->x[0], q->x[1], gq->name, d);
        }
      }
    }
  }
done:
  free(keys);
  return st;
}

/* Every fluid particle is at least dr/4 from every wall and not behind an open wall nearby. */
static enum clsph_status check_fluid_near_walls(struct build *b)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = b->s;
  for (size_t i = 0; i < b->np; ++i) {
    struct particle *p = &b->p[i];
    const struct scene_region *g = &s->regions[p->group];
    struct nearest r;
    index_nearest(&b->ix, p->x, -1, b->dr, &r);
    CLSPH_CHECK(!r.found || r.d >= 0.25 * b->dr, CLSPH_E_INPUT,
                "%s:%d: fluid region '%s' overlaps the wall of line %d: the particle at (%g, %g) "
                "is %g m from it, less than dr/4",
                s->case_path, g->line, g->name, s->walls[r.wall].line, p->x[0], p->x[1], r.d);
    for (int w = 0; r.found && w < s->nwalls; ++w) {
      if (s->walls[w].closed) continue; /* closed walls were checked by fill_fluid */
      struct nearest rw;
      index_nearest(&b->ix, p->x, w, b->dr, &rw);
      CLSPH_CHECK(!rw.found || rw.free_end || !solid_side(b, w, p->x, &rw), CLSPH_E_INPUT,
                  "%s:%d: fluid region '%s' crosses the wall of line %d: the particle at (%g, %g) "
                  "is on its solid side (the fluid must be on the left of a wall)",
                  s->case_path, g->line, g->name, s->walls[w].line, p->x[0], p->x[1]);
    }
    p->group = -1;
  }
done:
  return st;
}

/* ---- the container is closed --------------------------------------------------------------- */

/* The walls must keep the fluid in: a flood fill on a grid of dr/2 cells, from the fluid's cells,
 * through every cell no wall crosses, may reach the edge of the domain only where the fluid may
 * leave it: a periodic axis, an inflow or outflow section, or the side that faces up when there
 * is gravity (a free surface: the water of an open tank is kept in by gravity, not by a lid).
 * A wall polyline left open where it should close (a gap in a box, a missing lid on a confined
 * flow) is refused with the place where the fluid gets out. */
static int section_near(const struct scene *s, const double x[2], double tol)
{
  for (int k = 0; k < s->nsections; ++k) {
    const double *a = s->sections[k].a, *b = s->sections[k].b;
    double t[2] = {b[0] - a[0], b[1] - a[1]}, l2 = t[0] * t[0] + t[1] * t[1];
    double u = l2 > 0.0 ? ((x[0] - a[0]) * t[0] + (x[1] - a[1]) * t[1]) / l2 : 0.0;
    u = u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
    if (hypot(x[0] - a[0] - u * t[0], x[1] - a[1] - u * t[1]) <= tol) return 1;
  }
  return 0;
}

/* Marks with `value` the empty cells of the n[0] x n[1] grid (origin o, cell c) that the segment
 * pa-pe passes through (sampled at a quarter cell); a point on a non-periodic far edge falls in
 * the last cell. */
static void mark_segment(unsigned char *mark, const long n[2], const double o[2], double c,
                         const int periodic[2], const double *pa, const double *pe,
                         unsigned char value)
{
  long m = (long)ceil(4.0 * hypot(pe[0] - pa[0], pe[1] - pa[1]) / c) + 1;
  for (long q = 0; q <= m; ++q) {
    double t = (double)q / (double)m;
    long ix[2];
    for (int a = 0; a < 2; ++a) {
      ix[a] = (long)floor((pa[a] + t * (pe[a] - pa[a]) - o[a]) / c);
      if (periodic[a]) ix[a] = ((ix[a] % n[a]) + n[a]) % n[a];
      if (ix[a] == n[a] && !periodic[a]) ix[a] = n[a] - 1; /* on the far edge */
    }
    if (ix[0] >= 0 && ix[0] < n[0] && ix[1] >= 0 && ix[1] < n[1]) {
      unsigned char *cell = &mark[(size_t)ix[1] * (size_t)n[0] + (size_t)ix[0]];
      if (*cell == 0) *cell = value;
    }
  }
}

static enum clsph_status check_enclosed(struct build *b)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = b->s;
  const double c = 0.5 * b->dr; /* cell size */
  unsigned char *mark = NULL;   /* 1: a wall crosses it, 2: reached, 3: a section crosses it */
  size_t *queue = NULL;
  if (b->nfluid == 0) return CLSPH_OK; /* no walls at all: the flood reaches the domain's edges */
  /* a non-periodic axis gets a margin of one cell on each side, where walls on the domain's edge
   * fall; reaching a margin cell is leaving the domain */
  long n[2];
  double o[2];
  for (int a = 0; a < 2; ++a) {
    const int margin = s->periodic[a] ? 0 : 1;
    n[a] = (long)ceil((s->hi[a] - s->lo[a]) / c - 1e-9) + 2 * margin;
    o[a] = s->lo[a] - margin * c;
  }
  CLSPH_CHECK((double)n[0] * (double)n[1] < 2e8, CLSPH_E_INPUT,
              "%s: the domain is too large for dr = %g to check that the walls close it",
              s->case_path, b->dr);
  const size_t ncell = (size_t)n[0] * (size_t)n[1];
  mark = calloc(ncell, 1);
  queue = malloc(ncell * sizeof *queue);
  CLSPH_CHECK(mark != NULL && queue != NULL, CLSPH_E_NOMEM, "geometry: out of memory");
  /* walls: every cell a segment passes through */
  for (int w = 0; w < s->nwalls; ++w) {
    const struct scene_wall *wl = &s->walls[w];
    int nseg = wl->closed ? wl->npts : wl->npts - 1;
    for (int k = 0; k < nseg; ++k)
      mark_segment(mark, n, o, c, s->periodic, &wl->pts[2 * k], &wl->pts[2 * ((k + 1) % wl->npts)],
                   1);
  }
  /* sections: the fluid leaves through them (a section across a channel that runs at a slant to
   * the domain's sides opens no path to an edge; what lies beyond it is outside) */
  for (int k = 0; k < s->nsections; ++k)
    mark_segment(mark, n, o, c, s->periodic, s->sections[k].a, s->sections[k].b, 3);
  /* the flood, from the fluid's cells */
  size_t head = 0, tail = 0;
  for (size_t i = 0; i < b->nfluid; ++i) { /* the fluid particles come first */
    long ix = (long)floor((b->p[i].x[0] - o[0]) / c), iy = (long)floor((b->p[i].x[1] - o[1]) / c);
    if (ix < 0 || ix >= n[0] || iy < 0 || iy >= n[1]) continue;
    size_t k = (size_t)iy * (size_t)n[0] + (size_t)ix;
    if (mark[k] == 0) {
      mark[k] = 2;
      queue[tail++] = k;
    }
  }
  const double gn = hypot(s->gravity[0], s->gravity[1]);
  static const char *const side[4] = {"left (x min)", "right (x max)", "bottom (y min)",
                                      "top (y max)"};
  const long step[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
  while (head < tail) {
    size_t k = queue[head++];
    long ix = (long)(k % (size_t)n[0]), iy = (long)(k / (size_t)n[0]);
    for (int d = 0; d < 4; ++d) {
      long j[2] = {ix + step[d][0], iy + step[d][1]};
      for (int a = 0; a < 2; ++a)
        if (s->periodic[a]) j[a] = (j[a] + n[a]) % n[a];
      size_t kj = (size_t)j[1] * (size_t)n[0] + (size_t)j[0];
      if (mark[kj] != 0) continue;
      const int axis = step[d][0] != 0 ? 0 : 1;
      if (!s->periodic[axis] && (j[axis] == 0 || j[axis] == n[axis] - 1)) {
        /* out of the domain: allowed through a section, or upwards (a free surface) */
        const double x[2] = {o[0] + ((double)ix + 0.5) * c, o[1] + ((double)iy + 0.5) * c};
        const double up = -(step[d][0] * s->gravity[0] + step[d][1] * s->gravity[1]);
        CLSPH_CHECK((gn > 0.0 && up > 0.5 * gn) || section_near(s, x, 2.0 * b->dr), CLSPH_E_INPUT,
                    "%s: the walls do not close the fluid in: it can reach the %s side of the "
                    "domain near (%g, %g)%s; close the wall polyline (closed = true), add the "
                    "missing wall, or make that axis periodic",
                    s->case_path, side[d], x[0], x[1],
                    gn > 0.0 ? "" : " (with no gravity, the container needs a lid too)");
        continue;
      }
      mark[kj] = 2;
      queue[tail++] = kj;
    }
  }
done:
  free(queue);
  free(mark);
  return st;
}

/* ---- USAW vertices and segments ------------------------------------------------------------ */

/* The vertex particle at x of wall w: an existing one when x is the end of a wall (free_end: x is
 * a free end of wall w; else x is a vertex of the polyline and may be another wall's free end),
 * a new one otherwise. `exclude` is the previous vertex of the same polyline. */
static enum clsph_status usaw_vertex(struct build *b, int w, const double x[2], int polyline_pt,
                                     int free_end, size_t exclude, size_t *ends, size_t *nends,
                                     size_t *out)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = b->s;
  if (free_end) {
    for (size_t v = b->nfluid; v < b->np; ++v) {
      if (v != exclude && same_point(s, b->p[v].x, x)) {
        *out = v;
        goto done;
      }
    }
  } else if (polyline_pt) {
    for (size_t k = 0; k < *nends; ++k) {
      if (same_point(s, b->p[ends[k]].x, x)) {
        *out = ends[k];
        goto done;
      }
    }
  }
  struct particle p = {.x = {x[0], x[1]}, .kind = KIND_VERTEX, .group = w};
  wall_velocity(&s->walls[w], x, p.v);
  for (int a = 0; a < 2; ++a) { /* into [lo, hi) on a periodic axis */
    if (!s->periodic[a]) continue;
    double len = s->hi[a] - s->lo[a];
    p.x[a] = s->lo[a] + fmod(p.x[a] - s->lo[a], len);
    if (p.x[a] < s->lo[a]) p.x[a] += len;
    if (p.x[a] >= s->hi[a]) p.x[a] = s->lo[a];
  }
  CLSPH_TRY(push_particle(b, &p));
  *out = b->np - 1;
  if (free_end) ends[(*nends)++] = *out;
done:
  return st;
}

static enum clsph_status build_usaw(struct build *b)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = b->s;
  size_t *ends = NULL, *in = NULL, *out = NULL, nends = 0;
  const size_t none = SIZE_MAX;
  if (s->nwalls == 0) goto done;
  ends = malloc(2 * (size_t)s->nwalls * sizeof *ends);
  CLSPH_CHECK(ends != NULL, CLSPH_E_NOMEM, "geometry: out of memory");
  /* vertices along each polyline, and the segments between them */
  for (int w = 0; w < s->nwalls; ++w) {
    const struct scene_wall *wl = &s->walls[w];
    const int ne = wl->closed ? wl->npts : wl->npts - 1;
    size_t first = 0, prev = 0;
    int short_edges = 0;
    CLSPH_TRY(usaw_vertex(b, w, wl->pts, 1, !wl->closed, none, ends, &nends, &first));
    prev = first;
    for (int e = 0; e < ne; ++e) {
      const double *pa = wl->pts + 2 * e, *pb = wl->pts + 2 * ((e + 1) % wl->npts);
      const double len = hypot(pb[0] - pa[0], pb[1] - pa[1]);
      const long m = lround(len / b->dr) > 1 ? lround(len / b->dr) : 1;
      short_edges += len < 0.5 * b->dr;
      struct segment sg = {
          .t = {(pb[0] - pa[0]) / len, (pb[1] - pa[1]) / len}, .len = len / (double)m, .wall = w};
      sg.n[0] = -sg.t[1];
      sg.n[1] = sg.t[0];
      for (long j = 1; j <= m; ++j) {
        size_t next = 0;
        if (j < m) {
          double f = (double)j / (double)m;
          double x[2] = {pa[0] + f * (pb[0] - pa[0]), pa[1] + f * (pb[1] - pa[1])};
          CLSPH_TRY(usaw_vertex(b, w, x, 0, 0, prev, ends, &nends, &next));
        } else if (wl->closed && e == ne - 1) {
          next = first;
        } else {
          CLSPH_TRY(
              usaw_vertex(b, w, pb, 1, !wl->closed && e == ne - 1, prev, ends, &nends, &next));
        }
        sg.v[0] = prev;
        sg.v[1] = next;
        CLSPH_TRY(push_segment(b, &sg));
        prev = next;
      }
    }
    if (short_edges > 0)
      log_warn("%s:%d: %d wall edges are shorter than dr/2, so their vertex particles are closer "
               "than dr/2 (divide arcs at about dr)",
               s->case_path, wl->line, short_edges);
  }
  /* at each vertex: the segment that arrives and the one that leaves */
  const size_t nv = b->np - b->nfluid;
  in = malloc(nv * sizeof *in);
  out = malloc(nv * sizeof *out);
  CLSPH_CHECK(in != NULL && out != NULL, CLSPH_E_NOMEM, "geometry: out of memory");
  for (size_t v = 0; v < nv; ++v) in[v] = out[v] = none;
  for (size_t k = 0; k < b->nseg; ++k) {
    for (int end = 0; end < 2; ++end) {
      size_t *slot = end == 0 ? &out[b->seg[k].v[0] - b->nfluid] : &in[b->seg[k].v[1] - b->nfluid];
      const struct particle *p = &b->p[b->seg[k].v[end]];
      CLSPH_CHECK(*slot == none, CLSPH_E_INPUT,
                  "%s:%d: wall meets the wall of line %d at (%g, %g) with the opposite "
                  "orientation or as a third branch (the fluid must stay on the left of both)",
                  s->case_path, s->walls[b->seg[k].wall].line, s->walls[b->seg[*slot].wall].line,
                  p->x[0], p->x[1]);
      *slot = k;
    }
  }
  /* θ_v: the counter-clockwise angle from t_out to −t_in; normal: the bisector of that sector */
  for (size_t v = 0; v < nv; ++v) {
    struct particle *p = &b->p[b->nfluid + v];
    if (in[v] != none && out[v] != none) {
      const double *u = b->seg[out[v]].t, *ti = b->seg[in[v]].t;
      double c = u[0] * (-ti[1]) - u[1] * (-ti[0]), d = u[0] * (-ti[0]) + u[1] * (-ti[1]);
      double th = atan2(c, d);
      if (th <= 0.0) th += 2.0 * geom_pi;
      p->theta = th;
      p->normal[0] = cos(0.5 * th) * u[0] - sin(0.5 * th) * u[1];
      p->normal[1] = sin(0.5 * th) * u[0] + cos(0.5 * th) * u[1];
    } else { /* a free end: one segment; θ = π as if the wall went on straight */
      const struct segment *sg = &b->seg[in[v] != none ? in[v] : out[v]];
      p->theta = geom_pi;
      p->normal[0] = sg->n[0];
      p->normal[1] = sg->n[1];
    }
  }
done:
  free(out);
  free(in);
  free(ends);
  return st;
}

/* ---- dummy layers ------------------------------------------------------------------------- */

/* A fitted wall's dummy layers (wall { dummies = "fitted" }): rows along the wall on its solid
 * side at (j + ½) dr, j < layers (the polyline moved by the mitre of its segments' normals, as a
 * body-fitted fluid's rows run along it), each row cut into equal parts of about dr with a
 * particle at each part's middle (a closed wall: at each part's start). For smooth walls: where
 * a row folds on itself (a concave solid corner sharper than its offset) its particles crowd. */
static enum clsph_status build_fitted_dummy(struct build *b, int w, int layers)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = b->s;
  const struct scene_wall *wl = &s->walls[w];
  const double dr = b->dr;
  const int n = wl->npts, nseg = wl->closed ? n : n - 1;
  double *nrm = malloc(2 * (size_t)nseg * sizeof *nrm),
         *row = malloc(2 * (size_t)(n + 1) * sizeof *row);
  CLSPH_CHECK(nrm != NULL && row != NULL, CLSPH_E_NOMEM, "geometry: out of memory");
  for (int k = 0; k < nseg; ++k) { /* unit normals into the fluid (on the left) */
    const double *pa = &wl->pts[2 * k], *pe = &wl->pts[2 * ((k + 1) % n)];
    const double len = hypot(pe[0] - pa[0], pe[1] - pa[1]);
    nrm[2 * k] = -(pe[1] - pa[1]) / len;
    nrm[2 * k + 1] = (pe[0] - pa[0]) / len;
  }
  for (int j = 0; j < layers; ++j) {
    const double d = (j + 0.5) * dr;
    for (int i = 0; i < n; ++i) { /* the row's vertices: each moved by −d along its mitre */
      const int k1 = wl->closed ? (i + nseg - 1) % nseg : (i > 0 ? i - 1 : 0);
      const int k2 = wl->closed ? i % nseg : (i < nseg ? i : nseg - 1);
      const double *n1 = &nrm[2 * k1], *n2 = &nrm[2 * k2];
      const double c = 1.0 + n1[0] * n2[0] + n1[1] * n2[1];
      CLSPH_CHECK(c > 0.1, CLSPH_E_INPUT,
                  "%s:%d: wall with dummies = \"fitted\": it turns back on itself at (%g, %g); "
                  "fitted rows need a smooth wall (or dummies = \"lattice\")",
                  s->case_path, wl->line, wl->pts[2 * i], wl->pts[2 * i + 1]);
      row[2 * i] = wl->pts[2 * i] - d * (n1[0] + n2[0]) / c;
      row[2 * i + 1] = wl->pts[2 * i + 1] - d * (n1[1] + n2[1]) / c;
    }
    if (wl->closed) memcpy(&row[2 * n], &row[0], 2 * sizeof *row);
    const int nv = wl->closed ? n + 1 : n;
    double total = 0.0;
    for (int i = 0; i + 1 < nv; ++i)
      total += hypot(row[2 * i + 2] - row[2 * i], row[2 * i + 3] - row[2 * i + 1]);
    const long parts = lround(fmax(total / dr, wl->closed ? 3.0 : 1.0));
    const double step = total / (double)parts;
    int seg = 0;
    double at = 0.0; /* the arc length at the start of row segment seg */
    for (long q = 0; q < parts; ++q) {
      const double want = (wl->closed ? (double)q : (double)q + 0.5) * step;
      double len = hypot(row[2 * seg + 2] - row[2 * seg], row[2 * seg + 3] - row[2 * seg + 1]);
      while (at + len < want && seg + 2 < nv) {
        at += len;
        ++seg;
        len = hypot(row[2 * seg + 2] - row[2 * seg], row[2 * seg + 3] - row[2 * seg + 1]);
      }
      const double f = len > 0.0 ? fmin(1.0, (want - at) / len) : 0.0;
      struct particle p = {.x = {row[2 * seg] + f * (row[2 * seg + 2] - row[2 * seg]),
                                 row[2 * seg + 1] + f * (row[2 * seg + 3] - row[2 * seg + 1])},
                           .kind = KIND_DUMMY,
                           .group = w};
      struct nearest r;
      index_nearest(&b->ix, p.x, w, dr, &r);
      if (!r.found || r.d <= merge_tol * dr) continue;
      p.normal[0] = (r.q[0] - p.x[0]) / r.d;
      p.normal[1] = (r.q[1] - p.x[1]) / r.d;
      p.dist = r.d;
      wall_velocity(wl, p.x, p.v);
      CLSPH_TRY(push_particle(b, &p));
    }
  }
done:
  free(row);
  free(nrm);
  return st;
}

/* A point on the fluid side of its nearest wall `skip` can still be inside another wall's solid
 * layers, where a wall ends on another (a gate standing on a floor: beside its foot the floor is
 * nearer than the gate): the nearest such wall, if any, replaces *r. Fluid is never there (it is
 * refused on an open wall's solid side and kept out of closed ones). */
static int other_solid(const struct build *b, const double p[2], int skip, double thick,
                       struct nearest *r)
{
  struct nearest best;
  best.found = 0;
  for (int w = 0; w < b->s->nwalls; ++w) {
    if (w == skip) continue;
    struct nearest rw;
    index_nearest(&b->ix, p, w, b->dr, &rw);
    if (!rw.found || !solid_side(b, w, p, &rw) || fmax(rw.mitre, rw.d / sqrt(2.0)) > thick)
      continue;
    if (!best.found || rw.d < best.d) best = rw;
  }
  if (best.found) *r = best;
  return best.found;
}

static enum clsph_status build_dummy(struct build *b, int layers)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = b->s;
  const double dr = b->dr, thick = layers * dr + layer_tol * dr;
  const struct wall_index *ix = &b->ix;
  if (ix->nedges == 0) goto done;
  double bb[4] = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
  for (size_t e = 0; e < ix->nedges; ++e) {
    for (int a = 0; a < 2; ++a) {
      bb[2 * a] = fmin(bb[2 * a], fmin(ix->edges[e].a[a], ix->edges[e].b[a]) - ix->reach);
      bb[2 * a + 1] = fmax(bb[2 * a + 1], fmax(ix->edges[e].a[a], ix->edges[e].b[a]) + ix->reach);
    }
  }
  long k0[2], k1[2];
  CLSPH_TRY(lat_box(s, bb, k0, k1));
  for (long j = k0[1]; j <= k1[1]; ++j) {
    for (long i = k0[0]; i <= k1[0]; ++i) {
      struct particle p = {.x = {lat(s, 0, i), lat(s, 1, j)}, .kind = KIND_DUMMY};
      struct nearest r;
      index_nearest(ix, p.x, -1, dr, &r);
      if (!r.found || s->walls[r.wall].fitted) continue; /* (a fitted wall's rows: below) */
      if (r.d <= merge_tol * dr) { /* on the wall: normal from the edges there */
        double nn = hypot(r.nsum[0], r.nsum[1]);
        if (nn < 1e-12) continue;
        p.normal[0] = r.nsum[0] / nn;
        p.normal[1] = r.nsum[1] / nn;
      } else {
        if (!solid_side(b, r.wall, p.x, &r) && !other_solid(b, p.x, r.wall, thick, &r)) continue;
        if (fmax(r.mitre, r.d / sqrt(2.0)) > thick) continue;
        p.normal[0] = (r.q[0] - p.x[0]) / r.d;
        p.normal[1] = (r.q[1] - p.x[1]) / r.d;
      }
      p.dist = r.d;
      p.group = r.wall;
      wall_velocity(&s->walls[r.wall], p.x, p.v);
      CLSPH_TRY(push_particle(b, &p));
    }
  }
  for (int w = 0; w < s->nwalls; ++w)
    if (s->walls[w].fitted) CLSPH_TRY(build_fitted_dummy(b, w, layers));
done:
  return st;
}

/* ---- inflow and outflow layers ------------------------------------------------------------ */

static enum clsph_status build_section(struct build *b, int k)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = b->s;
  const struct scene_section *sc = &s->sections[k];
  const char *what = sc->kind == SCENE_INFLOW ? "inflow" : "outflow";
  const double dr = b->dr, tol = merge_tol * dr;
  const double len = hypot(sc->b[0] - sc->a[0], sc->b[1] - sc->a[1]);
  const double t[2] = {(sc->b[0] - sc->a[0]) / len, (sc->b[1] - sc->a[1]) / len};
  const double n[2] = {-t[1], t[0]};
  const int layers = sc->layers > 0 ? sc->layers : default_sec_layers;
  const double thick = layers * dr + layer_tol * dr;
  /* fluid next to the section, and none in its layers */
  int next_to = 0;
  for (size_t i = 0; i < b->nfluid; ++i) {
    const double ap[2] = {b->p[i].x[0] - sc->a[0], b->p[i].x[1] - sc->a[1]};
    const double along = dot2(ap, t), h = dot2(ap, n);
    if (along < -tol || along > len + tol) continue;
    if (h > 0.0 && h <= 1.5 * dr + tol) next_to = 1;
    CLSPH_CHECK(!(h < -tol && h >= -thick), CLSPH_E_INPUT,
                "%s:%d: the fluid particle at (%g, %g) lies in the layers of %s '%s' (the fluid "
                "must be on the left of a->b)",
                s->case_path, sc->line, b->p[i].x[0], b->p[i].x[1], what, sc->name);
  }
  CLSPH_CHECK(next_to, CLSPH_E_INPUT,
              "%s:%d: %s '%s' has no fluid next to it (none within 1.5 dr on the left of a->b)",
              s->case_path, sc->line, what, sc->name);
  /* the layers: 0 < −h <= layers·dr, 0 <= along <= len */
  double bb[4] = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
  for (int c = 0; c < 4; ++c) {
    const double *e = c % 2 == 0 ? sc->a : sc->b;
    const double back = c < 2 ? 0.0 : thick;
    for (int a = 0; a < 2; ++a) {
      bb[2 * a] = fmin(bb[2 * a], e[a] - back * n[a]);
      bb[2 * a + 1] = fmax(bb[2 * a + 1], e[a] - back * n[a]);
    }
  }
  long k0[2], k1[2];
  CLSPH_TRY(lat_box(s, bb, k0, k1));
  for (long j = k0[1]; j <= k1[1]; ++j) {
    for (long i = k0[0]; i <= k1[0]; ++i) {
      struct particle p = {.x = {lat(s, 0, i), lat(s, 1, j)},
                           .normal = {n[0], n[1]},
                           .kind = sc->kind == SCENE_INFLOW ? KIND_INFLOW : KIND_OUTFLOW,
                           .group = k,
                           .k0 = sc->k, /* an entry's k and ε (NAN: turbulence { }'s) */
                           .eps0 = sc->epsilon};
      const double ap[2] = {p.x[0] - sc->a[0], p.x[1] - sc->a[1]};
      const double along = dot2(ap, t), h = dot2(ap, n);
      if (along < -tol || along > len + tol || h >= -tol || h < -thick) continue;
      if (sc->kind == SCENE_INFLOW && sc->nprof > 0) { /* an entry's tables of k and ε */
        if (isnan(sc->k)) p.k0 = scene_section_value(sc, 1, along);
        if (isnan(sc->epsilon)) p.eps0 = scene_section_value(sc, 2, along);
      }
      if (sc->kind == SCENE_INFLOW || sc->profile != 0) { /* outflow: along −n */
        double f = fmin(1.0, fmax(0.0, along / len));
        double speed = sc->profile == SCENE_PARABOLIC ? sc->velocity * 4.0 * f * (1.0 - f)
                       : sc->profile == SCENE_TABLE   ? scene_section_value(sc, 0, along)
                                                      : sc->velocity;
        if (sc->kind == SCENE_OUTFLOW) speed = -speed;
        p.v[0] = speed * n[0];
        p.v[1] = speed * n[1];
      }
      CLSPH_TRY(push_particle(b, &p));
    }
  }
  if (sc->kind == SCENE_OUTFLOW && b->park != NULL && b->park->fraction > 0.0) {
    double exits = 0.0; /* the exits' total length: each gets its share */
    for (int q = 0; q < s->nsections; ++q)
      if (s->sections[q].kind == SCENE_OUTFLOW)
        exits += hypot(s->sections[q].b[0] - s->sections[q].a[0],
                       s->sections[q].b[1] - s->sections[q].a[1]);
    const long count = (long)ceil(b->park->fraction * (double)b->nfluid * len / exits);
    const double back = layers * dr + b->park->behind;
    for (long q = 0; q < count; ++q) {
      const double along = (q + 0.5) * len / (double)count;
      struct particle p = {
          .x = {sc->a[0] + along * t[0] - back * n[0], sc->a[1] + along * t[1] - back * n[1]},
          .normal = {n[0], n[1]},
          .kind = KIND_PARKED,
          .group = k};
      CLSPH_TRY(push_particle(b, &p));
    }
  }
done:
  return st;
}

/* ---- output ------------------------------------------------------------------------------- */

static enum clsph_status emit(struct build *b, struct geom *g)
{
  enum clsph_status st = CLSPH_OK;
  const size_t n = b->np, ns = b->nseg;
  struct geom t = {0};
  t.dim = 2;
  t.n = n;
  t.nfluid = b->nfluid;
  t.nseg = ns;
  if (n > 0) {
    t.x = malloc(2 * n * sizeof *t.x);
    t.v = malloc(2 * n * sizeof *t.v);
    t.p0 = malloc(n * sizeof *t.p0);
    t.rho0 = malloc(n * sizeof *t.rho0);
    t.k0 = malloc(n * sizeof *t.k0);
    t.eps0 = malloc(n * sizeof *t.eps0);
    t.normal = malloc(2 * n * sizeof *t.normal);
    t.theta = malloc(n * sizeof *t.theta);
    t.dist = malloc(n * sizeof *t.dist);
    t.kind = malloc(n * sizeof *t.kind);
    t.group = malloc(n * sizeof *t.group);
    CLSPH_CHECK(t.x != NULL && t.v != NULL && t.p0 != NULL && t.rho0 != NULL && t.k0 != NULL &&
                    t.eps0 != NULL && t.normal != NULL && t.theta != NULL && t.dist != NULL &&
                    t.kind != NULL && t.group != NULL,
                CLSPH_E_NOMEM, "geometry: out of memory for %zu particles", n);
  }
  if (ns > 0) {
    t.seg_v = malloc(2 * ns * sizeof *t.seg_v);
    t.seg_normal = malloc(2 * ns * sizeof *t.seg_normal);
    t.seg_len = malloc(ns * sizeof *t.seg_len);
    t.seg_wall = malloc(ns * sizeof *t.seg_wall);
    CLSPH_CHECK(t.seg_v != NULL && t.seg_normal != NULL && t.seg_len != NULL && t.seg_wall != NULL,
                CLSPH_E_NOMEM, "geometry: out of memory for %zu segments", ns);
  }
  for (size_t i = 0; i < n; ++i) {
    const struct particle *p = &b->p[i];
    for (int a = 0; a < 2; ++a) {
      t.x[2 * i + (size_t)a] = p->x[a];
      t.v[2 * i + (size_t)a] = p->v[a];
      t.normal[2 * i + (size_t)a] = p->normal[a];
    }
    t.p0[i] = p->kind == KIND_FLUID ? p->p0 : (double)NAN;
    t.rho0[i] = p->kind == KIND_FLUID ? p->rho0 : (double)NAN;
    const int carries = p->kind == KIND_FLUID || p->kind == KIND_INFLOW;
    t.k0[i] = carries ? p->k0 : (double)NAN;
    t.eps0[i] = carries ? p->eps0 : (double)NAN;
    t.theta[i] = p->theta;
    t.dist[i] = p->dist;
    t.kind[i] = p->kind;
    t.group[i] = p->group;
  }
  for (size_t k = 0; k < ns; ++k) {
    const struct segment *sg = &b->seg[k];
    t.seg_v[2 * k] = sg->v[0];
    t.seg_v[2 * k + 1] = sg->v[1];
    t.seg_normal[2 * k] = sg->n[0];
    t.seg_normal[2 * k + 1] = sg->n[1];
    t.seg_len[k] = sg->len;
    t.seg_wall[k] = sg->wall;
  }
  *g = t;
  memset(&t, 0, sizeof t); /* the caller owns the arrays now */
done:
  geometry_free(&t);
  return st;
}

enum clsph_status geometry_build(const struct scene *s, const char *model, int layers,
                                 const struct geom_park *park, struct geom *out)
{
  enum clsph_status st = CLSPH_OK;
  struct build b = {0};
  memset(out, 0, sizeof *out);
  if (s->dim == 3) return geometry_build3(s, model, layers, out);
  b.s = s;
  b.park = park;
  b.dr = s->dr;
  CLSPH_TRY(check_scene(s, model, layers, &b.model));
  /* closed walls: orientation */
  if (s->nwalls > 0) {
    b.area = calloc((size_t)s->nwalls, sizeof *b.area);
    CLSPH_CHECK(b.area != NULL, CLSPH_E_NOMEM, "geometry: out of memory");
    for (int w = 0; w < s->nwalls; ++w)
      if (s->walls[w].closed) b.area[w] = polygon_area(s->walls[w].pts, s->walls[w].npts);
  }
  /* wall index reaching 2 dr, or the mitred dummy layers (√2 layers·dr at a corner) */
  double reach = 2.0 * b.dr;
  if (b.model == MODEL_DUMMY) reach = fmax(reach, sqrt(2.0) * (layers + layer_tol) * b.dr);
  CLSPH_TRY(index_build(s, reach, &b.ix));
  /* fluid, then the walls, then the inflow/outflow layers */
  CLSPH_TRY(fill_fluid(&b));
  CLSPH_TRY(check_given_spacing(&b));
  CLSPH_TRY(check_fluid_near_walls(&b));
  b.nfluid = b.np;
  if (b.model == MODEL_USAW) CLSPH_TRY(build_usaw(&b));
  if (b.model == MODEL_DUMMY) CLSPH_TRY(build_dummy(&b, layers));
  const size_t nwallp = b.np - b.nfluid;
  for (int k = 0; k < s->nsections; ++k) CLSPH_TRY(build_section(&b, k));
  /* after the walls and sections, whose own errors say more about a broken wall */
  if (b.model != MODEL_NONE) CLSPH_TRY(check_enclosed(&b));
  CLSPH_TRY(emit(&b, out));
  for (int r = 0; r < s->nregions; ++r) { /* the first fill that gives them: for messages */
    if (s->regions[r].pressure && !out->has_p0) out->has_p0 = s->regions[r].line;
    if (s->regions[r].density && !out->has_rho0) out->has_rho0 = s->regions[r].line;
    if ((s->regions[r].k || s->regions[r].epsilon) && !out->has_k0)
      out->has_k0 = s->regions[r].line;
  }
  log_debug("geometry: %zu fluid, %zu %s wall particles, %zu segments, %zu inflow/outflow "
            "particles",
            b.nfluid, nwallp, model, b.nseg, b.np - b.nfluid - nwallp);
done:
  free(b.seg);
  free(b.p);
  index_free(&b.ix);
  free(b.area);
  return st;
}

void geometry_free(struct geom *g)
{
  free(g->x);
  free(g->v);
  free(g->p0);
  free(g->rho0);
  free(g->k0);
  free(g->eps0);
  free(g->normal);
  free(g->theta);
  free(g->dist);
  free(g->kind);
  free(g->group);
  free(g->seg_v);
  free(g->seg_normal);
  free(g->seg_len);
  free(g->seg_wall);
  memset(g, 0, sizeof *g);
}

/* CRC-32 of n bytes, continued from crc. */
static unsigned long digest_bytes(unsigned long crc, const void *p, size_t n)
{
  const unsigned char *b = p;
  while (n > 0) { /* zlib takes at most UINT_MAX bytes a call */
    const uInt k = n > 0x40000000u ? 0x40000000u : (uInt)n;
    crc = crc32(crc, b, k);
    b += k;
    n -= k;
  }
  return crc;
}

unsigned long geometry_digest(const struct scene *s, const struct geom *g)
{
  unsigned long c = crc32(0L, Z_NULL, 0);
  c = digest_bytes(c, &g->n, sizeof g->n);
  const size_t dim = g->dim == 3 ? 3 : 2;
  c = digest_bytes(c, g->x, dim * g->n * sizeof *g->x);
  c = digest_bytes(c, g->v, dim * g->n * sizeof *g->v);
  c = digest_bytes(c, g->kind, g->n * sizeof *g->kind);
  c = digest_bytes(c, g->group, g->n * sizeof *g->group);
  c = digest_bytes(c, &g->nseg, sizeof g->nseg);
  c = digest_bytes(c, g->seg_v, 2 * g->nseg * sizeof *g->seg_v);
  c = digest_bytes(c, g->seg_len, g->nseg * sizeof *g->seg_len);
  const double phys[] = {
      s->lo[0],       s->lo[1],      s->hi[0],         s->hi[1],         s->periodic[0],
      s->periodic[1], s->dr,         s->h_over_dr,     s->rho0,          s->nu,
      s->gravity[0],  s->gravity[1], s->body_force[0], s->body_force[1], s->flow.velocity,
      s->flow.on};
  c = digest_bytes(c, phys, sizeof phys);
  if (s->dim == 3) { /* z (2-D digests stay what they were) */
    const double z[] = {s->lo[2], s->hi[2], s->periodic[2], s->gravity[2], s->body_force[2], 3.0};
    c = digest_bytes(c, z, sizeof z);
    for (int w = 0; w < s->nwalls; ++w) {
      c = digest_bytes(c, s->walls[w].box3, 6 * sizeof(double));
      c = digest_bytes(c, s->walls[w].shape3, 7 * sizeof(double));
    }
  }
  c = digest_bytes(c, s->smoothing, strlen(s->smoothing));
  c = digest_bytes(c, s->scheme, strlen(s->scheme));
  for (int i = 0; i < s->noptions; ++i) {
    const struct scene_option *o = &s->options[i];
    c = digest_bytes(c, o->key, strlen(o->key));
    c = o->is_number ? digest_bytes(c, &o->number, sizeof o->number)
                     : digest_bytes(c, o->text, strlen(o->text));
  }
  for (int w = 0; w < s->nwalls; ++w) {
    const struct scene_wall *wl = &s->walls[w];
    const double m[] = {wl->motion,    wl->velocity[0], wl->velocity[1],
                        wl->centre[0], wl->centre[1],   wl->omega};
    c = digest_bytes(c, m, sizeof m);
  }
  for (int k = 0; k < s->nsections; ++k) {
    const struct scene_section *sc = &s->sections[k];
    const double q[] = {sc->kind, sc->profile, sc->velocity, sc->layers,
                        sc->a[0], sc->a[1],    sc->b[0],     sc->b[1]};
    c = digest_bytes(c, q, sizeof q);
  }
  return c;
}
