/* commands.c: the `run`, `info` and `render` commands. Everything is checked (case, geometry,
 * device, output folder, the field of frames) before the first step, so bad input leaves nothing
 * half-written. */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "case.h"
#include "cli.h"
#include "clsph_config.h"
#include "frames.h"
#include "io.h"
#include "interrupt.h"
#include "kern.h"
#include "loop.h"
#include "scheme.h"
#include "sim.h"
#include "str.h"

static enum clsph_status setup(const struct cli *cli, struct dev *dev, struct scene *scene,
                               struct case_script **script, struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  struct case_limits lim;
  case_limits_default(&lim);
  if (cli->case_instructions > 0.0) lim.instructions = cli->case_instructions;
  if (cli->case_memory > 0.0) lim.memory = cli->case_memory;
  CLSPH_TRY(case_load(cli->case_path, cli->nsets, cli->sets, &lim, scene, script));
  CLSPH_TRY(dev_open(cli->device, CLSPH_DOUBLE, dev));
  if (cli->device_memory > 0.0 && cli->device_memory < (double)dev->mem_limit)
    dev->mem_limit = (cl_ulong)cli->device_memory;
  CLSPH_TRY(sim_create(dev, scene, sim));
done:
  return st;
}

enum clsph_status info_command(const struct cli *cli)
{
  enum clsph_status st = CLSPH_OK;
  struct dev dev = {0};
  struct scene scene;
  struct sim sim;
  struct case_script *script = NULL; /* open while the particles are made (fill velocities) */
  memset(&scene, 0, sizeof scene);
  memset(&sim, 0, sizeof sim);
  CLSPH_TRY(setup(cli, &dev, &scene, &script, &sim));
  printf("device %d: %s (%s), precision %s\n", dev.index, dev.name, dev.platform_name,
         CLSPH_PRECISION_NAME);
  CLSPH_TRY(sim_info(&sim));
done:
  sim_destroy(&sim);
  case_close(script);
  scene_free(&scene);
  dev_close(&dev);
  return st;
}

/* The --profile table: device time per kernel, slowest first, as a share of the summed device time
 * and of the run's wall time; what is left of the wall time is the host's (set-up of launches,
 * outputs, reductions finished on the host) and waiting. */
static enum clsph_status print_profile(struct kern_profile *p, double wall)
{
  enum clsph_status st = CLSPH_OK;
  struct kern_profile_entry *e = NULL;
  size_t n = 0;
  double device = 0.0;
  long launches = 0;
  CLSPH_TRY(kern_profile_entries(p, &e, &n, &device));
  if (n == 0) goto done;
  int w = (int)strlen("host and waiting");
  for (size_t i = 0; i < n; ++i) {
    if ((int)strlen(e[i].name) > w) w = (int)strlen(e[i].name);
    launches += e[i].launches;
  }
  double dshare = device > 0.0 ? 100.0 / device : 0.0, wshare = wall > 0.0 ? 100.0 / wall : 0.0;
  printf("profile: device time per kernel over the run's %.3f s of wall time\n", wall);
  /* "mean µs" is 8 bytes shown in 7 columns: its field is one byte wider */
  printf("  %-*s %9s %10s %11s %8s %8s\n", w, "kernel", "launches", "total s", "mean µs", "device",
         "wall");
  for (size_t i = 0; i < n; ++i)
    printf("  %-*s %9ld %10.4f %10.1f %7.1f%% %7.1f%%\n", w, e[i].name, e[i].launches, e[i].seconds,
           1e6 * e[i].seconds / (double)e[i].launches, dshare * e[i].seconds,
           wshare * e[i].seconds);
  printf("  %-*s %9ld %10.4f %10s %7.1f%% %7.1f%%\n", w, "device total", launches, device, "",
         device > 0.0 ? 100.0 : 0.0, wshare * device);
  printf("  %-*s %9s %10.4f %10s %8s %7.1f%%\n", w, "host and waiting", "", wall - device, "", "",
         wshare * (wall - device));
done:
  free(e);
  return st;
}

