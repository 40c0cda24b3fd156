/* prog.c: program sources, build options, build with the compiler log, and the binary cache. */
#include "prog.h"

#include <errno.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "clsph_config.h"

static const char *kernel_dir = NULL;
static const char *cache_dir_opt = NULL;
static int fast_math = 0;
static int last_from_cache = 0;

void prog_set_kernel_dir(const char *dir)
{
  kernel_dir = dir;
}

void prog_set_cache_dir(const char *dir)
{
  cache_dir_opt = dir;
}

void prog_set_fast_math(int on)
{
  fast_math = on;
}

int prog_last_from_cache(void)
{
  return last_from_cache;
}

/* ---- options ---- */

static enum clsph_status opts_append(struct prog_opts *o, const char *fmt, ...)
{
  enum clsph_status st = CLSPH_OK;
  va_list ap;
  va_start(ap, fmt);
  int need = vsnprintf(NULL, 0, fmt, ap);
  va_end(ap);
  CLSPH_CHECK(need >= 0, CLSPH_E_INPUT, "cannot format a build option");
  if (o->len + (size_t)need + 2 > o->cap) {
    size_t cap = 2 * (o->len + (size_t)need + 2) + 64;
    char *grown = realloc(o->text, cap);
    CLSPH_CHECK(grown != NULL, CLSPH_E_NOMEM, "out of memory for build options");
    o->text = grown;
    o->cap = cap;
  }
  if (o->len > 0) o->text[o->len++] = ' ';
  va_start(ap, fmt);
  int wrote = vsnprintf(o->text + o->len, o->cap - o->len, fmt, ap);
  va_end(ap);
  CLSPH_ASSERT(wrote == need);
  o->len += (size_t)wrote;
done:
  return st;
}

enum clsph_status prog_opts_define(struct prog_opts *o, const char *name, const char *value)
{
  if (value == NULL) return opts_append(o, "-D %s", name);
  return opts_append(o, "-D %s=%s", name, value);
}

enum clsph_status prog_opts_define_int(struct prog_opts *o, const char *name, long v)
{
  return opts_append(o, "-D %s=%ld", name, v);
}

enum clsph_status prog_opts_define_real(struct prog_opts *o, const char *name, double v)
{
  /* %.17e always has a decimal point and exponent, so R() can append the float suffix. */
  return opts_append(o, "-D %s=R(%.17e)", name, v);
}

void prog_opts_free(struct prog_opts *o)
{
  free(o->text);
  o->text = NULL;
  o->len = o->cap = 0;
}

/* ---- sources ---- */

struct source_set {
  size_t n;       /* strings (each source is two: its #line directive and its text) */
  char **owned;   /* texts read from --kernel-dir, or NULL */
  const char **s; /* strings */
  size_t *len;    /* lengths */
  char **lines;   /* #line directives */
};

static void sources_free(struct source_set *set)
{
  for (size_t i = 0; i < (set->n + 1) / 2; ++i) {
    if (set->owned != NULL) free(set->owned[i]);
    if (set->lines != NULL) free(set->lines[i]);
  }
  free(set->owned);
  free(set->lines);
  free(set->s);
  free(set->len);
  memset(set, 0, sizeof *set);
}

static enum clsph_status read_file(const char *path, char **out, size_t *len)
{
  enum clsph_status st = CLSPH_OK;
  FILE *f = fopen(path, "rb");
  char *text = NULL;
  CLSPH_CHECK(f != NULL, CLSPH_E_IO, "cannot read kernel source %s: %s", path, strerror(errno));
  CLSPH_CHECK(fseek(f, 0, SEEK_END) == 0, CLSPH_E_IO, "cannot seek in %s", path);
  long size = ftell(f);
  CLSPH_CHECK(size >= 0, CLSPH_E_IO, "cannot size %s", path);
  rewind(f);
  text = malloc((size_t)size + 1);
  CLSPH_CHECK(text != NULL, CLSPH_E_NOMEM, "out of memory reading %s", path);
  CLSPH_CHECK(fread(text, 1, (size_t)size, f) == (size_t)size, CLSPH_E_IO, "cannot read %s", path);
  text[size] = '\0';
  *out = text;
  *len = (size_t)size;
  text = NULL;
done:
  free(text);
  if (f != NULL) fclose(f);
  return st;
}

