/* render.h: off-screen frames of a run, their PNG files, and movies (the render/ module).
 *
 * A frame shows the particles as round discs of diameter √V (V the particle's volume, an area in
 * 2-D: the discs of a lattice at spacing δr touch), coloured by one field through a colour map;
 * the walls as their polylines with a solid band on the solid side (a closed wall that holds the
 * solid inside, such as a cylinder, is filled); a colour bar with numbered ticks and the field's
 * name and unit; the case name, the scheme and the simulated time. It is drawn with OpenGL in an
 * OSMesa context (no display, no X server), its text with FreeType in DejaVu Sans, and written as
 * PNG with libpng; a movie is the frames encoded by ffmpeg (H.264 in MP4).
 *
 * The module reads host arrays only (a snapshot read from disk, or a host copy of the device
 * state), never device buffers. Same input, same bytes: the draw order is the order of the
 * arrays, and the PNG files carry no time stamp.
 *
 * Files: render.c (layout of a frame), draw.c (OSMesa and OpenGL), text.c (fontconfig and
 * FreeType), colormap.c (the colour tables), field.c (field values, vorticity, colour range),
 * image.c (PNG), movie.c (ffmpeg). */
#ifndef CLSPH_RENDER_H
#define CLSPH_RENDER_H

#include <stddef.h>

#include "status.h"

#define RENDER_NAME 32 /* longest field or array name + 1 */

/* ---- colour maps (colormap.c) ---- */

enum colormap_kind {
  COLORMAP_AUTO = 0, /* by the field: coolwarm for signed fields, kind for `kind`, else viridis */
  COLORMAP_VIRIDIS,  /* perceptually uniform, for magnitudes (van der Walt & Smith 2015) */
  COLORMAP_COOLWARM, /* diverging, for signed fields (Moreland 2009) */
  COLORMAP_KIND,     /* categorical: one colour per particle kind (Okabe & Ito 2008) */
};

/** @brief The map called `name` ("auto", "viridis", "coolwarm", "kind"); an unknown name lists
 *  them. */
enum clsph_status colormap_from_name(const char *name, enum colormap_kind *out);
/** @brief Name of a map. */
const char *colormap_name(enum colormap_kind k);
/** @brief Colour of t in [0, 1] (clamped; NaN: magenta) for a continuous map: entry
 *  min(⌊256 t⌋, 255) of its 256-entry table, as matplotlib indexes a 256-colour map. For
 *  COLORMAP_KIND, t is the kind (0 .. 4). */
void colormap_rgb(enum colormap_kind k, double t, unsigned char rgb[3]);

/* ---- particle data (field.c) ---- */

/** A particle array in host memory: n rows of ncomp doubles. */
struct render_array {
  const char *name; /* "pos", "vel", "kind", "vol", "p", ... */
  int ncomp;        /* components per particle */
  const double *v;  /* n x ncomp */
};

/** A wall polyline; the fluid is on its left (the convention of scene.h). */
struct render_wall {
  int npts;          /* vertices, >= 2 */
  const double *pts; /* npts x 2, m */
  int closed;        /* the last vertex joins the first */
};

/** What one frame shows. Arrays `pos` (n x 2), `vol` (n) and `kind` (n) are required. */
struct render_input {
  size_t n;                          /* particles */
  int narrays;                       /* stored arrays */
  const struct render_array *arrays; /* by name */
  int nwalls;
  const struct render_wall *walls;
  size_t nsurf3;         /* 3-D: the walls' faces, triangles (0: none drawn) */
  const double *surf3;   /* nsurf3 x 9, m, counter-clockwise seen from the fluid */
  double view[4];        /* x0, y0, x1, y1 of the region drawn, m; all 0: the box of the drawn
                            particles and the walls */
  double time;           /* simulated time, s */
  const char *case_name; /* title */
  const char *scheme;    /* shown beside the title (NULL: none) */
};

enum field_how {
  FIELD_SCALAR = 0, /* a stored one-component array */
  FIELD_COMPONENT,  /* component `comp` of a stored array ("vel_x" is vel's first) */
  FIELD_SPEED,      /* |vel| */
  FIELD_VORTICITY,  /* the SPH curl of vel (field_vorticity) */
  FIELD_KIND,       /* the particle kind, categorical */
};

/** A field resolved against the arrays of a run. */
struct field_spec {
  enum field_how how;
  char name[RENDER_NAME];  /* as asked: "speed", "p", "vel_x", ... */
  char array[RENDER_NAME]; /* the stored array it reads */
  int comp;                /* FIELD_COMPONENT: the component */
  char label[64];          /* colour bar title, UTF-8: "speed |u| (m/s)" */
  int is_signed;           /* a signed quantity: diverging map and a range symmetric about 0 */
};

