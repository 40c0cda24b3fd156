/* test_usaw_gamma.c: the analytic wall renormalisation of the unified semi-analytical walls
 * (Leroy et al. 2014 eqs 55-62), on the device, against the reference values of
 * shared/notes/usaw_gamma.md (h = 0.02; checked there against brute-force quadrature of eq 3):
 * a straight wall at several distances, a 90° corner at three points and its vertex (θ/2π).
 * Its gradient Σ_s ∇γ_as (eqs 6-7) must equal the finite-difference gradient of γ.
 * The same kernel flags a fluid particle behind a wall: checked on both sides of a straight wall,
 * of a concave and of a convex corner, and beyond the free end of an open wall.
 * With the vertex ids given, the collinear joints' terms are skipped (they cancel): the joints
 * found are counted, and γ and ∇γ at points all over the walls' supports must equal the sums
 * over every segment's ends to round-off. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clsph_config.h"
#include "smoothing.h"
#include "tcheck.h"
#include "walls.h"

#define NSEG 40

struct probe {
  const char *name;
  double x, y, theta, want;
};

/* γ and ∇γ at np points. */
static size_t joints_found;

static int evaluate(const struct dev *dev, cl_program prog, const struct usaw_segments *segs,
                    const struct grid_spec *box, size_t np, const double *xy, const double *theta,
                    double *gamma, double *grad, unsigned *flags)
{
  struct usaw_walls w;
  cl_uint f = 0;
  cl_mem d_pos = NULL, d_theta = NULL, d_g = NULL, d_gg = NULL;
  real *buf = calloc(6 * np, sizeof *buf);
  int ok = 0;
  memset(&w, 0, sizeof w);
  for (size_t i = 0; i < np; ++i) {
    buf[2 * i] = (real)xy[2 * i];
    buf[2 * i + 1] = (real)xy[2 * i + 1];
    buf[2 * np + i] = (real)theta[i];
  }
  if (buf == NULL || usaw_walls_create(dev, prog, segs, box, &w) ||
      kern_buffer(dev, 2 * np * sizeof(real), buf, &d_pos, "pos") ||
      kern_buffer(dev, np * sizeof(real), buf + 2 * np, &d_theta, "theta") ||
      kern_buffer(dev, np * sizeof(real), NULL, &d_g, "gamma") ||
      kern_buffer(dev, 2 * np * sizeof(real), NULL, &d_gg, "grad gamma") ||
      kern_fill(dev, w.d_flags, &f, sizeof f, sizeof f) ||
      usaw_walls_gamma(&w, dev, np, d_pos, d_theta, d_g, d_gg, w.d_flags) ||
      kern_read(dev, w.d_flags, sizeof f, &f) ||
      kern_read(dev, d_g, np * sizeof(real), buf + 3 * np) ||
      kern_read(dev, d_gg, 2 * np * sizeof(real), buf + 4 * np))
    goto done;
  for (size_t i = 0; i < np; ++i) {
    gamma[i] = (double)buf[3 * np + i];
    grad[2 * i] = (double)buf[4 * np + 2 * i];
    grad[2 * i + 1] = (double)buf[4 * np + 2 * i + 1];
  }
  if (flags != NULL) *flags = f;
  joints_found = w.njoints;
  ok = 1;
done:
  kern_release(&d_gg);
  kern_release(&d_g);
  kern_release(&d_theta);
  kern_release(&d_pos);
  usaw_walls_destroy(&w);
  free(buf);
  return ok;
}

