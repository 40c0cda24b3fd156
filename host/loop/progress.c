/* progress.c: the progress line of a run on stderr (a bar on a terminal, a line every 5 s
 * otherwise). */
#include "progress.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "scene.h"

double progress_now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void progress_show(const struct sim *sim, struct progress *pr, int final)
{
  double t = progress_now();
  if (pr->quiet || (!final && t - pr->last < (pr->tty ? 0.2 : 5.0))) return;
  pr->last = t;
  double frac = sim->scene->t_end > 0.0 ? sim->time / sim->scene->t_end : 1.0;
  double el = t - pr->start, rate = el > 0.0 ? (double)sim->step / el : 0.0;
  double eta = frac > 0.0 ? el * (1.0 - frac) / frac : 0.0;
  char solver[128] = "";
  if (sim->substeps > 0) /* dual-criteria time stepping: the acoustic sub-steps of the last step */
    snprintf(solver, sizeof solver, "  %ld acoustic sub-steps", sim->substeps);
  if (sim->solver_steps > 0)
    snprintf(solver + strlen(solver), sizeof solver - strlen(solver), "  solver %ld its (res %.1e)",
             sim->solver_its, sim->solver_res);
  if (sim->aux_its_sum > 0)
    snprintf(solver + strlen(solver), sizeof solver - strlen(solver), ", viscous %ld its",
             sim->aux_its);
  if (pr->tty) {
    char bar[21];
    int fill = (int)(20.0 * fmin(frac, 1.0));
    for (int i = 0; i < 20; ++i) bar[i] = i < fill ? '=' : ' ';
    bar[20] = '\0';
    fprintf(stderr, "\r[%s] t %.4g/%.4g s  step %ld  %.1f steps/s%s  ETA %.0f s   ", bar, sim->time,
            sim->scene->t_end, sim->step, rate, solver, eta);
    if (final) fputc('\n', stderr);
  } else {
    fprintf(stderr, "t %.6g/%.6g s (%.0f%%)  step %ld  %.1f steps/s%s  ETA %.0f s\n", sim->time,
            sim->scene->t_end, 100.0 * frac, sim->step, rate, solver, eta);
  }
}
