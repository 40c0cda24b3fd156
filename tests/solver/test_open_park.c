/* test_open_park.c: the park behind the exits (struct geom_park, solvers/open,
 * kernels/common/open.cl) on the scene of cases/poiseuille_open.lua with wcsph-riemann at
 * dr = 0.1 (100 fluid particles, 10 rows of 3 layers at the entry x < 0 and at the exit x > 1):
 *   geometry: ceil(0.1 x 100) = 10 parked particles (scheme_ops.open_reserve = 0.1), kind
 *     KIND_PARKED in the exit's section, at rest on the line x = 1 + 3 dr + support + dr/2,
 *     evenly along it (y = (q + 1/2)/10);
 *   open_layer_velocity leaves them where they are, at rest;
 *   open_recycle: the entry's front row reaches the fluid (every entry particle moved by dr) while
 *     nothing has left through the exit: its 10 particles become fluid all the same and the 10
 *     parked ones go to the back of the entry rows (x = -0.25, the entry's u_in), none waiting;
 *     then the exit's last row moved beyond the last layer while no entry wants it: it goes to
 *     the park (kind KIND_PARKED, on the park's line level with where it was, at rest).
 * The scheme's own sections live in its state; this test makes a second set beside them and
 * never steps the scheme. */
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
  real *pos, *vel, *u;
  cl_uint *kind, *section;
};

static int read_all(struct sim *sim, const struct open_sections *o, struct host *h)
{
  const struct dev *dev = sim->dev;
  const struct pset *ps = &sim->ps;
  const size_t n = h->n;
  return kern_read(dev, pset_mem(ps, sim->f_pos), 2 * n * sizeof(real), h->pos) ||
         kern_read(dev, pset_mem(ps, sim->f_vel), 2 * n * sizeof(real), h->vel) ||
         kern_read(dev, pset_mem(ps, o->f_u), 2 * n * sizeof(real), h->u) ||
         kern_read(dev, pset_mem(ps, sim->f_kind), n * sizeof(cl_uint), h->kind) ||
         kern_read(dev, pset_mem(ps, o->f_section), n * sizeof(cl_uint), h->section);
}

static size_t count_kind(const struct host *h, cl_uint kind)
{
  size_t c = 0;
  for (size_t i = 0; i < h->n; ++i) c += h->kind[i] == kind;
  return c;
}

/* the parked particles: on the park's line x = park, at rest, in the exit (section 1) */
static int bad_parked(const struct host *h, double park, double tol)
{
  int bad = 0;
  for (size_t i = 0; i < h->n; ++i)
    if (h->kind[i] == KIND_PARKED)
      bad += fabs((double)h->pos[2 * i] - park) > tol || h->section[i] != 1 || h->vel[2 * i] != 0 ||
             h->vel[2 * i + 1] != 0;
  return bad;
}

