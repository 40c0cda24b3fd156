/* frames.h: the frames of a run (clsph run --frames, clsph render) around the render module:
 * where they go, which field, and the movie at the end (see frames.c). */
#ifndef CLSPH_FRAMES_H
#define CLSPH_FRAMES_H

#include "render.h"
#include "scene.h"

/** What the command line and the case ask of frames. */
struct frames_opts {
  struct render_opts render; /* field, size, colour range and map, font */
  int movie;                 /* assemble the movie at the end */
  int fps;                   /* its frame rate */
};

struct frames;

/** @brief Defaults: speed, 1280 x 720, automatic range and map, a movie at 10 frames/s. */
void frames_defaults(struct frames_opts *o);
/** @brief Apply a case's render { } choices (field, range, colour map, camera) to o; `where` (the
 *  case or the snapshot) heads the message of a camera that cannot see. */
enum clsph_status frames_apply_case(const struct scene_render *r, const char *where,
                                    struct frames_opts *o);
/** @brief Start the frames of a run: resolve the field against the arrays there are (an unknown
 *  field lists the fields), create OUT/frames and open the renderer. Nothing is drawn yet. */
enum clsph_status frames_open(const struct frames_opts *o, const char *out_dir, int narrays,
                              const char *const *names, const int *ncomp, struct frames **out);
/** @brief The field being drawn. */
const struct field_spec *frames_field(const struct frames *fr);
/** @brief Fix the colour range of the frames to come. */
void frames_set_range(struct frames *fr, double lo, double hi);
/** @brief 3-D: the box the default camera sees whole (render_set_view3). */
void frames_set_view3(struct frames *fr, const double box[6]);
/** @brief Draw frame number `index` (OUT/frames/FIELD_NNNNNN.png). */
enum clsph_status frames_write(struct frames *fr, const struct render_input *in, int index);
/** @brief The movie (OUT/FIELD.mp4) of the frames written, with the frames before them that are
 *  there from an earlier run (a restart), and a line saying where everything is (unless quiet).
 *  No ffmpeg: a warning, and the frames stay. */
enum clsph_status frames_finish(struct frames *fr, int quiet);
/** @brief Release everything (NULL is fine). */
void frames_close(struct frames *fr);
/** @brief The region a frame shows: the scene's domain box (NULL: none) together with the
 *  walls' box; all 0 when there is neither (the renderer then fits the particles). */
void frames_view(const double *domain, int nwalls, const struct render_wall *walls, double view[4]);

#endif /* CLSPH_FRAMES_H */
