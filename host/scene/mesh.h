/* mesh.h: closed triangulated surfaces (STL files, ASCII or binary, read with ADMesh) as the
 * solids of 3-D walls: stl_wall { "file.stl", ... } (case.c), their particles (geometry3.c). */
#ifndef CLSPH_MESH_H
#define CLSPH_MESH_H

#include <stddef.h>

#include "status.h"

/** A closed, consistently oriented surface: what mesh_load accepts. */
struct mesh3 {
  size_t ntri;
  double *tri;    /* ntri x 9: each facet's vertices, counter-clockwise seen from outside, m */
  double *nrm;    /* ntri x 3: the facets' outward unit normals */
  double box[6];  /* its bounding box x0, y0, z0, x1, y1, z1, m */
  double volume;  /* the volume it encloses, m^3 */
  size_t dropped; /* facets of zero area in the file (left out) */
};

/** The search grids of a mesh for one spacing: the facets over (y, z) cells for the inside test
 *  (a ray along +x), and over cubic cells of side `reach` for the nearest point. */
struct mesh_index {
  int ny, nz;
  double hy, hz;
  size_t *row_first, *row_tri;
  double cell;
  int nc[3];
  size_t *cell_first, *cell_tri;
  unsigned char *hidden; /* ntri: 1 for a facet that faces no fluid (mesh_nearest skips it) */
};

/** @brief Read an STL file, place it (x' = scale x + offset) and check that it bounds a solid:
 *  closed (every edge shared by two facets), its facets consistently oriented, its normals
 *  outward (a positive enclosed volume). Errors name `where` (the case line and declaration) and
 *  the file. */
enum clsph_status mesh_load(const char *path, const char *where, double scale,
                            const double offset[3], struct mesh3 *out);
void mesh_free(struct mesh3 *m);

/** @brief Build the grids for nearest-point queries within `reach` (and the inside test). */
enum clsph_status mesh_index_build(const struct mesh3 *m, double reach, struct mesh_index *out);
void mesh_index_free(struct mesh_index *ix);

/** @brief Is x inside the solid? (ray parity along +x from a point moved by 1e-9 of the box's
 *  size across it, so that the ray meets no edge or vertex of a mesh on the lattice's planes) */
int mesh_inside(const struct mesh3 *m, const struct mesh_index *ix, const double x[3]);

/** @brief The nearest point q of the surface to x among the facets within `reach` of x's cell
 *  (farther ones may be missed) that are not hidden: its distance, or HUGE_VAL when none; *facet
 *  its facet. */
double mesh_nearest(const struct mesh3 *m, const struct mesh_index *ix, const double x[3],
                    double q[3], size_t *facet);

#endif
