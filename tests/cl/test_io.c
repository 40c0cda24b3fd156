/* test_io.c: snapshots, the XDMF index and checkpoints (host/output/io.c).
 *
 * A set of 1000 particles with known fields (2-D pos and vel, p, an unsigned kind, a signed int,
 * a 4-real field of which 3 are output, and a field that is never output) is written as a
 * snapshot and read back with the HDF5 API: every value must come back exactly, padding dropped,
 * the hidden field absent, and the attributes as given. Two snapshots get an XDMF index that must
 * be well-formed XML (xmllint, when installed) naming both files and times; h5dump -H must read
 * the snapshot (when installed). A checkpoint must restore every field bit for bit after the
 * device was overwritten, with time, step, dt and the blob; and each of a text file, a snapshot,
 * a truncated checkpoint, another case, another precision, a missing field and too small a
 * particle set must be refused with CLSPH_E_INPUT, one error message naming the file, and the
 * particle set untouched; a file that lacks one of the run's temporaries (pset_temporary) must be
 * read, the temporary left as it was.
 *
 * When pvpython is installed, tests/io/pv_check.py opens the index with ParaView's XDMF3 reader
 * and checks the points, the vertex cells and the arrays it sees at both times. An empty particle
 * set must give a snapshot, an index entry ParaView reads, and a checkpoint.
 *
 * Usage: test_io BUILD_DIR [PV_CHECK_SCRIPT] (files go to BUILD_DIR/io-test). */
#define _POSIX_C_SOURCE 200809L /* dup, dup2, open, mkdir: capture the log, make the folder */

#include <errno.h>
#include <fcntl.h>
#include <hdf5.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "clsph_config.h"
#include "io.h"
#include "kern.h"
#include "pset.h"
#include "tcheck.h"

#define NP    1000 /* particles */
#define NPATH 4096

#if CLSPH_DOUBLE
#define H5_REAL         H5T_NATIVE_DOUBLE
#define OTHER_PRECISION "float"
#else
#define H5_REAL         H5T_NATIVE_FLOAT
#define OTHER_PRECISION "double"
#endif

/* Host copies of the fields, as uploaded. */
struct data {
  real pos[NP * 2], vel[NP * 2], p[NP], pad[NP * 4], hidden[NP * 2];
  cl_uint kind[NP];
  cl_int cell[NP];
};

static const char *dir = NULL;
static const char *pv_script = NULL; /* tests/io/pv_check.py, or NULL */

static void path_of(char *out, const char *name)
{
  int len = snprintf(out, NPATH, "%s/%s", dir, name);
  if (len < 0 || len >= NPATH) {
    printf("FAIL: path %s/%s is too long\n", dir, name);
    exit(1);
  }
}

static void fill_data(struct data *d, double shift)
{
  for (int i = 0; i < NP; ++i) {
    d->pos[2 * i] = (real)(0.001 * i + 1.0 / 3.0);
    d->pos[2 * i + 1] = (real)sin(0.1 * i);
    d->vel[2 * i] = (real)(cos(0.37 * i) + shift);
    d->vel[2 * i + 1] = (real)(-1e-7 * i);
    d->p[i] = (real)(1000.0 * exp(-0.001 * i) + shift);
    for (int c = 0; c < 4; ++c) d->pad[4 * i + c] = (real)(c < 3 ? i * 0.5 + c : -7.0 - i);
    d->kind[i] = (cl_uint)(i % 3 == 0 ? 4000000000u : (unsigned)i);
    d->cell[i] = -(cl_int)i * 1000;
    /* raw bit patterns (NaN payloads, negative zero): a checkpoint must keep them */
    uint32_t bits[sizeof(real) / 4 * 2];
    for (size_t w = 0; w < sizeof bits / sizeof *bits; ++w)
      bits[w] = 0x7fa00000u + (uint32_t)(i * 7 + (int)w);
    memcpy(&d->hidden[2 * i], bits, sizeof bits);
    if (i == 5) d->hidden[2 * i] = (real)-0.0;
  }
}

enum variant { SAME, EXTRA_FIELD, WIDER_P, EXTRA_TEMP };

/* A particle set with the fields of `d` (n of them, room for cap); the variants add a field, a
 * temporary (pset_temporary) or give p two components. */
