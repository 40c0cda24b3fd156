/* walls.c: USAW wall segments on the device (see walls.h). */
#include "walls.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clsph_config.h"
#include "geometry.h"
#include "scene.h"
#include "sim.h"

enum clsph_status usaw_wall_distance_floor(const struct scene *sc, double spacings, double *d_min)
{
  enum clsph_status st = CLSPH_OK;
  double f = spacings;
  for (int i = 0; i < sc->noptions; ++i) {
    const struct scene_option *o = &sc->options[i];
    if (strcmp(o->key, "wall_distance_floor") != 0) continue;
    CLSPH_CHECK(o->is_number, CLSPH_E_INPUT,
                "%s: wall_distance_floor must be a number of spacings, not \"%s\"", sc->case_path,
                o->text);
    CLSPH_CHECK(o->number > 0.0 && o->number <= 1.0, CLSPH_E_INPUT,
                "%s: wall_distance_floor must be in (0, 1] spacings (the smallest wall distance of "
                "the viscous wall term; 1 is the paper's eq 17), not %g",
                sc->case_path, o->number);
    f = o->number;
  }
  *d_min = f * sc->dr;
done:
  return st;
}

enum clsph_status usaw_seg_cache_option(const struct scene *sc, unsigned dflt, unsigned *slots)
{
  enum clsph_status st = CLSPH_OK;
  *slots = dflt;
  for (int i = 0; i < sc->noptions; ++i) {
    const struct scene_option *o = &sc->options[i];
    if (strcmp(o->key, "segment_cache") != 0) continue;
    CLSPH_CHECK(o->is_number, CLSPH_E_INPUT,
                "%s: segment_cache must be a whole number of segments a particle, not \"%s\"",
                sc->case_path, o->text);
    CLSPH_CHECK(o->number == floor(o->number) && o->number >= 0.0 && o->number <= 64.0,
                CLSPH_E_INPUT,
                "%s: segment_cache must be a whole number of segments a particle from 0 (none) to "
                "64, not %g",
                sc->case_path, o->number);
    *slots = (unsigned)o->number;
  }
done:
  return st;
}

enum clsph_status usaw_seg_cache_define(const struct scene *sc, unsigned dflt, struct prog_opts *o)
{
  enum clsph_status st = CLSPH_OK;
  unsigned k = 0;
  CLSPH_TRY(usaw_seg_cache_option(sc, dflt, &k));
  CLSPH_TRY(prog_opts_define_int(o, "USAW_SEG_CACHE", (long)k));
done:
  return st;
}

enum clsph_status usaw_walls_cache(struct usaw_walls *w, const struct scene *sc, unsigned dflt)
{
  enum clsph_status st = CLSPH_OK;
  unsigned slots = 0;
  CLSPH_TRY(usaw_seg_cache_option(sc, dflt, &slots));
  /* gamma.cl: a slot keeps the segment's index in 28 bits, its periodic image in 4 */
  CLSPH_CHECK(slots == 0 || w->ps.n < (size_t)1 << 28, CLSPH_E_UNSUPPORTED,
              "%s: %zu wall segments, more than the segment cache indexes (2^28): set "
              "segment_cache = 0",
              sc->case_path, w->ps.n);
  w->cache_k = slots;
done:
  return st;
}

/* The cache's buffers for n particles (grown with a margin); a new count says "walk the grid"
 * (K + 1) until usaw_gamma has filled it. */
