/* cli.c: command-line parsing and help. */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "render.h"

void cli_usage(FILE *f)
{
  fputs("usage: clsph COMMAND [OPTIONS]\n"
        "\n"
        "clsph is a particle (SPH) flow solver in C11 with OpenCL kernels.\n"
        "\n"
        "commands:\n"
        "  run CASE              run a case script (cases/NAME.lua); outputs in --out\n"
        "  info CASE             particle counts, active modules, memory and time step of a\n"
        "                        case, without running it\n"
        "  render OUTDIR         frames and a movie from the snapshots of a run (its --out\n"
        "                        folder): OUTDIR/frames/FIELD_NNNNNN.png, OUTDIR/FIELD.mp4\n"
        "  devices               list OpenCL platforms and devices (index, type, OpenCL version,\n"
        "                        memory, double precision)\n"
        "  demo                  the default scene: a particle lattice, its device neighbour\n"
        "                        search and the SPH operators against exact derivatives\n"
        "  bench neighbours      neighbour search and operator sweeps for 1e4, 1e5, 1e6\n"
        "                        particles, against a native OpenMP loop\n"
        "  bench psolve          pressure solves of 1e3 .. 1e6 unknowns: BiCGStab (stored or\n"
        "                        recomputed operator, two preconditioners) and UMFPACK; writes\n"
        "                        --out/psolve.csv and psolve.png\n"
        "  bench render          frame times (median) for 1e4, 1e5, 1e6 particles at 1280 x 720\n"
        "  bench dambreak        DualSPHysics's CaseDambreakVal2D dam break through the time loop\n"
        "                        (cases/dam_break_dsph.lua, or --case FILE; --set applies): wall\n"
        "                        time, steps, particle-steps/s, pair interactions/s and device\n"
        "                        time per kernel, beside DualSPHysics 5.4's figures\n"
        "  help                  this text\n"
        "\n"
        "options:\n"
        "  --set NAME=VALUE      override a parameter the case declares (repeatable), e.g.\n"
        "                        --set dr=0.005 --set t_end=0.1\n"
        "  --out DIR             output folder of `run` (default out/CASE); of `render`, where\n"
        "                        the frames and the movie go (default OUTDIR)\n"
        "  --restart FILE        continue a run from one of its checkpoints (in its folder, the\n"
        "                        outputs after the checkpoint are removed)\n"
        "  --overwrite           run, bench dambreak: clear the outputs of an earlier run in\n"
        "                        --out (without it such a folder is refused)\n"
        "  --case-instructions N the case script's budget of Lua instructions for each call\n"
        "                        into it (top level, a fill's velocity, metrics(); default 1e9)\n"
        "  --case-memory MIB     the most memory the case script may hold (default 512)\n",
        f);
  fputs(
      "  --quiet               no progress line (and no --profile table)\n"
      "  --profile             time every kernel launch and transfer of `run` on the device\n"
      "                        (OpenCL profiling events): a table by kernel at the end, and\n"
      "                        \"profile\" in summary.json\n"
      "  --frames              run: a frame (PNG) with each snapshot in OUT/frames, and a\n"
      "                        movie OUT/FIELD.mp4 at the end (ffmpeg)\n"
      "  --field NAME          the field frames show: speed, vorticity, p, vel_x, vel_y, kind,\n"
      "                        or any field the scheme stores (default: the case's render {\n"
      "                        field }, else speed)\n"
      "  --range LO,HI|auto    colour range of frames (default: the case's, else auto: each\n"
      "                        frame's 0.5th to 99.5th percentile in a run, over every snapshot\n"
      "                        in `render`)\n"
      "  --colormap NAME       auto, viridis (magnitudes), coolwarm (signed), kind\n"
      "  --size WxH            frame size in pixels (default 1280x720)\n"
      "  --fps N               frames per second of the movie (default 10)\n"
      "  --no-movie            frames only\n"
      "  --font FILE           TrueType font of frames (default $CLSPH_FONT, else DejaVu Sans)\n"
      "  --slice AXIS=VALUE    render of a 3-D run: the particles within half a spacing of the\n"
      "                        plane AXIS = VALUE (m), seen along AXIS\n"
      "  --camera E,A[,U]      frames of a 3-D run: the eye EX,EY,EZ, the point AX,AY,AZ it looks\n"
      "                        at and up UX,UY,UZ (default 0,0,1), m (default: the case's\n"
      "                        render { camera }, else one that sees the fluid whole)\n"
      "  --fov DEG             the camera's vertical field of view (default 30)\n"
      "  --device N            device index from `clsph devices` (default: $CLSPH_DEVICE, else\n"
      "                        the first GPU, else the first CPU)\n"
      "  --device-memory MIB   run, info: the most device memory a run may use (default: the\n"
      "                        device's); a scene that needs more is refused before it runs\n"
      "  --kernel-dir DIR      read OpenCL sources from DIR instead of the embedded copy\n"
      "  --prog-cache-dir DIR  cache of built programs (default ~/.cache/clsph; '' disables)\n"
      "  --fast-math           allow -cl-fast-relaxed-math (off by default)\n"
      "  --bench-sizes LIST    particle counts for `bench`, e.g. 1e4,1e5 (default 1e4,1e5,1e6)\n"
      "  --bench-reps N        repetitions per figure; the median is printed (default 7; 1\n"
      "                        for bench dambreak, a run of minutes)\n"
      "  --case FILE           bench dambreak: the case script to time (default\n"
      "                        cases/dam_break_dsph.lua); outputs go to a temporary folder,\n"
      "                        removed afterwards, unless --out DIR\n"
      "  --bench-direct-max N  largest UMFPACK solve of `bench psolve` (default 2e5)\n"
      "  --demo-dr DR          lattice spacing of the demo on the unit square (default 0.01)\n"
      "  --verbose             debug messages (build options, cache hits)\n"
      "  -h, --help            this text\n",
      f);
  /* a second string: ISO C keeps a literal under 4095 characters */
  fputs("\n"
        "examples:\n"
        "  clsph run cases/hydrostatic.lua --set dr=0.02 --out out/tank\n"
        "  clsph info cases/hydrostatic.lua\n"
        "  clsph run cases/hydrostatic.lua --restart out/tank/checkpoint_000100.h5\n"
        "  clsph run cases/cavity.lua --set n=40 --set t_end=0.5 --profile\n"
        "  clsph run cases/cavity.lua --set n=30 --set t_end=2 --frames --field vorticity\n"
        "  clsph render out/cavity --field p --range -0.5,0.5 --fps 5\n"
        "  clsph bench render --bench-reps 5\n"
        "  clsph devices\n"
        "  clsph demo --device 0\n"
        "  clsph bench neighbours --bench-sizes 1e4,1e5 --bench-reps 5\n"
        "  clsph bench dambreak --set dp=0.02 --set riemann=0\n",
        f);
}

