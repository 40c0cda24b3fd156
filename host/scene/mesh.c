/* mesh.c: STL surfaces for 3-D walls. ADMesh (Debian's libadmesh) reads the file (ASCII or
 * binary) and matches the facets' edges; the checks, the placement and the queries are ours, in
 * double:
 *  - closed: every facet has a neighbour across each of its three edges (ADMesh's exact match of
 *    the edges' end points), else the surface bounds no solid;
 *  - oriented: ADMesh turns facets to agree with their neighbours; any it turns is an error;
 *  - outward: the enclosed volume Σ v0·(v1 × v2)/6 is positive (facets counter-clockwise seen
 *    from outside, as STL specifies), else the normals point inward.
 * Facets of zero area are left out (they bound nothing). The normals the file writes are not
 * read: STL's vertex order is what defines them. */
#include "mesh.h"

#include <admesh/stl.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "log.h"

void mesh_free(struct mesh3 *m)
{
  free(m->tri);
  free(m->nrm);
  memset(m, 0, sizeof *m);
}

void mesh_index_free(struct mesh_index *ix)
{
  free(ix->row_first);
  free(ix->row_tri);
  free(ix->cell_first);
  free(ix->cell_tri);
  free(ix->hidden);
  memset(ix, 0, sizeof *ix);
}

