/* sim.h: a simulation: the scene's particles on the device, the scheme, the reductions over them
 * and the blow-up checks. The time loop that drives it is host/loop/loop.h; what it writes is
 * host/output/. */
#ifndef CLSPH_SIM_H
#define CLSPH_SIM_H

#include "geometry.h"
#include "ops.h"
#include "pset.h"
#include "scene.h"
#include "smoothing.h"

#include <limits.h>
#include <stdio.h>

/** Maxima one step may leave for the step-end read (sim_max_norm_deferred, and the speed). */
#define SIM_DEFERRED 4
/** Work-groups of a reduction at most (sim_reduce_groups). */
#define SIM_REDUCE_MAX_GROUPS 64
#define SIM_KIND_UNSET        INT_MIN

struct scheme_ops;

/** A run split across ranks (host/bench/ranks_run.c): the reduction over the ranks of a maximum
 *  each rank has taken over its particles (ctx: the caller's). */
struct sim_comm {
  void *ctx;
  enum clsph_status (*max)(void *ctx, double *v);
};

/** Flow-rate control (eqs 67-68): the state a checkpoint carries (doubles only, in this order). */
struct sim_flow {
  double force;  /* F^{n−1}: the x body force of the last step, m/s² */
  double v1, v2; /* ṽ^{n−1}, ṽ^{n−2}: slice velocities before the last two steps, m/s */
  double primed; /* 0 before the first step (ṽ^{n−2} unknown), 1 after */
};

/** Values per wall group in a row of sim->force_rows. */
#define SIM_FORCE_COLS 5