static enum clsph_status parse_int(const char *opt, const char *text, int lo, int hi, int *out)
{
  enum clsph_status st = CLSPH_OK;
  char *end = NULL;
  errno = 0;
  long v = strtol(text, &end, 10);
  CLSPH_CHECK(errno == 0 && end != text && *end == '\0' && v >= lo && v <= hi, CLSPH_E_INPUT,
              "%s: '%s' is not a whole number from %d to %d", opt, text, lo, hi);
  *out = (int)v;
done:
  return st;
}

static enum clsph_status parse_real(const char *opt, const char *text, double *out)
{
  enum clsph_status st = CLSPH_OK;
  char *end = NULL;
  errno = 0;
  double v = strtod(text, &end);
  CLSPH_CHECK(errno == 0 && end != text && *end == '\0' && v > 0.0, CLSPH_E_INPUT,
              "%s: '%s' is not a positive number", opt, text);
  *out = v;
done:
  return st;
}

/* --range LO,HI or auto */
static enum clsph_status parse_range(const char *text, struct cli *c)
{
  enum clsph_status st = CLSPH_OK;
  char *end = NULL, *end2 = NULL;
  c->range_set = 1;
  if (strcmp(text, "auto") == 0) {
    c->range_auto = 1;
    goto done;
  }
  errno = 0;
  double lo = strtod(text, &end);
  double hi = end != text && *end == ',' ? strtod(end + 1, &end2) : 0.0;
  CLSPH_CHECK(errno == 0 && end != text && *end == ',' && end2 != end + 1 && end2 != NULL &&
                  *end2 == '\0' && isfinite(lo) && isfinite(hi),
              CLSPH_E_INPUT, "--range: '%s' is not LO,HI (two numbers, e.g. 0,1000) or auto", text);
  CLSPH_CHECK(lo < hi, CLSPH_E_INPUT, "--range: '%s': the low end %g must be below the high end %g",
              text, lo, hi);
  c->range_auto = 0;
  c->range[0] = lo;
  c->range[1] = hi;
done:
  return st;
}

