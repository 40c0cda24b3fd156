/* movie.c: frames into an MP4 movie with ffmpeg, run as a child process (no shell: the arguments
 * go to ffmpeg as they are). The video is H.264 (libx264) in yuv420p, the pixel format every
 * player reads, which needs even sides: an odd frame is padded by one pixel. ffmpeg is a tool
 * found at run time ($CLSPH_FFMPEG, else `ffmpeg` on the PATH), not a library we link: when it is
 * missing the frames stay and a warning says how to make the movie later. */
#include "render.h"

#include <errno.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

extern char **environ;

enum clsph_status movie_make(const char *pattern, int first, int count, int fps, const char *mp4,
                             int *made)
{
  enum clsph_status st = CLSPH_OK;
  char rate[32], start[32], frames[32];
  const char *env = getenv("CLSPH_FFMPEG");
  const char *ffmpeg = env != NULL && env[0] != '\0' ? env : "ffmpeg";
  *made = 0;
  CLSPH_CHECK(count > 0, CLSPH_E_INPUT, "no frames to make %s from", mp4);
  CLSPH_CHECK(fps > 0, CLSPH_E_INPUT, "a movie needs a positive frame rate, not %d", fps);
  snprintf(rate, sizeof rate, "%d", fps);
  snprintf(start, sizeof start, "%d", first);
  snprintf(frames, sizeof frames, "%d", count);
  char *const argv[] = {(char *)ffmpeg,
                        "-nostdin",
                        "-y",
                        "-loglevel",
                        "error",
                        "-framerate",
                        rate,
                        "-start_number",
                        start,
                        "-i",
                        (char *)pattern,
                        "-frames:v",
                        frames,
                        "-vf",
                        "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                        "-c:v",
                        "libx264",
                        "-pix_fmt",
                        "yuv420p",
                        "-movflags",
                        "+faststart",
                        (char *)mp4,
                        NULL};
  pid_t pid = 0;
  int err = posix_spawnp(&pid, ffmpeg, NULL, NULL, argv, environ);
  if (err == ENOENT || err == EACCES) {
    log_warn("no movie: %s was not found (install it with 'apt-get install ffmpeg'); the frames "
             "stay (%s)",
             ffmpeg, pattern);
    goto done;
  }
  CLSPH_CHECK(err == 0, CLSPH_E_IO, "cannot run %s for %s: %s", ffmpeg, mp4, strerror(err));
  int status = 0;
  pid_t w;
  do {
    w = waitpid(pid, &status, 0);
  } while (w < 0 && errno == EINTR);
  CLSPH_CHECK(w == pid, CLSPH_E_IO, "waiting for %s: %s", ffmpeg, strerror(errno));
  CLSPH_CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0, CLSPH_E_IO,
              "%s failed (%s %d) making %s from %d frames %s from %d; the frames stay", ffmpeg,
              WIFEXITED(status) ? "exit status" : "signal",
              WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status), mp4, count, pattern,
              first);
  *made = 1;
done:
  return st;
}
