/* draw.c: OpenGL drawing in an off-screen OSMesa context (Mesa's llvmpipe on the CPU: no
 * display, no X server, no GPU). Coordinates are pixels, x to the right and y down from the
 * top-left corner of the image (glOrtho(0, w, h, 0)); a pixel's centre is at (i + 1/2, j + 1/2).
 *
 * Discs of 2.5 pixels across and more are point sprites whose fragment shader cuts a disc with
 * a one-pixel anti-aliased edge (alpha = clamp(d/2 + 1/2 − |p − c|, 0, 1), blended over what is
 * there); smaller ones are plain square points of 1 or 2 pixels in their exact colour (a disc
 * that small is a pixel, and llvmpipe draws plain points about three times faster than
 * sprites). A disc's centre pixel carries its exact colour: alpha is 1 there, and the colour
 * goes through unchanged (8-bit in, 8-bit out).
 *
 * Everything is drawn in the order given, and llvmpipe rasterises the same input into the same
 * pixels, so a frame is reproducible bit for bit. */
#define GL_GLEXT_PROTOTYPES 1
#include "draw.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct draw {
  OSMesaContext ctx;
  int w, h;
  unsigned char *buf; /* OSMesa's colour buffer, w x h x 4 (RGBA), bottom row first */
  GLuint prog;        /* the disc shader */
  GLint a_diam;       /* its attribute: the disc's diameter, pixels */
  GLuint sphere;      /* the lit sphere shader (3-D views) */
  GLint s_diam;       /* its diameter attribute */
  char renderer[128]; /* GL_RENDERER and GL_VERSION */
};

static const char *const disc_vs =
    "#version 120\n"
    "attribute float a_diam;\n"
    "varying float v_diam;\n"
    "void main()\n"
    "{\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n"
    "  gl_FrontColor = gl_Color;\n"
    "  v_diam = a_diam;\n"
    "  gl_PointSize = a_diam + 2.0; /* room for the anti-aliased edge */\n"
    "}\n";

static const char *const disc_fs =
    "#version 120\n"
    "varying float v_diam;\n"
    "void main()\n"
    "{\n"
    "  float r = length((gl_PointCoord - vec2(0.5)) * (v_diam + 2.0));\n"
    "  float a = clamp(0.5 * v_diam + 0.5 - r, 0.0, 1.0);\n"
    "  if (a <= 0.0) discard;\n"
    "  gl_FragColor = vec4(gl_Color.rgb, a);\n"
    "}\n";

/* A lit sphere on a point sprite (3-D views: render.c draws them back to front): the sprite's
 * disc is the sphere seen from the camera, its normal n = (u, v, √(1 − u² − v²)) at the disc
 * point (u, v) (v up), lit by a light from the upper left behind the camera, L = (−0.40, 0.50,
 * 0.77): colour c (0.35 + 0.65 max(n·L, 0)) plus a white highlight 0.25 max(n·h, 0)^40 (h the
 * half-way vector of L and the view (0, 0, 1)), the edge anti-aliased as the disc's. */
static const char *const sphere_fs =
    "#version 120\n"
    "varying float v_diam;\n"
    "void main()\n"
    "{\n"
    "  vec2 q = (gl_PointCoord - vec2(0.5)) * (v_diam + 2.0);\n"
    "  float r = length(q);\n"
    "  float a = clamp(0.5 * v_diam + 0.5 - r, 0.0, 1.0);\n"
    "  if (a <= 0.0) discard;\n"
    "  vec2 uv = min(r / (0.5 * v_diam), 1.0) * normalize(vec2(q.x, -q.y) + vec2(1e-9, 0.0));\n"
    "  vec3 n = vec3(uv, sqrt(max(1.0 - dot(uv, uv), 0.0)));\n"
    "  vec3 l = normalize(vec3(-0.40, 0.50, 0.77));\n"
    "  vec3 h = normalize(l + vec3(0.0, 0.0, 1.0));\n"
    "  float shade = 0.35 + 0.65 * max(dot(n, l), 0.0);\n"
    "  float spec = 0.25 * pow(max(dot(n, h), 0.0), 40.0);\n"
    "  gl_FragColor = vec4(min(gl_Color.rgb * shade + vec3(spec), vec3(1.0)), a);\n"
    "}\n";