static int make_pset(const struct dev *dev, const struct data *d, size_t n, size_t cap,
                     enum variant v, struct pset *ps)
{
  int k = 0;
  pset_init(ps, n, cap);
  if (pset_add(ps, dev, "pos", 2 * sizeof(real), d->pos, &k)) return 0;
  if (pset_add(ps, dev, "vel", 2 * sizeof(real), d->vel, &k)) return 0;
  if (v == WIDER_P ? pset_add(ps, dev, "p", 2 * sizeof(real), NULL, &k)
                   : pset_add(ps, dev, "p", sizeof(real), d->p, &k))
    return 0;
  if (pset_add(ps, dev, "kind", sizeof(cl_uint), d->kind, &k)) return 0;
  pset_describe(ps, k, PF_UINT, 1, 1);
  if (pset_add(ps, dev, "cell", sizeof(cl_int), d->cell, &k)) return 0;
  pset_describe(ps, k, PF_INT, 1, 1);
  if (pset_add(ps, dev, "pad", 4 * sizeof(real), d->pad, &k)) return 0;
  pset_describe(ps, k, PF_REAL, 3, 1);
  if (pset_add(ps, dev, "hidden", 2 * sizeof(real), d->hidden, &k)) return 0;
  pset_describe(ps, k, PF_REAL, 2, 0);
  if (v == EXTRA_FIELD && pset_add(ps, dev, "extra", sizeof(real), NULL, &k)) return 0;
  if (v == EXTRA_TEMP) {
    if (pset_add(ps, dev, "extra_temp", sizeof(real), NULL, &k)) return 0;
    pset_temporary(ps, k);
  }
  return 1;
}

static void make_meta(struct io_meta *m, const struct scene_param *params, int nparams)
{
  memset(m, 0, sizeof *m);
  m->case_name = "io_test_case";
  m->case_path = "cases/io_test_case.lua";
  m->scheme = "none";
  m->precision = CLSPH_PRECISION_NAME;
  m->version = "9.8.7";
  m->time = 0.125;
  m->step = 4242;
  m->dt = 1.0 / 3.0e4;
  m->dim = 2;
  m->params = params;
  m->nparams = nparams;
}

static int file_exists(const char *path)
{
  FILE *f = fopen(path, "rb");
  if (f != NULL) fclose(f);
  return f != NULL;
}

/* ---------------------------------------------------------------------------------------------
 * Reading back with the HDF5 API */

static int attr_double(hid_t loc, const char *name, double *v)
{
  hid_t a = H5Aopen(loc, name, H5P_DEFAULT);
  int ok = a >= 0 && H5Aread(a, H5T_NATIVE_DOUBLE, v) >= 0;
  if (a >= 0) H5Aclose(a);
  return ok;
}

static int attr_int64(hid_t loc, const char *name, int64_t *v)
{
  hid_t a = H5Aopen(loc, name, H5P_DEFAULT);
  int ok = a >= 0 && H5Aread(a, H5T_NATIVE_INT64, v) >= 0;
  if (a >= 0) H5Aclose(a);
  return ok;
}

/* Does string attribute `name` equal `want`? */
static int attr_str_is(hid_t loc, const char *name, const char *want)
{
  char buf[256] = {0};
  int ok = 0;
  hid_t a = H5Aopen(loc, name, H5P_DEFAULT), t = H5Tcopy(H5T_C_S1);
  if (a >= 0 && H5Tset_size(t, sizeof buf) >= 0 && H5Aread(a, t, buf) >= 0)
    ok = strcmp(buf, want) == 0;
  if (!ok) printf("  attribute %s: '%s', want '%s'\n", name, buf, want);
  if (a >= 0) H5Aclose(a);
  H5Tclose(t);
  return ok;
}

/* Read dataset `name` of shape (d0) or (d0, d1) stored as `type`; 1 on success. */
static int read_dataset(hid_t loc, const char *name, hid_t type, hsize_t d0, hsize_t d1, void *out)
{
  hsize_t dims[2] = {0, 0};
  int ok = 0;
  hid_t ds = H5Dopen2(loc, name, H5P_DEFAULT);
  hid_t sp = ds >= 0 ? H5Dget_space(ds) : -1, ft = ds >= 0 ? H5Dget_type(ds) : -1;
  int rank = sp >= 0 ? H5Sget_simple_extent_ndims(sp) : -1;
  if (rank == (d1 == 0 ? 1 : 2) && H5Sget_simple_extent_dims(sp, dims, NULL) >= 0 &&
      dims[0] == d0 && (d1 == 0 || dims[1] == d1) && H5Tequal(ft, type) > 0)
    ok = H5Dread(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out) >= 0;
  if (!ok)
    printf("  dataset %s: rank %d, dims %llu x %llu, want %llu x %llu of the native type\n", name,
           rank, (unsigned long long)dims[0], (unsigned long long)dims[1], (unsigned long long)d0,
           (unsigned long long)d1);
  if (ft >= 0) H5Tclose(ft);
  if (sp >= 0) H5Sclose(sp);
  if (ds >= 0) H5Dclose(ds);
  return ok;
}

