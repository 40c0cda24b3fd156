/* surface3.c: the faces of a 3-D scene's walls as triangles, for the frames of 3-D runs
 * (scene_surfaces3). Each triangle's vertices run counter-clockwise seen from the fluid, so that
 * (b − a) × (c − a) points into the fluid: a frame draws the triangles whose fluid side faces the
 * camera (a container's far faces seen from inside, an obstacle's near faces) and leaves out the
 * others (a container's near faces, which would hide the water).
 *   - a box: its six faces (a container's faces across a periodic axis are not walls: left out;
 *     along a periodic axis the faces span the domain);
 *   - a sphere: SURFACE3_STACKS x SURFACE3_SLICES quadrilaterals between circles of latitude,
 *     the poles' rows triangles;
 *   - a cylinder: SURFACE3_SLICES quadrilaterals around its side and two fans for its caps;
 *   - an STL surface: its facets.
 * The curved solids' vertices lie on the surface: a chord sags by R (1 − cos(π/48)) = 0.002 R. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"

#define SURFACE3_SLICES 48
#define SURFACE3_STACKS 24

struct tri_out {
  double *t;
  size_t n, cap;
  int flip; /* the solid's outward side is the fluid's (an obstacle): 0; a container: 1 */
};

static enum clsph_status push_tri(struct tri_out *o, const double a[3], const double b[3],
                                  const double c[3])
{
  enum clsph_status st = CLSPH_OK;
  if (o->n == o->cap) {
    const size_t cap = o->cap > 0 ? 2 * o->cap : 64;
    double *t = realloc(o->t, cap * 9 * sizeof *t);
    CLSPH_CHECK(t != NULL, CLSPH_E_NOMEM, "out of memory for the walls' surfaces");
    o->t = t;
    o->cap = cap;
  }
  /* the solid's outward orientation is given; a container's fluid is inside: reversed */
  const double *v[3] = {a, o->flip ? c : b, o->flip ? b : c};
  for (int k = 0; k < 3; ++k)
    for (int e = 0; e < 3; ++e) o->t[9 * o->n + 3 * (size_t)k + (size_t)e] = v[k][e];
  ++o->n;
done:
  return st;
}

/* a quadrilateral a, b, c, d, counter-clockwise seen from outside the solid */
static enum clsph_status push_quad(struct tri_out *o, const double a[3], const double b[3],
                                   const double c[3], const double d[3])
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(push_tri(o, a, b, c));
  CLSPH_TRY(push_tri(o, a, c, d));
done:
  return st;
}

/* A box's faces, outward; a container's faces across a periodic axis left out, and along one
 * clipped to the domain. */
static enum clsph_status box_faces(const struct scene *s, const struct scene_wall *w,
                                   struct tri_out *o)
{
  enum clsph_status st = CLSPH_OK;
  double b[6];
  memcpy(b, w->box3, sizeof b);
  for (int a = 0; a < 3; ++a)
    if (w->box3d == 1 && s->periodic[a])
      b[a] = fmax(b[a], s->lo[a]), b[3 + a] = fmin(b[3 + a], s->hi[a]);
  for (int a = 0; a < 3; ++a) {
    if (w->box3d == 1 && s->periodic[a]) continue;
    const int u = (a + 1) % 3, v = (a + 2) % 3; /* (u, v, a) right-handed */
    for (int side = 0; side < 2; ++side) {
      double p[4][3];
      const double x = b[3 * side + a];
      const double cu[4] = {b[u], b[3 + u], b[3 + u], b[u]},
                   cv[4] = {b[v], b[v], b[3 + v], b[3 + v]};
      for (int k = 0; k < 4; ++k) {
        const int kk = side == 1 ? k : 3 - k; /* outward: +a on the far side, −a on the near */
        p[k][a] = x;
        p[k][u] = cu[kk];
        p[k][v] = cv[kk];
      }
      CLSPH_TRY(push_quad(o, p[0], p[1], p[2], p[3]));
    }
  }
done:
  return st;
}