static enum clsph_status sources_load(const char *const *paths, const char *extra_name,
                                      const char *extra_text, struct source_set *set)
{
  enum clsph_status st = CLSPH_OK;
  size_t count = 0;
  char *full = NULL;
  while (paths[count] != NULL) ++count;
  set->n = 2 * count + (extra_text != NULL ? 2 : 0);
  set->owned = calloc(count + 1, sizeof *set->owned);
  set->lines = calloc(count + 1, sizeof *set->lines);
  set->s = calloc(2 * count + 2, sizeof *set->s);
  set->len = calloc(2 * count + 2, sizeof *set->len);
  CLSPH_CHECK(set->owned && set->lines && set->s && set->len, CLSPH_E_NOMEM,
              "out of memory for kernel sources");
  for (size_t i = 0; i < count; ++i) {
    const char *text = NULL;
    size_t len = 0;
    if (kernel_dir != NULL) {
      size_t need = strlen(kernel_dir) + strlen(paths[i]) + 2;
      full = malloc(need);
      CLSPH_CHECK(full != NULL, CLSPH_E_NOMEM, "out of memory for kernel sources");
      snprintf(full, need, "%s/%s", kernel_dir, paths[i]);
      CLSPH_TRY(read_file(full, &set->owned[i], &len));
      text = set->owned[i];
      free(full);
      full = NULL;
    } else {
      for (size_t k = 0; k < prog_embedded_count; ++k) {
        if (strcmp(prog_embedded_sources[k].path, paths[i]) == 0) {
          text = prog_embedded_sources[k].text;
          len = prog_embedded_sources[k].len;
        }
      }
      CLSPH_CHECK(text != NULL, CLSPH_E_INPUT, "kernel source '%s' is not among the embedded ones",
                  paths[i]);
    }
    /* #line names the file in compiler messages; the newline ends a text without one. */
    size_t need = strlen(paths[i]) + 32;
    set->lines[i] = malloc(need);
    CLSPH_CHECK(set->lines[i] != NULL, CLSPH_E_NOMEM, "out of memory for kernel sources");
    snprintf(set->lines[i], need, "\n#line 1 \"kernels/%s\"\n", paths[i]);
    set->s[2 * i] = set->lines[i];
    set->len[2 * i] = strlen(set->lines[i]);
    set->s[2 * i + 1] = text;
    set->len[2 * i + 1] = len;
  }
  if (extra_text != NULL) {
    size_t need = strlen(extra_name) + 32;
    set->lines[count] = malloc(need);
    CLSPH_CHECK(set->lines[count] != NULL, CLSPH_E_NOMEM, "out of memory for kernel sources");
    snprintf(set->lines[count], need, "\n#line 1 \"%s\"\n", extra_name);
    set->s[2 * count] = set->lines[count];
    set->len[2 * count] = strlen(set->lines[count]);
    set->s[2 * count + 1] = extra_text;
    set->len[2 * count + 1] = strlen(extra_text);
  }
done:
  free(full);
  return st;
}

/* ---- cache ---- */

static uint64_t fnv1a(uint64_t h, const void *data, size_t len)
{
  const unsigned char *p = data;
  for (size_t i = 0; i < len; ++i) {
    h ^= p[i];
    h *= 1099511628211ull;
  }
  return h;
}

static uint64_t cache_key(const struct dev *dev, const char *opts, const struct source_set *set)
{
  uint64_t h = 14695981039346656037ull;
  const char *parts[] = {dev->platform_name, dev->name, dev->version, dev->driver, opts};
  for (size_t i = 0; i < sizeof parts / sizeof *parts; ++i)
    h = fnv1a(h, parts[i], strlen(parts[i]) + 1);
  for (size_t i = 0; i < set->n; ++i) {
    h = fnv1a(h, &set->len[i], sizeof set->len[i]);
    h = fnv1a(h, set->s[i], set->len[i]);
  }
  return h;
}

/* The cache folder, created if needed; NULL when disabled or impossible (not an error). */
static char *cache_dir(void)
{
  const char *base = cache_dir_opt;
  const char *suffix = "";
  if (base == NULL) base = getenv("CLSPH_CACHE_DIR");
  if (base == NULL) {
    base = getenv("XDG_CACHE_HOME");
    suffix = "/clsph";
  }
  if (base == NULL) {
    base = getenv("HOME");
    suffix = "/.cache/clsph";
  }
  if (base == NULL || base[0] == '\0') return NULL;
  size_t need = strlen(base) + strlen(suffix) + 1;
  char *dir = malloc(need);
  if (dir == NULL) return NULL;
  snprintf(dir, need, "%s%s", base, suffix);
  for (char *p = dir + 1; *p != '\0'; ++p) { /* mkdir -p */
    if (*p != '/') continue;
    *p = '\0';
    mkdir(dir, 0755);
    *p = '/';
  }
  if (mkdir(dir, 0755) != 0 && errno != EEXIST) {
    log_debug("program cache disabled: cannot create %s: %s", dir, strerror(errno));
    free(dir);
    return NULL;
  }
  return dir;
}

