/* geometry.h: turns a scene description into particles and wall elements (see geometry.c). */
#ifndef CLSPH_GEOMETRY_H
#define CLSPH_GEOMETRY_H

#include <stddef.h>

#include "scene.h"
#include "status.h"

/** Particle kinds, in the order the particles are stored. */
enum particle_kind {
  KIND_FLUID = 0,   /* free fluid particle */
  KIND_VERTEX = 1,  /* USAW vertex particle: a truncated fluid particle on the wall (Leroy 2014) */
  KIND_DUMMY = 2,   /* dummy wall particle inside the solid */
  KIND_INFLOW = 3,  /* inflow layer particle (outside an inflow section) */
  KIND_OUTFLOW = 4, /* outflow layer particle (outside an outflow section) */
  KIND_PARKED = 5,  /* parked behind an exit, out of every sum, until an entry takes it
                     * (struct geom_park) */
  KIND_OUT = 6      /* fluid that left the domain this step (CLSPH_KIND_OUT, domain.cl): dropped
                     * at the step's end (host/sim/checks.c); only blowup.h5 shows it */
};

/** Particles (host arrays, double precision) and USAW segments. Fluid particles come first. */
struct geom {
  int dim;           /* 2, or 3: the n x 2 arrays below are then n x 3 */
  size_t n;          /* particles of every kind */
  size_t nfluid;     /* the first nfluid are KIND_FLUID */
  double *x;         /* n x 2, position, m */
  double *v;         /* n x 2, initial velocity (the wall velocity for wall particles), m/s */
  double *p0;        /* n, the initial pressure fill { pressure } gives, Pa; NAN: the scheme's */
  double *rho0;      /* n, the initial density fill { density } gives, kg/m^3; NAN: the scheme's */
  double *k0, *eps0; /* n, the initial k and ε fill { k, epsilon } give; NAN: turbulence { }'s */
  int has_p0, has_rho0, has_k0; /* the line of the first fill that gives them (0: none does) */
  double *normal; /* n x 2, unit normal into the fluid (vertex, dummy, inflow/outflow); 0 else */
  double *theta;  /* n, vertex particles: angle of the fluid sector at the vertex, rad (π on a
                     straight wall, π/2 in a box corner, 3π/2 at a convex solid corner); else 0 */
  double *dist;   /* n, dummy particles: distance to the nearest wall point, m; else 0 */
  int *kind;      /* n, enum particle_kind */
  int *group;     /* n, index of the wall (scene walls[]) or section, −1 for fluid */
  size_t nseg;    /* USAW segments */
  size_t *seg_v;  /* nseg x 2, the vertex particles at each end (indices into the arrays above) */
  double *seg_normal; /* nseg x 2, unit normal into the fluid */
  double *seg_len;    /* nseg, length, m */
  int *seg_wall;      /* nseg, index of the wall in scene walls[] */
};

/** Particles parked behind the exits (outflow { }), for a weakly-compressible scheme whose fluid
 *  takes in more than it gives out while it is compressed: an entry particle that reaches the fluid
 *  takes a parked particle when no fluid has left through an exit (solvers/open). */
struct geom_park {
  double fraction; /* parked particles, as a fraction of the fluid's (0: none), shared among the
                    * exits by their lengths */
  double behind;   /* the park's distance behind the last layer, m: beyond the support of any
                    * particle that takes part in the fluid's sums */
};

/** @brief Build the particles of a scene: fluid first (rows of increasing y, then x), then the
 *  wall particles, then the inflow/outflow layers of each section (conventions: geometry.c).
 *  @param s      the scene (dr, regions, walls with the fluid on their left, sections)
 *  @param model  "usaw": vertex particles and segments; "dummy": `layers` layers of dummy
 *                particles; "none": fluid (and inflow/outflow layers) only
 *  @param layers dummy layers, >= 1 for "dummy" (ignored otherwise)
 *  @param park   particles parked behind the exits, after their layers (NULL: none)
 *  @param out    overwritten (free it first); zeroed on failure
 *  @return CLSPH_E_INPUT with a message naming the case file and line for invalid geometry,
 *          CLSPH_E_NOMEM */
enum clsph_status geometry_build(const struct scene *s, const char *model, int layers,
                                 const struct geom_park *park, struct geom *out);
/** @brief The particles of a 3-D scene (geometry3.c: box, sphere and cylinder fills, box, sphere,
 *  cylinder and STL walls; no segments,
 *  no sections); geometry_build calls it for scene.dim = 3. */
enum clsph_status geometry_build3(const struct scene *s, const char *model, int layers,
                                  struct geom *out);
/** @brief The obstacle (a 3-D wall with its fluid outside: box, sphere, cylinder or STL solid)
 *  that holds the point x, into *wall (−1: none); for a camera's eye. */
enum clsph_status geometry3_solid_at(const struct scene *s, const double x[3], int *wall);
/** @brief A digest (CRC-32) of what defines a scene besides its parameters' names: the generated
 *  particles (positions, initial velocities, kinds, wall groups) and segments, the domain and its
 *  periodic axes, the fluid's properties, the wall motions, the scheme and its options. Two runs
 *  with equal digests start from the same state; a checkpoint records it (restarts compare). */
unsigned long geometry_digest(const struct scene *s, const struct geom *g);
/** @brief Free the arrays (safe on a zeroed struct). */
void geometry_free(struct geom *g);

#endif /* CLSPH_GEOMETRY_H */
