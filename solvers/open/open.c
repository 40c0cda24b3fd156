/* open.c: entry and exit sections on the device (see open.h; kernels/common/open.cl). */
#include "open.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../scheme.h"
#include "clsph_config.h"
#include "geometry.h"
#include "kern.h"
#include "sim.h"

enum { OPEN_SEC = 11 }; /* reals per section in the table (open.cl) */

enum clsph_status open_define(const struct sim *sim, struct prog_opts *o)
{
  return prog_opts_define_int(o, "OPEN_SECTIONS", sim->scene->nsections > 0);
}

double open_speed(const struct scene *sc)
{
  double u = 0.0;
  for (int k = 0; k < sc->nsections; ++k) u = fmax(u, fabs(sc->sections[k].velocity));
  return u;
}

/* The section table (open.cl's layout) and its checks. */
static enum clsph_status upload_table(struct sim *sim, struct open_sections *o)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *sc = sim->scene;
  real *tab = calloc((size_t)sc->nsections * OPEN_SEC, sizeof *tab);
  CLSPH_CHECK(tab != NULL, CLSPH_E_NOMEM, "%s: out of memory", sim->scheme->name);
  for (int k = 0; k < sc->nsections; ++k) {
    const struct scene_section *c = &sc->sections[k];
    const double len = hypot(c->b[0] - c->a[0], c->b[1] - c->a[1]);
    const int in = c->kind == SCENE_INFLOW;
    o->ninflow += in;
    o->noutflow += !in;
    /* the layers must cover the support of the fluid next to the section (3 h, h = 1.2 dr) */
    CLSPH_CHECK(c->layers * sc->dr >= sim->sm.support - 0.75 * sc->dr, CLSPH_E_INPUT,
                "%s:%d: %s '%s': %d layers do not cover the smoothing support of the fluid next "
                "to it (%.3g dr); give layers = %d or more (the paper's 3, sec 3.3.2)",
                sc->case_path, c->line, in ? "inflow" : "outflow", c->name, c->layers,
                sim->sm.support / sc->dr, (int)ceil(sim->sm.support / sc->dr - 0.75));
    real *t = tab + (size_t)k * OPEN_SEC;
    t[0] = (real)c->a[0];
    t[1] = (real)c->a[1];
    t[2] = (real)((c->b[0] - c->a[0]) / len);
    t[3] = (real)((c->b[1] - c->a[1]) / len);
    t[4] = (real)len;
    t[5] = (real)(c->layers * sc->dr);
    t[6] = (real)c->velocity;
    t[7] = (real)(in ? 1 : 2);
    /* (a table's entry keeps the velocities the geometry gave its particles: no ramp) */
    t[8] = (real)(c->profile == SCENE_UNIFORM || c->profile == SCENE_TABLE ? 1
                  : c->profile == SCENE_PARABOLIC                          ? 2
                                                                           : 0);
    t[9] = (real)c->ramp;
    /* where an exit's particles wait for an entry: the park of geometry.c (struct geom_park), or
     * 0: where they stop, just behind the last layer */
    if (!in && sim->park.fraction > 0.0) t[10] = (real)(c->layers * sc->dr + sim->park.behind);
  }
  /* an entry feeds on what the exits give back (recycling), and the other way round */
  CLSPH_CHECK(o->ninflow > 0 && o->noutflow > 0, CLSPH_E_INPUT,
              "%s: %s needs an inflow and an outflow section together (the scene "
              "has %d inflow and %d outflow): the particles leaving through an exit are those "
              "entering through an entry",
              sc->case_path, sim->scheme->name, o->ninflow, o->noutflow);
  CLSPH_TRY(kern_buffer(sim->dev, (size_t)sc->nsections * OPEN_SEC * sizeof *tab, tab, &o->d_sec,
                        "sections"));
done:
  free(tab);
  return st;
}

