/* io.h: HDF5 snapshots with an XDMF index for ParaView, and checkpoints (file layouts: io.c).
 * Every file is written under "<path>.tmp" and renamed once complete. */
#ifndef CLSPH_IO_H
#define CLSPH_IO_H

#include "pset.h"
#include "scene.h"

/** What a snapshot or a checkpoint records besides the particle fields. */
struct io_meta {
  const char *case_name;            /* scene name */
  const char *case_path;            /* the script */
  const char *scheme;               /* scheme name */
  const char *precision;            /* "double" or "float" */
  const char *version;              /* clsph version */
  double time;                      /* simulated time, s */
  long step;                        /* time step count */
  double dt;                        /* last time step, s */
  int dim;                          /* 2 or 3 */
  const struct scene_param *params; /* the case parameters, as run */
  int nparams;
};

/** The snapshots written so far, for the XDMF index. */
struct io_series {
  int count, cap;
  char **files;  /* snapshot file names, relative to the output folder */
  double *times; /* s */
  size_t *n;     /* particles in each */
};

/** @brief Write every output field of `ps` (read back from the device) to an HDF5 file: one
 *  dataset per field in /particles, shape (n) or (n, nout), padding components dropped; the meta
 *  data as root attributes and the parameters in /parameters.
 *  @return CLSPH_E_IO when a file operation fails (logged with the call and the path). */
enum clsph_status io_snapshot_write(const char *path, const struct dev *dev, const struct pset *ps,
                                    const struct io_meta *m);
/** @brief Add a snapshot to the series (a zeroed struct is an empty series).
 *  @param file the snapshot's name relative to the folder of the XDMF file (copied) */
enum clsph_status io_series_add(struct io_series *s, const char *file, double time, size_t n);
/** @brief Free the series and zero it. */
void io_series_free(struct io_series *s);
/** @brief Write the XDMF 3 index of the series (fields as in `ps`, which must have an output
 *  field "pos" of `dim` reals): a temporal collection of one Polyvertex grid per snapshot. */
enum clsph_status io_xdmf_write(const char *path, const struct io_series *s, const struct pset *ps,
                                int dim);
/** @brief Write a checkpoint: every field of `ps`, all bytes, plus meta and an opaque blob
 *  (`blob_bytes` 0: none). */
enum clsph_status io_checkpoint_write(const char *path, const struct dev *dev,
                                      const struct pset *ps, const struct io_meta *m,
                                      const void *blob, size_t blob_bytes);
/** @brief Read a checkpoint into `ps` (whose fields, by name and size, must match). Refuses, with
 *  the reason, a file that is not a clsph checkpoint, is truncated, or comes from another case
 *  (`expect->case_name`; NULL: any) or precision (`expect->precision`; NULL: this build's), has
 *  more particles than `ps->cap`, or lacks a field of `ps` or stores it with another element
 *  type or size. A refusal is CLSPH_E_INPUT with one message, and leaves `ps` untouched. On
 *  success `ps->n` and every field on the device are those of the checkpoint.
 *  @param m    receives time, step and dt (strings in it are not touched)
 *  @param blob receives a malloc'd copy of the blob (NULL when empty) */
enum clsph_status io_checkpoint_read(const char *path, const struct dev *dev, struct pset *ps,
                                     const struct io_meta *expect, struct io_meta *m, void **blob,
                                     size_t *blob_bytes);

#endif /* CLSPH_IO_H */
