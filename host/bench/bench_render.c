/* bench_render.c: `clsph bench render`: the time of a frame for 10^4, 10^5 and 10^6 particles at
 * 1280 x 720 (--size), with the time of its parts: the field's values and colours on the host,
 * the OpenGL drawing (OSMesa, llvmpipe) with the read-back, the text, and the PNG file. The scene:
 * a jittered lattice filling a 16:9 box wall, the velocity of a row of Taylor-Green vortices,
 * field `speed` (automatic range) and, apart, `vorticity` (the host SPH curl over neighbours, the
 * costliest field). Figures are medians over --bench-reps frames after one warm-up frame (which
 * compiles llvmpipe's shaders); frames are written to --out (default out/bench_render). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "render.h"
#include "rng.h"

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static double median(double *v, int n)
{
  qsort(v, (size_t)n, sizeof *v, cmp_double);
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct scene_data {
  size_t n;
  double *pos, *vel, *vol, *kind;
  double box[8];
};

static enum clsph_status make_scene(long target, struct scene_data *s)
{
  enum clsph_status st = CLSPH_OK;
  const double lx = 16.0 / 9.0, ly = 1.0;
  const int ny = (int)lround(sqrt((double)target / lx)), nx = (int)lround((double)target / ny);
  const double dr = ly / ny, pi = 3.14159265358979323846;
  struct rng g;
  rng_seed(&g, 20240601);
  s->n = (size_t)nx * (size_t)ny;
  s->pos = malloc(2 * s->n * sizeof *s->pos);
  s->vel = malloc(2 * s->n * sizeof *s->vel);
  s->vol = malloc(s->n * sizeof *s->vol);
  s->kind = calloc(s->n, sizeof *s->kind);
  CLSPH_CHECK(s->pos && s->vel && s->vol && s->kind, CLSPH_E_NOMEM,
              "out of memory for %zu particles", s->n);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const size_t k = (size_t)j * (size_t)nx + (size_t)i;
      const double x = (i + 0.5 + 0.2 * (rng_uniform(&g) - 0.5)) * lx / nx;
      const double y = (j + 0.5 + 0.2 * (rng_uniform(&g) - 0.5)) * dr;
      s->pos[2 * k] = x;
      s->pos[2 * k + 1] = y;
      /* Taylor-Green vortices, 4 across the box */
      s->vel[2 * k] = sin(4.0 * pi * x / lx) * cos(pi * y);
      s->vel[2 * k + 1] = -(4.0 / lx) * cos(4.0 * pi * x / lx) * sin(pi * y);
      s->vol[k] = (lx / nx) * dr;
    }
  }
  const double box[8] = {0, 0, lx, 0, lx, ly, 0, ly};
  memcpy(s->box, box, sizeof box);
done:
  return st;
}

static void free_scene(struct scene_data *s)
{
  free(s->pos);
  free(s->vel);
  free(s->vol);
  free(s->kind);
  memset(s, 0, sizeof *s);
}