static enum clsph_status cache_reserve(struct usaw_walls *w, const struct dev *dev, size_t n)
{
  enum clsph_status st = CLSPH_OK;
  if (w->cache_k == 0 || (n <= w->cache_n && w->d_cache_cnt != NULL)) goto done;
  const size_t cap = n + n / 8 + 64;
  kern_release(&w->d_cache_cnt);
  kern_release(&w->d_cache_list);
  kern_release(&w->d_cache_gg);
  CLSPH_TRY(kern_buffer(dev, cap * sizeof(cl_uint), NULL, &w->d_cache_cnt, "segment cache counts"));
  CLSPH_TRY(kern_buffer(dev, cap * w->cache_k * sizeof(cl_uint), NULL, &w->d_cache_list,
                        "segment cache"));
  CLSPH_TRY(kern_buffer(dev, cap * w->cache_k * 2 * sizeof(real), NULL, &w->d_cache_gg,
                        "segment cache gradients"));
  const cl_uint walk = (cl_uint)w->cache_k + 1u;
  CLSPH_TRY(kern_fill(dev, w->d_cache_cnt, &walk, sizeof walk, cap * sizeof walk));
  w->cache_n = cap;
done:
  return st;
}

enum clsph_status usaw_wall_guard_option(const struct scene *sc, int auto_on, cl_uint *on)
{
  enum clsph_status st = CLSPH_OK;
  *on = auto_on ? 1u : 0u;
  for (int i = 0; i < sc->noptions; ++i) {
    const struct scene_option *o = &sc->options[i];
    if (strcmp(o->key, "wall_guard") != 0) continue;
    CLSPH_CHECK(!o->is_number, CLSPH_E_INPUT,
                "%s: wall_guard must be \"auto\" (on with gravity or turning walls), \"on\" or "
                "\"off\", not the number %g",
                sc->case_path, o->number);
    const char *t = o->text;
    CLSPH_CHECK(strcmp(t, "on") == 0 || strcmp(t, "off") == 0 || strcmp(t, "auto") == 0,
                CLSPH_E_INPUT,
                "%s: wall_guard must be \"auto\" (on with gravity or turning walls), \"on\" or "
                "\"off\", not \"%s\"",
                sc->case_path, t);
    if (strcmp(t, "on") == 0) *on = 1u;
    if (strcmp(t, "off") == 0) *on = 0u;
  }
done:
  return st;
}

struct seg_end {
  size_t v, s;
  int end; /* 0: a, 1: b */
};

static int seg_end_cmp(const void *x, const void *y)
{
  const struct seg_end *p = x, *q = y;
  if (p->v != q->v) return p->v < q->v ? -1 : 1;
  if (p->s != q->s) return p->s < q->s ? -1 : 1;
  return p->end - q->end;
}

/* The collinear joints (gamma.cl): a vertex where exactly one segment ends (its b) and exactly one
 * other starts (its a), both of one wall, at the same point in the device's precision (not across
 * a periodic seam, where the two ends are different images), with normals within 1e-12 rad and
 * tangents that point the same way. Bits of joint[s]: 1 at a, 2 at b. Without vertex ids there
 * are none. normal_out (n x 2) gets the normals with each chain of joined segments taking its
 * first segment's, so that the kernel's side of a joint (the sign of y there, from the normal and
 * the shared end) is the same number on both segments. */
