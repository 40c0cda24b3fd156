/* snapshot.c: the HDF5 snapshots of a run with their XDMF index, and a frame with each snapshot
 * (--frames), drawn from a host copy of the device state. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "snapshot.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "scheme.h"
#include "clsph_config.h"
#include "kern.h"
#include "series.h"
#include "str.h"
/* The fields a frame can show: the output fields, by name and components. */
int snapshot_frame_fields(const struct sim *sim, const char **names, int *ncomp)
{
  int n = 0;
  for (int k = 0; k < sim->ps.nfields; ++k) {
    if (!sim->ps.f[k].output) continue;
    names[n] = sim->ps.f[k].name;
    ncomp[n++] = sim->ps.f[k].nout;
  }
  return n;
}

/* Frames: resolve the field against the run's output fields, open the renderer, and list the
 * arrays a frame reads from the device. */
enum clsph_status snapshot_open_frames(struct sim *sim, const struct frames_opts *opts,
                                       const char *out_dir, struct run_out *o)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  const char *names[PSET_MAX_FIELDS];
  int ncomp[PSET_MAX_FIELDS];
  const int n = snapshot_frame_fields(sim, names, ncomp);
  CLSPH_TRY(frames_open(opts, out_dir, n, names, ncomp, &o->frames));
  if (s->dim == 3) { /* the default camera sees the domain whole: where the fluid can go */
    const double box[6] = {s->lo[0], s->lo[1], s->lo[2], s->hi[0], s->hi[1], s->hi[2]};
    frames_set_view3(o->frames, box);
  }
  const char *want[4] = {"pos", "vol", "kind", frames_field(o->frames)->array};
  for (int k = 0; k < 4; ++k) {
    int dup = 0;
    for (int j = 0; j < k; ++j) dup |= strcmp(want[j], want[k]) == 0;
    if (dup) continue;
    const int f = pset_find(&sim->ps, want[k]);
    CLSPH_CHECK(f >= 0, CLSPH_E_INPUT, "frames: the run has no field '%s'", want[k]);
    o->frame_in[o->nframe_arrays].name = sim->ps.f[f].name;
    o->frame_in[o->nframe_arrays].ncomp = sim->ps.f[f].nout;
    o->frame_arrays[o->nframe_arrays] =
        malloc(sim->ps.cap * (size_t)sim->ps.f[f].nout * sizeof(double));
    CLSPH_CHECK(o->frame_arrays[o->nframe_arrays] != NULL, CLSPH_E_NOMEM,
                "out of memory for the frames");
    o->frame_in[o->nframe_arrays].v = o->frame_arrays[o->nframe_arrays];
    ++o->nframe_arrays;
  }
  if (s->nwalls > 0) {
    o->walls = calloc((size_t)s->nwalls, sizeof *o->walls);
    CLSPH_CHECK(o->walls != NULL, CLSPH_E_NOMEM, "out of memory");
    for (int w = 0; w < s->nwalls; ++w)
      o->walls[w] = (struct render_wall){s->walls[w].npts, s->walls[w].pts, s->walls[w].closed};
  }
  const double domain[4] = {s->lo[0], s->lo[1], s->hi[0], s->hi[1]};
  frames_view(domain, s->nwalls, o->walls, o->view);
done:
  return st;
}

