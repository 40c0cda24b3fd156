/* bench_dambreak.c: `clsph bench dambreak`: the dam break of DualSPHysics 5.4's CaseDambreakVal2D
 * (cases/dam_break_dsph.lua, or --case FILE, with the --set overrides) run as `clsph run` runs it:
 * the case, the particles, the programs (sim_create), then the time loop (loop_run) with every
 * kernel profiled (kern_profile), into a temporary output folder removed afterwards (--out DIR
 * keeps it). Prints the device, precision, scheme, particle counts, simulated and wall time (the
 * time loop's, as summary.json's wall_seconds: set-up apart), advection steps and acoustic
 * sub-steps (sim->substeps_sum: dual-criteria time stepping, wcsph-riemann), the fluid
 * particle-steps per second counted both ways, pair interactions per second (sim->pairs_sum,
 * where the scheme counts them), the device time per kernel, and DualSPHysics 5.4's figures on
 * the same case. The figures are those of the run with the median wall time over --bench-reps
 * runs (default 1: a run takes minutes). */
#include <cjson/cJSON.h>
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "case.h"
#include "cli.h"
#include "clsph_config.h"
#include "interrupt.h"
#include "kern.h"
#include "loop.h"
#include "progress.h"
#include "scheme.h"
#include "sim.h"
#include "str.h"

/* The speed anchor (the figures): DualSPHysics 5.4 on its CaseDambreakVal2D, dp = 0.01 m
 * (20,000 fluid particles), c0 = 88.4 m/s, 0.5 s simulated, 2 cores; a DualSPHysics step is an
 * acoustic step (its time step follows the sound speed). */
#define DSPH_LINE                                                                                  \
  "DualSPHysics 5.4, CaseDambreakVal2D at dp = 0.01 m (20,000 fluid particles), 0.5 s on 2 "       \
  "cores: 120 s median wall time, 15,880 steps, 2.8e6 particle-steps/s, 65-75 M pair "             \
  "interactions/s"
static const double dsph_wall = 120.0, dsph_t_end = 0.5;
static const size_t dsph_fluid = 20000;

/* What one run gave. */
struct bench_run {
  double setup, wall; /* set-up (case, particles, programs) and time loop, s */
  double sim_time;    /* simulated, s */
  long steps;         /* advection steps (the time loop's) */
  long substeps;      /* acoustic sub-steps over the run (0: the scheme has none) */
  double pairs;       /* pair interactions over the run (0: not counted) */
  size_t n, nfluid;   /* particles in all and fluid */
  const char *scheme; /* the scheme's name (static) */
  int anchor;         /* the anchor's scene: this case at 20,000 fluid particles to 0.5 s */
  double dp;          /* the case's parameter dp, m (0: none) */
  char metrics[256];  /* the case's metrics, "name = value, ..." */
  struct kern_profile_entry *kernels; /* device time per kernel, slowest first */
  size_t nkernels;
  double device; /* summed device time, s */
};

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* Remove a folder and everything in it (the temporary output folder). */
static enum clsph_status remove_tree(const char *path)
{
  enum clsph_status st = CLSPH_OK;
  DIR *d = opendir(path);
  char *sub = NULL;
  CLSPH_CHECK(d != NULL, CLSPH_E_IO, "cannot read the folder %s: %s", path, strerror(errno));
  for (struct dirent *e; (e = readdir(d)) != NULL;) {
    if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
    struct stat sb;
    free(sub);
    sub = str_printf("%s/%s", path, e->d_name);
    CLSPH_CHECK(sub != NULL, CLSPH_E_NOMEM, "out of memory");
    if (lstat(sub, &sb) == 0 && S_ISDIR(sb.st_mode))
      CLSPH_TRY(remove_tree(sub));
    else
      CLSPH_CHECK(unlink(sub) == 0, CLSPH_E_IO, "cannot remove %s: %s", sub, strerror(errno));
  }
  CLSPH_CHECK(rmdir(path) == 0, CLSPH_E_IO, "cannot remove the folder %s: %s", path,
              strerror(errno));
done:
  free(sub);
  if (d != NULL) closedir(d);
  return st;
}

