/* turbulence.c: the USAW schemes' k-ε model on the host (turbulence.h). */
#include "turbulence.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clsph_config.h"
#include "geometry.h"
#include "scene.h"

const char *const usaw_turbulence_models[] = {"k-epsilon", NULL};

enum clsph_status usaw_turb_define(const struct sim *sim, struct prog_opts *o)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(prog_opts_define_int(o, "USAW_TURB", sim->scene->turb.on));
  CLSPH_TRY(prog_opts_define_int(o, "KE_ON", sim->scene->turb.on));
  CLSPH_TRY(prog_opts_define_int(o, "USAW_SCALABLE", sim->scene->turb.wall_law == 1));
  CLSPH_TRY(prog_opts_define_int(o, "USAW_PROD_STANDARD", sim->scene->turb.production == 1));
done:
  return st;
}

#define ARG(k, i, x) CLSPH_TRY(kern_set_at((k), (i)++, KARG(x)))

enum clsph_status usaw_turb_create(struct sim *sim, struct usaw_turb *t)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *sc = sim->scene;
  const struct scene_turbulence *tb = &sc->turb;
  const struct geom *geo = &sim->geom;
  real *uv = NULL;
  memset(t, 0, sizeof *t);
  t->ke.f_k = t->ke.f_eps = t->ke.f_nut = t->f_uvert = t->f_ufric = t->f_yplus = -1;
  if (!tb->on) goto done;
  /* the semi-analytical walls apply the wall law at each particle's own distance from each
   * segment (eq 23): wcsph-riemann's wall-model keys have no meaning here */
  CLSPH_CHECK(
      tb->y_p == 0.0, CLSPH_E_INPUT,
      "%s:%d: turbulence: y_p belongs to wcsph-riemann's wall model; %s applies the log law "
      "at each particle's own distance from the wall (Leroy et al. eq 23): drop y_p",
      sc->case_path, tb->line, sim->scheme->name);
  CLSPH_CHECK(isnan(tb->wall_weight), CLSPH_E_INPUT,
              "%s:%d: turbulence: wall_weight belongs to wcsph-riemann's wall model (w_s of Wang, "
              "Sun & Hu eq 40); %s has none: drop it",
              sc->case_path, tb->line, sim->scheme->name);
  CLSPH_CHECK(tb->delay == 0.0, CLSPH_E_INPUT,
              "%s:%d: turbulence: delay (the model's delayed start, Wang, Sun & Hu sec 5.2) is "
              "wcsph-riemann's; %s starts the model at once: drop it",
              sc->case_path, tb->line, sim->scheme->name);
  t->on = 1;
  CLSPH_TRY(kepsilon_create(sim, NAN, &t->ke));
  /* the vertices' own velocity starts as their wall's (eq 24) */
  uv = calloc(2 * geo->n + 2, sizeof *uv);
  CLSPH_CHECK(uv != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t i = 0; i < 2 * geo->n; ++i) uv[i] = (real)geo->v[i];
  struct pset *ps = &sim->ps;
  CLSPH_TRY(pset_add(ps, sim->dev, "u_vertex", 2 * sizeof(real), uv, &t->f_uvert));
  pset_describe(ps, t->f_uvert, PF_REAL, 0, 0); /* state: checkpoints keep every field */
  CLSPH_TRY(pset_add(ps, sim->dev, "u_star", sizeof(real), NULL, &t->f_ufric));
  pset_describe(ps, t->f_ufric, PF_REAL, 1, 1);
  CLSPH_TRY(pset_add(ps, sim->dev, "y_plus", sizeof(real), NULL, &t->f_yplus));
  pset_describe(ps, t->f_yplus, PF_REAL, 1, 1);
  CLSPH_TRY(prog_kernel(sim->prog, "usaw_turb_transport", &t->k_trans));
  CLSPH_TRY(prog_kernel(sim->prog, "usaw_turb_update", &t->k_update));
  CLSPH_TRY(prog_kernel(sim->prog, "usaw_turb_wall_shear", &t->k_force));
  CLSPH_TRY(kern_buffer(sim->dev, (geo->nseg + 1) * sizeof(cl_uint), NULL, &t->d_in_group,
                        "segment group mask"));
  CLSPH_TRY(kern_buffer(sim->dev, 4 * ps->cap * sizeof(real), NULL, &t->d_force,
                        "wall shear by particle"));
done:
  free(uv);
  return st;
}

enum clsph_status usaw_turb_predict_args(struct sim *sim, struct usaw_turb *t, cl_mem d_ggam,
                                         cl_kernel k, cl_uint *i)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  if (!t->on) goto done;
  cl_mem nut = pset_mem(ps, t->ke.f_nut), uv = pset_mem(ps, t->f_uvert);
  cl_mem uf = pset_mem(ps, t->f_ufric), yp = pset_mem(ps, t->f_yplus);
  ARG(k, *i, nut);
  ARG(k, *i, uv);
  ARG(k, *i, d_ggam);
  ARG(k, *i, uf);
  ARG(k, *i, yp);
done:
  return st;
}

