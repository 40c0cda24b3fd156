/* sound.c: the velocity scale U of a scene, from which the weakly-compressible schemes take their
 * default sound speed c0 = 10 U (wcsph-usaw, wcsph-riemann) and check the Mach number U/c0. */
#include "sound.h"

#include <math.h>
#include <stdio.h>

/* U is the largest of: the walls' speeds (sliding, or |ω| times the wall vertex farthest from the
 * centre: a polyline's farthest point from a point is one of its vertices), the inflow speeds,
 * the flow-rate control's target, the initial fluid speeds (fill velocities) and, under gravity,
 * the speed √(2 g D) of a fall through the fluid's depth D, its extent along g: the highest less
 * the lowest fluid particle along −g, plus dr (the particles sit dr/2 inside the filled region),
 * not the domain's height (raising a tank's side walls changed c0 before).
 * Free-surface flows: the paper fixes c0 at "10 times the maximum flow velocity" (Leroy et al.
 * 2014 sec 3.4, after eq 49) and scales its dam break by √(g H), H the initial fluid depth
 * (sec 4.3, t+ = t √(g/H)). Fluid set going by gravity alone takes its speed from the height it
 * falls, at most √(2 g D) for the whole depth (½ u² = g D), √2 times the paper's scale: it is
 * the larger of the two and the nearer to the largest speeds measured. In the dam break of
 * cases/dam_break.lua (H = 0.3 m, n = 20 and 40) the fluid's largest speed, at the tip of its
 * front, reaches 3.1 to 3.3 m/s = 1.3 √(2 g H), 1.8 √(g H): Mach 0.13 against 10 √(2 g D), where
 * 10 √(g D) would give 0.19. The paper's own wedge run took 20 m/s = 4.5 √(2 g H) (H = 1 m);
 * cases/dam_break_wedge.lua keeps that value explicitly. */
void sound_velocity_scale(const struct scene *s, const struct geom *g, struct sound_scale *vs)
{
  double u = 0.0;
  const char *what = "nothing: no drive";
  for (int w = 0; w < s->nwalls; ++w) {
    const struct scene_wall *wl = &s->walls[w];
    double uw = hypot(hypot(wl->velocity[0], wl->velocity[1]), wl->velocity[2]);
    for (int k = 0; k < wl->npts && wl->omega != 0.0; ++k)
      uw = fmax(uw, fabs(wl->omega) *
                        hypot(wl->pts[2 * k] - wl->centre[0], wl->pts[2 * k + 1] - wl->centre[1]));
    if (uw > u) {
      u = uw;
      what = "the walls' speed";
    }
  }
  for (int k = 0; k < s->nsections; ++k)
    if (fabs(s->sections[k].velocity) > u) {
      u = fabs(s->sections[k].velocity);
      what = "the inflow speed";
    }
  if (s->flow.on && fabs(s->flow.velocity) > u) {
    u = fabs(s->flow.velocity);
    what = "the flow-rate control's target";
  }
  const size_t dim = g->dim == 3 ? 3 : 2; /* the geometry's arrays are n x dim */
  for (size_t i = 0; i < g->nfluid; ++i) {
    const double *v = g->v + dim * i;
    const double vi = hypot(hypot(v[0], v[1]), dim == 3 ? v[2] : 0.0);
    if (vi > u) {
      u = vi;
      what = "the initial fluid speed";
    }
  }
  snprintf(vs->what, sizeof vs->what, "%s", what);
  const double gz = dim == 3 ? s->gravity[2] : 0.0;
  const double gn = hypot(hypot(s->gravity[0], s->gravity[1]), gz);
  if (gn > 0.0 && g->nfluid > 0) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (size_t i = 0; i < g->nfluid; ++i) {
      const double *x = g->x + dim * i;
      double gx = s->gravity[0] * x[0] + s->gravity[1] * x[1];
      if (dim == 3) gx += gz * x[2];
      const double z = -gx / gn;
      lo = fmin(lo, z);
      hi = fmax(hi, z);
    }
    const double depth = hi - lo + s->dr, uf = sqrt(2.0 * gn * depth);
    if (uf > u) {
      u = uf;
      snprintf(vs->what, sizeof vs->what, "√(2 g D), D = %.4g m the fluid's depth along gravity",
               depth);
    }
  }
  vs->u = u;
}