static enum clsph_status find_joints(const struct usaw_segments *segs, cl_uint *joint,
                                     double *normal_out, size_t *count)
{
  enum clsph_status st = CLSPH_OK;
  const size_t n = segs->n;
  struct seg_end *e = NULL;
  size_t *next = NULL;
  char *done = NULL;
  *count = 0;
  for (size_t s = 0; s < n; ++s) {
    joint[s] = 0;
    normal_out[2 * s] = segs->normal[2 * s];
    normal_out[2 * s + 1] = segs->normal[2 * s + 1];
  }
  if (segs->v == NULL || n < 2) return CLSPH_OK;
  e = malloc(2 * n * sizeof *e);
  next = malloc(n * sizeof *next);
  done = calloc(n, 1);
  CLSPH_CHECK(e != NULL && next != NULL && done != NULL, CLSPH_E_NOMEM,
              "out of memory for %zu segments", n);
  for (size_t s = 0; s < n; ++s)
    for (int k = 0; k < 2; ++k) e[2 * s + (size_t)k] = (struct seg_end){segs->v[2 * s + k], s, k};
  qsort(e, 2 * n, sizeof *e, seg_end_cmp);
  for (size_t i = 0; i < 2 * n;) {
    size_t j = i;
    while (j < 2 * n && e[j].v == e[i].v) ++j;
    if (j - i == 2 && e[i].end != e[i + 1].end && e[i].s != e[i + 1].s) {
      const size_t s1 = e[i].end == 1 ? e[i].s : e[i + 1].s; /* ends here */
      const size_t s2 = e[i].end == 1 ? e[i + 1].s : e[i].s; /* starts here */
      const double *a = segs->a, *b = segs->b, *n1 = segs->normal + 2 * s1,
                   *n2 = segs->normal + 2 * s2;
      const double t1[2] = {b[2 * s1] - a[2 * s1], b[2 * s1 + 1] - a[2 * s1 + 1]};
      const double t2[2] = {b[2 * s2] - a[2 * s2], b[2 * s2 + 1] - a[2 * s2 + 1]};
      const int same_wall = segs->wall == NULL || segs->wall[s1] == segs->wall[s2];
      const int same_point =
          (real)b[2 * s1] == (real)a[2 * s2] && (real)b[2 * s1 + 1] == (real)a[2 * s2 + 1];
      const double nn = n1[0] * n2[0] + n1[1] * n2[1];
      const double cross = n1[0] * n2[1] - n1[1] * n2[0];
      if (same_wall && same_point && nn > 0.0 && fabs(cross) < 1e-12 &&
          t1[0] * t2[0] + t1[1] * t2[1] > 0.0) {
        joint[s1] |= 2u;
        joint[s2] |= 1u;
        next[s1] = s2;
        *count += 2;
      }
    }
    i = j;
  }
  /* each chain from its first segment (then the closed ones from any) */
  for (int pass = 0; pass < 2; ++pass)
    for (size_t s = 0; s < n; ++s) {
      if (done[s] || (pass == 0 && (joint[s] & 1u))) continue;
      for (size_t k = s; !done[k]; k = next[k]) {
        done[k] = 1;
        normal_out[2 * k] = normal_out[2 * s];
        normal_out[2 * k + 1] = normal_out[2 * s + 1];
        if (!(joint[k] & 2u)) break;
      }
    }
done:
  free(done);
  free(next);
  free(e);
  return st;
}