enum clsph_status usaw_turb_advance(struct sim *sim, struct usaw_turb *t, struct usaw_walls *w,
                                    cl_mem d_gam, double dt, double d_min)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  cl_uint i;
  if (!t->on) goto done;
  const real rdt = (real)dt, nu = (real)sim->scene->nu, dm = (real)d_min;
  const real dr0 = (real)sim->scene->dr;
  cl_mem vel = pset_mem(ps, sim->f_vel), uv = pset_mem(ps, t->f_uvert);
  cl_mem k = pset_mem(ps, t->ke.f_k), eps = pset_mem(ps, t->ke.f_eps);
  cl_mem nut = pset_mem(ps, t->ke.f_nut), id = pset_mem(ps, sim->f_id);
  CLSPH_TRY(usaw_kernel_prefix(sim, w, d_gam, t->k_trans, &i));
  ARG(t->k_trans, i, vel);
  ARG(t->k_trans, i, uv);
  ARG(t->k_trans, i, k);
  ARG(t->k_trans, i, eps);
  ARG(t->k_trans, i, nut);
  ARG(t->k_trans, i, rdt);
  ARG(t->k_trans, i, nu);
  ARG(t->k_trans, i, dm);
  ARG(t->k_trans, i, dr0);
  ARG(t->k_trans, i, t->ke.d_knew);
  ARG(t->k_trans, i, t->ke.d_enew);
  ARG(t->k_trans, i, t->ke.d_clips);
  CLSPH_TRY(kern_launch(sim->dev, t->k_trans, ps->n, NULL));
  CLSPH_TRY(usaw_kernel_prefix(sim, w, d_gam, t->k_update, &i));
  ARG(t->k_update, i, id);
  ARG(t->k_update, i, t->ke.d_knew);
  ARG(t->k_update, i, t->ke.d_enew);
  ARG(t->k_update, i, dm);
  ARG(t->k_update, i, k);
  ARG(t->k_update, i, eps);
  ARG(t->k_update, i, nut);
  ARG(t->k_update, i, t->ke.d_nut2);
  CLSPH_TRY(kern_launch(sim->dev, t->k_update, ps->n, NULL));
  CLSPH_TRY(kepsilon_step_end(sim, &t->ke));
done:
  return st;
}

enum clsph_status usaw_turb_wall_force(struct sim *sim, struct usaw_turb *t, struct usaw_walls *w,
                                       cl_mem d_gam, double d_min, const char *group,
                                       double viscous[2])
{
  enum clsph_status st = CLSPH_OK;
  const struct geom *geo = &sim->geom;
  const struct scene *sc = sim->scene;
  const size_t n = sim->ps.n;
  cl_uint *mask = calloc(geo->nseg + 1, sizeof *mask);
  real *f = calloc(4 * n + 4, sizeof *f);
  cl_uint i;
  CLSPH_CHECK(mask != NULL && f != NULL, CLSPH_E_NOMEM, "out of memory");
  double len = 0.0; /* the group's length */
  for (size_t s = 0; s < geo->nseg; ++s) {
    mask[s] = strcmp(sc->walls[geo->seg_wall[s]].group, group) == 0;
    if (mask[s]) len += geo->seg_len[s];
  }
  CLSPH_TRY(kern_write(sim->dev, t->d_in_group, (geo->nseg + 1) * sizeof *mask, mask));
  const real nu = (real)sc->nu, dm = (real)d_min;
  cl_mem vel = pset_mem(&sim->ps, sim->f_vel), index = pset_mem(&w->ps, w->f_index);
  CLSPH_TRY(usaw_kernel_prefix(sim, w, d_gam, t->k_force, &i));
  ARG(t->k_force, i, vel);
  ARG(t->k_force, i, index);
  ARG(t->k_force, i, t->d_in_group);
  ARG(t->k_force, i, nu);
  ARG(t->k_force, i, dm);
  ARG(t->k_force, i, t->d_force);
  CLSPH_TRY(kern_launch(sim->dev, t->k_force, n, NULL));
  CLSPH_TRY(kern_read(sim->dev, t->d_force, 4 * n * sizeof *f, f));
  double sx = 0.0, sy = 0.0, sw = 0.0;
  for (size_t k = 0; k < n; ++k) {
    sx += (double)f[4 * k];
    sy += (double)f[4 * k + 1];
    sw += (double)f[4 * k + 2];
  }
  /* the mean shear over the group (turbulence.cl, usaw_turb_wall_shear) times its length */
  viscous[0] = sw > 0.0 ? sc->rho0 * len * sx / sw : 0.0;
  viscous[1] = sw > 0.0 ? sc->rho0 * len * sy / sw : 0.0;
done:
  free(f);
  free(mask);
  return st;
}

void usaw_turb_destroy(struct usaw_turb *t)
{
  cl_kernel *ks[] = {&t->k_trans, &t->k_update, &t->k_force};
  for (size_t k = 0; k < sizeof ks / sizeof *ks; ++k)
    if (*ks[k] != NULL) clReleaseKernel(*ks[k]);
  kern_release(&t->d_in_group);
  kern_release(&t->d_force);
  kepsilon_destroy(&t->ke);
}