/* The options of frames: the defaults, then the case's render { } choices (`r`, NULL: none), then
 * the command line. */
static enum clsph_status frame_options(const struct cli *cli, const struct scene_render *r,
                                       const char *where, struct frames_opts *fo)
{
  enum clsph_status st = CLSPH_OK;
  frames_defaults(fo);
  if (r != NULL) CLSPH_TRY(frames_apply_case(r, where, fo));
  if (cli->field != NULL) snprintf(fo->render.field, sizeof fo->render.field, "%s", cli->field);
  if (cli->range_set) {
    fo->render.fixed = !cli->range_auto;
    fo->render.lo = cli->range[0];
    fo->render.hi = cli->range[1];
  }
  if (cli->colormap != NULL) CLSPH_TRY(colormap_from_name(cli->colormap, &fo->render.map));
  if (cli->width > 0) {
    fo->render.width = cli->width;
    fo->render.height = cli->height;
  }
  if (cli->fps > 0) fo->fps = cli->fps;
  if (cli->no_movie) fo->movie = 0;
  fo->render.font = cli->font;
  if (cli->camera_set) { /* the command line's camera, with the case's field of view or 30° */
    struct render_camera *c = &fo->render.camera;
    const double fov = fo->render.camera_set ? c->fov : 30.0;
    memcpy(c->eye, cli->camera, sizeof c->eye);
    memcpy(c->at, cli->camera + 3, sizeof c->at);
    memcpy(c->up, cli->camera + 6, sizeof c->up);
    c->fov = fov;
    fo->render.camera_set = 1;
  }
  if (cli->fov > 0.0 && !fo->render.camera_set) { /* the default camera's eye, this fov */
    fo->render.fov_only = cli->fov;
  } else if (cli->fov > 0.0) {
    fo->render.camera.fov = cli->fov;
  }
  if (fo->render.camera_set) CLSPH_TRY(render_check_camera(&fo->render.camera, "--camera"));
done:
  return st;
}

enum clsph_status run_command(const struct cli *cli)
{
  enum clsph_status st = CLSPH_OK;
  struct dev dev = {0};
  struct scene scene;
  struct sim sim;
  struct case_script *script = NULL;
  char *out = NULL;
  memset(&scene, 0, sizeof scene);
  memset(&sim, 0, sizeof sim);
  interrupt_catch(); /* a first Ctrl-C stops the run at a safe point, a second at once */
  CLSPH_TRY(setup(cli, &dev, &scene, &script, &sim));
  if (cli->profile) CLSPH_TRY(kern_profile_create(&dev));
  out = cli->out_dir != NULL ? str_printf("%s", cli->out_dir) : str_printf("out/%s", scene.name);
  CLSPH_CHECK(out != NULL, CLSPH_E_NOMEM, "out of memory");
  if (!cli->quiet)
    printf("clsph run %s: scheme %s, %zu particles (%zu fluid), %s on %s, output in %s\n",
           scene.name, sim.scheme->name, sim.ps.n, sim.geom.nfluid, CLSPH_PRECISION_NAME, dev.name,
           out);
  struct frames_opts fo;
  if (cli->frames) CLSPH_TRY(frame_options(cli, &scene.render, scene.case_path, &fo));
  struct loop_options opt = {.out_dir = out,
                             .restart = cli->restart,
                             .overwrite = cli->overwrite,
                             .quiet = cli->quiet,
                             .frames = cli->frames ? &fo : NULL};
  st = loop_run(&sim, &opt, script);
  if (!cli->quiet && st == CLSPH_OK)
    printf("done: t = %g s in %ld steps; %s/summary.json\n", sim.time, sim.step, out);
  if (!cli->quiet && dev.profile != NULL) {
    enum clsph_status ps = print_profile(dev.profile, sim.wall);
    if (st == CLSPH_OK) st = ps;
  }
done:
  free(out);
  sim_destroy(&sim);
  case_close(script);
  scene_free(&scene);
  dev_close(&dev);
  interrupt_release();
  return st;
}