/* The case's metrics from the run's summary.json, "name = value, ..." (empty when none). */
static void read_metrics(const char *dir, char *out, size_t size)
{
  char *path = str_printf("%s/summary.json", dir), *text = NULL;
  FILE *f = path != NULL ? fopen(path, "rb") : NULL;
  cJSON *root = NULL;
  out[0] = '\0';
  if (f == NULL) goto done;
  long len = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
  if (len <= 0 || fseek(f, 0, SEEK_SET) != 0) goto done;
  text = malloc((size_t)len + 1);
  if (text == NULL || fread(text, 1, (size_t)len, f) != (size_t)len) goto done;
  text[len] = '\0';
  root = cJSON_Parse(text);
  const cJSON *m = cJSON_GetObjectItemCaseSensitive(root, "metrics");
  for (const cJSON *v = m != NULL ? m->child : NULL; v != NULL; v = v->next) {
    if (!cJSON_IsNumber(v)) continue;
    const size_t used = strlen(out);
    const int w = snprintf(out + used, size - used, "%s%s = %.6g", used > 0 ? ", " : "", v->string,
                           v->valuedouble);
    if (w < 0 || (size_t)w >= size - used) { /* no room: end the list with "..." */
      snprintf(out + (size > 4 ? size - 4 : 0), size > 4 ? 4 : size, "...");
      break;
    }
  }
done:
  cJSON_Delete(root);
  free(text);
  if (f != NULL) fclose(f);
  free(path);
}

/* The case script: --case, else cases/dam_break_dsph.lua from here, else from the sources. */
static enum clsph_status case_path(const struct cli *cli, char **out)
{
  enum clsph_status st = CLSPH_OK;
  static const char *const own = "cases/dam_break_dsph.lua";
  if (cli->bench_case != NULL)
    *out = str_printf("%s", cli->bench_case);
  else if (access(own, R_OK) == 0)
    *out = str_printf("%s", own);
  else
    *out = str_printf("%s/%s", CLSPH_SOURCE_DIR, own);
  CLSPH_CHECK(*out != NULL, CLSPH_E_NOMEM, "out of memory");
done:
  return st;
}

/* One run: the case loaded (its --set checked), the device opened and its profile attached at
 * the first run, the output folder (a temporary one made at the first run, whose path goes to
 * *tmp), the time loop, and what it gave. */
static enum clsph_status run_once(const struct cli *cli, const char *path, int rep, int reps,
                                  struct dev *dev, char **tmp, struct bench_run *r)
{
  enum clsph_status st = CLSPH_OK;
  struct scene scene;
  struct sim sim;
  struct case_script *script = NULL;
  struct case_limits lim;
  char *dir = NULL;
  memset(&scene, 0, sizeof scene);
  memset(&sim, 0, sizeof sim);
  case_limits_default(&lim);
  if (cli->case_instructions > 0.0) lim.instructions = cli->case_instructions;
  if (cli->case_memory > 0.0) lim.memory = cli->case_memory;

  /* set-up: the case, the device (once), the particles and programs */
  const double t0 = progress_now();
  CLSPH_TRY(case_load(path, cli->nsets, cli->sets, &lim, &scene, &script));
  if (dev->ctx == NULL) {
    CLSPH_TRY(dev_open(cli->device, CLSPH_DOUBLE, dev));
    if (cli->device_memory > 0.0 && cli->device_memory < (double)dev->mem_limit)
      dev->mem_limit = (cl_ulong)cli->device_memory;
    CLSPH_TRY(kern_profile_create(dev));
  }
  CLSPH_TRY(sim_create(dev, &scene, &sim));
  r->setup = progress_now() - t0;

