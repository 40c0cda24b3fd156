/* kepsilon.h: what the schemes' k-ε models share on the host (the kernels' side is
 * kernels/common/kepsilon.cl): the fields k, epsilon and nu_t, the buffers of the update, and the
 * step's end (the largest ν_t for the time step, the clip counts for summary.json). A laminar
 * scene creates none of it. */
#ifndef CLSPH_KEPSILON_H
#define CLSPH_KEPSILON_H

#include "sim.h"

struct kepsilon {
  int f_k, f_eps, f_nut; /* output fields, m²/s², m²/s³, m²/s */
  cl_mem d_knew, d_enew; /* the step's new k and ε, before they replace the old ones */
  cl_mem d_nut2;         /* ν_t as a vector (ν_t, 0), for the largest (sim_max_norm) */
  cl_mem d_clips;        /* k and ε values clipped so far (two uints, kernels count) */
  cl_uint h_clips[2];    /* their host copy, read with the step's end (kepsilon_step_end) */
  double nut_max;        /* the largest ν_t of the fluid, m²/s (the viscous time step) */
};

/** @brief The fields and buffers: k and ε from fill { k, epsilon } where a fill gives them, else
 *  turbulence { }'s; ν_t = nu_t_start where it is a number (a delayed model's), else C_μ k²/ε. */
enum clsph_status kepsilon_create(struct sim *sim, double nu_t_start, struct kepsilon *ke);
/** @brief At the end of a step whose update filled d_nut2: the largest ν_t and the clip counts
 *  come back with the step's closing read (sim_check_step), without a wait of their own; the
 *  counts are summary.json's (sim->turb_clip_counts). */
enum clsph_status kepsilon_step_end(struct sim *sim, struct kepsilon *ke);
void kepsilon_destroy(struct kepsilon *ke);

#endif /* CLSPH_KEPSILON_H */
