/* geometry3.c: the particles of a 3-D scene (geometry_build with scene.dim = 3). What 3-D scenes
 * hold: fills of boxes (fill { x0, y0, z0, x1, y1, z1 }), spheres and finite cylinders (fill {
 * sphere = ... }, fill { cylinder = ... }) in closed containers of the same three solids
 * (box_wall, sphere_wall, cylinder_wall, the fluid inside), around obstacles of the same solids
 * (fluid = "outside"), with the 2-D conventions carried over:
 *  - fluid on the lattice lo + (k + 1/2) dr of the domain, a point belonging to the first fill
 *    that holds it (x0 <= x < x1 on each axis), and inside some container when there is one, none
 *    within dr/2 of a box obstacle (nor inside a curved one: below);
 *  - an obstacle's dummies: its lattice points within `layers` spacings of its faces, each with
 *    the outward normal of its nearest face and its depth below it (the faces that lie on its
 *    container's, a gate's across the tank or a block's on the floor, face no fluid and count
 *    not);
 *  - dummies on the same lattice outside every container, within `layers` spacings of one of them
 *    in the max norm (the 2-D walls' mitred corners: a full block of layers at edges and
 *    corners), each with its distance to the nearest point q of its container's faces and the
 *    unit normal (q − x)/|q − x| into the fluid (across an edge or corner, diagonal; the
 *    virtual marker x + 2 d n then mirrors it through q, as in 2-D).
 * Spheres and cylinders: every lattice point outside the solid is fluid (a sphere or cylinder
 * obstacle carves no dr/2 around itself): the lattice meets a curved face at every distance, and a
 * shell of dr/2 left empty around it is half a layer of fluid missing from the supports next to
 * it, which drew the water into the solid: a sphere 5 dr across in a tank at rest
 * (cases/hydrostatic3d.lua sphere = 1, isph-stabilized) took the water next to it towards its
 * centre at 0.5 m/s within 0.04 s (particles 0.6 dr past its surface by 1 s); with the shell left
 * dr/4 thick at 0.16 m/s; without it at 3e-4 m/s, and the tank's pressure is as accurate as the box
 * tank's. A box's faces lie between the lattice's planes, where the shell holds no point, and a
 * container holds the fluid strictly inside it in every shape (no shell either).
 * Their dummies: a container's lie within `layers` spacings of it in the Euclidean
 * distance (a rounded rim: the points the max norm adds beyond a cylinder's rim are farther than
 * any fluid particle's support reaches), each with its distance to the nearest surface point q and
 * the normal (q − x)/|q − x|; an obstacle's are its points within `layers` spacings below its
 * surface, with the outward normal there (radial on a sphere and a cylinder's side, along the
 * axis on a cap) and their depth. A cylinder obstacle's cap that lies on a container's face (a
 * pillar from the floor) or, without a container, on the domain's boundary faces no fluid, as a
 * box obstacle's face on its container's.
 * STL surfaces (stl_wall, mesh.c): fluid on the lattice points inside a container's or outside
 * an obstacle's surface (no shell), dummies within `layers` spacings of the surface in the
 * Euclidean distance, each with its distance to the nearest surface point q and the normal
 * (q − x)/|q − x| into the fluid (on the surface: the facet's); an obstacle's facets whose centre
 * lies on a container's face (a block's bottom on the floor) face no fluid and count not.
 * A box container's sliding face (box_wall { ..., lid_velocity, lid_face }): the dummies whose
 * nearest wall point lies on it and that lie within its span (across the side walls' planes, or
 * along a periodic axis) move at the lid's velocity; those beyond its edges, the side walls', stay
 * at rest (the 2-D box_wall's corners, geometry.c).
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
  struct mesh_index *mi; /* nwalls: the search grids of the STL walls' surfaces */
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

/* A cylinder's coordinates of x: along the axis from its first end (t, of length len), the
 * distance from the axis (r) and the unit vectors of the axis (a) and from the axis to x (u; any
 * unit vector across the axis when r = 0). */
struct cyl3 {
  double t, len, r, a[3], u[3];
};

