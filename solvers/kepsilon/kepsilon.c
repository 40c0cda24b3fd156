/* kepsilon.c: the k-ε model's host side shared by the schemes that have it (kepsilon.h). */
#include "kepsilon.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clsph_config.h"

static enum clsph_status field(struct sim *sim, const char *name, const real *init, int *f)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(pset_add(&sim->ps, sim->dev, name, sizeof(real), init, f));
  pset_describe(&sim->ps, *f, PF_REAL, 1, 1);
done:
  return st;
}

enum clsph_status kepsilon_create(struct sim *sim, double nu_t_start, struct kepsilon *ke)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene_turbulence *t = &sim->scene->turb;
  const struct geom *geo = &sim->geom;
  const size_t n = geo->n, cap = sim->ps.cap;
  memset(ke, 0, sizeof *ke);
  ke->f_k = ke->f_eps = ke->f_nut = -1;
  real *buf = calloc(n + 1, sizeof *buf);
  CLSPH_CHECK(buf != NULL, CLSPH_E_NOMEM, "out of memory");
  for (size_t i = 0; i < n; ++i) buf[i] = (real)(isfinite(geo->k0[i]) ? geo->k0[i] : t->k);
  CLSPH_TRY(field(sim, "k", buf, &ke->f_k));
  for (size_t i = 0; i < n; ++i)
    buf[i] = (real)(isfinite(geo->eps0[i]) ? geo->eps0[i] : t->epsilon);
  CLSPH_TRY(field(sim, "epsilon", buf, &ke->f_eps));
  for (size_t i = 0; i < n; ++i) {
    const double k = isfinite(geo->k0[i]) ? geo->k0[i] : t->k;
    const double e = isfinite(geo->eps0[i]) ? geo->eps0[i] : t->epsilon;
    const double nut = isfinite(nu_t_start) ? nu_t_start : 0.09 * k * k / e; /* C_μ k²/ε */
    buf[i] = (real)nut;
    ke->nut_max = fmax(ke->nut_max, nut);
  }
  CLSPH_TRY(field(sim, "nu_t", buf, &ke->f_nut));
  CLSPH_TRY(kern_buffer(sim->dev, cap * sizeof(real), NULL, &ke->d_knew, "new k"));
  CLSPH_TRY(kern_buffer(sim->dev, cap * sizeof(real), NULL, &ke->d_enew, "new epsilon"));
  CLSPH_TRY(kern_buffer(sim->dev, cap * 2 * sizeof(real), NULL, &ke->d_nut2, "eddy viscosity"));
  const cl_uint zero[2] = {0, 0};
  CLSPH_TRY(kern_buffer(sim->dev, sizeof zero, zero, &ke->d_clips, "clip counts"));
  sim->turb_clip_counts = ke->h_clips;
done:
  free(buf);
  return st;
}

enum clsph_status kepsilon_step_end(struct sim *sim, struct kepsilon *ke)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(sim_max_norm_deferred(sim, ke->d_nut2, KIND_FLUID, &ke->nut_max));
  CLSPH_TRY(kern_read_nb(sim->dev, ke->d_clips, 0, sizeof ke->h_clips, ke->h_clips));
done:
  return st;
}

void kepsilon_destroy(struct kepsilon *ke)
{
  cl_mem *ms[] = {&ke->d_knew, &ke->d_enew, &ke->d_nut2, &ke->d_clips};
  for (size_t i = 0; i < sizeof ms / sizeof *ms; ++i) kern_release(ms[i]);
}
