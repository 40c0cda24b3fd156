/* progress.h: the progress line of a run. */
#ifndef CLSPH_PROGRESS_H
#define CLSPH_PROGRESS_H

#include "sim.h"

struct progress {
  int tty, quiet;
  double start, last; /* s (progress_now) */
};

/** @brief Monotonic wall-clock time, s. */
double progress_now(void);
/** @brief The progress line now (at most every 0.2 s on a terminal, 5 s otherwise; always when
 *  `final`). */
void progress_show(const struct sim *sim, struct progress *pr, int final);

#endif /* CLSPH_PROGRESS_H */
