/* geometry3.c: the particles of a 3-D scene (geometry_build with scene.dim = 3). What 3-D scenes
 * hold so far: box fills (fill { x0, y0, z0, x1, y1, z1 }) in closed box containers (box_wall in
 * 3-D, the fluid inside), with the 2-D conventions carried over:
 *  - fluid on the lattice lo + (k + 1/2) dr of the domain, a point belonging to the first fill
 *    that holds it (x0 <= x < x1 on each axis), and inside some container when there is one, none
 *    within dr/2 of an obstacle;
 *  - an obstacle's dummies: its lattice points within `layers` spacings of its faces, each with
 *    the outward normal of its nearest face and its depth below it (the faces that lie on its
 *    container's, a gate's across the tank or a block's on the floor, face no fluid and count
 *    not);
 *  - dummies on the same lattice outside every container, within `layers` spacings of one of them
 *    in the max norm (the 2-D walls' mitred corners: a full block of layers at edges and
 *    corners), each with its distance to the nearest point q of its container's faces and the
 *    unit normal (q − x)/|q − x| into the fluid (across an edge or corner, diagonal; the
 *    virtual marker x + 2 d n then mirrors it through q, as in 2-D).
 * Positions, velocities and normals are n x 3. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geometry.h"
#include "log.h"

static const double max_lattice3 = 1e9; /* lattice points one scan may visit */
static const double tol3 = 1e-9;        /* in dr: slack on layer thicknesses and box faces */

struct build3 {
  const struct scene *s;
  size_t n, cap;
  double *x, *v, *normal, *dist, *p0, *rho0;
  int *kind, *group;
};

static enum clsph_status push3(struct build3 *b, const double x[3], const double v[3],
                               const double nrm[3], double dist, int kind, int group, double p0,
                               double rho0)
{
  enum clsph_status st = CLSPH_OK;
  if (b->n == b->cap) {
    const size_t cap = b->cap ? 2 * b->cap : 4096;
    double *x2 = realloc(b->x, 3 * cap * sizeof *x2);
    if (x2 != NULL) b->x = x2;
    double *v2 = realloc(b->v, 3 * cap * sizeof *v2);
    if (v2 != NULL) b->v = v2;
    double *n2 = realloc(b->normal, 3 * cap * sizeof *n2);
    if (n2 != NULL) b->normal = n2;
    double *d2 = realloc(b->dist, cap * sizeof *d2);
    if (d2 != NULL) b->dist = d2;
    double *q2 = realloc(b->p0, cap * sizeof *q2);
    if (q2 != NULL) b->p0 = q2;
    double *r2 = realloc(b->rho0, cap * sizeof *r2);
    if (r2 != NULL) b->rho0 = r2;
    int *k2 = realloc(b->kind, cap * sizeof *k2);
    if (k2 != NULL) b->kind = k2;
    int *g2 = realloc(b->group, cap * sizeof *g2);
    if (g2 != NULL) b->group = g2;
    CLSPH_CHECK(x2 != NULL && v2 != NULL && n2 != NULL && d2 != NULL && q2 != NULL && r2 != NULL &&
                    k2 != NULL && g2 != NULL,
                CLSPH_E_NOMEM, "geometry: out of memory for %zu particles", cap);
    b->cap = cap;
  }
  for (int a = 0; a < 3; ++a) {
    b->x[3 * b->n + (size_t)a] = x[a];
    b->v[3 * b->n + (size_t)a] = v[a];
    b->normal[3 * b->n + (size_t)a] = nrm[a];
  }
  b->dist[b->n] = dist;
  b->kind[b->n] = kind;
  b->group[b->n] = group;
  b->p0[b->n] = p0;
  b->rho0[b->n] = rho0;
  ++b->n;
done:
  return st;
}

/* Lattice indices k0..k1 (per axis) whose points cover [bb[a], bb[3 + a]], clipped to the period
 * on a periodic axis. */