  /* the output folder: --out (one folder per run when there are several), else a new temporary
   * one */
  const char *root = cli->out_dir;
  if (root == NULL) {
    if (*tmp == NULL) {
      const char *base = getenv("TMPDIR");
      *tmp = str_printf("%s/clsph-bench-dambreak-XXXXXX", base != NULL && *base ? base : "/tmp");
      CLSPH_CHECK(*tmp != NULL, CLSPH_E_NOMEM, "out of memory");
      if (mkdtemp(*tmp) == NULL) {
        log_error("cannot make a temporary folder %s: %s (TMPDIR names where)", *tmp,
                  strerror(errno));
        free(*tmp);
        *tmp = NULL;
        st = CLSPH_E_IO;
        goto done;
      }
    }
    root = *tmp;
  }
  dir = reps > 1 ? str_printf("%s/run_%d", root, rep + 1) : str_printf("%s", root);
  CLSPH_CHECK(dir != NULL, CLSPH_E_NOMEM, "out of memory");
  if (!cli->quiet)
    printf("run %d of %d: %s, scheme %s, %zu particles (%zu fluid), output in %s%s\n", rep + 1,
           reps, scene.name, sim.scheme->name, sim.ps.n, sim.geom.nfluid, dir,
           cli->out_dir == NULL ? " (removed afterwards)" : "");
  fflush(stdout);

  /* the time loop, profiled from its start to its end */
  struct loop_options opt = {.out_dir = dir, .overwrite = cli->overwrite, .quiet = cli->quiet};
  CLSPH_TRY(loop_run(&sim, &opt, script));
  r->wall = sim.wall;
  r->sim_time = sim.time;
  r->steps = sim.step - sim.step0;
  r->substeps = sim.substeps_sum;
  r->pairs = sim.pairs_sum;
  r->n = sim.ps.n;
  r->nfluid = sim.geom.nfluid;
  r->scheme = sim.scheme->name;
  r->dp = 0.0;
  for (int k = 0; k < scene.nparams; ++k)
    if (strcmp(scene.params[k].name, "dp") == 0) r->dp = scene.params[k].value;
  r->anchor = strcmp(scene.name, "dam_break_dsph") == 0 && sim.geom.nfluid == dsph_fluid &&
              fabs(scene.t_end - dsph_t_end) < 1e-9;
  CLSPH_TRY(kern_profile_entries(dev->profile, &r->kernels, &r->nkernels, &r->device));
  read_metrics(dir, r->metrics, sizeof r->metrics);
done:
  free(dir);
  sim_destroy(&sim);
  case_close(script);
  scene_free(&scene);
  return st;
}

/* The device time per kernel of a run: calls, total, share of the summed device time and of the
 * wall time; what the device does not account for is the host's (launches, reductions finished
 * on the host, outputs) and waiting. */
static void print_kernels(const struct bench_run *r)
{
  int w = (int)strlen("host and waiting");
  long calls = 0;
  for (size_t i = 0; i < r->nkernels; ++i) {
    if ((int)strlen(r->kernels[i].name) > w) w = (int)strlen(r->kernels[i].name);
    calls += r->kernels[i].launches;
  }
  const double ds = r->device > 0.0 ? 100.0 / r->device : 0.0;
  const double ws = r->wall > 0.0 ? 100.0 / r->wall : 0.0;
  printf("device time per kernel (slowest first; share of the summed device time and of the "
         "wall time):\n");
  printf("  %-*s %10s %10s %8s %8s\n", w, "kernel", "calls", "total s", "device", "wall");
  for (size_t i = 0; i < r->nkernels; ++i) {
    const struct kern_profile_entry *e = &r->kernels[i];
    printf("  %-*s %10ld %10.4f %7.1f%% %7.1f%%\n", w, e->name, e->launches, e->seconds,
           ds * e->seconds, ws * e->seconds);
  }
  printf("  %-*s %10ld %10.4f %7.1f%% %7.1f%%\n", w, "device total", calls, r->device,
         r->device > 0.0 ? 100.0 : 0.0, ws * r->device);
  printf("  %-*s %10s %10.4f %8s %7.1f%%\n", w, "host and waiting", "", r->wall - r->device, "",
         ws * (r->wall - r->device));
}

