/* run.c: the `run` and `info` commands. Everything is checked (case, geometry, device, output
 * folder) before the first step, so bad input leaves nothing half-written. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case.h"
#include "cli.h"
#include "clsph_config.h"
#include "kern.h"
#include "scheme.h"
#include "sim.h"

static enum clsph_status setup(const struct cli *cli, struct dev *dev, struct scene *scene,
                               struct case_script **script, struct sim *sim)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(case_load(cli->case_path, cli->nsets, cli->sets, scene, script));
  CLSPH_TRY(dev_open(cli->device, CLSPH_DOUBLE, dev));
  CLSPH_TRY(sim_create(dev, scene, sim));
done:
  return st;
}

enum clsph_status info_command(const struct cli *cli)
{
  enum clsph_status st = CLSPH_OK;
  struct dev dev = {0};
  struct scene scene;
  struct sim sim;
  memset(&scene, 0, sizeof scene);
  memset(&sim, 0, sizeof sim);
  CLSPH_TRY(setup(cli, &dev, &scene, NULL, &sim));
  printf("device %d: %s (%s), precision %s\n", dev.index, dev.name, dev.platform_name,
         CLSPH_PRECISION_NAME);
  CLSPH_TRY(sim_info(&sim));
done:
  sim_destroy(&sim);
  scene_free(&scene);
  dev_close(&dev);
  return st;
}

/* The --profile table: device time per kernel, slowest first, as a share of the summed device time
 * and of the run's wall time; what is left of the wall time is the host's (set-up of launches,
 * outputs, reductions finished on the host) and waiting. */
static enum clsph_status print_profile(struct kern_profile *p, double wall)
{
  enum clsph_status st = CLSPH_OK;
  struct kern_profile_entry *e = NULL;
  size_t n = 0;
  double device = 0.0;
  long launches = 0;
  CLSPH_TRY(kern_profile_entries(p, &e, &n, &device));
  if (n == 0) goto done;
  int w = (int)strlen("host and waiting");
  for (size_t i = 0; i < n; ++i) {
    if ((int)strlen(e[i].name) > w) w = (int)strlen(e[i].name);
    launches += e[i].launches;
  }
  double dshare = device > 0.0 ? 100.0 / device : 0.0, wshare = wall > 0.0 ? 100.0 / wall : 0.0;
  printf("profile: device time per kernel over the run's %.3f s of wall time\n", wall);
  /* "mean µs" is 8 bytes shown in 7 columns: its field is one byte wider */
  printf("  %-*s %9s %10s %11s %8s %8s\n", w, "kernel", "launches", "total s", "mean µs", "device",
         "wall");
  for (size_t i = 0; i < n; ++i)
    printf("  %-*s %9ld %10.4f %10.1f %7.1f%% %7.1f%%\n", w, e[i].name, e[i].launches, e[i].seconds,
           1e6 * e[i].seconds / (double)e[i].launches, dshare * e[i].seconds,
           wshare * e[i].seconds);
  printf("  %-*s %9ld %10.4f %10s %7.1f%% %7.1f%%\n", w, "device total", launches, device, "",
         device > 0.0 ? 100.0 : 0.0, wshare * device);
  printf("  %-*s %9s %10.4f %10s %8s %7.1f%%\n", w, "host and waiting", "", wall - device, "", "",
         wshare * (wall - device));
done:
  free(e);
  return st;
}

enum clsph_status run_command(const struct cli *cli)
{
  enum clsph_status st = CLSPH_OK;
  struct dev dev = {0};
  struct scene scene;
  struct sim sim;
  struct case_script *script = NULL;
  char out[1024];
  memset(&scene, 0, sizeof scene);
  memset(&sim, 0, sizeof sim);
  CLSPH_TRY(setup(cli, &dev, &scene, &script, &sim));
  if (cli->profile) CLSPH_TRY(kern_profile_create(&dev));
  if (cli->out_dir != NULL)
    snprintf(out, sizeof out, "%s", cli->out_dir);
  else
    snprintf(out, sizeof out, "out/%s", scene.name);
  if (!cli->quiet)
    printf("clsph run %s: scheme %s, %zu particles (%zu fluid), %s on %s, output in %s\n",
           scene.name, sim.scheme->name, sim.ps.n, sim.geom.nfluid, CLSPH_PRECISION_NAME, dev.name,
           out);
  struct sim_options opt = {out, cli->restart, cli->quiet};
  st = sim_run(&sim, &opt, script);
  if (!cli->quiet && st == CLSPH_OK)
    printf("done: t = %g s in %ld steps; %s/summary.json\n", sim.time, sim.step, out);
  if (!cli->quiet && dev.profile != NULL) {
    enum clsph_status ps = print_profile(dev.profile, sim.wall);
    if (st == CLSPH_OK) st = ps;
  }
done:
  sim_destroy(&sim);
  case_close(script);
  scene_free(&scene);
  dev_close(&dev);
  return st;
}