static enum clsph_status lattice3(const struct scene *s, const double bb[6], long k0[3], long k1[3])
{
  enum clsph_status st = CLSPH_OK;
  double count = 1.0;
  for (int a = 0; a < 3; ++a) {
    const double f0 = (bb[a] - s->lo[a]) / s->dr - 0.5, f1 = (bb[3 + a] - s->lo[a]) / s->dr - 0.5;
    CLSPH_CHECK(fabs(f0) < max_lattice3 && fabs(f1) < max_lattice3, CLSPH_E_INPUT,
                "%s: dr = %g is too small for the extent [%g, %g] of axis %c", s->case_path, s->dr,
                bb[a], bb[3 + a], "xyz"[a]);
    k0[a] = (long)floor(f0);
    k1[a] = (long)ceil(f1);
    if (s->periodic[a]) {
      const long nper = (long)ceil((s->hi[a] - s->lo[a]) / s->dr - 0.5);
      if (k0[a] < 0) k0[a] = 0;
      if (k1[a] > nper - 1) k1[a] = nper - 1;
    }
    count *= k1[a] >= k0[a] ? (double)(k1[a] - k0[a] + 1) : 0.0;
  }
  CLSPH_CHECK(count <= max_lattice3, CLSPH_E_INPUT,
              "%s: dr = %g gives %.3g lattice points over [%g, %g] x [%g, %g] x [%g, %g] (at most "
              "%.0g)",
              s->case_path, s->dr, count, bb[0], bb[3], bb[1], bb[4], bb[2], bb[5], max_lattice3);
done:
  return st;
}

/* The lattice point lo + (k + 1/2) dr. */
static void lattice_point(const struct scene *s, long kx, long ky, long kz, double x[3])
{
  const long k[3] = {kx, ky, kz};
  for (int a = 0; a < 3; ++a) x[a] = s->lo[a] + ((double)k[a] + 0.5) * s->dr;
}

static int in_box(const double *box, const double x[3])
{
  return x[0] >= box[0] && x[0] < box[3] && x[1] >= box[1] && x[1] < box[4] && x[2] >= box[2] &&
         x[2] < box[5];
}

/* Strictly inside the box (the container's fluid side). */
static int inside_box(const double *box, const double x[3])
{
  return x[0] > box[0] && x[0] < box[3] && x[1] > box[1] && x[1] < box[4] && x[2] > box[2] &&
         x[2] < box[5];
}

/* The nearest point q of the box's faces to a point x outside it; returns the max-norm distance
 * (how many layers out it lies) and the Euclidean one in *d. */
static double box_nearest(const double *box, const double x[3], double q[3], double *d)
{
  double cheb = 0.0, d2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    q[a] = fmin(fmax(x[a], box[a]), box[3 + a]);
    const double e = fabs(x[a] - q[a]);
    cheb = fmax(cheb, e);
    d2 += e * e;
  }
  *d = sqrt(d2);
  return cheb;
}

