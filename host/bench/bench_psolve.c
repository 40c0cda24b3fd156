/* bench_psolve.c: `clsph bench psolve`: the pressure solve on the manufactured problem of
 * pproblem.h (jittered lattice, corrected Morris Laplacian: a non-symmetric operator with
 * Dirichlet rows) for 1e3 .. 1e6 unknowns: BiCGStab with the operator stored per solve (CSR) or
 * recomputed at each application, with Jacobi, Jacobi + 2 sweeps or the aggregation multigrid, and
 * UMFPACK on the host up to
 * --bench-direct-max unknowns. Prints iterations, time per solve and per iteration (medians of
 * --bench-reps cold solves from x = 0), writes OUT/psolve.csv and, with gnuplot, OUT/psolve.png
 * (time per solve against unknowns, log-log). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "clsph_config.h"
#include "pproblem.h"

struct config {
  const char *name;
  enum psolve_method method;
  enum psolve_apply apply;
  enum psolve_precond precond;
};

static const struct config configs[] = {
    {"bicgstab-stored-jacobi", PSOLVE_BICGSTAB, PSOLVE_STORED, PSOLVE_JACOBI},
    {"bicgstab-stored-sweeps", PSOLVE_BICGSTAB, PSOLVE_STORED, PSOLVE_JACOBI_SWEEPS},
    {"bicgstab-multigrid", PSOLVE_BICGSTAB, PSOLVE_STORED, PSOLVE_MULTIGRID},
    {"bicgstab-recompute-jacobi", PSOLVE_BICGSTAB, PSOLVE_RECOMPUTE, PSOLVE_JACOBI},
    {"bicgstab-recompute-sweeps", PSOLVE_BICGSTAB, PSOLVE_RECOMPUTE, PSOLVE_JACOBI_SWEEPS},
    {"umfpack", PSOLVE_DIRECT, PSOLVE_STORED, PSOLVE_JACOBI},
};

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static enum clsph_status bench_one(const struct dev *dev, long target, int reps, double direct_max,
                                   FILE *csv)
{
  enum clsph_status st = CLSPH_OK;
  struct pproblem pp;
  double t[64];
  memset(&pp, 0, sizeof pp);
  int side = (int)lround(sqrt((double)target));
  struct pproblem_spec spec = {.side = side, .jitter = 0.3, .kgc = 1, .seed = 11};
  CLSPH_TRY(pproblem_create(dev, &spec, &pp));
  printf("\n%zu unknowns (%d x %d lattice + Dirichlet layers, jittered 0.3 dr, corrected "
         "Laplacian)\n",
         pp.n, side, side);
  printf("  %-28s %6s %12s %14s %10s %12s\n", "solver", "its", "ms/solve", "ms/iteration",
         "residual", "error");
  int stored_its[2] = {0, 0}; /* iterations of the stored runs, by preconditioner */
  for (size_t c = 0; c < sizeof configs / sizeof *configs; ++c) {
    const struct config *cf = &configs[c];
    if (cf->method == PSOLVE_DIRECT && (double)pp.n > direct_max) continue;
    struct psolve ps;
    struct psolve_options o;
    struct psolve_result res;
    memset(&ps, 0, sizeof ps);
    psolve_defaults(&o);
    o.method = cf->method;
    o.apply = cf->apply;
    o.precond = cf->precond;
    o.max_it = 20000;
    cl_mem b = pset_mem(&pp.ps, pp.f_b), x = pset_mem(&pp.ps, pp.f_x);
    const real z = 0;
    double err = 0.0;
    int nrep = cf->method == PSOLVE_DIRECT ? 1 : reps;
    /* Past 2e5 unknowns a recomputed-operator solve takes many minutes on a CPU; its iterations
     * equal the stored run's (same operator), so 40 iterations give its time per iteration and
     * the solve time is estimated from the stored run's iteration count. */
    int capped = cf->apply == PSOLVE_RECOMPUTE && cf->method == PSOLVE_BICGSTAB && pp.n > 200000;
    if (capped) {
      o.max_it = 40;
      nrep = 1;
    }
    CLSPH_TRY(psolve_create(dev, pp.prog, pp.n, &o, &ps));
    for (int r = 0; r < nrep && st == CLSPH_OK; ++r) {
      st = kern_fill(dev, x, &z, sizeof z, pp.n * sizeof(real));
      if (st == CLSPH_OK) st = psolve_solve(&ps, &pp.po.op, b, x, &res);
      if (st == CLSPH_OK) st = kern_finish(dev);
      t[r] = res.seconds;
    }
    if (st == CLSPH_OK) st = pproblem_error(&pp, x, &err);
    psolve_destroy(&ps);
    CLSPH_TRY(st);
    qsort(t, (size_t)nrep, sizeof *t, cmp_double);
    double med = nrep % 2 ? t[nrep / 2] : 0.5 * (t[nrep / 2 - 1] + t[nrep / 2]);
    double per = res.its > 0 ? med / res.its : med;
    int pc = cf->precond == PSOLVE_JACOBI_SWEEPS;
    if (cf->method == PSOLVE_BICGSTAB && cf->apply == PSOLVE_STORED) stored_its[pc] = res.its;
    int its = res.its;
    if (capped) { /* the estimate */
      its = stored_its[pc];
      med = per * its;
    }
    const char *note = capped           ? "  (40 iterations timed; solve time estimated)"
                       : res.reason > 0 ? ""
                                        : "  (not converged)";
    printf("  %-28s %6d %12.3f %14.4f %10.1e %12.3e%s\n", cf->name, its, 1e3 * med, 1e3 * per,
           res.rnorm, err, note);
    fprintf(csv, "%s,%zu,%d,%.6g,%.6g,%.3g,%.4g,%s,%s\n", cf->name, pp.n, its, med, per, res.rnorm,
            err, CLSPH_PRECISION_NAME, capped ? "estimated" : "measured");
    fflush(csv);
  }