static void cross3(const double a[3], const double b[3], double c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot3(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

enum clsph_status mesh_load(const char *path, const char *where, double scale,
                            const double offset[3], struct mesh3 *out)
{
  enum clsph_status st = CLSPH_OK;
  stl_file s;
  int opened = 0;
  memset(out, 0, sizeof *out);
  memset(&s, 0, sizeof s);
  FILE *f = fopen(path, "rb");
  CLSPH_CHECK(f != NULL, CLSPH_E_INPUT, "%s: cannot open %s: %s", where, path, strerror(errno));
  fclose(f);
  char *name = strdup(path);
  CLSPH_CHECK(name != NULL, CLSPH_E_NOMEM, "out of memory");
  stl_open(&s, name);
  free(name);
  opened = 1;
  CLSPH_CHECK(!stl_get_error(&s) && s.stats.number_of_facets > 0, CLSPH_E_INPUT,
              "%s: %s is not an STL file that holds facets (ASCII or binary STL)", where, path);
  stl_check_facets_exact(&s);
  CLSPH_CHECK(!stl_get_error(&s), CLSPH_E_INPUT, "%s: %s: its edges could not be matched", where,
              path);
  const int nf = s.stats.number_of_facets;
  /* closed: a neighbour across every edge */
  int open = 0, first = -1;
  for (int i = 0; i < nf; ++i)
    for (int e = 0; e < 3; ++e)
      if (s.neighbors_start[i].neighbor[e] < 0) {
        ++open;
        if (first < 0) first = i;
        break;
      }
  if (open > 0) {
    const stl_vertex *v = s.facet_start[first].vertex;
    CLSPH_CHECK(0, CLSPH_E_INPUT,
                "%s: %s is not closed: %d of its %d facets have an edge that no other facet "
                "shares (the first has a vertex at (%g, %g, %g), in the file's units): a wall "
                "must bound a solid",
                where, path, open, nf, (double)v[0].x, (double)v[0].y, (double)v[0].z);
  }
  stl_fix_normal_directions(&s);
  CLSPH_CHECK(s.stats.facets_reversed == 0, CLSPH_E_INPUT,
              "%s: %s: its facets are not consistently oriented: %d of %d run the other way round "
              "from their neighbours (the vertices of every facet must run counter-clockwise seen "
              "from outside)",
              where, path, s.stats.facets_reversed, nf);
  out->tri = malloc((size_t)nf * 9 * sizeof *out->tri);
  out->nrm = malloc((size_t)nf * 3 * sizeof *out->nrm);
  CLSPH_CHECK(out->tri != NULL && out->nrm != NULL, CLSPH_E_NOMEM, "%s: out of memory for %s",
              where, path);
  double vol = 0.0;
  for (int a = 0; a < 3; ++a) {
    out->box[a] = HUGE_VAL;
    out->box[3 + a] = -HUGE_VAL;
  }
  for (int i = 0; i < nf; ++i) {
    double p[3][3];
    for (int k = 0; k < 3; ++k) {
      const stl_vertex *v = &s.facet_start[i].vertex[k];
      const double raw[3] = {(double)v->x, (double)v->y, (double)v->z};
      for (int a = 0; a < 3; ++a) p[k][a] = scale * raw[a] + offset[a];
    }
    double e1[3], e2[3], n[3];
    for (int a = 0; a < 3; ++a) {
      e1[a] = p[1][a] - p[0][a];
      e2[a] = p[2][a] - p[0][a];
    }
    cross3(e1, e2, n);
    const double area2 = sqrt(dot3(n, n));
    if (!(area2 > 0.0)) {
      ++out->dropped;
      continue;
    }
    double c[3];
    cross3(p[1], p[2], c);
    vol += dot3(p[0], c) / 6.0;
    double *t = out->tri + 9 * out->ntri, *m = out->nrm + 3 * out->ntri;
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) {
        t[3 * k + a] = p[k][a];
        out->box[a] = fmin(out->box[a], p[k][a]);
        out->box[3 + a] = fmax(out->box[3 + a], p[k][a]);
      }
    for (int a = 0; a < 3; ++a) m[a] = n[a] / area2;
    ++out->ntri;
  }
  CLSPH_CHECK(out->ntri > 0, CLSPH_E_INPUT, "%s: %s: every facet has zero area", where, path);
  CLSPH_CHECK(vol > 0.0, CLSPH_E_INPUT,
              "%s: %s: its normals point inward: its facets run clockwise seen from outside (the "
              "enclosed volume comes out %g m^3): reverse the order of each facet's vertices",
              where, path, vol);
  out->volume = vol;
  if (out->dropped > 0)
    log_info("%s: %s: %zu facets of zero area left out", where, path, out->dropped);
done:
  if (opened) stl_close(&s);
  if (st != CLSPH_OK) mesh_free(out);
  return st;
}

/* the facets' bounding boxes over a grid: first[c]..first[c + 1] index list[] (CSR) */
static enum clsph_status bin_facets(const struct mesh3 *m, int axes, const int *ax, const int *nc,
                                    const double *lo, const double *h, size_t **first_out,
                                    size_t **list_out)
{
  enum clsph_status st = CLSPH_OK;
  size_t ncell = 1;
  for (int k = 0; k < axes; ++k) ncell *= (size_t)nc[k];
  size_t *first = calloc(ncell + 1, sizeof *first), *list = NULL;
  CLSPH_CHECK(first != NULL, CLSPH_E_NOMEM, "mesh: out of memory for %zu cells", ncell);
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t t = 0; t < m->ntri; ++t) {
      int c0[3] = {0, 0, 0}, c1[3] = {0, 0, 0};
      for (int k = 0; k < axes; ++k) {
        const double *v = m->tri + 9 * t;
        const int a = ax[k];
        const double lo_v = fmin(fmin(v[a], v[3 + a]), v[6 + a]);
        const double hi_v = fmax(fmax(v[a], v[3 + a]), v[6 + a]);
        c0[k] = (int)fmax(0.0, floor((lo_v - lo[k]) / h[k]));
        c1[k] = (int)fmin((double)(nc[k] - 1), floor((hi_v - lo[k]) / h[k]));
      }
      for (int i = c0[0]; i <= c1[0]; ++i)
        for (int j = c0[1]; j <= c1[1]; ++j)
          for (int l = c0[2]; l <= c1[2]; ++l) {
            size_t c = (size_t)i;
            if (axes > 1) c = c * (size_t)nc[1] + (size_t)j;
            if (axes > 2) c = c * (size_t)nc[2] + (size_t)l;
            if (pass == 0)
              ++first[c + 1];
            else
              list[first[c]++] = t;
          }
    }
    if (pass == 0) {
      for (size_t c = 0; c < ncell; ++c) first[c + 1] += first[c];
      list = malloc((first[ncell] + 1) * sizeof *list);
      CLSPH_CHECK(list != NULL, CLSPH_E_NOMEM, "mesh: out of memory for %zu entries", first[ncell]);
    } else { /* first[c] moved to the cell's end: back */
      for (size_t c = ncell; c > 0; --c) first[c] = first[c - 1];
      first[0] = 0;
    }
  }
  *first_out = first;
  *list_out = list;
  first = list = NULL;