enum clsph_status open_create(struct sim *sim, int f_u, struct open_sections *out)
{
  enum clsph_status st = CLSPH_OK;
  struct open_sections o = {0};
  const struct geom *geo = &sim->geom;
  struct pset *ps = &sim->ps;
  cl_uint *u = NULL;
  real *v = NULL;
  *out = o;
  if (sim->scene->nsections == 0) goto done;
  o.nsec = (cl_uint)sim->scene->nsections;
  CLSPH_TRY(upload_table(sim, &o));
  /* fields: the section of each layer particle, its progenitor and its row's first fluid */
  u = calloc(geo->n, sizeof *u);
  CLSPH_CHECK(u != NULL, CLSPH_E_NOMEM, "%s: out of memory", sim->scheme->name);
  for (size_t i = 0; i < geo->n; ++i)
    u[i] =
        geo->kind[i] == KIND_INFLOW || geo->kind[i] == KIND_OUTFLOW || geo->kind[i] == KIND_PARKED
            ? (cl_uint)geo->group[i]
            : 0xffffffffu;
  CLSPH_TRY(pset_add(ps, sim->dev, "section", sizeof(cl_uint), u, &o.f_section));
  pset_describe(ps, o.f_section, PF_UINT, 0, 0);
  CLSPH_TRY(pset_add(ps, sim->dev, "vel_src", sizeof(cl_uint), NULL, &o.f_src));
  pset_describe(ps, o.f_src, PF_UINT, 0, 0);
  CLSPH_TRY(pset_add(ps, sim->dev, "p_near", sizeof(cl_uint), NULL, &o.f_near));
  pset_describe(ps, o.f_near, PF_UINT, 0, 0);
  o.f_u = f_u;
  if (f_u < 0) { /* the layers' velocity: the geometry's (u_in, a prescribed exit profile) */
    v = calloc(2 * geo->n, sizeof *v);
    CLSPH_CHECK(v != NULL, CLSPH_E_NOMEM, "%s: out of memory", sim->scheme->name);
    for (size_t i = 0; i < 2 * geo->n; ++i) v[i] = (real)geo->v[i];
    CLSPH_TRY(pset_add(ps, sim->dev, "open_u", 2 * sizeof(real), v, &o.f_u));
    pset_describe(ps, o.f_u, PF_REAL, 0, 0);
  }
  /* recycling: a role per particle, the pairs, the counts */
  CLSPH_TRY(kern_buffer(sim->dev, ps->cap * sizeof(cl_uint), NULL, &o.d_role, "recycle roles"));
  CLSPH_TRY(kern_buffer(sim->dev, ps->cap * sizeof(cl_uint), NULL, &o.d_list, "recycle list"));
  const cl_uint zeros[5] = {0, 0, 0, 0, 0};
  CLSPH_TRY(kern_buffer(sim->dev, sizeof zeros, zeros, &o.d_count, "recycle count"));
  const size_t groups = sim_reduce_groups(ps->cap);
  CLSPH_TRY(kern_buffer(sim->dev, o.nsec * sizeof(real), NULL, &o.d_exitval, "exit values"));
  CLSPH_TRY(
      kern_buffer(sim->dev, groups * o.nsec * 2 * sizeof(real), NULL, &o.d_partial, "exit sums"));
  o.h_exitval = calloc(o.nsec, sizeof *o.h_exitval);
  o.h_partial = calloc(groups * o.nsec * 2, sizeof *o.h_partial);
  CLSPH_CHECK(o.h_exitval != NULL && o.h_partial != NULL, CLSPH_E_NOMEM, "%s: out of memory",
              sim->scheme->name);
  const struct {
    cl_kernel *k;
    const char *name;
  } ks[] = {{&o.k_velocity, "open_layer_velocity"},
            {&o.k_scalar, "open_layer_scalar"},
            {&o.k_move, "open_move"},
            {&o.k_classify, "open_classify"},
            {&o.k_recycle, "open_recycle"},
            {&o.k_copy_real, "open_copy_real"},
            {&o.k_copy_realv, "open_copy_realv"},
            {&o.k_exit_sums, "open_exit_sums"}};
  for (size_t k = 0; k < sizeof ks / sizeof *ks; ++k)
    CLSPH_TRY(prog_kernel(sim->prog, ks[k].name, ks[k].k));
  *out = o;
  memset(&o, 0, sizeof o); /* the caller owns it now */
done:
  open_destroy(&o);
  free(v);
  free(u);
  return st;
}

