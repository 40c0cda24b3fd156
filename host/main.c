/* main.c: entry point of clsph. Exit codes: 0 success, 1 failure, 2 bad command line or input,
 * 130 and 143 a run interrupted by SIGINT or SIGTERM (with a checkpoint). */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "dev.h"
#include "interrupt.h"
#include "prog.h"

int main(int argc, char **argv)
{
  struct cli cli;
  enum clsph_status st = cli_parse(argc, argv, &cli);
  if (st != CLSPH_OK) return 2;
  if (cli.verbose) log_set_level(LOG_DEBUG);
  prog_set_kernel_dir(cli.kernel_dir);
  prog_set_cache_dir(cli.cache_dir);
  prog_set_fast_math(cli.fast_math);

  if (strcmp(cli.command, "help") == 0) {
    cli_usage(stdout);
    return 0;
  }
  if (strcmp(cli.command, "run") == 0)
    st = run_command(&cli);
  else if (strcmp(cli.command, "info") == 0)
    st = info_command(&cli);
  else if (strcmp(cli.command, "render") == 0)
    st = render_command(&cli);
  else if (strcmp(cli.command, "devices") == 0)
    st = dev_list();
  else if (strcmp(cli.command, "demo") == 0)
    st = demo_run(&cli);
  else if (strcmp(cli.command, "bench") == 0 && strcmp(cli.target, "psolve") == 0)
    st = bench_psolve(&cli);
  else if (strcmp(cli.command, "bench") == 0 && strcmp(cli.target, "render") == 0)
    st = bench_render(&cli);
  else if (strcmp(cli.command, "bench") == 0 && strcmp(cli.target, "dambreak") == 0)
    st = bench_dambreak(&cli);
  else if (strcmp(cli.command, "bench") == 0)
    st = bench_run(&cli);
  if (st == CLSPH_E_INPUT) return 2;
  if (st == CLSPH_E_INTERRUPTED) return 128 + interrupt_signal(); /* 130 SIGINT, 143 SIGTERM */
  return st == CLSPH_OK ? 0 : 1;
}
