/* cli.c: command-line parsing and help. */
#include "cli.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

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
        "  devices               list OpenCL platforms and devices (index, type, OpenCL version,\n"
        "                        memory, double precision)\n"
        "  demo                  the default scene: a particle lattice, its device neighbour\n"
        "                        search and the SPH operators against exact derivatives\n"
        "  bench neighbours      neighbour search and operator sweeps for 1e4, 1e5, 1e6\n"
        "                        particles, against a native OpenMP loop\n"
        "  bench psolve          pressure solves of 1e3 .. 1e6 unknowns: BiCGStab (stored or\n"
        "                        recomputed operator, two preconditioners) and UMFPACK; writes\n"
        "                        --out/psolve.csv and psolve.png\n"
        "  help                  this text\n"
        "\n"
        "options:\n"
        "  --set NAME=VALUE      override a parameter the case declares (repeatable), e.g.\n"
        "                        --set dr=0.005 --set t_end=0.1\n"
        "  --out DIR             output folder of `run` (default out/CASE)\n"
        "  --restart FILE        continue a run from one of its checkpoints\n"
        "  --quiet               no progress line (and no --profile table)\n"
        "  --profile             time every kernel launch and transfer of `run` on the device\n"
        "                        (OpenCL profiling events): a table by kernel at the end, and\n"
        "                        \"profile\" in summary.json\n"
        "  --device N            device index from `clsph devices` (default: $CLSPH_DEVICE, else\n"
        "                        the first GPU, else the first CPU)\n"
        "  --kernel-dir DIR      read OpenCL sources from DIR instead of the embedded copy\n"
        "  --prog-cache-dir DIR  cache of built programs (default ~/.cache/clsph; '' disables)\n"
        "  --fast-math           allow -cl-fast-relaxed-math (off by default)\n"
        "  --bench-sizes LIST    particle counts for `bench`, e.g. 1e4,1e5 (default 1e4,1e5,1e6)\n"
        "  --bench-reps N        repetitions per figure; the median is printed (default 7)\n"
        "  --bench-direct-max N  largest UMFPACK solve of `bench psolve` (default 2e5)\n"
        "  --demo-dr DR          lattice spacing of the demo on the unit square (default 0.01)\n"
        "  --verbose             debug messages (build options, cache hits)\n"
        "  -h, --help            this text\n"
        "\n"
        "examples:\n"
        "  clsph run cases/hydrostatic.lua --set dr=0.02 --out out/tank\n"
        "  clsph info cases/hydrostatic.lua\n"
        "  clsph run cases/hydrostatic.lua --restart out/tank/checkpoint_000100.h5\n"
        "  clsph run cases/cavity.lua --set n=40 --set t_end=0.5 --profile\n"
        "  clsph devices\n"
        "  clsph demo --device 0\n"
        "  clsph bench neighbours --bench-sizes 1e4,1e5 --bench-reps 5\n",
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

enum clsph_status cli_parse(int argc, char **argv, struct cli *out)
{
  enum clsph_status st = CLSPH_OK;
  static const char *const commands[] = {"run", "info", "devices", "demo", "bench", "help"};
  struct cli c;
  memset(&c, 0, sizeof c);
  c.device = -1;
  c.bench_reps = 7;
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
    } else if (strcmp(a, "--profile") == 0) {
      c.profile = 1;
    } else if (strncmp(a, "--", 2) == 0) {
      CLSPH_CHECK(val != NULL, CLSPH_E_INPUT, "option %s needs a value (see clsph --help)", a);
      if (strcmp(a, "--set") == 0) {
        CLSPH_CHECK(c.nsets < CLI_MAX_SETS, CLSPH_E_INPUT, "--set: at most %d", CLI_MAX_SETS);
        c.sets[c.nsets++] = argv[i + 1];
      } else if (strcmp(a, "--out") == 0) {
        c.out_dir = val;
      } else if (strcmp(a, "--restart") == 0) {
        c.restart = val;
      } else if (strcmp(a, "--device") == 0) {
        CLSPH_TRY(parse_int(a, val, 0, 999999, &c.device));
      } else if (strcmp(a, "--kernel-dir") == 0) {
        c.kernel_dir = val;
      } else if (strcmp(a, "--prog-cache-dir") == 0) {
        c.cache_dir = val;
      } else if (strcmp(a, "--bench-sizes") == 0) {
        c.bench_sizes = val;
      } else if (strcmp(a, "--bench-direct-max") == 0) {
        CLSPH_TRY(parse_real(a, val, &c.bench_direct_max));
      } else if (strcmp(a, "--bench-reps") == 0) {
        CLSPH_TRY(parse_int(a, val, 1, 1000, &c.bench_reps));
      } else if (strcmp(a, "--demo-dr") == 0) {
        CLSPH_TRY(parse_real(a, val, &c.demo_dr));
      } else {
        CLSPH_CHECK(0, CLSPH_E_INPUT, "unknown option %s (see clsph --help)", a);
      }
      ++i;
    } else if (c.command == NULL) {
      int known = 0;
      for (size_t k = 0; k < sizeof commands / sizeof *commands; ++k)
        known |= !strcmp(a, commands[k]);
      CLSPH_CHECK(known, CLSPH_E_INPUT,
                  "unknown command '%s'; commands: run, info, devices, demo, bench, help", a);
      c.command = a;
    } else if ((strcmp(c.command, "run") == 0 || strcmp(c.command, "info") == 0) &&
               c.case_path == NULL) {
      c.case_path = a;
    } else if (strcmp(c.command, "bench") == 0 && c.target == NULL) {
      CLSPH_CHECK(strcmp(a, "neighbours") == 0 || strcmp(a, "psolve") == 0, CLSPH_E_INPUT,
                  "unknown benchmark '%s'; benchmarks: neighbours, psolve", a);
      c.target = a;
    } else {
      CLSPH_CHECK(0, CLSPH_E_INPUT, "unexpected argument '%s' (see clsph --help)", a);
    }
  }
  if (c.command == NULL) c.command = "help";
  if (c.bench_sizes == NULL)
    c.bench_sizes =
        c.target != NULL && strcmp(c.target, "psolve") == 0 ? "1e3,1e4,1e5,1e6" : "1e4,1e5,1e6";
  CLSPH_CHECK((strcmp(c.command, "run") != 0 && strcmp(c.command, "info") != 0) ||
                  c.case_path != NULL,
              CLSPH_E_INPUT, "%s: name the case script, e.g. `clsph %s cases/hydrostatic.lua`",
              c.command, c.command);
  CLSPH_CHECK(strcmp(c.command, "bench") != 0 || c.target != NULL, CLSPH_E_INPUT,
              "bench: name the benchmark, e.g. `clsph bench neighbours`");
  *out = c;
done:
  return st;
}
