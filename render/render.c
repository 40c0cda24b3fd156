/* render.c: the layout of a frame, and its drawing from host arrays (see render.h).
 *
 * Layout of a W x H frame (sizes scale with u = H/720, with floors for small images):
 *   top left      the case name and the simulated time, t = ... s (24u pixels)
 *   top right     the scheme and the number of particles drawn (17u)
 *   right         the colour bar (22u wide, at most 62% of H tall) under the field's name and
 *                 unit, with numbered ticks at 1, 2 or 5 × 10^k; for `kind`, a legend of the
 *                 kinds present
 *   the rest      the view (the particles' and walls' box, or the given one), uniformly scaled
 *                 and centred, y up
 * Draw order: the solid side of the walls (a band 10u pixels wide behind each wall segment, with
 * the corners closed; a closed wall that holds the solid inside is filled), the particles in the
 * order of the arrays (discs of diameter √V), the wall lines (2u pixels, anti-aliased), the
 * colour bar; then the text, blended over the pixels read back. Colours are looked up on the
 * host, 8-bit, and reach the pixels of a disc's centre unchanged. */
#include "render.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "draw.h"
#include "text.h"

const unsigned char render_colour_bg[3] = {255, 255, 255};
const unsigned char render_colour_solid[3] = {178, 178, 178};
const unsigned char render_colour_wall[3] = {64, 64, 64};
const unsigned char render_colour_text[3] = {25, 25, 25};
static const unsigned char colour_faint[3] = {96, 96, 96};

struct render {
  struct render_opts o;
  struct draw *draw;
  struct text *text;
  unsigned char *rgb;          /* the frame, w x h x 3, top row first */
  struct render_layout layout; /* of the last frame */
  /* per-particle scratch, grown as needed */
  size_t cap;
  double *val;
  float *xy, *diam;
  unsigned char *col;
  size_t *order; /* drawn particles: small points of 1, of 2 pixels, then discs */
  /* wall triangles and lines, pixel coordinates */
  float *tri, *lines;
  size_t tri_cap, lines_cap, ntri, nlines;
  /* 3-D frames: the camera (the options', or the first frame's default, kept) and the depths */
  int have_camera;
  struct render_camera cam;
  struct render_depth *depth;
  size_t depth_cap;
  /* the last 3-D frame's projection (sphere_arrays): the camera's frame, the focal length and the
   * view's centre in pixels, and zref, the distance whose depth value is 1 (z_ndc = zref/z) */
  struct proj3 {
    double eye[3], fwd[3], right[3], up[3], focal, cx, cy, zref;
  } pj;
  float *sxyz, *face;  /* the spheres' pixel xyz; the walls' faces, 3 x 3 floats each */
  unsigned char *fcol; /* the faces' colours, 3 x 3 bytes each */
  size_t sxyz_cap, face_cap, fcol_cap, nface;
};

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

enum colormap_kind render_map_for(const struct field_spec *f, enum colormap_kind asked)
{
  if (asked != COLORMAP_AUTO) return asked;
  return f->how == FIELD_KIND ? COLORMAP_KIND : f->is_signed ? COLORMAP_COOLWARM : COLORMAP_VIRIDIS;
}

static double dot3(const double *a, const double *b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double *a, const double *b, double *c)
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

void render_default_camera(const double box[6], double fov, struct render_camera *c)
{
  static const double dir[3] = {0.55, -0.75, 0.45};
  const double nd = sqrt(dot3(dir, dir));
  double half = 0.0;
  memset(c, 0, sizeof *c);
  c->fov = fov > 0.0 ? fov : 30.0;
  c->up[2] = 1.0;
  for (int a = 0; a < 3; ++a) {
    c->at[a] = 0.5 * (box[a] + box[3 + a]);
    half += 0.25 * (box[3 + a] - box[a]) * (box[3 + a] - box[a]);
  }
  /* the box's bounding sphere fills the field of view's height */
  const double dist = fmax(sqrt(half), 1e-9) / sin(0.5 * c->fov * 3.141592653589793 / 180.0);
  for (int a = 0; a < 3; ++a) c->eye[a] = c->at[a] + dist * dir[a] / nd;
}

enum clsph_status render_check_camera(const struct render_camera *c, const char *what)
{
  enum clsph_status st = CLSPH_OK;
  int finite = isfinite(c->fov);
  for (int a = 0; a < 3; ++a)
    finite &= isfinite(c->eye[a]) && isfinite(c->at[a]) && isfinite(c->up[a]);
  CLSPH_CHECK(finite, CLSPH_E_INPUT, "%s: the camera's numbers must be finite", what);
  const double v[3] = {c->at[0] - c->eye[0], c->at[1] - c->eye[1], c->at[2] - c->eye[2]};
  double x[3];
  cross3(v, c->up, x);
  CLSPH_CHECK(dot3(v, v) > 0.0, CLSPH_E_INPUT,
              "%s: the camera looks at its own eye (%g, %g, %g): look_at must be elsewhere", what,
              c->eye[0], c->eye[1], c->eye[2]);
  CLSPH_CHECK(dot3(x, x) > 1e-12 * dot3(v, v) * dot3(c->up, c->up), CLSPH_E_INPUT,
              "%s: the camera's up (%g, %g, %g) is along its view (or zero): give an up across it",
              what, c->up[0], c->up[1], c->up[2]);
  CLSPH_CHECK(c->fov > 1.0 && c->fov < 170.0, CLSPH_E_INPUT,
              "%s: the field of view fov = %g must be between 1 and 170 degrees", what, c->fov);
done:
  return st;
}

void render_defaults(struct render_opts *o)
{
  memset(o, 0, sizeof *o);
  snprintf(o->field, sizeof o->field, "speed");
  o->width = 1280;
  o->height = 720;
  o->map = COLORMAP_AUTO;
}

