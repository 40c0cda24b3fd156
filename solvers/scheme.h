/* scheme.h: the one interface every scheme implements. A scheme is one solvers/<name>/ folder
 * (host side) and one kernels/<name>/ folder (device side), listed in solvers/registry.c. */
#ifndef CLSPH_SCHEME_H
#define CLSPH_SCHEME_H

#include "prog.h"

struct sim;

/** Force per unit length of the fluid on a wall group, N/m (Leroy et al. 2014 eq 69):
 *  pressure = Σ_s −p_s n_s S_s and viscous = Σ_s µ (∇u_s + ∇u_sᵀ)·n_s S_s, n_s the segment's
 *  normal into the fluid; the total is their sum. */
struct wall_force {
  double pressure[2];
  double viscous[2];
  double torque; /* moment of the whole force about the group's centre (scene_group_centre),
                  * N m per m of span, counter-clockwise positive */
};

/** Initial fields besides the velocity that a case's fill { } may set (scheme_ops.fill_fields). */
enum { SCHEME_FILL_PRESSURE = 1u, SCHEME_FILL_DENSITY = 2u };

struct scheme_ops {
  const char *name;              /* "isph-usaw" */
  const char *summary;           /* one line with its reference */
  const char *const *sources;    /* kernels after the common ones, NULL-terminated */
  const char *wall_model;        /* what the geometry makes: "usaw", "dummy" or "none" */
  int three_d;                   /* runs 3-D scenes too (its kernels and host path take DIM 3) */
  const char *smoothing;         /* default smoothing function name */
  double h_over_dr;              /* default smoothing length / spacing */
  double support_skin;           /* neighbour lists with a skin: the cells of the neighbour grid
                                  * cover support (1 + support_skin max(cfl, 1)), cfl the scene's
                                  * time-step factor (0: the support) */
  const char *const *options;    /* option names the scheme accepts, NULL-terminated */
  unsigned fill_fields;          /* the initial fields fill { } may give it (SCHEME_FILL_*): the
                                  * scheme's create takes them from geom.p0 and geom.rho0 */
  double open_reserve;           /* particles parked behind the exits, as a fraction of the fluid's
                                  * (struct geom_park): a weakly-compressible scheme's entries take
                                  * them while the fluid is compressed (0: none) */
  const char *const *turbulence; /* the turbulence models (scene turbulence { model }) it has,
                                  * NULL-terminated; NULL: none */
  int sorts_first;               /* 1: its step moves the particles and sorts them before it
                                  * looks for a neighbour, so the loop does not sort before it */
  int checks_domain;             /* 1: its step marks the fluid that left the domain as it moves
                                  * it (domain_left, kernels/common/domain.cl, with the box of
                                  * sim_domain_box), so a step that asks for no step-end maximum
                                  * launches no step_end (host/sim/reduce.c) */
  /** -D switches of the scheme's kernels (NULL: none). */
  enum clsph_status (*define)(const struct sim *sim, struct prog_opts *o);
  /** Add the scheme's particle fields and kernels; called after the common fields exist. */
  enum clsph_status (*create)(struct sim *sim, void **state);
  /** Advance by dt (the particles are sorted by cell and the cell table is current, unless
   *  sorts_first). */
  enum clsph_status (*step)(struct sim *sim, void *state, double dt);
  /** Largest stable time step now, s (before the case's cfl factor). */
  enum clsph_status (*max_dt)(struct sim *sim, void *state, double *dt);
  /** Force of the fluid on the walls of group `group`, N/m (NULL: the scheme computes no wall
   *  forces). */
  enum clsph_status (*wall_force)(struct sim *sim, void *state, const char *group,
                                  struct wall_force *f);
  /** Host-side doubles the scheme carries from one step to the next (NULL: none), as an array
   *  inside its state of *count values: a checkpoint saves them and a restart restores them, so
   *  that a resumed run continues bit for bit. */
  double *(*persist)(void *state, int *count);
  void (*destroy)(void *state);
};

/** @brief The scheme called `name`; an unknown name is reported with `where` (the case's
 *  "file:line", or NULL), the nearest scheme and the list of schemes. */
enum clsph_status scheme_find(const char *name, const char *where, const struct scheme_ops **out);
/** @brief Print the schemes, one line each. */
void scheme_print_list(void);

#endif /* CLSPH_SCHEME_H */
