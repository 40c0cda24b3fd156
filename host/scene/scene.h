/* scene.h: the scene description a case script produces (host/scene/case.c) and the geometry
 * generator (host/scene/geometry.c) turns into particles. Plain data: every length in m, velocity
 * in m/s, time in s, SI throughout. Points are x, y pairs in 2-D; a 3-D scene (a domain with z)
 * holds its vectors (domain, gravity, body force, velocities) as x, y, z and its fills and walls as
 * boxes (struct scene_region's and scene_wall's box3). */
#ifndef CLSPH_SCENE_H
#define CLSPH_SCENE_H

#include <stddef.h>

#include "mesh.h"
#include "status.h"

#define SCENE_NAME 64 /* longest name (group, probe, parameter, option) + 1 */

/** A parameter declared by `param { name = default }`, possibly overridden by --set. */
struct scene_param {
  char name[SCENE_NAME];
  double value;
  int overridden; /* set from the command line */
};

/** A scheme option: a number or a name (`scheme { "isph-usaw", shifting = 0.7 }`). */
struct scene_option {
  char key[SCENE_NAME];
  int is_number;
  double number;
  char text[SCENE_NAME];
};

/** The solid of a 3-D wall or fill: a box (box3), a sphere or a finite cylinder (shape3). */
enum scene_shape3 {
  SCENE_BOX3 = 0,
  SCENE_SPHERE,   /* shape3: cx, cy, cz, R */
  SCENE_CYLINDER, /* shape3: the axis' ends x0, y0, z0, x1, y1, z1, and R; closed by flat caps */
  SCENE_MESH,     /* a closed triangulated surface (stl_wall; walls only): scene_wall.mesh */
};

/** A fluid region filled at spacing dr on the lattice lo + (k + 1/2) dr. */
struct scene_region {
  char name[SCENE_NAME]; /* "fill 1", or the name the case gives */
  int npts;              /* polygon vertices (a rectangle is a 4-vertex polygon) */
  double *pts;           /* npts x 2, counter-clockwise or not (either works) */
  int given;      /* 1: pts are the particles' own positions (fill { points }), not a polygon */
  int line;       /* line of the case script that declared it */
  int velocity;   /* initial velocity: 0 at rest, 1 u0, 2 scene.velocity_fn's */
  double u0[3];   /* the constant initial velocity, m/s */
  double box3[6]; /* 3-D: the box x0, y0, z0, x1, y1, z1 it fills (npts is 0); for a sphere or a
                   * cylinder its bounding box */
  enum scene_shape3 shape;
  double shape3[7];
  int pressure, density; /* initial pressure and density: 0 the scheme's, 1 the constant below,
                          * 2 scene.velocity_fn's scalar function */
  double p0, rho0;       /* the constant initial pressure (Pa) and density (kg/m^3) */
  int k, epsilon;        /* the same for the turbulence's k (m²/s²) and ε (m²/s³) */
  double k0, eps0;
};

/** The initial velocity of a region's fluid given as a function of position by the case script
 *  (fill { velocity = function(x, y) ... }, function(x, y, z) in 3-D): eval fills v (m/s, the
 *  scene's dimension's components) at x for region `region`. */
struct scene_velocity_fn {
  enum clsph_status (*eval)(void *ctx, int region, const double *x, double *v);
  /** The initial pressure (what = 0, Pa), density (1, kg/m^3), k (2, m²/s²) or ε (3, m²/s³)
   *  function of region `region`. */
  enum clsph_status (*scalar)(void *ctx, int region, int what, const double *x, double *v);
  void *ctx; /* the case script's state: valid while it is open */
};

enum scene_motion {
  SCENE_FIXED = 0,
  SCENE_SLIDING,  /* every wall point moves with `velocity` but the geometry stays (lid) */
  SCENE_ROTATING, /* velocity = omega × (x − centre); the geometry turns */
};

/** A wall: a polyline (an arc or a circle arrives here already divided into vertices).
 *  Orientation convention: the fluid is on the LEFT of the direction of travel, so the inward
 *  normal of an edge from a to b is (−(b−a)_y, (b−a)_x)/|b−a| (a counter-clockwise closed
 *  polyline holds its fluid inside). The case loader orients every wall this way. */
