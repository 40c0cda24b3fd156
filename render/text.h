/* text.h: text drawn into RGB images with FreeType, for render.c (see text.c). */
#ifndef CLSPH_TEXT_H
#define CLSPH_TEXT_H

#include "status.h"

struct text;

/** The extent of a line of text, pixels. */
struct text_box {
  int width;   /* advance from the start to the end */
  int ascent;  /* the font's height above the baseline at this size */
  int descent; /* and below it */
};

/** @brief Open a font: the TrueType file `font`, else $CLSPH_FONT, else DejaVu Sans through
 *  fontconfig. A missing font is an error that names the Debian package (fonts-dejavu-core). */
enum clsph_status text_open(const char *font, struct text **out);
/** @brief The font file in use. */
const char *text_font_path(const struct text *t);
/** @brief Width of a UTF-8 string at a pixel size, and the font's ascent and descent. */
enum clsph_status text_measure(struct text *t, int px, const char *s, struct text_box *box);
/** @brief Draw a UTF-8 string into an RGB image (w x h x 3, top row first) from x along the
 *  baseline y, at a pixel size, blending its colour over the image by the glyphs' coverage.
 *  What falls outside the image is cut. */
enum clsph_status text_draw(struct text *t, unsigned char *rgb, int w, int h, int x, int baseline,
                            int px, const char *s, const unsigned char colour[3]);
/** @brief Release the font (NULL is fine). */
void text_close(struct text *t);

#endif /* CLSPH_TEXT_H */
