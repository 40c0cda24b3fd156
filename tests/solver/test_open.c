/* test_open.c: the shared entry and exit sections (solvers/open, kernels/common/open.cl) on the
 * scene of cases/poiseuille_open.lua at dr = 0.1 (10 rows of 3 layers at the entry x < 0 and at
 * the exit x > 1, the fluid 0 < x, y < 1): what a weakly-compressible scheme calls and
 * isph-rotational does not (open_create with its own velocity field, open_layer_scalar,
 * open_move), and the recycling both use.
 *   open_layer_velocity: entry layers carry u_in = 4 y (1 − y) (eq 30), exit layers their row's
 *     first fluid particle's velocity (n·∇u = 0), which is their progenitor, 0.5 dr inside, and
 *     its tangential part only where it flows back in;
 *   open_layer_scalar: entry layers take their row's first fluid particle's value, exit layers
 *     the exit value (or that copy too);
 *   open_move: layers x += δt u, nothing else moves;
 *   open_recycle: every particle moved by dr downstream: the entry's front row becomes fluid, the
 *     fluid's last column exit layers, the exit's last row goes to the back of the entry rows
 *     (x = −0.25, the entry's u_in, the copied fields of the entry particle it replaces); the
 *     kinds' counts do not change; then the next entry row alone: 10 left waiting.
 * isph-rotational's own sections live in its state; this test makes a second set beside them
 * (its fields are new particle fields) and never steps the scheme. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case.h"
#include "clsph_config.h"
#include "kern.h"
#include "open.h"
#include "sim.h"
#include "tcheck.h"

#define EPS REAL_EPS

struct host {
  size_t n;
  real *pos, *vel, *u, *a;
  cl_uint *kind, *section, *near, *src, *id;
};

static int read_all(struct sim *sim, const struct open_sections *o, int f_a, struct host *h)
{
  const struct dev *dev = sim->dev;
  const struct pset *ps = &sim->ps;
  const size_t n = h->n;
  return kern_read(dev, pset_mem(ps, sim->f_pos), 2 * n * sizeof(real), h->pos) ||
         kern_read(dev, pset_mem(ps, sim->f_vel), 2 * n * sizeof(real), h->vel) ||
         kern_read(dev, pset_mem(ps, o->f_u), 2 * n * sizeof(real), h->u) ||
         kern_read(dev, pset_mem(ps, f_a), n * sizeof(real), h->a) ||
         kern_read(dev, pset_mem(ps, sim->f_kind), n * sizeof(cl_uint), h->kind) ||
         kern_read(dev, pset_mem(ps, o->f_section), n * sizeof(cl_uint), h->section) ||
         kern_read(dev, pset_mem(ps, o->f_near), n * sizeof(cl_uint), h->near) ||
         kern_read(dev, pset_mem(ps, o->f_src), n * sizeof(cl_uint), h->src) ||
         kern_read(dev, pset_mem(ps, sim->f_id), n * sizeof(cl_uint), h->id);
}

static double u_in(double y)
{
  return 4.0 * y * (1.0 - y);
}

static void count_kinds(const struct host *h, size_t c[5])
{
  memset(c, 0, 5 * sizeof *c);
  for (size_t i = 0; i < h->n; ++i)
    if (h->kind[i] < 5) ++c[h->kind[i]];
}

int main(void)
{
  struct dev dev;
  struct scene scene;
  struct sim sim;
  struct open_sections o;
  struct host h = {0};
  real *before = NULL;
  char *sets[] = {"dr=0.1"};
  int f_a = -1;
  memset(&scene, 0, sizeof scene);
  memset(&sim, 0, sizeof sim);
  memset(&o, 0, sizeof o);
  tc_open_device(&dev);
  const double dr = 0.1, tol = 64 * EPS;
  int ok = case_load(CLSPH_SOURCE_DIR "/cases/poiseuille_open.lua", 1, sets, NULL, &scene, NULL) ==
               CLSPH_OK &&
           sim_create(&dev, &scene, &sim) == CLSPH_OK && open_create(&sim, -1, &o) == CLSPH_OK &&
           pset_add(&sim.ps, &dev, "test_a", sizeof(real), NULL, &f_a) == CLSPH_OK;
  TC_CHECK(ok, "the scene, its sim and a second set of sections");
  if (!ok) goto done;
  TC_CHECK(o.nsec == 2 && o.ninflow == 1 && o.noutflow == 1, "2 sections, an entry and an exit");
  TC_NEAR(open_speed(&scene), 1.0, 0.0, "open_speed: the entry's peak speed");
  const size_t n = h.n = sim.ps.n;
  h.pos = calloc(2 * n, sizeof(real));
  h.vel = calloc(2 * n, sizeof(real));
  h.u = calloc(2 * n, sizeof(real));
  h.a = calloc(n, sizeof(real));
  before = calloc(2 * n, sizeof(real));
  h.kind = calloc(5 * n, sizeof(cl_uint));
  if (!h.pos || !h.vel || !h.u || !h.a || !before || !h.kind) goto done;
  h.section = h.kind + n;
  h.near = h.kind + 2 * n;
  h.src = h.kind + 3 * n;
  h.id = h.kind + 4 * n;
  /* open_create initialised its fields in the geometry's order, as a scheme's create does; the sim
   * is sorted already: put them in its order through the particles' ids */
  ok = !read_all(&sim, &o, f_a, &h);
  for (size_t i = 0; ok && i < n; ++i) {
    const size_t g = h.id[i];
    const int layer = sim.geom.kind[g] == KIND_INFLOW || sim.geom.kind[g] == KIND_OUTFLOW;
    h.section[i] = layer ? (cl_uint)sim.geom.group[g] : 0xffffffffu;
    h.u[2 * i] = (real)sim.geom.v[2 * g];
    h.u[2 * i + 1] = (real)sim.geom.v[2 * g + 1];
    /* a velocity and a scalar that name the particle: u = (x + 1, y), a = 10 x + y */
    h.vel[2 * i] = (real)((double)h.pos[2 * i] + 1.0);
    h.vel[2 * i + 1] = h.pos[2 * i + 1];
    h.a[i] = (real)(10.0 * (double)h.pos[2 * i] + (double)h.pos[2 * i + 1]);
  }
  ok = ok && !kern_write(&dev, pset_mem(&sim.ps, o.f_section), n * sizeof(cl_uint), h.section) &&
       !kern_write(&dev, pset_mem(&sim.ps, o.f_u), 2 * n * sizeof(real), h.u) &&
       !kern_write(&dev, pset_mem(&sim.ps, sim.f_vel), 2 * n * sizeof(real), h.vel) &&
       !kern_write(&dev, pset_mem(&sim.ps, f_a), n * sizeof(real), h.a);
  TC_CHECK(ok, "the fields set");
  if (!ok) goto done;
  size_t c0[5], c[5];
  count_kinds(&h, c0);
  TC_CHECK(c0[KIND_FLUID] == 100 && c0[KIND_INFLOW] == 30 && c0[KIND_OUTFLOW] == 30,
           "100 fluid, 30 entry and 30 exit particles (%zu, %zu, %zu)", c0[KIND_FLUID],
           c0[KIND_INFLOW], c0[KIND_OUTFLOW]);

  /* the layers' velocity */
  ok = open_layer_velocity(&o, &sim) == CLSPH_OK && !read_all(&sim, &o, f_a, &h);
  TC_CHECK(ok, "open_layer_velocity");
  if (!ok) goto done;
  int bad_row = 0, bad_in = 0, bad_out = 0;
  for (size_t i = 0; i < n; ++i) {
    const cl_uint k = h.kind[i];
    if (k != KIND_INFLOW && k != KIND_OUTFLOW) continue;
    const cl_uint m = h.near[i];
    const double y = h.pos[2 * i + 1];
    /* the row's first fluid particle: fluid, level with it, 0.5 dr inside the section */
    const double xm = k == KIND_INFLOW ? 0.5 * dr : 1.0 - 0.5 * dr;
    bad_row += m >= n || h.kind[m] != KIND_FLUID || fabs((double)h.pos[2 * m + 1] - y) > tol ||
               fabs((double)h.pos[2 * m] - xm) > tol;
    if (k == KIND_INFLOW) {
      bad_in += fabs((double)h.vel[2 * i] - u_in(y)) > tol || h.vel[2 * i + 1] != 0 ||
                h.u[2 * i] != h.vel[2 * i] || h.src[i] != i;
    } else if (m < n) {
      bad_out += h.vel[2 * i] != h.vel[2 * m] || h.vel[2 * i + 1] != h.vel[2 * m + 1] ||
                 h.u[2 * i] != h.vel[2 * i] || h.u[2 * i + 1] != h.vel[2 * i + 1] ||
                 h.src[i] != m || fabs((double)h.vel[2 * m] - (xm + 1.0)) > tol;
    }
  }
  TC_CHECK(!bad_row, "every layer particle's row has its first fluid particle (%d wrong)", bad_row);
  TC_CHECK(!bad_in, "entry layers: u = u_in = 4 y (1 - y), their own progenitor (%d wrong)",
           bad_in);
  TC_CHECK(!bad_out, "exit layers: the velocity of their row's first fluid particle (%d wrong)",
           bad_out);

  /* backflow: with the fluid flowing back into the exit (u = (−(x + 1), y), u·n > 0 with n = −x
   * into the fluid) the exit layers take the tangential part only, (0, y), and stay put */
  for (size_t i = 0; i < n; ++i) {
    h.vel[2 * i] = (real)(-((double)h.pos[2 * i] + 1.0));
    h.vel[2 * i + 1] = h.pos[2 * i + 1];
  }
  ok = !kern_write(&dev, pset_mem(&sim.ps, sim.f_vel), 2 * n * sizeof(real), h.vel) &&
       open_layer_velocity(&o, &sim) == CLSPH_OK && !read_all(&sim, &o, f_a, &h);
  bad_out = !ok;
  for (size_t i = 0; ok && i < n; ++i) {
    if (h.kind[i] != KIND_OUTFLOW) continue;
    const cl_uint m = h.near[i];
    bad_out += m >= n || h.vel[2 * i] != 0 || h.vel[2 * i + 1] != h.vel[2 * m + 1] ||
               h.vel[2 * m] >= 0 || h.u[2 * i] != 0;
  }
  TC_CHECK(!bad_out, "backflow: exit layers take only the tangential part, u_x = 0 (%d wrong)",
           bad_out);
  for (size_t i = 0; i < n; ++i) { /* back to the named velocities, u = (x + 1, y) */
    h.vel[2 * i] = (real)((double)h.pos[2 * i] + 1.0);
    h.vel[2 * i + 1] = h.pos[2 * i + 1];
  }
  ok = !kern_write(&dev, pset_mem(&sim.ps, sim.f_vel), 2 * n * sizeof(real), h.vel) &&
       open_layer_velocity(&o, &sim) == CLSPH_OK && !read_all(&sim, &o, f_a, &h);
  TC_CHECK(ok, "open_layer_velocity again");
  if (!ok) goto done;

  /* a scalar of the layers: a fixed exit value, then copied there too */
  const double exit_value = -7.0;
  ok = open_layer_scalar(&o, &sim, pset_mem(&sim.ps, f_a), &exit_value) == CLSPH_OK &&
       !read_all(&sim, &o, f_a, &h);
  TC_CHECK(ok, "open_layer_scalar");
  if (!ok) goto done;
  int bad_a = 0;
  for (size_t i = 0; i < n; ++i) {
    const double want_self = 10.0 * (double)h.pos[2 * i] + (double)h.pos[2 * i + 1];
    if (h.kind[i] == KIND_INFLOW)
      bad_a += h.a[i] != h.a[h.near[i]];
    else if (h.kind[i] == KIND_OUTFLOW)
      bad_a += h.a[i] != (real)exit_value;
    else
      bad_a += fabs((double)h.a[i] - want_self) > tol * 10.0;
  }
  TC_CHECK(!bad_a,
           "entries copy their row's first fluid particle, exits -7, the rest keep theirs "
           "(%d wrong)",
           bad_a);
  ok = open_layer_scalar(&o, &sim, pset_mem(&sim.ps, f_a), NULL) == CLSPH_OK &&
       !read_all(&sim, &o, f_a, &h);
  bad_a = !ok;
  for (size_t i = 0; ok && i < n; ++i)
    if (h.kind[i] == KIND_OUTFLOW) bad_a += h.a[i] != h.a[h.near[i]];
  TC_CHECK(!bad_a, "exit_value NULL: the exits copy too (%d wrong)", bad_a);

  /* the layers' motion */
  const double dt = 0.01;
  memcpy(before, h.pos, 2 * n * sizeof(real));
  ok = open_move(&o, &sim, dt) == CLSPH_OK && !read_all(&sim, &o, f_a, &h);
  TC_CHECK(ok, "open_move");
  if (!ok) goto done;
  int bad_move = 0;
  for (size_t i = 0; i < n; ++i) {
    const int layer = h.kind[i] == KIND_INFLOW || h.kind[i] == KIND_OUTFLOW;
    for (int a = 0; a < 2; ++a) {
      const double want =
          (double)(layer ? before[2 * i + a] + (real)dt * h.vel[2 * i + a] : before[2 * i + a]);
      bad_move += fabs((double)h.pos[2 * i + a] - want) > tol * (1.0 + fabs(want));
    }
  }
  TC_CHECK(!bad_move, "the layers moved by dt u, nothing else (%d wrong)", bad_move);

  /* the recycling: every fluid and layer particle dr downstream of where it started */
  for (size_t i = 0; i < n; ++i) {
    const int moves = h.kind[i] != KIND_DUMMY;
    h.pos[2 * i] = (real)((double)before[2 * i] + (moves ? dr : 0.0));
    h.pos[2 * i + 1] = before[2 * i + 1];
    h.a[i] = (real)(10.0 * (double)h.pos[2 * i] + (double)h.pos[2 * i + 1]);
  }
  ok = !kern_write(&dev, pset_mem(&sim.ps, sim.f_pos), 2 * n * sizeof(real), h.pos) &&
       !kern_write(&dev, pset_mem(&sim.ps, f_a), n * sizeof(real), h.a) &&
       open_recycle(&o, &sim) == CLSPH_OK && open_recycle_copy(&o, &sim, f_a) == CLSPH_OK &&
       !read_all(&sim, &o, f_a, &h);
  TC_CHECK(ok, "open_recycle");
  if (!ok) goto done;
  count_kinds(&h, c);
  TC_CHECK(o.used == 10, "10 pairs (%u)", o.used);
  TC_CHECK(sim.open_waiting == 0 && sim.open_waiting_max == 0, "none left waiting (%ld, max %ld)",
           sim.open_waiting, sim.open_waiting_max);
  TC_CHECK(!memcmp(c, c0, sizeof c), "the kinds' counts unchanged (%zu, %zu, %zu)", c[KIND_FLUID],
           c[KIND_INFLOW], c[KIND_OUTFLOW]);
  int back = 0, bad_back = 0, bad_fluid = 0, bad_exit = 0;
  for (size_t i = 0; i < n; ++i) {
    const double x = h.pos[2 * i], y = h.pos[2 * i + 1];
    if (h.kind[i] == KIND_INFLOW && x < -0.2) { /* a recycled exit particle */
      ++back;
      bad_back += fabs(x + 0.25) > tol || h.section[i] != 0 ||
                  fabs((double)h.u[2 * i] - u_in(y)) > tol || h.u[2 * i + 1] != 0 ||
                  h.vel[2 * i] != h.u[2 * i] || h.vel[2 * i + 1] != h.u[2 * i + 1] ||
                  fabs((double)h.a[i] - (10.0 * (x + 0.3) + y)) > 100 * EPS;
    }
    if (h.kind[i] == KIND_FLUID) bad_fluid += h.section[i] != 0xffffffffu || x < 0.0 || x > 1.0;
    if (h.kind[i] == KIND_OUTFLOW) bad_exit += h.section[i] != 1 || x < 1.0 || x > 1.3;
  }
  TC_CHECK(back == 10 && !bad_back,
           "10 at the back of the entry rows, x = -0.25, u_in, the entry's value copied (%d, "
           "%d wrong)",
           back, bad_back);
  TC_CHECK(!bad_fluid, "the fluid lies within 0 < x < 1, in no section (%d wrong)", bad_fluid);
  TC_CHECK(!bad_exit, "the exit layers lie within 1 < x < 1.3 (%d wrong)", bad_exit);

  /* the entry's next row reaches the fluid with nothing at the exit to give */
  for (size_t i = 0; i < n; ++i)
    if (h.kind[i] == KIND_INFLOW) h.pos[2 * i] = (real)((double)h.pos[2 * i] + dr);
  ok = !kern_write(&dev, pset_mem(&sim.ps, sim.f_pos), 2 * n * sizeof(real), h.pos) &&
       open_recycle(&o, &sim) == CLSPH_OK && !read_all(&sim, &o, f_a, &h);
  count_kinds(&h, c);
  TC_CHECK(ok && o.used == 0 && sim.open_waiting == 10 && sim.open_waiting_max == 10 &&
               !memcmp(c, c0, sizeof c),
           "nothing to recycle: 10 entry particles left waiting (%u pairs, %ld waiting)", o.used,
           sim.open_waiting);
done:
  open_destroy(&o);
  sim_destroy(&sim);
  scene_free(&scene);
  free(before);
  free(h.kind);
  free(h.a);
  free(h.u);
  free(h.vel);
  free(h.pos);
  dev_close(&dev);
  return tc_finish("open");
}