/* ---- render: frames from the snapshots of a run ---- */

static int cmp_int(const void *a, const void *b)
{
  int x = *(const int *)a, y = *(const int *)b;
  return (x > y) - (x < y);
}

/* The numbers NNNNNN of the files snap_NNNNNN.h5 in a folder, ascending (malloc'd). */
static enum clsph_status list_snapshots(const char *dir, int **out, int *count)
{
  enum clsph_status st = CLSPH_OK;
  struct stat sb;
  DIR *d = NULL;
  int *num = NULL, n = 0, cap = 0;
  CLSPH_CHECK(stat(dir, &sb) == 0, CLSPH_E_INPUT,
              "render: the output folder %s does not exist (%s)", dir, strerror(errno));
  CLSPH_CHECK(S_ISDIR(sb.st_mode), CLSPH_E_INPUT,
              "render: %s is not a folder; name the --out folder of a run", dir);
  d = opendir(dir);
  CLSPH_CHECK(d != NULL, CLSPH_E_IO, "render: cannot read the folder %s: %s", dir, strerror(errno));
  for (struct dirent *e; (e = readdir(d)) != NULL;) {
    int k = -1, len = 0;
    if (strlen(e->d_name) != 14 || sscanf(e->d_name, "snap_%6d.h5%n", &k, &len) != 1 || len != 14 ||
        k < 0)
      continue;
    if (n == cap) {
      cap = cap ? 2 * cap : 64;
      int *p = realloc(num, (size_t)cap * sizeof *p);
      CLSPH_CHECK(p != NULL, CLSPH_E_NOMEM, "out of memory");
      num = p;
    }
    num[n++] = k;
  }
  CLSPH_CHECK(n > 0, CLSPH_E_INPUT,
              "render: no snapshots (snap_NNNNNN.h5) in %s; it is not the output folder of a "
              "run (clsph run CASE --out %s)",
              dir, dir);
  qsort(num, (size_t)n, sizeof *num, cmp_int);
  *out = num;
  num = NULL;
  *count = n;
done:
  if (d != NULL) closedir(d);
  free(num);
  return st;
}

/* DIR/snap_NNNNNN.h5 into *path (malloc'd; the previous one freed). */
static enum clsph_status snapshot_path(const char *dir, int k, char **path)
{
  enum clsph_status st = CLSPH_OK;
  free(*path);
  *path = str_printf("%s/snap_%06d.h5", dir, k);
  CLSPH_CHECK(*path != NULL, CLSPH_E_NOMEM, "out of memory");
done:
  return st;
}

/* A frame's input from a snapshot: its arrays (those read), walls, view, time and names. A slice
 * (`slice`) leaves the view to the renderer: the box of the drawn particles and the walls. */
static enum clsph_status snapshot_input(const struct io_snapshot *s, int slice,
                                        struct render_array *arrays, struct render_wall **walls,
                                        struct render_input *in)
{
  enum clsph_status st = CLSPH_OK;
  memset(in, 0, sizeof *in);
  in->n = s->n;
  for (int k = 0; k < s->narrays; ++k) {
    if (s->arrays[k].v == NULL) continue;
    arrays[in->narrays++] =
        (struct render_array){s->arrays[k].name, s->arrays[k].ncomp, s->arrays[k].v};
  }
  in->arrays = arrays;
  free(*walls);
  *walls = calloc(s->nwalls > 0 ? (size_t)s->nwalls : 1, sizeof **walls);
  CLSPH_CHECK(*walls != NULL, CLSPH_E_NOMEM, "out of memory");
  for (int w = 0; w < s->nwalls; ++w)
    (*walls)[w] = (struct render_wall){s->walls[w].npts, s->walls[w].pts, s->walls[w].closed};
  in->nwalls = s->nwalls;
  in->walls = *walls;
  in->nsurf3 = s->nsurf3;
  in->surf3 = s->surf3;
  if (!slice) frames_view(s->has_domain ? s->domain : NULL, s->nwalls, *walls, in->view);
  in->time = s->time;
  in->case_name = s->case_name;
  in->scheme = s->scheme;
done:
  return st;
}

