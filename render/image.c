/* image.c: PNG files through libpng. Frames are written as 8-bit RGB, not interlaced, with no
 * tIME, text or other ancillary chunk, so the same pixels give the same bytes; the file is written
 * under "<path>.tmp" and renamed once complete (a crash never leaves half a frame under its name).
 * libpng reports errors through a longjmp; each is reported once here with the path and
 * libpng's reason. */
#include "render.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "str.h"

/* libpng's error and warning handlers: keep the message, jump back. */
struct png_err {
  char msg[256];
};

static void on_error(png_structp png, png_const_charp msg)
{
  struct png_err *e = png_get_error_ptr(png);
  snprintf(e->msg, sizeof e->msg, "%s", msg);
  png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp msg)
{
  (void)png;
  log_debug("libpng: %s", msg);
}

/* The libpng calls of a write, in one frame that changes no local after setjmp. Returns 0 on
 * success. Compression: zlib level 3 with no row filter. Frames are large areas of flat colour,
 * which deflate finds best unfiltered: on the frames of `clsph bench render` (1e4 to 1e6
 * particles) the SUB, UP and adaptive filters gave files 1% to 30% larger and slower to write;
 * level 6 gave files from 3% larger to 31% smaller, in about twice the time. */
static int write_all(png_structp png, png_infop info, FILE *f, const unsigned char *rgb, int w,
                     int h)
{
  if (setjmp(png_jmpbuf(png))) return 1;
  png_init_io(png, f);
  png_set_compression_level(png, 3);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < h; ++y) png_write_row(png, rgb + (size_t)y * (size_t)w * 3);
  png_write_end(png, NULL);
  return 0;
}

enum clsph_status image_write_png(const char *path, const unsigned char *rgb, int width, int height)
{
  enum clsph_status st = CLSPH_OK;
  struct png_err e = {""};
  png_structp png = NULL;
  png_infop info = NULL;
  FILE *f = NULL;
  char *tmp = str_printf("%s.tmp", path);
  CLSPH_CHECK(tmp != NULL, CLSPH_E_NOMEM, "out of memory");
  f = fopen(tmp, "wb");
  CLSPH_CHECK(f != NULL, CLSPH_E_IO, "cannot write %s: %s", tmp, strerror(errno));
  png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &e, on_error, on_warning);
  info = png != NULL ? png_create_info_struct(png) : NULL;
  CLSPH_CHECK(info != NULL, CLSPH_E_NOMEM, "out of memory (libpng) writing %s", path);
  CLSPH_CHECK(write_all(png, info, f, rgb, width, height) == 0, CLSPH_E_IO,
              "cannot write %s: libpng: %s", path, e.msg);
  int closed = fclose(f);
  f = NULL;
  CLSPH_CHECK(closed == 0, CLSPH_E_IO, "cannot write %s: %s", tmp, strerror(errno));
  CLSPH_CHECK(rename(tmp, path) == 0, CLSPH_E_IO, "cannot rename %s to %s: %s", tmp, path,
              strerror(errno));
done:
  if (png != NULL) png_destroy_write_struct(&png, info != NULL ? &info : NULL);
  if (f != NULL) fclose(f);
  if (st != CLSPH_OK && tmp != NULL) remove(tmp);
  free(tmp);
  return st;
}

/* The libpng calls of a read into *rows (malloc'd by this function: volatile-free, since it is
 * only assigned once before any call that can jump). Returns 0 on success. */
static int read_all(png_structp png, png_infop info, FILE *f, unsigned char **out, int *w, int *h)
{
  if (setjmp(png_jmpbuf(png))) return 1;
  png_init_io(png, f);
  png_read_info(png, info);
  png_set_expand(png);
  png_set_strip_16(png);
  png_set_strip_alpha(png);
  png_set_gray_to_rgb(png);
  png_read_update_info(png, info);
  const png_uint_32 pw = png_get_image_width(png, info), ph = png_get_image_height(png, info);
  if (png_get_rowbytes(png, info) != (size_t)pw * 3 || pw == 0 || ph == 0 || pw > 65536 ||
      ph > 65536)
    return 2;
  *w = (int)pw;
  *h = (int)ph;
  *out = malloc((size_t)pw * (size_t)ph * 3);
  if (*out == NULL) return 3;
  for (png_uint_32 y = 0; y < ph; ++y) png_read_row(png, *out + (size_t)y * (size_t)pw * 3, NULL);
  png_read_end(png, NULL);
  return 0;
}

enum clsph_status image_read_png(const char *path, unsigned char **rgb, int *width, int *height)
{
  enum clsph_status st = CLSPH_OK;
  struct png_err e = {""};
  png_structp png = NULL;
  png_infop info = NULL;
  unsigned char *pix = NULL;
  FILE *f = fopen(path, "rb");
  CLSPH_CHECK(f != NULL, CLSPH_E_IO, "cannot read %s: %s", path, strerror(errno));
  png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &e, on_error, on_warning);
  info = png != NULL ? png_create_info_struct(png) : NULL;
  CLSPH_CHECK(info != NULL, CLSPH_E_NOMEM, "out of memory (libpng) reading %s", path);
  int w = 0, h = 0, rc = read_all(png, info, f, &pix, &w, &h);
  CLSPH_CHECK(rc != 1, CLSPH_E_IO, "cannot read %s: libpng: %s", path, e.msg);
  CLSPH_CHECK(rc != 2, CLSPH_E_IO, "cannot read %s: not an 8-bit RGB image of a sane size", path);
  CLSPH_CHECK(rc == 0, CLSPH_E_NOMEM, "out of memory reading %s", path);
  *rgb = pix;
  pix = NULL;
  *width = w;
  *height = h;
done:
  if (png != NULL) png_destroy_read_struct(&png, info != NULL ? &info : NULL, NULL);
  if (f != NULL) fclose(f);
  free(pix);
  return st;
}