static void cyl_coords(const double *sh, const double x[3], struct cyl3 *c)
{
  double d[3], len2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    d[k] = sh[3 + k] - sh[k];
    len2 += d[k] * d[k];
  }
  c->len = sqrt(len2);
  c->t = 0.0;
  for (int k = 0; k < 3; ++k) {
    c->a[k] = d[k] / c->len;
    c->t += (x[k] - sh[k]) * c->a[k];
  }
  double r2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    c->u[k] = x[k] - sh[k] - c->t * c->a[k];
    r2 += c->u[k] * c->u[k];
  }
  c->r = sqrt(r2);
  if (c->r > 0.0) {
    for (int k = 0; k < 3; ++k) c->u[k] /= c->r;
  } else { /* on the axis: a unit vector across it */
    const int m = fabs(c->a[0]) < 0.9 ? 0 : 1;
    double e[3] = {0.0, 0.0, 0.0}, n = 0.0;
    e[m] = 1.0;
    for (int k = 0; k < 3; ++k) {
      c->u[k] = e[k] - c->a[m] * c->a[k];
      n += c->u[k] * c->u[k];
    }
    for (int k = 0; k < 3; ++k) c->u[k] /= sqrt(n);
  }
}

static double dist3(const double x[3], const double y[3])
{
  return sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
              (x[2] - y[2]) * (x[2] - y[2]));
}

/* Is x in the solid (kind, box, sh) grown by `grow` (a box on each face, a sphere's and a
 * cylinder's radius and each cap)? strict: inside only (the fluid side of a container; an
 * obstacle's grown solid); else the boxes' half-open [x0, x1) of fills and the surface included
 * for spheres and cylinders. */
static int shape_in(enum scene_shape3 kind, const double *box, const double *sh, const double x[3],
                    double grow, int strict)
{
  if (kind == SCENE_SPHERE) {
    const double d = dist3(x, sh), r = sh[3] + grow;
    return strict ? d < r : d <= r;
  }
  if (kind == SCENE_CYLINDER) {
    struct cyl3 c;
    cyl_coords(sh, x, &c);
    const double r = sh[6] + grow;
    if (strict) return c.t > -grow && c.t < c.len + grow && c.r < r;
    return c.t >= -grow && c.t < c.len + grow && c.r < r;
  }
  const double g[6] = {box[0] - grow, box[1] - grow, box[2] - grow,
                       box[3] + grow, box[4] + grow, box[5] + grow};
  return strict ? inside_box(g, x) : in_box(g, x);
}

/* For x outside a container (kind, box, sh): the nearest point q of its surface, the Euclidean
 * distance in *d; returns the distance that decides the layers (the max norm of a box, whose
 * layers are mitred at its edges and corners; the Euclidean one of a sphere or cylinder). */
static double shape_nearest(enum scene_shape3 kind, const double *box, const double *sh,
                            const double x[3], double q[3], double *d)
{
  if (kind == SCENE_SPHERE) {
    const double r = dist3(x, sh);
    for (int k = 0; k < 3; ++k) q[k] = r > 0.0 ? sh[k] + sh[3] * (x[k] - sh[k]) / r : sh[k];
    *d = dist3(x, q);
    return *d;
  }
  if (kind == SCENE_CYLINDER) {
    struct cyl3 c;
    cyl_coords(sh, x, &c);
    const double t = fmin(fmax(c.t, 0.0), c.len), r = fmin(c.r, sh[6]);
    for (int k = 0; k < 3; ++k) q[k] = sh[k] + t * c.a[k] + r * c.u[k];
    *d = dist3(x, q);
    return *d;
  }
  return box_nearest(box, x, q, d);
}

/* The inward normal (into the fluid) of a container at a point x on its surface (within tol):
 * the sum of the normals of the faces it lies on, normalised; 0 when it lies on none. */
static void shape_surface_normal(const struct scene_wall *w, const double x[3], double tol,
                                 double nrm[3])
{
  const double *bx = w->box3, *sh = w->shape3;
  if (w->shape == SCENE_SPHERE) {
    const double r = dist3(x, sh);
    for (int a = 0; a < 3; ++a) nrm[a] = r > 0.0 ? (sh[a] - x[a]) / r : 0.0;
    return;
  }
  if (w->shape == SCENE_CYLINDER) {
    struct cyl3 c;
    cyl_coords(sh, x, &c);
    const double side = fabs(c.r - sh[6]) <= tol, cap0 = fabs(c.t) <= tol,
                 cap1 = fabs(c.t - c.len) <= tol;
    for (int a = 0; a < 3; ++a) nrm[a] = -side * c.u[a] + (cap0 - cap1) * c.a[a];
  } else {
    for (int a = 0; a < 3; ++a)
      nrm[a] = (fabs(x[a] - bx[a]) <= tol) - (fabs(x[a] - bx[3 + a]) <= tol);
  }
  const double nn = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
  for (int a = 0; a < 3; ++a) nrm[a] = nn > 0.0 ? nrm[a] / nn : 0.0;
}