/* The walls' faces (/walls3) cut by the plane x_ax = at: a segment per face that crosses it, in
 * the plane's axes (u, w), oriented with the fluid on its left as 2-D walls are (the face's
 * normal into the fluid, projected on the plane, to the left of the segment); s->walls, which a
 * 3-D snapshot leaves empty, receives them. */
static enum clsph_status slice_walls(struct io_snapshot *s, int ax, int u, int w, double at)
{
  enum clsph_status st = CLSPH_OK;
  if (s->nsurf3 == 0 || s->nwalls > 0) goto done;
  s->walls = calloc(s->nsurf3, sizeof *s->walls);
  CLSPH_CHECK(s->walls != NULL, CLSPH_E_NOMEM, "out of memory for the walls of the slice");
  for (size_t t = 0; t < s->nsurf3; ++t) {
    const double *v = s->surf3 + 9 * t;
    double q[2][2];
    int nq = 0;
    for (int k = 0; k < 3 && nq < 2; ++k) { /* the edges that cross the plane */
      const double *a = v + 3 * k, *b = v + 3 * ((k + 1) % 3);
      const double da = a[ax] - at, db = b[ax] - at;
      if ((da < 0.0) == (db < 0.0)) continue;
      const double f = da / (da - db);
      q[nq][0] = a[u] + f * (b[u] - a[u]);
      q[nq][1] = a[w] + f * (b[w] - a[w]);
      ++nq;
    }
    if (nq < 2 || (q[0][0] == q[1][0] && q[0][1] == q[1][1])) continue;
    double e1[3], e2[3];
    for (int c = 0; c < 3; ++c) e1[c] = v[3 + c] - v[c], e2[c] = v[6 + c] - v[c];
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                         e1[0] * e2[1] - e1[1] * e2[0]};
    const double du = q[1][0] - q[0][0], dw = q[1][1] - q[0][1];
    const int flip = -dw * n[u] + du * n[w] < 0.0; /* the fluid to the right: reversed */
    double *pts = malloc(4 * sizeof *pts);
    CLSPH_CHECK(pts != NULL, CLSPH_E_NOMEM, "out of memory for the walls of the slice");
    for (int k = 0; k < 2; ++k) {
      pts[2 * k] = q[flip ? 1 - k : k][0];
      pts[2 * k + 1] = q[flip ? 1 - k : k][1];
    }
    s->walls[s->nwalls++] = (struct io_wall){2, pts, 0};
  }
done:
  return st;
}

/* A 3-D snapshot as the 2-D one frames draw (--slice AXIS=VALUE): the particles within half a
 * spacing (from their volume, dr³) of the plane, their positions the two other axes in order
 * (x, z for a slice along y), their volumes the areas dr² the splats are drawn by, the other
 * arrays' rows kept alike, and the walls' faces cut by the plane as 2-D walls. A snapshot read
 * without its arrays' values (the first, for the fields) only takes the 2-D shape. */