static const char cache_magic[8] = {'C', 'L', 'S', 'P', 'H', 'B', 'N', '1'};

static char *cache_path(const char *dir, uint64_t key)
{
  size_t need = strlen(dir) + 32;
  char *path = malloc(need);
  if (path != NULL) snprintf(path, need, "%s/%016llx.bin", dir, (unsigned long long)key);
  return path;
}

/* Try the cached binary; any problem means "not cached" (and a rebuild), never an error. */
static cl_program cache_load(const struct dev *dev, const char *path, const char *opts)
{
  FILE *f = fopen(path, "rb");
  unsigned char *bin = NULL;
  cl_program prog = NULL;
  char magic[8];
  uint64_t size = 0;
  if (f == NULL) return NULL;
  if (fread(magic, 1, 8, f) != 8 || memcmp(magic, cache_magic, 8) != 0) goto fail;
  if (fread(&size, sizeof size, 1, f) != 1 || size == 0 || size > (1u << 30)) goto fail;
  bin = malloc((size_t)size);
  if (bin == NULL || fread(bin, 1, (size_t)size, f) != (size_t)size) goto fail;
  cl_int status = CL_SUCCESS, err = CL_SUCCESS;
  size_t len = (size_t)size;
  const unsigned char *bins[] = {bin};
  prog = clCreateProgramWithBinary(dev->ctx, 1, &dev->id, &len, bins, &status, &err);
  if (err != CL_SUCCESS || status != CL_SUCCESS) goto fail;
  if (clBuildProgram(prog, 1, &dev->id, opts, NULL, NULL) != CL_SUCCESS) goto fail;
  free(bin);
  fclose(f);
  return prog;
fail:
  log_debug("program cache: %s unusable, rebuilding", path);
  if (prog != NULL) clReleaseProgram(prog);
  free(bin);
  fclose(f);
  return NULL;
}

/* Store the binary; failures are only logged (the cache is an optimisation). */
static void cache_store(const struct dev *dev, cl_program prog, const char *path)
{
  size_t size = 0;
  unsigned char *bin = NULL;
  char *tmp = NULL;
  FILE *f = NULL;
  if (clGetProgramInfo(prog, CL_PROGRAM_BINARY_SIZES, sizeof size, &size, NULL) != CL_SUCCESS ||
      size == 0)
    goto done;
  bin = malloc(size);
  unsigned char *bins[] = {bin};
  if (bin == NULL ||
      clGetProgramInfo(prog, CL_PROGRAM_BINARIES, sizeof bins, bins, NULL) != CL_SUCCESS)
    goto done;
  size_t need = strlen(path) + 32;
  tmp = malloc(need);
  if (tmp == NULL) goto done;
  snprintf(tmp, need, "%s.%ld.tmp", path, (long)getpid());
  f = fopen(tmp, "wb");
  if (f == NULL) goto done;
  uint64_t size64 = size;
  int ok = fwrite(cache_magic, 1, 8, f) == 8 && fwrite(&size64, sizeof size64, 1, f) == 1 &&
           fwrite(bin, 1, size, f) == size;
  ok = (fclose(f) == 0) && ok;
  f = NULL;
  if (ok && rename(tmp, path) == 0)
    log_debug("program cache: stored %s (%s)", path, dev->name);
  else
    remove(tmp);
done:
  if (f != NULL) fclose(f);
  free(tmp);
  free(bin);
}

/* ---- build ---- */

static void log_build_failure(const struct dev *dev, cl_program prog, const char *opts)
{
  size_t size = 0;
  char *text = NULL;
  log_error("OpenCL program failed to compile for %s", dev->name);
  log_error("build options: %s", opts);
  if (clGetProgramBuildInfo(prog, dev->id, CL_PROGRAM_BUILD_LOG, 0, NULL, &size) == CL_SUCCESS &&
      size > 1 && (text = malloc(size)) != NULL &&
      clGetProgramBuildInfo(prog, dev->id, CL_PROGRAM_BUILD_LOG, size, text, NULL) == CL_SUCCESS)
    log_error("compiler log:\n%s", text);
  else
    log_error("the compiler gave no log");
  free(text);
}

enum clsph_status prog_build(const struct dev *dev, const char *const *sources,
                             const struct prog_opts *opts, cl_program *out)
{
  return prog_build_extra(dev, sources, NULL, NULL, opts, out);
}

/* The neighbour loops' lanes in double (real.h's NEIGH_W): 8 where the device's own double
 * vectors are that wide (AVX-512: PoCL says 8), else 4 (256 bits; a GPU says 1); CLSPH_LANES = 4
 * or 8 chooses (the tests run both). Float takes 8. */
