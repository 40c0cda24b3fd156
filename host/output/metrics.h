/* metrics.h: the run as a case script's metrics(sim) sees it. */
#ifndef CLSPH_METRICS_H
#define CLSPH_METRICS_H

#include "case.h"
#include "sim.h"

/** @brief The callbacks and figures of the run `sim` for case_metrics; `dir` the output folder. */
void metrics_api(struct sim *sim, const char *dir, struct case_sim_api *api);

#endif /* CLSPH_METRICS_H */