static enum clsph_status slice_snapshot(struct io_snapshot *s, const struct cli *cli,
                                        const char *path)
{
  enum clsph_status st = CLSPH_OK;
  struct io_array *pos = NULL, *vol = NULL;
  for (int k = 0; k < s->narrays; ++k) {
    if (strcmp(s->arrays[k].name, "pos") == 0) pos = &s->arrays[k];
    if (strcmp(s->arrays[k].name, "vol") == 0) vol = &s->arrays[k];
  }
  CLSPH_CHECK(pos != NULL, CLSPH_E_INPUT, "render: %s has no particle positions", path);
  CLSPH_CHECK(pos->ncomp == 3 || !cli->slice_set, CLSPH_E_INPUT,
              "render: --slice is for 3-D runs; %s is 2-D", path);
  if (pos->ncomp == 2 || !cli->slice_set) goto done; /* (3-D without a slice: the camera's view) */
  const int ax = cli->slice_axis, u = ax == 0 ? 1 : 0, w = ax == 2 ? 1 : 2;
  s->has_domain = 0; /* the view: the drawn particles' box */
  const size_t len = strlen(s->case_name);
  snprintf(s->case_name + len, sizeof s->case_name - len, " (%c = %g m)", "xyz"[ax],
           cli -> slice_at);
  CLSPH_TRY(slice_walls(s, ax, u, w, cli->slice_at)); /* and the walls where the plane cuts them */
  if (pos->v == NULL) { /* the shape only (the first snapshot's read): say what the plane cuts */
    if (!cli->quiet)
      printf("--slice %c=%g cuts the walls' faces in %d segments\n", "xyz"[ax], cli -> slice_at,
             s -> nwalls);
    pos->ncomp = 2;
    goto done;
  }
  CLSPH_CHECK(vol != NULL && vol->v != NULL, CLSPH_E_INPUT, "render: %s has no particle volumes",
              path);
  size_t kept = 0;
  for (size_t i = 0; i < s->n; ++i) {
    const double half = 0.5 * cbrt(vol->v[i]), d = pos->v[3 * i + (size_t)ax] - cli->slice_at;
    if (!(d >= -half && d < half)) continue;
    for (int k = 0; k < s->narrays; ++k) {
      struct io_array *a = &s->arrays[k];
      if (a->v == NULL || a == pos) continue;
      memmove(a->v + kept * (size_t)a->ncomp, a->v + i * (size_t)a->ncomp,
              (size_t)a->ncomp * sizeof *a->v);
    }
    const double pu = pos->v[3 * i + (size_t)u], pw = pos->v[3 * i + (size_t)w];
    pos->v[2 * kept] = pu;
    pos->v[2 * kept + 1] = pw;
    ++kept;
  }
  pos->ncomp = 2;
  s->n = kept;
  for (size_t i = 0; i < kept; ++i)
    vol->v[i] = pow(vol->v[i], 2.0 / 3.0); /* dr³ to dr²: the
                                            * splats' size */
  CLSPH_CHECK(kept > 0, CLSPH_E_INPUT,
              "render: --slice %c=%g: no particle of %s lies within half a spacing of the plane",
              "xyz"[ax], cli -> slice_at, path);
done:
  return st;
}

enum clsph_status render_command(const struct cli *cli)
{
  enum clsph_status st = CLSPH_OK;
  int *num = NULL, count = 0;
  struct io_snapshot snap;
  struct frames_opts fo;
  struct frames *fr = NULL;
  struct render_array arrays[PSET_MAX_FIELDS];
  struct render_wall *walls = NULL;
  struct render_input in;
  double *val = NULL;
  char *path = NULL;
  const char *out = cli->out_dir != NULL ? cli->out_dir : cli->snap_dir;
  memset(&snap, 0, sizeof snap);
  CLSPH_TRY(list_snapshots(cli->snap_dir, &num, &count));

  /* the first snapshot: the fields there are, and the case's render choices */
  CLSPH_TRY(snapshot_path(cli->snap_dir, num[0], &path));
  static const char *const nothing[] = {NULL};
  CLSPH_TRY(io_snapshot_read(path, nothing, &snap));
  if (!snap.has_domain)
    log_warn("%s records no domain and no walls (written by an older clsph): the frames show the "
             "particles only",
             path);
  CLSPH_TRY(slice_snapshot(&snap, cli, path));
  CLSPH_TRY(frame_options(cli, snap.render.on ? &snap.render : NULL, path, &fo));
  const char *names[PSET_MAX_FIELDS];
  int ncomp[PSET_MAX_FIELDS];
  int three = 0; /* 3-D particles drawn in perspective (no --slice) */
  const int has_box3 = snap.has_domain3;
  double box3[6];
  memcpy(box3, snap.domain3, sizeof box3);
  for (int k = 0; k < snap.narrays; ++k) {
    names[k] = snap.arrays[k].name;
    ncomp[k] = snap.arrays[k].ncomp;
    if (strcmp(names[k], "pos") == 0) three = ncomp[k] == 3;
  }
  if (cli->out_dir != NULL)
    CLSPH_CHECK(mkdir(out, 0755) == 0 || errno == EEXIST, CLSPH_E_IO,
                "render: the folder %s cannot be created: %s", out, strerror(errno));
  CLSPH_TRY(frames_open(&fo, out, snap.narrays, names, ncomp, &fr));
  io_snapshot_free(&snap);
  const struct field_spec *f = frames_field(fr);
  const char *const only[] = {"pos", "vol", "kind", f->array, NULL};