/* A frame of the device state now: the arrays it reads, copied to the host as doubles. */
static enum clsph_status write_frame(struct sim *sim, struct run_out *o)
{
  enum clsph_status st = CLSPH_OK;
  unsigned char *h = NULL;
  const size_t n = sim->ps.n;
  for (int a = 0; a < o->nframe_arrays; ++a) {
    const struct pfield *f = &sim->ps.f[pset_find(&sim->ps, o->frame_in[a].name)];
    h = malloc(n > 0 ? n * f->elem : 1);
    CLSPH_CHECK(h != NULL, CLSPH_E_NOMEM, "out of memory for a frame");
    if (n > 0) CLSPH_TRY(kern_read(sim->dev, f->d, n * f->elem, h));
    double *v = o->frame_arrays[a];
    const size_t nc = (size_t)f->ncomp, nout = (size_t)f->nout;
    for (size_t i = 0; i < n; ++i) {
      for (size_t c = 0; c < nout; ++c) {
        const size_t k = i * nc + c;
        v[i * nout + c] = f->type == PF_REAL   ? (double)((const real *)(const void *)h)[k]
                          : f->type == PF_UINT ? (double)((const cl_uint *)(const void *)h)[k]
                                               : (double)((const cl_int *)(const void *)h)[k];
      }
    }
    free(h);
    h = NULL;
  }
  struct render_input in;
  memset(&in, 0, sizeof in);
  in.n = n;
  in.narrays = o->nframe_arrays;
  in.arrays = o->frame_in;
  in.nwalls = sim->scene->nwalls;
  in.walls = o->walls;
  in.surf3 = o->surf3;
  in.nsurf3 = o->nsurf3;
  memcpy(in.view, o->view, sizeof in.view);
  in.time = sim->time;
  in.case_name = sim->scene->name;
  in.scheme = sim->scheme->name;
  CLSPH_TRY(frames_write(o->frames, &in, o->nsnap));
done:
  free(h);
  return st;
}

void snapshot_meta(const struct sim *sim, struct io_meta *m)
{
  memset(m, 0, sizeof *m);
  m->case_name = sim->scene->name;
  m->case_path = sim->scene->case_path;
  m->scheme = sim->scheme->name;
  m->precision = CLSPH_PRECISION_NAME;
  m->version = CLSPH_VERSION;
  m->time = sim->time;
  m->step = sim->step;
  m->dt = sim->dt;
  m->dim = sim->scene->dim;
  m->params = sim->scene->params;
  m->nparams = sim->scene->nparams;
  m->has_domain = 1;
  m->domain[0] = sim->scene->lo[0];
  m->domain[1] = sim->scene->lo[1];
  m->domain[2] = sim->scene->hi[0];
  m->domain[3] = sim->scene->hi[1];
  m->has_domain3 = sim->scene->dim == 3;
  for (int a = 0; a < 3; ++a) {
    m->domain3[a] = sim->scene->lo[a];
    m->domain3[3 + a] = sim->scene->hi[a];
  }
  m->walls = sim->scene->walls; /* the polylines frames draw (3-D: their faces, place_walls) */
  m->nwalls = sim->scene->dim == 2 ? sim->scene->nwalls : 0;
  m->render = &sim->scene->render;
}

/* The walls where they stand now, when some turn or a gate lifts them (into o->turned; the
 * frames' walls follow), and in 3-D their faces (o->surf3). */
static enum clsph_status place_walls(const struct sim *sim, struct run_out *o)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  double lift[3];
  sim_moved_offset(sim, sim->time, lift);
  if (s->dim == 3) {
    free(o->surf3);
    o->surf3 = NULL;
    CLSPH_TRY(scene_surfaces3(s, sim->moved.group, lift, &o->surf3, &o->nsurf3));
    goto done;
  }
  size_t npts = 0;
  int any = 0;
  for (int w = 0; w < s->nwalls; ++w) {
    any |= scene_wall_turns(&s->walls[w]) ||
           (sim->moved.group != NULL && strcmp(s->walls[w].group, sim->moved.group) == 0);
    npts += (size_t)s->walls[w].npts;
  }
  if (!any) return CLSPH_OK;
  if (o->turned == NULL) {
    o->turned = calloc((size_t)s->nwalls, sizeof *o->turned);
    o->turned_pts = calloc(2 * npts, sizeof *o->turned_pts);
    CLSPH_CHECK(o->turned != NULL && o->turned_pts != NULL, CLSPH_E_NOMEM, "out of memory");
  }
  double *q = o->turned_pts;
  for (int w = 0; w < s->nwalls; ++w) {
    const struct scene_wall *wl = &s->walls[w];
    const int lifted = sim->moved.group != NULL && strcmp(wl->group, sim->moved.group) == 0;
    o->turned[w] = *wl;
    o->turned[w].pts = q;
    for (int k = 0; k < wl->npts; ++k) {
      scene_wall_turn(wl, sim->time, wl->pts + 2 * k, 0, q + 2 * k);
      if (lifted) q[2 * k] += lift[0], q[2 * k + 1] += lift[1];
    }
    if (o->walls != NULL) o->walls[w].pts = q;
    q += 2 * wl->npts;
  }
