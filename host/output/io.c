/* io.c: HDF5 snapshots, their XDMF index for ParaView, and checkpoints.
 *
 * Snapshot (one HDF5 file per output time):
 *   /                 attributes time (double, s), step (int64), dt (double, s), case, case_path,
 *                     scheme, precision, clsph_version (strings), dim (int32), n (uint64)
 *   /parameters       one double attribute per case parameter, as run
 *   /particles/<name> one dataset per output field: shape (n) when the field carries one
 *                     component, (n, nout) otherwise; padding components are dropped (a 3-D
 *                     position stored as 4 reals is written n x 3). Reals are stored in the
 *                     precision of the build, integers as 32-bit.
 *   /topology         int32 0 .. n-1: the vertex list of the XDMF Polyvertex topology. ParaView's
 *                     XDMF3 reader counts the cells of a topology from its data, so a topology
 *                     without one is read as points with no cells (nothing to draw).
 *   What frames need besides the particles (`clsph render` redraws a run from its snapshots):
 *   domain            root attribute, 4 doubles: the scene's box x0, y0, x1, y1 (m)
 *   /walls/wall_NNN   the wall polylines as declared, doubles (npts, 2), the fluid on their left;
 *                     attribute closed (int32, 1: the last point joins the first)
 *   domain3, /walls3  3-D: the box x0, y0, z0, x1, y1, z1 (root attribute, 6 doubles) and the
 *                     walls' faces where they stand (a lifted gate moved), doubles (ntri, 9): each
 *                     triangle's vertices, counter-clockwise seen from the fluid
 *   /render           the case's render { } choices as attributes: field (string), colormap
 *                     (string), range (2 doubles, only when fixed), camera (10 doubles: eye,
 *                     look_at, up, fov; 3-D, only when given); absent without render { }
 *
 * XDMF (Version 3.0): a temporal collection with one uniform grid per snapshot that points into
 * the snapshot files ("snap_000001.h5:/particles/vel"); the HDF5 files hold all the data.
 *
 * Checkpoint: the snapshot attributes plus clsph_checkpoint = 1 (int32), /parameters, every field
 * with all its components as stored on the device in /fields/<name> (shape (n) or (n, ncomp), the
 * native types of the build, so the bytes come back unchanged), and the caller's opaque state as
 * a uint8 dataset /blob (absent when empty).
 *
 * Every file is written under "<path>.tmp" and renamed over `path` once complete and closed, so
 * a crash never leaves a half-written file under the final name. HDF5's own error printing is
 * switched off; each failure is reported once here, with the call, the path and HDF5's reason. */
#include "io.h"

#include <errno.h>
#include <hdf5.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "clsph_config.h"
#include "kern.h"
#include "str.h"

#ifndef CLSPH_VERSION
#define CLSPH_VERSION "unknown"
#endif

#if CLSPH_DOUBLE
#define IO_H5_REAL H5T_NATIVE_DOUBLE
#else
#define IO_H5_REAL H5T_NATIVE_FLOAT
#endif

/* ---------------------------------------------------------------------------------------------
 * HDF5 errors */

/* The outermost and innermost descriptions on HDF5's error stack (a message: truncation is
 * harmless). */
struct h5_reason {
  int count;
  char outer[160], inner[160];
};

static herr_t h5_walk(unsigned n, const H5E_error2_t *e, void *data)
{
  struct h5_reason *r = data;
  (void)n;
  if (e->desc == NULL || e->desc[0] == '\0') return 0;
  if (r->count++ == 0) snprintf(r->outer, sizeof r->outer, "%s", e->desc);
  snprintf(r->inner, sizeof r->inner, "%s", e->desc);
  return 0;
}

/* HDF5's reason for the last failure, as "outer: inner" (empty when the stack is empty). */
static void h5_reason(char *out, size_t size)
{
  struct h5_reason r = {0};
  out[0] = '\0';
  if (H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, h5_walk, &r) < 0 || r.count == 0) return;
  if (r.count == 1 || strcmp(r.outer, r.inner) == 0)
    snprintf(out, size, "%s", r.inner);
  else
    snprintf(out, size, "%s: %s", r.outer, r.inner);
}

/* Report a failed HDF5 call: "<path>: H5Dwrite failed (reason) (io.c:123)". */
static void h5_fail(const char *call, const char *path, const char *file, int line)
{
  char reason[400];
  const char *name = call, *eq = strstr(call, "= "), *paren = strchr(call, '(');
  int len;
  if (eq != NULL && paren != NULL && eq < paren) name = eq + 2; /* "f = H5Fopen(...)": callee */
  len = (int)strcspn(name, "(");
  h5_reason(reason, sizeof reason);
  log_error("%s: %.*s failed%s%s%s (%s:%d)", path, len, name, reason[0] ? " (" : "", reason,
            reason[0] ? ")" : "", file, line);
}

/* Check an HDF5 call (negative: failure): report it with the path and return CLSPH_E_IO. */
#define IO_H5(call, path)                                                                          \
  do {                                                                                             \
    if ((call) < 0) {                                                                              \
      h5_fail(#call, (path), __FILE__, __LINE__);                                                  \
      st = CLSPH_E_IO;                                                                             \
      goto done;                                                                                   \
    }                                                                                              \
  } while (0)

/* HDF5 prints its error stack to stderr by default; we report errors ourselves. */
static void h5_quiet(void)
{
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
}

static void h5_close_id(hid_t *id)
{
  if (*id < 0) return;
  switch (H5Iget_type(*id)) {
  case H5I_FILE:
    H5Fclose(*id);
    break;
  case H5I_GROUP:
    H5Gclose(*id);
    break;
  case H5I_DATASET:
    H5Dclose(*id);
    break;
  case H5I_DATASPACE:
    H5Sclose(*id);
    break;
  case H5I_DATATYPE:
    H5Tclose(*id);
    break;
  case H5I_ATTR:
    H5Aclose(*id);
    break;
  default:
    break;
  }
  *id = H5I_INVALID_HID;
}

/* Close a file, group or dataset on the success path, checked (closing a file flushes it). */
static enum clsph_status h5_close_checked(hid_t *handle, const char *path)
{
  enum clsph_status st = CLSPH_OK;
  const hid_t id = *handle;
  *handle = H5I_INVALID_HID;
  switch (H5Iget_type(id)) {
  case H5I_FILE:
    IO_H5(H5Fclose(id), path);
    break;
  case H5I_GROUP:
    IO_H5(H5Gclose(id), path);
    break;
  case H5I_DATASET:
    IO_H5(H5Dclose(id), path);
    break;
  default:
    CLSPH_ASSERT(!"h5_close_checked: not a file, group or dataset");
    break;
  }
done:
  return st;
}

/* ---------------------------------------------------------------------------------------------
 * Small helpers */

static const char *or_empty(const char *s)
{
  return s != NULL ? s : "";
}

/* Bytes of one component of a field, and its HDF5 memory type. */
static size_t field_comp_bytes(const struct pfield *f)
{
  return f->type == PF_REAL ? sizeof(real) : 4;
}

static hid_t field_h5_type(const struct pfield *f)
{
  switch (f->type) {
  case PF_UINT:
    return H5T_NATIVE_UINT32;
  case PF_INT:
    return H5T_NATIVE_INT32;
  case PF_REAL:
    break;
  }
  return IO_H5_REAL;
}

/* Every field's description must be consistent before anything is written. */
static enum clsph_status check_fields(const struct pset *ps)
{
  enum clsph_status st = CLSPH_OK;
  for (int k = 0; k < ps->nfields; ++k) {
    const struct pfield *f = &ps->f[k];
    size_t cb = field_comp_bytes(f);
    CLSPH_CHECK(f->ncomp >= 1 && (size_t)f->ncomp * cb == f->elem && f->nout >= 1 &&
                    f->nout <= f->ncomp,
                CLSPH_E_INPUT,
                "particle field '%s': %zu bytes per particle do not hold %d components of %zu "
                "bytes (%d of them output)",
                f->name, f->elem, f->ncomp, cb, f->nout);
  }
done:
  return st;
}

static enum clsph_status tmp_name(const char *path, char **out)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_CHECK(path != NULL && path[0] != '\0', CLSPH_E_INPUT, "output file name is empty");
  *out = str_printf("%s.tmp", path);
  CLSPH_CHECK(*out != NULL, CLSPH_E_NOMEM, "out of memory (file name %s)", path);
done:
  return st;
}