static void check_snapshot_file(const char *path, const struct data *d, const struct io_meta *m)
{
  static real r2[NP * 3];
  static cl_uint u[NP];
  static cl_int s[NP];
  static int32_t topo[NP];
  double t = 0.0, dt = 0.0, dr = 0.0, re = 0.0;
  int64_t step = 0, n = 0, dim = 0;
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  TC_CHECK(f >= 0, "snapshot %s opens with HDF5", path);
  if (f < 0) return;
  hid_t g = H5Gopen2(f, "particles", H5P_DEFAULT), par = H5Gopen2(f, "parameters", H5P_DEFAULT);
  TC_CHECK(g >= 0 && par >= 0, "snapshot has /particles and /parameters");

  /* root attributes */
  int ok_t = attr_double(f, "time", &t), ok_step = attr_int64(f, "step", &step);
  int ok_dt = attr_double(f, "dt", &dt), ok_n = attr_int64(f, "n", &n);
  int ok_dim = attr_int64(f, "dim", &dim);
  TC_CHECK(ok_t && t == m->time, "time attribute %.17g", t);
  TC_CHECK(ok_step && step == m->step, "step attribute %lld", (long long)step);
  TC_CHECK(ok_dt && dt == m->dt, "dt attribute %.17g", dt);
  TC_CHECK(ok_n && n == NP, "n attribute %lld", (long long)n);
  TC_CHECK(ok_dim && dim == 2, "dim attribute %lld", (long long)dim);
  TC_CHECK(attr_str_is(f, "case", m->case_name), "case attribute");
  TC_CHECK(attr_str_is(f, "case_path", m->case_path), "case_path attribute");
  TC_CHECK(attr_str_is(f, "scheme", m->scheme), "scheme attribute");
  TC_CHECK(attr_str_is(f, "precision", CLSPH_PRECISION_NAME), "precision attribute");
  TC_CHECK(attr_str_is(f, "clsph_version", m->version), "clsph_version attribute");
  TC_CHECK(H5Aexists(f, "clsph_checkpoint") == 0, "a snapshot is not marked as a checkpoint");
  int ok_dr = attr_double(par, "dr", &dr), ok_re = attr_double(par, "re", &re);
  TC_CHECK(ok_dr && dr == 0.01, "parameter dr %.17g", dr);
  TC_CHECK(ok_re && re == 100.0, "parameter re %.17g", re);

  /* fields: exact values, padding dropped, the hidden field absent */
  TC_CHECK(read_dataset(g, "pos", H5_REAL, NP, 2, r2) && memcmp(r2, d->pos, sizeof d->pos) == 0,
           "pos: n x 2 reals, exact");
  TC_CHECK(read_dataset(g, "vel", H5_REAL, NP, 2, r2) && memcmp(r2, d->vel, sizeof d->vel) == 0,
           "vel: n x 2 reals, exact");
  TC_CHECK(read_dataset(g, "p", H5_REAL, NP, 0, r2) && memcmp(r2, d->p, sizeof d->p) == 0,
           "p: n reals, exact");
  TC_CHECK(read_dataset(g, "kind", H5T_NATIVE_UINT32, NP, 0, u) &&
               memcmp(u, d->kind, sizeof d->kind) == 0,
           "kind: n uint32, exact");
  TC_CHECK(read_dataset(g, "cell", H5T_NATIVE_INT32, NP, 0, s) &&
               memcmp(s, d->cell, sizeof d->cell) == 0,
           "cell: n int32, exact");
  int pad_ok = read_dataset(g, "pad", H5_REAL, NP, 3, r2);
  for (int i = 0; i < NP && pad_ok; ++i)
    pad_ok = memcmp(&r2[3 * i], &d->pad[4 * i], 3 * sizeof(real)) == 0;
  TC_CHECK(pad_ok, "pad: n x 3 reals (the 4th component dropped), exact");
  TC_CHECK(H5Lexists(g, "hidden", H5P_DEFAULT) == 0, "a field without output is not written");
  int topo_ok = read_dataset(f, "topology", H5T_NATIVE_INT32, NP, 0, topo);
  for (int i = 0; i < NP && topo_ok; ++i) topo_ok = topo[i] == i;
  TC_CHECK(topo_ok, "topology: 0 .. n-1");

  if (par >= 0) H5Gclose(par);
  if (g >= 0) H5Gclose(g);
  H5Fclose(f);
}

/* ---------------------------------------------------------------------------------------------
 * External tools and the log */

static int have_tool(const char *name)
{
  char cmd[256];
  snprintf(cmd, sizeof cmd, "command -v %s >/dev/null 2>&1", name);
  return system(cmd) == 0;
}

/* Run `tool args` (output in io-test/<tool>.log, printed when it fails); skip with a note when the
 * tool is not installed. */