/* --size WxH */
static enum clsph_status parse_size(const char *text, int *w, int *h)
{
  enum clsph_status st = CLSPH_OK;
  char *end = NULL, *end2 = NULL;
  errno = 0;
  long a = strtol(text, &end, 10);
  long b = end != text && (*end == 'x' || *end == 'X') ? strtol(end + 1, &end2, 10) : 0;
  CLSPH_CHECK(errno == 0 && end2 != NULL && end2 != end + 1 && *end2 == '\0', CLSPH_E_INPUT,
              "--size: '%s' is not WIDTHxHEIGHT in pixels, e.g. 1280x720", text);
  CLSPH_CHECK(a >= 16 && a <= 8192 && b >= 16 && b <= 8192, CLSPH_E_INPUT,
              "--size: %ldx%ld: each side must be from 16 to 8192 pixels", a, b);
  *w = (int)a;
  *h = (int)b;
done:
  return st;
}

enum clsph_status cli_parse(int argc, char **argv, struct cli *out)
{
  enum clsph_status st = CLSPH_OK;
  static const char *const commands[] = {"run",  "info",  "render", "devices",
                                         "demo", "bench", "help"};
  struct cli c;
  memset(&c, 0, sizeof c);
  c.device = -1;
  c.bench_reps = 0; /* not given: 7, or 1 for bench dambreak (below) */
  c.bench_sizes = NULL;
  c.bench_direct_max = 2e5;
  c.demo_dr = 0.01;