/* Move the finished temporary file over the final name. */
static enum clsph_status commit(const char *tmp, const char *path)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_CHECK(rename(tmp, path) == 0, CLSPH_E_IO, "cannot rename %s to %s: %s", tmp, path,
              strerror(errno));
done:
  return st;
}

/* ---------------------------------------------------------------------------------------------
 * Writing */

static enum clsph_status attr_write(hid_t loc, const char *name, hid_t type, const void *value,
                                    const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t space = H5I_INVALID_HID, attr = H5I_INVALID_HID;
  IO_H5(space = H5Screate(H5S_SCALAR), path);
  IO_H5(attr = H5Acreate2(loc, name, type, space, H5P_DEFAULT, H5P_DEFAULT), path);
  IO_H5(H5Awrite(attr, type, value), path);
done:
  h5_close_id(&attr);
  h5_close_id(&space);
  return st;
}

/* A 1-D attribute of `count` values. */
static enum clsph_status attr_write_array(hid_t loc, const char *name, hid_t type, size_t count,
                                          const void *value, const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t space = H5I_INVALID_HID, attr = H5I_INVALID_HID;
  const hsize_t dims[1] = {(hsize_t)count};
  IO_H5(space = H5Screate_simple(1, dims, NULL), path);
  IO_H5(attr = H5Acreate2(loc, name, type, space, H5P_DEFAULT, H5P_DEFAULT), path);
  IO_H5(H5Awrite(attr, type, value), path);
done:
  h5_close_id(&attr);
  h5_close_id(&space);
  return st;
}

/* A fixed-length, null-terminated string attribute. */
static enum clsph_status attr_write_str(hid_t loc, const char *name, const char *s,
                                        const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t type = H5I_INVALID_HID;
  s = or_empty(s);
  IO_H5(type = H5Tcopy(H5T_C_S1), path);
  IO_H5(H5Tset_size(type, strlen(s) + 1), path);
  IO_H5(H5Tset_strpad(type, H5T_STR_NULLTERM), path);
  CLSPH_TRY(attr_write(loc, name, type, s, path));
done:
  h5_close_id(&type);
  return st;
}

/* CRC-32 (zlib) of n bytes. */
static uint32_t crc_of(const void *data, size_t n)
{
  const unsigned char *b = data;
  uLong c = crc32(0L, Z_NULL, 0);
  while (n > 0) { /* zlib takes at most UINT_MAX bytes a call */
    const uInt k = n > 0x40000000u ? 0x40000000u : (uInt)n;
    c = crc32(c, b, k);
    b += k;
    n -= k;
  }
  return (uint32_t)c;
}

/* The checkpoint's scalars under one checksum: time, step, dt, n and the scene digest. */
static uint32_t meta_crc(double time, int64_t step, double dt, uint64_t n, uint64_t digest)
{
  unsigned char b[40];
  memcpy(b, &time, 8);
  memcpy(b + 8, &step, 8);
  memcpy(b + 16, &dt, 8);
  memcpy(b + 24, &n, 8);
  memcpy(b + 32, &digest, 8);
  return crc_of(b, sizeof b);
}