done:
  return st;
}

enum clsph_status snapshot_write(struct sim *sim, struct run_out *o)
{
  enum clsph_status st = CLSPH_OK;
  char name[64], *path = NULL;
  struct io_meta m;
  snapshot_meta(sim, &m);
  CLSPH_TRY(place_walls(sim, o));
  if (o->turned != NULL) m.walls = o->turned;
  m.surf3 = o->surf3;
  m.nsurf3 = o->nsurf3;
  snprintf(name, sizeof name, "snap_%06d.h5", o->nsnap);
  CLSPH_TRY(out_path(o, name, &path));
  CLSPH_TRY(io_snapshot_write(path, sim->dev, &sim->ps, &m));
  free(path);
  path = NULL;
  CLSPH_TRY(io_series_add(&o->series, name, sim->time, sim->ps.n));
  CLSPH_TRY(out_path(o, "snapshots.xdmf", &path));
  CLSPH_TRY(io_xdmf_write(path, &o->series, &sim->ps, sim->scene->dim));
  if (o->frames != NULL) CLSPH_TRY(write_frame(sim, o));
  /* with run { sample_every }, the time series keep their own cadence (see sim_run) */
  CLSPH_TRY(series_write(sim, o,
                         sim->scene->sample_every > 0.0 && sim->time > 0.0
                             ? SERIES_PROFILES
                             : SERIES_TIME | SERIES_PROFILES));
  ++o->nsnap;
done:
  free(path);
  return st;
}

enum clsph_status snapshot_resume_index(struct run_out *o, const char *restart)
{
  enum clsph_status st = CLSPH_OK;
  static const char *const nothing[] = {NULL};
  const char *slash = strrchr(restart, '/');
  char *ckdir =
      slash == NULL ? str_printf(".") : str_printf("%.*s", (int)(slash - restart), restart);
  char *path = NULL, *name = NULL, *ckreal = NULL, *outreal = NULL;
  struct io_snapshot snap;
  memset(&snap, 0, sizeof snap);
  CLSPH_CHECK(ckdir != NULL, CLSPH_E_NOMEM, "out of memory");
  ckreal = realpath(ckdir, NULL);
  outreal = realpath(o->dir, NULL);
  const int here = ckreal != NULL && outreal != NULL && strcmp(ckreal, outreal) == 0;
  int missing = 0;
  for (int k = 0; k < o->nsnap; ++k) {
    free(path);
    free(name);
    path = str_printf("%s/snap_%06d.h5", ckreal != NULL ? ckreal : ckdir, k);
    /* in the run's own folder by name; elsewhere by the whole path, which ParaView follows */
    name = here ? str_printf("snap_%06d.h5", k) : str_printf("%s", path != NULL ? path : "");
    CLSPH_CHECK(path != NULL && name != NULL, CLSPH_E_NOMEM, "out of memory");
    if (access(path, R_OK) != 0) {
      ++missing;
      continue;
    }
    CLSPH_TRY(io_snapshot_read(path, nothing, &snap));
    CLSPH_TRY(io_series_add(&o->series, name, snap.time, snap.n));
    io_snapshot_free(&snap);
  }
  if (missing > 0)
    log_warn("%d of the %d snapshots before the checkpoint are not in %s: snapshots.xdmf lists "
             "the others",
             missing, o->nsnap, ckdir);
done:
  io_snapshot_free(&snap);
  free(outreal);
  free(ckreal);
  free(name);
  free(path);
  free(ckdir);
  return st;
}

enum clsph_status snapshot_write_blowup(struct sim *sim, struct run_out *o)
{
  enum clsph_status st = CLSPH_OK;
  char *path = NULL;
  struct io_meta m;
  snapshot_meta(sim, &m);
  CLSPH_TRY(place_walls(sim, o));
  if (o->turned != NULL) m.walls = o->turned;
  m.surf3 = o->surf3;
  m.nsurf3 = o->nsurf3;
  CLSPH_TRY(out_path(o, "blowup.h5", &path));
  CLSPH_TRY(io_snapshot_write(path, sim->dev, &sim->ps, &m));
done:
  free(path);
  return st;
}
