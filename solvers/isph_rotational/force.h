/* force.h: the force of the fluid on the dummy-particle walls of a force group (Hosseini & Feng
 * 2011 eqs 31-32; kernels/isph_rotational/force.cl): sample points along the group's wall lines,
 * pressure and velocity gradient interpolated to them on the device, the traction summed on the
 * host. */
#ifndef CLSPH_ROT_FORCE_H
#define CLSPH_ROT_FORCE_H

#include "grid.h"
#include "kern.h"
#include "prog.h"
#include "scene.h"

/** The sample points of one force group. */
struct rot_samples {
  char group[SCENE_NAME];
  size_t n;
  double *nrm, *len;       /* unit normal into the fluid, length of wall each stands for */
  double *x;               /* position, m */
  double centre[2];        /* the point the torque is taken about (scene_group_centre) */
  cl_mem d_x, d_uw, d_out; /* position, wall velocity, the 5 values per point */
  real *h_out;
};

struct rot_force {
  cl_kernel k;
  int ngroups;
  struct rot_samples *g;
};

/** @brief Sample points for every force group of the scene (at most dr apart on its walls). */
enum clsph_status rot_force_create(const struct dev *dev, cl_program prog, const struct scene *sc,
                                   struct rot_force *out);
/** @brief Pressure and viscous force of the fluid on the walls of `group` (N/m in 2-D), and its
 *  moment about the group's centre (N m/m). */
enum clsph_status rot_force_eval(struct rot_force *rf, const struct dev *dev, const struct grid *g,
                                 size_t n, cl_mem pos, cl_mem vol, cl_mem kind, cl_mem vel,
                                 cl_mem p, double mu, const char *group, double pressure[2],
                                 double viscous[2], double *torque);
/** @brief Release (safe on a zeroed struct). */
void rot_force_destroy(struct rot_force *rf);

#endif /* CLSPH_ROT_FORCE_H */
