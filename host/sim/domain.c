/* domain.c: the fluid stays in the scene's domain: a fluid particle more than a spacing beyond the
 * domain's box on a non-periodic axis (but on the side gravity points away from) raises the
 * escape flag, which the time loop reads with the others (kernels/common/domain.cl). */
#include <math.h>

#include "clsph_config.h"
#include "kern.h"
#include "sim.h"

enum clsph_status sim_domain_check(struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *s = sim->scene;
  const double g = hypot(hypot(s->gravity[0], s->gravity[1]), s->gravity[2]);
  real4 lo = {{0}}, hi = {{0}};
  for (int a = 0; a < s->dim; ++a) {
    /* the side gravity points away from is open (up: −g·e_a > g/2 for the upper side) */
    const int up_hi = g > 0.0 && -s->gravity[a] > 0.5 * g,
              up_lo = g > 0.0 && s->gravity[a] > 0.5 * g;
    lo.s[a] = up_lo ? (real)-HUGE_VAL : (real)(s->lo[a] - s->dr);
    hi.s[a] = up_hi ? (real)HUGE_VAL : (real)(s->hi[a] + s->dr);
  }
  cl_uint n = (cl_uint)sim->ps.n;
  cl_mem pos = pset_mem(&sim->ps, sim->f_pos), kind = pset_mem(&sim->ps, sim->f_kind);
  if (n == 0) goto done;
  CLSPH_TRY(KERN_SET(sim->k_domain, KARG(n), KARG(pos), KARG(kind), KARG(lo), KARG(hi),
                     KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, sim->k_domain, sim->ps.n, NULL));
done:
  return st;
}