  /* an automatic range spans every snapshot, so that colours mean the same in every frame */
  if (!fo.render.fixed && f->how != FIELD_KIND) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    enum colormap_kind map = render_map_for(f, fo.render.map);
    for (int k = 0; k < count; ++k) {
      CLSPH_TRY(snapshot_path(cli->snap_dir, num[k], &path));
      CLSPH_TRY(io_snapshot_read(path, only, &snap));
      CLSPH_TRY(slice_snapshot(&snap, cli, path));
      CLSPH_TRY(snapshot_input(&snap, cli->slice_set, arrays, &walls, &in));
      const struct render_array *kind = field_array(&in, "kind");
      CLSPH_CHECK(kind != NULL, CLSPH_E_INPUT, "%s has no particle kinds", path);
      free(val);
      val = malloc((snap.n > 0 ? snap.n : 1) * sizeof *val);
      CLSPH_CHECK(val != NULL, CLSPH_E_NOMEM, "out of memory");
      CLSPH_TRY(field_values(f, &in, val));
      double a, b;
      if (field_percentiles(f, snap.n, val, kind->v, &a, &b) > 0) {
        lo = fmin(lo, a);
        hi = fmax(hi, b);
      }
      io_snapshot_free(&snap);
    }
    field_range_rules(f, map, hi >= lo, &lo, &hi);
    frames_set_range(fr, lo, hi);
    if (!cli->quiet)
      printf("colour range of %s over %d snapshots: %g .. %g\n", f->name, count, lo, hi);
  }
  /* 3-D without a camera: the default one sees the domain whole, as the run's frames do (the
   * first snapshot's fluid alone left a dam break's surge out of the later frames); snapshots
   * written before the 3-D domain was recorded: the drawn particles of every snapshot */
  if (three && !cli->slice_set && !fo.render.camera_set && has_box3) {
    frames_set_view3(fr, box3);
  } else if (three && !cli->slice_set && !fo.render.camera_set) {
    double box[6] = {HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    const char *const pk[] = {"pos", "kind", NULL};
    for (int k = 0; k < count; ++k) {
      CLSPH_TRY(snapshot_path(cli->snap_dir, num[k], &path));
      CLSPH_TRY(io_snapshot_read(path, pk, &snap));
      CLSPH_TRY(snapshot_input(&snap, cli->slice_set, arrays, &walls, &in));
      render_extend_box(f, &in, box);
      io_snapshot_free(&snap);
    }
    if (box[3] >= box[0] && box[4] >= box[1] && box[5] >= box[2]) frames_set_view3(fr, box);
  }
  for (int k = 0; k < count; ++k) {
    CLSPH_TRY(snapshot_path(cli->snap_dir, num[k], &path));
    CLSPH_TRY(io_snapshot_read(path, only, &snap));
    CLSPH_TRY(slice_snapshot(&snap, cli, path));
    CLSPH_TRY(snapshot_input(&snap, cli->slice_set, arrays, &walls, &in));
    CLSPH_TRY(frames_write(fr, &in, num[k]));
    io_snapshot_free(&snap);
  }
  CLSPH_TRY(frames_finish(fr, cli->quiet));
done:
  free(path);
  free(val);
  free(walls);
  io_snapshot_free(&snap);
  frames_close(fr);
  free(num);
  return st;
}
