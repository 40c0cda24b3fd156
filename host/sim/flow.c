/* flow.c: the flow-rate control of a periodic channel's body force (Leroy et al. 2014 eqs 67-68).
 */
#include <stdio.h>

#include "sim.h"

/* Flow-rate control, before a step of length δt (Leroy et al. 2014 eq 67, from Morris, Fox &
 * Zhu 1997):
 *   F^n = F^{n−1} + (⟨v⟩ − 2ṽ^{n−1} + ṽ^{n−2})/δt,
 * ṽ (eq 68) the mean x velocity of the fluid particles in the slice; before the first step
 * ṽ^{n−2} = ṽ^{n−1}. The controller needs steps of (nearly) constant length: a short step cut
 * to land on an output time made it unstable (cylinder array, n = 20: steps of 0.08 s with one
 * of 0.01 s every 0.25 s gave a period-4 oscillation of F growing 25% a cycle), which is why
 * the time loop lands on outputs in equal steps. One line per step goes to flow_control.csv. */
enum clsph_status sim_flow_control(struct sim *sim, double dt, FILE *log)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene_flow_control *c = &sim->scene->flow;
  struct sim_flow *f = &sim->flow;
  double v = 0.0, count = 0.0;
  CLSPH_TRY(sim_slice_velocity(sim, c->slice[0], c->slice[1], &v, &count));
  if (!(count > 0.0)) {
    snprintf(sim->status, sizeof sim->status,
             "flow-rate control: no fluid particle in the slice [%g, %g) at step %ld, t = %.9g s",
             c->slice[0], c->slice[1], sim->step, sim->time);
    log_error("%s:%d: %s", sim->scene->case_path, c->line, sim->status);
    snprintf(sim->failure, sizeof sim->failure, "flow_control");
    st = sim->step == 0 ? CLSPH_E_INPUT : CLSPH_E_BLOWUP;
    goto done;
  }
  if (f->primed == 0.0) f->v1 = v; /* ṽ^{n−2} = ṽ^{n−1} at the first step */
  f->v2 = f->v1;
  f->v1 = v;
  f->force += (c->velocity - 2.0 * f->v1 + f->v2) / dt;
  f->primed = 1.0;
  sim->body_force[0] = f->force;
  if (log != NULL)
    fprintf(log, "%.17g,%.9g,%.9g,%.9g,%.0f\n", sim->time, dt, f->force, f->v1, count);
done:
  return st;
}
