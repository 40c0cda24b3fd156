/* case.h: case scripts (cases/NAME.lua) run in a Lua 5.4 sandbox and turned into a scene. */
#ifndef CLSPH_CASE_H
#define CLSPH_CASE_H

#include "scene.h"
#include "status.h"

struct case_script;
struct cJSON;

/** What a case's `metrics(sim)` function can ask of the finished run. */
struct case_sim_api {
  void *ctx;           /* passed back to the callbacks */
  void *run;           /* what the callbacks read (struct sim for metrics_api) */
  char why[256];       /* why a callback refused its input: the script's error quotes it */
  double time;         /* simulated time, s */
  long steps;          /* time steps */
  double particles;    /* particle count */
  long wall_steps;     /* steps at which a fluid particle was behind a wall */
  long wall_most;      /* most fluid particles behind a wall at one step */
  long escaped;        /* fluid particles dropped on leaving the domain (host/sim/checks.c) */
  double body[3];      /* the body force now, m/s² (the scene's; x: the flow-rate control's) */
  const char *stopped; /* NULL for a run that reached its end; else the failure class that
                        * stopped it (summary.json "failure"): metrics of the state at the stop */
  /** Statistics of component `comp` of a field over the particles of `kind` (−1: all) in the
   *  box region = {x0, y0, x1, y1} (NULL: everywhere); *count of them (0: min, max, mean unset). */
  enum clsph_status (*stats)(void *ctx, const char *field, int comp, int kind, const double *region,
                             double *min, double *max, double *mean, size_t *count);
  /** Interpolated values of component `comp` of a field at np points of ncoord coordinates
   *  each (x, y or x, y, z: an input error unless ncoord is the scene's dimension); order 0:
   *  Shepard, 1: first-order moving least squares (sim_sample). */
  enum clsph_status (*sample_many)(void *ctx, const char *field, int comp, int order, int np,
                                   int ncoord, const double *pts, double *values);
  /** Component `comp` of a field at the probe `name` now: its point's value or its face's mean
   *  (sim_sample_probes; NaN where there is no fluid); an input error for an unknown probe. */
  enum clsph_status (*probe)(void *ctx, const char *name, const char *field, int comp,
                             double *value);
  /** Mean force of a wall group over the outputs at t >= since (since < 0: the last output):
   *  out = total x, y, pressure x, y, viscous x, y (N/m), torque (N m/m, about the group's
   *  centre: scene_group_centre); samples = outputs averaged. */
  enum clsph_status (*force)(void *ctx, const char *group, double since, double out[7],
                             int *samples);
  /** The recorded total force of a wall group at each row with t >= since: n rows of (t, x, y,
   *  torque) in an array the caller frees. */
  enum clsph_status (*force_history)(void *ctx, const char *group, double since, size_t *n,
                                     double **rows);
  const char *dir; /* the output folder (profile_<name>.csv for sim.profile); NULL: none */
  /** The particles of `kind` (−1: all): their positions (n x, y, z triples, z = 0 in 2-D) and
   *  component `comp` of a field, in arrays the caller frees. */
  enum clsph_status (*field_values)(void *ctx, const char *field, int comp, int kind, size_t *n,
                                    double **xy, double **values);
  /** What sample() recorded under `name`: n rows of (time, value) in an array the caller frees;
   *  an input error when it records no such name (NULL: no sample()). */
  enum clsph_status (*series)(void *ctx, const char *name, size_t *n, double **rows);
};

/** The values one call of the case's sample(sim) returned, by name: the names (sorted) are those
 *  of its first call, which every later call must return too. */
struct case_values {
  int n;
  char (*names)[SCENE_NAME];
  double *values;
};

/** The limits of the case sandbox: every entry into the script (its top level, a fill's velocity
 *  function, metrics()) may run `instructions` Lua VM instructions; the Lua state may hold
 *  `memory` bytes. */
struct case_limits {
  double instructions; /* per entry (default 1e9, a few seconds) */
  double memory;       /* bytes (default 512 MiB) */
};

/** @brief The default limits. */
void case_limits_default(struct case_limits *l);
/** @brief Run a case script and fill the scene.
 *  @param sets   --set overrides, "name=value" each; a name the case does not declare is refused
 *                with the nearest declared names
 *  @param limits the sandbox's limits (NULL: the defaults)
 *  @param script receives the Lua state (kept for metrics); NULL to close it at once */
enum clsph_status case_load(const char *path, int nsets, char *const *sets,
                            const struct case_limits *limits, struct scene *out,
                            struct case_script **script);
/** @brief Run the case's `metrics(sim)` function, if it has one, adding its numbers to `out`
 *  (a JSON object). */
enum clsph_status case_metrics(struct case_script *cs, const struct case_sim_api *api,
                               struct cJSON *out);
/** @brief Does the case declare sample(sim) (NULL: no script, no)? */
int case_has_sample(const struct case_script *cs);
/** @brief Call the case's sample(sim), which returns named numbers (series.csv, one row per
 *  call): into v (v->n = 0 before the first call: its names become the columns; afterwards the
 *  same names are required). */
enum clsph_status case_sample(struct case_script *cs, const struct case_sim_api *api,
                              struct case_values *v);
/** @brief Free what case_sample allocated, and zero it. */
void case_values_free(struct case_values *v);
/** @brief Close the Lua state (NULL is fine). */
void case_close(struct case_script *cs);

#endif /* CLSPH_CASE_H */