struct sim {
  const struct dev *dev;
  const struct scene *scene;
  const struct scheme_ops *scheme;
  void *state;                 /* the scheme's */
  const struct sim_comm *comm; /* a run split across ranks: sim_max_speed and sim_max_norm take
                                * the largest over every rank's (NULL: one device) */
  struct geom_park park;       /* the particles parked behind the exits (geometry_build) */
  struct geom geom;            /* host copy of the generated particles and wall segments */
  struct smoothing sm;
  struct grid_spec gspec;
  struct grid grid;
  cl_program prog; /* common kernels + the scheme's */
  struct pset ps;
  int f_pos, f_vel, f_kind, f_id, f_vol; /* fields every scheme has (indices in ps) */
  cl_mem d_flags;        /* error bits raised by kernels (kernels/common/flags.h), then a counter */
  cl_kernel k_probe;     /* interpolation at arbitrary points */
  cl_kernel k_max_speed; /* reduction */
  cl_mem d_partial;      /* per-work-group partial results of reductions */
  /* maxima read with the flags at the end of the step (sim_check_step), so that the host waits
   * once there: the largest speed the next max_dt asks for, and sim_max_norm_deferred's */
  cl_mem d_deferred; /* SIM_DEFERRED slots of SIM_REDUCE_MAX_GROUPS partials */
  real *h_deferred;
  double *deferred_to[SIM_DEFERRED];    /* where each launched slot's maximum goes */
  size_t deferred_groups[SIM_DEFERRED]; /* and how many partials it has */
  int ndeferred;                        /* slots launched this step */
  struct sim_lazy {                     /* sim_max_field_deferred: launched at the step's end */
    int field, kind;
    double *dest;
  } lazy[SIM_DEFERRED];
  int nlazy;
  int speed_kind;  /* the kind sim_max_speed was last asked for (SIM_KIND_UNSET: never) */
  int speed_ready; /* 1: speed is the step-end value for the next sim_max_speed(speed_kind) */
  double speed;
  cl_kernel k_count;    /* reduction: nonzero entries of a uint field */
  cl_kernel k_step_end; /* the domain check and the step-end maxima (domain.c) */
  cl_mem d_inv;         /* current index of each original particle index (after sim_sort:
                         * grid_sort_inv) */
  double body_force[3]; /* body force now, m/s²: the scene's, x under flow-rate control */
  /* a wall group translated at a constant speed over [start, stop) (a gate: solvers/gate sets
   * it), so that the outputs draw its walls where they stand (sim_moved_offset); group NULL:
   * none */
  struct sim_moved {
    const char *group;
    double dir[3], speed, start, stop;
  } moved;
  struct sim_flow flow; /* flow-rate control state (scene->flow.on) */
  cl_kernel k_slice;    /* reduction: x velocity and count of the fluid in the control slice */
  double time, dt;      /* simulated time and last step, s */
  /* what the case's sample(sim) returned at each sample (series.csv), a restart's rows too:
   * ncols named values per row after the time */
  struct sim_samples {
    int ncols;
    char (*names)[SCENE_NAME];
    double *rows; /* nrows x (1 + ncols) */
    size_t nrows, cap;
  } samples;
  double *force_rows; /* wall forces at each output: time, then per group of scene->forces
                       * SIM_FORCE_COLS values: pressure x, y and viscous x, y (N/m), and the
                       * torque (N m/m, struct wall_force) */
  size_t nforce_rows, force_rows_cap;
  long step;
  long step0;        /* the step this run started from (a restart's checkpoint; 0 otherwise) */
  long solver_its;   /* the pressure solver's iterations of the last step (schemes set) */
  double solver_res; /* and its final relative residual */
  long solver_its_sum, solver_its_max, solver_steps;
  long aux_its; /* a second solve's iterations of the last step (isph-rotational's
                 * implicit viscous prediction, both components), 0: none */
  long aux_its_sum;
  /* dual-criteria time stepping (wcsph-riemann): the acoustic sub-steps of the last step (0: the
   * scheme has none) and their sum over this run */
  unsigned long sorts; /* sorts so far (sim_sort): per-particle buffers outside the particle set,
                        * which a sort does not reorder, belong to the order they were made in */
  long substeps, substeps_sum;
  /* k and ε values clipped by the turbulence model so far (summary.json): the scheme's host copy,
   * which each step's closing read brings up to date (solvers/kepsilon); NULL: no model */
  const cl_uint *turb_clip_counts;
  /* pair interactions the scheme evaluated in the last step (0: it does not count them) and their
   * sum over this run: a pair loop over n particles with on average k neighbours inside the
   * support counts n k */
  double pairs, pairs_sum;
  /* entry layer particles left waiting for a recycled exit particle (the entry and exit sections
   * of solvers/open) at the last step, and the most at one step over this run; −1: no entry */
  long open_waiting, open_waiting_max;
  const char *failed_solve; /* the solve whose failure stops a run (schemes set it when it is
                             * not the pressure's; NULL: "pressure") */
  /* fluid particles found behind a wall (CLSPH_FLAG_WALL): steps with any, most at one step, and
   * the first such step (−1: none) and its time; over this run (since its start or restart) */
  long wall_steps, wall_most, wall_first_step;
  double wall_first_time;
  double wall_depth_max; /* the deepest of those crossings, in units of dr */
  /* fluid particles that left the domain (domain.cl) and were dropped from the run, over the
   * whole run (a restart's included), the first step that lost one (−1: none) and its time */
  long escaped, escaped_first_step;
  double escaped_first_time;
  cl_kernel k_health; /* reduction: kinetic energy, volume and spacing of the fluid */
  cl_mem d_health;    /* its per-work-group results */
  double u_ref;       /* the scene's velocity scale of the energy check, m/s (0: no check) */
  /* health checks of this run (sim_check_step), the whole-run state a restart continues:
   * health_checks     checks done;
   * energy_ratio_max  the largest kinetic energy of the fluid over ½ M U² (U = u_ref);
   * spacing_min       the smallest nearest-fluid-neighbour distance over dr (HUGE_VAL: none yet);
   * cluster_max       the largest fraction of the fluid closer than checks.cluster_h h to
   *                   another fluid particle (the clustered fraction) */
  long health_checks;
  double energy_ratio_max, spacing_min, cluster_max;
  double wall;          /* wall-clock time of this run so far (summary.json wall_seconds), s */
  double wall_before;   /* of the run before its checkpoint (a restart's), s */
  double out_wall;      /* of wall: the outputs (the first snapshot, snapshots, series with the
                         * case's sample(), checkpoints), each timed from an idle device, s */
  unsigned long digest; /* geometry_digest of the scene: checkpoints record it */
  double mem_estimate;  /* device memory the run needs, estimated at set-up, bytes */
  /* every probe's value of one field in one state (metrics.c's sim.probe: the sensors a case's
   * sample() reads one by one cost one launch and one read together); valid while v != NULL and
   * field, step, sorts and time are the run's */
  struct sim_probe_cache {
    int field;
    long step;
    unsigned long sorts;
    double time;
    double *v; /* nprobes x the field's components */
  } probe_cache;
  char status[1024]; /* "ok" or why the run stopped */
  char failure[32];  /* "none", or the class of the failure (summary.json "failure"): "nan",
                      * "escaped", "neighbours", "wall_crossing", "solver", "clustering",
                      * "energy", "dt_collapse", "dt_bound", "flow_control", "metrics",
                      * "interrupted", "error" */
};