/* The figures of the median run, the wall time the median over the runs. */
static void print_result(const struct cli *cli, const struct dev *dev, const char *path,
                         const struct bench_run *r, double wall, int reps)
{
  const double fluid = (double)r->nfluid;
  printf("\nclsph bench dambreak: %s, %s of %d run%s\n", path, reps > 1 ? "median" : "figures",
         reps, reps > 1 ? "s" : "");
  printf("  device:              %s (%s; --device %d)\n", dev->name, dev->platform_name,
         dev->index);
  printf("  precision:           %s\n", CLSPH_PRECISION_NAME);
  printf("  scheme:              %s\n", r->scheme);
  printf("  particles:           %zu fluid, %zu in all (walls and their layers included)\n",
         r->nfluid, r->n);
  if (r->dp > 0.0) printf("  dp:                  %g m\n", r->dp);
  printf("  simulated time:      %g s\n", r->sim_time);
  printf("  set-up:              %.2f s (case, particles, programs; not in the wall time)\n",
         r->setup);
  printf("  wall time:           %.3f s (the time loop: steps, checks, outputs)\n", wall);
  printf("  advection steps:     %ld\n", r->steps);
  if (r->substeps > 0)
    printf("  acoustic sub-steps:  %ld (%.2f per advection step)\n", r->substeps,
           (double)r->substeps / (double)(r->steps > 0 ? r->steps : 1));
  else
    printf("  acoustic sub-steps:  none (%s does not sub-step: each step is an acoustic step)\n",
           r->scheme);
  printf("  fluid particle-steps/s, per advection step:   %.4g\n",
         wall > 0.0 ? fluid * (double)r->steps / wall : 0.0);
  if (r->substeps > 0)
    printf("  fluid particle-steps/s, per acoustic sub-step: %.4g\n",
           wall > 0.0 ? fluid * (double)r->substeps / wall : 0.0);
  else
    printf("  fluid particle-steps/s, per acoustic sub-step: the same (no sub-steps)\n");
  if (r->pairs > 0.0)
    printf("  pair interactions/s: %.4g (%.4g pair interactions)\n",
           wall > 0.0 ? r->pairs / wall : 0.0, r->pairs);
  else
    printf("  pair interactions/s: not counted (%s does not count them)\n", r->scheme);
  if (r->metrics[0] != '\0') printf("  case metrics:        %s\n", r->metrics);
  print_kernels(r);
  printf("anchor: " DSPH_LINE "\n");
  if (r->anchor)
    printf("  this run's wall time is %.3g times DualSPHysics's\n", wall / dsph_wall);
  else
    printf("  this run is not the anchor's scene (%zu fluid particles, %g s): compare the rates, "
           "not the times\n",
           r->nfluid, r->sim_time);
  if (cli->out_dir != NULL) printf("outputs: %s\n", cli->out_dir);
}

enum clsph_status bench_dambreak(const struct cli *cli)
{
  enum clsph_status st = CLSPH_OK;
  struct dev dev = {0};
  struct bench_run *runs = NULL;
  double *walls = NULL;
  char *path = NULL, *tmp = NULL;
  const int reps = cli->bench_reps;
  interrupt_catch(); /* Ctrl-C ends the run after its step; the temporary folder goes */
  CLSPH_TRY(case_path(cli, &path));
  runs = calloc((size_t)reps, sizeof *runs);
  walls = calloc((size_t)reps, sizeof *walls);
  CLSPH_CHECK(runs != NULL && walls != NULL, CLSPH_E_NOMEM, "out of memory");
  for (int k = 0; k < reps; ++k) {
    CLSPH_TRY(run_once(cli, path, k, reps, &dev, &tmp, &runs[k]));
    walls[k] = runs[k].wall;
  }
  qsort(walls, (size_t)reps, sizeof *walls, cmp_double);
  const double wall = reps % 2 ? walls[reps / 2] : 0.5 * (walls[reps / 2 - 1] + walls[reps / 2]);
  /* the median run: the one whose wall time is the median (of an even count, the lower one) */
  int med = 0;
  for (int k = 0; k < reps; ++k)
    if (runs[k].wall == walls[(reps - 1) / 2]) med = k;
  print_result(cli, &dev, path, &runs[med], wall, reps);
done:
  if (tmp != NULL) {
    enum clsph_status rs = remove_tree(tmp);
    if (st == CLSPH_OK) st = rs;
  }
  for (int k = 0; runs != NULL && k < reps; ++k) free(runs[k].kernels);
  free(runs);
  free(walls);
  free(tmp);
  free(path);
  dev_close(&dev);
  interrupt_release();
  return st;
}
