/* checkpoint.h: checkpoints and restarts. */
#ifndef CLSPH_CHECKPOINT_H
#define CLSPH_CHECKPOINT_H

#include "out.h"
#include "sim.h"

/** @brief Write checkpoint_<step>.h5 of the state now. */
enum clsph_status checkpoint_write(struct sim *sim, struct run_out *o);
/** @brief Continue from a checkpoint: the fields, time, step and host state it carries;
 *  o->nsnap becomes the number of the next snapshot. */
enum clsph_status checkpoint_restore(struct sim *sim, const char *path, struct run_out *o);

#endif /* CLSPH_CHECKPOINT_H */
