/* summary.h: summary.json of a run. */
#ifndef CLSPH_SUMMARY_H
#define CLSPH_SUMMARY_H

#include "case.h"
#include "out.h"
#include "sim.h"

/** @brief Write summary.json (see README); the case's metrics run when the run ended well, and a
 *  failing metrics() turns the status into "metrics failed". */
enum clsph_status summary_write(struct sim *sim, const struct run_out *o, double wall,
                                struct case_script *script);

#endif /* CLSPH_SUMMARY_H */
