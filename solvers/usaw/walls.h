/* walls.h: the wall segments of the unified semi-analytical walls (Leroy et al. 2014) on the
 * device, shared by isph-usaw and wcsph-usaw: their fields, their own cell grid (binned by
 * midpoint), and the analytic wall renormalisation γ_a and ∇γ_a (kernels/usaw/gamma.cl). */
#ifndef CLSPH_USAW_WALLS_H
#define CLSPH_USAW_WALLS_H

#include "../scheme.h"
#include "grid.h"
#include "pset.h"

/** Kernel sources after the grid and smoothing sources. */
#define USAW_SOURCES "usaw/gamma.cl"

/** Segments on the host, one per entry: ends a and b, unit normal into the fluid, the original
 *  indices (ids) of the vertex particles at a and b (or NULL), and each segment's wall (or NULL:
 *  one wall). Where one segment ends at a vertex and the next of the same wall starts there on
 *  the same line, the joint's terms of γ and ∇γ cancel and are not evaluated (gamma.cl). */
struct usaw_segments {
  size_t n;
  const double *a, *b, *normal; /* n x 2 each */
  const size_t *v;              /* n x 2 vertex particle ids, or NULL */
  const int *wall;              /* n: the wall each segment belongs to, or NULL */
};

struct usaw_walls {
  struct grid g;  /* the segments' grid: cells of at least (support + max length/2)/GRID_SUB */
  struct pset ps; /* segment fields: mid, a, b, n (realv); v1, v2, index, joint (uint) */
  int f_mid, f_a, f_b, f_n, f_v1, f_v2;
  int f_joint;    /* bit 0: the end a is a collinear joint with the previous segment, bit 1: b */
  size_t njoints; /* how many ends are such joints */
  int f_index;    /* each segment's index in the order given (the geometry's), after the sort */
  cl_kernel k_gamma;
  cl_mem d_flags;
  /* walls that turn (wall { omega, centre }: the geometry rotates about the centre, θ = ω t;
   * kernels/usaw/motion.cl); all zero when none does */
  int turning;        /* 1: some segment turns */
  double t_now;       /* the time the turning walls stand at, s */
  cl_mem d_rot;       /* per scene wall: centre x, y and ω (3 reals; kernels/usaw/motion.cl) */
  cl_mem d_seg_turn;  /* per segment (the geometry's order): its wall if it turns, else −1 */
  cl_mem d_seg0;      /* per segment: a, b, n at t = 0 (3 realv), the ends the images nearest
                       * their wall's centre */
  cl_mem d_vert_turn; /* per particle (original index): its wall if a turning vertex, else −1 */
  cl_mem d_vert0;     /* per particle: the position at t = 0 nearest its wall's centre, and
                       * its normal */
  int f_vnormal;      /* the particle field of the vertices' normals that usaw_walls_turn turns
                       * with them (the scheme's; −1: none) */
  cl_kernel k_turn_vertices, k_turn_segments;
  /* the segment cache (kernels/usaw/gamma.cl, -D USAW_SEG_CACHE): slots a particle (0: none), and
   * for cache_n particles their counts, the slots' segments and their ∇γ_as */
  unsigned cache_k;
  size_t cache_n;
  cl_mem d_cache_cnt, d_cache_list, d_cache_gg;
};

/** @brief Upload the segments and sort them into their grid.
 *  @param box the particles' grid spec (domain, periodic axes, support) */
enum clsph_status usaw_walls_create(const struct dev *dev, cl_program prog,
                                    const struct usaw_segments *segs, const struct grid_spec *box,
                                    struct usaw_walls *out);
/** @brief γ_a and ∇γ_a of n particles at d_pos (theta: θ_v of vertex particles, 0 elsewhere);
 *  raises CLSPH_FLAG_WALL in d_flags where a fluid particle is behind a wall. */
enum clsph_status usaw_walls_gamma(struct usaw_walls *w, const struct dev *dev, size_t n,
                                   cl_mem d_pos, cl_mem d_theta, cl_mem d_gamma,
                                   cl_mem d_grad_gamma, cl_mem d_flags);