enum clsph_status render_create(const struct render_opts *o, struct render **out)
{
  enum clsph_status st = CLSPH_OK;
  struct render *r = calloc(1, sizeof *r);
  CLSPH_CHECK(r != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_CHECK(o->width >= 16 && o->width <= 8192 && o->height >= 16 && o->height <= 8192,
              CLSPH_E_INPUT, "a frame of %d x %d pixels: each side must be from 16 to 8192",
              o->width, o->height);
  CLSPH_CHECK(!o->fixed || (isfinite(o->lo) && isfinite(o->hi) && o->lo < o->hi), CLSPH_E_INPUT,
              "colour range %g .. %g: the low end must be below the high end", o->lo, o->hi);
  r->o = *o;
  r->rgb = malloc((size_t)o->width * (size_t)o->height * 3);
  CLSPH_CHECK(r->rgb != NULL, CLSPH_E_NOMEM, "out of memory for a %d x %d frame", o->width,
              o->height);
  CLSPH_TRY(text_open(o->font, &r->text));
  r->o.font = NULL; /* not kept: the caller's string */
  CLSPH_TRY(draw_create(o->width, o->height, &r->draw));
  *out = r;
  r = NULL;
done:
  render_destroy(r);
  return st;
}

void render_set_range(struct render *r, double lo, double hi)
{
  r->o.fixed = 1;
  r->o.lo = lo;
  r->o.hi = hi;
}

void render_extend_box(const struct field_spec *f, const struct render_input *in, double box[6])
{
  const struct render_array *pos = field_array(in, "pos"), *kind = field_array(in, "kind");
  if (pos == NULL || kind == NULL || pos->ncomp != 3) return;
  for (size_t i = 0; i < in->n; ++i) {
    if (!field_drawn(f, (int)kind->v[i])) continue;
    for (int a = 0; a < 3; ++a) {
      const double x = pos->v[3 * i + (size_t)a];
      if (!isfinite(x)) continue;
      box[a] = fmin(box[a], x);
      box[3 + a] = fmax(box[3 + a], x);
    }
  }
}

void render_set_view3(struct render *r, const double box[6])
{
  if (r->o.camera_set || r->have_camera) return;
  memcpy(r->o.box3, box, sizeof r->o.box3);
  r->o.box3_set = 1;
}

void render_layout(const struct render *r, struct render_layout *out)
{
  *out = r->layout;
}

void render_to_pixel(const struct render_layout *l, double x, double y, double *px, double *py)
{
  *px = l->origin[0] + l->scale * (x - l->view[0]);
  *py = l->origin[1] + l->scale * (l->view[3] - y);
}

const unsigned char *render_pixels(const struct render *r, int *width, int *height)
{
  *width = r->o.width;
  *height = r->o.height;
  return r->rgb;
}

void render_describe(const struct render *r, const char **gl, const char **font)
{
  *gl = draw_renderer(r->draw);
  *font = text_font_path(r->text);
}

void render_destroy(struct render *r)
{
  if (r == NULL) return;
  draw_destroy(r->draw);
  text_close(r->text);
  free(r->rgb);
  free(r->val);
  free(r->xy);
  free(r->diam);
  free(r->col);
  free(r->order);
  free(r->tri);
  free(r->lines);
  free(r->depth);
  free(r->sxyz);
  free(r->face);
  free(r->fcol);
  free(r);
}

/* ---- scratch ---- */

static enum clsph_status reserve(struct render *r, size_t n)
{
  enum clsph_status st = CLSPH_OK;
  if (n <= r->cap) goto done;
  free(r->val);
  free(r->xy);
  free(r->diam);
  free(r->col);
  free(r->order);
  r->val = malloc(n * sizeof *r->val);
  r->xy = malloc(2 * n * sizeof *r->xy);
  r->diam = malloc(n * sizeof *r->diam);
  r->col = malloc(3 * n);
  r->order = malloc(n * sizeof *r->order);
  r->cap = n;
  if (r->val == NULL || r->xy == NULL || r->diam == NULL || r->col == NULL || r->order == NULL) {
    r->cap = 0;
    CLSPH_CHECK(0, CLSPH_E_NOMEM, "out of memory drawing %zu particles", n);
  }
done:
  return st;
}

/* Room for `more` floats in a growing array. */
static enum clsph_status grow(float **a, size_t *cap, size_t used, size_t more)
{
  enum clsph_status st = CLSPH_OK;
  if (used + more <= *cap) goto done;
  size_t c = *cap ? *cap : 1024;
  while (c < used + more) c *= 2;
  float *p = realloc(*a, c * sizeof *p);
  CLSPH_CHECK(p != NULL, CLSPH_E_NOMEM, "out of memory for the walls");
  *a = p;
  *cap = c;
done:
  return st;
}

/* ---- the view ---- */

/* World (m, y up) to pixels (y down). */
struct xform {
  double s;        /* pixels per metre */
  double ox, oy;   /* pixel position of the view's (x0, y1) corner */
  double vx0, vy1; /* that corner, m */
  double band;     /* solid band behind a wall, m */
};

static void to_px(const struct xform *x, double wx, double wy, float *p)
{
  p[0] = (float)(x->ox + x->s * (wx - x->vx0));
  p[1] = (float)(x->oy + x->s * (x->vy1 - wy));
}

/* The side of a particle's square: √V, or the typical spacing when it has no volume. */
static double side(double vol, double spacing)
{
  return vol > 0.0 && isfinite(vol) ? sqrt(vol) : spacing;
}

/* The box of the drawn particles (with their radius) and the walls. */
static void view_box(const struct field_spec *f, const struct render_input *in, const double *pos,
                     const double *vol, const double *kind, double spacing, double box[4])
{
  double b[4] = {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (size_t i = 0; i < in->n; ++i) {
    if (!field_drawn(f, (int)kind[i])) continue;
    double x = pos[2 * i], y = pos[2 * i + 1], rad = 0.5 * side(vol[i], spacing);
    if (!isfinite(x) || !isfinite(y) || !isfinite(rad)) continue;
    b[0] = fmin(b[0], x - rad);
    b[1] = fmin(b[1], y - rad);
    b[2] = fmax(b[2], x + rad);
    b[3] = fmax(b[3], y + rad);
  }
  for (int w = 0; w < in->nwalls; ++w) {
    for (int k = 0; k < in->walls[w].npts; ++k) {
      b[0] = fmin(b[0], in->walls[w].pts[2 * k]);
      b[1] = fmin(b[1], in->walls[w].pts[2 * k + 1]);
      b[2] = fmax(b[2], in->walls[w].pts[2 * k]);
      b[3] = fmax(b[3], in->walls[w].pts[2 * k + 1]);
    }
  }
  if (!(b[2] >= b[0] && b[3] >= b[1])) b[0] = b[1] = 0.0, b[2] = b[3] = 1.0;
  for (int a = 0; a < 2; ++a) { /* a flat box gets a size */
    if (b[2 + a] - b[a] < 1e-12 * (1.0 + fabs(b[a]))) {
      double c = b[a];
      b[a] = c - 0.5;
      b[2 + a] = c + 0.5;
    }
  }
  memcpy(box, b, sizeof b);
}

/* ---- walls ---- */

/* Two triangles of the quad a b c d (in order around it), world coordinates. */
static void quad(struct render *r, const struct xform *x, const double *a, const double *b,
                 const double *c, const double *d)
{
  float *t = r->tri + 2 * 3 * r->ntri;
  to_px(x, a[0], a[1], t);
  to_px(x, b[0], b[1], t + 2);
  to_px(x, c[0], c[1], t + 4);
  to_px(x, a[0], a[1], t + 6);
  to_px(x, c[0], c[1], t + 8);
  to_px(x, d[0], d[1], t + 10);
  r->ntri += 2;
}

/* Unit normal into the fluid of the edge a -> b (fluid on the left), and whether it has length. */
static int inward(const double *a, const double *b, double n[2])
{
  double dx = b[0] - a[0], dy = b[1] - a[1], len = hypot(dx, dy);
  if (!(len > 0.0)) return 0;
  n[0] = -dy / len;
  n[1] = dx / len;
  return 1;
}

/* The corner of the band at b between the edges a -> b and b -> c, whose inward normals are n and
 * m. Where the path turns left (the fluid inside the turn) the bands of the two edges leave a gap
 * on the solid side: the quadrilateral b, b − w n, the miter point b − w (n + m)/(1 + n·m),
 * b − w m closes it; past a 120° turn the miter grows long, and the bevel triangle b, b − w n,
 * b − w m closes it instead. Where the path turns right the bands overlap. */
static void corner(struct render *r, const struct xform *x, const double *a, const double *b,
                   const double *c)
{
  double n[2], m[2];
  if (!inward(a, b, n) || !inward(b, c, m)) return;
  const double turn = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
  if (turn <= 0.0) return;
  const double w = x->band, cosine = n[0] * m[0] + n[1] * m[1];
  const double p1[2] = {b[0] - w * n[0], b[1] - w * n[1]};
  const double p3[2] = {b[0] - w * m[0], b[1] - w * m[1]};
  if (1.0 + cosine > 0.5) {
    const double k = w / (1.0 + cosine);
    const double p2[2] = {b[0] - k * (n[0] + m[0]), b[1] - k * (n[1] + m[1])};
    quad(r, x, b, p1, p2, p3);
  } else {
    quad(r, x, b, p1, p3, p3); /* a triangle, and a degenerate one that covers nothing */
  }
}

static enum clsph_status wall_geometry(struct render *r, const struct render_input *in,
                                       const struct xform *x)
{
  enum clsph_status st = CLSPH_OK;
  r->ntri = r->nlines = 0;
  for (int wi = 0; wi < in->nwalls; ++wi) {
    const struct render_wall *w = &in->walls[wi];
    const int np = w->npts, nseg = w->closed ? np : np - 1;
    if (np < 2) continue;
    CLSPH_TRY(grow(&r->lines, &r->lines_cap, 4 * r->nlines, 4 * (size_t)nseg));
    for (int k = 0; k < nseg; ++k) {
      to_px(x, w->pts[2 * k], w->pts[2 * k + 1], r->lines + 4 * r->nlines);
      int k1 = (k + 1) % np;
      to_px(x, w->pts[2 * k1], w->pts[2 * k1 + 1], r->lines + 4 * r->nlines + 2);
      ++r->nlines;
    }
    double area = 0.0; /* > 0: counter-clockwise, the fluid inside */
    for (int k = 0; w->closed && k < np; ++k) {
      const double *a = w->pts + 2 * k, *b = w->pts + 2 * ((k + 1) % np);
      area += a[0] * b[1] - b[0] * a[1];
    }
    if (w->closed && area < 0.0) continue; /* a solid inside: filled in draw_walls */
    /* the band on the solid side of each segment, and the corners where it opens (the fluid on
     * the inside of a left turn) */
    CLSPH_TRY(grow(&r->tri, &r->tri_cap, 6 * r->ntri, 6 * 4 * (size_t)nseg));
    for (int k = 0; k < nseg; ++k) {
      const double *a = w->pts + 2 * k, *b = w->pts + 2 * ((k + 1) % np);
      double n[2];
      if (!inward(a, b, n)) continue;
      const double a2[2] = {a[0] - x->band * n[0], a[1] - x->band * n[1]};
      const double b2[2] = {b[0] - x->band * n[0], b[1] - x->band * n[1]};
      quad(r, x, a, b, b2, a2);
      if (!w->closed && k == nseg - 1) continue;
      const double *c = w->pts + 2 * ((k + 2) % np);
      corner(r, x, a, b, c);
    }
  }
  /* where an open wall ends at the start of another (a lid on a tank), their bands join too */
  for (int wa = 0; wa < in->nwalls; ++wa) {
    const struct render_wall *A = &in->walls[wa];
    if (A->closed || A->npts < 2) continue;
    const double *a = A->pts + 2 * (A->npts - 2), *b = A->pts + 2 * (A->npts - 1);
    for (int wb = 0; wb < in->nwalls; ++wb) {
      const struct render_wall *B = &in->walls[wb];
      if (wb == wa || B->closed || B->npts < 2) continue;
      const double tol = 1e-9 * (1.0 + fabs(b[0]) + fabs(b[1]));
      if (fabs(B->pts[0] - b[0]) > tol || fabs(B->pts[1] - b[1]) > tol) continue;
      CLSPH_TRY(grow(&r->tri, &r->tri_cap, 6 * r->ntri, 6 * 2));
      corner(r, x, a, b, B->pts + 2);
    }
  }
done:
  return st;
}

static enum clsph_status fill_solids(struct render *r, const struct render_input *in,
                                     const struct xform *x)
{
  enum clsph_status st = CLSPH_OK;
  float *poly = NULL;
  for (int wi = 0; wi < in->nwalls; ++wi) {
    const struct render_wall *w = &in->walls[wi];
    double area = 0.0;
    for (int k = 0; w->closed && k < w->npts; ++k) {
      const double *a = w->pts + 2 * k, *b = w->pts + 2 * ((k + 1) % w->npts);
      area += a[0] * b[1] - b[0] * a[1];
    }
    if (!w->closed || !(area < 0.0) || w->npts < 3) continue;
    poly = malloc(2 * (size_t)w->npts * sizeof *poly);
    CLSPH_CHECK(poly != NULL, CLSPH_E_NOMEM, "out of memory for a wall");
    for (int k = 0; k < w->npts; ++k) to_px(x, w->pts[2 * k], w->pts[2 * k + 1], poly + 2 * k);
    draw_polygon(r->draw, w->npts, poly, render_colour_solid);
    free(poly);
    poly = NULL;
  }
done:
  free(poly);
  return st;
}

/* ---- the colour bar ---- */

/* Ticks at multiples of 1, 2 or 5 × 10^k inside [lo, hi], about `want` of them. */
static int ticks(double lo, double hi, int want, double *at, int max)
{
  double raw = (hi - lo) / (want > 1 ? want - 1 : 1);
  double mag = pow(10.0, floor(log10(raw)));
  double norm = raw / mag;
  double step = (norm < 1.5 ? 1.0 : norm < 3.0 ? 2.0 : norm < 7.0 ? 5.0 : 10.0) * mag;
  int n = 0;
  for (double k = ceil(lo / step - 1e-9); n < max; k += 1.0) {
    double v = k * step;
    if (v > hi + 1e-9 * step) break;
    if (fabs(v) < 1e-9 * step) v = 0.0; /* no "-0" */
    at[n++] = v;
  }
  return n;
}

/* A tick label: enough decimals to tell the ticks apart, scientific for huge or tiny numbers; a
 * minus sign (U+2212), not a hyphen. */
static void tick_label(double v, double step, double big, char *buf, size_t size)
{
  char t[24];
  if (v != 0.0 && (big >= 1e6 || big < 1e-3)) {
    snprintf(t, sizeof t, "%.3g", fabs(v));
  } else {
    int dec = step >= 1.0 ? 0 : (int)ceil(-log10(step) - 1e-9);
    if (dec > 6) dec = 6;
    snprintf(t, sizeof t, "%.*f", dec, fabs(v));
  }
  snprintf(buf, size, "%s%s", v < 0.0 ? "\xE2\x88\x92" : "", t);
}

struct bar {
  int x0, x1, y0, y1; /* the bar's pixels: [x0, x1) x [y0, y1) */
  double lo, hi;      /* the colour range */
  int nt;
  double at[16];
  char label[16][32];   /* UTF-8, at most 3 + 23 bytes */
  int kinds[5], nkinds; /* the legend of `kind` */
};

static const char *const kind_names[5] = {"fluid", "wall vertex", "dummy", "inflow", "outflow"};

/* ---- a frame ---- */

static enum clsph_status draw_text_frame(struct render *r, const struct field_spec *f,
                                         const struct render_input *in, const struct bar *b,
                                         int label_px, int title_px, int margin, size_t drawn,
                                         enum colormap_kind map)
{
  enum clsph_status st = CLSPH_OK;
  const int W = r->o.width, H = r->o.height;
  struct text_box tb, lb;
  char title[160], sub[160];
  snprintf(title, sizeof title, "%s    t = %.4g s", in->case_name ? in->case_name : "", in->time);
  CLSPH_TRY(text_measure(r->text, title_px, title, &tb));
  const int title_base = margin + tb.ascent;
  CLSPH_TRY(
      text_draw(r->text, r->rgb, W, H, margin, title_base, title_px, title, render_colour_text));
  if (in->scheme != NULL && in->scheme[0] != '\0')
    snprintf(sub, sizeof sub, "%s, %zu particles", in->scheme, drawn);
  else
    snprintf(sub, sizeof sub, "%zu particles", drawn);
  CLSPH_TRY(text_measure(r->text, label_px, sub, &lb));
  CLSPH_TRY(text_draw(r->text, r->rgb, W, H, W - margin - lb.width, title_base, label_px, sub,
                      colour_faint));
  /* the field's name above the bar */
  CLSPH_TRY(text_measure(r->text, label_px, f->label, &lb));
  const int gap = b->x1 - b->x0 > 0 ? (int)lround(0.3 * (b->x1 - b->x0)) : 4;
  CLSPH_TRY(text_draw(r->text, r->rgb, W, H, b->x0, b->y0 - gap - lb.descent, label_px, f->label,
                      render_colour_text));
  if (map == COLORMAP_KIND) {
    const int step = (int)lround(1.6 * (lb.ascent + lb.descent));
    for (int k = 0; k < b->nkinds; ++k) {
      int yc = b->y0 + k * step + (b->x1 - b->x0) / 2;
      CLSPH_TRY(text_draw(r->text, r->rgb, W, H, b->x1 + gap, yc + lb.ascent / 2 - 1, label_px,
                          kind_names[b->kinds[k]], render_colour_text));
    }
    goto done;
  }
  for (int k = 0; k < b->nt; ++k) {
    double y = b->y1 - (b->at[k] - b->lo) / (b->hi - b->lo) * (b->y1 - b->y0);
    int base = (int)lround(y) + (lb.ascent - lb.descent) / 2;
    CLSPH_TRY(text_draw(r->text, r->rgb, W, H, b->x1 + 2 * gap, base, label_px, b->label[k],
                        render_colour_text));
  }
done:
  return st;
}

/* Sizes of a frame's parts, pixels, scaled with u = H/720. */
struct sizes {
  int margin, title_px, label_px, label_h, bar_w, tick, gap, band_px, header;
  float line_px;
};

static enum clsph_status frame_sizes(struct render *r, struct sizes *z)
{
  enum clsph_status st = CLSPH_OK;
  struct text_box tb, lb;
  const double u = (double)r->o.height / 720.0;
  z->margin = (int)fmax(6.0, lround(16.0 * u));
  z->title_px = (int)fmax(10.0, lround(24.0 * u));
  z->label_px = (int)fmax(9.0, lround(17.0 * u));
  z->bar_w = (int)fmax(8.0, lround(22.0 * u));
  z->tick = (int)fmax(3.0, lround(6.0 * u));
  z->gap = (int)lround(0.3 * z->bar_w);
  z->band_px = (int)fmax(3.0, lround(10.0 * u));
  z->line_px = (float)fmax(1.5, round(2.0 * u));
  CLSPH_TRY(text_measure(r->text, z->title_px, "Mg", &tb));
  CLSPH_TRY(text_measure(r->text, z->label_px, "Mg", &lb));
  z->label_h = lb.ascent + lb.descent;
  z->header = z->margin + tb.ascent + tb.descent + z->margin / 2;
done:
  return st;
}

/* The colour bar (or the legend of kinds) at the right: its ticks and labels first, for its
 * width. */
static enum clsph_status bar_layout(struct render *r, const struct field_spec *f,
                                    const struct render_input *in, const double *kind,
                                    const struct sizes *z, enum colormap_kind map, struct bar *b)
{
  enum clsph_status st = CLSPH_OK;
  struct text_box wb;
  const int W = r->o.width, H = r->o.height;
  b->y0 = z->header + z->label_h + z->gap + z->label_h / 2;
  const int avail = H - z->margin - z->label_h / 2 - b->y0;
  int bar_h = (int)fmin(avail, lround(0.62 * H));
  if (bar_h < 2 * z->label_h) bar_h = avail;
  b->y1 = b->y0 + bar_h;
  int label_w = 0;
  if (map == COLORMAP_KIND) {
    int present[5] = {0, 0, 0, 0, 0};
    for (size_t i = 0; i < in->n; ++i) {
      const int k = (int)kind[i];
      if (k >= 0 && k < 5) present[k] = 1;
    }
    for (int k = 0; k < 5; ++k) {
      if (!present[k]) continue;
      b->kinds[b->nkinds++] = k;
      CLSPH_TRY(text_measure(r->text, z->label_px, kind_names[k], &wb));
      label_w = wb.width > label_w ? wb.width : label_w;
    }
  } else {
    const int want = (int)fmin(8.0, fmax(2.0, bar_h / (2.5 * z->label_h)));
    b->nt = ticks(b->lo, b->hi, want, b->at, 16);
    const double step = b->nt > 1 ? b->at[1] - b->at[0] : b->hi - b->lo;
    const double big = fmax(fabs(b->lo), fabs(b->hi));
    for (int k = 0; k < b->nt; ++k) {
      tick_label(b->at[k], step, big, b->label[k], sizeof b->label[k]);
      CLSPH_TRY(text_measure(r->text, z->label_px, b->label[k], &wb));
      label_w = wb.width > label_w ? wb.width : label_w;
    }
  }
  CLSPH_TRY(text_measure(r->text, z->label_px, f->label, &wb));
  int block = z->bar_w + 2 * z->gap + label_w;
  if (wb.width > block) block = wb.width;
  b->x0 = W - z->margin - block;
  b->x1 = b->x0 + z->bar_w;
done:
  return st;
}

/* The colour bar: 256 bands of the map's entries, bottom up, its outline and ticks; or the
 * swatches of the legend of kinds. */
static void draw_bar(struct render *r, const struct bar *b, const struct sizes *z,
                     enum colormap_kind map)
{
  float rects[4 * 256], lines[4 * (4 + 16)];
  unsigned char rc[3 * 256];
  size_t nr = 0, nl = 0;
  const double bar_h = b->y1 - b->y0;
  if (map == COLORMAP_KIND) {
    const int step = (int)lround(1.6 * z->label_h);
    for (int k = 0; k < b->nkinds; ++k) {
      float *q = rects + 4 * nr;
      q[0] = (float)b->x0;
      q[1] = (float)(b->y0 + k * step);
      q[2] = (float)b->x1;
      q[3] = (float)(b->y0 + k * step + z->bar_w);
      colormap_rgb(COLORMAP_KIND, b->kinds[k], rc + 3 * nr++);
    }
  } else {
    for (int k = 0; k < 256; ++k) {
      float *q = rects + 4 * nr;
      q[0] = (float)b->x0;
      q[1] = (float)(b->y1 - (double)(k + 1) / 256.0 * bar_h);
      q[2] = (float)b->x1;
      q[3] = (float)(b->y1 - (double)k / 256.0 * bar_h);
      colormap_rgb(map, (k + 0.5) / 256.0, rc + 3 * nr++);
    }
    /* the outline runs through the centres of the pixels around the bar */
    const float e[4] = {(float)b->x0 - 0.5f, (float)b->y0 - 0.5f, (float)b->x1 + 0.5f,
                        (float)b->y1 + 0.5f};
    const float outline[16] = {e[0], e[1], e[2], e[1], e[2], e[1], e[2], e[3],
                               e[2], e[3], e[0], e[3], e[0], e[3], e[0], e[1]};
    memcpy(lines, outline, sizeof outline);
    nl = 4;
    for (int k = 0; k < b->nt; ++k) {
      const float y = (float)lround(b->y1 - (b->at[k] - b->lo) / (b->hi - b->lo) * bar_h) + 0.5f;
      float *q = lines + 4 * nl++;
      q[0] = (float)b->x1;
      q[1] = y;
      q[2] = (float)(b->x1 + z->tick);
      q[3] = y;
    }
  }
  draw_rects(r->draw, nr, rects, rc);
  draw_lines(r->draw, nl, lines, 1.0f, 0, render_colour_wall);
}

/* The particles into pixel positions, diameters and colours, in three groups: points of 1 pixel
 * (d < 1.5), of 2 pixels (d < 2.5), then discs; each group in the order of the arrays. */
static void particle_arrays(struct render *r, const struct field_spec *f,
                            const struct render_input *in, const struct xform *x, double spacing,
                            enum colormap_kind map, double lo, double hi, size_t group[3],
                            struct render_times *tm)
{
  const struct render_array *pos = field_array(in, "pos"), *vol = field_array(in, "vol");
  const struct render_array *kind = field_array(in, "kind");
  size_t nd = 0, n1 = 0, n2 = 0;
  const double inv = 1.0 / (hi - lo);
  double dsum = 0.0;
  for (size_t i = 0; i < in->n; ++i) {
    if (!field_drawn(f, (int)kind->v[i])) continue;
    const double d = x->s * side(vol->v[i], spacing);
    r->order[nd++] = i;
    n1 += d < 1.5;
    n2 += d >= 1.5 && d < 2.5;
    dsum += d;
  }
  size_t k1 = 0, k2 = n1, k3 = n1 + n2;
  for (size_t k = 0; k < nd; ++k) {
    const size_t i = r->order[k];
    const double d = x->s * side(vol->v[i], spacing);
    const size_t slot = d < 1.5 ? k1++ : d < 2.5 ? k2++ : k3++;
    to_px(x, pos->v[2 * i], pos->v[2 * i + 1], r->xy + 2 * slot);
    r->diam[slot] = (float)fmin(d, 253.0); /* sprites reach 255 pixels with the edge */
    const double tv = map == COLORMAP_KIND ? r->val[i] : (r->val[i] - lo) * inv;
    colormap_rgb(map, tv, r->col + 3 * slot);
  }
  group[0] = n1;
  group[1] = n2;
  group[2] = nd - n1 - n2;
  tm->drawn = nd;
  tm->disc_px = nd > 0 ? dsum / (double)nd : 0.0;
}

/* 3-D frames: the drawn particles seen by the camera, in perspective, as spheres of diameter ∛V
 * (a lattice's spheres touch), sorted back to front (the farthest first; a tie in the order of the
 * arrays) so that the nearer ones cover them. The view area [px0, px1] x [py0, py1] holds the
 * camera's field of view vertically (the horizontal follows the pixels), its centre the camera's
 * axis; particles behind the camera or whose sphere leaves no pixel in the area are not drawn.
 * Returns how many are drawn (r->xy, r->diam, r->col in drawing order); *scale: pixels per metre
 * at the target's distance. */
struct render_depth {
  double z; /* distance along the camera's axis */
  size_t i; /* the particle */
};

static int cmp_depth(const void *a, const void *b)
{
  const struct render_depth *p = a, *q = b;
  if (p->z != q->z) return p->z > q->z ? -1 : 1;
  return p->i < q->i ? -1 : p->i > q->i;
}

static enum clsph_status sphere_arrays(struct render *r, const struct field_spec *f,
                                       const struct render_input *in, double px0, double px1,
                                       double py0, double py1, enum colormap_kind map, double lo,
                                       double hi, size_t *drawn, double *scale, double centre[2],
                                       struct render_times *tm)
{
  enum clsph_status st = CLSPH_OK;
  const struct render_array *pos = field_array(in, "pos"), *vol = field_array(in, "vol");
  const struct render_array *kind = field_array(in, "kind");
  if (in->n > r->depth_cap) {
    free(r->depth);
    r->depth = malloc(in->n * sizeof *r->depth);
    r->depth_cap = r->depth != NULL ? in->n : 0;
    CLSPH_CHECK(r->depth != NULL, CLSPH_E_NOMEM, "out of memory drawing %zu particles", in->n);
  }
  if (!r->have_camera) { /* the options' camera, or one that sees the drawn particles whole */
    if (r->o.camera_set) {
      r->cam = r->o.camera;
    } else if (r->o.box3_set) {
      render_default_camera(r->o.box3, r->o.fov_only, &r->cam);
    } else {
      double box[6] = {HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
      render_extend_box(f, in, box);
      if (!(box[3] >= box[0])) box[0] = box[1] = box[2] = 0.0, box[3] = box[4] = box[5] = 1.0;
      render_default_camera(box, r->o.fov_only, &r->cam);
    }
    CLSPH_TRY(render_check_camera(&r->cam, "render"));
    r->have_camera = 1;
  }
  const struct render_camera *c = &r->cam;
  double fwd[3], right[3], up[3];
  for (int a = 0; a < 3; ++a) fwd[a] = c->at[a] - c->eye[a];
  const double dist = sqrt(dot3(fwd, fwd));
  for (int a = 0; a < 3; ++a) fwd[a] /= dist;
  cross3(fwd, c->up, right);
  const double nr = sqrt(dot3(right, right));
  for (int a = 0; a < 3; ++a) right[a] /= nr;
  cross3(right, fwd, up);
  const double focal = 0.5 * (py1 - py0) / tan(0.5 * c->fov * 3.141592653589793 / 180.0);
  const double cx = 0.5 * (px0 + px1), cy = 0.5 * (py0 + py1), inv = 1.0 / (hi - lo);
  size_t nd = 0;
  double dsum = 0.0;
  for (size_t i = 0; i < in->n; ++i) {
    if (!field_drawn(f, (int)kind->v[i])) continue;
    const double d[3] = {pos->v[3 * i] - c->eye[0], pos->v[3 * i + 1] - c->eye[1],
                         pos->v[3 * i + 2] - c->eye[2]};
    const double z = dot3(d, fwd);
    const double size = vol->v[i] > 0.0 && isfinite(vol->v[i]) ? cbrt(vol->v[i]) : 0.0;
    if (!(z > 0.5 * size) || !isfinite(z)) continue; /* behind the camera, or at its eye */
    const double u = cx + focal * dot3(d, right) / z, v = cy - focal * dot3(d, up) / z;
    const double diam = fmax(1.0, focal * size / z);
    if (u + 0.5 * diam < px0 || u - 0.5 * diam > px1 || v + 0.5 * diam < py0 ||
        v - 0.5 * diam > py1)
      continue;
    r->depth[nd++] = (struct render_depth){z, i};
  }
  qsort(r->depth, nd, sizeof *r->depth, cmp_depth);
  CLSPH_TRY(grow(&r->sxyz, &r->sxyz_cap, 0, 3 * nd + 3));
  /* the depth values: zref/z, 1 at half the nearest sphere's distance or at 1e-3 of the target's
   * (the walls' faces are cut there) */
  r->pj.zref = 0.5 * fmin(nd > 0 ? r->depth[nd - 1].z : HUGE_VAL, 1e-3 * dist);
  for (int a = 0; a < 3; ++a) {
    r->pj.eye[a] = c->eye[a];
    r->pj.fwd[a] = fwd[a];
    r->pj.right[a] = right[a];
    r->pj.up[a] = up[a];
  }
  r->pj.focal = focal;
  r->pj.cx = cx;
  r->pj.cy = cy;
  for (size_t k = 0; k < nd; ++k) {
    const size_t i = r->depth[k].i;
    const double d[3] = {pos->v[3 * i] - c->eye[0], pos->v[3 * i + 1] - c->eye[1],
                         pos->v[3 * i + 2] - c->eye[2]};
    const double z = r->depth[k].z;
    const double size = vol->v[i] > 0.0 && isfinite(vol->v[i]) ? cbrt(vol->v[i]) : 0.0;
    const double diam = fmin(fmax(1.0, focal * size / z), 253.0);
    r->sxyz[3 * k] = (float)(cx + focal * dot3(d, right) / z);
    r->sxyz[3 * k + 1] = (float)(cy - focal * dot3(d, up) / z);
    r->sxyz[3 * k + 2] = (float)(r->pj.zref / z);
    r->diam[k] = (float)diam;
    dsum += diam;
    const double tv = map == COLORMAP_KIND ? r->val[i] : (r->val[i] - lo) * inv;
    colormap_rgb(map, tv, r->col + 3 * k);
  }
  *drawn = nd;
  *scale = focal / dist;
  centre[0] = cx;
  centre[1] = cy;
  tm->drawn = nd;
  tm->disc_px = nd > 0 ? dsum / (double)nd : 0.0;
done:
  return st;
}

/* 3-D frames: the walls' faces seen from their fluid side (a container's far faces from inside,
 * an obstacle's near faces; the others would hide the water, and are left out), cut at the
 * distance zref from the camera (Sutherland-Hodgman against that plane), projected as the
 * spheres are, in the solid band's grey lit as the spheres are (flat: by each face's normal). */
static enum clsph_status face_arrays(struct render *r, const struct render_input *in)
{
  enum clsph_status st = CLSPH_OK;
  const struct proj3 *p = &r->pj;
  const double l0[3] = {-0.40, 0.50, 0.77}, nl = sqrt(dot3(l0, l0));
  r->nface = 0;
  for (size_t t = 0; t < in->nsurf3; ++t) {
    const double *v = in->surf3 + 9 * t;
    double e1[3], e2[3], n[3], toeye[3];
    for (int a = 0; a < 3; ++a) {
      e1[a] = v[3 + a] - v[a];
      e2[a] = v[6 + a] - v[a];
      toeye[a] = p->eye[a] - v[a];
    }
    cross3(e1, e2, n);
    const double nn = sqrt(dot3(n, n));
    if (!(nn > 0.0) || !(dot3(n, toeye) > 0.0)) continue; /* seen from the solid's side */
    /* its light: the normal in the camera's axes (x right, y up, z towards the camera) */
    const double nc[3] = {dot3(n, p->right) / nn, dot3(n, p->up) / nn, -dot3(n, p->fwd) / nn};
    const double shade = 0.6 + 0.4 * fmax(0.0, dot3(nc, l0) / nl); /* lighter than the spheres */
    unsigned char col[3];
    for (int a = 0; a < 3; ++a)
      col[a] = (unsigned char)lround(fmin(255.0, render_colour_solid[a] * shade));
    /* the polygon in front of the plane z = zref (at most 4 vertices), as camera coordinates */
    double q[4][3];
    int nq = 0;
    for (int k = 0; k < 3; ++k) {
      const double *a = v + 3 * k, *b = v + 3 * ((k + 1) % 3);
      double da[3], db[3];
      for (int c = 0; c < 3; ++c) da[c] = a[c] - p->eye[c], db[c] = b[c] - p->eye[c];
      const double za = dot3(da, p->fwd), zb = dot3(db, p->fwd);
      if (za >= p->zref) memcpy(q[nq++], da, sizeof da);
      if ((za >= p->zref) != (zb >= p->zref)) {
        const double s = (p->zref - za) / (zb - za);
        for (int c = 0; c < 3; ++c) q[nq][c] = da[c] + s * (db[c] - da[c]);
        ++nq;
      }
    }
    if (nq < 3) continue;
    CLSPH_TRY(grow(&r->face, &r->face_cap, 9 * r->nface, 9 * (size_t)(nq - 2)));
    if (r->fcol_cap < 9 * (r->nface + (size_t)nq)) {
      const size_t cap = 2 * (9 * (r->nface + (size_t)nq)) + 1024;
      unsigned char *c = realloc(r->fcol, cap);
      CLSPH_CHECK(c != NULL, CLSPH_E_NOMEM, "out of memory for the walls' faces");
      r->fcol = c;
      r->fcol_cap = cap;
    }
    for (int k = 1; k + 1 < nq; ++k) { /* a fan */
      const int idx[3] = {0, k, k + 1};
      for (int j = 0; j < 3; ++j) {
        const double *d = q[idx[j]];
        const double z = fmax(dot3(d, p->fwd), p->zref);
        float *o = r->face + 9 * r->nface + 3 * j;
        o[0] = (float)(p->cx + p->focal * dot3(d, p->right) / z);
        o[1] = (float)(p->cy - p->focal * dot3(d, p->up) / z);
        o[2] = (float)(p->zref / z);
        memcpy(r->fcol + 9 * r->nface + 3 * j, col, 3);
      }
      ++r->nface;
    }
  }
done:
  return st;
}

enum clsph_status render_frame(struct render *r, const struct field_spec *f,
                               const struct render_input *in, const char *png_path, double lo_hi[2],
                               struct render_times *t)
{
  enum clsph_status st = CLSPH_OK;
  struct render_times tm;
  struct sizes z;
  struct bar b;
  struct xform x;
  size_t group[3];
  memset(&tm, 0, sizeof tm);
  memset(&b, 0, sizeof b);
  const double t0 = now();
  const int W = r->o.width, H = r->o.height;
  const struct render_array *pos = field_array(in, "pos"), *vol = field_array(in, "vol");
  const struct render_array *kind = field_array(in, "kind");
  CLSPH_CHECK(pos != NULL && (pos->ncomp == 2 || pos->ncomp == 3) && vol != NULL &&
                  vol->ncomp == 1 && kind != NULL && kind->ncomp == 1,
              CLSPH_E_INPUT, "a frame needs the arrays pos (2 or 3 components), vol and kind");
  const int three = pos->ncomp == 3;
  CLSPH_TRY(reserve(r, in->n));

  /* the values, the map and the range */
  CLSPH_TRY(field_values(f, in, r->val));
  const enum colormap_kind map = render_map_for(f, r->o.map);
  double lo = r->o.lo, hi = r->o.hi;
  if (!r->o.fixed) field_auto_range(f, map, in->n, r->val, kind->v, &lo, &hi);
  b.lo = lo;
  b.hi = hi;

  /* the layout: sizes, the colour bar, and the view in what is left */
  CLSPH_TRY(frame_sizes(r, &z));
  CLSPH_TRY(bar_layout(r, f, in, kind->v, &z, map, &b));
  int novol = 0; /* particles with no volume of their own are drawn at the typical spacing */
  for (size_t i = 0; i < in->n && !novol; ++i)
    novol = field_drawn(f, (int)kind->v[i]) && !(vol->v[i] > 0.0 && isfinite(vol->v[i]));
  const double spacing = novol ? field_spacing(f, in->n, vol->v, kind->v) : 0.0;
  double box[4] = {0.0, 0.0, 0.0, 0.0};
  const double px0 = z.margin, px1 = b.x0 - 2 * z.margin, py0 = z.header, py1 = H - z.margin;
  size_t nspheres = 0;
  memset(&x, 0, sizeof x);
  if (three) { /* a 3-D run: lit spheres seen by the camera, and the walls' faces behind them */
    double centre[2];
    CLSPH_TRY(
        sphere_arrays(r, f, in, px0, px1, py0, py1, map, lo, hi, &nspheres, &x.s, centre, &tm));
    x.ox = centre[0];
    x.oy = centre[1];
    CLSPH_TRY(face_arrays(r, in));
  } else {
    if (in->view[0] != 0.0 || in->view[1] != 0.0 || in->view[2] != 0.0 || in->view[3] != 0.0)
      memcpy(box, in->view, sizeof box);
    else
      view_box(f, in, pos->v, vol->v, kind->v, spacing, box);
    const double pad = z.band_px + z.line_px, vw = box[2] - box[0], vh = box[3] - box[1];
    x.s = fmax(1e-12, fmin((px1 - px0 - 2 * pad) / vw, (py1 - py0 - 2 * pad) / vh));
    x.ox = px0 + 0.5 * (px1 - px0 - x.s * vw);
    x.oy = py0 + 0.5 * (py1 - py0 - x.s * vh);
    x.vx0 = box[0];
    x.vy1 = box[3];
    x.band = z.band_px / x.s;
    /* pixel positions and colours */
    particle_arrays(r, f, in, &x, spacing, map, lo, hi, group, &tm);
    CLSPH_TRY(wall_geometry(r, in, &x));
  }
  const double t1 = now();

  /* OpenGL: the solid side of the walls, the particles, the wall lines, the colour bar */
  CLSPH_TRY(draw_begin(r->draw, render_colour_bg));
  if (three) { /* the walls' faces first: they hide the spheres behind them */
    draw_depth(r->draw, 1, (int)floor(px0), (int)floor(py0), (int)ceil(px1), (int)ceil(py1));
    draw_faces(r->draw, r->nface, r->face, r->fcol);
    draw_spheres(r->draw, nspheres, r->sxyz, r->diam, r->col);
    draw_depth(r->draw, 0, 0, 0, 0, 0);
  } else {
    draw_triangles(r->draw, r->ntri, r->tri, render_colour_solid);
    CLSPH_TRY(fill_solids(r, in, &x));
    const size_t n1 = group[0], n12 = group[0] + group[1];
    draw_points(r->draw, group[0], r->xy, 1, r->col);
    draw_points(r->draw, group[1], r->xy + 2 * n1, 2, r->col + 3 * n1);
    draw_discs(r->draw, group[2], r->xy + 2 * n12, r->diam + n12, r->col + 3 * n12);
    draw_lines(r->draw, r->nlines, r->lines, z.line_px, 1, render_colour_wall);
  }
  draw_bar(r, &b, &z, map);
  CLSPH_TRY(draw_read(r->draw, r->rgb));
  const double t2 = now();

  /* text, and the file */
  CLSPH_TRY(draw_text_frame(r, f, in, &b, z.label_px, z.title_px, z.margin, tm.drawn, map));
  const double t3 = now();
  if (png_path != NULL) CLSPH_TRY(image_write_png(png_path, r->rgb, W, H));
  const double t4 = now();

  tm.field = t1 - t0;
  tm.draw = t2 - t1;
  tm.text = t3 - t2;
  tm.png = t4 - t3;
  tm.total = t4 - t0;
  if (lo_hi != NULL) {
    lo_hi[0] = lo;
    lo_hi[1] = hi;
  }
  if (t != NULL) *t = tm;
  struct render_layout *l = &r->layout;
  l->scale = x.s;
  memcpy(l->view, box, sizeof box);
  l->origin[0] = x.ox;
  l->origin[1] = x.oy;
  l->band_px = z.band_px;
  l->line_px = z.line_px;
  l->bar[0] = b.x0;
  l->bar[1] = b.y0;
  l->bar[2] = b.x1;
  l->bar[3] = b.y1;
  l->margin = z.margin;
  l->title_px = z.title_px;
  l->label_px = z.label_px;
  l->map = map;
  l->lo = lo;
  l->hi = hi;
done:
  return st;
}
