/* test_movie.c: frames into an MP4 through ffmpeg, checked with ffprobe: H.264, the frame count
 * and the size (an odd-sized frame is padded to even sides, which yuv420p needs). Skipped (77)
 * where ffmpeg or ffprobe is not installed. No OpenCL needed. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "render.h"
#include "tcheck.h"

#define NX 12

/* Is `prog` an executable on the PATH? */
static int on_path(const char *prog)
{
  const char *path = getenv("PATH");
  char dir[1024], file[1200];
  while (path != NULL && *path != '\0') {
    size_t len = strcspn(path, ":");
    snprintf(dir, sizeof dir, "%.*s", (int)len, path);
    snprintf(file, sizeof file, "%s/%s", len ? dir : ".", prog);
    if (access(file, X_OK) == 0) return 1;
    path += len + (path[len] == ':');
  }
  return 0;
}

/* ffprobe's codec, size and decoded frame count of the video stream. */
static int probe(const char *mp4, char *codec, size_t size, int *w, int *h, int *frames)
{
  char cmd[1400], line[256];
  snprintf(cmd, sizeof cmd,
           "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
           "stream=codec_name,width,height,nb_read_frames -of default=noprint_wrappers=1 '%s'",
           mp4);
  FILE *p = popen(cmd, "r");
  if (p == NULL) return 0;
  *w = *h = *frames = -1;
  codec[0] = '\0';
  while (fgets(line, sizeof line, p) != NULL) {
    line[strcspn(line, "\n")] = '\0';
    printf("ffprobe: %s\n", line);
    if (strncmp(line, "codec_name=", 11) == 0)
      snprintf(codec, size, "%.*s", (int)size - 1, line + 11);
    sscanf(line, "width=%d", w);
    sscanf(line, "height=%d", h);
    sscanf(line, "nb_read_frames=%d", frames);
  }
  return pclose(p) == 0;
}

static void movie(const char *dir, int width, int height, int count, int want_w, int want_h)
{
  static double pos[2 * NX * NX], vel[2 * NX * NX], vol[NX * NX], kind[NX * NX];
  static const double box[] = {0, 0, 1, 0, 1, 1, 0, 1};
  char sub[1100], pattern[1200], path[1300], mp4[1200], codec[64];
  struct render *r = NULL;
  struct render_opts o;
  struct field_spec f;
  const char *names[] = {"pos", "vel", "vol", "kind"};
  const int nc[] = {2, 2, 1, 1};
  snprintf(sub, sizeof sub, "%s/movie_%dx%d", dir, width, height);
  mkdir(sub, 0755);
  render_defaults(&o);
  o.width = width;
  o.height = height;
  o.fixed = 1;
  o.lo = 0.0;
  o.hi = 1.0;
  int ok = field_find("speed", 4, names, nc, &f) == CLSPH_OK && render_create(&o, &r) == CLSPH_OK;
  TC_CHECK(ok, "renderer of %d x %d frames", width, height);
  if (!ok) return;
  struct render_array arrays[4] = {
      {"pos", 2, pos}, {"vel", 2, vel}, {"vol", 1, vol}, {"kind", 1, kind}};
  struct render_wall wall = {4, box, 1};
  struct render_input in;
  memset(&in, 0, sizeof in);
  in.n = NX * NX;
  in.narrays = 4;
  in.arrays = arrays;
  in.nwalls = 1;
  in.walls = &wall;
  in.case_name = "movie";
  snprintf(pattern, sizeof pattern, "%s/speed_%%06d.png", sub);
  for (int k = 0; k < count; ++k) { /* a turning flow, one frame per step */
    for (int j = 0; j < NX; ++j) {
      for (int i = 0; i < NX; ++i) {
        const int q = j * NX + i;
        pos[2 * q] = (i + 0.5) / NX;
        pos[2 * q + 1] = (j + 0.5) / NX;
        vel[2 * q] = cos(0.5 * k + pos[2 * q]);
        vel[2 * q + 1] = 0.0;
        vol[q] = 1.0 / (NX * NX);
        kind[q] = 0;
      }
    }
    in.time = 0.1 * k;
    snprintf(path, sizeof path, "%s/speed_%06d.png", sub, k + 3); /* from 3, as on a restart */
    TC_CHECK(render_frame(r, &f, &in, path, NULL, NULL) == CLSPH_OK, "frame %d", k);
  }
  render_destroy(r);
  snprintf(mp4, sizeof mp4, "%s/speed.mp4", sub);
  remove(mp4);
  int made = 0;
  TC_CHECK(movie_make(pattern, 3, count, 6, mp4, &made) == CLSPH_OK && made, "ffmpeg made %s", mp4);
  int w = 0, h = 0, frames = 0;
  TC_CHECK(probe(mp4, codec, sizeof codec, &w, &h, &frames), "ffprobe reads %s", mp4);
  TC_CHECK(strcmp(codec, "h264") == 0, "H.264 video (got '%s')", codec);
  TC_CHECK(w == want_w && h == want_h, "%d x %d frames give a %d x %d movie (got %d x %d)", width,
           height, want_w, want_h, w, h);
  TC_CHECK(frames == count, "%d frames in the movie (got %d)", count, frames);
}

int main(int argc, char **argv)
{
  const char *dir = argc > 1 ? argv[1] : ".";
  const char *env = getenv("CLSPH_FFMPEG");
  if (!(env != NULL && env[0] != '\0' ? access(env, X_OK) == 0 : on_path("ffmpeg")) ||
      !on_path("ffprobe")) {
    printf("skip: ffmpeg or ffprobe is not installed (apt-get install ffmpeg)\n");
    return TC_SKIP;
  }
  movie(dir, 320, 240, 12, 320, 240);
  movie(dir, 321, 241, 5, 322, 242);
  return tc_finish("test_movie");
}