enum clsph_status open_layer_velocity(struct open_sections *o, struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  const real dr = (real)sim->scene->dr, time = (real)sim->time;
  if (o->nsec == 0) goto done;
  cl_mem pos = pset_mem(ps, sim->f_pos), kind = pset_mem(ps, sim->f_kind);
  cl_mem section = pset_mem(ps, o->f_section), vel = pset_mem(ps, sim->f_vel);
  cl_mem ul = pset_mem(ps, o->f_u), src = pset_mem(ps, o->f_src), near = pset_mem(ps, o->f_near);
  CLSPH_TRY(KERN_SET(o->k_velocity, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start),
                     KARG(pos), KARG(kind), KARG(section), KARG(o->d_sec), KARG(dr), KARG(time),
                     KARG(vel), KARG(ul), KARG(src), KARG(near), KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, o->k_velocity, n, NULL));
done:
  return st;
}

/* the layers' scalar with the exits' values in h_exitval (copy_exit: from the fluid instead) */
static enum clsph_status layer_scalar(struct open_sections *o, struct sim *sim, cl_mem a,
                                      cl_uint copy_exit)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  if (!copy_exit)
    CLSPH_TRY(kern_write(sim->dev, o->d_exitval, o->nsec * sizeof(real), o->h_exitval));
  cl_mem kind = pset_mem(ps, sim->f_kind), near = pset_mem(ps, o->f_near);
  cl_mem section = pset_mem(ps, o->f_section);
  CLSPH_TRY(KERN_SET(o->k_scalar, KARG(n), KARG(kind), KARG(near), KARG(section), KARG(copy_exit),
                     KARG(o->d_exitval), KARG(a)));
  CLSPH_TRY(kern_launch(sim->dev, o->k_scalar, n, NULL));
done:
  return st;
}

enum clsph_status open_layer_scalar(struct open_sections *o, struct sim *sim, cl_mem a,
                                    const double *exit_value)
{
  if (o->nsec == 0) return CLSPH_OK;
  for (cl_uint k = 0; k < o->nsec; ++k)
    o->h_exitval[k] = exit_value != NULL ? (real)*exit_value : (real)0;
  return layer_scalar(o, sim, a, exit_value == NULL);
}

enum clsph_status open_layer_scalar_exits(struct open_sections *o, struct sim *sim, cl_mem a,
                                          const double *exit_value)
{
  if (o->nsec == 0) return CLSPH_OK;
  for (cl_uint k = 0; k < o->nsec; ++k) o->h_exitval[k] = (real)exit_value[k];
  return layer_scalar(o, sim, a, 0u);
}

enum clsph_status open_layer_scalar_prescribed(struct open_sections *o, struct sim *sim, cl_mem a)
{
  if (o->nsec == 0) return CLSPH_OK;
  return layer_scalar(o, sim, a, 2u);
}

enum clsph_status open_exit_speed(struct open_sections *o, struct sim *sim, double *speed)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  const real dr = (real)sim->scene->dr;
  const size_t groups = sim_reduce_groups(ps->n);
  if (o->nsec == 0) goto done;
  cl_mem pos = pset_mem(ps, sim->f_pos), vel = pset_mem(ps, sim->f_vel);
  cl_mem kind = pset_mem(ps, sim->f_kind);
  for (cl_uint k = 0; k < o->nsec; ++k) {
    speed[k] = 0.0;
    if (sim->scene->sections[k].kind != SCENE_OUTFLOW) continue;
    CLSPH_TRY(KERN_SET(o->k_exit_sums, KARG(n), KARG(pos), KARG(vel), KARG(kind), KARG(o->d_sec),
                       KARG(k), KARG(dr), KARG(o->d_partial)));
    CLSPH_TRY(kern_launch_wg(sim->dev, o->k_exit_sums, groups * 64, 64, NULL));
    CLSPH_TRY(kern_read(sim->dev, o->d_partial, groups * 2 * sizeof(real), o->h_partial));
    double u = 0.0, m = 0.0;
    for (size_t g = 0; g < groups; ++g) {
      u += (double)o->h_partial[g];
      m += (double)o->h_partial[groups + g];
    }
    speed[k] = m > 0.0 ? u / m : 0.0;
  }