static void run_tool(const char *tool, const char *args, const char *what)
{
  char cmd[3 * NPATH], log[NPATH], name[64];
  if (!have_tool(tool)) {
    printf("note: %s is not installed: %s not checked\n", tool, what);
    return;
  }
  snprintf(name, sizeof name, "%s.log", tool);
  path_of(log, name);
  int len = snprintf(cmd, sizeof cmd, "%s %s >'%s' 2>&1", tool, args, log);
  int ok = len > 0 && len < (int)sizeof cmd && system(cmd) == 0;
  TC_CHECK(ok, "%s %s exits 0 (%s)", tool, args, what);
  if (!ok) {
    char *text = tc_read_text(log);
    printf("%s", text);
    free(text);
  }
}

/* stderr into a file while a call runs, to check what it reports. */
static int saved_stderr = -1;

static void capture_begin(void)
{
  char log[NPATH];
  path_of(log, "stderr.txt");
  fflush(stderr);
  saved_stderr = dup(2);
  int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (saved_stderr < 0 || fd < 0 || dup2(fd, 2) < 0) {
    printf("FAIL: cannot capture stderr in %s: %s\n", log, strerror(errno));
    exit(1);
  }
  close(fd);
}

/* The text captured (malloc'd). */
static char *capture_end(void)
{
  char log[NPATH];
  path_of(log, "stderr.txt");
  fflush(stderr);
  dup2(saved_stderr, 2);
  close(saved_stderr);
  saved_stderr = -1;
  return tc_read_text(log);
}

static int count_lines(const char *s)
{
  int lines = 0;
  for (; *s != '\0'; ++s) lines += *s == '\n';
  return lines;
}

/* The refusal of `path`: CLSPH_E_INPUT, one error line naming the file and saying `why`, and the
 * particle set untouched. */
static void check_refused(const char *what, const char *path, const struct dev *dev,
                          struct pset *ps, const char *expect_case, const char *why)
{
  struct io_meta expect, m;
  void *blob = (void *)&expect;
  size_t bytes = 99, n0 = ps->n;
  char *text = NULL;
  make_meta(&expect, NULL, 0);
  if (expect_case != NULL) expect.case_name = expect_case;
  memset(&m, 0, sizeof m);
  capture_begin();
  enum clsph_status st = io_checkpoint_read(path, dev, ps, &expect, &m, &blob, &bytes);
  text = capture_end();
  TC_CHECK(st == CLSPH_E_INPUT, "%s: refused with CLSPH_E_INPUT (got %s)", what,
           clsph_status_str(st));
  TC_CHECK(count_lines(text) == 1 && strncmp(text, "clsph: error: ", 14) == 0 &&
               strstr(text, path) != NULL && strstr(text, why) != NULL,
           "%s: one error line naming the file and saying '%s'; got: %.*s", what, why,
           (int)strcspn(text, "\n"), text);
  TC_CHECK(blob == NULL && bytes == 0 && ps->n == n0 && m.step == 0,
           "%s: nothing returned, particle count unchanged", what);
  printf("%s: %s", what, text);
  free(text);
}

/* ---------------------------------------------------------------------------------------------
 * Files for the refusals */

static void write_text_file(const char *path, const char *text)
{
  FILE *f = fopen(path, "w");
  if (f == NULL || fputs(text, f) < 0 || fclose(f) != 0) {
    printf("FAIL: cannot write %s\n", path);
    exit(1);
  }
}

/* Copy the first half of the bytes of `from` to `to`. */
static void write_truncated(const char *from, const char *to)
{
  FILE *in = fopen(from, "rb"), *out = fopen(to, "wb");
  if (in == NULL || out == NULL) {
    printf("FAIL: cannot copy %s to %s\n", from, to);
    exit(1);
  }
  fseek(in, 0, SEEK_END);
  long size = ftell(in);
  rewind(in);
  char *buf = malloc((size_t)size);
  if (buf == NULL || fread(buf, 1, (size_t)size, in) != (size_t)size ||
      fwrite(buf, 1, (size_t)size / 2, out) != (size_t)size / 2) {
    printf("FAIL: cannot copy %s to %s\n", from, to);
    exit(1);
  }
  free(buf);
  fclose(in);
  fclose(out);
}

/* Overwrite the precision attribute of an HDF5 file with the other precision. */
static int set_other_precision(const char *path)
{
  const char *other = OTHER_PRECISION;
  hid_t f = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT), t = H5Tcopy(H5T_C_S1);
  hid_t sp = H5Screate(H5S_SCALAR), a = -1;
  int ok = f >= 0 && H5Adelete(f, "precision") >= 0 && H5Tset_size(t, strlen(other) + 1) >= 0 &&
           (a = H5Acreate2(f, "precision", t, sp, H5P_DEFAULT, H5P_DEFAULT)) >= 0 &&
           H5Awrite(a, t, other) >= 0;
  if (a >= 0) H5Aclose(a);
  H5Sclose(sp);
  H5Tclose(t);
  if (f >= 0) ok = H5Fclose(f) >= 0 && ok;
  return ok;
}

/* ---------------------------------------------------------------------------------------------
 * The checks */