enum clsph_status usaw_walls_create(const struct dev *dev, cl_program prog,
                                    const struct usaw_segments *segs, const struct grid_spec *box,
                                    struct usaw_walls *out)
{
  enum clsph_status st = CLSPH_OK;
  struct usaw_walls w;
  real *buf = NULL;
  cl_uint *ids = NULL, *joint = NULL;
  double *normal = NULL;
  const cl_uint zero = 0;
  const size_t n = segs->n, vs = (size_t)(box->dim == 2 ? 2 : 4);
  memset(&w, 0, sizeof w);
  CLSPH_CHECK(box->dim == 2, CLSPH_E_UNSUPPORTED, "USAW walls are 2-D");
  buf = calloc(4 * vs * (n > 0 ? n : 1), sizeof *buf);
  CLSPH_CHECK(buf != NULL, CLSPH_E_NOMEM, "out of memory for %zu segments", n);
  double lmax = 0.0;
  for (size_t s = 0; s < n; ++s)
    lmax =
        fmax(lmax, hypot(segs->b[2 * s] - segs->a[2 * s], segs->b[2 * s + 1] - segs->a[2 * s + 1]));
  /* the segments' grid: a segment within the support of a particle has its midpoint within
   * support + length/2 of it */
  struct grid_spec gs = *box;
  gs.support = box->support + 0.5 * lmax;
  CLSPH_TRY(grid_create(dev, prog, &gs, n > 0 ? n : 1, &w.g));
  real *mid = buf, *a = buf + vs * n, *b = buf + 2 * vs * n, *nn = buf + 3 * vs * n;
  joint = calloc(n > 0 ? n : 1, sizeof *joint);
  normal = calloc(2 * (n > 0 ? n : 1), sizeof *normal);
  CLSPH_CHECK(joint != NULL && normal != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(find_joints(segs, joint, normal, &w.njoints));
  for (size_t s = 0; s < n; ++s) {
    for (size_t c = 0; c < 2; ++c) {
      a[vs * s + c] = (real)segs->a[2 * s + c];
      b[vs * s + c] = (real)segs->b[2 * s + c];
      nn[vs * s + c] = (real)normal[2 * s + c];
      mid[vs * s + c] = (real)(0.5 * (segs->a[2 * s + c] + segs->b[2 * s + c]));
    }
  }
  w.f_vnormal = -1;
  pset_init(&w.ps, n, n > 0 ? n : 1);
  CLSPH_TRY(pset_add(&w.ps, dev, "mid", vs * sizeof(real), mid, &w.f_mid));
  CLSPH_TRY(pset_add(&w.ps, dev, "a", vs * sizeof(real), a, &w.f_a));
  CLSPH_TRY(pset_add(&w.ps, dev, "b", vs * sizeof(real), b, &w.f_b));
  CLSPH_TRY(pset_add(&w.ps, dev, "n", vs * sizeof(real), nn, &w.f_n));
  ids = calloc(2 * (n > 0 ? n : 1), sizeof *ids);
  CLSPH_CHECK(ids != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t s = 0; segs->v != NULL && s < n; ++s) {
    ids[s] = (cl_uint)segs->v[2 * s];
    ids[n + s] = (cl_uint)segs->v[2 * s + 1];
  }
  CLSPH_TRY(pset_add(&w.ps, dev, "v1", sizeof(cl_uint), ids, &w.f_v1));
  CLSPH_TRY(pset_add(&w.ps, dev, "v2", sizeof(cl_uint), ids + n, &w.f_v2));
  for (size_t s = 0; s < n; ++s) ids[s] = (cl_uint)s; /* the order given, kept through the sort */
  CLSPH_TRY(pset_add(&w.ps, dev, "index", sizeof(cl_uint), ids, &w.f_index));
  CLSPH_TRY(pset_add(&w.ps, dev, "joint", sizeof(cl_uint), joint, &w.f_joint));
  /* the bits, a counter and the deepest crossing (as the sim's flags: usaw_walls_gamma may be
   * given this buffer) */
  const cl_uint zeros[3] = {0, 0, 0};
  CLSPH_TRY(kern_buffer(dev, sizeof zeros, zeros, &w.d_flags, "segment flags"));
  CLSPH_TRY(prog_kernel(prog, "usaw_gamma", &w.k_gamma));
  if (n > 0) {
    CLSPH_TRY(grid_sort(&w.g, dev, n, pset_mem(&w.ps, w.f_mid), NULL, w.d_flags));
    CLSPH_TRY(pset_reorder(&w.ps, &w.g, dev));
  } else {
    CLSPH_TRY(kern_fill(dev, w.g.d_start, &zero, sizeof zero, (w.g.ncells + 1) * sizeof zero));
  }
  *out = w;
  memset(&w, 0, sizeof w);
done:
  usaw_walls_destroy(&w);
  free(normal);
  free(joint);
  free(ids);
  free(buf);
  return st;
}

enum clsph_status usaw_walls_gamma(struct usaw_walls *w, const struct dev *dev, size_t n,
                                   cl_mem d_pos, cl_mem d_theta, cl_mem d_gamma,
                                   cl_mem d_grad_gamma, cl_mem d_flags)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint np = (cl_uint)n;
  cl_mem a = pset_mem(&w->ps, w->f_a), b = pset_mem(&w->ps, w->f_b), nn = pset_mem(&w->ps, w->f_n);
  cl_mem joint = pset_mem(&w->ps, w->f_joint);
  CLSPH_TRY(KERN_SET(w->k_gamma, KARG(np), KARG(w->g.geom), KARG(w->g.d_start), KARG(a), KARG(b),
                     KARG(nn), KARG(joint), KARG(d_pos), KARG(d_theta), KARG(d_gamma),
                     KARG(d_grad_gamma), KARG(d_flags)));
  if (w->cache_k > 0) {
    CLSPH_TRY(cache_reserve(w, dev, n));
    CLSPH_TRY(kern_set_at(w->k_gamma, 12, KARG(w->d_cache_cnt)));
    CLSPH_TRY(kern_set_at(w->k_gamma, 13, KARG(w->d_cache_list)));
    CLSPH_TRY(kern_set_at(w->k_gamma, 14, KARG(w->d_cache_gg)));
  }
  CLSPH_TRY(kern_launch(dev, w->k_gamma, n, NULL));
done:
  return st;
}