static enum clsph_status compile(GLenum type, const char *src, GLuint *out)
{
  enum clsph_status st = CLSPH_OK;
  char log[1024];
  GLint ok = 0;
  GLuint s = glCreateShader(type);
  CLSPH_CHECK(s != 0, CLSPH_E_UNSUPPORTED, "OSMesa: glCreateShader failed (no GLSL support?)");
  glShaderSource(s, 1, &src, NULL);
  glCompileShader(s);
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    glGetShaderInfoLog(s, sizeof log, NULL, log);
    glDeleteShader(s);
    CLSPH_CHECK(0, CLSPH_E_UNSUPPORTED, "OSMesa: the disc shader does not compile: %s", log);
  }
  *out = s;
done:
  return st;
}

enum clsph_status draw_create(int w, int h, struct draw **out)
{
  enum clsph_status st = CLSPH_OK;
  struct draw *d = calloc(1, sizeof *d);
  GLuint vs = 0, fs = 0;
  CLSPH_CHECK(d != NULL, CLSPH_E_NOMEM, "out of memory");
  d->w = w;
  d->h = h;
  d->buf = malloc((size_t)w * (size_t)h * 4);
  CLSPH_CHECK(d->buf != NULL, CLSPH_E_NOMEM, "out of memory for a %d x %d image", w, h);
  static const int attribs[] = {OSMESA_FORMAT,
                                OSMESA_RGBA,
                                OSMESA_DEPTH_BITS,
                                24,
                                OSMESA_STENCIL_BITS,
                                8,
                                OSMESA_PROFILE,
                                OSMESA_COMPAT_PROFILE,
                                OSMESA_CONTEXT_MAJOR_VERSION,
                                2,
                                OSMESA_CONTEXT_MINOR_VERSION,
                                1,
                                0};
  d->ctx = OSMesaCreateContextAttribs(attribs, NULL);
  CLSPH_CHECK(
      d->ctx != NULL, CLSPH_E_UNSUPPORTED,
      "OSMesa cannot create an OpenGL 2.1 context with depth and stencil buffers (libosmesa6)");
  CLSPH_CHECK(OSMesaMakeCurrent(d->ctx, d->buf, GL_UNSIGNED_BYTE, w, h), CLSPH_E_UNSUPPORTED,
              "OSMesa cannot draw into a %d x %d image", w, h);
  snprintf(d->renderer, sizeof d->renderer, "%s, OpenGL %s", (const char *)glGetString(GL_RENDERER),
           (const char *)glGetString(GL_VERSION));
  GLint maxdim[2] = {0, 0};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxdim);
  CLSPH_CHECK(w <= maxdim[0] && h <= maxdim[1], CLSPH_E_INPUT,
              "a %d x %d image is larger than OSMesa draws (%d x %d)", w, h, maxdim[0], maxdim[1]);
  CLSPH_TRY(compile(GL_VERTEX_SHADER, disc_vs, &vs));
  CLSPH_TRY(compile(GL_FRAGMENT_SHADER, disc_fs, &fs));
  d->prog = glCreateProgram();
  glAttachShader(d->prog, vs);
  glAttachShader(d->prog, fs);
  glLinkProgram(d->prog);
  GLint ok = 0;
  glGetProgramiv(d->prog, GL_LINK_STATUS, &ok);
  CLSPH_CHECK(ok, CLSPH_E_UNSUPPORTED, "OSMesa: the disc shader does not link");
  d->a_diam = glGetAttribLocation(d->prog, "a_diam");
  CLSPH_CHECK(d->a_diam >= 0, CLSPH_E_UNSUPPORTED, "OSMesa: the disc shader lost its attribute");
  glDeleteShader(fs);
  fs = 0;
  CLSPH_TRY(compile(GL_FRAGMENT_SHADER, sphere_fs, &fs));
  d->sphere = glCreateProgram();
  glAttachShader(d->sphere, vs);
  glAttachShader(d->sphere, fs);
  glLinkProgram(d->sphere);
  glGetProgramiv(d->sphere, GL_LINK_STATUS, &ok);
  CLSPH_CHECK(ok, CLSPH_E_UNSUPPORTED, "OSMesa: the sphere shader does not link");
  d->s_diam = glGetAttribLocation(d->sphere, "a_diam");
  CLSPH_CHECK(d->s_diam >= 0, CLSPH_E_UNSUPPORTED, "OSMesa: the sphere shader lost its attribute");
  /* pixel coordinates, y down */
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, (double)w, (double)h, 0.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_DITHER);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  *out = d;
  d = NULL;
