/* open.h: entry and exit sections (inflow { } and outflow { } of a case), shared by the schemes
 * that have them: a velocity inlet, and an outlet with n·∇u = 0 or a prescribed profile, made of
 * layers of particles outside the fluid that are recycled, so that the count of particles never
 * changes and nothing leaves the device (Hosseini & Feng 2011 sec 3.3.2-3.3.3; the formulas are
 * in kernels/common/open.cl). isph-rotational uses it (solvers/isph_rotational; the φ and p rows
 * of its layers are kernels/isph_rotational/open.cl).
 *
 * What it owns: the section table (d_sec) and three particle fields: "section" (the section of a
 * layer particle), "vel_src" (its velocity progenitor: the fluid particle it copies at a natural
 * exit, itself elsewhere) and "p_near" (its row's first fluid particle: the fluid particle nearest
 * to the point level with it δr/2 inside the section; itself when there is none). The layers'
 * velocity is kept in a realv field that holds the geometry's velocities (geom.v): the scheme's
 * own (a dummy scheme's wall velocity) or one open_create adds. Layer particles are of kinds
 * KIND_INFLOW (3) and KIND_OUTFLOW (4) of host/scene/geometry.h; they keep their volume and id.
 *
 * How a scheme uses it:
 *   define:  open_define(sim, o); OPEN_SOURCES in its sources, before its own kernels (which may
 *            call open_section_load and open_nearest_fluid under #if OPEN_SECTIONS);
 *   create:  open_create(sim, f_u, &o) after its own fields (for a scene without sections it
 *            makes nothing, and every call below then does nothing); the scheme accepts particles
 *            of kinds KIND_INFLOW and KIND_OUTFLOW;
 *   max_dt:  the CFL speed is at least open_speed(scene) (a fluid at rest behind an entry would
 *            otherwise get only the viscous bound);
 *   step, with the particles sorted and the grid current, in this order:
 *     1. open_layer_velocity, before any kernel that reads the layers' velocity (the dummies'
 *        extrapolation, the viscous term, the continuity equation): the entry layers get their
 *        prescribed u_in, the exit layers their progenitor's velocity (n·∇u = 0) or the
 *        prescribed exit profile, and "p_near" and "vel_src" are set;
 *     2. the scheme's own state of the layers (its pressure, density, ...), from "p_near";
 *     3. the scheme's kernels: the layer particles are the fluid's neighbours like fluid
 *        particles (and count as fluid in a dummy's extrapolation), but nothing integrates them;
 *     4. the layers' motion x += δt u: open_move, or the scheme's own move kernel;
 *     5. open_recycle after the step's last motion, then open_recycle_copy for each field of the
 *        scheme's that a recycled particle must take over from the entry particle it replaces
 *        (positions change: the next step's sort bins them).
 *
 * A weakly-compressible scheme (ρ and p per particle, dummy walls, a zero-pressure outlet): the
 * entry layers carry the prescribed velocity and ρ and p from the nearest fluid (a copy of the
 * row's first fluid particle: n·∇ρ = n·∇p = 0), the exit layers their progenitor's velocity and
 * ρ = ρ0, p = 0. Each step:
 *     open_layer_velocity(&o, sim);                the velocity of every layer particle
 *     open_layer_scalar(&o, sim, d_rho, &rho0);    ρ: entry from the row's first fluid particle,
 *     open_layer_scalar(&o, sim, d_p, &zero);      p: exit ρ0 and 0
 *     ... the dummies' state (their image may lie among layer particles), dρ/dt and du/dt of the
 *         fluid over all its neighbours, layers included; the update kernels change only the
 *         fluid's ρ, p and u ...
 *     open_move(&o, sim, dt);                      the layers: x += δt u
 *     open_recycle(&o, sim);
 *     open_recycle_copy(&o, sim, f_rho);           and f_p, and any state carried from one step
 *                                                  to the next (an earlier stage's ρ or u)
 * With several stages or acoustic sub-steps within one sort: open_layer_velocity once after the
 * sort (it searches the grid), open_layer_scalar before each stage that reads the layers (their
 * rows' fluid particles stay those found after the sort), open_move with each sub-step's δt,
 * open_recycle once at the end. A scheme whose p follows from ρ by its equation of state may set
 * ρ alone (then ρ0 gives p = 0 at the exit only without a background pressure). */
#ifndef CLSPH_OPEN_H
#define CLSPH_OPEN_H

#include "prog.h"

/** Kernel sources after the common ones (built for every scene: empty without sections). */
#define OPEN_SOURCES "common/open.cl"

struct scene;
struct sim;

/** The sections on the device (nsec = 0: none, and nothing below exists). */
struct open_sections {
  cl_uint nsec;                 /* sections */
  int ninflow, noutflow;        /* of which inflows and outflows */
  cl_mem d_sec;                 /* the section table, OPEN_SEC reals per section (open.cl) */
  int f_section, f_src, f_near; /* per particle: section, velocity progenitor, row's first fluid */
  int f_u;                      /* the layers' velocity, m/s (the scheme's field, or "open_u") */
  cl_mem d_role, d_list;        /* recycling: role per particle, its pairs */
  cl_mem d_count;               /* recycled so far, entry and exit particles left waiting, pairs
                                 * of the last recycling and where their entry particles start */
  cl_uint used, off;            /* pairs of the last recycling, read back: see d_count */
  cl_mem d_exitval;             /* per section: an exit's value of a layer scalar */
  cl_mem d_partial;             /* the exits' sums, per work-group and section */
  real *h_exitval, *h_partial;
  cl_kernel k_velocity, k_scalar, k_move, k_classify, k_recycle, k_copy_real, k_copy_realv;
  cl_kernel k_exit_sums;
};