static enum clsph_status fluid3(struct build3 *b)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = b->s;
  size_t *count = calloc((size_t)s->nregions + 1, sizeof *count);
  CLSPH_CHECK(count != NULL, CLSPH_E_NOMEM, "geometry: out of memory");
  double bb[6] = {HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (int r = 0; r < s->nregions; ++r)
    for (int a = 0; a < 3; ++a) {
      bb[a] = fmin(bb[a], s->regions[r].box3[a]);
      bb[3 + a] = fmax(bb[3 + a], s->regions[r].box3[3 + a]);
    }
  long k0[3], k1[3];
  CLSPH_TRY(lattice3(s, bb, k0, k1));
  int ncont = 0;
  for (int w = 0; w < s->nwalls; ++w) ncont += s->walls[w].box3d == 1;
  const double clear = (0.5 - tol3) * s->dr; /* fluid keeps dr/2 from an obstacle */
  for (long kz = k0[2]; kz <= k1[2]; ++kz)
    for (long ky = k0[1]; ky <= k1[1]; ++ky)
      for (long kx = k0[0]; kx <= k1[0]; ++kx) {
        double x[3];
        lattice_point(s, kx, ky, kz, x);
        int first = -1;
        for (int r = 0; r < s->nregions && first < 0; ++r)
          if (in_box(s->regions[r].box3, x)) first = r;
        if (first < 0) continue;
        const struct scene_region *g = &s->regions[first];
        int held = ncont == 0, carved = 0;
        for (int w = 0; w < s->nwalls; ++w) {
          const double *bx = s->walls[w].box3;
          if (s->walls[w].box3d == 1) held |= inside_box(bx, x);
          if (s->walls[w].box3d == 2) {
            const double grown[6] = {bx[0] - clear, bx[1] - clear, bx[2] - clear,
                                     bx[3] + clear, bx[4] + clear, bx[5] + clear};
            carved |= inside_box(grown, x);
          }
        }
        if (carved) continue;
        CLSPH_CHECK(held, CLSPH_E_INPUT,
                    "%s:%d: fluid region '%s' extends past the walls: the particle at (%g, %g, "
                    "%g) is inside no box_wall",
                    s->case_path, g->line, g->name, x[0], x[1], x[2]);
        const double zero[3] = {0.0, 0.0, 0.0};
        double u[3] = {0.0, 0.0, 0.0}, val[2] = {NAN, NAN};
        if (g->velocity == 1) memcpy(u, g->u0, sizeof u);
        if (g->velocity == 2)
          CLSPH_CHECK(s->velocity_fn.eval != NULL &&
                          s->velocity_fn.eval(s->velocity_fn.ctx, first, x, u) == CLSPH_OK,
                      CLSPH_E_INPUT,
                      "%s:%d: fluid region '%s': its velocity at (%g, %g, %g) failed", s->case_path,
                      g->line, g->name, x[0], x[1], x[2]);
        const int mode[2] = {g->pressure, g->density};
        const double given[2] = {g->p0, g->rho0};
        for (int k = 0; k < 2; ++k) { /* the initial pressure and density */
          if (mode[k] == 1) val[k] = given[k];
          if (mode[k] == 2)
            CLSPH_CHECK(
                s->velocity_fn.scalar != NULL &&
                    s->velocity_fn.scalar(s->velocity_fn.ctx, first, k, x, &val[k]) == CLSPH_OK,
                CLSPH_E_INPUT, "%s:%d: fluid region '%s': its %s at (%g, %g, %g) failed",
                s->case_path, g->line, g->name, k ? "density" : "pressure", x[0], x[1], x[2]);
          CLSPH_CHECK(mode[k] == 0 || (isfinite(val[k]) && (k == 0 || val[k] > 0.0)), CLSPH_E_INPUT,
                      "%s:%d: fluid region '%s': its initial %s at (%g, %g, %g) is %g: it must be "
                      "%s",
                      s->case_path, g->line, g->name, k ? "density" : "pressure", x[0], x[1], x[2],
                      val[k], k ? "positive" : "finite");
        }
        CLSPH_CHECK(isfinite(u[0]) && isfinite(u[1]) && isfinite(u[2]), CLSPH_E_INPUT,
                    "%s:%d: fluid region '%s': its initial velocity at (%g, %g, %g) is not finite",
                    s->case_path, g->line, g->name, x[0], x[1], x[2]);
        CLSPH_TRY(push3(b, x, u, zero, 0.0, KIND_FLUID, -1, val[0], val[1]));
        ++count[first];
      }
  for (int r = 0; r < s->nregions; ++r)
    CLSPH_CHECK(count[r] > 0, CLSPH_E_INPUT,
                "%s:%d: fluid region '%s' contains no particle at dr = %g", s->case_path,
                s->regions[r].line, s->regions[r].name, s->dr);
done:
  free(count);
  return st;
}

/* A lattice point x inside an obstacle box within `thick` of its surface becomes a dummy of it,
 * its normal the outward normal of the nearest face (the first axis of the nearest, on a tie), its
 * distance the depth below that face. */
