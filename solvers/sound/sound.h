/* sound.h: the velocity scale of a scene for the weakly-compressible schemes' sound speed. */
#ifndef CLSPH_SOUND_H
#define CLSPH_SOUND_H

#include "geometry.h"
#include "scene.h"

/** The scene's velocity scale U and what sets it. */
struct sound_scale {
  double u;       /* m/s (0: nothing drives the flow) */
  char what[160]; /* "the walls' speed", "√(2 g D), D = 0.3 m the fluid's depth ...", ... */
};

/** @brief The largest speed the scene's drives give its fluid (walls, inflows, flow-rate control,
 *  initial velocities, the fall through the fluid's depth under gravity); see sound.c. */
void sound_velocity_scale(const struct scene *s, const struct geom *g, struct sound_scale *vs);

#endif /* CLSPH_SOUND_H */