done:
  if (vs != 0) glDeleteShader(vs);
  if (fs != 0) glDeleteShader(fs);
  draw_destroy(d);
  return st;
}

enum clsph_status draw_begin(struct draw *d, const unsigned char rgb[3])
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_CHECK(OSMesaMakeCurrent(d->ctx, d->buf, GL_UNSIGNED_BYTE, d->w, d->h), CLSPH_E_UNSUPPORTED,
              "OSMesa cannot draw into a %d x %d image", d->w, d->h);
  glClearColor((float)rgb[0] / 255.0f, (float)rgb[1] / 255.0f, (float)rgb[2] / 255.0f, 1.0f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
done:
  return st;
}

/* Vertex positions and colours from client arrays. */
static void arrays_on(const float *xy, const unsigned char *rgb)
{
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, xy);
  if (rgb != NULL) {
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(3, GL_UNSIGNED_BYTE, 0, rgb);
  }
}

static void arrays_off(void)
{
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
}

/* point sprites of a program with a diameter attribute, blended over what is there; vertices of
 * ncomp (2: xy, 3: xyz) floats */
static void sprites(GLuint prog, GLint attr, size_t n, int ncomp, const float *xy,
                    const float *diam, const unsigned char *rgb)
{
  if (n == 0) return;
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_POINT_SPRITE);
  glEnable(GL_VERTEX_PROGRAM_POINT_SIZE);
  glUseProgram(prog);
  arrays_on(xy, rgb);
  glVertexPointer(ncomp, GL_FLOAT, 0, xy);
  glEnableVertexAttribArray((GLuint)attr);
  glVertexAttribPointer((GLuint)attr, 1, GL_FLOAT, GL_FALSE, 0, diam);
  glDrawArrays(GL_POINTS, 0, (GLsizei)n);
  glDisableVertexAttribArray((GLuint)attr);
  arrays_off();
  glUseProgram(0);
  glDisable(GL_VERTEX_PROGRAM_POINT_SIZE);
  glDisable(GL_POINT_SPRITE);
  glDisable(GL_BLEND);
}

void draw_discs(struct draw *d, size_t n, const float *xy, const float *diam,
                const unsigned char *rgb)
{
  sprites(d->prog, d->a_diam, n, 2, xy, diam, rgb);
}

void draw_spheres(struct draw *d, size_t n, const float *xyz, const float *diam,
                  const unsigned char *rgb)
{
  sprites(d->sphere, d->s_diam, n, 3, xyz, diam, rgb);
}

/* glOrtho(…, −1, 1) maps a vertex's z to the window depth (1 − z)/2: larger z is nearer. The
 * scissor box counts rows from the bottom. */
void draw_depth(struct draw *d, int on, int x0, int y0, int x1, int y1)
{
  if (on) {
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDepthFunc(GL_LESS);
    glEnable(GL_DEPTH_TEST);
    glScissor(x0, d->h - y1, x1 - x0, y1 - y0);
    glEnable(GL_SCISSOR_TEST);
  } else {
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
  }
}

void draw_faces(struct draw *d, size_t ntri, const float *xyz, const unsigned char *rgb)
{
  (void)d;
  if (ntri == 0) return;
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, xyz);
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, rgb);
  glDrawArrays(GL_TRIANGLES, 0, (GLsizei)(3 * ntri));
  arrays_off();
}

void draw_points(struct draw *d, size_t n, const float *xy, int size, const unsigned char *rgb)
{
  (void)d;
  if (n == 0) return;
  glPointSize((float)size);
  arrays_on(xy, rgb);
  glDrawArrays(GL_POINTS, 0, (GLsizei)n);
  arrays_off();
  glPointSize(1.0f);
}

