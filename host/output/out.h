/* out.h: the output folder of a run and the files open in it while the time loop runs (the CSV
 * series, the snapshot index, the frames); each kind of output has its own file beside this one:
 * series.c, snapshot.c, checkpoint.c, summary.c. */
#ifndef CLSPH_OUT_H
#define CLSPH_OUT_H

#include <stdio.h>

#include "case.h"
#include "frames.h"
#include "io.h"
#include "scene.h"

struct run_out {
  char *dir; /* the output folder (malloc'd) */
  struct io_series series;
  struct case_script *script; /* the case: its sample(sim) writes series.csv (NULL: none) */
  FILE *probes, *forces, *flow, *samples;
  struct case_values values; /* the last values of sample(sim) */
  FILE **profiles;
  int nsnap;
  long checkpoint_step; /* the step of the last checkpoint written (−1: none yet) */
  /* per force group, over the samples written: the largest |F| (time, fx, fy) and the last F */
  struct force_stat {
    double peak, peak_time, peak_f[2], last[2];
  } * force_stats;
  double *force_scratch; /* one row of the force history */
  /* frames (--frames): the renderer, the walls as it reads them, the region shown, and a host
   * copy of the arrays a frame reads (pos, vol, kind and the field's) */
  struct frames *frames;
  struct render_wall *walls;
  /* the walls where they stand at the snapshot's time when some turn (scene_wall_turns) or are
   * lifted (a gate, sim.moved): a copy of the scene's with the points moved (NULL when none
   * moves) */
  struct scene_wall *turned;
  double *turned_pts;
  double *surf3; /* 3-D: the walls' faces where they stand (scene_surfaces3), nsurf3 triangles */
  size_t nsurf3;
  double view[4];
  double *frame_arrays[4];
  struct render_array frame_in[4];
  int nframe_arrays;
};

/** @brief `dir/name` into a malloc'd *path (the caller frees it). */
enum clsph_status out_path(const struct run_out *o, const char *name, char **path);
/** @brief May a run write into `dir`? Yes when it holds no outputs of a run; with `overwrite`,
 *  after removing them (refused when they hold the checkpoint `restart` continues from); when
 *  `restart` (NULL: none) is a checkpoint in that folder, the run continues it there (*here
 *  = 1; out_drop_after then removes what came after it). Otherwise refused, saying what to do. */
enum clsph_status out_claim_dir(const char *dir, const char *restart, int overwrite, int *here);
/** @brief A run continued in its own folder: remove the snapshots numbered from nsnap on, the
 *  checkpoints after step `step`, their frames, the movies and unfinished files (they belong to
 *  the abandoned continuation; the CSV series drop their rows by themselves, series.c). */
enum clsph_status out_drop_after(const char *dir, long nsnap, long step);
/** @brief Create the folder (and its parents) and prove it can be written, before anything runs. */
enum clsph_status out_prepare_dir(const char *dir);
/** @brief Close every file and free what the run's outputs hold. */
void out_close(const struct scene *s, struct run_out *o);

#endif /* CLSPH_OUT_H */
