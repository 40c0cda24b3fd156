/* out.c: the output folder of a run: paths in it, its creation, and closing what is open. */
#include "out.h"

#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

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

/* Is `name`, an entry of an output folder, something `clsph run` writes there? Its number
 * (snapshots, checkpoints, frames) into *num when it has one, else −1. */
static int is_output(const char *name, long *num)
{
  static const char *const files[] = {"snapshots.xdmf", "summary.json",     "probes.csv",
                                      "forces.csv",     "flow_control.csv", "series.csv",
                                      "blowup.h5"};
  const size_t len = strlen(name);
  int n = 0;
  *num = -1;
  for (size_t k = 0; k < sizeof files / sizeof *files; ++k)
    if (strcmp(name, files[k]) == 0) return 1;
  if (sscanf(name, "snap_%ld.h5%n", num, &n) == 1 && (size_t)n == len) return 1;
  if (sscanf(name, "checkpoint_%ld.h5%n", num, &n) == 1 && (size_t)n == len) return 1;
  *num = -1;
  if (strncmp(name, "profile_", 8) == 0 && len > 12 && strcmp(name + len - 4, ".csv") == 0)
    return 1;
  if (len > 4 && (strcmp(name + len - 4, ".mp4") == 0 || strcmp(name + len - 4, ".tmp") == 0))
    return 1;
  return strcmp(name, "frames") == 0;
}

/* A frame FIELD_NNNNNN.png: its number, else −1. */
static long frame_number(const char *name)
{
  const size_t len = strlen(name);
  if (len < 15 || strcmp(name + len - 4, ".png") != 0 || name[len - 11] != '_') return -1;
  long k = 0;
  for (size_t i = len - 10; i < len - 4; ++i) {
    if (name[i] < '0' || name[i] > '9') return -1;
    k = 10 * k + (name[i] - '0');
  }
  return k;
}

/* Remove dir/name, or the frames folder with the frames in it (the frames numbered from
 * `from` on, and the folder when it is left empty; from = 0: all). */
static enum clsph_status remove_output(const char *dir, const char *name, long from)
{
  enum clsph_status st = CLSPH_OK;
  char *path = str_printf("%s/%s", dir, name), *file = NULL;
  DIR *d = NULL;
  CLSPH_CHECK(path != NULL, CLSPH_E_NOMEM, "out of memory");
  if (strcmp(name, "frames") == 0) {
    d = opendir(path);
    for (struct dirent *e; d != NULL && (e = readdir(d)) != NULL;) {
      const long k = frame_number(e->d_name);
      if (k < from) continue;
      free(file);
      file = str_printf("%s/%s", path, e->d_name);
      CLSPH_CHECK(file != NULL, CLSPH_E_NOMEM, "out of memory");
      CLSPH_CHECK(remove(file) == 0, CLSPH_E_IO, "cannot remove %s: %s", file, strerror(errno));
    }
    if (from == 0) rmdir(path); /* left when it holds other files */
  } else {
    CLSPH_CHECK(remove(path) == 0, CLSPH_E_IO, "cannot remove %s: %s", path, strerror(errno));
  }
done:
  if (d != NULL) closedir(d);
  free(file);
  free(path);
  return st;
}

/* Do two paths name the same folder? */
static int same_dir(const char *a, const char *b)
{
  struct stat sa, sb;
  return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

enum clsph_status out_claim_dir(const char *dir, const char *restart, int overwrite, int *here_out)
{
  enum clsph_status st = CLSPH_OK;
  *here_out = 0;
  DIR *d = opendir(dir);
  char *ckdir = NULL, found[160] = "";
  long count = 0, num = 0;
  if (d == NULL) goto done; /* not there yet (or not a folder: out_prepare_dir says so) */
  for (struct dirent *e; (e = readdir(d)) != NULL;) {
    if (!is_output(e->d_name, &num)) continue;
    if (count++ < 3 && strlen(found) + strlen(e->d_name) + 3 < sizeof found) {
      if (count > 1) strcat(found, ", ");
      strcat(found, e->d_name);
    }
  }
  if (count == 0) goto done;
  if (restart != NULL) {
    const char *slash = strrchr(restart, '/');
    ckdir = slash == NULL ? str_printf(".") : str_printf("%.*s", (int)(slash - restart), restart);
    CLSPH_CHECK(ckdir != NULL, CLSPH_E_NOMEM, "out of memory");
  }
  const int here = ckdir != NULL && same_dir(ckdir, dir);
  *here_out = here;
  if (overwrite) {
    CLSPH_CHECK(!here, CLSPH_E_INPUT,
                "--overwrite would delete %s, the checkpoint --restart continues from: leave out "
                "--overwrite to continue in its folder, or give another --out",
                restart);
    rewinddir(d);
    for (struct dirent *e; (e = readdir(d)) != NULL;)
      if (is_output(e->d_name, &num)) CLSPH_TRY(remove_output(dir, e->d_name, 0));
    log_info("--overwrite: removed %ld outputs of an earlier run from %s", count, dir);
    goto done;
  }
  CLSPH_CHECK(here, CLSPH_E_INPUT,
              "--out %s holds the outputs of another run (%s%s): --overwrite clears them, "
              "--restart FILE continues a run from one of the checkpoints in its own folder; or "
              "choose another --out",
              dir, found, count > 3 ? ", ..." : "");
done:
  if (d != NULL) closedir(d);
  free(ckdir);
  return st;
}

enum clsph_status out_drop_after(const char *dir, long nsnap, long step)
{
  enum clsph_status st = CLSPH_OK;
  DIR *d = opendir(dir);
  long num = 0, dropped = 0;
  CLSPH_CHECK(d != NULL, CLSPH_E_IO, "cannot read the folder %s: %s", dir, strerror(errno));
  for (struct dirent *e; (e = readdir(d)) != NULL;) {
    if (!is_output(e->d_name, &num)) continue;
    const int snap = strncmp(e->d_name, "snap_", 5) == 0;
    const int later = num >= 0 ? (snap ? num >= nsnap : num > step)
                               : strcmp(e->d_name, "blowup.h5") == 0; /* the abandoned run's */
    const size_t len = strlen(e->d_name);
    const int movie = len > 4 && (strcmp(e->d_name + len - 4, ".mp4") == 0 ||
                                  strcmp(e->d_name + len - 4, ".tmp") == 0);
    if (strcmp(e->d_name, "frames") == 0) {
      CLSPH_TRY(remove_output(dir, e->d_name, nsnap));
    } else if (later || movie) {
      CLSPH_TRY(remove_output(dir, e->d_name, 0));
      ++dropped;
    }
  }
  if (dropped > 0)
    log_info("restart in %s: removed %ld snapshots, checkpoints and movies of the run after the "
             "checkpoint",
             dir, dropped);
done:
  if (d != NULL) closedir(d);
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
  if (o->samples != NULL) fclose(o->samples);
  case_values_free(&o->values);
  for (int p = 0; o->profiles != NULL && p < s->nprofiles; ++p)
    if (o->profiles[p] != NULL) fclose(o->profiles[p]);
  free(o->profiles);
  free(o->force_stats);
  free(o->force_scratch);
  io_series_free(&o->series);
  frames_close(o->frames);
  free(o->walls);
  free(o->turned);
  free(o->turned_pts);
  free(o->surf3);
  for (int a = 0; a < o->nframe_arrays; ++a) free(o->frame_arrays[a]);
  free(o->dir);
  o->dir = NULL;
}