  for (int i = 1; i < argc; ++i) {
    const char *a = argv[i];
    const char *val = i + 1 < argc ? argv[i + 1] : NULL;
    if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
      c.command = "help";
    } else if (strcmp(a, "--verbose") == 0) {
      c.verbose = 1;
    } else if (strcmp(a, "--fast-math") == 0) {
      c.fast_math = 1;
    } else if (strcmp(a, "--quiet") == 0) {
      c.quiet = 1;
    } else if (strcmp(a, "--overwrite") == 0) {
      c.overwrite = 1;
    } else if (strcmp(a, "--profile") == 0) {
      c.profile = 1;
    } else if (strcmp(a, "--frames") == 0) {
      c.frames = 1;
    } else if (strcmp(a, "--no-movie") == 0) {
      c.no_movie = 1;
    } else if (strncmp(a, "--", 2) == 0) {
      CLSPH_CHECK(val != NULL, CLSPH_E_INPUT, "option %s needs a value (see clsph --help)", a);
      if (strcmp(a, "--set") == 0) {
        CLSPH_CHECK(c.nsets < CLI_MAX_SETS, CLSPH_E_INPUT, "--set: at most %d", CLI_MAX_SETS);
        c.sets[c.nsets++] = argv[i + 1];
      } else if (strcmp(a, "--out") == 0) {
        c.out_dir = val;
      } else if (strcmp(a, "--restart") == 0) {
        c.restart = val;
      } else if (strcmp(a, "--case-instructions") == 0) {
        CLSPH_TRY(parse_real(a, val, &c.case_instructions));
        CLSPH_CHECK(c.case_instructions >= 1e4 && c.case_instructions <= 1e15, CLSPH_E_INPUT,
                    "%s: %s is not a budget from 1e4 to 1e15 instructions", a, val);
      } else if (strcmp(a, "--case-memory") == 0) {
        CLSPH_TRY(parse_real(a, val, &c.case_memory));
        CLSPH_CHECK(c.case_memory >= 1.0 && c.case_memory <= 1048576.0, CLSPH_E_INPUT,
                    "%s: %s is not a size from 1 to 1048576 MiB", a, val);
        c.case_memory *= 1048576.0;
      } else if (strcmp(a, "--device") == 0) {
        CLSPH_TRY(parse_int(a, val, 0, 999999, &c.device));
      } else if (strcmp(a, "--device-memory") == 0) {
        CLSPH_TRY(parse_real(a, val, &c.device_memory));
        CLSPH_CHECK(c.device_memory >= 1.0 && c.device_memory <= 1e9, CLSPH_E_INPUT,
                    "%s: %s is not a size from 1 to 1e9 MiB", a, val);
        c.device_memory *= 1048576.0;
      } else if (strcmp(a, "--kernel-dir") == 0) {
        c.kernel_dir = val;
      } else if (strcmp(a, "--prog-cache-dir") == 0) {
        c.cache_dir = val;
      } else if (strcmp(a, "--case") == 0) {
        c.bench_case = val;
      } else if (strcmp(a, "--bench-sizes") == 0) {
        c.bench_sizes = val;
      } else if (strcmp(a, "--bench-direct-max") == 0) {
        CLSPH_TRY(parse_real(a, val, &c.bench_direct_max));
      } else if (strcmp(a, "--bench-reps") == 0) {
        CLSPH_TRY(parse_int(a, val, 1, 1000, &c.bench_reps));
      } else if (strcmp(a, "--demo-dr") == 0) {
        CLSPH_TRY(parse_real(a, val, &c.demo_dr));
      } else if (strcmp(a, "--field") == 0) {
        CLSPH_CHECK(val[0] != '\0' && strlen(val) < RENDER_NAME, CLSPH_E_INPUT,
                    "--field: '%s' is not a field name", val);
        c.field = val;
      } else if (strcmp(a, "--range") == 0) {
        CLSPH_TRY(parse_range(val, &c));
      } else if (strcmp(a, "--colormap") == 0) {
        enum colormap_kind k;
        CLSPH_TRY(colormap_from_name(val, &k));
        c.colormap = val;
      } else if (strcmp(a, "--size") == 0) {
        CLSPH_TRY(parse_size(val, &c.width, &c.height));
      } else if (strcmp(a, "--fps") == 0) {
        CLSPH_TRY(parse_int(a, val, 1, 240, &c.fps));
      } else if (strcmp(a, "--font") == 0) {
        c.font = val;
      } else if (strcmp(a, "--camera") == 0) {
        int k = 0;
        const char *p = val;
        for (; k < 9 && *p != '\0'; ++k) {
          char *end = NULL;
          c.camera[k] = strtod(p, &end);
          CLSPH_CHECK(end != p && isfinite(c.camera[k]) && (*end == ',' || *end == '\0'),
                      CLSPH_E_INPUT,
                      "--camera: '%s' is not EX,EY,EZ,AX,AY,AZ[,UX,UY,UZ] (the eye, the point "
                      "it looks at and, optionally, up; m)",
                      val);
          p = *end == ',' ? end + 1 : end;
        }
        CLSPH_CHECK((k == 6 || k == 9) && *p == '\0', CLSPH_E_INPUT,
                    "--camera: '%s' gives %d numbers: give 6 (eye, look-at) or 9 (and up)", val, k);
        if (k == 6) c.camera[6] = c.camera[7] = 0.0, c.camera[8] = 1.0;
        c.camera_set = 1;
      } else if (strcmp(a, "--fov") == 0) {
        CLSPH_TRY(parse_real(a, val, &c.fov));
        CLSPH_CHECK(c.fov > 1.0 && c.fov < 170.0, CLSPH_E_INPUT,
                    "--fov: %s is not a field of view between 1 and 170 degrees", val);
      } else if (strcmp(a, "--slice") == 0) {
        char *end = NULL;
        const char *axes = "xyz", *at = strchr(axes, val[0]);
        CLSPH_CHECK(val[0] != '\0' && at != NULL && val[1] == '=', CLSPH_E_INPUT,
                    "--slice: '%s' is not AXIS=VALUE with AXIS x, y or z (e.g. --slice y=0.075)",
                    val);
        c.slice_at = strtod(val + 2, &end);
        CLSPH_CHECK(end != val + 2 && *end == '\0' && isfinite(c.slice_at), CLSPH_E_INPUT,
                    "--slice: '%s': the plane's position '%s' is not a number (m)", val, val + 2);
        c.slice_axis = (int)(at - axes);
        c.slice_set = 1;
      } else {
        CLSPH_CHECK(0, CLSPH_E_INPUT, "unknown option %s (see clsph --help)", a);
      }
      ++i;
    } else if (c.command == NULL) {
      int known = 0;
      for (size_t k = 0; k < sizeof commands / sizeof *commands; ++k)
        known |= !strcmp(a, commands[k]);
      CLSPH_CHECK(known, CLSPH_E_INPUT,
                  "unknown command '%s'; commands: run, info, render, devices, demo, bench, help",
                  a);
      c.command = a;
    } else if ((strcmp(c.command, "run") == 0 || strcmp(c.command, "info") == 0) &&
               c.case_path == NULL) {
      c.case_path = a;
    } else if (strcmp(c.command, "render") == 0 && c.snap_dir == NULL) {
      c.snap_dir = a;
    } else if (strcmp(c.command, "bench") == 0 && c.target == NULL) {
      CLSPH_CHECK(strcmp(a, "neighbours") == 0 || strcmp(a, "psolve") == 0 ||
                      strcmp(a, "render") == 0 || strcmp(a, "dambreak") == 0,
                  CLSPH_E_INPUT,
                  "unknown benchmark '%s'; benchmarks: neighbours, psolve, render, dambreak", a);
      c.target = a;
    } else {
      CLSPH_CHECK(0, CLSPH_E_INPUT, "unexpected argument '%s' (see clsph --help)", a);
    }
  }
  if (c.command == NULL) c.command = "help";
  const int dambreak =
      strcmp(c.command, "bench") == 0 && c.target != NULL && strcmp(c.target, "dambreak") == 0;
  if (c.bench_reps == 0) c.bench_reps = dambreak ? 1 : 7;
  CLSPH_CHECK(
      c.bench_case == NULL || dambreak, CLSPH_E_INPUT,
      "--case belongs to `clsph bench dambreak`; `clsph run` and `clsph info` take the case "
      "script as their argument");
  if (c.bench_sizes == NULL)
    c.bench_sizes =
        c.target != NULL && strcmp(c.target, "psolve") == 0 ? "1e3,1e4,1e5,1e6" : "1e4,1e5,1e6";
  CLSPH_CHECK((strcmp(c.command, "run") != 0 && strcmp(c.command, "info") != 0) ||
                  c.case_path != NULL,
              CLSPH_E_INPUT, "%s: name the case script, e.g. `clsph %s cases/hydrostatic.lua`",
              c.command, c.command);
  CLSPH_CHECK(strcmp(c.command, "bench") != 0 || c.target != NULL, CLSPH_E_INPUT,
              "bench: name the benchmark, e.g. `clsph bench neighbours`");
  CLSPH_CHECK(strcmp(c.command, "render") != 0 || c.snap_dir != NULL, CLSPH_E_INPUT,
              "render: name the output folder of a run, e.g. `clsph render out/cavity`");
  {
    /* the options of frames belong to run --frames, render and bench render */
    const int takes_frames =
        (strcmp(c.command, "run") == 0 && c.frames) || strcmp(c.command, "render") == 0 ||
        (strcmp(c.command, "bench") == 0 && c.target != NULL && strcmp(c.target, "render") == 0);
    CLSPH_CHECK(!c.slice_set || strcmp(c.command, "render") == 0, CLSPH_E_INPUT,
                "--slice belongs to `clsph render OUTDIR` (of a 3-D run)");
    const char *given = c.field        ? "--field"
                        : c.range_set  ? "--range"
                        : c.colormap   ? "--colormap"
                        : c.width      ? "--size"
                        : c.fps        ? "--fps"
                        : c.no_movie   ? "--no-movie"
                        : c.font       ? "--font"
                        : c.camera_set ? "--camera"
                        : c.fov > 0.0  ? "--fov"
                                       : NULL;
    CLSPH_CHECK(given == NULL || takes_frames, CLSPH_E_INPUT,
                "%s is an option of frames: use it with `clsph run CASE --frames` or `clsph "
                "render OUTDIR`",
                given);
    CLSPH_CHECK(c.restart == NULL || strcmp(c.command, "run") == 0, CLSPH_E_INPUT,
                "--restart belongs to `clsph run CASE`");
    CLSPH_CHECK(!c.overwrite || strcmp(c.command, "run") == 0 || dambreak, CLSPH_E_INPUT,
                "--overwrite belongs to `clsph run CASE` and `clsph bench dambreak`");
    CLSPH_CHECK(!c.frames || strcmp(c.command, "run") == 0, CLSPH_E_INPUT,
                "--frames belongs to `clsph run CASE`; `clsph render OUTDIR` draws frames of a "
                "finished run");
  }
  *out = c;
done:
  return st;
}
