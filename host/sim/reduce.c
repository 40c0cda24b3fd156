/* reduce.c: reductions over the particles on the device, finished on the host in double (a few
 * dozen partial results per reduction, kernels/common/reduce.cl), and interpolation at points
 * (kernels/common/probe.cl). */
#include <math.h>
#include <stdlib.h>

#include "kern.h"
#include "scheme.h"
#include "sim.h"

enum clsph_status sim_count_queued(struct sim *sim, cl_mem d_field, real *part, size_t *groups)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint n = (cl_uint)sim->ps.n;
  *groups = sim_reduce_groups(sim->ps.n);
  CLSPH_TRY(KERN_SET(sim->k_count, KARG(n), KARG(d_field), KARG(sim->d_partial)));
  CLSPH_TRY(kern_launch_wg(sim->dev, sim->k_count, *groups * 64, 64, NULL));
  CLSPH_TRY(kern_read_nb(sim->dev, sim->d_partial, 0, *groups * sizeof *part, part));
done:
  return st;
}

enum clsph_status sim_count(struct sim *sim, cl_mem d_field, double *count)
{
  enum clsph_status st = CLSPH_OK;
  real *part = NULL;
  cl_uint n = (cl_uint)sim->ps.n;
  size_t groups = sim_reduce_groups(sim->ps.n);
  part = malloc(groups * sizeof *part);
  CLSPH_CHECK(part != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(KERN_SET(sim->k_count, KARG(n), KARG(d_field), KARG(sim->d_partial)));
  CLSPH_TRY(kern_launch_wg(sim->dev, sim->k_count, groups * 64, 64, NULL));
  CLSPH_TRY(kern_read(sim->dev, sim->d_partial, groups * sizeof *part, part));
  double c = 0.0;
  for (size_t g = 0; g < groups; ++g) c += (double)part[g];
  *count = c;
done:
  free(part);
  return st;
}

enum clsph_status sim_slice_velocity(struct sim *sim, double x0, double x1, double *mean,
                                     double *count)
{
  enum clsph_status st = CLSPH_OK;
  real *part = NULL;
  const struct scene *s = sim->scene;
  cl_uint n = (cl_uint)sim->ps.n;
  size_t groups = sim_reduce_groups(sim->ps.n);
  const real rx0 = (real)x0, width = (real)(x1 - x0);
  const real period = (real)(s->periodic[0] ? s->hi[0] - s->lo[0] : 0.0);
  cl_mem pos = pset_mem(&sim->ps, sim->f_pos), vel = pset_mem(&sim->ps, sim->f_vel);
  cl_mem kind = pset_mem(&sim->ps, sim->f_kind);
  part = malloc(2 * groups * sizeof *part);
  CLSPH_CHECK(part != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(KERN_SET(sim->k_slice, KARG(n), KARG(pos), KARG(vel), KARG(kind), KARG(rx0),
                     KARG(width), KARG(period), KARG(sim->d_partial)));
  CLSPH_TRY(kern_launch_wg(sim->dev, sim->k_slice, groups * 64, 64, NULL));
  CLSPH_TRY(kern_read(sim->dev, sim->d_partial, 2 * groups * sizeof *part, part));
  double u = 0.0, c = 0.0;
  for (size_t g = 0; g < groups; ++g) {
    u += (double)part[g];
    c += (double)part[groups + g];
  }
  *mean = c > 0.0 ? u / c : 0.0;
  *count = c;
done:
  free(part);
  return st;
}

enum clsph_status sim_max_speed(struct sim *sim, int kind, double *vmax)
{
  if (sim->speed_ready && kind == sim->speed_kind) { /* read at the end of the last step */
    sim->speed_ready = 0;
    *vmax = sim->speed;
    return sim->comm != NULL ? sim->comm->max(sim->comm->ctx, vmax) : CLSPH_OK;
  }
  sim->speed_kind = kind; /* from now on the step-end read brings it along */
  return sim_max_norm(sim, pset_mem(&sim->ps, sim->f_vel), kind, vmax);
}

/* The largest norm's partials, one per work-group, into partial[at ...] (raises the NaN flag). */
static enum clsph_status max_norm_launch(struct sim *sim, cl_mem d_vec, int kind, cl_mem partial,
                                         size_t at, size_t groups)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint n = (cl_uint)sim->ps.n, first = (cl_uint)at;
  cl_int only = kind;
  cl_mem kd = pset_mem(&sim->ps, sim->f_kind);
  CLSPH_TRY(KERN_SET(sim->k_max_speed, KARG(n), KARG(d_vec), KARG(kd), KARG(only), KARG(partial),
                     KARG(first), KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch_wg(sim->dev, sim->k_max_speed, groups * 64, 64, NULL));
done:
  return st;
}

enum clsph_status sim_max_norm(struct sim *sim, cl_mem d_vec, int kind, double *vmax)
{
  enum clsph_status st = CLSPH_OK;
  real *part = NULL;
  size_t groups = sim_reduce_groups(sim->ps.n);
  part = malloc(groups * sizeof *part);
  CLSPH_CHECK(part != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(max_norm_launch(sim, d_vec, kind, sim->d_partial, 0, groups));
  CLSPH_TRY(kern_read(sim->dev, sim->d_partial, groups * sizeof *part, part));
  double m = 0.0;
  for (size_t g = 0; g < groups; ++g) m = fmax(m, (double)part[g]);
  if (sim->comm != NULL) CLSPH_TRY(sim->comm->max(sim->comm->ctx, &m));
  *vmax = m;
done:
  free(part);
  return st;
}

enum clsph_status sim_max_norm_deferred(struct sim *sim, cl_mem d_vec, int kind, double *dest)
{
  enum clsph_status st = CLSPH_OK;
  const size_t groups = sim_reduce_groups(sim->ps.n); /* n as it is now: it may change later */
  CLSPH_CHECK(sim->ndeferred < SIM_DEFERRED, CLSPH_E_INPUT,
              "more than %d step-end maxima in one step", SIM_DEFERRED);
  /* slot k holds its partials from k SIM_REDUCE_MAX_GROUPS on: the step-end read takes them all */
  CLSPH_TRY(max_norm_launch(sim, d_vec, kind, sim->d_deferred,
                            (size_t)sim->ndeferred * SIM_REDUCE_MAX_GROUPS, groups));
  sim->deferred_groups[sim->ndeferred] = groups;
  sim->deferred_to[sim->ndeferred++] = dest;
done:
  return st;
}

enum clsph_status sim_max_field_deferred(struct sim *sim, int field, int kind, double *dest)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_CHECK(sim->nlazy < SIM_DEFERRED, CLSPH_E_INPUT, "more than %d step-end maxima in one step",
              SIM_DEFERRED);
  sim->lazy[sim->nlazy].field = field;
  sim->lazy[sim->nlazy].kind = kind;
  sim->lazy[sim->nlazy++].dest = dest;
done:
  return st;
}

/* The domain check, the largest speed when max_dt has asked for it and the fields' maxima asked
 * for this step: one launch (domain.cl step_end; a third vector and more launch their own), then
 * one non-blocking transfer of every deferred maximum that the flags' blocking read completes
 * (sim_check_step). */
enum clsph_status sim_deferred_enqueue(struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  cl_mem vec[2];
  int kinds[2], nvec = 0;
  size_t slot[2];
  double *dest[2];
  if (sim->speed_kind != SIM_KIND_UNSET) {
    vec[nvec] = pset_mem(&sim->ps, sim->f_vel);
    kinds[nvec] = sim->speed_kind;
    dest[nvec++] = &sim->speed;
  }
  for (int k = 0; k < sim->nlazy; ++k) {
    cl_mem v = pset_mem(&sim->ps, sim->lazy[k].field); /* as the step's sorts have left it */
    if (nvec < 2) {
      vec[nvec] = v;
      kinds[nvec] = sim->lazy[k].kind;
      dest[nvec++] = sim->lazy[k].dest;
    } else
      CLSPH_TRY(sim_max_norm_deferred(sim, v, sim->lazy[k].kind, sim->lazy[k].dest));
  }
  sim->nlazy = 0;
  const size_t groups = sim_reduce_groups(sim->ps.n);
  CLSPH_CHECK(sim->ndeferred + nvec <= SIM_DEFERRED, CLSPH_E_INPUT,
              "more than %d step-end maxima in one step", SIM_DEFERRED);
  for (int v = 0; v < nvec; ++v) {
    slot[v] = (size_t)sim->ndeferred * SIM_REDUCE_MAX_GROUPS;
    sim->deferred_groups[sim->ndeferred] = groups;
    sim->deferred_to[sim->ndeferred++] = dest[v];
  }
  /* a scheme whose step checked the domain (scheme_ops.checks_domain) needs no launch for it */
  if (nvec > 0 || !sim->scheme->checks_domain) CLSPH_TRY(sim_step_end(sim, nvec, vec, kinds, slot));
  if (sim->ndeferred > 0)
    CLSPH_TRY(kern_read_nb(sim->dev, sim->d_deferred, 0,
                           (size_t)sim->ndeferred * SIM_REDUCE_MAX_GROUPS * sizeof(real),
                           sim->h_deferred));
done:
  return st;
}

void sim_deferred_finish(struct sim *sim)
{
  for (int k = 0; k < sim->ndeferred; ++k) {
    double m = 0.0;
    for (size_t g = 0; g < sim->deferred_groups[k]; ++g)
      m = fmax(m, (double)sim->h_deferred[(size_t)k * SIM_REDUCE_MAX_GROUPS + g]);
    *sim->deferred_to[k] = m;
    if (sim->deferred_to[k] == &sim->speed) sim->speed_ready = 1;
  }
  sim->ndeferred = 0;
}

enum clsph_status sim_sample(struct sim *sim, int field, int order, size_t np, const double *at,
                             double *out)
{
  enum clsph_status st = CLSPH_OK;
  const struct pfield *f = &sim->ps.f[field];
  real *buf = NULL;
  cl_mem d_at = NULL, d_out = NULL;
  cl_uint ncomp = (cl_uint)f->ncomp, npts = (cl_uint)np, ord = (cl_uint)order;
  CLSPH_CHECK(f->type == PF_REAL && f->ncomp <= 4, CLSPH_E_INPUT,
              "field '%s' cannot be interpolated", f->name);
  const size_t dim = (size_t)sim->gspec.dim, stride = dim == 3 ? 4 : 2; /* realv */
  buf = calloc(np * (stride + ncomp), sizeof *buf);
  CLSPH_CHECK(buf != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t p = 0; p < np; ++p)
    for (size_t a = 0; a < dim; ++a) buf[stride * p + a] = (real)at[dim * p + a];
  CLSPH_TRY(kern_buffer(sim->dev, stride * np * sizeof(real), buf, &d_at, "sample points"));
  CLSPH_TRY(kern_buffer(sim->dev, ncomp * np * sizeof(real), NULL, &d_out, "samples"));
  cl_mem pos = pset_mem(&sim->ps, sim->f_pos), vol = pset_mem(&sim->ps, sim->f_vol);
  cl_mem kind = pset_mem(&sim->ps, sim->f_kind);
  CLSPH_TRY(KERN_SET(sim->k_probe, KARG(npts), KARG(d_at), KARG(sim->grid.geom),
                     KARG(sim->grid.d_start), KARG(pos), KARG(vol), KARG(kind), KARG(f->d),
                     KARG(ncomp), KARG(ord), KARG(d_out)));
  CLSPH_TRY(kern_launch(sim->dev, sim->k_probe, np, NULL));
  CLSPH_TRY(kern_read(sim->dev, d_out, ncomp * np * sizeof(real), buf + stride * np));
  for (size_t k = 0; k < ncomp * np; ++k) out[k] = (double)buf[stride * np + k];
done:
  kern_release(&d_out);
  kern_release(&d_at);
  free(buf);
  return st;
}

enum clsph_status sim_sample_probes(struct sim *sim, int field, int np,
                                    const struct scene_probe *probes, double *out)
{
  enum clsph_status st = CLSPH_OK;
  const size_t ncomp = (size_t)sim->ps.f[field].ncomp;
  size_t total = 0;
  double *at = NULL, *v = NULL;
  const int dim = sim->gspec.dim;
  for (int p = 0; p < np; ++p) total += (size_t)probes[p].npts;
  at = calloc((size_t)dim * total + 1, sizeof *at);
  v = malloc(ncomp * total * sizeof *v + 1);
  CLSPH_CHECK(at != NULL && v != NULL, CLSPH_E_NOMEM, "out of memory");
  /* every probe's points: a point, the midpoints of a face's npts equal parts, a disc's lattice */
  double *q = at;
  for (int p = 0; p < np; ++p) {
    const int k = scene_probe_points(&probes[p], dim, sim->scene->dr, q);
    CLSPH_CHECK(k == probes[p].npts, CLSPH_E_INPUT, "probe '%s': %d points, not the %d counted",
                probes[p].name, k, probes[p].npts);
    q += (size_t)dim * (size_t)k;
  }
  CLSPH_TRY(sim_sample(sim, field, 0, total, at, v));
  /* each probe's mean over its wet points (a dry point interpolates to NaN) */
  const double *row = v;
  for (int p = 0; p < np; ++p) {
    for (size_t c = 0; c < ncomp; ++c) {
      double sum = 0.0;
      int wet = 0;
      for (int k = 0; k < probes[p].npts; ++k) {
        const double y = row[(size_t)k * ncomp + c];
        if (isnan(y)) continue;
        sum += y;
        ++wet;
      }
      out[(size_t)p * ncomp + c] = wet > 0 ? sum / wet : (double)NAN;
    }
    row += (size_t)probes[p].npts * ncomp;
  }
done:
  free(v);
  free(at);
  return st;
}
