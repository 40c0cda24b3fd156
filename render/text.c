/* text.c: text drawn into RGB images with FreeType, in DejaVu Sans (Debian fonts-dejavu-core)
 * found through fontconfig, or in a TrueType file named by --font or $CLSPH_FONT.
 *
 * Glyphs are rendered hinted, 8-bit anti-aliased (FT_LOAD_RENDER), and laid down along the
 * baseline at whole-pixel advances with the font's kerning; each glyph's coverage a blends the
 * text colour c over the image: out = (out (255 − a) + c a + 127) / 255. The same font file and
 * the same FreeType give the same pixels. Strings are UTF-8. */
#include "text.h"

#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include FT_FREETYPE_H

#define TEXT_FAMILY "DejaVu Sans"

struct text {
  FT_Library lib;
  FT_Face face;
  int px; /* the pixel size set on the face (0: none yet) */
  char path[1024];
};

/* DejaVu Sans (Book) through fontconfig; anything else fontconfig offers instead is refused, so
 * that frames look the same everywhere. */
static enum clsph_status find_font(char *path, size_t size)
{
  enum clsph_status st = CLSPH_OK;
  FcConfig *cfg = NULL;
  FcPattern *pat = NULL, *match = NULL;
  FcChar8 *file = NULL, *family = NULL;
  FcResult res = FcResultNoMatch;
  cfg = FcInitLoadConfigAndFonts();
  CLSPH_CHECK(cfg != NULL, CLSPH_E_IO, "fontconfig cannot load its configuration");
  pat = FcNameParse((const FcChar8 *)TEXT_FAMILY ":style=Book");
  CLSPH_CHECK(pat != NULL, CLSPH_E_NOMEM, "out of memory");
  FcConfigSubstitute(cfg, pat, FcMatchPattern);
  FcDefaultSubstitute(pat);
  match = FcFontMatch(cfg, pat, &res);
  int found = match != NULL && FcPatternGetString(match, FC_FAMILY, 0, &family) == FcResultMatch &&
              FcPatternGetString(match, FC_FILE, 0, &file) == FcResultMatch &&
              strcmp((const char *)family, TEXT_FAMILY) == 0;
  CLSPH_CHECK(found, CLSPH_E_IO,
              "the font " TEXT_FAMILY " is not installed (fontconfig offers '%s' instead): install "
              "it with 'apt-get install fonts-dejavu-core', or name a TrueType file with --font "
              "FILE or CLSPH_FONT=FILE",
              family != NULL ? (const char *)family : "nothing");
  CLSPH_CHECK(strlen((const char *)file) < size, CLSPH_E_IO, "font path too long: %s", file);
  snprintf(path, size, "%s", (const char *)file);
done:
  if (match != NULL) FcPatternDestroy(match);
  if (pat != NULL) FcPatternDestroy(pat);
  if (cfg != NULL) FcConfigDestroy(cfg);
  return st;
}

enum clsph_status text_open(const char *font, struct text **out)
{
  enum clsph_status st = CLSPH_OK;
  struct text *t = calloc(1, sizeof *t);
  CLSPH_CHECK(t != NULL, CLSPH_E_NOMEM, "out of memory");
  const char *env = getenv("CLSPH_FONT");
  const char *given = font != NULL ? font : (env != NULL && env[0] != '\0' ? env : NULL);
  if (given != NULL) {
    CLSPH_CHECK(strlen(given) < sizeof t->path, CLSPH_E_INPUT, "font path too long: %s", given);
    snprintf(t->path, sizeof t->path, "%s", given);
  } else {
    CLSPH_TRY(find_font(t->path, sizeof t->path));
  }
  FT_Error err = FT_Init_FreeType(&t->lib);
  CLSPH_CHECK(err == 0, CLSPH_E_IO, "FreeType cannot start (error %d)", err);
  err = FT_New_Face(t->lib, t->path, 0, &t->face);
  CLSPH_CHECK(err == 0, CLSPH_E_IO, "cannot open the font %s%s (FreeType error %d); %s", t->path,
              given != NULL ? (font != NULL ? " (--font)" : " ($CLSPH_FONT)") : "", err,
              "name a TrueType file, e.g. /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf "
              "(apt-get install fonts-dejavu-core)");
  log_debug("text: font %s", t->path);
  *out = t;
  t = NULL;
done:
  text_close(t);
  return st;
}

const char *text_font_path(const struct text *t)
{
  return t->path;
}

static enum clsph_status set_size(struct text *t, int px)
{
  enum clsph_status st = CLSPH_OK;
  if (t->px == px) goto done;
  FT_Error err = FT_Set_Pixel_Sizes(t->face, 0, (FT_UInt)px);
  CLSPH_CHECK(err == 0, CLSPH_E_IO, "font %s: no %d-pixel size (FreeType error %d)", t->path, px,
              err);
  t->px = px;
done:
  return st;
}