enum clsph_status prog_neigh_lanes(const struct dev *dev, int *lanes)
{
  enum clsph_status st = CLSPH_OK;
  *lanes = CLSPH_DOUBLE && dev->native_double < 8 ? 4 : 8;
  const char *env = getenv("CLSPH_LANES");
  if (env != NULL && env[0] != '\0') {
    CLSPH_CHECK(strcmp(env, "8") == 0 || (CLSPH_DOUBLE && strcmp(env, "4") == 0), CLSPH_E_INPUT,
                "CLSPH_LANES must be %s (or unset: the device's double vector width), not \"%s\"",
                CLSPH_DOUBLE ? "4 or 8" : "8 in a float build", env);
    *lanes = env[0] - '0';
  }
done:
  return st;
}

enum clsph_status prog_build_extra(const struct dev *dev, const char *const *sources,
                                   const char *extra_name, const char *extra_text,
                                   const struct prog_opts *opts, cl_program *out)
{
  enum clsph_status st = CLSPH_OK;
  struct source_set set = {0};
  struct prog_opts all = {0};
  cl_program prog = NULL;
  char *dir = NULL, *path = NULL;
  cl_int err = CL_SUCCESS;

  last_from_cache = 0;
  CLSPH_TRY(prog_opts_define_int(&all, "CLSPH_DOUBLE", CLSPH_DOUBLE));
  /* how a work-item of a reduction over stored rows takes them (blas1.cl's BLAS1_FOR_ROWS): a
   * contiguous run except on a GPU, where strided rows read coalesced; CLSPH_REDUCE_ROWS =
   * "strided" or "contiguous" chooses (the tests run the solver both ways) */
  int contiguous = !(dev->type & CL_DEVICE_TYPE_GPU);
  const char *rows = getenv("CLSPH_REDUCE_ROWS");
  if (rows != NULL && rows[0] != '\0') {
    CLSPH_CHECK(strcmp(rows, "strided") == 0 || strcmp(rows, "contiguous") == 0, CLSPH_E_INPUT,
                "CLSPH_REDUCE_ROWS must be \"strided\" or \"contiguous\" (or unset: contiguous "
                "except on a GPU), not \"%s\"",
                rows);
    contiguous = strcmp(rows, "contiguous") == 0;
  }
  CLSPH_TRY(prog_opts_define_int(&all, "BLAS1_CONTIGUOUS_ROWS", contiguous));
  int lanes = 0;
  CLSPH_TRY(prog_neigh_lanes(dev, &lanes));
  CLSPH_TRY(prog_opts_define_int(&all, "NEIGH_LANES", lanes));
  CLSPH_TRY(opts_append(&all, "-cl-std=CL1.2"));
  if (fast_math) CLSPH_TRY(opts_append(&all, "-cl-fast-relaxed-math"));
  if (opts != NULL && opts->len > 0) CLSPH_TRY(opts_append(&all, "%s", opts->text));
  log_debug("build options: %s", all.text);
  CLSPH_TRY(sources_load(sources, extra_name, extra_text, &set));

  uint64_t key = cache_key(dev, all.text, &set);
  dir = cache_dir();
  if (dir != NULL) path = cache_path(dir, key);
  if (path != NULL && (prog = cache_load(dev, path, all.text)) != NULL) {
    last_from_cache = 1;
    log_debug("program cache: loaded %s", path);
  } else {
    prog = clCreateProgramWithSource(dev->ctx, (cl_uint)set.n, set.s, set.len, &err);
    CLSPH_CL_CHECK_ERR(err, "clCreateProgramWithSource");
    err = clBuildProgram(prog, 1, &dev->id, all.text, NULL, NULL);
    if (err != CL_SUCCESS) {
      log_build_failure(dev, prog, all.text);
      st = CLSPH_E_BUILD;
      goto done;
    }
    if (path != NULL) cache_store(dev, prog, path);
  }
  *out = prog;
  prog = NULL;
done:
  if (prog != NULL) clReleaseProgram(prog);
  free(path);
  free(dir);
  prog_opts_free(&all);
  sources_free(&set);
  return st;
}

enum clsph_status prog_kernel(cl_program prog, const char *name, cl_kernel *out)
{
  enum clsph_status st = CLSPH_OK;
  cl_int err = CL_SUCCESS;
  cl_kernel k = clCreateKernel(prog, name, &err);
  if (err != CL_SUCCESS) {
    log_error("clCreateKernel(%s): %s", name, dev_cl_error_str(err));
    st = CLSPH_E_CL;
    goto done;
  }
  *out = k;
done:
  return st;
}