/* The image of x nearest c on the periodic axes of box. */
static void nearest_image(const struct grid_spec *box, const double c[2], double x[2])
{
  for (int a = 0; a < 2; ++a)
    if (box->periodic[a]) {
      const double len = box->hi[a] - box->lo[a];
      x[a] -= len * round((x[a] - c[a]) / len);
    }
}

/* What usaw_walls_turn needs of the turning walls: the geometry at t = 0 (segment ends and vertex
 * positions as the images nearest their wall's centre), which wall each turns with, the kernels. */
static enum clsph_status turning_create(const struct dev *dev, cl_program prog,
                                        const struct geom *geo, const double *seg_normal,
                                        const struct scene *sc, const struct grid_spec *box,
                                        struct usaw_walls *w)
{
  enum clsph_status st = CLSPH_OK;
  cl_int *turn = NULL;
  real *x0 = NULL, *rot = NULL;
  const size_t ns = geo->nseg > 0 ? geo->nseg : 1, np = geo->n > 0 ? geo->n : 1;
  turn = calloc(ns > np ? ns : np, sizeof *turn);
  x0 = calloc(6 * (ns > np ? ns : np), sizeof *x0);
  rot = calloc(3 * (size_t)(sc->nwalls > 0 ? sc->nwalls : 1), sizeof *rot);
  CLSPH_CHECK(turn != NULL && x0 != NULL && rot != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t s = 0; s < geo->nseg; ++s) {
    const int wi = geo->seg_wall[s];
    const struct scene_wall *wl = &sc->walls[wi];
    turn[s] = scene_wall_turns(wl) ? wi : -1;
    if (turn[s] < 0) continue;
    w->turning = 1;
    for (int e = 0; e < 2; ++e) {
      double x[2] = {geo->x[2 * geo->seg_v[2 * s + e]], geo->x[2 * geo->seg_v[2 * s + e] + 1]};
      nearest_image(box, wl->centre, x);
      x0[6 * s + 2 * e] = (real)x[0];
      x0[6 * s + 2 * e + 1] = (real)x[1];
    }
    x0[6 * s + 4] = (real)seg_normal[2 * s];
    x0[6 * s + 5] = (real)seg_normal[2 * s + 1];
  }
  if (!w->turning) goto done;
  CLSPH_TRY(kern_buffer(dev, ns * sizeof *turn, turn, &w->d_seg_turn, "turning segments"));
  CLSPH_TRY(kern_buffer(dev, 6 * ns * sizeof *x0, x0, &w->d_seg0, "turning segments at t = 0"));
  memset(x0, 0, 6 * (ns > np ? ns : np) * sizeof *x0); /* now 4 per particle: x, normal */
  for (size_t i = 0; i < geo->n; ++i) {
    turn[i] = -1;
    if (geo->kind[i] != KIND_VERTEX || geo->group[i] < 0) continue;
    const struct scene_wall *wl = &sc->walls[geo->group[i]];
    if (!scene_wall_turns(wl)) continue;
    turn[i] = geo->group[i];
    double x[2] = {geo->x[2 * i], geo->x[2 * i + 1]};
    nearest_image(box, wl->centre, x);
    x0[4 * i] = (real)x[0];
    x0[4 * i + 1] = (real)x[1];
    x0[4 * i + 2] = (real)geo->normal[2 * i];
    x0[4 * i + 3] = (real)geo->normal[2 * i + 1];
  }
  CLSPH_TRY(kern_buffer(dev, np * sizeof *turn, turn, &w->d_vert_turn, "turning vertices"));
  CLSPH_TRY(kern_buffer(dev, 4 * np * sizeof *x0, x0, &w->d_vert0, "turning vertices at t = 0"));
  for (int k = 0; k < sc->nwalls; ++k) { /* centre and ω of each wall (motion.cl) */
    rot[3 * k] = (real)sc->walls[k].centre[0];
    rot[3 * k + 1] = (real)sc->walls[k].centre[1];
    rot[3 * k + 2] = (real)sc->walls[k].omega;
  }
  CLSPH_TRY(kern_buffer(dev, 3 * (size_t)(sc->nwalls > 0 ? sc->nwalls : 1) * sizeof *rot, rot,
                        &w->d_rot, "wall rotations"));
  CLSPH_TRY(prog_kernel(prog, "usaw_turn_vertices", &w->k_turn_vertices));
  CLSPH_TRY(prog_kernel(prog, "usaw_turn_segments", &w->k_turn_segments));
  w->t_now = 0.0;
done:
  free(rot);
  free(x0);
  free(turn);
  return st;
}

