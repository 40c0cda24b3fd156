/* test_mesh.c: the STL surfaces of 3-D walls (host/scene/mesh.c): loading and placing the files
 * of cases/stl (ASCII and binary, through ADMesh), the checks that refuse the broken ones of
 * tests/case/stl, the inside test and the nearest point.
 *
 * Tolerances. The icosphere of cases/stl/sphere.stl (level 3, 1280 facets) has its vertices on
 * the unit sphere, stored in float (7e-8), and its facets' planes down to 0.99547 of the radius
 * from the centre (computed from make_stl.py's vertices): every point farther than 0.005 r from
 * the sphere is on the same side of the surface, and the distance to the surface is |d − r|
 * within 0.005 r; the enclosed volume is 0.86% under the sphere's (4.15275 against 4.18879 at
 * radius 1), bounded by 1%.
 * The cube's vertices are exact (0 and 1 in float), its volume exact to rounding. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mesh.h"
#include "tcheck.h"

static const double pi = 3.14159265358979323846;

static void path_of(char *out, size_t size, const char *rel)
{
  snprintf(out, size, "%s/%s", CLSPH_SOURCE_DIR, rel);
}

/* the unit cube [0, 1]^3 placed at 2 x + (−0.5, 0, 1): inside, on the faces' diagonals too */
static void test_cube(void)
{
  char p[1024];
  path_of(p, sizeof p, "cases/stl/cube.stl");
  struct mesh3 m;
  const double off[3] = {-0.5, 0.0, 1.0};
  TC_CHECK(mesh_load(p, "test", 2.0, off, &m) == CLSPH_OK, "the cube loads");
  TC_CHECK(m.ntri == 12, "12 facets (%zu)", m.ntri);
  TC_NEAR(m.volume, 8.0, 1e-12, "the cube's volume");
  const double box[6] = {-0.5, 0.0, 1.0, 1.5, 2.0, 3.0};
  for (int k = 0; k < 6; ++k) TC_NEAR(m.box[k], box[k], 1e-15, "box[%d]", k);
  struct mesh_index ix;
  TC_CHECK(mesh_index_build(&m, 0.3, &ix) == CLSPH_OK, "its grids");
  /* points on a 0.1 lattice through the box and 0.3 around it, many on the planes of the
   * facets' edges (y = z − 1 runs along the diagonals of the faces x = const) */
  int wrong = 0, n = 0;
  for (int i = -8; i <= 28; ++i)
    for (int j = -3; j <= 23; ++j)
      for (int k = -3; k <= 23; ++k) {
        const double x[3] = {-0.5 + 0.1 * i + 0.05, 0.1 * j, 1.0 + 0.1 * k};
        const int want =
            x[0] > -0.5 && x[0] < 1.5 && x[1] > 0.0 && x[1] < 2.0 && x[2] > 1.0 && x[2] < 3.0;
        const int on = fabs(x[1]) < 1e-12 || fabs(x[1] - 2.0) < 1e-12 || fabs(x[2] - 1.0) < 1e-12 ||
                       fabs(x[2] - 3.0) < 1e-12;
        if (on) continue; /* on a face: either side */
        wrong += mesh_inside(&m, &ix, x) != want;
        ++n;
      }
  TC_CHECK(wrong == 0, "inside the cube: %d of %d points wrong", wrong, n);
  /* the nearest point: below the floor, beside an edge, inside near a face */
  const double a[3] = {0.5, 1.0, 0.8}, b[3] = {1.7, 2.1, 2.0}, c[3] = {0.5, 1.9, 2.0};
  double q[3];
  size_t t = 99;
  TC_NEAR(mesh_nearest(&m, &ix, a, q, &t), 0.2, 1e-12, "0.2 below the floor");
  TC_NEAR(q[2], 1.0, 1e-12, "its point on the floor");
  TC_NEAR(m.nrm[3 * t + 2], -1.0, 1e-12, "the floor's outward normal");
  TC_NEAR(mesh_nearest(&m, &ix, b, q, NULL), sqrt(0.2 * 0.2 + 0.1 * 0.1), 1e-12, "by an edge");
  TC_NEAR(mesh_nearest(&m, &ix, c, q, NULL), 0.1, 1e-12, "0.1 inside the face y = 2");
  const double far[3] = {5.0, 5.0, 5.0};
  TC_CHECK(mesh_nearest(&m, &ix, far, q, NULL) == HUGE_VAL, "beyond the grid: no facet");
  ix.hidden[t] = 1; /* the floor's facet hidden: the next nearest */
  TC_CHECK(mesh_nearest(&m, &ix, a, q, &t) > 0.2 - 1e-12, "a hidden facet is skipped");
  mesh_index_free(&ix);
  mesh_free(&m);
}

/* the binary icosphere, radius 0.3 at (1, 2, 3) */
static void test_sphere(void)
{
  char p[1024];
  path_of(p, sizeof p, "cases/stl/sphere.stl");
  struct mesh3 m;
  const double c[3] = {1.0, 2.0, 3.0}, r = 0.3;
  TC_CHECK(mesh_load(p, "test", r, c, &m) == CLSPH_OK, "the sphere loads");
  TC_CHECK(m.ntri == 1280, "1280 facets (%zu)", m.ntri);
  const double v = 4.0 / 3.0 * pi * r * r * r;
  TC_CHECK(m.volume < v && m.volume > 0.99 * v, "volume %.6g within 1%% under %.6g", m.volume, v);
  struct mesh_index ix;
  TC_CHECK(mesh_index_build(&m, 0.05, &ix) == CLSPH_OK, "its grids");
  int wrong = 0, n = 0;
  double worst = 0.0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j)
      for (int k = 0; k <= 40; ++k) {
        const double x[3] = {c[0] - 0.4 + 0.02 * i, c[1] - 0.4 + 0.02 * j, c[2] - 0.4 + 0.02 * k};
        const double d = sqrt((x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1]) +
                              (x[2] - c[2]) * (x[2] - c[2]));
        if (fabs(d - r) > 5e-3 * r) {
          wrong += mesh_inside(&m, &ix, x) != (d < r);
          ++n;
        }
        if (fabs(d - r) < 0.04) { /* within the grid's reach: the distance to the surface */
          double q[3];
          worst = fmax(worst, fabs(mesh_nearest(&m, &ix, x, q, NULL) - fabs(d - r)));
        }
      }
  TC_CHECK(wrong == 0, "inside the sphere: %d of %d points wrong", wrong, n);
  TC_CHECK(worst < 5e-3 * r, "the nearest point's distance within %.3g of |d − r| (worst %.3g)",
           5e-3 * r, worst);
  mesh_index_free(&ix);
  mesh_free(&m);
}

/* the broken surfaces: each refused, nothing left allocated */
static void test_refused(void)
{
  const char *bad[] = {"tests/case/stl/open.stl", "tests/case/stl/inverted.stl",
                       "tests/case/stl/flipped.stl", "tests/case/stl/junk.stl",
                       "tests/case/stl/none.stl"};
  const double off[3] = {0.0, 0.0, 0.0};
  for (size_t k = 0; k < sizeof bad / sizeof *bad; ++k) {
    char p[1024];
    path_of(p, sizeof p, bad[k]);
    struct mesh3 m;
    TC_CHECK(mesh_load(p, "test", 1.0, off, &m) == CLSPH_E_INPUT, "%s is refused", bad[k]);
    TC_CHECK(m.tri == NULL && m.ntri == 0, "%s: nothing kept", bad[k]);
  }
}

int main(void)
{
  test_cube();
  test_sphere();
  test_refused();
  return tc_finish("mesh");
}