/* The next code point of a UTF-8 string (a bad byte reads as U+FFFD and is skipped). */
static unsigned long next_cp(const char **s)
{
  const unsigned char *p = (const unsigned char *)*s;
  unsigned long cp = 0xFFFDul;
  int extra = 0;
  if (p[0] < 0x80) {
    cp = p[0];
  } else if ((p[0] & 0xE0) == 0xC0) {
    cp = p[0] & 0x1Fu;
    extra = 1;
  } else if ((p[0] & 0xF0) == 0xE0) {
    cp = p[0] & 0x0Fu;
    extra = 2;
  } else if ((p[0] & 0xF8) == 0xF0) {
    cp = p[0] & 0x07u;
    extra = 3;
  }
  int k = 1;
  for (; k <= extra; ++k) {
    if ((p[k] & 0xC0) != 0x80) {
      cp = 0xFFFDul;
      break;
    }
    cp = (cp << 6) | (p[k] & 0x3Fu);
  }
  *s += k > extra ? extra + 1 : k;
  return cp;
}

enum clsph_status text_measure(struct text *t, int px, const char *s, struct text_box *box)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(set_size(t, px));
  FT_UInt prev = 0;
  long pen = 0;
  while (*s != '\0') {
    FT_UInt g = FT_Get_Char_Index(t->face, next_cp(&s));
    if (prev != 0 && g != 0 && FT_HAS_KERNING(t->face)) {
      FT_Vector k;
      if (FT_Get_Kerning(t->face, prev, g, FT_KERNING_DEFAULT, &k) == 0)
        pen += k.x / 64; /* grid-fitted: whole pixels */
    }
    FT_Error err = FT_Load_Glyph(t->face, g, FT_LOAD_DEFAULT);
    CLSPH_CHECK(err == 0, CLSPH_E_IO, "font %s: glyph %u (FreeType error %d)", t->path, g, err);
    pen += (t->face->glyph->advance.x + 32) >> 6;
    prev = g;
  }
  box->width = (int)pen;
  box->ascent = (int)((t->face->size->metrics.ascender + 63) >> 6);
  box->descent = (int)((-t->face->size->metrics.descender + 63) >> 6);
done:
  return st;
}

enum clsph_status text_draw(struct text *t, unsigned char *rgb, int w, int h, int x, int baseline,
                            int px, const char *s, const unsigned char colour[3])
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(set_size(t, px));
  FT_UInt prev = 0;
  long pen = x;
  while (*s != '\0') {
    FT_UInt g = FT_Get_Char_Index(t->face, next_cp(&s));
    if (prev != 0 && g != 0 && FT_HAS_KERNING(t->face)) {
      FT_Vector k;
      if (FT_Get_Kerning(t->face, prev, g, FT_KERNING_DEFAULT, &k) == 0)
        pen += k.x / 64; /* grid-fitted: whole pixels */
    }
    FT_Error err = FT_Load_Glyph(t->face, g, FT_LOAD_RENDER);
    CLSPH_CHECK(err == 0, CLSPH_E_IO, "font %s: glyph %u (FreeType error %d)", t->path, g, err);
    const FT_GlyphSlot gs = t->face->glyph;
    const FT_Bitmap *bm = &gs->bitmap;
    CLSPH_CHECK(bm->pixel_mode == FT_PIXEL_MODE_GRAY || bm->rows == 0, CLSPH_E_IO,
                "font %s: glyph %u is not an 8-bit grey bitmap", t->path, g);
    const long x0 = pen + gs->bitmap_left, y0 = (long)baseline - gs->bitmap_top;
    for (unsigned r = 0; r < bm->rows; ++r) {
      const long y = y0 + (long)r;
      if (y < 0 || y >= h) continue;
      const unsigned char *src = bm->buffer + (long)r * bm->pitch;
      for (unsigned c = 0; c < bm->width; ++c) {
        const long xx = x0 + (long)c;
        const unsigned a = src[c];
        if (xx < 0 || xx >= w || a == 0) continue;
        unsigned char *p = rgb + 3 * ((size_t)y * (size_t)w + (size_t)xx);
        for (int k = 0; k < 3; ++k)
          p[k] = (unsigned char)((p[k] * (255u - a) + colour[k] * a + 127u) / 255u);
      }
    }
    pen += (gs->advance.x + 32) >> 6;
    prev = g;
  }
done:
  return st;
}

void text_close(struct text *t)
{
  if (t == NULL) return;
  if (t->face != NULL) FT_Done_Face(t->face);
  if (t->lib != NULL) FT_Done_FreeType(t->lib);
  free(t);
}
