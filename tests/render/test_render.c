/* test_render.c: frames of a small known scene (no OpenCL needed), checked pixel by pixel.
 *
 * The scene: a unit box wall holding a 10 x 10 lattice of particles at δr = 0.1 (pressure
 * p = 100 (x + 2 y) Pa, a solid-body rotation for the velocity), and a clockwise closed square
 * wall in its middle (a solid obstacle: filled) with no particles inside. Rendered at 480 x 320:
 *   - the PNG has that size and no time stamp or text chunk;
 *   - the corners are the background colour;
 *   - the pixel under each particle's centre is exactly the colour map's colour of its value:
 *     colours are 8-bit on the host and the disc's alpha is 1 at its centre (the disc is 26
 *     pixels across here), so llvmpipe passes the colour through unchanged: tolerance 0;
 *   - the solid band behind the box wall and the inside of the obstacle are the solid colour
 *     (flat triangles: exact), and the wall line's pixels are darker than the band;
 *   - the colour bar's bottom and top rows are the map's first and last entries;
 *   - there is text beside the colour bar (its tick labels), above it (the field's name) and in
 *     the title (case and time), and none in an empty corner;
 *   - the same input gives the same PNG bytes, twice in one renderer and in a fresh one.
 * Also: the colour tables at known entries, field names, the automatic range, and the vorticity
 * of linear velocity fields (exact with the corrected gradient, to round-off). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render.h"
#include "scene.h"
#include "tcheck.h"

#define W  480
#define H  320
#define NX 10

static double pos[2 * NX * NX], vel[2 * NX * NX], vol[NX * NX], kind[NX * NX], p[NX * NX];
static size_t n;
static const double box_pts[] = {0, 0, 1, 0, 1, 1, 0, 1}; /* counter-clockwise: fluid inside */
static const double obst_pts[] = {0.4, 0.4, 0.4, 0.6, 0.6, 0.6, 0.6, 0.4}; /* clockwise: solid */

static void make_scene(struct render_input *in, struct render_array *arrays,
                       struct render_wall *walls)
{
  n = 0;
  for (int j = 0; j < NX; ++j) {
    for (int i = 0; i < NX; ++i) {
      double x = (i + 0.5) / NX, y = (j + 0.5) / NX;
      if (x > 0.4 && x < 0.6 && y > 0.4 && y < 0.6) continue; /* inside the obstacle */
      pos[2 * n] = x;
      pos[2 * n + 1] = y;
      vel[2 * n] = -(y - 0.5);
      vel[2 * n + 1] = x - 0.5;
      vol[n] = 0.01;
      kind[n] = 0;
      p[n] = 100.0 * (x + 2.0 * y);
      ++n;
    }
  }
  arrays[0] = (struct render_array){"pos", 2, pos};
  arrays[1] = (struct render_array){"vel", 2, vel};
  arrays[2] = (struct render_array){"vol", 1, vol};
  arrays[3] = (struct render_array){"kind", 1, kind};
  arrays[4] = (struct render_array){"p", 1, p};
  walls[0] = (struct render_wall){4, box_pts, 1};
  walls[1] = (struct render_wall){4, obst_pts, 1};
  memset(in, 0, sizeof *in);
  in->n = n;
  in->narrays = 5;
  in->arrays = arrays;
  in->nwalls = 2;
  in->walls = walls;
  in->time = 1.25;
  in->case_name = "known_scene";
  in->scheme = "none";
}

static const unsigned char *px_at(const unsigned char *rgb, int x, int y)
{
  return rgb + 3 * ((size_t)y * W + (size_t)x);
}