struct scene_wall {
  char group[SCENE_NAME]; /* force group ("walls" unless named) */
  int npts;               /* vertices, >= 2 */
  double *pts;            /* npts x 2 */
  int closed;             /* the last vertex joins the first */
  int fitted; /* dummy layers in rows along the wall (wall { dummies = "fitted" }), not on the
               * lattice */
  enum scene_motion motion;
  double velocity[3]; /* sliding velocity, m/s (z: 3-D only) */
  double centre[2];   /* rotation centre, m */
  double omega;       /* angular velocity, rad/s, counter-clockwise positive */
  int box3d; /* 3-D: a solid (npts 0): 1 a container, its fluid inside; 2 an obstacle, outside */
  double box3[6]; /* x0, y0, z0, x1, y1, z1 of the box's faces (a sphere's or cylinder's bounding
                   * box), m */
  enum scene_shape3 shape;
  double shape3[7];
  struct mesh3 *mesh; /* SCENE_MESH: the surface (owned by the scene) */
  int lid3;  /* 3-D box container: 1 + the face whose dummies slide at `velocity` (2 a + side: 0 x0,
              * 1 x1, 2 y0, 3 y1, 4 z0, 5 z1); 0: none */
  char *stl; /* SCENE_MESH: its file (beside the case script unless absolute) */
  double stl_scale, stl_offset[3]; /* its placement: x' = scale x + offset */
  int line;                        /* line of the case script */
};

enum scene_section_kind { SCENE_INFLOW = 1, SCENE_OUTFLOW };
enum scene_profile { SCENE_UNIFORM = 1, SCENE_PARABOLIC, SCENE_TABLE };

/** An inflow or outflow section: the segment a-b across the channel; the flow enters (inflow) or
 *  leaves (outflow) along its normal pointing into the fluid (left of a->b). */
struct scene_section {
  enum scene_section_kind kind;
  char name[SCENE_NAME];
  double a[2], b[2];
  enum scene_profile profile; /* outflow: 0 (natural exit, n·∇u = 0) unless prescribed; an
                               * inflow's SCENE_TABLE: prof below */
  double velocity; /* mean (uniform) or peak (parabolic) normal speed, m/s; 0 for a natural exit */
  int layers;      /* particle layers outside the section (3 unless given) */
  double ramp; /* the prescribed velocity rises as ½(1 − cos(π t/ramp)) until t = ramp, s (0:
                * at once) */
  /* an entry's k and ε under the k-ε model, m²/s², m²/s³ (NAN: turbulence { }'s, or the table) */
  double k, epsilon;
  /* an entry given as functions of s, the distance from a along the section (profile
   * SCENE_TABLE for the velocity; k and ε may be functions too): nprof samples at s = len i /
   * (nprof − 1) of u, k and ε (prof[3 i + 0, 1, 2]; NAN where given as a number); velocity is
   * then the largest |u| and mean its mean over the section (m/s) */
  int nprof;
  double *prof;
  double mean;
  int line;
};

/** A probe: the interpolated fields at a point, or their mean over a face (a segment, e.g. the
 *  face of a pressure sensor; in 3-D also a disc): the mean over its npts points
 *  (scene_probe_points), the points with no fluid within the support left out (series.c,
 *  sim_sample_probes). */
struct scene_probe {
  char name[SCENE_NAME];
  double x[3];      /* the point, the face's first end or the disc's centre, m (z: 3-D) */
  double b[3];      /* the face's second end, m (a segment face) */
  double normal[3]; /* a disc's unit normal */
  double radius;    /* a disc's radius, m */
  int face;         /* 0: a point probe at x; 1: a segment face from x to b; 2: a disc (3-D) */
  int npts;         /* points sampled: 1 for a point probe; for a segment, `points =` or as many as
                     * keep them dr/4 apart or closer (at least 2); for a disc, those of a square
                     * lattice dr/4 apart or closer (at most radius/2) within it */
  int line;         /* line of the case script */
};

struct scene_profile_line {
  char name[SCENE_NAME];
  double a[3], b[3]; /* its ends ({x, y} or {x, y, z}: the scene's dimension) */
  int npts;          /* sample points from a to b inclusive */
  int order;         /* interpolation: 0 Shepard, 1 first-order moving least squares (sim_sample) */
  int line;          /* line of the case script */
};

