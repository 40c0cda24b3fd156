/* bench.c: `clsph bench neighbours`: device neighbour search (binning, sort, cell tables,
 * reordering) and one sweep of each common operator, for several particle counts in 2-D, each
 * against a plain C loop of the same operator compiled with OpenMP (native.c, the machine's own
 * reference), run in turn with it so that both see the same machine. Figures are medians over
 * --bench-reps repetitions (the ratio: the median of each repetition's ratio); pair evaluations
 * count the pairs within the support radius (i itself included), the same count for device and
 * native. */
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>

#include "cli.h"
#include "clsph_config.h"
#include "lattice.h"
#include "native.h"
#include "ops.h"
#include "pset.h"
#include "smoothing.h"

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static double median(double *v, int n)
{
  qsort(v, (size_t)n, sizeof *v, cmp_double);
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static enum clsph_status bench_size(const struct dev *dev, const struct cli *cli, long target)
{
  enum clsph_status st = CLSPH_OK;
  const int reps = cli->bench_reps;
  const int side = (int)lround(sqrt((double)target));
  const double dr = 1.0; /* spacing 1: every size shares one program (h = 2) */
  struct lattice lat = {0};
  struct smoothing sm;
  cl_program prog[2] = {NULL, NULL};
  struct ops ops[2];
  struct grid g = {0};
  struct pset ps;
  cl_mem d_flags = NULL, d_L = NULL, d_s = NULL, d_s4 = NULL, d_v = NULL;
  real *pos = NULL, *nat_out = NULL, *dev_out = NULL, *vol = NULL, *fld = NULL, *Lh = NULL;
  real *fld_a = NULL, *fld_u = NULL;
  cl_uint *start = NULL;
  double *t = NULL, *tn = NULL, *ratio = NULL, *stage = NULL;
  const cl_uint zero = 0;
  int i_pos, i_vol, i_f, i_u, i_id;

  memset(ops, 0, sizeof ops);
  pset_init(&ps, 0, 0);
  const int cells[3] = {side, side, 1};
  const double lo[3] = {0, 0, 0};
  CLSPH_TRY(lattice_make(2, cells, dr, lo, 0.2, 1, 7, &lat));
  size_t n = lat.n;
  pset_init(&ps, n, n);
  CLSPH_TRY(smoothing_make(SMOOTHING_WENDLAND_C2, 2, 2.0 * dr, &sm));
  struct grid_spec spec = {
      .dim = 2, .lo = {0, 0, 0}, .hi = {side * dr, side * dr, 0}, .support = sm.support, .sm = sm};
  for (int k = 0; k < 2; ++k) {
    CLSPH_TRY(ops_build(dev, &spec, &sm, k, &prog[k]));
    CLSPH_TRY(ops_create(prog[k], k, &ops[k]));
  }
  CLSPH_TRY(grid_create(dev, prog[0], &spec, n, &g));

  t = malloc((size_t)reps * sizeof *t);
  tn = malloc((size_t)reps * sizeof *tn);
  ratio = malloc((size_t)reps * sizeof *ratio);
  stage = malloc(5 * (size_t)reps * sizeof *stage);
  pos = malloc(2 * n * sizeof *pos);
  nat_out = malloc(4 * n * sizeof *nat_out);
  dev_out = malloc(4 * n * sizeof *dev_out);
  Lh = malloc(4 * n * sizeof *Lh);
  fld_a = malloc(n * sizeof *fld_a);
  fld_u = malloc(2 * n * sizeof *fld_u);
  vol = malloc(n * sizeof *vol);
  fld = malloc(2 * n * sizeof *fld);
  start = malloc((g.ncells + 1) * sizeof *start);
  CLSPH_CHECK(t && tn && ratio && stage && pos && nat_out && dev_out && Lh && fld_a && fld_u &&
                  vol && fld && start,
              CLSPH_E_NOMEM, "bench: out of memory for %zu particles", n);
  for (size_t i = 0; i < n; ++i) vol[i] = (real)(dr * dr);
  for (size_t i = 0; i < 2 * n; ++i) fld[i] = (real)(0.001 * (double)(i % 1000));
  cl_uint *id = (cl_uint *)nat_out; /* scratch for the initial ids */
  for (size_t i = 0; i < n; ++i) id[i] = (cl_uint)i;
  CLSPH_TRY(kern_buffer(dev, sizeof(cl_uint), &zero, &d_flags, "flags"));
  CLSPH_TRY(pset_add(&ps, dev, "pos", 2 * sizeof(real), lat.pos, &i_pos));
  CLSPH_TRY(pset_add(&ps, dev, "vel", 2 * sizeof(real), fld, &i_u));
  CLSPH_TRY(pset_add(&ps, dev, "vol", sizeof(real), vol, &i_vol));
  CLSPH_TRY(pset_add(&ps, dev, "p", sizeof(real), fld, &i_f));
  CLSPH_TRY(pset_add(&ps, dev, "id", sizeof(cl_uint), id, &i_id));
  CLSPH_TRY(kern_buffer(dev, n * 4 * sizeof(real), NULL, &d_L, "L"));
  CLSPH_TRY(kern_buffer(dev, n * sizeof(real), NULL, &d_s, "sum"));
  CLSPH_TRY(kern_buffer(dev, n * 4 * sizeof(real), NULL, &d_s4, "matrix out"));
  CLSPH_TRY(kern_buffer(dev, n * 2 * sizeof(real), NULL, &d_v, "vector out"));

  /* neighbour search: first on the shuffled set, then the steady state (nearly sorted) */
  double t0 = now();
  CLSPH_TRY(grid_sort(&g, dev, n, pset_mem(&ps, i_pos), NULL, d_flags));
  CLSPH_TRY(pset_reorder(&ps, &g, dev));
  CLSPH_TRY(kern_finish(dev));
  double first = now() - t0;
  for (int r = 0; r < reps; ++r) {
    grid_timing(&g, 1);
    t0 = now();
    CLSPH_TRY(grid_sort(&g, dev, n, pset_mem(&ps, i_pos), NULL, d_flags));
    CLSPH_TRY(pset_reorder(&ps, &g, dev));
    CLSPH_TRY(kern_finish(dev));
    t[r] = now() - t0;
    stage[0 * reps + r] = g.t_bin.seconds;
    stage[1 * reps + r] = g.t_scan.seconds;
    stage[2 * reps + r] = g.t_scatter.seconds + g.t_order.seconds;
    stage[3 * reps + r] = g.t_gather.seconds;
  }
  grid_timing(&g, 0);
  double search = median(t, reps);
  double bin = median(stage, reps), scan = median(stage + reps, reps);
  double sort = median(stage + 2 * reps, reps), gather = median(stage + 3 * reps, reps);

  /* the sorted particles and fields, for the native loops */
  cl_mem P = pset_mem(&ps, i_pos), V = pset_mem(&ps, i_vol);
  CLSPH_TRY(kern_read(dev, P, 2 * n * sizeof(real), pos));
  CLSPH_TRY(kern_read(dev, pset_mem(&ps, i_f), n * sizeof(real), fld_a));
  CLSPH_TRY(kern_read(dev, pset_mem(&ps, i_u), 2 * n * sizeof(real), fld_u));
  CLSPH_TRY(kern_read(dev, g.d_start, (g.ncells + 1) * sizeof(cl_uint), start));
  CLSPH_TRY(ops_apply(&ops[0], OP_CORRECTION, dev, &g, n, P, V, NULL, NULL, d_L, NULL));
  CLSPH_TRY(kern_read(dev, d_L, 4 * n * sizeof(real), Lh));
  struct native_set ns = {.pos = pos,
                          .vol = vol, /* uniform: the same in the sorted order */
                          .start = start,
                          .n = n,
                          .nc = {g.n[0], g.n[1]},
                          .cell_inv = g.geom.inv_cell.s[0],
                          .sub = GRID_SUB_DEFAULT,
                          .h = sm.h,
                          .alpha = sm.alpha};
  long pairs = 0;
  native_op(OP_SHEPARD, &ns, NULL, nat_out, &pairs);
  printf("\n%zu particles (%d x %d, jittered lattice, shuffled), %ld pairs within 2h "
         "(%.1f per particle), %zu cells\n",
         n, side, side, pairs, (double)pairs / (double)n, g.ncells);
  printf("  neighbour search (wall, median): %9.3f ms   [first, from shuffled: %.3f ms]\n",
         1e3 * search, 1e3 * first);
  printf("    device time: bin %.3f ms, scan %.3f ms, scatter+order %.3f ms, reorder 5 fields "
         "%.3f ms\n",
         1e3 * bin, 1e3 * scan, 1e3 * sort, 1e3 * gather);

  /* operator sweeps: device time per sweep against the native loop's (OpenMP threads), in turn */
  double shepard = 0.0, worst = INFINITY, worst_diff = 0.0;
  char worst_label[64] = "";
  printf("  %-28s %10s %12s %10s %8s %9s\n", "operator sweep", "device ms", "pairs/s", "native ms",
         "/native", "rel diff");
  for (int k = 0; k < 2; ++k) {
    ns.L = k ? Lh : NULL;
    for (int op = 0; op < OP_COUNT; ++op) {
      if (k == 1 && (op == OP_SHEPARD || op == OP_INTERP)) continue; /* no gradient inside */
      if (k == 1 && op == OP_CORRECTION) continue;
      int vector_in = op == OP_DIV;
      int width = native_out_width((enum op_kind)op);
      cl_mem in = vector_in ? pset_mem(&ps, i_u) : pset_mem(&ps, i_f);
      cl_mem out = op == OP_CORRECTION ? d_s4 : width == 2 ? d_v : d_s;
      if (op == OP_CORRECTION || op == OP_SHEPARD) in = NULL;
      const real *in_h = vector_in ? fld_u : fld_a;
      long np = 0;
      /* one untimed pass of each first: the first launch of a kernel and the first touch of its
       * output cost more */
      native_op((enum op_kind)op, &ns, in_h, nat_out, &np);
      CLSPH_TRY(ops_apply(&ops[k], (enum op_kind)op, dev, &g, n, P, V, d_L, in, out, NULL));
      for (int r = 0; r < reps; ++r) {
        struct kern_timer kt = {1, 0.0, 0};
        tn[r] = native_op((enum op_kind)op, &ns, in_h, nat_out, &np);
        CLSPH_TRY(ops_apply(&ops[k], (enum op_kind)op, dev, &g, n, P, V, d_L, in, out, &kt));
        t[r] = kt.seconds;
        ratio[r] = tn[r] / kt.seconds;
      }
      CLSPH_CHECK(np == pairs, CLSPH_E_UNSUPPORTED,
                  "bench: the native %s loop saw %ld pairs, not %ld", ops_name((enum op_kind)op),
                  np, pairs);
      /* the device's result against the native one, relative to the largest native value */
      CLSPH_TRY(kern_read(dev, out, (size_t)width * n * sizeof(real), dev_out));
      double diff = 0.0, scale = 0.0;
      for (size_t i = 0; i < (size_t)width * n; ++i) {
        diff = fmax(diff, fabs((double)dev_out[i] - (double)nat_out[i]));
        scale = fmax(scale, fabs((double)nat_out[i]));
      }
      diff /= scale > 0.0 ? scale : 1.0;
      double ts = median(t, reps), tnat = median(tn, reps), rat = median(ratio, reps);
      if (op == OP_SHEPARD) shepard = ts;
      char label[64];
      snprintf(label, sizeof label, "%s%s", ops_name((enum op_kind)op), k ? " (corrected)" : "");
      printf("  %-28s %10.3f %12.3e %10.3f %8.2f %9.1e\n", label, 1e3 * ts, (double)pairs / ts,
             1e3 * tnat, rat, diff);
      if (rat < worst) {
        worst = rat;
        snprintf(worst_label, sizeof worst_label, "%s", label);
      }
      worst_diff = fmax(worst_diff, diff);
    }
  }
  /* the two computed the same sums: a few roundings apart (5e-16 double, 3e-7 float measured) */
  CLSPH_CHECK(worst_diff < (CLSPH_DOUBLE ? 1e-12 : 1e-5), CLSPH_E_UNSUPPORTED,
              "bench: the device's operators differ from the native loops by %.1e (relative): "
              "the device does not compute what the kernels say",
              worst_diff);
  printf("  slowest against its native loop (%d threads): %s at %.2f (target >= 0.8); largest "
         "relative difference %.1e; neighbour search / one sweep: %.2f (target < 1)\n",
         omp_get_max_threads(), worst_label, worst, worst_diff, search / shepard);
done:
  kern_release(&d_v);
  kern_release(&d_s4);
  kern_release(&d_s);
  kern_release(&d_L);
  kern_release(&d_flags);
  pset_destroy(&ps);
  grid_destroy(&g);
  for (int k = 0; k < 2; ++k) {
    ops_destroy(&ops[k]);
    if (prog[k] != NULL) clReleaseProgram(prog[k]);
  }
  free(start);
  free(fld);
  free(vol);
  free(fld_u);
  free(fld_a);
  free(Lh);
  free(dev_out);
  free(nat_out);
  free(pos);
  free(stage);
  free(ratio);
  free(tn);
  free(t);
  lattice_free(&lat);
  return st;
}

enum clsph_status bench_run(const struct cli *cli)
{
  enum clsph_status st = CLSPH_OK;
  struct dev dev = {0};
  char *list = NULL;
  CLSPH_TRY(dev_open(cli->device, CLSPH_DOUBLE, &dev));
  printf("clsph bench neighbours: device %d %s (%s), precision %s, 2-D, Wendland C2, h = 2 dr, "
         "median of %d\n",
         dev.index, dev.name, dev.platform_name, CLSPH_PRECISION_NAME, cli->bench_reps);
  /* After a parallel loop libgomp's threads spin for a while before they sleep, unless told to
   * be passive, and the device's sweep that follows shares the cores with them: at 10^4
   * particles its time doubled in whole runs of repetitions. libgomp reads the setting when it
   * loads, so it is the caller's to give. */
  const char *wait = getenv("OMP_WAIT_POLICY");
  if (wait == NULL || strcasecmp(wait, "passive") != 0)
    printf("note: OMP_WAIT_POLICY is not passive: the native loops' threads spin after each loop "
           "and slow the device's sweeps that follow (run with OMP_WAIT_POLICY=passive)\n");
  list = malloc(strlen(cli->bench_sizes) + 1);
  CLSPH_CHECK(list != NULL, CLSPH_E_NOMEM, "bench: out of memory");
  strcpy(list, cli->bench_sizes);
  for (char *tok = strtok(list, ","); tok != NULL; tok = strtok(NULL, ",")) {
    char *end = NULL;
    double v = strtod(tok, &end);
    CLSPH_CHECK(end != tok && *end == '\0' && v >= 100 && v <= 1e8, CLSPH_E_INPUT,
                "--bench-sizes: '%s' is not a particle count from 100 to 1e8", tok);
    CLSPH_TRY(bench_size(&dev, cli, (long)v));
  }
done:
  free(list);
  dev_close(&dev);
  return st;
}