static void check_series(void)
{
  struct io_series s = {0};
  char name[32];
  int ok = 1;
  for (int i = 0; i < 40; ++i) {
    snprintf(name, sizeof name, "snap_%06d.h5", i);
    ok &= io_series_add(&s, name, 0.5 * i, (size_t)(10 + i)) == CLSPH_OK;
    name[0] = 'X'; /* the series keeps its own copy */
  }
  TC_CHECK(ok && s.count == 40 && s.cap >= 40, "series grows to 40 entries");
  TC_CHECK(strcmp(s.files[0], "snap_000000.h5") == 0 && strcmp(s.files[39], "snap_000039.h5") == 0,
           "series owns copies of the file names");
  TC_CHECK(s.times[17] == 8.5 && s.n[39] == 49, "series times and particle counts");
  io_series_free(&s);
  TC_CHECK(s.count == 0 && s.files == NULL, "series freed");
}

static void check_snapshots(const struct dev *dev, struct data *d, struct pset *ps,
                            const struct io_meta *m)
{
  char snap1[NPATH], snap2[NPATH], xdmf[NPATH], tmp[NPATH + 8], args[3 * NPATH];
  struct io_meta m2 = *m;
  struct io_series s = {0};
  int ip = pset_find(ps, "p");

  path_of(snap1, "snap_000001.h5");
  path_of(snap2, "snap_000002.h5");
  path_of(xdmf, "particles.xdmf");
  remove(snap1);
  TC_CHECK(io_snapshot_write(snap1, dev, ps, m) == CLSPH_OK, "snapshot 1 written");
  snprintf(tmp, sizeof tmp, "%s.tmp", snap1);
  TC_CHECK(file_exists(snap1) && !file_exists(tmp), "snapshot under its name, no temporary left");
  check_snapshot_file(snap1, d, m);
  snprintf(args, sizeof args, "-H '%s'", snap1);
  run_tool("h5dump", args, "HDF5 structure");

  /* a second snapshot, later, with other pressures */
  for (int i = 0; i < NP; ++i) d->p[i] = (real)(-(double)i);
  if (kern_write(dev, pset_mem(ps, ip), sizeof d->p, d->p) != CLSPH_OK) exit(1);
  m2.time = 0.25;
  /* 3-D walls' faces (/walls3): two triangles, read back as written; snapshot 1 has none */
  static const double faces[18] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5, 0.25, 1, 2, 0, 1, 0, 2, 1};
  m2.surf3 = faces;
  m2.nsurf3 = 2;
  TC_CHECK(io_snapshot_write(snap2, dev, ps, &m2) == CLSPH_OK, "snapshot 2 written");
  {
    struct io_snapshot back;
    static const char *const none[] = {NULL};
    TC_CHECK(io_snapshot_read(snap2, none, &back) == CLSPH_OK && back.nsurf3 == 2 &&
                 memcmp(back.surf3, faces, sizeof faces) == 0,
             "walls3 read back: 2 triangles, the same bits");
    io_snapshot_free(&back);
    TC_CHECK(io_snapshot_read(snap1, none, &back) == CLSPH_OK && back.nsurf3 == 0 &&
                 back.surf3 == NULL,
             "a snapshot without walls3 reads none");
    io_snapshot_free(&back);
    /* a walls3 of rows that are not triangles (8 numbers) is refused, naming the file */
    char bad[NPATH];
    path_of(bad, "bad_walls3.h5");
    TC_CHECK(io_snapshot_write(bad, dev, ps, m) == CLSPH_OK, "snapshot for the bad walls3");
    hid_t f = H5Fopen(bad, H5F_ACC_RDWR, H5P_DEFAULT);
    const hsize_t dims[2] = {2, 8};
    hid_t sp = H5Screate_simple(2, dims, NULL);
    hid_t ds =
        H5Dcreate2(f, "walls3", H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    TC_CHECK(ds >= 0 && H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, faces) >= 0,
             "a walls3 of 2 x 8 written");
    H5Dclose(ds);
    H5Sclose(sp);
    H5Fclose(f);
    capture_begin();
    const enum clsph_status st = io_snapshot_read(bad, none, &back);
    char *text = capture_end();
    TC_CHECK(st == CLSPH_E_INPUT && strstr(text, bad) != NULL &&
                 strstr(text, "walls3 holds 8 numbers a row, not a triangle's 9") != NULL,
             "a walls3 of 8 numbers a row refused; got: %s", text);
    free(text);
    io_snapshot_free(&back);
  }

  TC_CHECK(io_series_add(&s, "snap_000001.h5", m->time, NP) == CLSPH_OK &&
               io_series_add(&s, "snap_000002.h5", m2.time, NP) == CLSPH_OK,
           "series of two snapshots");
  TC_CHECK(io_xdmf_write(xdmf, &s, ps, 2) == CLSPH_OK, "XDMF index written");
  snprintf(tmp, sizeof tmp, "%s.tmp", xdmf);
  TC_CHECK(file_exists(xdmf) && !file_exists(tmp), "XDMF under its name, no temporary left");
  char *x = tc_read_text(xdmf);
  static const char *const want[] = {
      "<Xdmf Version=\"3.0\">",
      "GridType=\"Collection\" CollectionType=\"Temporal\"",
      "<Time Value=\"0.125\"/>",
      "<Time Value=\"0.25\"/>",
      "TopologyType=\"Polyvertex\" NumberOfElements=\"1000\" NodesPerElement=\"1\"",
      "snap_000001.h5:/topology",
      "<Geometry GeometryType=\"XY\">",
      "Dimensions=\"1000 2\" NumberType=\"Float\" Precision=\"" /* pos, vel */,
      "Format=\"HDF\">snap_000001.h5:/particles/pos</DataItem>",
      "Format=\"HDF\">snap_000002.h5:/particles/pos</DataItem>",
      "<Attribute Name=\"vel\" AttributeType=\"Vector\" Center=\"Node\">",
      "<Attribute Name=\"p\" AttributeType=\"Scalar\" Center=\"Node\">",
      "<Attribute Name=\"pad\" AttributeType=\"Matrix\" Center=\"Node\">",
      "Dimensions=\"1000 3\"",
      "Dimensions=\"1000\" NumberType=\"UInt\" Precision=\"4\" "
      "Format=\"HDF\">snap_000002.h5:/particles/kind</DataItem>",
      "Dimensions=\"1000\" NumberType=\"Int\" Precision=\"4\" "
      "Format=\"HDF\">snap_000002.h5:/particles/cell</DataItem>",
  };
  for (size_t i = 0; i < sizeof want / sizeof *want; ++i)
    TC_CHECK(strstr(x, want[i]) != NULL, "XDMF contains %s", want[i]);
  char precision[64];
  snprintf(precision, sizeof precision, "NumberType=\"Float\" Precision=\"%zu\"", sizeof(real));
  TC_CHECK(strstr(x, precision) != NULL, "XDMF reals have %s", precision);
  TC_CHECK(strstr(x, "\"hidden\"") == NULL, "XDMF omits the field without output");
  free(x);
  snprintf(args, sizeof args, "--noout '%s'", xdmf);
  run_tool("xmllint", args, "well-formed XML");
  if (pv_script != NULL) {
    snprintf(args, sizeof args, "'%s' '%s' %d 0.125,0.25 vel:2,p:1,kind:1,cell:1,pad:3", pv_script,
             xdmf, NP);
    run_tool("pvpython", args, "ParaView XDMF3 reader");
  }
  io_series_free(&s);
}

