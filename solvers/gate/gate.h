/* gate.h: a wall group lifted at a prescribed speed (the Lobovsky et al. dam break's gate, S sec
 * 4.2: 4.53 m/s): scheme options gate = "<wall group>", gate_speed (m/s), gate_start and gate_stop
 * (s); the group's dummies translate against gravity (+y without it) while gate_start <= t <
 * gate_stop and carry that velocity as their wall velocity. Shared by the dummy-wall schemes
 * (isph-stabilized, wcsph-riemann); a scene without a gate builds nothing of it.
 *   define:  nothing (GATE_SOURCES among the scheme's sources)
 *   create:  gate_read (the options, checked), gate_create (the per-particle flag, the kernel),
 *            gate_check (the lifted dummies stay inside the domain)
 *   step:    gate_move over each interval the dummies must follow */
#ifndef CLSPH_GATE_H
#define CLSPH_GATE_H

#include "sim.h"

#define GATE_SOURCES "common/gate.cl"

struct gate {
  int on;                 /* the scene has a gate */
  char group[SCENE_NAME]; /* its wall group */
  double speed, start, stop, dir[3];
  double v_prev[3]; /* its velocity over the last interval (a checkpoint keeps it) */
  int f_gate;       /* the per-particle flag (1: a dummy of the gate), −1 without a gate */
  cl_kernel k_move;
};

/** @brief The gate options of `scheme` (its name heads the messages); g->on = 0 without them. */
enum clsph_status gate_read(const struct scene *sc, const char *scheme, struct gate *g);
/** @brief The flag field "gate" and the kernel (after the scheme's program is built). */
enum clsph_status gate_create(struct sim *sim, struct gate *g);
/** @brief The gate's dummies stay inside the neighbour grid after the whole lift. */
enum clsph_status gate_check(const struct sim *sim, const struct gate *g, const char *scheme);
/** @brief The gate over [t, t + dt]: its velocity v (the lift's overlap with [start, stop] over
 *  dt, exact, so that it stops where it should) and, when it moves or changes, its dummies moved
 *  by v dt with wall velocity v (wall_vel: the scheme's array of the walls' velocities). */
enum clsph_status gate_move(struct sim *sim, struct gate *g, double t, double dt, cl_mem wall_vel,
                            double v[3]);
/** @brief Its speed when it moves at some time of [t0, t1], else 0 (time steps, list skins). */
double gate_speed_at(const struct gate *g, double t0, double t1);
void gate_destroy(struct gate *g);

#endif