/** @brief Resolve a field name against the stored arrays (names and component counts): `speed`,
 *  `vorticity`, `vel_x`, `vel_y` (need vel), `kind`, any one-component array (`p`, `rho`, ...),
 *  and `NAME_x`, `NAME_y` of a vector array.
 *  @return CLSPH_E_INPUT with a message listing the fields there are, for an unknown name */
enum clsph_status field_find(const char *name, int narrays, const char *const *names,
                             const int *ncomp, struct field_spec *out);
/** @brief The array of `in` called `name`, or NULL. */
const struct render_array *field_array(const struct render_input *in, const char *name);
/** @brief Whether a particle of this kind is drawn for this field: every kind for `kind`; fluid,
 *  inflow and outflow particles for the others (wall particles are the walls' business). */
int field_drawn(const struct field_spec *f, int kind);
/** @brief Values of a field at every particle (n, into out). */
enum clsph_status field_values(const struct field_spec *f, const struct render_input *in,
                               double *out);
/** @brief Vorticity ω = ∂v/∂x − ∂u/∂y of every particle by a corrected SPH gradient over its
 *  neighbours (the formula: field.c), found through a cell grid.
 *  @param pos n x 2, m; vel n x 2, m/s; vol n, m²
 *  @param out n, 1/s */
enum clsph_status field_vorticity(size_t n, const double *pos, const double *vel, const double *vol,
                                  double *out);
/** @brief The typical spacing of the drawn particles: √(median V) over those with a volume, 0 when
 *  none has one. Particles with no volume of their own (USAW wall vertices) are drawn this size. */
double field_spacing(const struct field_spec *f, size_t n, const double *vol, const double *kind);
/** @brief The 0.5th and 99.5th percentiles of the finite values of the drawn particles (the
 *  extremes for fewer than 200 values), into lo and hi when there are any.
 *  @return how many values there are */
size_t field_percentiles(const struct field_spec *f, size_t n, const double *v, const double *kind,
                         double *lo, double *hi);
/** @brief The rules of an automatic range on lo .. hi (`have` 0: nothing drawn): from 0 for the
 *  speed; symmetric about 0 for a diverging map; widened around the value when flat. */
void field_range_rules(const struct field_spec *f, enum colormap_kind map, int have, double *lo,
                       double *hi);
/** @brief Automatic colour range of a frame from the values of its drawn particles: the 0.5th to
 *  the 99.5th percentile (a few spikes at wall corners do not wash the picture out); from 0 for
 *  the speed; symmetric about 0 (±the 99.5th percentile of |value|) for a diverging map; widened
 *  when empty or flat. */
void field_auto_range(const struct field_spec *f, enum colormap_kind map, size_t n, const double *v,
                      const double *kind, double *lo, double *hi);

/* ---- frames (render.c) ---- */

/** A camera for 3-D frames: the particles seen in perspective from `eye`, looking at `at`, `up`
 *  upward in the picture, `fov` the vertical field of view, degrees. */
struct render_camera {
  double eye[3], at[3], up[3];
  double fov;
};

/** How frames are drawn: the command line's and the case's choices. */
struct render_opts {
  char field[RENDER_NAME]; /* field name (field_find) */
  int width, height;       /* pixels */
  int fixed;               /* 1: the colour range is lo .. hi; 0: automatic */
  double lo, hi;           /* the fixed range, in the field's unit */
  enum colormap_kind map;  /* COLORMAP_AUTO: by the field */
  const char *font;        /* a TrueType file; NULL: $CLSPH_FONT, else DejaVu Sans (fontconfig) */
  int camera_set;          /* 3-D frames: 1, the camera below; 0, render_default_camera's of
                            * box3, or of the first frame's particles without it, kept for the
                            * frames after it */
  struct render_camera camera;
  double fov_only; /* > 0 without camera_set: the default camera with this field of view */
  int box3_set;    /* 3-D: 1, the default camera sees box3 (x0, y0, z0, x1, y1, z1) whole */
  double box3[6];
};

/** @brief A camera that sees a box (x0, y0, z0, x1, y1, z1) whole: from the front, right and above
 *  (the direction (0.55, −0.75, 0.45) from its centre), z up, a field of view of `fov` degrees
 *  (0: 30). */
void render_default_camera(const double box[6], double fov, struct render_camera *c);
/** @brief Check a camera: finite, its eye off its target, `up` not along the view, 1° < fov < 170°;
 *  the message names `what` (e.g. "--camera"). */
enum clsph_status render_check_camera(const struct render_camera *c, const char *what);

/** Where the time of a frame went, s. */
struct render_times {
  double field;   /* field values, colour range, colours, pixel coordinates */
  double draw;    /* OpenGL drawing and reading the pixels back */
  double text;    /* the colour bar's and the title's text */
  double png;     /* PNG encoding and writing */
  double total;   /* all of it */
  size_t drawn;   /* particles drawn */
  double disc_px; /* diameter of a typical disc, pixels */
};