/** @brief The -D switches of kernels/common/open.cl: OPEN_SECTIONS = 1 for a scene with
 *  sections, 0 otherwise (then nothing of it is compiled). Call from the scheme's define. */
enum clsph_status open_define(const struct sim *sim, struct prog_opts *o);

/** @brief Checks the scene's sections (their layers cover the smoothing support; an inflow and
 *  an outflow together, as the recycling needs both), uploads the section table, adds the fields
 *  "section", "vel_src" and "p_near" and gets the kernels. A scene without sections gets a zeroed
 *  struct and nothing else.
 *  @param f_u the scheme's realv field that holds the layers' velocity, initialised from the
 *         geometry's velocities (geom.v: u_in at an entry, the prescribed profile at an exit), or
 *         −1: open_create adds it ("open_u")
 *  @param out the sections; release with open_destroy() */
enum clsph_status open_create(struct sim *sim, int f_u, struct open_sections *out);

/** @brief The largest prescribed speed of the scene's sections, m/s (0: none), for the CFL bound
 *  of a scheme's max_dt. */
double open_speed(const struct scene *sc);

/** @brief The layers' velocity, each step with the particles sorted (sec 3.3.2-3.3.3): vel and
 *  the f_u field of the entry layers get their prescribed u_in, those of the exit layers their
 *  progenitor's velocity (n·∇u = 0) or the prescribed exit profile (0 beyond the last layer);
 *  "p_near" and "vel_src" are set for every layer particle. */
enum clsph_status open_layer_velocity(struct open_sections *o, struct sim *sim);

/** @brief A scalar field of the layers (after open_layer_velocity): the entry layers take the
 *  value of their row's first fluid particle; the exit layers *exit_value, or with exit_value
 *  NULL their row's first fluid particle's too.
 *  @param a a field of reals (e.g. ρ or p) */
enum clsph_status open_layer_scalar(struct open_sections *o, struct sim *sim, cl_mem a,
                                    const double *exit_value);

/** @brief open_layer_scalar with a value per section: the exit layers of section k take
 *  exit_value[k] (entries copy their row's first fluid particle as above).
 *  @param exit_value nsec values, those of the entries unused */
enum clsph_status open_layer_scalar_exits(struct open_sections *o, struct sim *sim, cl_mem a,
                                          const double *exit_value);

/** @brief A scalar with prescribed entry values (after open_layer_velocity): the exit layers take
 *  their row's first fluid particle's value (n·∇a = 0), the entry layers keep theirs (set at the
 *  start and handed on by open_recycle_copy). */
enum clsph_status open_layer_scalar_prescribed(struct open_sections *o, struct sim *sim, cl_mem a);

/** @brief The mean normal speed through each section of the fluid in its first row (0 <= h < δr),
 *  in at an entry and out at an exit, m/s, into speed[k] for section k (0 without fluid there). */
enum clsph_status open_exit_speed(struct open_sections *o, struct sim *sim, double *speed);

/** @brief The volume flux (per unit depth, m²/s) that the entries let in at time t, less what the
 *  exits with a prescribed profile let out: what the natural exits must let out in a steady
 *  incompressible flow. With the ramps (inflow { ramp }). */
double open_natural_flux(const struct scene *sc, double t);

/** @brief The mean speed out of the natural exits (outflow without a profile) of the fluid as the
 *  geometry starts it: the normal outflow of the fluid particles in each exit's first row
 *  (0 <= h < δr), weighted by the exits' lengths, m/s (0 for a fluid at rest or without such an
 *  exit). The speed the exits let out before the entries' start-up wave arrives. */
double open_initial_outflow(const struct sim *sim);

/** @brief The shortest distance from an entry's midpoint to a natural exit's, m (0 without
 *  such a pair): the path of the start-up wave from the entries to the exits. */
double open_transit(const struct scene *sc);

/** @brief The total length of the natural exits (outflow without a profile), m. */
double open_natural_width(const struct scene *sc);

/** @brief Move the layer particles with their velocity, x += dt u (in place). */
enum clsph_status open_move(struct open_sections *o, struct sim *sim, double dt);

/** @brief The recycling, after the motion: fluid that crossed an exit becomes an exit layer
 *  particle, entry layer particles that reached the fluid become fluid and exit particles beyond
 *  the last layer take their places at the back of their rows (position, kind, section, velocity
 *  and f_u). Sets sim->open_waiting and sim->open_waiting_max (entry particles left waiting). */
enum clsph_status open_recycle(struct open_sections *o, struct sim *sim);

/** @brief After open_recycle: each recycled particle takes the value of field `field` (reals or
 *  realv) of the entry particle it replaced. */
enum clsph_status open_recycle_copy(struct open_sections *o, struct sim *sim, int field);

/** @brief Release (safe on a zeroed struct). */
void open_destroy(struct open_sections *o);

#endif /* CLSPH_OPEN_H */