/* shape_in of wall w (an STL surface: inside it, whatever grow and strict) */
static int wall_in(const struct build3 *b, int w, const double x[3], double grow, int strict)
{
  const struct scene_wall *wl = &b->s->walls[w];
  if (wl->shape == SCENE_MESH) return mesh_inside(wl->mesh, &b->mi[w], x);
  return shape_in(wl->shape, wl->box3, wl->shape3, x, grow, strict);
}

/* shape_nearest of container w (an STL surface: the Euclidean distance within the grid's reach,
 * HUGE_VAL beyond) */
static double wall_nearest(const struct build3 *b, int w, const double x[3], double q[3], double *d)
{
  const struct scene_wall *wl = &b->s->walls[w];
  if (wl->shape == SCENE_MESH) {
    *d = mesh_nearest(wl->mesh, &b->mi[w], x, q, NULL);
    return *d;
  }
  return shape_nearest(wl->shape, wl->box3, wl->shape3, x, q, d);
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
  const double clear = (0.5 - tol3) * s->dr; /* fluid keeps dr/2 from a box obstacle */
  for (long kz = k0[2]; kz <= k1[2]; ++kz)
    for (long ky = k0[1]; ky <= k1[1]; ++ky)
      for (long kx = k0[0]; kx <= k1[0]; ++kx) {
        double x[3];
        lattice_point(s, kx, ky, kz, x);
        int first = -1;
        for (int r = 0; r < s->nregions && first < 0; ++r) {
          const struct scene_region *g = &s->regions[r];
          if (shape_in(g->shape, g->box3, g->shape3, x, 0.0, g->shape != SCENE_BOX3)) first = r;
        }
        if (first < 0) continue;
        const struct scene_region *g = &s->regions[first];
        int held = ncont == 0, carved = 0;
        for (int w = 0; w < s->nwalls; ++w) {
          const struct scene_wall *wl = &s->walls[w];
          if (wl->box3d == 1) held |= wall_in(b, w, x, 0.0, 1);
          if (wl->box3d == 2) carved |= wall_in(b, w, x, wl->shape == SCENE_BOX3 ? clear : 0.0, 1);
        }
        if (carved) continue;
        CLSPH_CHECK(held, CLSPH_E_INPUT,
                    "%s:%d: fluid region '%s' extends past the walls: the particle at (%g, %g, "
                    "%g) is inside no container (box_wall, sphere_wall or cylinder_wall)",
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

/* Does an obstacle's face or cap at point c face fluid? Not when it lies on the face of the
 * container that holds the obstacle's centre `mid` (a gate across the tank, a block or a pillar on
 * the floor), nor, without any container, on the domain's boundary. */
static int faces_fluid(const struct build3 *b, const double mid[3], const double c[3])
{
  const struct scene *s = b->s;
  const double tol = tol3 * s->dr;
  int any = 0;
  for (int k = 0; k < s->nwalls; ++k) {
    const struct scene_wall *wl = &s->walls[k];
    if (wl->box3d != 1) continue;
    any = 1;
    if (wall_in(b, k, mid, 0.0, 1)) {
      if (wl->shape != SCENE_MESH) return shape_in(wl->shape, wl->box3, wl->shape3, c, -tol, 1);
      double q[3], d;
      return wall_in(b, k, c, 0.0, 1) && wall_nearest(b, k, c, q, &d) > tol;
    }
  }
  if (any) return 1;
  for (int a = 0; a < 3; ++a)
    if (fabs(c[a] - s->lo[a]) <= tol || fabs(c[a] - s->hi[a]) <= tol) return 0;
  return 1;
}

/* A lattice point x inside an obstacle within `thick` of its surface becomes a dummy of it: in a
 * box, its normal the outward normal of the nearest face (the first axis of the nearest, on a
 * tie), its distance the depth below that face; in a sphere or cylinder, the depth below the
 * nearest of its side and its caps and the outward normal there. */
static enum clsph_status obstacle_dummy(struct build3 *b, const double x[3], double thick)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = b->s;
  for (int w = 0; w < s->nwalls; ++w) {
    const struct scene_wall *wl = &s->walls[w];
    const double *bx = wl->box3, *sh = wl->shape3;
    if (wl->box3d != 2 || !wall_in(b, w, x, 0.0, 0)) continue;
    double depth = HUGE_VAL, nrm[3] = {0.0, 0.0, 0.0};
    if (wl->shape == SCENE_MESH) { /* the nearest surface point q: n = (q − x)/|q − x| */
      double q[3];
      size_t t = 0;
      depth = mesh_nearest(wl->mesh, &b->mi[w], x, q, &t);
      for (int a = 0; a < 3; ++a)
        nrm[a] = depth > tol3 * s->dr ? (q[a] - x[a]) / depth : wl->mesh->nrm[3 * t + a];
    } else if (wl->shape == SCENE_SPHERE) {
      const double r = dist3(x, sh);
      depth = sh[3] - r;
      for (int a = 0; a < 3; ++a) nrm[a] = r > 0.0 ? (x[a] - sh[a]) / r : a == 2;
    } else if (wl->shape == SCENE_CYLINDER) {
      struct cyl3 c;
      cyl_coords(sh, x, &c);
      const double mid[3] = {0.5 * (sh[0] + sh[3]), 0.5 * (sh[1] + sh[4]), 0.5 * (sh[2] + sh[5])};
      depth = sh[6] - c.r;
      memcpy(nrm, c.u, sizeof nrm);
      for (int e = 0; e < 2; ++e) {
        const double dc = e ? c.len - c.t : c.t;
        if (dc < depth && faces_fluid(b, mid, sh + 3 * e)) {
          depth = dc;
          for (int a = 0; a < 3; ++a) nrm[a] = (e ? 1.0 : -1.0) * c.a[a];
        }
      }
    } else {
      /* its container: the first that holds its centre; a face on or beyond the container's
       * (a gate across the tank's width, a block on the floor) faces no fluid */
      const double c[3] = {0.5 * (bx[0] + bx[3]), 0.5 * (bx[1] + bx[4]), 0.5 * (bx[2] + bx[5])};
      const double *cb = NULL, tol = tol3 * s->dr;
      for (int k = 0; k < s->nwalls && cb == NULL; ++k)
        if (s->walls[k].box3d == 1 && s->walls[k].shape == SCENE_BOX3 &&
            inside_box(s->walls[k].box3, c))
          cb = s->walls[k].box3;
      int axis = -1;
      double sign = 0.0;
      for (int a = 0; a < 3; ++a) {
        const double lo = x[a] - bx[a], hi = bx[3 + a] - x[a];
        if (lo < depth && (cb == NULL || bx[a] > cb[a] + tol)) depth = lo, axis = a, sign = -1.0;
        if (hi < depth && (cb == NULL || bx[3 + a] < cb[3 + a] - tol))
          depth = hi, axis = a, sign = 1.0;
      }
      if (axis < 0) return st;
      nrm[axis] = sign;
    }
    if (!(depth <= thick)) return st;
    const double zero[3] = {0.0, 0.0, 0.0};
    return push3(b, x, zero, nrm, fmax(depth, 0.0), KIND_DUMMY, w, (double)NAN, (double)NAN);
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
          const struct scene_wall *wl = &s->walls[w];
          if (wl->box3d != 1) continue;
          if (wall_in(b, w, x, 0.0, 1)) {
            inside = 1; /* the fluid side of a container */
            break;
          }
          double qw[3], d;
          const double layer = wall_nearest(b, w, x, qw, &d);
          if (layer <= thick && d < best) {
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
          if (s->walls[wall].shape == SCENE_MESH) { /* into the fluid: against the facet's */
            double qs[3];
            size_t t = 0;
            mesh_nearest(s->walls[wall].mesh, &b->mi[wall], x, qs, &t);
            for (int a = 0; a < 3; ++a) nrm[a] = -s->walls[wall].mesh->nrm[3 * t + a];
          } else {
            shape_surface_normal(&s->walls[wall], x, tol3 * s->dr, nrm);
          }
          if (nrm[0] == 0.0 && nrm[1] == 0.0 && nrm[2] == 0.0) continue;
        }
        double v[3] = {0.0, 0.0, 0.0};
        const struct scene_wall *wl = &s->walls[wall];
        if (wl->lid3 > 0) { /* on the sliding face, within its span: the lid's velocity */
          const int a = (wl->lid3 - 1) / 2, hi = (wl->lid3 - 1) % 2;
          int on = fabs(q[a] - wl->box3[3 * hi + a]) <= tol3 * s->dr;
          for (int e = 0; e < 3; ++e)
            if (e != a && !s->periodic[e]) on = on && x[e] > wl->box3[e] && x[e] < wl->box3[3 + e];
          if (on) memcpy(v, wl->velocity, sizeof v);
        }
        CLSPH_TRY(push3(b, x, v, nrm, best, KIND_DUMMY, wall, (double)NAN, (double)NAN));
      }
done:
  return st;
}

enum clsph_status geometry3_solid_at(const struct scene *s, const double x[3], int *wall)
{
  enum clsph_status st = CLSPH_OK;
  struct build3 b;
  memset(&b, 0, sizeof b);
  b.s = s;
  *wall = -1;
  b.mi = calloc((size_t)s->nwalls + 1, sizeof *b.mi);
  CLSPH_CHECK(b.mi != NULL, CLSPH_E_NOMEM, "geometry: out of memory");
  for (int w = 0; w < s->nwalls && *wall < 0; ++w) {
    const struct scene_wall *wl = &s->walls[w];
    if (wl->box3d != 2) continue;
    if (wl->shape == SCENE_MESH) CLSPH_TRY(mesh_index_build(wl->mesh, s->dr, &b.mi[w]));
    if (wall_in(&b, w, x, 0.0, 0)) *wall = w;
  }
done:
  for (int w = 0; b.mi != NULL && w < s->nwalls; ++w) mesh_index_free(&b.mi[w]);
  free(b.mi);
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
      CLSPH_CHECK(
          s->periodic[a] || (wl->box3[a] >= s->lo[a] - tol3 * s->dr &&
                             wl->box3[3 + a] <= s->hi[a] + tol3 * s->dr),
          CLSPH_E_INPUT,
          "%s:%d: %s (group '%s') reaches past the domain along %c: [%g, %g] "
          "against [%g, %g]",
          s->case_path, wl->line,
          (const char *[]){"box_wall", "sphere_wall", "cylinder_wall", "stl_wall"}[wl->shape],
          wl->group, "xyz"[a], wl -> box3[a], wl -> box3[3 + a], s -> lo[a], s -> hi[a]);
  }
  b.mi = calloc((size_t)s->nwalls + 1, sizeof *b.mi);
  CLSPH_CHECK(b.mi != NULL, CLSPH_E_NOMEM, "geometry: out of memory");
  for (int w = 0; w < s->nwalls; ++w) /* the dummies lie within `layers` spacings */
    if (s->walls[w].shape == SCENE_MESH)
      CLSPH_TRY(mesh_index_build(s->walls[w].mesh, (layers + 1) * s->dr, &b.mi[w]));
  for (int w = 0; w < s->nwalls; ++w) { /* an obstacle's facets on a container face no fluid */
    const struct scene_wall *wl = &s->walls[w];
    if (wl->shape != SCENE_MESH || wl->box3d != 2) continue;
    const double *bx = wl->mesh->box;
    const double mid[3] = {0.5 * (bx[0] + bx[3]), 0.5 * (bx[1] + bx[4]), 0.5 * (bx[2] + bx[5])};
    size_t hidden = 0;
    for (size_t t = 0; t < wl->mesh->ntri; ++t) {
      const double *v = wl->mesh->tri + 9 * t;
      const double c[3] = {(v[0] + v[3] + v[6]) / 3.0, (v[1] + v[4] + v[7]) / 3.0,
                           (v[2] + v[5] + v[8]) / 3.0};
      b.mi[w].hidden[t] = (unsigned char)!faces_fluid(&b, mid, c);
      hidden += b.mi[w].hidden[t];
    }
    CLSPH_CHECK(hidden < wl->mesh->ntri, CLSPH_E_INPUT,
                "%s:%d: stl_wall (group '%s'): none of its facets faces the fluid: every one lies "
                "on a container's face",
                s->case_path, wl->line, wl->group);
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
  struct mesh_index *mi = b.mi;
  memset(&b, 0, sizeof b); /* the geometry owns them now */
  b.mi = mi;
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
  for (int w = 0; b.mi != NULL && w < s->nwalls; ++w) mesh_index_free(&b.mi[w]);
  free(b.mi);
  return st;
}