static enum clsph_status bench_size(struct render *r, const struct cli *cli, const char *out,
                                    long target)
{
  enum clsph_status st = CLSPH_OK;
  struct scene_data s;
  const int reps = cli->bench_reps;
  double *t = NULL;
  memset(&s, 0, sizeof s);
  CLSPH_TRY(make_scene(target, &s));
  t = malloc(6 * (size_t)reps * sizeof *t);
  CLSPH_CHECK(t != NULL, CLSPH_E_NOMEM, "out of memory");
  struct render_array arrays[4] = {
      {"pos", 2, s.pos}, {"vel", 2, s.vel}, {"vol", 1, s.vol}, {"kind", 1, s.kind}};
  struct render_wall wall = {4, s.box, 1};
  struct render_input in;
  memset(&in, 0, sizeof in);
  in.n = s.n;
  in.narrays = 4;
  in.arrays = arrays;
  in.nwalls = 1;
  in.walls = &wall;
  memcpy(in.view, (double[4]){0.0, 0.0, s.box[2], s.box[5]}, sizeof in.view);
  in.case_name = "bench";
  in.scheme = "none";
  const char *names[] = {"pos", "vel", "vol", "kind"};
  const int nc[] = {2, 2, 1, 1};
  struct field_spec speed, vort;
  CLSPH_TRY(field_find("speed", 4, names, nc, &speed));
  CLSPH_TRY(field_find("vorticity", 4, names, nc, &vort));
  char path[1200];
  int w = snprintf(path, sizeof path, "%s/speed_%zu.png", out, s.n);
  CLSPH_CHECK(w > 0 && (size_t)w < sizeof path, CLSPH_E_INPUT, "--out: path too long: %s", out);
  struct render_times rt;
  CLSPH_TRY(render_frame(r, &speed, &in, path, NULL, &rt)); /* warm-up */
  for (int k = 0; k < reps; ++k) {
    in.time = 0.01 * k;
    CLSPH_TRY(render_frame(r, &speed, &in, path, NULL, &rt));
    t[k] = rt.field;
    t[reps + k] = rt.draw;
    t[2 * reps + k] = rt.text;
    t[3 * reps + k] = rt.png;
    t[4 * reps + k] = rt.total;
  }
  const double disc = rt.disc_px;
  double m[5];
  for (int q = 0; q < 5; ++q) m[q] = median(t + q * reps, reps);
  /* vorticity: a whole frame, the field's time apart */
  w = snprintf(path, sizeof path, "%s/vorticity_%zu.png", out, s.n);
  CLSPH_CHECK(w > 0 && (size_t)w < sizeof path, CLSPH_E_INPUT, "--out: path too long: %s", out);
  const int vreps = target >= 1000000 ? (reps < 3 ? reps : 3) : reps;
  for (int k = 0; k < vreps; ++k) {
    CLSPH_TRY(render_frame(r, &vort, &in, path, NULL, &rt));
    t[k] = rt.field;
    t[reps + k] = rt.total;
  }
  const double vfield = median(t, vreps), vtotal = median(t + reps, vreps);
  printf("%10zu %7.2f %9.1f %9.1f %8.1f %8.1f %10.1f %12.1f %10.1f\n", s.n, disc, 1e3 * m[0],
         1e3 * m[1], 1e3 * m[2], 1e3 * m[3], 1e3 * m[4], 1e3 * vfield, 1e3 * vtotal);
  fflush(stdout);
done:
  free(t);
  free_scene(&s);
  return st;
}

enum clsph_status bench_render(const struct cli *cli)
{
  enum clsph_status st = CLSPH_OK;
  struct render *r = NULL;
  struct render_opts o;
  char *list = NULL;
  const char *out = cli->out_dir != NULL ? cli->out_dir : "out/bench_render";
  render_defaults(&o);
  if (cli->width > 0) {
    o.width = cli->width;
    o.height = cli->height;
  }
  o.font = cli->font;
  if (cli->colormap != NULL) CLSPH_TRY(colormap_from_name(cli->colormap, &o.map));
  if (cli->out_dir == NULL)
    CLSPH_CHECK(mkdir("out", 0755) == 0 || errno == EEXIST, CLSPH_E_IO, "cannot create out: %s",
                strerror(errno));
  CLSPH_CHECK(mkdir(out, 0755) == 0 || errno == EEXIST, CLSPH_E_IO, "cannot create %s: %s", out,
              strerror(errno));
  CLSPH_TRY(render_create(&o, &r));
  const char *gl = NULL, *font = NULL;
  render_describe(r, &gl, &font);
  printf("clsph bench render: %d x %d frames, %s; font %s; median of %d frames (after a warm-up); "
         "frames in %s\n",
         o.width, o.height, gl, font, cli->bench_reps, out);
  printf("field speed (automatic range): ms per frame by part; vorticity: its field time and its "
         "whole frame\n");
  printf("%10s %7s %9s %9s %8s %8s %10s %12s %10s\n", "particles", "disc px", "field ms", "draw ms",
         "text ms", "png ms", "frame ms", "vort. field", "vort. frame");
  list = malloc(strlen(cli->bench_sizes) + 1);
  CLSPH_CHECK(list != NULL, CLSPH_E_NOMEM, "out of memory");
  strcpy(list, cli->bench_sizes);
  for (char *tok = strtok(list, ","); tok != NULL; tok = strtok(NULL, ",")) {
    char *end = NULL;
    double v = strtod(tok, &end);
    CLSPH_CHECK(end != tok && *end == '\0' && v >= 16 && v <= 1e8, CLSPH_E_INPUT,
                "--bench-sizes: '%s' is not a particle count from 16 to 1e8", tok);
    CLSPH_TRY(bench_size(r, cli, out, (long)v));
  }
done:
  free(list);
  render_destroy(r);
  return st;
}
