/* draw.h: OpenGL drawing in an off-screen OSMesa context, for render.c (see draw.c). Pixel
 * coordinates: x right, y down from the top-left corner; colours are 8-bit RGB. */
#ifndef CLSPH_DRAW_H
#define CLSPH_DRAW_H

#include <stddef.h>

#include "status.h"

struct draw;

/** @brief An OSMesa context drawing into a w x h RGBA buffer, with a stencil buffer and the disc
 *  shader. */
enum clsph_status draw_create(int w, int h, struct draw **out);
/** @brief Make the context current and clear the image to a colour. */
enum clsph_status draw_begin(struct draw *d, const unsigned char rgb[3]);
/** @brief Anti-aliased discs: centres xy (n x 2), diameters (n), colours rgb (n x 3). */
void draw_discs(struct draw *d, size_t n, const float *xy, const float *diam,
                const unsigned char *rgb);
/** @brief Lit spheres (3-D views), drawn in the order given (back to front): centres xyz (n x 3:
 *  pixels, and the depth in [−1, 1], larger nearer, tested against draw_faces' while
 *  draw_depth is on), diameters (n), colours rgb (n x 3). */
void draw_spheres(struct draw *d, size_t n, const float *xyz, const float *diam,
                  const unsigned char *rgb);
/** @brief Depth testing on (the depth buffer cleared), drawing only inside the pixels [x0, x1) x
 *  [y0, y1), or both off (on = 0), for 3-D views: what is drawn while it is on hides what is
 *  drawn after it farther away. */
void draw_depth(struct draw *d, int on, int x0, int y0, int x1, int y1);
/** @brief Triangles (ntri x 3 vertices of xyz: pixels and the depth as draw_spheres'), each
 *  vertex in its colour (ntri x 3 x 3). */
void draw_faces(struct draw *d, size_t ntri, const float *xyz, const unsigned char *rgb);
/** @brief Square points of `size` pixels (1 or 2): centres xy (n x 2), colours rgb (n x 3). */
void draw_points(struct draw *d, size_t n, const float *xy, int size, const unsigned char *rgb);
/** @brief Triangles (ntri x 3 vertices of xy) in one colour. */
void draw_triangles(struct draw *d, size_t ntri, const float *xy, const unsigned char rgb[3]);
/** @brief Axis-aligned rectangles x0, y0, x1, y1 (n x 4), each in its colour (n x 3). */
void draw_rects(struct draw *d, size_t n, const float *rect, const unsigned char *rgb);
/** @brief Line segments (nseg x 2 vertices of xy) of a width in pixels, anti-aliased when
 *  `smooth`, in one colour. */
void draw_lines(struct draw *d, size_t nseg, const float *xy, float width, int smooth,
                const unsigned char rgb[3]);
/** @brief Fill a simple polygon (npts vertices of xy, convex or not) in one colour, through the
 *  stencil buffer (even-odd rule). */
void draw_polygon(struct draw *d, int npts, const float *xy, const unsigned char rgb[3]);
/** @brief Finish drawing and copy the image out: w x h x 3 bytes, top row first. */
enum clsph_status draw_read(struct draw *d, unsigned char *rgb);
/** @brief What draws: OpenGL's renderer and version strings. */
const char *draw_renderer(const struct draw *d);
/** @brief Release the context (NULL is fine). */
void draw_destroy(struct draw *d);

#endif /* CLSPH_DRAW_H */