static void check(const struct dev *dev, cl_program prog, const char *what,
                  const struct usaw_segments *segs, const struct grid_spec *box,
                  const struct probe *p, size_t np, double h)
{
  /* each probe and its four finite-difference neighbours */
  const double delta = (CLSPH_DOUBLE ? 1e-4 : 2e-2) * h;
  const size_t m = 5 * np;
  double *xy = calloc(2 * m, sizeof *xy), *th = calloc(m, sizeof *th);
  double *g = calloc(m, sizeof *g), *gg = calloc(2 * m, sizeof *gg);
  if (!xy || !th || !g || !gg) goto done;
  for (size_t i = 0; i < np; ++i) {
    const double off[5][2] = {{0, 0}, {delta, 0}, {-delta, 0}, {0, delta}, {0, -delta}};
    for (int k = 0; k < 5; ++k) {
      xy[2 * (5 * i + (size_t)k)] = p[i].x + off[k][0];
      xy[2 * (5 * i + (size_t)k) + 1] = p[i].y + off[k][1];
      th[5 * i + (size_t)k] = k == 0 ? p[i].theta : 0.0;
    }
  }
  if (!evaluate(dev, prog, segs, box, m, xy, th, g, gg, NULL)) {
    TC_CHECK(0, "%s: evaluation runs", what);
    goto done;
  }
  /* the reference values have 6 decimals; float evaluates ψ's cancelling terms at ~1e-6 */
  const double tol = CLSPH_DOUBLE ? 1e-6 : 3e-5;
  for (size_t i = 0; i < np; ++i) {
    TC_NEAR(g[5 * i], p[i].want, tol, "%s: γ at %s", what, p[i].name);
    if (p[i].theta > 0.0 || p[i].y < 2 * delta) continue; /* no difference across a wall */
    double fx = (g[5 * i + 1] - g[5 * i + 2]) / (2 * delta);
    double fy = (g[5 * i + 3] - g[5 * i + 4]) / (2 * delta);
    /* eq 6 from its antiderivative (exact) against a central difference of eq 60 (error
     * ~(δ/h)² ~1e-8 of |∇γ| ~ 1/h, and its rounding ~1e-12/δ) in double; float differences of γ at
     * δ = 0.02h lose ~1e-4 */
    double scale = 1.0 / h, gtol = (CLSPH_DOUBLE ? 2e-6 : 2e-3) * scale;
    TC_NEAR(gg[2 * (5 * i)], fx, gtol, "%s: ∂γ/∂x at %s (Σ ∇γ_as vs difference)", what, p[i].name);
    TC_NEAR(gg[2 * (5 * i) + 1], fy, gtol, "%s: ∂γ/∂y at %s (Σ ∇γ_as vs difference)", what,
            p[i].name);
    printf("%-7s %-16s γ %.6f (want %.6f)  ∇γ (%9.4f, %9.4f) vs difference (%9.4f, %9.4f)\n", what,
           p[i].name, g[5 * i], p[i].want, gg[10 * i], gg[10 * i + 1], fx, fy);
  }
done:
  free(gg);
  free(g);
  free(th);
  free(xy);
}

/* One point against the walls: is it flagged as behind a wall (CLSPH_FLAG_WALL = 8)? */
static void crossing(const struct dev *dev, cl_program prog, const char *what,
                     const struct usaw_segments *segs, const struct grid_spec *box, double x,
                     double y, int behind)
{
  double xy[2] = {x, y}, th = 0.0, g, gg[2];
  unsigned f = 0;
  TC_CHECK(evaluate(dev, prog, segs, box, 1, xy, &th, &g, gg, &f), "%s: evaluation runs", what);
  TC_CHECK(((f & 8u) != 0) == behind, "%s: (%g, %g) is %s a wall (flags %u)", what, x, y,
           behind ? "behind" : "not behind", f);
}

/* The same walls with their vertex ids (joints skipped) and without (every end evaluated): γ and
 * ∇γ at a lattice of points around them and behind them. The corner's lattice ends on the row
 * y = 10 dr, through a vertex: there the foot falls on a joint, and the two segments must agree
 * on which side of it the foot is (an earlier form, with the side from each segment's own ends,
 * halved ∇γ there). */
static void joints(const struct dev *dev, cl_program prog, const char *what,
                   const struct usaw_segments *segs, const size_t *ids, const struct grid_spec *box,
                   double h, double x0, double x1, double y0, double y1, size_t want_joints)
{
  const size_t nx = 41, ny = 41, m = nx * ny;
  double *xy = calloc(2 * m, sizeof *xy), *th = calloc(m, sizeof *th);
  double *g = calloc(2 * m, sizeof *g), *gg = calloc(4 * m, sizeof *gg);
  struct usaw_segments with = *segs;
  with.v = ids;
  if (!xy || !th || !g || !gg) goto done;
  for (size_t i = 0; i < nx; ++i)
    for (size_t j = 0; j < ny; ++j) {
      xy[2 * (i * ny + j)] = x0 + (x1 - x0) * (double)i / (double)(nx - 1);
      xy[2 * (i * ny + j) + 1] = y0 + (y1 - y0) * (double)j / (double)(ny - 1);
    }
  if (!evaluate(dev, prog, segs, box, m, xy, th, g, gg, NULL)) goto fail;
  TC_CHECK(joints_found == 0, "%s: no joints without vertex ids (%zu)", what, joints_found);
  if (!evaluate(dev, prog, &with, box, m, xy, th, g + m, gg + 2 * m, NULL)) goto fail;
  TC_CHECK(joints_found == want_joints, "%s: %zu joint ends found, want %zu", what, joints_found,
           want_joints);
  /* every-end sums cancel ψ ~ 1 terms pairwise: round-off ~1e-15 a term in double, ~1e-7 in
   * float, over up to 2 x 16 terms */
  const double tol = CLSPH_DOUBLE ? 1e-12 : 1e-5, gtol = tol / h;
  double dg = 0.0, dgg = 0.0;
  for (size_t k = 0; k < m; ++k) {
    dg = fmax(dg, fabs(g[k] - g[m + k]));
    dgg = fmax(dgg, fmax(fabs(gg[2 * k] - gg[2 * m + 2 * k]),
                         fabs(gg[2 * k + 1] - gg[2 * m + 2 * k + 1])));
  }
  TC_CHECK(dg < tol, "%s: γ with joints skipped within %g of every end's sum (%.3g)", what, tol,
           dg);
  TC_CHECK(dgg < gtol, "%s: ∇γ with joints skipped within %g of every end's sum (%.3g)", what, gtol,
           dgg);
  printf("%-7s joints %zu: largest difference γ %.3g, ∇γ %.3g (1/h = %g)\n", what, joints_found, dg,
         dgg, 1.0 / h);
  goto done;
fail:
  TC_CHECK(0, "%s: evaluation runs", what);
done:
  free(gg);
  free(g);
  free(th);
  free(xy);
}

