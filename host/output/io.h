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
  /* snapshots only (what frames need besides the particles; NULL or 0: not written) */
  int has_domain;                 /* write the domain */
  double domain[4];               /* the scene's box x0, y0, x1, y1, m */
  int has_domain3;                /* 3-D: write domain3 too */
  double domain3[6];              /* the box x0, y0, z0, x1, y1, z1, m */
  const struct scene_wall *walls; /* the wall polylines */
  int nwalls;
  const double *surf3; /* 3-D: the walls' faces, nsurf3 triangles x 9 coordinates (m),
                        * counter-clockwise seen from the fluid (scene_surfaces3) */
  size_t nsurf3;
  const struct scene_render *render; /* the case's render { } choices */
  /* checkpoints only */
  unsigned long digest; /* geometry_digest of the scene (0: not recorded) */
  int nstats;           /* figures of the whole run so far (summary.json's worst and
                         * total values), by name: written from `stats`; a read fills
                         * `stats` of its `expect` with the ones the checkpoint has and
                         * counts them in the stats_read of its `m` */
  const char *const *stat_names;
  double *stats;
  int stats_read;
};

/** A particle dataset of a snapshot read as doubles (io_snapshot_read). */
struct io_array {
  char name[32];
  int ncomp; /* 1, or the second dimension */
  double *v; /* n x ncomp, or NULL when not read */
};

/** A wall polyline of a snapshot (the fluid on its left). */
struct io_wall {
  int npts;
  double *pts; /* npts x 2, m */
  int closed;
};

/** A snapshot read back for frames. */
struct io_snapshot {
  double time; /* s */
  long step;
  char case_name[64], scheme[64];
  size_t n; /* particles */
  int narrays;
  struct io_array arrays[PSET_MAX_FIELDS]; /* every dataset of /particles, by name */
  int has_domain;
  double domain[4];  /* x0, y0, x1, y1, m */
  int has_domain3;   /* a 3-D snapshot's box (0: 2-D, or written before it was recorded) */
  double domain3[6]; /* x0, y0, z0, x1, y1, z1, m */
  int nwalls;        /* 0 also when the snapshot predates /walls */
  struct io_wall *walls;
  size_t nsurf3; /* 3-D: the walls' faces (0 also when the snapshot predates /walls3) */
  double *surf3; /* nsurf3 x 9, m, counter-clockwise seen from the fluid */
  struct scene_render render; /* the case's render { } (render.on = 0: none recorded) */
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
 *  data as root attributes and the parameters in /parameters; the domain, the walls (/walls) and
 *  the case's render choices (/render) when `m` has them.
 *  @return CLSPH_E_IO when a file operation fails (logged with the call and the path). */
enum clsph_status io_snapshot_write(const char *path, const struct dev *dev, const struct pset *ps,
                                    const struct io_meta *m);
/** @brief Read a snapshot back: its time, step, case and scheme names, the names and components
 *  of every particle dataset, the data (as doubles) of those named in `only` (NULL-terminated;
 *  NULL: all), the domain, the walls and the render choices. A file that is not a snapshot, or is
 *  damaged, is refused with the reason (CLSPH_E_INPUT). Free it with io_snapshot_free. */
enum clsph_status io_snapshot_read(const char *path, const char *const *only,
                                   struct io_snapshot *out);
/** @brief Free a snapshot read back, and zero it. */
void io_snapshot_free(struct io_snapshot *s);
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
 *  the reason, a file that is not a clsph checkpoint, is truncated, or fails a checksum (each
 *  dataset's CRC-32, and one over time, step, dt, n and the digest), comes from another case
 *  (`expect->case_name`; NULL: any), another scene (a parameter of `expect->params` other than
 *  t_end differs, is missing or is extra, naming it; then `expect->digest`, when not 0; params
 *  NULL: not compared) or
 *  precision (`expect->precision`; NULL: this build's), has more particles than `ps->cap`, or
 *  lacks a field of `ps` or stores it with another element type or size. A refusal is
 *  CLSPH_E_INPUT with one message, and leaves `ps` untouched. On success `ps->n` and every field
 *  on the device are those of the checkpoint. A checkpoint of an older clsph without checksums,
 *  digest or statistics is accepted with a warning.
 *  @param m    receives time, step, dt and stats_read (nothing else in it is touched)
 *  @param blob receives a malloc'd copy of the blob (NULL when empty) */
enum clsph_status io_checkpoint_read(const char *path, const struct dev *dev, struct pset *ps,
                                     const struct io_meta *expect, struct io_meta *m, void **blob,
                                     size_t *blob_bytes);

#endif /* CLSPH_IO_H */