/** Flow-rate control (Leroy et al. 2014 eqs 67-68, after Morris et al. 1997): the x component of
 *  the body force is updated every step so that the mean x velocity of the fluid particles in the
 *  slice x0 <= x < x1 (modulo the period on a periodic x axis) reaches `velocity`. */
struct scene_flow_control {
  int on;
  double velocity; /* target mean x velocity ⟨v⟩ in the slice, m/s */
  double slice[2]; /* x0, x1 of the slice, m */
  int line;        /* line of the case script */
};

/** A turbulence model (`turbulence { model = "k-epsilon", k = ..., epsilon = ..., y_p = ... }`),
 *  for the schemes that have one (scheme_ops.turbulence): the k-ε RANS model of Wang, Sun & Hu
 *  (sec 2-4) with its wall model at the distance y_p from the walls. */
struct scene_turbulence {
  int on;
  char model[SCENE_NAME]; /* "k-epsilon" */
  double k, epsilon;      /* the initial (and the entries') k, m²/s², and ε, m²/s³ */
  double y_p;             /* the wall model's distance from the wall, m (eq 10; 0: dr/2) */
  double delay;           /* s: until then k and ε stay and ν_t = nu_t_delay (sec 5.2) */
  double nu_t_delay;      /* m²/s, the eddy viscosity of the delay */
  double wall_weight;     /* w_s of eq 40 (NaN: the scheme's, 0.1 without ARD, 0.5 with) */
  int wall_law; /* the USAW schemes' wall law: −1 not given (0), 0 "two-layer" (Leroy et al. eq 23:
                 * linear below y+ = 11.06), 1 "scalable" (y+ held at 11.06 and above) */
  int production; /* the USAW schemes' production of k: −1 not given (0), 0 "semi-linear" (Leroy
                   * et al. eq 20: min(√C_μ k S, ν_T S²)), 1 "standard" (ν_T S², OpenFOAM's) */
  int line;       /* line of the case script */
};

/** How frames show this case (`render { field = "p", range = {0, 1e4}, colormap = "viridis" }`):
 *  the defaults of `clsph run --frames` and `clsph render`, which the command line overrides. */
struct scene_render {
  int on;                                /* the case declares render { } */
  char field[SCENE_NAME];                /* field name ("" : the default, speed) */
  int fixed;                             /* a fixed colour range */
  double range[2];                       /* low and high end, in the field's unit */
  char colormap[SCENE_NAME];             /* "auto", "viridis", "coolwarm", "kind" ("": auto) */
  int camera;                            /* 3-D: 1 when the camera below is given */
  double eye[3], look_at[3], up[3], fov; /* the camera: eye, target, up, field of view (deg) */
  int line;                              /* line of the case script */
};

/** Thresholds of the health checks of the time loop (run { checks = { ... } }; the defaults,
 *  and the measurements behind them, are in host/scene/scene.c). A run that passes one stops as a
 *  blow-up with its reason in summary.json. */
struct scene_checks {
  int every;               /* steps between the clustering and energy checks (and the last) */
  double cluster_h;        /* a fluid particle is clustered when its nearest fluid neighbour is
                            * closer than cluster_h h (h the smoothing length) */
  double cluster_fraction; /* the run fails when more than this fraction of the fluid is
                            * clustered */
  double energy;           /* the run fails when the kinetic energy of the fluid exceeds energy
                            * times ½ M U² (M its mass, U the scene's velocity scale, sim/sim.c) */
  double wall_depth;       /* the run fails when a fluid particle is more than wall_depth dr
                            * behind a wall (shallower crossings are counted) */
  double escaped;          /* the run fails when more than this fraction of the fluid has left
                            * the domain (fewer are dropped and counted; 0: none may leave) */
};