enum clsph_status usaw_walls_from_geom(const struct dev *dev, cl_program prog,
                                       const struct geom *geo, const struct scene *sc,
                                       const struct grid_spec *box, struct usaw_walls *out)
{
  enum clsph_status st = CLSPH_OK;
  double *ab = calloc(4 * (geo->nseg + 1), sizeof *ab), *normal = NULL;
  cl_uint *joint = NULL;
  size_t njoints = 0;
  CLSPH_CHECK(ab != NULL, CLSPH_E_NOMEM, "out of memory for %zu segments", geo->nseg);
  /* The ends are the vertex particles' positions. On a periodic axis those are wrapped into
   * [lo, hi), so a segment that crosses the boundary takes the image of its second end nearest
   * the first, and both ends move by a period where needed to put the midpoint (which bins the
   * segment) in [lo, hi); the kernels add the image shift of the midpoint's cell to both ends. */
  for (size_t s = 0; s < geo->nseg; ++s)
    for (size_t c = 0; c < 2; ++c) {
      double xa = geo->x[2 * geo->seg_v[2 * s] + c], xb = geo->x[2 * geo->seg_v[2 * s + 1] + c];
      if (box->periodic[c]) {
        const double len = box->hi[c] - box->lo[c];
        xb -= len * round((xb - xa) / len);
        const double shift = len * floor((0.5 * (xa + xb) - box->lo[c]) / len);
        xa -= shift;
        xb -= shift;
      }
      ab[2 * s + c] = xa;
      ab[2 * geo->nseg + 2 * s + c] = xb;
    }
  struct usaw_segments segs = {geo->nseg,       ab,         ab + 2 * geo->nseg,
                               geo->seg_normal, geo->seg_v, geo->seg_wall};
  joint = calloc(geo->nseg + 1, sizeof *joint);
  normal = calloc(2 * (geo->nseg + 1), sizeof *normal);
  CLSPH_CHECK(joint != NULL && normal != NULL, CLSPH_E_NOMEM, "out of memory for %zu segments",
              geo->nseg);
  /* the turning walls' segments at t = 0 take the joined chains' normals too */
  CLSPH_TRY(find_joints(&segs, joint, normal, &njoints));
  CLSPH_TRY(usaw_walls_create(dev, prog, &segs, box, out));
  st = turning_create(dev, prog, geo, normal, sc, box, out);
  if (st != CLSPH_OK) usaw_walls_destroy(out);
done:
  free(normal);
  free(joint);
  free(ab);
  return st;
}