done:
  return st;
}

/* the rise of a section's prescribed speed at time t (kernels/common/open.cl) */
static double ramp_factor(const struct scene_section *c, double t)
{
  if (t < 0.0) return 0.0; /* before the start (open_natural_flux at a delayed time) */
  return t < c->ramp ? 0.5 * (1.0 - cos(acos(-1.0) * t / c->ramp)) : 1.0;
}

/* the flux of a prescribed profile per unit depth: U len (uniform), ⅔ U len (parabolic), the
 * table's mean times len */
static double section_flux(const struct scene_section *c, double t)
{
  const double len = hypot(c->b[0] - c->a[0], c->b[1] - c->a[1]);
  const double shape = c->profile == SCENE_PARABOLIC ? 2.0 / 3.0
                       : c->profile == SCENE_TABLE   ? c->mean / c->velocity
                                                     : 1.0;
  return ramp_factor(c, t) * c->velocity * shape * len;
}

double open_natural_flux(const struct scene *sc, double t)
{
  double q = 0.0;
  for (int k = 0; k < sc->nsections; ++k) {
    const struct scene_section *c = &sc->sections[k];
    if (c->kind == SCENE_INFLOW)
      q += section_flux(c, t);
    else if (c->profile != 0)
      q -= section_flux(c, t);
  }
  return q;
}

double open_initial_outflow(const struct sim *sim)
{
  const struct scene *sc = sim->scene;
  const struct geom *geo = &sim->geom;
  double sum = 0.0, width = 0.0;
  for (int k = 0; k < sc->nsections; ++k) {
    const struct scene_section *c = &sc->sections[k];
    if (c->kind != SCENE_OUTFLOW || c->profile != 0) continue;
    const double len = hypot(c->b[0] - c->a[0], c->b[1] - c->a[1]);
    const double t[2] = {(c->b[0] - c->a[0]) / len, (c->b[1] - c->a[1]) / len},
                 n[2] = {-t[1], t[0]};
    double u = 0.0;
    size_t m = 0;
    for (size_t i = 0; i < geo->nfluid; ++i) {
      const double d[2] = {geo->x[2 * i] - c->a[0], geo->x[2 * i + 1] - c->a[1]};
      const double along = d[0] * t[0] + d[1] * t[1], h = d[0] * n[0] + d[1] * n[1];
      if (h < 0.0 || h >= sc->dr || along < 0.0 || along > len) continue;
      u -= geo->v[2 * i] * n[0] + geo->v[2 * i + 1] * n[1]; /* out of the fluid: along −n */
      ++m;
    }
    if (m > 0) sum += len * u / (double)m;
    width += len;
  }
  return width > 0.0 ? sum / width : 0.0;
}

double open_transit(const struct scene *sc)
{
  double d = HUGE_VAL;
  for (int k = 0; k < sc->nsections; ++k) {
    const struct scene_section *in = &sc->sections[k];
    if (in->kind != SCENE_INFLOW) continue;
    for (int m = 0; m < sc->nsections; ++m) {
      const struct scene_section *out = &sc->sections[m];
      if (out->kind != SCENE_OUTFLOW || out->profile != 0) continue;
      d = fmin(d, 0.5 * hypot(out->a[0] + out->b[0] - in->a[0] - in->b[0],
                              out->a[1] + out->b[1] - in->a[1] - in->b[1]));
    }
  }
  return isfinite(d) ? d : 0.0;
}

