/* out.c: the output folder of a run: paths in it, its creation, and closing what is open. */
#include "out.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "log.h"
#include "str.h"

enum clsph_status out_path(const struct run_out *o, const char *name, char **path)
{
  enum clsph_status st = CLSPH_OK;
  *path = str_printf("%s/%s", o->dir, name);
  CLSPH_CHECK(*path != NULL, CLSPH_E_NOMEM, "out of memory");
done:
  return st;
}

enum clsph_status out_prepare_dir(const char *dir)
{
  enum clsph_status st = CLSPH_OK;
  char *path = NULL;
  CLSPH_CHECK(strlen(dir) > 0, CLSPH_E_INPUT, "--out: the folder name is empty");
  path = str_printf("%s", dir);
  CLSPH_CHECK(path != NULL, CLSPH_E_NOMEM, "out of memory");
  for (char *p = path + 1; *p != '\0'; ++p) {
    if (*p != '/') continue;
    *p = '\0';
    mkdir(path, 0755);
    *p = '/';
  }
  if (mkdir(path, 0755) != 0 && errno != EEXIST) {
    log_error("output folder %s cannot be created: %s", dir, strerror(errno));
    st = CLSPH_E_IO;
    goto done;
  }
  free(path);
  path = str_printf("%s/.clsph-write-test", dir);
  CLSPH_CHECK(path != NULL, CLSPH_E_NOMEM, "out of memory");
  FILE *f = fopen(path, "w");
  if (f == NULL) {
    log_error("output folder %s cannot be written: %s", dir, strerror(errno));
    st = CLSPH_E_IO;
    goto done;
  }
  fclose(f);
  remove(path);
done:
  free(path);
  return st;
}

void out_close(const struct scene *s, struct run_out *o)
{
  if (o->probes != NULL) fclose(o->probes);
  if (o->forces != NULL) fclose(o->forces);
  if (o->flow != NULL) fclose(o->flow);
  for (int p = 0; o->profiles != NULL && p < s->nprofiles; ++p)
    if (o->profiles[p] != NULL) fclose(o->profiles[p]);
  free(o->profiles);
  free(o->force_stats);
  free(o->force_scratch);
  io_series_free(&o->series);
  frames_close(o->frames);
  free(o->walls);
  for (int a = 0; a < o->nframe_arrays; ++a) free(o->frame_arrays[a]);
  free(o->dir);
  o->dir = NULL;
}
