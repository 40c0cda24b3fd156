/* ranks_run.h: `clsph-ranks run`, a whole run split across MPI ranks (ranks_run.c). */
#ifndef CLSPH_RANKS_RUN_H
#define CLSPH_RANKS_RUN_H

#include <mpi.h>

#include "status.h"

struct cJSON;

/** @brief `clsph-ranks run CASE ...` on the ranks of comm (argv[1] is "run"); returns the exit
 *  code: 0, 1 failure, 2 bad command line or a scene the split cannot run. */
int ranks_run(int argc, char **argv, MPI_Comm comm);

/** @brief Write a JSON object to path, indented (clsph-ranks --json). */
enum clsph_status ranks_write_json(const char *path, struct cJSON *j);

#endif /* CLSPH_RANKS_RUN_H */