/* Root attributes and the /parameters group, common to snapshots and checkpoints. */
static enum clsph_status write_meta(hid_t file, const struct io_meta *m, size_t n, const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t grp = H5I_INVALID_HID;
  const int64_t step = (int64_t)m->step;
  const uint64_t n64 = (uint64_t)n;
  const int32_t dim = (int32_t)m->dim;

  CLSPH_TRY(attr_write(file, "time", H5T_NATIVE_DOUBLE, &m->time, path));
  CLSPH_TRY(attr_write(file, "step", H5T_NATIVE_INT64, &step, path));
  CLSPH_TRY(attr_write(file, "dt", H5T_NATIVE_DOUBLE, &m->dt, path));
  CLSPH_TRY(attr_write_str(file, "case", m->case_name, path));
  CLSPH_TRY(attr_write_str(file, "case_path", m->case_path, path));
  CLSPH_TRY(attr_write_str(file, "scheme", m->scheme, path));
  /* the data is in the precision of this build, whatever the caller says */
  CLSPH_TRY(attr_write_str(file, "precision", CLSPH_PRECISION_NAME, path));
  CLSPH_TRY(attr_write_str(file, "clsph_version", m->version ? m->version : CLSPH_VERSION, path));
  CLSPH_TRY(attr_write(file, "dim", H5T_NATIVE_INT32, &dim, path));
  CLSPH_TRY(attr_write(file, "n", H5T_NATIVE_UINT64, &n64, path));

  IO_H5(grp = H5Gcreate2(file, "parameters", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path);
  for (int i = 0; i < m->nparams; ++i)
    CLSPH_TRY(attr_write(grp, m->params[i].name, H5T_NATIVE_DOUBLE, &m->params[i].value, path));
  CLSPH_TRY(h5_close_checked(&grp, path));
done:
  h5_close_id(&grp);
  return st;
}

/* A dataset of n rows of ncomp values: shape (n) when ncomp is 1, else (n, ncomp); with
 * `bytes` > 0, an attribute "crc32", the CRC-32 of its `bytes` bytes (checkpoints). */
static enum clsph_status write_dataset(hid_t loc, const char *name, hid_t type, size_t n, int ncomp,
                                       const void *data, size_t bytes, const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t space = H5I_INVALID_HID, dset = H5I_INVALID_HID;
  const hsize_t dims[2] = {(hsize_t)n, (hsize_t)ncomp};
  IO_H5(space = H5Screate_simple(ncomp == 1 ? 1 : 2, dims, NULL), path);
  IO_H5(dset = H5Dcreate2(loc, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path);
  IO_H5(H5Dwrite(dset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), path);
  if (bytes > 0) {
    const uint32_t crc = crc_of(data, bytes);
    CLSPH_TRY(attr_write(dset, "crc32", H5T_NATIVE_UINT32, &crc, path));
  }
  CLSPH_TRY(h5_close_checked(&dset, path));
done:
  h5_close_id(&dset);
  h5_close_id(&space);
  return st;
}

/* The domain, the walls and the render choices of a snapshot (what frames need). */
static enum clsph_status write_frame_meta(hid_t file, const struct io_meta *m, const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t grp = H5I_INVALID_HID, dset = H5I_INVALID_HID;
  char name[32];
  if (m->has_domain)
    CLSPH_TRY(attr_write_array(file, "domain", H5T_NATIVE_DOUBLE, 4, m->domain, path));
  if (m->has_domain3)
    CLSPH_TRY(attr_write_array(file, "domain3", H5T_NATIVE_DOUBLE, 6, m->domain3, path));
  if (m->nwalls > 0) {
    IO_H5(grp = H5Gcreate2(file, "walls", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path);
    for (int w = 0; w < m->nwalls; ++w) {
      const struct scene_wall *sw = &m->walls[w];
      const int32_t closed = sw->closed != 0;
      snprintf(name, sizeof name, "wall_%03d", w);
      CLSPH_TRY(write_dataset(grp, name, H5T_NATIVE_DOUBLE, (size_t)sw->npts, 2, sw->pts, 0, path));
      IO_H5(dset = H5Dopen2(grp, name, H5P_DEFAULT), path);
      CLSPH_TRY(attr_write(dset, "closed", H5T_NATIVE_INT32, &closed, path));
      CLSPH_TRY(h5_close_checked(&dset, path));
    }
    CLSPH_TRY(h5_close_checked(&grp, path));
  }
  if (m->nsurf3 > 0)
    CLSPH_TRY(write_dataset(file, "walls3", H5T_NATIVE_DOUBLE, m->nsurf3, 9, m->surf3, 0, path));
  if (m->render != NULL && m->render->on) {
    IO_H5(grp = H5Gcreate2(file, "render", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path);
    CLSPH_TRY(attr_write_str(grp, "field", m->render->field, path));
    CLSPH_TRY(attr_write_str(grp, "colormap", m->render->colormap, path));
    if (m->render->fixed)
      CLSPH_TRY(attr_write_array(grp, "range", H5T_NATIVE_DOUBLE, 2, m->render->range, path));
    if (m->render->camera) { /* eye, look_at, up, fov */
      const struct scene_render *r = m->render;
      const double cam[10] = {r->eye[0],     r->eye[1], r->eye[2], r->look_at[0], r->look_at[1],
                              r->look_at[2], r->up[0],  r->up[1],  r->up[2],      r->fov};
      CLSPH_TRY(attr_write_array(grp, "camera", H5T_NATIVE_DOUBLE, 10, cam, path));
    }
    CLSPH_TRY(h5_close_checked(&grp, path));
  }
done:
  h5_close_id(&dset);
  h5_close_id(&grp);
  return st;
}

/* Bytes of the largest field (host staging buffer). */
static size_t max_field_bytes(const struct pset *ps)
{
  size_t most = 1;
  for (int k = 0; k < ps->nfields; ++k)
    if (ps->n * ps->f[k].elem > most) most = ps->n * ps->f[k].elem;
  return most;
}

static enum clsph_status read_field(const struct dev *dev, const struct pset *ps,
                                    const struct pfield *f, void *h)
{
  enum clsph_status st = CLSPH_OK;
  if (ps->n > 0) CLSPH_TRY(kern_read(dev, f->d, ps->n * f->elem, h));
done:
  return st;
}

enum clsph_status io_snapshot_write(const char *path, const struct dev *dev, const struct pset *ps,
                                    const struct io_meta *m)
{
  enum clsph_status st = CLSPH_OK;
  char *tmp = NULL;
  unsigned char *h = NULL;
  int32_t *vertex = NULL;
  hid_t file = H5I_INVALID_HID, grp = H5I_INVALID_HID;

  h5_quiet();
  CLSPH_TRY(check_fields(ps));
  CLSPH_CHECK(ps->n <= (size_t)INT32_MAX, CLSPH_E_INPUT,
              "%s: %zu particles are more than a snapshot can index", or_empty(path), ps->n);
  CLSPH_TRY(tmp_name(path, &tmp));
  h = malloc(max_field_bytes(ps));
  vertex = malloc(ps->n > 0 ? ps->n * sizeof *vertex : 1);
  CLSPH_CHECK(h != NULL && vertex != NULL, CLSPH_E_NOMEM, "out of memory writing %s", path);

  IO_H5(file = H5Fcreate(tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), path);
  CLSPH_TRY(write_meta(file, m, ps->n, path));

  /* the output fields, without their padding components */
  IO_H5(grp = H5Gcreate2(file, "particles", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path);
  for (int k = 0; k < ps->nfields; ++k) {
    const struct pfield *f = &ps->f[k];
    if (!f->output) continue;
    const size_t cb = field_comp_bytes(f), row = (size_t)f->nout * cb;
    CLSPH_TRY(read_field(dev, ps, f, h));
    if (f->nout < f->ncomp)
      for (size_t i = 0; i < ps->n; ++i) memmove(h + i * row, h + i * f->elem, row);
    CLSPH_TRY(write_dataset(grp, f->name, field_h5_type(f), ps->n, f->nout, h, 0, path));
  }
  CLSPH_TRY(h5_close_checked(&grp, path));

  /* the vertex list of the XDMF topology */
  for (size_t i = 0; i < ps->n; ++i) vertex[i] = (int32_t)i;
  CLSPH_TRY(write_dataset(file, "topology", H5T_NATIVE_INT32, ps->n, 1, vertex, 0, path));
  CLSPH_TRY(write_frame_meta(file, m, path));

  CLSPH_TRY(h5_close_checked(&file, path));
  CLSPH_TRY(commit(tmp, path));
done:
  h5_close_id(&grp);
  h5_close_id(&file);
  if (st != CLSPH_OK && tmp != NULL) remove(tmp);
  free(vertex);
  free(h);
  free(tmp);
  return st;
}

enum clsph_status io_checkpoint_write(const char *path, const struct dev *dev,
                                      const struct pset *ps, const struct io_meta *m,
                                      const void *blob, size_t blob_bytes)
{
  enum clsph_status st = CLSPH_OK;
  char *tmp = NULL;
  unsigned char *h = NULL;
  hid_t file = H5I_INVALID_HID, grp = H5I_INVALID_HID;
  const int32_t one = 1;

  h5_quiet();
  CLSPH_TRY(check_fields(ps));
  CLSPH_CHECK(blob_bytes == 0 || blob != NULL, CLSPH_E_INPUT,
              "%s: checkpoint blob of %zu bytes has no data", or_empty(path), blob_bytes);
  CLSPH_TRY(tmp_name(path, &tmp));
  h = malloc(max_field_bytes(ps));
  CLSPH_CHECK(h != NULL, CLSPH_E_NOMEM, "out of memory writing %s", path);

  IO_H5(file = H5Fcreate(tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), path);
  CLSPH_TRY(attr_write(file, "clsph_checkpoint", H5T_NATIVE_INT32, &one, path));
  CLSPH_TRY(write_meta(file, m, ps->n, path));
  /* the scene's digest, the whole run's figures, a checksum of the scalars */
  const uint64_t digest = (uint64_t)m->digest;
  const uint32_t mcrc =
      meta_crc(m->time, (int64_t)m->step, m->dt, (uint64_t)ps->n, (uint64_t)m->digest);
  CLSPH_TRY(attr_write(file, "scene_digest", H5T_NATIVE_UINT64, &digest, path));
  CLSPH_TRY(attr_write(file, "meta_crc32", H5T_NATIVE_UINT32, &mcrc, path));
  IO_H5(grp = H5Gcreate2(file, "statistics", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path);
  for (int k = 0; k < m->nstats; ++k)
    CLSPH_TRY(attr_write(grp, m->stat_names[k], H5T_NATIVE_DOUBLE, &m->stats[k], path));
  CLSPH_TRY(h5_close_checked(&grp, path));

  /* every field, every component, in the native types: the bytes come back unchanged */
  IO_H5(grp = H5Gcreate2(file, "fields", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path);
  for (int k = 0; k < ps->nfields; ++k) {
    const struct pfield *f = &ps->f[k];
    CLSPH_TRY(read_field(dev, ps, f, h));
    CLSPH_TRY(
        write_dataset(grp, f->name, field_h5_type(f), ps->n, f->ncomp, h, ps->n * f->elem, path));
  }
  CLSPH_TRY(h5_close_checked(&grp, path));

  if (blob_bytes > 0)
    CLSPH_TRY(write_dataset(file, "blob", H5T_NATIVE_UINT8, blob_bytes, 1, blob, blob_bytes, path));

  CLSPH_TRY(h5_close_checked(&file, path));
  CLSPH_TRY(commit(tmp, path));
done:
  h5_close_id(&grp);
  h5_close_id(&file);
  if (st != CLSPH_OK && tmp != NULL) remove(tmp);
  free(h);
  free(tmp);
  return st;
}

/* ---------------------------------------------------------------------------------------------
 * Series and XDMF */

static char *str_copy(const char *s)
{
  size_t len = strlen(s) + 1;
  char *c = malloc(len);
  if (c != NULL) memcpy(c, s, len);
  return c;
}

enum clsph_status io_series_add(struct io_series *s, const char *file, double time, size_t n)
{
  enum clsph_status st = CLSPH_OK;
  char *name = NULL;
  CLSPH_CHECK(file != NULL && file[0] != '\0', CLSPH_E_INPUT, "snapshot file name is empty");
  name = str_copy(file);
  CLSPH_CHECK(name != NULL, CLSPH_E_NOMEM, "out of memory (snapshot series)");
  if (s->count == s->cap) {
    int cap = s->cap > 0 ? 2 * s->cap : 16;
    char **files = realloc(s->files, (size_t)cap * sizeof *files);
    if (files != NULL) s->files = files;
    double *times = realloc(s->times, (size_t)cap * sizeof *times);
    if (times != NULL) s->times = times;
    size_t *ns = realloc(s->n, (size_t)cap * sizeof *ns);
    if (ns != NULL) s->n = ns;
    CLSPH_CHECK(files != NULL && times != NULL && ns != NULL, CLSPH_E_NOMEM,
                "out of memory (snapshot series of %d)", cap);
    s->cap = cap;
  }
  s->files[s->count] = name;
  s->times[s->count] = time;
  s->n[s->count] = n;
  ++s->count;
  name = NULL; /* the series owns it */
done:
  free(name);
  return st;
}

void io_series_free(struct io_series *s)
{
  for (int i = 0; i < s->count; ++i) free(s->files[i]);
  free(s->files);
  free(s->times);
  free(s->n);
  memset(s, 0, sizeof *s);
}

/* Text with the five XML special characters escaped. */
static void xml_text(FILE *f, const char *s)
{
  for (; *s != '\0'; ++s) {
    switch (*s) {
    case '&':
      fputs("&amp;", f);
      break;
    case '<':
      fputs("&lt;", f);
      break;
    case '>':
      fputs("&gt;", f);
      break;
    case '"':
      fputs("&quot;", f);
      break;
    case '\'':
      fputs("&apos;", f);
      break;
    default:
      fputc(*s, f);
      break;
    }
  }
}

/* <DataItem> pointing at a dataset of a snapshot: Dimensions "n" or "n ncomp". */
static void xdmf_data_item(FILE *f, const char *indent, const struct pfield *fld, size_t n,
                           const char *file, const char *dataset)
{
  const char *number = fld->type == PF_REAL ? "Float" : fld->type == PF_UINT ? "UInt" : "Int";
  fprintf(f, "%s<DataItem Dimensions=\"%zu", indent, n);
  if (fld->nout > 1) fprintf(f, " %d", fld->nout);
  fprintf(f, "\" NumberType=\"%s\" Precision=\"%zu\" Format=\"HDF\">", number,
          field_comp_bytes(fld));
  xml_text(f, file);
  fputs(":/particles/", f);
  xml_text(f, dataset);
  fputs("</DataItem>\n", f);
}

static const char *xdmf_attribute_type(const struct pfield *f, int dim)
{
  if (f->nout == 1) return "Scalar";
  if (f->nout == dim) return "Vector";
  return "Matrix";
}

/* One uniform grid: a snapshot. */
static void xdmf_grid(FILE *f, const char *file, double time, size_t n, const struct pset *ps,
                      int ipos, int dim)
{
  fputs("      <Grid Name=\"", f);
  xml_text(f, file);
  fputs("\" GridType=\"Uniform\">\n", f);
  fprintf(f, "        <Time Value=\"%.17g\"/>\n", time);
  fprintf(f,
          "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%zu\" "
          "NodesPerElement=\"1\">\n",
          n);
  fprintf(f,
          "          <DataItem Dimensions=\"%zu\" NumberType=\"Int\" Precision=\"4\" "
          "Format=\"HDF\">",
          n);
  xml_text(f, file);
  fputs(":/topology</DataItem>\n", f);
  fputs("        </Topology>\n", f);
  fprintf(f, "        <Geometry GeometryType=\"%s\">\n", dim == 2 ? "XY" : "XYZ");
  xdmf_data_item(f, "          ", &ps->f[ipos], n, file, "pos");
  fputs("        </Geometry>\n", f);
  for (int k = 0; k < ps->nfields; ++k) {
    const struct pfield *fld = &ps->f[k];
    if (!fld->output || k == ipos) continue; /* the positions are the geometry */
    fputs("        <Attribute Name=\"", f);
    xml_text(f, fld->name);
    fprintf(f, "\" AttributeType=\"%s\" Center=\"Node\">\n", xdmf_attribute_type(fld, dim));
    xdmf_data_item(f, "          ", fld, n, file, fld->name);
    fputs("        </Attribute>\n", f);
  }
  fputs("      </Grid>\n", f);
}

enum clsph_status io_xdmf_write(const char *path, const struct io_series *s, const struct pset *ps,
                                int dim)
{
  enum clsph_status st = CLSPH_OK;
  char *tmp = NULL;
  FILE *f = NULL;
  int ipos = pset_find(ps, "pos"), werr = 0;

  CLSPH_CHECK(dim == 2 || dim == 3, CLSPH_E_INPUT, "%s: dimension %d is not 2 or 3", or_empty(path),
              dim);
  CLSPH_TRY(check_fields(ps));
  CLSPH_CHECK(
      ipos >= 0 && ps->f[ipos].output && ps->f[ipos].type == PF_REAL && ps->f[ipos].nout == dim,
      CLSPH_E_INPUT, "%s: the particles need an output field 'pos' of %d reals for the geometry",
      or_empty(path), dim);
  CLSPH_TRY(tmp_name(path, &tmp));
  f = fopen(tmp, "w");
  CLSPH_CHECK(f != NULL, CLSPH_E_IO, "cannot write %s: %s", tmp, strerror(errno));

  fputs("<?xml version=\"1.0\" ?>\n"
        "<Xdmf Version=\"3.0\">\n"
        "  <Domain>\n"
        "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n",
        f);
  for (int i = 0; i < s->count; ++i) xdmf_grid(f, s->files[i], s->times[i], s->n[i], ps, ipos, dim);
  fputs("    </Grid>\n"
        "  </Domain>\n"
        "</Xdmf>\n",
        f);

  werr = ferror(f);
  werr |= fclose(f) != 0;
  f = NULL;
  CLSPH_CHECK(!werr, CLSPH_E_IO, "cannot write %s: %s", tmp, strerror(errno));
  CLSPH_TRY(commit(tmp, path));
done:
  if (f != NULL) fclose(f);
  if (st != CLSPH_OK && tmp != NULL) remove(tmp);
  free(tmp);
  return st;
}

/* ---------------------------------------------------------------------------------------------
 * Reading a checkpoint */

/* A refusal: one message naming the file and the reason. */
#define IO_REFUSE(cond, ...) CLSPH_CHECK(cond, CLSPH_E_INPUT, __VA_ARGS__)

/* An HDF5 call that fails on a file that is not what it should be: "truncated or damaged", with
 * HDF5's reason. */
#define IO_DAMAGED(call)                                                                           \
  do {                                                                                             \
    if ((call) < 0) {                                                                              \
      damaged(path, NULL);                                                                         \
      st = CLSPH_E_INPUT;                                                                          \
      goto done;                                                                                   \
    }                                                                                              \
  } while (0)

static void damaged(const char *path, const char *why)
{
  char reason[400];
  if (why == NULL) {
    h5_reason(reason, sizeof reason);
    why = reason;
  }
  log_error("%s is truncated or damaged%s%s%s", path, why[0] ? " (" : "", why, why[0] ? ")" : "");
}

/* Is the file HDF5? (1 yes, 0 no, negative: cannot tell). */
static htri_t h5_is_hdf5(const char *path)
{
#if H5_VERSION_GE(1, 12, 0)
  return H5Fis_accessible(path, H5P_DEFAULT);
#else
  return H5Fis_hdf5(path);
#endif
}

/* A 1-D attribute of exactly `count` values read into `type`; *found = 0 when absent. */
static enum clsph_status attr_read_array(hid_t loc, const char *name, hid_t type, size_t count,
                                         void *value, int *found, const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t attr = H5I_INVALID_HID, space = H5I_INVALID_HID;
  htri_t exists;
  *found = 0;
  IO_DAMAGED(exists = H5Aexists(loc, name));
  if (!exists) goto done;
  IO_DAMAGED(attr = H5Aopen(loc, name, H5P_DEFAULT));
  IO_DAMAGED(space = H5Aget_space(attr));
  if (H5Sget_simple_extent_npoints(space) != (hssize_t)count) {
    damaged(path, "an attribute has the wrong number of values");
    st = CLSPH_E_INPUT;
    goto done;
  }
  IO_DAMAGED(H5Aread(attr, type, value));
  *found = 1;
done:
  h5_close_id(&space);
  h5_close_id(&attr);
  return st;
}

/* A scalar attribute read into `type` (HDF5 converts numbers); *found = 0 when absent. */
static enum clsph_status attr_read(hid_t loc, const char *name, hid_t type, void *value, int *found,
                                   const char *path)
{
  return attr_read_array(loc, name, type, 1, value, found, path);
}

/* A string attribute (fixed-length or variable-length) as a malloc'd string; NULL when absent. */
static enum clsph_status attr_read_str(hid_t loc, const char *name, char **out, const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t attr = H5I_INVALID_HID, type = H5I_INVALID_HID, mem = H5I_INVALID_HID;
  char *s = NULL, *vs = NULL;
  htri_t exists, var;
  *out = NULL;
  IO_DAMAGED(exists = H5Aexists(loc, name));
  if (!exists) goto done;
  IO_DAMAGED(attr = H5Aopen(loc, name, H5P_DEFAULT));
  IO_DAMAGED(type = H5Aget_type(attr));
  if (H5Tget_class(type) != H5T_STRING) {
    damaged(path, "a string attribute is not a string");
    st = CLSPH_E_INPUT;
    goto done;
  }
  IO_DAMAGED(var = H5Tis_variable_str(type));
  IO_DAMAGED(mem = H5Tcopy(H5T_C_S1));
  if (var) {
    IO_DAMAGED(H5Tset_size(mem, H5T_VARIABLE));
    IO_DAMAGED(H5Aread(attr, mem, &vs));
    s = str_copy(vs != NULL ? vs : "");
  } else {
    size_t size = H5Tget_size(type);
    IO_DAMAGED(H5Tset_size(mem, size + 1));
    IO_DAMAGED(H5Tset_strpad(mem, H5T_STR_NULLTERM));
    s = calloc(size + 1, 1);
    if (s != NULL) IO_DAMAGED(H5Aread(attr, mem, s));
  }
  CLSPH_CHECK(s != NULL, CLSPH_E_NOMEM, "out of memory reading %s", path);
  *out = s;
  s = NULL;
done:
  if (vs != NULL) H5free_memory(vs);
  free(s);
  h5_close_id(&mem);
  h5_close_id(&type);
  h5_close_id(&attr);
  return st;
}

static const char *class_name(H5T_class_t cls, hid_t type)
{
  if (cls == H5T_FLOAT) return "floats";
  if (cls != H5T_INTEGER) return "non-numbers";
  return H5Tget_sign(type) == H5T_SGN_NONE ? "unsigned integers" : "integers";
}

/* Does the dataset of field f match it (type, component size, components)? Reads its rows. */
/* The dataset's "crc32" against the CRC-32 of the `bytes` bytes read from it: a mismatch is a
 * refusal naming `what`; *unchecked counts datasets without one (older checkpoints). */
static enum clsph_status check_crc(hid_t dset, const void *data, size_t bytes, const char *what,
                                   int *unchecked, const char *path)
{
  enum clsph_status st = CLSPH_OK;
  uint32_t stored = 0;
  int found = 0;
  CLSPH_TRY(attr_read(dset, "crc32", H5T_NATIVE_UINT32, &stored, &found, path));
  if (!found) {
    ++*unchecked;
    goto done;
  }
  const uint32_t got = crc_of(data, bytes);
  IO_REFUSE(got == stored,
            "%s is damaged: %s fails its checksum (CRC-32 %08lx recorded, %08lx read)", path, what,
            (unsigned long)stored, (unsigned long)got);
done:
  return st;
}

static enum clsph_status read_field_dataset(hid_t grp, const struct pfield *f, size_t n, void *h,
                                            int *unchecked, const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t dset = H5I_INVALID_HID, space = H5I_INVALID_HID, type = H5I_INVALID_HID;
  hid_t mem = H5I_INVALID_HID;
  hsize_t dims[2] = {0, 1};
  htri_t exists;
  H5T_class_t cls;
  size_t tsize;
  const size_t cb = field_comp_bytes(f);
  int rank, same_type;
  char why[160];

  IO_DAMAGED(exists = H5Lexists(grp, f->name, H5P_DEFAULT));
  IO_REFUSE(exists, "%s has no field '%s' (this run needs it)", path, f->name);
  IO_DAMAGED(dset = H5Dopen2(grp, f->name, H5P_DEFAULT));
  IO_DAMAGED(space = H5Dget_space(dset));
  IO_DAMAGED(rank = H5Sget_simple_extent_ndims(space));
  IO_REFUSE(rank == 1 || rank == 2, "%s: field '%s' has %d dimensions, not 1 or 2", path, f->name,
            rank);
  IO_DAMAGED(H5Sget_simple_extent_dims(space, dims, NULL));
  IO_DAMAGED(type = H5Dget_type(dset));
  /* the same element type and size: the bytes are copied, never converted */
  cls = H5Tget_class(type);
  tsize = H5Tget_size(type);
  if (f->type == PF_REAL)
    same_type = cls == H5T_FLOAT;
  else
    same_type =
        cls == H5T_INTEGER && H5Tget_sign(type) == (f->type == PF_INT ? H5T_SGN_2 : H5T_SGN_NONE);
  IO_REFUSE(same_type && tsize == cb && dims[1] * tsize == f->elem,
            "%s: field '%s' holds %llu x %zu-byte %s per particle; this run stores %d x %zu-byte "
            "%s",
            path, f->name, (unsigned long long)dims[1], tsize, class_name(cls, type), f->ncomp, cb,
            f->type == PF_REAL  ? "floats"
            : f->type == PF_INT ? "integers"
                                : "unsigned integers");
  if (dims[0] != (hsize_t)n) {
    snprintf(why, sizeof why, "field '%s' holds %llu particles, not %zu", f->name,
             (unsigned long long)dims[0], n);
    damaged(path, why);
    st = CLSPH_E_INPUT;
    goto done;
  }
  IO_DAMAGED(mem = H5Tget_native_type(type, H5T_DIR_ASCEND));
  IO_DAMAGED(H5Dread(dset, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, h));
  snprintf(why, sizeof why, "field '%s'", f->name);
  CLSPH_TRY(check_crc(dset, h, n * f->elem, why, unchecked, path));
done:
  h5_close_id(&mem);
  h5_close_id(&type);
  h5_close_id(&space);
  h5_close_id(&dset);
  return st;
}

/* The blob, or NULL and 0 when the checkpoint has none. */
static enum clsph_status read_blob(hid_t file, void **out, size_t *bytes, int *unchecked,
                                   const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t dset = H5I_INVALID_HID, space = H5I_INVALID_HID;
  hsize_t dims[1] = {0};
  unsigned char *b = NULL;
  htri_t exists;
  IO_DAMAGED(exists = H5Lexists(file, "blob", H5P_DEFAULT));
  if (!exists) goto done;
  IO_DAMAGED(dset = H5Dopen2(file, "blob", H5P_DEFAULT));
  IO_DAMAGED(space = H5Dget_space(dset));
  if (H5Sget_simple_extent_ndims(space) != 1) {
    damaged(path, "the blob is not a 1-D byte array");
    st = CLSPH_E_INPUT;
    goto done;
  }
  IO_DAMAGED(H5Sget_simple_extent_dims(space, dims, NULL));
  b = malloc(dims[0] > 0 ? (size_t)dims[0] : 1);
  CLSPH_CHECK(b != NULL, CLSPH_E_NOMEM, "out of memory reading %s", path);
  IO_DAMAGED(H5Dread(dset, H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, b));
  CLSPH_TRY(check_crc(dset, b, (size_t)dims[0], "the state blob", unchecked, path));
  *bytes = (size_t)dims[0];
  *out = b;
  b = NULL;
done:
  free(b);
  h5_close_id(&space);
  h5_close_id(&dset);
  return st;
}

/* Open a file that should be a clsph `what` ("checkpoint", "snapshot") read-only: a missing file
 * and a file that is not HDF5 are refused with the reason, a damaged one as damaged. */
static enum clsph_status open_clsph_file(const char *path, const char *what, hid_t *out)
{
  enum clsph_status st = CLSPH_OK;
  htri_t is;
  FILE *probe = fopen(path, "rb");
  IO_REFUSE(probe != NULL, "cannot open %s %s: %s", what, path, strerror(errno));
  fclose(probe);
  is = h5_is_hdf5(path);
  IO_REFUSE(is != 0, "%s is not a clsph %s (not an HDF5 file)", path, what);
  IO_DAMAGED(is);
  IO_DAMAGED(*out = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT));
done:
  return st;
}

/* H5Aiterate2: the first attribute name that `expect` does not declare (t_end aside). */
struct extra_param {
  const struct io_meta *expect;
  char name[64];
};

static herr_t find_extra(hid_t loc, const char *name, const H5A_info_t *info, void *data)
{
  (void)loc;
  (void)info;
  struct extra_param *x = data;
  if (strcmp(name, "t_end") == 0) return 0;
  for (int i = 0; i < x->expect->nparams; ++i)
    if (strcmp(x->expect->params[i].name, name) == 0) return 0;
  snprintf(x->name, sizeof x->name, "%s", name);
  return 1;
}

/* The scene of the checkpoint is the scene of this run: the same parameters (t_end may change:
 * a restart may run further) and the same digest (geometry_digest) when both have one. */
static enum clsph_status check_scene(hid_t file, const struct io_meta *expect, uint64_t digest,
                                     int has_digest, const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t grp = H5I_INVALID_HID;
  htri_t exists;
  IO_DAMAGED(exists = H5Lexists(file, "parameters", H5P_DEFAULT));
  IO_REFUSE(exists, "%s records no parameters: it is not a clsph checkpoint", path);
  IO_DAMAGED(grp = H5Gopen2(file, "parameters", H5P_DEFAULT));
  for (int i = 0; i < expect->nparams; ++i) {
    const struct scene_param *p = &expect->params[i];
    double v = 0.0;
    int found = 0;
    if (strcmp(p->name, "t_end") == 0) continue;
    CLSPH_TRY(attr_read(grp, p->name, H5T_NATIVE_DOUBLE, &v, &found, path));
    IO_REFUSE(found,
              "%s comes from another scene: its run declares no parameter '%s' (this run: %s = "
              "%.10g); a restart continues the same scene, only t_end may change",
              path, p->name, p->name, p->value);
    IO_REFUSE(v == p->value,
              "%s comes from another scene: its run had %s = %.10g, this run %s = %.10g; a "
              "restart continues the same scene, only t_end may change",
              path, p->name, v, p->name, p->value);
  }
  struct extra_param x = {expect, ""};
  hsize_t at = 0;
  IO_DAMAGED(H5Aiterate2(grp, H5_INDEX_NAME, H5_ITER_INC, &at, find_extra, &x));
  IO_REFUSE(x.name[0] == '\0',
            "%s comes from another scene: its run has a parameter '%s' that this case does not "
            "declare",
            path, x.name);
  if (has_digest && expect->digest != 0)
    IO_REFUSE(digest == (uint64_t)expect->digest,
              "%s comes from another scene: the parameters agree, but the particles, walls, "
              "domain, fluid or scheme options differ from the checkpoint's run (was the case "
              "file changed?)",
              path);
  else
    log_warn("%s records no digest of its scene (written by an older clsph): only its "
             "parameters were compared",
             path);
done:
  h5_close_id(&grp);
  return st;
}

/* The statistics the caller asks for (ask->stat_names, into ask->stats), from the group
 * "statistics"; how many into *count. */
static enum clsph_status read_stats(hid_t file, const struct io_meta *ask, int *count,
                                    const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t grp = H5I_INVALID_HID;
  htri_t exists;
  *count = 0;
  if (ask == NULL || ask->nstats == 0) goto done;
  IO_DAMAGED(exists = H5Lexists(file, "statistics", H5P_DEFAULT));
  if (!exists) goto done;
  IO_DAMAGED(grp = H5Gopen2(file, "statistics", H5P_DEFAULT));
  for (int k = 0; k < ask->nstats; ++k) {
    int found = 0;
    double v = 0.0;
    CLSPH_TRY(attr_read(grp, ask->stat_names[k], H5T_NATIVE_DOUBLE, &v, &found, path));
    if (!found) continue;
    ask->stats[k] = v;
    ++*count;
  }
done:
  h5_close_id(&grp);
  return st;
}

enum clsph_status io_checkpoint_read(const char *path, const struct dev *dev, struct pset *ps,
                                     const struct io_meta *expect, struct io_meta *m, void **blob,
                                     size_t *blob_bytes)
{
  enum clsph_status st = CLSPH_OK;
  hid_t file = H5I_INVALID_HID, grp = H5I_INVALID_HID;
  char *precision = NULL, *case_name = NULL;
  unsigned char *h[PSET_MAX_FIELDS] = {NULL};
  void *b = NULL;
  size_t bbytes = 0, n = 0;
  int32_t magic = 0;
  uint64_t n64 = 0;
  int64_t step = 0;
  double time = 0.0, dt = 0.0;
  int found = 0, found_step = 0, found_time = 0, found_dt = 0, has_digest = 0, unchecked = 0;
  int stats_read = 0;
  uint64_t digest = 0;
  uint32_t mcrc = 0;
  const char *want_precision =
      expect != NULL && expect->precision != NULL ? expect->precision : CLSPH_PRECISION_NAME;

  h5_quiet();
  *blob = NULL;
  *blob_bytes = 0;
  CLSPH_TRY(check_fields(ps));

  CLSPH_TRY(open_clsph_file(path, "checkpoint", &file));

  /* a checkpoint, of this precision and this case? */
  CLSPH_TRY(attr_read(file, "clsph_checkpoint", H5T_NATIVE_INT32, &magic, &found, path));
  IO_REFUSE(found && magic == 1, "%s is not a clsph checkpoint", path);
  CLSPH_TRY(attr_read_str(file, "precision", &precision, path));
  IO_REFUSE(precision != NULL, "%s is not a clsph checkpoint (it records no precision)", path);
  IO_REFUSE(strcmp(precision, want_precision) == 0,
            "%s was written in %s precision; this build is %s", path, precision, want_precision);
  CLSPH_TRY(attr_read_str(file, "case", &case_name, path));
  IO_REFUSE(case_name != NULL, "%s is not a clsph checkpoint (it names no case)", path);
  IO_REFUSE(expect == NULL || expect->case_name == NULL ||
                strcmp(case_name, expect->case_name) == 0,
            "%s was written by case '%s', not '%s'", path, case_name,
            expect != NULL && expect->case_name != NULL ? expect->case_name : "");
  CLSPH_TRY(attr_read(file, "time", H5T_NATIVE_DOUBLE, &time, &found_time, path));
  CLSPH_TRY(attr_read(file, "step", H5T_NATIVE_INT64, &step, &found_step, path));
  CLSPH_TRY(attr_read(file, "dt", H5T_NATIVE_DOUBLE, &dt, &found_dt, path));
  CLSPH_TRY(attr_read(file, "n", H5T_NATIVE_UINT64, &n64, &found, path));
  if (!(found && found_time && found_step && found_dt)) {
    damaged(path, "time, step, dt or n is missing");
    st = CLSPH_E_INPUT;
    goto done;
  }
  CLSPH_TRY(attr_read(file, "scene_digest", H5T_NATIVE_UINT64, &digest, &has_digest, path));
  CLSPH_TRY(attr_read(file, "meta_crc32", H5T_NATIVE_UINT32, &mcrc, &found, path));
  if (found) {
    const uint32_t got = meta_crc(time, step, dt, n64, has_digest ? digest : 0);
    IO_REFUSE(got == mcrc,
              "%s is damaged: its time, step, dt or particle count fails its checksum (CRC-32 "
              "%08lx recorded, %08lx read)",
              path, (unsigned long)mcrc, (unsigned long)got);
  } else {
    ++unchecked;
  }
  if (expect != NULL && expect->params != NULL)
    CLSPH_TRY(check_scene(file, expect, digest, has_digest, path));
  IO_REFUSE(n64 <= (uint64_t)ps->cap, "%s holds %llu particles; this run has room for %zu", path,
            (unsigned long long)n64, ps->cap);
  n = (size_t)n64;

  /* every field into host memory first: a refused file leaves the device untouched */
  IO_DAMAGED(grp = H5Gopen2(file, "fields", H5P_DEFAULT));
  for (int k = 0; k < ps->nfields; ++k) {
    /* a temporary (pset_temporary) may be missing: a step makes it after its sort before it
     * reads it, so a checkpoint from a build whose scheme kept other ones restarts too; where
     * the file has it, it comes back with the rest (bit for bit, the entries no step wrote too) */
    if (ps->f[k].temp) {
      htri_t has;
      IO_DAMAGED(has = H5Lexists(grp, ps->f[k].name, H5P_DEFAULT));
      if (!has) continue;
    }
    h[k] = malloc(n > 0 ? n * ps->f[k].elem : 1);
    CLSPH_CHECK(h[k] != NULL, CLSPH_E_NOMEM, "out of memory reading %s", path);
    CLSPH_TRY(read_field_dataset(grp, &ps->f[k], n, h[k], &unchecked, path));
  }
  CLSPH_TRY(read_blob(file, &b, &bbytes, &unchecked, path));
  CLSPH_TRY(read_stats(file, expect, &stats_read, path));
  if (unchecked > 0)
    log_warn("%s carries no checksums on %d of its datasets (written by an older clsph): they "
             "were read unchecked",
             path, unchecked);

  /* accepted: to the device */
  for (int k = 0; k < ps->nfields && n > 0; ++k)
    if (h[k] != NULL) CLSPH_TRY(kern_write(dev, ps->f[k].d, n * ps->f[k].elem, h[k]));
  ps->n = n;
  m->time = time;
  m->step = (long)step;
  m->dt = dt;
  m->stats_read = stats_read;
  *blob = b;
  *blob_bytes = bbytes;
  b = NULL; /* the caller owns it */
done:
  h5_close_id(&grp);
  h5_close_id(&file);
  for (int k = 0; k < PSET_MAX_FIELDS; ++k) free(h[k]);
  free(b);
  free(case_name);
  free(precision);
  return st;
}

/* ---------------------------------------------------------------------------------------------
 * Reading a snapshot (for frames) */

/* Shape of a dataset: rows and components (1 for a 1-D dataset). */
static enum clsph_status dataset_shape(hid_t dset, hsize_t *rows, int *ncomp, const char *what,
                                       const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t space = H5I_INVALID_HID;
  hsize_t dims[2] = {0, 1};
  int rank;
  IO_DAMAGED(space = H5Dget_space(dset));
  IO_DAMAGED(rank = H5Sget_simple_extent_ndims(space));
  IO_REFUSE(rank == 1 || rank == 2, "%s: %s has %d dimensions, not 1 or 2", path, what, rank);
  IO_DAMAGED(H5Sget_simple_extent_dims(space, dims, NULL));
  IO_REFUSE(dims[1] >= 1 && dims[1] <= 16, "%s: %s has %llu components", path, what,
            (unsigned long long)dims[1]);
  *rows = dims[0];
  *ncomp = (int)dims[1];
done:
  h5_close_id(&space);
  return st;
}

static void copy_name(char *dst, size_t size, const char *src)
{
  snprintf(dst, size, "%s", src != NULL ? src : "");
}

static int wanted(const char *const *only, const char *name)
{
  if (only == NULL) return 1;
  for (int k = 0; only[k] != NULL; ++k)
    if (strcmp(only[k], name) == 0) return 1;
  return 0;
}

static enum clsph_status read_walls(hid_t file, struct io_snapshot *s, const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t grp = H5I_INVALID_HID, dset = H5I_INVALID_HID;
  H5G_info_t info;
  htri_t exists;
  char name[64];
  IO_DAMAGED(exists = H5Lexists(file, "walls", H5P_DEFAULT));
  if (!exists) goto done;
  IO_DAMAGED(grp = H5Gopen2(file, "walls", H5P_DEFAULT));
  IO_DAMAGED(H5Gget_info(grp, &info));
  s->walls = calloc(info.nlinks > 0 ? (size_t)info.nlinks : 1, sizeof *s->walls);
  CLSPH_CHECK(s->walls != NULL, CLSPH_E_NOMEM, "out of memory reading %s", path);
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    ssize_t len;
    IO_DAMAGED(len = H5Lget_name_by_idx(grp, ".", H5_INDEX_NAME, H5_ITER_INC, k, name, sizeof name,
                                        H5P_DEFAULT));
    IO_DAMAGED(dset = H5Dopen2(grp, name, H5P_DEFAULT));
    hsize_t rows = 0;
    int nc = 0, found = 0;
    int32_t closed = 0;
    CLSPH_TRY(dataset_shape(dset, &rows, &nc, name, path));
    IO_REFUSE(nc == 2 && rows >= 2, "%s: wall %s is not a polyline of points (x, y)", path, name);
    struct io_wall *w = &s->walls[s->nwalls];
    w->pts = malloc((size_t)rows * 2 * sizeof *w->pts);
    CLSPH_CHECK(w->pts != NULL, CLSPH_E_NOMEM, "out of memory reading %s", path);
    w->npts = (int)rows;
    ++s->nwalls;
    IO_DAMAGED(H5Dread(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, w->pts));
    CLSPH_TRY(attr_read(dset, "closed", H5T_NATIVE_INT32, &closed, &found, path));
    w->closed = found && closed != 0;
    h5_close_id(&dset);
  }
done:
  h5_close_id(&dset);
  h5_close_id(&grp);
  return st;
}

/* /walls3 (3-D), when the snapshot has it */
static enum clsph_status read_surf3(hid_t file, struct io_snapshot *s, const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t dset = H5I_INVALID_HID;
  htri_t exists;
  IO_DAMAGED(exists = H5Lexists(file, "walls3", H5P_DEFAULT));
  if (!exists) goto done;
  IO_DAMAGED(dset = H5Dopen2(file, "walls3", H5P_DEFAULT));
  hsize_t rows = 0;
  int nc = 0;
  CLSPH_TRY(dataset_shape(dset, &rows, &nc, "walls3", path));
  IO_REFUSE(nc == 9, "%s: walls3 holds %d numbers a row, not a triangle's 9", path, nc);
  s->surf3 = malloc(rows > 0 ? (size_t)rows * 9 * sizeof *s->surf3 : 1);
  CLSPH_CHECK(s->surf3 != NULL, CLSPH_E_NOMEM, "out of memory reading %s", path);
  s->nsurf3 = (size_t)rows;
  if (rows > 0)
    IO_DAMAGED(H5Dread(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, s->surf3));
done:
  h5_close_id(&dset);
  return st;
}

static enum clsph_status read_render(hid_t file, struct io_snapshot *s, const char *path)
{
  enum clsph_status st = CLSPH_OK;
  hid_t grp = H5I_INVALID_HID;
  char *field = NULL, *map = NULL;
  htri_t exists;
  int found = 0;
  IO_DAMAGED(exists = H5Lexists(file, "render", H5P_DEFAULT));
  if (!exists) goto done;
  IO_DAMAGED(grp = H5Gopen2(file, "render", H5P_DEFAULT));
  CLSPH_TRY(attr_read_str(grp, "field", &field, path));
  CLSPH_TRY(attr_read_str(grp, "colormap", &map, path));
  CLSPH_TRY(attr_read_array(grp, "range", H5T_NATIVE_DOUBLE, 2, s->render.range, &found, path));
  s->render.on = 1;
  s->render.fixed = found;
  double cam[10];
  CLSPH_TRY(attr_read_array(grp, "camera", H5T_NATIVE_DOUBLE, 10, cam, &found, path));
  if (found) {
    s->render.camera = 1;
    memcpy(s->render.eye, cam, 3 * sizeof *cam);
    memcpy(s->render.look_at, cam + 3, 3 * sizeof *cam);
    memcpy(s->render.up, cam + 6, 3 * sizeof *cam);
    s->render.fov = cam[9];
  }
  copy_name(s->render.field, sizeof s->render.field, field);
  copy_name(s->render.colormap, sizeof s->render.colormap, map);
done:
  free(field);
  free(map);
  h5_close_id(&grp);
  return st;
}

enum clsph_status io_snapshot_read(const char *path, const char *const *only,
                                   struct io_snapshot *out)
{
  enum clsph_status st = CLSPH_OK;
  struct io_snapshot s;
  hid_t file = H5I_INVALID_HID, grp = H5I_INVALID_HID, dset = H5I_INVALID_HID;
  char *case_name = NULL, *scheme = NULL;
  uint64_t n64 = 0;
  int64_t step = 0;
  int found_n = 0, found_t = 0, found_s = 0;
  H5G_info_t info;
  memset(&s, 0, sizeof s);
  h5_quiet();

  CLSPH_TRY(open_clsph_file(path, "snapshot", &file));
  CLSPH_TRY(attr_read(file, "n", H5T_NATIVE_UINT64, &n64, &found_n, path));
  CLSPH_TRY(attr_read(file, "time", H5T_NATIVE_DOUBLE, &s.time, &found_t, path));
  CLSPH_TRY(attr_read(file, "step", H5T_NATIVE_INT64, &step, &found_s, path));
  IO_REFUSE(found_n && found_t && found_s, "%s is not a clsph snapshot (no n, time or step)", path);
  s.n = (size_t)n64;
  s.step = (long)step;
  CLSPH_TRY(attr_read_str(file, "case", &case_name, path));
  CLSPH_TRY(attr_read_str(file, "scheme", &scheme, path));
  copy_name(s.case_name, sizeof s.case_name, case_name);
  copy_name(s.scheme, sizeof s.scheme, scheme);
  CLSPH_TRY(attr_read_array(file, "domain", H5T_NATIVE_DOUBLE, 4, s.domain, &s.has_domain, path));
  CLSPH_TRY(
      attr_read_array(file, "domain3", H5T_NATIVE_DOUBLE, 6, s.domain3, &s.has_domain3, path));

  /* the particle datasets */
  htri_t has;
  IO_DAMAGED(has = H5Lexists(file, "particles", H5P_DEFAULT));
  IO_REFUSE(has, "%s is not a clsph snapshot (no /particles)", path);
  IO_DAMAGED(grp = H5Gopen2(file, "particles", H5P_DEFAULT));
  IO_DAMAGED(H5Gget_info(grp, &info));
  IO_REFUSE(info.nlinks <= PSET_MAX_FIELDS, "%s holds %llu particle fields, more than %d", path,
            (unsigned long long)info.nlinks, PSET_MAX_FIELDS);
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    struct io_array *a = &s.arrays[s.narrays];
    ssize_t len;
    IO_DAMAGED(len = H5Lget_name_by_idx(grp, ".", H5_INDEX_NAME, H5_ITER_INC, k, a->name,
                                        sizeof a->name, H5P_DEFAULT));
    IO_REFUSE(len > 0 && (size_t)len < sizeof a->name, "%s: a particle field name is too long",
              path);
    IO_DAMAGED(dset = H5Dopen2(grp, a->name, H5P_DEFAULT));
    hsize_t rows = 0;
    CLSPH_TRY(dataset_shape(dset, &rows, &a->ncomp, a->name, path));
    if (rows != (hsize_t)s.n) {
      char why[160];
      snprintf(why, sizeof why, "field '%s' holds %llu particles, not %zu", a->name,
               (unsigned long long)rows, s.n);
      damaged(path, why);
      st = CLSPH_E_INPUT;
      goto done;
    }
    ++s.narrays;
    if (wanted(only, a->name)) {
      a->v = malloc(s.n > 0 ? s.n * (size_t)a->ncomp * sizeof *a->v : 1);
      CLSPH_CHECK(a->v != NULL, CLSPH_E_NOMEM, "out of memory reading %s", path);
      if (s.n > 0)
        IO_DAMAGED(H5Dread(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, a->v));
    }
    h5_close_id(&dset);
  }
  CLSPH_TRY(read_walls(file, &s, path));
  CLSPH_TRY(read_surf3(file, &s, path));
  CLSPH_TRY(read_render(file, &s, path));
  *out = s;
  memset(&s, 0, sizeof s); /* the caller owns it */
done:
  io_snapshot_free(&s);
  h5_close_id(&dset);
  h5_close_id(&grp);
  h5_close_id(&file);
  free(case_name);
  free(scheme);
  return st;
}

void io_snapshot_free(struct io_snapshot *s)
{
  for (int k = 0; k < s->narrays; ++k) free(s->arrays[k].v);
  for (int w = 0; w < s->nwalls; ++w) free(s->walls[w].pts);
  free(s->walls);
  free(s->surf3);
  memset(s, 0, sizeof *s);
}
