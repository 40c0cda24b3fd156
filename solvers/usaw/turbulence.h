/* turbulence.h: the k-ε model of the USAW schemes (Leroy et al. 2014 sec 2, eqs 14, 18-29;
 * kernels/usaw/turbulence.cl), shared by isph-usaw and wcsph-usaw: a scene that declares
 * turbulence { model = "k-epsilon", k = ..., epsilon = ... } gets the fields k, epsilon, nu_t,
 * u_star and y_plus (outputs) and the vertices' own velocity (eq 24); a laminar scene none. */
#ifndef CLSPH_USAW_TURBULENCE_H
#define CLSPH_USAW_TURBULENCE_H

#include "kepsilon.h"
#include "walls.h"

struct usaw_turb {
  int on;
  struct kepsilon ke;
  int f_uvert, f_ufric, f_yplus; /* u_vertex (hidden), u_star and y_plus (outputs) */
  cl_kernel k_trans, k_update, k_force;
  cl_mem d_in_group, d_force; /* the wall force's segment mask and per-particle forces */
};

/** The turbulence models the USAW schemes have (scheme_ops.turbulence). */
extern const char *const usaw_turbulence_models[];

/** @brief The kernels' switches: USAW_TURB and KE_ON. */
enum clsph_status usaw_turb_define(const struct sim *sim, struct prog_opts *o);
/** @brief The fields, buffers and kernels when the scene declares the model (t->on), else
 *  nothing; refuses the keys of wcsph-riemann's wall model (y_p, wall_weight, delay). */
enum clsph_status usaw_turb_create(struct sim *sim, struct usaw_turb *t);
/** @brief The arguments usaw_predict takes under the model, from index *i on (d_ggam: ∇γ). */
enum clsph_status usaw_turb_predict_args(struct sim *sim, struct usaw_turb *t, cl_mem d_ggam,
                                         cl_kernel k, cl_uint *i);
/** @brief k and ε over dt at the current positions (γ current, u^n in vel), then ν_t and the
 *  vertices' k and ε; the largest ν_t and the clip counts come with the step's end. */
enum clsph_status usaw_turb_advance(struct sim *sim, struct usaw_turb *t, struct usaw_walls *w,
                                    cl_mem d_gam, double dt, double d_min);
/** @brief The viscous force of the fluid on the walls of `group` under the wall law (eq 22), N/m
 *  (γ current). */
enum clsph_status usaw_turb_wall_force(struct sim *sim, struct usaw_turb *t, struct usaw_walls *w,
                                       cl_mem d_gam, double d_min, const char *group,
                                       double viscous[2]);
void usaw_turb_destroy(struct usaw_turb *t);

#endif /* CLSPH_USAW_TURBULENCE_H */