struct render;

/** @brief The map a frame of field f uses when `asked` (COLORMAP_AUTO: by the field: kind for
 *  `kind`, coolwarm for signed fields, else viridis). */
enum colormap_kind render_map_for(const struct field_spec *f, enum colormap_kind asked);
/** @brief Defaults: speed, 1280 x 720, automatic range and map, the default font. */
void render_defaults(struct render_opts *o);
/** @brief Open an off-screen renderer: OSMesa context, pixel buffer, font. Fails (with the
 *  reason) when the size is not from 16 to 8192 pixels, OSMesa cannot make a context, or the font
 *  is not found. */
enum clsph_status render_create(const struct render_opts *o, struct render **out);
/** @brief Fix the colour range of the frames to come (e.g. over a whole series). */
void render_set_range(struct render *r, double lo, double hi);
/** @brief Grow box (x0, y0, z0, x1, y1, z1) over the 3-D particles a field draws. */
void render_extend_box(const struct field_spec *f, const struct render_input *in, double box[6]);
/** @brief The box the default camera of 3-D frames sees whole (what render_opts.box3 says), from
 *  the next frame on; nothing when a camera is set or the first frame has fixed it. */
void render_set_view3(struct render *r, const double box[6]);
/** @brief Draw one frame of field `f` and write it to `png_path` (through "<path>.tmp").
 *  @param lo_hi receives the colour range used (NULL: not wanted)
 *  @param t     receives where the time went (NULL: not wanted) */
enum clsph_status render_frame(struct render *r, const struct field_spec *f,
                               const struct render_input *in, const char *png_path, double lo_hi[2],
                               struct render_times *t);
/** Where things are in the last frame (for tests and tools). */
struct render_layout {
  double scale;           /* pixels per metre (3-D: at the distance of the camera's target) */
  double view[4];         /* the view box x0, y0, x1, y1, m (3-D: 0) */
  double origin[2];       /* pixel position of the view's top-left corner (x0, y1) (3-D: of the
                           * camera's target, the view's centre) */
  int band_px;            /* width of the solid band behind a wall, pixels */
  float line_px;          /* width of a wall line, pixels */
  int bar[4];             /* the colour bar's pixels [x0, x1) x [y0, y1): x0, y0, x1, y1 */
  int margin;             /* outer margin, pixels */
  int title_px, label_px; /* text sizes, pixels */
  enum colormap_kind map; /* the map used */
  double lo, hi;          /* the colour range used */
};

/** Colours of a frame's parts (RGB). */
extern const unsigned char render_colour_bg[3], render_colour_solid[3], render_colour_wall[3],
    render_colour_text[3];

/** @brief The layout of the last frame. */
void render_layout(const struct render *r, struct render_layout *out);
/** @brief Pixel coordinates (x right, y down, pixel (i, j) spans [i, i+1) x [j, j+1)) of a world
 *  point in a frame of this layout. */
void render_to_pixel(const struct render_layout *l, double x, double y, double *px, double *py);
/** @brief The last frame's pixels: width x height x 3 bytes (RGB, top row first). */
const unsigned char *render_pixels(const struct render *r, int *width, int *height);
/** @brief What draws (OpenGL's renderer and version) and the font file, for reports. */
void render_describe(const struct render *r, const char **gl, const char **font);
/** @brief Release everything (NULL is fine). */
void render_destroy(struct render *r);

/* ---- PNG (image.c) ---- */

/** @brief Write RGB pixels (top row first) as an 8-bit PNG, with no time stamp or text chunk, under
 *  "<path>.tmp" and renamed once complete. */
enum clsph_status image_write_png(const char *path, const unsigned char *rgb, int width,
                                  int height);
/** @brief Read a PNG into malloc'd RGB pixels (top row first; alpha dropped, palettes and grey
 *  expanded, 16-bit reduced to 8). */
enum clsph_status image_read_png(const char *path, unsigned char **rgb, int *width, int *height);

/* ---- movies (movie.c) ---- */

/** @brief Encode frames FRAMES_NNNNNN.png (`pattern` is the printf pattern, e.g.
 *  "out/cavity/frames/speed_%06d.png"; `count` frames from number `first`) into an H.264 MP4 at
 *  `fps` frames per second by running ffmpeg ($CLSPH_FFMPEG, else `ffmpeg` on the PATH) as a
 *  child process. When ffmpeg is not there, a warning says so (the frames stay) and *made is 0.
 *  @return CLSPH_E_IO when ffmpeg fails (its exit status and the command in the message) */
enum clsph_status movie_make(const char *pattern, int first, int count, int fps, const char *mp4,
                             int *made);

#endif /* CLSPH_RENDER_H */
