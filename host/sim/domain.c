/* domain.c: the fluid stays in the scene's domain: a fluid particle more than a spacing beyond the
 * domain's box on a non-periodic axis (but on the side gravity points away from), or beyond it
 * at all while above that side (over the rim of the walls on the domain's edge) has left it:
 * domain.cl marks it and counts it in d_flags[3], and the time loop drops it or stops
 * (host/sim/checks.c, run { checks = { escaped } }). */
#include <math.h>

#include "clsph_config.h"
#include "kern.h"
#include "sim.h"

void sim_open_sides(const struct scene *s, int open_lo[3], int open_hi[3])
{
  const double g = hypot(hypot(s->gravity[0], s->gravity[1]), s->gravity[2]);
  for (int a = 0; a < 3; ++a) {
    /* up: −g·e_a > g/2 for the upper side */
    open_hi[a] = a < s->dim && !s->periodic[a] && g > 0.0 && -s->gravity[a] > 0.5 * g;
    open_lo[a] = a < s->dim && !s->periodic[a] && g > 0.0 && s->gravity[a] > 0.5 * g;
  }
}

void sim_domain_box(const struct sim *sim, real4 *lo, real4 *hi, real *margin, cl_uint *open)
{
  const struct scene *s = sim->scene;
  int up_lo[3], up_hi[3];
  sim_open_sides(s, up_lo, up_hi);
  *lo = (real4){{0}};
  *hi = (real4){{0}};
  *open = 0;
  for (int a = 0; a < s->dim; ++a) {
    lo->s[a] = (real)s->lo[a];
    hi->s[a] = (real)s->hi[a];
    *open |= (up_hi[a] ? 1u << a : 0u) | (up_lo[a] ? 16u << a : 0u);
  }
  *margin = (real)s->dr;
}

enum clsph_status sim_step_end(struct sim *sim, int nvec, const cl_mem *vec, const int *kinds,
                               const size_t *slot)
{
  enum clsph_status st = CLSPH_OK;
  real4 lo, hi;
  real margin;
  cl_uint open;
  sim_domain_box(sim, &lo, &hi, &margin, &open);
  CLSPH_CHECK(nvec >= 0 && nvec <= 2, CLSPH_E_INPUT, "step_end takes 0 to 2 vectors, not %d", nvec);
  const cl_uint n = (cl_uint)sim->ps.n, nv = (cl_uint)nvec;
  cl_mem pos = pset_mem(&sim->ps, sim->f_pos), kind = pset_mem(&sim->ps, sim->f_kind);
  cl_mem v0 = nvec > 0 ? vec[0] : pos, v1 = nvec > 1 ? vec[1] : v0;
  const cl_int k0 = nvec > 0 ? kinds[0] : -1, k1 = nvec > 1 ? kinds[1] : -1;
  const cl_uint at0 = nvec > 0 ? (cl_uint)slot[0] : 0u, at1 = nvec > 1 ? (cl_uint)slot[1] : 0u;
  const size_t groups = sim_reduce_groups(sim->ps.n);
  CLSPH_TRY(KERN_SET(sim->k_step_end, KARG(n), KARG(pos), KARG(kind), KARG(lo), KARG(hi),
                     KARG(margin), KARG(open), KARG(nv), KARG(v0), KARG(k0), KARG(at0), KARG(v1),
                     KARG(k1), KARG(at1), KARG(sim->d_deferred), KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch_wg(sim->dev, sim->k_step_end, groups * 64, 64, NULL));
done:
  return st;
}
