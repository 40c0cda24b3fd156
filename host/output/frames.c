/* frames.c: the frames of a run around the render module. Frames go to OUT/frames/FIELD_NNNNNN.png
 * (NNNNNN: the number of the snapshot they show, so a frame and snap_NNNNNN.h5 belong together),
 * the movie to OUT/FIELD.mp4. Precedence of the choices: the command line over the case's
 * render { } over the defaults. */
#include "frames.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "str.h"

struct frames {
  struct frames_opts o;
  struct render *r;
  struct field_spec f;
  char *out;        /* the output folder */
  char *dir;        /* OUT/frames */
  int first, count; /* frames written here: numbers first .. first + count − 1 */
  int last;         /* the last number written */
};

void frames_defaults(struct frames_opts *o)
{
  memset(o, 0, sizeof *o);
  render_defaults(&o->render);
  o->movie = 1;
  o->fps = 10;
}

enum clsph_status frames_apply_case(const struct scene_render *r, const char *where,
                                    struct frames_opts *o)
{
  enum clsph_status st = CLSPH_OK;
  if (!r->on) goto done;
  CLSPH_CHECK(strlen(r->field) < sizeof o->render.field, CLSPH_E_INPUT,
              "render { field = \"%s\" }: no field has so long a name", r->field);
  if (r->field[0] != '\0')
    snprintf(o->render.field, sizeof o->render.field, "%.*s", (int)sizeof o->render.field - 1,
             r->field);
  if (r->fixed) {
    o->render.fixed = 1;
    o->render.lo = r->range[0];
    o->render.hi = r->range[1];
  }
  if (r->colormap[0] != '\0') CLSPH_TRY(colormap_from_name(r->colormap, &o->render.map));
  if (r->camera) {
    struct render_camera *c = &o->render.camera;
    memcpy(c->eye, r->eye, sizeof c->eye);
    memcpy(c->at, r->look_at, sizeof c->at);
    memcpy(c->up, r->up, sizeof c->up);
    c->fov = r->fov;
    char what[1100];
    snprintf(what, sizeof what, "%s:%d: render camera", where, r->line);
    CLSPH_TRY(render_check_camera(c, what));
    o->render.camera_set = 1;
  }
done:
  return st;
}

static enum clsph_status make_dir(const char *dir)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_CHECK(mkdir(dir, 0755) == 0 || errno == EEXIST, CLSPH_E_IO,
              "the frames folder %s cannot be created: %s", dir, strerror(errno));
done:
  return st;
}

enum clsph_status frames_open(const struct frames_opts *o, const char *out_dir, int narrays,
                              const char *const *names, const int *ncomp, struct frames **out)
{
  enum clsph_status st = CLSPH_OK;
  struct frames *fr = calloc(1, sizeof *fr);
  CLSPH_CHECK(fr != NULL, CLSPH_E_NOMEM, "out of memory");
  fr->o = *o;
  fr->first = -1;
  CLSPH_TRY(field_find(o->render.field, narrays, names, ncomp, &fr->f));
  fr->out = str_printf("%s", out_dir);
  fr->dir = str_printf("%s/frames", out_dir);
  CLSPH_CHECK(fr->out != NULL && fr->dir != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(make_dir(fr->dir));
  CLSPH_TRY(render_create(&o->render, &fr->r));
  *out = fr;
  fr = NULL;
done:
  frames_close(fr);
  return st;
}

const struct field_spec *frames_field(const struct frames *fr)
{
  return &fr->f;
}

void frames_set_range(struct frames *fr, double lo, double hi)
{
  render_set_range(fr->r, lo, hi);
}

void frames_set_view3(struct frames *fr, const double box[6])
{
  render_set_view3(fr->r, box);
}

/* OUT/frames/FIELD_NNNNNN.png, malloc'd (NULL: out of memory). */
static char *frame_path(const struct frames *fr, int index)
{
  return str_printf("%s/%s_%06d.png", fr->dir, fr->f.name, index);
}

enum clsph_status frames_write(struct frames *fr, const struct render_input *in, int index)
{
  enum clsph_status st = CLSPH_OK;
  char *path = frame_path(fr, index);
  CLSPH_CHECK(path != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(render_frame(fr->r, &fr->f, in, path, NULL, NULL));
  if (fr->first < 0) fr->first = index;
  fr->last = index;
  ++fr->count;
done:
  free(path);
  return st;
}

enum clsph_status frames_finish(struct frames *fr, int quiet)
{
  enum clsph_status st = CLSPH_OK;
  char *path = NULL, *pattern = NULL, *mp4 = NULL;
  int made = 0;
  if (fr == NULL || fr->count == 0) goto done;
  /* the movie runs over consecutive frames: those written here, and those before them that a
   * run restarted here left */
  int first = fr->first;
  for (; first > 0; --first) {
    free(path);
    path = frame_path(fr, first - 1);
    CLSPH_CHECK(path != NULL, CLSPH_E_NOMEM, "out of memory");
    if (access(path, F_OK) != 0) break;
  }
  const int count = fr->last - first + 1;
  pattern = str_printf("%s/%s_%%06d.png", fr->dir, fr->f.name);
  mp4 = str_printf("%s/%s.mp4", fr->out, fr->f.name);
  CLSPH_CHECK(pattern != NULL && mp4 != NULL, CLSPH_E_NOMEM, "out of memory");
  if (fr->o.movie) CLSPH_TRY(movie_make(pattern, first, count, fr->o.fps, mp4, &made));
  if (!quiet) {
    printf("frames: %s/%s_%06d.png .. %06d.png (%d)", fr->dir, fr->f.name, fr->first, fr->last,
           fr->count);
    if (made) printf("; movie: %s (%d frames, %d/s)", mp4, count, fr->o.fps);
    printf("\n");
  }
done:
  free(path);
  free(pattern);
  free(mp4);
  return st;
}

void frames_close(struct frames *fr)
{
  if (fr == NULL) return;
  render_destroy(fr->r);
  free(fr->out);
  free(fr->dir);
  free(fr);
}

void frames_view(const double *domain, int nwalls, const struct render_wall *walls, double view[4])
{
  double b[4] = {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  if (domain != NULL) memcpy(b, domain, sizeof b);
  for (int w = 0; w < nwalls; ++w) {
    for (int k = 0; k < walls[w].npts; ++k) {
      b[0] = fmin(b[0], walls[w].pts[2 * k]);
      b[1] = fmin(b[1], walls[w].pts[2 * k + 1]);
      b[2] = fmax(b[2], walls[w].pts[2 * k]);
      b[3] = fmax(b[3], walls[w].pts[2 * k + 1]);
    }
  }
  if (!(b[2] > b[0] && b[3] > b[1])) b[0] = b[1] = b[2] = b[3] = 0.0;
  memcpy(view, b, sizeof b);
}
