/* loop.h: the time loop of a run: it steps the simulation (host/sim/) and writes its outputs
 * (host/output/). */
#ifndef CLSPH_LOOP_H
#define CLSPH_LOOP_H

#include "case.h"
#include "frames.h"
#include "sim.h"

/** Options of a run from the command line. */
struct loop_options {
  const char *out_dir;              /* output folder (created) */
  const char *restart;              /* checkpoint to continue from, or NULL */
  int overwrite;                    /* clear the outputs of an earlier run in out_dir */
  int quiet;                        /* no progress line */
  const struct frames_opts *frames; /* a frame per snapshot and a movie (frames.h), or NULL */
};

/** @brief Run to the end time, writing the outputs into opt->out_dir (see README). A profile on
 *  the device (--profile) records from the start of the run to its end (the window of sim->wall)
 *  and goes into summary.json. With interrupt_catch (runtime/interrupt.h) in force, a SIGINT or
 *  SIGTERM ends the run after the step it interrupts, with a checkpoint and summary.json
 *  (CLSPH_E_INTERRUPTED). */
enum clsph_status loop_run(struct sim *sim, const struct loop_options *opt,
                           struct case_script *script);

#endif /* CLSPH_LOOP_H */