static void check_checkpoints(const struct dev *dev, const struct data *d, struct pset *ps,
                              const struct io_meta *m)
{
  char ck[NPATH], text[NPATH], trunc[NPATH], other[NPATH], snap[NPATH], missing[NPATH];
  static unsigned char before[PSET_MAX_FIELDS][NP * 4 * sizeof(real)];
  static unsigned char after[NP * 4 * sizeof(real)];
  const char blob_in[] = "opaque scheme state \x01\x02\x00\xff end";
  struct io_meta got;
  void *blob = NULL;
  size_t bytes = 0;
  int ok;

  path_of(ck, "check.h5");
  path_of(text, "not_hdf5.txt");
  path_of(trunc, "truncated.h5");
  path_of(other, "other_precision.h5");
  path_of(snap, "snap_000001.h5");
  path_of(missing, "does_not_exist.h5");

  /* round trip: write, overwrite the device with garbage, read back */
  for (int k = 0; k < ps->nfields; ++k)
    if (kern_read(dev, ps->f[k].d, ps->n * ps->f[k].elem, before[k]) != CLSPH_OK) exit(1);
  TC_CHECK(io_checkpoint_write(ck, dev, ps, m, blob_in, sizeof blob_in) == CLSPH_OK,
           "checkpoint written");
  const cl_uint garbage = 0xdeadbeefu;
  for (int k = 0; k < ps->nfields; ++k)
    if (kern_fill(dev, ps->f[k].d, &garbage, sizeof garbage, ps->cap * ps->f[k].elem)) exit(1);
  ps->n = 17;
  memset(&got, 0, sizeof got);
  TC_CHECK(io_checkpoint_read(ck, dev, ps, m, &got, &blob, &bytes) == CLSPH_OK, "checkpoint read");
  TC_CHECK(ps->n == NP, "particle count restored (%zu)", ps->n);
  ok = 1;
  for (int k = 0; k < ps->nfields; ++k) {
    if (kern_read(dev, ps->f[k].d, NP * ps->f[k].elem, after) != CLSPH_OK) exit(1);
    int same = memcmp(after, before[k], NP * ps->f[k].elem) == 0;
    if (!same) printf("  field %s differs after the restart\n", ps->f[k].name);
    ok &= same;
  }
  TC_CHECK(ok, "every field (padding and non-output fields too) restored bit for bit");
  TC_CHECK(memcmp(before[pset_find(ps, "hidden")], d->hidden, sizeof d->hidden) == 0,
           "the raw bit patterns were on the device");
  TC_CHECK(got.time == m->time && got.step == m->step && got.dt == m->dt,
           "time %.17g, step %ld, dt %.17g restored", got.time, got.step, got.dt);
  TC_CHECK(blob != NULL && bytes == sizeof blob_in && memcmp(blob, blob_in, bytes) == 0,
           "blob restored (%zu bytes)", bytes);
  free(blob);
  blob = NULL;

  /* without a blob */
  TC_CHECK(io_checkpoint_write(ck, dev, ps, m, NULL, 0) == CLSPH_OK &&
               io_checkpoint_read(ck, dev, ps, m, &got, &blob, &bytes) == CLSPH_OK &&
               blob == NULL && bytes == 0,
           "a checkpoint without a blob reads back without one");

  /* refusals */
  write_text_file(text, "this is not a checkpoint\n");
  check_refused("text file", text, dev, ps, NULL, "not a clsph checkpoint (not an HDF5 file)");
  check_refused("snapshot", snap, dev, ps, NULL, "is not a clsph checkpoint");
  write_truncated(ck, trunc);
  check_refused("truncated", trunc, dev, ps, NULL, "is truncated or damaged");
  check_refused("other case", ck, dev, ps, "cavity",
                "was written by case 'io_test_case', not 'cavity'");
  TC_CHECK(io_checkpoint_write(other, dev, ps, m, NULL, 0) == CLSPH_OK &&
               set_other_precision(other),
           "checkpoint with the other precision attribute made");
  check_refused("other precision", other, dev, ps, NULL,
                "was written in " OTHER_PRECISION
                " precision; this build is " CLSPH_PRECISION_NAME);
  check_refused("missing file", missing, dev, ps, NULL, "cannot open checkpoint");

  /* particle sets that do not match the checkpoint */
  static const struct {
    const char *what;
    size_t cap;
    enum variant v;
    const char *why;
  } sets[] = {
      {"too many particles", 10, SAME, "holds 1000 particles; this run has room for 10"},
      {"missing field", NP, EXTRA_FIELD, "has no field 'extra'"},
      {"other element size", NP, WIDER_P, "field 'p' holds 1 x "},
  };
  /* a temporary the file lacks (a build whose scheme keeps another within its step): read, the
   * rest restored, the temporary left as it was */
  {
    struct pset tp;
    int made = make_pset(dev, d, NP, NP, EXTRA_TEMP, &tp);
    TC_CHECK(made, "extra temporary: particle set made");
    if (made) {
      const int kt = tp.nfields - 1, kp = pset_find(&tp, "p");
      const cl_uint mark = 0x5a5a5a5au;
      if (kern_fill(dev, tp.f[kt].d, &mark, sizeof mark, tp.cap * tp.f[kt].elem)) exit(1);
      if (kern_fill(dev, tp.f[kp].d, &mark, sizeof mark, tp.cap * tp.f[kp].elem)) exit(1);
      struct io_meta got2;
      memset(&got2, 0, sizeof got2);
      TC_CHECK(io_checkpoint_read(ck, dev, &tp, m, &got2, &blob, &bytes) == CLSPH_OK,
               "a checkpoint without one of the run's temporaries is read");
      free(blob);
      blob = NULL;
      real *pv = malloc(NP * sizeof *pv);
      cl_uint *tv = malloc(NP * sizeof *tv);
      if (pv == NULL || tv == NULL || kern_read(dev, tp.f[kp].d, NP * sizeof *pv, pv) ||
          kern_read(dev, tp.f[kt].d, NP * sizeof *tv, tv))
        exit(1);
      TC_CHECK(memcmp(pv, before[pset_find(ps, "p")], NP * sizeof *pv) == 0,
               "its other fields restored (p)");
      int left = 1;
      for (size_t i = 0; i < NP; ++i) left &= tv[i] == mark;
      TC_CHECK(left, "the temporary left as it was");
      free(pv);
      free(tv);
    }
    pset_destroy(&tp);
  }
  for (size_t i = 0; i < sizeof sets / sizeof *sets; ++i) {
    struct pset other_ps;
    size_t n = sets[i].cap < NP ? sets[i].cap : NP;
    int made = make_pset(dev, d, n, sets[i].cap, sets[i].v, &other_ps);
    TC_CHECK(made, "%s: particle set made", sets[i].what);
    if (made) check_refused(sets[i].what, ck, dev, &other_ps, NULL, sets[i].why);
    pset_destroy(&other_ps);
  }
}

