/* cli.h: the command line and the commands it dispatches to. */
#ifndef CLSPH_CLI_H
#define CLSPH_CLI_H

#include <stdio.h>

#include "status.h"

#define CLI_MAX_SETS 64

struct cli {
  const char *command;      /* "run", "info", "render", "devices", "demo", "bench", "help" */
  const char *case_path;    /* run, info: the case script */
  char *sets[CLI_MAX_SETS]; /* --set name=value, in order */
  int nsets;
  const char *out_dir;      /* --out DIR (default out/<case>) */
  const char *restart;      /* --restart FILE */
  int overwrite;            /* --overwrite: clear an earlier run's outputs in --out */
  double case_instructions; /* --case-instructions N: the case sandbox's budget (0: default) */
  double case_memory;       /* --case-memory MIB: its memory ceiling, bytes (0: default) */
  int quiet;                /* --quiet: no progress line */
  int profile;              /* --profile: device time per kernel of a run */
  const char *target;       /* bench: "neighbours", "psolve", "render", "dambreak" */
  const char *bench_case;   /* --case FILE: the case `bench dambreak` times (NULL: its own) */
  int device;               /* --device N, -1: $CLSPH_DEVICE or the default */
  double device_memory;     /* --device-memory MIB: the most device memory a run may use, bytes
                             * (0: the device's) */
  const char *kernel_dir;   /* --kernel-dir DIR, NULL: embedded sources */
  const char *cache_dir;    /* --prog-cache-dir DIR ("" disables), NULL: default */
  int fast_math;            /* --fast-math */
  int verbose;              /* --verbose */
  const char *bench_sizes;  /* --bench-sizes 1e4,1e5,1e6 */
  int bench_reps;           /* --bench-reps N (default 7; 1 for bench dambreak) */
  double bench_direct_max;  /* --bench-direct-max N: largest UMFPACK solve of `bench psolve` */
  double demo_dr;           /* --demo-dr spacing of the demo lattice */
  /* frames: run --frames, render, bench render */
  const char *snap_dir; /* render: the output folder of a run */
  int frames;           /* --frames: a frame per snapshot and a movie */
  const char *field;    /* --field NAME (NULL: the case's, else speed) */
  int range_set;        /* --range given: */
  int range_auto;       /*   --range auto */
  double range[2];      /*   --range LO,HI */
  const char *colormap; /* --colormap NAME (NULL: the case's, else by the field) */
  int width, height;    /* --size WxH (0: 1280 x 720) */
  int fps;              /* --fps N (0: 10) */
  int no_movie;         /* --no-movie */
  const char *font;     /* --font FILE (NULL: $CLSPH_FONT, else DejaVu Sans) */
  int camera_set;       /* --camera EX,EY,EZ,AX,AY,AZ[,UX,UY,UZ] given (3-D frames): */
  double camera[9];     /*   eye, look-at point, up (default 0, 0, 1) */
  double fov;           /* --fov DEG (0: the case's, else 30) */
  int slice_set;        /* --slice AXIS=VALUE given (render of a 3-D run): */
  int slice_axis;       /*   0, 1, 2: x, y, z */
  double slice_at;      /*   the plane's position, m */
};

/** @brief Parse argv; bad input is reported with the offending argument. */
enum clsph_status cli_parse(int argc, char **argv, struct cli *out);
/** @brief The --help text. */
void cli_usage(FILE *f);

/** @brief `clsph run CASE`: run a case (see commands.c). */
enum clsph_status run_command(const struct cli *cli);
/** @brief `clsph info CASE`: what a run would do, without running. */
enum clsph_status info_command(const struct cli *cli);
/** @brief `clsph demo`: the operator demonstration (see demo.c). */
enum clsph_status demo_run(const struct cli *cli);
/** @brief `clsph bench neighbours`. */
enum clsph_status bench_run(const struct cli *cli);
/** @brief `clsph bench psolve`. */
enum clsph_status bench_psolve(const struct cli *cli);
/** @brief `clsph bench dambreak`: a case run through the time loop, timed and profiled (see
 *  bench_dambreak.c). */
enum clsph_status bench_dambreak(const struct cli *cli);
/** @brief `clsph render OUTDIR`: frames and a movie from a run's snapshots (see commands.c). */
enum clsph_status render_command(const struct cli *cli);
/** @brief `clsph bench render`: frame times (see bench_render.c). */
enum clsph_status bench_render(const struct cli *cli);

#endif /* CLSPH_CLI_H */