static enum clsph_status obstacle_dummy(struct build3 *b, const double x[3], double thick)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = b->s;
  for (int w = 0; w < s->nwalls; ++w) {
    const double *bx = s->walls[w].box3;
    if (s->walls[w].box3d != 2 || !in_box(bx, x)) continue;
    /* its container: the first that holds its centre; a face on or beyond the container's
     * (a gate across the tank's width, a block on the floor) faces no fluid */
    const double c[3] = {0.5 * (bx[0] + bx[3]), 0.5 * (bx[1] + bx[4]), 0.5 * (bx[2] + bx[5])};
    const double *cb = NULL, tol = tol3 * s->dr;
    for (int k = 0; k < s->nwalls && cb == NULL; ++k)
      if (s->walls[k].box3d == 1 && inside_box(s->walls[k].box3, c)) cb = s->walls[k].box3;
    double depth = HUGE_VAL, nrm[3] = {0.0, 0.0, 0.0};
    int axis = -1;
    double sign = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double lo = x[a] - bx[a], hi = bx[3 + a] - x[a];
      if (lo < depth && (cb == NULL || bx[a] > cb[a] + tol)) depth = lo, axis = a, sign = -1.0;
      if (hi < depth && (cb == NULL || bx[3 + a] < cb[3 + a] - tol))
        depth = hi, axis = a, sign = 1.0;
    }
    if (axis < 0 || depth > thick) return st;
    nrm[axis] = sign;
    const double zero[3] = {0.0, 0.0, 0.0};
    return push3(b, x, zero, nrm, depth, KIND_DUMMY, w, (double)NAN, (double)NAN);
  }
  return st;
}

static enum clsph_status dummy3(struct build3 *b, int layers)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = b->s;
  const double thick = (layers + tol3) * s->dr;
  double bb[6] = {HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  int any = 0;
  for (int w = 0; w < s->nwalls; ++w) {
    if (!s->walls[w].box3d) continue;
    any = 1; /* (an obstacle's layers lie inside it: within these bounds too) */
    for (int a = 0; a < 3; ++a) {
      bb[a] = fmin(bb[a], s->walls[w].box3[a] - thick);
      bb[3 + a] = fmax(bb[3 + a], s->walls[w].box3[3 + a] + thick);
    }
  }
  if (!any) goto done;
  long k0[3], k1[3];
  CLSPH_TRY(lattice3(s, bb, k0, k1));
  for (long kz = k0[2]; kz <= k1[2]; ++kz)
    for (long ky = k0[1]; ky <= k1[1]; ++ky)
      for (long kx = k0[0]; kx <= k1[0]; ++kx) {
        double x[3];
        lattice_point(s, kx, ky, kz, x);
        int wall = -1, inside = 0;
        double best = HUGE_VAL, q[3] = {0, 0, 0};
        for (int w = 0; w < s->nwalls && !inside; ++w) {
          if (s->walls[w].box3d != 1) continue;
          if (inside_box(s->walls[w].box3, x)) {
            inside = 1; /* the fluid side of a container */
            break;
          }
          double qw[3], d;
          const double cheb = box_nearest(s->walls[w].box3, x, qw, &d);
          if (cheb <= thick && d < best) {
            best = d;
            wall = w;
            memcpy(q, qw, sizeof q);
          }
        }
        if (inside) { /* in a container's fluid space: an obstacle's dummy, or nothing */
          CLSPH_TRY(obstacle_dummy(b, x, thick));
          continue;
        }
        if (wall < 0) continue;
        double nrm[3] = {0.0, 0.0, 0.0};
        if (best > tol3 * s->dr) {
          for (int a = 0; a < 3; ++a) nrm[a] = (q[a] - x[a]) / best;
        } else { /* on a face, an edge or a corner: the faces' inward normals, summed */
          const double *bx = s->walls[wall].box3;
          double nn = 0.0;
          for (int a = 0; a < 3; ++a) {
            nrm[a] =
                (fabs(x[a] - bx[a]) <= tol3 * s->dr) - (fabs(x[a] - bx[3 + a]) <= tol3 * s->dr);
            nn += nrm[a] * nrm[a];
          }
          if (nn == 0.0) continue;
          for (int a = 0; a < 3; ++a) nrm[a] /= sqrt(nn);
        }
        const double zero[3] = {0.0, 0.0, 0.0};
        CLSPH_TRY(push3(b, x, zero, nrm, best, KIND_DUMMY, wall, (double)NAN, (double)NAN));
      }
done:
  return st;
}