/* No particles: a snapshot, an index and a checkpoint still work (open boundaries can empty a
 * set). */
static void check_empty(const struct dev *dev, const struct data *d, const struct io_meta *m)
{
  char snap[NPATH], xdmf[NPATH], ck[NPATH];
  struct io_series s = {0};
  struct io_meta got;
  struct pset ps;
  void *blob = NULL;
  size_t bytes = 0;
  int64_t n = -1;
  path_of(snap, "snap_empty.h5");
  path_of(xdmf, "empty.xdmf");
  path_of(ck, "check_empty.h5");
  if (!make_pset(dev, d, 10, 10, SAME, &ps)) exit(1);
  ps.n = 0;
  TC_CHECK(io_snapshot_write(snap, dev, &ps, m) == CLSPH_OK, "empty snapshot written");
  hid_t f = H5Fopen(snap, H5F_ACC_RDONLY, H5P_DEFAULT);
  int ok_n = f >= 0 && attr_int64(f, "n", &n);
  real none[1];
  TC_CHECK(ok_n && n == 0 && read_dataset(f, "particles/pos", H5_REAL, 0, 2, none),
           "empty snapshot: n = 0, pos 0 x 2");
  if (f >= 0) H5Fclose(f);
  TC_CHECK(io_series_add(&s, "snap_000001.h5", 0.125, NP) == CLSPH_OK &&
               io_series_add(&s, "snap_empty.h5", 0.5, 0) == CLSPH_OK &&
               io_xdmf_write(xdmf, &s, &ps, 2) == CLSPH_OK,
           "index with an empty snapshot written");
  io_series_free(&s);
  if (pv_script != NULL) {
    char args[3 * NPATH];
    snprintf(args, sizeof args, "'%s' '%s' %d,0 0.125,0.5 p:1", pv_script, xdmf, NP);
    run_tool("pvpython", args, "ParaView XDMF3 reader, empty snapshot");
  }
  TC_CHECK(io_checkpoint_write(ck, dev, &ps, m, NULL, 0) == CLSPH_OK, "empty checkpoint written");
  ps.n = 7;
  enum clsph_status st = io_checkpoint_read(ck, dev, &ps, m, &got, &blob, &bytes);
  TC_CHECK(st == CLSPH_OK && ps.n == 0, "empty checkpoint read: n = %zu", ps.n);
  pset_destroy(&ps);
}