int main(void)
{
  struct dev dev;
  struct prog_opts o = {0};
  struct smoothing sm;
  cl_program prog = NULL;
  static const char *const sources[] = {GRID_SOURCES, USAW_SOURCES, NULL};
  const double h = 0.02, dr = h / 2, pi = 3.14159265358979323846;
  double a[4 * NSEG], b[4 * NSEG], n[4 * NSEG];
  size_t ids[4 * NSEG];
  int wall_of[2 * NSEG];
  tc_open_device(&dev);
  struct grid_spec box = {.dim = 2, .lo = {-0.3, -0.3}, .hi = {0.3, 0.3}};
  if (smoothing_make(SMOOTHING_WENDLAND_C2, 2, h, &sm) || grid_define(&box, &o) ||
      smoothing_define(&sm, &o) || prog_build(&dev, sources, &o, &prog)) {
    printf("FAIL: program\n");
    return 1;
  }
  box.support = sm.support;
  box.sm = sm;

  /* a straight wall y = 0 from x = −0.2 to 0.2, fluid above */
  for (int s = 0; s < NSEG; ++s) {
    a[2 * s] = -0.2 + s * dr;
    a[2 * s + 1] = 0.0;
    b[2 * s] = -0.2 + (s + 1) * dr;
    b[2 * s + 1] = 0.0;
    n[2 * s] = 0.0;
    n[2 * s + 1] = 1.0;
  }
  struct usaw_segments wall = {NSEG, a, b, n, NULL, NULL};
  for (int s = 0; s < NSEG; ++s) {
    ids[2 * s] = (size_t)s;
    ids[2 * s + 1] = (size_t)s + 1;
  }
  /* a joint at each of the NSEG − 1 inner vertices, two ends each */
  /* no lattice point on the wall's line or above a vertex: there the every-end sum is itself off
   * in float, where a point 3e-17 past a vertex is behind the end of one segment (y_b = y_a + len
   * rounds to 0) and past the start of the next (on the line, eq 62 then counts 3/4 of it; above
   * it, ψ's terms ±ψ(q, q/2) that should vanish are ~1e-4) */
  joints(&dev, prog, "wall", &wall, ids, &box, h, -0.2213, 0.2187, -0.03, 0.052,
         2 * (size_t)(NSEG - 1));
  const struct probe wp[] = {{"d = 0", 0.003, 0.0, 0, 0.500000},
                             {"d = 0.25h", 0.003, 0.25 * h, 0, 0.678883},
                             {"d = 0.5h", 0.003, 0.5 * h, 0, 0.823497},
                             {"d = h", 0.003, h, 0, 0.971491},
                             {"d = 1.5h", 0.003, 1.5 * h, 0, 0.999130}};
  check(&dev, prog, "wall", &wall, &box, wp, sizeof wp / sizeof *wp, h);
  /* 1e-4 h from the wall either way: far above the round-off of either precision */
  crossing(&dev, prog, "wall, in front", &wall, &box, 0.003, 1e-4 * h, 0);
  crossing(&dev, prog, "wall, behind", &wall, &box, 0.003, -1e-4 * h, 1);
  crossing(&dev, prog, "wall, deep behind", &wall, &box, 0.013, -1.5 * h, 1);
  crossing(&dev, prog, "wall, past its free end", &wall, &box, -0.21, -0.005, 0);

  /* a 90° corner: fluid in x > 0, y > 0; walls along both axes */
  for (int s = 0; s < NSEG; ++s) {
    a[2 * s] = s * dr; /* along x, left to right: normal +y */
    a[2 * s + 1] = 0.0;
    b[2 * s] = (s + 1) * dr;
    b[2 * s + 1] = 0.0;
    n[2 * s] = 0.0;
    n[2 * s + 1] = 1.0;
    int k = NSEG + s; /* along y, downwards: normal +x */
    a[2 * k] = 0.0;
    a[2 * k + 1] = (s + 1) * dr;
    b[2 * k] = 0.0;
    b[2 * k + 1] = s * dr;
    n[2 * k] = 1.0;
    n[2 * k + 1] = 0.0;
  }
  struct usaw_segments corner = {2 * NSEG, a, b, n, NULL, NULL};
  /* vertex ids: along x 0..NSEG from the corner; along y NSEG + 1 + s at (0, (s + 1) dr), the
   * corner (id 0) ending the last segment down: no joint there (the normals differ) */
  for (int s = 0; s < NSEG; ++s) {
    ids[2 * s] = (size_t)s;
    ids[2 * s + 1] = (size_t)s + 1;
    ids[2 * (NSEG + s)] = (size_t)(NSEG + 1 + s);
    ids[2 * (NSEG + s) + 1] = s == 0 ? 0 : (size_t)(NSEG + s);
  }
  joints(&dev, prog, "corner", &corner, ids, &box, h, -0.03, 0.1, -0.03, 0.1,
         4 * (size_t)(NSEG - 1));
  /* the two walls' segments given as different walls: still joints within each, none between */
  for (int s = 0; s < 2 * NSEG; ++s) wall_of[s] = s < NSEG ? 0 : 1;
  corner.wall = wall_of;
  joints(&dev, prog, "walls", &corner, ids, &box, h, -0.03, 0.1, -0.03, 0.1,
         4 * (size_t)(NSEG - 1));
  /* the x wall cut in two walls at its middle vertex: that joint is no longer one */
  for (int s = 0; s < 2 * NSEG; ++s) wall_of[s] = s < NSEG / 2 ? 0 : 1;
  joints(&dev, prog, "cut", &corner, ids, &box, h, -0.03, 0.1, -0.03, 0.1,
         4 * (size_t)(NSEG - 1) - 2);
  corner.wall = NULL;
  const struct probe cp[] = {{"(0.5h, 0.5h)", 0.5 * h, 0.5 * h, 0, 0.677299},
                             {"(1.0h, 0.3h)", 1.0 * h, 0.3 * h, 0, 0.690482},
                             {"(0.2h, 1.5h)", 0.2 * h, 1.5 * h, 0, 0.644385},
                             {"vertex", 0.0, 0.0, 0.5 * pi, 0.250000}};
  check(&dev, prog, "corner", &corner, &box, cp, sizeof cp / sizeof *cp, h);
  /* the concave corner of a tank (fluid in the quadrant): behind either wall, or both */
  crossing(&dev, prog, "tank corner, inside", &corner, &box, 0.2 * dr, 0.1 * dr, 0);
  crossing(&dev, prog, "tank corner, behind x = 0", &corner, &box, -0.1 * dr, 0.5 * dr, 1);
  crossing(&dev, prog, "tank corner, behind both", &corner, &box, -0.1 * dr, -0.2 * dr, 1);
  /* the same walls reversed make a convex solid corner (a wedge's apex, solid in the quadrant):
   * points beside the apex are nearest to the shared vertex and in the fluid */
  for (int s = 0; s < 2 * NSEG; ++s) {
    for (int c = 0; c < 2; ++c) {
      double t = a[2 * s + c];
      a[2 * s + c] = b[2 * s + c];
      b[2 * s + c] = t;
      n[2 * s + c] = -n[2 * s + c];
    }
  }
  crossing(&dev, prog, "apex, beside", &corner, &box, -0.3 * dr, -0.1 * dr, 0);
  crossing(&dev, prog, "apex, diagonal", &corner, &box, -0.2 * dr, -0.2 * dr, 0);
  crossing(&dev, prog, "apex, inside the solid", &corner, &box, 0.3 * dr, 0.1 * dr, 1);

  clReleaseProgram(prog);
  prog_opts_free(&o);
  dev_close(&dev);
  return tc_finish("test_usaw_gamma");
}