/** @brief Set up a simulation of a scene: geometry, program, fields, scheme. Nothing is written. */
enum clsph_status sim_create(const struct dev *dev, const struct scene *scene, struct sim *out);
/** @brief Print particle counts, active modules, memory per particle and the first time step. */
enum clsph_status sim_info(struct sim *sim);
/** @brief Sort the particles by cell and reorder every field (before each step). */
enum clsph_status sim_sort(struct sim *sim);
/** @brief The checks at a step's end, with one wait: the domain check and the step-end maxima
 *  (sim_deferred_enqueue), the health checks when `health`, then the error flags. A raised flag
 *  ends the run with a reason in sim->status and its class in sim->failure, except
 *  CLSPH_FLAG_WALL (a fluid particle behind a wall), which is counted and cleared, and ends the
 *  run only when the particle is more than the scene's checks.wall_depth dr behind the wall.
 *  Fluid that left the domain (sim_step_end) is counted and dropped: sorted past the other
 *  particles, which then number fewer (sim->ps.n); the run ends when more than checks.escaped of
 *  the fluid has left. The health checks (scene checks): particle clustering, the fraction of the
 *  fluid whose nearest fluid neighbour is closer than checks.cluster_h h (h the smoothing
 *  length), above checks.cluster_fraction; and energy growth, the kinetic energy of the fluid
 *  above checks.energy times ½ M U² (M its mass, U = sim->u_ref). A failed check ends the run
 *  (CLSPH_E_BLOWUP) with the reason in sim->status and sim->failure. */
enum clsph_status sim_check_step(struct sim *sim, int health);
/** @brief Record a failed check: its class into sim->failure (the reason is already in
 *  sim->status), logged once; returns CLSPH_E_BLOWUP. */
enum clsph_status sim_fail(struct sim *sim, const char *failure);
/** @brief Flow-rate control (Leroy et al. 2014 eqs 67-68): set the x body force for a step of
 *  length dt from the slice velocity; one row to `log` (flow_control.csv) when not NULL. */
enum clsph_status sim_flow_control(struct sim *sim, double dt, FILE *log);
/** @brief (sim_deferred_enqueue) One launch at the step's end: mark and count (for
 *  sim_check_step) the fluid particles more than dr beyond the domain's box on a non-periodic axis,
 *  but for the side gravity points away from; then the largest norm of nvec (0 to 2) vectors, each
 *  over the particles of its kind (−1: all) as the check leaves them, into d_deferred from
 *  slot[v] on. */
enum clsph_status sim_step_end(struct sim *sim, int nvec, const cl_mem *vec, const int *kinds,
                               const size_t *slot);
/** @brief The domain check's box (sim_step_end, domain.cl's domain_left): lower and upper
 *  corners, the margin (dr) and the open sides' bits, for a scheme that checks as it moves
 *  (scheme_ops.checks_domain). */