/* A write that cannot happen fails with CLSPH_E_IO and one message naming the file. */
static void check_write_failure(const struct dev *dev, struct pset *ps, const struct io_meta *m)
{
  char bad[NPATH];
  char *text = NULL;
  path_of(bad, "no_such_folder/snap.h5");
  capture_begin();
  enum clsph_status st = io_snapshot_write(bad, dev, ps, m);
  text = capture_end();
  TC_CHECK(st == CLSPH_E_IO, "snapshot into a missing folder: CLSPH_E_IO (got %s)",
           clsph_status_str(st));
  TC_CHECK(count_lines(text) == 1 && strstr(text, bad) != NULL && strstr(text, "H5Fcreate"),
           "one error line naming the file and the call; got: %.*s", (int)strcspn(text, "\n"),
           text);
  printf("write failure: %s", text);
  free(text);
}

int main(int argc, char **argv)
{
  static struct data d;
  static char folder[NPATH];
  struct dev dev;
  struct pset ps;
  struct io_meta m;
  const struct scene_param params[] = {{"dr", 0.01, 0}, {"re", 100.0, 1}};

  if (argc != 2 && argc != 3) {
    printf("usage: test_io BUILD_DIR [PV_CHECK_SCRIPT]\n");
    return 1;
  }
  int len = snprintf(folder, sizeof folder, "%s/io-test", argv[1]);
  if (len < 0 || len >= (int)sizeof folder || (mkdir(folder, 0755) != 0 && errno != EEXIST)) {
    printf("FAIL: cannot make the folder %s/io-test\n", argv[1]);
    return 1;
  }
  dir = folder;
  pv_script = argc == 3 ? argv[2] : NULL;
  check_series();

  tc_open_device(&dev);
  fill_data(&d, 0.0);
  make_meta(&m, params, (int)(sizeof params / sizeof *params));
  if (!make_pset(&dev, &d, NP, NP + NP / 5, SAME, &ps)) {
    printf("FAIL: cannot build the particle set\n");
    return 1;
  }
  check_snapshots(&dev, &d, &ps, &m);
  check_checkpoints(&dev, &d, &ps, &m);
  check_write_failure(&dev, &ps, &m);
  check_empty(&dev, &d, &m);
  pset_destroy(&ps);
  dev_close(&dev);
  return tc_finish("test_io");
}