/** Everything a case declares. Anything it does not state is off. */
struct scene {
  char case_path[1024];  /* the script */
  char name[SCENE_NAME]; /* case name: the script's file name without .lua */
  int dim;               /* 2, or 3 when the domain gives z */
  double lo[3], hi[3];   /* domain box, m (periodic axes: the period); z only in 3-D */
  int periodic[3];
  double dr;                      /* particle spacing, m */
  double h_over_dr;               /* smoothing length / dr (scheme default unless given) */
  char smoothing[SCENE_NAME];     /* smoothing function name ("" = the scheme's default) */
  double rho0;                    /* reference density, kg/m^3 */
  double nu;                      /* kinematic viscosity, m^2/s */
  double gravity[3];              /* m/s^2 (z: 3-D only) */
  double body_force[3];           /* acceleration, m/s^2 (e.g. a pressure-gradient drive) */
  struct scene_flow_control flow; /* flow-rate control of the x body force (off unless given) */
  char scheme[SCENE_NAME];
  int scheme_line; /* line of the case script that names it */
  int noptions;
  struct scene_option *options;
  char wall_model[SCENE_NAME]; /* "usaw" or "dummy": the scheme decides; "" until then */
  int dummy_layers;            /* layers of dummy particles (dummy walls) */
  double t_end;                /* end time, s (the parameter t_end) */
  double output_every;         /* snapshot cadence, s (0: only the last) */
  double sample_every;         /* cadence of probes.csv and forces.csv, s (0: with snapshots) */
  double checkpoint_every;     /* checkpoint cadence, s (0: only the last) */
  double max_snapshots;        /* most snapshots and checkpoints a run may write (10000) */
  int run_line;                /* line of the case script's run { } */
  double cfl;                  /* time-step factor (1 = the scheme's bounds) */
  double dt;                   /* fixed time step, s (0: from the scheme's bounds) */
  struct scene_checks checks;  /* health-check thresholds */
  int nparams;
  struct scene_param *params;
  int nregions;
  struct scene_region *regions;
  struct scene_velocity_fn velocity_fn; /* for regions with velocity 2 */
  int nwalls;
  struct scene_wall *walls;
  int nsections;
  struct scene_section *sections;
  int nprobes;
  struct scene_probe *probes;
  int nprofiles;
  struct scene_profile_line *profiles;
  int nforces;
  char (*forces)[SCENE_NAME];   /* wall groups whose force is recorded */
  struct scene_render render;   /* how frames show it */
  struct scene_turbulence turb; /* off unless declared */
};

/** @brief An entry's tabulated value `what` (0 u, 1 k, 2 ε) at the distance s along it (linear
 *  between the samples, clamped to the section; NAN where the entry gives no table of it). */
double scene_section_value(const struct scene_section *c, int what, double s);

/** @brief The points a probe samples (points x dim values into out when it is not NULL): its
 *  point; the midpoints of a segment face's npts equal parts; a disc's points on the square
 *  lattice of spacing min(dr/4, radius/2) in its plane, centred on it, within the radius. Returns
 *  their count (a disc's from dr, at most 10000 + 1; the others' npts). */
int scene_probe_points(const struct scene_probe *p, int dim, double dr, double *out);

/** @brief Free everything a scene owns (safe on a zeroed scene). */
void scene_free(struct scene *s);

/** @brief Value of a parameter, or `fallback` when the case declares none of that name. */
double scene_param(const struct scene *s, const char *name, double fallback);

/** @brief 1 when the wall turns: rotating (omega ≠ 0); its geometry then stands rotated by ω t
 *  about its centre at time t (scene_wall_turn). */
int scene_wall_turns(const struct scene_wall *w);
/** @brief Where the point x of wall w (given at t = 0) stands at time t: x itself unless the wall
 *  turns. With `vector`, x is a direction (a normal): rotated, not moved with the centre. */
void scene_wall_turn(const struct scene_wall *w, double t, const double x[2], int vector,
                     double out[2]);
/** @brief The faces of a 3-D scene's walls (box, sphere, cylinder and STL solids; surface3.c) as
 *  triangles, ntri x 9 vertex coordinates (m) into *tri (malloc'd; NULL and 0 in 2-D or without
 *  walls), counter-clockwise seen from the fluid; the walls of group `moved_group` (NULL: none)
 *  moved by `offset` (a lifted gate). */
enum clsph_status scene_surfaces3(const struct scene *s, const char *moved_group,
                                  const double offset[3], double **tri, size_t *ntri);
/** @brief The point a wall group's moment (struct wall_force's torque) is taken about: the centre
 *  of its first turning wall, else the origin. */
void scene_group_centre(const struct scene *s, const char *group, double c[2]);

/** @brief The default health-check thresholds (what healthy runs were measured to stay within). */
void scene_checks_default(struct scene_checks *c);

#endif /* CLSPH_SCENE_H */