static enum clsph_status sphere_faces(const double *sh, struct tri_out *o)
{
  enum clsph_status st = CLSPH_OK;
  const double pi = 3.141592653589793, R = sh[3];
  double ring[2][SURFACE3_SLICES + 1][3];
  for (int i = 0; i <= SURFACE3_STACKS; ++i) {
    const double th = pi * (double)i / SURFACE3_STACKS; /* from the +z pole */
    double(*cur)[3] = ring[i % 2];
    for (int j = 0; j <= SURFACE3_SLICES; ++j) {
      const double ph = 2.0 * pi * (double)(j % SURFACE3_SLICES) / SURFACE3_SLICES;
      cur[j][0] = sh[0] + R * sin(th) * cos(ph);
      cur[j][1] = sh[1] + R * sin(th) * sin(ph);
      cur[j][2] = sh[2] + R * cos(th);
    }
    if (i == 0) continue;
    double(*prev)[3] = ring[(i + 1) % 2];
    for (int j = 0; j < SURFACE3_SLICES; ++j) { /* outward: prev (north) j, cur j, cur j+1 */
      if (i == 1)
        CLSPH_TRY(push_tri(o, prev[j], cur[j], cur[j + 1]));
      else if (i == SURFACE3_STACKS)
        CLSPH_TRY(push_tri(o, prev[j], cur[j], prev[j + 1]));
      else
        CLSPH_TRY(push_quad(o, prev[j], cur[j], cur[j + 1], prev[j + 1]));
    }
  }
done:
  return st;
}

static enum clsph_status cylinder_faces(const double *sh, struct tri_out *o)
{
  enum clsph_status st = CLSPH_OK;
  const double pi = 3.141592653589793, R = sh[6];
  double ax[3], len = 0.0;
  for (int k = 0; k < 3; ++k) ax[k] = sh[3 + k] - sh[k], len += ax[k] * ax[k];
  len = sqrt(len);
  for (int k = 0; k < 3; ++k) ax[k] /= len;
  /* e1, e2 across the axis, (e1, e2, ax) right-handed */
  const int m = fabs(ax[0]) < 0.9 ? 0 : 1;
  double e1[3] = {0.0, 0.0, 0.0}, e2[3], n1 = 0.0;
  e1[m] = 1.0;
  for (int k = 0; k < 3; ++k) e1[k] -= ax[m] * ax[k], n1 += e1[k] * e1[k];
  for (int k = 0; k < 3; ++k) e1[k] /= sqrt(n1);
  e2[0] = ax[1] * e1[2] - ax[2] * e1[1];
  e2[1] = ax[2] * e1[0] - ax[0] * e1[2];
  e2[2] = ax[0] * e1[1] - ax[1] * e1[0];
  const double *c0 = sh, *c1 = sh + 3;
  for (int j = 0; j < SURFACE3_SLICES; ++j) {
    double p[2][2][3]; /* [end][j, j + 1] */
    for (int jj = 0; jj < 2; ++jj) {
      const double ph = 2.0 * pi * (double)((j + jj) % SURFACE3_SLICES) / SURFACE3_SLICES;
      for (int k = 0; k < 3; ++k) {
        const double r = R * (cos(ph) * e1[k] + sin(ph) * e2[k]);
        p[0][jj][k] = c0[k] + r;
        p[1][jj][k] = c1[k] + r;
      }
    }
    CLSPH_TRY(push_quad(o, p[0][0], p[0][1], p[1][1], p[1][0])); /* side, outward */
    CLSPH_TRY(push_tri(o, c1, p[1][0], p[1][1]));                /* cap at the second end: +ax */
    CLSPH_TRY(push_tri(o, c0, p[0][1], p[0][0]));                /* the first: −ax */
  }
done:
  return st;
}

enum clsph_status scene_surfaces3(const struct scene *s, const char *moved_group,
                                  const double offset[3], double **tri, size_t *ntri)
{
  enum clsph_status st = CLSPH_OK;
  struct tri_out o = {NULL, 0, 0, 0};
  *tri = NULL;
  *ntri = 0;
  if (s->dim != 3) goto done;
  for (int w = 0; w < s->nwalls; ++w) {
    const struct scene_wall *wl = &s->walls[w];
    if (wl->box3d == 0) continue;
    const size_t first = o.n;
    o.flip = wl->box3d == 1;
    if (wl->shape == SCENE_SPHERE)
      CLSPH_TRY(sphere_faces(wl->shape3, &o));
    else if (wl->shape == SCENE_CYLINDER)
      CLSPH_TRY(cylinder_faces(wl->shape3, &o));
    else if (wl->shape == SCENE_MESH)
      for (size_t t = 0; t < wl->mesh->ntri; ++t)
        CLSPH_TRY(push_tri(&o, wl->mesh->tri + 9 * t, wl->mesh->tri + 9 * t + 3,
                           wl->mesh->tri + 9 * t + 6));
    else
      CLSPH_TRY(box_faces(s, wl, &o));
    if (moved_group != NULL && strcmp(wl->group, moved_group) == 0)
      for (size_t t = first; t < o.n; ++t)
        for (int k = 0; k < 9; ++k) o.t[9 * t + (size_t)k] += offset[k % 3];
  }
  *tri = o.t;
  *ntri = o.n;
  o.t = NULL;
done:
  free(o.t);
  return st;
}