enum clsph_status usaw_walls_turn(struct usaw_walls *w, struct sim *sim, double t)
{
  enum clsph_status st = CLSPH_OK;
  if (!w->turning || t == w->t_now) return CLSPH_OK;
  const real rt = (real)t;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n, ns = (cl_uint)w->ps.n;
  cl_mem id = pset_mem(ps, sim->f_id), pos = pset_mem(ps, sim->f_pos);
  cl_mem vel = pset_mem(ps, sim->f_vel);
  const cl_uint has_normal = w->f_vnormal >= 0;
  cl_mem nrm = has_normal ? pset_mem(ps, w->f_vnormal) : w->d_vert0;
  CLSPH_TRY(KERN_SET(w->k_turn_vertices, KARG(n), KARG(sim->grid.geom), KARG(id),
                     KARG(w->d_vert_turn), KARG(w->d_vert0), KARG(w->d_rot), KARG(rt), KARG(pos),
                     KARG(vel), KARG(has_normal), KARG(nrm)));
  CLSPH_TRY(kern_launch(sim->dev, w->k_turn_vertices, ps->n, NULL));
  cl_mem index = pset_mem(&w->ps, w->f_index), a = pset_mem(&w->ps, w->f_a);
  cl_mem b = pset_mem(&w->ps, w->f_b), nn = pset_mem(&w->ps, w->f_n);
  cl_mem mid = pset_mem(&w->ps, w->f_mid);
  CLSPH_TRY(KERN_SET(w->k_turn_segments, KARG(ns), KARG(w->g.geom), KARG(index),
                     KARG(w->d_seg_turn), KARG(w->d_seg0), KARG(w->d_rot), KARG(rt), KARG(a),
                     KARG(b), KARG(nn), KARG(mid)));
  CLSPH_TRY(kern_launch(sim->dev, w->k_turn_segments, w->ps.n, NULL));
  CLSPH_TRY(grid_sort(&w->g, sim->dev, w->ps.n, mid, NULL, w->d_flags));
  CLSPH_TRY(pset_reorder(&w->ps, &w->g, sim->dev));
  w->t_now = t;
done:
  return st;
}

enum clsph_status usaw_wall_force(const struct dev *dev, const struct geom *geo,
                                  const struct scene *sc, size_t n, cl_mem d_p, cl_mem d_strain,
                                  cl_mem d_inv, double mu, double t, const char *group,
                                  struct wall_force *f)
{
  enum clsph_status st = CLSPH_OK;
  real *p = malloc(4 * n * sizeof *p);
  cl_uint *inv = malloc(geo->n * sizeof *inv); /* by original index: the walls' come last */
  CLSPH_CHECK(p != NULL && inv != NULL, CLSPH_E_NOMEM, "out of memory");
  real *e = p + n; /* strain: xx, xy, yy per particle */
  CLSPH_TRY(kern_read(dev, d_p, n * sizeof *p, p));
  CLSPH_TRY(kern_read(dev, d_strain, 3 * n * sizeof *e, e));
  CLSPH_TRY(kern_read(dev, d_inv, geo->n * sizeof *inv, inv));
  memset(f, 0, sizeof *f);
  double c[2];
  scene_group_centre(sc, group, c);
  for (size_t s = 0; s < geo->nseg; ++s) {
    const struct scene_wall *wl = &sc->walls[geo->seg_wall[s]];
    if (strcmp(wl->group, group) != 0) continue;
    const size_t i1 = geo->seg_v[2 * s], i2 = geo->seg_v[2 * s + 1];
    const size_t v1 = inv[i1], v2 = inv[i2];
    double nrm[2], m[2];
    scene_wall_turn(wl, t, geo->seg_normal + 2 * s, 1, nrm);
    /* the midpoint at t = 0 (the ends' images nearest each other), where it stands at t */
    double m0[2] = {geo->x[2 * i1], geo->x[2 * i1 + 1]},
           x2[2] = {geo->x[2 * i2], geo->x[2 * i2 + 1]};
    for (int k = 0; k < 2; ++k) {
      if (sc->periodic[k]) {
        const double len = sc->hi[k] - sc->lo[k];
        x2[k] -= len * round((x2[k] - m0[k]) / len);
      }
      m0[k] = 0.5 * (m0[k] + x2[k]);
    }
    scene_wall_turn(wl, t, m0, 0, m);
    for (int k = 0; k < 2; ++k)
      if (sc->periodic[k]) { /* the image nearest the centre */
        const double len = sc->hi[k] - sc->lo[k];
        m[k] -= len * round((m[k] - c[k]) / len);
      }
    const double len = geo->seg_len[s];
    const double ps = 0.5 * ((double)p[v1] + (double)p[v2]);
    double es[3];
    for (int k = 0; k < 3; ++k) es[k] = 0.5 * ((double)e[3 * v1 + k] + (double)e[3 * v2 + k]);
    const double fp[2] = {-ps * nrm[0] * len, -ps * nrm[1] * len};
    const double fv[2] = {mu * (es[0] * nrm[0] + es[1] * nrm[1]) * len,
                          mu * (es[1] * nrm[0] + es[2] * nrm[1]) * len};
    for (int k = 0; k < 2; ++k) {
      f->pressure[k] += fp[k];
      f->viscous[k] += fv[k];
    }
    f->torque += (m[0] - c[0]) * (fp[1] + fv[1]) - (m[1] - c[1]) * (fp[0] + fv[0]);
  }
done:
  free(inv);
  free(p);
  return st;
}

