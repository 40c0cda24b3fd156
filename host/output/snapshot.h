/* snapshot.h: snapshots (HDF5 + XDMF) and the frames drawn with them. */
#ifndef CLSPH_SNAPSHOT_H
#define CLSPH_SNAPSHOT_H

#include "frames.h"
#include "out.h"
#include "sim.h"

/** @brief The fields a frame can show: the output fields, by name and components; returns how
 *  many. */
int snapshot_frame_fields(const struct sim *sim, const char **names, int *ncomp);
/** @brief Frames: resolve the field against the run's output fields, open the renderer, and list
 *  the arrays a frame reads from the device. */
enum clsph_status snapshot_open_frames(struct sim *sim, const struct frames_opts *opts,
                                       const char *out_dir, struct run_out *o);
/** @brief What a snapshot or a checkpoint records besides the fields, for the state now. */
void snapshot_meta(const struct sim *sim, struct io_meta *m);
/** @brief Write snapshot number o->nsnap, its line in the XDMF index, its frame (--frames) and
 *  the series that go with it. */
enum clsph_status snapshot_write(struct sim *sim, struct run_out *o);
/** @brief The state at a blow-up, in blowup.h5 (the fields of a snapshot, in no index). */
enum clsph_status snapshot_write_blowup(struct sim *sim, struct run_out *o);

/** @brief A run continued from the checkpoint `restart`: the snapshots before it (numbers
 *  0 .. o->nsnap − 1 in the checkpoint's folder) go into the index first, so that
 *  snapshots.xdmf lists the whole run (by name in the same folder, else by their whole path). */
enum clsph_status snapshot_resume_index(struct run_out *o, const char *restart);

#endif /* CLSPH_SNAPSHOT_H */