done:
  free(first);
  free(list);
  return st;
}

enum clsph_status mesh_index_build(const struct mesh3 *m, double reach, struct mesh_index *out)
{
  enum clsph_status st = CLSPH_OK;
  memset(out, 0, sizeof *out);
  const double *b = m->box;
  /* the rows: about √n cells a side, at most 512 */
  const int side = (int)fmin(512.0, fmax(1.0, ceil(sqrt((double)m->ntri))));
  out->ny = out->nz = side;
  out->hy = fmax((b[4] - b[1]) / side, 1e-300);
  out->hz = fmax((b[5] - b[2]) / side, 1e-300);
  {
    const int ax[2] = {1, 2}, nc[2] = {out->ny, out->nz};
    const double lo[2] = {b[1], b[2]}, h[2] = {out->hy, out->hz};
    CLSPH_TRY(bin_facets(m, 2, ax, nc, lo, h, &out->row_first, &out->row_tri));
  }
  /* the cells: side `reach`, at most 256 along an axis (then larger) */
  double cell = reach;
  for (int a = 0; a < 3; ++a) cell = fmax(cell, (b[3 + a] - b[a] + 2.0 * reach) / 256.0);
  out->cell = cell;
  for (int a = 0; a < 3; ++a)
    out->nc[a] = (int)fmax(1.0, ceil((b[3 + a] - b[a] + 2.0 * reach) / cell));
  {
    const int ax[3] = {0, 1, 2};
    const double lo[3] = {b[0] - reach, b[1] - reach, b[2] - reach}, h[3] = {cell, cell, cell};
    CLSPH_TRY(bin_facets(m, 3, ax, out->nc, lo, h, &out->cell_first, &out->cell_tri));
  }
  out->hidden = calloc(m->ntri + 1, 1);
  CLSPH_CHECK(out->hidden != NULL, CLSPH_E_NOMEM, "mesh: out of memory");
done:
  if (st != CLSPH_OK) mesh_index_free(out);
  return st;
}

int mesh_inside(const struct mesh3 *m, const struct mesh_index *ix, const double x[3])
{
  const double *b = m->box;
  const double size = (b[3] - b[0]) + (b[4] - b[1]) + (b[5] - b[2]);
  const double y = x[1] + 1.2345678e-9 * size, z = x[2] + 2.3456789e-9 * size;
  if (x[0] > b[3] || y < b[1] || y > b[4] || z < b[2] || z > b[5]) return 0;
  const int j = (int)fmin((double)(ix->ny - 1), floor((y - b[1]) / ix->hy));
  const int k = (int)fmin((double)(ix->nz - 1), floor((z - b[2]) / ix->hz));
  const size_t c = (size_t)j * (size_t)ix->nz + (size_t)k;
  int crossings = 0;
  for (size_t q = ix->row_first[c]; q < ix->row_first[c + 1]; ++q) {
    const size_t t = ix->row_tri[q];
    const double *v = m->tri + 9 * t, *n = m->nrm + 3 * t;
    if (n[0] == 0.0) continue; /* parallel to the ray */
    /* (y, z) inside the facet's projection: the three edge functions of one sign */
    double e[3];
    for (int a = 0; a < 3; ++a) {
      const double *p = v + 3 * a, *r = v + 3 * ((a + 1) % 3);
      e[a] = (r[1] - p[1]) * (z - p[2]) - (r[2] - p[2]) * (y - p[1]);
    }
    if (!((e[0] >= 0.0 && e[1] >= 0.0 && e[2] >= 0.0) ||
          (e[0] <= 0.0 && e[1] <= 0.0 && e[2] <= 0.0)))
      continue;
    const double xh = v[0] - (n[1] * (y - v[1]) + n[2] * (z - v[2])) / n[0];
    if (xh > x[0]) ++crossings;
  }
  return crossings & 1;
}