double open_natural_width(const struct scene *sc)
{
  double w = 0.0;
  for (int k = 0; k < sc->nsections; ++k) {
    const struct scene_section *c = &sc->sections[k];
    if (c->kind == SCENE_OUTFLOW && c->profile == 0)
      w += hypot(c->b[0] - c->a[0], c->b[1] - c->a[1]);
  }
  return w;
}

enum clsph_status open_move(struct open_sections *o, struct sim *sim, double dt)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  const real rdt = (real)dt;
  if (o->nsec == 0) goto done;
  cl_mem kind = pset_mem(ps, sim->f_kind), vel = pset_mem(ps, sim->f_vel);
  cl_mem pos = pset_mem(ps, sim->f_pos);
  CLSPH_TRY(KERN_SET(o->k_move, KARG(n), KARG(kind), KARG(vel), KARG(rdt), KARG(pos),
                     KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, o->k_move, n, NULL));
done:
  return st;
}

enum clsph_status open_recycle(struct open_sections *o, struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  const real tol = (real)(1e-6 * sim->scene->dr);
  cl_uint count[5];
  if (o->nsec == 0) goto done;
  cl_mem pos = pset_mem(ps, sim->f_pos), kind = pset_mem(ps, sim->f_kind);
  cl_mem section = pset_mem(ps, o->f_section), vel = pset_mem(ps, sim->f_vel);
  cl_mem ul = pset_mem(ps, o->f_u);
  CLSPH_TRY(KERN_SET(o->k_classify, KARG(n), KARG(pos), KARG(kind), KARG(section), KARG(o->d_sec),
                     KARG(o->nsec), KARG(tol), KARG(o->d_role)));
  CLSPH_TRY(kern_launch(sim->dev, o->k_classify, n, NULL));
  CLSPH_TRY(KERN_SET(o->k_recycle, KARG(n), KARG(o->d_role), KARG(o->d_list), KARG(o->d_sec),
                     KARG(pos), KARG(kind), KARG(section), KARG(vel), KARG(ul), KARG(o->d_count)));
  CLSPH_TRY(kern_launch(sim->dev, o->k_recycle, 1, NULL));
  CLSPH_TRY(kern_read(sim->dev, o->d_count, sizeof count, count));
  o->used = count[3];
  o->off = count[4];
  sim->open_waiting = (long)count[1];
  if (sim->open_waiting > sim->open_waiting_max) sim->open_waiting_max = sim->open_waiting;
done:
  return st;
}

enum clsph_status open_recycle_copy(struct open_sections *o, struct sim *sim, int field)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  if (o->nsec == 0 || o->used == 0) goto done;
  const size_t elem = ps->f[field].elem;
  CLSPH_CHECK(elem == sizeof(real) || elem == 2 * sizeof(real), CLSPH_E_UNSUPPORTED,
              "open_recycle_copy: field '%s' is neither reals nor 2-D vectors of reals",
              ps->f[field].name);
  cl_kernel k = elem == sizeof(real) ? o->k_copy_real : o->k_copy_realv;
  cl_mem a = pset_mem(ps, field);
  CLSPH_TRY(KERN_SET(k, KARG(o->used), KARG(o->off), KARG(o->d_list), KARG(a)));
  CLSPH_TRY(kern_launch(sim->dev, k, o->used, NULL));
done:
  return st;
}

void open_destroy(struct open_sections *o)
{
  cl_kernel ks[] = {o->k_velocity, o->k_scalar,    o->k_move,       o->k_classify,
                    o->k_recycle,  o->k_copy_real, o->k_copy_realv, o->k_exit_sums};
  for (size_t k = 0; k < sizeof ks / sizeof *ks; ++k)
    if (ks[k] != NULL) clReleaseKernel(ks[k]);
  cl_mem *bufs[] = {&o->d_sec, &o->d_role, &o->d_list, &o->d_count, &o->d_exitval, &o->d_partial};
  for (size_t k = 0; k < sizeof bufs / sizeof *bufs; ++k) kern_release(bufs[k]);
  free(o->h_exitval);
  free(o->h_partial);
  memset(o, 0, sizeof *o);
}