int main(void)
{
  struct dev dev;
  struct scene scene;
  struct sim sim;
  struct open_sections o;
  struct host h = {0};
  char *sets[] = {"dr=0.1", "riemann=1", "c0=30"};
  memset(&scene, 0, sizeof scene);
  memset(&sim, 0, sizeof sim);
  memset(&o, 0, sizeof o);
  tc_open_device(&dev);
  const double dr = 0.1, tol = 64 * EPS;
  int ok = case_load(CLSPH_SOURCE_DIR "/cases/poiseuille_open.lua", 3, sets, NULL, &scene, NULL) ==
               CLSPH_OK &&
           sim_create(&dev, &scene, &sim) == CLSPH_OK && open_create(&sim, -1, &o) == CLSPH_OK;
  TC_CHECK(ok, "the scene (wcsph-riemann), its sim and a second set of sections");
  if (!ok) goto done;
  const double park = 1.0 + 3.0 * dr + sim.sm.support + 0.5 * dr;

  /* the geometry's park */
  size_t parked = 0;
  int bad_geom = 0;
  for (size_t g = 0; g < sim.geom.n; ++g) {
    if (sim.geom.kind[g] != KIND_PARKED) continue;
    const double y = 0.05 + 0.1 * (double)parked++;
    bad_geom += fabs(sim.geom.x[2 * g] - park) > 1e-12 || fabs(sim.geom.x[2 * g + 1] - y) > 1e-12 ||
                sim.geom.group[g] != 1 || sim.geom.v[2 * g] != 0.0 || sim.geom.v[2 * g + 1] != 0.0;
  }
  TC_CHECK(parked == 10 && !bad_geom,
           "10 parked at x = %.3f, y = 0.05 + 0.1 q, at rest, in the exit (%zu, %d wrong)", park,
           parked, bad_geom);

  const size_t n = h.n = sim.ps.n;
  h.pos = calloc(2 * n, sizeof(real));
  h.vel = calloc(2 * n, sizeof(real));
  h.u = calloc(2 * n, sizeof(real));
  h.kind = calloc(2 * n, sizeof(cl_uint));
  if (!h.pos || !h.vel || !h.u || !h.kind) goto done;
  h.section = h.kind + n;
  /* the second set's fields are in the geometry's order, the sim's in the sorted order: the
   * velocity field and the sections again, through the ids */
  cl_uint *id = calloc(n, sizeof *id);
  ok = id != NULL && !kern_read(&dev, pset_mem(&sim.ps, sim.f_id), n * sizeof(cl_uint), id) &&
       !read_all(&sim, &o, &h);
  for (size_t i = 0; ok && i < n; ++i) {
    const size_t g = id[i];
    const int k = sim.geom.kind[g];
    h.section[i] = k == KIND_INFLOW || k == KIND_OUTFLOW || k == KIND_PARKED
                       ? (cl_uint)sim.geom.group[g]
                       : 0xffffffffu;
    h.u[2 * i] = (real)sim.geom.v[2 * g];
    h.u[2 * i + 1] = (real)sim.geom.v[2 * g + 1];
  }
  free(id);
  ok = ok && !kern_write(&dev, pset_mem(&sim.ps, o.f_section), n * sizeof(cl_uint), h.section) &&
       !kern_write(&dev, pset_mem(&sim.ps, o.f_u), 2 * n * sizeof(real), h.u) &&
       open_layer_velocity(&o, &sim) == CLSPH_OK && !read_all(&sim, &o, &h);
  TC_CHECK(ok, "open_layer_velocity");
  if (!ok) goto done;
  const size_t fluid0 = count_kind(&h, KIND_FLUID), entry0 = count_kind(&h, KIND_INFLOW);
  TC_CHECK(count_kind(&h, KIND_PARKED) == 10 && !bad_parked(&h, park, tol),
           "open_layer_velocity leaves the 10 parked ones on the park's line, at rest (%d wrong)",
           bad_parked(&h, park, tol));

  /* the entry's front row reaches the fluid; nothing has left through the exit */
  for (size_t i = 0; i < n; ++i)
    if (h.kind[i] == KIND_INFLOW) h.pos[2 * i] = (real)((double)h.pos[2 * i] + dr);
  ok = !kern_write(&dev, pset_mem(&sim.ps, sim.f_pos), 2 * n * sizeof(real), h.pos) &&
       open_recycle(&o, &sim) == CLSPH_OK && !read_all(&sim, &o, &h);
  TC_CHECK(ok, "open_recycle");
  if (!ok) goto done;
  int back = 0, bad_back = 0;
  for (size_t i = 0; i < n; ++i) {
    const double x = h.pos[2 * i], y = h.pos[2 * i + 1];
    if (h.kind[i] == KIND_INFLOW && x < -0.2) { /* a parked particle at the back of a row */
      ++back;
      bad_back += fabs(x + 0.25) > tol || h.section[i] != 0 ||
                  fabs((double)h.u[2 * i] - 4.0 * y * (1.0 - y)) > tol ||
                  h.vel[2 * i] != h.u[2 * i] || h.vel[2 * i + 1] != 0;
    }
  }
  TC_CHECK(o.used == 10 && sim.open_waiting == 0, "10 pairs, none waiting (%u, %ld)", o.used,
           sim.open_waiting);
  TC_CHECK(count_kind(&h, KIND_FLUID) == fluid0 + 10 && count_kind(&h, KIND_PARKED) == 0 &&
               count_kind(&h, KIND_INFLOW) == entry0,
           "the fluid gains the entry's row, the park gives its 10 (%zu fluid, %zu parked)",
           count_kind(&h, KIND_FLUID), count_kind(&h, KIND_PARKED));
  TC_CHECK(back == 10 && !bad_back,
           "10 at the back of the entry rows, x = -0.25, u_in (%d, %d wrong)", back, bad_back);

  /* the exit's last row beyond the last layer; no entry particle wants it */
  double ys[16];
  int nlast = 0;
  for (size_t i = 0; i < n; ++i)
    if (h.kind[i] == KIND_OUTFLOW && (double)h.pos[2 * i] > 1.2) {
      h.pos[2 * i] = (real)((double)h.pos[2 * i] + dr);
      if (nlast < 16) ys[nlast] = h.pos[2 * i + 1];
      ++nlast;
    }
  ok = nlast == 10 &&
       !kern_write(&dev, pset_mem(&sim.ps, sim.f_pos), 2 * n * sizeof(real), h.pos) &&
       open_recycle(&o, &sim) == CLSPH_OK && !read_all(&sim, &o, &h);
  TC_CHECK(ok, "open_recycle, the exit's last row (%d particles)", nlast);
  if (!ok) goto done;
  int level = 0;
  for (size_t i = 0; i < n; ++i)
    if (h.kind[i] == KIND_PARKED)
      for (int q = 0; q < nlast; ++q) level += h.pos[2 * i + 1] == (real)ys[q];
  TC_CHECK(o.used == 0 && count_kind(&h, KIND_PARKED) == 10 && !bad_parked(&h, park, tol) &&
               level == 10,
           "the row goes to the park, level with where it was, at rest (%zu parked, %d wrong, %d "
           "level)",
           count_kind(&h, KIND_PARKED), bad_parked(&h, park, tol), level);
done:
  open_destroy(&o);
  sim_destroy(&sim);
  scene_free(&scene);
  free(h.kind);
  free(h.u);
  free(h.vel);
  free(h.pos);
  dev_close(&dev);
  return tc_finish("open_park");
}
