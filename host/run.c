/* run.c: the `run` and `info` commands. Everything is checked (case, geometry, device, output
 * folder) before the first step, so bad input leaves nothing half-written. */
#include <stdio.h>
#include <string.h>

#include "case.h"
#include "cli.h"
#include "clsph_config.h"
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
done:
  sim_destroy(&sim);
  case_close(script);
  scene_free(&scene);
  dev_close(&dev);
  return st;
}