void draw_triangles(struct draw *d, size_t ntri, const float *xy, const unsigned char rgb[3])
{
  (void)d;
  if (ntri == 0) return;
  glColor3ub(rgb[0], rgb[1], rgb[2]);
  arrays_on(xy, NULL);
  glDrawArrays(GL_TRIANGLES, 0, (GLsizei)(3 * ntri));
  arrays_off();
}

void draw_rects(struct draw *d, size_t n, const float *rect, const unsigned char *rgb)
{
  (void)d;
  glBegin(GL_QUADS);
  for (size_t k = 0; k < n; ++k) {
    const float *r = rect + 4 * k;
    glColor3ub(rgb[3 * k], rgb[3 * k + 1], rgb[3 * k + 2]);
    glVertex2f(r[0], r[1]);
    glVertex2f(r[2], r[1]);
    glVertex2f(r[2], r[3]);
    glVertex2f(r[0], r[3]);
  }
  glEnd();
}

void draw_lines(struct draw *d, size_t nseg, const float *xy, float width, int smooth,
                const unsigned char rgb[3])
{
  (void)d;
  if (nseg == 0) return;
  if (smooth) {
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  }
  glLineWidth(width);
  glColor3ub(rgb[0], rgb[1], rgb[2]);
  arrays_on(xy, NULL);
  glDrawArrays(GL_LINES, 0, (GLsizei)(2 * nseg));
  arrays_off();
  glLineWidth(1.0f);
  glDisable(GL_LINE_SMOOTH);
  glDisable(GL_BLEND);
}

void draw_polygon(struct draw *d, int npts, const float *xy, const unsigned char rgb[3])
{
  (void)d;
  if (npts < 3) return;
  /* pass 1: invert the stencil under each triangle of a fan from the first vertex; a pixel ends
   * at 1 when an odd number of triangles cover it, i.e. inside the polygon (even-odd rule) */
  glEnable(GL_STENCIL_TEST);
  glClear(GL_STENCIL_BUFFER_BIT);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glStencilMask(1);
  glStencilFunc(GL_ALWAYS, 0, 1);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
  arrays_on(xy, NULL);
  glDrawArrays(GL_TRIANGLE_FAN, 0, npts);
  /* pass 2: colour where the stencil is 1, clearing it */
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilFunc(GL_EQUAL, 1, 1);
  glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
  glColor3ub(rgb[0], rgb[1], rgb[2]);
  glDrawArrays(GL_TRIANGLE_FAN, 0, npts);
  arrays_off();
  glDisable(GL_STENCIL_TEST);
}

enum clsph_status draw_read(struct draw *d, unsigned char *rgb)
{
  enum clsph_status st = CLSPH_OK;
  glFinish(); /* OSMesa's buffer holds the frame once every command has run */
  GLenum err = glGetError();
  CLSPH_CHECK(err == GL_NO_ERROR, CLSPH_E_UNSUPPORTED, "OSMesa: OpenGL error 0x%04x while drawing",
              (unsigned)err);
  /* OpenGL's rows go up from the bottom; the image's go down from the top */
  for (int y = 0; y < d->h; ++y) {
    const unsigned char *src = d->buf + (size_t)(d->h - 1 - y) * (size_t)d->w * 4;
    unsigned char *dst = rgb + (size_t)y * (size_t)d->w * 3;
    for (int x = 0; x < d->w; ++x) {
      dst[3 * x] = src[4 * x];
      dst[3 * x + 1] = src[4 * x + 1];
      dst[3 * x + 2] = src[4 * x + 2];
    }
  }
done:
  return st;
}

const char *draw_renderer(const struct draw *d)
{
  return d->renderer;
}

void draw_destroy(struct draw *d)
{
  if (d == NULL) return;
  if (d->ctx != NULL) {
    if (d->prog != 0) glDeleteProgram(d->prog);
    if (d->sphere != 0) glDeleteProgram(d->sphere);
    OSMesaDestroyContext(d->ctx);
  }
  free(d->buf);
  free(d);
}