enum clsph_status geometry_build3(const struct scene *s, const char *model, int layers,
                                  struct geom *out)
{
  enum clsph_status st = CLSPH_OK;
  struct build3 b;
  memset(&b, 0, sizeof b);
  memset(out, 0, sizeof *out);
  b.s = s;
  CLSPH_CHECK(strcmp(model, "dummy") == 0 || strcmp(model, "none") == 0, CLSPH_E_INPUT,
              "%s: 3-D scenes take dummy walls (or none), not \"%s\": the semi-analytical walls "
              "are 2-D",
              s->case_path, model);
  CLSPH_CHECK(strcmp(model, "dummy") != 0 || layers >= 1, CLSPH_E_INPUT,
              "%s: dummy walls need at least one layer", s->case_path);
  for (int w = 0; w < s->nwalls; ++w) { /* the domain holds the container and its layers */
    const struct scene_wall *wl = &s->walls[w];
    for (int a = 0; a < 3 && strcmp(model, "dummy") == 0; ++a)
      CLSPH_CHECK(s->periodic[a] || (wl->box3[a] >= s->lo[a] - tol3 * s->dr &&
                                     wl->box3[3 + a] <= s->hi[a] + tol3 * s->dr),
                  CLSPH_E_INPUT,
                  "%s:%d: box_wall (group '%s') reaches past the domain along %c: [%g, %g] "
                  "against [%g, %g]",
                  s->case_path, wl->line, wl->group, "xyz"[a], wl -> box3[a], wl -> box3[3 + a],
                  s -> lo[a], s -> hi[a]);
  }
  CLSPH_TRY(fluid3(&b));
  const size_t nfluid = b.n;
  if (strcmp(model, "dummy") == 0) CLSPH_TRY(dummy3(&b, layers));
  const size_t n = b.n;
  out->dim = 3;
  out->n = n;
  out->nfluid = nfluid;
  out->x = b.x;
  out->v = b.v;
  out->normal = b.normal;
  out->dist = b.dist;
  out->p0 = b.p0;
  out->rho0 = b.rho0;
  out->kind = b.kind;
  out->group = b.group;
  memset(&b, 0, sizeof b); /* the geometry owns them now */
  out->k0 = malloc((n + 1) * sizeof *out->k0);
  out->eps0 = malloc((n + 1) * sizeof *out->eps0);
  out->theta = calloc(n + 1, sizeof *out->theta);
  CLSPH_CHECK(out->k0 != NULL && out->eps0 != NULL && out->theta != NULL, CLSPH_E_NOMEM,
              "geometry: out of memory for %zu particles", n);
  for (size_t i = 0; i < n; ++i) out->k0[i] = out->eps0[i] = NAN;
  for (int r = 0; r < s->nregions; ++r) { /* the first fill that gives them: for messages */
    if (s->regions[r].pressure && !out->has_p0) out->has_p0 = s->regions[r].line;
    if (s->regions[r].density && !out->has_rho0) out->has_rho0 = s->regions[r].line;
  }
  log_debug("geometry: 3-D, %zu fluid, %zu %s wall particles", nfluid, n - nfluid, model);
done:
  if (st != CLSPH_OK) geometry_free(out);
  free(b.x);
  free(b.v);
  free(b.normal);
  free(b.dist);
  free(b.p0);
  free(b.rho0);
  free(b.kind);
  free(b.group);
  return st;
}