/* the nearest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection 5.1.5) */
static void closest_on_triangle(const double *a, const double *b, const double *c,
                                const double p[3], double q[3])
{
  double ab[3], ac[3], ap[3];
  for (int k = 0; k < 3; ++k) {
    ab[k] = b[k] - a[k];
    ac[k] = c[k] - a[k];
    ap[k] = p[k] - a[k];
  }
  const double d1 = dot3(ab, ap), d2 = dot3(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) {
    memcpy(q, a, 3 * sizeof *q);
    return;
  }
  double bp[3], cp[3];
  for (int k = 0; k < 3; ++k) {
    bp[k] = p[k] - b[k];
    cp[k] = p[k] - c[k];
  }
  const double d3 = dot3(ab, bp), d4 = dot3(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) {
    memcpy(q, b, 3 * sizeof *q);
    return;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    for (int k = 0; k < 3; ++k) q[k] = a[k] + v * ab[k];
    return;
  }
  const double d5 = dot3(ab, cp), d6 = dot3(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) {
    memcpy(q, c, 3 * sizeof *q);
    return;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    for (int k = 0; k < 3; ++k) q[k] = a[k] + w * ac[k];
    return;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    for (int k = 0; k < 3; ++k) q[k] = b[k] + w * (c[k] - b[k]);
    return;
  }
  const double denom = 1.0 / (va + vb + vc), v = vb * denom, w = vc * denom;
  for (int k = 0; k < 3; ++k) q[k] = a[k] + v * ab[k] + w * ac[k];
}

double mesh_nearest(const struct mesh3 *m, const struct mesh_index *ix, const double x[3],
                    double q[3], size_t *facet)
{
  const double reach = ix->cell; /* the grid's low corner is the box less one cell's reach */
  int c[3];
  for (int a = 0; a < 3; ++a) {
    const double f = floor((x[a] - (m->box[a] - reach)) / ix->cell);
    if (f < -1.0 || f > (double)ix->nc[a]) return HUGE_VAL;
    c[a] = (int)f;
  }
  double best = HUGE_VAL;
  for (int i = c[0] - 1; i <= c[0] + 1; ++i)
    for (int j = c[1] - 1; j <= c[1] + 1; ++j)
      for (int k = c[2] - 1; k <= c[2] + 1; ++k) {
        if (i < 0 || j < 0 || k < 0 || i >= ix->nc[0] || j >= ix->nc[1] || k >= ix->nc[2]) continue;
        const size_t cell =
            ((size_t)i * (size_t)ix->nc[1] + (size_t)j) * (size_t)ix->nc[2] + (size_t)k;
        for (size_t p = ix->cell_first[cell]; p < ix->cell_first[cell + 1]; ++p) {
          const size_t t = ix->cell_tri[p];
          if (ix->hidden[t]) continue;
          const double *v = m->tri + 9 * t;
          double y[3];
          closest_on_triangle(v, v + 3, v + 6, x, y);
          const double d2 = (y[0] - x[0]) * (y[0] - x[0]) + (y[1] - x[1]) * (y[1] - x[1]) +
                            (y[2] - x[2]) * (y[2] - x[2]);
          if (d2 < best) {
            best = d2;
            memcpy(q, y, 3 * sizeof *q);
            if (facet != NULL) *facet = t;
          }
        }
      }
  return sqrt(best);
}
