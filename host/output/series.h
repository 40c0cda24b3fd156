/* series.h: the CSV series of a run (probes, profiles, forces, flow-rate control). */
#ifndef CLSPH_SERIES_H
#define CLSPH_SERIES_H

#include "out.h"
#include "sim.h"

/** What series_write writes: the time series (probes.csv, forces.csv), the profiles, or both. */
enum { SERIES_TIME = 1, SERIES_PROFILES = 2 };

/** @brief Open the CSV series of the run. On a restart (restart: the checkpoint's path), each
 *  goes on from the rows the restarted run wrote up to the checkpoint's time, so that it reads as
 *  one run. */
enum clsph_status series_open(struct sim *sim, struct run_out *o, const char *restart);
/** @brief One row of the time series, the profiles, or both (`what`: SERIES_*) at the time now. */
enum clsph_status series_write(struct sim *sim, struct run_out *o, int what);

#endif /* CLSPH_SERIES_H */