enum clsph_status usaw_kernel_prefix(struct sim *sim, struct usaw_walls *w, cl_mem gam, cl_kernel k,
                                     cl_uint *next)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  cl_mem pos = pset_mem(ps, sim->f_pos), vol = pset_mem(ps, sim->f_vol);
  cl_mem kind = pset_mem(ps, sim->f_kind);
  cl_mem sa = pset_mem(&w->ps, w->f_a), sb = pset_mem(&w->ps, w->f_b);
  cl_mem sn = pset_mem(&w->ps, w->f_n), v1 = pset_mem(&w->ps, w->f_v1);
  cl_mem v2 = pset_mem(&w->ps, w->f_v2);
  CLSPH_TRY(KERN_SET(k, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start), KARG(pos),
                     KARG(vol), KARG(kind), KARG(gam), KARG(w->g.geom), KARG(w->g.d_start),
                     KARG(sa), KARG(sb), KARG(sn), KARG(v1), KARG(v2), KARG(sim->d_inv)));
  *next = 15;
  if (w->cache_k > 0) { /* USAW_CACHE_ARGS */
    CLSPH_TRY(cache_reserve(w, sim->dev, n));
    CLSPH_TRY(kern_set_at(k, (*next)++, KARG(w->d_cache_cnt)));
    CLSPH_TRY(kern_set_at(k, (*next)++, KARG(w->d_cache_list)));
    CLSPH_TRY(kern_set_at(k, (*next)++, KARG(w->d_cache_gg)));
  }
done:
  return st;
}

void usaw_walls_destroy(struct usaw_walls *w)
{
  cl_kernel *ks[] = {&w->k_gamma, &w->k_turn_vertices, &w->k_turn_segments};
  for (size_t k = 0; k < sizeof ks / sizeof *ks; ++k) {
    if (*ks[k] != NULL) clReleaseKernel(*ks[k]);
    *ks[k] = NULL;
  }
  cl_mem *ms[] = {&w->d_rot,   &w->d_seg_turn,  &w->d_seg0,       &w->d_vert_turn,
                  &w->d_vert0, &w->d_cache_cnt, &w->d_cache_list, &w->d_cache_gg};
  for (size_t k = 0; k < sizeof ms / sizeof *ms; ++k) kern_release(ms[k]);
  w->turning = 0;
  kern_release(&w->d_flags);
  pset_destroy(&w->ps);
  grid_destroy(&w->g);
}