done:
  pproblem_destroy(&pp);
  return st;
}

static void chart(const char *dir, const char *csv)
{
  char cmd[4096];
  const int w =
      snprintf(cmd, sizeof cmd,
               "gnuplot -e \"set terminal pngcairo size 900,600; set output '%s/psolve.png'; "
               "set datafile separator ','; set logscale xy; set grid; set key top left; "
               "set xlabel 'unknowns'; set ylabel 'seconds per solve'; "
               "set title 'pressure solve, corrected Morris Laplacian (jittered lattice)'; "
               "plot for [s in 'bicgstab-stored-jacobi bicgstab-stored-sweeps "
               "bicgstab-recompute-jacobi bicgstab-recompute-sweeps umfpack'] "
               "'< grep ^'.s.', %s' using 2:4 with linespoints title s\" 2>&1",
               dir, csv);
  if (w < 0 || (size_t)w >= sizeof cmd) {
    log_warn("the output path is too long for the chart's command; the CSV is %s", csv);
    return;
  }
  FILE *p = popen(cmd, "r");
  if (p == NULL) {
    log_warn("cannot run gnuplot; the CSV is %s", csv);
    return;
  }
  char line[512];
  while (fgets(line, sizeof line, p) != NULL) fputs(line, stderr);
  int rc = pclose(p);
  if (rc != 0)
    log_warn("gnuplot failed (install gnuplot-nox for the chart); the CSV is %s", csv);
  else
    printf("chart: %s/psolve.png\n", dir);
}

enum clsph_status bench_psolve(const struct cli *cli)
{
  enum clsph_status st = CLSPH_OK;
  struct dev dev = {0};
  char *list = NULL, path[1100];
  FILE *csv = NULL;
  const char *dir = cli->out_dir != NULL ? cli->out_dir : "out/bench";
  CLSPH_TRY(dev_open(cli->device, CLSPH_DOUBLE, &dev));
  mkdir("out", 0755);
  mkdir(dir, 0755);
  const int w = snprintf(path, sizeof path, "%s/psolve.csv", dir);
  CLSPH_CHECK(w > 0 && (size_t)w < sizeof path, CLSPH_E_INPUT, "--out: path too long: %s", dir);
  csv = fopen(path, "w");
  CLSPH_CHECK(csv != NULL, CLSPH_E_IO, "cannot write %s", path);
  fprintf(csv, "solver,unknowns,iterations,seconds_per_solve,seconds_per_iteration,residual,"
               "error,precision,solve_time\n");
  printf("clsph bench psolve: device %d %s, precision %s, rtol %g, median of %d cold solves\n",
         dev.index, dev.name, CLSPH_PRECISION_NAME, CLSPH_DOUBLE ? 1e-8 : 1e-5, cli->bench_reps);
  list = malloc(strlen(cli->bench_sizes) + 1);
  CLSPH_CHECK(list != NULL, CLSPH_E_NOMEM, "out of memory");
  strcpy(list, cli->bench_sizes);
  for (char *tok = strtok(list, ","); tok != NULL; tok = strtok(NULL, ",")) {
    char *end = NULL;
    double v = strtod(tok, &end);
    CLSPH_CHECK(end != tok && *end == '\0' && v >= 100 && v <= 1e8, CLSPH_E_INPUT,
                "--bench-sizes: '%s' is not a count from 100 to 1e8", tok);
    CLSPH_TRY(bench_one(&dev, (long)v, cli->bench_reps, cli->bench_direct_max, csv));
  }
  fclose(csv);
  csv = NULL;
  printf("\nCSV: %s\n", path);
  chart(dir, path);
done:
  if (csv != NULL) fclose(csv);
  free(list);
  dev_close(&dev);
  return st;
}