struct geom;
struct scene;
/** @brief usaw_walls_create() with the segments of a generated geometry (geometry.h); the walls
 *  of the scene that turn (scene_wall_turns) get what usaw_walls_turn() needs (the program then
 *  holds kernels/usaw/motion.cl). */
enum clsph_status usaw_walls_from_geom(const struct dev *dev, cl_program prog,
                                       const struct geom *geo, const struct scene *sc,
                                       const struct grid_spec *box, struct usaw_walls *out);
/** @brief Put the turning walls where they stand at time t (rotated by ω t about their centres):
 *  their vertex particles' positions and velocities ω × (r − c), their segments, re-binned.
 *  A no-op when no wall turns or they stand at t already. Sort the particles after it. */
enum clsph_status usaw_walls_turn(struct usaw_walls *w, struct sim *sim, double t);
/** @brief Force of the fluid on the walls of a group (eq 69): p_s and ∇u_s + ∇u_sᵀ are the means
 *  of the segment's two vertex values (eq 70; the strain from the kernel usaw_vertex_strain,
 *  three reals xx, xy, yy per particle); reads p, the strain and the inverse index (current index
 *  of each original particle) back from the device. Its moment (f->torque) is about the group's
 *  centre (wall_force_centre), each segment's force at its midpoint; turning walls stand where
 *  they are at time t.
 *  @param mu dynamic viscosity, Pa s */
enum clsph_status usaw_wall_force(const struct dev *dev, const struct geom *geo,
                                  const struct scene *sc, size_t n, cl_mem d_p, cl_mem d_strain,
                                  cl_mem d_inv, double mu, double t, const char *group,
                                  struct wall_force *f);
/** The scheme options both USAW schemes take: their viscous wall term's distance floor
 *  (kernels/usaw/viscous.cl), the wall guard (usaw_wall_guard, kernels/usaw/common.cl) and the
 *  segment cache (kernels/usaw/gamma.cl). */
#define USAW_WALL_OPTION_NAMES "wall_distance_floor", "wall_guard", "segment_cache"
/** @brief Whether the wall guard is on: the option wall_guard ("on", "off", or "auto", the
 *  default, which takes `auto_on`: the scheme's own rule). */
enum clsph_status usaw_wall_guard_option(const struct scene *sc, int auto_on, cl_uint *on);
/** @brief The smallest wall distance δr_as of the viscous wall term (eq 17), in m: the option
 *  wall_distance_floor (spacings, in (0, 1]; 1 is the paper's δr), or the scheme's default
 *  `spacings`, times δr. */
enum clsph_status usaw_wall_distance_floor(const struct scene *sc, double spacings, double *d_min);
/** @brief The segment cache's slots a particle (kernels/usaw/gamma.cl): the option segment_cache
 *  (0: none, up to 64), else the scheme's default dflt. */
enum clsph_status usaw_seg_cache_option(const struct scene *sc, unsigned dflt, unsigned *slots);
/** @brief The -D switches of the segment cache (USAW_SEG_CACHE), the scheme's default dflt. */
enum clsph_status usaw_seg_cache_define(const struct scene *sc, unsigned dflt, struct prog_opts *o);
/** @brief Turn the segment cache on as the option says (the scheme's default dflt), after
 *  usaw_walls_from_geom() and with the program that usaw_seg_cache_define() made. */
enum clsph_status usaw_walls_cache(struct usaw_walls *w, const struct scene *sc, unsigned dflt);
/** @brief Release. */
/** @brief The particle and segment arguments every USAW kernel starts with (USAW_PART_ARGS,
 *  USAW_SEG_ARGS; gam: γ of the particles); *next gets the next argument's index. */
enum clsph_status usaw_kernel_prefix(struct sim *sim, struct usaw_walls *w, cl_mem gam, cl_kernel k,
                                     cl_uint *next);
void usaw_walls_destroy(struct usaw_walls *w);

#endif /* CLSPH_USAW_WALLS_H */