void sim_domain_box(const struct sim *sim, real4 *lo, real4 *hi, real *margin, cl_uint *open);
/** @brief The sides gravity points away from (more than half of it along the axis), open to
 *  splashes: 1 per axis for its lower and upper side; 0 for periodic and absent axes. */
void sim_open_sides(const struct scene *s, int open_lo[3], int open_hi[3]);
/** @brief Work-groups of 64 of a reduction over n particles: at most 64, so a few dozen partial
 *  results come back to the host per reduction (reduce.cl). */
size_t sim_reduce_groups(size_t n);
/** @brief Largest speed over the particles of one kind (−1: all), reduced on the device. */
enum clsph_status sim_max_speed(struct sim *sim, int kind, double *vmax);
/** @brief How far the moved wall group (sim.moved) stands from its place at t = 0 at time t, m
 *  (0 without one). */
void sim_moved_offset(const struct sim *sim, double t, double d[3]);
/** @brief Largest norm of a vector field (2 reals per particle) over one kind (−1: all). */
enum clsph_status sim_max_norm(struct sim *sim, cl_mem d_vec, int kind, double *vmax);
/** @brief The same maximum without waiting for it: *dest receives it at the step's end, when
 *  sim_check_step reads it with the flags (dest must outlive the step). */
enum clsph_status sim_max_norm_deferred(struct sim *sim, cl_mem d_vec, int kind, double *dest);
/** @brief The largest norm of a particle field (a vector) at the step's end, in the launch of the
 *  domain check (sim_step_end): the field as it stands then, reordered by the step's sorts, into
 *  *dest (which must outlive the step) with the flags' read. */
enum clsph_status sim_max_field_deferred(struct sim *sim, int field, int kind, double *dest);
/** @brief sim_count without waiting: part (SIM_REDUCE_MAX_GROUPS reals) receives `groups` partial
 *  counts to add up once a later blocking transfer has returned. */
enum clsph_status sim_count_queued(struct sim *sim, cl_mem d_field, real *part, size_t *groups);
/** @brief (sim_check_step) Launch the domain check with the step-end speed and fields' maxima
 *  (sim_step_end) and queue the read of every deferred maximum. */
enum clsph_status sim_deferred_enqueue(struct sim *sim);
/** @brief (sim_check_step, after a blocking read) Hand each deferred maximum to its place. */
void sim_deferred_finish(struct sim *sim);
/** @brief Mean x velocity and count of the fluid particles with x0 <= x < x1 (modulo the period
 *  on a periodic x axis), reduced on the device. */
enum clsph_status sim_slice_velocity(struct sim *sim, double x0, double x1, double *mean,
                                     double *count);
/** @brief Number of nonzero entries of a uint field, reduced on the device. */
enum clsph_status sim_count(struct sim *sim, cl_mem d_field, double *count);
/** @brief Interpolate a real field at np points (host array of dim doubles per point); `out` gets
 *  ncomp values per point. order 0: Shepard; 1: first-order moving least squares, exact for a
 *  linear field (kernels/common/probe.cl). */
enum clsph_status sim_sample(struct sim *sim, int field, int order, size_t np, const double *at,
                             double *out);
/** @brief A real field at np probes (struct scene_probe): at a point probe, its interpolated value;
 *  at a face, the mean over its points (scene_probe_points: a segment's npts midpoints, a disc's
 *  lattice) of the points with
 *  fluid within the support (NaN, the interpolation's value where there is none, only when the
 *  whole face is dry). `out` gets ncomp values per probe. */
enum clsph_status sim_sample_probes(struct sim *sim, int field, int np,
                                    const struct scene_probe *probes, double *out);
struct psolve_options;
/** @brief The pressure-solver options a case sets through its scheme options (`solver =
 *  "direct"`, `solver_rtol = 1e-6`, ...), over the defaults. */
enum clsph_status sim_psolve_options(const struct sim *sim, struct psolve_options *o);
/** @brief Release everything. */
void sim_destroy(struct sim *sim);

#endif /* CLSPH_SIM_H */