static int same(const unsigned char *a, const unsigned char *b)
{
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

/* Pixels in [x0, x1) x [y0, y1) darker than mid-grey: glyph ink. */
static int dark_pixels(const unsigned char *rgb, int x0, int y0, int x1, int y1)
{
  int c = 0;
  for (int y = y0 < 0 ? 0 : y0; y < y1 && y < H; ++y)
    for (int x = x0 < 0 ? 0 : x0; x < x1 && x < W; ++x) c += px_at(rgb, x, y)[0] < 128;
  return c;
}

static unsigned char *read_file(const char *path, size_t *size)
{
  FILE *f = fopen(path, "rb");
  unsigned char *b = NULL;
  long s = -1;
  if (f != NULL && fseek(f, 0, SEEK_END) == 0) s = ftell(f);
  if (s > 0 && fseek(f, 0, SEEK_SET) == 0) {
    b = malloc((size_t)s);
    if (b != NULL && fread(b, 1, (size_t)s, f) != (size_t)s) {
      free(b);
      b = NULL;
    }
  }
  if (f != NULL) fclose(f);
  *size = b != NULL ? (size_t)s : 0;
  return b;
}

static void check_colormaps(void)
{
  unsigned char c[3];
  colormap_rgb(COLORMAP_VIRIDIS, 0.0, c);
  TC_CHECK(c[0] == 68 && c[1] == 1 && c[2] == 84, "viridis(0) = #440154, got %d %d %d", c[0], c[1],
           c[2]);
  colormap_rgb(COLORMAP_VIRIDIS, 1.0, c);
  TC_CHECK(c[0] == 253 && c[1] == 231 && c[2] == 37, "viridis(1) = #fde725, got %d %d %d", c[0],
           c[1], c[2]);
  colormap_rgb(COLORMAP_VIRIDIS, 0.5, c); /* entry 128: (0.127568, 0.566949, 0.550556) */
  TC_CHECK(c[0] == 33 && c[1] == 145 && c[2] == 140, "viridis(0.5) = #21918c, got %d %d %d", c[0],
           c[1], c[2]);
  colormap_rgb(COLORMAP_VIRIDIS, -3.0, c);
  TC_CHECK(c[0] == 68 && c[2] == 84, "viridis clamps below 0");
  colormap_rgb(COLORMAP_VIRIDIS, NAN, c);
  TC_CHECK(c[0] == 255 && c[1] == 0 && c[2] == 255, "NaN is magenta");
  colormap_rgb(COLORMAP_COOLWARM, 0.0, c); /* Moreland's first colour (0.2298, 0.2987, 0.7537) */
  TC_CHECK(c[0] == 59 && c[1] == 76 && c[2] == 192, "coolwarm(0) = #3b4cc0, got %d %d %d", c[0],
           c[1], c[2]);
  colormap_rgb(COLORMAP_COOLWARM, 1.0, c); /* and last (0.7057, 0.0156, 0.1502) */
  TC_CHECK(c[0] == 180 && c[1] == 4 && c[2] == 38, "coolwarm(1) = #b40426, got %d %d %d", c[0],
           c[1], c[2]);
  colormap_rgb(COLORMAP_COOLWARM, 0.5, c); /* entry 128, just past the grey centre (0.8654) */
  TC_CHECK(abs(c[0] - 221) <= 2 && abs(c[1] - 220) <= 2 && abs(c[2] - 219) <= 2,
           "coolwarm(0.5) is the light grey centre, got %d %d %d", c[0], c[1], c[2]);
  colormap_rgb(COLORMAP_KIND, 0, c);
  TC_CHECK(c[0] == 0 && c[1] == 114 && c[2] == 178, "kind 0 (fluid) is Okabe-Ito blue");
  enum colormap_kind k;
  TC_CHECK(colormap_from_name("coolwarm", &k) == CLSPH_OK && k == COLORMAP_COOLWARM,
           "colour map by name");
  TC_CHECK(colormap_from_name("jet", &k) == CLSPH_E_INPUT, "an unknown map is refused");
}

static void check_fields(void)
{
  const char *names[] = {"pos", "vel", "kind", "vol", "p"};
  const int nc[] = {2, 2, 1, 1, 1};
  struct field_spec f;
  TC_CHECK(field_find("speed", 5, names, nc, &f) == CLSPH_OK && f.how == FIELD_SPEED &&
               !f.is_signed,
           "speed is derived from vel");
  TC_CHECK(field_find("vorticity", 5, names, nc, &f) == CLSPH_OK && f.how == FIELD_VORTICITY &&
               f.is_signed,
           "vorticity is derived and signed");
  TC_CHECK(field_find("vel_y", 5, names, nc, &f) == CLSPH_OK && f.how == FIELD_COMPONENT &&
               f.comp == 1,
           "vel_y is vel's second component");
  TC_CHECK(field_find("p", 5, names, nc, &f) == CLSPH_OK && f.how == FIELD_SCALAR &&
               strstr(f.label, "(Pa)") != NULL,
           "p is stored, labelled with its unit: %s", f.label);
  TC_CHECK(field_find("kind", 5, names, nc, &f) == CLSPH_OK && f.how == FIELD_KIND,
           "kind is categorical");
  TC_CHECK(field_find("temperature", 5, names, nc, &f) == CLSPH_E_INPUT, "unknown field refused");
  TC_CHECK(field_find("vel", 5, names, nc, &f) == CLSPH_E_INPUT, "a vector is not a field");
  TC_CHECK(field_find("speed", 3, names + 2, nc + 2, &f) == CLSPH_E_INPUT, "no speed without vel");

  /* the automatic range: extremes for fewer than 200 values; speed from 0; symmetric when
   * diverging; a flat field gets a width */
  double v[100], kd[100], lo, hi;
  for (int i = 0; i < 100; ++i) {
    v[i] = 3.0 + i;
    kd[i] = i == 99 ? 1 : 0; /* a wall vertex: not drawn, not counted */
  }
  field_find("p", 5, names, nc, &f);
  field_auto_range(&f, COLORMAP_VIRIDIS, 100, v, kd, &lo, &hi);
  TC_CHECK(lo == 3.0 && hi == 101.0, "auto range of p: 3 .. 101, got %g .. %g", lo, hi);
  field_auto_range(&f, COLORMAP_COOLWARM, 100, v, kd, &lo, &hi);
  TC_CHECK(lo == -101.0 && hi == 101.0, "diverging: symmetric, got %g .. %g", lo, hi);
  field_find("speed", 5, names, nc, &f);
  field_auto_range(&f, COLORMAP_VIRIDIS, 100, v, kd, &lo, &hi);
  TC_CHECK(lo == 0.0 && hi == 101.0, "speed from 0, got %g .. %g", lo, hi);
  for (int i = 0; i < 100; ++i) v[i] = 0.0;
  field_auto_range(&f, COLORMAP_VIRIDIS, 100, v, kd, &lo, &hi);
  TC_CHECK(lo == 0.0 && hi > 0.0, "speed at rest: 0 .. %g", hi);
  /* 1000 values: the 0.5th and 99.5th percentiles leave out a spike */
  double w[1000], kw[1000];
  for (int i = 0; i < 1000; ++i) {
    w[(i * 7) % 1000] = i == 500 ? 1e9 : (double)i; /* shuffled, with one spike */
    kw[i] = 0;
  }
  field_find("p", 5, names, nc, &f);
  field_auto_range(&f, COLORMAP_VIRIDIS, 1000, w, kw, &lo, &hi);
  /* sorted: 0 .. 499, 501 .. 999, 1e9; entries ⌊0.005 × 999⌋ = 4 and ⌈0.995 × 999⌉ = 995 */
  TC_CHECK(lo == 4.0 && hi == 996.0, "percentiles 0.5 and 99.5: 4 .. 996, got %g .. %g", lo, hi);
}

/* Vorticity of linear velocity fields on a lattice cut by the domain's edges: the corrected
 * gradient is exact for them, at every particle, the edges included. */
static void check_vorticity(void)
{
  enum { M = 30 };
  static double x[2 * M * M], u[2 * M * M], vv[M * M], w[M * M];
  const double d = 1.0 / M;
  for (int j = 0; j < M; ++j) {
    for (int i = 0; i < M; ++i) {
      size_t k = (size_t)(j * M + i);
      x[2 * k] = (i + 0.5) * d + 0.1 * d * sin(3.0 * k); /* jittered */
      x[2 * k + 1] = (j + 0.5) * d + 0.1 * d * cos(5.0 * k);
      vv[k] = d * d;
    }
  }
  const double omega = 3.0, shear = 2.0;
  for (size_t k = 0; k < M * M; ++k) { /* rotation about (0.3, 0.7) plus a uniform drift */
    u[2 * k] = -omega * (x[2 * k + 1] - 0.7) + 0.4;
    u[2 * k + 1] = omega * (x[2 * k] - 0.3) - 1.1;
  }
  TC_CHECK(field_vorticity(M * M, x, u, vv, w) == CLSPH_OK, "vorticity runs");
  double err = 0.0;
  for (size_t k = 0; k < M * M; ++k) err = fmax(err, fabs(w[k] - 2.0 * omega));
  TC_NEAR(err, 0.0, 1e-9 * omega, "solid-body rotation: ω = 2Ω at every particle (largest error)");
  for (size_t k = 0; k < M * M; ++k) { /* simple shear u = γ y: ω = −γ */
    u[2 * k] = shear * x[2 * k + 1];
    u[2 * k + 1] = 0.0;
  }
  field_vorticity(M * M, x, u, vv, w);
  err = 0.0;
  for (size_t k = 0; k < M * M; ++k) err = fmax(err, fabs(w[k] + shear));
  TC_NEAR(err, 0.0, 1e-9 * shear, "simple shear: ω = −γ at every particle (largest error)");
}

static void check_frame(const char *dir)
{
  struct render_input in;
  struct render_array arrays[5];
  struct render_wall walls[2];
  struct render_opts o;
  struct render *r = NULL, *r2 = NULL;
  struct field_spec f;
  struct render_layout l;
  char path1[1024], path2[1024], path3[1024];
  unsigned char *img = NULL, *b1 = NULL, *b2 = NULL, *b3 = NULL;
  int w = 0, h = 0;
  size_t s1 = 0, s2 = 0, s3 = 0;
  make_scene(&in, arrays, walls);
  render_defaults(&o);
  snprintf(o.field, sizeof o.field, "p");
  o.width = W;
  o.height = H;
  o.fixed = 1;
  o.lo = 0.0;
  o.hi = 300.0;
  snprintf(path1, sizeof path1, "%s/known_1.png", dir);
  snprintf(path2, sizeof path2, "%s/known_2.png", dir);
  snprintf(path3, sizeof path3, "%s/known_3.png", dir);
  const char *names[] = {"pos", "vel", "vol", "kind", "p"};
  const int nc[] = {2, 2, 1, 1, 1};
  int ok = field_find("p", 5, names, nc, &f) == CLSPH_OK && render_create(&o, &r) == CLSPH_OK;
  TC_CHECK(ok, "an OSMesa renderer opens, field p");
  if (!ok) goto done;
  TC_CHECK(render_frame(r, &f, &in, path1, NULL, NULL) == CLSPH_OK, "frame 1 written");
  TC_CHECK(render_frame(r, &f, &in, path2, NULL, NULL) == CLSPH_OK, "frame 2 written");
  render_layout(r, &l);

  /* size, corners */
  ok = image_read_png(path1, &img, &w, &h) == CLSPH_OK;
  TC_CHECK(ok, "the PNG reads back");
  if (!ok) goto done;
  TC_CHECK(w == W && h == H, "image size %d x %d, want %d x %d", w, h, W, H);
  TC_CHECK(same(px_at(img, 0, 0), render_colour_bg) &&
               same(px_at(img, W - 1, H - 1), render_colour_bg) &&
               same(px_at(img, 0, H - 1), render_colour_bg),
           "the corners are the background colour");

  /* particles: the pixel under each centre has the map's colour of its value, exactly */
  int bad = 0;
  for (size_t i = 0; i < n; ++i) {
    double fx, fy;
    unsigned char want[3];
    render_to_pixel(&l, pos[2 * i], pos[2 * i + 1], &fx, &fy);
    colormap_rgb(COLORMAP_VIRIDIS, p[i] / 300.0, want);
    const unsigned char *got = px_at(img, (int)floor(fx), (int)floor(fy));
    if (!same(got, want)) {
      if (bad++ < 3)
        printf("particle %zu at (%g, %g): pixel (%d, %d) is %d %d %d, want %d %d %d\n", i,
               pos[2 * i], pos[2 * i + 1], (int)floor(fx), (int)floor(fy), got[0], got[1], got[2],
               want[0], want[1], want[2]);
    }
  }
  TC_CHECK(bad == 0, "%zu particle centres have their colour-map colour (%d do not)", n, bad);
  TC_CHECK(l.scale * 0.1 > 20.0, "discs are %g pixels across (√V = δr)", l.scale * 0.1);

  /* walls: the band behind the left wall, the obstacle's inside, and the wall line */
  double wx, wy;
  render_to_pixel(&l, 0.0, 0.5, &wx, &wy);
  const unsigned char *band = px_at(img, (int)floor(wx - 0.5 * l.band_px - 0.5), (int)floor(wy));
  TC_CHECK(same(band, render_colour_solid),
           "the band behind the wall is the solid colour: %d %d %d", band[0], band[1], band[2]);
  /* the line (anti-aliased, 1.5 pixels wide here) straddles x = wx: its darker pixel */
  const unsigned char *l0 = px_at(img, (int)floor(wx - 0.5), (int)floor(wy));
  const unsigned char *l1 = px_at(img, (int)floor(wx + 0.5), (int)floor(wy));
  const unsigned char *line = l0[0] < l1[0] ? l0 : l1;
  TC_CHECK(line[0] < render_colour_solid[0] - 40 && line[0] == line[1] && line[1] == line[2],
           "the wall line is dark grey: %d %d %d", line[0], line[1], line[2]);
  render_to_pixel(&l, 0.5, 0.5, &wx, &wy);
  const unsigned char *solid = px_at(img, (int)floor(wx), (int)floor(wy));
  TC_CHECK(same(solid, render_colour_solid), "the obstacle is filled: %d %d %d", solid[0], solid[1],
           solid[2]);
  render_to_pixel(&l, 0.5, -0.5 * l.band_px / l.scale - 0.01, &wx, &wy);
  TC_CHECK(same(px_at(img, (int)floor(wx), (int)floor(wy)), render_colour_bg),
           "beyond the band: background");

  /* the colour bar: first and last entries at its ends */
  unsigned char c0[3], c1[3];
  colormap_rgb(COLORMAP_VIRIDIS, 0.0, c0);
  colormap_rgb(COLORMAP_VIRIDIS, 1.0, c1);
  const int bx = (l.bar[0] + l.bar[2]) / 2;
  TC_CHECK(l.bar[3] - l.bar[1] > 128, "colour bar %d pixels tall (> 128: one pixel per entry)",
           l.bar[3] - l.bar[1]);
  TC_CHECK(same(px_at(img, bx, l.bar[3] - 1), c0) && same(px_at(img, bx, l.bar[1]), c1),
           "the bar runs from viridis(0) at the bottom to viridis(1) at the top");

  /* text: tick labels right of the bar, the field's name above, the title; an empty corner */
  const int lh = l.label_px;
  int ticks_ink = dark_pixels(img, l.bar[2] + 2, l.bar[1] - lh, W, l.bar[3] + lh);
  int name_ink = dark_pixels(img, l.bar[0], l.bar[1] - 3 * lh, W, l.bar[1] - 2);
  int title_ink = dark_pixels(img, 0, 0, W / 2, l.margin + 2 * l.title_px);
  int empty = dark_pixels(img, 0, H - l.margin, l.margin, H);
  printf("ink: tick labels %d, field name %d, title %d pixels, empty corner %d\n", ticks_ink,
         name_ink, title_ink, empty);
  TC_CHECK(ticks_ink > 50, "tick labels drawn beside the colour bar (%d dark pixels)", ticks_ink);
  TC_CHECK(name_ink > 30, "the field's name drawn above the colour bar (%d)", name_ink);
  TC_CHECK(title_ink > 50, "the title drawn (%d)", title_ink);
  TC_CHECK(empty == 0, "no ink in an empty corner (%d)", empty);

  /* determinism: the same bytes twice, and from a fresh renderer */
  TC_CHECK(render_create(&o, &r2) == CLSPH_OK, "a second renderer opens");
  if (r2 != NULL) TC_CHECK(render_frame(r2, &f, &in, path3, NULL, NULL) == CLSPH_OK, "frame 3");
  b1 = read_file(path1, &s1);
  b2 = read_file(path2, &s2);
  b3 = read_file(path3, &s3);
  TC_CHECK(b1 != NULL && s1 == s2 && memcmp(b1, b2, s1) == 0, "same input, same PNG bytes");
  TC_CHECK(b1 != NULL && s1 == s3 && memcmp(b1, b3, s1) == 0,
           "same bytes from a fresh renderer (%zu bytes)", s1);
  /* no time stamp and no text chunks */
  int chunks = 0;
  for (size_t k = 0; b1 != NULL && k + 4 <= s1; ++k) {
    static const char *const forbidden[] = {"tIME", "tEXt", "zTXt", "iTXt"};
    for (int q = 0; q < 4; ++q) chunks += memcmp(b1 + k, forbidden[q], 4) == 0;
  }
  TC_CHECK(b1 != NULL && memcmp(b1 + 1, "PNG", 3) == 0 && chunks == 0,
           "a PNG with no tIME or text chunk");

  /* the kind legend, and a vorticity frame with its diverging map and automatic range */
  struct field_spec fk, fv;
  field_find("kind", 5, names, nc, &fk);
  field_find("vorticity", 5, names, nc, &fv);
  TC_CHECK(render_frame(r2, &fk, &in, NULL, NULL, NULL) == CLSPH_OK, "kind frame");
  render_layout(r2, &l);
  const unsigned char *pix = render_pixels(r2, &w, &h);
  TC_CHECK(l.map == COLORMAP_KIND &&
               dark_pixels(pix, l.bar[2], l.bar[1], W, l.bar[1] + 2 * lh) > 20,
           "kind: a legend with the kind's name");
  double range[2];
  render_destroy(r2);
  r2 = NULL;
  o.fixed = 0;
  snprintf(o.field, sizeof o.field, "vorticity");
  TC_CHECK(render_create(&o, &r2) == CLSPH_OK, "renderer, automatic range");
  TC_CHECK(r2 != NULL && render_frame(r2, &fv, &in, NULL, range, NULL) == CLSPH_OK,
           "vorticity frame");
  if (r2 != NULL) render_layout(r2, &l);
  TC_CHECK(l.map == COLORMAP_COOLWARM && range[0] == -range[1] && fabs(range[1] - 2.0) < 1e-6,
           "vorticity of a rotation at 1 rad/s: coolwarm, range ±2 (got %g .. %g)", range[0],
           range[1]);
done:
  free(img);
  free(b1);
  free(b2);
  free(b3);
  render_destroy(r);
  render_destroy(r2);
}

/* A renderer for 3-D frames: W x H, the pressure from 0 to 100 Pa, the camera given; and the
 * field p of the arrays pos (3), vol, kind, p. NULL (a failed check) when none opens. */
static struct render *open3(struct render_camera cam, struct field_spec *f)
{
  struct render_opts o;
  render_defaults(&o);
  o.width = W;
  o.height = H;
  o.fixed = 1;
  o.lo = 0.0;
  o.hi = 100.0;
  o.camera_set = 1;
  o.camera = cam;
  const char *names[] = {"pos", "vol", "kind", "p"};
  const int ncomp[] = {3, 1, 1, 1};
  TC_CHECK(field_find("p", 4, names, ncomp, f) == CLSPH_OK, "field p");
  struct render *r = NULL;
  if (render_create(&o, &r) != CLSPH_OK) {
    TC_CHECK(0, "no renderer");
    return NULL;
  }
  return r;
}

/* A 3-D frame (pos of 3 components): the camera at (0, −1.5, 0) looking at the origin, z up, 30°;
 * particles of volume 1e-3 (spheres 0.1 across) at the origin (A, p = 0), 0.3 to its right (B,
 * p = 100) and, in a second frame, a third in front of A on the axis (C, p = 100). Checked:
 *   - A's centre lies at the view's centre (the layout's origin), B's 0.3 m times the scale to its
 *     right: the perspective projection, to a pixel;
 *   - A's centre pixel is its map colour times the shader's light at the sphere's front, n =
 *     (0, 0, 1): 0.35 + 0.65 L_z plus the highlight 0.25 (n·h)^40, L = (−0.40, 0.50, 0.77)/|L|,
 *     h = (L + (0, 0, 1))/|L + (0, 0, 1)|, to 2 levels (llvmpipe's float shading, 8-bit out);
 *   - the upper left of a sphere (towards the light) is brighter than its lower right;
 *   - the nearer sphere covers the farther: with C in front, A's centre pixel is C's colour;
 *   - a camera looking at its own eye, or with up along its view, is refused. */
static void check_frame3(const char *dir)
{
  double pos3[9] = {0, 0, 0, 0.3, 0, 0, 0, -0.5, 0}, vol3[3] = {1e-3, 1e-3, 1e-3},
         kind3[3] = {0, 0, 0}, p3[3] = {0, 100, 100};
  struct render_array arrays[4] = {
      {"pos", 3, pos3}, {"vol", 1, vol3}, {"kind", 1, kind3}, {"p", 1, p3}};
  struct render_input in;
  memset(&in, 0, sizeof in);
  in.n = 2;
  in.narrays = 4;
  in.arrays = arrays;
  in.case_name = "spheres";
  struct field_spec f;
  struct render *r = open3((struct render_camera){{0, -1.5, 0}, {0, 0, 0}, {0, 0, 1}, 30.0}, &f);
  if (r == NULL) return;
  char path[1024];
  snprintf(path, sizeof path, "%s/spheres.png", dir);
  TC_CHECK(render_frame(r, &f, &in, path, NULL, NULL) == CLSPH_OK, "the 3-D frame");
  struct render_layout l;
  render_layout(r, &l);
  int w = 0, h = 0;
  const unsigned char *rgb = render_pixels(r, &w, &h);
  const int ax = (int)floor(l.origin[0]), ay = (int)floor(l.origin[1]);
  const int bx = (int)floor(l.origin[0] + 0.3 * l.scale);
  const double rad = 0.5 * 0.1 * l.scale; /* A's radius, pixels */
  TC_CHECK(rad > 12.0, "spheres of %.1f pixels", 2.0 * rad);
  const double lz = 0.77 / sqrt(0.40 * 0.40 + 0.50 * 0.50 + 0.77 * 0.77);
  const double hz = (lz + 1.0) / sqrt(2.0 + 2.0 * lz);
  const double shade = 0.35 + 0.65 * lz, spec = 0.25 * pow(hz, 40.0);
  unsigned char base[3];
  colormap_rgb(COLORMAP_VIRIDIS, 0.0, base);
  const unsigned char *pa = px_at(rgb, ax, ay);
  for (int k = 0; k < 3; ++k) {
    const double want = fmin(255.0, base[k] * shade + 255.0 * spec);
    TC_NEAR(pa[k], want, 2.0, "A's centre, channel %d (base %d)", k, base[k]);
  }
  colormap_rgb(COLORMAP_VIRIDIS, 1.0, base);
  const unsigned char *pb = px_at(rgb, bx, ay);
  TC_NEAR(pb[1], fmin(255.0, base[1] * shade + 255.0 * spec), 2.0, "B's centre, green");
  const int d = (int)lround(0.4 * rad);
  const unsigned char *ul = px_at(rgb, ax - d, ay - d), *lr = px_at(rgb, ax + d, ay + d);
  TC_CHECK(ul[0] + ul[1] + ul[2] > lr[0] + lr[1] + lr[2], "lit from the upper left (%d > %d)",
           ul[0] + ul[1] + ul[2], lr[0] + lr[1] + lr[2]);
  in.n = 3; /* C in front of A */
  TC_CHECK(render_frame(r, &f, &in, NULL, NULL, NULL) == CLSPH_OK, "the frame with C");
  rgb = render_pixels(r, &w, &h);
  TC_NEAR(px_at(rgb, ax, ay)[1], fmin(255.0, base[1] * shade + 255.0 * spec), 2.0,
          "C covers A: A's centre shows C's colour");
  render_destroy(r);
  struct render_camera bad = {{1, 2, 3}, {1, 2, 3}, {0, 0, 1}, 30.0};
  TC_CHECK(render_check_camera(&bad, "test") == CLSPH_E_INPUT, "a camera looking at its eye");
  bad = (struct render_camera){{0, 0, 5}, {0, 0, 0}, {0, 0, 1}, 30.0};
  TC_CHECK(render_check_camera(&bad, "test") == CLSPH_E_INPUT, "up along the view");
}

/* A box's 12 faces (x0, y0, z0, x1, y1, z1), counter-clockwise seen from the fluid: inside
 * (a container) or outside (an obstacle), through scene_surfaces3 as a run draws them. */
static size_t box_faces(const double b[6], int container, double *tri)
{
  struct scene s;
  struct scene_wall w;
  memset(&s, 0, sizeof s);
  memset(&w, 0, sizeof w);
  s.dim = 3;
  s.nwalls = 1;
  s.walls = &w;
  w.box3d = container ? 1 : 2;
  w.shape = SCENE_BOX3;
  memcpy(w.box3, b, sizeof w.box3);
  double *t = NULL;
  size_t nt = 0;
  const double zero[3] = {0.0, 0.0, 0.0};
  if (scene_surfaces3(&s, NULL, zero, &t, &nt) != CLSPH_OK || nt != 12) {
    free(t);
    return 0;
  }
  memcpy(tri, t, nt * 9 * sizeof *t);
  free(t);
  return nt;
}

/* 3-D frames draw the walls' faces seen from the fluid, lit flat, before the spheres, with a depth
 * test. The camera of check_frame3 (at (0, −1.5, 0), looking along +y) in a container box
 * [−0.5, 0.5]³ seen from outside, and an obstacle cube 0.2 wide at y = −0.3 (between the camera
 * and the origin). Checked:
 *   - the container's near face (y = −0.5) is left out and its far face (y = 0.5, seen face on)
 *     drawn in the solid grey times 0.6 + 0.4 L_z, to 2 levels;
 *   - a sphere at the origin is drawn over the far face;
 *   - the obstacle hides a sphere behind it (the centre pixel is the face's grey again);
 *   - a camera inside the container (a field of view of 120°), its floor reaching behind it, sees
 *     the floor (cut at the near plane) in the view's lower part: grey lit by L_y. */
static void check_faces3(const char *dir)
{
  double pos3[3] = {0, 0, 0}, vol3[1] = {1e-3}, kind3[1] = {0}, p3[1] = {0};
  struct render_array arrays[4] = {
      {"pos", 3, pos3}, {"vol", 1, vol3}, {"kind", 1, kind3}, {"p", 1, p3}};
  double tri[2 * 12 * 9];
  const double tank[6] = {-0.5, -0.5, -0.5, 0.5, 0.5, 0.5};
  const double cube[6] = {-0.1, -0.4, -0.1, 0.1, -0.2, 0.1};
  const size_t nt = box_faces(tank, 1, tri), nc = box_faces(cube, 0, tri + 9 * 12);
  TC_CHECK(nt == 12 && nc == 12, "a box's faces: 12 triangles (%zu, %zu)", nt, nc);
  struct render_input in;
  memset(&in, 0, sizeof in);
  in.n = 0;
  in.narrays = 4;
  in.arrays = arrays;
  in.nsurf3 = 12;
  in.surf3 = tri;
  in.case_name = "faces";
  struct field_spec f;
  struct render *r = open3((struct render_camera){{0, -1.5, 0}, {0, 0, 0}, {0, 0, 1}, 30.0}, &f);
  if (r == NULL) return;
  const double nl = sqrt(0.40 * 0.40 + 0.50 * 0.50 + 0.77 * 0.77);
  const double face_on = 0.6 + 0.4 * 0.77 / nl, floor_lit = 0.6 + 0.4 * 0.50 / nl;
  char path[1024];
  snprintf(path, sizeof path, "%s/faces.png", dir);
  TC_CHECK(render_frame(r, &f, &in, path, NULL, NULL) == CLSPH_OK, "the frame of the faces");
  struct render_layout l;
  render_layout(r, &l);
  int w = 0, h = 0;
  const unsigned char *rgb = render_pixels(r, &w, &h);
  const int cx = (int)floor(l.origin[0]), cy = (int)floor(l.origin[1]);
  TC_NEAR(px_at(rgb, cx, cy)[0], render_colour_solid[0] * face_on, 2.0,
          "the far face, seen face on, and not the near one");
  in.n = 1; /* the sphere at the origin, in front of the far face */
  TC_CHECK(render_frame(r, &f, &in, NULL, NULL, NULL) == CLSPH_OK, "the frame with a sphere");
  rgb = render_pixels(r, &w, &h);
  unsigned char base[3];
  colormap_rgb(COLORMAP_VIRIDIS, 0.0, base);
  const double lz = 0.77 / nl, hz = (lz + 1.0) / sqrt(2.0 + 2.0 * lz);
  for (int k = 0; k < 3; ++k) /* check_frame3's sphere centre */
    TC_NEAR(px_at(rgb, cx, cy)[k],
            fmin(255.0, base[k] * (0.35 + 0.65 * lz) + 255.0 * 0.25 * pow(hz, 40.0)), 2.0,
            "the sphere over the far face, channel %d", k);
  in.nsurf3 = 24; /* the cube in front of it */
  TC_CHECK(render_frame(r, &f, &in, NULL, NULL, NULL) == CLSPH_OK, "the frame with the cube");
  rgb = render_pixels(r, &w, &h);
  TC_NEAR(px_at(rgb, cx, cy)[0], render_colour_solid[0] * face_on, 2.0,
          "the cube's near face hides the sphere");
  TC_NEAR(px_at(rgb, cx, cy)[1], render_colour_solid[1] * face_on, 2.0,
          "the cube's near face hides the sphere (green)");
  render_destroy(r);
  r = NULL;
  /* a camera inside, looking along +y: the floor at z = −0.5 reaches behind it */
  in.n = 0;
  in.nsurf3 = 12;
  r = open3((struct render_camera){{0, -0.3, 0}, {0, 0.5, 0}, {0, 0, 1}, 120.0}, &f);
  if (r == NULL) return;
  TC_CHECK(render_frame(r, &f, &in, NULL, NULL, NULL) == CLSPH_OK, "the frame from inside");
  render_layout(r, &l);
  rgb = render_pixels(r, &w, &h);
  const int by = (int)floor(l.origin[1]) + (int)(0.8 * (H - l.origin[1]));
  TC_NEAR(px_at(rgb, (int)floor(l.origin[0]), by)[0], render_colour_solid[0] * floor_lit, 2.0,
          "the floor below the view's centre, cut at the near plane");
  render_destroy(r);
}

int main(int argc, char **argv)
{
  const char *dir = argc > 1 ? argv[1] : ".";
  check_colormaps();
  check_fields();
  check_vorticity();
  check_frame(dir);
  check_frame3(dir);
  check_faces3(dir);
  return tc_finish("test_render");
}
